// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Conversions between the Poincare disk and the Klein, hyperboloid and upper half-plane models, and hyperbolic
// circles as Euclidean circles (functors of Poincare_disk_traits_2).
#ifndef CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_MODEL_CONVERSIONS_H
#define CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_MODEL_CONVERSIONS_H

#include <CGAL/Poincare_disk_traits_2/internal/checks.h>
#include <CGAL/Poincare_disk_traits_2/internal/constructions.h>
#include <CGAL/Poincare_disk_traits_2/internal/polynomials.h>

#include <cmath>
#include <utility>

namespace CGAL {
namespace Poincare_disk_internal {

/// Klein image 2z / (1 + |z|^2) (rational).
template <class K>
class Construct_Klein_point_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& p) const
  {
    check_point_in_disk(p, "Construct_Klein_point_2");
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
  typedef Point_3 result_type;
  Point_3 operator()(const Point_2& p) const
  {
    check_point_in_disk(p, "Construct_hyperboloid_point_3");
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
  typedef Point_2 result_type;
  Point_2 operator()(const Point_3& h) const
  {
    if(!(h.z() > FT(0)))
      throw Poincare_disk_domain_error("Construct_point_from_hyperboloid_2: T must be positive");
    const FT den = FT(1) + h.z();
    const Point_2 p(h.x() / den, h.y() / den);
    check_point_in_disk(p, "Construct_point_from_hyperboloid_2");
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
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& p) const
  {
    check_point_in_disk(p, "Construct_upper_half_plane_point_2");
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
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& w) const
  {
    if(!(w.y() > FT(0)) || !is_finite_coordinate(w.x()))
      throw Poincare_disk_domain_error("Construct_point_from_upper_half_plane_2: need a finite point with v > 0");
    const FT u = w.x(), v = w.y(), den = u * u + (v + FT(1)) * (v + FT(1));
    return Point_2((u * u + v * v - FT(1)) / den, FT(-2) * u / den);
  }
};

/// The Euclidean circle that is the hyperbolic circle of centre c and radius r, with the radius given as
/// `sinh2_half_radius = sinh^2(r/2)` (rational: exact on exact FT), or as the radius itself (rounded).
/// Euclidean centre c / (1 + s n_c), squared radius |centre|^2 - (|c|^2 - s n_c) / (1 + s n_c), n_c = 1 - |c|^2.
template <class K>
class Construct_hyperbolic_circle_2
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Circle_2 Circle_2;
  typedef Circle_2 result_type;
  Circle_2 operator()(const Point_2& c, const FT& sinh2_half_radius) const
  {
    check_point_in_disk(c, "Construct_hyperbolic_circle_2");
    if(!(sinh2_half_radius >= FT(0)))
      throw Poincare_disk_domain_error("Construct_hyperbolic_circle_2: negative or NaN radius");
    const FT s = sinh2_half_radius, nc = lift_n(c.x(), c.y()), den = FT(1) + s * nc;
    const Point_2 e(c.x() / den, c.y() / den);
    const FT r2 = e.x() * e.x() + e.y() * e.y() - (c.x() * c.x() + c.y() * c.y() - s * nc) / den;
    return Circle_2(e, r2);
  }
  Circle_2 from_radius(const Point_2& c, double radius) const
  {
    const double sh = std::sinh(radius / 2);
    return (*this)(c, FT(sh * sh));
  }
};

/// Hyperbolic centre and radius of a Euclidean circle contained in the open unit disk (Lemma 3.3 of the thesis);
/// throws `Poincare_disk_domain_error` if the circle is not inside the disk. Rounded.
template <class Traits>
class Construct_hyperbolic_circle_from_Euclidean_2
{
public:
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::Circle_2 Circle_2;
  typedef std::pair<Point_2, FT> result_type;
  std::pair<Point_2, FT> operator()(const Circle_2& circle) const
  {
    const double cx = CGAL::to_double(circle.center().x()), cy = CGAL::to_double(circle.center().y());
    const double R = std::sqrt(CGAL::to_double(circle.squared_radius())), c = std::hypot(cx, cy);
    if(!(c + R < 1.0))
      throw Poincare_disk_domain_error("Construct_hyperbolic_circle_from_Euclidean_2: circle not inside the disk");
    if(c == 0) return std::make_pair(Point_2(FT(0), FT(0)), FT(2 * std::atanh(R)));
    // the diameter of the circle on the line through the origin and its centre is a hyperbolic diameter
    const double ux = cx / c, uy = cy / c;
    const Point_2 a(FT((c - R) * ux), FT((c - R) * uy)), b(FT((c + R) * ux), FT((c + R) * uy));
    const Point_2 m = typename Traits::Construct_hyperbolic_midpoint_2()(a, b);
    return std::make_pair(m, FT(CGAL::to_double(typename Traits::Compute_hyperbolic_distance_2()(a, b)) / 2));
  }
};

} // namespace Poincare_disk_internal
} // namespace CGAL

#endif
