// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A double with a rigorous bound on its absolute error (running error analysis): the cheap first stage of the
// face tests of the refinement, in front of the traits' interval / exact-rational evaluation. Signs and
// comparisons return CGAL::Uncertain values, so a polynomial written for Interval_nt runs on it unchanged;
// an undecided sign throws Uncertain_conversion_exception when converted (the caller then falls back).
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_BOUNDED_DOUBLE_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_BOUNDED_DOUBLE_H

#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

#include <cmath>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace internal {

/// `v` is the computed value, `e` a bound on |v - x| where x is the exact value of the same expression on the
/// exact inputs. Inputs (constructed from a double or an int) are exact (e = 0). Every operation adds its own
/// rounding error (u |result|, u = 2^-53, plus 2^-1000 for an underflowing product) to the propagated errors and
/// multiplies the sum by 1 + 2^-50, which covers the (at most 7) roundings of the bound's own evaluation.
/// Round-to-nearest is assumed (the default mode; the traits' interval stage sets and restores its own).
struct Bounded_double
{
  double v = 0, e = 0;
  Bounded_double() {}
  Bounded_double(double x) : v(x) {}
  Bounded_double(int x) : v(double(x)) {}
  Bounded_double(double value, double error) : v(value), e(error) {}

  static constexpr double u = 1.1102230246251565e-16;   // 2^-53
  static constexpr double grow = 1.0 + 8.8817841970012523e-16; // 1 + 2^-50
  static constexpr double eta = 9.3326361850321888e-302;  // 2^-1000: covers the underflow of a product

  friend Bounded_double operator+(const Bounded_double& a, const Bounded_double& b)
  { const double s = a.v + b.v; return Bounded_double(s, (a.e + b.e + u * std::abs(s)) * grow); }
  friend Bounded_double operator-(const Bounded_double& a, const Bounded_double& b)
  { const double s = a.v - b.v; return Bounded_double(s, (a.e + b.e + u * std::abs(s)) * grow); }
  friend Bounded_double operator-(const Bounded_double& a) { return Bounded_double(-a.v, a.e); }
  friend Bounded_double operator*(const Bounded_double& a, const Bounded_double& b)
  {
    const double p = a.v * b.v;
    return Bounded_double(p, (std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + u * std::abs(p) + eta) * grow);
  }

  /// the sign if the error bound decides it (an exact zero only for an error-free zero)
  Uncertain<Sign> sign() const
  {
    if(v > e) return POSITIVE;
    if(v < -e) return NEGATIVE;
    if(v == 0 && e == 0) return ZERO;
    return Uncertain<Sign>::indeterminate();
  }
  friend Uncertain<bool> operator<=(const Bounded_double& a, const Bounded_double& b)
  {
    const Uncertain<Sign> s = (b - a).sign();
    if(is_indeterminate(s)) return Uncertain<bool>::indeterminate();
    return get_certain(s) != NEGATIVE;
  }
  friend Uncertain<bool> operator<(const Bounded_double& a, const Bounded_double& b)
  {
    const Uncertain<Sign> s = (b - a).sign();
    if(is_indeterminate(s)) return Uncertain<bool>::indeterminate();
    return get_certain(s) == POSITIVE;
  }
};

/// sign of a number of any of the stages: Bounded_double, Interval_nt (Uncertain results) or exact
inline Uncertain<Sign> sign_of(const Bounded_double& x) { return x.sign(); }
template <class NT> auto sign_of(const NT& x) { return CGAL::sign(x); }

} // namespace internal
} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif
