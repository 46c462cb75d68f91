// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality bounds of Delaunay refinement in the hyperbolic plane (thesis, chapter 3, Section 3.2.1,
// Theorems 3.1 and 3.2): theta*(h), rho(h), rho(r, theta) and the termination conditions of the generalized
// Chew and Ruppert algorithms.
#ifndef CGAL_HYPERBOLIC_MESH_2_QUALITY_BOUNDS_H
#define CGAL_HYPERBOLIC_MESH_2_QUALITY_BOUNDS_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace CGAL {
namespace Hyperbolic_mesh_2 {

/// \ingroup PkgHyperbolicMesh2Ref
/// The constant h* = 2.3101 below which the generalized Chew algorithm provably terminates (thesis Theorem 3.1;
/// it is where rho(h) = 1.5).
constexpr double Chew_termination_bound = 2.3101;

/// \ingroup PkgHyperbolicMesh2Ref
/// theta*(h): the angle of an equilateral hyperbolic triangle of side h, cos theta* = (cosh^2 h - cosh h) /
/// sinh^2 h = cosh h / (cosh h + 1) (thesis eq. before (3.9)). It is also the central angle of a chord of length h
/// in a circle of radius h, hence "central angle of the shortest edge below theta*(r)" is the same as "shortest edge
/// shorter than the circumradius r". Decreases from pi/3 (h -> 0) to 0 (h -> infinity). O(1).
/// \pre h >= 0 (h = 0 gives the limit pi/3).
inline double theta_star(double h)
{
  if(!(h >= 0)) throw CGAL::Invalid_option_error("theta_star: h must be >= 0");
  if(h == 0) return std::acos(0.5);
  const double c = std::cosh(h);
  if(!std::isfinite(c)) return 0.0;
  return std::acos(c / (c + 1.0));
}

/// \ingroup PkgHyperbolicMesh2Ref
/// rho(h) = d(A, B) / h where AB is the chord of central angle 2 theta*(h) in a circle of radius h
/// (eq. (3.9): d(A, B) = 2 asinh(sin theta*(h) sinh h)). Decreases from sqrt(3) (h -> 0) to 1 (h -> infinity);
/// rho(2.3101) = 1.5. O(1). \pre h >= 0 (h = 0 gives the limit sqrt(3)).
inline double rho(double h)
{
  if(!(h >= 0)) throw CGAL::Invalid_option_error("rho: h must be >= 0");
  if(h < 1e-6) return std::sqrt(3.0) * (1.0 - h * h / 16.0); // series, avoids 0/0
  if(h > 60) return 1.0 + 2.0 * std::log(2.0) / h; // d(A, B) = h + 2 ln 2 + O(e^-h)
  const double c = std::cosh(h), sin_theta = std::sqrt(2.0 * c + 1.0) / (c + 1.0); // sin theta*(h)
  return 2.0 * std::asinh(sin_theta * std::sinh(h)) / h;
}

/// \ingroup PkgHyperbolicMesh2Ref
/// rho(r, theta) = acosh(cosh^2 r - sinh^2 r cos theta) / r: the length of the chord of central angle theta in a
/// circle of radius r, divided by r (thesis Section 3.4). Tends to 2 sin(theta / 2) as r -> 0 and increases with r.
/// O(1). \pre r >= 0, 0 <= theta <= pi.
inline double rho(double r, double theta)
{
  if(!(r >= 0)) throw CGAL::Invalid_option_error("rho(r, theta): r must be >= 0");
  if(!(theta >= 0 && theta <= 3.14159265358979323846 + 1e-12))
    throw CGAL::Invalid_option_error("rho(r, theta): theta must be in [0, pi]");
  const double s = std::sin(theta / 2);
  if(r < 1e-6) return 2.0 * s;
  // cosh^2 r - sinh^2 r cos theta = 1 + 2 sinh^2 r sin^2(theta/2); acosh(1 + x) = 2 asinh(sqrt(x / 2))
  const double sh = std::sinh(r);
  if(!std::isfinite(sh)) return 2.0;
  return 2.0 * std::asinh(sh * s) / r;
}

/// \ingroup PkgHyperbolicMesh2Ref
/// The termination margin of the generalized Ruppert algorithm (thesis Theorem 3.2):
/// 1 - rho(r_bar, alpha) rho(r_bar, pi/2), where alpha is the central-angle bound and r_bar the maximum
/// circumradius. Termination is guaranteed when it is positive. In the Euclidean limit r_bar -> 0 it is
/// 1 - 2 sqrt(2) sin(alpha / 2), positive iff alpha < 41.41 degrees (Ruppert's 20.7 degree minimum angle).
inline double Ruppert_termination_margin(double r_bar, double alpha)
{
  return 1.0 - rho(r_bar, alpha) * rho(r_bar, 3.14159265358979323846 / 2);
}

/// \ingroup PkgHyperbolicMesh2Ref
/// The largest maximum circumradius r_bar for which the Ruppert termination condition holds for the central-angle
/// bound alpha (bisection on the increasing function r -> rho(r, alpha) rho(r, pi/2); 200 steps, O(1)).
/// Returns 0 when no r_bar > 0 works (alpha >= 2 asin(1 / (2 sqrt 2)) = 41.41 degrees). The result is always
/// finite: the product tends to 4 as r -> infinity.
inline double Ruppert_maximum_circumradius(double alpha)
{
  if(!(alpha > 0 && alpha <= 3.14159265358979323846))
    throw CGAL::Invalid_option_error("Ruppert_maximum_circumradius: alpha must be in (0, pi]");
  if(Ruppert_termination_margin(0.0, alpha) <= 0) return 0.0;
  double lo = 0.0, hi = 1.0;
  while(Ruppert_termination_margin(hi, alpha) > 0 && hi < 1e6) hi *= 2;
  for(int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Ruppert_termination_margin(mid, alpha) > 0 ? lo : hi) = mid;
  }
  return lo;
}

/// \ingroup PkgHyperbolicMesh2Ref
/// The central-angle bound alpha whose threshold is `sin2_half_alpha` = sin^2(alpha / 2). In the Euclidean limit
/// alpha / 2 is the minimum angle, so CGAL Mesh_2's bound B = sin^2(minimum angle) is the same number.
inline double central_angle_from_sin2_half(double sin2_half_alpha)
{
  if(!(sin2_half_alpha > 0 && sin2_half_alpha <= 1))
    throw CGAL::Invalid_option_error("central_angle_from_sin2_half: need 0 < sin^2(alpha/2) <= 1");
  return 2.0 * std::asin(std::sqrt(sin2_half_alpha));
}

} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_QUALITY_BOUNDS_H
