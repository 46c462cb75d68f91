// Feature loops: the sides of a fundamental polygon as constrained edges (closed geodesic loops on the
// surface). After refinement every side is a chain of output edges (the lengths of the constrained edges on
// each side of the frame add up to the side length), the polygon is a union of output faces, and every other
// output check holds (locally Delaunay away from the constraints, angle sums, area, criteria, simplicial, Euler).
#include "test_support.h"

#include <CGAL/Random.h>

using namespace hsm2_test;

namespace {

/// Klein images of the polygon's vertices, and the side of the polygon that the segment xy (frame) lies on,
/// or -1 (both ends on the side's Klein line up to `tol`, between its ends)
int side_of(const Polygon& P, const Point& x, const Point& y, double tol)
{
  const Point kx = DT::Geometry::to_klein(x), ky = DT::Geometry::to_klein(y);
  for(std::size_t s = 0; s < P.size(); ++s) {
    const Point a = DT::Geometry::to_klein(P.vertex(s)), b = DT::Geometry::to_klein(P.vertex(s + 1));
    const double ex = b.x() - a.x(), ey = b.y() - a.y(), l2 = ex * ex + ey * ey;
    bool on = true;
    for(const Point& k : {kx, ky}) {
      const double cr = (ex * (k.y() - a.y()) - ey * (k.x() - a.x())) / std::sqrt(l2);
      const double t = (ex * (k.x() - a.x()) + ey * (k.y() - a.y())) / l2;
      if(!(std::abs(cr) < tol && t > -tol && t < 1 + tol)) on = false;
    }
    if(on) return int(s);
  }
  return -1;
}

void check_features(const Polygon& P, const DT& t, int genus, double eps, double alpha, const HSM::Refinement_statistics& st)
{
  CGAL_HC_CHECK_MSG(st.status == HSM::Refinement_status::SUCCESS, st);
  // the regular polygons' side midpoints make exactly cocircular quadrilaterals: every unconstrained edge is
  // locally Delaunay up to the rounding of its lifts (constrained edges count as Delaunay)
  check_triangulation(t, genus, /*require_delaunay*/ false);
  check_delaunay_up_to_rounding(t);
  CGAL_HC_CHECK(t.is_simplicial_complex() && st.simplicial_complex && st.euler_characteristic == 2 - 2 * genus);
  CGAL_HC_CHECK(st.faces_failing_criteria == 0 && st.segment_splits > 0);
  const CGAL::Poincare_disk_traits_2<K> gt;
  const double c = std::cosh(eps), s = std::sin(alpha / 2);
  std::size_t poor = 0, stray = 0, outside = 0, constrained = 0;
  std::vector<double> covered(P.size(), 0.0);
  for(std::size_t f : t.faces()) {
    const auto& z = t.lift(f);
    if(gt.compare_hyperbolic_circumradius_2_object()(z[0], z[1], z[2], c * c) == CGAL::LARGER ||
       gt.compare_central_angle_2_object()(z[0], z[1], z[2], s * s) == CGAL::SMALLER) ++poor;
    const auto m = t.to_frame(f);
    // the face lies in the polygon (its barycentre strictly, its corners up to rounding)
    const Point b = m.apply_unchecked(Point(0, 0));
    for(std::size_t k = 0; k < P.size(); ++k)
      if(gt.orientation_2_object()(P.vertex(k), P.vertex(k + 1), b) != CGAL::LEFT_TURN) { ++outside; break; }
    for(int i = 0; i < 3; ++i) {
      if(!t.is_constrained(f, i)) continue;
      ++constrained;
      const int side = side_of(P, m.apply_unchecked(z[i]), m.apply_unchecked(z[(i + 1) % 3]), 1e-9);
      if(side < 0) { ++stray; continue; }
      covered[side] += t.edge_length(f, i);
    }
  }
  CGAL_HC_CHECK_MSG(poor == 0 && stray == 0 && outside == 0,
                    poor << " poor, " << stray << " constrained edges off the sides, " << outside << " faces outside the polygon");
  CGAL_HC_CHECK(constrained == 2 * t.number_of_constrained_edges());
  double worst = 0;
  for(std::size_t k = 0; k < P.size(); ++k) {
    const double len = DT::Geometry::distance(P.vertex(k), P.vertex(k + 1));
    worst = (std::max)(worst, std::abs(covered[k] - len) / len);
  }
  CGAL_HC_CHECK_MSG(worst < 1e-9, "a side is not covered by its chain of constrained edges: relative error " << worst);
}

} // namespace

