// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Orientation-preserving isometries of the Poincare disk, f(z) = (alpha z + beta) / (conj(beta) z + conj(alpha)),
// stored as the SU(1,1) matrix [[alpha, beta], [conj(beta), conj(alpha)]] up to a positive real factor.
// Keeping the factor free (det = |alpha|^2 - |beta|^2 > 0, not forced to 1) makes every operation rational:
// apply, compose and invert are exact on an exact field type (CGAL::Gmpq), and `normalized()` (which
// needs a square root) is only instantiated where it is called.
#ifndef CGAL_POINCARE_DISK_ISOMETRY_2_H
#define CGAL_POINCARE_DISK_ISOMETRY_2_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/number_utils.h>
#include <CGAL/Poincare_disk_traits_2/internal/checks.h>

#include <cmath>
#include <ostream>

namespace CGAL {

/*!
  \ingroup PkgPoincareDiskTraits2Ref
  An orientation-preserving isometry of the Poincare disk (a Moebius map of SU(1,1) form):
  \f$ f(z) = (\alpha z + \beta) / (\bar\beta z + \bar\alpha) \f$, \f$ |\alpha|^2 - |\beta|^2 > 0 \f$.
  `K` is a CGAL kernel; points are `K::Point_2` in Poincare coordinates.
  Apply, compose, invert and the squared normalized trace are exact with an exact `K::FT`.
*/
template <class K>
class Poincare_disk_isometry_2
{
public:
  typedef typename K::FT      FT;
  typedef typename K::Point_2 Point_2;

  /// the identity
  Poincare_disk_isometry_2() : ar_(1), ai_(0), br_(0), bi_(0) {}

  /// the map with alpha = ar + i ai, beta = br + i bi; throws `CGAL::Invalid_input_error` unless |alpha| > |beta|.
  Poincare_disk_isometry_2(const FT& ar, const FT& ai, const FT& br, const FT& bi)
    : ar_(ar), ai_(ai), br_(br), bi_(bi)
  {
    if(!(determinant() > FT(0)))
      throw CGAL::Invalid_input_error("Poincare_disk_isometry_2: |alpha|^2 - |beta|^2 must be positive");
  }

  /// the hyperbolic translation taking `a` to the origin: z -> (z - a) / (1 - conj(a) z).
  static Poincare_disk_isometry_2 translation_to_origin(const Point_2& a)
  {
    Poincare_disk_internal::check_point_in_disk(a, "Poincare_disk_isometry_2::translation_to_origin");
    return Poincare_disk_isometry_2(FT(1), FT(0), -a.x(), -a.y());
  }

  /// the hyperbolic translation taking the origin to `a`: z -> (z + a) / (1 + conj(a) z).
  static Poincare_disk_isometry_2 translation_from_origin(const Point_2& a)
  {
    Poincare_disk_internal::check_point_in_disk(a, "Poincare_disk_isometry_2::translation_from_origin");
    return Poincare_disk_isometry_2(FT(1), FT(0), a.x(), a.y());
  }

  /// the rotation z -> (c + i s) z about the origin, for c^2 + s^2 = 1 (checked up to the FT's accuracy
  /// only through the positivity of the determinant; rational (c, s) on the unit circle are exact).
  static Poincare_disk_isometry_2 rotation(const FT& c, const FT& s)
  {
    // z -> alpha z / conj(alpha) with arg(alpha) = theta / 2: alpha = 1 + e^{i theta} = 2 cos(theta/2) e^{i theta/2}
    // for c >= 0, alpha = s + i (1 - c) = 2 sin(theta/2) e^{i theta/2} for c < 0; never 1 + c near theta = pi,
    // which cancels (a direction 1e-4 rad off the negative axis lost 1e-8 rad). Both are exact on rationals.
    if(c >= FT(0)) return Poincare_disk_isometry_2(FT(1) + c, s, FT(0), FT(0));
    return Poincare_disk_isometry_2(s, FT(1) - c, FT(0), FT(0));
  }

  const FT& alpha_real() const { return ar_; }
  const FT& alpha_imag() const { return ai_; }
  const FT& beta_real() const { return br_; }
  const FT& beta_imag() const { return bi_; }

  /// |alpha|^2 - |beta|^2 (positive; 1 for a normalized matrix)
  FT determinant() const { return ar_ * ar_ + ai_ * ai_ - br_ * br_ - bi_ * bi_; }

  /// (trace / sqrt(det))^2 = 4 Re(alpha)^2 / det: > 4 hyperbolic, = 4 parabolic (or identity), < 4 elliptic.
  FT squared_normalized_trace() const { return FT(4) * ar_ * ar_ / determinant(); }

  /// the image of `z` (|z| < 1 is checked)
  Point_2 operator()(const Point_2& z) const
  {
    Poincare_disk_internal::check_point_in_disk(z, "Poincare_disk_isometry_2::operator()");
    return apply_unchecked(z);
  }

