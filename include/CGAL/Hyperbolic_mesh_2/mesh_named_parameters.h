// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL named parameters of the refinement entry points (refine_hyperbolic_Ruppert_mesh_2,
// refine_hyperbolic_Chew_mesh_2). CGAL's own `callback` and `verbose` are used; the package adds `seeds`,
// `seeds_are_in_domain`, `maximum_number_of_operations`, `corner_lopping` and `off_centers` in
// `CGAL::Hyperbolic_mesh_2::parameters`. They are read into a `Mesh_parameters` (whose setters check the
// ranges), so the two option styles share one implementation.
#ifndef CGAL_HYPERBOLIC_MESH_2_MESH_NAMED_PARAMETERS_H
#define CGAL_HYPERBOLIC_MESH_2_MESH_NAMED_PARAMETERS_H

#include <CGAL/Hyperbolic_geometry_named_parameters.h>
#include <CGAL/Hyperbolic_mesh_2/mesh_types.h>

#include <functional>
#include <iterator>
#include <type_traits>

CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_seeds_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_seeds_are_in_domain_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_maximum_number_of_operations_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_corner_lopping_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_off_centers_t)

namespace CGAL {
namespace Hyperbolic_mesh_2 {
/*!
  \ingroup PkgHyperbolicMesh2Ref
  Package-specific named parameters of the refiners. Each takes its value and, optionally, the chain it extends:
  \code
  namespace HP = CGAL::Hyperbolic_mesh_2::parameters;
  auto np = HP::off_centers(true, HP::seeds(holes, CGAL::parameters::verbose(true)));
  \endcode
  - `seeds(range)`: a range of `Point_2` (copied), as in `refine_Delaunay_mesh_2` (default: empty);
  - `seeds_are_in_domain(bool)` (default `false`);
  - `maximum_number_of_operations(double)`: work bound, >= 0 (default `default_maximum_number_of_operations`;
    negative or NaN throws `CGAL::Invalid_option_error`);
  - `corner_lopping(bool)` (default `true`); `off_centers(bool)` (default `false`, Ruppert only).
  CGAL's own: `CGAL::parameters::callback(f)` with `f` callable as `bool(const Progress&)` (return false to
  stop), `CGAL::parameters::verbose(bool)`.
*/
namespace parameters {
CGAL_HYPERBOLIC_NAMED_PARAMETER(seeds, hm2_seeds_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(seeds_are_in_domain, hm2_seeds_are_in_domain_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(maximum_number_of_operations, hm2_maximum_number_of_operations_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(corner_lopping, hm2_corner_lopping_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(off_centers, hm2_off_centers_t)
} // namespace parameters

namespace internal {

/// Reads the named parameters `np` into a `Mesh_parameters` (defaults for the absent ones; the setters
/// check the ranges and throw `CGAL::Invalid_option_error`).
template <class Point_2, class NP>
Mesh_parameters<Point_2> mesh_parameters_from_named_parameters(const NP& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  Mesh_parameters<Point_2> prm;
  if constexpr(!is_default_parameter<NP, CGAL::internal_np::hm2_seeds_t>::value) {
    const auto& s = get_parameter(np, CGAL::internal_np::hm2_seeds_t_v);
    prm.seeds(std::begin(s), std::end(s));
  }
  prm.seeds_are_in_domain(choose_parameter(get_parameter(np, CGAL::internal_np::hm2_seeds_are_in_domain_t_v), false));
  prm.maximum_number_of_operations(
      double(choose_parameter(get_parameter(np, CGAL::internal_np::hm2_maximum_number_of_operations_t_v),
                              double(default_maximum_number_of_operations))));
  prm.corner_lopping(choose_parameter(get_parameter(np, CGAL::internal_np::hm2_corner_lopping_t_v), true));
  prm.off_centers(choose_parameter(get_parameter(np, CGAL::internal_np::hm2_off_centers_t_v), false));
  prm.verbose(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false));
  if constexpr(!is_default_parameter<NP, CGAL::internal_np::callback_t>::value)
    prm.callback(std::function<bool(const Progress&)>(get_parameter(np, CGAL::internal_np::callback)));
  return prm;
}

} // namespace internal
} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_MESH_NAMED_PARAMETERS_H