CGAL_HC_TEST_CASE(feature_loops_polygon_sides)
{
  // the configurations that terminate (Ruppert, alpha = 20 degrees; the corners have 45 degrees for g = 2
  // and 30 for g = 3)
  struct Run { int g; double eps; };
  for(const Run& r : {Run{2, 0.5}, Run{2, 0.2}, Run{2, 0.1}, Run{3, 0.5}, Run{3, 0.2}, Run{3, 0.1}}) {
    const Polygon P = Polygon::regular(r.g);
    DT t(P, true);
    CGAL_HC_CHECK(t.number_of_constrained_edges() == 2 * std::size_t(r.g)); // 4g sides glued in pairs
    const double alpha = 20 * CGAL_PI / 180;
    const auto st = HSM::refine_Ruppert(t, HSMP::maximum_circumradius(r.eps, HSMP::minimum_central_angle(alpha)));
    check_features(P, t, r.g, r.eps, alpha, st);
    // the constraints survive removals of unconstrained vertices
    const std::size_t nc = t.number_of_constrained_edges();
    std::size_t removed = 0;
    for(std::size_t v : t.vertices()) { if(removed >= 20) break; if(t.remove(v)) ++removed; }
    CGAL_HC_CHECK_MSG(removed > 0 && t.number_of_constrained_edges() == nc, removed << " removed");
    std::string why;
    CGAL_HC_CHECK_MSG(t.is_valid(&why), why);
    check_delaunay_up_to_rounding(t);
  }
}

CGAL_HC_TEST_CASE(feature_loops_Chew_within_the_work_bound)
{
  // Chew (central angles of about 60 degrees) at the 45-degree corners of the Bolza octagon: it either meets
  // the criteria (then every check) or the work bound stops it with that status; the triangulation is valid
  // and the sides are chains of edges in both cases
  const Polygon P = Polygon::regular(2);
  DT t(P, true);
  const auto st = HSM::refine_Chew(t, HSMP::maximum_circumradius(0.3, HSMP::maximum_number_of_insertions(3000)));
  std::cout << "  Chew with the octagon's sides as features: " << HSM::to_string(st.status) << ", "
            << st.final_vertices << " vertices" << std::endl;
  if(st.status == HSM::Refinement_status::SUCCESS) {
    check_features(P, t, 2, 0.3, CGAL::Hyperbolic_mesh_2::theta_star(0.3) * 0.999, st);
    return;
  }
  CGAL_HC_CHECK(st.status == HSM::Refinement_status::WORK_BOUND_REACHED);
  check_triangulation(t, 2, false);
  check_delaunay_up_to_rounding(t);
  std::vector<double> covered(P.size(), 0.0);
  std::size_t stray = 0;
  for(std::size_t f : t.faces())
    for(int i = 0; i < 3; ++i) {
      if(!t.is_constrained(f, i)) continue;
      const auto m = t.to_frame(f);
      const int side = side_of(P, m.apply_unchecked(t.lift(f)[i]), m.apply_unchecked(t.lift(f)[(i + 1) % 3]), 1e-9);
      if(side < 0) ++stray; else covered[side] += t.edge_length(f, i);
    }
  CGAL_HC_CHECK(stray == 0);
  for(std::size_t k = 0; k < P.size(); ++k)
    CGAL_HC_CHECK(std::abs(covered[k] - DT::Geometry::distance(P.vertex(k), P.vertex(k + 1))) < 1e-9);
}

