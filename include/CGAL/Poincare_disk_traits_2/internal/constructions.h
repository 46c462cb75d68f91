// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers of the constructions of Poincare_disk_traits_2: square roots on any field type (exact where the
// number type has one, rounded through double otherwise), and the geodesic segment / arc type.
#ifndef CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_CONSTRUCTIONS_H
#define CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_CONSTRUCTIONS_H

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <cmath>
#include <ostream>
#include <type_traits>

namespace CGAL {
namespace Poincare_disk_internal {

/// true when FT has an exact (or, for double, the native) square root
template <class FT>
struct Has_sqrt
  : std::integral_constant<bool,
        !std::is_same<typename Algebraic_structure_traits<FT>::Sqrt, Null_functor>::value> {};

/// sqrt(x) in FT: FT's own square root where it has one, else rounded through double.
template <class FT>
FT sqrt_of(const FT& x)
{
  if constexpr(Has_sqrt<FT>::value) {
    return CGAL::sqrt(x);
  } else {
    return FT(std::sqrt(CGAL::to_double(x)));
  }
}

} // namespace Poincare_disk_internal

/*!
  \ingroup PkgPoincareDiskTraits2Ref
  A geodesic segment of the Poincare disk: the arc between `source()` and `target()` of the circle orthogonal to
  the unit circle through both points, or, when the two points are collinear with the origin, the straight
  segment between them (`is_line_segment()`). Endpoints may be ideal points (on the unit circle) for geodesic
  lines and rays (Voronoi edges, bisectors). The supporting circle is rational in the endpoints.
*/
template <class K>
class Poincare_disk_geodesic_segment_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Circle_2 Circle_2;

  Poincare_disk_geodesic_segment_2() : line_(true) {}

  Poincare_disk_geodesic_segment_2(const Point_2& s, const Point_2& t) : s_(s), t_(t)
  {
    // circle x^2 + y^2 + D x + E y + 1 = 0 through s and t (orthogonal to the unit circle)
    const FT det = s.x() * t.y() - s.y() * t.x();
    line_ = (det == FT(0));
    if(!line_) {
      const FT ws = FT(1) + s.x() * s.x() + s.y() * s.y(), wt = FT(1) + t.x() * t.x() + t.y() * t.y();
      const FT D = (wt * s.y() - ws * t.y()) / det, E = (ws * t.x() - wt * s.x()) / det;
      center_ = Point_2(-D / FT(2), -E / FT(2));
      sq_radius_ = center_.x() * center_.x() + center_.y() * center_.y() - FT(1);
    }
  }

  const Point_2& source() const { return s_; }
  const Point_2& target() const { return t_; }
  /// true for a piece of a diameter (a Euclidean straight segment)
  bool is_line_segment() const { return line_; }
  /// the centre of the supporting circle (precondition: `!is_line_segment()`)
  const Point_2& center() const { return center_; }
  /// the squared radius of the supporting circle (precondition: `!is_line_segment()`)
  const FT& squared_radius() const { return sq_radius_; }
  /// the supporting circle, oriented counterclockwise (precondition: `!is_line_segment()`)
  Circle_2 supporting_circle() const { return Circle_2(center_, sq_radius_); }
  /// the same geodesic segment traversed the other way
  Poincare_disk_geodesic_segment_2 opposite() const { return Poincare_disk_geodesic_segment_2(t_, s_); }

  friend std::ostream& operator<<(std::ostream& os, const Poincare_disk_geodesic_segment_2& g)
  {
    return os << "geodesic(" << g.s_ << " -> " << g.t_ << ")";
  }

private:
  Point_2 s_, t_;
  bool line_;
  Point_2 center_;
  FT sq_radius_;
};

} // namespace CGAL

#endif
