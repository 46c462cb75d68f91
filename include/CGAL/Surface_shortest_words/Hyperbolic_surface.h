// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Points and paths on a closed hyperbolic surface: a thin adaptor over the shared layer's
// Hyperbolic_surface_2::Hyperbolic_surface_triangulation (which owns the checks, angles, charts, transitions).
#ifndef CGAL_SURFACE_SHORTEST_WORDS_HYPERBOLIC_SURFACE_H
#define CGAL_SURFACE_SHORTEST_WORDS_HYPERBOLIC_SURFACE_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Surface_shortest_words/internal/layout.h>
#include <CGAL/Hyperbolic_surface_2/Hyperbolic_surface_triangulation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Path_on_surface.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_shortest_words {

namespace internal {
// validity of handles given by the user (Surface_mesh: index in range and not removed; other graphs: trusted)
template <class P>
bool is_valid_handle(const CGAL::Surface_mesh<P>& m, typename CGAL::Surface_mesh<P>::Vertex_index v)
{ return std::size_t(v) < m.num_vertices() && !m.is_removed(v); }
template <class P>
bool is_valid_handle(const CGAL::Surface_mesh<P>& m, typename CGAL::Surface_mesh<P>::Halfedge_index h)
{ return std::size_t(h) < m.num_halfedges() && !m.is_removed(m.edge(h)); }
template <class P>
bool is_valid_handle(const CGAL::Surface_mesh<P>& m, typename CGAL::Surface_mesh<P>::Face_index f)
{ return std::size_t(f) < m.num_faces() && !m.is_removed(f); }
template <class G, class H>
bool is_valid_handle(const G&, const H&) { return true; }
} // namespace internal

/// the package's exceptions are the common ones (`<CGAL/Hyperbolic_geometry_errors.h>`)
using CGAL::Invalid_metric_error;
using CGAL::Invalid_mesh_error;
using CGAL::Invalid_path_error;

/// \ingroup PkgSurfaceShortestWordsRef
/// Thrown when a computation needs more precision than double arithmetic offers (the lifted end point of a
/// path lies farther than `max_lift_distance` from its start in the universal cover), or does not terminate
/// within its step bound.
class Precision_error : public CGAL::Numerical_error
{
public:
  explicit Precision_error(const std::string& w) : CGAL::Numerical_error(w) {}
};

/*!
  \ingroup PkgSurfaceShortestWordsRef
  A point of a triangulated surface: a vertex, or the point of the edge of halfedge `h` at the fraction `t`
  (0 < t < 1) of the edge's hyperbolic length, measured from `source(h)`.

  Where faces use a vertex more than once (`Hyperbolic_surface::needs_corners()`), both faces of an edge may
  contain the next point: the segment after an edge point of halfedge `h` lies in `face(opposite(h))` when
  that face contains the next point (the convention of the traced paths: the halfedge of a crossing points
  out of the face the path leaves).

  A vertex point may name a *corner*: `h` a halfedge with `target(h) == v`, the corner of `face(h)` at
  `target(h)` (`corner()`); otherwise `h` is the null halfedge (`vertex()`). Corners are needed where a face
  uses a vertex more than once (intrinsic triangulations with self-loop edges): there "the vertex v in face f"
  does not say which corner of f is meant. Two consecutive vertex points of the same vertex are a *turn*
  (a path of length 0 staying at the vertex, from the first corner to the second).
*/
template <class TriangleMesh>
struct Surface_point
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor   vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  bool on_vertex = true;
  vertex_descriptor v{};
  halfedge_descriptor h = GT::null_halfedge();
  double t = 0;

  /// true for a vertex point naming its corner
  bool has_corner() const { return on_vertex && h != GT::null_halfedge(); }

  static Surface_point vertex(vertex_descriptor vd) { Surface_point p; p.on_vertex = true; p.v = vd; return p; }
  /// the vertex `vd` (= target(hd)) at the corner of `face(hd)` at `target(hd)`
  static Surface_point corner(vertex_descriptor vd, halfedge_descriptor hd)
  { Surface_point p; p.on_vertex = true; p.v = vd; p.h = hd; return p; }
  static Surface_point on_edge(halfedge_descriptor hd, double tt)
  { Surface_point p; p.on_vertex = false; p.h = hd; p.t = tt; return p; }
};

/// a path on the surface: consecutive points lie in a common face (the path is the geodesic segment between
/// them inside that face); a loop is a path whose first and last points coincide.
template <class TriangleMesh>
using Surface_path = std::vector<Surface_point<TriangleMesh> >;

/*!
  \ingroup PkgSurfaceShortestWordsRef
  A closed triangulated surface with a hyperbolic metric, with points and paths on it: a thin adaptor over
  the shared layer's `CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation` (a model of
  `HyperbolicSurfaceTriangulation_2`), which it *is* (public base class): the checks, lengths, corner angles,
  angle defects, area, charts, transitions, `neighbor_apex()` and `develop()` are the layer's, written once.
  This class only adds the combinatorics of `Surface_point` / `Surface_path` (common faces, corners, turns,
  conversion from and to halfedge paths and CGAL's `Path_on_surface`) and the length of a path.

  `TriangleMesh` is a model of `FaceGraph` (closed, triangles, connected); faces may use a vertex more than
  once and vertices may be joined by several edges (intrinsic triangulations). `EdgeLengthMap` is a readable
  property map from `edge_descriptor` to `double`. The constructor throws what the layer throws
  (`CGAL::Invalid_mesh_error`: not closed, not triangulated, not connected, genus < 2;
  `CGAL::Invalid_metric_error`: a length or a triangle inequality, an angle sum not 2 pi up to the tolerance)
  and `CGAL::Invalid_mesh_error` for a halfedge whose face is not on a `Surface_mesh`.

  The object keeps a reference to the mesh and a copy of the map: the mesh must outlive it and not change.
*/
template <class TriangleMesh, class EdgeLengthMap,
          class Traits = CGAL::Poincare_disk_traits_2<CGAL::Exact_predicates_inexact_constructions_kernel> >