namespace {

/// the geodesic segments of the feature loops (frame), for the coverage checks
struct Loop_segments
{
  std::vector<std::pair<Point, Point> > seg;
  double length = 0;
  void add(const std::vector<Point>& lift)
  {
    for(std::size_t k = 0; k + 1 < lift.size(); ++k) {
      seg.emplace_back(lift[k], lift[k + 1]);
      length += DT::Geometry::distance(lift[k], lift[k + 1]);
    }
  }
};

/// true if the frame segment xy lies on segment ab (Klein line, between its ends, up to `tol`)
bool on_segment(const Point& a, const Point& b, const Point& x, const Point& y, double tol)
{
  const Point ka = DT::Geometry::to_klein(a), kb = DT::Geometry::to_klein(b);
  const double ex = kb.x() - ka.x(), ey = kb.y() - ka.y(), l2 = ex * ex + ey * ey;
  for(const Point& p : {x, y}) {
    const Point k = DT::Geometry::to_klein(p);
    const double cr = (ex * (k.y() - ka.y()) - ey * (k.x() - ka.x())) / std::sqrt(l2);
    const double t = (ex * (k.x() - ka.x()) + ey * (k.y() - ka.y())) / l2;
    if(!(std::abs(cr) < tol && t > -tol && t < 1 + tol)) return false;
  }
  return true;
}

/// Every constrained edge lies on a segment of the loops or on its image under a side pairing (the frame of
/// a face near a side may be the copy across it), and the constrained edges add up to the loops' length.
void check_loop_coverage(const Polygon& P, const DT& t, const Loop_segments& L)
{
  // (the identity, the side pairings and their products of two: faces near a polygon vertex)
  std::vector<DT::Isometry_2> images(1, DT::Isometry_2());
  for(std::size_t s = 0; s < P.size(); ++s) images.push_back(P.side_pairing(s));
  for(std::size_t s = 0; s < P.size(); ++s)
    for(std::size_t r = 0; r < P.size(); ++r) images.push_back(P.side_pairing(s) * P.side_pairing(r));
  double total = 0;
  std::size_t stray = 0, constrained = 0;
  for(std::size_t f : t.faces())
    for(int i = 0; i < 3; ++i) {
      if(!t.is_constrained(f, i)) continue;
      ++constrained;
      const auto m = t.to_frame(f);
      const Point x = m.apply_unchecked(t.lift(f)[i]), y = m.apply_unchecked(t.lift(f)[(i + 1) % 3]);
      bool on = false;
      // (tolerance on the Klein distance to the segment: 1e-9 in the frame itself; the images under pairings
      // leave the frame, whose coordinates there lose digits: genus 3 edges measured 3e-11 to 3e-10 off the image
      // under one pairing, so 1e-8 there and 1e-7 for products of two pairings)
      for(std::size_t k = 0; k < images.size() && !on; ++k)
        for(const auto& s : L.seg)
          if(!on && on_segment(images[k].apply_unchecked(s.first), images[k].apply_unchecked(s.second), x, y,
                               k == 0 ? 1e-9 : (k <= P.size() ? 1e-8 : 1e-7))) on = true;
      if(!on) ++stray;
      total += t.edge_length(f, i);
    }
  total /= 2; // each constrained edge from both sides
  CGAL_HC_CHECK_MSG(stray == 0, stray << " constrained edge sides off the loops");
  CGAL_HC_CHECK(constrained == 2 * t.number_of_constrained_edges());
  CGAL_HC_CHECK_MSG(std::abs(total - L.length) < 1e-9 * L.length,
                    "the constrained edges add up to " << total << ", the loops to " << L.length);
}

/// the quality checks of a refinement with feature loops that ended with SUCCESS
void check_refined_with_loops(const DT& t, int genus, double eps, double alpha, const HSM::Refinement_statistics& st)
{
  CGAL_HC_CHECK_MSG(st.status == HSM::Refinement_status::SUCCESS, st);
  check_triangulation(t, genus, /*require_delaunay*/ false);
  check_delaunay_up_to_rounding(t); // constrained edges count as Delaunay; cocircular sets up to rounding
  CGAL_HC_CHECK(t.is_simplicial_complex() && st.simplicial_complex && st.euler_characteristic == 2 - 2 * genus);
  CGAL_HC_CHECK(long(t.number_of_vertices()) - long(t.number_of_edges()) + long(t.number_of_faces()) == 2 - 2 * genus);
  const CGAL::Poincare_disk_traits_2<K> gt;
  const double c = std::cosh(eps), s = std::sin(alpha / 2);
  std::size_t poor = 0;
  for(std::size_t f : t.faces()) {
    const auto& z = t.lift(f);
    if(gt.compare_hyperbolic_circumradius_2_object()(z[0], z[1], z[2], c * c) == CGAL::LARGER ||
       gt.compare_central_angle_2_object()(z[0], z[1], z[2], s * s) == CGAL::SMALLER) ++poor;
  }
  CGAL_HC_CHECK_MSG(poor == 0 && st.faces_failing_criteria == 0, poor << " faces fail the criteria");
}

/// the 2g closed geodesics through the midpoints of paired sides of the regular 4g-gon (the axes of its side
/// pairings, all through the origin): as 2-point lifts [m_i, m_{i+2g}] for even i (their crossings at the
/// origin are found by the insertion) and 3-point lifts [m_i, 0, m_{i+2g}] for odd i
std::vector<std::vector<Point> > axis_loops(const Polygon& P, int g)
{
  const CGAL::Poincare_disk_traits_2<K> gt;
  auto mid = [&](std::size_t i) { return gt.construct_hyperbolic_midpoint_2_object()(P.vertex(i), P.vertex(i + 1)); };
  std::vector<std::vector<Point> > r;
  for(int i = 0; i < 2 * g; ++i) {
    if(i % 2 == 0) r.push_back({mid(i), mid(i + 2 * g)});
    else r.push_back({mid(i), Point(0, 0), mid(i + 2 * g)});
  }
  return r;
}

/// a closed geodesic 12-gon inscribed in the hyperbolic circle of radius rho about c (frame), as a lift p_12 = p_0
std::vector<Point> circle_loop(const Point& c, double rho)
{
  const auto to_c = DT::Isometry_2::translation_from_origin(c);
  std::vector<Point> r;
  const double e = std::tanh(rho / 2);
  for(int k = 0; k <= 12; ++k) {
    const double a = 2 * CGAL_PI * (k % 12) / 12 + 0.1;
    r.push_back(to_c.apply_unchecked(Point(e * std::cos(a), e * std::sin(a))));
  }
  return r;
}

} // namespace

