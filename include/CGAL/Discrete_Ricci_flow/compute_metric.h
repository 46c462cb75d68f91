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
#include <CGAL/Discrete_Ricci_flow/internal/newton.h>
#include <CGAL/Hyperbolic_surface_2/Hyperbolic_surface_triangulation.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {

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
template <class Point_3> class Discrete_metric;
namespace internal { struct Metric_access; }

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
    geo_ = o.geo_; scheme_ = o.scheme_; u_ = o.u_; stats_ = o.stats_; target_ = o.target_; genus_ = o.genus_;
    input_valid_ = o.input_valid_;
    initial_flips_ = o.initial_flips_; flips_ = o.flips_;
    return *this;
  }

  /// the intrinsic triangulation (see the class description)
  const Mesh& intrinsic_mesh() const { return mesh_; }
  /// its edge lengths (property `"e:length"` of `intrinsic_mesh()`)
  Edge_length_map edge_length_map() const { return lengths_; }
  double length(Edge_index e) const { return lengths_[e]; }
  double length(Halfedge_index h) const { return lengths_[mesh_.edge(h)]; }
  Background_geometry background_geometry() const { return geo_; }
  /// the scheme that relates the lengths to the conformal factors (`scheme()` named parameter of
  /// `compute_metric()`; `Scheme::VERTEX_SCALING` for the uniformization entry points)
  Scheme scheme() const { return scheme_; }
  /// u_i, indexed like the vertices of the input
  const std::vector<double>& conformal_factors() const { return u_; }
  /// the target curvatures used (K for interior vertices, geodesic curvature for border vertices)
  const std::vector<double>& target_curvatures() const { return target_; }
  const Flow_statistics& statistics() const { return stats_; }
  bool converged() const { return stats_.converged(); }
  long genus() const { return genus_; }
  /// true if the Penner lengths on the input connectivity satisfy all triangle inequalities
  bool input_connectivity_is_valid() const { return input_valid_; }
  /*!
    The flips that turned the input connectivity into `intrinsic_mesh()`, in order: first the metric-preserving
    (Euclidean) Delaunay flips of the input (`initial_flips()`, see `parameters::geometric_initial_flips()`),
    then the Ptolemy flips of the flow (`flips()`, `statistics().number_of_flips` of them). Each is an edge of
    `intrinsic_mesh()`; replaying them with `internal::flip_connectivity()` on the input connectivity (vertex
    `i` = the `i`-th vertex, faces in `faces(tm)` order) reproduces every intermediate triangulation with the
    same indices. A geometric flip keeps the piecewise-linear Euclidean metric of the input; a Ptolemy flip of
    edge (a b) between faces (a b c), (b a d) gives the new edge the Penner coordinate
    lambda_cd = (lambda_ca lambda_db + lambda_ad lambda_bc) / lambda_ab (at u = 0, lambda = half the input
    length) and keeps the decorated ideal hyperbolic surface (Gillespie-Springborn-Crane 2021). Set by
    `compute_metric()` (and so by `hyperbolic_uniformization()`, `flat_metric()`); empty otherwise.
  */
  const std::vector<Edge_index>& initial_flips() const { return initial_flips_; }
  /// the Ptolemy flips of the flow, in order (see `initial_flips()`)
  const std::vector<Edge_index>& flips() const { return flips_; }

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

  /*!
    The metric as the shared surface layer's `CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation`
    on `intrinsic_mesh()` with `edge_length_map()` (hyperbolic background, closed surface of genus >= 2):
    charts, transitions, developments, the input of `Surface_shortest_words` and of the embedding. The
    surface refers to this metric's mesh: the metric must outlive it. Named parameters as the layer's
    constructor (`angle_tolerance`, `require_smooth_metric`).
    \throws CGAL::Invalid_mesh_error, CGAL::Invalid_metric_error as the layer's constructor.
  */
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<Mesh, Edge_length_map>
  hyperbolic_surface(const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    if(geo_ != Background_geometry::HYPERBOLIC)
      internal::throw_metric_error("hyperbolic_surface(): the metric has no hyperbolic background");
    return CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<Mesh, Edge_length_map>(mesh_, lengths_, np);
  }

