// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality criteria of hyperbolic Delaunay refinement (thesis chapter 3):
//   Hyperbolic_mesh_criteria_2       generalized Ruppert (Algorithm 6): central angle of the shortest edge >= alpha,
//                                    optional maximum hyperbolic circumradius epsilon;
//   Hyperbolic_Chew_mesh_criteria_2  generalized Chew (Algorithm 5): central angle of the shortest edge >= theta*(r)
//                                    (r the circumradius), r <= epsilon.
#ifndef CGAL_HYPERBOLIC_MESH_CRITERIA_2_H
#define CGAL_HYPERBOLIC_MESH_CRITERIA_2_H

#include <CGAL/Hyperbolic_mesh_2/quality_bounds.h>
#include <CGAL/Hyperbolic_mesh_2/internal/exact_quality.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Hyperbolic_mesh_2 {

/// \ingroup PkgHyperbolicMesh2Ref
/// Why a face is poor (`Criteria::badness`).
enum class Face_badness { GOOD = 0, BAD_ANGLE = 1, BAD_SIZE = 2 };

} // namespace Hyperbolic_mesh_2

/*!
  \ingroup PkgHyperbolicMesh2Ref

  Criteria of the generalized Ruppert algorithm (thesis Algorithm 6) for a
  `Constrained_Delaunay_triangulation_2<Poincare_disk_traits_2<K>, Tds>` (`CDT`).

  A face pqr is *skinny* if the central angle of its shortest edge in its hyperbolic circumcircle is below
  `alpha`, and *too big* if its hyperbolic circumradius exceeds `epsilon` (optional). Faces whose circumcircle is
  not compact (horocycle / hypercycle, "infinite radius") are skinny. Both tests are exact: the traits' predicate
  `Compare_central_angle_2` (threshold sin^2(alpha/2)) and the sign of sinh^2 r - sinh^2 epsilon (the same
  comparison as `Compare_hyperbolic_circumradius_2`, written without the cancellation of cosh^2 for tiny radii).

  The central angle is twice the Euclidean minimum angle in the Euclidean limit: CGAL Mesh_2's bound
  `B = sin^2(min angle)` is the same number as `sin2_half_alpha()` here (`B = 0.125` <-> alpha = 41.41 degrees).

  Termination (thesis Theorem 3.2) is guaranteed when 1 - rho(epsilon, alpha) rho(epsilon, pi/2) > 0: see
  `termination_guaranteed()`, and `with_automatic_circumradius()` which chooses the largest such epsilon.
*/
template <class CDT>
class Hyperbolic_mesh_criteria_2
{
public:
  typedef typename CDT::Geom_traits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef typename Geom_traits::Point_2 Point_2;
  typedef typename CDT::Face_handle Face_handle;

  /// `alpha`: minimum central angle of the shortest edge, radians, 0 < alpha <= 2 pi / 3 (an equilateral
  /// triangle has central angles 2 pi / 3); `epsilon`: maximum hyperbolic circumradius (> 0; +infinity: none).
  /// Throws `std::invalid_argument` otherwise.
  explicit Hyperbolic_mesh_criteria_2(double alpha = 0.6, double epsilon = std::numeric_limits<double>::infinity(),
                                      const Geom_traits& gt = Geom_traits())
    : gt_(gt)
  {
    if(!(alpha > 0 && alpha <= 2.0 * std::acos(-1.0) / 3.0 + 1e-12))
      throw std::invalid_argument("Hyperbolic_mesh_criteria_2: alpha must be in (0, 2 pi / 3], got " +
                                  std::to_string(alpha));
    set_size_bound(epsilon);
    alpha_ = alpha;
    const double s = std::sin(alpha / 2);
    sin2_half_alpha_ = s * s;
  }

