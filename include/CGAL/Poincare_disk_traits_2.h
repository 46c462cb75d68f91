// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Poincare_disk_traits_2: geometric traits of the hyperbolic plane in the Poincare disk model, with exact,
// filtered predicates and hyperbolic constructions. Plugs into CGAL's Delaunay_triangulation_2,
// Constrained_Delaunay_triangulation_2, Hyperbolic_Delaunay_triangulation_2 and refine_Delaunay_mesh_2.
#ifndef CGAL_POINCARE_DISK_TRAITS_2_H
#define CGAL_POINCARE_DISK_TRAITS_2_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_structural_filtering_traits.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Poincare_disk_isometry_2.h>
#include <CGAL/Poincare_disk_traits_2/internal/checks.h>
#include <CGAL/Poincare_disk_traits_2/internal/constructions.h>
#include <CGAL/Poincare_disk_traits_2/internal/construction_functors.h>
#include <CGAL/Poincare_disk_traits_2/internal/exponential_map.h>
#include <CGAL/Poincare_disk_traits_2/internal/model_conversions.h>
#include <CGAL/Poincare_disk_traits_2/internal/filtered_evaluation.h>
#include <CGAL/Poincare_disk_traits_2/internal/polynomials.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <boost/optional.hpp>
#include <boost/variant.hpp>

#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {

/*!
  \ingroup PkgPoincareDiskTraits2Ref

  Geometric traits of the hyperbolic plane in the Poincare disk model.

  A point is a `Kernel::Point_2` with Poincare coordinates z = (x, y), |z| < 1. Geodesics are arcs of circles
  orthogonal to the unit circle (straight lines in the Klein model k(z) = 2z / (1 + |z|^2)).

  Every predicate is the sign of a polynomial in the Poincare coordinates of its arguments:
  - `Orientation_2`: side of the geodesic through p, q (the Klein orientation det[[2x, 2y, 1 + |z|^2]]);
  - `Compare_x_2`, `Compare_y_2`: Klein coordinates, so that points on a geodesic are sorted along it;
  - `Side_of_oriented_circle_2`: the Euclidean in-circle determinant of the Poincare coordinates, which is the side
    of the hyperboloid lift of s w.r.t. the plane through the lifts of p, q, r. With the Klein orientation, CGAL's
    `Delaunay_triangulation_2` computes the hyperbolic Delaunay triangulation of the hyperbolic convex hull
    (Epstein-Penner); faces whose circumcircle leaves the disk have horocycles/hypercycles as empty "circles";
  - `Is_Delaunay_hyperbolic`, `Side_of_hyperbolic_diametral_circle_2`, `Compare_central_angle_2`,
    `Compare_hyperbolic_distance_2`, `Compare_hyperbolic_circumradius_2`: see each functor.
  With `Kernel = Epick` they are filtered (static filter, then interval arithmetic, then exact rationals built
  exactly from the doubles), hence exact on all double input. With exact kernels (`Epeck`,
  `Exact_predicates_exact_constructions_kernel_with_sqrt`, `Simple_cartesian<Gmpq>`) they are evaluated exactly.

  Constructions are rounded with `Epick`, exact with a kernel whose FT has an exact square root; with
  `Simple_cartesian<Gmpq>` the rational ones (Klein and hyperboloid images, supporting circles, hyperbolic circles
  from a rational `sinh^2(r/2)`, isometries) are exact and those that need a square root are rounded through
  `double`.

  Input points on or outside the unit circle, or with non-finite coordinates, make the predicates used at
  insertion (`Less_x_2`, `Less_y_2`, `Compare_x_2`, `Compare_y_2`, `Orientation_2`) and every construction throw
  `Poincare_disk_domain_error`. Range insertion (`insert(first, last)` and the range constructors) validates all
  points before the triangulation is modified (see `spatial_sort()` below). CGAL calls no traits function when
  the first vertex is inserted alone into an empty triangulation: such a bad point is reported by the next
  insertion, whose predicates involve it.

  \cgalModels `DelaunayTriangulationTraits_2`
  \cgalModels `ConstrainedDelaunayTriangulationTraits_2`
  \cgalModels `HyperbolicDelaunayTriangulationTraits_2`
  \cgalModels `DelaunayMeshTraits_2`
*/
template <class Kernel_ = Exact_predicates_inexact_constructions_kernel>
class Poincare_disk_traits_2
{
  typedef Poincare_disk_traits_2<Kernel_> Self;

public:
  typedef Kernel_                       Kernel;
  typedef typename Kernel::FT           FT;
  typedef typename Kernel::RT           RT;
  typedef typename Kernel::Point_2      Point_2;
  typedef typename Kernel::Segment_2    Segment_2;   ///< a geodesic segment given by its two endpoints
  typedef typename Kernel::Triangle_2   Triangle_2;  ///< a geodesic triangle given by its three vertices
  typedef typename Kernel::Line_2       Line_2;
  typedef typename Kernel::Ray_2        Ray_2;
  typedef typename Kernel::Vector_2     Vector_2;
  typedef typename Kernel::Direction_2  Direction_2;
  typedef typename Kernel::Circle_2     Circle_2;
  typedef typename Kernel::Iso_rectangle_2 Iso_rectangle_2;
  typedef typename Kernel::Point_3      Point_3;
  typedef typename Kernel::Angle_2::result_type Angle;

  // HyperbolicDelaunayTriangulationTraits_2
  typedef Point_2                                  Hyperbolic_point_2;
  typedef Point_2                                  Hyperbolic_Voronoi_point_2;
  typedef Triangle_2                               Hyperbolic_triangle_2;
  typedef Poincare_disk_geodesic_segment_2<Kernel> Hyperbolic_segment_2;
  typedef Poincare_disk_isometry_2<Kernel>         Isometry_2;

  Poincare_disk_traits_2(const Kernel& k = Kernel()) : kernel_(k) {}