private:
  friend struct internal::Metric_access;
  Mesh mesh_;
  Edge_length_map lengths_;
  Background_geometry geo_ = Background_geometry::HYPERBOLIC;
  Scheme scheme_ = Scheme::VERTEX_SCALING;
  std::vector<double> u_, target_;
  Flow_statistics stats_;
  long genus_ = 0;
  bool input_valid_ = true;
  std::vector<Edge_index> initial_flips_, flips_;
};

namespace internal {

/// write access to a `Discrete_metric` for the functions that build it
struct Metric_access
{
  template <class P> static typename Discrete_metric<P>::Mesh& mesh(Discrete_metric<P>& m) { return m.mesh_; }
  template <class P> static Flow_statistics& statistics(Discrete_metric<P>& m) { return m.stats_; }
  template <class P>
  static void set(Discrete_metric<P>& m, Background_geometry geo, const std::vector<double>& u,
                  const std::vector<double>& target, long genus, bool input_valid,
                  Scheme scheme = Scheme::VERTEX_SCALING)
  {
    m.geo_ = geo; m.scheme_ = scheme; m.u_ = u; m.target_ = target; m.genus_ = genus; m.input_valid_ = input_valid;
  }
  template <class P>
  static void set_flips(Discrete_metric<P>& m, const std::vector<typename Discrete_metric<P>::Edge_index>& initial,
                        const std::vector<typename Discrete_metric<P>::Edge_index>& flow)
  {
    m.initial_flips_ = initial; m.flips_ = flow;
  }
  /// creates the length property (all zero) and returns it
  template <class P>
  static typename Discrete_metric<P>::Edge_length_map& add_lengths(Discrete_metric<P>& m)
  {
    m.lengths_ = m.mesh_.template add_property_map<typename Discrete_metric<P>::Edge_index, double>("e:length", 0.0).first;
    return m.lengths_;
  }
};

} // namespace internal

namespace internal {

template <class NP>
Background_geometry get_background(const NP& np, Background_geometry def)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::ricci_background_geometry_t_v), def);
}

// the optional callback: a callable taking const Flow_progress& and returning bool (false cancels) or void
template <class Callback>
bool call_progress(const Callback& cb, const Flow_progress& p, std::true_type) { return cb(p); }
template <class Callback>
bool call_progress(const Callback& cb, const Flow_progress& p, std::false_type) { cb(p); return true; }
template <class Callback>
std::function<bool(const Flow_progress&)> make_progress(const Callback& cb)
{
  if constexpr(std::is_same<Callback, CGAL::internal_np::Param_not_found>::value) return {};
  else {
    return [cb](const Flow_progress& p) {
      typedef decltype(cb(p)) R;
      return call_progress(cb, p, std::integral_constant<bool, std::is_convertible<R, bool>::value>());
    };
  }
}

/// the Newton options from the named parameters. Default accuracy: 1e-11 for the status CONVERGED, then
/// Newton steps while the error at least halves (the rounding level); an explicit `accuracy` disables that.
template <class NP>
Newton_options newton_options(const NP& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  Newton_options o;
  o.max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 100);
  o.accuracy = choose_parameter(get_parameter(np, CGAL::internal_np::accuracy), 1e-11);
  o.polish = is_default_parameter<NP, CGAL::internal_np::accuracy_t>::value;
  o.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  o.solver = choose_parameter(get_parameter(np, CGAL::internal_np::ricci_sparse_solver_t_v), Sparse_solver::DEFAULT);
  o.callback = make_progress(get_parameter(np, CGAL::internal_np::callback));
  o.reuse_factorization = choose_parameter(get_parameter(np, CGAL::internal_np::ricci_reuse_factorization_t_v), true);
  if(!(o.accuracy > 0) || !std::isfinite(o.accuracy)) throw_option_error("accuracy must be positive and finite");
  if(o.max_iterations < 0) throw_option_error("number_of_iterations must be non-negative");
  return o;
}

