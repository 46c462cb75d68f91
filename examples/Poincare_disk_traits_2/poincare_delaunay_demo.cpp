// The traits demo: CGAL's own triangulations with Poincare_disk_traits_2.
//
//   poincare_delaunay_demo [points.xy] [output_dir]
//
// 1. Delaunay_triangulation_2 of the points (hyperbolic Delaunay triangulation of their hyperbolic convex hull);
//    faces whose circumcircle leaves the disk (horocycle / hypercycle "circles") are shaded.
// 2. Constrained_Delaunay_triangulation_2 with geodesic constraints: a regular hyperbolic heptagon and two
//    crossing geodesic chords (Exact_predicates_tag: split at their geodesic intersection).
// 3. refine_Delaunay_mesh_2 with Hyperbolic_Ruppert_mesh_criteria_2 inside the heptagon.
// Writes poincare_delaunay.svg, poincare_cdt.svg, poincare_mesh.svg.
#include <CGAL/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_mesh_criteria_2.h>
#include <CGAL/IO/Poincare_disk_svg.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_triangulation_2.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace SP = CGAL::Poincare_disk_svg::parameters;  // the options of the SVG writer

typedef CGAL::Poincare_disk_traits_2<> Gt;
typedef Gt::Point_2 Point;
typedef CGAL::Delaunay_triangulation_2<Gt> DT;
typedef CGAL::Delaunay_mesh_vertex_base_2<Gt> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<Gt> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<Gt, Tds, CGAL::Exact_predicates_tag> CDT;

static std::vector<Point> read_points(const std::string& file)
{
  std::ifstream in(file);
  if(!in) throw std::runtime_error("cannot read " + file);
  std::vector<Point> pts;
  std::string line;
  while(std::getline(in, line)) {
    if(line.empty() || line[0] == '#') continue;
    std::istringstream is(line);
    double x, y;
    if(!(is >> x >> y)) throw std::runtime_error("bad line in " + file + ": " + line);
    pts.emplace_back(x, y);
  }
  return pts;
}

// a regular hyperbolic n-gon with vertices at hyperbolic distance r from the origin
static std::vector<Point> regular_polygon(int n, double r, double phase)
{
  std::vector<Point> v;
  const double t = std::tanh(r / 2);
  for(int i = 0; i < n; ++i) {
    const double a = phase + 2 * M_PI * i / n;
    v.emplace_back(t * std::cos(a), t * std::sin(a));
  }
  return v;
}

template <class Tr>
static void draw_edges(CGAL::Poincare_disk_svg_writer& svg, const Tr& tr)
{
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    const Point& p = e->first->vertex(tr.cw(e->second))->point();
    const Point& q = e->first->vertex(tr.ccw(e->second))->point();
    svg.add_geodesic_segment(p, q, SP::stroke("#1f4e79", SP::stroke_width(0.6)));
  }
}

static std::vector<double> face_xy(const Point& a, const Point& b, const Point& c)
{
  return {a.x(), a.y(), b.x(), b.y(), c.x(), c.y()};
}

