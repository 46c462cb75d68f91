// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Known values (regular triangle, thesis section 3.2: theta*(h), rho(h)), the constructions (checked with the
// exact predicates or the reference), and the rejection of points outside the open disk.
#include "cgal_hc_test.h"
#include "test_support.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Poincare_disk_isometry_2.h>
#include <CGAL/Poincare_disk_traits_2.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace pd_test;

namespace {

const double PI = 3.14159265358979323846;

/// thesis section 3.2: theta*(h) is the central angle of a chord of length h in a circle of radius h
/// (hyperbolic law of cosines cosh h = cosh^2 h - sinh^2 h cos theta)
double theta_star(double h) { return std::acos((std::cosh(h) * std::cosh(h) - std::cosh(h)) / (std::sinh(h) * std::sinh(h))); }
/// rho(h) = 2 asinh(sin theta*(h) sinh h) / h: the chord of central angle 2 theta*(h), in units of h
double rho(double h) { return 2 * std::asinh(std::sin(theta_star(h)) * std::sinh(h)) / h; }

double deg(double rad) { return rad * 180 / PI; }

bool rel_close(double a, double b, double tol) { return std::abs(a - b) <= tol * std::max(1.0, std::abs(b)); }

} // namespace

CGAL_HC_TEST_CASE(thesis_theta_star_and_rho)
{
  // the formulas themselves (thesis section 3.2 and DESIGN.md)
  CGAL_HC_CHECK_MSG(std::abs(deg(theta_star(2.3101)) - 33.3) < 0.05, deg(theta_star(2.3101)));
  CGAL_HC_CHECK_MSG(std::abs(rho(2.3101) - 1.5) < 0.005, rho(2.3101));
  CGAL_HC_CHECK_MSG(std::abs(deg(theta_star(1e-4)) - 60.0) < 1e-3, deg(theta_star(1e-4)));
  CGAL_HC_CHECK_MSG(std::abs(rho(1e-4) - std::sqrt(3.0)) < 1e-6, rho(1e-4));
  // monotone decrease of theta* and rho in between
  for(double h = 0.1; h < 5; h += 0.1) {
    CGAL_HC_CHECK(theta_star(h + 0.1) < theta_star(h));
    CGAL_HC_CHECK(rho(h + 0.1) < rho(h) && rho(h) > 1.0);
  }

  // the traits see the same geometry: a circle of radius h about the origin (Euclidean radius tanh(h/2)),
  // p at angle 0, q at angle theta*(h) (shortest edge), t opposite
  typedef CGAL::Poincare_disk_traits_2<Epick> Tr;
  typedef Epick::Point_2 P;
  const Tr tr;
  for(double h : {0.05, 0.5, 1.0, 2.3101, 4.0}) {
    const double r = std::tanh(h / 2), th = theta_star(h);
    const P p(r, 0), q(r * std::cos(th), r * std::sin(th)), t(r * std::cos(PI + th / 2), r * std::sin(PI + th / 2));
    const double s2 = std::sin(th / 2) * std::sin(th / 2), c2 = std::cosh(h) * std::cosh(h);
    CGAL_HC_CHECK_MSG(tr.compare_central_angle_2_object()(p, q, t, s2 * (1 - 1e-8)) == CGAL::LARGER, h);
    CGAL_HC_CHECK_MSG(tr.compare_central_angle_2_object()(p, q, t, s2 * (1 + 1e-8)) == CGAL::SMALLER, h);
    CGAL_HC_CHECK_MSG(tr.compare_central_angle_2_object()(t, p, q, s2 * (1 + 1e-8)) == CGAL::SMALLER, h); // any order
    CGAL_HC_CHECK_MSG(tr.compare_hyperbolic_circumradius_2_object()(p, q, t, c2 * (1 - 1e-8)) == CGAL::LARGER, h);
    CGAL_HC_CHECK_MSG(tr.compare_hyperbolic_circumradius_2_object()(p, q, t, c2 * (1 + 1e-8)) == CGAL::SMALLER, h);
    // the chord of central angle theta* has length h, the chord of central angle 2 theta* has length rho(h) h
    CGAL_HC_CHECK_MSG(rel_close(tr.compute_cosh_hyperbolic_distance_2_object()(p, q), std::cosh(h), 1e-9), h);
    const P q2(r * std::cos(2 * th), r * std::sin(2 * th));
    CGAL_HC_CHECK_MSG(rel_close(tr.compute_hyperbolic_distance_2_object()(p, q2), rho(h) * h, 1e-9),
                      h << ": " << tr.compute_hyperbolic_distance_2_object()(p, q2) << " vs " << rho(h) * h);
  }
}