CGAL_HC_TEST_CASE(feature_loops_closed_geodesics_and_crossing_loops)
{
  // genus 2 and 3: the 2g axes (closed geodesics crossing at the origin at 45 / 30 degrees), then a geodesic
  // 12-gon about the midpoint of side 0 that crosses side 0 (its lift leaves the frame) and crosses axis 0
  // twice on the surface; Ruppert with alpha = 20 degrees
  struct Run { int g; double eps; };
  for(const Run& r : {Run{2, 0.3}, Run{2, 0.15}, Run{3, 0.3}, Run{3, 0.15}}) {
    const Polygon P = Polygon::regular(r.g);
    DT t(P);
    Loop_segments L;
    std::size_t crossings = 0;
    for(const auto& loop : axis_loops(P, r.g)) {
      const auto res = t.insert_feature_loop(loop);
      CGAL_HC_CHECK(res.complete);
      crossings += res.crossings;
      L.add(loop);
    }
    const CGAL::Poincare_disk_traits_2<K> gt;
    const Point m0 = gt.construct_hyperbolic_midpoint_2_object()(P.vertex(0), P.vertex(1));
    const std::vector<Point> circle = circle_loop(m0, 0.35);
    const auto res = t.insert_feature_loop(circle);
    CGAL_HC_CHECK(res.complete);
    CGAL_HC_CHECK_MSG(res.crossings + crossings >= 2, res.crossings << " crossings of the circle");
    L.add(circle);
    std::string why;
    CGAL_HC_CHECK_MSG(t.is_valid(&why), why);
    check_loop_coverage(P, t, L); // before the refinement
    const double alpha = 20 * CGAL_PI / 180;
    const auto st = HSM::refine_Ruppert(t, HSMP::maximum_circumradius(r.eps, HSMP::minimum_central_angle(alpha)));
    std::cout << "  genus " << r.g << " epsilon " << r.eps << ": " << 2 * r.g << " axes and a 12-gon, "
              << crossings + res.crossings << " crossings inserted, " << t.number_of_constrained_edges()
              << " constrained edges, " << HSM::to_string(st.status) << ", " << st.final_vertices << " vertices" << std::endl;
    check_refined_with_loops(t, r.g, r.eps, alpha, st);
    check_loop_coverage(P, t, L); // after: every split kept the chain on the loops
  }
}

