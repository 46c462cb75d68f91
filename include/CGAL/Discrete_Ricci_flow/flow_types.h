// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Types shared by the entry points of the Discrete_Ricci_flow package: background geometries, schemes,
// statuses, the exception type, progress information and the package's own named parameters.
#ifndef CGAL_DISCRETE_RICCI_FLOW_FLOW_TYPES_H
#define CGAL_DISCRETE_RICCI_FLOW_FLOW_TYPES_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_geometry_named_parameters.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_type_config.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

// package-specific named-parameter tags (looked up with parameters::get_parameter like CGAL's own)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ricci_background_geometry_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ricci_scheme_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ricci_edge_length_map_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ricci_geometric_initial_flips_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ricci_sparse_solver_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ricci_puncture_vertex_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ricci_reuse_factorization_t)

namespace CGAL {
namespace Discrete_Ricci_flow {

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
  DEGENERATE_TRIANGLES,    ///< the curvatures are reached only with degenerate triangles (Luo's extension
                           ///< of the angles): not a metric; Ptolemy flips (`do_flip(true)`) avoid it
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
    case Flow_status::DEGENERATE_TRIANGLES: return "degenerate triangles at the solution (flips needed)";
    default: return "stagnated (rounding floor above the requested accuracy)";
  }
}

/*!
  \ingroup PkgDiscreteRicciFlowRef
  The errors of the package are the shared ones of `CGAL/Hyperbolic_geometry_errors.h`:
  - `CGAL::Invalid_mesh_error`: empty, open where a closed surface is needed, several connected components
    (checked first), not triangulated (quad meshes: triangulate with
    `CGAL::Polygon_mesh_processing::triangulate_faces()`), non-manifold, wrong genus for the entry point;
  - `CGAL::Invalid_metric_error`: input edge lengths that are not positive and finite, or faces that stay
    degenerate after the intrinsic Delaunay flips of the input;
  - `CGAL::Invalid_option_error`: a named parameter out of its range (accuracy, number of iterations, an
    invalid vertex index map or puncture vertex, a scheme that the entry point does not support);
  - `CGAL::Invalid_input_error`: target curvatures that violate Gauss-Bonnet or are not finite;
  - `CGAL::Numerical_error`: a computation that could not be carried out in double precision (e.g. the
    Moebius normalization of the spherical map did not converge).
  `Ricci_flow_error` is kept as the name of their common base for input problems: it *is*
  `CGAL::Invalid_input_error`, so `catch(const Ricci_flow_error&)` catches every input error of the package.
  Non-convergence of the flow is not an exception but a `Flow_status`.
*/
typedef CGAL::Invalid_input_error Ricci_flow_error;

namespace internal {
inline std::string message(const std::string& what) { return "CGAL::Discrete_Ricci_flow: " + what; }
[[noreturn]] inline void throw_mesh_error(const std::string& what) { throw CGAL::Invalid_mesh_error(message(what)); }
[[noreturn]] inline void throw_metric_error(const std::string& what) { throw CGAL::Invalid_metric_error(message(what)); }
[[noreturn]] inline void throw_option_error(const std::string& what) { throw CGAL::Invalid_option_error(message(what)); }
[[noreturn]] inline void throw_input_error(const std::string& what) { throw CGAL::Invalid_input_error(message(what)); }
[[noreturn]] inline void throw_numerical_error(const std::string& what) { throw CGAL::Numerical_error(message(what)); }
} // namespace internal

/// \ingroup PkgDiscreteRicciFlowRef
/// The sparse Cholesky factorization of the Newton systems. `DEFAULT` is CHOLMOD's supernodal Cholesky for
/// meshes of at least 100,000 vertices when the library was configured with SuiteSparse (macro
/// `CGAL_HC_HAS_CHOLMOD`), else Eigen's `SimplicialLDLT` (faster on smaller meshes, see the manual's
/// performance section).
/// An indefinite Hessian (spherical background) falls back to `SimplicialLDLT` for that iteration.
enum class Sparse_solver { DEFAULT, SUPERNODAL_CHOLMOD, SIMPLICIAL_LDLT };

