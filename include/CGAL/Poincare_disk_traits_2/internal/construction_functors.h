// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: the construction functors of Poincare_disk_traits_2 (hyperbolic circumcenter, the concepts'
// circumcenter, hyperbolic midpoint, geodesic segment, bisectors, intersection of geodesic segments), as templates
// on the traits class, which names them (`Poincare_disk_traits_2<K>::Construct_hyperbolic_circumcenter_2`, ...).
// Documented in Poincare_disk_traits_2.h.
#ifndef CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_CONSTRUCTION_FUNCTORS_H
#define CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_CONSTRUCTION_FUNCTORS_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Poincare_disk_traits_2/internal/checks.h>
#include <CGAL/Poincare_disk_traits_2/internal/constructions.h>
#include <CGAL/Poincare_disk_traits_2/internal/filtered_evaluation.h>
#include <CGAL/Poincare_disk_traits_2/internal/polynomials.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <boost/optional.hpp>
#include <boost/variant.hpp>

#include <cmath>
#include <utility>

namespace CGAL {
namespace Poincare_disk_internal {

template <class Traits>
class Construct_hyperbolic_circumcenter_2
{
public:
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_2 Point_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    const char* where = "Construct_hyperbolic_circumcenter_2";
    check_point_in_disk(p, where); check_point_in_disk(q, where); check_point_in_disk(r, where);
    if(!typename Traits::Is_Delaunay_hyperbolic()(p, q, r))
      throw Poincare_disk_domain_error("Construct_hyperbolic_circumcenter_2: the circumcircle is not compact "
                                       "(horocycle or hypercycle): no hyperbolic circumcenter");
    const Circle_coefficients<FT> cc(p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
    const FT s = cc.A + cc.G;
    const FT den = sqrt_of<FT>(cc.delta()) + CGAL::abs(s);
    const FT f = (s > FT(0) ? FT(-1) : FT(1)) / den;
    return Point_2(f * cc.B, f * cc.C);
  }
};

template <class Traits>
class Construct_hyperbolic_midpoint_2
{
public:
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_2 Point_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& p, const Point_2& q) const
  {
    check_point_in_disk(p, "Construct_hyperbolic_midpoint_2");
    check_point_in_disk(q, "Construct_hyperbolic_midpoint_2");
    using namespace Poincare_disk_internal;
    const FT np = lift_n(p.x(), p.y()), nq = lift_n(q.x(), q.y());
    // S = (1-|p|^2)(1-|q|^2) (L(p) + L(q))
    const FT sx = FT(2) * (nq * p.x() + np * q.x()), sy = FT(2) * (nq * p.y() + np * q.y());
    const FT st = nq * lift_w(p.x(), p.y()) + np * lift_w(q.x(), q.y());
    const FT den = sqrt_of<FT>(st * st - sx * sx - sy * sy) + st;
    return Point_2(sx / den, sy / den);
  }
};

template <class Traits>
class Construct_circumcenter_2
{
public:
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_2 Point_2;
  typedef Point_2 result_type;
  Point_2 operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    if(typename Traits::Is_Delaunay_hyperbolic()(p, q, r)) return Construct_hyperbolic_circumcenter_2<Traits>()(p, q, r);
    typename Traits::Compare_hyperbolic_distance_2 cmp;
    // longest edge
    const Point_2 *a = &p, *b = &q;
    if(cmp(q, r, *a, *b) == LARGER) { a = &q; b = &r; }
    if(cmp(r, p, *a, *b) == LARGER) { a = &r; b = &p; }
    return Construct_hyperbolic_midpoint_2<Traits>()(*a, *b);
  }
  Point_2 operator()(const Point_2& p, const Point_2& q) const { return Construct_hyperbolic_midpoint_2<Traits>()(p, q); }
};

template <class Traits>
class Construct_hyperbolic_segment_2
{
public:
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::Hyperbolic_segment_2 Hyperbolic_segment_2;
  typedef Hyperbolic_segment_2 result_type;
  Hyperbolic_segment_2 operator()(const Point_2& p, const Point_2& q) const
  {
    check_point_in_disk(p, "Construct_hyperbolic_segment_2");
    check_point_in_disk(q, "Construct_hyperbolic_segment_2");
    return Hyperbolic_segment_2(p, q);
  }
};

