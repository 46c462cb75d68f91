// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Entry points of the discrete Ricci flow: compute_metric (any target curvature, any scheme and background),
// hyperbolic_uniformization (genus >= 2, K = 0 in H^2) and flat_metric (genus 1, K = 0 in E^2).
#ifndef CGAL_DISCRETE_RICCI_FLOW_COMPUTE_METRIC_H
#define CGAL_DISCRETE_RICCI_FLOW_COMPUTE_METRIC_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/Discrete_Ricci_flow/internal/flow_engine.h>
#include <CGAL/Discrete_Ricci_flow/internal/mesh_checks.h>
#include <CGAL/Discrete_Ricci_flow/internal/triangle_geometry.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Ricci_flow {

/*!
  \ingroup PkgDiscreteRicciFlowRef
  The result of a flow: statistics and the computed metric as an *intrinsic triangulation*.

  The intrinsic triangulation is a `CGAL::Surface_mesh<Point_3>` with the same vertex set as the input mesh
  (vertex `i` of `intrinsic_mesh()` is the `i`-th vertex of `vertices(tm)`, with the input position copied:
  positions are meaningless for the metric) whose connectivity is the input's after the Ptolemy flips done
  by the flow (identical to the input when `statistics().number_of_flips == 0`). Its edge lengths
  (`edge_length_map()`, the property `"e:length"`) define a polyhedral metric of constant curvature
  (`background_geometry()`) with the requested cone curvatures. It may contain multi-edges and loops
  (intrinsic triangulations do), never degenerate triangles when the flow converged.

  The conformal factors `conformal_factors()[i]` (u_i) relate the result to the input through the scheme; for
  vertex scaling the final metric on the input connectivity has Penner coordinates
  `lambda_ij = e^{(u_i+u_j)/2} l_ij / 2` (lengths `2 asinh(lambda)` in H^2, `2 lambda` in E^2): this is what
  `compute_metric()` writes into the user's edge length map. When flips happened, those lengths may violate
  triangle inequalities (the metric is then realized only by the intrinsic triangulation);
  `input_connectivity_is_valid()` tells.
*/
template <class Point_3>
class Discrete_metric
{
public:
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Edge_index Edge_index;
  typedef typename Mesh::Face_index Face_index;
  typedef typename Mesh::template Property_map<Edge_index, double> Edge_length_map;

  Discrete_metric() {}
  Discrete_metric(const Discrete_metric& o) { *this = o; }
  Discrete_metric& operator=(const Discrete_metric& o)
  {
    mesh_ = o.mesh_;
    lengths_ = mesh_.template property_map<Edge_index, double>("e:length").first;
    geo_ = o.geo_; u_ = o.u_; stats_ = o.stats_; target_ = o.target_; genus_ = o.genus_;
    input_valid_ = o.input_valid_;
    return *this;
  }

  /// the intrinsic triangulation (see the class description)
  const Mesh& intrinsic_mesh() const { return mesh_; }
  /// its edge lengths (property `"e:length"` of `intrinsic_mesh()`)
  Edge_length_map edge_length_map() const { return lengths_; }
  double length(Edge_index e) const { return lengths_[e]; }
  double length(Halfedge_index h) const { return lengths_[mesh_.edge(h)]; }
  Background_geometry background_geometry() const { return geo_; }
  /// u_i, indexed like the vertices of the input
  const std::vector<double>& conformal_factors() const { return u_; }
  /// the target curvatures used (K for interior vertices, geodesic curvature for border vertices)
  const std::vector<double>& target_curvatures() const { return target_; }
  const Flow_statistics& statistics() const { return stats_; }
  bool converged() const { return stats_.converged(); }
  long genus() const { return genus_; }
  /// true if the Penner lengths on the input connectivity satisfy all triangle inequalities
  bool input_connectivity_is_valid() const { return input_valid_; }

  /// the corner angle at the corner opposite to `h` in `face(h)` (computed from the lengths)
  double angle_opposite(Halfedge_index h) const
  {
    double l[3] = {length(h), length(mesh_.next(h)), length(mesh_.prev(h))}, th[3], d[3][3];
    internal::triangle_angles(geo_, l, th, d);
    return th[0];
  }

