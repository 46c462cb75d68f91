// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Thesis Theorem 2.6's setting: the canonical system of shortest geodesic loops through the base point and
// the fundamental polygon they bound, with the checks of its properties.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_GEODESIC_CANONICAL_SYSTEM_H
#define CGAL_SURFACE_SHORTEST_WORDS_GEODESIC_CANONICAL_SYSTEM_H

#include <CGAL/Surface_shortest_words/Shortest_word_solver.h>
#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>

#include <cmath>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_shortest_words {

/*!
  \ingroup PkgSurfaceShortestWordsRef
  The canonical system of geodesic loops through p of a `Shortest_word_solver` (given or computed canonical
  system), and its fundamental polygon in the Poincare disk (base frame: the layer's chart of the solver's base
  face recentred at p).
*/
template <class TriangleMesh>
struct Geodesic_canonical_system
{
  std::vector<Surface_path<TriangleMesh> > loops; ///< loop i: the shortest loop through p homotopic to generator i
  std::vector<double> lengths;                   ///< their hyperbolic lengths
  Word relator;                                  ///< the boundary word of the polygon (a1 b1 a1^-1 b1^-1 ...)
  /// the 4g vertices of the fundamental polygon, the lifts P_k = D(r_1 ... r_k)(p) of p (P_0 = p = origin):
  /// side k, from P_k to P_k+1, is the lift of loop |r_k+1| (backwards for an inverse letter)
  std::vector<internal::Layout_kernel::Point_2> polygon;
  std::vector<double> polygon_angles; ///< the interior angle of the polygon at each vertex
  double angle_sum = 0;               ///< their sum (2 pi: the corners at p fit together)
  double area = 0;                    ///< the polygon's area from a fan of triangles (4 pi (g - 1))
};

namespace internal {
// the angle at the origin-side point z0 from direction z1 to direction z2, counterclockwise, in [0, 2 pi)
inline double ccw_angle_at(const Cplx& z0, const Cplx& z1, const Cplx& z2)
{
  const Isometry m = to_origin(z0);
  const Cplx u = apply_isometry(m, z1), v = apply_isometry(m, z2);
  double a = std::arg(v) - std::arg(u);
  while(a < 0) a += 2 * CGAL_PI;
  while(a >= 2 * CGAL_PI) a -= 2 * CGAL_PI;
  return a;
}
} // namespace internal

/*!
  \ingroup PkgSurfaceShortestWordsRef
  Computes the shortest geodesic loops through p of the solver's canonical generators (traced from their deck
  transformations, `Shortest_word_solver::shortest_loop_of_word()`) and the fundamental polygon they bound:
  its vertices, interior angles (at P_k, from the side towards P_k+1 counterclockwise to the side towards
  P_k-1, for a counterclockwise polygon), their sum and the area of the polygon (signed fan of triangles from
  P_0, each by l'Huilier's formula from its side lengths). By thesis Theorem 2.6 (uniqueness of geodesic
  loops in a hyperbolic metric) the loops are simple and pairwise disjoint except at p and the polygon is a
  fundamental domain: angle sum 2 pi and area 4 pi (g - 1); `check_geodesic_system()` verifies the loops.
  \throws Precision_error if the solver has no deck transformations (`use_geometry(false)`) or a loop
  cannot be traced
*/
template <class TriangleMesh, class EdgeLengthMap>
Geodesic_canonical_system<TriangleMesh>
geodesic_canonical_system(const Shortest_word_solver<TriangleMesh, EdgeLengthMap>& solver)
{
  typedef internal::Cplx Cplx;
  if(!solver.is_canonical())
    throw CGAL::Invalid_input_error("geodesic_canonical_system: the solver's system is not canonical (make_canonical(false))");
  Geodesic_canonical_system<TriangleMesh> r;
  const std::size_t n = 2 * std::size_t(solver.genus());
  for(std::size_t i = 0; i < n; ++i) {
    const Shortest_path_result<TriangleMesh> sp = solver.shortest_loop_of_word(Word(1, int(i) + 1));
    r.loops.push_back(sp.path);
    r.lengths.push_back(sp.length);
  }
  r.relator = solver.relator();
  std::vector<Cplx> P;
  internal::Isometry D;
  P.push_back(Cplx(0, 0));
  for(std::size_t k = 0; k + 1 < r.relator.size(); ++k) {
    const int l = r.relator[k];
    const internal::Isometry& g = solver.deck_transformation(std::size_t(std::abs(l) - 1));
    D = (D * (l > 0 ? g : g.inverse())).normalized();
    P.push_back(internal::apply_isometry(D, Cplx(0, 0)));
  }
  const std::size_t m = P.size();
  // orientation (the Klein polygon has straight sides: its signed Euclidean area)
  double orient = 0;
  for(std::size_t k = 0; k < m; ++k) orient += internal::cross(internal::to_klein(P[k]), internal::to_klein(P[(k + 1) % m]));
  for(std::size_t k = 0; k < m; ++k) {
    const Cplx prev = P[(k + m - 1) % m], next = P[(k + 1) % m];
    const double a = orient > 0 ? internal::ccw_angle_at(P[k], next, prev) : internal::ccw_angle_at(P[k], prev, next);
    r.polygon_angles.push_back(a);
    r.angle_sum += a;
    r.polygon.push_back(internal::to_point(P[k]));
  }
  for(std::size_t k = 1; k + 1 < m; ++k) {
    const double a = internal::hyperbolic_distance(P[k], P[k + 1]), b = internal::hyperbolic_distance(P[0], P[k + 1]),
                 c = internal::hyperbolic_distance(P[0], P[k]);
    const double sign = internal::cross(internal::to_klein(P[k]) - internal::to_klein(P[0]),
                                        internal::to_klein(P[k + 1]) - internal::to_klein(P[0])) * orient >= 0 ? 1 : -1;
    r.area += sign * CGAL::Hyperbolic_surface_2::triangle_area(a, b, c);
  }
  return r;
}

