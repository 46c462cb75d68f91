// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shortest homotopic paths (thesis Algorithm 2, transient embedding) and loops (Algorithm 3, iterated
// re-basing) on a closed hyperbolic surface.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_HOMOTOPIC_PATH_H
#define CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_HOMOTOPIC_PATH_H

#include <CGAL/Surface_shortest_words/Hyperbolic_surface.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Hyperbolic_geometry_named_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <sstream>

CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_tolerance_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_max_lift_distance_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_vertex_snap_t)

namespace CGAL {
namespace Surface_shortest_words {

/*!
  \ingroup PkgSurfaceShortestWordsRef
  Numerical parameters of the shortest path computations (see the user manual, section "Numerical care").
*/
struct Shortest_path_options
{
  /// radius of one chart: a one-chart computation keeps every lifted point within this hyperbolic distance
  /// of the chart's origin (double precision keeps about 16 digits; at distance d a point of the Poincare
  /// disk is known to about 1e-16 e^d); longer paths are chained through charts of this radius
  double max_lift_distance = 25.0;
  /// a crossing closer than this fraction of an edge to a vertex is snapped to the vertex
  double vertex_snap = 1e-9;
  /// progress callback (number of faces processed so far); called every 2^16 faces if set
  std::function<void(std::size_t)> progress;
};

/// \ingroup PkgSurfaceShortestWordsRef
/// \throws CGAL::Invalid_option_error unless 0 < max_lift_distance <= 36 and 0 <= vertex_snap <= 1e-3
/// (a larger snap moves crossings visibly and gives longer "shortest" paths)
inline void check_options(const Shortest_path_options& o)
{
  if(!(o.max_lift_distance > 0 && o.max_lift_distance <= 36))
    throw CGAL::Invalid_option_error("Surface_shortest_words: max_lift_distance must be in (0, 36] (at hyperbolic distance d "
                                     "a point of the Poincare disk has 1 - |z| ~ 2 e^-d, below double precision beyond 36)");
  if(!(o.vertex_snap >= 0 && o.vertex_snap <= 1e-3))
    throw CGAL::Invalid_option_error("Surface_shortest_words: vertex_snap must be in [0, 1e-3]");
}

namespace parameters {
/// relative length change below which `shortest_homotopic_loop()` stops
CGAL_HYPERBOLIC_NAMED_PARAMETER(tolerance, ssw_tolerance_t)
/// `Shortest_path_options::max_lift_distance`
CGAL_HYPERBOLIC_NAMED_PARAMETER(max_lift_distance, ssw_max_lift_distance_t)
/// `Shortest_path_options::vertex_snap`
CGAL_HYPERBOLIC_NAMED_PARAMETER(vertex_snap, ssw_vertex_snap_t)
} // namespace parameters

/// the path options given by named parameters (defaults of `Shortest_path_options` otherwise), checked
template <class NP>
Shortest_path_options path_options(const NP& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Shortest_path_options o;
  o.max_lift_distance = choose_parameter(get_parameter(np, internal_np::ssw_max_lift_distance_t_v), o.max_lift_distance);
  o.vertex_snap = choose_parameter(get_parameter(np, internal_np::ssw_vertex_snap_t_v), o.vertex_snap);
  check_options(o);
  return o;
}

/// \ingroup PkgSurfaceShortestWordsRef
/// result of `shortest_homotopic_path()` and of the loop functions
template <class TriangleMesh>
struct Shortest_path_result
{
  Surface_path<TriangleMesh> path;  ///< the shortest path: start, edge crossings / vertices, end
  double length = 0;                ///< its hyperbolic length
  double lift_distance = 0;         ///< distance of the lifted end points in the universal cover
  std::size_t embedded_faces = 0;   ///< faces embedded (transiently) while lifting and tracing
  std::size_t iterations = 0;       ///< re-basing iterations (loops only)
  bool converged = true;            ///< loops only: the length change fell below the tolerance
};

namespace internal {

// The transient embedding of Algorithm 2: a single face laid out in the Poincare disk (the chart), moved
// from face to face by unfolding across edges, re-centred so that the current point stays at the origin.
template <class Surface>
class Transient_chart
{
public:
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  typedef typename Surface::face_descriptor face_descriptor;
  typedef typename Surface::vertex_descriptor vertex_descriptor;

  explicit Transient_chart(const Surface& s) : s_(s) {}

  void set_face(face_descriptor f) { s_.layout_face(f, h0_, z_); face_ = f; ++count_; }
  face_descriptor current_face() const { return face_; }
  halfedge_descriptor h0() const { return h0_; }
  const Cplx* z() const { return z_; }
  std::size_t count() const { return count_; }
  const Isometry& accumulated() const { return phi_; }

  int index_of(halfedge_descriptor h) const
  {
    halfedge_descriptor g = h0_;
    for(int i = 0; i < 3; ++i, g = next(g, s_.mesh())) if(g == h) return i;
    return -1;
  }
  halfedge_descriptor halfedge_at(int i) const
  {
    halfedge_descriptor g = h0_;
    for(int k = 0; k < i; ++k) g = next(g, s_.mesh());
    return g;
  }
  int index_of_vertex(vertex_descriptor v) const
  {
    halfedge_descriptor g = h0_;
    for(int i = 0; i < 3; ++i, g = next(g, s_.mesh())) if(source(g, s_.mesh()) == v) return i;
    return -1;
  }

  /// moves the chart to the face across the edge of `h` (a halfedge of the current face)
  void unfold(halfedge_descriptor h)
  {
    const int i = index_of(h);
    CGAL_assertion(i >= 0);
    const Cplx A = z_[(i + 1) % 3], B = z_[i]; // target(h), source(h)
    const halfedge_descriptor o = opposite(h, s_.mesh());
    const halfedge_descriptor on = next(o, s_.mesh()), op = next(on, s_.mesh());
    h0_ = o;
    z_[0] = A; z_[1] = B;
    z_[2] = third_vertex(A, B, s_.length(on), s_.length(op), s_.length(o));
    face_ = face(o, s_.mesh());
    ++count_;
  }

  /// rotates the chart around vertex `v` of the current face until it reaches face `target`
  /// (the shorter way round); returns the halfedges crossed
  void rotate_to(vertex_descriptor v, face_descriptor target)
  {
    if(face_ == target) return;
    // count the steps both ways
    const int ccw = steps_around(v, target, true), cw = steps_around(v, target, false);
    if(ccw < 0) throw Invalid_path_error("Surface_shortest_words: face not incident to the vertex");
    const bool use_ccw = ccw <= cw;
    const int n = use_ccw ? ccw : cw;
    for(int k = 0; k < n; ++k) unfold(rotation_halfedge(v, use_ccw));
  }

  /// the halfedge of the current face whose edge is crossed when turning around `v` (ccw or cw)
  halfedge_descriptor rotation_halfedge(vertex_descriptor v, bool ccw) const
  {
    const int i = index_of_vertex(v);
    // halfedge entering v is at index i-1, leaving v at index i
    return ccw ? halfedge_at((i + 2) % 3) : halfedge_at(i);
  }

  /// applies the isometry f to the chart (new coordinates = f(old)) and records it
  void transform(const Isometry& f)
  {
    for(int k = 0; k < 3; ++k) z_[k] = apply_isometry(f, z_[k]);
    phi_ = f * phi_;
    if(++since_normalize_ >= 8) { phi_ = phi_.normalized(); since_normalize_ = 0; }
  }

  void recentre(const Cplx& c)
  {
    if(std::norm(c) == 0) return;
    transform(to_origin(c));
  }

  void reset_accumulated() { phi_ = Isometry(); }

private:
  int steps_around(vertex_descriptor v, face_descriptor target, bool ccw) const
  {
    const auto& tm = s_.mesh();
    // find the halfedge of face_ with target v
    halfedge_descriptor h = halfedge_at((index_of_vertex(v) + 2) % 3);
    int steps = 0;
    face_descriptor f = face_;
    while(f != target) {
      h = ccw ? prev(opposite(h, tm), tm) : opposite(next(h, tm), tm);
      f = face(h, tm);
      if(++steps > 100000 || f == face_) return -1;
    }
    return steps;
  }

  const Surface& s_;
  face_descriptor face_{};
  halfedge_descriptor h0_{};
  Cplx z_[3];
  Isometry phi_;
  int since_normalize_ = 0;
  std::size_t count_ = 0;
};


// Exact reduction of a sequence of crossed edges (each crossing goes from face(h) to face(opposite(h))):
// an immediate backtrack cancels, and more than half a turn around a vertex is replaced by the shorter turn
// the other way (a full turn disappears). Both are homotopies that fix the end points. Stack based, linear.
template <class TriangleMesh>
class Crossing_reducer
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  struct Entry { halfedge_descriptor h; std::size_t ccw, cw; };
public:
  explicit Crossing_reducer(const TriangleMesh& tm) : tm_(tm) {}

