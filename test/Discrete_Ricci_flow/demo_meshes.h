// The closed connected manifold meshes of CGAL's demo data (and extra files), triangulated, of genus in
// [genus_min, genus_max]: the mesh loop shared by the Ricci-flow test files.
#ifndef CGAL_HC_TEST_RICCI_DEMO_MESHES_H
#define CGAL_HC_TEST_RICCI_DEMO_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace ricci_test {

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
    try { if(!CGAL::IO::read_polygon_mesh(f, m) || m.is_empty() || !m.is_valid(false) || !CGAL::is_closed(m)) continue; }
    catch(...) { continue; }
    std::vector<std::size_t> cc(m.number_of_faces());
    if(CGAL::Polygon_mesh_processing::connected_components(m, CGAL::make_property_map(cc)) != 1) continue;
    if(!CGAL::is_triangle_mesh(m)) CGAL::Polygon_mesh_processing::triangulate_faces(m);
    const long chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
    if(chi > 2 || chi % 2 != 0) continue;
    const long g = (2 - chi) / 2;
    if(g < genus_min || g > genus_max) continue;
    r.emplace_back(f.substr(f.find_last_of('/') + 1), std::move(m));
  }
  return r;
}

} // namespace ricci_test

#endif