template <class Traits>
class Construct_hyperbolic_bisector_2
{
public:
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::Hyperbolic_segment_2 Hyperbolic_segment_2;
  typedef Hyperbolic_segment_2 result_type;
  Hyperbolic_segment_2 operator()(const Point_2& p, const Point_2& q) const
  {
    const std::pair<Point_2, Point_2> e = ideal_endpoints(p, q);
    return Hyperbolic_segment_2(e.first, e.second);
  }
  Hyperbolic_segment_2 operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    const Point_2 c = Construct_hyperbolic_circumcenter_2<Traits>()(p, q, r);
    const std::pair<Point_2, Point_2> e = ideal_endpoints(p, q);
    // keep the ideal end on the other side of the geodesic pq than r
    const Orientation orr = typename Traits::Orientation_2()(p, q, r);
    const Orientation oe = Exact_evaluator<FT>::eval(klein_poly, p.x(), p.y(), q.x(), q.y(), e.first.x(), e.first.y());
    return Hyperbolic_segment_2(c, oe != orr ? e.first : e.second);
  }
  Hyperbolic_segment_2 operator()(const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& s) const
  {
    return Hyperbolic_segment_2(Construct_hyperbolic_circumcenter_2<Traits>()(p, q, r),
                                Construct_hyperbolic_circumcenter_2<Traits>()(p, s, q));
  }
  /// the two points of the unit circle on the bisector of p and q, in counterclockwise order seen from p
  static std::pair<Point_2, Point_2> ideal_endpoints(const Point_2& p, const Point_2& q)
  {
    check_point_in_disk(p, "Construct_hyperbolic_bisector_2");
    check_point_in_disk(q, "Construct_hyperbolic_bisector_2");
    using namespace Poincare_disk_internal;
    // { z : a |z|^2 - 2 z.v + a = 0 },  a = n_q - n_p, v = n_q p - n_p q; on |z| = 1: z.v = a
    const FT np = lift_n(p.x(), p.y()), nq = lift_n(q.x(), q.y());
    const FT a = nq - np, vx = nq * p.x() - np * q.x(), vy = nq * p.y() - np * q.y();
    const FT v2 = vx * vx + vy * vy;
    const FT h = sqrt_of<FT>(v2 - a * a);
    // z = (a v +- h v_perp) / |v|^2, v_perp = (-vy, vx)
    const Point_2 z1((a * vx - h * vy) / v2, (a * vy + h * vx) / v2);
    const Point_2 z2((a * vx + h * vy) / v2, (a * vy - h * vx) / v2);
    return std::make_pair(z1, z2);
  }
private:
  struct Klein_poly {
    template <class NT>
    auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry) const
    { return CGAL::sign(klein_orientation_det(px, py, qx, qy, rx, ry)); }
  };
  static constexpr Klein_poly klein_poly{};
};

template <class Traits>
class Intersect_2
{
public:
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::Segment_2 Segment_2;
  typedef boost::optional<boost::variant<Point_2, Segment_2> > result_type;
  result_type operator()(const Segment_2& s1, const Segment_2& s2) const
  {
    const Point_2 &a = s1.source(), &b = s1.target(), &c = s2.source(), &d = s2.target();
    typename Traits::Orientation_2 o;
    const Orientation abc = o(a, b, c), abd = o(a, b, d), cda = o(c, d, a), cdb = o(c, d, b);
    if(abc == COLLINEAR && abd == COLLINEAR) {
      // on one geodesic: CGAL's CDT only asks for crossings, overlaps are handled combinatorially
      return result_type();
    }
    if(abc == abd || cda == cdb) return result_type(); // no crossing
    if(abc == COLLINEAR) return result_type(boost::variant<Point_2, Segment_2>(c));
    if(abd == COLLINEAR) return result_type(boost::variant<Point_2, Segment_2>(d));
    if(cda == COLLINEAR) return result_type(boost::variant<Point_2, Segment_2>(a));
    if(cdb == COLLINEAR) return result_type(boost::variant<Point_2, Segment_2>(b));
    return result_type(boost::variant<Point_2, Segment_2>(intersection_point(a, b, c, d)));
  }
  /// intersection of the geodesic lines ab and cd (precondition: they cross inside the disk)
  static Point_2 intersection_point(const Point_2& a, const Point_2& b, const Point_2& c, const Point_2& d)
  {
    typename Traits::Construct_Klein_point_2 k;
    const Point_2 ka = k(a), kb = k(b), kc = k(c), kd = k(d);
    // ka + t (kb - ka) on the line kc kd
    const FT ux = kb.x() - ka.x(), uy = kb.y() - ka.y(), vx = kd.x() - kc.x(), vy = kd.y() - kc.y();
    const FT den = ux * vy - uy * vx;
    const FT t = ((kc.x() - ka.x()) * vy - (kc.y() - ka.y()) * vx) / den;
    const FT x = ka.x() + t * ux, y = ka.y() + t * uy;
    // the crossing is inside the disk (exact orientations); with a rounded number type it may round onto or
    // outside the circle at infinity (two geodesics crossing at |z| = 1 - 1e-9: |k| = 1 - 1e-18)
    const double dx = CGAL::to_double(x), dy = CGAL::to_double(y);
    if(!(std::isfinite(dx) && std::isfinite(dy)) || !(x * x + y * y < FT(1)))
      throw Numerical_error("Intersect_2: the crossing of two geodesics is too close to the circle at infinity to "
                            "be represented with this number type (use an exact number type, or constraints that "
                            "cross farther inside)");
    return typename Traits::Construct_point_from_Klein_2()(Point_2(x, y));
  }
};

} // namespace Poincare_disk_internal
} // namespace CGAL

#endif // CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_CONSTRUCTION_FUNCTORS_H
