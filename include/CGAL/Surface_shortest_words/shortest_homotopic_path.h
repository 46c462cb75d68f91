// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shortest homotopic paths (thesis Algorithm 2, transient embedding) and loops (Algorithm 3, iterated
// re-basing) on a closed hyperbolic surface.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_HOMOTOPIC_PATH_H
#define CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_HOMOTOPIC_PATH_H

#include <CGAL/Surface_shortest_words/Hyperbolic_surface.h>
#include <CGAL/Surface_shortest_words/internal/transient_chart.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Hyperbolic_geometry_named_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <boost/iterator/function_output_iterator.hpp>

#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_tolerance_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_max_lift_distance_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_vertex_snap_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_use_geometry_t)       // Shortest_word_solver
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_shorten_generators_t) // Shortest_word_solver
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_make_canonical_t)     // Shortest_word_solver
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(ssw_basis_construction_t) // Shortest_word_solver

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

namespace internal {
// no option is dropped silently: options of other functions are compile-time errors here
template <class NP, bool loop>
void check_path_named_parameters()
{
  using CGAL::parameters::is_default_parameter;
  static_assert(is_default_parameter<NP, internal_np::ssw_use_geometry_t>::value &&
                is_default_parameter<NP, internal_np::ssw_shorten_generators_t>::value &&
                is_default_parameter<NP, internal_np::ssw_make_canonical_t>::value &&
                is_default_parameter<NP, internal_np::ssw_basis_construction_t>::value,
                "use_geometry, shorten_generators, make_canonical, basis_construction are options of Shortest_word_solver");
  static_assert(loop || (is_default_parameter<NP, internal_np::ssw_tolerance_t>::value &&
                         is_default_parameter<NP, internal_np::number_of_iterations_t>::value),
                "tolerance and number_of_iterations are options of shortest_homotopic_loop()");
}
} // namespace internal

/// The path options given by named parameters (defaults of `Shortest_path_options` otherwise), checked:
/// `max_lift_distance`, `vertex_snap`, and CGAL's `callback` (a functor called with the number of faces
/// processed so far, `Shortest_path_options::progress`). \throws CGAL::Invalid_option_error (`check_options()`)
template <class NP>
Shortest_path_options path_options(const NP& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Shortest_path_options o;
  o.max_lift_distance = choose_parameter(get_parameter(np, internal_np::ssw_max_lift_distance_t_v), o.max_lift_distance);
  o.vertex_snap = choose_parameter(get_parameter(np, internal_np::ssw_vertex_snap_t_v), o.vertex_snap);
  o.progress = choose_parameter(get_parameter(np, internal_np::callback), o.progress);
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
  /// a-posteriori error: the hyperbolic distance between the lift of the end point the trace aimed at and
  /// the end point it reached (summed over the traced pieces); it bounds the effect of the rounding of the
  /// lift, and of the metric's residual angle defects, on `length`
  double end_mismatch = 0;
};

