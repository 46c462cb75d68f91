// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Generates the pictures of the Poincare_disk_traits_2 user manual (doc/Poincare_disk_traits_2/fig/):
//   hyperbolic_delaunay.svg    Delaunay_triangulation_2<Poincare_disk_traits_2<>> of random points; faces with a
//                              compact circumcircle (hyperbolic faces) in blue, the others (horocycle / hypercycle
//                              "circles", thesis Fig. 3.5) in orange, a few empty hyperbolic circles in green
//   constrained_delaunay.svg   Constrained_Delaunay_triangulation_2 with Exact_predicates_tag: geodesic constraints
//                              (red) crossing each other, split at their intersection points (black dots)
//   refined_mesh.svg           refine_Delaunay_mesh_2 with Hyperbolic_Ruppert_mesh_criteria_2 in a geodesic hexagon
//   encroachment.svg           the hyperbolic diametral disk of a geodesic segment (green) vs the Euclidean
//                              Thales disk (dashed grey): the mesher's Angle_2 uses the green one
// Usage: make_Poincare_disk_traits_2_figures [output_directory]   (default: the current directory)
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/IO/Poincare_disk_svg.h>
#include <CGAL/Hyperbolic_mesh_criteria_2.h>
#include <CGAL/Poincare_disk_traits_2.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Poincare_disk_traits_2<> Gt;
typedef Gt::Point_2 Point;
namespace SP = CGAL::Poincare_disk_svg::parameters;