/// \ingroup PkgDiscreteRicciFlowRef
/// true if CHOLMOD is available (the library was configured with SuiteSparse)
inline constexpr bool has_cholmod()
{
#ifdef CGAL_HC_HAS_CHOLMOD
  return true;
#else
  return false;
#endif
}

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
  std::size_t number_of_symbolic_factorizations = 0; ///< symbolic analyses (after pattern changes)
  /// fill-reducing orderings computed: the first, and a new one whenever Ptolemy flips have made the kept
  /// ordering's factor more than 1.2 times larger than it was for the pattern the ordering was computed for
  std::size_t number_of_orderings = 0;
  std::size_t number_of_factorizations = 0;  ///< numeric factorizations (at most one per Newton iteration)
  double factorization_seconds = 0;          ///< time spent in analyzePattern + factorize + solve
  double first_factorization_seconds = 0;    ///< time of the first analyzePattern + factorize + solve
  Sparse_solver solver_used = Sparse_solver::SIMPLICIAL_LDLT; ///< the solver of the last Newton system
  std::size_t number_of_solver_fallbacks = 0; ///< iterations that fell back to SimplicialLDLT (indefinite)
  /// factorizations of H + mu I (Levenberg-Marquardt) for a singular Hessian of a convex energy (E^2, H^2:
  /// an interior vertex whose triangles are all degenerate)
  std::size_t number_of_shifted_factorizations = 0;
  /// conjugate-gradient iterations on Newton systems preconditioned by an earlier factorization (each costs
  /// one solve with the factor and one product with the Hessian)
  std::size_t number_of_cg_iterations = 0;
  double cg_seconds = 0;                     ///< time spent in those conjugate gradients
  double hessian_seconds = 0;                ///< time spent assembling the Hessians
  /// Newton steps taken after the requested accuracy was reached (default accuracy: until the error stops
  /// halving, see `compute_metric()`)
  int polishing_iterations = 0;
  bool converged() const { return status == Flow_status::CONVERGED; }
};

namespace parameters {

/// named parameter `background_geometry(Background_geometry g [, np])`: the background geometry (default
/// depends on the entry point). The optional second argument chains other named parameters, e.g.
/// `background_geometry(Background_geometry::EUCLIDEAN, CGAL::parameters::number_of_iterations(50))`;
/// CGAL's own parameters chain as members: `scheme(s).number_of_iterations(50).verbose(true)`.
CGAL_HYPERBOLIC_NAMED_PARAMETER(background_geometry, ricci_background_geometry_t)
/// named parameter `scheme(Scheme s [, np])` (default `Scheme::VERTEX_SCALING`)
CGAL_HYPERBOLIC_NAMED_PARAMETER(scheme, ricci_scheme_t)
/// named parameter `input_edge_length_map(map [, np])`: a readable edge property map with the input edge
/// lengths (default: Euclidean lengths from the vertex point map). Starts the flow from an intrinsic metric.
CGAL_HYPERBOLIC_NAMED_PARAMETER(input_edge_length_map, ricci_edge_length_map_t)
/// named parameter `geometric_initial_flips(bool [, np])` (default false; vertex scaling only): first make the
/// input intrinsically Delaunay by geometric flips (which keep its piecewise-linear Euclidean metric), then flow
/// with Ptolemy flips (Gillespie-Springborn-Crane 2021). The result then depends only on the input's metric,
/// not on its triangulation; without it, the discrete conformal class is the Penner class of the input
/// triangulation (Moebius invariant). Inputs with degenerate (zero-area) faces get these flips automatically.
CGAL_HYPERBOLIC_NAMED_PARAMETER(geometric_initial_flips, ricci_geometric_initial_flips_t)
/// named parameter `sparse_solver(Sparse_solver s [, np])` (default `Sparse_solver::DEFAULT`)
CGAL_HYPERBOLIC_NAMED_PARAMETER(sparse_solver, ricci_sparse_solver_t)
/// named parameter `reuse_factorization(bool [, np])` (default true): solve the Newton systems by conjugate
/// gradients preconditioned with the Cholesky factorization of an earlier Newton step, factorizing again only
/// when they do not reach the inexact-Newton tolerance within a budget of a fraction of a factorization's
/// cost (see `compute_metric()`); false: one factorization per Newton step. The convergence test is the same.
CGAL_HYPERBOLIC_NAMED_PARAMETER(reuse_factorization, ricci_reuse_factorization_t)
/// named parameter `puncture_vertex(std::size_t i [, np])`: the vertex (index in `vertices(tm)`) sent to the
/// north pole by `spherical_uniformization()` (default: a vertex of largest degree)
CGAL_HYPERBOLIC_NAMED_PARAMETER(puncture_vertex, ricci_puncture_vertex_t)

} // namespace parameters

} // namespace Discrete_Ricci_flow

/// \ingroup PkgDiscreteRicciFlowRef
/// Short alias of the package namespace: `CGAL::Ricci_flow::hyperbolic_uniformization(tm)`.
namespace Ricci_flow = Discrete_Ricci_flow;
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_FLOW_TYPES_H
