// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one criteria family of hyperbolic Delaunay refinement (thesis chapter 3). Both classes model CGAL's
// `MeshingCriteria_2` (usable with `CGAL::refine_Delaunay_mesh_2`) and the package's
// `HyperbolicMeshRefinementCriteria_2` (used by `refine_hyperbolic_Ruppert_mesh_2` / `refine_hyperbolic_Chew_mesh_2`):
//   Hyperbolic_Ruppert_mesh_criteria_2  generalized Ruppert (Algorithm 6): central angle of the shortest edge >= alpha,
//                                       optional maximum hyperbolic circumradius epsilon;
//   Hyperbolic_Chew_mesh_criteria_2     generalized Chew (Algorithm 5): central angle of the shortest edge >= theta*(r)
//                                       (r the circumradius), r <= epsilon.
// A size violation is `CGAL::Mesh_2::IMPERATIVELY_BAD`, a shape violation `CGAL::Mesh_2::BAD`.
#ifndef CGAL_HYPERBOLIC_MESH_CRITERIA_2_H
#define CGAL_HYPERBOLIC_MESH_CRITERIA_2_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_mesh_2/quality_bounds.h>
#include <CGAL/Hyperbolic_mesh_2/internal/exact_quality.h>
#include <CGAL/Mesh_2/Face_badness.h>
#include <CGAL/Poincare_disk_traits_2/internal/polynomials.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Hyperbolic_mesh_2 {

/// \ingroup PkgHyperbolicMesh2Ref
/// Refinement policy tag of `Hyperbolic_Ruppert_mesh_criteria_2` (`Criteria::Refinement_policy`): encroached
/// constrained edges are split at their midpoints, circumcenters that encroach are rejected (thesis Algorithm 6).
struct Ruppert_policy {};
/// \ingroup PkgHyperbolicMesh2Ref
/// Refinement policy tag of `Hyperbolic_Chew_mesh_criteria_2`: circumcenters beyond a constrained edge split it
/// (midpoint or thirds) and nearby circumcenters are removed (thesis Algorithm 5).
struct Chew_policy {};

namespace internal {

// What both criteria share: the traits, the size bound, the `MeshingCriteria_2` quality (an approximation that only
// orders the queue of CGAL's mesher; every decision is exact) and the guard of CGAL's mesher against collapse.
template <class Criteria> class Is_bad_functor;

template <class CDT>
class Hyperbolic_criteria_base
{
  template <class> friend class Is_bad_functor;

public:
  typedef typename CDT::Geom_traits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef typename Geom_traits::Point_2 Point_2;
  typedef typename CDT::Face_handle Face_handle;

  /// `MeshingCriteria_2::Quality`: approximations of sin^2(alpha*/2) (alpha* the central angle of the shortest
  /// edge) and of cosh^2(r) / cosh^2(epsilon) (0 without a size bound), and the exact badness. `q1 < q2`: q1 is
  /// refined first (imperatively bad faces first, largest first; then the smallest central angle first).
  struct Quality
  {
    double sine = 0;
    double size = 0;
    Mesh_2::Face_badness badness = Mesh_2::NOT_BAD;

    bool operator<(const Quality& q) const
    {
      const bool big = badness == Mesh_2::IMPERATIVELY_BAD, qbig = q.badness == Mesh_2::IMPERATIVELY_BAD;
      if(big != qbig) return big;
      if(big) return size > q.size;
      return sine < q.sine;
    }
  };

  double epsilon() const { return epsilon_; }
  bool has_size_bound() const { return std::isfinite(epsilon_); }
  const Geom_traits& geom_traits() const { return gt_; }

protected:
  Hyperbolic_criteria_base(double epsilon, const Geom_traits& gt, const char* who) : gt_(gt) { set_epsilon(epsilon, who); }

  void set_epsilon(double epsilon, const char* who)
  {
    if(!(epsilon > 0)) throw CGAL::Invalid_option_error(std::string(who) + ": epsilon must be > 0 (or +infinity)");
    const double sh = std::sinh(epsilon), ch = std::cosh(epsilon);
    if(std::isfinite(epsilon) && !std::isfinite(ch * ch))
      throw CGAL::Invalid_option_error(std::string(who) + ": epsilon too large (sinh^2 overflows); use infinity");
    epsilon_ = epsilon;
    sinh2_epsilon_ = std::isfinite(epsilon) ? FT(sh * sh) : FT(0);
    cosh2_epsilon_ = std::isfinite(epsilon) ? ch * ch : 0;
  }

