// Delaunay triangulations of closed hyperbolic surfaces: fundamental polygons (checks and errors), point
// insertion and removal, and the comparison with CGAL's Periodic_4_hyperbolic_Delaunay_triangulation_2 on the
// Bolza surface (the Delaunay triangulation of a point set on a surface is unique; for degenerate sets the
// Delaunay decomposition is, so the multisets of circumradii and of strictly Delaunay edges are).
#include "test_support.h"

#include <CGAL/Hyperbolic_octagon_translation.h>
#include <CGAL/Periodic_4_hyperbolic_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_4_hyperbolic_Delaunay_triangulation_traits_2.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <vector>

using namespace hsm2_test;
typedef HSM::Delaunay_triangulation_on_surface<>::Geometry Geometry;

typedef CGAL::Periodic_4_hyperbolic_Delaunay_triangulation_traits_2<> P4Traits;
typedef CGAL::Periodic_4_hyperbolic_Delaunay_triangulation_2<P4Traits> P4T;
typedef P4Traits::Point_2 P4Point;

namespace {

Point to_double(const P4Point& p) { return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

struct Summary
{
  std::size_t v = 0, e = 0, f = 0;
  std::vector<double> edge_lengths, strict_edge_lengths, circumradii;
};

double circumradius(const Point& a, const Point& b, const Point& c)
{
  const CGAL::Poincare_disk_traits_2<K> gt;
  const Point o = gt.construct_hyperbolic_circumcenter_2_object()(a, b, c);
  return Geometry::distance(o, a);
}

Summary summarize(const P4T& t)
{
  Summary s;
  s.v = t.number_of_vertices(); s.e = t.number_of_edges(); s.f = t.number_of_faces();
  for(auto e = t.edges_begin(); e != t.edges_end(); ++e) {
    auto f = e->first; const int i = e->second;
    const Point p = to_double(t.construct_point(f->vertex((i + 1) % 3)->point(), f->translation((i + 1) % 3)));
    const Point q = to_double(t.construct_point(f->vertex((i + 2) % 3)->point(), f->translation((i + 2) % 3)));
    s.edge_lengths.push_back(Geometry::distance(p, q));
  }
  for(auto f = t.faces_begin(); f != t.faces_end(); ++f) {
    Point z[3];
    for(int k = 0; k < 3; ++k) z[k] = to_double(t.construct_point(f->vertex(k)->point(), f->translation(k)));
    s.circumradii.push_back(circumradius(z[0], z[1], z[2]));
  }
  return s;
}

Summary summarize(const DT& t)
{
  Summary s;
  s.v = t.number_of_vertices(); s.e = t.number_of_edges(); s.f = t.number_of_faces();
  const CGAL::Poincare_disk_traits_2<K> gt;
  for(std::size_t f : t.faces()) {
    const auto& z = t.lift(f);
    s.circumradii.push_back(circumradius(z[0], z[1], z[2]));
    for(int i = 0; i < 3; ++i) {
      const std::size_t g = t.neighbor(f, i);
      if(!(f < g || (f == g && i < t.mirror_index(f, i)))) continue;
      s.edge_lengths.push_back(t.edge_length(f, i));
      const Point d = t.neighbor_apex(f, i);
      if(gt.side_of_oriented_circle_2_object()(z[i], z[(i + 1) % 3], z[(i + 2) % 3], d) == CGAL::ON_NEGATIVE_SIDE)
        s.strict_edge_lengths.push_back(t.edge_length(f, i));
    }
  }
  return s;
}

bool same_multiset(std::vector<double> a, std::vector<double> b, double tol, double* worst)
{
  if(a.size() != b.size()) return false;
  std::sort(a.begin(), a.end()); std::sort(b.begin(), b.end());
  *worst = 0;
  for(std::size_t i = 0; i < a.size(); ++i) *worst = (std::max)(*worst, std::abs(a[i] - b[i]));
  return *worst <= tol;
}

/// Inserts the points into P4HT2 (it rejects points outside its half-open octagon) and the accepted ones
/// into a triangulation of the Bolza polygon; P4HT2's remaining dummy points are inserted into ours too, and
/// our polygon vertex is removed. Compares counts, edge lengths (all, or only the unique ones when
/// `degenerate`) and circumradii.
void compare_with_P4HT2(const std::vector<Point>& pts, bool degenerate)
{
  P4T p4;
  std::vector<Point> accepted;
  for(const Point& p : pts)
    if(p4.insert(P4Point(p.x(), p.y())) != P4T::Vertex_handle()) accepted.push_back(p);
  p4.try_to_remove_dummy_vertices();
  CGAL_HC_CHECK(p4.is_valid());
  DT t(Polygon::Bolza());
  const std::size_t polygon_vertex = t.vertices().front();
  for(const Point& p : accepted) t.insert_in_frame(p);
  std::size_t dummies = 0;
  for(auto v = p4.vertices_begin(); v != p4.vertices_end(); ++v)
    if(p4.is_dummy_vertex(v)) {
      // P4HT2 recognizes dummies by their coordinates: an inserted point equal to a dummy point is reported too
      const Point q = to_double(v->point());
      if(std::find(accepted.begin(), accepted.end(), q) != accepted.end()) continue;
      t.insert_in_frame(q); ++dummies;
    }
  const bool removed = t.remove(polygon_vertex);
  CGAL_HC_CHECK_MSG(removed, "the polygon vertex could not be removed");
  check_triangulation(t, 2, !degenerate);
  if(degenerate) check_delaunay_up_to_rounding(t);
  const Summary a = summarize(p4), b = summarize(t);
  CGAL_HC_CHECK_MSG(a.v == b.v && a.e == b.e && a.f == b.f,
                    "P4HT2 " << a.v << "/" << a.e << "/" << a.f << " vs " << b.v << "/" << b.e << "/" << b.f
                    << " (" << p4.number_of_dummy_points() << " dummies left, " << dummies << " dummy vertices, "
                    << accepted.size() << " points)");
  double worst = 0;
  // (the circumcentre of a thin triangle of a cocircular cell is ill-conditioned: 1e-6 for degenerate sets)
  CGAL_HC_CHECK_MSG(same_multiset(a.circumradii, b.circumradii, degenerate ? 1e-6 : 1e-9, &worst),
                    "circumradii differ by " << worst);
  if(!degenerate) {
    CGAL_HC_CHECK_MSG(same_multiset(a.edge_lengths, b.edge_lengths, 1e-9, &worst), "edge lengths differ by " << worst);
    CGAL_HC_CHECK_MSG(b.strict_edge_lengths.size() == b.edge_lengths.size(), "a random set has cocircular points");
  }
}

} // namespace

CGAL_HC_TEST_CASE(polygon_checks)
{
  const Polygon bolza = Polygon::Bolza();
  CGAL_HC_CHECK(bolza.genus() == 2 && bolza.number_of_vertex_cycles() == 1);
  CGAL_HC_CHECK(std::abs(bolza.area() - 4 * CGAL_PI) < 1e-12);
  // the side pairing of the Bolza octagon: |trace| = 2 + 2 sqrt 2 (DESIGN.md), and it maps side j onto side i
  for(std::size_t i = 0; i < 8; ++i) {
    const auto g = bolza.side_pairing(i);
    CGAL_HC_CHECK(std::abs(2 * g.half_trace() - (2 + 2 * std::sqrt(2.0))) < 1e-12);
    const std::size_t j = std::size_t(bolza.paired_side(i));
    CGAL_HC_CHECK(Geometry::distance(g.apply_unchecked(bolza.vertex(j)), bolza.vertex(i + 1)) < 1e-12);
    CGAL_HC_CHECK(Geometry::distance(g.apply_unchecked(bolza.vertex(j + 1)), bolza.vertex(i)) < 1e-12);
  }
  for(int g = 2; g <= 6; ++g) {
    const Polygon p = Polygon::regular(g);
    CGAL_HC_CHECK(p.genus() == g && p.number_of_vertex_cycles() == 1);
    CGAL_HC_CHECK(std::abs(p.area() - 4 * CGAL_PI * (g - 1)) < 1e-9);
  }
  CGAL_HC_CHECK_THROWS(Polygon::regular(1), CGAL::Invalid_input_error);
  std::vector<Point> w = bolza.vertices();
  std::vector<int> pairing{4, 5, 6, 7, 0, 1, 2, 3};
  // a scaled octagon: paired sides still equal, but the angle sum is not 2 pi (the pairings do not close up)
  std::vector<Point> small;
  for(const Point& p : w) small.push_back(Point(0.9 * p.x(), 0.9 * p.y()));
  CGAL_HC_CHECK_THROWS(Polygon(small, pairing), CGAL::Invalid_metric_error);
  // a perturbed vertex: paired sides of different lengths
  std::vector<Point> bad = w; bad[1] = Point(0.99 * w[1].x(), w[1].y());
  CGAL_HC_CHECK_THROWS(Polygon(bad, pairing), CGAL::Invalid_metric_error);
  // not an involution / fixed point
  CGAL_HC_CHECK_THROWS(Polygon(w, std::vector<int>{4, 5, 6, 7, 0, 1, 3, 2}), CGAL::Invalid_input_error);
  CGAL_HC_CHECK_THROWS(Polygon(w, std::vector<int>{0, 5, 6, 7, 4, 1, 2, 3}), CGAL::Invalid_input_error);
  // adjacent sides glued (a b b^-1 ...): genus drops
  CGAL_HC_CHECK_THROWS(Polygon(w, std::vector<int>{1, 0, 3, 2, 5, 4, 7, 6}), CGAL::Invalid_input_error);
  // a point outside the disk, a non-convex (clockwise) polygon
  std::vector<Point> out = w; out[3] = Point(1.2, 0.0);
  CGAL_HC_CHECK_THROWS(Polygon(out, pairing), CGAL::Poincare_disk_domain_error);
  std::vector<Point> cw(w.rbegin(), w.rend());
  CGAL_HC_CHECK_THROWS(Polygon(cw, pairing), CGAL::Invalid_input_error);
  // a square with opposite sides glued is a torus: genus 1
  std::vector<Point> sq{Point(0.5, 0.5), Point(-0.5, 0.5), Point(-0.5, -0.5), Point(0.5, -0.5)};
  CGAL_HC_CHECK_THROWS(Polygon(sq, std::vector<int>{2, 3, 0, 1}), CGAL::Invalid_mesh_error);
}

CGAL_HC_TEST_CASE(polygon_triangulations)
{
  for(int g = 2; g <= 5; ++g) {
    DT t(Polygon::regular(g));
    CGAL_HC_CHECK(t.number_of_vertices() == 1 && t.genus() == g);
    check_triangulation(t, g, false); // one vertex: the 4g lifts around the centre are cocircular
    check_delaunay_up_to_rounding(t);
    CGAL_HC_CHECK(!t.is_simplicial_complex());
    // random points of the polygon's frame, anywhere in the disk (lifts are located across the pairings)
    CGAL::Random rng(g);
    for(int k = 0; k < 300; ++k) {
      const double r = 0.95 * std::sqrt(rng.get_double()), a = rng.get_double(0, 2 * CGAL_PI);
      t.insert_in_frame(Point(r * std::cos(a), r * std::sin(a)));
    }
    check_triangulation(t, g);
    CGAL_HC_CHECK(t.number_of_vertices() == 301);
    CGAL_HC_CHECK(t.is_simplicial_complex());
    // the same point again (a lift under a side pairing) adds no vertex
    const std::size_t nv = t.number_of_vertices();
    t.insert_in_frame(Point(0.1, 0.2));
    t.insert_in_frame(Point(0.1, 0.2));
    CGAL_HC_CHECK(t.number_of_vertices() == nv + 1);
  }
  DT t(Polygon::Bolza());
  CGAL_HC_CHECK_THROWS(t.insert_in_frame(Point(1.0, 0.0)), CGAL::Poincare_disk_domain_error);
  CGAL_HC_CHECK_THROWS(t.insert_in_frame(Point(std::nan(""), 0.0)), CGAL::Poincare_disk_domain_error);
  // inside the disk, maybe beyond what double can reduce into the domain (found by the fuzzer on the genus-3
  // polygon: an Invalid_input_error from an overflowing isometry): inserted, or Numerical_error
  for(int genus = 2; genus <= 4; ++genus) {
    DT u(genus == 2 ? Polygon::Bolza() : Polygon::regular(genus));
    std::size_t refused = 0;
    for(const Point& q : {Point(0.99999999999999989, 0.0), Point(0.0, -(1 - 1e-13)), Point(-(1 - 1e-11), 0.0),
                          Point(0.6, 0.8 * (1 - 1e-12))}) {
      try { u.insert_in_frame(q); } catch(const CGAL::Numerical_error&) { ++refused; }
      std::string why;
      CGAL_HC_CHECK_MSG(u.is_valid(&why), why);
      CGAL_HC_CHECK(u.euler_characteristic() == 2 - 2 * genus);
    }
    std::cout << "  genus " << genus << ": " << refused << " of 4 points within 1e-11 of the circle refused\n";
  }
  CGAL_HC_CHECK(!t.remove(t.vertices().front())); // the only vertex
}

CGAL_HC_TEST_CASE(removal)
{
  DT t(Polygon::Bolza());
  CGAL::Random rng(7);
  std::vector<std::size_t> vs;
  for(int k = 0; k < 200; ++k) vs.push_back(t.insert_in_frame(Point(rng.get_double(-0.6, 0.6), rng.get_double(-0.6, 0.6))));
  std::size_t removed = 0;
  for(std::size_t i = 0; i < vs.size(); i += 3) removed += t.remove(vs[i]) ? 1 : 0;
  CGAL_HC_CHECK(removed == (vs.size() + 2) / 3);
  check_triangulation(t, 2);
  CGAL_HC_CHECK(t.number_of_vertices() == 201 - removed);
}

// Clusters of points 1e-16 to 1e-8 apart (near the origin, in the middle, next to a polygon corner), some given
// several times, then removals and a refinement. Found by fuzz_surface_mesher (genus 3, points about 1.8e-6 from
// the origin 1e-15 to 1e-10 apart): the same point given again became a new vertex (the duplicate test was only
// relative to the tiny edges), and a removal then folded a recentred chart ("a chart is not counterclockwise").
CGAL_HC_TEST_CASE(clustered_points_removal_and_refinement)
{
  CGAL::Random rng(11);
  for(int genus = 2; genus <= 4; ++genus) {
    const Polygon P = Polygon::regular(genus);
    const Point corner = P.vertex(0);
    const Point centres[3] = {Point(-1.8325506472120096e-06, -1.8325506472120096e-06), Point(0.21, -0.13),
                              Point(corner.x() * (1 - 1e-3), corner.y() * (1 - 1e-3))};
    for(const Point& c : centres) {
      const bool near_corner = &c == &centres[2]; // (see the manual's limitations: chart drift near the corners)
      DT t(P);
      std::vector<std::size_t> vs;
      std::vector<Point> given;
      std::vector<bool> fresh;
      for(int k = 0; k < 60; ++k) {
        Point p = c;
        if(k < 8) // a ring of radius 1e-3 first: small faces, so that the relative duplicate test is small too
          p = Point(c.x() + 1e-3 * std::cos(k * CGAL_PI / 4), c.y() + 1e-3 * std::sin(k * CGAL_PI / 4));
        else if(k % 4 != 0) {
          const double step = std::pow(10.0, -rng.get_double(8, 16));
          p = Point(c.x() + step * rng.get_int(-3, 4), c.y() + step * rng.get_int(-3, 4));
        } else
          p = given[rng.get_int(0, int(given.size()))]; // the same point again
        const std::size_t nv = t.number_of_vertices();
        const std::size_t v = t.insert_in_frame(p);
        // a point that made a vertex is that vertex when given again (a point that snapped to a vertex may snap
        // to a nearer one inserted later)
        for(std::size_t q = 0; q < given.size(); ++q)
          if(given[q] == p && fresh[q] && !near_corner) CGAL_HC_CHECK_MSG(v == vs[q], "a point given twice gave two vertices");
        fresh.push_back(t.number_of_vertices() == nv + 1);
        given.push_back(p); vs.push_back(v);
        std::string why;
        CGAL_HC_CHECK_MSG(t.is_valid(&why), why);
      }
      for(std::size_t i = 0; i < vs.size(); i += 3)
        if(vs[i] != DT::null_index && t.is_vertex(vs[i])) {
          t.remove(vs[i]);
          std::string why;
          CGAL_HC_CHECK_MSG(t.is_valid(&why), why << " after removing vertex " << vs[i]);
        }
      // the angles of a needle are as accurate as its vertices' positions (rounded to about 1e-16 in the charts,
      // to about 1e-14 through the frame near the polygon's corners) over its shortest edge
      double shortest = 1;
      for(std::size_t f : t.faces()) for(int i = 0; i < 3; ++i) shortest = (std::min)(shortest, t.edge_length(f, i));
      const double angle_tol = near_corner ? 1.0 : (std::max)(1e-7, 1e-14 / shortest);
      std::cout << "  genus " << genus << " cluster at " << c << ": " << t.number_of_vertices()
                << " vertices, shortest edge " << shortest << ", angle-sum tolerance " << angle_tol << "\n";
      check_triangulation(t, genus, true, angle_tol);
      const auto st = HSM::refine_Chew(t, HSMP::maximum_circumradius(0.76, HSMP::maximum_number_of_insertions(20000)));
      CGAL_HC_CHECK_MSG(st.status == HSM::Refinement_status::SUCCESS, st);
      check_triangulation(t, genus, true, angle_tol);
    }
  }
}

CGAL_HC_TEST_CASE(bolza_against_P4HT2_random)
{
  for(unsigned seed : {1u, 2u, 3u}) {
    for(std::size_t n : {30, 200, 1000}) {
      CGAL::Random rng(seed * 1000 + unsigned(n));
      std::vector<Point> pts;
      while(pts.size() < n) {
        const double x = rng.get_double(-0.85, 0.85), y = rng.get_double(-0.85, 0.85);
        if(x * x + y * y < 0.85 * 0.85) pts.push_back(Point(x, y));
      }
      compare_with_P4HT2(pts, false);
    }
  }
}

CGAL_HC_TEST_CASE(range_insertion)
{
  // the range insertion (Hilbert order, located from the previous vertex) gives the same triangulation as
  // one-by-one insertion (unique for random points): same sorted edge lengths
  CGAL::Random rng(5);
  std::vector<Point> pts;
  for(int k = 0; k < 2000; ++k) pts.push_back(Point(rng.get_double(-0.6, 0.6), rng.get_double(-0.6, 0.6)));
  DT a(Polygon::Bolza()), b(Polygon::Bolza());
  for(const Point& p : pts) a.insert_in_frame(p);
  CGAL_HC_CHECK(b.insert_in_frame(pts.begin(), pts.end()) == pts.size());
  check_triangulation(b, 2);
  double worst = 0;
  CGAL_HC_CHECK_MSG(same_multiset(summarize(a).edge_lengths, summarize(b).edge_lengths, 1e-9, &worst), worst);
  std::vector<Point> bad{Point(0, 0), Point(2, 0)};
  CGAL_HC_CHECK_THROWS(b.insert_in_frame(bad.begin(), bad.end()), CGAL::Poincare_disk_domain_error);
  CGAL_HC_CHECK(b.number_of_vertices() == pts.size() + 1); // nothing inserted
}

CGAL_HC_TEST_CASE(bolza_against_P4HT2_degenerate)
{
  // symmetric sets: the origin and regular n-gons around it (cocircular points), under the octagon's
  // 8-fold symmetry
  for(int n : {4, 8, 16}) {
    std::vector<Point> pts{Point(0, 0)};
    for(double r : {0.2, 0.45, 0.7})
      for(int k = 0; k < n; ++k) pts.push_back(Point(r * std::cos(2 * CGAL_PI * k / n), r * std::sin(2 * CGAL_PI * k / n)));
    compare_with_P4HT2(pts, true);
  }
  // a square grid (many cocircular quadruples)
  std::vector<Point> grid;
  for(int i = -6; i <= 6; ++i) for(int j = -6; j <= 6; ++j) grid.push_back(Point(0.1 * i, 0.1 * j));
  compare_with_P4HT2(grid, true);
}

CGAL_HC_TEST_CASE(points_near_the_circle_at_infinity_and_high_genus)
{
  // lifts far from the fundamental polygon (hyperbolic distance up to 7.6 from the origin) are located across
  // many side pairings; the charts stay near the origin
  for(int g : {2, 8}) {
    DT t(Polygon::regular(g));
    CGAL::Random rng(g + 100);
    for(int k = 0; k < 200; ++k) {
      const double r = 1 - std::pow(10.0, -rng.get_double(1, 3)), a = rng.get_double(0, 2 * CGAL_PI);
      t.insert_in_frame(Point(r * std::cos(a), r * std::sin(a)));
    }
    check_triangulation(t, g, true, 1e-6);
    CGAL_HC_CHECK_MSG(t.number_of_vertices() == 201, t.number_of_vertices());
    double far = 0;
    for(std::size_t f : t.faces()) for(const Point& z : t.lift(f)) far = (std::max)(far, DT::Geometry::distance_to_origin(z));
    CGAL_HC_CHECK_MSG(far < 12, "a chart point at distance " << far);
  }
  // a refinement of a genus-8 surface
  DT t(Polygon::regular(8));
  const auto st = CGAL::Hyperbolic_surface_mesh_2::refine_Chew(t, CGAL::Hyperbolic_surface_mesh_2::parameters::maximum_circumradius(0.3));
  CGAL_HC_CHECK(st.status == CGAL::Hyperbolic_surface_mesh_2::Refinement_status::SUCCESS && st.simplicial_complex);
  check_triangulation(t, 8);
}