/// \ingroup PkgSurfaceShortestWordsRef
/// The checks of a system of loops through p (`Geodesic_canonical_system::loops`) by `check_geodesic_system()`.
struct Geodesic_system_report
{
  bool simple_and_disjoint = true; ///< no two segments meet except consecutive ones and at the base vertex
  std::size_t intersections = 0;   ///< pairs of segments (or shared vertices / edge points) that meet
  double min_side_angle = 10;      ///< the smallest angle on either side at an interior point of a loop
  std::size_t interior_points = 0; ///< interior points checked (edge crossings and vertices passed)
};

namespace internal {
// a segment of a loop in the chart of its face (`index` among the `count` segments of loop `loop`)
struct Loop_segment { std::size_t loop, index, count; Cplx a, b; bool a_base, b_base; };

// the number of pairs of segments of one face that meet, except consecutive segments of a loop and segments
// that only share the base point (Klein chords, in the face's chart)
inline std::size_t meeting_segments(const std::vector<Loop_segment>& v, double tol)
{
  std::size_t n = 0;
  auto near = [tol](const Cplx& u, const Cplx& w) { return std::abs(u - w) < tol; };
  for(std::size_t x = 0; x < v.size(); ++x)
    for(std::size_t y = x + 1; y < v.size(); ++y) {
      const Loop_segment &A = v[x], &B = v[y];
      if(A.loop == B.loop && (A.index + 1 == B.index || B.index + 1 == A.index ||
                              (A.count > 1 && ((A.index == 0 && B.index + 1 == A.count) || (B.index == 0 && A.index + 1 == A.count)))))
        continue;
      const Cplx a0 = to_klein(A.a), a1 = to_klein(A.b), b0 = to_klein(B.a), b1 = to_klein(B.b);
      if((A.a_base && (near(a0, b0) || near(a0, b1))) || (A.b_base && (near(a1, b0) || near(a1, b1)))) {
        // a shared end point at p: they meet only if they leave p in the same direction
        const Cplx pa = A.a_base ? a0 : a1, da = (A.a_base ? a1 : a0) - pa;
        const Cplx db = (near(pa, b0) ? b1 : b0) - pa;
        if(std::abs(cross(da, db)) > tol * std::abs(da) * std::abs(db) || (da.real() * db.real() + da.imag() * db.imag()) < 0) continue;
        ++n;
        continue;
      }
      const double d1 = cross(a1 - a0, b0 - a0), d2 = cross(a1 - a0, b1 - a0);
      const double d3 = cross(b1 - b0, a0 - b0), d4 = cross(b1 - b0, a1 - b0);
      if(d1 * d2 <= 0 && d3 * d4 <= 0) ++n;
    }
  return n;
}
} // namespace internal

/*!
  \ingroup PkgSurfaceShortestWordsRef
  Checks a system of loops through the base vertex `p`: every interior point of a loop (edge crossing or
  vertex passed) has an angle of at least pi on both sides (a geodesic; exactly pi on a smooth hyperbolic
  metric), and the loops are simple and pairwise disjoint except at `p` (segments in a common face tested
  pairwise in its chart, edge crossings and vertices compared). Cost: O(total size + sum over faces of the
  squared number of segments in the face).
*/
template <class Surface>
Geodesic_system_report check_geodesic_system(const Surface& s, typename Surface::vertex_descriptor p,
                                             const std::vector<typename Surface::Path>& loops, double tol = 1e-9)
{
  typedef typename Surface::face_descriptor face_descriptor;
  typedef internal::Cplx Cplx;
  const auto& tm = s.mesh();
  Geodesic_system_report rep;
  typedef internal::Loop_segment Seg;
  std::map<face_descriptor, std::vector<Seg> > by_face;
  std::map<std::pair<typename Surface::halfedge_descriptor, long>, std::size_t> edge_points; // (edge, t in 1e-9) -> loop
  std::map<typename Surface::vertex_descriptor, std::size_t> vertices_passed;
  for(std::size_t l = 0; l < loops.size(); ++l) {
    const typename Surface::Path& L = loops[l];
    const auto st = s.steps(L);
    std::vector<std::size_t> real; // indices of the non-turn steps
    for(std::size_t i = 0; i < st.size(); ++i) if(!st[i].turn) real.push_back(i);
    for(std::size_t j = 0; j < real.size(); ++j) {
      const std::size_t i = real[j];
      const auto c = s.chart(st[i].face);
      Seg sg{l, j, real.size(), s.position(L[i], st[i].in, c), s.position(L[i + 1], st[i].out, c),
             L[i].on_vertex && L[i].v == p, L[i + 1].on_vertex && L[i + 1].v == p};
      by_face[st[i].face].push_back(sg);
    }
    // interior points: the angle on both sides
    for(std::size_t j = 0; j + 1 < real.size(); ++j) {
      const std::size_t i = real[j], k = real[j + 1];
      const auto& q = L[i + 1];
      if(q.on_vertex && q.v == p) { rep.simple_and_disjoint = false; ++rep.intersections; continue; }
      const auto ci = s.chart(st[i].face), ck = s.chart(st[k].face);
      const Cplx a = s.position(L[i], st[i].in, ci), x = s.position(q, st[i].out, ci);
      if(!q.on_vertex) {
        // unfold the next face onto this one across the crossed edge
        auto h = q.h;
        if(face(h, tm) != st[i].face) h = opposite(h, tm);
        // (a midpoint marking a run along a side from corner to corner: both segments in the same face)
        const bool along = q.t == 0.5 && st[i].face == st[k].face && L[i].on_vertex && L[k + 1].on_vertex;
        if(!along) { // (along an edge, marked by its midpoint, the loop is straight by construction)
          const auto tr = s.transition(h).inverse(); // chart(face(opposite(h))) -> chart(face(h))
          const Cplx b = internal::apply_isometry(tr, s.position(L[k + 1], st[k].out, ck));
          const double side = internal::ccw_angle_at(x, b, a);
          rep.min_side_angle = (std::min)(rep.min_side_angle, (std::min)(side, 2 * CGAL_PI - side));
        }
        // (the same crossing point named from the other halfedge: t -> 1 - t)
        const auto h0 = halfedge(edge(q.h, tm), tm);
        const long key = std::lround((q.h == h0 ? q.t : 1 - q.t) * 1e9);
        auto ins = edge_points.emplace(std::make_pair(h0, key), l);
        if(!ins.second) { rep.simple_and_disjoint = false; ++rep.intersections; }
      } else {
        // a vertex passed: the angle from the incoming to the outgoing direction counterclockwise, through
        // the corners between st[i].out and st[k].in
        auto in = st[i].out, out = st[k].in;
        const Cplx b = s.position(L[k + 1], st[k].out, ck), y = s.position(q, out, ck);
        const Cplx X = internal::to_cplx(ci.source_point(in)); // the ccw side of the corner `in`
        const Cplx Y = internal::to_cplx(ck.target_point(next(out, tm))); // the cw side of the corner `out`
        double theta;
        if(in == out && internal::ccw_angle_at(x, internal::to_cplx(ci.target_point(next(in, tm))), b) >=
                          internal::ccw_angle_at(x, internal::to_cplx(ci.target_point(next(in, tm))), a))
          theta = internal::ccw_angle_at(x, a, b);
        else {
          theta = internal::ccw_angle_at(x, a, X);
          auto c = prev(opposite(in, tm), tm);
          for(std::size_t guard = 0; c != out && guard < 100000; ++guard) { theta += s.angle_at_target(c); c = prev(opposite(c, tm), tm); }
          theta += internal::ccw_angle_at(y, Y, b);
        }
        const double total = s.angle_sum(q.v);
        rep.min_side_angle = (std::min)(rep.min_side_angle, (std::min)(theta, total - theta));
        if(!vertices_passed.emplace(q.v, l).second) { rep.simple_and_disjoint = false; ++rep.intersections; }
      }
      ++rep.interior_points;
    }
  }
  // segments in a common face: the Klein chords meet only at consecutive points of one loop or at p
  for(const auto& fs : by_face) {
    const std::size_t n = internal::meeting_segments(fs.second, tol);
    if(n > 0) { rep.simple_and_disjoint = false; rep.intersections += n; }
  }
  return rep;
}

} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_GEODESIC_CANONICAL_SYSTEM_H