  const Kernel& kernel() const { return kernel_; }

private:
  typedef Poincare_disk_internal::Exact_evaluator<FT> Eval;
  static constexpr bool is_double = std::is_same<FT, double>::value;

  // ---------------------------------------------------------------- input checks
  // Exact check that p is a finite point of the open disk. For double input the common case costs one
  // comparison on 1 + |p|^2, which the static filters compute anyway.
  static void check(const Point_2& p, const char* where) { Poincare_disk_internal::check_point_in_disk(p, where); }
  // A threshold of a comparison predicate must be finite (a NaN would reach GMP's mpq_set_d: SIGFPE).
  static void check_threshold(const FT& t, const char* where)
  {
    if(!Poincare_disk_internal::is_finite_coordinate(t))
      throw Invalid_input_error(std::string(where) + ": the threshold is not finite");
  }

public:
  // ================================================================ predicates

  /// Klein orientation: LEFT_TURN iff r lies to the left of the oriented geodesic from p to q.
  class Orientation_2
  {
  public:
    typedef Orientation result_type;
    Orientation result(const Point_2& p, const Point_2& q, const Point_2& r) const { return (*this)(p, q, r); }
    Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      check(p, "Orientation_2"); check(q, "Orientation_2"); check(r, "Orientation_2");
      if constexpr(is_double) {
        // Static filter: |x|, |y| < 1 and w < 2 give |det| error <= ~98 u < 3e-14 (u = 2^-53).
        CGAL_PD_COUNT(calls);
        const double det = Poincare_disk_internal::klein_orientation_det(p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
        if(det > 3e-14) return LEFT_TURN;
        if(det < -3e-14) return RIGHT_TURN;
        return Eval::eval_after_static_filter(orientation_poly, p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
      } else {
        return Eval::eval(orientation_poly, p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
      }
    }
  private:
    struct Poly {
      template <class NT>
      auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry) const
      { return CGAL::sign(Poincare_disk_internal::klein_orientation_det(px, py, qx, qy, rx, ry)); }
    };
    static constexpr Poly orientation_poly{};
  };

  /// Compares the Klein x-coordinates (x / (1 + |z|^2)): points on a geodesic are monotone in it.
  class Compare_x_2
  {
  public:
    typedef Comparison_result result_type;
    Comparison_result operator()(const Point_2& p, const Point_2& q) const
    {
      check(p, "Compare_x_2"); check(q, "Compare_x_2");
      return compare_klein(p.x(), p.y(), q.x(), q.y());
    }
    // shared with Compare_y_2 (swap the coordinates)
    static Comparison_result compare_klein(const FT& px, const FT& py, const FT& qx, const FT& qy)
    {
      if constexpr(is_double) {
        CGAL_PD_COUNT(calls);
        const double d = Poincare_disk_internal::klein_x_difference(px, py, qx, qy);
        if(d > 1e-14) return LARGER;
        if(d < -1e-14) return SMALLER;
        return Eval::eval_after_static_filter(poly, px, py, qx, qy);
      } else {
        return Eval::eval(poly, px, py, qx, qy);
      }
    }
  private:
    struct Poly {
      template <class NT>
      auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy) const
      { return CGAL::sign(Poincare_disk_internal::klein_x_difference(px, py, qx, qy)); }
    };
    static constexpr Poly poly{};
  };

  /// Compares the Klein y-coordinates.
  class Compare_y_2
  {
  public:
    typedef Comparison_result result_type;
    Comparison_result operator()(const Point_2& p, const Point_2& q) const
    {
      check(p, "Compare_y_2"); check(q, "Compare_y_2");
      return Compare_x_2::compare_klein(p.y(), p.x(), q.y(), q.x());
    }
  };

  class Less_x_2
  {
  public:
    typedef bool result_type;
    bool operator()(const Point_2& p, const Point_2& q) const { return Compare_x_2()(p, q) == SMALLER; }
  };

  class Less_y_2
  {
  public:
    typedef bool result_type;
    bool operator()(const Point_2& p, const Point_2& q) const { return Compare_y_2()(p, q) == SMALLER; }
  };

  /// Lexicographic Klein comparison (x, then y).
  class Compare_xy_2
  {
  public:
    typedef Comparison_result result_type;
    Comparison_result operator()(const Point_2& p, const Point_2& q) const
    {
      const Comparison_result c = Compare_x_2()(p, q);
      return c != EQUAL ? c : Compare_y_2()(p, q);
    }
  };

  class Less_xy_2
  {
  public:
    typedef bool result_type;
    bool operator()(const Point_2& p, const Point_2& q) const { return Compare_xy_2()(p, q) == SMALLER; }
  };

  /// p, q, r on a common geodesic.
  class Collinear_2
  {
  public:
    typedef bool result_type;
    bool operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    { return Orientation_2()(p, q, r) == COLLINEAR; }
  };

  /// The in-circle predicate: the kernel's Euclidean one on Poincare coordinates (exact and, with Epick,
  /// statically filtered). ON_POSITIVE_SIDE iff s is inside the hyperbolic circle (or horocycle / hypercycle)
  /// through p, q, r when (p, q, r) is positively oriented (Klein orientation). See the class documentation.
  /// Throws `Poincare_disk_domain_error` for a point outside the open disk, as the other predicates.
  class Side_of_oriented_circle_2
  {
  public:
    typedef Oriented_side result_type;
    Side_of_oriented_circle_2(const typename Kernel::Side_of_oriented_circle_2& k =
                                  typename Kernel::Side_of_oriented_circle_2()) : k_(k) {}
    Oriented_side operator()(const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& s) const
    {
      check(p, "Side_of_oriented_circle_2"); check(q, "Side_of_oriented_circle_2");
      check(r, "Side_of_oriented_circle_2"); check(s, "Side_of_oriented_circle_2");
      return k_(p, q, r, s);
    }
  private:
    typename Kernel::Side_of_oriented_circle_2 k_;
  };

