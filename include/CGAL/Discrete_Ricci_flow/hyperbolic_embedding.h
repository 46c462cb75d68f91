// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Embedding of the universal cover of a uniformized surface (thesis Section 2.3.1): greedy tree-cotree
// homotopy basis at a base vertex, cut to a topological disk, isometric layout of the fundamental domain in
// the Poincare disk (or the plane for a flat torus), deck transformations (holonomies of the basis loops),
// the relator, side pairings, a tiling of the disk by the group, and the flat-torus lattice parameter tau.
#ifndef CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H
#define CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H

#include <CGAL/Discrete_Ricci_flow/compute_metric.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Poincare_disk_svg.h>
#include <CGAL/Poincare_disk_isometry_2.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <complex>
#include <deque>
#include <functional>
#include <memory>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Ricci_flow {

namespace internal {

// the layout runs in long double: the domain reaches far towards the boundary of the disk, where double
// coordinates lose about log10(e^D) digits at hyperbolic distance D from the origin
typedef long double Real;
typedef std::complex<Real> Cplx;

/// a Moebius map z -> (a z + b) / (c z + d) as a complex 2x2 matrix (isometries of H^2 in the Poincare disk
/// and Euclidean motions z -> e^{i phi} z + t are both of this form)
struct Moebius
{
  Cplx a = 1, b = 0, c = 0, d = 1;
  Cplx operator()(Cplx z) const { return (a * z + b) / (c * z + d); }
  Moebius operator*(const Moebius& g) const
  {
    Moebius r;
    r.a = a * g.a + b * g.c; r.b = a * g.b + b * g.d; r.c = c * g.a + d * g.c; r.d = c * g.b + d * g.d;
    return r;
  }
  Moebius inverse() const { Moebius r; r.a = d; r.b = -b; r.c = -c; r.d = a; return r; }
  Moebius normalized() const
  {
    const Cplx s = std::sqrt(a * d - b * c);
    Moebius r; r.a = a / s; r.b = b / s; r.c = c / s; r.d = d / s;
    return r;
  }
};

/// the isometry taking p to 0 and q to the positive real axis (hyperbolic: Poincare disk; else Euclidean)
inline Moebius standard_position(bool hyperbolic, Cplx p, Cplx q)
{
  Moebius t;
  if(hyperbolic) { t.a = 1; t.b = -p; t.c = -std::conj(p); t.d = 1; }
  else { t.a = 1; t.b = -p; t.c = 0; t.d = 1; }
  const Cplx w = t(q);
  const Cplx rot = std::conj(w) / Real(std::abs(w));
  t.a *= rot; t.b *= rot;
  return t;
}

/// the orientation-preserving isometry mapping p1 -> p2 and q1 -> q2 (assuming d(p1,q1) = d(p2,q2))
inline Moebius isometry_from_pairs(bool hyperbolic, Cplx p1, Cplx q1, Cplx p2, Cplx q2)
{
  return standard_position(hyperbolic, p2, q2).inverse() * standard_position(hyperbolic, p1, q1);
}

} // namespace internal

/*!
  \ingroup PkgDiscreteRicciFlowRef
  The universal cover of a closed surface with a hyperbolic metric (genus >= 2) embedded in the Poincare disk,
  or of a flat torus (genus 1) embedded in the plane, computed from a `Discrete_metric` (thesis Section 2.3.1).

  Construction (cost O(n log n)):
  - homotopy basis at the base vertex b (Erickson-Whittlesey greedy tree-cotree): T = shortest-path tree from
    b, C = maximum spanning tree of the dual graph on the edges not in T, weighted by the length of the loop
    through the edge; the 2g remaining edges e_i = (u_i -> v_i) give the loops
    `gamma_i = T(b -> u_i) . e_i . T(v_i -> b)` (`homotopy_basis()`, halfedges of the intrinsic mesh);
  - the fundamental domain D: the surface cut along a *compact* cut graph (the edges not crossed by a
    shortest-path tree of the dual graph grown from the base face, pruned of dangling trees), laid out
    isometrically (cosine law, breadth-first, in long double) with the base vertex at the origin
    (`corner_position()`, `domain_boundary()`); every face stays within a few units of the origin, where double
    coordinates are accurate;
  - deck transformations: the holonomy of each loop gamma_i (developing the metric along gamma_i through D,
    composing the side pairings crossed), an element of SU(1,1) (`deck_transformations()`), or a translation for
    the torus (`periods()`);
  - the relator: the boundary of the disk cut along the loops gamma_i (read combinatorially) as a word in the
    loops; the product of the deck transformations in that order is the identity (`relator()`,
    `relator_product()`, `relator_polygon()`);
  - the side pairings of D: each maximal path of its cut graph appears twice on the boundary of D; the isometry
    mapping one copy onto the other (`side_pairings()`), used for the tiling (`write_tiling_svg()`).

  The deck transformation of a based loop maps the lift of its start (in D) to the lift of its end, and its
  translation length `2 acosh(|trace| / 2)` is the length of the closed geodesic freely homotopic to the loop.
*/
template <class Point_3>
class Hyperbolic_embedding
{
public:
  typedef Discrete_metric<Point_3> Metric;
  typedef typename Metric::Mesh Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Edge_index Edge_index;
  typedef typename Mesh::Face_index Face_index;
  typedef CGAL::Epick Kernel;
  typedef Kernel::Point_2 Point_2;
  /// SU(1,1) isometries of the Poincare disk in double precision
  typedef CGAL::Poincare_disk_isometry_2<Kernel> Isometry;
  typedef std::complex<double> Complex;

  /// one side of the domain: the cut path as halfedges with D on their left, its twin side, and the map
  /// taking the twin copy onto this one
  struct Side
  {
    std::vector<Halfedge_index> halfedges; ///< consecutive halfedges along the boundary of D
    std::size_t twin = 0;                  ///< index of the paired side
    internal::Moebius pairing;             ///< maps the twin's copy onto this side's copy
  };

  /*!
    Builds the embedding (a copy of `metric` is kept, shared by copies of the embedding). `metric` must be a
    converged (or stagnated below 1e-9) metric of a closed surface with a hyperbolic background
    (genus >= 2) or a Euclidean background (genus 1), with zero target curvature everywhere (no cones).
    \throws Ricci_flow_error otherwise.
  */
  explicit Hyperbolic_embedding(const Metric& metric, Vertex_index base = Vertex_index(0))
    : metric_ptr_(std::make_shared<const Metric>(metric)), metric_(*metric_ptr_), m_(metric_.intrinsic_mesh()),
      base_(base)
  {
    hyperbolic_ = metric.background_geometry() == Background_geometry::HYPERBOLIC;
    if(metric.background_geometry() == Background_geometry::SPHERICAL)
      throw Ricci_flow_error("no embedding for the spherical background");
    if(!CGAL::is_closed(m_)) throw Ricci_flow_error("the embedding needs a closed surface");
    if(std::size_t(base) >= m_.number_of_vertices()) throw Ricci_flow_error("invalid base vertex");
    for(double k : metric.target_curvatures())
      if(k != 0) throw Ricci_flow_error("the embedding needs zero target curvature at every vertex (no cone points)");
    const long g = metric.genus();
    if(hyperbolic_ && g < 2) throw Ricci_flow_error("a hyperbolic embedding needs genus >= 2");
    if(!hyperbolic_ && g != 1) throw Ricci_flow_error("a Euclidean embedding needs genus 1");
    if(!metric.converged() && !(metric.statistics().status == Flow_status::STAGNATED &&
                                metric.statistics().max_curvature_error < 1e-9))
      throw Ricci_flow_error("the metric did not converge");
    build_homotopy_basis();
    build_domain_cut();
    layout();
    compute_holonomies();
    compute_boundary();
  }

  /// the metric (the embedding's copy) and its intrinsic mesh, whose halfedges the loops refer to
  const Metric& metric() const { return metric_; }
  const Mesh& mesh() const { return m_; }
  Vertex_index base_vertex() const { return base_; }
  long genus() const { return metric_.genus(); }
  std::size_t number_of_generators() const { return loops_.size(); }

  /// the 2g loops of the homotopy basis: halfedges of `mesh()` (the same indices as in the metric's
  /// `intrinsic_mesh()`), each loop starts and ends at `base_vertex()`
  const std::vector<std::vector<Halfedge_index> >& homotopy_basis() const { return loops_; }

  /// the length of loop i in the metric (at least its translation length)
  double loop_length(std::size_t i) const
  {
    double s = 0;
    for(Halfedge_index h : loops_[i]) s += metric_.length(h);
    return s;
  }

  /// the deck transformation of loop i as a Moebius map (complex 2x2, determinant 1)
  const internal::Moebius& holonomy(std::size_t i) const { return hol_[i]; }

  /// the deck transformations of the 2g loops as SU(1,1) isometries (hyperbolic background only)
  std::vector<Isometry> deck_transformations() const
  {
    std::vector<Isometry> r;
    for(const auto& h : hol_) r.push_back(to_isometry(h));
    return r;
  }

  /// translation length of the deck transformation of loop i: 2 acosh(|trace| / 2) (H^2), |period| (E^2)
  double translation_length(std::size_t i) const
  {
    if(!hyperbolic_) return double(std::abs(hol_[i].b / hol_[i].d));
    return 2 * std::acosh((std::max)(1.0, absolute_trace(i) / 2));
  }

  /// |trace| of the normalized deck transformation of loop i (> 2 for a hyperbolic translation)
  double absolute_trace(std::size_t i) const { return double(std::abs((hol_[i].a + hol_[i].d).real())); }

  /// the relator: the boundary of the fundamental domain read as letters (loop index, +1 or -1)
  const std::vector<std::pair<std::size_t, int> >& relator() const { return relator_; }

  /// the product of the deck transformations along `relator()` (the identity up to rounding)
  internal::Moebius relator_product() const
  {
    internal::Moebius m;
    for(const auto& l : relator_) m = m * (l.second > 0 ? hol_[l.first] : hol_[l.first].inverse());
    return m.normalized();
  }

  /// The relator polygon: the 4g lifts of the base vertex P_k = w_1 ... w_k (0), k = 0 .. 4g-1, for the letters
  /// w_k of `relator()` (the base vertex's copy is at the origin). Its geodesic sides are lifts of the geodesic
  /// loops based at the base vertex in the classes of the basis loops; when those geodesic loops are simple and
  /// meet only at the base vertex it is a fundamental polygon of the group, paired by the deck transformations
  /// (e.g. the regular octagon of the Bolza surface based at a Weierstrass point).
  std::vector<Complex> relator_polygon() const
  {
    std::vector<Complex> p;
    internal::Moebius m;
    for(const auto& l : relator_) {
      const internal::Cplx z = m(internal::Cplx(0));
      p.push_back(Complex(double(z.real()), double(z.imag())));
      m = m * (l.second > 0 ? hol_[l.first] : hol_[l.first].inverse());
    }
    return p;
  }

  /// distance of `relator_product()` to +-I (max entry difference)
  double relator_defect() const
  {
    const internal::Moebius m = relator_product();
    const internal::Cplx one(1);
    const internal::Real dp = (std::max)({std::abs(m.a - one), std::abs(m.b), std::abs(m.c), std::abs(m.d - one)});
    const internal::Real dm = (std::max)({std::abs(m.a + one), std::abs(m.b), std::abs(m.c), std::abs(m.d + one)});
    return double((std::min)(dp, dm));
  }

  /// position of `target(h)` in the copy of `face(h)` laid out in the fundamental domain
  Complex corner_position(Halfedge_index h) const { return Complex(double(pos_[h].real()), double(pos_[h].imag())); }
  Point_2 corner_point(Halfedge_index h) const { return Point_2(double(pos_[h].real()), double(pos_[h].imag())); }

  /// true if the edge is on the cut (on the boundary of the fundamental domain)
  bool is_cut(Edge_index e) const { return cut_[e] != 0; }

  /// the boundary of the fundamental domain: cut halfedges with the domain on their left, in
  /// counterclockwise order; vertex k of the polygon is `corner_position(domain_boundary()[k])`
  const std::vector<Halfedge_index>& domain_boundary() const { return boundary_; }

  /// the sides of the domain (maximal cut paths), each paired with its twin
  const std::vector<Side>& side_pairings() const { return sides_; }

  /// the flat torus only: the two periods (translations of the two loops), the lattice parameter
  /// tau = period_2 / period_1 reduced to the fundamental region of SL(2,Z) (Im tau > 0, |Re tau| <= 1/2,
  /// |tau| >= 1)
  std::pair<Complex, Complex> periods() const
  {
    if(hyperbolic_ || hol_.size() != 2) throw Ricci_flow_error("periods() is for the flat torus");
    const internal::Cplx p0 = hol_[0].b / hol_[0].d, p1 = hol_[1].b / hol_[1].d;
    return {Complex(double(p0.real()), double(p0.imag())), Complex(double(p1.real()), double(p1.imag()))};
  }

  Complex lattice_parameter() const
  {
    const auto p = periods();
    Complex tau = p.second / p.first;
    if(tau.imag() < 0) tau = -tau;
    for(int it = 0; it < 1000; ++it) {
      tau = Complex(tau.real() - std::floor(tau.real() + 0.5), tau.imag());
      if(std::norm(tau) < 1 - 1e-14) tau = -1.0 / tau;
      else break;
    }
    return tau;
  }

  /// SVG picture of the fundamental domain: triangles (shaded by area) and the cut in red
  void write_fundamental_domain_svg(const std::string& filename, double size_px = 900) const
  {
    CGAL::Poincare_disk_svg_writer w(size_px, hyperbolic_ ? 1.0 : view_zoom(), 0, 0);
    if(hyperbolic_) w.add_unit_circle();
    const internal::Moebius t = view_transform();
    for(Face_index f : m_.faces()) {
      const Halfedge_index h = m_.halfedge(f);
      std::vector<double> xy;
      for(Halfedge_index g : {h, m_.next(h), m_.prev(h)}) { const internal::Cplx z = t(pos_[g]); xy.push_back(double(z.real())); xy.push_back(double(z.imag())); }
      w.add_geodesic_polygon(xy, "#cfe0f5", "#7a8ea8", 0.3);
    }
    for(Halfedge_index h : boundary_) {
      const internal::Cplx a = t(pos_[m_.prev(h)]), b = t(pos_[h]);
      w.add_geodesic_segment(double(a.real()), double(a.imag()), double(b.real()), double(b.imag()), "#c00", 1.6);
    }
    const internal::Cplx o = t(internal::Cplx(0));
    w.add_point(double(o.real()), double(o.imag()), "#000", 3);
    w.write(filename);
  }

  /// SVG picture of the tiling: the images of the fundamental domain under the group elements given by
  /// words of length <= `max_word_length` in the side pairings (breadth-first from the domain across its sides,
  /// duplicates removed; tiles smaller than about two pixels are drawn but not expanded; at most `max_tiles`).
  /// Returns the number of tiles drawn.
  std::size_t write_tiling_svg(const std::string& filename, int max_word_length = 3, double size_px = 900,
                               std::size_t max_tiles = 4000) const
  {
    CGAL::Poincare_disk_svg_writer w(size_px, hyperbolic_ ? 1.0 : view_zoom() / (1 + max_word_length), 0, 0);
    if(hyperbolic_) w.add_unit_circle();
    const internal::Moebius view = view_transform();
    struct Node { internal::Moebius g; int len; };
    std::deque<Node> queue;
    queue.push_back({internal::Moebius(), 0});
    std::vector<internal::Cplx> seen;
    const internal::Cplx probe = internal::Real(0.5) * pos_[m_.next(root_)];
    std::size_t drawn = 0;
    while(!queue.empty() && drawn < max_tiles) {
      const Node nd = queue.front(); queue.pop_front();
      const internal::Cplx c = view(nd.g(probe));
      bool dup = false;
      for(const internal::Cplx& s : seen) if(std::abs(s - c) < 1e-9) { dup = true; break; }
      if(dup) continue;
      seen.push_back(c);
      std::vector<double> xy;
      double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
      for(Halfedge_index h : boundary_) {
        const internal::Cplx zl = view(nd.g(pos_[h]));
        const double zx = double(zl.real()), zy = double(zl.imag());
        xy.push_back(zx); xy.push_back(zy);
        xmin = (std::min)(xmin, zx); xmax = (std::max)(xmax, zx);
        ymin = (std::min)(ymin, zy); ymax = (std::max)(ymax, zy);
      }
      const double t = double(nd.len) / (max_word_length + 1);
      w.add_geodesic_polygon(xy, CGAL::Poincare_disk_svg_writer::color_ramp(0.15 + 0.7 * t), "#333",
                             nd.len == 0 ? 1.2 : 0.4, nd.len == 0 ? 0.9 : 0.6);
      ++drawn;
      const bool tiny = hyperbolic_ && (xmax - xmin) + (ymax - ymin) < 4.0 / size_px;
      if(nd.len >= max_word_length || tiny) continue;
      for(const Side& sd : sides_) queue.push_back({nd.g * sd.pairing, nd.len + 1});
    }
    w.write(filename);
    return drawn;
  }

private:
  static Isometry to_isometry(const internal::Moebius& h)
  {
    const internal::Moebius n = h.normalized();
    return Isometry(double(n.a.real()), double(n.a.imag()), double(n.b.real()), double(n.b.imag()));
  }

  // the isometry moving the (Euclidean) mean of the domain's corners to the origin, for pictures
  internal::Moebius view_transform() const
  {
    internal::Cplx c(0);
    for(const internal::Cplx& z : pos_) c += z;
    c /= internal::Real(pos_.empty() ? 1 : pos_.size());
    internal::Moebius t;
    if(hyperbolic_) { t.b = -c; t.c = -std::conj(c); } else t.b = -c;
    return t;
  }

  double view_zoom() const
  {
    double r = 1e-300;
    const internal::Moebius t = view_transform();
    for(const internal::Cplx& z : pos_) r = (std::max)(r, double(std::abs(t(z))));
    return 0.9 / r;
  }

  double len(Halfedge_index h) const { return metric_.length(h); }

  // ---------------------------------------------------------------- greedy tree-cotree
  void build_homotopy_basis()
  {
    const std::size_t nv = m_.number_of_vertices(), ne = m_.number_of_edges(), nf = m_.number_of_faces();
    // shortest-path tree from the base vertex (Dijkstra)
    dist_.assign(nv, std::numeric_limits<double>::infinity());
    parent_.assign(nv, Mesh::null_halfedge());
    typedef std::pair<double, std::size_t> QE;
    std::priority_queue<QE, std::vector<QE>, std::greater<QE> > pq;
    dist_[base_] = 0; pq.push({0.0, std::size_t(base_)});
    while(!pq.empty()) {
      const QE top = pq.top(); pq.pop();
      const Vertex_index v(static_cast<typename Vertex_index::size_type>(top.second));
      if(top.first > dist_[v]) continue;
      for(Halfedge_index h : CGAL::halfedges_around_source(v, m_)) {
        const Vertex_index w = m_.target(h);
        const double d = dist_[v] + len(h);
        if(d < dist_[w]) { dist_[w] = d; parent_[w] = h; pq.push({d, std::size_t(w)}); }
      }
    }
    std::vector<char> in_tree(ne, 0);
    for(Vertex_index v : m_.vertices()) {
      if(v == base_) continue;
      if(parent_[v] == Mesh::null_halfedge()) throw Ricci_flow_error("the mesh is not connected");
      in_tree[m_.edge(parent_[v])] = 1;
    }
    // cotree: maximum spanning tree of the dual graph among non-tree edges, weight = loop length
    std::vector<std::pair<double, std::size_t> > cand;
    for(Edge_index e : m_.edges())
      if(!in_tree[e]) {
        const Halfedge_index h = m_.halfedge(e);
        cand.push_back({dist_[m_.source(h)] + len(h) + dist_[m_.target(h)], std::size_t(e)});
      }
    std::sort(cand.begin(), cand.end(), [](const std::pair<double, std::size_t>& a, const std::pair<double, std::size_t>& b) {
      return a.first > b.first || (a.first == b.first && a.second < b.second);
    });
    std::vector<std::size_t> rank(nf, 0), par(nf);
    boost::disjoint_sets<std::size_t*, std::size_t*> ds(rank.data(), par.data());
    for(std::size_t f = 0; f < nf; ++f) ds.make_set(f);
    std::vector<std::pair<double, Edge_index> > leftover;
    for(const auto& c : cand) {
      const Edge_index e(static_cast<typename Edge_index::size_type>(c.second));
      const Halfedge_index h = m_.halfedge(e);
      const std::size_t f1 = m_.face(h), f2 = m_.face(m_.opposite(h));
      const std::size_t r1 = ds.find_set(f1), r2 = ds.find_set(f2);
      if(r1 != r2) ds.link(r1, r2);
      else leftover.push_back({c.first, e});
    }
    if(long(leftover.size()) != 2 * metric_.genus())
      throw Ricci_flow_error("tree-cotree found " + std::to_string(leftover.size()) + " generators, expected 2g");
    std::sort(leftover.begin(), leftover.end(), [](const std::pair<double, Edge_index>& a, const std::pair<double, Edge_index>& b) {
      return a.first < b.first || (a.first == b.first && a.second < b.second);
    });
    // loops and their union (the greedy cut graph)
    greedy_cut_.assign(ne, 0);
    for(const auto& lo : leftover) {
      const Halfedge_index h = m_.halfedge(lo.second);
      std::vector<Halfedge_index> up, loop;
      for(Vertex_index v = m_.source(h); v != base_; v = m_.source(parent_[v])) up.push_back(parent_[v]);
      loop.assign(up.rbegin(), up.rend());
      loop.push_back(h);
      for(Vertex_index v = m_.target(h); v != base_; v = m_.source(parent_[v])) loop.push_back(m_.opposite(parent_[v]));
      for(Halfedge_index g : loop) greedy_cut_[m_.edge(g)] = 1;
      generator_edge_.push_back(h);
      loops_.push_back(loop);
    }
  }

  // ---------------------------------------------------------------- a compact cut for the layout
  // The domain D is grown from the root face by a shortest-path tree of the dual graph (each step weighted by
  // the distance between incircle-ish centres, approximated by a third of the two perimeters), so that every
  // face of D is close to the base: the layout then stays far from the boundary of the disk, where double
  // precision degrades. The cut is the set of edges not crossed by that dual tree, pruned of its dangling trees.
  void build_domain_cut()
  {
    const std::size_t nf = m_.number_of_faces(), ne = m_.number_of_edges();
    root_ = m_.halfedge(base_); // target(root_) == base
    std::vector<double> perim(nf, 0), fd(nf, std::numeric_limits<double>::infinity());
    for(Face_index f : m_.faces()) {
      const Halfedge_index h = m_.halfedge(f);
      perim[f] = len(h) + len(m_.next(h)) + len(m_.prev(h));
    }
    std::vector<char> crossed(ne, 0);
    std::vector<Halfedge_index> via(nf, Mesh::null_halfedge());
    typedef std::pair<double, std::size_t> QE;
    std::priority_queue<QE, std::vector<QE>, std::greater<QE> > pq;
    const Face_index f0 = m_.face(root_);
    fd[f0] = 0; pq.push({0.0, std::size_t(f0)});
    std::vector<char> done(nf, 0);
    while(!pq.empty()) {
      const QE top = pq.top(); pq.pop();
      const Face_index f(static_cast<typename Face_index::size_type>(top.second));
      if(done[f]) continue;
      done[f] = 1;
      if(via[f] != Mesh::null_halfedge()) crossed[m_.edge(via[f])] = 1;
      const Halfedge_index h0 = m_.halfedge(f);
      for(Halfedge_index h : {h0, m_.next(h0), m_.prev(h0)}) {
        const Face_index g = m_.face(m_.opposite(h));
        const double d = fd[f] + (perim[f] + perim[g]) / 6;
        if(!done[g] && d < fd[g]) { fd[g] = d; via[g] = h; pq.push({d, std::size_t(g)}); }
      }
    }
    cut_.assign(ne, 0);
    std::vector<std::size_t> degree(m_.number_of_vertices(), 0);
    for(Edge_index e : m_.edges())
      if(!crossed[e]) {
        cut_[e] = 1;
        ++degree[m_.vertex(e, 0)]; ++degree[m_.vertex(e, 1)];
      }
    // prune: remove cut edges at vertices of cut-degree 1, repeatedly (a loop edge counts twice)
    std::vector<Vertex_index> stack;
    for(Vertex_index v : m_.vertices()) if(degree[v] == 1) stack.push_back(v);
    while(!stack.empty()) {
      const Vertex_index v = stack.back(); stack.pop_back();
      if(degree[v] != 1) continue;
      for(Halfedge_index h : CGAL::halfedges_around_source(v, m_)) {
        if(!cut_[m_.edge(h)]) continue;
        cut_[m_.edge(h)] = 0;
        --degree[v];
        const Vertex_index w = m_.target(h);
        if(--degree[w] == 1) stack.push_back(w);
        break;
      }
    }
  }

  // ---------------------------------------------------------------- layout of the disk D
  void layout()
  {
    const bool hyp = hyperbolic_;
    pos_.assign(m_.number_of_halfedges(), internal::Cplx(0));
    std::vector<char> placed(m_.number_of_faces(), 0);
    // root face: the face of a halfedge entering the base vertex; base at 0, the edge along the real axis
    const Face_index f0 = m_.face(root_);
    {
      const Halfedge_index h = root_;             // source(h) -> base
      const Halfedge_index n = m_.next(h);        // base -> third
      const double l_h = len(h), l_n = len(n), l_p = len(m_.prev(h));
      // corner at base between n and h: angle opposite to prev(h)
      const internal::Real th = angle_opposite(m_.prev(h));
      pos_[h] = 0; // base
      pos_[n] = polar(hyp, l_n, 0.0);                       // third vertex on the positive real axis
      pos_[m_.prev(h)] = polar(hyp, l_h, th);               // source(h), at angle th counterclockwise
      (void)l_p;
      placed[f0] = 1;
    }
    std::deque<Face_index> queue(1, f0);
    while(!queue.empty()) {
      const Face_index f = queue.front(); queue.pop_front();
      const Halfedge_index h0 = m_.halfedge(f);
      for(Halfedge_index h : {h0, m_.next(h0), m_.prev(h0)}) {
        if(cut_[m_.edge(h)]) continue;
        const Halfedge_index o = m_.opposite(h);
        const Face_index g = m_.face(o);
        if(placed[g]) continue;
        // o runs target(h) -> source(h); positions from face f: p = source(o) = target(h), q = target(o)
        const internal::Cplx p = pos_[h], q = pos_[m_.prev(h)];
        pos_[o] = q;
        pos_[m_.prev(o)] = p;
        // third vertex r = target(next(o)), left of p -> q, at distance len(prev(o)) from p, angle at p
        const internal::Real th = angle_opposite(m_.next(o)); // corner at source(o) is opposite to next(o)
        const internal::Moebius s = internal::standard_position(hyp, p, q);
        pos_[m_.next(o)] = s.inverse()(polar(hyp, len(m_.prev(o)), th));
        placed[g] = 1;
        queue.push_back(g);
      }
    }
    for(Face_index f : m_.faces())
      if(!placed[f]) throw Ricci_flow_error("the cut does not leave a disk (layout incomplete)");
  }

  static internal::Cplx polar(bool hyperbolic, double length, internal::Real angle)
  {
    const internal::Real l = length;
    const internal::Real r = hyperbolic ? std::tanh(l / 2) : l;
    return std::polar(r, angle);
  }

  // the corner angle opposite to h in face(h), in long double (half-angle formula)
  internal::Real angle_opposite(Halfedge_index h) const
  {
    const internal::Real a = len(h), b = len(m_.next(h)), c = len(m_.prev(h));
    const internal::Real s = (a + b + c) / 2;
    auto f = [&](internal::Real x) { return hyperbolic_ ? std::sinh(x) : x; };
    const internal::Real num = f(s - b) * f(s - c), den = f(s) * f(s - a);
    if(!(num > 0) || !(den > 0)) return !(num > 0) ? internal::Real(0) : internal::Real(CGAL_PI);
    return 2 * std::atan2(std::sqrt(num), std::sqrt(den));
  }

  // the transition across halfedge g: maps the copy of face(opposite(g)) onto the copy of face(g)
  internal::Moebius transition(Halfedge_index g) const
  {
    const Halfedge_index o = m_.opposite(g);
    // in face(g): source(g) at pos[prev(g)], target(g) at pos[g]; in face(o): source(g) = target(o) at pos[o],
    // target(g) = source(o) at pos[prev(o)]
    return internal::isometry_from_pairs(hyperbolic_, pos_[o], pos_[m_.prev(o)], pos_[m_.prev(g)], pos_[g]);
  }

  // ---------------------------------------------------------------- holonomies of the loops
  // Developing along a loop: the current corner c (a halfedge entering the current vertex, in the current face);
  // rotating counterclockwise to the next corner crosses edge(next(c)); crossing a cut edge composes the
  // transition. M maps the domain copy of the current face to its lift.
  void rotate(Halfedge_index& c, internal::Moebius& M) const
  {
    const Halfedge_index g = m_.next(c);
    if(cut_[m_.edge(g)]) M = M * transition(g);
    c = m_.opposite(g);
  }

  internal::Moebius develop(const std::vector<Halfedge_index>& loop) const
  {
    internal::Moebius M;
    Halfedge_index c = root_;
    for(Halfedge_index h : loop) {
      std::size_t guard = 0;
      while(m_.next(c) != h) {
        rotate(c, M);
        if(++guard > m_.number_of_halfedges()) throw Ricci_flow_error("develop: invalid loop");
      }
      c = h;
    }
    std::size_t guard = 0;
    while(c != root_) {
      rotate(c, M);
      if(++guard > m_.number_of_halfedges()) throw Ricci_flow_error("develop: invalid loop");
    }
    return M.normalized();
  }

  void compute_holonomies()
  {
    hol_.clear();
    for(const auto& loop : loops_) hol_.push_back(develop(loop));
  }

  // ---------------------------------------------------------------- boundary, relator, sides
  // the face walk of the ribbon graph formed by the cut edges: from a cut halfedge h, rotate around target(h)
  // (crossing non-cut edges) to the next cut halfedge. For a cut graph this walks once around the disk.
  std::vector<Halfedge_index> boundary_walk(const std::vector<char>& cut) const
  {
    Halfedge_index start = Mesh::null_halfedge();
    for(Halfedge_index h : m_.halfedges()) if(cut[m_.edge(h)]) { start = h; break; }
    std::vector<Halfedge_index> walk;
    const std::size_t ncut = std::size_t(std::count(cut.begin(), cut.end(), char(1)));
    Halfedge_index h = start;
    do {
      walk.push_back(h);
      Halfedge_index g = m_.next(h);
      while(!cut[m_.edge(g)]) g = m_.next(m_.opposite(g));
      h = g;
      if(walk.size() > 2 * ncut) throw Ricci_flow_error("boundary walk does not close");
    } while(h != start);
    if(walk.size() != 2 * ncut) throw Ricci_flow_error("the cut graph does not bound a single disk");
    return walk;
  }

  void compute_boundary()
  {
    boundary_ = boundary_walk(cut_);
    // relator letters: the boundary of the disk cut along the greedy loops, read in the loops
    relator_.clear();
    for(Halfedge_index b : boundary_walk(greedy_cut_))
      for(std::size_t i = 0; i < generator_edge_.size(); ++i) {
        if(b == generator_edge_[i]) relator_.push_back({i, +1});
        else if(b == m_.opposite(generator_edge_[i])) relator_.push_back({i, -1});
      }
    // sides: maximal runs of the boundary whose twin halfedges are consecutive in reverse
    std::vector<std::size_t> index_of(m_.number_of_halfedges(), std::size_t(-1));
    for(std::size_t k = 0; k < boundary_.size(); ++k) index_of[boundary_[k]] = k;
    const std::size_t nb = boundary_.size();
    auto twin_index = [&](std::size_t k) { return index_of[m_.opposite(boundary_[k])]; };
    // a side starts at k if the twin of k-1 is not the successor of the twin of k
    std::vector<char> starts(nb, 0);
    for(std::size_t k = 0; k < nb; ++k) {
      const std::size_t prev = (k + nb - 1) % nb;
      starts[k] = twin_index(prev) != (twin_index(k) + 1) % nb;
    }
    sides_.clear();
    std::vector<std::size_t> side_of(nb, 0);
    std::size_t k0 = 0;
    while(k0 < nb && !starts[k0]) ++k0;
    if(k0 == nb) k0 = 0;
    for(std::size_t t = 0; t < nb; ++t) {
      const std::size_t k = (k0 + t) % nb;
      if(starts[k] || sides_.empty()) sides_.push_back(Side());
      sides_.back().halfedges.push_back(boundary_[k]);
      side_of[k] = sides_.size() - 1;
    }
    for(std::size_t s = 0; s < sides_.size(); ++s) {
      const Halfedge_index first = sides_[s].halfedges.front();
      sides_[s].twin = side_of[index_of[m_.opposite(first)]];
      sides_[s].pairing = transition(first).normalized();
    }
  }

  std::shared_ptr<const Metric> metric_ptr_;
  const Metric& metric_;
  const Mesh& m_;
  Vertex_index base_;
  bool hyperbolic_ = true;
  Halfedge_index root_;
  std::vector<double> dist_;
  std::vector<Halfedge_index> parent_;
  std::vector<char> cut_, greedy_cut_;
  std::vector<Halfedge_index> generator_edge_;
  std::vector<std::vector<Halfedge_index> > loops_;
  std::vector<internal::Cplx> pos_;
  std::vector<internal::Moebius> hol_;
  std::vector<Halfedge_index> boundary_;
  std::vector<std::pair<std::size_t, int> > relator_;
  std::vector<Side> sides_;
};

} // namespace Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H