  /// the curvature of a vertex: 2 pi (pi on the border) minus the sum of its corner angles
  double curvature(Vertex_index v) const
  {
    double k = mesh_.is_border(v) ? CGAL_PI : 2 * CGAL_PI;
    for(Halfedge_index h : CGAL::halfedges_around_target(v, mesh_))
      if(!mesh_.is_border(h)) k -= angle_opposite(mesh_.prev(h));
    return k;
  }

  /// total area (the sum of the triangle areas of the background geometry)
  double total_area() const
  {
    double a = 0;
    for(Face_index f : mesh_.faces()) {
      const Halfedge_index h = mesh_.halfedge(f);
      double l[3] = {length(h), length(mesh_.next(h)), length(mesh_.prev(h))}, th[3], d[3][3];
      internal::triangle_angles(geo_, l, th, d);
      a += internal::triangle_area(geo_, l, th);
    }
    return a;
  }

  // implementation details, filled by compute_metric() (not part of the documented interface)
  Mesh mesh_;
  Edge_length_map lengths_;
  Background_geometry geo_ = Background_geometry::HYPERBOLIC;
  std::vector<double> u_, target_;
  Flow_statistics stats_;
  long genus_ = 0;
  bool input_valid_ = true;
};

namespace internal {

template <class NP>
Background_geometry get_background(const NP& np, Background_geometry def)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::ricci_background_geometry), def);
}

// the optional callback: a callable taking const Flow_progress& and returning bool (false cancels) or void
template <class Callback>
bool call_progress(const Callback& cb, const Flow_progress& p, std::true_type) { return cb(p); }
template <class Callback>
bool call_progress(const Callback& cb, const Flow_progress& p, std::false_type) { cb(p); return true; }
inline bool call_progress_any(const CGAL::internal_np::Param_not_found&, const Flow_progress&) { return true; }
template <class Callback>
bool call_progress_any(const Callback& cb, const Flow_progress& p)
{
  typedef decltype(cb(p)) R;
  return call_progress(cb, p, std::integral_constant<bool, std::is_convertible<R, bool>::value>());
}

} // namespace internal

/*!
  \ingroup PkgDiscreteRicciFlowRef
  Computes a metric of constant background curvature on `tm` with prescribed vertex curvatures, by Newton's
  method on the convex discrete Ricci energy (thesis Algorithm 1).

  \tparam TriangleMesh a model of `FaceListGraph` (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`), connected,
          pure triangle, manifold; closed or with boundary.
  \param tm the input mesh; its initial metric is given by the vertex positions or `input_edge_length_map`.
  \param target_curvature a readable vertex property map (value convertible to `double`): the target Gaussian
         curvature K_i (2 pi minus the cone angle) of interior vertices and the target geodesic curvature
         (pi minus the boundary angle) of border vertices. Gauss-Bonnet is checked: sum = 2 pi chi in E^2,
         sum > 2 pi chi in H^2 (the difference is the area), sum < 2 pi chi in S^2.
  \param edge_length_out a writable edge property map of `tm` receiving the resulting edge lengths of the
         input connectivity (see `Discrete_metric` when flips happened).
  \param np optional named parameters:
    - `background_geometry(g)` (default HYPERBOLIC), `scheme(s)` (default VERTEX_SCALING),
      `input_edge_length_map(m)` (default: Euclidean lengths from `vertex_point_map`),
    - `CGAL::parameters::vertex_point_map`, `vertex_index_map`,
    - `number_of_iterations(n)`: maximum number of Newton iterations (default 100),
    - `accuracy(eps)`: stop when max |K_i - target_i| < eps (radians, default 1e-11),
    - `do_flip(b)`: keep the triangulation intrinsically Delaunay with Ptolemy flips (default true; vertex
      scaling only),
    - `geometric_initial_flips(b)`: first make the input intrinsically Delaunay by metric-preserving flips
      (default false; see `parameters::geometric_initial_flips()`),
    - `verbose(b)`: one line per iteration on `std::cerr`,
    - `callback(f)`: `f(const Flow_progress&)` after each iteration; return `false` to stop (status CANCELLED).
  \returns the result (status, statistics, intrinsic triangulation, conformal factors).
  \throws Ricci_flow_error on invalid input (see `Ricci_flow_error`). Non-convergence is not an exception:
          the status says it, the metric is the last accepted iterate (finite lengths).

  Cost per iteration: one sparse Cholesky (`Eigen::SimplicialLDLT`) factorization of the n x n Hessian, whose
  symbolic analysis is reused until flips change the sparsity pattern; O(F) for the rest. On the test meshes
  3 to 8 iterations.
*/
template <class TriangleMesh, class VertexTargetMap, class EdgeLengthOutMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Discrete_metric<typename boost::property_traits<
  typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>::value_type>
compute_metric(const TriangleMesh& tm, VertexTargetMap target_curvature, EdgeLengthOutMap edge_length_out,
               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef Discrete_metric<Point_3> Result;
  typedef typename Result::Mesh Mesh;
  typedef typename Mesh::Vertex_index V;
  typedef typename Mesh::Halfedge_index H;
  typedef typename Mesh::Edge_index E;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor tm_vertex;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor tm_face;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor tm_edge;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor tm_halfedge;

  const auto t_start = std::chrono::steady_clock::now();
  internal::check_triangle_mesh(tm);

  const Background_geometry geo = internal::get_background(np, Background_geometry::HYPERBOLIC);
  const Scheme scheme = choose_parameter(get_parameter(np, internal_np::ricci_scheme), Scheme::VERTEX_SCALING);
  const int max_iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 100);
  const double accuracy = choose_parameter(get_parameter(np, internal_np::accuracy), 1e-11);
  const bool do_flip = choose_parameter(get_parameter(np, internal_np::do_flip), true);
  const bool verbose = choose_parameter(get_parameter(np, internal_np::verbose), false);
  const auto callback = get_parameter(np, internal_np::callback);
  VPM vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  if(!(accuracy > 0)) throw Ricci_flow_error("accuracy must be positive");
  if(max_iterations < 0) throw Ricci_flow_error("number_of_iterations must be non-negative");

  // ---- copy the connectivity into the intrinsic triangulation
  Result res;
  Mesh& m = res.mesh_;
  const std::size_t nv = vertices(tm).size();
  std::vector<V> vmap(nv);
  for(tm_vertex v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    if(i >= nv) throw Ricci_flow_error("invalid vertex index map");
    vmap[i] = m.add_vertex(get(vpm, v));
  }
  for(tm_face f : faces(tm)) {
    std::vector<V> fv;
    for(tm_vertex v : CGAL::vertices_around_face(halfedge(f, tm), tm)) fv.push_back(vmap[get(vim, v)]);
    if(m.add_face(fv) == Mesh::null_face()) throw Ricci_flow_error("the mesh is not an oriented 2-manifold");
  }
  // input lengths (on the intrinsic mesh's edges) and the user-edge -> mesh-edge correspondence
  std::vector<double> input_len(m.number_of_edges(), -1.0);
  std::vector<std::pair<tm_edge, E> > edge_corr;
  edge_corr.reserve(edges(tm).size());
  const auto elm = get_parameter(np, internal_np::ricci_edge_length_map);
  for(tm_edge e : edges(tm)) {
    const tm_halfedge h = halfedge(e, tm);
    const V a = vmap[get(vim, source(h, tm))], b = vmap[get(vim, target(h, tm))];
    const H mh = m.halfedge(a, b);
    if(mh == Mesh::null_halfedge()) throw Ricci_flow_error("inconsistent mesh connectivity");
    double l;
    if constexpr(std::is_same<typename std::decay<decltype(elm)>::type, CGAL::internal_np::Param_not_found>::value)
      l = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
    else
      l = CGAL::to_double(get(elm, e));
    if(!(l > 0) || !std::isfinite(l)) throw Ricci_flow_error("an edge has zero, negative or non-finite length");
    input_len[m.edge(mh)] = l;
    edge_corr.emplace_back(e, m.edge(mh));
  }
  // degenerate faces
  double input_area = 0;
  for(auto f : m.faces()) {
    const H h = m.halfedge(f);
    const double l[3] = {input_len[m.edge(h)], input_len[m.edge(m.next(h))], input_len[m.edge(m.prev(h))]};
    const double s = 0.5 * (l[0] + l[1] + l[2]);
    for(int i = 0; i < 3; ++i)
      if(!(l[i] < l[(i + 1) % 3] + l[(i + 2) % 3] - 1e-12 * s)) {
        std::ostringstream os;
        os << "degenerate face " << std::size_t(f) << " (edge lengths " << l[0] << ", " << l[1] << ", " << l[2] << ")";
        throw Ricci_flow_error(os.str());
      }
    input_area += std::sqrt(s * (s - l[0]) * (s - l[1]) * (s - l[2]));
  }

  // ---- topology and Gauss-Bonnet
  const internal::Mesh_topology topo = internal::mesh_topology(m);
  if(topo.components != 1)
    throw Ricci_flow_error("the mesh has " + std::to_string(topo.components) + " connected components (need 1)");
  res.genus_ = topo.genus;
  std::vector<double> target_k(nv);
  double target_sum = 0;
  for(tm_vertex v : vertices(tm)) {
    const double k = CGAL::to_double(get(target_curvature, v));
    if(!std::isfinite(k)) throw Ricci_flow_error("non-finite target curvature");
    target_k[std::size_t(vmap[get(vim, v)])] = k;
    target_sum += k;
  }
  const double two_pi_chi = 2 * CGAL_PI * double(topo.euler_characteristic);
  const double gb_tol = 1e-9 * (2 * CGAL_PI + std::abs(two_pi_chi));
  double target_area = 0; // area of the result implied by Gauss-Bonnet (H^2, S^2)
  {
    std::ostringstream os;
    os.precision(12);
    os << "target curvatures violate Gauss-Bonnet: sum = " << target_sum << ", 2 pi chi = " << two_pi_chi
       << " (chi = " << topo.euler_characteristic << ")";
    if(geo == Background_geometry::EUCLIDEAN && std::abs(target_sum - two_pi_chi) > gb_tol)
      throw Ricci_flow_error(os.str() + "; E^2 needs sum = 2 pi chi");
    if(geo == Background_geometry::HYPERBOLIC && !(target_sum - two_pi_chi > gb_tol))
      throw Ricci_flow_error(os.str() + "; H^2 needs sum > 2 pi chi");
    if(geo == Background_geometry::SPHERICAL && !(two_pi_chi - target_sum > gb_tol))
      throw Ricci_flow_error(os.str() + "; S^2 needs sum < 2 pi chi");
    target_area = std::abs(target_sum - two_pi_chi);
  }

  // ---- optional: make the input intrinsically Delaunay by geometric flips (its PL metric is unchanged)
  const bool geometric_initial =
    choose_parameter(get_parameter(np, internal_np::ricci_geometric_initial_flips), false) && scheme == Scheme::VERTEX_SCALING;
  std::vector<E> initial_flips;
  Mesh mesh_after_initial_flips;
  std::vector<double> lambda_after_initial_flips;
  if(geometric_initial) {
    internal::Flow_engine<Point_3> eng0(m, Background_geometry::EUCLIDEAN, Scheme::VERTEX_SCALING, true);
    eng0.geometric_flips = true;
    for(E e : m.edges()) eng0.edge_data[e] = 0.5 * input_len[e];
    eng0.compute_lengths();
    eng0.compute_angles();
    if(!eng0.make_delaunay()) throw Ricci_flow_error("the geometric Delaunay flips of the input did not terminate");
    for(E e : m.edges()) input_len[e] = eng0.len[e];
    initial_flips = eng0.flip_log;
    res.stats_.number_of_initial_flips = initial_flips.size();
    if(!initial_flips.empty()) { mesh_after_initial_flips = m; lambda_after_initial_flips = eng0.edge_data; }
  }

  // ---- initial state: a uniform scale making the triangles' total area about the target area
  internal::Flow_engine<Point_3> eng(m, geo, scheme, do_flip);
  eng.target = target_k;
  const double scale = geo == Background_geometry::EUCLIDEAN ? 1.0 : std::sqrt(target_area / input_area);
  if(scheme == Scheme::VERTEX_SCALING) {
    for(E e : m.edges()) eng.edge_data[e] = 0.5 * input_len[e];
    std::fill(eng.u.begin(), eng.u.end(), std::log(scale));
  } else {
    // radii: mean tangent length (l_ij + l_ik - l_jk) / 2 of the incident corners
    std::vector<double> rsum(nv, 0.0), rcount(nv, 0.0);
    for(auto f : m.faces()) {
      const H h = m.halfedge(f);
      const H hs[3] = {h, m.next(h), m.prev(h)};
      for(int i = 0; i < 3; ++i) { // corner at source(hs[i]) between hs[i] and hs[i-1]
        const double a = input_len[m.edge(hs[i])], b = input_len[m.edge(hs[(i + 2) % 3])],
                     c = input_len[m.edge(hs[(i + 1) % 3])];
        rsum[m.source(hs[i])] += 0.5 * (a + b - c);
        rcount[m.source(hs[i])] += 1;
      }
    }
    std::vector<double> r(nv);
    for(std::size_t i = 0; i < nv; ++i) r[i] = rsum[i] / rcount[i];
    for(E e : m.edges()) {
      const std::size_t a = m.vertex(e, 0), b = m.vertex(e, 1);
      const double l = input_len[e];
      double I = (l * l - r[a] * r[a] - r[b] * r[b]) / (2 * r[a] * r[b]);
      if(scheme == Scheme::TANGENTIAL_CIRCLE_PACKING) I = 1;
      if(scheme == Scheme::THURSTON_CIRCLE_PACKING) I = I < 0 ? 0 : (I > 1 ? 1 : I);
      eng.edge_data[e] = I;
    }
    for(std::size_t i = 0; i < nv; ++i) eng.u[i] = internal::u_from_radius(geo, scale * r[i]);
  }

  // ---- Newton's method with line search (thesis Algorithm 1)
  Flow_statistics& st = res.stats_;
  const int n = int(nv);
  const bool gauge = geo == Background_geometry::EUCLIDEAN; // E^2: u is defined up to a constant: pin u_0
  std::vector<double> g(nv);
  auto evaluate = [&](double& max_err) -> bool {
    eng.compute_lengths();
    eng.compute_angles();
    if(!eng.make_delaunay()) return false;
    eng.compute_curvature();
    max_err = 0;
    for(std::size_t i = 0; i < nv; ++i) {
      g[i] = eng.K[i] - eng.target[i];
      if(!std::isfinite(g[i])) { max_err = std::numeric_limits<double>::infinity(); return true; }
      max_err = (std::max)(max_err, std::abs(g[i]));
    }
    return true;
  };
  double err = 0;
  if(!evaluate(err)) st.status = Flow_status::FLIP_LIMIT_REACHED;
  else if(!std::isfinite(err)) st.status = Flow_status::NUMERICAL_FAILURE;
  else st.status = Flow_status::MAXIMUM_ITERATIONS;
  st.error_history.push_back(err);
  st.energy_history.push_back(0.0);
  double energy = 0;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > solver;
  int analyzed_version = -1;
  std::vector<Eigen::Triplet<double> > trip;
  Eigen::SparseMatrix<double> Hm(n, n);
  Eigen::VectorXd rhs(n), delta(n);
  std::vector<double> u_old, g_old;
  double best_err = err;
  int iterations_without_progress = 0;
  while(st.status == Flow_status::MAXIMUM_ITERATIONS) {
    if(err < accuracy) { st.status = Flow_status::CONVERGED; break; }
    if(st.iterations >= max_iterations) break;
    if(iterations_without_progress >= 5) { st.status = Flow_status::STAGNATED; break; }
    // Hessian dK/du
    eng.hessian_triplets(trip);
    if(gauge) {
      trip.erase(std::remove_if(trip.begin(), trip.end(),
                                [](const Eigen::Triplet<double>& t) { return t.row() == 0 || t.col() == 0; }),
                 trip.end());
      trip.emplace_back(0, 0, 1.0);
    }
    Hm.setFromTriplets(trip.begin(), trip.end());
    const auto tf0 = std::chrono::steady_clock::now();
    if(analyzed_version != eng.pattern_version) {
      solver.analyzePattern(Hm);
      analyzed_version = eng.pattern_version;
      ++st.number_of_symbolic_factorizations;
    }
    solver.factorize(Hm);
    ++st.number_of_factorizations;
    if(solver.info() != Eigen::Success) {
      st.factorization_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - tf0).count();
      st.status = Flow_status::NUMERICAL_FAILURE; break;
    }
    for(int i = 0; i < n; ++i) rhs[i] = -g[i];
    if(gauge) rhs[0] = 0;
    delta = solver.solve(rhs);
    st.factorization_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - tf0).count();
    if(!delta.allFinite()) { st.status = Flow_status::NUMERICAL_FAILURE; break; }
    double slope0 = 0;
    for(int i = 0; i < n; ++i) slope0 += g[i] * delta[i];
    // line search: accept t when the energy decreases (trapezoidal estimate from the directional derivatives;
    // the energy is convex for E^2 / H^2) or the max error decreases
    u_old = eng.u; g_old = g;
    const double err_old = err;
    double t = 1.0;
    bool accepted = false;
    while(t > 1e-12) {
      for(int i = 0; i < n; ++i) eng.u[i] = u_old[i] + t * delta[i];
      double e2 = 0;
      if(!evaluate(e2)) { st.status = Flow_status::FLIP_LIMIT_REACHED; break; }
      if(std::isfinite(e2)) {
        double slope_t = 0;
        for(int i = 0; i < n; ++i) slope_t += g[i] * delta[i];
        const double de = 0.5 * t * (slope0 + slope_t);
        if((slope0 < 0 && de <= 1e-4 * t * slope0) || e2 < err_old * (1 - 1e-4 * t)) {
          accepted = true; err = e2; energy += de; break;
        }
      }
      t *= 0.5;
    }
    if(st.status == Flow_status::FLIP_LIMIT_REACHED) {
      eng.u = u_old; eng.compute_lengths(); eng.compute_angles(); eng.compute_curvature(); g = g_old; err = err_old;
      break;
    }
    if(!accepted) {
      eng.u = u_old; double e2 = 0; evaluate(e2); err = e2;
      st.status = Flow_status::LINE_SEARCH_FAILED; break;
    }
    ++st.iterations;
    // stagnation is only declared in the rounding regime (far from the solution Newton may need several
    // iterations before the max error drops)
    if(err < 0.5 * best_err) { best_err = err; iterations_without_progress = 0; }
    else if(best_err < 1e-6) ++iterations_without_progress;
    st.error_history.push_back(err);
    st.energy_history.push_back(energy);
    Flow_progress pr; pr.iteration = st.iterations; pr.max_curvature_error = err; pr.step_length = t;
    pr.number_of_flips = eng.flips;
    if(verbose)
      std::cerr << "Ricci flow: iteration " << st.iterations << "  max |K - target| = " << err
                << "  step = " << t << "  flips = " << eng.flips << std::endl;
    if(!internal::call_progress_any(callback, pr)) {
      st.status = err < accuracy ? Flow_status::CONVERGED : Flow_status::CANCELLED; break;
    }
  }
  st.max_curvature_error = err;
  st.number_of_flips = eng.flips;

  // ---- results
  res.geo_ = geo;
  res.u_ = eng.u;
  res.target_ = target_k;
  res.lengths_ = m.template add_property_map<E, double>("e:length", 0.0).first;
  for(E e : m.edges()) {
    // only a non-finite initial state can get here (steps with non-finite values are never accepted)
    if(!std::isfinite(eng.len[e]))
      throw Ricci_flow_error("numerical failure: the initial state of the scheme has non-finite edge lengths");
    res.lengths_[e] = eng.len[e];
  }
  // the user's mesh: lengths of the input connectivity under the final conformal factors
  res.input_valid_ = true;
  // Penner coordinates (at u = 0) of the input connectivity: the input half-lengths, or, after geometric initial
  // flips, the Ptolemy images of the Delaunay triangulation's half-lengths flipped back in reverse order
  std::vector<double> penner0(m.number_of_edges());
  for(const auto& ec : edge_corr) penner0[ec.second] = 0.5 * input_len[ec.second];
  if(!initial_flips.empty()) {
    internal::Flow_engine<Point_3> back(mesh_after_initial_flips, Background_geometry::EUCLIDEAN, Scheme::VERTEX_SCALING, true);
    back.edge_data = lambda_after_initial_flips;
    back.compute_lengths();
    back.compute_angles();
    for(auto it = initial_flips.rbegin(); it != initial_flips.rend(); ++it) back.flip(*it);
    for(const auto& ec : edge_corr) penner0[ec.second] = back.edge_data[ec.second];
  }
  {
    for(const auto& ec : edge_corr) {
      const tm_halfedge h = halfedge(ec.first, tm);
      const std::size_t a = std::size_t(vmap[get(vim, source(h, tm))]), b = std::size_t(vmap[get(vim, target(h, tm))]);
      double l;
      if(scheme == Scheme::VERTEX_SCALING)
        l = internal::length_from_lambda(geo, std::exp(0.5 * (eng.u[a] + eng.u[b])) * penner0[ec.second]);
      else
        l = eng.len[ec.second]; // no flips for the circle packings: same connectivity
      put(edge_length_out, ec.first, l);
    }
    if(eng.flips > 0 || !initial_flips.empty()) {
      // check the triangle inequalities of the input faces with the written lengths
      for(tm_face f : faces(tm)) {
        double l[3] = {0, 0, 0}; int i = 0;
        for(tm_halfedge h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
          if(i >= 3) break;
          l[i++] = CGAL::to_double(get(edge_length_out, edge(h, tm)));
        }
        for(int k = 0; k < 3; ++k)
          if(!(l[k] < l[(k + 1) % 3] + l[(k + 2) % 3])) res.input_valid_ = false;
      }
    }
  }
  st.time_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  if(verbose)
    std::cerr << "Ricci flow: " << to_string(st.status) << " after " << st.iterations << " iterations, max error "
              << st.max_curvature_error << ", " << st.number_of_flips << " flips, " << st.time_seconds << " s" << std::endl;
  return res;
}