  /// true iff the Euclidean circumcircle of p, q, r lies inside the open unit disk, i.e. it is a hyperbolic
  /// circle (compact). With `int& ind`, when false, `ind` is the index of the edge (opposite vertex `ind` of
  /// (p0, p1, p2)) beyond which the circumcircle leaves the disk.
  class Is_Delaunay_hyperbolic
  {
  public:
    typedef bool result_type;
    /// false (and no exception) when a point is not a finite point of the open disk: CGAL's
    /// Hyperbolic_Delaunay_triangulation_2 evaluates this predicate on its infinite faces too, whose infinite
    /// vertex carries an arbitrary point.
    bool operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      if(bad_vertex(p, q, r) >= 0) return false;
      return Eval::eval(poly, p.x(), p.y(), q.x(), q.y(), r.x(), r.y()) == POSITIVE;
    }
    bool operator()(const Point_2& p0, const Point_2& p1, const Point_2& p2, int& ind) const
    {
      const int bad = bad_vertex(p0, p1, p2);
      if(bad >= 0) { ind = (bad + 1) % 3; return false; } // an edge through the bad (infinite) vertex
      if(Eval::eval(poly, p0.x(), p0.y(), p1.x(), p1.y(), p2.x(), p2.y()) == POSITIVE) return true;
      ind = Eval::eval(edge_poly, p0.x(), p0.y(), p1.x(), p1.y(), p2.x(), p2.y());
      return false;
    }
  private:
    static bool in_disk(const Point_2& p)
    {
      if constexpr(is_double) {
        const double w = 1.0 + p.x() * p.x() + p.y() * p.y();
        if(w < 1.9999999999999) return true;
      }
      return Poincare_disk_internal::is_in_open_disk(p);
    }
    static int bad_vertex(const Point_2& p, const Point_2& q, const Point_2& r)
    {
      return !in_disk(p) ? 0 : (!in_disk(q) ? 1 : (!in_disk(r) ? 2 : -1));
    }

    struct Poly {
      template <class NT>
      auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry) const
      { return CGAL::sign(Poincare_disk_internal::Circle_coefficients<NT>(px, py, qx, qy, rx, ry).delta()); }
    };
    static constexpr Poly poly{};

    // The arc of the circumcircle outside the disk contains the point of the circle farthest from the origin,
    // in direction c (the Euclidean centre) seen from c. It lies on the arc between two consecutive vertices;
    // the edge joining them is the answer. Signs of cross products: intervals first, then exact.
    struct Edge_poly {
      template <class NT>
      int operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry) const
      {
        const NT x[3] = {px, qx, rx}, y[3] = {py, qy, ry};
        const Poincare_disk_internal::Circle_coefficients<NT> cc(px, py, qx, qy, rx, ry);
        const bool ccw = (CGAL::sign(cc.A) == POSITIVE);
        if(!ccw && CGAL::sign(cc.A) == ZERO) return 0; // Euclidean-collinear: a line, any answer is as good
        // centre c = (-B, -C) / (2A); vectors from c to the vertices, scaled by 2A sign(A) > 0
        const NT sa(ccw ? 1 : -1);
        NT vx[3], vy[3];
        for(int i = 0; i < 3; ++i) { vx[i] = sa * (NT(2) * cc.A * x[i] + cc.B); vy[i] = sa * (NT(2) * cc.A * y[i] + cc.C); }
        const NT dx = -sa * cc.B, dy = -sa * cc.C; // direction of c from the origin
        auto positive_cross = [](const NT& ax, const NT& ay, const NT& bx, const NT& by) -> bool {
          return CGAL::sign(ax * by - ay * bx) == POSITIVE;
        };
        // d strictly counterclockwise between a and b (turning counterclockwise from a to b)
        auto ccw_between = [&](int a, int b) -> bool {
          const bool ab = positive_cross(vx[a], vy[a], vx[b], vy[b]);
          const bool ad = positive_cross(vx[a], vy[a], dx, dy), db = positive_cross(dx, dy, vx[b], vy[b]);
          return ab ? (ad && db) : (ad || db);
        };
        // walk the vertices counterclockwise around c
        const int order[3] = {0, ccw ? 1 : 2, ccw ? 2 : 1};
        for(int k = 0; k < 3; ++k) {
          const int a = order[k], b = order[(k + 1) % 3];
          if(ccw_between(a, b)) return 3 - a - b; // the edge (a, b) is opposite vertex 3 - a - b
        }
        return 0;
      }
    };
    static constexpr Edge_poly edge_poly{};
  };

  /// Side of the geodesic line through p and q (ON_ORIENTED_BOUNDARY iff the query is on it). Consistent with
  /// `Orientation_2`: ON_POSITIVE_SIDE iff LEFT_TURN.
  class Side_of_oriented_hyperbolic_segment_2
  {
  public:
    typedef Oriented_side result_type;
    Oriented_side operator()(const Point_2& p, const Point_2& q, const Point_2& query) const
    {
      return Oriented_side(Orientation_2()(p, q, query));
    }
  };

  /// Hyperbolic encroachment: ON_BOUNDED_SIDE iff s lies strictly inside the hyperbolic disk whose diameter is
  /// the geodesic segment pq (s encroaches pq), ON_BOUNDARY on its circle, ON_UNBOUNDED_SIDE outside.
  /// Polynomial: |p-q|^2 (1-|s|^2) - |s-p|^2 (1-|q|^2) - |s-q|^2 (1-|p|^2) (positive inside).
  class Side_of_hyperbolic_diametral_circle_2
  {
  public:
    typedef Bounded_side result_type;
    Bounded_side operator()(const Point_2& p, const Point_2& q, const Point_2& s) const
    {
      check(p, "Side_of_hyperbolic_diametral_circle_2"); check(q, "Side_of_hyperbolic_diametral_circle_2");
      check(s, "Side_of_hyperbolic_diametral_circle_2");
      const Sign sg = Eval::eval(poly, p.x(), p.y(), q.x(), q.y(), s.x(), s.y());
      return sg == POSITIVE ? ON_BOUNDED_SIDE : (sg == ZERO ? ON_BOUNDARY : ON_UNBOUNDED_SIDE);
    }
  private:
    struct Poly {
      template <class NT>
      auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& sx, const NT& sy) const
      { return CGAL::sign(Poincare_disk_internal::diametral_disk_polynomial(px, py, qx, qy, sx, sy)); }
    };
    static constexpr Poly poly{};
  };

  /// Compares d(p, q) with d(p, r); with four points, d(p, q) with d(r, s).
  class Compare_hyperbolic_distance_2
  {
  public:
    typedef Comparison_result result_type;
    Comparison_result operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      check(p, "Compare_hyperbolic_distance_2"); check(q, "Compare_hyperbolic_distance_2");
      check(r, "Compare_hyperbolic_distance_2");
      return Eval::eval(poly3, p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
    }
    Comparison_result operator()(const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& s) const
    {
      check(p, "Compare_hyperbolic_distance_2"); check(q, "Compare_hyperbolic_distance_2");
      check(r, "Compare_hyperbolic_distance_2"); check(s, "Compare_hyperbolic_distance_2");
      return Eval::eval(poly4, p.x(), p.y(), q.x(), q.y(), r.x(), r.y(), s.x(), s.y());
    }
  private:
    struct Poly3 {
      template <class NT>
      auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry) const
      { return CGAL::sign(Poincare_disk_internal::distance_comparison_polynomial(px, py, qx, qy, rx, ry)); }
    };
    struct Poly4 {
      template <class NT>
      auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy,
                      const NT& rx, const NT& ry, const NT& sx, const NT& sy) const
      { return CGAL::sign(Poincare_disk_internal::distance_comparison_polynomial_4(px, py, qx, qy, rx, ry, sx, sy)); }
    };
    static constexpr Poly3 poly3{};
    static constexpr Poly4 poly4{};
  };

  /// `Compare_distance_2` of the triangulation concepts is the hyperbolic one.
  typedef Compare_hyperbolic_distance_2 Compare_distance_2;

  /// Central angle of the shortest edge of triangle pqr in its hyperbolic circumcircle, compared with a threshold
  /// theta given as `sin2_half_theta = sin^2(theta / 2)` (0 < theta <= pi). SMALLER iff the angle is below theta.
  /// With h the circumradius, sin^2(alpha/2) = sinh^2(d/2) / sinh^2 h (d: the edge length): all rational.
  /// A triangle whose circumcircle is not compact (horocycle / hypercycle, "infinite radius") has central angle
  /// 0: SMALLER for every positive threshold.
  class Compare_central_angle_2
  {
  public:
    typedef Comparison_result result_type;
    Comparison_result operator()(const Point_2& p, const Point_2& q, const Point_2& r, const FT& sin2_half_theta) const
    {
      check(p, "Compare_central_angle_2"); check(q, "Compare_central_angle_2"); check(r, "Compare_central_angle_2");
      check_threshold(sin2_half_theta, "Compare_central_angle_2");
      return Eval::eval(poly, p.x(), p.y(), q.x(), q.y(), r.x(), r.y(), sin2_half_theta);
    }
  private:
    struct Poly {
      template <class NT>
      auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry,
                      const NT& s) const
      {
        using namespace Poincare_disk_internal;
        const Circle_coefficients<NT> cc(px, py, qx, qy, rx, ry);
        const NT delta = cc.delta();
        const NT npq = lift_n(px, py), nqq = lift_n(qx, qy), nr = lift_n(rx, ry);
        const NT dpq = squared_euclidean(px, py, qx, qy), dqr = squared_euclidean(qx, qy, rx, ry),
                 drp = squared_euclidean(rx, ry, px, py);
        // A(x, y) = |x - y|^2 / (n_x n_y); compare A(pq) = dpq / (np nq), A(qr) = dqr / (nq nr), A(rp) = drp / (nr np)
        // by cross-multiplying with the positive n's: A(pq) < A(qr)  <=>  dpq nr < dqr np.
        const NT apq = dpq * nr, aqr = dqr * npq, arp = drp * nqq; // each = A(.) * np nq nr
        // shortest edge value A_min * np nq nr, chosen with exact comparisons
        const auto pq_le_qr = (apq <= aqr), pq_le_rp = (apq <= arp), qr_le_rp = (aqr <= arp);
        typedef decltype(CGAL::sign(delta)) Result_sign;
        // sin^2(alpha/2) = A_min / sinh^2 h = A_min * delta / (B^2 + C^2 - 4AG);
        // compare with s: sign(A_min * delta - s * (B^2 + C^2 - 4AG))   (both denominators positive when delta > 0)
        const NT sinh2num = cc.sinh2_numerator();
        const NT nn = npq * nqq * nr;
        auto result_for = [&](const NT& a_min_times_nn) -> Result_sign {
          return CGAL::sign(a_min_times_nn * delta - s * sinh2num * nn);
        };
        const Result_sign dsign = CGAL::sign(delta);
        return combine(dsign, pq_le_qr, pq_le_rp, qr_le_rp, result_for, apq, aqr, arp);
      }

      // double/exact: plain booleans and signs
      template <class F, class NT>
      static Sign combine(Sign dsign, bool pq_le_qr, bool pq_le_rp, bool qr_le_rp, const F& result_for,
                          const NT& apq, const NT& aqr, const NT& arp)
      {
        if(dsign != POSITIVE) return NEGATIVE; // not compact: central angle 0
        if(pq_le_qr && pq_le_rp) return result_for(apq);
        if(qr_le_rp) return result_for(aqr);
        return result_for(arp);
      }
      // intervals: uncertain booleans; an uncertain one throws Uncertain_conversion_exception -> exact fallback
      template <class F, class NT>
      static Uncertain<Sign> combine(Uncertain<Sign> dsign, Uncertain<bool> pq_le_qr, Uncertain<bool> pq_le_rp,
                                     Uncertain<bool> qr_le_rp, const F& result_for,
                                     const NT& apq, const NT& aqr, const NT& arp)
      {
        if(dsign.make_certain() != POSITIVE) return NEGATIVE;
        if(pq_le_qr.make_certain() && pq_le_rp.make_certain()) return result_for(apq);
        if(qr_le_rp.make_certain()) return result_for(aqr);
        return result_for(arp);
      }
    };
    static constexpr Poly poly{};
  };

  /// Compares the hyperbolic circumradius h of p, q, r with a bound given as `cosh2_bound = cosh^2(bound)`.
  /// Exact: cosh^2 h = (A - G)^2 / Delta (see internal/polynomials.h). Non-compact circumcircles: LARGER.
  class Compare_hyperbolic_circumradius_2
  {
  public:
    typedef Comparison_result result_type;
    Comparison_result operator()(const Point_2& p, const Point_2& q, const Point_2& r, const FT& cosh2_bound) const
    {
      check(p, "Compare_hyperbolic_circumradius_2"); check(q, "Compare_hyperbolic_circumradius_2");
      check(r, "Compare_hyperbolic_circumradius_2");
      check_threshold(cosh2_bound, "Compare_hyperbolic_circumradius_2");
      return Eval::eval(poly, p.x(), p.y(), q.x(), q.y(), r.x(), r.y(), cosh2_bound);
    }
  private:
    struct Poly {
      template <class NT>
      auto operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry,
                      const NT& c2) const
      {
        const Poincare_disk_internal::Circle_coefficients<NT> cc(px, py, qx, qy, rx, ry);
        const NT delta = cc.delta();
        // cosh^2 h - c2 has the sign of (A - G)^2 - c2 Delta = (B^2 + C^2 - 4AG) - (c2 - 1) Delta: the same
        // polynomial, written with sinh^2 h so that small radii do not cancel (c2 - 1 is exact for c2 in [1, 2]).
        return combine(CGAL::sign(delta), cc.sinh2_numerator() - (c2 - NT(1)) * delta);
      }
      template <class NT>
      static Uncertain<Sign> combine(Uncertain<Sign> dsign, const NT& diff)
      { return dsign.make_certain() != POSITIVE ? Uncertain<Sign>(POSITIVE) : CGAL::sign(diff); }
      template <class NT>
      static Sign combine(Sign dsign, const NT& diff) { return dsign != POSITIVE ? POSITIVE : Sign(CGAL::sign(diff)); }
    };
    static constexpr Poly poly{};
  };

  /// The encroachment test of `refine_Delaunay_mesh_2`: `Angle_2(a, p, b)` is OBTUSE iff p is strictly inside
  /// the hyperbolic diametral disk of the geodesic segment ab, RIGHT on its circle, ACUTE outside (in the
  /// Euclidean limit this is the Thales test on the angle apb; in H^2 the two differ).
  class Angle_2
  {
  public:
    typedef Angle result_type;
    Angle operator()(const Point_2& a, const Point_2& p, const Point_2& b) const
    {
      const Bounded_side bs = Side_of_hyperbolic_diametral_circle_2()(a, b, p);
      return bs == ON_BOUNDED_SIDE ? OBTUSE : (bs == ON_BOUNDARY ? RIGHT : ACUTE);
    }
  };

  // ================================================================ constructions

  /// cosh d(p, q) = 1 + 2 |p - q|^2 / ((1 - |p|^2)(1 - |q|^2)), exact.
  class Compute_cosh_hyperbolic_distance_2
  {
  public:
    typedef FT result_type;
    FT operator()(const Point_2& p, const Point_2& q) const
    {
      check(p, "Compute_cosh_hyperbolic_distance_2"); check(q, "Compute_cosh_hyperbolic_distance_2");
      using namespace Poincare_disk_internal;
      return FT(1) + FT(2) * squared_euclidean(p.x(), p.y(), q.x(), q.y()) /
                           (lift_n(p.x(), p.y()) * lift_n(q.x(), q.y()));
    }
  };

  /// d(p, q) = 2 asinh(sqrt(A)), A = |p - q|^2 / ((1 - |p|^2)(1 - |q|^2)); rounded (through double).
  class Compute_hyperbolic_distance_2
  {
  public:
    typedef FT result_type;
    FT operator()(const Point_2& p, const Point_2& q) const
    {
      check(p, "Compute_hyperbolic_distance_2"); check(q, "Compute_hyperbolic_distance_2");
      using namespace Poincare_disk_internal;
      const FT a = squared_euclidean(p.x(), p.y(), q.x(), q.y()) / (lift_n(p.x(), p.y()) * lift_n(q.x(), q.y()));
      return FT(2.0 * std::asinh(std::sqrt(CGAL::to_double(a))));
    }
  };

  /// Hyperbolic circumcenter of p, q, r; throws `Poincare_disk_domain_error` if the circumcircle is not compact
  /// (check `Is_Delaunay_hyperbolic` first). Needs a square root (rounded unless FT has an exact one).
  typedef Poincare_disk_internal::Construct_hyperbolic_circumcenter_2<Self> Construct_hyperbolic_circumcenter_2;

  /// `Construct_circumcenter_2` of the triangulation / mesher concepts: the hyperbolic circumcenter when the
  /// circumcircle is compact; otherwise (no hyperbolic centre exists) the hyperbolic midpoint of the longest
  /// edge, which is where `refine_Delaunay_mesh_2` should split such a face. Documented limit.
  typedef Poincare_disk_internal::Construct_circumcenter_2<Self> Construct_circumcenter_2;

  /// Hyperbolic midpoint of the geodesic segment pq: the normalized sum of the hyperboloid lifts.
  typedef Poincare_disk_internal::Construct_hyperbolic_midpoint_2<Self> Construct_hyperbolic_midpoint_2;

  /// `Construct_midpoint_2` of the triangulation / mesher concepts is the hyperbolic midpoint, so that
  /// `refine_Delaunay_mesh_2` splits constrained edges on their geodesic.
  typedef Construct_hyperbolic_midpoint_2 Construct_midpoint_2;

  /// The point of the geodesic segment pq at distance t d(p, q) from p (rounded).
  typedef Poincare_disk_internal::Construct_hyperbolic_point_on_segment_2<Kernel> Construct_hyperbolic_point_on_segment_2;

  /// The geodesic segment from p to q (an arc orthogonal to the unit circle, or a piece of a diameter).
  typedef Poincare_disk_internal::Construct_hyperbolic_segment_2<Self> Construct_hyperbolic_segment_2;

  /// Hyperbolic bisectors (Voronoi edges): (p, q) the whole geodesic line equidistant from p and q, between its
  /// two ideal endpoints; (p, q, r) the ray from the circumcenter of pqr to the ideal point on the side of the
  /// geodesic pq away from r; (p, q, r, s) the segment between the circumcenters of pqr and of psq.
  typedef Poincare_disk_internal::Construct_hyperbolic_bisector_2<Self> Construct_hyperbolic_bisector_2;

  /// The Euclidean circle that is the hyperbolic circle of centre c and radius r, with the radius given as
  /// `sinh2_half_radius = sinh^2(r/2)` (rational: exact on exact FT), or as the radius itself (rounded).
  /// Euclidean centre c / (1 + s n_c), squared radius |centre|^2 - (|c|^2 - s n_c) / (1 + s n_c), n_c = 1 - |c|^2.
  typedef Poincare_disk_internal::Construct_hyperbolic_circle_2<Kernel> Construct_hyperbolic_circle_2;

  /// Hyperbolic centre and radius of a Euclidean circle contained in the open unit disk (Lemma 3.3 of the thesis);
  /// throws `Poincare_disk_domain_error` if the circle is not inside the disk. Rounded.
  typedef Poincare_disk_internal::Construct_hyperbolic_circle_from_Euclidean_2<Self> Construct_hyperbolic_circle_from_Euclidean_2;

  /// Intersection of two geodesic segments given by their endpoints (`Segment_2`), as CGAL's
  /// `Constrained_triangulation_2` with `Exact_predicates_tag` asks for it: the intersection of the two Klein
  /// straight lines, mapped back to Poincare coordinates (one square root: rounded unless FT has an exact one).
  /// Empty when the segments do not cross (decided with the exact `Orientation_2`). Throws `Numerical_error`
  /// when a rounded crossing falls onto or outside the circle at infinity (crossings within about 1e-9 of it
  /// on double coordinates); `Hyperbolic_mesh_2::insert_geodesic_pslg` rejects crossing segments before that.
  typedef Poincare_disk_internal::Intersect_2<Self> Intersect_2;

  // ---------------------------------------------------------------- models

  /// Klein image 2z / (1 + |z|^2) (rational).
  typedef Poincare_disk_internal::Construct_Klein_point_2<Kernel> Construct_Klein_point_2;

  /// Poincare point of a Klein point k: k / (1 + sqrt(1 - |k|^2)).
  typedef Poincare_disk_internal::Construct_point_from_Klein_2<Kernel> Construct_point_from_Klein_2;

  /// Hyperboloid lift (2x, 2y, 1 + |z|^2) / (1 - |z|^2) (rational).
  typedef Poincare_disk_internal::Construct_hyperboloid_point_3<Kernel> Construct_hyperboloid_point_3;

  /// Poincare point (X, Y) / (1 + T) of a point of the upper sheet of the hyperboloid (rational).
  typedef Poincare_disk_internal::Construct_point_from_hyperboloid_2<Kernel> Construct_point_from_hyperboloid_2;

  /// Upper half-plane image by the Cayley map w = i (1 + z) / (1 - z) (rational).
  typedef Poincare_disk_internal::Construct_upper_half_plane_point_2<Kernel> Construct_upper_half_plane_point_2;

  /// Poincare point (w - i) / (w + i) of a point w of the upper half-plane (rational).
  typedef Poincare_disk_internal::Construct_point_from_upper_half_plane_2<Kernel> Construct_point_from_upper_half_plane_2;

  /// Hyperbolic translations (`Isometry_2`): (a) takes a to the origin; (a, b) is the translation along the
  /// geodesic ab taking a to b.
  class Construct_hyperbolic_translation_2
  {
  public:
    typedef Isometry_2 result_type;
    Isometry_2 operator()(const Point_2& a) const { return Isometry_2::translation_to_origin(a); }
    Isometry_2 operator()(const Point_2& a, const Point_2& b) const
    {
      const Isometry_2 t = Isometry_2::translation_to_origin(a);
      return t.inverse() * Isometry_2::translation_from_origin(t(b)) * t;
    }
  };

  // ---------------------------------------------------------------- vectors: the exponential map
  // A vector at a point a is a tangent vector in Poincare coordinates scaled to hyperbolic length:
  // `Construct_vector_2(a, b)` = log_a(b) has the direction of the geodesic from a to b at a and length d(a, b);
  // `Construct_translated_point_2(a, v)` = exp_a(v) is the point at distance |v| from a on the geodesic leaving
  // a in direction v. Hence translate(a, s * vector(a, b)) is the point of the geodesic ray from a through b at
  // distance s d(a, b), and vector(a, midpoint(a, b)) * 2 = vector(a, b): CGAL's Mesh_2 relies on both when it
  // splits constrained edges near small input angles. Both are rounded (they need atanh / tanh).

  /// log_a(b): the direction of the geodesic from a to b at a, with length d(a, b) (rounded).
  typedef Poincare_disk_internal::Construct_vector_2<Kernel> Construct_vector_2;

  /// exp_a(v): the point at distance |v| from a on the geodesic leaving a in direction v (rounded).
  typedef Poincare_disk_internal::Construct_translated_point_2<Kernel> Construct_translated_point_2;

  typedef typename Kernel::Construct_scaled_vector_2      Construct_scaled_vector_2;

  /// For two points: 4 sinh^2(d(p, q) / 2) = 4 |p - q|^2 / ((1 - |p|^2)(1 - |q|^2)) = 2 (cosh d - 1), the squared
  /// Minkowski chord between the hyperboloid lifts: exact (rational), increasing in the hyperbolic distance d, and
  /// d^2 + O(d^4) for short edges, so CGAL's Mesh_2 can compare and scale edge lengths with it.
  /// Other argument lists (e.g. a line and a point, used by the constrained triangulation's fallback when an
  /// intersection cannot be constructed) are the kernel's Euclidean squared distances in Poincare coordinates.
  class Compute_squared_distance_2
  {
  public:
    typedef FT result_type;
    FT operator()(const Point_2& p, const Point_2& q) const
    {
      check(p, "Compute_squared_distance_2"); check(q, "Compute_squared_distance_2");
      using namespace Poincare_disk_internal;
      return FT(4) * squared_euclidean(p.x(), p.y(), q.x(), q.y()) / (lift_n(p.x(), p.y()) * lift_n(q.x(), q.y()));
    }
    template <class A, class B>
    FT operator()(const A& a, const B& b) const { return typename Kernel::Compute_squared_distance_2()(a, b); }
  };

  /// Signed hyperbolic area of the geodesic triangle pqr (positive iff LEFT_TURN), rounded:
  /// tan(area / 2) = det[L(p), L(q), L(r)] / (1 + cosh d(p,q) + cosh d(q,r) + cosh d(r,p)), L the hyperboloid lift
  /// (the numerator and denominator are rational). With `Compute_squared_distance_2`, CGAL's Euclidean criteria
  /// classes (`Delaunay_mesh_size_criteria_2`) then measure shape and size hyperbolically for small triangles.
  class Compute_area_2
  {
  public:
    typedef FT result_type;
    FT operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      check(p, "Compute_area_2"); check(q, "Compute_area_2"); check(r, "Compute_area_2");
      using namespace Poincare_disk_internal;
      const FT np = lift_n(p.x(), p.y()), nq = lift_n(q.x(), q.y()), nr = lift_n(r.x(), r.y());
      const FT det = FT(4) * klein_orientation_det(p.x(), p.y(), q.x(), q.y(), r.x(), r.y()) / (np * nq * nr);
      const FT den = FT(4) + FT(2) * (squared_euclidean(p.x(), p.y(), q.x(), q.y()) / (np * nq) +
                                      squared_euclidean(q.x(), q.y(), r.x(), r.y()) / (nq * nr) +
                                      squared_euclidean(r.x(), r.y(), p.x(), p.y()) / (nr * np));
      return FT(2 * std::atan2(CGAL::to_double(det), CGAL::to_double(den)));
    }
  };

  // ---------------------------------------------------------------- Euclidean functors required by the concepts
  // Combinatorial helpers of the triangulations (no hyperbolic meaning; documented as Euclidean):
  typedef typename Kernel::Construct_segment_2            Construct_segment_2;
  typedef typename Kernel::Construct_triangle_2           Construct_triangle_2;
  typedef typename Kernel::Construct_point_2              Construct_point_2;
  typedef typename Kernel::Construct_bbox_2               Construct_bbox_2;
  typedef typename Kernel::Construct_line_2               Construct_line_2;
  typedef typename Kernel::Construct_ray_2                Construct_ray_2;
  typedef typename Kernel::Construct_direction_2          Construct_direction_2;
  typedef typename Kernel::Construct_bisector_2           Construct_bisector_2;  ///< Euclidean (DT2's dim-1 dual)
  typedef typename Kernel::Equal_2                        Equal_2;
  typedef typename Kernel::Has_on_bounded_side_2          Has_on_bounded_side_2;

  // ================================================================ accessors
  Orientation_2 orientation_2_object() const { return Orientation_2(); }
  Compare_x_2 compare_x_2_object() const { return Compare_x_2(); }
  Compare_y_2 compare_y_2_object() const { return Compare_y_2(); }
  Less_x_2 less_x_2_object() const { return Less_x_2(); }
  Less_y_2 less_y_2_object() const { return Less_y_2(); }
  Compare_xy_2 compare_xy_2_object() const { return Compare_xy_2(); }
  Less_xy_2 less_xy_2_object() const { return Less_xy_2(); }
  Collinear_2 collinear_2_object() const { return Collinear_2(); }
  Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const
  { return Side_of_oriented_circle_2(kernel_.side_of_oriented_circle_2_object()); }
  Is_Delaunay_hyperbolic is_Delaunay_hyperbolic_2_object() const { return Is_Delaunay_hyperbolic(); }
  Side_of_oriented_hyperbolic_segment_2 side_of_oriented_hyperbolic_segment_2_object() const
  { return Side_of_oriented_hyperbolic_segment_2(); }
  Side_of_hyperbolic_diametral_circle_2 side_of_hyperbolic_diametral_circle_2_object() const
  { return Side_of_hyperbolic_diametral_circle_2(); }
  Compare_hyperbolic_distance_2 compare_hyperbolic_distance_2_object() const { return Compare_hyperbolic_distance_2(); }
  Compare_distance_2 compare_distance_2_object() const { return Compare_distance_2(); }
  Compare_central_angle_2 compare_central_angle_2_object() const { return Compare_central_angle_2(); }
  Compare_hyperbolic_circumradius_2 compare_hyperbolic_circumradius_2_object() const
  { return Compare_hyperbolic_circumradius_2(); }
  Angle_2 angle_2_object() const { return Angle_2(); }

  Compute_cosh_hyperbolic_distance_2 compute_cosh_hyperbolic_distance_2_object() const
  { return Compute_cosh_hyperbolic_distance_2(); }
  Compute_hyperbolic_distance_2 compute_hyperbolic_distance_2_object() const { return Compute_hyperbolic_distance_2(); }
  Construct_hyperbolic_circumcenter_2 construct_hyperbolic_circumcenter_2_object() const
  { return Construct_hyperbolic_circumcenter_2(); }
  Construct_circumcenter_2 construct_circumcenter_2_object() const { return Construct_circumcenter_2(); }
  Construct_hyperbolic_midpoint_2 construct_hyperbolic_midpoint_2_object() const
  { return Construct_hyperbolic_midpoint_2(); }
  Construct_midpoint_2 construct_midpoint_2_object() const { return Construct_midpoint_2(); }
  Construct_hyperbolic_point_on_segment_2 construct_hyperbolic_point_on_segment_2_object() const
  { return Construct_hyperbolic_point_on_segment_2(); }
  Construct_hyperbolic_segment_2 construct_hyperbolic_segment_2_object() const
  { return Construct_hyperbolic_segment_2(); }
  Construct_hyperbolic_bisector_2 construct_hyperbolic_bisector_2_object() const
  { return Construct_hyperbolic_bisector_2(); }
  Construct_hyperbolic_circle_2 construct_hyperbolic_circle_2_object() const { return Construct_hyperbolic_circle_2(); }
  Construct_hyperbolic_circle_from_Euclidean_2 construct_hyperbolic_circle_from_Euclidean_2_object() const
  { return Construct_hyperbolic_circle_from_Euclidean_2(); }
  Intersect_2 intersect_2_object() const { return Intersect_2(); }
  Construct_Klein_point_2 construct_Klein_point_2_object() const { return Construct_Klein_point_2(); }
  Construct_point_from_Klein_2 construct_point_from_Klein_2_object() const { return Construct_point_from_Klein_2(); }
  Construct_hyperboloid_point_3 construct_hyperboloid_point_3_object() const { return Construct_hyperboloid_point_3(); }
  Construct_point_from_hyperboloid_2 construct_point_from_hyperboloid_2_object() const
  { return Construct_point_from_hyperboloid_2(); }
  Construct_upper_half_plane_point_2 construct_upper_half_plane_point_2_object() const
  { return Construct_upper_half_plane_point_2(); }
  Construct_point_from_upper_half_plane_2 construct_point_from_upper_half_plane_2_object() const
  { return Construct_point_from_upper_half_plane_2(); }
  Construct_hyperbolic_translation_2 construct_hyperbolic_translation_2_object() const
  { return Construct_hyperbolic_translation_2(); }

  Construct_segment_2 construct_segment_2_object() const { return kernel_.construct_segment_2_object(); }
  Construct_triangle_2 construct_triangle_2_object() const { return kernel_.construct_triangle_2_object(); }
  Construct_point_2 construct_point_2_object() const { return kernel_.construct_point_2_object(); }
  Construct_bbox_2 construct_bbox_2_object() const { return kernel_.construct_bbox_2_object(); }
  Construct_line_2 construct_line_2_object() const { return kernel_.construct_line_2_object(); }
  Construct_ray_2 construct_ray_2_object() const { return kernel_.construct_ray_2_object(); }
  Construct_direction_2 construct_direction_2_object() const { return kernel_.construct_direction_2_object(); }
  Construct_vector_2 construct_vector_2_object() const { return Construct_vector_2(); }
  Construct_scaled_vector_2 construct_scaled_vector_2_object() const { return kernel_.construct_scaled_vector_2_object(); }
  Construct_translated_point_2 construct_translated_point_2_object() const { return Construct_translated_point_2(); }
  Construct_bisector_2 construct_bisector_2_object() const { return kernel_.construct_bisector_2_object(); }
  Compute_squared_distance_2 compute_squared_distance_2_object() const { return Compute_squared_distance_2(); }
  Compute_area_2 compute_area_2_object() const { return Compute_area_2(); }
  Equal_2 equal_2_object() const { return kernel_.equal_2_object(); }
  Has_on_bounded_side_2 has_on_bounded_side_2_object() const { return kernel_.has_on_bounded_side_2_object(); }