  /// exact: the circumradius exceeds epsilon (or the circumcircle is not compact)
  bool too_big(const Point_2& p, const Point_2& q, const Point_2& r) const
  { return has_size_bound() && Hyperbolic_mesh_2::internal::circumradius_larger_than(p, q, r, sinh2_epsilon_); }

  // the `Quality` approximation (double; orders CGAL's queue only)
  void approximate(const Point_2& p, const Point_2& r, const Point_2& s, Quality& q) const
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
    q.size = has_size_bound() ? cc.cosh2_numerator() / delta / cosh2_epsilon_ : 0;
  }

  // what `Is_bad` does besides `badness()`: the collapse guard and the quality approximation
  void check_for_Mesh_2(const Point_2& p, const Point_2& r, const Point_2& s, Quality& q) const
  {
    check_not_collapsed(p, r, s);
    approximate(p, r, s, q);
  }

  // CGAL's Mesh_2 handles small input angles with Euclidean concentric shells; in H^2 it can refine towards a
  // vertex without end. Its `Is_bad` stops with an exception long before the points collide in floating point.
  static void check_not_collapsed(const Point_2& p, const Point_2& r, const Point_2& s)
  {
    const double e = 1.0 / (1 << 18) / (1 << 18); // 2^-36 ~ 1.5e-11
    auto d2 = [](const Point_2& a, const Point_2& b) {
      const double dx = CGAL::to_double(a.x()) - CGAL::to_double(b.x()), dy = CGAL::to_double(a.y()) - CGAL::to_double(b.y());
      return dx * dx + dy * dy;
    };
    if(d2(p, r) < e * e || d2(r, s) < e * e || d2(s, p) < e * e)
      throw Numerical_error("Hyperbolic mesh criteria: the refinement by CGAL's refine_Delaunay_mesh_2 collapsed (an "
                            "edge shorter than 1.5e-11), typically at an input angle below 60 degrees: Mesh_2's "
                            "cluster handling is Euclidean. Use Hyperbolic_mesh_2's refiners (corner lopping).");
  }

  Geom_traits gt_;
  double epsilon_ = 0, cosh2_epsilon_ = 0;
  FT sinh2_epsilon_ = FT(0);
};

// `MeshingCriteria_2::Is_bad` of both criteria: the exact `badness()` of the criteria (copied: CGAL's mesher may
// outlive the criteria object), the quality approximation and the collapse guard.
template <class Criteria>
class Is_bad_functor
{
  typedef typename Criteria::Quality Quality;
  typedef typename Criteria::Face_handle Face_handle;

public:
  typedef typename Criteria::Point_2 Point_2;

  explicit Is_bad_functor(const Criteria& c) : c_(c) {}

  Mesh_2::Face_badness operator()(const Quality& q) const { return q.badness; }

  Mesh_2::Face_badness operator()(const Face_handle& fh, Quality& q) const
  {
    const Point_2 &p = fh->vertex(0)->point(), &r = fh->vertex(1)->point(), &s = fh->vertex(2)->point();
    c_.check_for_Mesh_2(p, r, s, q);
    q.badness = c_.badness(p, r, s);
    return q.badness;
  }

private:
  Criteria c_;
};

} // namespace internal
} // namespace Hyperbolic_mesh_2

