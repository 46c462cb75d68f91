// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Thesis Theorem 2.6's setting in a surface triangulation: the shortest geodesic loops of a canonical system
// through p inserted into a Hyperbolic_surface_mesh_2::Delaunay_triangulation_on_surface as chains of
// constrained edges, and the fundamental polygon they bound as the faces of the cut surface (a disk), laid out
// in the polygon's frame. The only header of Surface_shortest_words that depends on Hyperbolic_surface_mesh_2.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_GEODESIC_SYSTEM_TRIANGULATION_H
#define CGAL_SURFACE_SHORTEST_WORDS_GEODESIC_SYSTEM_TRIANGULATION_H

#include <CGAL/Surface_shortest_words/geodesic_canonical_system.h>
#include <CGAL/Hyperbolic_surface_mesh_2/Delaunay_triangulation_on_surface.h>
#include <CGAL/Hyperbolic_surface_mesh_2/refine_surface_mesh.h> // the named parameter maximum_number_of_insertions

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_shortest_words {

/*!
  \ingroup PkgSurfaceShortestWordsRef
  A surface triangulation in which the loops of a `Geodesic_canonical_system` are chains of constrained edges,
  and the fundamental polygon they bound (`geodesic_system_triangulation()`).

  Edges are named as in `Delaunay_triangulation_on_surface`: (face f, index k), from corner k to corner k+1
  of f. The handles stay valid as long as the triangulation is not modified.
*/
struct Geodesic_system_triangulation
{
  typedef CGAL::Hyperbolic_surface_mesh_2::Delaunay_triangulation_on_surface<> Triangulation;
  typedef Triangulation::Face_index Face_index;
  typedef Triangulation::Vertex_index Vertex_index;
  typedef Triangulation::Point_2 Point_2;
  typedef std::pair<Face_index, int> Edge;

  explicit Geodesic_system_triangulation(const Triangulation& t) : triangulation(t) {}

  /// the triangulation of the surface (Delaunay away from the constrained edges) with the loops inserted
  Triangulation triangulation;
  /// the vertex of p
  Vertex_index base = Triangulation::null_index;
  /// per loop i (generator i + 1), its chain of constrained edges from p back to p in the direction of the
  /// loop: each edge (f, k) runs from `vertex(f, k)` to `vertex(f, k + 1)`, so f is the face on its left
  std::vector<std::vector<Edge> > loop_edges;
  /// per loop, the vertices of its chain (p, ..., p)
  std::vector<std::vector<Vertex_index> > loop_vertices;
  /// per loop, the sum of the hyperbolic lengths of its edges (measured in the charts of the triangulation)
  std::vector<double> loop_lengths;
  /// the faces of the cut surface, all faces of the triangulation, in the order of their development: first
  /// the faces on the loops, placed by their edge on the polygon's side, then across the edges that are not
  /// on a loop
  std::vector<Face_index> polygon_faces;
  /// their corners (corner k of the face at index k) in the frame of `Geodesic_canonical_system::polygon`:
  /// their union is the fundamental polygon bounded by the loops
  std::vector<std::array<Point_2, 3> > polygon_face_points;
  /// Checks computed from the cut surface (the triangulation cut open along the loops): its Euler
  /// characteristic V - E + F (1 for a disk; vertices are the classes of corners joined across uncut edges,
  /// every cut edge counts twice), its number of boundary cycles and of connected components (1 and 1 for a
  /// disk), and the boundary word, read along the boundary in the direction of the polygon's vertices from
  /// side 0 (one letter per loop chain traversed from end to end, + along the loop, - against it).
  long cut_euler_characteristic = 0;
  std::size_t cut_boundary_cycles = 0;
  std::size_t cut_components = 0;
  Word boundary_word;
  /// the largest hyperbolic distance between the two images in the polygon's frame of an end of an edge that
  /// is not on a loop (the faces are developed from the polygon's sides inwards: rounding only)
  double max_development_error = 0;
  /// the number of vertices the insertion of the loops added (their midpoint splits)
  std::size_t vertices_inserted = 0;
};

namespace internal {

// union-find with path halving
struct Corner_classes
{
  std::vector<std::size_t> up;
  explicit Corner_classes(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), std::size_t(0)); }
  std::size_t find(std::size_t x) { while(up[x] != x) { up[x] = up[up[x]]; x = up[x]; } return x; }
  void unite(std::size_t a, std::size_t b) { a = find(a); b = find(b); if(a != b) up[a] = b; }
};

} // namespace internal

/*!
  \ingroup PkgSurfaceShortestWordsRef
  Inserts the shortest geodesic loops of a canonical system (`geodesic_canonical_system(solver)`, thesis
  Theorem 2.6) into a triangulation of the surface as edges, and returns the fundamental polygon they bound.

  The triangulation is `Delaunay_triangulation_on_surface::from_surface_triangulation(s)` (one vertex per
  vertex of `s.mesh()`, made Delaunay by flips). Loop i is the geodesic segment from the lift of p to its image
  under the deck transformation of generator i (`Shortest_word_solver::deck_transformation()`), mapped into
  the frame of the triangulation through the chart of the solver's base face; `insert_feature_loop()` makes it a
  chain of constrained edges by midpoint splits (a segment with an empty diametral disk is a Delaunay edge).
  The loops meet only at p (they are disjoint geodesic loops, Theorem 2.6): a crossing of two loops throws.

  The chains are then read off the triangulation: from every constrained edge at p, the walk along constrained
  edges through vertices with exactly two of them, back to p; the lift of its end point identifies the loop
  and its direction. The cut surface (the faces, glued across the edges that are not on a loop) is counted
  (Euler characteristic, components, boundary cycles, boundary word) and developed into the frame of
  `sys.polygon`: the faces on the loops placed by their edge on the polygon's side, the others breadth first
  across uncut edges from them (`Geodesic_system_triangulation`).

  Named parameters: `CGAL::Hyperbolic_surface_mesh_2::parameters::maximum_number_of_insertions(n)`, the work
  bound of the insertion of each loop (default 10^5 splits per loop).

  Cost: the triangulation (O(n) plus the flips), the insertions (a walk per segment tested), and a linear pass
  over the faces.

  \throws Invalid_input_error if `sys` does not have the solver's 2g loops, the solver's system is not
          canonical or the solver is not on `s`; Invalid_option_error for a negative or non-finite work bound;
          Precision_error if the solver has no deck transformations; Numerical_error if a loop
          is not inserted within the work bound, two loops cross, a chain does not close at p or does not end
          at a lift of p by a generator, or the cut surface cannot be read (rounding).
*/
template <class TriangleMesh, class EdgeLengthMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Geodesic_system_triangulation
geodesic_system_triangulation(const Hyperbolic_surface<TriangleMesh, EdgeLengthMap>& s,
                              const Shortest_word_solver<TriangleMesh, EdgeLengthMap>& solver,
                              const Geodesic_canonical_system<TriangleMesh>& sys,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef Geodesic_system_triangulation Result;
  typedef Result::Triangulation T;
  typedef Result::Face_index Face_index;
  typedef Result::Vertex_index Vertex_index;
  typedef Result::Point_2 Point_2;
  typedef T::Isometry_2 Isometry_2;
  typedef internal::Cplx Cplx;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double max_ins = double(choose_parameter(get_parameter(np, internal_np::hsm2_maximum_insertions_t_v), 100000));
  if(!(max_ins >= 0) || !std::isfinite(max_ins))
    throw CGAL::Invalid_option_error("geodesic_system_triangulation: maximum_number_of_insertions must be >= 0 and finite");
  const std::size_t n = 2 * std::size_t(solver.genus());
  if(!solver.is_canonical())
    throw Invalid_input_error("geodesic_system_triangulation: the solver's system is not canonical");
  if(sys.loops.size() != n || sys.lengths.size() != n || sys.relator.size() != 2 * n || sys.polygon.size() != 2 * n)
    throw Invalid_input_error("geodesic_system_triangulation: the system is not the solver's canonical system "
                              "(geodesic_canonical_system(solver))");
  const auto& tm = s.mesh();

  Result r(T::from_surface_triangulation(s));
  T& t = r.triangulation;
  const std::size_t nv0 = t.number_of_vertices();

  // the solver's frame (the chart of its base face recentred at p) -> the frame of the triangulation (its
  // reference face of the base face: faces and vertices are numbered in the order of the mesh)
  std::size_t ref = 0, pv = 0;
  {
    bool found = false;
    for(auto f : faces(tm)) { if(f == solver.base_face()) { found = true; break; } ++ref; }
    bool found_v = false;
    for(auto v : vertices(tm)) { if(v == solver.base()) { found_v = true; break; } ++pv; }
    if(!found || !found_v) throw Invalid_input_error("geodesic_system_triangulation: the solver is not on this surface");
  }
  r.base = pv;
  const auto chart = s.chart(solver.base_face());
  const Cplx p_in_chart = s.position(s.corner(solver.base_corner()), solver.base_corner(), chart);
  const Isometry_2 M = (t.reference().faces[ref].to_frame * internal::to_origin(p_in_chart).inverse()).normalized();
  const Point_2 p_frame = M.apply_unchecked(Point_2(0, 0));
  std::vector<Point_2> ends_plus, ends_minus; // the lifts of p at the two ends of the lift of each loop from p
  for(std::size_t i = 0; i < n; ++i) {
    const internal::Isometry& g = solver.deck_transformation(i);
    ends_plus.push_back(M.apply_unchecked(g.apply_unchecked(Point_2(0, 0))));
    ends_minus.push_back(M.apply_unchecked(g.inverse().apply_unchecked(Point_2(0, 0))));
  }

  // 1. the loops as chains of constrained edges
  for(std::size_t i = 0; i < n; ++i) {
    // the lift: the segment from p to its image, through the vertices the traced loop passes (at their
    // distance along it): a segment through a vertex would be split at midpoints towards it forever (its
    // rounded position is off the segment by 1e-16)
    std::vector<Point_2> lift(1, p_frame);
    const typename Hyperbolic_surface<TriangleMesh, EdgeLengthMap>::Path& L = sys.loops[i];
    const auto st = s.steps(L);
    double along = 0;
    for(std::size_t k = 0; k < st.size(); ++k) {
      if(st[k].turn) continue;
      const auto c = s.chart(st[k].face);
      along += internal::hyperbolic_distance(s.position(L[k], st[k].in, c), s.position(L[k + 1], st[k].out, c));
      if(!L[k + 1].on_vertex || k + 1 == L.size() - 1) continue;
      if(along < 1e-9 || sys.lengths[i] - along < 1e-9) continue;
      const Point_2 q = T::Geometry::point_along(p_frame, ends_plus[i], along);
      if(T::Geometry::distance(q, lift.back()) > 1e-9) lift.push_back(q);
    }
    lift.push_back(ends_plus[i]);
    const auto res = t.insert_feature_loop(lift, std::size_t(max_ins));
    if(!res.complete)
      throw Numerical_error("geodesic_system_triangulation: loop " + std::to_string(i + 1) +
                            " was not inserted within maximum_number_of_insertions");
    if(res.crossings > 0)
      throw Numerical_error("geodesic_system_triangulation: loop " + std::to_string(i + 1) +
                            " crosses another loop (not a system of disjoint loops)");
  }
  r.vertices_inserted = t.number_of_vertices() - nv0;

  // 2. the chains, from the corners of p (walked clockwise around p from the corner located at its lift)
  Isometry_2 C; // frame -> chart of the current face
  const typename T::Location lp = t.locate_in_frame(p_frame, &C);
  if(lp.type != T::Location::ON_VERTEX || t.vertex(lp.face, lp.index) != r.base)
    throw Numerical_error("geodesic_system_triangulation: p is not found at its lift (rounding)");
  const std::size_t edge_bound = t.number_of_edges() + 1;
  // the next constrained edge out of the vertex at corner (f, c) (clockwise from the corner's outgoing edge,
  // the chart map carried along); false if none within a turn
  auto next_constrained = [&t, edge_bound](Face_index& f, int& c, Isometry_2& map) {
    for(std::size_t step = 0; step < edge_bound; ++step) {
      if(t.is_constrained(f, c)) return true;
      const Face_index g = t.neighbor(f, c);
      const int j = t.mirror_index(f, c);
      map = (t.transition(f, c) * map).normalized();
      f = g; c = (j + 1) % 3;
    }
    return false;
  };
  auto degree_in_loops = [&t, edge_bound](Face_index f, int c) {
    std::size_t d = 0;
    const Face_index f0 = f; const int c0 = c;
    for(std::size_t step = 0; step < edge_bound; ++step) {
      if(t.is_constrained(f, c)) ++d;
      const Face_index g = t.neighbor(f, c);
      const int j = t.mirror_index(f, c);
      f = g; c = (j + 1) % 3;
      if(f == f0 && c == c0) return d;
    }
    throw Numerical_error("geodesic_system_triangulation: a vertex star does not close");
  };
  r.loop_edges.assign(n, {});
  r.loop_vertices.assign(n, {});
  r.loop_lengths.assign(n, 0.);
  std::vector<int> found_dir(n, 0); // bit 1: found along the loop, bit 2: against it
  std::vector<std::pair<Face_index, int> > first_edge(n); // first edge of chain i along the loop
  {
    if(degree_in_loops(lp.face, lp.index) != 2 * n)
      throw Numerical_error("geodesic_system_triangulation: p is not on 2 x 2g loop edges");
    Face_index f = lp.face; int c = lp.index; Isometry_2 map = C;
    for(std::size_t k = 0; k < 2 * n; ++k) {
      if(!next_constrained(f, c, map)) throw Numerical_error("geodesic_system_triangulation: no loop edge at p");
      // walk the chain from the edge (f, c)
      std::vector<std::pair<Face_index, int> > chain;
      std::vector<Vertex_index> verts(1, r.base);
      double len = 0;
      Face_index g = f; int e = c; Isometry_2 m = map;
      Point_2 end;
      for(std::size_t step = 0;; ++step) {
        if(step > edge_bound) throw Numerical_error("geodesic_system_triangulation: a loop chain does not close at p");
        chain.emplace_back(g, e);
        len += t.edge_length(g, e);
        const int cw = (e + 1) % 3; // the corner of the next vertex in g
        const Vertex_index w = t.vertex(g, cw);
        verts.push_back(w);
        if(w == r.base) { end = m.inverse().apply_unchecked(t.lift(g)[cw]); break; }
        if(degree_in_loops(g, cw) != 2)
          throw Numerical_error("geodesic_system_triangulation: two loops meet away from p");
        // clockwise from the arriving edge (the incoming edge of the corner, met last): the first constrained
        // edge out of w is the other one
        int d = cw;
        if(!next_constrained(g, d, m)) throw Numerical_error("geodesic_system_triangulation: a loop chain stops");
        e = d;
      }
      // which loop and direction: the end is the lift of p by a generator or its inverse
      std::size_t best = n; bool plus = true;
      double dmin = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < n; ++i) {
        const double dp = T::Geometry::distance(end, ends_plus[i]), dm = T::Geometry::distance(end, ends_minus[i]);
        if(dp < dmin) { dmin = dp; best = i; plus = true; }
        if(dm < dmin) { dmin = dm; best = i; plus = false; }
      }
      if(best == n || !(dmin < 1e-6))
        throw Numerical_error("geodesic_system_triangulation: a loop chain does not end at a lift of p by a generator");
      if(found_dir[best] & (plus ? 1 : 2))
        throw Numerical_error("geodesic_system_triangulation: a loop is found twice at p");
      found_dir[best] |= (plus ? 1 : 2);
      if(plus) {
        r.loop_edges[best] = chain;
        r.loop_vertices[best] = verts;
        r.loop_lengths[best] = len;
        first_edge[best] = chain.front();
      }
      // the next corner of p clockwise
      const Face_index g1 = t.neighbor(f, c);
      const int j = t.mirror_index(f, c);
      map = (t.transition(f, c) * map).normalized();
      f = g1; c = (j + 1) % 3;
    }
    for(std::size_t i = 0; i < n; ++i)
      if(found_dir[i] != 3) throw Numerical_error("geodesic_system_triangulation: a loop is missing at p");
  }

  // 3. the cut surface: constrained edges, labels of the boundary sides
  const std::size_t cap = t.face_capacity();
  std::vector<long> side_label(3 * cap, 0);      // +-(i + 1) on a cut side: along / against loop i
  std::vector<std::size_t> side_pos(3 * cap, 0); // position of the edge along its chain
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = 0; k < r.loop_edges[i].size(); ++k) {
      const auto& ed = r.loop_edges[i][k];
      side_label[3 * ed.first + std::size_t(ed.second)] = long(i) + 1;
      side_pos[3 * ed.first + std::size_t(ed.second)] = k;
      const Face_index o = t.neighbor(ed.first, ed.second);
      const int oi = t.mirror_index(ed.first, ed.second);
      side_label[3 * o + std::size_t(oi)] = -(long(i) + 1);
      side_pos[3 * o + std::size_t(oi)] = r.loop_edges[i].size() - 1 - k;
    }
  const std::vector<Face_index> fs = t.faces();
  std::size_t cut_sides = 0, uncut_sides = 0;
  internal::Corner_classes cc(3 * cap);
  for(Face_index f : fs)
    for(int c = 0; c < 3; ++c) {
      const bool cut = t.is_constrained(f, c);
      if(cut != (side_label[3 * f + std::size_t(c)] != 0))
        throw Numerical_error("geodesic_system_triangulation: a constrained edge is on no loop chain");
      if(cut) { ++cut_sides; continue; }
      ++uncut_sides;
      cc.unite(3 * f + std::size_t(c), 3 * t.neighbor(f, c) + std::size_t((t.mirror_index(f, c) + 1) % 3));
    }
  std::size_t classes = 0;
  for(Face_index f : fs) for(int c = 0; c < 3; ++c) if(cc.find(3 * f + std::size_t(c)) == 3 * f + std::size_t(c)) ++classes;
  r.cut_euler_characteristic = long(classes) - long(uncut_sides / 2 + cut_sides) + long(fs.size());

  // 4. the boundary of the cut surface (counterclockwise: each side with its face on the left), read from
  //    side 0 of the polygon
  const std::size_t m = sys.polygon.size();
  double orient = 0;
  for(std::size_t k = 0; k < m; ++k)
    orient += internal::cross(internal::to_klein(internal::to_cplx(sys.polygon[k])),
                              internal::to_klein(internal::to_cplx(sys.polygon[(k + 1) % m])));
  const int r0 = sys.relator.front();
  if(r0 <= 0) throw Invalid_input_error("geodesic_system_triangulation: the relator does not start with a generator");
  // side 0 runs from P_0 along loop r0: the first edge of its chain, seen from the face on its left (a
  // counterclockwise polygon) or on its right (the polygon is inside)
  Face_index start_face = first_edge[std::size_t(r0 - 1)].first;
  int start_side = first_edge[std::size_t(r0 - 1)].second;
  if(orient < 0) {
    const Face_index o = t.neighbor(start_face, start_side);
    start_side = t.mirror_index(start_face, start_side);
    start_face = o;
  }
  std::vector<char> side_done(3 * cap, 0);
  // the sides of the boundary cycle through (f, c), in order
  auto read_cycle = [&](Face_index f, int c) {
    std::vector<std::size_t> sides;
    for(std::size_t step = 0;; ++step) {
      if(step > cut_sides) throw Numerical_error("geodesic_system_triangulation: a boundary cycle does not close");
      const std::size_t key = 3 * f + std::size_t(c);
      if(side_done[key]) break;
      side_done[key] = 1;
      sides.push_back(key);
      // the next cut side out of the end vertex of (f, c): clockwise across uncut edges
      Face_index g = f; int d = (c + 1) % 3;
      Isometry_2 unused;
      if(!next_constrained(g, d, unused)) throw Numerical_error("geodesic_system_triangulation: a boundary cycle stops");
      f = g; c = d;
    }
    return sides;
  };
  std::vector<std::size_t> boundary = read_cycle(start_face, start_side);
  r.cut_boundary_cycles = 1;
  for(Face_index f : fs)
    for(int c = 0; c < 3; ++c)
      if(t.is_constrained(f, c) && !side_done[3 * f + std::size_t(c)]) { ++r.cut_boundary_cycles; read_cycle(f, c); }
  // counterclockwise polygon: the cycle from side 0 starts at P_0; clockwise: the start side is the last
  // edge of side 0 read backwards, which ends at P_0
  if(orient < 0) std::rotate(boundary.begin(), boundary.begin() + 1, boundary.end());
  // runs: one per chain traversed from its first to its last edge, (first side, number of sides, letter)
  struct Run { std::size_t first, count; int letter; };
  std::vector<Run> runs;
  for(std::size_t k = 0; k < boundary.size(); ++k) {
    const long lab = side_label[boundary[k]];
    const std::size_t len = r.loop_edges[std::size_t(std::abs(lab) - 1)].size();
    if(side_pos[boundary[k]] + 1 != len) continue;
    bool whole = k + 1 >= len;
    for(std::size_t q = k + 1 - (whole ? len : 0); whole && q <= k; ++q)
      whole = side_label[boundary[q]] == lab && side_pos[boundary[q]] == q - (k + 1 - len);
    if(!whole) throw Numerical_error("geodesic_system_triangulation: the boundary does not traverse a loop chain from end to end");
    runs.push_back(Run{k + 1 - len, len, int(lab)});
  }
  if(orient >= 0) for(const Run& u : runs) r.boundary_word.push_back(u.letter);
  else for(std::size_t k = runs.size(); k-- > 0;) r.boundary_word.push_back(-runs[k].letter); // the inverse word

  // 5. the development of the cut surface into the polygon's frame: every face on the boundary is placed by
  //    its boundary side on the polygon's side (counterclockwise run j goes from A_j to A_j+1, the polygon's
  //    vertices in counterclockwise order, at the distance along the run of its edges), the other faces
  //    across uncut edges from them (breadth first: the charts compose over the fewest transitions)
  std::vector<Isometry_2> to_polygon(cap); // chart -> polygon frame
  std::vector<char> seen(cap, 0);
  std::deque<Face_index> queue;
  if(r.boundary_word.size() == m) {
    for(std::size_t j = 0; j < runs.size(); ++j) {
      const Point_2 A = sys.polygon[orient >= 0 ? j : (m - j) % m];
      const Point_2 B = sys.polygon[orient >= 0 ? (j + 1) % m : (2 * m - j - 1) % m];
      double along = 0;
      for(std::size_t q = runs[j].first; q < runs[j].first + runs[j].count; ++q) {
        const Face_index f = boundary[q] / 3;
        const int c = int(boundary[q] % 3);
        const double len = t.edge_length(f, c);
        if(!seen[f]) {
          seen[f] = 1;
          to_polygon[f] = T::Geometry::isometry_from_pairs(t.lift(f)[c], t.lift(f)[(c + 1) % 3],
                                                            T::Geometry::point_along(A, B, along),
                                                            T::Geometry::point_along(A, B, along + len));
          queue.push_back(f);
        }
        along += len;
      }
    }
  }
  if(queue.empty()) throw Numerical_error("geodesic_system_triangulation: the boundary of the cut surface is not the polygon's");
  std::size_t reached = queue.size();
  while(!queue.empty()) {
    const Face_index f = queue.front(); queue.pop_front();
    r.polygon_faces.push_back(f);
    std::array<Point_2, 3> z;
    for(int k = 0; k < 3; ++k) z[k] = to_polygon[f].apply_unchecked(t.lift(f)[k]);
    r.polygon_face_points.push_back(z);
    for(int k = 0; k < 3; ++k) {
      if(t.is_constrained(f, k)) continue;
      const Face_index g = t.neighbor(f, k);
      if(seen[g]) continue;
      seen[g] = 1;
      ++reached;
      to_polygon[g] = (to_polygon[f] * t.transition(f, k).inverse()).normalized();
      queue.push_back(g);
    }
  }
  // the agreement of the development across the uncut edges: the largest distance between the two images
  // of an end of an uncut edge
  for(std::size_t k = 0; k < r.polygon_faces.size(); ++k) {
    const Face_index f = r.polygon_faces[k];
    for(int c = 0; c < 3; ++c) {
      if(t.is_constrained(f, c)) continue;
      const Face_index g = t.neighbor(f, c);
      const int j = t.mirror_index(f, c);
      r.max_development_error = (std::max)(r.max_development_error,
        (std::max)(T::Geometry::distance(r.polygon_face_points[k][c], to_polygon[g].apply_unchecked(t.lift(g)[(j + 1) % 3])),
                   T::Geometry::distance(r.polygon_face_points[k][(c + 1) % 3], to_polygon[g].apply_unchecked(t.lift(g)[j]))));
    }
  }
  // connected components of the cut surface: those reached from the boundary, plus any other
  r.cut_components = reached > 0 ? 1 : 0;
  for(Face_index f : fs) {
    if(seen[f]) continue;
    ++r.cut_components;
    std::deque<Face_index> q(1, f);
    seen[f] = 1;
    while(!q.empty()) {
      const Face_index a = q.front(); q.pop_front();
      for(int k = 0; k < 3; ++k)
        if(!t.is_constrained(a, k) && !seen[t.neighbor(a, k)]) { seen[t.neighbor(a, k)] = 1; q.push_back(t.neighbor(a, k)); }
    }
  }
  return r;
}

} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_GEODESIC_SYSTEM_TRIANGULATION_H
