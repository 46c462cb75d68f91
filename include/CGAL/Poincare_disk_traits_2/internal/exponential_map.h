// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Points along geodesics and the exponential / logarithm maps (functors of Poincare_disk_traits_2): a vector at
// a point a is a tangent vector at a in Poincare coordinates, scaled to hyperbolic length.
#ifndef CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_EXPONENTIAL_MAP_H
#define CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_EXPONENTIAL_MAP_H

#include <CGAL/Poincare_disk_isometry_2.h>
#include <CGAL/Poincare_disk_traits_2/internal/checks.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Poincare_disk_internal {

/// log_a(b) for two points; the kernel's constructions for the other argument lists.
template <class K>
class Construct_vector_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Vector_2 result_type;
  Vector_2 operator()(const Point_2& a, const Point_2& b) const
  {
    check_point_in_disk(a, "Construct_vector_2"); check_point_in_disk(b, "Construct_vector_2");
    typedef Simple_cartesian<double>::Point_2 P;
    typedef Poincare_disk_isometry_2<Simple_cartesian<double> > Iso;
    const P ad(CGAL::to_double(a.x()), CGAL::to_double(a.y()));
    // the translation taking a to 0 has a positive real derivative at a: directions are kept
    const P b0 = Iso::translation_to_origin(ad).apply_unchecked(P(CGAL::to_double(b.x()), CGAL::to_double(b.y())));
    const double r = std::hypot(b0.x(), b0.y());
    if(r == 0) return Vector_2(FT(0), FT(0));
    const double f = 2 * std::atanh((std::min)(r, 1.0 - 1e-16)) / r;
    return Vector_2(FT(f * b0.x()), FT(f * b0.y()));
  }
  template <class... Args>
  Vector_2 operator()(const Args&... args) const { return typename K::Construct_vector_2()(args...); }
};

/// exp_a(v); throws `Poincare_disk_domain_error` if the result rounds onto the unit circle (|v| > ~37).
template <class K>
class Construct_translated_point_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Vector_2 Vector_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& a, const Vector_2& v) const
  {
    check_point_in_disk(a, "Construct_translated_point_2");
    typedef Simple_cartesian<double>::Point_2 P;
    typedef Poincare_disk_isometry_2<Simple_cartesian<double> > Iso;
    const double vx = CGAL::to_double(v.x()), vy = CGAL::to_double(v.y()), len = std::hypot(vx, vy);
    if(len == 0) return a;
    const double f = std::tanh(len / 2) / len;
    const P ad(CGAL::to_double(a.x()), CGAL::to_double(a.y()));
    const P r = Iso::translation_from_origin(ad).apply_unchecked(P(f * vx, f * vy));
    const Point_2 res(FT(r.x()), FT(r.y()));
    check_point_in_disk(res, "Construct_translated_point_2 (result)");
    return res;
  }
};

/// The point of the geodesic segment pq at distance t d(p, q) from p (0 <= t <= 1): exp_p(t log_p(q)); rounded
/// (through double). Throws `Poincare_disk_domain_error` if the result rounds onto the unit circle.
template <class K>
class Construct_hyperbolic_point_on_segment_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& p, const Point_2& q, const FT& t) const
  {
    const typename K::Vector_2 v = Construct_vector_2<K>()(p, q);
    return Construct_translated_point_2<K>()(p, typename K::Vector_2(t * v.x(), t * v.y()));
  }
};

} // namespace Poincare_disk_internal
} // namespace CGAL

#endif