/*!
  \ingroup PkgHyperbolicMesh2Ref

  Criteria of the generalized Ruppert algorithm (thesis Algorithm 6) for a
  `Constrained_Delaunay_triangulation_2<Poincare_disk_traits_2<K>, Tds>` (`CDT`).
  \cgalModels `MeshingCriteria_2` (for `CGAL::refine_Delaunay_mesh_2`) and `HyperbolicMeshRefinementCriteria_2`
  (for `refine_hyperbolic_Ruppert_mesh_2`; `Refinement_policy` = `Hyperbolic_mesh_2::Ruppert_policy`).

  A face pqr is *bad* (`CGAL::Mesh_2::BAD`) if the central angle of its shortest edge in its hyperbolic
  circumcircle is below `alpha`, and *imperatively bad* (`CGAL::Mesh_2::IMPERATIVELY_BAD`) if its hyperbolic
  circumradius exceeds `epsilon` (optional). Faces whose circumcircle is not compact (horocycle / hypercycle,
  "infinite radius") are bad (imperatively with a size bound). Both tests are exact: the traits' predicate
  `Compare_central_angle_2` (threshold sin^2(alpha/2)) and the sign of sinh^2 r - sinh^2 epsilon (the same
  comparison as `Compare_hyperbolic_circumradius_2`, written without the cancellation of cosh^2 for tiny radii).

  The central angle is twice the Euclidean minimum angle in the Euclidean limit: CGAL Mesh_2's bound
  `B = sin^2(min angle)` is the same number as `sin2_half_alpha()` here (`B = 0.125` <-> alpha = 41.41 degrees).

  Termination (thesis Theorem 3.2) is guaranteed when 1 - rho(epsilon, alpha) rho(epsilon, pi/2) > 0: see
  `termination_guaranteed()`, and `with_automatic_circumradius()` which chooses the largest such epsilon.

  With CGAL's `refine_Delaunay_mesh_2` (no work bound, Euclidean cluster handling) `is_bad_object()` throws
  `CGAL::Invalid_option_error` for alpha above `maximum_alpha_for_Mesh_2` (60 degrees: larger bounds cannot
  terminate or are not known to), and `Is_bad` throws `CGAL::Numerical_error` when the mesh collapses (an edge
  shorter than 1.5e-11).
*/
template <class CDT>
class Hyperbolic_Ruppert_mesh_criteria_2 : public Hyperbolic_mesh_2::internal::Hyperbolic_criteria_base<CDT>
{
  typedef Hyperbolic_mesh_2::internal::Hyperbolic_criteria_base<CDT> Base;

public:
  typedef typename Base::Geom_traits Geom_traits;
  typedef typename Base::FT FT;
  typedef typename Base::Point_2 Point_2;
  typedef typename Base::Face_handle Face_handle;
  typedef typename Base::Quality Quality;
  typedef Hyperbolic_mesh_2::Ruppert_policy Refinement_policy;
  /// `MeshingCriteria_2::Is_bad`
  typedef Hyperbolic_mesh_2::internal::Is_bad_functor<Hyperbolic_Ruppert_mesh_criteria_2> Is_bad;

  /// The largest `alpha` accepted by `is_bad_object()`, i.e. with CGAL's `refine_Delaunay_mesh_2`: 60 degrees (a
  /// smallest angle of 30 degrees in the Euclidean limit, where Delaunay refinement still terminates in practice).
  static constexpr double maximum_alpha_for_Mesh_2 = 60 * 3.14159265358979323846 / 180;

  /// `alpha`: minimum central angle of the shortest edge, radians, 0 < alpha <= 2 pi / 3 (an equilateral
  /// triangle has central angles 2 pi / 3); `epsilon`: maximum hyperbolic circumradius (> 0; +infinity: none).
  /// Throws `CGAL::Invalid_option_error` otherwise.
  explicit Hyperbolic_Ruppert_mesh_criteria_2(double alpha = 0.6,
                                              double epsilon = std::numeric_limits<double>::infinity(),
                                              const Geom_traits& gt = Geom_traits())
    : Base(epsilon, gt, "Hyperbolic_Ruppert_mesh_criteria_2")
  {
    if(!(alpha > 0 && alpha <= 2.0 * std::acos(-1.0) / 3.0 + 1e-12))
      throw CGAL::Invalid_option_error("Hyperbolic_Ruppert_mesh_criteria_2: alpha must be in (0, 2 pi / 3], got " +
                                  std::to_string(alpha));
    set_alpha(alpha);
  }