int main(int argc, char** argv)
{
  try {
    const std::string input = argc > 1 ? argv[1] : "";
    const std::string out = argc > 2 ? std::string(argv[2]) + "/" : "";
    Gt gt;

    // ------------------------------------------------------------ 1. Delaunay triangulation
    std::vector<Point> pts = input.empty() ? regular_polygon(60, 3, 0) : read_points(input);
    DT dt(pts.begin(), pts.end());
    std::size_t compact = 0, non_compact = 0;
    CGAL::Poincare_disk_svg_writer svg1;
    svg1.add_unit_circle();
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const Point &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
      if(gt.is_Delaunay_hyperbolic_2_object()(a, b, c)) ++compact;
      else { ++non_compact; svg1.add_geodesic_polygon(face_xy(a, b, c), SP::fill("#f4c430", SP::stroke_width(0, SP::fill_opacity(0.6)))); }
    }
    draw_edges(svg1, dt);
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      svg1.add_point(v->point(), SP::fill("#c00", SP::radius(1.6)));
    svg1.add_text(10, 20, "Delaunay_triangulation_2<Poincare_disk_traits_2<>>: " + std::to_string(dt.number_of_vertices()) +
                  " vertices, " + std::to_string(compact) + " faces with compact circumcircle, " +
                  std::to_string(non_compact) + " without (shaded)", SP::font_size(12));
    svg1.write(out + "poincare_delaunay.svg");
    std::cout << "Delaunay: " << dt.number_of_vertices() << " vertices, " << dt.number_of_faces() << " faces ("
              << compact << " compact, " << non_compact << " horocycle/hypercycle), valid: " << dt.is_valid() << "\n";
    if(!dt.is_valid()) return EXIT_FAILURE;

    // ------------------------------------------------------------ 2. constrained Delaunay triangulation
    CDT cdt;
    const std::vector<Point> hept = regular_polygon(7, 2.5, 0.3);
    for(std::size_t i = 0; i < hept.size(); ++i) cdt.insert_constraint(hept[i], hept[(i + 1) % hept.size()]);
    cdt.insert_constraint(hept[0], hept[3]); // two crossing geodesic chords
    cdt.insert_constraint(hept[1], hept[5]);
    for(const Point& p : pts) if(CGAL::to_double(p.x() * p.x() + p.y() * p.y()) < 0.5) cdt.insert(p);
    CGAL::Poincare_disk_svg_writer svg2;
    svg2.add_unit_circle();
    draw_edges(svg2, cdt);
    for(auto e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e)
      svg2.add_geodesic_segment(e->first->vertex(cdt.cw(e->second))->point(),
                                e->first->vertex(cdt.ccw(e->second))->point(), SP::stroke("#c00000", SP::stroke_width(2.0)));
    svg2.add_text(10, 20, "Constrained_Delaunay_triangulation_2 with geodesic constraints (red)", SP::font_size(12));
    svg2.write(out + "poincare_cdt.svg");
    std::cout << "CDT: " << cdt.number_of_vertices() << " vertices (crossing chords split at their geodesic "
              << "intersection), valid: " << cdt.is_valid() << "\n";
    if(!cdt.is_valid()) return EXIT_FAILURE;

    // ------------------------------------------------------------ 3. CGAL's Mesh_2 with hyperbolic criteria
    CDT mesh;
    for(std::size_t i = 0; i < hept.size(); ++i) mesh.insert_constraint(hept[i], hept[(i + 1) % hept.size()]);
    const double angle = 2 * 20.7 * M_PI / 180, radius = 0.6;
    CGAL::refine_Delaunay_mesh_2(mesh, CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>(angle, radius));
    CGAL::Poincare_disk_svg_writer svg3;
    svg3.add_unit_circle();
    std::size_t in_domain = 0;
    for(auto f = mesh.finite_faces_begin(); f != mesh.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      ++in_domain;
      svg3.add_geodesic_polygon(face_xy(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()),
                                SP::fill("#dbe9f6", SP::stroke("#1f4e79", SP::stroke_width(0.5))));
    }
    svg3.add_text(10, 20, "refine_Delaunay_mesh_2 + Hyperbolic_Ruppert_mesh_criteria_2 (central angle >= 41.4 deg, "
                          "circumradius <= 0.6): " + std::to_string(in_domain) + " triangles", SP::font_size(12));
    svg3.write(out + "poincare_mesh.svg");
    std::cout << "Mesh_2: " << mesh.number_of_vertices() << " vertices, " << in_domain
              << " triangles in the heptagon, valid: " << mesh.is_valid() << "\n";
    std::cout << "wrote " << out << "poincare_delaunay.svg, poincare_cdt.svg, poincare_mesh.svg\n";
    return mesh.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
