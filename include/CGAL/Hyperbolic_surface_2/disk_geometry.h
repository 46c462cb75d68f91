// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Floating-point constructions in the Poincare disk that the surface layer and its users need on charts:
// distances, the isometry that puts a segment in standard position, points along geodesics, the apex of a
// triangle laid out on a given base, the Klein map. Points are `K::Point_2`, isometries
// `CGAL::Poincare_disk_isometry_2<K>`, for a kernel `K` with a floating-point `FT` (double, long double).
#ifndef CGAL_HYPERBOLIC_SURFACE_2_DISK_GEOMETRY_H
#define CGAL_HYPERBOLIC_SURFACE_2_DISK_GEOMETRY_H

#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>
#include <CGAL/Poincare_disk_isometry_2.h>

#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Hyperbolic_surface_2 {

/*!
  \ingroup PkgHyperbolicSurface2Ref
  Floating-point geometry of the Poincare disk on the points of a kernel `K` (static functions). Accuracy:
  a point at hyperbolic distance d from the origin carries an absolute error of about 1e-16 e^d in double
  precision: use these on charts near the origin.
*/
template <class K>
struct Disk_geometry
{
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef CGAL::Poincare_disk_isometry_2<K> Isometry_2;

  static FT squared_norm(const Point_2& p) { return p.x() * p.x() + p.y() * p.y(); }

  /// sinh^2(d / 2) = |p - q|^2 / ((1 - |p|^2)(1 - |q|^2)) for the hyperbolic distance d of (px, py) and
  /// (qx, qy), without cancellation and without a transcendental function (monotone in d: compare these
  /// instead of distances); infinity when a point is not in the open disk
  static FT sinh2_half_distance(const FT& px, const FT& py, const FT& qx, const FT& qy)
  {
    const FT den = (FT(1) - (px * px + py * py)) * (FT(1) - (qx * qx + qy * qy));
    if(!(den > 0)) return std::numeric_limits<FT>::infinity();
    const FT dx = px - qx, dy = py - qy;
    return (dx * dx + dy * dy) / den;
  }
  static FT sinh2_half_distance(const Point_2& p, const Point_2& q)
  { return sinh2_half_distance(p.x(), p.y(), q.x(), q.y()); }

  /// hyperbolic distance, 2 asinh sqrt(sinh^2(d / 2)) (accurate for small distances); infinity when a point
  /// is not in the open disk
  static FT distance(const Point_2& p, const Point_2& q)
  {
    using std::sqrt; using std::asinh;
    return 2 * asinh(sqrt(sinh2_half_distance(p, q)));
  }

  /// hyperbolic distance from the origin, 2 atanh |z|
  static FT distance_to_origin(const Point_2& z)
  {
    using std::sqrt; using std::atanh;
    const FT r = sqrt(squared_norm(z));
    if(!(r < 1)) return std::numeric_limits<FT>::infinity();
    return 2 * atanh(r);
  }

  /// the point of the positive real axis at hyperbolic distance `s` from the origin
  static Point_2 point_on_real_axis(FT s) { using std::tanh; return Point_2(tanh(s / 2), FT(0)); }

  /// the isometry taking `a` to the origin and `b` (distinct from `a`) to the positive real axis
  static Isometry_2 standard_position(const Point_2& a, const Point_2& b)
  {
    using std::sqrt;
    const Isometry_2 t = Isometry_2::translation_to_origin(a);
    const Point_2 bb = t.apply_unchecked(b);
    const FT r = sqrt(squared_norm(bb));
    if(!(r > 0)) return t;
    // the rotation z -> w z, w = conj(bb) / r, as alpha z / conj(alpha) with alpha = r + x - i y (a multiple
    // of 1 + w) or alpha = -y + i (r - x) (a multiple of i (1 - w)), whichever does not cancel: 1 + cos for
    // an angle near pi loses all digits of the rotation (1e-8 rad for a direction 1e-4 rad off the negative axis)
    // (alpha scaled to modulus 1: determinant 1, so long products neither overflow nor underflow)
    const FT x = bb.x(), y = bb.y();
    const FT ar = x >= FT(0) ? r + x : -y, ai = x >= FT(0) ? -y : r - x;
    const FT n = sqrt(ar * ar + ai * ai);
    return Isometry_2(ar / n, ai / n, FT(0), FT(0)) * t;
  }