/// the input's connectivity copied into `m` (vertex i of m = the vertex of index i of tm); vmap[i] = that vertex
template <class TriangleMesh, class VPM, class VIM, class Mesh>
void copy_connectivity(const TriangleMesh& tm, VPM vpm, VIM vim, Mesh& m, std::vector<typename Mesh::Vertex_index>& vmap)
{
  typedef typename Mesh::Vertex_index V;
  const std::size_t nv = vertices(tm).size();
  vmap.assign(nv, V());
  std::vector<char> used(nv, 0);
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> by_index(nv);
  for(auto v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    if(i >= nv || used[i]) throw_option_error("invalid vertex index map (not one to one onto 0 .. n-1)");
    used[i] = 1; by_index[i] = v;
  }
  m.reserve(typename Mesh::size_type(nv), typename Mesh::size_type(edges(tm).size()), typename Mesh::size_type(faces(tm).size()));
  for(std::size_t i = 0; i < nv; ++i) vmap[i] = m.add_vertex(get(vpm, by_index[i]));
  std::vector<V> fv;
  for(auto f : faces(tm)) {
    fv.clear();
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) fv.push_back(vmap[get(vim, v)]);
    if(m.add_face(fv) == Mesh::null_face()) throw_mesh_error("the mesh is not an oriented 2-manifold");
  }
}

/// the input length of edge e of tm (from `elm`, or Euclidean from `vpm`), checked
template <class TriangleMesh, class VPM, class ELM>
double input_edge_length(const TriangleMesh& tm, VPM vpm, const ELM& elm,
                         typename boost::graph_traits<TriangleMesh>::edge_descriptor e)
{
  double l;
  if constexpr(std::is_same<ELM, CGAL::internal_np::Param_not_found>::value) {
    const auto h = halfedge(e, tm);
    l = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
  } else
    l = CGAL::to_double(get(elm, e));
  if(!(l > 0) || !std::isfinite(l)) throw_metric_error("an edge has zero, negative or non-finite length");
  return l;
}

/// the edge of m joining the images of the ends of the edge of tm with halfedge h (null if there is none)
template <class TriangleMesh, class VIM, class Mesh>
typename Mesh::Edge_index corresponding_edge(const TriangleMesh& tm, VIM vim, const Mesh& m,
                                             const std::vector<typename Mesh::Vertex_index>& vmap,
                                             typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  const auto mh = m.halfedge(vmap[get(vim, source(h, tm))], vmap[get(vim, target(h, tm))]);
  return mh == Mesh::null_halfedge() ? typename Mesh::Edge_index() : m.edge(mh);
}

/// the input lengths on the edges of m (a copy of tm's connectivity), see `input_edge_length()`
template <class TriangleMesh, class VPM, class VIM, class ELM, class Mesh>
std::vector<double> input_lengths(const TriangleMesh& tm, VPM vpm, VIM vim, const ELM& elm, const Mesh& m,
                                  const std::vector<typename Mesh::Vertex_index>& vmap)
{
  std::vector<double> len(m.number_of_edges(), -1.0);
  for(auto e : edges(tm)) {
    const auto me = corresponding_edge(tm, vim, m, vmap, halfedge(e, tm));
    if(me == typename Mesh::Edge_index()) throw_mesh_error("inconsistent mesh connectivity");
    len[me] = input_edge_length(tm, vpm, elm, e);
  }
  return len;
}

/// divides the lengths by a power of two within a factor 4 of their mean (computed without overflow; exact,
/// so that the flow of a mesh scaled by 2^k is the same computation) and returns that power
inline double normalize_lengths(std::vector<double>& len)
{
  double mx = 0;
  for(double l : len) mx = (std::max)(mx, l);
  double mean = 0;
  for(double l : len) mean += l / mx;
  const double unit = std::ldexp(1.0, std::ilogb(mx) + std::ilogb(mean / double(len.size())));
  for(double& l : len) l /= unit;
  return unit;
}

