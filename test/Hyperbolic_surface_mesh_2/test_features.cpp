// Feature loops: the sides of a fundamental polygon as constrained edges (closed geodesic loops on the
// surface). After refinement every side is a chain of output edges (the lengths of the constrained edges on
// each side of the frame add up to the side length), the polygon is a union of output faces, and every other
// output check holds (locally Delaunay away from the constraints, angle sums, area, criteria, simplicial, Euler).
#include "test_support.h"

using namespace hsm2_test;
namespace HSM = CGAL::Hyperbolic_surface_mesh_2;
namespace HSMP = CGAL::Hyperbolic_surface_mesh_2::parameters;

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