  /// Criteria with the bound given as CGAL Mesh_2's `B = sin^2(alpha / 2)` (0 < B <= 3/4).
  static Hyperbolic_mesh_criteria_2 from_sin2_half_angle(double B,
                                                         double epsilon = std::numeric_limits<double>::infinity(),
                                                         const Geom_traits& gt = Geom_traits())
  {
    if(!(B > 0 && B <= 0.75))
      throw std::invalid_argument("Hyperbolic_mesh_criteria_2: B = sin^2(alpha/2) must be in (0, 3/4]");
    Hyperbolic_mesh_criteria_2 c(Hyperbolic_mesh_2::central_angle_from_sin2_half(B), epsilon, gt);
    c.sin2_half_alpha_ = B; // exactly the user's number (no round trip through asin / sin)
    return c;
  }

  /// Criteria whose maximum circumradius is chosen so that the termination condition of Theorem 3.2 holds
  /// (0.999 times `Ruppert_maximum_circumradius(alpha)`, or `epsilon` if smaller). Throws `std::invalid_argument`
  /// if no positive radius works (alpha >= 41.41 degrees).
  static Hyperbolic_mesh_criteria_2 with_automatic_circumradius(double alpha,
                                                                double epsilon = std::numeric_limits<double>::infinity(),
                                                                const Geom_traits& gt = Geom_traits())
  {
    const double r = Hyperbolic_mesh_2::Ruppert_maximum_circumradius(alpha);
    if(!(r > 0))
      throw std::invalid_argument("Hyperbolic_mesh_criteria_2: no maximum circumradius makes Ruppert's "
                                  "termination condition hold for alpha >= 41.41 degrees");
    return Hyperbolic_mesh_criteria_2(alpha, std::min(epsilon, 0.999 * r), gt);
  }

  double alpha() const { return alpha_; }
  double sin2_half_alpha() const { return sin2_half_alpha_; }
  double epsilon() const { return epsilon_; }
  bool has_size_bound() const { return std::isfinite(epsilon_); }
  const Geom_traits& geom_traits() const { return gt_; }

  /// 1 - rho(epsilon, alpha) rho(epsilon, pi/2) (with epsilon = +infinity: the limit -3).
  double termination_margin() const
  {
    if(!has_size_bound()) return -3.0;
    return Hyperbolic_mesh_2::Ruppert_termination_margin(epsilon_, alpha_);
  }
  /// Theorem 3.2 applies (for inputs without angles below pi/2).
  bool termination_guaranteed() const { return termination_margin() > 0; }

  /// The exact classification of the face (p, q, r): `BAD_SIZE` first, then `BAD_ANGLE`, else `GOOD`.
  Hyperbolic_mesh_2::Face_badness badness(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    if(has_size_bound() && Hyperbolic_mesh_2::internal::circumradius_larger_than(p, q, r, sinh2_epsilon_))
      return Hyperbolic_mesh_2::Face_badness::BAD_SIZE;
    if(gt_.compare_central_angle_2_object()(p, q, r, FT(sin2_half_alpha_)) == SMALLER)
      return Hyperbolic_mesh_2::Face_badness::BAD_ANGLE;
    return Hyperbolic_mesh_2::Face_badness::GOOD;
  }
  Hyperbolic_mesh_2::Face_badness badness(Face_handle f) const
  { return badness(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()); }
  bool is_bad(Face_handle f) const { return badness(f) != Hyperbolic_mesh_2::Face_badness::GOOD; }
  /// The angle test alone (exact).
  bool is_skinny(const Point_2& p, const Point_2& q, const Point_2& r) const
  { return gt_.compare_central_angle_2_object()(p, q, r, FT(sin2_half_alpha_)) == SMALLER; }

  /// short description for reports
  std::string description() const
  {
    return "Ruppert: central angle >= " + std::to_string(alpha_ * 180 / std::acos(-1.0)) + " deg, circumradius <= " +
           (has_size_bound() ? std::to_string(epsilon_) : std::string("inf"));
  }

private:
  void set_size_bound(double epsilon)
  {
    if(!(epsilon > 0))
      throw std::invalid_argument("Hyperbolic_mesh_criteria_2: epsilon must be > 0 (or +infinity)");
    epsilon_ = epsilon;
    const double sh = std::sinh(epsilon);
    if(std::isfinite(epsilon) && !std::isfinite(sh * sh))
      throw std::invalid_argument("Hyperbolic_mesh_criteria_2: epsilon too large (sinh^2 overflows); use infinity");
    sinh2_epsilon_ = std::isfinite(epsilon) ? FT(sh * sh) : FT(0);
  }

  Geom_traits gt_;
  double alpha_ = 0, sin2_half_alpha_ = 0, epsilon_ = 0;
  FT sinh2_epsilon_ = FT(0);
};

/// \ingroup PkgHyperbolicMesh2Ref
/// The name of the Ruppert criteria consistent with `Hyperbolic_Chew_mesh_criteria_2` (issue 8); the same class.
template <class CDT>
using Hyperbolic_Ruppert_mesh_criteria_2 = Hyperbolic_mesh_criteria_2<CDT>;

/*!
  \ingroup PkgHyperbolicMesh2Ref

  Criteria of the generalized Chew algorithm (thesis Algorithm 5). A face with hyperbolic circumradius r is poor
  if the central angle of its shortest edge is below theta*(r) or if r > epsilon.

  Since theta*(r) is the central angle of a chord of length r in a circle of radius r, "central angle below
  theta*(r)" is exactly "shortest edge shorter than r": the test is one exact polynomial sign
  (sinh^2 of the edge vs sinh^2 r, see `internal/exact_quality.h`), evaluated with interval arithmetic and an
  exact rational fallback. Output meshes therefore have central angles >= theta*(epsilon).
*/
template <class CDT>
class Hyperbolic_Chew_mesh_criteria_2
{
public:
  typedef typename CDT::Geom_traits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef typename Geom_traits::Point_2 Point_2;
  typedef typename CDT::Face_handle Face_handle;

  /// `epsilon`: maximum hyperbolic circumradius (> 0; +infinity: only the angle criterion). Throws
  /// `std::invalid_argument` otherwise.
  explicit Hyperbolic_Chew_mesh_criteria_2(double epsilon = std::numeric_limits<double>::infinity(),
                                           const Geom_traits& gt = Geom_traits())
    : gt_(gt)
  {
    if(!(epsilon > 0)) throw std::invalid_argument("Hyperbolic_Chew_mesh_criteria_2: epsilon must be > 0");
    const double sh = std::sinh(epsilon);
    if(std::isfinite(epsilon) && !std::isfinite(sh * sh))
      throw std::invalid_argument("Hyperbolic_Chew_mesh_criteria_2: epsilon too large (sinh^2 overflows)");
    epsilon_ = epsilon;
    sinh2_epsilon_ = std::isfinite(epsilon) ? FT(sh * sh) : FT(0);
  }

  double epsilon() const { return epsilon_; }
  bool has_size_bound() const { return std::isfinite(epsilon_); }
  const Geom_traits& geom_traits() const { return gt_; }
  /// theta*(epsilon): the central angle every output face reaches.
  double minimum_central_angle() const { return Hyperbolic_mesh_2::theta_star(has_size_bound() ? epsilon_ : 0.0); }

  Hyperbolic_mesh_2::Face_badness badness(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    if(has_size_bound() && Hyperbolic_mesh_2::internal::circumradius_larger_than(p, q, r, sinh2_epsilon_))
      return Hyperbolic_mesh_2::Face_badness::BAD_SIZE;
    if(Hyperbolic_mesh_2::internal::has_edge_shorter_than_circumradius(p, q, r))
      return Hyperbolic_mesh_2::Face_badness::BAD_ANGLE;
    return Hyperbolic_mesh_2::Face_badness::GOOD;
  }
  Hyperbolic_mesh_2::Face_badness badness(Face_handle f) const
  { return badness(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()); }
  bool is_bad(Face_handle f) const { return badness(f) != Hyperbolic_mesh_2::Face_badness::GOOD; }

  std::string description() const
  {
    return "Chew: central angle >= theta*(r), circumradius <= " +
           (has_size_bound() ? std::to_string(epsilon_) : std::string("inf"));
  }

private:
  Geom_traits gt_;
  double epsilon_ = 0;
  FT sinh2_epsilon_ = FT(0);
};

} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_CRITERIA_2_H