/*!
  \ingroup PkgDiscreteRicciFlowRef
  Hyperbolic uniformization of a closed surface of genus g >= 2: the metric of curvature -1 (target K_i = 0
  at every vertex, background H^2) discretely conformal (vertex scaling, with Ptolemy flips) to the input.
  Its total area is 4 pi (g - 1). Named parameters as `compute_metric()`; the edge lengths of the input
  connectivity are not written (use `compute_metric()` for that).
  \throws Ricci_flow_error if the mesh is open, has several components, genus < 2, or is otherwise invalid.
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto hyperbolic_uniformization(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_triangle_mesh(tm);
  if(!CGAL::is_closed(tm)) throw Ricci_flow_error("hyperbolic uniformization needs a closed surface");
  const long chi = long(vertices(tm).size()) - long(edges(tm).size()) + long(faces(tm).size());
  if(chi >= 0 && chi % 2 == 0 && (2 - chi) / 2 < 2)
    throw Ricci_flow_error("hyperbolic uniformization needs genus >= 2 (this surface has genus " +
                           std::to_string((2 - chi) / 2) + ")");
  if(internal::get_background(np, Background_geometry::HYPERBOLIC) != Background_geometry::HYPERBOLIC)
    throw Ricci_flow_error("hyperbolic uniformization uses the hyperbolic background");
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor tm_edge;
  return compute_metric(tm, CGAL::Constant_property_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>(0.0),
                        CGAL::Constant_property_map<tm_edge, double>(0.0),
                        parameters::background_geometry(Background_geometry::HYPERBOLIC, np));
}

/*!
  \ingroup PkgDiscreteRicciFlowRef
  The flat metric (K_i = 0, background E^2) of a closed surface of genus 1, discretely conformal to the input.
  \throws Ricci_flow_error unless the mesh is a closed torus.
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto flat_metric(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_triangle_mesh(tm);
  if(!CGAL::is_closed(tm)) throw Ricci_flow_error("the flat torus metric needs a closed surface");
  const long chi = long(vertices(tm).size()) - long(edges(tm).size()) + long(faces(tm).size());
  if(chi != 0) throw Ricci_flow_error("the flat torus metric needs genus 1 (Euler characteristic " + std::to_string(chi) + ")");
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor tm_edge;
  return compute_metric(tm, CGAL::Constant_property_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>(0.0),
                        CGAL::Constant_property_map<tm_edge, double>(0.0),
                        parameters::background_geometry(Background_geometry::EUCLIDEAN, np));
}

} // namespace Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_COMPUTE_METRIC_H
