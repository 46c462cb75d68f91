// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Types shared by the entry points of the Discrete_Ricci_flow package: background geometries, schemes,
// statuses, the exception type, progress information and the package's own named parameters.
#ifndef CGAL_DISCRETE_RICCI_FLOW_FLOW_TYPES_H
#define CGAL_DISCRETE_RICCI_FLOW_FLOW_TYPES_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_type_config.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace internal_np {
// package-specific named-parameter tags (looked up with parameters::get_parameter like CGAL's own)
enum ricci_background_geometry_t { ricci_background_geometry };
enum ricci_scheme_t { ricci_scheme };
enum ricci_edge_length_map_t { ricci_edge_length_map };
enum ricci_geometric_initial_flips_t { ricci_geometric_initial_flips };
} // namespace internal_np

namespace Ricci_flow {

/// \ingroup PkgDiscreteRicciFlowRef
/// The constant-curvature geometry of the triangles: E^2 (K = 0), H^2 (K = -1), S^2 (K = +1).
enum class Background_geometry { EUCLIDEAN, HYPERBOLIC, SPHERICAL };

/// \ingroup PkgDiscreteRicciFlowRef
/// How the conformal factors u_i change the edge lengths (thesis Section 2.2.3).
///  - VERTEX_SCALING: discrete conformal / discrete Yamabe flow, sinh(l~/2) = e^{(u_i+u_j)/2} sinh(l/2) in H^2,
///    l~ = e^{(u_i+u_j)/2} l in E^2, sin(l~/2) = e^{(u_i+u_j)/2} sin(l/2) in S^2. Supports Ptolemy flips.
///  - TANGENTIAL_CIRCLE_PACKING: circles of radius r_i (u = log r in E^2, log tanh(r/2) in H^2) tangent along
///    each edge (inversive distance 1).
///  - THURSTON_CIRCLE_PACKING: circles intersecting at angles Phi_ij in [0, pi/2] computed from the input
///    (I = cos Phi = the input inversive distance clamped to [0, 1]).
///  - INVERSIVE_DISTANCE: circles with the inversive distances of the input (may be > 1).
/// The radii of the three packing schemes start from the tangent lengths of the input triangles.
enum class Scheme { VERTEX_SCALING, TANGENTIAL_CIRCLE_PACKING, THURSTON_CIRCLE_PACKING, INVERSIVE_DISTANCE };

/// \ingroup PkgDiscreteRicciFlowRef
/// Outcome of a flow.
enum class Flow_status {
  CONVERGED,               ///< max |K_i - target_i| below the tolerance
  MAXIMUM_ITERATIONS,      ///< stopped after the allowed number of Newton iterations
  LINE_SEARCH_FAILED,      ///< no step along the Newton direction decreased the energy
  NUMERICAL_FAILURE,       ///< the Hessian could not be factorized or a non-finite value appeared
  FLIP_LIMIT_REACHED,      ///< the Delaunay flip loop exceeded its budget
  CANCELLED,               ///< the progress callback asked to stop
  STAGNATED                ///< below 1e-6, five iterations without halving the error: the rounding floor of
                           ///< double arithmetic is above the requested accuracy (the error reached is reported)
};

inline const char* to_string(Flow_status s)
{
  switch(s) {
    case Flow_status::CONVERGED: return "converged";
    case Flow_status::MAXIMUM_ITERATIONS: return "maximum number of iterations reached";
    case Flow_status::LINE_SEARCH_FAILED: return "line search failed";
    case Flow_status::NUMERICAL_FAILURE: return "numerical failure";
    case Flow_status::FLIP_LIMIT_REACHED: return "flip limit reached";
    case Flow_status::CANCELLED: return "cancelled";
    default: return "stagnated (rounding floor above the requested accuracy)";
  }
}

/// \ingroup PkgDiscreteRicciFlowRef
/// Thrown for input that the flow cannot handle: not a triangle mesh, non-manifold, open where a closed surface
/// is needed, several connected components, degenerate faces, wrong genus for the requested background, target
/// curvatures violating Gauss-Bonnet, inconsistent options.
class Ricci_flow_error : public std::runtime_error
{
public:
  explicit Ricci_flow_error(const std::string& what) : std::runtime_error("CGAL::Ricci_flow: " + what) {}
};

/// \ingroup PkgDiscreteRicciFlowRef
/// What the progress callback receives after each Newton iteration.
struct Flow_progress
{
  int iteration = 0;                 ///< Newton iterations done so far
  double max_curvature_error = 0;    ///< max_i |K_i - target_i| at the current iterate
  double step_length = 0;            ///< accepted line-search step t in (0, 1]
  std::size_t number_of_flips = 0;   ///< Ptolemy flips so far
};

/// The statistics of a flow: status, iterations, errors, energy, time, flips, factorizations.
struct Flow_statistics
{
  Flow_status status = Flow_status::MAXIMUM_ITERATIONS;
  int iterations = 0;                        ///< Newton iterations (accepted steps)
  double max_curvature_error = 0;            ///< max_i |K_i - target_i| at the returned metric (radians)
  std::vector<double> error_history;         ///< max curvature error before each iteration and at the end
  /// energy of the flow relative to its start, E(u_k) - E(u_0), one entry per iterate (the first is 0). The
  /// energy is the convex potential whose gradient is K - target; its increments are integrated along each
  /// step with the trapezoidal rule from the gradient (exact for a quadratic energy).
  std::vector<double> energy_history;
  double time_seconds = 0;                   ///< wall-clock time of the flow
  std::size_t number_of_flips = 0;           ///< Ptolemy (intrinsic Delaunay) flips during the flow
  std::size_t number_of_initial_flips = 0;   ///< geometric flips of the input (`geometric_initial_flips`)
  std::size_t number_of_symbolic_factorizations = 0; ///< Eigen analyzePattern calls (pattern changes)
  std::size_t number_of_factorizations = 0;  ///< Eigen numeric factorizations (one per Newton iteration)
  double factorization_seconds = 0;          ///< time spent in analyzePattern + factorize
  bool converged() const { return status == Flow_status::CONVERGED; }
};

namespace parameters {

#define CGAL_RICCI_FLOW_NAMED_PARAMETER(NAME, TAG)                                                   \
  template <class T>                                                                                  \
  CGAL::Named_function_parameters<T, CGAL::internal_np::TAG> NAME(const T& v)                         \
  { return CGAL::Named_function_parameters<T, CGAL::internal_np::TAG>(v); }                           \
  template <class T, class T2, class Tag2, class Base2>                                               \
  CGAL::Named_function_parameters<T, CGAL::internal_np::TAG, CGAL::Named_function_parameters<T2, Tag2, Base2> > \
  NAME(const T& v, const CGAL::Named_function_parameters<T2, Tag2, Base2>& base)                      \
  { return CGAL::Named_function_parameters<T, CGAL::internal_np::TAG,                                 \
                                           CGAL::Named_function_parameters<T2, Tag2, Base2> >(v, base); }

/// named parameter `background_geometry(Background_geometry g [, np])`: the background geometry (default
/// depends on the entry point). The optional second argument chains other named parameters, e.g.
/// `background_geometry(Background_geometry::EUCLIDEAN, CGAL::parameters::number_of_iterations(50))`;
/// CGAL's own parameters chain as members: `scheme(s).number_of_iterations(50).verbose(true)`.
CGAL_RICCI_FLOW_NAMED_PARAMETER(background_geometry, ricci_background_geometry_t)
/// named parameter `scheme(Scheme s [, np])` (default `Scheme::VERTEX_SCALING`)
CGAL_RICCI_FLOW_NAMED_PARAMETER(scheme, ricci_scheme_t)
/// named parameter `input_edge_length_map(map [, np])`: a readable edge property map with the input edge
/// lengths (default: Euclidean lengths from the vertex point map). Starts the flow from an intrinsic metric.
CGAL_RICCI_FLOW_NAMED_PARAMETER(input_edge_length_map, ricci_edge_length_map_t)

/// named parameter `geometric_initial_flips(bool [, np])` (default false; vertex scaling only): first make the
/// input intrinsically Delaunay by geometric flips (which keep its piecewise-linear Euclidean metric), then flow
/// with Ptolemy flips (Gillespie-Springborn-Crane 2021). The result then depends only on the input's metric,
/// not on its triangulation; without it, the discrete conformal class is the Penner class of the input
/// triangulation (Moebius invariant).
CGAL_RICCI_FLOW_NAMED_PARAMETER(geometric_initial_flips, ricci_geometric_initial_flips_t)

#undef CGAL_RICCI_FLOW_NAMED_PARAMETER

} // namespace parameters

} // namespace Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_FLOW_TYPES_H