  /// Criteria with the bound given as CGAL Mesh_2's `B = sin^2(alpha / 2)` (0 < B <= 3/4).
  static Hyperbolic_Ruppert_mesh_criteria_2 from_sin2_half_angle(double B,
                                                                 double epsilon = std::numeric_limits<double>::infinity(),
                                                                 const Geom_traits& gt = Geom_traits())
  {
    if(!(B > 0 && B <= 0.75))
      throw CGAL::Invalid_option_error("Hyperbolic_Ruppert_mesh_criteria_2: B = sin^2(alpha/2) must be in (0, 3/4]");
    Hyperbolic_Ruppert_mesh_criteria_2 c(Hyperbolic_mesh_2::central_angle_from_sin2_half(B), epsilon, gt);
    c.sin2_half_alpha_ = B; // exactly the user's number (no round trip through asin / sin)
    return c;
  }

  /// Criteria whose maximum circumradius is chosen so that the termination condition of Theorem 3.2 holds
  /// (0.999 times `Ruppert_maximum_circumradius(alpha)`, or `epsilon` if smaller). Throws `CGAL::Invalid_option_error`
  /// if no positive radius works (alpha >= 41.41 degrees).
  static Hyperbolic_Ruppert_mesh_criteria_2 with_automatic_circumradius(double alpha,
                                                                        double epsilon = std::numeric_limits<double>::infinity(),
                                                                        const Geom_traits& gt = Geom_traits())
  {
    const double r = Hyperbolic_mesh_2::Ruppert_maximum_circumradius(alpha);
    if(!(r > 0))
      throw CGAL::Invalid_option_error("Hyperbolic_Ruppert_mesh_criteria_2: no maximum circumradius makes Ruppert's "
                                  "termination condition hold for alpha >= 41.41 degrees");
    return Hyperbolic_Ruppert_mesh_criteria_2(alpha, std::min(epsilon, 0.999 * r), gt);
  }

  double alpha() const { return alpha_; }
  double sin2_half_alpha() const { return sin2_half_alpha_; }

  /// 1 - rho(epsilon, alpha) rho(epsilon, pi/2) (with epsilon = +infinity: the limit -3).
  double termination_margin() const
  {
    if(!this->has_size_bound()) return -3.0;
    return Hyperbolic_mesh_2::Ruppert_termination_margin(this->epsilon_, alpha_);
  }
  /// Theorem 3.2 applies (for inputs without angles below pi/2).
  bool termination_guaranteed() const { return termination_margin() > 0; }

  /// The exact classification of the face (p, q, r): `IMPERATIVELY_BAD` (too big) first, then `BAD` (skinny),
  /// else `NOT_BAD`.
  Mesh_2::Face_badness badness(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    if(this->too_big(p, q, r)) return Mesh_2::IMPERATIVELY_BAD;
    return is_skinny(p, q, r) ? Mesh_2::BAD : Mesh_2::NOT_BAD;
  }
  Mesh_2::Face_badness badness(Face_handle f) const
  { return badness(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()); }
  bool is_bad(Face_handle f) const { return badness(f) != Mesh_2::NOT_BAD; }
  /// The angle test alone (exact).
  bool is_skinny(const Point_2& p, const Point_2& q, const Point_2& r) const
  { return this->gt_.compare_central_angle_2_object()(p, q, r, FT(sin2_half_alpha_)) == SMALLER; }

  /// `MeshingCriteria_2::is_bad_object()`; throws `CGAL::Invalid_option_error` if alpha > `maximum_alpha_for_Mesh_2`
  /// (only CGAL's `refine_Delaunay_mesh_2` calls it; it would not terminate).
  Is_bad is_bad_object() const
  {
    if(!(alpha_ <= maximum_alpha_for_Mesh_2 * (1 + 1e-12)))
      throw Invalid_option_error("Hyperbolic_Ruppert_mesh_criteria_2: with CGAL's refine_Delaunay_mesh_2 the minimum "
                                 "central angle must be at most 60 degrees (refinement cannot terminate, or is not "
                                 "known to, for larger bounds), got " + std::to_string(alpha_ * 180 / std::acos(-1.0)) +
                                 " degrees");
    return Is_bad(*this);
  }

