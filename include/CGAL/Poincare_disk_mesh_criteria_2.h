// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Deprecated: hyperbolic quality criteria for CGAL's own Delaunay refinement (`CGAL::refine_Delaunay_mesh_2`) with
// the former constructor contract. The criteria are `CGAL::Hyperbolic_Ruppert_mesh_criteria_2` (Hyperbolic_mesh_2's
// one criteria family, a model of `MeshingCriteria_2`); this class only keeps the old constructor and setters.
#ifndef CGAL_POINCARE_DISK_MESH_CRITERIA_2_H
#define CGAL_POINCARE_DISK_MESH_CRITERIA_2_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_mesh_criteria_2.h>

#include <cmath>
#include <limits>
#include <string>

namespace CGAL {

/*!
  \ingroup PkgPoincareDiskTraits2Ref

  \deprecated Use `CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>(alpha, epsilon)` (`<CGAL/Hyperbolic_mesh_criteria_2.h>`),
  which this class is (it derives from it and adds nothing but the former constructor contract).

  \cgalModels `MeshingCriteria_2`, for `refine_Delaunay_mesh_2` on a
  `Constrained_Delaunay_triangulation_2<Poincare_disk_traits_2<K>, Tds>`: a face is *bad* if the central angle of
  its shortest edge is smaller than `min_central_angle`, *imperatively bad* if its hyperbolic circumradius exceeds
  `max_circumradius` (0: no size bound).

  The constructor and the setters throw `CGAL::Invalid_option_error` for a minimum central angle outside
  (0, `maximum_min_central_angle`] (60 degrees: CGAL's mesher cannot terminate, or is not known to, for larger
  bounds) and for a negative or infinite maximum circumradius.
*/
template <class CDT>
class Poincare_disk_mesh_criteria_2 : public Hyperbolic_Ruppert_mesh_criteria_2<CDT>
{
  typedef Hyperbolic_Ruppert_mesh_criteria_2<CDT> Base;

public:
  typedef typename Base::Geom_traits Geom_traits;

  static constexpr double maximum_min_central_angle = Base::maximum_alpha_for_Mesh_2;

  Poincare_disk_mesh_criteria_2(double min_central_angle = 2 * 20.7 * 3.14159265358979323846 / 180,
                                double max_circumradius = 0, const Geom_traits& traits = Geom_traits())
    : Base(checked_angle(min_central_angle), checked_radius(max_circumradius), traits)
  {}

  void set_min_central_angle(double a) { this->set_alpha(checked_angle(a)); }
  void set_max_circumradius(double r) { this->set_epsilon(checked_radius(r), "Poincare_disk_mesh_criteria_2"); }

  double min_central_angle() const { return this->alpha(); }
  double max_circumradius() const { return this->has_size_bound() ? this->epsilon() : 0.0; }

private:
  static double checked_angle(double a)
  {
    if(!(a > 0 && a <= maximum_min_central_angle * (1 + 1e-12)))
      throw Invalid_option_error("Poincare_disk_mesh_criteria_2: the minimum central angle must be in (0, 60 degrees] "
                                 "(refinement cannot terminate, or is not known to, for larger bounds), got " +
                                 std::to_string(a * 180 / 3.14159265358979323846) + " degrees");
    return a;
  }
  // 0 (no size bound) is +infinity for the base class
  static double checked_radius(double r)
  {
    if(!(r >= 0) || !std::isfinite(r))
      throw Invalid_option_error("Poincare_disk_mesh_criteria_2: the maximum circumradius must be >= 0 and finite");
    return r == 0 ? std::numeric_limits<double>::infinity() : r;
  }
};

} // namespace CGAL

#endif
