// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The motions of the model plane used by the embedding: hyperbolic isometries (the shared
// Poincare_disk_isometry_2, in long double for the accumulation of long products) and, for the flat torus,
// Euclidean motions z -> a z + b with |a| = 1; the Euclidean face charts and transitions of the flat torus.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_MOTIONS_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_MOTIONS_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Poincare_disk_isometry_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

typedef long double Real;
typedef std::complex<Real> Cplx;
typedef CGAL::Simple_cartesian<long double> Long_kernel;
typedef CGAL::Poincare_disk_isometry_2<Long_kernel> Long_isometry;

inline Long_isometry to_long(const CGAL::Poincare_disk_isometry_2<CGAL::Epick>& g)
{
  return Long_isometry(g.alpha_real(), g.alpha_imag(), g.beta_real(), g.beta_imag());
}

/// the normalized isometry rounded to double; throws `CGAL::Numerical_error` when the rounded matrix has no
/// positive determinant (|alpha|^2 above about 1e16: the isometry moves the origin by more than about 37)
inline CGAL::Poincare_disk_isometry_2<CGAL::Epick> to_double(const Long_isometry& g)
{
  const Long_isometry n = g.normalized();
  const double ar = double(n.alpha_real()), ai = double(n.alpha_imag()), br = double(n.beta_real()), bi = double(n.beta_imag());
  if(!(ar * ar + ai * ai - br * br - bi * bi > 0))
    throw CGAL::Numerical_error("Hyperbolic_embedding: a deck transformation is not representable in double "
                                "(|alpha|^2 = " + std::to_string(double(n.alpha_real() * n.alpha_real() + n.alpha_imag() * n.alpha_imag())) +
                                ": it moves every point of the frame's chart too far)");
  return CGAL::Poincare_disk_isometry_2<CGAL::Epick>(ar, ai, br, bi);
}

/// a motion of the model plane: a hyperbolic isometry of the Poincare disk, or a Euclidean motion z -> a z + b
struct Motion
{
  bool hyperbolic = true;
  Long_isometry h;
  Cplx a = 1, b = 0;

  static Motion identity(bool hyp) { Motion m; m.hyperbolic = hyp; return m; }
  static Motion from(const Long_isometry& g) { Motion m; m.h = g; return m; }
  static Motion euclidean(Cplx a, Cplx b) { Motion m; m.hyperbolic = false; m.a = a; m.b = b; return m; }
  /// the hyperbolic translation taking c (in the disk) to the origin
  static Motion translation_to_origin(const Cplx& c)
  {
    return from(Long_isometry::translation_to_origin(Long_kernel::Point_2(c.real(), c.imag())));
  }

  Cplx operator()(Cplx z) const
  {
    if(!hyperbolic) return a * z + b;
    const Long_kernel::Point_2 p = h.apply_unchecked(Long_kernel::Point_2(z.real(), z.imag()));
    return Cplx(p.x(), p.y());
  }
  Motion operator*(const Motion& g) const
  {
    if(hyperbolic) return from(h * g.h);
    return euclidean(a * g.a, a * g.b + b);
  }
  Motion inverse() const
  {
    if(hyperbolic) return from(h.inverse());
    return euclidean(Real(1) / a, -b / a);
  }
  Motion normalized() const { return hyperbolic ? from(h.normalized()) : *this; }
  /// distance to the identity (max entry difference of the normalized matrix, up to sign; |a - 1| + |b|);
  /// +infinity for a motion with a non-finite entry (an overflowed product is never "close to the identity")
  Real defect() const
  {
    const Real inf = std::numeric_limits<Real>::infinity();
    if(!hyperbolic) { const Real d = std::abs(a - Real(1)) + std::abs(b); return std::isfinite(d) ? d : inf; }
    const Long_isometry n = h.normalized(); // NaN entries if the determinant is not positive
    if(!std::isfinite(n.alpha_real() + n.alpha_imag() + n.beta_real() + n.beta_imag())) return inf;
    const Real d[4] = {n.alpha_real() - 1, n.alpha_imag(), n.beta_real(), n.beta_imag()};
    const Real e[4] = {n.alpha_real() + 1, n.alpha_imag(), n.beta_real(), n.beta_imag()};
    Real dp = 0, dm = 0;
    for(int i = 0; i < 4; ++i) { dp = (std::max)(dp, std::abs(d[i])); dm = (std::max)(dm, std::abs(e[i])); }
    const Real r = (std::min)(dp, dm);
    return std::isfinite(r) ? r : inf;
  }
};

/// the letter l of a word over `generators`: generator l - 1 for l > 0, the inverse of generator -l - 1 for l < 0
template <class G>
G letter(const std::vector<G>& generators, int l)
{
  return l > 0 ? generators[l - 1] : generators[-l - 1].inverse();
}

/// the product of the letters of the word w over `generators`, right-multiplied onto m (the identity)
template <class G>
G word_product(const std::vector<G>& generators, const std::vector<int>& w, G m)
{
  for(const int l : w) m = m * letter(generators, l);
  return m;
}

/// |alpha|^2 + |beta|^2 of an SU(1,1) matrix: cosh d(0, g 0) when g is normalized
template <class Isometry>
typename Isometry::FT squared_norm(const Isometry& g)
{
  return g.alpha_real() * g.alpha_real() + g.alpha_imag() * g.alpha_imag() + g.beta_real() * g.beta_real() +
         g.beta_imag() * g.beta_imag();
}

/// the Euclidean chart of a triangle with side lengths l0 = |z0 z1|, l1 = |z1 z2|, l2 = |z2 z0|,
/// counterclockwise, centroid at the origin
inline std::array<Cplx, 3> euclidean_chart(Real l0, Real l1, Real l2)
{
  // z0 = 0, z1 = l0, z2 at distance l2 from z0 and l1 from z1
  const Real x = (l0 * l0 + l2 * l2 - l1 * l1) / (2 * l0);
  const Real y2 = l2 * l2 - x * x;
  const Cplx z2(x, y2 > 0 ? std::sqrt(y2) : Real(0));
  std::array<Cplx, 3> z = {Cplx(0), Cplx(l0), z2};
  const Cplx c = (z[0] + z[1] + z[2]) / Real(3);
  for(Cplx& p : z) p -= c;
  return z;
}

/// the Euclidean motion mapping p1 -> p2 and the direction of q1 - p1 to that of q2 - p2
inline Motion euclidean_from_pairs(Cplx p1, Cplx q1, Cplx p2, Cplx q2)
{
  Cplx r = (q2 - p2) / (q1 - p1);
  r /= std::abs(r);
  return Motion::euclidean(r, p2 - r * p1);
}

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_MOTIONS_H