CGAL_HC_TEST_CASE(regular_triangle_central_angles)
{
  // a regular triangle inscribed in a hyperbolic circle has central angles 2 pi / 3: sin^2(pi / 3) = 3 / 4
  {
    typedef CGAL::Poincare_disk_traits_2<Epeck_sqrt> Tr;
    typedef Epeck_sqrt::FT FT;
    typedef Epeck_sqrt::Point_2 P;
    typedef CGAL::Poincare_disk_isometry_2<Epeck_sqrt> Iso;
    const Tr tr;
    const FT s3 = CGAL::sqrt(FT(3));
    for(const FT& r : {FT(1) / 10, FT(1) / 2, FT(99) / 100}) {
      std::vector<P> v = {P(r, 0), P(-r / 2, r * s3 / 2), P(-r / 2, -r * s3 / 2)};
      const FT ch = (1 + r * r) / (1 - r * r); // cosh of the circumradius 2 atanh(r)
      for(const Iso& f : {Iso(), Iso(FT(1), FT(0), FT(1) / 3, FT(-1) / 2), Iso(FT(2), FT(1), FT(-1) / 4, FT(5) / 4)}) {
        const P a = f(v[0]), b = f(v[1]), c = f(v[2]);
        CGAL_HC_CHECK(tr.compare_central_angle_2_object()(a, b, c, FT(3) / 4) == CGAL::EQUAL);
        CGAL_HC_CHECK(tr.compare_central_angle_2_object()(b, c, a, FT(3) / 4 - FT(1) / 1000000) == CGAL::LARGER);
        CGAL_HC_CHECK(tr.compare_central_angle_2_object()(c, a, b, FT(3) / 4 + FT(1) / 1000000) == CGAL::SMALLER);
        CGAL_HC_CHECK(tr.compare_hyperbolic_circumradius_2_object()(a, b, c, ch * ch) == CGAL::EQUAL);
        CGAL_HC_CHECK(tr.compare_hyperbolic_distance_2_object()(a, b, b, c) == CGAL::EQUAL);
        // its circumcentre is the image of the origin
        const P o = tr.construct_hyperbolic_circumcenter_2_object()(a, b, c), fo = f(P(0, 0));
        CGAL_HC_CHECK(o.x() == fo.x() && o.y() == fo.y());
      }
    }
  }
  {
    typedef CGAL::Poincare_disk_traits_2<Epick> Tr;
    typedef Epick::Point_2 P;
    const Tr tr;
    for(double r : {1e-3, 0.3, 0.9, 0.999}) {
      const P a(r, 0), b(-r / 2, r * std::sqrt(3.0) / 2), c(-r / 2, -r * std::sqrt(3.0) / 2);
      const double tol = 1e-9 / (1 - r);
      CGAL_HC_CHECK_MSG(tr.compare_central_angle_2_object()(a, b, c, 0.75 * (1 - tol)) == CGAL::LARGER, r);
      CGAL_HC_CHECK_MSG(tr.compare_central_angle_2_object()(a, b, c, 0.75 * (1 + tol)) == CGAL::SMALLER, r);
      const double ch = (1 + r * r) / (1 - r * r);
      CGAL_HC_CHECK_MSG(tr.compare_hyperbolic_circumradius_2_object()(a, b, c, ch * ch * (1 - tol)) == CGAL::LARGER, r);
      CGAL_HC_CHECK_MSG(tr.compare_hyperbolic_circumradius_2_object()(a, b, c, ch * ch * (1 + tol)) == CGAL::SMALLER, r);
      const P o = tr.construct_hyperbolic_circumcenter_2_object()(a, b, c);
      CGAL_HC_CHECK_MSG(std::abs(o.x()) < 1e-12 && std::abs(o.y()) < 1e-12, r);
    }
  }
}