CGAL_HC_TEST_CASE(feature_loops_bad_input_work_bound_and_Chew)
{
  const Polygon P = Polygon::regular(2);
  DT t(P);
  const std::size_t nv = t.number_of_vertices();
  const CGAL::Poincare_disk_traits_2<K> gt;
  const Point m0 = gt.construct_hyperbolic_midpoint_2_object()(P.vertex(0), P.vertex(1));
  // the last point is not a lift of the first: Invalid_path_error, the vertex set is unchanged
  const std::vector<Point> open_loop{m0, Point(0.1, 0)}, one_point{m0}, repeated{m0, m0, m0}, outside{m0, Point(1.5, 0), m0};
  CGAL_HC_CHECK_THROWS(t.insert_feature_loop(open_loop), CGAL::Invalid_path_error);
  CGAL_HC_CHECK(t.number_of_vertices() == nv);
  CGAL_HC_CHECK_THROWS(t.insert_feature_loop(one_point), CGAL::Invalid_path_error);
  CGAL_HC_CHECK_THROWS(t.insert_feature_loop(repeated), CGAL::Invalid_path_error);
  CGAL_HC_CHECK_THROWS(t.insert_feature_loop(outside), CGAL::Poincare_disk_domain_error);
  CGAL_HC_CHECK(t.number_of_vertices() == nv);
  // the work bound: a loop that needs splits (among 300 points) stops with complete = false and a valid
  // triangulation
  CGAL::Random rng(7);
  std::vector<Point> cloud;
  while(cloud.size() < 300) { const Point p(rng.get_double(-0.6, 0.6), rng.get_double(-0.6, 0.6)); if(p.x() * p.x() + p.y() * p.y() < 0.36) cloud.push_back(p); }
  t.insert_in_frame(cloud.begin(), cloud.end());
  const auto res = t.insert_feature_loop(circle_loop(Point(0.1, 0.05), 0.4), 0);
  CGAL_HC_CHECK(!res.complete);
  std::string why;
  CGAL_HC_CHECK_MSG(t.is_valid(&why), why);
  // Chew with a contractible loop: the refinement meets the criteria or stops at its work bound, valid either way
  DT u(P);
  Loop_segments L;
  const std::vector<Point> c = circle_loop(Point(-0.2, 0.1), 0.5);
  CGAL_HC_CHECK(u.insert_feature_loop(c).complete);
  L.add(c);
  const auto st = HSM::refine_Chew(u, HSMP::maximum_circumradius(0.2, HSMP::maximum_number_of_insertions(20000)));
  std::cout << "  Chew with a geodesic 12-gon as a feature loop: " << HSM::to_string(st.status) << ", "
            << st.final_vertices << " vertices" << std::endl;
  CGAL_HC_CHECK(st.status == HSM::Refinement_status::SUCCESS || st.status == HSM::Refinement_status::WORK_BOUND_REACHED);
  CGAL_HC_CHECK_MSG(u.is_valid(&why), why);
  check_delaunay_up_to_rounding(u);
  check_loop_coverage(P, u, L);
}

CGAL_HC_TEST_CASE(feature_loop_crossing_itself_at_tiny_angles_stays_valid)
{
  // the fuzzer's input test/fuzz/corpus/surface_mesher/seed3_loop: a self-crossing hexagon of random points, the
  // same points inserted, every third removed, Chew with epsilon 0.325: the splits cascaded at a tiny crossing
  // angle and folded faces (a chart not counterclockwise) before split points were checked and constrained edges
  // below 1e-6 epsilon were no longer split
  DT t(Polygon::regular(2));
  const double c[14] = {0.1, 0.1, 0.3, -0.2, -0.2, 0.25, 0.05, -0.3, 0.6, 0.1, -0.5, -0.4, 0.2, 0.7};
  std::vector<Point> loop;
  for(int k = 0; k < 6; ++k) loop.push_back(Point(c[2 * k], c[2 * k + 1]));
  loop.push_back(loop.front());
  CGAL_HC_CHECK(t.insert_feature_loop(loop, 300).complete);
  std::vector<std::size_t> inserted;
  for(int k = 0; k < 7; ++k) inserted.push_back(t.insert_in_frame(Point(c[2 * k], c[2 * k + 1])));
  for(std::size_t k = 0; k < inserted.size(); k += 3) if(t.is_vertex(inserted[k])) t.remove(inserted[k]);
  const auto st = HSM::refine_Chew(t, HSMP::maximum_circumradius(0.325, HSMP::maximum_number_of_insertions(2000)));
  std::cout << "  self-crossing hexagon, Chew: " << HSM::to_string(st.status) << ", " << st.unrefinable_faces
            << " unrefinable, minimum angle " << st.minimum_angle * 180 / CGAL_PI << " degrees" << std::endl;
  std::string why;
  CGAL_HC_CHECK_MSG(t.is_valid(&why, 1e-6), why);
  CGAL_HC_CHECK(t.euler_characteristic() == -2);
  CGAL_HC_CHECK(st.status != HSM::Refinement_status::SUCCESS || st.faces_failing_criteria == 0);
}
