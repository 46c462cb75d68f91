// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Member functions of Delaunay_triangulation_on_surface for feature loops given on the surface: a loop given
// as a lift (a polyline of the disk in the frame of the reference triangulation) becomes a chain of constrained
// edges by conforming midpoint splits, with its crossings with constrained edges inserted as vertices.
// Included by <CGAL/Hyperbolic_surface_mesh_2/Delaunay_triangulation_on_surface.h>.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_FEATURE_LOOPS_IMPL_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_FEATURE_LOOPS_IMPL_H

#include <vector>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {

#define CGAL_HSM2_DT Delaunay_triangulation_on_surface<Traits_>

template <class Traits_>
template <class PointRange>
typename CGAL_HSM2_DT::Feature_loop_result CGAL_HSM2_DT::insert_feature_loop(const PointRange& lift,
                                                                              std::size_t max_insertions)
{
  const std::vector<Point_2> pts(lift.begin(), lift.end());
  if(pts.size() < 2)
    throw Invalid_path_error("Delaunay_triangulation_on_surface::insert_feature_loop: a loop needs at least two "
                             "points (the last one a lift of the first)");
  for(const Point_2& p : pts) internal::check_in_disk(p, "Delaunay_triangulation_on_surface::insert_feature_loop");
  for(std::size_t k = 0; k + 1 < pts.size(); ++k)
    if(!(Geometry::distance(pts[k], pts[k + 1]) > 0))
      throw Invalid_path_error("Delaunay_triangulation_on_surface::insert_feature_loop: two consecutive points are equal");
  Feature_loop_result res;
  const std::size_t nv0 = nv_;
  // the loop must close: the last point is located on the vertex of the first (else the triangulation is given
  // back its vertex set and nothing else changes)
  const Vertex_index first = insert_loop_point(pts.front());
  const Location last = locate_in_frame(pts.back());
  if(first == null_index || last.type != Location::ON_VERTEX || faces_[last.face].v[last.index] != first) {
    if(first != null_index && nv_ > nv0) remove(first);
    throw Invalid_path_error("Delaunay_triangulation_on_surface::insert_feature_loop: the last point is not a lift "
                             "of the first (the loop does not close on the surface)");
  }
  std::vector<Vertex_index> vs(1, first);
  for(std::size_t k = 1; k < pts.size(); ++k) {
    const Vertex_index v = insert_loop_point(pts[k]);
    if(v == null_index) throw Numerical_error("Delaunay_triangulation_on_surface::insert_feature_loop: a point of the loop could not be inserted");
    vs.push_back(v);
  }
  res.vertices_inserted = nv_ - nv0;
  std::vector<Loop_segment> todo; // (consecutive points on the same vertex: a loop edge, at distinct lifts)
  for(std::size_t k = pts.size() - 1; k-- > 0;) todo.push_back(Loop_segment{pts[k], pts[k + 1], vs[k], vs[k + 1]});
  const auto midpoint = gt_.construct_hyperbolic_midpoint_2_object();
  std::size_t work = 0;
  while(!todo.empty()) {
    if(++work > 4 * max_insertions + 16) return res; // (each segment is either an edge or split: bounded work)
    const Loop_segment s = todo.back(); todo.pop_back();
    Trace tr = trace_segment(s);
    if(tr.type == Trace::EDGE) {
      if(!is_constrained(tr.face, tr.index)) {
        set_constrained(tr.face, tr.index, true);
        set_constrained(faces_[tr.face].nb[tr.index], faces_[tr.face].ne[tr.index], true);
        ++res.constrained_edges;
      }
      continue;
    }
    if(res.splits >= max_insertions) return res;
    ++res.splits;
    Vertex_index w = null_index;
    Point_2 wf;
    if(tr.type == Trace::VERTEX) { w = faces_[tr.face].v[tr.index]; wf = tr.frame_point; }
    else if(tr.type == Trace::CROSSING) {
      Location loc;
      loc.type = Location::ON_EDGE; loc.face = tr.face; loc.index = tr.index; loc.point = tr.point;
      snap_to_near_vertex(loc, nullptr, frame_resolution(tr.frame_point)); // (a crossing at a vertex, up to rounding)
      wf = tr.frame_point;
      if(loc.type == Location::ON_VERTEX && faces_[loc.face].v[loc.index] == faces_[tr.face].v[(tr.index + 2) % 3]) {
        // the other loop passes within rounding of the apex of the face, across the edge (e.g. two
        // geodesics through one point, which is a vertex of this loop): it is rerouted through that vertex (its
        // edge replaced by the two other edges of the face) and the segment is traced again
        for(int e = 0; e < 3; ++e) {
          const bool on = e != tr.index;
          if(on && !is_constrained(tr.face, e)) ++res.constrained_edges;
          set_constrained(tr.face, e, on);
          set_constrained(faces_[tr.face].nb[e], faces_[tr.face].ne[e], on);
        }
        --res.constrained_edges;
        todo.push_back(s);
        continue;
      }
      if(loc.type == Location::ON_VERTEX) w = faces_[loc.face].v[loc.index];
      else { w = insert(loc); ++res.crossings; ++res.vertices_inserted; }
    } else { // not an edge yet: split at the midpoint (conforming Delaunay refinement of the loop)
      wf = midpoint(s.a, s.b);
      const std::size_t nv = nv_;
      w = insert_loop_point(wf);
      if(nv_ > nv) ++res.vertices_inserted;
    }
    if(w == null_index || w == s.u || w == s.v)
      throw Numerical_error("Delaunay_triangulation_on_surface::insert_feature_loop: a segment of the loop became "
                            "too short to be split (rounding)");
    todo.push_back(Loop_segment{wf, s.b, w, s.v});
    todo.push_back(Loop_segment{s.a, wf, s.u, w});
  }
  res.complete = true;
  return res;
}

template <class Traits_>
typename CGAL_HSM2_DT::Vertex_index CGAL_HSM2_DT::insert_loop_point(const Point_2& p)
{
  // a point of a loop within rounding of a constrained edge (an exact crossing of two loops, e.g. two closed
  // geodesics through the same point) is inserted on that edge: else the two loops would meet at two vertices
  // 1e-16 apart
  Location loc = locate_in_frame(p);
  if(loc.type == Location::IN_FACE) {
    const Face& F = faces_[loc.face];
    const Point_2 kp = Geometry::to_klein(loc.point);
    for(int i = 0; i < 3; ++i) {
      if(!is_constrained(loc.face, i)) continue;
      const Point_2 a = Geometry::to_klein(F.z[i]), b = Geometry::to_klein(F.z[(i + 1) % 3]);
      const double ex = b.x() - a.x(), ey = b.y() - a.y(), l2 = ex * ex + ey * ey;
      const double cr = ex * (kp.y() - a.y()) - ey * (kp.x() - a.x());
      if(cr * cr < 1e-24 * l2 * l2) { loc.type = Location::ON_EDGE; loc.index = i; break; }
    }
  }
  return insert(loc);
}

template <class Traits_>
typename CGAL_HSM2_DT::Trace CGAL_HSM2_DT::trace_segment(const Loop_segment& s) const
{
  Trace r;
  Isometry_2 phi; // frame -> chart of the current face
  const Location la = locate_in_frame(s.a, &phi);
  if(la.type != Location::ON_VERTEX || faces_[la.face].v[la.index] != s.u)
    throw Numerical_error("Delaunay_triangulation_on_surface::insert_feature_loop: a vertex of the loop is not found "
                          "again at its position (rounding)");
  const auto orient = gt_.orientation_2_object();
  Point_2 B = phi.apply_unchecked(s.b);
  const double len = Geometry::distance(faces_[la.face].z[la.index], B);
  const double tol = (std::max)(frame_resolution(s.b), duplicate_distance * len);
  // 1. around u (twice): first the edge to v at B, then the corner whose wedge contains the direction to B
  Face_index g = la.face;
  int c = la.index;
  const Isometry_2 phi0 = phi;
  const Point_2 B0 = B;
  bool wedge = false;
  for(int pass = 0; pass < 2 && !wedge; ++pass) {
    g = la.face; c = la.index; phi = phi0; B = B0;
    for(std::size_t step = 0; step <= 3 * nf_ + 3; ++step) {
      const Face& F = faces_[g];
      const Point_2 &U = F.z[c], &P1 = F.z[(c + 1) % 3], &P2 = F.z[(c + 2) % 3];
      if(pass == 0) {
        if(F.v[(c + 1) % 3] == s.v && Geometry::distance(P1, B) < tol) { r.type = Trace::EDGE; r.face = g; r.index = c; return r; }
      } else {
        const CGAL::Orientation o1 = orient(U, P1, B), o2 = orient(P2, U, B);
        if(o1 == CGAL::COLLINEAR && Geometry::distance(P1, B) < len && Geometry::distance(U, P1) < len) {
          // the segment runs along edge c through its other end: that vertex is on the loop
          r.type = Trace::VERTEX; r.face = g; r.index = (c + 1) % 3;
          r.frame_point = rescaled(phi).inverse().apply_unchecked(P1);
          return r;
        }
        if(o1 == CGAL::LEFT_TURN && o2 == CGAL::LEFT_TURN) { wedge = true; break; }
      }
      const int e = (c + 2) % 3;
      const Isometry_2 t = transition(g, e);
      B = t.apply_unchecked(B);
      phi = rescaled(t * phi);
      c = F.ne[e];
      g = F.nb[e];
      if(g == la.face && c == la.index) break;
    }
  }
  if(!wedge) { r.type = Trace::NOT_AN_EDGE; return r; }
  // 2. the straight walk along the segment from the corner (g, c), through the edges it crosses
  Point_2 A = faces_[g].z[c];
  int k = (c + 1) % 3; // the edge crossed next
  for(std::size_t step = 0; step <= 10 * nf_ + 1000; ++step) {
    const Face& F = faces_[g];
    if(is_constrained(g, k)) { // a crossing with another loop (or a polygon side): a vertex there
      const Point_2 P = F.z[k], Q = F.z[(k + 1) % 3];
      const Point_2 ka = Geometry::to_klein(A), kb = Geometry::to_klein(B), kp = Geometry::to_klein(P), kq = Geometry::to_klein(Q);
      const double ex = kq.x() - kp.x(), ey = kq.y() - kp.y(), dx = kb.x() - ka.x(), dy = kb.y() - ka.y();
      const double den = dx * ey - dy * ex;
      const double t = ((kp.x() - ka.x()) * ey - (kp.y() - ka.y()) * ex) / den;
      const Point_2 X = Geometry::from_klein(Point_2(ka.x() + t * dx, ka.y() + t * dy));
      r.frame_point = rescaled(phi).inverse().apply_unchecked(X);
      r.face = g;
      const double sep = frame_resolution(r.frame_point), s_min = shortest_edge_sinh2(F);
      const double dk = near_corner(F, k, X, sep, s_min), dk1 = near_corner(F, (k + 1) % 3, X, sep, s_min);
      if(dk >= 0 && (dk1 < 0 || dk <= dk1)) { r.type = Trace::VERTEX; r.index = k; return r; }
      if(dk1 >= 0) { r.type = Trace::VERTEX; r.index = (k + 1) % 3; return r; }
      r.type = Trace::CROSSING; r.index = k; r.point = X;
      return r;
    }
    const Isometry_2 t = transition(g, k);
    A = t.apply_unchecked(A); B = t.apply_unchecked(B);
    phi = rescaled(t * phi);
    const int j = F.ne[k];
    g = F.nb[k];
    const Face& G = faces_[g];
    const int apex = (j + 2) % 3;
    if(G.v[apex] == s.v && Geometry::distance(G.z[apex], B) < tol) { r.type = Trace::NOT_AN_EDGE; return r; }
    // the end is in G (rounding: not met at the apex): the segment crosses edges, it is not an edge
    if(orient(G.z[(j + 1) % 3], G.z[apex], B) != CGAL::RIGHT_TURN && orient(G.z[apex], G.z[j], B) != CGAL::RIGHT_TURN)
    { r.type = Trace::NOT_AN_EDGE; return r; }
    const CGAL::Orientation oa = orient(A, B, G.z[apex]);
    if(oa == CGAL::COLLINEAR) { // the segment passes through the apex: a vertex on the loop
      r.type = Trace::VERTEX; r.face = g; r.index = apex;
      r.frame_point = rescaled(phi).inverse().apply_unchecked(G.z[apex]);
      return r;
    }
    // leave through the edge from the apex to the end of edge j on the other side of the segment's line
    const bool left_is_start = orient(A, B, G.z[j]) == CGAL::LEFT_TURN;
    if(oa == CGAL::RIGHT_TURN) k = left_is_start ? (j + 2) % 3 : (j + 1) % 3;
    else k = left_is_start ? (j + 1) % 3 : (j + 2) % 3;
  }
  throw Numerical_error("Delaunay_triangulation_on_surface::insert_feature_loop: the walk along a segment exceeded its work bound");
}

#undef CGAL_HSM2_DT

} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif
