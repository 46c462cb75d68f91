// Spherical uniformization of a closed genus-0 mesh (default: CGAL's bear.off, or an OFF given as argument;
// quad meshes are triangulated first): writes the mesh on the unit sphere (OFF) and an SVG picture (the front
// hemisphere in orthographic projection, faces shaded by the log of their area ratio, i.e. the conformal factor).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/IO/Poincare_disk_svg.h>

#include <fstream>
#include <CGAL/Discrete_Ricci_flow.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace RF = CGAL::Discrete_Ricci_flow;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/bear.off";
  Mesh tm;
  if(!CGAL::IO::read_polygon_mesh(file, tm)) { std::cerr << "cannot read " << file << std::endl; return 1; }
  if(!CGAL::is_triangle_mesh(tm)) CGAL::Polygon_mesh_processing::triangulate_faces(tm);
  try {
    const auto s = RF::spherical_uniformization(tm);
    std::cout << file << ": " << RF::to_string(s.statistics().status) << " after " << s.statistics().iterations
              << " Newton iterations, " << s.statistics().number_of_flips << " flips, " << s.statistics().time_seconds
              << " s; flipped faces " << s.number_of_flipped_faces() << ", |centre of mass| " << s.center_of_mass_norm()
              << ", spherical area - 4 pi = " << s.metric().total_area() - 4 * CGAL_PI << std::endl;
    // the input connectivity with the vertices on the sphere
    Mesh out = tm;
    for(auto v : out.vertices()) out.point(v) = s.sphere_points()[std::size_t(v)];
    const std::string off = std::string(CGAL_HC_OUTPUT_DIR) + "/spherical_uniformization.off";
    CGAL::IO::write_polygon_mesh(off, out, CGAL::parameters::stream_precision(17));
    // picture: front hemisphere (z > 0) seen from +z, shaded by log(area on the sphere / input area)
    const double ratio = 4 * CGAL_PI / CGAL::Polygon_mesh_processing::area(tm);
    const std::string svg = std::string(CGAL_HC_OUTPUT_DIR) + "/spherical_uniformization.svg";
    std::ofstream os(svg);
    const double px = 400; // pixels per unit: the unit disk is the sphere's outline
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"820\" height=\"820\" viewBox=\"-410 -410 820 820\">\n"
       << "<circle cx=\"0\" cy=\"0\" r=\"" << px << "\" fill=\"#fff\" stroke=\"#000\"/>\n";
    for(auto f : out.faces()) {
      std::ostringstream path;
      bool front = true;
      char cmd = 'M';
      for(auto v : CGAL::vertices_around_face(out.halfedge(f), out)) {
        const Point_3& p = out.point(v);
        if(p.z() <= 0) front = false;
        path << cmd << " " << px * p.x() << " " << -px * p.y() << " ";
        cmd = 'L';
      }
      if(!front) continue;
      const double a = CGAL::Polygon_mesh_processing::face_area(f, out) / (ratio * CGAL::Polygon_mesh_processing::face_area(f, tm));
      const double t = 0.5 + 0.1 * std::log(a);
      os << "<path d=\"" << path.str() << "Z\" fill=\"" << CGAL::Poincare_disk_svg_writer::color_ramp(t < 0 ? 0 : (t > 1 ? 1 : t))
         << "\" stroke=\"#333\" stroke-width=\"0.2\"/>\n";
    }
    os << "</svg>\n";
    std::cout << "wrote " << off << " and " << svg << std::endl;
    return s.converged() ? 0 : 2;
  } catch(const CGAL::Hyperbolic_geometry_error& e) {
    std::cerr << e.what() << std::endl;
    return 1;
  }
}