  void push(halfedge_descriptor c)
  {
    todo_.push_back(c);
    while(!todo_.empty()) {
      c = todo_.front(); todo_.pop_front();
      if(!st_.empty() && st_.back().h == opposite(c, tm_)) { st_.pop_back(); continue; }
      std::size_t rccw = 1, rcw = 1;
      if(!st_.empty()) {
        if(c == prev(opposite(st_.back().h, tm_), tm_)) rccw = st_.back().ccw + 1;
        if(c == next(opposite(st_.back().h, tm_), tm_)) rcw = st_.back().cw + 1;
      }
      st_.push_back(Entry{c, rccw, rcw});
      const std::size_t dccw = CGAL::halfedges_around_target(target(c, tm_), tm_).size();
      const std::size_t dcw = CGAL::halfedges_around_target(source(c, tm_), tm_).size();
      std::vector<halfedge_descriptor> rep;
      if(2 * rccw > dccw) {
        // counterclockwise around target(c): replace by the clockwise turn
        halfedge_descriptor h = st_[st_.size() - rccw].h;
        const auto B = face(opposite(c, tm_), tm_);
        st_.resize(st_.size() - rccw);
        while(face(h, tm_) != B) { rep.push_back(next(h, tm_)); h = opposite(next(h, tm_), tm_); }
      } else if(2 * rcw > dcw) {
        // clockwise around source(c): replace by the counterclockwise turn
        halfedge_descriptor h = prev(st_[st_.size() - rcw].h, tm_);
        const auto B = face(opposite(c, tm_), tm_);
        st_.resize(st_.size() - rcw);
        while(face(h, tm_) != B) { rep.push_back(h); h = prev(opposite(h, tm_), tm_); }
      } else {
        continue;
      }
      todo_.insert(todo_.begin(), rep.begin(), rep.end());
    }
  }