  /// the image of any point of the extended plane where the denominator does not vanish
  /// (points of the unit circle go to the unit circle); no disk check.
  Point_2 apply_unchecked(const Point_2& z) const
  {
    const FT x = z.x(), y = z.y();
    // numerator alpha z + beta, denominator conj(beta) z + conj(alpha)
    const FT nr = ar_ * x - ai_ * y + br_, ni = ar_ * y + ai_ * x + bi_;
    const FT dr = br_ * x + bi_ * y + ar_, di = br_ * y - bi_ * x - ai_;
    const FT d2 = dr * dr + di * di;
    return Point_2((nr * dr + ni * di) / d2, (ni * dr - nr * di) / d2);
  }

  /// composition: (f * g)(z) = f(g(z))
  Poincare_disk_isometry_2 operator*(const Poincare_disk_isometry_2& g) const
  {
    // [[a, b], [conj b, conj a]] [[c, d], [conj d, conj c]] = [[ac + b conj d, ad + b conj c], ...]
    const FT r_ar = ar_ * g.ar_ - ai_ * g.ai_ + br_ * g.br_ + bi_ * g.bi_;
    const FT r_ai = ar_ * g.ai_ + ai_ * g.ar_ + bi_ * g.br_ - br_ * g.bi_;
    const FT r_br = ar_ * g.br_ - ai_ * g.bi_ + br_ * g.ar_ + bi_ * g.ai_;
    const FT r_bi = ar_ * g.bi_ + ai_ * g.br_ + bi_ * g.ar_ - br_ * g.ai_;
    Poincare_disk_isometry_2 r; r.ar_ = r_ar; r.ai_ = r_ai; r.br_ = r_br; r.bi_ = r_bi;
    return r;
  }

  /// the inverse map (the adjugate matrix; same determinant)
  Poincare_disk_isometry_2 inverse() const
  {
    Poincare_disk_isometry_2 r; r.ar_ = ar_; r.ai_ = -ai_; r.br_ = -br_; r.bi_ = -bi_;
    return r;
  }

  /// the same map with determinant 1 and Re(alpha) >= 0 (needs `CGAL::sqrt` on FT).
  Poincare_disk_isometry_2 normalized() const
  {
    FT s = CGAL::sqrt(determinant());
    if(ar_ < FT(0)) s = -s;
    Poincare_disk_isometry_2 r; r.ar_ = ar_ / s; r.ai_ = ai_ / s; r.br_ = br_ / s; r.bi_ = bi_ / s;
    return r;
  }

  /// true if both maps are the same Moebius map (exact for exact FT): the matrices are proportional.
  bool is_same_map(const Poincare_disk_isometry_2& g) const
  {
    // proportional by a real factor: all 2x2 "cross products" of the 4 real coordinates vanish.
    const FT a[4] = {ar_, ai_, br_, bi_}, b[4] = {g.ar_, g.ai_, g.br_, g.bi_};
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(a[i] * b[j] != a[j] * b[i]) return false;
    return true;
  }

  /// for floating-point FT: the largest entry difference between the normalized matrices of this map and
  /// of `g` (taken up to sign, since M and -M are the same map).
  double distance_to(const Poincare_disk_isometry_2& g) const
  {
    const double s1 = std::sqrt(CGAL::to_double(determinant())), s2 = std::sqrt(CGAL::to_double(g.determinant()));
    const double a[4] = {CGAL::to_double(ar_) / s1, CGAL::to_double(ai_) / s1, CGAL::to_double(br_) / s1, CGAL::to_double(bi_) / s1};
    const double b[4] = {CGAL::to_double(g.ar_) / s2, CGAL::to_double(g.ai_) / s2, CGAL::to_double(g.br_) / s2, CGAL::to_double(g.bi_) / s2};
    double dp = 0, dm = 0;
    for(int i = 0; i < 4; ++i) { dp = (std::max)(dp, std::abs(a[i] - b[i])); dm = (std::max)(dm, std::abs(a[i] + b[i])); }
    return (std::min)(dp, dm);
  }

  /// for floating-point FT: |trace| / 2 of the normalized matrix (> 1 for a hyperbolic translation); the
  /// translation length is 2 acosh(|trace| / 2).
  double half_trace() const
  {
    return std::sqrt(CGAL::to_double(squared_normalized_trace())) / 2.0;
  }

  friend std::ostream& operator<<(std::ostream& os, const Poincare_disk_isometry_2& f)
  {
    return os << "[alpha = " << f.ar_ << " + " << f.ai_ << " i, beta = " << f.br_ << " + " << f.bi_ << " i]";
  }

private:
  FT ar_, ai_, br_, bi_;
};

} // namespace CGAL

#endif // CGAL_POINCARE_DISK_ISOMETRY_2_H
