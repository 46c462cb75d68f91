// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Per-triangle formulas of the discrete Ricci flow (thesis Section 2.2.3): cosine laws of the three
// background geometries, angle derivatives with respect to the edge lengths, and the length functions of the
// schemes (vertex scaling, circle packing with intersection angles, inversive distance) with their derivatives
// with respect to the conformal factors u.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_TRIANGLE_GEOMETRY_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_TRIANGLE_GEOMETRY_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

/// The quadrilateral a b c d of the Euclidean triangles (a b c) and (b a d) glued along a b, unfolded in the
/// plane in long double: a at the origin, b on the positive x-axis, c to the left of a -> b, d to the right
/// (a degenerate triangle gets its apex on the axis). The one formula of a metric-preserving (geometric) flip:
/// the flow's initial Delaunay flips and their replay by the remesher's map to the input both use it.
inline std::array<std::array<long double, 2>, 4> unfold_euclidean_quadrilateral(double ab, double bc, double ca,
                                                                              double ad, double db)
{
  const long double lab = ab;
  auto apex = [lab](long double from_a, long double from_b, long double side) {
    const long double x = (lab * lab + from_a * from_a - from_b * from_b) / (2 * lab);
    const long double y2 = from_a * from_a - x * x;
    return std::array<long double, 2>{{x, side * std::sqrt(y2 > 0 ? y2 : 0.0L)}};
  };
  return {{{{0, 0}}, {{lab, 0}}, apex(ca, bc, 1), apex(ad, db, -1)}};
}

/// the length of the diagonal c d of that quadrilateral (the new edge of the geometric flip of a b)
inline double euclidean_flip_diagonal(double ab, double bc, double ca, double ad, double db)
{
  const std::array<std::array<long double, 2>, 4> p = unfold_euclidean_quadrilateral(ab, bc, ca, ad, db);
  const long double dx = p[2][0] - p[3][0], dy = p[2][1] - p[3][1];
  return double(std::sqrt(dx * dx + dy * dy));
}

/// atan2(y, x) for y >= 0 (an angle in [0, pi]): the corner angles of the flow's faces, atan2(sqrt(Q), 2 num),
/// 3 per face and evaluation, were the largest share of libm in a flow (10% at 22k faces). t = min(y, |x|) /
/// max(y, |x|) in [0, 1] is split at c = k / 16 (k = floor(16 t)): atan t = atan c + atan r with
/// r = (num - c den) / (den + c num) in (-1/16, 1/16), atan c in double-double (k = 0 .. 16; the constants are
/// atan(k / 16) to 200 bits, rounded to a double and the double of the remainder) and atan r by its Taylor
/// series to r^13 (the first omitted term is below 2^-60 |r|); then the reflections pi / 2 -+ and pi -.
/// Within 1.5 ulp of atan2l (test `upper_half_plane_angle_matches_long_double`: at most 1.43 ulp on 10^6
/// inputs, among them t near every k / 16 and near 1, y / x down to 1e-17; 1.49 ulp on 4M inputs in a scratch
/// run); glibc's atan2 is correctly rounded to 0.52 ulp but 1.6 times as slow. y = 0, magnitudes beyond [1e-290, 1e300], infinities and NaN go to
/// std::atan2.
inline double upper_half_plane_angle(double y, double x)
{
  static constexpr double atan_hi[17] = {
    0x0.0p+0, 0x1.ff55bb72cfdeap-5, 0x1.fd5ba9aac2f6ep-4, 0x1.7b97b4bce5b02p-3, 0x1.f5b75f92c80ddp-3,
    0x1.362773707ebccp-2, 0x1.6f61941e4def1p-2, 0x1.a64eec3cc23fdp-2, 0x1.dac670561bb4fp-2, 0x1.0657e94db30d0p-1,
    0x1.1e00babdefeb4p-1, 0x1.345f01cce37bbp-1, 0x1.4978fa3269ee1p-1, 0x1.5d58987169b18p-1, 0x1.700a7c5784634p-1,
    0x1.819d0b7158a4dp-1, 0x1.921fb54442d18p-1};
  static constexpr double atan_lo[17] = {
    0x0.0p+0, -0x1.c934d86d23f1dp-60, -0x1.cd37686760c17p-59, 0x1.347b0b4f881cap-58, 0x1.8ab6e3cf7afbdp-57,
    -0x1.963a544b672d8p-57, -0x1.c63aae6f6e918p-56, -0x1.24dec1b50b7ffp-56, 0x1.a2b7f222f65e2p-56,
    -0x1.d5b495f6349e6p-56, -0x1.928df287a668fp-58, 0x1.1021137c71102p-55, 0x1.2419a87f2a458p-56,
    0x1.0028e4bc5e7cap-57, -0x1.8c34d25aadef6p-56, -0x1.bf76229d3b917p-56, 0x1.1a62633145c07p-55};
  const double ax = std::abs(x);
  // den + c num below must not overflow, nor c den lose bits to subnormals
  if(!(y > 0) || !(ax < 1e300) || !(y < 1e300) || !(y > 1e-290 || ax > 1e-290)) return std::atan2(y, x);
  const bool steep = y > ax;
  const double num = steep ? ax : y, den = steep ? y : ax; // t = num / den in [0, 1]
  const int k = int(num / den * 16);        // t in [k / 16, (k + 1) / 16)
  const double c = k * 0.0625;
  const double r = (num - c * den) / (den + c * num); // atan t = atan c + atan r, |r| < 1 / 16
  const double r2 = r * r;
  const double p = r * r2 * (-1.0 / 3 + r2 * (1.0 / 5 + r2 * (-1.0 / 7 + r2 * (1.0 / 9 + r2 * (-1.0 / 11 + r2 * (1.0 / 13))))));
  const double a = atan_hi[k] + (r + (p + atan_lo[k])); // atan t in [0, pi / 4]
  const double pi_2_hi = 0x1.921fb54442d18p+0, pi_2_lo = 0x1.1a62633145c07p-54;
  const double pi_hi = 0x1.921fb54442d18p+1, pi_lo = 0x1.1a62633145c07p-53;
  if(steep) return x >= 0 ? (pi_2_hi - a) + pi_2_lo : (pi_2_hi + a) + pi_2_lo;
  return x >= 0 ? a : (pi_hi - a) + pi_lo;
}

inline double clamp_cos(double c) { return c < -1.0 ? -1.0 : (c > 1.0 ? 1.0 : c); }

// g(l) in the angle derivatives: l (E2), sinh l (H2), sin l (S2)
inline double length_sine(Background_geometry geo, double l)
{
  switch(geo) {
    case Background_geometry::EUCLIDEAN: return l;
    case Background_geometry::HYPERBOLIC: return std::sinh(l);
    default: return std::sin(l);
  }
}

/// The corner angles only (same conventions as `triangle_angles()`); false for a degenerate triangle. The
/// half perimeter differences s - l_i come from `CGAL::Hyperbolic_surface_2::half_perimeter_differences()`
/// (Kahan's order), so that nearly flat triangles keep their angles to a few ulps: with s - l_i from a rounded
/// s the angles lost up to 1.3e-6 (test `triangle_angles_are_accurate_on_flat_triangles`; anchor.off stretched
/// 1000 times ended with a face of angles 4e-7 and pi - 8e-7, and the returned metric's max |K| differed from
/// the flow's by 1e-5).
inline bool triangle_angles_only(Background_geometry geo, const double l[3], double theta[3])
{
  for(int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if(!(l[i] < l[j] + l[k])) { theta[i] = CGAL_PI; theta[j] = 0; theta[k] = 0; return false; }
  }
  if(geo == Background_geometry::SPHERICAL && !(l[0] + l[1] + l[2] < 2 * CGAL_PI)) {
    theta[0] = theta[1] = theta[2] = CGAL_PI;
    return false;
  }
  double s, d[3], f[3];
  CGAL::Hyperbolic_surface_2::half_perimeter_differences(l[0], l[1], l[2], s, d[0], d[1], d[2]);
  const double fs = length_sine(geo, s);
  for(int i = 0; i < 3; ++i) f[i] = length_sine(geo, (std::max)(d[i], 0.0));
  for(int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    theta[i] = 2 * std::atan2(std::sqrt(f[j] * f[k]), std::sqrt(fs * f[i]));
  }
  return true;
}

/// Corner angles and their derivatives of a triangle with edge lengths `l[0..2]`, `l[i]` opposite corner i.
/// `theta[i]`: angle at corner i (cosine law). `dtheta[i][j]` = d theta_i / d l_j:
///   d theta_i / d l_i = g(l_i) / A,  d theta_i / d l_j = -g(l_i) cos theta_k / A  (i, j, k distinct),
/// with g = id, sinh, sin and A = g(l_j) g(l_k) sin theta_i (symmetric in i by the sine law).
/// A triangle violating the triangle inequality gets the extended angles (pi, 0, 0) (Luo's C^1 convex
/// extension) and zero derivatives. Returns false for such a degenerate triangle.
inline bool triangle_angles(Background_geometry geo, const double l[3], double theta[3], double dtheta[3][3])
{
  for(int i = 0; i < 3; ++i) for(int j = 0; j < 3; ++j) dtheta[i][j] = 0;
  // the triangle inequalities (and, on the sphere, perimeter < 2 pi), and the half-angle formulas (accurate
  // for angles near 0 and pi, unlike acos of the cosine law):
  // tan^2(theta_i / 2) = f(s - l_j) f(s - l_k) / (f(s) f(s - l_i)), f = id (E^2), sinh (H^2), sin (S^2)
  if(!triangle_angles_only(geo, l, theta)) return false;
  double c[3];
  for(int i = 0; i < 3; ++i) c[i] = std::cos(theta[i]);
  for(int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double A = length_sine(geo, l[j]) * length_sine(geo, l[k]) * std::sin(theta[i]);
    if(!(A > 0)) return true; // flat limit: derivatives left at 0
    const double gi = length_sine(geo, l[i]) / A;
    dtheta[i][i] = gi;
    dtheta[i][j] = -gi * c[k];
    dtheta[i][k] = -gi * c[j];
  }
  return true;
}

/// The derivatives d theta_i / d l_j of `triangle_angles()` from known (non-degenerate) angles.
inline void triangle_angle_derivatives(Background_geometry geo, const double l[3], const double theta[3], double dtheta[3][3])
{
  double c[3], g[3];
  for(int i = 0; i < 3; ++i) { c[i] = std::cos(theta[i]); g[i] = length_sine(geo, l[i]); }
  for(int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double A = g[j] * g[k] * std::sin(theta[i]);
    if(!(A > 0)) { dtheta[i][0] = dtheta[i][1] = dtheta[i][2] = 0; continue; }
    const double gi = g[i] / A;
    dtheta[i][i] = gi;
    dtheta[i][j] = -gi * c[k];
    dtheta[i][k] = -gi * c[j];
  }
}

/// Area of a triangle with lengths l (E2: Heron; H2 and S2: the angle excess |pi - sum of angles|).
inline double triangle_area(Background_geometry geo, const double l[3], const double theta[3])
{
  if(geo == Background_geometry::EUCLIDEAN) { // Heron, with Kahan's differences
    double s, d[3];
    CGAL::Hyperbolic_surface_2::half_perimeter_differences(l[0], l[1], l[2], s, d[0], d[1], d[2]);
    const double a2 = s * d[0] * d[1] * d[2];
    return a2 > 0 ? std::sqrt(a2) : 0.0;
  }
  const double sum = theta[0] + theta[1] + theta[2];
  return geo == Background_geometry::HYPERBOLIC ? CGAL_PI - sum : sum - CGAL_PI;
}

// ------------------------------------------------------------------ vertex scaling
// The "Penner coordinate" lambda of an edge: lambda = l / 2 (E2), sinh(l / 2) (H2), sin(l / 2) (S2).
// Vertex scaling (Bobenko-Pinkall-Springborn 2015): lambda~_ij = e^{(u_i + u_j) / 2} lambda_ij; Ptolemy flips
// act on lambda.
inline double length_from_lambda(Background_geometry geo, double lambda)
{
  switch(geo) {
    case Background_geometry::EUCLIDEAN: return 2 * lambda;
    case Background_geometry::HYPERBOLIC: return 2 * std::asinh(lambda);
    default: return lambda < 1 ? 2 * std::asin(lambda) : CGAL_PI * 2; // no spherical edge: degenerate
  }
}

/// d l_ij / d u_i for vertex scaling at the current length l: l / 2 (E2), tanh(l / 2) (H2), tan(l / 2) (S2).
inline double vertex_scaling_length_derivative(Background_geometry geo, double l)
{
  switch(geo) {
    case Background_geometry::EUCLIDEAN: return 0.5 * l;
    case Background_geometry::HYPERBOLIC: return std::tanh(0.5 * l);
    default: return l < CGAL_PI ? std::tan(0.5 * l) : 0.0;
  }
}

// ------------------------------------------------------------------ circle packings
/// radius from the conformal factor: r = e^u (E2), u = log tanh(r / 2) (H2), u = log tan(r / 2) (S2).
inline double radius_from_u(Background_geometry geo, double u)
{
  switch(geo) {
    case Background_geometry::EUCLIDEAN: return std::exp(u);
    case Background_geometry::HYPERBOLIC: return u < 0 ? 2 * std::atanh(std::exp(u)) : 40.0;
    default: return 2 * std::atan(std::exp(u));
  }
}

inline double u_from_radius(Background_geometry geo, double r)
{
  switch(geo) {
    case Background_geometry::EUCLIDEAN: return std::log(r);
    case Background_geometry::HYPERBOLIC: return std::log(std::tanh(0.5 * r));
    default: return std::log(std::tan(0.5 * r));
  }
}

/// dr / du: r (E2), sinh r (H2), sin r (S2)
inline double radius_derivative(Background_geometry geo, double r)
{
  switch(geo) {
    case Background_geometry::EUCLIDEAN: return r;
    case Background_geometry::HYPERBOLIC: return std::sinh(r);
    default: return std::sin(r);
  }
}

/// Length of an edge between circles of radii ri, rj with inversive distance I (I = cos Phi for an
/// intersection angle Phi, I = 1 tangent): E2 l^2 = ri^2 + rj^2 + 2 I ri rj; H2 cosh l = cosh ri cosh rj +
/// I sinh ri sinh rj; S2 cos l = cos ri cos rj - I sin ri sin rj. Also d l / d ri and d l / d rj.
inline double circle_packing_length(Background_geometry geo, double ri, double rj, double I,
                                    double& dl_dri, double& dl_drj)
{
  double l;
  switch(geo) {
    case Background_geometry::EUCLIDEAN: {
      const double l2 = ri * ri + rj * rj + 2 * I * ri * rj;
      l = l2 > 0 ? std::sqrt(l2) : 0.0;
      dl_dri = l > 0 ? (ri + I * rj) / l : 0.0;
      dl_drj = l > 0 ? (rj + I * ri) / l : 0.0;
      return l;
    }
    case Background_geometry::HYPERBOLIC: {
      const double ch = std::cosh(ri) * std::cosh(rj) + I * std::sinh(ri) * std::sinh(rj);
      l = ch > 1 ? std::acosh(ch) : 0.0;
      const double sl = std::sinh(l);
      dl_dri = sl > 0 ? (std::sinh(ri) * std::cosh(rj) + I * std::cosh(ri) * std::sinh(rj)) / sl : 0.0;
      dl_drj = sl > 0 ? (std::sinh(rj) * std::cosh(ri) + I * std::cosh(rj) * std::sinh(ri)) / sl : 0.0;
      return l;
    }
    default: {
      const double c = clamp_cos(std::cos(ri) * std::cos(rj) - I * std::sin(ri) * std::sin(rj));
      l = std::acos(c);
      const double sl = std::sin(l);
      dl_dri = sl > 0 ? (std::sin(ri) * std::cos(rj) + I * std::cos(ri) * std::sin(rj)) / sl : 0.0;
      dl_drj = sl > 0 ? (std::sin(rj) * std::cos(ri) + I * std::cos(rj) * std::sin(ri)) / sl : 0.0;
      return l;
    }
  }
}

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_TRIANGLE_GEOMETRY_H