/// the first face of m that is degenerate for the Euclidean lengths `len` (relative tolerance 1e-12), or
/// null; `area` receives the total Euclidean area; `unit`: the input's unit of `len` (for the message)
template <class Mesh>
typename Mesh::Face_index degenerate_face(const Mesh& m, const std::vector<double>& len, double& area, std::string& msg,
                                          double unit = 1.0)
{
  area = 0;
  typename Mesh::Face_index bad = Mesh::null_face();
  for(auto f : m.faces()) {
    const auto h = m.halfedge(f);
    const double l[3] = {len[m.edge(h)], len[m.edge(m.next(h))], len[m.edge(m.prev(h))]};
    const double s = 0.5 * (l[0] + l[1] + l[2]);
    for(int i = 0; i < 3; ++i)
      if(bad == Mesh::null_face() && !(l[i] < l[(i + 1) % 3] + l[(i + 2) % 3] - 1e-12 * s)) {
        std::ostringstream os;
        os << "degenerate face " << std::size_t(f) << " (edge lengths " << unit * l[0] << ", " << unit * l[1]
           << ", " << unit * l[2] << ")";
        msg = os.str(); bad = f;
      }
    area += triangle_area(Background_geometry::EUCLIDEAN, l, nullptr);
  }
  return bad;
}

/// checks the target curvatures against Gauss-Bonnet; returns the area they imply (H^2, S^2)
inline double check_gauss_bonnet(Background_geometry geo, const std::vector<double>& target, long chi)
{
  double sum = 0;
  for(double k : target) {
    if(!std::isfinite(k)) throw_input_error("non-finite target curvature");
    sum += k;
  }
  const double two_pi_chi = 2 * CGAL_PI * double(chi);
  const double tol = 1e-9 * (2 * CGAL_PI + std::abs(two_pi_chi));
  std::ostringstream os;
  os.precision(12);
  os << "target curvatures violate Gauss-Bonnet: sum = " << sum << ", 2 pi chi = " << two_pi_chi << " (chi = " << chi << ")";
  if(geo == Background_geometry::EUCLIDEAN && std::abs(sum - two_pi_chi) > tol) throw_input_error(os.str() + "; E^2 needs sum = 2 pi chi");
  if(geo == Background_geometry::HYPERBOLIC && !(sum - two_pi_chi > tol)) throw_input_error(os.str() + "; H^2 needs sum > 2 pi chi");
  if(geo == Background_geometry::SPHERICAL && !(two_pi_chi - sum > tol)) throw_input_error(os.str() + "; S^2 needs sum < 2 pi chi");
  return std::abs(sum - two_pi_chi);
}

/// the record of the metric-preserving (geometric) Delaunay flips of the input, to map lengths back to it
template <class Point_3>
struct Initial_flips
{
  std::vector<typename CGAL::Surface_mesh<Point_3>::Edge_index> flips;
  CGAL::Surface_mesh<Point_3> mesh_after;
  std::vector<double> lambda_after;
};

/// makes m intrinsically Delaunay for the Euclidean lengths `len` by geometric flips (the PL metric is kept;
/// degenerate faces disappear); `len` receives the lengths of the flipped triangulation
template <class Point_3>
Initial_flips<Point_3> geometric_delaunay_flips(CGAL::Surface_mesh<Point_3>& m, std::vector<double>& len)
{
  Initial_flips<Point_3> r;
  Flow_engine<Point_3> eng(m, Background_geometry::EUCLIDEAN, Scheme::VERTEX_SCALING, true);
  eng.geometric_flips = true;
  for(auto e : m.edges()) eng.edge_data[e] = 0.5 * len[e];
  eng.compute_lengths();
  eng.compute_angles();
  if(!eng.make_delaunay()) throw_numerical_error("the geometric Delaunay flips of the input did not terminate");
  for(auto e : m.edges()) len[e] = eng.length(e);
  r.flips = eng.flip_log;
  if(!r.flips.empty()) { r.mesh_after = m; r.lambda_after = eng.edge_data; }
  return r;
}

/// the initial state of the engine: vertex scaling from the input lengths at a uniform scale, or the radii and
/// inversive distances of the circle packings from the tangent lengths of the input corners
template <class Point_3>
void initial_state(Flow_engine<Point_3>& eng, const std::vector<double>& len, double scale)
{
  const auto& m = eng.m;
  const Background_geometry geo = eng.geo;
  if(eng.scheme == Scheme::VERTEX_SCALING) {
    for(auto e : m.edges()) eng.edge_data[e] = 0.5 * len[e];
    std::fill(eng.u.begin(), eng.u.end(), std::log(scale));
    return;
  }
  const std::size_t nv = m.number_of_vertices();
  std::vector<double> rsum(nv, 0.0), rcount(nv, 0.0);
  for(auto f : m.faces()) {
    const auto h = m.halfedge(f);
    const typename CGAL::Surface_mesh<Point_3>::Halfedge_index hs[3] = {h, m.next(h), m.prev(h)};
    for(int i = 0; i < 3; ++i) { // corner at source(hs[i]) between hs[i] and hs[i-1]
      const double a = len[m.edge(hs[i])], b = len[m.edge(hs[(i + 2) % 3])], c = len[m.edge(hs[(i + 1) % 3])];
      rsum[m.source(hs[i])] += 0.5 * (a + b - c);
      rcount[m.source(hs[i])] += 1;
    }
  }
  std::vector<double> r(nv);
  for(std::size_t i = 0; i < nv; ++i) r[i] = rsum[i] / rcount[i];
  for(auto e : m.edges()) {
    const std::size_t a = m.vertex(e, 0), b = m.vertex(e, 1);
    double I = (len[e] * len[e] - r[a] * r[a] - r[b] * r[b]) / (2 * r[a] * r[b]);
    if(eng.scheme == Scheme::TANGENTIAL_CIRCLE_PACKING) I = 1;
    if(eng.scheme == Scheme::THURSTON_CIRCLE_PACKING) I = I < 0 ? 0 : (I > 1 ? 1 : I);
    eng.edge_data[e] = I;
  }
  for(std::size_t i = 0; i < nv; ++i) eng.u[i] = u_from_radius(geo, scale * r[i]);
}

/// the lengths of the input connectivity under the final conformal factors, written to the user's map;
/// returns whether they satisfy every triangle inequality of the input faces. The input lengths are read
/// again from tm (`input_edge_length()`, divided by the flow's `unit`: the same values as at the start), so
/// that the flow does not hold them.
template <class TriangleMesh, class VPM, class VIM, class ELM, class OutMap, class Point_3>
bool write_input_lengths(const TriangleMesh& tm, VPM vpm, VIM vim, const ELM& elm, OutMap out,
                         const Flow_engine<Point_3>& eng, const std::vector<typename CGAL::Surface_mesh<Point_3>::Vertex_index>& vmap,
                         const Initial_flips<Point_3>& init, double unit, double out_scale)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  // Penner coordinates (at u = 0) of the input connectivity: the input half-lengths, or, after geometric initial
  // flips, the Ptolemy images of the Delaunay triangulation's half-lengths flipped back in reverse order (on a
  // copy of the flipped mesh, which is then the input connectivity again)
  std::unique_ptr<Mesh> copy;
  std::unique_ptr<Flow_engine<Point_3> > back;
  if(!init.flips.empty()) {
    copy.reset(new Mesh(init.mesh_after));
    back.reset(new Flow_engine<Point_3>(*copy, Background_geometry::EUCLIDEAN, Scheme::VERTEX_SCALING, true));
    back->edge_data = init.lambda_after;
    back->compute_lengths();
    back->compute_angles();
    for(auto it = init.flips.rbegin(); it != init.flips.rend(); ++it) back->flip(*it);
  }
  // the lengths are kept here (CGAL's dynamic edge property of tm: an array for Surface_mesh) and checked from
  // here: `out` may be write-only (the uniformization functions pass a constant map, which reads back 0)
  auto written = get(CGAL::dynamic_edge_property_t<double>(), tm);
  for(auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    const std::size_t a = get(vim, source(h, tm)), b = get(vim, target(h, tm));
    auto edge_in = [&](const Mesh& mm) { // (mm has the input's connectivity)
      const auto me = corresponding_edge(tm, vim, mm, vmap, h);
      if(me == typename Mesh::Edge_index()) throw_mesh_error("inconsistent mesh connectivity");
      return me;
    };
    double l;
    if(eng.scheme == Scheme::VERTEX_SCALING) {
      const double penner0 = back ? back->edge_data[edge_in(*copy)] : 0.5 * (input_edge_length(tm, vpm, elm, e) / unit);
      l = length_from_lambda(eng.geo, std::exp(0.5 * (eng.u[a] + eng.u[b])) * penner0);
    } else
      l = eng.length(edge_in(eng.m)); // no flips for the circle packings: same connectivity
    put(out, e, out_scale * l);
    put(written, e, l); // (checked in the flow's unit)
  }
  // checked even without flips: a flow that ends with degenerate triangles (status DEGENERATE_TRIANGLES, e.g.
  // with do_flip(false)) leaves lengths on the input connectivity that violate a triangle inequality
  for(auto f : faces(tm)) {
    double l[3] = {0, 0, 0}; int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) { if(i >= 3) break; l[i++] = get(written, edge(h, tm)); }
    for(int k = 0; k < 3; ++k) if(!(l[k] < l[(k + 1) % 3] + l[(k + 2) % 3])) return false;
  }
  return true;
}