private:
  Kernel kernel_;
};

/// Spatial sorting for the range insertions of CGAL's triangulations (found by argument-dependent lookup,
/// more specialized than CGAL's generic `spatial_sort`): every point is validated once (|p| < 1, finite;
/// `Poincare_disk_domain_error` otherwise, before the triangulation is touched), then the points are sorted
/// along a Hilbert curve of their Poincare coordinates by the kernel. Any order with spatial locality serves
/// the insertion; the Euclidean one of the Poincare coordinates is the cheapest.
template <class RandomAccessIterator, class K>
void spatial_sort(RandomAccessIterator begin, RandomAccessIterator end, const Poincare_disk_traits_2<K>& gt)
{
  for(RandomAccessIterator it = begin; it != end; ++it)
    Poincare_disk_internal::check_point_in_disk(*it, "Poincare_disk_traits_2 (range insertion)");
  CGAL::spatial_sort(begin, end, gt.kernel());
}

/// Structural filtering: point location first walks with a plain double orientation of the Poincare
/// coordinates (a heuristic at the scale of one face), then finishes with the exact Klein orientation.
template <>
struct Triangulation_structural_filtering_traits<Poincare_disk_traits_2<Epick> >
{
  typedef Tag_true Use_structural_filtering_tag;
};

} // namespace CGAL

#endif // CGAL_POINCARE_DISK_TRAITS_2_H
