// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Spherical uniformization of closed genus-0 meshes: the Euclidean flow (vertex scaling with Ptolemy flips) on
// the mesh punctured at a vertex p, with the Dirichlet condition that puts p at infinity, the layout of the
// flat disk, the inverse stereographic projection (p goes to the north pole) and the Moebius normalization
// that puts the centre of mass of the vertices at the origin.
#ifndef CGAL_DISCRETE_RICCI_FLOW_SPHERICAL_UNIFORMIZATION_H
#define CGAL_DISCRETE_RICCI_FLOW_SPHERICAL_UNIFORMIZATION_H

#include <CGAL/Discrete_Ricci_flow/compute_metric.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_motions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <exception>
#include <limits>
#include <map>
#include <set>
#include <CGAL/boost/graph/Euler_operations.h>
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {

/*!
  \ingroup PkgDiscreteRicciFlowRef
  The result of `spherical_uniformization()`: the vertices on the unit sphere and the spherical metric.

  `metric()` is a `Discrete_metric` with the spherical background on the *spherical Delaunay triangulation* of
  the points (the convex hull of `sphere_points()`: the flow's intrinsic triangulation of the punctured disk
  plus the triangles at the puncture vertex), with the spherical geodesic lengths 2 asin(|X_i - X_j| / 2) of
  the points before their rounding to double (computed in long double); its
  vertex i is vertex i of the input. Its statistics are those of the Euclidean flow of the punctured disk.
  The map is discretely conformal in the sense of Bobenko-Pinkall-Springborn: the chord lengths of the
  inscribed polyhedron are a vertex scaling of the input lengths (after Ptolemy flips).
*/
template <class Point_3> class Spherical_map;
namespace internal {
template <class Point_3>
Spherical_map<Point_3> spherical_map_with_puncture(const CGAL::Surface_mesh<Point_3>& m0, const std::vector<double>& len,
                                                   std::size_t p, const Newton_options& o);
} // namespace internal

template <class Point_3>
class Spherical_map
{
public:
  typedef Discrete_metric<Point_3> Metric;
  typedef typename Metric::Mesh Mesh;

  /// the spherical metric (see the class description)
  const Metric& metric() const { return metric_; }
  /// the position of input vertex i on the unit sphere
  const std::vector<Point_3>& sphere_points() const { return points_; }
  /// the vertex sent to the north pole before the normalization
  std::size_t puncture_vertex() const { return puncture_; }
  /// true if the flow converged and the result is a valid map: no flipped face of the double-precision points
  /// (`number_of_flipped_faces()`), the centre of mass at the origin (below 1e-10), and the angle sums of
  /// `metric()` are 2 pi within 1e-8 (`max_angle_sum_error()`). A conformal map shrinks the protrusions of a
  /// mesh exponentially: faces far below 1e-8 on the sphere (cow.off: edges of 1e-13) are accurate in
  /// `metric()`, but their double-precision points carry a relative error of about 1e-16 / (edge length).
  /// The flow counts as converged also when it stagnated at its rounding floor (status `STAGNATED`) with
  /// max |K| below 1e-8, the tolerance of the angle sums (dragknob.off: every puncture's flow stagnates at
  /// 1e-10 to 1e-9 or fails; the map of a stagnated flow is valid and conformally consistent to 1e-9).
  bool converged() const
  {
    const Flow_statistics& st = metric_.statistics();
    const bool flow = st.converged() || (st.status == Flow_status::STAGNATED && st.max_curvature_error < 1e-8);
    return flow && flipped_ == 0 && center_norm_ < 1e-10 && max_angle_sum_error_ < 1e-8;
  }
  /// max over the vertices of |2 pi - angle sum| in `metric()`
  double max_angle_sum_error() const { return max_angle_sum_error_; }
  const Flow_statistics& statistics() const { return metric_.statistics(); }
  /// iterations of the Moebius normalization and the norm of the centre of mass it reached
  int normalization_iterations() const { return normalization_iterations_; }
  double center_of_mass_norm() const { return center_norm_; }

  /// the number of faces of `metric().intrinsic_mesh()` whose three points are clockwise seen from outside
  /// the sphere (0 for a map that preserves the orientation)
  std::size_t number_of_flipped_faces() const
  {
    std::size_t n = 0;
    const Mesh& m = metric_.intrinsic_mesh();
    const Point_3 o = CGAL::ORIGIN;
    for(auto f : m.faces()) {
      const auto h = m.halfedge(f);
      const Point_3 &a = points_[m.source(h)], &b = points_[m.target(h)], &c = points_[m.target(m.next(h))];
      // the kernel's orientation predicate (exact with Epick): the double determinant misreads faces of size
      // 1e-9 (bull.off: 210 "flipped" faces, none in fact)
      if(CGAL::orientation(o, a, b, c) != CGAL::POSITIVE) ++n;
    }
    return n;
  }

private:
  template <class TM, class NP> friend Spherical_map<typename boost::property_traits<
    typename CGAL::GetVertexPointMap<TM, NP>::const_type>::value_type> spherical_uniformization(const TM&, const NP&);
  template <class P> friend Spherical_map<P> internal::spherical_map_with_puncture(
    const CGAL::Surface_mesh<P>&, const std::vector<double>&, std::size_t, const internal::Newton_options&);
  Metric metric_;
  std::vector<Point_3> points_;
  std::size_t puncture_ = 0;
  int normalization_iterations_ = 0;
  double center_norm_ = 0;
  std::size_t flipped_ = 0;
  double max_angle_sum_error_ = 0;
};

namespace internal {

// points on the sphere during the normalization, in long double: the boosts expand the small faces of the
// limbs, so their rounding errors are amplified (camel.off: flipped faces of size 1e-5 with double)
typedef std::array<long double, 3> Vec3;

/// the disk: a copy of the sphere triangulation `m` without the star of p (Euler operations, so loops and
/// multi-edges of an intrinsic triangulation are fine); the properties "v:orig" and "e:lambda" follow
template <class Mesh>
Mesh punctured_disk(const Mesh& m, typename Mesh::Vertex_index p)
{
  Mesh disk = m;
  const auto h = disk.halfedge(p); // target(h) == p
  if(h == Mesh::null_halfedge()) throw_mesh_error("spherical uniformization: isolated puncture vertex");
  std::set<typename Mesh::Vertex_index> link;
  std::size_t degree = 0;
  for(auto g : CGAL::halfedges_around_target(p, disk)) {
    ++degree;
    if(disk.source(g) == p || !link.insert(disk.source(g)).second)
      throw_numerical_error("spherical uniformization: the star of the puncture vertex is not a disk");
  }
  if(degree < 3) throw_numerical_error("spherical uniformization: the puncture vertex has degree < 3");
  const auto merged = CGAL::Euler::remove_center_vertex(h, disk);
  CGAL::Euler::make_hole(merged, disk);
  disk.collect_garbage();
  return disk;
}

/// the sphere triangulation: the disk with the star of a new vertex (original index `p_orig`) filling its
/// hole; the edges to it get the Penner coordinates `star` (by the original index of the link vertex)
template <class Mesh>
typename Mesh::Vertex_index close_disk(Mesh& s, std::size_t p_orig, const std::map<std::size_t, double>& star)
{
  auto orig = s.template property_map<typename Mesh::Vertex_index, std::size_t>("v:orig").first;
  auto lam = s.template property_map<typename Mesh::Edge_index, double>("e:lambda").first;
  typename Mesh::Halfedge_index b = Mesh::null_halfedge();
  for(auto h : s.halfedges()) if(s.is_border(h)) { b = h; break; }
  CGAL::Euler::fill_hole(b, s);
  const auto c = s.target(CGAL::Euler::add_center_vertex(b, s));
  orig[c] = p_orig;
  for(auto h : CGAL::halfedges_around_source(c, s)) {
    const auto it = star.find(orig[s.target(h)]);
    if(it == star.end()) throw_numerical_error("spherical uniformization: lost an edge of the puncture vertex");
    lam[s.edge(h)] = it->second;
  }
  return c;
}

/// positions of the disk's vertices in the plane from its flat metric (face by face, Euclidean charts)
template <class Point_3>
std::vector<Cplx> layout_flat_disk(const Flow_engine<Point_3>& eng)
{
  const auto& m = eng.m;
  typedef typename CGAL::Surface_mesh<Point_3>::Face_index F;
  std::vector<Cplx> pos(m.number_of_vertices());
  std::vector<char> placed_f(m.number_of_faces(), 0), placed_v(m.number_of_vertices(), 0);
  std::vector<Motion> place(m.number_of_faces(), Motion::identity(false));
  auto chart = [&](F f) { const auto h = m.halfedge(f); return euclidean_chart(eng.length(m.edge(h)), eng.length(m.edge(m.next(h))), eng.length(m.edge(m.prev(h)))); };
  const F f0 = *m.faces().begin();
  placed_f[f0] = 1;
  std::deque<F> queue(1, f0);
  while(!queue.empty()) {
    const F f = queue.front(); queue.pop_front();
    const auto h0 = m.halfedge(f);
    const auto hs = std::array<typename CGAL::Surface_mesh<Point_3>::Halfedge_index, 3>{h0, m.next(h0), m.prev(h0)};
    const std::array<Cplx, 3> z = chart(f);
    for(int i = 0; i < 3; ++i)
      if(!placed_v[m.source(hs[i])]) { placed_v[m.source(hs[i])] = 1; pos[m.source(hs[i])] = place[f](z[i]); }
    for(int i = 0; i < 3; ++i) {
      const auto o = m.opposite(hs[i]);
      if(m.is_border(o)) continue;
      const F g = m.face(o);
      if(placed_f[g]) continue;
      const std::array<Cplx, 3> zg = chart(g);
      const int io = o == m.halfedge(g) ? 0 : (o == m.next(m.halfedge(g)) ? 1 : 2);
      // the chart of g placed so that its edge o matches the placed edge hs[i] (source(hs[i]) = target(o)): the
      // transition between the two charts (both at the scale of their triangles) composed with the placement
      // of f, not fitted to the placed points: a conformal map can shrink faces below the resolution of the
      // coordinates, where two placed points coincide (triceratops.off stretched 30 times: NaN positions)
      place[g] = place[f] * euclidean_from_pairs(zg[(io + 1) % 3], zg[io], z[i], z[(i + 1) % 3]);
      placed_f[g] = 1;
      queue.push_back(g);
    }
  }
  return pos;
}

/// the Moebius transformation of the unit sphere along the unit axis d with parameter beta in (-1, 1)
/// (a boost of the light cone: points move away from d for beta > 0)
inline Vec3 boost(const Vec3& x, const Vec3& d, long double beta)
{
  const long double z = x[0] * d[0] + x[1] * d[1] + x[2] * d[2];
  const long double den = 1 - beta * z, s = std::sqrt(1 - beta * beta) / den;
  const long double zn = (z - beta) / den;
  Vec3 r;
  for(int k = 0; k < 3; ++k) r[k] = (x[k] - z * d[k]) * s + zn * d[k];
  const long double n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  for(int k = 0; k < 3; ++k) r[k] /= n;
  return r;
}

/// moves the centre of mass of the points to the origin by boosts (Newton steps); returns the iterations,
/// `residual` the final |centre|. A boost b (direction b / |b|, parameter |b|) moves the centre mu by (M - I) b
/// to first order, M the mean of x x^T (the boost's derivative at x is (x.b) x - b): the step solves
/// (I - M) b = mu (I - M is positive semi-definite, singular only when all points lie on one axis; then the
/// scalar step below), damped to |b| <= 0.5. (The scalar step b = mu / rho, rho = mu^T (I - M) mu / |mu|^2,
/// used alone before 2026-12-07, converged linearly, 1% per iteration, when the points form two antipodal
/// clusters: cheese-box.off stretched 30 times along x did not reach 1e-13 in 1000 iterations.)
inline int moebius_normalize(std::vector<Vec3>& x, double& residual)
{
  typedef Eigen::Matrix<long double, 3, 1> V3;
  typedef Eigen::Matrix<long double, 3, 3> M3;
  const int max_iterations = 1000;
  const long double inv_n = 1.0L / (long double)(x.size());
  for(int it = 0; it < max_iterations; ++it) {
    V3 mu = V3::Zero();
    M3 A = M3::Identity(); // I - M
    for(const Vec3& q : x) {
      const V3 p(q[0], q[1], q[2]);
      mu += inv_n * p;
      A -= inv_n * (p * p.transpose());
    }
    const long double norm = mu.norm();
    residual = double(norm);
    if(residual < 1e-13) return it;
    const Eigen::LLT<M3> llt(A);
    V3 b;
    if(llt.info() == Eigen::Success) b = llt.solve(mu);
    if(llt.info() != Eigen::Success || !b.allFinite() || !(b.dot(mu) > 0))
      b = mu / (std::max)(mu.dot(A * mu) / (norm * norm), 1e-3L);
    const long double bn = b.norm();
    const Vec3 d = {b[0] / bn, b[1] / bn, b[2] / bn};
    const long double beta = (std::min)(bn, 0.5L);
    for(Vec3& p : x) p = boost(p, d, beta);
  }
  throw_numerical_error("spherical uniformization: the Moebius normalization did not converge");
}

/// adds the statistics of one round of the disk flow
inline void accumulate(Flow_statistics& st, const Flow_statistics& rs)
{
  st.iterations += rs.iterations; st.polishing_iterations += rs.polishing_iterations;
  st.number_of_factorizations += rs.number_of_factorizations; st.factorization_seconds += rs.factorization_seconds;
  st.number_of_symbolic_factorizations += rs.number_of_symbolic_factorizations;
  st.number_of_orderings += rs.number_of_orderings;
  st.number_of_flips += rs.number_of_flips;
  st.number_of_shifted_factorizations += rs.number_of_shifted_factorizations;
  st.status = rs.status; st.max_curvature_error = rs.max_curvature_error;
  st.error_history.insert(st.error_history.end(), rs.error_history.begin(), rs.error_history.end());
}

/// the edges at p of the sphere `s` (p = `c`) that violate the Delaunay condition at the disk's solution: an
/// edge p-j when the disk's angle sum at j exceeds pi (the boundary polygon is not convex at j), a link edge
/// j-k when its triangle in the disk is degenerate (its apex lies on j-k)
template <class Point_3>
std::vector<typename CGAL::Surface_mesh<Point_3>::Edge_index>
delaunay_violations_at_puncture(const Flow_engine<Point_3>& eng, const CGAL::Surface_mesh<Point_3>& s,
                                typename CGAL::Surface_mesh<Point_3>::Vertex_index c)
{
  const auto& disk = eng.m;
  std::vector<typename CGAL::Surface_mesh<Point_3>::Edge_index> r;
  // s is the disk plus the star of c: the disk's vertices and edges keep their indices in s
  for(auto h : CGAL::halfedges_around_source(c, s)) {
    const auto j = s.target(h);
    double sum = 0;
    for(auto g : CGAL::halfedges_around_target(j, disk)) if(!disk.is_border(g)) sum += eng.angle[disk.prev(g)];
    if(sum > CGAL_PI * (1 + 1e-12)) r.push_back(s.edge(h));
  }
  for(auto h : disk.halfedges())
    if(disk.is_border(h) && eng.angle[disk.opposite(h)] >= CGAL_PI * (1 - 1e-12)) r.push_back(s.edge(h));
  return r;
}

/// The flow of the punctured disk with the Dirichlet condition at the link of p, repeated after Ptolemy flips
/// of the sphere's edges at p where the solution violates the Delaunay condition (at most 30 rounds, each with
/// the Newton iteration bound). `m`
/// (properties "v:orig", "e:lambda": Penner coordinates) is the sphere triangulation, updated; `disk` and
/// `eng` receive the last disk and its flow. Returns the puncture vertex of the final `m`.
template <class Point_3>
typename CGAL::Surface_mesh<Point_3>::Vertex_index
sphere_flow(CGAL::Surface_mesh<Point_3>& m, typename CGAL::Surface_mesh<Point_3>::Vertex_index p,
            const Newton_options& options, CGAL::Surface_mesh<Point_3>& disk,
            std::unique_ptr<Flow_engine<Point_3> >& eng, Flow_statistics& st)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  const int max_rounds = 30;
  // a round's flow gets at most `round_iterations` of the iteration bound: a disk whose boundary (the link of p)
  // is not the one of the solution has no minimizer (the flow wanders), and only the flips at p between rounds
  // change that boundary. The next round starts from the last u of each vertex that stays interior (a warm
  // start: the same Newton iteration continues where the boundary did not change)
  const int round_iterations = 30;
  std::vector<double> u_last(m.number_of_vertices(), std::numeric_limits<double>::quiet_NaN());
  double mean_log_last = 0;
  for(int round = 0; ; ++round) {
    auto orig = m.template property_map<typename Mesh::Vertex_index, std::size_t>("v:orig").first;
    auto lam = m.template property_map<typename Mesh::Edge_index, double>("e:lambda").first;
    std::map<std::size_t, double> star; // original index of a link vertex -> lambda of its edge to p
    double mean_log = 0;
    for(auto h : CGAL::halfedges_around_source(p, m)) { star[orig[m.target(h)]] = lam[m.edge(h)]; mean_log += std::log(lam[m.edge(h)]); }
    mean_log /= double(star.size());
    const std::size_t p_orig = orig[p];
    disk = punctured_disk(m, p);
    auto dorig = disk.template property_map<typename Mesh::Vertex_index, std::size_t>("v:orig").first;
    auto dlam = disk.template property_map<typename Mesh::Edge_index, double>("e:lambda").first;
    eng.reset(new Flow_engine<Point_3>(disk, Background_geometry::EUCLIDEAN, Scheme::VERTEX_SCALING, true));
    for(auto e : disk.edges()) eng->edge_data[e] = dlam[e];
    Newton_options o = options;
    o.return_to_start_on_failure = false; // (see Newton_solver::return_to_start())
    // the iteration bound is for all rounds together
    o.max_iterations = (std::min)(options.max_iterations - st.iterations, round_iterations);
    o.fixed.assign(disk.number_of_vertices(), 0);
    o.fixed_in_error = false;
    for(auto v : disk.vertices()) {
      if(disk.is_border(v)) { o.fixed[v] = 1; eng->u[v] = -2 * (std::log(star.at(dorig[v])) - mean_log); }
      // the Dirichlet values moved by 2 (mean_log - mean_log_last): the solution moves with them
      else if(std::isfinite(u_last[dorig[v]])) eng->u[v] = u_last[dorig[v]] + 2 * (mean_log - mean_log_last);
    }
    Flow_statistics rs;
    Newton_solver<Point_3>(*eng, o, rs).run();
    accumulate(st, rs);
    for(auto v : disk.vertices()) u_last[dorig[v]] = eng->u[v];
    mean_log_last = mean_log;
    const bool cancelled = rs.status == Flow_status::CANCELLED;
    // the round's share of the iteration bound ran out: continue (after the flips at p, if any)
    const bool unfinished = rs.status == Flow_status::MAXIMUM_ITERATIONS && st.iterations < options.max_iterations;
    // the sphere after the disk's flips: the disk's (intrinsic) triangulation and the star of p
    Mesh s = disk;
    auto slam = s.template property_map<typename Mesh::Edge_index, double>("e:lambda").first;
    for(auto e : s.edges()) slam[e] = eng->edge_data[e];
    const auto c = close_disk(s, p_orig, star);
    const std::vector<typename Mesh::Edge_index> bad = delaunay_violations_at_puncture(*eng, s, c);
    m = s; p = c;
    if(cancelled || round >= max_rounds || st.iterations >= options.max_iterations) return p;
    if(bad.empty()) { if(unfinished) continue; return p; }
    Flow_engine<Point_3> se(m, Background_geometry::EUCLIDEAN, Scheme::VERTEX_SCALING, true);
    auto mlam = m.template property_map<typename Mesh::Edge_index, double>("e:lambda").first;
    for(auto e : m.edges()) se.edge_data[e] = mlam[e];
    se.compute_lengths(); se.compute_angles();
    std::size_t done = 0;
    for(auto e : bad) {
      const auto h = m.halfedge(e), o = m.opposite(h);
      if(m.face(h) == m.face(o)) continue;
      const auto a = m.target(m.next(h)), b = m.target(m.next(o)); // the new edge joins a and b
      if(m.source(h) == p || m.target(h) == p) {
        if(m.degree(p) <= 3 || a == b) continue;
      } else {
        // a link edge: the flip joins p to the apex on the other side, which must not be a neighbour of p
        // already (the star of p would not be a disk: a multi-edge of the intrinsic triangulation)
        const auto q = a == p ? b : a;
        if(q == p || m.halfedge(p, q) != Mesh::null_halfedge()) continue;
      }
      se.flip(e); ++done;
    }
    for(auto e : m.edges()) mlam[e] = se.edge_data[e];
    st.number_of_flips += done;
    if(done == 0 && !unfinished) return p;
  }
}

/// one attempt of `spherical_uniformization()` with the puncture vertex `p` of the sphere triangulation `m0`
/// (the input connectivity with its Euclidean lengths `len`): the disk flow, the layout, the projection, the
/// normalization and the spherical Delaunay triangulation. Throws `Numerical_error` when it cannot build them.
template <class Point_3>
Spherical_map<Point_3> spherical_map_with_puncture(const CGAL::Surface_mesh<Point_3>& m0, const std::vector<double>& len,
                                                   std::size_t p, const Newton_options& o)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Vertex_index V;
  Mesh m = m0;
  const V pv(static_cast<typename V::size_type>(p));
  auto orig = m.template add_property_map<V, std::size_t>("v:orig", 0).first;
  auto lam = m.template add_property_map<typename Mesh::Edge_index, double>("e:lambda", 0.0).first;
  for(V v : m.vertices()) orig[v] = std::size_t(v);
  for(auto e : m.edges()) lam[e] = 0.5 * len[e];
  const std::size_t nv = m.number_of_vertices();

  Spherical_map<Point_3> res;
  Flow_statistics& st = Metric_access::statistics(res.metric_);
  Mesh disk;
  std::unique_ptr<Flow_engine<Point_3> > eng;
  const V pc = sphere_flow(m, pv, o, disk, eng, st);
  auto dorig = disk.template property_map<V, std::size_t>("v:orig").first;
  auto morig = m.template property_map<V, std::size_t>("v:orig").first;
  // the callback asked to stop: the statistics, no map (the layout of an unfinished flow can be anything)
  if(st.status == Flow_status::CANCELLED) { res.puncture_ = morig[pc]; return res; }

  // layout, inverse stereographic projection (the mirror image: the projection reverses the orientation),
  // Moebius normalization
  std::vector<Cplx> w = layout_flat_disk(*eng);
  Cplx c(0); Real r = 0;
  std::size_t nlink = 0;
  for(auto v : disk.vertices()) if(disk.is_border(v)) { c += w[v]; ++nlink; }
  c /= Real(nlink);
  for(auto v : disk.vertices()) if(disk.is_border(v)) r += std::abs(w[v] - c) / Real(nlink);
  std::vector<Vec3> x(nv, Vec3{0, 0, 1});
  for(auto v : disk.vertices()) {
    const Cplx z = std::conj((w[v] - c) / r);
    const Real n2 = std::norm(z);
    x[dorig[v]] = Vec3{2 * z.real() / (n2 + 1), 2 * z.imag() / (n2 + 1), (n2 - 1) / (n2 + 1)};
  }
  for(const auto& q : x) if(!(std::isfinite(q[0]) && std::isfinite(q[1]) && std::isfinite(q[2])))
    throw_numerical_error("spherical uniformization: non-finite layout (the flow did not converge)");
  res.normalization_iterations_ = moebius_normalize(x, res.center_norm_);
  for(const auto& q : x) res.points_.push_back(Point_3(double(q[0]), double(q[1]), double(q[2])));
  res.puncture_ = morig[pc];

  // the spherical Delaunay triangulation: the final sphere triangulation, vertices in the input's order
  Mesh& sm = Metric_access::mesh(res.metric_);
  for(std::size_t i = 0; i < nv; ++i) sm.add_vertex(res.points_[i]);
  for(auto f : m.faces()) {
    const auto h = m.halfedge(f);
    if(sm.add_face(V(typename V::size_type(morig[m.source(h)])), V(typename V::size_type(morig[m.target(h)])),
                   V(typename V::size_type(morig[m.target(m.next(h))]))) == Mesh::null_face())
      throw_numerical_error("spherical uniformization: the final triangulation is not simplicial (the flow did not converge)");
  }
  // the lengths from the long double points, not from their rounding to double: a conformal map shrinks the
  // protrusions of a mesh exponentially (cow, dino, man: edges of 1e-14 to 1e-13 on the sphere, below the
  // resolution of double coordinates near 1); the double points gave those faces angle errors up to 2e-6
  auto& lengths = Metric_access::add_lengths(res.metric_);
  for(auto e : sm.edges()) {
    const Vec3 &a = x[sm.vertex(e, 0)], &b = x[sm.vertex(e, 1)];
    const long double d = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    lengths[e] = double(2 * std::asin((std::min)(1.0L, d / 2)));
  }
  Metric_access::set(res.metric_, Background_geometry::SPHERICAL, std::vector<double>(),
                     std::vector<double>(m.number_of_vertices(), 0.0), 0, false);
  res.flipped_ = res.number_of_flipped_faces();
  for(auto v : sm.vertices()) { // a NaN angle sum counts as infinite
    const double k = std::abs(res.metric_.curvature(v));
    if(!(k <= res.max_angle_sum_error_)) res.max_angle_sum_error_ = std::isnan(k) ? std::numeric_limits<double>::infinity() : k;
  }
  return res;
}

} // namespace internal

