// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hyperbolic quality criteria for CGAL's own Delaunay refinement (`CGAL::refine_Delaunay_mesh_2`) on a
// constrained Delaunay triangulation with `Poincare_disk_traits_2`.
#ifndef CGAL_POINCARE_DISK_MESH_CRITERIA_2_H
#define CGAL_POINCARE_DISK_MESH_CRITERIA_2_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Mesh_2/Face_badness.h>
#include <CGAL/Poincare_disk_traits_2/internal/polynomials.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace CGAL {

/*!
  \ingroup PkgPoincareDiskTraits2Ref

  A model of CGAL's `MeshingCriteria_2` for `refine_Delaunay_mesh_2` on a
  `Constrained_Delaunay_triangulation_2<Poincare_disk_traits_2<K>, Tds>`.

  A face is *bad* if the central angle of its shortest edge in its hyperbolic circumcircle is smaller than
  `min_central_angle` (the hyperbolic analogue of the smallest angle: in the Euclidean limit the central angle of
  the shortest edge is twice the smallest angle), and *imperatively bad* if its hyperbolic circumradius exceeds
  `max_circumradius` (0: no size bound). Faces whose circumcircle is not compact (horocycles, hypercycles) have
  central angle 0 and infinite radius: they are bad. Both decisions use the exact predicates
  `Compare_central_angle_2` and `Compare_hyperbolic_circumradius_2`; the double-valued quality only orders
  the mesher's queue.

  Limits, inherited from CGAL's Mesh_2 (a Euclidean mesher): its cluster handling at small input angles uses
  Euclidean vectors, and it has no termination guarantee in H^2; keep `min_central_angle` at most ~41 degrees
  (thesis ch. 3: the hyperbolic Ruppert bound) and prefer `Hyperbolic_mesh_2`'s own refiners, which implement
  the thesis' algorithms with their guarantees.
*/
template <class CDT>
class Poincare_disk_mesh_criteria_2
{
public:
  typedef typename CDT::Geom_traits Geom_traits;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename Geom_traits::FT FT;

  /// the quality of a face: approximations of sin^2(alpha*/2) and of cosh^2(h) / cosh^2(bound), and the badness
  /// decided exactly; faces are refined in increasing order (imperatively bad ones first, largest first).
  struct Quality
  {
    double sine = 0;            ///< sin^2(alpha*/2), alpha* the central angle of the shortest edge
    double size = 0;            ///< cosh^2(h) / cosh^2(max radius) (> 1: too big); 0 without a size bound
    Mesh_2::Face_badness badness = Mesh_2::NOT_BAD;

    bool operator<(const Quality& q) const
    {
      const bool big = badness == Mesh_2::IMPERATIVELY_BAD, qbig = q.badness == Mesh_2::IMPERATIVELY_BAD;
      if(big != qbig) return big;
      if(big) return size > q.size;
      return sine < q.sine;
    }
  };

  /// `min_central_angle` in radians in (0, `maximum_min_central_angle`] (60 degrees), `max_circumradius`
  /// hyperbolic (0 for none, else finite); throws `CGAL::Invalid_option_error` (an `Invalid_input_error`) otherwise.
  Poincare_disk_mesh_criteria_2(double min_central_angle = 2 * 20.7 * 3.14159265358979323846 / 180,
                                double max_circumradius = 0,
                                const Geom_traits& traits = Geom_traits())
    : traits_(traits)
  {
    set_min_central_angle(min_central_angle);
    set_max_circumradius(max_circumradius);
  }

  /// The largest accepted `min_central_angle`: 60 degrees (a smallest angle of 30 degrees in the Euclidean limit,
  /// where Delaunay refinement still terminates in practice; termination is proven up to 41.41 degrees). Larger
  /// bounds cannot terminate or are not known to: no hyperbolic triangle reaches a central angle of 120 degrees (the
  /// equilateral Euclidean limit), so `refine_Delaunay_mesh_2` would refine forever.
  static constexpr double maximum_min_central_angle = 60 * 3.14159265358979323846 / 180;

  void set_min_central_angle(double a)
  {
    if(!(a > 0 && a <= maximum_min_central_angle * (1 + 1e-12)))
      throw Invalid_option_error("Poincare_disk_mesh_criteria_2: the minimum central angle must be in (0, 60 degrees] "
                                 "(refinement cannot terminate, or is not known to, for larger bounds), got " +
                                 std::to_string(a * 180 / 3.14159265358979323846) + " degrees");
    angle_ = a;
    const double s = std::sin(a / 2);
    sin2_ = s * s;
  }