class Hyperbolic_surface
  : public CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<TriangleMesh, EdgeLengthMap, Traits>
{
public:
  typedef CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<TriangleMesh, EdgeLengthMap, Traits> Base;
  typedef TriangleMesh Triangle_mesh;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor   vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor     edge_descriptor;
  typedef typename GT::face_descriptor     face_descriptor;
  typedef typename Base::Face_chart Face_chart;
  typedef Surface_point<TriangleMesh> Point;
  typedef Surface_path<TriangleMesh>  Path;

  /// One segment of a path: its face, and the corners of its end points in that face (halfedges of `face`
  /// with the vertex as target; null for edge points). A turn has `turn` set and `in == out`.
  struct Step
  {
    face_descriptor face;
    halfedge_descriptor in = GT::null_halfedge(), out = GT::null_halfedge();
    bool turn = false;
  };

  /// checks the surface with the layer, `angle_tolerance` on |angle sum - 2 pi|
  Hyperbolic_surface(const TriangleMesh& tm, EdgeLengthMap lengths, double angle_tolerance = 1e-6)
    : Base(checked_handles(tm), lengths, CGAL::Hyperbolic_surface_2::parameters::angle_tolerance(angle_tolerance))
  { init(); }

  /// the same with the layer's named parameters (`angle_tolerance`, `require_smooth_metric`)
  template <class T, class Tag, class B>
  Hyperbolic_surface(const TriangleMesh& tm, EdgeLengthMap lengths, const CGAL::Named_function_parameters<T, Tag, B>& np)
    : Base(checked_handles(tm), lengths, np)
  { init(); }

  using Base::mesh;
  using Base::length;

  /// true if some face uses a vertex more than once or two edges join the same two vertices: then vertex
  /// points need corners and `path_from_halfedges()` returns corner points and edge midpoints
  bool needs_corners() const { return needs_corners_; }

  // ------------------------------------------------------------------ points
  /// checks that `p` is a valid point; throws `Invalid_path_error` otherwise
  void check_point(const Point& p) const
  {
    const TriangleMesh& tm = mesh();
    if(p.on_vertex) {
      if(!internal::is_valid_handle(tm, p.v)) throw Invalid_path_error("Surface_shortest_words: invalid vertex (not on the mesh)");
      if(p.has_corner() && (!internal::is_valid_handle(tm, p.h) || target(p.h, tm) != p.v))
        throw Invalid_path_error("Surface_shortest_words: the corner of a vertex point is not a halfedge into the vertex");
      return;
    }
    if(!internal::is_valid_handle(tm, p.h) || p.h == GT::null_halfedge())
      throw Invalid_path_error("Surface_shortest_words: invalid halfedge (not on the mesh)");
    if(!(p.t > 0.0 && p.t < 1.0) || !std::isfinite(p.t))
      throw Invalid_path_error("Surface_shortest_words: an edge point needs 0 < t < 1 (use a vertex point at the ends)");
  }

  /// the vertex point of `target(h)` at its corner in `face(h)`
  Point corner(halfedge_descriptor h) const { return Point::corner(target(h, mesh()), h); }

  /// the faces containing `p` (the incident faces of a vertex, the two faces of an edge)
  std::vector<face_descriptor> faces_of(const Point& p) const
  {
    std::vector<face_descriptor> r;
    if(p.on_vertex) {
      for(halfedge_descriptor h : CGAL::halfedges_around_target(p.v, mesh())) r.push_back(face(h, mesh()));
    } else {
      r.push_back(face(p.h, mesh()));
      r.push_back(face(opposite(p.h, mesh()), mesh()));
    }
    return r;
  }

  /// true if `p` and `q` denote the same point of the surface (corners are ignored)
  bool same_point(const Point& p, const Point& q) const
  {
    if(p.on_vertex != q.on_vertex) return false;
    if(p.on_vertex) return p.v == q.v;
    if(p.h == q.h) return p.t == q.t;
    return p.h == opposite(q.h, mesh()) && p.t == 1.0 - q.t;
  }

  /// true if `p` lies on the closure of face `f` (at its own corner if it names one)
  bool in_face(const Point& p, face_descriptor f) const
  {
    const TriangleMesh& tm = mesh();
    if(!p.on_vertex) return face(p.h, tm) == f || face(opposite(p.h, tm), tm) == f;
    if(p.has_corner()) return face(p.h, tm) == f;
    const halfedge_descriptor h0 = halfedge(f, tm);
    return target(h0, tm) == p.v || target(next(h0, tm), tm) == p.v || source(h0, tm) == p.v;
  }

  /// the corner of the vertex point `p` in face `f` (its own, or the unique one); throws
  /// `Invalid_path_error` if `f` uses the vertex more than once and `p` names no corner
  halfedge_descriptor corner_in(const Point& p, face_descriptor f) const
  {
    const TriangleMesh& tm = mesh();
    if(p.has_corner()) return p.h;
    halfedge_descriptor h = halfedge(f, tm), c = GT::null_halfedge();
    for(int i = 0; i < 3; ++i, h = next(h, tm))
      if(target(h, tm) == p.v) {
        if(c != GT::null_halfedge())
          throw Invalid_path_error("Surface_shortest_words: a face uses a vertex of the path more than once: the vertex "
                                   "point must name its corner (Surface_point::corner)");
        c = h;
      }
    if(c == GT::null_halfedge()) throw Invalid_path_error("Surface_shortest_words: point not in face");
    return c;
  }

  /// the segment from `p` to `q`: a face containing both, preferring `hint`, with the corners of vertex
  /// points; two vertex points of the same vertex are a turn. Throws `Invalid_path_error` if there is none.
  Step step(const Point& p, const Point& q, face_descriptor hint) const
  {
    const TriangleMesh& tm = mesh();
    Step s;
    if(p.on_vertex && q.on_vertex && p.v == q.v) {
      s.turn = true;
      if(p.has_corner()) s.face = face(p.h, tm);
      else if(hint != GT::null_face() && in_face(p, hint)) s.face = hint;
      else s.face = face(halfedge(p.v, tm), tm);
      s.in = s.out = corner_in(p, s.face);
      return s;
    }
    if(!needs_corners_ && p.on_vertex && q.on_vertex && !p.has_corner() && !q.has_corner())
      return vertex_step(p.v, q.v, hint);
    s.face = GT::null_face();
    if(needs_corners_ && !p.on_vertex && in_face(q, face(opposite(p.h, tm), tm))) {
      // both faces of p's edge may contain q (a face using a vertex twice): the crossing convention decides,
      // the segment after an edge point is in face(opposite(h))
      s.face = face(opposite(p.h, tm), tm);
    }
    else if(hint != GT::null_face() && in_face(p, hint) && in_face(q, hint)) s.face = hint;
    else if(p.has_corner()) { if(in_face(q, face(p.h, tm))) s.face = face(p.h, tm); }
    else if(p.on_vertex) {
      for(halfedge_descriptor h : CGAL::halfedges_around_target(p.v, tm))
        if(in_face(q, face(h, tm))) { s.face = face(h, tm); break; }
    } else {
      const face_descriptor f0 = face(p.h, tm), f1 = face(opposite(p.h, tm), tm);
      if(in_face(q, f0)) s.face = f0; else if(in_face(q, f1)) s.face = f1;
    }
    if(s.face == GT::null_face())
      throw Invalid_path_error("Surface_shortest_words: consecutive path points do not lie in a common face");
    if(p.on_vertex) s.in = corner_in(p, s.face);
    if(q.on_vertex) s.out = corner_in(q, s.face);
    return s;
  }

private:
  // step() between the distinct vertices a and b of a mesh in which no face uses a vertex twice (the path
  // of an edge loop: most of the steps of `steps()`), with the same choice of face as the general case (the
  // hint, else the first face around a, in the order of `halfedges_around_target`, that has b as a vertex) and
  // the corners read from the halfedge found instead of searched for
  Step vertex_step(vertex_descriptor a, vertex_descriptor b, face_descriptor hint) const
  {
    const TriangleMesh& tm = mesh();
    Step s;
    if(hint != GT::null_face()) {
      const halfedge_descriptor h0 = halfedge(hint, tm), h1 = next(h0, tm), h2 = next(h1, tm);
      const halfedge_descriptor hs[3] = {h0, h1, h2};
      halfedge_descriptor ca = GT::null_halfedge(), cb = GT::null_halfedge();
      for(halfedge_descriptor h : hs) {
        const vertex_descriptor t = target(h, tm);
        if(t == a) ca = h; else if(t == b) cb = h;
      }
      if(ca != GT::null_halfedge() && cb != GT::null_halfedge()) { s.face = hint; s.in = ca; s.out = cb; return s; }
    }
    for(halfedge_descriptor h : CGAL::halfedges_around_target(a, tm)) {
      if(source(h, tm) == b) { s.face = face(h, tm); s.in = h; s.out = prev(h, tm); return s; }
      const halfedge_descriptor n = next(h, tm);
      if(target(n, tm) == b) { s.face = face(h, tm); s.in = h; s.out = n; return s; }
    }
    throw Invalid_path_error("Surface_shortest_words: consecutive path points do not lie in a common face");
  }

public:
  /// a face containing both points, preferring `hint` (the face of `step()`)
  face_descriptor common_face(const Point& p, const Point& q, face_descriptor hint) const { return step(p, q, hint).face; }

  /// the segments of a path (checks it: points valid, consecutive points in a common face); throws
  /// `Invalid_path_error`
  std::vector<Step> steps(const Path& path) const
  {
    if(path.empty()) throw Invalid_path_error("Surface_shortest_words: empty path");
    for(const Point& p : path) check_point(p);
    std::vector<Step> r;
    r.reserve(path.size());
    face_descriptor f = GT::null_face();
    for(std::size_t i = 0; i + 1 < path.size(); ++i) { r.push_back(step(path[i], path[i + 1], f)); f = r.back().face; }
    return r;
  }

  /// checks a path (points valid, consecutive points in a common face); throws `Invalid_path_error`
  void check_path(const Path& path) const { steps(path); }

  /// Appends to `out` the halfedges crossed when turning around `target(a)` from corner `a` to corner `b`
  /// (counterclockwise if `ccw`); returns their number. Throws `Invalid_path_error` if `b` is not a corner
  /// of that vertex.
  template <class Out>
  std::size_t turn(halfedge_descriptor a, halfedge_descriptor b, bool ccw, Out out) const
  {
    const TriangleMesh& tm = mesh();
    std::size_t n = 0;
    for(halfedge_descriptor h = a; h != b; ++n) {
      const halfedge_descriptor c = ccw ? h : next(h, tm);
      *out++ = c;
      h = ccw ? prev(opposite(h, tm), tm) : opposite(next(h, tm), tm);
      if(h == a) throw Invalid_path_error("Surface_shortest_words: a corner is not around the vertex of the path");
    }
    return n;
  }

  /// number of halfedges crossed by `turn(a, b, ccw, ...)`
  std::size_t turn_length(halfedge_descriptor a, halfedge_descriptor b, bool ccw) const
  {
    struct Counter { Counter& operator*() { return *this; } Counter& operator++(int) { return *this; }
                     Counter& operator=(halfedge_descriptor) { return *this; } } c;
    return turn(a, b, ccw, c);
  }

  /// The halfedges crossed at the path point `p` from the step `from` (ending at `p`) to the step `to`
  /// (starting at `p`): the edge of an edge point, or the shorter turn around a vertex.
  template <class Out>
  void crossings_at(const Point& p, const Step& from, const Step& to, Out out) const
  {
    const TriangleMesh& tm = mesh();
    if(!p.on_vertex) {
      if(from.face == to.face) return;
      halfedge_descriptor h = p.h;
      if(face(h, tm) != from.face) h = opposite(h, tm);
      if(face(h, tm) != from.face || face(opposite(h, tm), tm) != to.face)
        throw Invalid_path_error("Surface_shortest_words: inconsistent path");
      *out++ = h;
      return;
    }
    if(from.out == to.in) return;
    const bool ccw = turn_length(from.out, to.in, true) <= turn_length(from.out, to.in, false);
    turn(from.out, to.in, ccw, out);
  }

  // ------------------------------------------------------------------ conversions
  /// the path of a halfedge path (each halfedge starting where the previous one ends): its vertices, or,
  /// if `needs_corners()`, for every halfedge its source corner, its midpoint and its target corner
  Path path_from_halfedges(const std::vector<halfedge_descriptor>& hs) const
  {
    const TriangleMesh& tm = mesh();
    Path r;
    if(hs.empty()) return r;
    for(halfedge_descriptor h : hs)
      if(!internal::is_valid_handle(tm, h) || h == GT::null_halfedge())
        throw Invalid_path_error("Surface_shortest_words: invalid halfedge (not on the mesh)");
    for(std::size_t i = 1; i < hs.size(); ++i)
      if(source(hs[i], tm) != target(hs[i - 1], tm))
        throw Invalid_path_error("Surface_shortest_words: halfedge path is not connected");
    if(!needs_corners_) {
      r.push_back(Point::vertex(source(hs.front(), tm)));
      for(halfedge_descriptor h : hs) r.push_back(Point::vertex(target(h, tm)));
      return r;
    }
    for(halfedge_descriptor h : hs) {
      const Point a = corner(prev(h, tm));
      if(r.empty() || !(r.back().v == a.v && r.back().h == a.h)) r.push_back(a);
      r.push_back(Point::on_edge(h, 0.5));
      r.push_back(corner(h));
    }
    return r;
  }

  /// the path of a CGAL `Surface_mesh_topology::Path_on_surface` (requires its map to be this mesh)
  Path path_from_path_on_surface(const CGAL::Surface_mesh_topology::Path_on_surface<TriangleMesh>& p) const
  {
    std::vector<halfedge_descriptor> hs;
    for(std::size_t i = 0; i < p.length(); ++i) hs.push_back(p[i]);
    return path_from_halfedges(hs);
  }

  /// the halfedges of an edge path: vertex points, consecutive ones adjacent or of the same vertex (a turn),
  /// or separated by one edge point of an edge joining them (as `path_from_halfedges()` gives);
  /// throws `Invalid_path_error` otherwise
  std::vector<halfedge_descriptor> halfedges_of_edge_path(const Path& path) const
  {
    const TriangleMesh& tm = mesh();
    std::vector<halfedge_descriptor> hs;
    for(std::size_t i = 0; i + 1 < path.size(); ++i) {
      const Point& a = path[i];
      if(!a.on_vertex) throw Invalid_path_error("Surface_shortest_words: not an edge path (a point is not a vertex)");
      const Point& b = path[i + 1];
      if(!b.on_vertex) {
        if(i + 2 >= path.size() || !path[i + 2].on_vertex)
          throw Invalid_path_error("Surface_shortest_words: not an edge path (an edge point between two vertices expected)");
        const Point& c = path[i + 2];
        // from a to c; a self-loop is oriented by the corners (source corner prev(h), target corner h)
        const halfedge_descriptor cand[2] = {b.h, opposite(b.h, tm)};
        halfedge_descriptor h = GT::null_halfedge();
        for(halfedge_descriptor g : cand)
          if(source(g, tm) == a.v && target(g, tm) == c.v && (!a.has_corner() || a.h == prev(g, tm)) &&
             (!c.has_corner() || c.h == g)) { h = g; break; }
        if(h == GT::null_halfedge())
          for(halfedge_descriptor g : cand)
            if(source(g, tm) == a.v && target(g, tm) == c.v) { h = g; break; }
        if(h == GT::null_halfedge())
          throw Invalid_path_error("Surface_shortest_words: not an edge path (an edge point on an edge not joining its neighbours)");
        hs.push_back(h);
        ++i;
        continue;
      }
      if(a.v == b.v) continue;
      if(a.has_corner()) {
        // the side of face(a.h) from the corner of a to b: next(a.h) or a.h backwards
        const halfedge_descriptor n = next(a.h, tm), p = prev(a.h, tm);
        if(target(n, tm) == b.v && (!b.has_corner() || b.h == n)) hs.push_back(n);
        else if(source(a.h, tm) == b.v && (!b.has_corner() || b.h == p)) hs.push_back(opposite(a.h, tm));
        else throw Invalid_path_error("Surface_shortest_words: consecutive vertices are not adjacent in the corner's face");
        continue;
      }
      std::pair<halfedge_descriptor, bool> hb = halfedge(a.v, b.v, tm);
      if(!hb.second) throw Invalid_path_error("Surface_shortest_words: consecutive vertices are not adjacent");
      hs.push_back(hb.first);
    }
    return hs;
  }

  /// the CGAL `Path_on_surface` of an edge path
  CGAL::Surface_mesh_topology::Path_on_surface<TriangleMesh> to_path_on_surface(const Path& path) const
  {
    CGAL::Surface_mesh_topology::Path_on_surface<TriangleMesh> r(mesh());
    for(halfedge_descriptor h : halfedges_of_edge_path(path)) r.push_back(h);
    return r;
  }

  // ------------------------------------------------------------------ geometry (the layer's charts)
  /// position of a point of face `c.face` in the layer's chart `c` (vertex points at corner `corner`, a
  /// halfedge of the face with the vertex as target)
  internal::Cplx position(const Point& p, halfedge_descriptor corner, const Face_chart& c) const
  {
    if(p.on_vertex) return internal::to_cplx(c.target_point(corner));
    for(int i = 0; i < 3; ++i) {
      if(p.h == c.h[i])
        return internal::point_along(internal::to_cplx(c.z[i]), internal::to_cplx(c.z[(i + 1) % 3]), p.t * length(p.h));
      if(p.h == opposite(c.h[i], mesh()))
        return internal::point_along(internal::to_cplx(c.z[(i + 1) % 3]), internal::to_cplx(c.z[i]), p.t * length(p.h));
    }
    throw Invalid_path_error("Surface_shortest_words: point not in face");
  }

  /// the hyperbolic length of a path (each segment measured in the layer's chart of its face)
  double path_length(const Path& path) const
  {
    const std::vector<Step> st = steps(path);
    double len = 0;
    for(std::size_t i = 0; i < st.size(); ++i) {
      if(st[i].turn) continue;
      const Face_chart c = this->chart(st[i].face);
      len += internal::hyperbolic_distance(position(path[i], st[i].in, c), position(path[i + 1], st[i].out, c));
    }
    return len;
  }

private:
  static const TriangleMesh& checked_handles(const TriangleMesh& tm)
  {
    for(halfedge_descriptor h : halfedges(tm)) {
      const face_descriptor f = face(h, tm);
      if(f != GT::null_face() && !internal::is_valid_handle(tm, f))
        throw Invalid_mesh_error("Surface_shortest_words: a halfedge refers to a face that is not on the mesh (invalid mesh)");
    }
    return tm;
  }

  void init()
  {
    const TriangleMesh& tm = mesh();
    needs_corners_ = false;
    for(face_descriptor f : faces(tm)) {
      const halfedge_descriptor h = halfedge(f, tm);
      const vertex_descriptor a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
      if(a == b || b == c || a == c) { needs_corners_ = true; return; }
    }
    // multi-edges: two edges with the same end vertices
    std::unordered_set<vertex_descriptor> nb;
    for(vertex_descriptor v : vertices(tm)) {
      nb.clear();
      for(halfedge_descriptor h : CGAL::halfedges_around_source(v, tm))
        if(!nb.insert(target(h, tm)).second) { needs_corners_ = true; return; }
    }
  }

  bool needs_corners_ = false;
};

} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_HYPERBOLIC_SURFACE_H