  /// the orientation-preserving isometry taking p1 to p2 and the geodesic ray p1 q1 to the ray p2 q2 (q1 to
  /// q2 when d(p1, q1) = d(p2, q2))
  static Isometry_2 isometry_from_pairs(const Point_2& p1, const Point_2& q1, const Point_2& p2, const Point_2& q2)
  {
    return standard_position(p2, q2).inverse() * standard_position(p1, q1);
  }

  /// the point at hyperbolic distance `s` from `a` on the geodesic ray from `a` through `b`
  static Point_2 point_along(const Point_2& a, const Point_2& b, FT s)
  {
    return standard_position(a, b).inverse().apply_unchecked(point_on_real_axis(s));
  }

  /// the apex C of the counterclockwise triangle (A, B, C) with |BC| = a, |CA| = b, given A and B
  /// (|AB| = c is only used for the angle at A)
  static Point_2 apex(const Point_2& A, const Point_2& B, FT a, FT b, FT c)
  {
    using std::tanh; using std::cos; using std::sin;
    const FT alpha = corner_angle(a, b, c);
    const FT r = tanh(b / 2);
    return standard_position(A, B).inverse().apply_unchecked(Point_2(r * cos(alpha), r * sin(alpha)));
  }

  /// The lift of a triangle with side lengths `l0` = |z0 z1|, `l1` = |z1 z2|, `l2` = |z2 z0|: z0, z1, z2
  /// counterclockwise, barycentre (`barycenter()`) at the origin (the chart of a face,
  /// `Hyperbolic_surface_triangulation::chart()`). In the precision of `FT` (e.g. long double lengths with a
  /// long-double kernel). Cost: O(1).
  static std::array<Point_2, 3> triangle_chart(FT l0, FT l1, FT l2)
  {
    const Point_2 a(0, 0), b = point_on_real_axis(l0);
    const Point_2 c = apex(a, b, l1, l2, l0);
    const Isometry_2 t = Isometry_2::translation_to_origin(barycenter(a, b, c));
    return {{t.apply_unchecked(a), t.apply_unchecked(b), t.apply_unchecked(c)}};
  }

  /// Klein image 2z / (1 + |z|^2) (geodesics are straight lines there)
  static Point_2 to_klein(const Point_2& z)
  {
    const FT s = FT(2) / (FT(1) + squared_norm(z));
    return Point_2(s * z.x(), s * z.y());
  }

  /// Poincare image k / (1 + sqrt(1 - |k|^2)) of a Klein point
  static Point_2 from_klein(const Point_2& k)
  {
    using std::sqrt;
    const FT w = FT(1) - squared_norm(k);
    const FT s = FT(1) / (FT(1) + sqrt(w > 0 ? w : FT(0)));
    return Point_2(s * k.x(), s * k.y());
  }

  /// the hyperbolic barycentre of three points (normalized sum of their hyperboloid lifts), in the disk
  static Point_2 barycenter(const Point_2& p, const Point_2& q, const Point_2& r)
  {
    using std::sqrt;
    FT X = 0, Y = 0, T = 0;
    for(const Point_2* z : {&p, &q, &r}) {
      const FT n = squared_norm(*z), d = FT(1) - n;
      X += 2 * z->x() / d; Y += 2 * z->y() / d; T += (FT(1) + n) / d;
    }
    const FT m = sqrt(T * T - X * X - Y * Y); // -<S,S> > 0 for a sum of future timelike vectors
    X /= m; Y /= m; T /= m;
    return Point_2(X / (FT(1) + T), Y / (FT(1) + T));
  }
};

} // namespace Hyperbolic_surface_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_2_DISK_GEOMETRY_H