/*!
  \ingroup PkgDiscreteRicciFlowRef
  Spherical uniformization of a closed genus-0 mesh: a discrete conformal map to the unit sphere.

  Method (Bobenko-Pinkall-Springborn 2015; Springborn 2020; Gillespie-Springborn-Crane 2021): the star of the
  puncture vertex p is removed; on the remaining disk the Euclidean vertex-scaling flow with Ptolemy flips
  solves K = 0 at the interior vertices with the Dirichlet condition u_j = -2 log l_pj (+ const) at the link of
  p, which is the condition that p lies at infinity (the Penner coordinates of the edges to p). The energy is
  strictly convex with Ptolemy flips (its minimum exists for every triangulated sphere, Springborn 2020), so
  Newton with line search converges. The flat disk is laid out, mapped to the sphere by inverse stereographic
  projection (p at the north pole) and normalized by a Moebius transformation that puts the centre of mass of
  the vertices at the origin.

  \param tm a closed connected genus-0 triangle mesh (`FaceListGraph`)
  The outcome depends on the puncture vertex (the Delaunay condition at p is restored by Ptolemy flips between
  disk solves, which can cycle or end in a non-simplicial triangulation; a disk solve gets at most 30 Newton
  iterations of the bound, the next one starts from the last conformal factors): without `puncture_vertex`, a
  vertex of largest degree is tried first, then the next two by degree and 4 vertices spread over the index
  range, then (small meshes) the other vertices by degree, until one gives a valid map
  (`Spherical_map::converged()`: a converged flow can still leave the Delaunay condition at p violated,
  camel.off); the result and its statistics are those of that attempt (else of the first one). The input is
  scaled by a power of two to edge lengths of mean about 1 first (the map does not depend on the scale).
  Work bound: max(7, min(n, 24, 20000 / F)) attempts (n vertices, F faces), each with the iteration bound.
  Limitation: a conformal map shrinks long thin protrusions exponentially (a tube of length L and
  circumference c by about exp(-2 pi L / c)); where that takes faces below the resolution of double
  coordinates (about 1e-16 near the sphere), the points cannot represent the map and `converged()` is false
  (flipped faces): e.g. bull.off stretched 30 times along x.

  \param np named parameters: `puncture_vertex(i)` (default: the candidates above), `vertex_point_map`,
         `vertex_index_map`, `input_edge_length_map`, `number_of_iterations`, `accuracy`, `sparse_solver`,
         `verbose`, `callback` (as `compute_metric()`; when it returns false, the call returns at once with the
         status `CANCELLED`, no other puncture is tried, and the map has no points). Zero-area faces are
         flipped away first.
  \throws CGAL::Invalid_mesh_error unless `tm` is a closed connected genus-0 triangle mesh;
          CGAL::Numerical_error if the normalization fails. Non-convergence of the flow is a status.
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Spherical_map<typename boost::property_traits<typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>::value_type>
spherical_uniformization(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Vertex_index V;
  const auto t0 = std::chrono::steady_clock::now();
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  internal::check_closed_surface(tm, vim, "spherical uniformization", "genus 0", [](long g) { return g == 0; });
  VPM vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  internal::Newton_options o = internal::newton_options(np);
  Mesh m;
  std::vector<V> vmap;
  internal::copy_connectivity(tm, vpm, vim, m, vmap);
  std::vector<double> len = internal::input_lengths(tm, vpm, vim, get_parameter(np, CGAL::internal_np::ricci_edge_length_map_t_v), m, vmap);
  // the map does not depend on the input's scale: the flow runs on lengths of mean about 1 (a mesh in units
  // of 1e-150 underflowed in the Heron products: NUMERICAL_FAILURE, or the flip limit after minutes)
  const double unit = internal::normalize_lengths(len);
  double area = 0; std::string msg;
  std::size_t initial_flips = 0;
  if(internal::degenerate_face(m, len, area, msg, unit) != Mesh::null_face()) {
    initial_flips = internal::geometric_delaunay_flips(m, len).flips.size();
    if(internal::degenerate_face(m, len, area, msg, unit) != Mesh::null_face())
      internal::throw_metric_error(msg + " after the intrinsic Delaunay flips of the input");
  }
  // the puncture vertex: the given one, else candidates (a vertex of largest degree first, then vertices
  // spread over the index range) tried in turn until one gives a valid map
  std::size_t p = choose_parameter(get_parameter(np, CGAL::internal_np::ricci_puncture_vertex_t_v), std::size_t(-1));
  std::vector<std::size_t> candidates;
  if(p == std::size_t(-1)) {
    // the 3 vertices of largest degree (the first of them as before: the default), then 4 spread by index
    std::vector<std::pair<std::size_t, std::size_t> > by_degree; // (-degree, index): stable order
    for(V v : m.vertices()) by_degree.push_back({std::size_t(-1) - m.degree(v), std::size_t(v)});
    std::sort(by_degree.begin(), by_degree.end());
    const std::size_t n = m.number_of_vertices();
    for(std::size_t i = 0; i < 3 && i < n; ++i) candidates.push_back(by_degree[i].second);
    for(std::size_t i = 1; i <= 4; ++i) {
      const std::size_t c = (i * n) / 5;
      if(c < n && std::find(candidates.begin(), candidates.end(), c) == candidates.end()) candidates.push_back(c);
    }
    // small meshes: then the other vertices by degree, up to min(24, 20,000 / F) attempts in all (beam.off
    // with Gaussian vertex noise of 0.3 edge lengths, 8 vertices: the 7 candidates above failed, 3 of the other
    // vertices gave valid maps)
    const std::size_t max_attempts = (std::max)(std::size_t(7), (std::min)({n, std::size_t(24), std::size_t(20000) / (std::max)(std::size_t(1), std::size_t(m.number_of_faces()))}));
    for(std::size_t i = 0; i < n && candidates.size() < max_attempts; ++i)
      if(std::find(candidates.begin(), candidates.end(), by_degree[i].second) == candidates.end())
        candidates.push_back(by_degree[i].second);
  } else if(p >= m.number_of_vertices()) internal::throw_option_error("puncture_vertex: no such vertex");
  else candidates.push_back(p);
  // the result: the first valid map, else the first attempt's result; the first error if every attempt threw
  Spherical_map<Point_3> res;
  bool have = false;
  std::exception_ptr error;
  for(std::size_t c : candidates) {
    try {
      Spherical_map<Point_3> r = internal::spherical_map_with_puncture<Point_3>(m, len, c, o);
      // the callback asked to stop: no other candidate
      const bool cancelled = r.statistics().status == Flow_status::CANCELLED;
      if(r.converged() || !have || cancelled) { res = std::move(r); have = true; }
      if(res.converged() || cancelled) break;
    } catch(const CGAL::Numerical_error&) {
      if(!error) error = std::current_exception();
    }
  }
  if(!have) std::rethrow_exception(error);
  Flow_statistics& st = internal::Metric_access::statistics(res.metric_);
  st.number_of_initial_flips = initial_flips;
  st.time_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_SPHERICAL_UNIFORMIZATION_H
