// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Delaunay refinement of planar geodesic graphs in the Poincare disk (thesis chapter 3):
//   refine_hyperbolic_Ruppert_mesh_2  generalized Ruppert, Algorithm 6
//   refine_hyperbolic_Chew_mesh_2     generalized Chew's second algorithm, Algorithm 5
#ifndef CGAL_REFINE_HYPERBOLIC_MESH_2_H
#define CGAL_REFINE_HYPERBOLIC_MESH_2_H

#include <CGAL/Hyperbolic_mesh_2/internal/Refiner.h>
#include <CGAL/Hyperbolic_mesh_2/mesh_named_parameters.h>
#include <CGAL/Hyperbolic_mesh_2/mesh_types.h>
#include <CGAL/Hyperbolic_mesh_criteria_2.h>

namespace CGAL {
namespace Hyperbolic_mesh_2 {
namespace internal {

// The one implementation of the entry points: the algorithm is the criteria's Refinement_policy.
template <class CDT, class Criteria>
Mesh_statistics refine_hyperbolic_mesh(CDT& cdt, const Criteria& criteria, const Mesh_parameters<typename CDT::Point>& prm)
{
  Refiner<CDT, Criteria> r(cdt, criteria, prm);
  return r.run();
}

// Options given as named parameters: read into the Mesh_parameters (the setters check the ranges).
template <class CDT, class Criteria, class NP>
Mesh_statistics refine_hyperbolic_mesh_np(CDT& cdt, const Criteria& criteria, const NP& np)
{
  return refine_hyperbolic_mesh(cdt, criteria, mesh_parameters_from_named_parameters<typename CDT::Point>(np));
}

} // namespace internal
} // namespace Hyperbolic_mesh_2

/*!
  \ingroup PkgHyperbolicMesh2Ref

  Refines `cdt` with the generalized Ruppert algorithm (thesis Algorithm 6) until every face of the domain meets
  `criteria` (central angle of the shortest edge >= alpha, hyperbolic circumradius <= epsilon).

  \tparam CDT a `Constrained_Delaunay_triangulation_2<Poincare_disk_traits_2<K>, Tds>` whose face base has the
  in-domain mark of `Delaunay_mesh_face_base_2` (`is_in_domain()`, `set_in_domain()`). Its constrained edges
  are the geodesic segments of the input; a triangulation without constrained edges is a point cloud, whose
  convex hull edges are then constrained.

  Algorithm: the constrained edges encroached by a vertex (exact `Side_of_hyperbolic_diametral_circle_2`) are
  split at their hyperbolic midpoints first; then the poor faces, largest circumradius first, get their
  hyperbolic circumcenter (the midpoint of the longest edge when the circumcircle is not compact), unless the
  circumcenter encroaches a constrained edge of its conflict zone or lies beyond it (thesis Lemma 3.5): then the
  circumcenter is rejected and those edges are split. Input angles below pi/2 are lopped (thesis Fig. 3.6): every
  segment at such an apex is split at lfs/3 from it, and poor faces whose shortest edge joins the two segments of
  a small angle are left as they are (`Mesh_statistics::protected_faces`). Optional off-centers
  (`off_centers(true)`).

  \deprecated This overload takes the options as a `Hyperbolic_mesh_2::Mesh_parameters` struct; prefer the
  named-parameter overload below (same options, same implementation).

  The domain is marked as in `refine_Delaunay_mesh_2` (`parameters.seeds(...)`, `.seeds_are_in_domain(...)`)
  and kept up to date: on return `f->is_in_domain()` is the domain.

  Termination: guaranteed (Theorem 3.2) when 1 - rho(epsilon, alpha) rho(epsilon, pi/2) > 0 and no input angle
  is below pi/2; reported in `Mesh_statistics::termination_guaranteed`. In every case the work is bounded by
  `parameters.maximum_number_of_operations()` insertions + removals; the status says whether it was reached.

  Throws `Hyperbolic_mesh_2::Pslg_error` if `cdt` has dimension < 2, `CGAL::Poincare_disk_domain_error` if a vertex
  or seed is not inside the disk (both are `Hyperbolic_mesh_2::Input_error` = `CGAL::Invalid_input_error`).
  Status: `SUCCESS` only if every face of the domain meets `criteria` (exact test at the end) but the counted
  protected faces; `UNREFINED_FACES_LEFT` if no work is left but some faces fail (rounding limits).
  Cost: O(log n) expected per insertion for the queues plus the CDT insertion (conflict zone size); O(n) to mark
  the domain; O(k (n + m)) for the k small angles.
*/
template <class CDT>
Hyperbolic_mesh_2::Mesh_statistics
refine_hyperbolic_Ruppert_mesh_2(CDT& cdt, const Hyperbolic_Ruppert_mesh_criteria_2<CDT>& criteria,
                                 const Hyperbolic_mesh_2::Mesh_parameters<typename CDT::Point>& parameters)
{ return Hyperbolic_mesh_2::internal::refine_hyperbolic_mesh(cdt, criteria, parameters); }

/*!
  \ingroup PkgHyperbolicMesh2Ref
  Same as above with the options as CGAL named parameters (the preferred form; the `Mesh_parameters` overload
  is deprecated):
  \cgalNamedParamsBegin
    \cgalParamNBegin{CGAL::Hyperbolic_mesh_2::parameters::seeds} a range of `CDT::Point`, default empty \cgalParamNEnd
    \cgalParamNBegin{CGAL::Hyperbolic_mesh_2::parameters::seeds_are_in_domain} `bool`, default `false` \cgalParamNEnd
    \cgalParamNBegin{CGAL::Hyperbolic_mesh_2::parameters::maximum_number_of_operations} `double` >= 0, default
      `Hyperbolic_mesh_2::default_maximum_number_of_operations`; else `CGAL::Invalid_option_error` \cgalParamNEnd
    \cgalParamNBegin{CGAL::Hyperbolic_mesh_2::parameters::corner_lopping} `bool`, default `true` \cgalParamNEnd
    \cgalParamNBegin{CGAL::Hyperbolic_mesh_2::parameters::off_centers} `bool`, default `false` \cgalParamNEnd
    \cgalParamNBegin{callback} callable as `bool(const Hyperbolic_mesh_2::Progress&)`; false stops \cgalParamNEnd
    \cgalParamNBegin{verbose} `bool`, default `false` \cgalParamNEnd
  \cgalNamedParamsEnd
*/
template <class CDT, typename CGAL_NP_TEMPLATE_PARAMETERS>
Hyperbolic_mesh_2::Mesh_statistics
refine_hyperbolic_Ruppert_mesh_2(CDT& cdt, const Hyperbolic_Ruppert_mesh_criteria_2<CDT>& criteria,
                                 const CGAL_NP_CLASS& np = parameters::default_values())
{ return Hyperbolic_mesh_2::internal::refine_hyperbolic_mesh_np(cdt, criteria, np); }

/*!
  \ingroup PkgHyperbolicMesh2Ref

  Refines `cdt` with the generalized Chew second algorithm (thesis Algorithm 5): a face with circumradius r is
  poor if the central angle of its shortest edge is below theta*(r) (equivalently: an edge shorter than r) or
  r > epsilon. Poor faces are processed largest circumradius first. A circumcenter lying beyond a constrained
  edge (on the other side from the face, thesis Lemma 3.5) is not inserted; the edge is split instead:
  - into thirds if its length is in [2 rho(h*) h*, 4 h*], then the circumcenters closer than a third of its
    length to a new vertex are removed;
  - otherwise at its hyperbolic midpoint, then the circumcenters inside its diametral disk are removed.
  h* is the minimum of epsilon, half the shortest input segment and the smallest distance between non-incident
  input features (`Mesh_statistics::h_star`). Termination is guaranteed when h* < 2.3101 (Theorem 3.1) and no
  input angle is below pi/2; otherwise the run is bounded by `parameters.maximum_number_of_operations()` and the
  status tells how it ended. Corner lopping and the protected faces work as for the Ruppert entry point.

  Same template parameter, parameters, exceptions and cost as `refine_hyperbolic_Ruppert_mesh_2()`, plus
  O(n m) for h* (n vertices, m segments; only local segments when n m > 2e7).
*/
template <class CDT>
Hyperbolic_mesh_2::Mesh_statistics
refine_hyperbolic_Chew_mesh_2(CDT& cdt, const Hyperbolic_Chew_mesh_criteria_2<CDT>& criteria,
                              const Hyperbolic_mesh_2::Mesh_parameters<typename CDT::Point>& parameters)
{ return Hyperbolic_mesh_2::internal::refine_hyperbolic_mesh(cdt, criteria, parameters); }

/*!
  \ingroup PkgHyperbolicMesh2Ref
  Same as above with the options as CGAL named parameters (the same ones as the named-parameter
  `refine_hyperbolic_Ruppert_mesh_2()`; the `Mesh_parameters` overload is deprecated).
*/
template <class CDT, typename CGAL_NP_TEMPLATE_PARAMETERS>
Hyperbolic_mesh_2::Mesh_statistics
refine_hyperbolic_Chew_mesh_2(CDT& cdt, const Hyperbolic_Chew_mesh_criteria_2<CDT>& criteria,
                              const CGAL_NP_CLASS& np = parameters::default_values())
{ return Hyperbolic_mesh_2::internal::refine_hyperbolic_mesh_np(cdt, criteria, np); }

/*!
  \ingroup PkgHyperbolicMesh2Ref
  Marks the domain of `cdt` without refining it (same rules as the refinement entry points).
*/
template <class CDT, class SeedIterator>
void mark_hyperbolic_domain_2(CDT& cdt, SeedIterator seeds_begin, SeedIterator seeds_end, bool seeds_are_in_domain = false)
{
  std::vector<typename CDT::Point> seeds(seeds_begin, seeds_end);
  Hyperbolic_mesh_2::internal::mark_domain(cdt, seeds, seeds_are_in_domain);
}

} // namespace CGAL

#endif // CGAL_REFINE_HYPERBOLIC_MESH_2_H
