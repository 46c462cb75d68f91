// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shortest loop through the base point of an element of pi_1(S, p) given as a product of deck
// transformations, at any length, without iterative straightening: the geodesic is located piece by piece
// in local frames from its two end points, which are known there to double precision.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORD_GEODESIC_H
#define CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORD_GEODESIC_H

#include <CGAL/Surface_shortest_words/shortest_homotopic_path.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_shortest_words {
namespace internal {

// a point of the closed unit disk (rounding may push an image of an ideal point slightly outside)
inline Cplx clamp_to_disk(const Cplx& z)
{
  const double r = std::abs(z);
  return r > 1 ? z / r : z;
}

// the parameter lambda of the point of the Klein chord kA + lambda (kB - kA) nearest to the Klein point k
inline double chord_parameter(const Cplx& kA, const Cplx& kB, const Cplx& k)
{
  const Cplx d = kB - kA;
  return ((k - kA).real() * d.real() + (k - kA).imag() * d.imag()) / std::norm(d);
}

// A frame of the universal cover: the layer's chart of `step.face` recentred at the point `q` of that face
// (at the corner `step.in` if `q` is a vertex point): trace_geodesic's start chart at q.
template <class Surface>
struct Cover_frame
{
  typename Surface::Point q;
  typename Surface::Step step; // step.face: the face; step.in: the corner of q (vertex points)
};

// A point of the geodesic gamma where it crosses an edge, or a mesh vertex that gamma passes within
// `kink`, in a frame of the universal cover (a lift of the base chart: the base face laid out as in the
// layer's chart recentred at the base corner).
template <class Surface>
struct Geodesic_anchor
{
  typename Surface::Point q;   // the surface point (an edge point, or a vertex point)
  typename Surface::Step first; // its face (the face gamma is read in) for trace_geodesic
  Isometry to_start;           // frame coordinates -> coordinates of trace_geodesic's start chart at q
  Cplx Q;                      // q in frame coordinates
  double kink = 0;             // a vertex anchor: bound on its distance to gamma (0 for an edge point)
};

// An edge crossing of gamma closer to a vertex than this fraction of the edge is no safe anchor (the
// trace that ends there must find it on the right side of the vertex): the anchor is the vertex itself.
// (Closer than 1e-6 was walked along gamma to the next safe crossing: a based geodesic of a power of a loop
// through the vertex passes every lift of that vertex within 1e-9 to 1e-5, so no crossing was safe, the
// anchors were skipped and the pieces grew to 20 and 33 units, beyond double precision: the one-vertex
// genus-3 fuzz inputs of issue 10; an anchor 2e-6 from a vertex was found on the wrong side of it.)
constexpr double anchor_vertex_snap = 1e-5;

// Upper bound on the length a traced piece of length `l` gains at an end that is a vertex anchor `kink`
// away from gamma instead of a point of gamma: r^2 coth(l) / 2 to second order (twice that here), and at
// most r (triangle inequality).
inline double kink_excess(double r, double l)
{
  if(r == 0) return 0;
  return (std::min)(r, r * r / std::tanh((std::max)(l, 1e-300)));
}

// Where the line o + l d (Klein model) leaves the triangle K: the largest l over the edges i that the line
// meets within [-tol, 1 + tol] of their own parameter; `edge` receives i, -1 if no edge is met.
inline double klein_exit(const Cplx K[3], Cplx o, Cplx d, double tol, int& edge)
{
  double best = -std::numeric_limits<double>::infinity();
  edge = -1;
  for(int i = 0; i < 3; ++i) {
    const Cplx P = K[i] - o, e = K[(i + 1) % 3] - K[i];
    const double den = cross(d, e);
    if(den == 0) continue;
    const double l = cross(P, e) / den, w = cross(P, d) / den;
    if(w < -tol || w > 1 + tol) continue;
    if(l > best) { best = l; edge = i; }
  }
  return best;
}

// Locates the geodesic gamma through the points A and B of the closed disk (frame coordinates; either may be
// ideal) near the origin of the frame: walks from the base face to the face containing the foot of the
// perpendicular from the origin to gamma, then takes the point where gamma leaves that face towards B, or
// the vertex of that edge if the point is within `anchor_vertex_snap` (relative) of it (or within
// `vertex_snap`, if larger). Returns false (no anchor) if the walk exceeds its step bound.
template <class Surface>
bool anchor_on_geodesic(const Surface& s, const Cover_frame<Surface>& frame, Cplx A, Cplx B, double vertex_snap,
                        Geodesic_anchor<Surface>& out)
{
  typedef typename Surface::Point Point;
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  Transient_chart<Surface> tr(s);
  tr.set_face(frame.step.face);
  tr.recentre(s.position(frame.q, frame.step.in, tr.face_chart()));
  tr.reset_accumulated();
  Cplx kA = to_klein(A), kB = to_klein(B);
  if(!(std::norm(kB - kA) > 1e-24)) return false;
  // the foot of the perpendicular from the origin (in the Klein model, the Euclidean foot: the reflection in
  // the diameter perpendicular to the chord preserves both)
  Cplx X = from_klein(kA + chord_parameter(kA, kB, Cplx(0, 0)) * (kB - kA));
  Cplx S = to_cplx(Disk::barycenter(to_point(tr.z()[0]), to_point(tr.z()[1]), to_point(tr.z()[2])));
  auto move_all = [&](const Isometry& m) {
    tr.transform(m);
    A = clamp_to_disk(apply_isometry(m, A)); B = clamp_to_disk(apply_isometry(m, B));
    X = apply_isometry(m, X); S = apply_isometry(m, S);
  };
  move_all(to_origin(S));
  // into the neighbour across edge i of the current face, recentred at its barycentre
  auto step_across = [&](int i) {
    tr.unfold(tr.halfedge_at(i));
    move_all(to_origin(to_cplx(Disk::barycenter(to_point(tr.z()[0]), to_point(tr.z()[1]), to_point(tr.z()[2])))));
  };
  // straight walk (Klein model: geodesics are straight) from the barycentre of the base face to X
  for(std::size_t step = 0;; ++step) {
    if(step > 100000) return false;
    Cplx K[3];
    for(int i = 0; i < 3; ++i) K[i] = to_klein(tr.z()[i]);
    const Cplx kX = to_klein(X), kS = to_klein(S);
    bool inside = true;
    for(int i = 0; i < 3; ++i)
      if(cross(K[(i + 1) % 3] - K[i], kX - K[i]) < -1e-13) inside = false;
    if(inside) break;
    int best_i = -1;
    const double best_s = klein_exit(K, kS, kX - kS, 1e-9, best_i);
    if(best_i < 0) return false;
    // the walk leaves the face at or beyond X: X lies in it up to rounding (X at a vertex or on an edge: else
    // the walk could turn around that vertex, or back and forth across the edge, forever)
    if(best_s >= 1 - 1e-9) break;
    step_across(best_i);
  }
  // where gamma leaves the face towards B
  kA = to_klein(A); kB = to_klein(B);
  const Cplx D = kB - kA;
  Cplx K[3];
  for(int i = 0; i < 3; ++i) K[i] = to_klein(tr.z()[i]);
  int best_i = -1;
  const double best_l = klein_exit(K, kA, D, 1e-12, best_i);
  if(best_i < 0) return false;
  Cplx zx = from_klein(kA + best_l * D);
  const Cplx za = tr.z()[best_i], zb = tr.z()[(best_i + 1) % 3];
  const double da = hyperbolic_distance(za, zx), db = hyperbolic_distance(zx, zb);
  const double t = da / (da + db), snap = (std::max)(anchor_vertex_snap, vertex_snap);
  const halfedge_descriptor h = tr.halfedge_at(best_i);
  out.first = typename Surface::Step();
  out.first.face = tr.current_face();
  halfedge_descriptor corner = halfedge_descriptor();
  if(t > snap && t < 1 - snap) {
    out.q = Point::on_edge(h, t);
    out.kink = 0;
  } else {
    // gamma passes that close to a vertex (e.g. a geodesic along mesh edges on a symmetric mesh, or
    // converging to an axis through mesh vertices): anchored at the vertex, at its corner in the current face
    const int iv = t < 0.5 ? best_i : (best_i + 1) % 3; // z[iv] = source(halfedge_at(iv))
    corner = tr.halfedge_at((iv + 2) % 3);             // target = that vertex
    out.q = s.needs_corners() ? s.corner(corner) : Point::vertex(target(corner, s.mesh()));
    out.first.in = out.first.out = corner;
    out.kink = t < 0.5 ? da : db;
    zx = tr.z()[iv];
  }
  // frame -> current chart -> the layer's chart of the face -> recentred at q (trace_geodesic's start chart)
  const typename Surface::Face_chart layer = s.chart(tr.current_face());
  const Isometry L = Disk::isometry_from_pairs(layer.z[0], layer.z[1], to_point(tr.z()[0]), to_point(tr.z()[1]));
  out.to_start = to_origin(s.position(out.q, corner, layer)) * L.inverse() * tr.accumulated();
  out.Q = apply_isometry(tr.accumulated().inverse(), zx);
  return true;
}

// The shortest path from the origin of frame 0 to the origin of frame n in the homotopy class given by a
// chain of frames of the universal cover: D_k (k = 1..n) maps coordinates of frame k to those of frame k-1,
// each moving the origin by a bounded distance, their product a quasi-geodesic (the pieces of a geodesic
// word, or of a path cut into geodesic pieces that cannot be merged). The lift of the result is the geodesic
// gamma from 0 to D_1 ... D_n (0). In frame k (the lattice point or path point p_k = D_1 ... D_k (0),
// coordinates M_k^-1, M_k = D_1 ... D_k), gamma is the geodesic through A_k = M_k^-1 (0) and
// B_k = D_k+1 ... D_n (0): both are computed by sweeps of Moebius maps, which contract towards the frame (a
// point far away, or ideal, keeps its direction to double precision), so gamma is known near p_k to double
// precision whatever its length. gamma is anchored at an edge crossing near each p_k, and the pieces between
// consecutive anchors are traced (trace_geodesic) in the chart of the first: every point within a piece's
// length of its chart's origin. Cost: O(n + faces crossed by gamma). Throws Precision_error if a piece cannot
// be traced (two consecutive anchors farther apart than max_lift_distance).
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
geodesic_of_frames(const Surface& s, const std::vector<Cover_frame<Surface> >& frames, const std::vector<Isometry>& D,
                   const Shortest_path_options& o)
{
  typedef typename Surface::Path Path;
  const std::size_t n = D.size();
  CGAL_assertion(frames.size() == n + 1 && n >= 1);
  std::vector<Cplx> A(n + 1), B(n + 1);
  A[0] = Cplx(0, 0);
  for(std::size_t k = 1; k <= n; ++k) A[k] = clamp_to_disk(apply_isometry(D[k - 1].inverse(), A[k - 1]));
  B[n] = Cplx(0, 0);
  for(std::size_t k = n; k-- > 0;) B[k] = clamp_to_disk(apply_isometry(D[k], B[k + 1]));
  // anchors: the start, one anchor near each p_k progressing along gamma, the end
  Geodesic_anchor<Surface> prev;
  prev.q = frames[0].q;
  prev.first = frames[0].step;
  prev.Q = Cplx(0, 0);
  std::size_t prev_k = 0;
  Isometry since; // D_{prev_k + 1} ... D_k: frame k -> frame prev_k
  Shortest_path_result<typename Surface::Triangle_mesh> res;
  Path& cur = res.path;
  // (the end mismatch of the result also bounds what its vertex anchors add to its length: kink_excess())
  auto trace_to = [&](const Cplx& X, const typename Surface::Point& end, double end_kink) {
    const Cplx T = apply_isometry(prev.to_start, X); // (identity at the start: frame 0 is the start chart)
    const Shortest_path_result<typename Surface::Triangle_mesh> piece = trace_geodesic(s, prev.q, prev.first, T, end, o, 0);
    if(cur.empty()) cur = piece.path;
    else { cur.back() = piece.path.front(); cur.insert(cur.end(), piece.path.begin() + 1, piece.path.end()); }
    res.length += piece.length;
    res.end_mismatch += piece.end_mismatch + kink_excess(prev.kink, piece.length) + kink_excess(end_kink, piece.length);
    res.embedded_faces += piece.embedded_faces;
    if(o.progress) o.progress(res.embedded_faces);
  };
  for(std::size_t k = 1; k <= n; ++k) {
    since = (since * D[k - 1]).normalized();
    if(k == n) { trace_to(apply_isometry(since, Cplx(0, 0)), frames[n].q, 0.0); break; }
    Geodesic_anchor<Surface> a;
    if(!anchor_on_geodesic(s, frames[k], A[k], B[k], o.vertex_snap, a)) continue;
    // in the frame of the previous anchor: ahead of it along gamma (towards B), within one chart
    const Cplx X = apply_isometry(since, a.Q);
    const double lx = chord_parameter(to_klein(A[prev_k]), to_klein(B[prev_k]), to_klein(X));
    const double lp = chord_parameter(to_klein(A[prev_k]), to_klein(B[prev_k]), to_klein(prev.Q));
    if(!(lx > lp) || hyperbolic_distance(prev.Q, X) < 0.5) continue;
    trace_to(X, a.q, a.kink);
    prev = a; prev_k = k; since = Isometry();
  }
  res.lift_distance = res.length;
  return res;
}

// The shortest loop through the base point p (at the corner `base_corner` of `base_face`) of the element
// D_1 D_2 ... D_n, the D_k isometries of the base frame (the base face's layer chart recentred at p), each
// moving the origin by a bounded distance, their product a quasi-geodesic: `geodesic_of_frames()` with every
// frame the base frame (the frame of the lattice point p_k is the base frame moved by M_k).
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
geodesic_of_deck_product(const Surface& s, typename Surface::face_descriptor base_face,
                         typename Surface::halfedge_descriptor base_corner, const std::vector<Isometry>& D,
                         const Shortest_path_options& o)
{
  Cover_frame<Surface> f;
  f.q = s.needs_corners() ? s.corner(base_corner) : Surface::Point::vertex(target(base_corner, s.mesh()));
  f.step.face = base_face; f.step.in = f.step.out = base_corner;
  return geodesic_of_frames(s, std::vector<Cover_frame<Surface> >(D.size() + 1, f), D, o);
}

// The lift of a path by chart chaining: the path is cut into geodesic pieces (`geodesic_pieces()`: each
// traced in one chart, adjacent pieces not mergeable into a geodesic shorter than 0.4 max_lift_distance),
// whose concatenation is cut again at points q_k every 0.4 max_lift_distance units of its length; at each
// q_k a frame (the layer's chart of the face the path leaves q_k in, recentred at q_k); D_k, from frame k to
// frame k-1, is the development of the crossings between q_k-1 and q_k in one chart (every point within
// 0.4 max_lift_distance of frame k-1's origin, known to about 1e-16 e^10). Then the geodesic in the universal cover (`geodesic_of_frames()`).
// No iteration: O(n + m) for a path meeting n faces whose result crosses m faces.
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_path_chained(const Surface& surface, const typename Surface::Path& path, const Shortest_path_options& options)
{
  typedef typename Surface::Path Path;
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  std::size_t faces = 0;
  const std::vector<Path> pieces = geodesic_pieces(surface, path, options, 0.4 * options.max_lift_distance, faces);
  Path cur = pieces.front();
  for(std::size_t i = 1; i < pieces.size(); ++i) {
    cur.back() = pieces[i].front();
    cur.insert(cur.end(), pieces[i].begin() + 1, pieces[i].end());
  }
  // junctions every `reach` units of length along the broken geodesic (a piece may be as long as one chart:
  // its development would carry errors of about 1e-16 e^25 = 7e-6)
  const double reach = 0.4 * options.max_lift_distance;
  std::vector<std::size_t> junction(1, 0);
  double acc = 0;
  for(std::size_t i = 0; i + 1 < cur.size(); ++i) {
    const double l = surface.path_length(Path{cur[i], cur[i + 1]});
    if(acc > 0 && acc + l > reach) { junction.push_back(i); acc = 0; }
    acc += l;
  }
  junction.push_back(cur.size() - 1);
  const std::vector<typename Surface::Step> st = surface.steps(cur);
  const std::size_t n = junction.size() - 1;
  std::vector<Cover_frame<Surface> > frames(n + 1);
  std::vector<Isometry> D(n);
  for(std::size_t k = 0; k <= n; ++k) {
    frames[k].q = cur[junction[k]];
    if(k < n) frames[k].step = st[junction[k]];
    else { frames[k].step.face = st.back().face; frames[k].step.in = st.back().out; }
  }
  std::vector<halfedge_descriptor> crossings;
  for(std::size_t k = 1; k <= n; ++k) {
    crossings.clear();
    const std::size_t a = junction[k - 1], b = junction[k];
    auto out = boost::make_function_output_iterator([&crossings](halfedge_descriptor h) { crossings.push_back(h); });
    for(std::size_t i = a + 1; i < b; ++i) surface.crossings_at(cur[i], st[i - 1], st[i], out);
    if(k < n) surface.crossings_at(cur[b], st[b - 1], st[b], out); // into frame k's face
    const Transient_chart<Surface> chart =
      develop_crossings(surface, frames[k - 1].step.face, frames[k - 1].q, frames[k - 1].step.in, crossings, options);
    faces += chart.count();
    CGAL_assertion(chart.current_face() == frames[k].step.face);
    // frame k -> the layer's chart of its face -> the developed chart -> frame k-1
    const typename Surface::Face_chart layer = surface.chart(frames[k].step.face);
    const int i0 = chart.index_of(layer.h[0]), i1 = chart.index_of(layer.h[1]);
    const Isometry L = Disk::isometry_from_pairs(layer.z[0], layer.z[1], to_point(chart.z()[i0]), to_point(chart.z()[i1]));
    const Cplx qk = surface.position(frames[k].q, frames[k].step.in, layer);
    D[k - 1] = (chart.accumulated().inverse() * L * to_origin(qk).inverse()).normalized();
  }
  Shortest_path_result<typename Surface::Triangle_mesh> res = geodesic_of_frames(surface, frames, D, options);
  res.embedded_faces += faces;
  return res;
}

} // namespace internal
} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORD_GEODESIC_H
