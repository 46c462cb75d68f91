// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The polynomials behind the Poincare disk predicates, written once for any number type NT (double with
// interval arithmetic, Interval_nt, Gmpq, lazy exact numbers). Every predicate of Poincare_disk_traits_2 is the
// sign of one of these polynomials in the Poincare coordinates of its arguments (DESIGN.md, "Predicates").
#ifndef CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_POLYNOMIALS_H
#define CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_POLYNOMIALS_H

namespace CGAL {
namespace Poincare_disk_internal {

/// 1 + |z|^2: the third homogeneous coordinate of the Klein (and hyperboloid) lift (2x, 2y, 1 + |z|^2).
template <class NT>
NT lift_w(const NT& x, const NT& y) { return NT(1) + x * x + y * y; }

/// 1 - |z|^2 (positive inside the disk)
template <class NT>
NT lift_n(const NT& x, const NT& y) { return NT(1) - x * x - y * y; }

/// Klein orientation: det[[x_p, y_p, w_p], [x_q, y_q, w_q], [x_r, y_r, w_r]], w = 1 + |z|^2.
/// Positive iff r is to the left of the oriented geodesic from p to q.
template <class NT>
NT klein_orientation_det(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry)
{
  const NT wp = lift_w(px, py), wq = lift_w(qx, qy), wr = lift_w(rx, ry);
  return wp * (qx * ry - rx * qy) - wq * (px * ry - rx * py) + wr * (px * qy - qx * py);
}

/// Klein x-comparison: sign of x_p (1 + |q|^2) - x_q (1 + |p|^2) = sign of (Klein x of p - Klein x of q).
template <class NT>
NT klein_x_difference(const NT& px, const NT& py, const NT& qx, const NT& qy)
{
  return px * lift_w(qx, qy) - qx * lift_w(px, py);
}

/// A(p, q) (1 - |p|^2)(1 - |q|^2) = |p - q|^2: numerator of sinh^2(d(p,q)/2).
template <class NT>
NT squared_euclidean(const NT& px, const NT& py, const NT& qx, const NT& qy)
{
  const NT dx = px - qx, dy = py - qy;
  return dx * dx + dy * dy;
}

/// Coefficients of the Euclidean circle A (x^2 + y^2) + B x + C y + G = 0 through p, q, r
/// (expansion of det[[x^2 + y^2, x, y, 1], [|p|^2, px, py, 1], [|q|^2, ...], [|r|^2, ...]] = 0).
/// A is the Euclidean orientation determinant of (p, q, r). The plane through the hyperboloid lifts of p, q, r is
/// <N, X> = A - G with Minkowski normal N = (B, C, -(A + G)), so that
///   the circle is compact in H^2      <=>  Delta = (A + G)^2 - B^2 - C^2 > 0,
///   cosh^2 h = (A - G)^2 / Delta,      sinh^2 h = (B^2 + C^2 - 4 A G) / Delta   (h: hyperbolic radius),
///   hyperbolic centre = -sign(A + G) (B, C) / (sqrt(Delta) + |A + G|).
template <class NT>
struct Circle_coefficients
{
  NT A, B, C, G;

  Circle_coefficients(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry)
  {
    const NT sp = px * px + py * py, sq = qx * qx + qy * qy, sr = rx * rx + ry * ry;
    // 2x2 minors of the (x, y) columns and of the (s, .) columns
    const NT mxy = (qx * ry - rx * qy) - (px * ry - rx * py) + (px * qy - qx * py); // det[[x,y,1]]
    const NT msy = sp * (qy - ry) - sq * (py - ry) + sr * (py - qy);                // det[[s,y,1]]
    const NT msx = sp * (qx - rx) - sq * (px - rx) + sr * (px - qx);                // det[[s,x,1]]
    const NT msxy = sp * (qx * ry - rx * qy) - sq * (px * ry - rx * py) + sr * (px * qy - qx * py); // det[[s,x,y]]
    A = mxy;
    B = -msy;
    C = msx;
    G = -msxy;
  }

  NT delta() const { const NT s = A + G; return s * s - B * B - C * C; }
  NT cosh2_numerator() const { const NT d = A - G; return d * d; }          // times 1/delta
  NT sinh2_numerator() const { return B * B + C * C - NT(4) * A * G; }       // times 1/delta
};

/// Encroachment: positive iff s is strictly inside the hyperbolic disk with diameter pq:
///   |p - q|^2 (1 - |s|^2) - |s - p|^2 (1 - |q|^2) - |s - q|^2 (1 - |p|^2).
template <class NT>
NT diametral_disk_polynomial(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& sx, const NT& sy)
{
  return squared_euclidean(px, py, qx, qy) * lift_n(sx, sy)
       - squared_euclidean(sx, sy, px, py) * lift_n(qx, qy)
       - squared_euclidean(sx, sy, qx, qy) * lift_n(px, py);
}

/// d(p, q) vs d(p, r): sign of |p - q|^2 (1 - |r|^2) - |p - r|^2 (1 - |q|^2)  (the factor 1 - |p|^2 cancels).
template <class NT>
NT distance_comparison_polynomial(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry)
{
  return squared_euclidean(px, py, qx, qy) * lift_n(rx, ry) - squared_euclidean(px, py, rx, ry) * lift_n(qx, qy);
}

/// d(p, q) vs d(r, s): sign of |p - q|^2 (1 - |r|^2)(1 - |s|^2) - |r - s|^2 (1 - |p|^2)(1 - |q|^2).
template <class NT>
NT distance_comparison_polynomial_4(const NT& px, const NT& py, const NT& qx, const NT& qy,
                                    const NT& rx, const NT& ry, const NT& sx, const NT& sy)
{
  return squared_euclidean(px, py, qx, qy) * lift_n(rx, ry) * lift_n(sx, sy)
       - squared_euclidean(rx, ry, sx, sy) * lift_n(px, py) * lift_n(qx, qy);
}

} // namespace Poincare_disk_internal
} // namespace CGAL

#endif