  /// short description for reports
  std::string description() const
  {
    return "Ruppert: central angle >= " + std::to_string(alpha_ * 180 / std::acos(-1.0)) + " deg, circumradius <= " +
           (this->has_size_bound() ? std::to_string(this->epsilon_) : std::string("inf"));
  }

protected:
  void set_alpha(double alpha)
  {
    alpha_ = alpha;
    const double s = std::sin(alpha / 2);
    sin2_half_alpha_ = s * s;
  }


  double alpha_ = 0, sin2_half_alpha_ = 0;
};

/// \ingroup PkgHyperbolicMesh2Ref
/// \deprecated The former name of `Hyperbolic_Ruppert_mesh_criteria_2` (the same class).
template <class CDT>
using Hyperbolic_mesh_criteria_2 = Hyperbolic_Ruppert_mesh_criteria_2<CDT>;

/*!
  \ingroup PkgHyperbolicMesh2Ref

  Criteria of the generalized Chew algorithm (thesis Algorithm 5).
  \cgalModels `MeshingCriteria_2` and `HyperbolicMeshRefinementCriteria_2` (for `refine_hyperbolic_Chew_mesh_2`;
  `Refinement_policy` = `Hyperbolic_mesh_2::Chew_policy`).

  A face with hyperbolic circumradius r is bad (`CGAL::Mesh_2::BAD`) if the central angle of its shortest edge is
  below theta*(r), imperatively bad (`CGAL::Mesh_2::IMPERATIVELY_BAD`) if r > epsilon.

  Since theta*(r) is the central angle of a chord of length r in a circle of radius r, "central angle below
  theta*(r)" is exactly "shortest edge shorter than r": the test is one exact polynomial sign
  (sinh^2 of the edge vs sinh^2 r, see `internal/exact_quality.h`), evaluated with interval arithmetic and an
  exact rational fallback. Output meshes therefore have central angles >= theta*(epsilon) (<= 60 degrees, so
  CGAL's `refine_Delaunay_mesh_2` accepts these criteria too).
*/
template <class CDT>
class Hyperbolic_Chew_mesh_criteria_2 : public Hyperbolic_mesh_2::internal::Hyperbolic_criteria_base<CDT>
{
  typedef Hyperbolic_mesh_2::internal::Hyperbolic_criteria_base<CDT> Base;

public:
  typedef typename Base::Geom_traits Geom_traits;
  typedef typename Base::FT FT;
  typedef typename Base::Point_2 Point_2;
  typedef typename Base::Face_handle Face_handle;
  typedef typename Base::Quality Quality;
  typedef Hyperbolic_mesh_2::Chew_policy Refinement_policy;
  typedef Hyperbolic_mesh_2::internal::Is_bad_functor<Hyperbolic_Chew_mesh_criteria_2> Is_bad;

  /// `epsilon`: maximum hyperbolic circumradius (> 0; +infinity: only the angle criterion). Throws
  /// `CGAL::Invalid_option_error` otherwise.
  explicit Hyperbolic_Chew_mesh_criteria_2(double epsilon = std::numeric_limits<double>::infinity(),
                                           const Geom_traits& gt = Geom_traits())
    : Base(epsilon, gt, "Hyperbolic_Chew_mesh_criteria_2")
  {}

  /// theta*(epsilon): the central angle every output face reaches.
  double minimum_central_angle() const
  { return Hyperbolic_mesh_2::theta_star(this->has_size_bound() ? this->epsilon_ : 0.0); }

  Mesh_2::Face_badness badness(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    if(this->too_big(p, q, r)) return Mesh_2::IMPERATIVELY_BAD;
    return Hyperbolic_mesh_2::internal::has_edge_shorter_than_circumradius(p, q, r) ? Mesh_2::BAD : Mesh_2::NOT_BAD;
  }
  Mesh_2::Face_badness badness(Face_handle f) const
  { return badness(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()); }
  bool is_bad(Face_handle f) const { return badness(f) != Mesh_2::NOT_BAD; }

  /// `MeshingCriteria_2::is_bad_object()`
  Is_bad is_bad_object() const { return Is_bad(*this); }

  std::string description() const
  {
    return "Chew: central angle >= theta*(r), circumradius <= " +
           (this->has_size_bound() ? std::to_string(this->epsilon_) : std::string("inf"));
  }
};

} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_CRITERIA_2_H