// ------------------------------------------------------------------------------------------------ constructions

CGAL_HC_TEST_CASE(constructions_exact_with_sqrt)
{
  // with an exact square root the constructions are exact: verified with the exact predicates
  typedef CGAL::Poincare_disk_traits_2<Epeck_sqrt> Tr;
  typedef Epeck_sqrt::FT FT;
  typedef Epeck_sqrt::Point_2 P;
  const Tr tr;
  const P p(FT(1) / 3, FT(1) / 5), q(FT(-1) / 2, FT(1) / 7), r(FT(1) / 9, FT(-2) / 3), s(FT(3) / 4, FT(1) / 2);

  const P c = tr.construct_hyperbolic_circumcenter_2_object()(p, q, r);
  CGAL_HC_CHECK(tr.compare_distance_2_object()(c, p, q) == CGAL::EQUAL);
  CGAL_HC_CHECK(tr.compare_distance_2_object()(c, q, r) == CGAL::EQUAL);
  CGAL_HC_CHECK(tr.construct_circumcenter_2_object()(p, q, r) == c);

  const P m = tr.construct_hyperbolic_midpoint_2_object()(p, s);
  CGAL_HC_CHECK(tr.orientation_2_object()(p, s, m) == CGAL::COLLINEAR);
  CGAL_HC_CHECK(tr.compare_distance_2_object()(m, p, s) == CGAL::EQUAL);
  CGAL_HC_CHECK(tr.compare_x_2_object()(p, m) != tr.compare_x_2_object()(s, m)); // between p and s
  CGAL_HC_CHECK(tr.construct_midpoint_2_object()(p, s) == m);

  const P k = tr.construct_Klein_point_2_object()(s);
  CGAL_HC_CHECK(tr.construct_point_from_Klein_2_object()(k) == s);

  // geodesic crossing: exactly on both geodesics
  typedef Epeck_sqrt::Segment_2 S;
  const P a1(FT(-1) / 2, FT(1) / 10), a2(FT(1) / 2, FT(1) / 5), b1(FT(1) / 10, FT(-1) / 2), b2(FT(1) / 7, FT(3) / 5);
  const QP qa1(Q(-1, 2), Q(1, 10)), qa2(Q(1, 2), Q(1, 5)), qb1(Q(1, 10), Q(-1, 2)), qb2(Q(1, 7), Q(3, 5));
  CGAL_HC_CHECK(pd_ref::orientation(qa1, qa2, qb1) * pd_ref::orientation(qa1, qa2, qb2) < 0); // they cross
  CGAL_HC_CHECK(pd_ref::orientation(qb1, qb2, qa1) * pd_ref::orientation(qb1, qb2, qa2) < 0);
  const auto x = tr.intersect_2_object()(S(a1, a2), S(b1, b2));
  CGAL_HC_CHECK(bool(x));
  if(x) {
    const P* i = boost::get<P>(&*x);
    CGAL_HC_CHECK(i != nullptr);
    if(i) {
      CGAL_HC_CHECK(tr.orientation_2_object()(a1, a2, *i) == CGAL::COLLINEAR);
      CGAL_HC_CHECK(tr.orientation_2_object()(b1, b2, *i) == CGAL::COLLINEAR);
    }
  }
  CGAL_HC_CHECK(!tr.intersect_2_object()(S(a1, b1), S(a2, b2))); // disjoint (two sides of the quadrilateral)

  // bisector: ideal endpoints on the unit circle, horocyclically equidistant from p and q
  // (|e - p|^2 / (1 - |p|^2) = |e - q|^2 / (1 - |q|^2), the limit of d(e, p) = d(e, q))
  const auto b = tr.construct_hyperbolic_bisector_2_object()(p, q);
  for(const P& e : {b.source(), b.target()}) {
    CGAL_HC_CHECK(e.x() * e.x() + e.y() * e.y() == FT(1));
    CGAL_HC_CHECK(CGAL::squared_distance(e, p) * (1 - q.x() * q.x() - q.y() * q.y()) ==
                  CGAL::squared_distance(e, q) * (1 - p.x() * p.x() - p.y() * p.y()));
  }
  // Voronoi edge pieces: the ray from the circumcentre (p, q, r) goes away from r
  const auto ray = tr.construct_hyperbolic_bisector_2_object()(p, q, r);
  CGAL_HC_CHECK(ray.source() == c);
  // its ideal end is on the other side of the geodesic pq than r (Klein determinant, written out: w = 1 + |z|^2)
  auto klein_det = [](const P& a, const P& b, const P& z) {
    const FT wa = 1 + a.x() * a.x() + a.y() * a.y(), wb = 1 + b.x() * b.x() + b.y() * b.y(), wz = 1 + z.x() * z.x() + z.y() * z.y();
    return CGAL::sign(a.x() * (b.y() * wz - wb * z.y()) - a.y() * (b.x() * wz - wb * z.x()) + wa * (b.x() * z.y() - b.y() * z.x()));
  };
  CGAL_HC_CHECK(ray.target().x() * ray.target().x() + ray.target().y() * ray.target().y() == FT(1));
  CGAL_HC_CHECK(klein_det(p, q, ray.target()) == -klein_det(p, q, r) && klein_det(p, q, r) != CGAL::ZERO);
}

CGAL_HC_TEST_CASE(constructions_rational_exact_on_gmpq)
{
  typedef CGAL::Poincare_disk_traits_2<SC_gmpq> Tr;
  typedef SC_gmpq::Point_2 P;
  typedef CGAL::Gmpq G;
  const Tr tr;
  std::mt19937_64 rng(5);
  const std::vector<QP> pts = random_euclidean(rng, 20, 0.99);
  for(std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const P p(pts[i].x, pts[i].y), q(pts[i + 1].x, pts[i + 1].y);
    // hyperboloid lift and back, upper half-plane and back: rational, hence exact
    const auto h = tr.construct_hyperboloid_point_3_object()(p);
    CGAL_HC_CHECK(h.x() * h.x() + h.y() * h.y() - h.z() * h.z() == G(-1));
    CGAL_HC_CHECK(tr.construct_point_from_hyperboloid_2_object()(h) == p);
    const P w = tr.construct_upper_half_plane_point_2_object()(p);
    CGAL_HC_CHECK(w.y() > 0);
    CGAL_HC_CHECK(tr.construct_point_from_upper_half_plane_2_object()(w) == p);
    // cosh d is exact and equals the reference -<L(p), L(q)>
    CGAL_HC_CHECK(tr.compute_cosh_hyperbolic_distance_2_object()(p, q) == pd_ref::cosh_d(pts[i], pts[i + 1]));
    // translation along pq takes p to q, exactly
    const auto t = tr.construct_hyperbolic_translation_2_object()(p, q);
    CGAL_HC_CHECK(t(p) == q);
    CGAL_HC_CHECK(tr.construct_hyperbolic_translation_2_object()(p)(p) == P(0, 0));
    // the geodesic segment's supporting circle is orthogonal to the unit circle and passes through p and q
    const auto g = tr.construct_hyperbolic_segment_2_object()(p, q);
    if(!g.is_line_segment()) {
      const P c = g.center();
      CGAL_HC_CHECK(c.x() * c.x() + c.y() * c.y() - g.squared_radius() == G(1));
      CGAL_HC_CHECK(CGAL::squared_distance(c, p) == g.squared_radius());
      CGAL_HC_CHECK(CGAL::squared_distance(c, q) == g.squared_radius());
    }
    // the hyperbolic circle of centre p and sinh^2(r/2) = 1/3: z is inside the Euclidean circle iff
    // sinh^2(d(p, z)/2) < 1/3 (reference), for every test point z
    const G s2(1, 3);
    const auto circ = tr.construct_hyperbolic_circle_2_object()(p, s2);
    for(const QP& z : pts) {
      const int inside_e = CGAL::sign(circ.squared_radius() - CGAL::squared_distance(circ.center(), P(z.x, z.y)));
      CGAL_HC_CHECK(inside_e == pd_ref::sgn(s2 - pd_ref::sinh2_half_d(pts[i], z)));
    }
  }
}

CGAL_HC_TEST_CASE(constructions_rounded_on_epick)
{
  typedef CGAL::Poincare_disk_traits_2<Epick> Tr;
  typedef Epick::Point_2 P;
  const Tr tr;
  std::mt19937_64 rng(17);
  const std::vector<QP> pts = random_hyperbolic(rng, 60, 4.0);
  auto cd = [&](const P& a, const P& b) { return CGAL::to_double(pd_ref::cosh_d(qp(a.x(), a.y()), qp(b.x(), b.y()))); };
  for(std::size_t i = 0; i + 2 < pts.size(); ++i) {
    const P p(pts[i].dx(), pts[i].dy()), q(pts[i + 1].dx(), pts[i + 1].dy()), r(pts[i + 2].dx(), pts[i + 2].dy());
    const P m = tr.construct_hyperbolic_midpoint_2_object()(p, q);
    CGAL_HC_CHECK(rel_close(cd(m, p), cd(m, q), 1e-9));
    const double d = tr.compute_hyperbolic_distance_2_object()(p, q);
    CGAL_HC_CHECK(rel_close(d, std::acosh(cd(p, q)), 1e-9));
    CGAL_HC_CHECK(rel_close(tr.compute_hyperbolic_distance_2_object()(p, m), d / 2, 1e-8));
    const P t = tr.construct_hyperbolic_point_on_segment_2_object()(p, q, 0.25);
    CGAL_HC_CHECK(rel_close(tr.compute_hyperbolic_distance_2_object()(p, t), d / 4, 1e-8));
    CGAL_HC_CHECK(rel_close(tr.compute_hyperbolic_distance_2_object()(t, q), 3 * d / 4, 1e-8));
    if(tr.is_Delaunay_hyperbolic_2_object()(p, q, r)) {
      const P c = tr.construct_hyperbolic_circumcenter_2_object()(p, q, r);
      CGAL_HC_CHECK(rel_close(cd(c, p), cd(c, q), 1e-8) && rel_close(cd(c, p), cd(c, r), 1e-8));
      // circle from a Euclidean circle: back to the same centre and radius
      const auto circle = tr.construct_hyperbolic_circle_2_object().from_radius(c, std::acosh(cd(c, p)));
      const auto cr = tr.construct_hyperbolic_circle_from_Euclidean_2_object()(circle);
      CGAL_HC_CHECK(std::abs(cr.first.x() - c.x()) < 1e-8 && std::abs(cr.first.y() - c.y()) < 1e-8);
      CGAL_HC_CHECK(rel_close(cr.second, std::acosh(cd(c, p)), 1e-8));
    } else {
      CGAL_HC_CHECK_THROWS(tr.construct_hyperbolic_circumcenter_2_object()(p, q, r), CGAL::Poincare_disk_domain_error);
    }
  }
}

// Two geodesics crossing at |z| = 1 - 10^-k (k = 3..15): on double coordinates the crossing is returned inside
// the disk, near the true one, or Numerical_error says it cannot be represented (issue 12: a NaN-point message
// from the Klein conversion at 1 - 1e-9).
CGAL_HC_TEST_CASE(crossings_near_the_circle_at_infinity)
{
  typedef CGAL::Poincare_disk_traits_2<Epick> Tr;
  typedef Epick::Point_2 P;
  typedef Epick::Segment_2 S;
  const Tr tr;
  std::size_t returned = 0, refused = 0;
  for(int k = 3; k <= 15; ++k)
    for(int a = 0; a < 8; ++a) {
      const double r = 1 - std::pow(10.0, -k), th = 0.4 + a * 0.7;
      const P X(r * std::cos(th), r * std::sin(th));
      const CGAL::Poincare_disk_isometry_2<Epick> T = CGAL::Poincare_disk_isometry_2<Epick>::translation_to_origin(X).inverse();
      auto chord = [&](double phi) {
        return S(T.apply_unchecked(P(-0.5 * std::cos(phi), -0.5 * std::sin(phi))), T.apply_unchecked(P(0.5 * std::cos(phi), 0.5 * std::sin(phi))));
      };
      const S s1 = chord(0.3), s2 = chord(1.9);
      bool inside = true;
      for(const P& q : {s1.source(), s1.target(), s2.source(), s2.target()}) inside = inside && q.x() * q.x() + q.y() * q.y() < 1;
      if(!inside) continue; // the end points themselves rounded onto the circle
      try {
        const auto x = tr.intersect_2_object()(s1, s2);
        if(!x) continue; // rounded end points may no longer cross
        const P* i = boost::get<P>(&*x);
        CGAL_HC_CHECK(i != nullptr);
        if(!i) continue;
        CGAL_HC_CHECK(std::isfinite(i->x()) && std::isfinite(i->y()) && i->x() * i->x() + i->y() * i->y() < 1);
        CGAL_HC_CHECK_MSG(std::hypot(i->x() - X.x(), i->y() - X.y()) < 1e-6, "k " << k << " crossing " << *i << " vs " << X);
        ++returned;
      } catch(const CGAL::Numerical_error&) { ++refused; }
    }
  std::cout << "  crossings near the circle: " << returned << " returned, " << refused << " refused (Numerical_error)\n";
  CGAL_HC_CHECK(returned > 0 && refused > 0);
}

// ------------------------------------------------------------------------------------------------ bad input

