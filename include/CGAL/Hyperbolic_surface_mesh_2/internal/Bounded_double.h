// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A double with a rigorous a-priori bound on its absolute error: the cheap first stage of the face tests of
// the refinement, in front of the traits' interval / exact-rational evaluation. Signs and comparisons return
// CGAL::Uncertain values, so a polynomial written for Interval_nt runs on it unchanged; an undecided sign
// throws Uncertain_conversion_exception when converted (the caller then falls back).
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_BOUNDED_DOUBLE_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_BOUNDED_DOUBLE_H

#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

#include <cmath>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace internal {

/// The forward error bound of an expression tree (Higham, "Accuracy and Stability of Numerical Algorithms",
/// 2nd ed., Lemma 3.3 and section 3.1): `v` is the value computed in double precision (round to nearest, the
/// default mode; the traits' interval stage sets and restores its own), `m` the magnitude (the same tree
/// evaluated on the absolute values of the inputs with every subtraction an addition, plus 2^-1022 per
/// product), `d` the rounding count (0 for an input, max + 1 for a sum or difference, d_a + d_b + 1 for a
/// product). With gamma_d = d u / (1 - d u), u = 2^-53, the exact value x of the tree on the exact inputs
/// satisfies |v - x| <= gamma_d M, M the exact magnitude: a sum adds one relative rounding to the larger count
/// ((1 + gamma_k)(1 + u) <= 1 + gamma_{k+1}), a product multiplies the relative errors
/// ((1 + gamma_a)(1 + gamma_b)(1 + u) <= 1 + gamma_{a+b+1}), and the absolute error 2^-1075 of an underflowing
/// product is u times the 2^-1022 added to its magnitude (sums of doubles do not underflow). The magnitude is
/// itself computed in double precision with at most 2 d roundings of nonnegative numbers, so M <= m / (1 -
/// u)^(2 d); for d u <= 1/8 the bound (2 d + 1) u m covers gamma_d M and its own rounding. An inf or NaN
/// anywhere leaves every sign undecided. Two floating-point operations per operation (the counts are constants
/// of the expression, folded by the compiler), against eight to ten for a running error bound.
struct Bounded_double
{
  double v = 0, m = 0;
  int d = 0;
  Bounded_double() {}
  Bounded_double(double x) : v(x), m(std::abs(x)) {}
  Bounded_double(int x) : v(double(x)), m(std::abs(double(x))) {}

  static constexpr double u = 1.1102230246251565e-16;     // 2^-53
  static constexpr double tau = 2.2250738585072014e-308;  // 2^-1022: 2^-1075 / u, the underflow of a product
  static constexpr int max_count = 1 << 20;               // d u <= 1/8 with a wide margin

  friend Bounded_double operator+(const Bounded_double& a, const Bounded_double& b)
  { return make(a.v + b.v, a.m + b.m, (a.d > b.d ? a.d : b.d) + 1); }
  friend Bounded_double operator-(const Bounded_double& a, const Bounded_double& b)
  { return make(a.v - b.v, a.m + b.m, (a.d > b.d ? a.d : b.d) + 1); }
  friend Bounded_double operator-(const Bounded_double& a) { return make(-a.v, a.m, a.d); }
  friend Bounded_double operator*(const Bounded_double& a, const Bounded_double& b)
  { return make(a.v * b.v, a.m * b.m + tau, a.d + b.d + 1); }

  /// the bound on |v - exact value| (+infinity if the count is out of range)
  double error() const
  {
    if(d > max_count) return HUGE_VAL;
    return double(2 * d + 1) * u * m;
  }
  /// the sign if the error bound decides it (an exact zero only for an error-free zero)
  Uncertain<Sign> sign() const
  {
    const double e = error();
    if(v > e) return POSITIVE;
    if(v < -e) return NEGATIVE;
    if(v == 0 && d == 0) return ZERO; // an input zero
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

private:
  static Bounded_double make(double v, double m, int d) { Bounded_double r; r.v = v; r.m = m; r.d = d; return r; }
};

/// sign of a number of any of the stages: Bounded_double, Interval_nt (Uncertain results) or exact
inline Uncertain<Sign> sign_of(const Bounded_double& x) { return x.sign(); }
template <class NT> auto sign_of(const NT& x) { return CGAL::sign(x); }

} // namespace internal
} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif
