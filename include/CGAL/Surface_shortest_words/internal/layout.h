// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small hyperbolic-geometry helpers for the transient embeddings of Surface_shortest_words: laying out a
// triangle from its edge lengths (hyperbolic law of cosines), points along geodesics, Klein coordinates and
// the re-centring isometries (CGAL::Poincare_disk_isometry_2<CGAL::Epick>).
#ifndef CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_LAYOUT_H
#define CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_LAYOUT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poincare_disk_isometry_2.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace CGAL {
namespace Surface_shortest_words {
namespace internal {

typedef std::complex<double> Cplx;
typedef CGAL::Epick Layout_kernel;
typedef CGAL::Poincare_disk_isometry_2<Layout_kernel> Isometry;

inline Cplx apply_isometry(const Isometry& f, const Cplx& z)
{
  const Layout_kernel::Point_2 p = f.apply_unchecked(Layout_kernel::Point_2(z.real(), z.imag()));
  return Cplx(p.x(), p.y());
}

/// the hyperbolic translation taking `a` to the origin
inline Isometry to_origin(const Cplx& a)
{
  return Isometry::translation_to_origin(Layout_kernel::Point_2(a.real(), a.imag()));
}

/// hyperbolic distance between two points of the Poincare disk: cosh d = 1 + 2|p-q|^2/((1-|p|^2)(1-|q|^2)).
/// Written as 2 asinh(sqrt(A)) to stay accurate for small distances.
inline double hyperbolic_distance(const Cplx& p, const Cplx& q)
{
  const double den = (1.0 - std::norm(p)) * (1.0 - std::norm(q));
  if(!(den > 0)) return std::numeric_limits<double>::infinity();
  return 2.0 * std::asinh(std::sqrt(std::norm(p - q) / den));
}

/// hyperbolic distance from the origin to z
inline double distance_to_origin(const Cplx& z)
{
  const double r = std::abs(z);
  if(r >= 1.0) return std::numeric_limits<double>::infinity();
  return 2.0 * std::atanh(r);
}

/// the isometry taking `a` to the origin and `b` (distinct from `a`) to the positive real axis
inline Isometry frame(const Cplx& a, const Cplx& b)
{
  const Isometry t = to_origin(a);
  const Cplx bb = apply_isometry(t, b);
  const double r = std::abs(bb);
  if(!(r > 0)) return t;
  return Isometry::rotation(bb.real() / r, -bb.imag() / r) * t;
}

/// the point at hyperbolic distance `s` from `a` on the geodesic ray from `a` through `b`
inline Cplx point_along(const Cplx& a, const Cplx& b, double s)
{
  const Isometry f = frame(a, b);
  return apply_isometry(f.inverse(), Cplx(std::tanh(s / 2.0), 0.0));
}

/// angle at the vertex opposite to side `a` of a hyperbolic triangle with sides a, b, c (law of cosines)
inline double angle_opposite(double a, double b, double c)
{
  const double num = std::cosh(b) * std::cosh(c) - std::cosh(a);
  const double den = std::sinh(b) * std::sinh(c);
  const double x = num / den;
  return std::acos((std::max)(-1.0, (std::min)(1.0, x)));
}

/// true if a, b, c satisfy the strict triangle inequalities (a hyperbolic triangle exists)
inline bool is_triangle(double a, double b, double c)
{
  return a > 0 && b > 0 && c > 0 && std::isfinite(a) && std::isfinite(b) && std::isfinite(c) &&
         a < b + c && b < a + c && c < a + b;
}

/// The third vertex C of the triangle (A, B, C), counterclockwise, with |AB| = c, |AC| = b, |BC| = a, given
/// the positions of A and B in the disk.
inline Cplx third_vertex(const Cplx& A, const Cplx& B, double a, double b, double c)
{
  const double alpha = angle_opposite(a, b, c);
  const Isometry f = frame(A, B);
  const Cplx local = std::polar(std::tanh(b / 2.0), alpha);
  return apply_isometry(f.inverse(), local);
}

/// Klein image of a Poincare point: k = 2z / (1 + |z|^2)
inline Cplx to_klein(const Cplx& z) { return 2.0 * z / (1.0 + std::norm(z)); }

/// Poincare image of a Klein point: z = k / (1 + sqrt(1 - |k|^2))
inline Cplx from_klein(const Cplx& k) { return k / (1.0 + std::sqrt((std::max)(0.0, 1.0 - std::norm(k)))); }

inline double cross(const Cplx& u, const Cplx& v) { return u.real() * v.imag() - u.imag() * v.real(); }

} // namespace internal
} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_LAYOUT_H