CGAL_HC_TEST_CASE(points_outside_the_disk_are_rejected)
{
  typedef CGAL::Poincare_disk_traits_2<Epick> Tr;
  typedef Epick::Point_2 P;
  const Tr tr;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const P ok(0.1, 0.2), ok2(-0.3, 0.4);
  const std::vector<P> bad = {P(1, 0), P(0, -1), P(2, 0), P(nan, 0), P(0, nan), P(inf, 0), P(-inf, 0.5), P(0.6, 0.8)};
  for(const P& b : bad) {
    CGAL_HC_CHECK_THROWS(tr.orientation_2_object()(ok, ok2, b), CGAL::Poincare_disk_domain_error);
    CGAL_HC_CHECK_THROWS(tr.orientation_2_object()(b, ok, ok2), CGAL::Poincare_disk_domain_error);
    CGAL_HC_CHECK_THROWS(tr.compare_x_2_object()(b, ok), CGAL::Poincare_disk_domain_error);
    CGAL_HC_CHECK_THROWS(tr.compare_y_2_object()(ok, b), CGAL::Poincare_disk_domain_error);
    CGAL_HC_CHECK_THROWS(tr.less_xy_2_object()(ok, b), CGAL::Poincare_disk_domain_error);
    CGAL_HC_CHECK_THROWS(tr.construct_Klein_point_2_object()(b), CGAL::Poincare_disk_domain_error);
    CGAL_HC_CHECK_THROWS(tr.construct_hyperbolic_midpoint_2_object()(ok, b), CGAL::Poincare_disk_domain_error);
    CGAL_HC_CHECK_THROWS(tr.compute_hyperbolic_distance_2_object()(b, ok), CGAL::Poincare_disk_domain_error);
    CGAL_HC_CHECK_THROWS(tr.construct_hyperboloid_point_3_object()(b), CGAL::Poincare_disk_domain_error);
    // a clear message
    try { tr.orientation_2_object()(ok, ok2, b); } catch(const std::exception& e) {
      CGAL_HC_CHECK(std::string(e.what()).find("not in the open unit disk") != std::string::npos);
    }
  }
  // doubles next to the unit circle: accepted iff x^2 + y^2 < 1 exactly
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 2 * PI);
  int accepted = 0, rejected = 0;
  for(int i = 0; i < 2000; ++i) {
    const double t = u(rng);
    double x = std::cos(t), y = std::sin(t);
    if(i % 3 == 1) x = std::nextafter(x, 0.0);
    if(i % 3 == 2) y = std::nextafter(y, 0.0);
    const bool inside = pd_ref::in_open_disk(qp(x, y));
    bool threw = false;
    try { tr.orientation_2_object()(ok, ok2, P(x, y)); } catch(const CGAL::Poincare_disk_domain_error&) { threw = true; }
    CGAL_HC_CHECK_MSG(threw == !inside, x << " " << y);
    (inside ? accepted : rejected)++;
  }
  CGAL_HC_CHECK(accepted > 100 && rejected > 100); // both cases exercised
  const double below1 = std::nextafter(1.0, 0.0);
  CGAL_HC_CHECK(tr.orientation_2_object()(P(below1, 0), P(0, below1), P(-below1, 0)) == CGAL::LEFT_TURN);

  // exact kernels: a rational point on the unit circle
  typedef CGAL::Poincare_disk_traits_2<SC_gmpq> Trq;
  typedef SC_gmpq::Point_2 Pq;
  const Pq on_circle(CGAL::Gmpq(3, 5), CGAL::Gmpq(4, 5)), inside(CGAL::Gmpq(3, 5), CGAL::Gmpq(799, 1000));
  CGAL_HC_CHECK_THROWS(Trq().orientation_2_object()(Pq(0, 0), inside, on_circle), CGAL::Poincare_disk_domain_error);
  CGAL_HC_CHECK(Trq().orientation_2_object()(Pq(0, 0), Pq(CGAL::Gmpq(1, 2), 0), inside) == CGAL::LEFT_TURN);
}

