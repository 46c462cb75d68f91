// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: exact quality predicates and approximate quality measures of Poincare-disk triangles.
#ifndef CGAL_HYPERBOLIC_MESH_2_INTERNAL_EXACT_QUALITY_H
#define CGAL_HYPERBOLIC_MESH_2_INTERNAL_EXACT_QUALITY_H

#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>
#include <CGAL/Poincare_disk_traits_2.h>
#include <CGAL/Poincare_disk_traits_2/internal/filtered_evaluation.h>
#include <CGAL/Poincare_disk_traits_2/internal/polynomials.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Uncertain.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace CGAL {
namespace Hyperbolic_mesh_2 {
namespace internal {

// Chew's test "some edge is shorter than the circumradius r" as a polynomial sign (POSITIVE: yes, or the
// circumcircle is not compact). With the circle coefficients, sinh^2 r = (B^2 + C^2 - 4AG) / Delta, and
// sinh^2 d(a, b) = 4 A_ab (1 + A_ab), A_ab = |a - b|^2 / (n_a n_b), n = 1 - |z|^2. Edge ab shorter than r iff
// 4 |a-b|^2 (n_a n_b + |a-b|^2) Delta < (B^2 + C^2 - 4AG) (n_a n_b)^2. Written with sinh^2 (not cosh^2) so that
// tiny triangles (Euclidean limit) do not suffer from the cancellation in cosh^2 - 1.
struct Edge_shorter_than_circumradius_poly
{
  template <class NT>
  auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry) const
      -> decltype(CGAL::sign(px))
  {
    using namespace Poincare_disk_internal;
    typedef decltype(CGAL::sign(px)) S;
    const Circle_coefficients<NT> cc(px, py, qx, qy, rx, ry);
    const NT delta = cc.delta();
    if(CGAL::make_certain(CGAL::sign(delta)) != POSITIVE) return S(POSITIVE);
    const NT s2 = cc.sinh2_numerator();
    const NT np = lift_n(px, py), nq = lift_n(qx, qy), nr = lift_n(rx, ry);
    auto shorter = [&](const NT& na, const NT& nb, const NT& d2) {
      const NT nn = na * nb;
      return CGAL::make_certain(CGAL::sign(s2 * nn * nn - NT(4) * d2 * (nn + d2) * delta));
    };
    const Sign s1 = shorter(np, nq, squared_euclidean(px, py, qx, qy));
    if(s1 == POSITIVE) return S(POSITIVE);
    const Sign sb = shorter(nq, nr, squared_euclidean(qx, qy, rx, ry));
    if(sb == POSITIVE) return S(POSITIVE);
    const Sign s3 = shorter(nr, np, squared_euclidean(rx, ry, px, py));
    if(s3 == POSITIVE) return S(POSITIVE);
    return S((s1 == ZERO || sb == ZERO || s3 == ZERO) ? ZERO : NEGATIVE);
  }
};

/// Exact (filtered): some edge of pqr is strictly shorter than its hyperbolic circumradius (or the circumcircle
/// is not compact).
template <class Point_2>
bool has_edge_shorter_than_circumradius(const Point_2& p, const Point_2& q, const Point_2& r)
{
  typedef typename Kernel_traits<Point_2>::Kernel::FT FT;
  return Poincare_disk_internal::Exact_evaluator<FT>::eval(Edge_shorter_than_circumradius_poly(), p.x(), p.y(),
                                                          q.x(), q.y(), r.x(), r.y()) == POSITIVE;
}

// Circumradius r > bound, with the bound given as sinh^2(bound): sign((B^2 + C^2 - 4AG) - s Delta); non-compact
// circumcircles are larger. Same test as the traits' Compare_hyperbolic_circumradius_2 but on sinh^2, which has no
// cancellation for tiny radii (cosh^2 r - cosh^2 bound does).
struct Circumradius_larger_poly
{
  template <class NT>
  auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry,
                  const NT& sinh2_bound) const -> decltype(CGAL::sign(px))
  {
    typedef decltype(CGAL::sign(px)) S;
    const Poincare_disk_internal::Circle_coefficients<NT> cc(px, py, qx, qy, rx, ry);
    const NT delta = cc.delta();
    if(CGAL::make_certain(CGAL::sign(delta)) != POSITIVE) return S(POSITIVE);
    return CGAL::sign(cc.sinh2_numerator() - sinh2_bound * delta);
  }
};

/// Exact (filtered): the hyperbolic circumradius of pqr is larger than the bound b given as sinh^2(b).
template <class Point_2, class FT>
bool circumradius_larger_than(const Point_2& p, const Point_2& q, const Point_2& r, const FT& sinh2_bound)
{
  return Poincare_disk_internal::Exact_evaluator<FT>::eval(Circumradius_larger_poly(), p.x(), p.y(), q.x(), q.y(),
                                                          r.x(), r.y(), sinh2_bound) == POSITIVE;
}

