// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Adaptors of the shared layer's disk geometry (Hyperbolic_surface_2::Disk_geometry, corner_angle) to the
// complex numbers the transient embeddings of Surface_shortest_words work with.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_LAYOUT_H
#define CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_LAYOUT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poincare_disk_isometry_2.h>
#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>
#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace CGAL {
namespace Surface_shortest_words {
namespace internal {

// The geometry is the shared layer's (Hyperbolic_surface_2::Disk_geometry, corner_angle): these are thin
// adaptors to std::complex<double>, the package's working type for points of the disk.
typedef std::complex<double> Cplx;
typedef CGAL::Epick Layout_kernel;
typedef CGAL::Poincare_disk_isometry_2<Layout_kernel> Isometry;
typedef CGAL::Hyperbolic_surface_2::Disk_geometry<Layout_kernel> Disk;

inline Layout_kernel::Point_2 to_point(const Cplx& z) { return Layout_kernel::Point_2(z.real(), z.imag()); }
inline Cplx to_cplx(const Layout_kernel::Point_2& p) { return Cplx(p.x(), p.y()); }

inline Cplx apply_isometry(const Isometry& f, const Cplx& z) { return to_cplx(f.apply_unchecked(to_point(z))); }

/// the hyperbolic translation taking `a` to the origin
inline Isometry to_origin(const Cplx& a) { return Isometry::translation_to_origin(to_point(a)); }

/// hyperbolic distance between two points of the Poincare disk (infinity outside)
inline double hyperbolic_distance(const Cplx& p, const Cplx& q) { return Disk::distance(to_point(p), to_point(q)); }

/// hyperbolic distance from the origin to z
inline double distance_to_origin(const Cplx& z) { return Disk::distance_to_origin(to_point(z)); }

/// the isometry taking `a` to the origin and `b` (distinct from `a`) to the positive real axis
inline Isometry frame(const Cplx& a, const Cplx& b) { return Disk::standard_position(to_point(a), to_point(b)); }

/// the point at hyperbolic distance `s` from `a` on the geodesic ray from `a` through `b`
inline Cplx point_along(const Cplx& a, const Cplx& b, double s) { return to_cplx(Disk::point_along(to_point(a), to_point(b), s)); }

/// angle at the vertex opposite to side `a` of a hyperbolic triangle with sides a, b, c (half-angle formula)
inline double angle_opposite(double a, double b, double c) { return CGAL::Hyperbolic_surface_2::corner_angle(a, b, c); }

/// true if a, b, c satisfy the strict triangle inequalities (a hyperbolic triangle exists)
inline bool is_triangle(double a, double b, double c) { return CGAL::Hyperbolic_surface_2::is_hyperbolic_triangle(a, b, c); }

/// The third vertex C of the triangle (A, B, C), counterclockwise, with |AB| = c, |AC| = b, |BC| = a, given
/// the positions of A and B in the disk.
inline Cplx third_vertex(const Cplx& A, const Cplx& B, double a, double b, double c)
{
  return to_cplx(Disk::apex(to_point(A), to_point(B), a, b, c));
}

/// Klein image of a Poincare point: k = 2z / (1 + |z|^2)
inline Cplx to_klein(const Cplx& z) { return to_cplx(Disk::to_klein(to_point(z))); }

/// Poincare image of a Klein point: z = k / (1 + sqrt(1 - |k|^2))
inline Cplx from_klein(const Cplx& k) { return to_cplx(Disk::from_klein(to_point(k))); }

inline double cross(const Cplx& u, const Cplx& v) { return u.real() * v.imag() - u.imag() * v.real(); }

/// true if the Klein point k lies in the triangle K[0], K[1], K[2] (either orientation) or within the
/// Euclidean distance `tol` of it in the Klein model
inline bool in_klein_triangle(const Cplx K[3], const Cplx& k, double tol)
{
  const double sign = cross(K[1] - K[0], K[2] - K[0]) >= 0 ? 1.0 : -1.0;
  for(int i = 0; i < 3; ++i) {
    const Cplx e = K[(i + 1) % 3] - K[i];
    const double n = std::abs(e);
    if(!(n > 0)) continue;
    if(sign * cross(e, k - K[i]) / n < -tol) return false;
  }
  return true;
}

} // namespace internal
} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_LAYOUT_H
