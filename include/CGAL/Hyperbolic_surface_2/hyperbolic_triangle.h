// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hyperbolic triangles given by their side lengths: corner angles, area, the third side from two sides and
// the included angle. Written once for every package (Ricci flow, shortest words, surface meshing), in forms
// that do not cancel: half-angle formulas instead of acos of the cosine law, sinh^2 (d/2) instead of cosh d.
#ifndef CGAL_HYPERBOLIC_SURFACE_2_HYPERBOLIC_TRIANGLE_H
#define CGAL_HYPERBOLIC_SURFACE_2_HYPERBOLIC_TRIANGLE_H

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Hyperbolic_surface_2 {

/// \ingroup PkgHyperbolicSurface2Ref
/// true if `a`, `b`, `c` are finite, positive and satisfy the strict triangle inequalities (a hyperbolic
/// triangle with these side lengths exists).
template <class FT>
bool is_hyperbolic_triangle(FT a, FT b, FT c)
{
  using std::isfinite;
  return a > 0 && b > 0 && c > 0 && isfinite(a) && isfinite(b) && isfinite(c) &&
         a < b + c && b < a + c && c < a + b;
}

/// \ingroup PkgHyperbolicSurface2Ref
/// The half perimeter s = (a+b+c)/2 of a triangle with side lengths `a`, `b`, `c` (of any geometry) and the
/// differences s-a, s-b, s-c, in Kahan's order (W. Kahan, "Miscalculating area and angles of a needle-like
/// triangle", 2014): with the sides sorted, p >= q >= r, 2(s-p) = r - (p - q), 2(s-q) = r + (p - q),
/// 2(s-r) = p + (q - r), where p - q is exact whenever it cancels. In floating point each result is within a
/// few ulps of its exact value for these inputs, also when the triangle is nearly flat (s - p tiny), where
/// s - p computed from a rounded s keeps only an absolute error of about eps s (the angles of the half-angle
/// formulas then lose up to half their digits: 1e-6 in double, measured). A violated triangle inequality
/// gives a negative difference. Cost: O(1).
template <class FT>
void half_perimeter_differences(FT a, FT b, FT c, FT& s, FT& sa, FT& sb, FT& sc)
{
  FT* d[3] = {&sa, &sb, &sc};
  const FT l[3] = {a, b, c};
  int p = 0, q = 1, r = 2; // indices of the sides sorted decreasingly
  if(l[p] < l[q]) std::swap(p, q);
  if(l[q] < l[r]) std::swap(q, r);
  if(l[p] < l[q]) std::swap(p, q);
  const FT pq = l[p] - l[q];
  s = (l[p] + (l[q] + l[r])) / 2;
  *d[p] = (l[r] - pq) / 2;
  *d[q] = (l[r] + pq) / 2;
  *d[r] = (l[p] + (l[q] - l[r])) / 2;
}

/// \ingroup PkgHyperbolicSurface2Ref
/// The angle opposite side `a` of the hyperbolic triangle with sides `a`, `b`, `c`, by the half-angle
/// formula tan(alpha/2) = sqrt(sinh(s-b) sinh(s-c) / (sinh(s) sinh(s-a))), s = (a+b+c)/2: accurate to a few
/// ulps for tiny and needle triangles, where acos of the cosine law loses half the digits. Nearly flat (cap)
/// triangles lose more: s - a is computed from a rounded s, and the angles of caps were measured up to 1.7e-6
/// off in double (`half_perimeter_differences()` does not have that error, and `triangle_area()` uses it; see
/// the user manual, section "Stable formulas", for why this function does not use it yet).
/// Degenerate triangles (an equality in the triangle inequality) give 0 or pi; the result is NaN when the
/// inequality is violated. Cost: O(1).
template <class FT>
FT corner_angle(FT a, FT b, FT c)
{
  using std::sinh; using std::atan2; using std::sqrt;
  const FT s = (a + b + c) / 2;
  const FT sa = s - a, sb = s - b, sc = s - c;
  if(sa < 0 || sb < 0 || sc < 0) return FT(std::nan(""));
  return 2 * atan2(sqrt(sinh(sb) * sinh(sc)), sqrt(sinh(s) * sinh(sa)));
}

/// \ingroup PkgHyperbolicSurface2Ref
/// The area pi - (alpha + beta + gamma) of the hyperbolic triangle with sides `a`, `b`, `c`, by the
/// hyperbolic l'Huilier formula tan(A/4)^2 = tanh(s/2) tanh((s-a)/2) tanh((s-b)/2) tanh((s-c)/2), the
/// differences from `half_perimeter_differences()`, which keeps its relative accuracy for small, needle and
/// nearly flat triangles (pi minus the angle sum does not): at most 5.6e-16 relative on 40,000 caps and
/// needles, where s - a from a rounded s gave relative errors up to 1 (test
/// `flat_triangle_differences_and_areas_are_accurate`). Cost: O(1).
template <class FT>
FT triangle_area(FT a, FT b, FT c)
{
  using std::tanh; using std::atan; using std::sqrt;
  FT s, sa, sb, sc;
  half_perimeter_differences(a, b, c, s, sa, sb, sc);
  if(sa < 0 || sb < 0 || sc < 0) return FT(std::nan(""));
  return 4 * atan(sqrt(tanh(s / 2) * tanh(sa / 2) * tanh(sb / 2) * tanh(sc / 2)));
}

/// \ingroup PkgHyperbolicSurface2Ref
/// The side opposite the angle `theta` between sides `b` and `c`: the cosine law in its haversine form
/// sinh^2(a/2) = sinh^2((b-c)/2) + sinh(b) sinh(c) sin^2(theta/2), exact in the limit of small a.
/// `theta` may exceed pi (the length is then that of the angle 2 pi - theta). Cost: O(1).
template <class FT>
FT third_side(FT b, FT c, FT theta)
{
  using std::sinh; using std::sin; using std::asinh; using std::sqrt;
  const FT h = sinh((b - c) / 2), st = sin(theta / 2);
  return 2 * asinh(sqrt(h * h + sinh(b) * sinh(c) * st * st));
}

/// \ingroup PkgHyperbolicSurface2Ref
/// The length of the other diagonal of the quadrilateral formed by two triangles glued along an edge of
/// length `e`: triangle (e, a1, b1) with `a1` the side at the edge's source, and triangle (e, a2, b2) on the
/// other side with `a2` at the same source. This is the new edge length of an intrinsic (metric-preserving)
/// edge flip. The quadrilateral must be convex at the source (angle sum below pi is not required: the
/// diagonal is always the geodesic through the union of the two triangles' corners at the source, which is
/// correct when the flipped edge lies in the quadrilateral, i.e. both angles at the edge's ends sum to < pi).
template <class FT>
FT flipped_diagonal(FT e, FT a1, FT b1, FT a2, FT b2)
{
  const FT t = corner_angle(b1, e, a1) + corner_angle(b2, e, a2);
  return third_side(a1, a2, t);
}

} // namespace Hyperbolic_surface_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_2_HYPERBOLIC_TRIANGLE_H
