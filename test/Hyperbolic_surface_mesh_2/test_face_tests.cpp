// The refinement's face tests are exact: Chew's shape test (shortest edge < circumradius) against an
// independent exact rational reference on the hyperboloid, on faces within a few ulps of the threshold; the
// Bounded_double stage of every test agrees with the traits' exact predicates whenever it decides; the
// Bounded_double error bound holds on random expression trees (cancellation, underflow) against exact rationals.
#include "test_support.h"

#include <CGAL/Exact_rational.h>
#include <CGAL/Random.h>

using namespace hsm2_test;

namespace {

typedef CGAL::Exact_rational Q;
typedef std::array<Q, 3> Lift; // hyperboloid (t, x, y), Minkowski form -t t' + x x' + y y'

Lift hyperboloid(const Point& p)
{
  const Q x(p.x()), y(p.y()), n = x * x + y * y, d = Q(1) - n;
  return {{(Q(1) + n) / d, Q(2) * x / d, Q(2) * y / d}};
}
Q minkowski(const Lift& a, const Lift& b) { return -a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// exact reference: +1 if the shortest edge is shorter than the circumradius, 0 if equal, -1 if longer,
/// -2 if the circumcircle is not compact. The circumcentre is the timelike normal n of the plane through the
/// three lifts (the Minkowski cross product of two chords): cosh^2 r = <n, P>^2 / -<n, n>; cosh d = -<P, Q>.
int chew_reference(const Point& p, const Point& q, const Point& r)
{
  const Lift P = hyperboloid(p), Qh = hyperboloid(q), R = hyperboloid(r);
  const Lift u{{Qh[0] - P[0], Qh[1] - P[1], Qh[2] - P[2]}}, v{{R[0] - P[0], R[1] - P[1], R[2] - P[2]}};
  // Euclidean cross product, then J = diag(-1, 1, 1): <J w, u> = w . u = 0
  const Lift n{{-(u[1] * v[2] - u[2] * v[1]), u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
  const Q nn = minkowski(n, n);
  if(!(nn < 0)) return -2;
  const Q np = minkowski(n, P), cosh2_r = np * np / -nn;
  const Q c1 = -minkowski(P, Qh), c2 = -minkowski(Qh, R), c3 = -minkowski(R, P);
  const Q cmin = (std::min)({c1, c2, c3});
  const Q d = cosh2_r - cmin * cmin;
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}

/// a random expression tree of the given depth on random inputs (scales from 1e-170 to 1, so that products
/// underflow; differences of nearly equal subtrees, so that sums cancel), evaluated in both number types
void random_tree(CGAL::Random& rng, int depth, HSM::internal::Bounded_double& b, Q& q)
{
  typedef HSM::internal::Bounded_double BD;
  if(depth == 0) {
    const int kind = rng.get_int(0, 4);
    const double x = kind == 0 ? 0.0 : std::ldexp(rng.get_double(-1, 1), kind == 1 ? -rng.get_int(0, 560) : -rng.get_int(0, 8));
    b = BD(x); q = Q(x);
    return;
  }
  BD b1, b2; Q q1, q2;
  random_tree(rng, depth - 1, b1, q1);
  const int op = rng.get_int(0, 4);
  if(op == 3) { // a - a': a tree minus a perturbed copy of itself (cancellation)
    const double s = 1 + std::ldexp(rng.get_double(-1, 1), -rng.get_int(20, 60));
    b2 = b1 * BD(s); q2 = q1 * Q(s);
    b = b1 - b2; q = q1 - q2;
    return;
  }
  random_tree(rng, depth - 1, b2, q2);
  if(op == 0) { b = b1 + b2; q = q1 + q2; }
  else if(op == 1) { b = b1 - b2; q = q1 - q2; }
  else { b = b1 * b2; q = q1 * q2; }
}

Point rotate(const Point& p, double a) { return Point(std::cos(a) * p.x() - std::sin(a) * p.y(), std::sin(a) * p.x() + std::cos(a) * p.y()); }

} // namespace

CGAL_HC_TEST_CASE(chew_shape_test_exact_near_threshold)
{
  // three points on the circle of hyperbolic radius h about a centre: the chord of central angle theta* =
  // 2 asin(1 / (2 cosh(h / 2))) has length h; the third point is opposite. Angles theta* (1 + k 2^-52) and
  // a random isometry put the rounded faces within a few ulps of the threshold, on both sides.
  CGAL::Random rng(5);
  DT t(Polygon::Bolza());
  std::size_t poor = 0, fine = 0, tie = 0, filter_decided = 0, old_test_wrong = 0, n = 0;
  for(double h : {1e-3, 0.01, 0.1, 0.5, 1.0, 2.0}) {
    const double rho = std::tanh(h / 2), theta = 2 * std::asin(1 / (2 * std::cosh(h / 2)));
    const HSM::internal::Face_quality<DT> q(t, true, 2 * h, 0.5);
    for(int k = -40; k <= 40; ++k) {
      const double th = theta * (1 + k * std::ldexp(1.0, -52)), a0 = rng.get_double(0, 2 * CGAL_PI);
      Point p = rotate(Point(rho, 0), a0), pq = rotate(Point(rho * std::cos(th), rho * std::sin(th)), a0),
            pr = rotate(Point(rho * std::cos(CGAL_PI + th / 2), rho * std::sin(CGAL_PI + th / 2)), a0);
      if(k % 2 != 0) { // move off the origin by a translation (the rounded images are a new near-threshold face)
        const auto m = DT::Isometry_2::translation_from_origin(Point(rng.get_double(-0.4, 0.4), rng.get_double(-0.4, 0.4)));
        p = m.apply_unchecked(p); pq = m.apply_unchecked(pq); pr = m.apply_unchecked(pr);
      }
      const int ref = chew_reference(p, pq, pr);
      CGAL_HC_CHECK(ref != -2);
      ++n;
      const bool exact = HSM::internal::chew_shape_is_poor(p, pq, pr);
      CGAL_HC_CHECK_MSG(exact == (ref == 1), "h " << h << " k " << k << " reference " << ref);
      if(ref == 1) ++poor; else if(ref == -1) ++fine; else ++tie;
      // the filtered face test (size bound 2h: never poor by size) decides the same whenever it decides
      typename HSM::internal::Face_quality<DT>::Evaluation ev{};
      if(q.fast_evaluate(p, pq, pr, ev)) { ++filter_decided; CGAL_HC_CHECK(ev.bad == (ref == 1)); }
      CGAL_HC_CHECK(q.evaluate_points(p, pq, pr) == (ref == 1));
      // the former double test (shortest < r (1 - 1e-12)) on the same face
      const CGAL::Poincare_disk_traits_2<K> gt;
      const double r = DT::Geometry::distance(gt.construct_hyperbolic_circumcenter_2_object()(p, pq, pr), p);
      const double d = (std::min)({DT::Geometry::distance(p, pq), DT::Geometry::distance(pq, pr), DT::Geometry::distance(pr, p)});
      if((d < r * (1 - 1e-12)) != (ref == 1)) ++old_test_wrong;
    }
  }
  std::cout << "  chew near threshold: " << n << " faces, " << poor << " poor, " << fine << " fine, " << tie
            << " ties, the filter decided " << filter_decided << ", the former double test was wrong on "
            << old_test_wrong << std::endl;
  CGAL_HC_CHECK(poor > 50 && fine > 50); // both sides of the threshold are exercised
  CGAL_HC_CHECK(filter_decided < n);     // some faces needed the exact stage
}

CGAL_HC_TEST_CASE(bounded_double_error_bound)
{
  // |computed - exact| <= error() on every tree, and a decided sign is the exact sign; some signs are decided
  // and some not (both outcomes exercised)
  CGAL::Random rng(11);
  std::size_t decided = 0, undecided = 0, n = 0;
  for(int k = 0; k < 6000; ++k) {
    HSM::internal::Bounded_double b; Q q;
    random_tree(rng, 1 + k % 6, b, q);
    ++n;
    const Q err = CGAL::abs(Q(b.v) - q);
    CGAL_HC_CHECK_MSG(err <= Q(b.error()), "tree " << k << " value " << b.v << " bound " << b.error()
                      << " actual error " << CGAL::to_double(err));
    const CGAL::Uncertain<CGAL::Sign> s = b.sign();
    if(CGAL::is_indeterminate(s)) { ++undecided; continue; }
    ++decided;
    CGAL_HC_CHECK_MSG(CGAL::get_certain(s) == CGAL::sign(q), "tree " << k);
  }
  std::cout << "  Bounded_double: " << n << " trees, " << decided << " signs decided, " << undecided << " not" << std::endl;
  CGAL_HC_CHECK(decided > 100 && undecided > 100);
}

CGAL_HC_TEST_CASE(filtered_face_tests_agree_with_exact_predicates)
{
  // every face of refined triangulations (genus 2 and 3, both criteria), and random triangles of every size
  // near the origin and near the circle at infinity, against the traits' predicates alone
  std::size_t checked = 0, undecided = 0;
  for(int g : {2, 3}) {
    for(bool chew : {false, true}) {
      DT t(Polygon::regular(g));
      const double eps = 0.3, alpha = 30 * CGAL_PI / 180;
      if(chew) HSM::refine_Chew(t, HSMP::maximum_circumradius(eps));
      else HSM::refine_Ruppert(t, HSMP::maximum_circumradius(eps, HSMP::minimum_central_angle(alpha)));
      for(double e2 : {eps, 0.2, 0.15}) for(double a2 : {alpha, 0.9}) {
        const HSM::internal::Face_quality<DT> q(t, chew, e2, a2);
        for(std::size_t f : t.faces()) {
          ++checked;
          CGAL_HC_CHECK(q.is_bad(f) == q.is_bad_exact(f));
        }
      }
    }
  }
  CGAL::Random rng(3);
  DT t(Polygon::Bolza());
  for(bool chew : {false, true}) {
    const HSM::internal::Face_quality<DT> q(t, chew, 0.4, 0.6);
    for(int k = 0; k < 4000; ++k) {
      const double rad = k % 4 == 0 ? 0.999999 : (k % 4 == 1 ? 0.5 : 0.05);
      Point z[3];
      for(Point& p : z) { const double a = rng.get_double(0, 2 * CGAL_PI), s = rad * std::sqrt(rng.get_double(0, 1)); p = Point(s * std::cos(a), s * std::sin(a)); }
      if(CGAL::Poincare_disk_traits_2<K>().orientation_2_object()(z[0], z[1], z[2]) != CGAL::LEFT_TURN) std::swap(z[1], z[2]);
      typename HSM::internal::Face_quality<DT>::Evaluation ev{};
      ++checked;
      if(q.fast_evaluate(z[0], z[1], z[2], ev)) CGAL_HC_CHECK(ev.bad == q.is_bad_exact(z[0], z[1], z[2]));
      else ++undecided;
    }
  }
  std::cout << "  filtered face tests: " << checked << " checked, " << undecided << " left to the exact stage" << std::endl;
}