  void set_max_circumradius(double r)
  {
    if(!(r >= 0) || !std::isfinite(r))
      throw Invalid_option_error("Poincare_disk_mesh_criteria_2: the maximum circumradius must be >= 0 and finite");
    radius_ = r;
    const double c = std::cosh(r);
    cosh2_ = c * c;
  }

  double min_central_angle() const { return angle_; }
  double max_circumradius() const { return radius_; }

  class Is_bad
  {
  public:
    // copies the bounds: the mesher may outlive the criteria object
    Is_bad(const Geom_traits& gt, double sin2, double cosh2, double radius)
      : gt_(gt), sin2_(sin2), cosh2_(cosh2), radius_(radius) {}

    Mesh_2::Face_badness operator()(const Quality& q) const { return q.badness; }

    Mesh_2::Face_badness operator()(const Face_handle& fh, Quality& q) const
    {
      const auto& p = fh->vertex(0)->point();
      const auto& r = fh->vertex(1)->point();
      const auto& s = fh->vertex(2)->point();
      check_not_collapsed(p, r, s);
      approximate(p, r, s, q);
      if(radius_ > 0 && gt_.compare_hyperbolic_circumradius_2_object()(p, r, s, FT(cosh2_)) == LARGER)
        q.badness = Mesh_2::IMPERATIVELY_BAD;
      else if(gt_.compare_central_angle_2_object()(p, r, s, FT(sin2_)) == SMALLER)
        q.badness = Mesh_2::BAD;
      else
        q.badness = Mesh_2::NOT_BAD;
      return q.badness;
    }

  private:
    // CGAL's Mesh_2 handles small input angles with Euclidean concentric shells; in H^2 it can refine towards a
    // vertex without end. Stop with an exception long before the points collide in floating point.
    template <class P>
    static void check_not_collapsed(const P& p, const P& r, const P& s)
    {
      const double e = 1.0 / (1 << 18) / (1 << 18); // 2^-36 ~ 1.5e-11
      auto d2 = [](const P& a, const P& b) {
        const double dx = CGAL::to_double(a.x()) - CGAL::to_double(b.x()), dy = CGAL::to_double(a.y()) - CGAL::to_double(b.y());
        return dx * dx + dy * dy;
      };
      if(d2(p, r) < e * e || d2(r, s) < e * e || d2(s, p) < e * e)
        throw std::runtime_error("Poincare_disk_mesh_criteria_2: the refinement by CGAL's refine_Delaunay_mesh_2 "
                                 "collapsed (an edge shorter than 1.5e-11), typically at an input angle below 60 "
                                 "degrees: Mesh_2's cluster handling is Euclidean. Use Hyperbolic_mesh_2's refiners "
                                 "(corner lopping) for such input.");
    }

    template <class P>
    void approximate(const P& p, const P& r, const P& s, Quality& q) const
    {
      using namespace Poincare_disk_internal;
      const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y()), rx = CGAL::to_double(r.x()),
                   ry = CGAL::to_double(r.y()), sx = CGAL::to_double(s.x()), sy = CGAL::to_double(s.y());
      const Circle_coefficients<double> cc(px, py, rx, ry, sx, sy);
      const double delta = cc.delta();
      if(!(delta > 0)) { q.sine = 0; q.size = 1e300; return; }
      const double a1 = squared_euclidean(px, py, rx, ry) / (lift_n(px, py) * lift_n(rx, ry));
      const double a2 = squared_euclidean(rx, ry, sx, sy) / (lift_n(rx, ry) * lift_n(sx, sy));
      const double a3 = squared_euclidean(sx, sy, px, py) / (lift_n(sx, sy) * lift_n(px, py));
      const double amin = (std::min)(a1, (std::min)(a2, a3));
      q.sine = amin * delta / cc.sinh2_numerator();
      q.size = radius_ > 0 ? cc.cosh2_numerator() / delta / cosh2_ : 0;
    }
    Geom_traits gt_;
    double sin2_, cosh2_, radius_;
  };

  Is_bad is_bad_object() const { return Is_bad(traits_, sin2_, cosh2_, radius_); }

private:
  Geom_traits traits_;
  double angle_ = 0, sin2_ = 0, radius_ = 0, cosh2_ = 1;
};

} // namespace CGAL

#endif