// Issue 12: Side_of_hyperbolic_diametral_circle_2, Angle_2 and Compare_central_angle_2 crashed with a NaN point
// (SIGFPE in GMP's mpq_set_d in release builds); they, Compare_distance_2 and the other predicates answered
// silently for points outside the disk. Every public functor now checks its points as the insertion predicates.
CGAL_HC_TEST_CASE(issue12_every_public_predicate_checks_its_points)
{
  typedef CGAL::Poincare_disk_traits_2<Epick> Tr;
  typedef Epick::Point_2 P;
  const Tr tr;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const P ok(0.1, 0.2), ok2(-0.3, 0.4), ok3(0.2, -0.5);
  const std::vector<P> bad = {P(nan, 0), P(0, nan), P(nan, nan), P(inf, 0), P(1, 0), P(0.6, 0.8), P(2, 3)};
  for(const P& b : bad) {
    for(int k = 0; k < 3; ++k) {
      P v[3] = {ok, ok2, ok3};
      v[k] = b;
      CGAL_HC_CHECK_THROWS(tr.side_of_hyperbolic_diametral_circle_2_object()(v[0], v[1], v[2]),
                           CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK_THROWS(tr.angle_2_object()(v[0], v[1], v[2]), CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK_THROWS(tr.compare_central_angle_2_object()(v[0], v[1], v[2], 0.25), CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK_THROWS(tr.compare_hyperbolic_circumradius_2_object()(v[0], v[1], v[2], 2.0),
                           CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK_THROWS(tr.compare_distance_2_object()(v[0], v[1], v[2]), CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK_THROWS(tr.compare_hyperbolic_distance_2_object()(v[0], v[1], v[2], ok),
                           CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK_THROWS(tr.side_of_oriented_circle_2_object()(v[0], v[1], v[2], ok), CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK_THROWS(tr.side_of_oriented_circle_2_object()(ok, v[1], v[2], v[0]), CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK_THROWS(tr.side_of_oriented_hyperbolic_segment_2_object()(v[0], v[1], v[2]),
                           CGAL::Poincare_disk_domain_error);
      if(k < 2) CGAL_HC_CHECK_THROWS(tr.compute_squared_distance_2_object()(v[0], v[1]), CGAL::Poincare_disk_domain_error);
    }
  }
  // a non-finite threshold is bad input too (it reached mpq_set_d)
  CGAL_HC_CHECK_THROWS(tr.compare_central_angle_2_object()(ok, ok2, ok3, nan), CGAL::Invalid_input_error);
  CGAL_HC_CHECK_THROWS(tr.compare_hyperbolic_circumradius_2_object()(ok, ok2, ok3, inf), CGAL::Invalid_input_error);
  // good input still answers
  CGAL_HC_CHECK(tr.angle_2_object()(P(-0.5, 0), P(0, 0), P(0.5, 0)) == CGAL::OBTUSE);
  CGAL_HC_CHECK(tr.compare_distance_2_object()(P(0, 0), P(0.1, 0), P(0.2, 0)) == CGAL::SMALLER);
}

CGAL_HC_TEST_CASE(triangulation_insertion_rejects_bad_points)
{
  typedef CGAL::Poincare_disk_traits_2<Epick> Tr;
  typedef CGAL::Delaunay_triangulation_2<Tr> DT;
  typedef Epick::Point_2 P;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(const P& b : {P(1, 0), P(3, 4), P(nan, 0.5)}) {
    {
      DT dt;
      dt.insert(P(0.1, 0.1)); dt.insert(P(-0.2, 0.3)); dt.insert(P(0.3, -0.5));
      CGAL_HC_CHECK_THROWS(dt.insert(b), CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK(dt.number_of_vertices() == 3 && dt.is_valid());
    }
    {
      std::vector<P> v = {P(0.1, 0.1), P(-0.2, 0.3), b, P(0.3, -0.5), P(0.5, 0.5)};
      DT dt;
      CGAL_HC_CHECK_THROWS(dt.insert(v.begin(), v.end()), CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK(dt.number_of_vertices() == 0); // validated before the triangulation is modified
      DT dt3;
      dt3.insert(P(0.1, 0.1)); dt3.insert(P(-0.2, 0.3));
      CGAL_HC_CHECK_THROWS(dt3.insert(v.begin(), v.end()), CGAL::Poincare_disk_domain_error);
      CGAL_HC_CHECK(dt3.number_of_vertices() == 2 && dt3.is_valid());
    }
    {
      // the very first point of an empty triangulation: CGAL calls no traits functor, so (documented) the bad
      // point is reported by the next insertion, whose predicates involve it
      DT dt;
      bool threw_first = false, threw_next = false;
      try { dt.insert(b); } catch(const CGAL::Poincare_disk_domain_error&) { threw_first = true; }
      if(!threw_first) {
        try { dt.insert(P(0.1, 0.2)); } catch(const CGAL::Poincare_disk_domain_error&) { threw_next = true; }
      }
      CGAL_HC_CHECK_MSG(threw_first || threw_next, "bad first point " << b << " never reported");
    }
  }
}