namespace internal {

// true if direction u (from the origin, where the corner `c` of the chart's face sits) lies in the face's
// angle at that corner
template <class Chart>
bool in_sector(const Chart& chart, typename Chart::halfedge_descriptor c, const Cplx& u, double tol)
{
  const int iv = chart.index_of_corner(c);
  const Cplx A = chart.z()[(iv + 1) % 3], B = chart.z()[(iv + 2) % 3];
  return cross(A, u) >= -tol * std::abs(A) && cross(u, B) >= -tol * std::abs(B);
}

// rotates the chart around the vertex of corner `c` (at the origin) to the corner whose angle contains
// direction u; returns that corner
template <class Surface, class Chart>
typename Surface::halfedge_descriptor
rotate_to_direction(const Surface& s, Chart& chart, typename Surface::halfedge_descriptor c, const Cplx& u)
{
  const std::size_t deg = CGAL::halfedges_around_target(target(c, s.mesh()), s.mesh()).size();
  for(double tol : {0.0, 1e-12, 1e-9, 1e-6}) {
    for(std::size_t k = 0; k <= deg; ++k) {
      if(in_sector(chart, c, u, tol)) return c;
      chart.unfold(chart.rotation_halfedge(c, true));
      c = chart.rotated_corner(c, true);
    }
  }
  throw Precision_error("Surface_shortest_words: no face around a vertex contains the geodesic direction");
}

// the vertex point of the corner `c`: a corner point where vertex points need corners
template <class Surface>
typename Surface::Point vertex_point(const Surface& s, typename Surface::halfedge_descriptor c)
{
  return s.needs_corners() ? s.corner(c) : Surface::Point::vertex(target(c, s.mesh()));
}

// appends `q` unless it is the same as the last point (corners compared too)
template <class Surface>
void append_point(const Surface& s, typename Surface::Path& path, const typename Surface::Point& q)
{
  if(!path.empty() && s.same_point(path.back(), q) && (!q.on_vertex || path.back().h == q.h)) return;
  path.push_back(q);
}

// Develops the crossed halfedges `crossings` one face at a time (the layer's chart of `f` recentred at the
// point `origin` at corner `origin_corner`, then the layer's neighbour apices), re-centred after every step;
// returns the chart at the end: `accumulated()` maps the start frame to its frame. Throws `Precision_error`
// when the development leaves `max_lift_distance`.
template <class Surface>
Transient_chart<Surface> develop_crossings(const Surface& surface, typename Surface::face_descriptor f,
                                           const typename Surface::Point& origin,
                                           typename Surface::halfedge_descriptor origin_corner,
                                           const std::vector<typename Surface::halfedge_descriptor>& crossings,
                                           const Shortest_path_options& options)
{
  internal::Transient_chart<Surface> chart(surface);
  chart.set_face(f);
  chart.recentre(surface.position(origin, origin_corner, chart.face_chart()));
  chart.reset_accumulated();
  std::size_t next_report = std::size_t(1) << 16;
  const double max_alpha_beta = std::tanh(options.max_lift_distance / 2);
  for(typename Surface::halfedge_descriptor c : crossings) {
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
  return chart;
}

// Algorithm 2, steps 1-3: the lifted end point T of `path` in the chart of the first step recentred at
// path[0] (the faces met, as crossed edges, exactly reduced, then developed); `lifted` counts the faces
template <class Surface>
Cplx lift_end_point(const Surface& surface, const typename Surface::Path& path,
                    const std::vector<typename Surface::Step>& st, const Shortest_path_options& options, std::size_t& lifted)
{
  internal::Crossing_reducer<typename Surface::Triangle_mesh> reducer(surface.mesh());
  for(std::size_t i = 1; i < st.size(); ++i)
    surface.crossings_at(path[i], st[i - 1], st[i],
                         boost::make_function_output_iterator([&reducer](typename Surface::halfedge_descriptor h) { reducer.push(h); }));
  const Transient_chart<Surface> chart = develop_crossings(surface, st.front().face, path[0], st.front().in, reducer.result(), options);
  CGAL_assertion(chart.current_face() == st.back().face);
  const Cplx end_local = surface.position(path.back(), st.back().out, chart.face_chart());
  lifted = chart.count();
  return internal::apply_isometry(chart.accumulated().inverse(), end_local);
}

// appends the end point of a trace that ends in the chart's current face, where the end point's lift is T;
// returns the position of the end point in the chart (its lift in the current face nearest T): the traced
// length is measured to it, so that the recorded path gives back the traced length exactly (T itself carries
// the rounding and metric errors of the lift, up to about 1e-14 e^d at distance d)
template <class Surface, class Chart>
Cplx finish_at_end(const Surface& s, const Chart& tr, const Cplx& T, const typename Surface::Point& end,
                   typename Surface::halfedge_descriptor from_corner, typename Surface::Path& path)
{
  const auto& tm = s.mesh();
  if(!end.on_vertex) {
    Cplx best = T; double bd = std::numeric_limits<double>::infinity();
    for(int i = 0; i < 3; ++i) {
      const Cplx a = tr.z()[i], b = tr.z()[(i + 1) % 3];
      Cplx q;
      if(tr.halfedge_at(i) == end.h) q = point_along(a, b, end.t * s.length(end.h));
      else if(tr.halfedge_at(i) == opposite(end.h, tm)) q = point_along(b, a, end.t * s.length(end.h));
      else continue;
      if(std::abs(q - T) < bd) { bd = std::abs(q - T); best = q; }
    }
    if(!s.same_point(path.back(), end)) path.push_back(end);
    return best;
  }
  // the corner of the current face at the lift of the end vertex
  int best = -1; double bd = std::numeric_limits<double>::infinity();
  for(int i = 0; i < 3; ++i)
    if(target(tr.halfedge_at(i), tm) == end.v) {
      const double d = std::abs(tr.z()[(i + 1) % 3] - T);
      if(d < bd) { bd = d; best = i; }
    }
  if(best < 0) throw Precision_error("Surface_shortest_words: the trace ends in a face without the end vertex");
  const Cplx position = tr.z()[(best + 1) % 3];
  if(!s.needs_corners()) { if(!s.same_point(path.back(), end)) path.push_back(end); return position; }
  const typename Surface::halfedge_descriptor c = tr.halfedge_at(best);
  // (from the corner `from_corner` of the same face: along a side, marked by its midpoint)
  if(from_corner != boost::graph_traits<typename Surface::Triangle_mesh>::null_halfedge() && from_corner != c)
    path.push_back(Surface::Point::on_edge(c == next(from_corner, tm) ? c : from_corner, 0.5));
  append_point(s, path, s.corner(c));
  if(end.has_corner() && end.h != c) path.push_back(end);
  return position;
}

// Algorithm 2, steps 4-7: the geodesic from `start` (a point of the face `first.face`, at the corner
// `first.in` if it is a vertex) to `end`, whose lift is T in the layer's chart of `first.face` recentred at
// `start`, traced one face at a time; `lifted` (faces embedded before) is added to `embedded_faces`.
// A trace that ends farther than this from its aim ended at another lift of its end point (lifts of a point
// are a closed geodesic apart), i.e. in another homotopy class: such a result is refused, never kept.
constexpr double other_lift_mismatch = 1e-3;

template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
trace_geodesic(const Surface& surface, const typename Surface::Point& start, const typename Surface::Step& first,
               Cplx T, const typename Surface::Point& end, const Shortest_path_options& options, std::size_t lifted)
{
  typedef typename Surface::Point Point;
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  const auto& tm = surface.mesh();
  Shortest_path_result<typename Surface::Triangle_mesh> res;
  res.lift_distance = internal::distance_to_origin(T);
  if(!(res.lift_distance <= options.max_lift_distance)) {
    std::ostringstream os;
    os << "Surface_shortest_words: the lifted end point lies at hyperbolic distance " << res.lift_distance
       << " > max_lift_distance = " << options.max_lift_distance << " (beyond double precision)";
    throw Precision_error(os.str());
  }

  // ---- trace (steps 4-7): the geodesic from the start towards T, one face at a time
  res.path.push_back(start.on_vertex && surface.needs_corners() ? surface.corner(first.in) : start);
  if(res.lift_distance < 1e-12) {
    if(!surface.same_point(start, end) || (end.on_vertex && end.h != res.path[0].h)) res.path.push_back(end);
    res.end_mismatch = res.lift_distance;
    res.embedded_faces = lifted;
    return res;
  }
  internal::Transient_chart<Surface> tr(surface);
  tr.set_face(first.face);
  // the same deterministic layout as the start chart of the lift: T is expressed in tr's chart
  tr.recentre(surface.position(start, first.in, tr.face_chart()));
  tr.reset_accumulated();
  halfedge_descriptor corner = first.in; // corner of the current vertex point, if any
  bool at_vertex = start.on_vertex;      // the origin is that corner (no edge crossed since)
  {
    // choose the start face containing the direction of T
    const Cplx u = T / std::abs(T);
    if(start.on_vertex) {
      corner = internal::rotate_to_direction(surface, tr, corner, u);
      if(surface.needs_corners() && corner != first.in) res.path.push_back(surface.corner(corner));
    } else {
      halfedge_descriptor h = start.h;
      if(face(h, tm) != tr.current_face()) h = opposite(h, tm);
      const int i = tr.index_of(h);
      const Cplx third = tr.z()[(i + 2) % 3], a = tr.z()[i], b = tr.z()[(i + 1) % 3];
      const double side_third = internal::cross(b - a, third - a), side_u = internal::cross(b - a, u);
      if(side_third * side_u < 0) tr.unfold(h);
      // the crossing convention of paths that need corners: the segment after an edge point of halfedge g
      // lies in face(opposite(g))
      if(surface.needs_corners() && face(opposite(start.h, tm), tm) != tr.current_face())
        res.path[0] = Point::on_edge(opposite(start.h, tm), 1.0 - start.t);
    }
  }
  const std::size_t max_steps = 64 * (lifted + 1000);
  std::size_t steps = 0, next_report = std::size_t(1) << 16;
  // An end vertex is aimed at where the trace's own development puts it, once a face of the trace has it as
  // a corner within other_lift_mismatch of T (its distance to T is then part of the end mismatch). The metric
  // in double is a cone metric (angle sums 2 pi up to about 1e-14), and the lift of the path and the trace
  // pass vertex lifts on different sides: their developments of the end vertex disagree by about 1e-14 sinh d
  // (3e-6 at 20 units on the one-vertex genus-3 polygon), tangentially to the trace. Aimed at T, the trace
  // passed the vertex and circled it in steps of the mismatch, a first-order excess (2.3e-6 there); aimed at
  // the vertex, the excess is of second order.
  double reaimed = 0;
  while(true) {
    if(++steps > max_steps) throw Precision_error("Surface_shortest_words: geodesic tracing did not reach the end point");
    if(options.progress && lifted + tr.count() >= next_report) { options.progress(lifted + tr.count()); next_report <<= 1; }
    if(end.on_vertex && reaimed == 0) {
      for(int i = 0; i < 3; ++i) {
        // (d(z, T) >= |z - T|: the cheap test first)
        if(source(tr.halfedge_at(i), tm) != end.v || !(std::norm(tr.z()[i] - T) < other_lift_mismatch * other_lift_mismatch)) continue;
        const double d = internal::hyperbolic_distance(tr.z()[i], T);
        if(d > 0 && d < other_lift_mismatch && internal::distance_to_origin(tr.z()[i]) > 0) { reaimed = d; T = tr.z()[i]; break; }
      }
    }
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
    const bool end_here = surface.in_face(end.on_vertex ? Point::vertex(end.v) : end, tr.current_face());
    // no exit found (the ray leaves through a vertex, up to rounding): the trace may finish here only if T
    // lies in the face. (On a one-vertex surface every face contains the end vertex: a lost trace finished
    // at a corner 7 units from T, in another homotopy class.)
    const bool lost = best_i < 0 && !internal::in_klein_triangle(k, internal::to_klein(T), 1e-9);
    if(lost) throw Precision_error("Surface_shortest_words: lost the geodesic while tracing");
    if(best_i < 0 || kT <= best_s * (1 + 1e-12) + 1e-15) {
      if(!end_here) {
        if(best_i < 0) throw Precision_error("Surface_shortest_words: lost the geodesic while tracing");
        // numerically the target is on the exit edge: continue into the next face
        if(kT < best_s * (1 - 1e-9)) throw Precision_error("Surface_shortest_words: traced geodesic misses the end point");
      } else {
        const Cplx E = finish_at_end(surface, tr, T, end, at_vertex ? corner : boost::graph_traits<typename Surface::Triangle_mesh>::null_halfedge(), res.path);
        res.length += internal::distance_to_origin(E);
        res.end_mismatch = reaimed + internal::hyperbolic_distance(E, T);
        break;
      }
    }
    const Cplx kx = best_s * u;
    const Cplx zx = internal::from_klein(kx);
    const halfedge_descriptor h = tr.halfedge_at(best_i);
    const Cplx za = z[best_i], zb = z[(best_i + 1) % 3];
    const double da = internal::hyperbolic_distance(za, zx), db = internal::hyperbolic_distance(zx, zb);
    const double t = da / (da + db);
    // arriving at the end vertex: the lift T of the end carries an error of about 1e-14 e^d, so a geodesic
    // ending at a vertex may cross an edge at it within that error; snapped to the end instead of leaving
    // a spurious last crossing (and a kink) next to it
    const bool at_end_a = end.on_vertex && da < 1e-6 && source(h, tm) == end.v && internal::hyperbolic_distance(za, T) < 1e-6;
    const bool at_end_b = end.on_vertex && db < 1e-6 && target(h, tm) == end.v && internal::hyperbolic_distance(zb, T) < 1e-6;
    if(at_end_a || at_end_b || t < options.vertex_snap || t > 1 - options.vertex_snap) {
      const halfedge_descriptor reached = t < 0.5 ? prev(h, tm) : h; // the corner of the current face at the snapped vertex
      // from a corner along a side to another corner: the side's midpoint keeps it apart from a turn
      if(at_vertex && surface.needs_corners()) res.path.push_back(Point::on_edge(reached == next(corner, tm) ? reached : corner, 0.5));
      corner = reached;
      at_vertex = true;
      const Cplx zv = t < 0.5 ? za : zb;
      res.length += internal::distance_to_origin(zv);
      internal::append_point(surface, res.path, internal::vertex_point(surface, corner));
      // re-centre at the vertex and turn to the face containing the new direction
      const internal::Isometry m = internal::to_origin(zv);
      tr.transform(m);
      T = internal::apply_isometry(m, T);
      if(end.on_vertex && end.v == target(corner, tm) && internal::distance_to_origin(T) < ((at_end_a || at_end_b) ? 1e-6 : 1e-7)) {
        if(surface.needs_corners() && end.has_corner() && end.h != corner) res.path.push_back(end);
        // ended at the vertex, up to 1e-6 from the aim: that distance is the end mismatch (it was left at 0
        // here, so that a trace that missed its aim by 4e-6 and circled the end vertex in steps of 1e-6 was
        // accepted, 4.6e-7 too long, on a genus-3 one-vertex surface with edge lengths moved by one ulp)
        res.end_mismatch = reaimed + internal::distance_to_origin(T);
        break;
      }
      corner = internal::rotate_to_direction(surface, tr, corner, T / std::abs(T));
      if(surface.needs_corners()) internal::append_point(surface, res.path, surface.corner(corner));
    } else {
      res.length += internal::distance_to_origin(zx);
      res.path.push_back(Point::on_edge(h, t));
      at_vertex = false;
      tr.unfold(h);
      const internal::Isometry m = internal::to_origin(zx);
      tr.transform(m);
      T = internal::apply_isometry(m, T);
    }
  }
  res.embedded_faces = lifted + tr.count();
  return res;
}


// Algorithm 2 in one chart (the lifted path must stay within max_lift_distance of its start)
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_path_one_chart(const Surface& surface, const typename Surface::Path& path,
                        const Shortest_path_options& options)
{
  const std::vector<typename Surface::Step> st = surface.steps(path);
  if(path.size() == 1) { Shortest_path_result<typename Surface::Triangle_mesh> res; res.path = path; return res; }
  std::size_t lifted = 0;
  const Cplx T = lift_end_point(surface, path, st, options, lifted);
  return trace_geodesic(surface, path.front(), st.front(), T, path.back(), options, lifted);
}

// Geodesic pieces on a stack: the path is cut into chunks, each shortened in one chart; a new piece is
// merged with the top of the stack (shortened again as one path) while the merged geodesic is no longer than
// `merge_length`, so backtracking and wandering cancel without any long lift. The chunks grow (doubling)
// while they fit one chart and shrink (halving) when they do not, so a chunk lifts to about one chart's
// reach whatever the mesh's edge length: the number of merges is about the length of the result over the
// chart's reach, not the number of path points over a fixed chunk size. A merge whose lifted end point is
// farther than `merge_length` is refused before its geodesic is traced.
// Cost: O(n + m) for a path meeting n faces (each face developed a bounded number of times: a chunk that does
// not fit is retried at half its size) and m faces crossed by the merged geodesics.
template <class Surface>
std::vector<typename Surface::Path>
geodesic_pieces(const Surface& surface, const typename Surface::Path& path, const Shortest_path_options& options,
                double merge_length, std::size_t& faces)
{
  typedef typename Surface::Path Path;
  typedef Shortest_path_result<typename Surface::Triangle_mesh> Result;
  std::vector<Path> stack;
  auto concat = [](const Path& a, const Path& b) { Path r(a); r.back() = b.front(); r.insert(r.end(), b.begin() + 1, b.end()); return r; };
  // the shortest path homotopic to `p` in one chart if its lift is at most `bound` away; false if it is
  // farther, or if the lift or the trace fails (`error` then says why)
  std::string error;
  auto shorten = [&](const Path& p, double bound, Result& r) {
    const std::vector<typename Surface::Step> st = surface.steps(p);
    std::size_t lifted = 0;
    try {
      const Cplx T = lift_end_point(surface, p, st, options, lifted);
      faces += lifted;
      lifted = 0;
      if(!(internal::distance_to_origin(T) <= bound)) {
        error = "Surface_shortest_words: the lifted path leaves the double precision range (max_lift_distance)";
        return false;
      }
      r = trace_geodesic(surface, p.front(), st.front(), T, p.back(), options, 0);
    } catch(const Precision_error& e) { faces += lifted; error = e.what(); return false; }
    // a piece is within one chart: its trace ends within about 1e-14 e^25 of its aim; farther means it
    // ended at another lift of its end point (another homotopy class)
    if(!(r.end_mismatch <= other_lift_mismatch)) {
      faces += r.embedded_faces;
      error = "Surface_shortest_words: traced geodesic misses the end point";
      return false;
    }
    faces += r.embedded_faces;
    return true;
  };
  // pushes a geodesic piece, merged with the top of the stack while the merge is no longer than merge_length
  auto push = [&](Path cur) {
    while(!stack.empty()) {
      Result m;
      if(!shorten(concat(stack.back(), cur), merge_length, m)) break;
      cur = m.path;
      stack.pop_back();
    }
    stack.push_back(cur);
  };
  // chunk sizes: the first chunk has 256 points; a chunk doubles after a success (up to 2^20; not right
  // after a failure) and halves after a failure, down to single steps
  const std::size_t first_chunk = 256, max_chunk = std::size_t(1) << 20;
  std::size_t K = first_chunk;
  bool grow = true;
  for(std::size_t i = 0; i + 1 < path.size();) {
    const std::size_t e = (std::min)(path.size() - 1, i + K);
    Result piece;
    if(!shorten(Path(path.begin() + std::ptrdiff_t(i), path.begin() + std::ptrdiff_t(e) + 1), options.max_lift_distance, piece)) {
      if(e - i <= 1) throw Precision_error(error);
      K = (e - i) / 2;
      grow = false;
      continue;
    }
    // pushed in sub-pieces of at most `merge_length` (a chunk's geodesic may be longer): adjacent pieces
    // on the stack are then each no longer than `merge_length` and not mergeable within it, so they meet
    // at angles bounded away from a backtrack (a quasi-geodesic, as geodesic_of_frames() needs)
    const Path& p = piece.path;
    std::size_t from = 0;
    double acc = 0;
    for(std::size_t j = 0; j + 1 < p.size(); ++j) {
      const double l = surface.path_length(Path{p[j], p[j + 1]});
      const bool last = j + 2 == p.size();
      if(acc > 0 && acc + l > merge_length) { push(Path(p.begin() + std::ptrdiff_t(from), p.begin() + std::ptrdiff_t(j) + 1)); from = j; acc = 0; }
      acc += l;
      if(last) push(Path(p.begin() + std::ptrdiff_t(from), p.end()));
    }
    i = e;
    // (a chunk that did not fit is not tried again at once: one failed attempt per about two chunks)
    if(grow) K = (std::min)(2 * K, max_chunk);
    grow = true;
  }
  return stack;
}

// Paths longer than one chart: the lift by chart chaining and the geodesic in the universal cover
// (internal/word_geodesic.h, included at the end of this header)
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_path_chained(const Surface& surface, const typename Surface::Path& path, const Shortest_path_options& options);

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
  only while the lifted path stays within `options.max_lift_distance` of its start, and its result is kept
  only if its trace ends within 1e-9 (1 + length) of the lifted end point (`end_mismatch`); otherwise chart
  chaining (below) is run too and the result with the smaller length + end mismatch is kept. Longer paths (any
  length) are lifted by chart chaining, without iteration: the path is cut into chunks (their length adapted
  so that each lifts to about one chart's reach), each shortened in one chart and merged on a stack with the
  previous geodesic piece while the merged geodesic is shorter than 0.4 max_lift_distance (removing
  back-and-forth wandering); at each junction of two pieces a frame
  (a chart centred at the junction), and between consecutive frames the isometry given by the development of
  the piece in one chart. The geodesic of the universal cover from the start to the lifted end point is then
  located in every frame from its two end points, carried there by sweeps of these isometries (a point far
  away keeps its direction to double precision), anchored at an edge crossing near every junction, and
  traced between consecutive anchors, each piece in its own chart (`internal::geodesic_of_frames()`, the
  machinery of `Shortest_word_solver`'s loops). No point is ever far from the origin of its chart, whatever
  the total length (tested beyond 10^4 hyperbolic units against quadruple-precision holonomies).

  \param surface the hyperbolic surface
  \param path a path on it (consecutive points in a common face); the end points are kept
  \param options numerical parameters and progress callback
  \returns the shortest path (start point, its crossings with edges or vertices, end point) and its length.
  \throws Invalid_path_error if `path` is not a path on the mesh
  \throws Precision_error if a piece cannot be traced (the geodesic lost near a vertex, or two consecutive
  anchors farther apart than max_lift_distance)
  Cost: O(n + m) time, n = faces met by `path`, m = faces crossed by the result; O(1) extra memory for a path
  that fits one chart, O(number of geodesic pieces) otherwise.
*/
template <class Surface>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_homotopic_path(const Surface& surface, const typename Surface::Path& path,
                        const Shortest_path_options& options = Shortest_path_options())
{
  check_options(options);
  Shortest_path_result<typename Surface::Triangle_mesh> one;
  try {
    one = internal::shortest_path_one_chart(surface, path, options);
  } catch(const Precision_error&) {
    // too long for one chart: chart chaining
    return internal::shortest_path_chained(surface, path, options);
  }
  // A lift far from the start carries rounding errors of about 1e-16 e^d, more where the lifted path winds
  // around vertices: on the one-vertex genus-3 surface a 3-edge loop lifted to 19.2 units was traced 5e-5 too
  // long (end mismatch 6.6e-5), chart chaining gave it to 1e-12 (mismatch 1.8e-8). Above 1e-9 (1 + length)
  // chaining is tried too, and the result with the smaller length + end mismatch (an upper bound on the
  // shortest length) is kept.
  if(one.end_mismatch <= 1e-9 * (1 + one.length)) return one;
  try {
    Shortest_path_result<typename Surface::Triangle_mesh> ch = internal::shortest_path_chained(surface, path, options);
    ch.embedded_faces += one.embedded_faces;
    if(ch.length + ch.end_mismatch < one.length + one.end_mismatch) return ch;
  } catch(const Precision_error&) {}
  return one;
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
  for(std::size_t i = 1; i < pieces.size(); ++i) { r.back() = pieces[i].front(); r.insert(r.end(), pieces[i].begin() + 1, pieces[i].end()); }
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
    // (through p.front() too where corners matter: p.back() -> p.front() is then a turn at the vertex)
    rebased.insert(rebased.end(), p.begin() + (surface.needs_corners() ? 0 : 1), p.begin() + mid + 1);
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
  (default 1e-12), `max_lift_distance(d)` (default 25), `vertex_snap(s)` (default 1e-9), CGAL's
  `callback(f)` (progress: `f(faces processed)`). Example:
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
  internal::check_path_named_parameters<CGAL::Named_function_parameters<T, Tag, Base>, true>();
  const double n = double(choose_parameter(get_parameter(np, internal_np::number_of_iterations), 200));
  if(!(n >= 1) || !std::isfinite(n)) throw CGAL::Invalid_option_error("shortest_homotopic_loop: number_of_iterations must be >= 1");
  const double tol = choose_parameter(get_parameter(np, internal_np::ssw_tolerance_t_v), 1e-12);
  return shortest_homotopic_loop(surface, loop, tol, std::size_t(n), path_options(np));
}

/// `shortest_loop_through_base()` with named parameters `max_lift_distance`, `vertex_snap`, `callback`
template <class Surface, class T, class Tag, class Base>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_loop_through_base(const Surface& surface, const typename Surface::Path& loop,
                           const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  internal::check_path_named_parameters<CGAL::Named_function_parameters<T, Tag, Base>, false>();
  return shortest_loop_through_base(surface, loop, path_options(np));
}

/// `shortened_homotopic_path()` with named parameters `max_lift_distance`, `vertex_snap`, `callback`
template <class Surface, class T, class Tag, class Base>
typename Surface::Path
shortened_homotopic_path(const Surface& surface, const typename Surface::Path& path,
                         const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  internal::check_path_named_parameters<CGAL::Named_function_parameters<T, Tag, Base>, false>();
  return shortened_homotopic_path(surface, path, path_options(np));
}

/// `shortest_homotopic_path()` with named parameters `max_lift_distance`, `vertex_snap`, `callback`
template <class Surface, class T, class Tag, class Base>
Shortest_path_result<typename Surface::Triangle_mesh>
shortest_homotopic_path(const Surface& surface, const typename Surface::Path& path,
                        const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  internal::check_path_named_parameters<CGAL::Named_function_parameters<T, Tag, Base>, false>();
  return shortest_homotopic_path(surface, path, path_options(np));
}

} // namespace Surface_shortest_words
} // namespace CGAL

#include <CGAL/Surface_shortest_words/internal/word_geodesic.h>

#endif // CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_HOMOTOPIC_PATH_H
