// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The transient embedding of Algorithm 2 on the shared layer's charts, and the exact reduction of a
// sequence of crossed edges.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_TRANSIENT_CHART_H
#define CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_TRANSIENT_CHART_H

#include <CGAL/Surface_shortest_words/internal/layout.h>
#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <deque>
#include <vector>

namespace CGAL {
namespace Surface_shortest_words {
namespace internal {

// One face of the surface in the Poincare disk, moved from face to face: it starts as the layer's chart of
// a face (`Hyperbolic_surface_triangulation::chart()`) and is unfolded across edges with the layer's
// `neighbor_apex()`, then moved by isometries (`transform()`) to keep the current point at the origin.
// z()[i] is the position of source(halfedge_at(i)) (the layer's Face_chart convention).
template <class Surface>
class Transient_chart
{
public:
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  typedef typename Surface::face_descriptor face_descriptor;
  typedef typename Surface::vertex_descriptor vertex_descriptor;

  explicit Transient_chart(const Surface& s) : s_(s) {}

  /// the layer's chart of `f`
  void set_face(face_descriptor f)
  {
    const typename Surface::Face_chart c = s_.chart(f);
    for(int i = 0; i < 3; ++i) { h_[i] = c.h[i]; z_[i] = to_cplx(c.z[i]); }
    face_ = f;
    ++count_;
  }
  /// the current face as a layer chart (current coordinates)
  typename Surface::Face_chart face_chart() const
  {
    typename Surface::Face_chart c;
    c.face = face_;
    for(int i = 0; i < 3; ++i) { c.h[i] = h_[i]; c.z[i] = to_point(z_[i]); }
    return c;
  }
  face_descriptor current_face() const { return face_; }
  const Cplx* z() const { return z_; }
  std::size_t count() const { return count_; }
  const Isometry& accumulated() const { return phi_; }

  int index_of(halfedge_descriptor h) const { return h == h_[0] ? 0 : (h == h_[1] ? 1 : (h == h_[2] ? 2 : -1)); }
  halfedge_descriptor halfedge_at(int i) const { return h_[i]; }
  /// index of the position of the corner `c` (a halfedge of the face; the corner at target(c))
  int index_of_corner(halfedge_descriptor c) const { return (index_of(c) + 1) % 3; }

  /// moves the chart to the face across the edge of `h` (a halfedge of the current face): the layer's
  /// neighbour apex on the lifted edge
  void unfold(halfedge_descriptor h)
  {
    const int i = index_of(h);
    CGAL_assertion(i >= 0);
    const Cplx zs = z_[i], zt = z_[(i + 1) % 3]; // source(h), target(h)
    const auto& tm = s_.mesh();
    const halfedge_descriptor o = opposite(h, tm);
    const Cplx apex = to_cplx(s_.neighbor_apex(h, to_point(zs), to_point(zt)));
    face_ = face(o, tm);
    h_[0] = halfedge(face_, tm); h_[1] = next(h_[0], tm); h_[2] = next(h_[1], tm);
    const int j = index_of(o);
    z_[j] = zt; z_[(j + 1) % 3] = zs; z_[(j + 2) % 3] = apex; // source(o) = target(h)
    ++count_;
  }

  /// the halfedge of the current face crossed when turning around the corner `c` (ccw: c itself, cw:
  /// next(c)), and the corner reached
  halfedge_descriptor rotation_halfedge(halfedge_descriptor c, bool ccw) const { return ccw ? c : next(c, s_.mesh()); }
  halfedge_descriptor rotated_corner(halfedge_descriptor c, bool ccw) const
  {
    const auto& tm = s_.mesh();
    return ccw ? prev(opposite(c, tm), tm) : opposite(next(c, tm), tm);
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
  const Surface& s_;
  face_descriptor face_{};
  halfedge_descriptor h_[3];
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
    for(;;) {
      reduce(c);
      if(todo_.empty()) return;
      c = todo_.front();
      todo_.pop_front();
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
  std::size_t degree(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v) const
  {
    return CGAL::halfedges_around_target(v, tm_).size();
  }

  // pushes the crossing c, replacing the run it ends by the shorter turn if it is more than half a turn
  // (the replacement crossings go to the front of todo_)
  void reduce(halfedge_descriptor c)
  {
    if(!st_.empty() && st_.back().h == opposite(c, tm_)) { st_.pop_back(); return; }
    std::size_t rccw = 1, rcw = 1;
    if(!st_.empty()) {
      if(c == prev(opposite(st_.back().h, tm_), tm_)) rccw = st_.back().ccw + 1;
      if(c == next(opposite(st_.back().h, tm_), tm_)) rcw = st_.back().cw + 1;
    }
    st_.push_back(Entry{c, rccw, rcw});
    // more than half a turn: 2 r > degree. A run of one crossing is that only around a vertex of degree 1,
    // which is recognised without circulating (the degree is counted only for longer runs)
    std::vector<halfedge_descriptor> rep;
    if(rccw > 1 ? 2 * rccw > degree(target(c, tm_)) : opposite(next(c, tm_), tm_) == c) {
      // counterclockwise around target(c): replace by the clockwise turn
      // (corners, not faces: a face may meet the vertex at several corners)
      halfedge_descriptor h = st_[st_.size() - rccw].h;
      const halfedge_descriptor end = prev(opposite(c, tm_), tm_);
      st_.resize(st_.size() - rccw);
      while(h != end) { rep.push_back(next(h, tm_)); h = opposite(next(h, tm_), tm_); }
    } else if(rcw > 1 ? 2 * rcw > degree(source(c, tm_)) : next(opposite(c, tm_), tm_) == c) {
      // clockwise around source(c): replace by the counterclockwise turn
      halfedge_descriptor h = prev(st_[st_.size() - rcw].h, tm_);
      const halfedge_descriptor end = opposite(c, tm_);
      st_.resize(st_.size() - rcw);
      while(h != end) { rep.push_back(h); h = prev(opposite(h, tm_), tm_); }
    } else {
      return;
    }
    todo_.insert(todo_.begin(), rep.begin(), rep.end());
  }

  const TriangleMesh& tm_;
  std::vector<Entry> st_;
  std::deque<halfedge_descriptor> todo_;
};

} // namespace internal
} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_TRANSIENT_CHART_H
