// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Conversions between the Poincare disk and the Klein, hyperboloid and upper half-plane models (functors of
// Poincare_disk_traits_2).
#ifndef CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_MODEL_CONVERSIONS_H
#define CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_MODEL_CONVERSIONS_H

#include <CGAL/Poincare_disk_traits_2/internal/checks.h>
#include <CGAL/Poincare_disk_traits_2/internal/constructions.h>
#include <CGAL/Poincare_disk_traits_2/internal/polynomials.h>

namespace CGAL {
namespace Poincare_disk_internal {

/// Klein image 2z / (1 + |z|^2) (rational).
template <class K>
class Construct_Klein_point_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_2 Vector_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& p) const
  {
    check_point_in_disk_fast(p, "Construct_Klein_point_2");
    const FT w = lift_w(p.x(), p.y());
    return Point_2(FT(2) * p.x() / w, FT(2) * p.y() / w);
  }
};

/// Poincare point of a Klein point k: k / (1 + sqrt(1 - |k|^2)).
template <class K>
class Construct_point_from_Klein_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_2 Vector_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& k) const
  {
    check_point_in_disk(k, "Construct_point_from_Klein_2");
    const FT den = FT(1) + sqrt_of(lift_n(k.x(), k.y()));
    return Point_2(k.x() / den, k.y() / den);
  }
};

/// Hyperboloid lift (2x, 2y, 1 + |z|^2) / (1 - |z|^2) (rational), Minkowski product x1x2 + y1y2 - t1t2.
template <class K>
class Construct_hyperboloid_point_3
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_2 Vector_2;
  typedef Point_3 result_type;
  Point_3 operator()(const Point_2& p) const
  {
    check_point_in_disk_fast(p, "Construct_hyperboloid_point_3");
    using namespace Poincare_disk_internal;
    const FT n = lift_n(p.x(), p.y());
    return Point_3(FT(2) * p.x() / n, FT(2) * p.y() / n, lift_w(p.x(), p.y()) / n);
  }
};

/// Poincare point of a point (X, Y, T) of the upper sheet of the hyperboloid: (X, Y) / (1 + T) (rational).
template <class K>
class Construct_point_from_hyperboloid_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_2 Vector_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_3& h) const
  {
    if(!(h.z() > FT(0)))
      throw Poincare_disk_domain_error("Construct_point_from_hyperboloid_2: T must be positive");
    const FT den = FT(1) + h.z();
    const Point_2 p(h.x() / den, h.y() / den);
    check_point_in_disk_fast(p, "Construct_point_from_hyperboloid_2");
    return p;
  }
};

/// Upper half-plane image by the Cayley map w = i (1 + z) / (1 - z) (rational).
template <class K>
class Construct_upper_half_plane_point_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_2 Vector_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& p) const
  {
    check_point_in_disk_fast(p, "Construct_upper_half_plane_point_2");
    const FT den = (FT(1) - p.x()) * (FT(1) - p.x()) + p.y() * p.y();
    return Point_2(FT(-2) * p.y() / den, lift_n(p.x(), p.y()) / den);
  }
};

/// Poincare point of a point (u, v), v > 0, of the upper half-plane: z = (w - i) / (w + i) (rational).
template <class K>
class Construct_point_from_upper_half_plane_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_2 Vector_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& w) const
  {
    if(!(w.y() > FT(0)) || !is_finite_coordinate(w.x()))
      throw Poincare_disk_domain_error("Construct_point_from_upper_half_plane_2: need a finite point with v > 0");
    const FT u = w.x(), v = w.y(), den = u * u + (v + FT(1)) * (v + FT(1));
    return Point_2((u * u + v * v - FT(1)) / den, FT(-2) * u / den);
  }
};

} // namespace Poincare_disk_internal
} // namespace CGAL

#endif