  std::vector<halfedge_descriptor> result() const
  {
    std::vector<halfedge_descriptor> r;
    r.reserve(st_.size());
    for(const Entry& e : st_) r.push_back(e.h);
    return r;
  }

private:
  const TriangleMesh& tm_;
  std::vector<Entry> st_;
  std::deque<halfedge_descriptor> todo_;
};

// the crossings from face a to face b, both containing point p (across the edge of p, or the shorter way
// around the vertex p)
template <class Surface, class Reducer>
void crossings_between(const Surface& s, const typename Surface::Point& p, typename Surface::face_descriptor a,
                       typename Surface::face_descriptor b, Reducer& out)
{
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  const auto& tm = s.mesh();
  if(a == b) return;
  if(!p.on_vertex) {
    halfedge_descriptor h = p.h;
    if(face(h, tm) != a) h = opposite(h, tm);
    if(face(h, tm) != a || face(opposite(h, tm), tm) != b) throw Invalid_path_error("Surface_shortest_words: inconsistent path");
    out.push(h);
    return;
  }
  halfedge_descriptor h0 = halfedge(a, tm);
  while(target(h0, tm) != p.v) h0 = next(h0, tm);
  std::vector<halfedge_descriptor> ccw, cw;
  halfedge_descriptor h = h0;
  while(face(h, tm) != b) {
    ccw.push_back(h); h = prev(opposite(h, tm), tm);
    if(h == h0) throw Invalid_path_error("Surface_shortest_words: face not incident to the vertex");
  }
  h = h0;
  while(face(h, tm) != b) { cw.push_back(next(h, tm)); h = opposite(next(h, tm), tm); }
  for(halfedge_descriptor c : (ccw.size() <= cw.size() ? ccw : cw)) out.push(c);
}

template <class Surface, class Chart>
void move_across_point(const Surface& s, Chart& chart, const typename Surface::Point& p,
                       typename Surface::face_descriptor target)
{
  if(chart.current_face() == target) return;
  const auto& tm = s.mesh();
  if(p.on_vertex) { chart.rotate_to(p.v, target); return; }
  typename Surface::halfedge_descriptor h = p.h;
  if(face(h, tm) != chart.current_face()) h = opposite(h, tm);
  if(face(h, tm) != chart.current_face() || face(opposite(h, tm), tm) != target)
    throw Invalid_path_error("Surface_shortest_words: inconsistent path");
  chart.unfold(h);
}

// true if direction u (from the origin, where vertex v of the chart's face sits) lies in the face's angle at v
template <class Chart>
bool in_sector(const Chart& chart, int iv, const Cplx& u, double tol)
{
  const Cplx A = chart.z()[(iv + 1) % 3], B = chart.z()[(iv + 2) % 3];
  return cross(A, u) >= -tol * std::abs(A) && cross(u, B) >= -tol * std::abs(B);
}

// rotates the chart around vertex v (at the origin) to the face whose angle at v contains direction u
template <class Surface, class Chart>
void rotate_to_direction(const Surface& s, Chart& chart, typename Surface::vertex_descriptor v, const Cplx& u)
{
  const std::size_t deg = CGAL::halfedges_around_target(v, s.mesh()).size();
  for(double tol : {0.0, 1e-12, 1e-9, 1e-6}) {
    for(std::size_t k = 0; k <= deg; ++k) {
      if(in_sector(chart, chart.index_of_vertex(v), u, tol)) return;
      chart.unfold(chart.rotation_halfedge(v, true));
    }
  }
  throw Precision_error("Surface_shortest_words: no face around a vertex contains the geodesic direction");
}

} // namespace internal

namespace internal {

// Algorithm 2 in one chart (the lifted path must stay within max_lift_distance of its start)
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_path_one_chart(const Surface& surface, const typename Surface::Path& path,
                        const Shortest_path_options& options)
{
  typedef typename Surface::Point Point;
  typedef typename Surface::face_descriptor face_descriptor;
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  typedef internal::Cplx Cplx;
  const auto& tm = surface.mesh();

  surface.check_path(path);
  Shortest_path_result<typename Surface::Triangle_mesh> res;
  if(path.size() == 1) { res.path = path; return res; }

  // ---- lift (steps 1-3): the faces met by the path, as the sequence of crossed edges (a path in the dual
  // graph of the universal cover), exactly reduced (backtracks cancelled, turns around a vertex by more than
  // half its degree replaced by the turn the other way: both fix the lifted end point), then embedded
  // transiently: one face at a time, unfolded across the next edge, the chart re-centred at every step.
  internal::Crossing_reducer<typename Surface::Triangle_mesh> reducer(tm);
  face_descriptor f = surface.common_face(path[0], path[1], boost::graph_traits<typename Surface::Triangle_mesh>::null_face());
  const face_descriptor start_face = f;
  for(std::size_t i = 1; i + 1 < path.size(); ++i) {
    const face_descriptor fn = surface.common_face(path[i], path[i + 1], f);
    internal::crossings_between(surface, path[i], f, fn, reducer);
    f = fn;
  }
  internal::Transient_chart<Surface> chart(surface);
  chart.set_face(start_face);
  chart.recentre(surface.position_in_face(path[0], chart.h0(), chart.z()));
  chart.reset_accumulated();
  std::size_t next_report = std::size_t(1) << 16;
  const double max_alpha_beta = std::tanh(options.max_lift_distance / 2);
  for(halfedge_descriptor c : reducer.result()) {
    chart.unfold(c);
    chart.recentre(chart.z()[0]);
    // the chart's origin must stay within max_lift_distance of the start (else rounding errors grow
    // like e^distance): |Phi^-1(0)| = |beta| / |alpha|
    const Isometry& phi = chart.accumulated();
    const double a2 = phi.alpha_real() * phi.alpha_real() + phi.alpha_imag() * phi.alpha_imag();
    const double b2 = phi.beta_real() * phi.beta_real() + phi.beta_imag() * phi.beta_imag();
    if(!(b2 <= max_alpha_beta * max_alpha_beta * a2))
      throw Precision_error("Surface_shortest_words: the lifted path leaves the double precision range (max_lift_distance)");
    if(options.progress && chart.count() >= next_report) { options.progress(chart.count()); next_report <<= 1; }
  }
  CGAL_assertion(chart.current_face() == f);
  const Cplx end_local = surface.position_in_face(path.back(), chart.h0(), chart.z());
  Cplx T = internal::apply_isometry(chart.accumulated().inverse(), end_local);
  res.lift_distance = internal::distance_to_origin(T);
  if(!(res.lift_distance <= options.max_lift_distance)) {
    std::ostringstream os;
    os << "Surface_shortest_words: the lifted end point lies at hyperbolic distance " << res.lift_distance
       << " > max_lift_distance = " << options.max_lift_distance << " (beyond double precision)";
    throw Precision_error(os.str());
  }
  std::size_t lifted = chart.count();

  // ---- trace (steps 4-7): the geodesic from the start towards T, one face at a time
  res.path.push_back(path[0]);
  const Point& end = path.back();
  if(res.lift_distance < 1e-12) {
    if(!surface.same_point(path[0], end)) res.path.push_back(end);
    res.embedded_faces = lifted;
    return res;
  }
  internal::Transient_chart<Surface> tr(surface);
  tr.set_face(start_face);
  // the same deterministic layout as the start chart of the lift
  tr.recentre(surface.position_in_face(path[0], tr.h0(), tr.z()));
  tr.reset_accumulated();
  // T is expressed in the start chart, which equals tr's chart (same face, same construction)
  Point cur = path[0];
  // choose the start face containing the direction of T
  {
    const Cplx u = T / std::abs(T);
    if(cur.on_vertex) {
      internal::rotate_to_direction(surface, tr, cur.v, u);
    } else {
      halfedge_descriptor h = cur.h;
      if(face(h, tm) != tr.current_face()) h = opposite(h, tm);
      const int i = tr.index_of(h);
      const Cplx third = tr.z()[(i + 2) % 3], a = tr.z()[i], b = tr.z()[(i + 1) % 3];
      const double side_third = internal::cross(b - a, third - a), side_u = internal::cross(b - a, u);
      if(side_third * side_u < 0) tr.unfold(h);
    }
  }
  const std::vector<face_descriptor> end_faces = surface.faces_of(end);
  const std::size_t max_steps = 64 * (lifted + 1000);
  std::size_t steps = 0;
  while(true) {
    if(++steps > max_steps) throw Precision_error("Surface_shortest_words: geodesic tracing did not reach the end point");
    if(options.progress && lifted + tr.count() >= next_report) { options.progress(lifted + tr.count()); next_report <<= 1; }
    const Cplx u = T / std::abs(T);
    const Cplx* z = tr.z();
    Cplx k[3];
    for(int i = 0; i < 3; ++i) k[i] = internal::to_klein(z[i]);
    // exit of the ray s u (s > 0) from the face
    double best_s = -1; int best_i = -1;
    for(int i = 0; i < 3; ++i) {
      const Cplx P = k[i], d = k[(i + 1) % 3] - k[i];
      const double den = internal::cross(u, d);
      if(den == 0) continue;
      const double s = internal::cross(P, d) / den, w = internal::cross(P, u) / den;
      if(s <= 1e-14 || w < -1e-9 || w > 1 + 1e-9) continue;
      if(s > best_s) { best_s = s; best_i = i; }
    }
    const double kT = std::abs(internal::to_klein(T));
    const bool end_here = std::find(end_faces.begin(), end_faces.end(), tr.current_face()) != end_faces.end();
    if(best_i < 0 || kT <= best_s * (1 + 1e-12) + 1e-15) {
      if(!end_here) {
        if(best_i < 0) throw Precision_error("Surface_shortest_words: lost the geodesic while tracing");
        // numerically the target is on the exit edge: continue into the next face
        if(kT < best_s * (1 - 1e-9)) throw Precision_error("Surface_shortest_words: traced geodesic misses the end point");
      } else {
        res.length += internal::distance_to_origin(T);
        if(!surface.same_point(res.path.back(), end)) res.path.push_back(end);
        break;
      }
    }
    const Cplx kx = best_s * u;
    const Cplx zx = internal::from_klein(kx);
    const halfedge_descriptor h = tr.halfedge_at(best_i);
    const Cplx za = z[best_i], zb = z[(best_i + 1) % 3];
    const double da = internal::hyperbolic_distance(za, zx), db = internal::hyperbolic_distance(zx, zb);
    const double t = da / (da + db);
    if(t < options.vertex_snap || t > 1 - options.vertex_snap) {
      const auto v = t < 0.5 ? source(h, tm) : target(h, tm);
      const Cplx zv = t < 0.5 ? za : zb;
      res.length += internal::distance_to_origin(zv);
      const Point pv = Point::vertex(v);
      if(!surface.same_point(res.path.back(), pv)) res.path.push_back(pv);
      // re-centre at the vertex and turn to the face containing the new direction
      const internal::Isometry m = internal::to_origin(zv);
      tr.transform(m);
      T = internal::apply_isometry(m, T);
      const Cplx un = T / std::abs(T);
      if(std::find(end_faces.begin(), end_faces.end(), tr.current_face()) != end_faces.end() && end.on_vertex && end.v == v &&
         internal::distance_to_origin(T) < 1e-7) {
        break;
      }
      internal::rotate_to_direction(surface, tr, v, un);
    } else {
      res.length += internal::distance_to_origin(zx);
      res.path.push_back(Point::on_edge(h, t));
      tr.unfold(h);
      const internal::Isometry m = internal::to_origin(zx);
      tr.transform(m);
      T = internal::apply_isometry(m, T);
    }
  }
  res.embedded_faces = lifted + tr.count();
  return res;
}

// Geodesic pieces on a stack: the path is cut into short chunks, each shortened in one chart; a new piece
// is merged with the top of the stack (shortened again as one path) while the merged geodesic is shorter
// than `merge_length`, so backtracking and wandering cancel without any long lift.
template <class Surface>
std::vector<typename Surface::Path>
geodesic_pieces(const Surface& surface, const typename Surface::Path& path, const Shortest_path_options& options,
                double merge_length, std::size_t& faces)
{
  typedef typename Surface::Path Path;
  std::vector<Path> stack;
  std::vector<double> lengths;
  auto concat = [](const Path& a, const Path& b) { Path r(a); r.insert(r.end(), b.begin() + 1, b.end()); return r; };
  std::function<void(const Path&)> push_chunk = [&](const Path& chunk) {
    Shortest_path_result<typename Surface::Triangle_mesh> piece;
    try {
      piece = shortest_path_one_chart(surface, chunk, options);
    } catch(const Precision_error&) {
      if(chunk.size() <= 2) throw;
      const std::size_t mid = chunk.size() / 2;
      push_chunk(Path(chunk.begin(), chunk.begin() + std::ptrdiff_t(mid) + 1));
      push_chunk(Path(chunk.begin() + std::ptrdiff_t(mid), chunk.end()));
      return;
    }
    faces += piece.embedded_faces;
    Path cur = piece.path; double len = piece.length;
    while(!stack.empty()) {
      try {
        Shortest_path_result<typename Surface::Triangle_mesh> m = shortest_path_one_chart(surface, concat(stack.back(), cur), options);
        faces += m.embedded_faces;
        if(m.length > merge_length) break;
        cur = m.path; len = m.length;
        stack.pop_back(); lengths.pop_back();
      } catch(const Precision_error&) { break; }
    }
    stack.push_back(cur); lengths.push_back(len);
  };
  const std::size_t K = 256;
  for(std::size_t i = 0; i + 1 < path.size(); i += K) {
    const std::size_t e = (std::min)(path.size() - 1, i + K);
    push_chunk(Path(path.begin() + std::ptrdiff_t(i), path.begin() + std::ptrdiff_t(e) + 1));
  }
  return stack;
}

// Chart chaining for paths of any length (Birkhoff curve shortening with fixed end points): the path is
// first cut into geodesic pieces (`geodesic_pieces()`), then repeatedly re-cut into windows of path length
// about `window` <= max_lift_distance / 2, each replaced by its shortest homotopic path computed in its own
// chart (`shortest_path_one_chart()`: every point within `window` of that chart's origin, so double
// precision suffices whatever the total length). The cut points alternate between two offsets (0 and
// window / 2), so every cut point of one round lies in the middle of a window of the next and is
// straightened there. A fixed point is a path that is geodesic on every window containing a cut point,
// i.e. a geodesic; in negative curvature the corner angles shrink by a factor of about cosh(window / 2)
// per round, and the length is monotone. Stops after two rounds without relative length change above
// 1e-12 plus two more rounds (corner angles below about 1e-10), or throws `Precision_error` after
// `max_rounds` rounds.
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_path_chained(const Surface& surface, const typename Surface::Path& path, const Shortest_path_options& options)
{
  typedef typename Surface::Path Path;
  Shortest_path_result<typename Surface::Triangle_mesh> res;
  std::size_t faces = 0;
  const std::vector<Path> pieces = geodesic_pieces(surface, path, options, 0.5 * options.max_lift_distance, faces);
  Path cur = pieces.front();
  for(std::size_t i = 1; i < pieces.size(); ++i) cur.insert(cur.end(), pieces[i].begin() + 1, pieces[i].end());
  const double window = (std::min)(10.0, 0.4 * options.max_lift_distance);
  double prev = std::numeric_limits<double>::infinity();
  int quiet = 0, extra = 0;
  // work bound: a spike of excess length E retracts by about window / 2 per round
  const std::size_t max_rounds = 200 + std::size_t(4 * surface.path_length(cur) / window);
  std::vector<double> seg;
  for(std::size_t round = 0;; ++round) {
    if(round >= max_rounds) {
      std::ostringstream os;
      os << "Surface_shortest_words: chart-chained shortening did not converge in " << max_rounds << " rounds";
      throw Precision_error(os.str());
    }
    seg.resize(cur.size() - 1);
    for(std::size_t i = 0; i + 1 < cur.size(); ++i) seg[i] = surface.path_length(Path{cur[i], cur[i + 1]});
    Path next;
    next.reserve(cur.size());
    next.push_back(cur.front());
    double len = 0, acc = 0, cut = (round % 2 == 1) ? 0.5 * window : window;
    std::size_t a = 0;
    for(std::size_t i = 1; i < cur.size(); ++i) {
      acc += seg[i - 1];
      if(acc < cut && i + 1 < cur.size()) continue;
      const Shortest_path_result<typename Surface::Triangle_mesh> r =
        shortest_path_one_chart(surface, Path(cur.begin() + std::ptrdiff_t(a), cur.begin() + std::ptrdiff_t(i) + 1), options);
      next.insert(next.end(), r.path.begin() + 1, r.path.end());
      len += r.length;
      faces += r.embedded_faces;
      a = i;
      cut = acc + window;
    }
    if(next.size() == 1) next.push_back(cur.back());
    cur.swap(next);
    res.length = len;
    if(options.progress) options.progress(faces);
    if(std::abs(prev - len) <= 1e-12 * (std::max)(1.0, len)) ++quiet; else quiet = 0;
    prev = len;
    if(quiet >= 2 && ++extra > 2) break;
  }
  res.path = cur;
  res.lift_distance = res.length;
  res.embedded_faces = faces;
  return res;
}

} // namespace internal

/*!
  \ingroup PkgSurfaceShortestWordsRef
  Computes the shortest path homotopic to `path` with both end points fixed (thesis Algorithm 2).

  The path is lifted to the universal cover (the hyperbolic plane, Poincare disk model) by a transient
  embedding: the sequence of faces it meets (crossed edges, turns around vertices) is first reduced exactly
  (backtracks cancel, more than half a turn around a vertex becomes the shorter turn), then laid out one
  face at a time, unfolded across the next edge, the chart re-centred after every step; memory is constant
  and time linear in the number of faces met. The lifted end point is joined to the start by the hyperbolic
  geodesic, traced through the faces it crosses, again embedding one face at a time. The result is the unique
  geodesic in the homotopy class (the metric has no cone points).

  Double precision keeps a lifted point accurate to about 1e-16 e^d at distance d, so one chart serves
  only while the lifted path stays within `options.max_lift_distance` of its start. Longer paths (any
  length) are computed by chart chaining: the path is cut into short chunks shortened separately and merged
  on a stack (removing back-and-forth wandering), then straightened by windows of path length about
  min(10, 0.4 max_lift_distance), each computed in its own chart around its own points, with cut points
  alternating between two offsets until the length is stationary (Birkhoff curve shortening; in negative
  curvature the corner angles at the cut points shrink by a factor of about cosh(window / 2) per round).
  No point is ever far from the origin of its chart, whatever the total length (tested beyond 10^4
  hyperbolic units against quadruple-precision holonomies).

  \param surface the hyperbolic surface
  \param path a path on it (consecutive points in a common face); the end points are kept
  \param options numerical parameters and progress callback
  \returns the shortest path (start point, its crossings with edges or vertices, end point) and its length.
  \throws Invalid_path_error if `path` is not a path on the mesh
  \throws Precision_error if a window cannot be traced (the geodesic lost near a vertex) or the chained
  shortening does not become stationary within its round bound (200 + 4 length / window rounds)
  Cost: O(n + m) time, O(1) extra memory for the embedding, n = faces met by `path`, m = faces crossed by
  the result; for paths longer than one chart, O(n + R m) with R rounds (typically 6 to 10).
*/
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_homotopic_path(const Surface& surface, const typename Surface::Path& path,
                        const Shortest_path_options& options = Shortest_path_options())
{
  check_options(options);
  try {
    return internal::shortest_path_one_chart(surface, path, options);
  } catch(const Precision_error&) {}
  // too long for one chart: chart chaining
  return internal::shortest_path_chained(surface, path, options);
}

/// \ingroup PkgSurfaceShortestWordsRef
/// A path homotopic to `path` (end points fixed) made of geodesic pieces, each shorter than
/// `options.max_lift_distance` / 2 except where no merge was possible: the shortest path when it is short,
/// otherwise a locally shortened representative (used by `Shortest_word_solver` for long loops).
template <class Surface>
typename Surface::Path
shortened_homotopic_path(const Surface& surface, const typename Surface::Path& path,
                         const Shortest_path_options& options = Shortest_path_options())
{
  surface.check_path(path);
  if(path.size() < 2) return path;
  try {
    return internal::shortest_path_one_chart(surface, path, options).path;
  } catch(const Precision_error&) {}
  std::size_t faces = 0;
  const std::vector<typename Surface::Path> pieces =
    internal::geodesic_pieces(surface, path, options, 0.5 * options.max_lift_distance, faces);
  typename Surface::Path r = pieces.front();
  for(std::size_t i = 1; i < pieces.size(); ++i) r.insert(r.end(), pieces[i].begin() + 1, pieces[i].end());
  return r;
}

/*!
  \ingroup PkgSurfaceShortestWordsRef
  The shortest loop through the fixed base point `loop.front()` homotopic to `loop` (with the base point
  fixed): Algorithm 2 applied to the loop as a path from its base point to itself.
  \throws Invalid_path_error if `loop` is not closed (first and last points differ) or not on the mesh
*/
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_loop_through_base(const Surface& surface, const typename Surface::Path& loop,
                           const Shortest_path_options& options = Shortest_path_options())
{
  if(loop.empty() || !surface.same_point(loop.front(), loop.back()))
    throw Invalid_path_error("Surface_shortest_words: a loop is required (first and last points must coincide)");
  return shortest_homotopic_path(surface, loop, options);
}

/*!
  \ingroup PkgSurfaceShortestWordsRef
  The shortest loop freely homotopic to `loop` (thesis Algorithm 3): the loop is shortened with a fixed
  base point (Algorithm 2), then re-based at the point of the result half-way along its length, and so on
  until the length changes by less than `tolerance` (relative) or after `max_iterations` iterations; the
  result reports the iteration count and whether it converged. The limit is the unique closed geodesic of
  the free homotopy class (midpoint shortening in a hyperbolic metric).
  \throws Invalid_path_error if `loop` is not closed
  Cost: O(iterations * n).
*/
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_homotopic_loop(const Surface& surface, const typename Surface::Path& loop, double tolerance = 1e-12,
                        std::size_t max_iterations = 200,
                        const Shortest_path_options& options = Shortest_path_options())
{
  typedef typename Surface::Path Path;
  if(!(tolerance >= 0) || !std::isfinite(tolerance))
    throw CGAL::Invalid_option_error("shortest_homotopic_loop: the tolerance must be finite and >= 0");
  if(max_iterations < 1) throw CGAL::Invalid_option_error("shortest_homotopic_loop: at least one iteration is needed");
  check_options(options);
  Shortest_path_result<typename Surface::Triangle_mesh> r = shortest_loop_through_base(surface, loop, options);
  r.iterations = 1;
  r.converged = false;
  std::size_t faces = r.embedded_faces;
  double prev = r.length;
  while(r.iterations < max_iterations) {
    if(r.length == 0 || r.path.size() < 3) { r.converged = true; break; }
    // re-base at the path point nearest to half the length
    const Path& p = r.path;
    double acc = 0, best = std::numeric_limits<double>::infinity();
    std::size_t mid = 1;
    std::vector<double> seg(p.size() - 1);
    for(std::size_t i = 0; i + 1 < p.size(); ++i) seg[i] = surface.path_length(Path{p[i], p[i + 1]});
    for(std::size_t i = 1; i + 1 < p.size(); ++i) {
      acc += seg[i - 1];
      const double dist = std::abs(acc - r.length / 2);
      if(dist < best) { best = dist; mid = i; }
    }
    Path rebased(p.begin() + mid, p.end());
    rebased.insert(rebased.end(), p.begin() + 1, p.begin() + mid + 1);
    Shortest_path_result<typename Surface::Triangle_mesh> n = shortest_homotopic_path(surface, rebased, options);
    faces += n.embedded_faces;
    n.iterations = r.iterations + 1;
    r = n;
    r.converged = false; // the inner result's flag says nothing about the loop iteration
    if(std::abs(prev - r.length) <= tolerance * (std::max)(1.0, r.length)) { r.converged = true; break; }
    prev = r.length;
  }
  r.embedded_faces = faces;
  return r;
}


/*!
  \ingroup PkgSurfaceShortestWordsRef
  `shortest_homotopic_loop()` with CGAL named parameters: `CGAL::parameters::number_of_iterations(n)` (the
  maximum number of re-basing iterations, default 200), `Surface_shortest_words::parameters::tolerance(t)`
  (default 1e-12), `max_lift_distance(d)` (default 25), `vertex_snap(s)` (default 1e-9). Example:
  `shortest_homotopic_loop(surface, loop, SSW::parameters::tolerance(1e-10, CGAL::parameters::number_of_iterations(50)))`.
  \throws CGAL::Invalid_option_error for a negative or non-finite tolerance, zero iterations, or an option
  out of its range (see `check_options()`).
*/
template <class Surface, class T, class Tag, class Base>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_homotopic_loop(const Surface& surface, const typename Surface::Path& loop,
                        const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double n = double(choose_parameter(get_parameter(np, internal_np::number_of_iterations), 200));
  if(!(n >= 1) || !std::isfinite(n)) throw CGAL::Invalid_option_error("shortest_homotopic_loop: number_of_iterations must be >= 1");
  const double tol = choose_parameter(get_parameter(np, internal_np::ssw_tolerance_t_v), 1e-12);
  return shortest_homotopic_loop(surface, loop, tol, std::size_t(n), path_options(np));
}

/// `shortest_homotopic_path()` with named parameters `max_lift_distance`, `vertex_snap`
template <class Surface, class T, class Tag, class Base>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_homotopic_path(const Surface& surface, const typename Surface::Path& path,
                        const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return shortest_homotopic_path(surface, path, path_options(np));
}

} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_HOMOTOPIC_PATH_H