namespace {

const double PI = 3.14159265358979323846;

std::vector<Point> random_hyperbolic(std::size_t n, double R, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> v;
  for(std::size_t i = 0; i < n; ++i) {
    const double rho = std::acosh(1 + (std::cosh(R) - 1) * u(rng)), t = 2 * PI * u(rng), e = std::tanh(rho / 2);
    v.emplace_back(e * std::cos(t), e * std::sin(t));
  }
  return v;
}

std::vector<Point> polygon(int n, double hyperbolic_radius, double phase)
{
  std::vector<Point> v;
  const double r = std::tanh(hyperbolic_radius / 2);
  for(int i = 0; i < n; ++i) v.emplace_back(r * std::cos(phase + 2 * PI * i / n), r * std::sin(phase + 2 * PI * i / n));
  return v;
}

template <class Face_handle>
std::vector<double> face_xy(Face_handle f)
{
  std::vector<double> xy;
  for(int i = 0; i < 3; ++i) { xy.push_back(f->vertex(i)->point().x()); xy.push_back(f->vertex(i)->point().y()); }
  return xy;
}

void legend(CGAL::Poincare_disk_svg_writer& svg, const std::string& line1, const std::string& line2)
{
  svg.add_text(10, 20, line1, SP::font_size(14.0));
  svg.add_text(10, 38, line2, SP::font_size(12.0, SP::fill(std::string("#444"))));
}

} // namespace

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? std::string(argv[1]) + "/" : std::string();
  const Gt gt;

  { // 1. hyperbolic Delaunay triangulation
    const std::vector<Point> pts = random_hyperbolic(150, 4.0, 7);
    CGAL::Delaunay_triangulation_2<Gt> dt(pts.begin(), pts.end());
    CGAL::Poincare_disk_svg_writer svg(SP::image_size(700.0));
    svg.add_unit_circle();
    std::size_t compact = 0, other = 0;
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const bool h = gt.is_Delaunay_hyperbolic_2_object()(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      (h ? compact : other)++;
      svg.add_geodesic_polygon(face_xy(f), SP::fill(std::string(h ? "#cfe0f5" : "#f8d9b0"), SP::stroke(std::string("#1d3f6e"), SP::stroke_width(0.6))));
    }
    int drawn = 0;
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end() && drawn < 3; ++f) {
      const Point &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
      if(!gt.is_Delaunay_hyperbolic_2_object()(a, b, c) || std::hypot(a.x(), a.y()) > 0.7) continue;
      // the empty circle: the Euclidean circle through the three vertices
      const Point o = CGAL::circumcenter(a, b, c);
      svg.add_euclidean_circle(o.x(), o.y(), std::sqrt(CGAL::squared_distance(o, a)), SP::stroke(std::string("#0a0"), SP::stroke_width(1.5)));
      ++drawn;
    }
    for(const Point& p : pts) svg.add_point(p, SP::fill(std::string("#c00"), SP::radius(2.0)));
    legend(svg, "Delaunay_triangulation_2<Poincare_disk_traits_2<>>: 150 points",
           std::to_string(compact) + " faces with a compact circumcircle (blue), " + std::to_string(other) +
             " with a horocycle / hypercycle (orange); green: empty circles");
    svg.write(dir + "hyperbolic_delaunay.svg");
  }

  { // 2. constrained Delaunay triangulation with crossing geodesic constraints
    typedef CGAL::Constrained_Delaunay_triangulation_2<Gt, CGAL::Default, CGAL::Exact_predicates_tag> CDT;
    CDT cdt;
    const std::vector<Point> hept = polygon(7, 3.0, 0.2);
    std::vector<std::pair<Point, Point> > cons;
    for(std::size_t i = 0; i < hept.size(); ++i) cons.emplace_back(hept[i], hept[(i + 1) % hept.size()]);
    cons.emplace_back(hept[0], hept[3]);
    cons.emplace_back(hept[1], hept[5]);
    cons.emplace_back(hept[2], hept[6]);
    for(const auto& c : cons) cdt.insert_constraint(c.first, c.second);
    const std::vector<Point> pts = random_hyperbolic(60, 2.5, 3);
    cdt.insert(pts.begin(), pts.end());
    CGAL::Poincare_disk_svg_writer svg(SP::image_size(700.0));
    svg.add_unit_circle();
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      svg.add_geodesic_polygon(face_xy(f), SP::fill(std::string("#eef3fa"), SP::stroke(std::string("#5a7cab"), SP::stroke_width(0.6))));
    for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
      if(cdt.is_constrained(*e))
        svg.add_geodesic_segment(e->first->vertex(cdt.ccw(e->second))->point(), e->first->vertex(cdt.cw(e->second))->point(), SP::stroke(std::string("#c00"), SP::stroke_width(2.0)));
    std::size_t crossings = 0;
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
      bool input = false;
      for(const Point& p : hept) input |= (p == v->point());
      for(const Point& p : pts) input |= (p == v->point());
      if(!input) { svg.add_point(v->point(), SP::fill(std::string("#000"), SP::radius(4.0))); ++crossings; }
      else svg.add_point(v->point(), SP::fill(std::string("#c00"), SP::radius(2.0)));
    }
    legend(svg, "Constrained_Delaunay_triangulation_2 with Exact_predicates_tag",
           "geodesic constraints (red) split at their " + std::to_string(crossings) + " intersection points (black)");
    svg.write(dir + "constrained_delaunay.svg");
  }

  { // 3. refine_Delaunay_mesh_2 with the hyperbolic criteria
    typedef CGAL::Delaunay_mesh_vertex_base_2<Gt> Vb;
    typedef CGAL::Delaunay_mesh_face_base_2<Gt> Fb;
    typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
    typedef CGAL::Constrained_Delaunay_triangulation_2<Gt, Tds> CDT;
    CDT cdt;
    const std::vector<Point> hex = polygon(6, 3.0, 0.3);
    for(std::size_t i = 0; i < hex.size(); ++i) cdt.insert_constraint(hex[i], hex[(i + 1) % hex.size()]);
    CGAL::refine_Delaunay_mesh_2(cdt, CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>(2 * 20.0 * PI / 180, 0.5));
    CGAL::Poincare_disk_svg_writer svg(SP::image_size(700.0));
    svg.add_unit_circle();
    std::size_t faces = 0;
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      ++faces;
      svg.add_geodesic_polygon(face_xy(f), SP::fill(std::string("#e3f1e3"), SP::stroke(std::string("#2f6b2f"), SP::stroke_width(0.6))));
    }
    for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
      if(cdt.is_constrained(*e))
        svg.add_geodesic_segment(e->first->vertex(cdt.ccw(e->second))->point(), e->first->vertex(cdt.cw(e->second))->point(), SP::stroke(std::string("#c00"), SP::stroke_width(1.5)));
    legend(svg, "refine_Delaunay_mesh_2 + Hyperbolic_Ruppert_mesh_criteria_2",
           std::to_string(faces) + " faces in a geodesic hexagon (circumradius 3): central angle >= 40 deg, radius <= 0.5");
    svg.write(dir + "refined_mesh.svg");
  }

  { // 4. hyperbolic diametral disk vs Thales disk
    CGAL::Poincare_disk_svg_writer svg(SP::image_size(700.0));
    svg.add_unit_circle();
    const Point p(-0.15, 0.55), q(0.75, 0.2);
    svg.add_geodesic_segment(p, q, SP::stroke(std::string("#c00"), SP::stroke_width(2.5)));
    const Point m = gt.construct_hyperbolic_midpoint_2_object()(p, q);
    const double d = gt.compute_hyperbolic_distance_2_object()(p, q);
    const auto circle = gt.construct_hyperbolic_circle_2_object().from_radius(m, d / 2);
    svg.add_euclidean_circle(circle.center().x(), circle.center().y(), std::sqrt(circle.squared_radius()), SP::stroke(std::string("#0a0"), SP::stroke_width(2.0)));
    const double tx = (p.x() + q.x()) / 2, ty = (p.y() + q.y()) / 2;
    svg.add_raw("<circle cx=\"" + std::to_string(350 + tx * 336) + "\" cy=\"" + std::to_string(350 - ty * 336) +
                "\" r=\"" + std::to_string(336 * std::hypot(p.x() - q.x(), p.y() - q.y()) / 2) +
                "\" fill=\"none\" stroke=\"#777\" stroke-dasharray=\"6,4\" stroke-width=\"1.5\"/>");
    // sample points: encroaching (Angle_2 == OBTUSE) in green, not encroaching in grey
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1, 1);
    for(int i = 0; i < 1500; ++i) {
      const Point s(u(rng), u(rng));
      if(s.x() * s.x() + s.y() * s.y() >= 0.98) continue;
      const bool enc = gt.angle_2_object()(p, s, q) == CGAL::OBTUSE;
      const bool thales = (p.x() - s.x()) * (q.x() - s.x()) + (p.y() - s.y()) * (q.y() - s.y()) < 0;
      if(enc != thales) svg.add_point(s, SP::fill(std::string(enc ? "#0a0" : "#777"), SP::radius(2.5)));
    }
    svg.add_point(p, SP::fill(std::string("#c00"), SP::radius(4.0)));
    svg.add_point(q, SP::fill(std::string("#c00"), SP::radius(4.0)));
    legend(svg, "Encroachment of pq: hyperbolic diametral disk (green) vs Thales (dashed)",
           "dots: points where the two tests disagree, by Angle_2 (green: OBTUSE = encroaching)");
    svg.write(dir + "encroachment.svg");
  }
  std::cout << "figures written to " << (dir.empty() ? std::string("./") : dir) << std::endl;
  return 0;
}
