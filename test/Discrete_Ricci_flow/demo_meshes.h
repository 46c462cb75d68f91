// The closed connected manifold meshes of CGAL's demo data (and extra files), triangulated, of genus in
// [genus_min, genus_max]: the mesh loop shared by the Ricci-flow test files. A file that does not load as a
// closed connected mesh is given the repair a CGAL user applies to a polygon soup (repair_polygon_soup,
// orient_polygon_soup, polygon_soup_to_polygon_mesh, stitch_borders) and kept if that makes it one: the
// '-shuffled' soups (inconsistent orientations) and boeing.off (122 patches that stitch into a genus-10
// surface); its name then ends in " (repaired)".
#ifndef CGAL_HC_TEST_RICCI_DEMO_MESHES_H
#define CGAL_HC_TEST_RICCI_DEMO_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace ricci_test {

// m = the mesh of file f, read as a mesh or (repair) as a polygon soup repaired as described above; true if m
// is then a valid, closed, connected mesh
inline bool closed_connected_mesh(const std::string& f, CGAL::Surface_mesh<CGAL::Epick::Point_3>& m, bool repair)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  m.clear();
  try {
    if(repair) {
      std::vector<CGAL::Epick::Point_3> points;
      std::vector<std::vector<std::size_t> > polygons;
      if(!CGAL::IO::read_polygon_soup(f, points, polygons)) return false;
      PMP::repair_polygon_soup(points, polygons);
      PMP::orient_polygon_soup(points, polygons);
      PMP::polygon_soup_to_polygon_mesh(points, polygons, m);
      PMP::stitch_borders(m);
    } else if(!CGAL::IO::read_polygon_mesh(f, m))
      return false;
    if(m.is_empty() || !m.is_valid(false) || !CGAL::is_closed(m)) return false;
  } catch(...) { return false; }
  std::vector<std::size_t> cc(m.number_of_faces());
  return PMP::connected_components(m, CGAL::make_property_map(cc)) == 1;
}

// m = the demo mesh of file f as the loop below takes it (read, else repaired; triangulated), `name` its name
// in the loop; false if it is not closed and connected either way
inline bool load_demo_mesh(const std::string& f, CGAL::Surface_mesh<CGAL::Epick::Point_3>& m, std::string& name)
{
  name = f.substr(f.find_last_of('/') + 1);
  if(!closed_connected_mesh(f, m, false)) {
    if(!closed_connected_mesh(f, m, true)) return false;
    name += " (repaired)";
  }
  if(!CGAL::is_triangle_mesh(m)) CGAL::Polygon_mesh_processing::triangulate_faces(m);
  return true;
}

// the demo mesh meshes/<file> of CGAL's demo data (load_demo_mesh()); an empty mesh if it cannot be loaded
inline CGAL::Surface_mesh<CGAL::Epick::Point_3> demo_mesh(const std::string& file)
{
  CGAL::Surface_mesh<CGAL::Epick::Point_3> m;
  std::string name;
  if(!load_demo_mesh(std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/" + file, m, name)) m.clear();
  return m;
}

inline std::vector<std::pair<std::string, CGAL::Surface_mesh<CGAL::Epick::Point_3> > >
demo_meshes(long genus_min, long genus_max, const std::vector<std::string>& extra_files = std::vector<std::string>())
{
  typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
  std::vector<std::string> files;
  for(const auto& e : std::filesystem::directory_iterator(std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes"))
    if(e.path().extension() == ".off") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  files.insert(files.end(), extra_files.begin(), extra_files.end());
  std::vector<std::pair<std::string, Mesh> > r;
  for(const std::string& f : files) {
    Mesh m;
    std::string name;
    if(!load_demo_mesh(f, m, name)) continue;
    const long chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
    if(chi > 2 || chi % 2 != 0) continue;
    const long g = (2 - chi) / 2;
    if(g < genus_min || g > genus_max) continue;
    r.emplace_back(name, std::move(m));
  }
  return r;
}

} // namespace ricci_test

#endif
