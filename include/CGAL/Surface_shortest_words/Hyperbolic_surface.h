// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A closed triangle mesh with a hyperbolic metric given by edge lengths, points and paths on it.
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
#include <sstream>
#include <stdexcept>
#include <string>
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
using CGAL::Invalid_path_error;

/// \ingroup PkgSurfaceShortestWordsRef
/// Thrown when a computation needs more precision than double arithmetic offers (the lifted end point of a
/// path lies farther than `max_lift_distance` from its start in the universal cover), or does not terminate
/// within its step bound.
class Precision_error : public std::runtime_error
{
public:
  explicit Precision_error(const std::string& w) : std::runtime_error(w) {}
};

/*!
  \ingroup PkgSurfaceShortestWordsRef
  A point of a triangulated surface: a vertex, or the point of the edge of halfedge `h` at the fraction `t`
  (0 < t < 1) of the edge's hyperbolic length, measured from `source(h)`.
*/
template <class TriangleMesh>
struct Surface_point
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor   vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  bool on_vertex = true;
  vertex_descriptor v{};
  halfedge_descriptor h{};
  double t = 0;

  static Surface_point vertex(vertex_descriptor vd) { Surface_point p; p.on_vertex = true; p.v = vd; return p; }
  static Surface_point on_edge(halfedge_descriptor hd, double tt)
  { Surface_point p; p.on_vertex = false; p.h = hd; p.t = tt; return p; }
};

/// a path on the surface: consecutive points lie in a common face (the path is the geodesic segment between
/// them inside that face); a loop is a path whose first and last points coincide.
template <class TriangleMesh>
using Surface_path = std::vector<Surface_point<TriangleMesh> >;