/// `compute_metric()` on a mesh that `check_triangle_mesh()` (with the vertex index map of `np`) has accepted,
/// of topology `topo` (the uniformization functions check the mesh once, with their own messages); the
/// statistics' time counts from `t_start` (before the checks)
template <class TriangleMesh, class VertexTargetMap, class EdgeLengthOutMap, class NamedParameters>
Discrete_metric<typename boost::property_traits<
  typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>::value_type>
compute_metric_checked(const TriangleMesh& tm, const Mesh_topology& topo, VertexTargetMap target_curvature,
                       EdgeLengthOutMap edge_length_out, const NamedParameters& np,
                       std::chrono::steady_clock::time_point t_start)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef Discrete_metric<Point_3> Result;
  typedef typename Result::Mesh Mesh;

  VPM vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const Background_geometry geo = internal::get_background(np, Background_geometry::HYPERBOLIC);
  const Scheme scheme = choose_parameter(get_parameter(np, CGAL::internal_np::ricci_scheme_t_v), Scheme::VERTEX_SCALING);
  const bool do_flip = choose_parameter(get_parameter(np, internal_np::do_flip), true);
  const internal::Newton_options options = internal::newton_options(np);

  Result res;
  Mesh& m = internal::Metric_access::mesh(res);
  std::vector<typename Mesh::Vertex_index> vmap;
  internal::copy_connectivity(tm, vpm, vim, m, vmap);
  const auto elm = get_parameter(np, CGAL::internal_np::ricci_edge_length_map_t_v);
  std::vector<double> input_len = internal::input_lengths(tm, vpm, vim, elm, m, vmap);
  // the flow is invariant under a uniform scale of the input: it runs on lengths of mean about 1 (a mesh in
  // units of 1e80 or 1e-80 has areas and Heron products out of the range of double), and the conformal
  // factors are converted back to the input's lengths at the end
  const double unit = internal::normalize_lengths(input_len);
  std::vector<double> target_k(vmap.size());
  for(auto v : vertices(tm)) target_k[get(vim, v)] = CGAL::to_double(get(target_curvature, v));
  const double target_area = internal::check_gauss_bonnet(geo, target_k, topo.euler_characteristic);

  // a degenerate (zero-area) face: the geometric Delaunay flips of the input remove it without changing the
  // metric (vertex scaling only)
  double input_area = 0;
  std::string degenerate_msg;
  const bool degenerate = internal::degenerate_face(m, input_len, input_area, degenerate_msg, unit) != Mesh::null_face();
  if(degenerate && scheme != Scheme::VERTEX_SCALING)
    internal::throw_metric_error(degenerate_msg + "; only the vertex-scaling scheme can flip it away");
  internal::Initial_flips<Point_3> init;
  if(scheme == Scheme::VERTEX_SCALING &&
     (degenerate || choose_parameter(get_parameter(np, CGAL::internal_np::ricci_geometric_initial_flips_t_v), false))) {
    init = internal::geometric_delaunay_flips(m, input_len);
    internal::Metric_access::statistics(res).number_of_initial_flips = init.flips.size();
    if(internal::degenerate_face(m, input_len, input_area, degenerate_msg, unit) != Mesh::null_face())
      internal::throw_metric_error(degenerate_msg + " after the intrinsic Delaunay flips of the input");
  }

  // initial state: a uniform scale making the triangles' total area about the target area, then Newton
  internal::Flow_engine<Point_3> eng(m, geo, scheme, do_flip);
  eng.target = std::move(target_k); // (read back from the engine below: one copy)
  internal::initial_state(eng, input_len, geo == Background_geometry::EUCLIDEAN ? 1.0 : std::sqrt(target_area / input_area));
  std::vector<double>().swap(input_len); // (not held during the flow: read again from tm at the end)
  internal::Newton_options o = options;
  if(geo == Background_geometry::EUCLIDEAN) { // u is defined up to a constant: pin u_0
    o.fixed.assign(vmap.size(), 0); o.fixed[0] = 1; o.fixed_in_error = true;
  }
  Flow_statistics& st = internal::Metric_access::statistics(res);
  internal::Newton_solver<Point_3>(eng, o, st).run();

  auto& lengths = internal::Metric_access::add_lengths(res);
  // only an unusable initial state can get here (the line search accepts no state with a zero or non-finite
  // length): the metric would not be the last accepted iterate
  if(!eng.lengths_are_usable())
    internal::throw_numerical_error("the initial state of the scheme has zero, non-finite or overflowing edge "
                                    "lengths (input edge lengths too far apart for double arithmetic)");
  // back to the input's unit: E^2 lengths scale with it (the flow ran with u of order 1: u of order
  // log(1e80) would lose two digits of the curvature), H^2 and S^2 lengths are absolute; the conformal factors
  // are relative to the input lengths for vertex scaling (lambda = e^{(u_i+u_j)/2} l_ij / 2) and
  // log(radius) (E^2) or absolute (H^2, S^2) for the circle packings
  const bool euclidean = geo == Background_geometry::EUCLIDEAN;
  const double out_scale = euclidean ? unit : 1.0;
  for(auto e : m.edges()) lengths[e] = out_scale * eng.length(e);
  const bool valid = internal::write_input_lengths(tm, vpm, vim, elm, edge_length_out, eng, vmap, init, unit, out_scale);
  std::vector<double> u = eng.u;
  const double du = scheme == Scheme::VERTEX_SCALING ? (euclidean ? 0.0 : -std::log(unit)) : (euclidean ? std::log(unit) : 0.0);
  for(double& x : u) x += du;
  internal::Metric_access::set(res, geo, u, eng.target, topo.genus, valid, scheme);
  internal::Metric_access::set_flips(res, init.flips, eng.flip_log);
  st.time_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  if(options.verbose)
    std::cerr << "Ricci flow: " << to_string(st.status) << " after " << st.iterations << " iterations, max error "
              << st.max_curvature_error << ", " << st.number_of_flips << " flips, " << st.time_seconds << " s" << std::endl;
  return res;
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
    - `accuracy(eps)`: stop when max |K_i - target_i| < eps (radians). Default: the status is CONVERGED once
      the error is below 1e-11, and Newton then continues while each step at least halves the error (at
      most 4 more steps): the flow ends at the rounding level of double arithmetic (about 1e-14 on the demo
      meshes), which the embedding's relator needs. With an explicit accuracy the flow stops at it.
    - `do_flip(b)`: keep the triangulation intrinsically Delaunay with Ptolemy flips (default true; vertex
      scaling only),
    - `geometric_initial_flips(b)`: first make the input intrinsically Delaunay by metric-preserving flips
      (default false; see `parameters::geometric_initial_flips()`; automatic when the input has a degenerate,
      zero-area face: such faces are removed by these flips without changing the metric),
    - `sparse_solver(s)`: see `Sparse_solver` (default CHOLMOD when available),
    - `reuse_factorization(b)`: inexact Newton with an earlier factorization as preconditioner (default true,
      see below; the convergence test and the polishing are the same),
    - `verbose(b)`: one line per iteration on `std::cerr`,
    - `callback(f)`: `f(const Flow_progress&)` after each iteration; return `false` to stop (status CANCELLED).
  \returns the result (status, statistics, intrinsic triangulation, conformal factors).
  \throws CGAL::Invalid_mesh_error, CGAL::Invalid_metric_error, CGAL::Invalid_option_error,
          CGAL::Invalid_input_error on invalid input (see `Ricci_flow_error`). Non-convergence is not an
          exception: the status says it, the metric is the last accepted iterate (finite lengths).

  Cost: the Hessian (its lower triangle) is assembled in place into a sparsity pattern that is rebuilt only
  when flips change the connectivity. The Newton systems are solved by inexact Newton: conjugate gradients
  preconditioned by the sparse Cholesky factorization of an earlier Newton step (CHOLMOD supernodal or Eigen's
  `SimplicialLDLT`) to the relative residual min(0.1, max(error, 1e-8)), which keeps the convergence
  quadratic; a new factorization (symbolic analysis reused, both solvers keeping their first fill-reducing ordering)
  only when they do not converge within a budget of a fraction of a factorization's cost, or when the line
  search rejects their direction. `reuse_factorization(false)` factorizes at every step. On the demo meshes 3
  to 10 Newton iterations with 2 to 4 factorizations; O(F) per iteration for the rest.
*/
template <class TriangleMesh, class VertexTargetMap, class EdgeLengthOutMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Discrete_metric<typename boost::property_traits<
  typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>::value_type>
compute_metric(const TriangleMesh& tm, VertexTargetMap target_curvature, EdgeLengthOutMap edge_length_out,
               const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto t_start = std::chrono::steady_clock::now();
  const internal::Mesh_topology topo = internal::check_triangle_mesh(tm, CGAL::get_initialized_vertex_index_map(tm, np));
  return internal::compute_metric_checked(tm, topo, target_curvature, edge_length_out, np, t_start);
}

/*!
  \ingroup PkgDiscreteRicciFlowRef
  Hyperbolic uniformization of a closed surface of genus g >= 2: the metric of curvature -1 (target K_i = 0
  at every vertex, background H^2) discretely conformal (vertex scaling, with Ptolemy flips) to the input.
  Its total area is 4 pi (g - 1). Named parameters as `compute_metric()`; the edge lengths of the input
  connectivity are not written (use `compute_metric()` for that).
  \throws CGAL::Invalid_mesh_error if the mesh has several components (checked first), is open, not
          triangulated, of genus < 2 or otherwise invalid.
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto hyperbolic_uniformization(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto t_start = std::chrono::steady_clock::now();
  const internal::Mesh_topology topo = internal::check_closed_surface(
    tm, CGAL::get_initialized_vertex_index_map(tm, np), "hyperbolic uniformization", "genus >= 2", [](long g) { return g >= 2; });
  if(internal::get_background(np, Background_geometry::HYPERBOLIC) != Background_geometry::HYPERBOLIC)
    internal::throw_option_error("hyperbolic uniformization uses the hyperbolic background");
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor tm_edge;
  return internal::compute_metric_checked(
    tm, topo, CGAL::Constant_property_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>(0.0),
    CGAL::Constant_property_map<tm_edge, double>(0.0), parameters::background_geometry(Background_geometry::HYPERBOLIC, np),
    t_start);
}

/*!
  \ingroup PkgDiscreteRicciFlowRef
  The flat metric (K_i = 0, background E^2) of a closed surface of genus 1, discretely conformal to the input.
  \throws CGAL::Invalid_mesh_error unless the mesh is a closed connected torus (components checked first).
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto flat_metric(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto t_start = std::chrono::steady_clock::now();
  const internal::Mesh_topology topo = internal::check_closed_surface(
    tm, CGAL::get_initialized_vertex_index_map(tm, np), "the flat torus metric", "genus 1", [](long g) { return g == 1; });
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor tm_edge;
  return internal::compute_metric_checked(
    tm, topo, CGAL::Constant_property_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>(0.0),
    CGAL::Constant_property_map<tm_edge, double>(0.0), parameters::background_geometry(Background_geometry::EUCLIDEAN, np),
    t_start);
}

} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_COMPUTE_METRIC_H