/// The circle coefficients (double) of the triangle pqr moved by the isometry z -> (z - p) / (1 - conj(p) z),
/// which takes p to the origin. The hyperbolic circumradius and the central angles are invariant; after the move the
/// circle is near the origin, so sinh^2 h = (B^2 + C^2 - 4AG) / Delta does not cancel for tiny triangles (on the
/// original coordinates B^2 + C^2 and 4AG agree to |centre|^2 / r^2: 3% error for r = 1e-5 at |centre| = 0.6).
template <class Point_2>
Poincare_disk_internal::Circle_coefficients<double> translated_circle(const Point_2& p, const Point_2& q, const Point_2& r)
{
  const std::complex<double> a(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  auto move = [&](const Point_2& z) {
    const std::complex<double> w(CGAL::to_double(z.x()), CGAL::to_double(z.y()));
    return (w - a) / (1.0 - std::conj(a) * w);
  };
  const std::complex<double> mq = move(q), mr = move(r);
  return Poincare_disk_internal::Circle_coefficients<double>(0.0, 0.0, mq.real(), mq.imag(), mr.real(), mr.imag());
}

/// Approximate cosh^2 of the hyperbolic circumradius (+infinity if the circumcircle is not compact), in double.
/// Used only to order the work queue.
template <class Point_2>
double approximate_cosh2_circumradius(const Point_2& p, const Point_2& q, const Point_2& r)
{
  const Poincare_disk_internal::Circle_coefficients<double> cc(
      CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(q.x()), CGAL::to_double(q.y()),
      CGAL::to_double(r.x()), CGAL::to_double(r.y()));
  const double delta = cc.delta();
  if(!(delta > 0)) return std::numeric_limits<double>::infinity();
  return cc.cosh2_numerator() / delta;
}

/// Approximate sinh^2 of the hyperbolic circumradius (+infinity if not compact), without cancellation.
template <class Point_2>
double approximate_sinh2_circumradius(const Point_2& p, const Point_2& q, const Point_2& r)
{
  const Poincare_disk_internal::Circle_coefficients<double> cc = translated_circle(p, q, r);
  const double delta = cc.delta();
  if(!(delta > 0)) return std::numeric_limits<double>::infinity();
  return std::max(0.0, cc.sinh2_numerator() / delta);
}

/// Approximate hyperbolic circumradius (+infinity if not compact).
template <class Point_2>
double approximate_circumradius(const Point_2& p, const Point_2& q, const Point_2& r)
{
  const double s2 = approximate_sinh2_circumradius(p, q, r);
  if(!std::isfinite(s2)) return s2;
  return std::asinh(std::sqrt(s2));
}

/// the shared layer's disk geometry in double precision
typedef Hyperbolic_surface_2::Disk_geometry<CGAL::Simple_cartesian<double> > Double_disk_geometry;

/// A(p, q) = sinh^2(d(p, q) / 2) in double (+infinity if a rounded point is not in the open disk).
template <class Point_2>
double approximate_sinh2_half_distance(const Point_2& p, const Point_2& q)
{
  return Double_disk_geometry::sinh2_half_distance(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                                   CGAL::to_double(q.x()), CGAL::to_double(q.y()));
}

/// Approximate hyperbolic distance.
template <class Point_2>
double approximate_distance(const Point_2& p, const Point_2& q)
{
  typedef Double_disk_geometry::Point_2 P;
  return Double_disk_geometry::distance(P(CGAL::to_double(p.x()), CGAL::to_double(p.y())),
                                        P(CGAL::to_double(q.x()), CGAL::to_double(q.y())));
}

/// Approximate central angle of the shortest edge of pqr (0 if the circumcircle is not compact), radians:
/// sin^2(alpha/2) = A_min / sinh^2 h, both without cancellation (A = |p - q|^2 / (n_p n_q); sinh^2 h from
/// `approximate_sinh2_circumradius`; the former cosh^2 h - 1 gave 0 for faces with edges of 1e-5).
template <class Point_2>
double approximate_central_angle(const Point_2& p, const Point_2& q, const Point_2& r)
{
  const double sh2 = approximate_sinh2_circumradius(p, q, r);
  if(!std::isfinite(sh2) || !(sh2 > 0)) return 0.0;
  const double a = std::min({approximate_sinh2_half_distance(p, q), approximate_sinh2_half_distance(q, r),
                             approximate_sinh2_half_distance(r, p)});
  const double s2 = std::min(1.0, a / sh2);
  return 2.0 * std::asin(std::sqrt(s2));
}

} // namespace internal
} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_INTERNAL_EXACT_QUALITY_H