/*!
  \ingroup PkgSurfaceShortestWordsRef
  A closed triangulated surface with a hyperbolic metric: a `TriangleMesh` (model of `FaceGraph`, closed,
  triangles only, no face using a vertex twice) and a readable property map `EdgeLengthMap` from
  `edge_descriptor` to `double` giving the hyperbolic length of every edge.

  The constructor checks, in release builds too, that the mesh is closed and triangulated, that every face
  satisfies the strict triangle inequality, that the angle sum at every vertex (hyperbolic law of cosines)
  is 2 pi up to `angle_tolerance` (zero curvature: the metric is a smooth hyperbolic metric, so the universal
  cover embeds isometrically in the hyperbolic plane) and that the genus is at least 2 (Gauss-Bonnet).
  It throws `Invalid_metric_error` otherwise. Cost: linear in the mesh size.

  The object keeps references to the mesh and the map: they must outlive it and not change.
*/
template <class TriangleMesh, class EdgeLengthMap>
class Hyperbolic_surface
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor   vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor     edge_descriptor;
  typedef typename GT::face_descriptor     face_descriptor;
  typedef Surface_point<TriangleMesh> Point;
  typedef Surface_path<TriangleMesh>  Path;

  Hyperbolic_surface(const TriangleMesh& tm, EdgeLengthMap lengths, double angle_tolerance = 1e-6)
    : tm_(tm), lengths_(lengths), angle_tolerance_(angle_tolerance)
  {
    check();
  }

  const TriangleMesh& mesh() const { return tm_; }

  /// hyperbolic length of the edge of `h`
  double length(halfedge_descriptor h) const { return get(lengths_, edge(h, tm_)); }

  /// the interior angle at `target(h)` of the face of `h` (between `h` and `next(h)`)
  double angle_at_target(halfedge_descriptor h) const
  {
    const halfedge_descriptor n = next(h, tm_), p = prev(h, tm_);
    return CGAL::Hyperbolic_surface_2::corner_angle(length(p), length(h), length(n));
  }

  /// genus, from the Euler characteristic
  int genus() const { return genus_; }

  /// largest |angle sum - 2 pi| over the vertices (measured at construction)
  double max_angle_defect() const { return max_defect_; }

  /// the hyperbolic area 4 pi (g - 1) (Gauss-Bonnet)
  double area() const { return 4.0 * CGAL_PI * (genus_ - 1); }

  // ------------------------------------------------------------------ paths
  /// checks that `p` is a valid point; throws `Invalid_path_error` otherwise
  void check_point(const Point& p) const
  {
    if(p.on_vertex) {
      if(!internal::is_valid_handle(tm_, p.v)) throw Invalid_path_error("Surface_shortest_words: invalid vertex (not on the mesh)");
      return;
    }
    if(!internal::is_valid_handle(tm_, p.h)) throw Invalid_path_error("Surface_shortest_words: invalid halfedge (not on the mesh)");
    if(!(p.t > 0.0 && p.t < 1.0) || !std::isfinite(p.t))
      throw Invalid_path_error("Surface_shortest_words: an edge point needs 0 < t < 1 (use a vertex point at the ends)");
  }

  /// the faces containing `p` (the incident faces of a vertex, the two faces of an edge)
  std::vector<face_descriptor> faces_of(const Point& p) const
  {
    std::vector<face_descriptor> r;
    if(p.on_vertex) {
      for(halfedge_descriptor h : CGAL::halfedges_around_target(p.v, tm_)) r.push_back(face(h, tm_));
    } else {
      r.push_back(face(p.h, tm_));
      r.push_back(face(opposite(p.h, tm_), tm_));
    }
    return r;
  }

  /// true if `p` and `q` denote the same point of the surface
  bool same_point(const Point& p, const Point& q) const
  {
    if(p.on_vertex != q.on_vertex) return false;
    if(p.on_vertex) return p.v == q.v;
    if(p.h == q.h) return p.t == q.t;
    return p.h == opposite(q.h, tm_) && p.t == 1.0 - q.t;
  }

  /// a face containing both points, preferring `hint`; throws `Invalid_path_error` if there is none
  face_descriptor common_face(const Point& p, const Point& q, face_descriptor hint) const
  {
    face_descriptor found = GT::null_face();
    auto consider = [&](face_descriptor f) {
      if(f == hint) { found = f; return true; }
      if(found == GT::null_face()) found = f;
      return false;
    };
    if(p.on_vertex && q.on_vertex) {
      if(p.v == q.v) {
        for(halfedge_descriptor h : CGAL::halfedges_around_target(p.v, tm_)) if(consider(face(h, tm_))) break;
      } else {
        for(halfedge_descriptor h : CGAL::halfedges_around_source(p.v, tm_))
          if(target(h, tm_) == q.v) {
            if(consider(face(h, tm_))) break;
            if(consider(face(opposite(h, tm_), tm_))) break;
          }
        // p and q may also be opposite corners' vertices of a face only through an edge: done above
      }
    } else if(p.on_vertex != q.on_vertex) {
      const Point& v = p.on_vertex ? p : q;
      const Point& e = p.on_vertex ? q : p;
      const halfedge_descriptor hs[2] = {e.h, opposite(e.h, tm_)};
      for(halfedge_descriptor h : hs)
        if(source(h, tm_) == v.v || target(h, tm_) == v.v || target(next(h, tm_), tm_) == v.v)
          if(consider(face(h, tm_))) break;
    } else {
      const face_descriptor fp[2] = {face(p.h, tm_), face(opposite(p.h, tm_), tm_)};
      const face_descriptor fq[2] = {face(q.h, tm_), face(opposite(q.h, tm_), tm_)};
      bool stop = false;
      for(int i = 0; i < 2 && !stop; ++i)
        for(int j = 0; j < 2 && !stop; ++j)
          if(fp[i] == fq[j]) stop = consider(fp[i]);
    }
    if(found == GT::null_face())
      throw Invalid_path_error("Surface_shortest_words: consecutive path points do not lie in a common face");
    return found;
  }

  /// checks a path (points valid, consecutive points in a common face); throws `Invalid_path_error`
  void check_path(const Path& path) const
  {
    if(path.empty()) throw Invalid_path_error("Surface_shortest_words: empty path");
    for(const Point& p : path) check_point(p);
    face_descriptor f = GT::null_face();
    for(std::size_t i = 0; i + 1 < path.size(); ++i) f = common_face(path[i], path[i + 1], f);
  }

  /// the path of the vertices of a halfedge path (each halfedge starting where the previous one ends)
  Path path_from_halfedges(const std::vector<halfedge_descriptor>& hs) const
  {
    Path r;
    if(hs.empty()) return r;
    for(halfedge_descriptor h : hs)
      if(!internal::is_valid_handle(tm_, h)) throw Invalid_path_error("Surface_shortest_words: invalid halfedge (not on the mesh)");
    r.push_back(Point::vertex(source(hs.front(), tm_)));
    for(std::size_t i = 0; i < hs.size(); ++i) {
      if(i > 0 && source(hs[i], tm_) != target(hs[i - 1], tm_))
        throw Invalid_path_error("Surface_shortest_words: halfedge path is not connected");
      r.push_back(Point::vertex(target(hs[i], tm_)));
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

  /// the halfedges of a path whose points are all vertices, consecutive vertices adjacent (an edge path);
  /// throws `Invalid_path_error` otherwise
  std::vector<halfedge_descriptor> halfedges_of_edge_path(const Path& path) const
  {
    std::vector<halfedge_descriptor> hs;
    for(std::size_t i = 0; i + 1 < path.size(); ++i) {
      if(!path[i].on_vertex || !path[i + 1].on_vertex)
        throw Invalid_path_error("Surface_shortest_words: not an edge path (a point is not a vertex)");
      if(path[i].v == path[i + 1].v) continue;
      std::pair<halfedge_descriptor, bool> hb = halfedge(path[i].v, path[i + 1].v, tm_);
      if(!hb.second) throw Invalid_path_error("Surface_shortest_words: consecutive vertices are not adjacent");
      hs.push_back(hb.first);
    }
    return hs;
  }

  /// the CGAL `Path_on_surface` of an edge path
  CGAL::Surface_mesh_topology::Path_on_surface<TriangleMesh> to_path_on_surface(const Path& path) const
  {
    CGAL::Surface_mesh_topology::Path_on_surface<TriangleMesh> r(tm_);
    for(halfedge_descriptor h : halfedges_of_edge_path(path)) r.push_back(h);
    return r;
  }

  /// the hyperbolic length of a path (each segment measured in a layout of its face)
  double path_length(const Path& path) const
  {
    check_path(path);
    double len = 0;
    face_descriptor f = GT::null_face();
    for(std::size_t i = 0; i + 1 < path.size(); ++i) {
      f = common_face(path[i], path[i + 1], f);
      internal::Cplx z[3]; halfedge_descriptor h0;
      layout_face(f, h0, z);
      len += internal::hyperbolic_distance(position_in_face(path[i], h0, z), position_in_face(path[i + 1], h0, z));
    }
    return len;
  }

  // ------------------------------------------------------------------ layouts (used by the algorithms)
  /// lays out face `f` with `source(halfedge(f))` at the origin and its target on the positive real axis
  void layout_face(face_descriptor f, halfedge_descriptor& h0, std::complex<double> z[3]) const
  {
    h0 = halfedge(f, tm_);
    const halfedge_descriptor h1 = next(h0, tm_), h2 = next(h1, tm_);
    z[0] = internal::Cplx(0, 0);
    z[1] = internal::Cplx(std::tanh(length(h0) / 2.0), 0);
    z[2] = internal::third_vertex(z[0], z[1], length(h1), length(h2), length(h0));
  }

  /// position of a point of the face of `h0` whose vertices source(h0), target(h0), target(next(h0)) are
  /// at z[0], z[1], z[2]
  std::complex<double> position_in_face(const Point& p, halfedge_descriptor h0, const std::complex<double> z[3]) const
  {
    halfedge_descriptor h = h0;
    for(int i = 0; i < 3; ++i, h = next(h, tm_)) {
      const int j = (i + 1) % 3;
      if(p.on_vertex) {
        if(source(h, tm_) == p.v) return z[i];
      } else if(p.h == h) {
        return internal::point_along(z[i], z[j], p.t * length(h));
      } else if(p.h == opposite(h, tm_)) {
        return internal::point_along(z[j], z[i], p.t * length(h));
      }
    }
    throw Invalid_path_error("Surface_shortest_words: point not in face");
  }

private:
  void check()
  {
    if(num_faces(tm_) == 0) throw Invalid_metric_error("Surface_shortest_words: empty mesh");
    for(halfedge_descriptor h : halfedges(tm_)) {
      const face_descriptor f = face(h, tm_);
      if(f != GT::null_face() && !internal::is_valid_handle(tm_, f))
        throw Invalid_metric_error("Surface_shortest_words: a halfedge refers to a face that is not on the mesh (invalid mesh)");
      if(is_border(h, tm_))
        throw Invalid_metric_error("Surface_shortest_words: the mesh has a boundary (a closed surface is required)");
    }
    for(face_descriptor f : faces(tm_)) {
      const halfedge_descriptor h0 = halfedge(f, tm_), h1 = next(h0, tm_), h2 = next(h1, tm_);
      if(next(h2, tm_) != h0) throw Invalid_metric_error("Surface_shortest_words: the mesh has a non-triangular face");
      const vertex_descriptor a = source(h0, tm_), b = target(h0, tm_), c = target(h1, tm_);
      if(a == b || b == c || a == c)
        throw Invalid_metric_error("Surface_shortest_words: a face uses a vertex twice (the mesh must be simplicial)");
      if(!internal::is_triangle(length(h0), length(h1), length(h2))) {
        std::ostringstream os;
        os << "Surface_shortest_words: edge lengths " << length(h0) << ", " << length(h1) << ", " << length(h2)
           << " of a face violate the triangle inequality";
        throw Invalid_metric_error(os.str());
      }
    }
    // the shared layer checks the rest (connected, orientable surface) and measures the angle sums
    // (half-angle formula); the tolerance is applied here to keep this class's message and exception type
    const CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<TriangleMesh, EdgeLengthMap> layer(
      tm_, lengths_, CGAL::Hyperbolic_surface_2::parameters::require_smooth_metric(false));
    genus_ = layer.genus();
    max_defect_ = 0;
    for(vertex_descriptor v : vertices(tm_)) {
      const double sum = layer.angle_sum(v);
      const double defect = std::abs(sum - 2.0 * CGAL_PI);
      max_defect_ = (std::max)(max_defect_, defect);
      if(!(defect <= angle_tolerance_)) {
        std::ostringstream os;
        os.precision(12);
        os << "Surface_shortest_words: the metric is not hyperbolic: angle sum " << sum
           << " at a vertex differs from 2 pi by " << defect << " (tolerance " << angle_tolerance_ << ")";
        throw Invalid_metric_error(os.str());
      }
    }
    if(genus_ < 2) {
      std::ostringstream os;
      os << "Surface_shortest_words: genus " << genus_ << " < 2 has no hyperbolic metric";
      throw Invalid_metric_error(os.str());
    }
  }

  const TriangleMesh& tm_;
  EdgeLengthMap lengths_;
  double angle_tolerance_;
  int genus_ = 0;
  double max_defect_ = 0;
};

} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_HYPERBOLIC_SURFACE_H
