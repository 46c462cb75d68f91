// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mutable Delaunay triangulation of a closed hyperbolic surface: faces with charts (the lift of their three
// vertices near the origin of the Poincare disk), adjacency across edges, point location by walking across the
// transitions, point insertion, vertex removal, Lawson flips decided by the traits' exact in-circle predicate in
// one chart per edge.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_DELAUNAY_TRIANGULATION_ON_SURFACE_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_DELAUNAY_TRIANGULATION_ON_SURFACE_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>
#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>
#include <CGAL/Hyperbolic_surface_mesh_2/Fundamental_polygon.h>
#include <CGAL/Hyperbolic_surface_mesh_2/internal/Large_block_allocator.h>
#include <CGAL/Hyperbolic_surface_mesh_2/internal/Reference_triangulation.h>
#include <CGAL/Poincare_disk_traits_2.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {

/*!
  \ingroup PkgHyperbolicSurfaceMesh2Ref
  A triangulation of a closed orientable hyperbolic surface (genus g >= 2), kept Delaunay.

  Storage: per face the *chart* `lift(f)` (three points of the Poincare disk, counterclockwise, barycentre at
  the origin), the three vertices and, per edge `i` (from corner `i` to corner `i+1`), the neighbour face
  `neighbor(f, i)` and the index of the same edge there, `mirror_index(f, i)`. The transition isometry across
  an edge, `transition(f, i)`, maps the chart of `f` to the chart of its neighbour (it takes the lift of the
  edge onto the other lift). Loops and multiple edges are allowed (a Delta-complex); `is_simplicial_complex()`
  says whether there are none.

  Every edge test is the traits' exact in-circle predicate (`Side_of_oriented_circle_2`: the Euclidean in-circle
  of the Poincare coordinates, which is the hyperbolic empty-circle test) on the lifted quadrilateral, evaluated
  in the chart of the face with the smaller index: an edge's status does not depend on the side it is looked at
  from. Lawson flips restore the Delaunay property after every insertion and removal (they terminate on
  hyperbolic surfaces: Despre, Schlenker, Teillaud 2020); a work bound turns a failure into
  `CGAL::Numerical_error`.

  The first triangulation (from a `Fundamental_polygon` or a `Hyperbolic_surface_2::Hyperbolic_surface_triangulation`)
  is kept as the *reference triangulation*: every live face is anchored to a reference face by an isometry of
  charts, so that every point can be mapped back to the polygon's frame or to a face of the input mesh
  (`vertex_reference()`).

  `Traits` is `CGAL::Poincare_disk_traits_2<K>` for a kernel with double coordinates (default `Epick`).
*/
template <class Traits_ = CGAL::Poincare_disk_traits_2<CGAL::Exact_predicates_inexact_constructions_kernel> >
class Delaunay_triangulation_on_surface
{
public:
  typedef Traits_ Geom_traits;
  typedef typename Geom_traits::Kernel Kernel;
  typedef typename Geom_traits::Point_2 Point_2;
  typedef CGAL::Poincare_disk_isometry_2<Kernel> Isometry_2;
  typedef Hyperbolic_surface_2::Disk_geometry<Kernel> Geometry;
  typedef std::size_t Face_index;
  typedef std::size_t Vertex_index;
  static constexpr std::size_t null_index = (std::numeric_limits<std::size_t>::max)();
  /// A point closer to a vertex than this times the shortest edge of the face it is located in is located on
  /// the vertex. Positions are floating-point: a point mapped into a chart through the anchors and
  /// transitions, and the vertex positions in the charts, drift by about 1e-16 per rebuilt face generation
  /// (measured: 2e-9 after 150 insertions with many cocircular flips on the Bolza octagon, edges about 0.2),
  /// so a point given twice is recognized up to this relative distance.
  static constexpr double duplicate_distance = 1e-7;
  /// The hyperbolic size of 100 units in the last place of a point `p` given in the frame: the resolution of
  /// frame points. A point given in the frame (`locate_in_frame()`, `insert_in_frame()`) closer than this to a
  /// vertex, or than `duplicate_distance` times the shortest edge of the face it falls in, is located on the
  /// nearest such vertex (found by the fuzzer: points about 1e-15 apart given again became new vertices, then
  /// needles; the relative test alone shrinks with the needles). About 4.4e-14 at the origin, 4e-12 at
  /// |p| = 0.94. Points given in a chart (`locate()`, `insert()`) use the relative test only (charts of tiny
  /// faces are accurate to their size: Ricci-flow metrics of real meshes have edges of 1e-10).
  static double frame_resolution(const Point_2& p)
  {
    const double r2 = p.x() * p.x() + p.y() * p.y();
    return 100 * 2 * std::numeric_limits<double>::epsilon() / (1 - r2);
  }

  /// The result of `locate()`: the face, the point in its chart, and whether it is inside, on edge `index`,
  /// or on the vertex at corner `index`.
  struct Location
  {
    enum Type { IN_FACE, ON_EDGE, ON_VERTEX } type = IN_FACE;
    Face_index face = null_index;
    int index = -1;
    Point_2 point;
  };

  /// A point on the reference triangulation: a reference face and the point in its chart.
  struct Reference_point
  {
    Face_index reference_face = null_index;
    Point_2 point;
  };

  // ---------------------------------------------------------------- construction
  /// The triangulation of the surface glued from `polygon`: its vertex cycles are the vertices (one for a
  /// regular 4g-gon), the polygon is cut into a fan of triangles from its first vertex, then made Delaunay by
  /// flips. The frame of the reference triangulation is the polygon's (`insert_in_frame()`). Cost: O(n).
  explicit Delaunay_triangulation_on_surface(const Fundamental_polygon<Kernel>& polygon) { build_from_polygon(polygon, false); }
  /// The same, with the sides of the polygon as constrained edges (`sides_as_constraints`): on the surface they
  /// form closed geodesic loops (the paired sides glued); the triangulation is then Delaunay away from them
  /// (constrained Delaunay), flips never remove them, insertions on them split them into constrained halves,
  /// and the refinement splits them at midpoints when encroached, so that the polygon stays a union of faces.
  Delaunay_triangulation_on_surface(const Fundamental_polygon<Kernel>& polygon, bool sides_as_constraints)
  { build_from_polygon(polygon, sides_as_constraints); }

  /// The triangulation of `st` (a `Hyperbolic_surface_2::Hyperbolic_surface_triangulation`): one face per face of
  /// `st.mesh()` (in the order of `faces(st.mesh())`, with `z[i]` the source of the i-th halfedge from
  /// `halfedge(f)`), one vertex per vertex (in the order of `vertices(st.mesh())`), then made Delaunay by
  /// flips. The frame is a development of the mesh along a breadth-first spanning tree of its faces. O(n).
  template <class SurfaceTriangulation>
  static Delaunay_triangulation_on_surface from_surface_triangulation(const SurfaceTriangulation& st)
  {
    Delaunay_triangulation_on_surface t;
    t.build_from_surface(st);
    return t;
  }

  // ---------------------------------------------------------------- access
  std::size_t number_of_vertices() const { return nv_; }
  std::size_t number_of_faces() const { return nf_; }
  std::size_t number_of_edges() const { return 3 * nf_ / 2; }
  /// the genus from the Euler characteristic V - E + F = 2 - 2g
  int genus() const { return int((2 - euler_characteristic()) / 2); }
  long euler_characteristic() const { return long(nv_) - long(number_of_edges()) + long(nf_); }
  /// one past the largest face index (faces are `is_face(f)` for f below it)
  std::size_t face_capacity() const { return faces_.size(); }
  std::size_t vertex_capacity() const { return vertices_.size(); }
  bool is_face(Face_index f) const { return f < faces_.size() && faces_[f].alive; }
  bool is_vertex(Vertex_index v) const { return v < vertices_.size() && vertices_[v].alive; }
  /// the alive faces / vertices
  std::vector<Face_index> faces() const { std::vector<Face_index> r; for(Face_index f = 0; f < faces_.size(); ++f) if(faces_[f].alive) r.push_back(f); return r; }
  std::vector<Vertex_index> vertices() const { std::vector<Vertex_index> r; for(Vertex_index v = 0; v < vertices_.size(); ++v) if(vertices_[v].alive) r.push_back(v); return r; }

  /// the chart of `f`: the lifts of its corners, counterclockwise, barycentre at the origin
  const std::array<Point_2, 3>& lift(Face_index f) const { return faces_[f].z; }
  Vertex_index vertex(Face_index f, int i) const { return faces_[f].v[i]; }
  Face_index neighbor(Face_index f, int i) const { return faces_[f].nb[i]; }
  int mirror_index(Face_index f, int i) const { return faces_[f].ne[i]; }
  /// a face incident to `v` and the corner of `v` in it
  std::pair<Face_index, int> incident_face(Vertex_index v) const { return {vertices_[v].face, vertices_[v].corner}; }

  /// true if edge i of f is constrained (a piece of a feature loop)
  bool is_constrained(Face_index f, int i) const { return (faces_[f].cons >> i) & 1u; }
  /// number of constrained edges
  std::size_t number_of_constrained_edges() const
  {
    std::size_t n = 0;
    for(Face_index f = 0; f < faces_.size(); ++f)
      if(faces_[f].alive) for(int i = 0; i < 3; ++i) if(is_constrained(f, i)) ++n;
    return n / 2;
  }
  /// the isometry from the chart of `f` to the chart of `neighbor(f, i)` (lift of edge i onto its other lift).
  /// Cached per edge (computed once from the two charts, the reverse transition stored as its inverse, so the two
  /// sides of an edge agree exactly); the cache of an edge is dropped whenever a face on it is rebuilt or
  /// relinked. The cache makes the const accessors non-reentrant: do not share one triangulation between threads.
  Isometry_2 transition(Face_index f, int i) const { return cached_transition(f, i); }
  /// the apex of `neighbor(f, i)` (its corner off edge i) in the chart of `f`
  Point_2 neighbor_apex(Face_index f, int i) const
  {
    const Face& G = faces_[faces_[f].nb[i]];
    return cached_transition(f, i).inverse().apply_unchecked(G.z[(faces_[f].ne[i] + 2) % 3]);
  }
  /// hyperbolic length of edge i of f (from its chart)
  double edge_length(Face_index f, int i) const { return Geometry::distance(faces_[f].z[i], faces_[f].z[(i + 1) % 3]); }
  /// the anchor of `f`: its reference face and the isometry from its chart into that face's chart
  std::pair<Face_index, Isometry_2> anchor(Face_index f) const { return {faces_[f].ref, faces_[f].to_ref}; }
  /// the isometry from the chart of `f` into the frame of the reference triangulation's fundamental domain
  Isometry_2 to_frame(Face_index f) const { return ref_.faces[faces_[f].ref].to_frame * faces_[f].to_ref; }
  /// the position of `v` on the reference triangulation (for a mesh input: a face of the input mesh)
  const Reference_point& vertex_reference(Vertex_index v) const { return vertices_[v].refp; }
  /// the reference triangulation (read only)
  const internal::Reference_triangulation<Geom_traits>& reference() const { return ref_; }
  const Geom_traits& geom_traits() const { return gt_; }
  /// number of Lawson flips done so far
  std::size_t number_of_flips() const { return flips_; }

  // ---------------------------------------------------------------- predicates
  /// true if edge i of f is constrained or locally Delaunay: the apex of the neighbour is not strictly inside the
  /// circumcircle of the face (exact, in the chart of the face with the smaller index). An edge whose two
  /// sides are the same face counts as Delaunay (it cannot be flipped).
  bool is_locally_delaunay(Face_index f, int i) const
  {
    const Face_index g = faces_[f].nb[i];
    if(g == f || is_constrained(f, i)) return true; // constrained edges count as Delaunay (never flipped)
    const int j = faces_[f].ne[i];
    const Face_index a = f < g ? f : g;
    const int k = f < g ? i : j;
    const Point_2 d = neighbor_apex(a, k);
    const auto& z = faces_[a].z;
    return gt_.side_of_oriented_circle_2_object()(z[k], z[(k + 1) % 3], z[(k + 2) % 3], d) != CGAL::ON_POSITIVE_SIDE;
  }
  /// true if every edge is locally Delaunay
  bool is_delaunay() const
  {
    for(Face_index f = 0; f < faces_.size(); ++f)
      if(faces_[f].alive)
        for(int i = 0; i < 3; ++i) if(!is_locally_delaunay(f, i)) return false;
    return true;
  }
  /// true if there is no loop edge, no multiple edge and no two faces with the same three vertices. Linear:
  /// the edges from each vertex are marked around its star (no sort). Without loops and multiple edges two
  /// faces on the same three vertices would share their three edges and form a closed sphere on their own,
  /// which a connected surface of genus >= 2 is not, so that case is only tested for two faces.
  bool is_simplicial_complex() const
  {
    bool ok = true;
    for_each_non_simplicial_edge([&](Face_index, int) { ok = false; return false; });
    if(!ok) return false;
    if(nf_ == 2) {
      std::array<Vertex_index, 3> t[2];
      int k = 0;
      for(Face_index f = 0; f < faces_.size(); ++f) if(faces_[f].alive) { t[k] = faces_[f].v; std::sort(t[k].begin(), t[k].end()); ++k; }
      return t[0] != t[1];
    }
    return true;
  }
  /// Calls `fn(f, i)` for every loop edge (from both of its sides) and for every copy of a multiple edge (the
  /// first copy again with each later one), until `fn` returns false. Linear: one pass over the faces in index
  /// order buckets each edge at its smaller vertex (counting sort), one pass over the buckets marks the other
  /// vertices (no sort, no walk around the stars: sequential memory access).
  template <class Function>
  void for_each_non_simplicial_edge(const Function& fn) const
  {
    const std::size_t nvc = vertices_.size();
    auto canonical = [&](Face_index f, int i) {
      const Face_index g = faces_[f].nb[i];
      return f < g || (f == g && i < int(faces_[f].ne[i]));
    };
    std::vector<std::size_t> start(nvc + 1, 0);
    for(Face_index f = 0; f < faces_.size(); ++f) {
      if(!faces_[f].alive) continue;
      for(int i = 0; i < 3; ++i) {
        if(!canonical(f, i)) continue;
        const Vertex_index a = faces_[f].v[i], b = faces_[f].v[(i + 1) % 3];
        if(a == b) { if(!fn(f, i) || !fn(faces_[f].nb[i], int(faces_[f].ne[i]))) return; continue; }
        ++start[(std::min)(a, b) + 1];
      }
    }
    for(std::size_t u = 0; u < nvc; ++u) start[u + 1] += start[u];
    std::vector<std::size_t> pos(start.begin(), start.end() - 1);
    std::vector<Vertex_index> other(start[nvc]);
    std::vector<Edge_ref> edge(start[nvc]);
    for(Face_index f = 0; f < faces_.size(); ++f) {
      if(!faces_[f].alive) continue;
      for(int i = 0; i < 3; ++i) {
        const Vertex_index a = faces_[f].v[i], b = faces_[f].v[(i + 1) % 3];
        if(a == b || !canonical(f, i)) continue;
        const std::size_t k = pos[(std::min)(a, b)]++;
        other[k] = (std::max)(a, b);
        edge[k] = Edge_ref(f, i);
      }
    }
    std::vector<Vertex_index> mark(nvc, null_index);
    std::vector<std::size_t> first(nvc);
    for(Vertex_index u = 0; u < nvc; ++u)
      for(std::size_t k = start[u]; k < start[u + 1]; ++k) {
        const Vertex_index w = other[k];
        if(mark[w] == u) { if(!fn(edge[first[w]].first, edge[first[w]].second) || !fn(edge[k].first, edge[k].second)) return; }
        else { mark[w] = u; first[w] = k; }
      }
  }
  /// number of loop edges plus number of extra copies of multiple edges
  std::size_t number_of_non_simplicial_edges() const;
  /// Combinatorial and metric consistency (release-build check used by the tests): adjacency is symmetric,
  /// glued edges have the same vertices and (up to `tol`) the same length in both charts, every chart is a
  /// counterclockwise triangle, vertex records point to corners of the vertex. `why` gets the first problem.
  bool is_valid(std::string* why = nullptr, double tol = 1e-8) const;
  /// sum of the corner angles at v (from the charts)
  double angle_sum(Vertex_index v) const;
  /// total hyperbolic area (l'Huilier on the chart edge lengths); 4 pi (g - 1)
  double area() const;
  /// the corner (face, index) of v in counterclockwise order around v
  std::vector<std::pair<Face_index, int> > star(Vertex_index v) const;
  /// the same, into `r` (cleared first; no allocation when `r` has room)
  void star(Vertex_index v, std::vector<std::pair<Face_index, int> >& r) const;
  /// reserves room for `nf` faces and `nv` vertices (no copy of the arrays while the triangulation grows to that)
  void reserve(std::size_t nf, std::size_t nv) { faces_.reserve(nf); vertices_.reserve(nv); }
  /// the degree of v (number of corners around it)
  std::size_t degree(Vertex_index v) const { return star(v).size(); }

  // ---------------------------------------------------------------- location and insertion
  /// Walks from `start` to the face containing `p` (given in the chart of `start`), crossing edges whose
  /// supporting geodesic separates the face from the point (exact Klein orientation in the current chart) and
  /// mapping `p` by the transitions. Throws `Poincare_disk_domain_error` if `p` is not in the open disk and
  /// `Numerical_error` if the walk exceeds its work bound (10 F + 1000 steps). Cost: the number of faces crossed.
  /// With `blocking` non-null, the walk stops before crossing a constrained edge and stores it there (else
  /// `blocking->first` is `null_index`): the point is then not visible from `start` inside the feature loops.
  /// With `to_chart` non-null, the transitions crossed are composed onto `*to_chart` (on return it maps the
  /// chart of `start` composed with the former `*to_chart` into the chart of the face found).
  /// A point within `separation` (hyperbolic) of a vertex, or within `duplicate_distance` times the shortest
  /// edge of the face found, is located on the nearest such vertex.
  Location locate(const Point_2& p, Face_index start, std::pair<Face_index, int>* blocking = nullptr,
                  Isometry_2* to_chart = nullptr, double separation = 0) const;
  /// Locates a point given in the frame of the reference triangulation (the polygon's frame; for a mesh
  /// input, the frame of its development): walks in the reference triangulation, then in this one. With
  /// `frame_to_chart` non-null, it receives the isometry from the frame to the chart of the face found.
  /// \throws Poincare_disk_domain_error for a point not in the open disk; Numerical_error for a point whose
  ///         reduction into the domain cannot be represented in double (about |p| > 1 - 1e-10: hyperbolic
  ///         distance above 23.7 from the frame's origin).
  Location locate_in_frame(const Point_2& p, Isometry_2* frame_to_chart = nullptr) const;

  /// Inserts the point `p` given in the chart of `start` (see `locate()`) and restores the Delaunay
  /// property. Returns the new vertex, or the existing one if `p` is (exactly) a lift of a vertex. Points on
  /// an edge split the edge. Returns `null_index` (no change) for a point on an edge whose two sides are one
  /// face (not splittable), or for a point that would leave one of the new faces not counterclockwise in its
  /// chart (exact test on the rounded recentred corners; a rounded point next to a tiny angle or a needle).
  Vertex_index insert(const Point_2& p, Face_index start) { return insert(locate(p, start)); }
  /// inserts a located point (see `locate()`)
  Vertex_index insert(const Location& loc);
  /// Inserts a point given in the frame of the reference triangulation (e.g. a point of the fundamental
  /// polygon, or any of its lifts under the side pairings). Throws as `locate_in_frame()`.
  Vertex_index insert_in_frame(const Point_2& p) { return insert(locate_in_frame(p)); }
  /// Inserts the points of a range given in the frame of the reference triangulation, in Hilbert order (each
  /// point located from the face of the previous one). Returns the number of new vertices. Every point is
  /// checked (`Poincare_disk_domain_error`) before the triangulation is modified.
  template <class InputIterator>
  std::size_t insert_in_frame(InputIterator first, InputIterator last)
  {
    std::vector<Point_2> pts(first, last);
    for(const Point_2& p : pts) internal::check_in_disk(p, "Delaunay_triangulation_on_surface::insert_in_frame");
    CGAL::hilbert_sort(pts.begin(), pts.end());
    const std::size_t nv = nv_;
    Vertex_index prev = null_index;
    for(const Point_2& p : pts) {
      if(prev != null_index && is_vertex(prev)) {
        const Face_index f = vertices_[prev].face;
        const Point_2 q = to_frame(f).inverse().apply_unchecked(p);
        if(q.x() * q.x() + q.y() * q.y() < 0.99) { const Vertex_index v = insert(q, f); if(v != null_index) prev = v; continue; }
      }
      const Vertex_index v = insert_in_frame(p);
      if(v != null_index) prev = v;
    }
    return nv_ - nv;
  }

  /// What `insert_feature_loop()` did.
  struct Feature_loop_result
  {
    bool complete = false;              ///< every segment of the loop is a chain of constrained edges
    std::size_t vertices_inserted = 0;  ///< the loop's points, midpoints and crossings that are new vertices
    std::size_t splits = 0;             ///< segments split (at a midpoint, a crossing or a vertex on them)
    std::size_t crossings = 0;          ///< crossings with constrained edges (other loops), inserted as vertices
    std::size_t constrained_edges = 0;  ///< edges newly constrained
  };
  /// Inserts a feature loop given by a lift: points `p_0, ..., p_n` in the frame of the reference triangulation
  /// (see `insert_in_frame()`), consecutive points joined by the geodesic segments of the disk, `p_n` a lift of
  /// `p_0` (the same point of the surface: `p_n = p_0` for a loop drawn inside the frame, `p_n = gamma(p_0)` for
  /// a deck transformation gamma otherwise, e.g. a closed geodesic through paired sides of a polygon). The
  /// loop (a closed geodesic, a geodesic loop, any closed geodesic polyline, e.g. the lift of a shortest loop)
  /// becomes a chain of constrained edges: every segment that is not an edge of the triangulation is split at its
  /// hyperbolic midpoint (conforming Delaunay refinement: a segment with an empty diametral disk is a Delaunay
  /// edge), and where it crosses a constrained edge (another loop, a polygon side) the crossing point is inserted
  /// on both. Loops may share points and cross each other. The constrained edges are kept by the flips and by
  /// the refinement (`refine_Ruppert()`, `refine_Chew()`: encroachment and midpoint splits). Work bound: at most
  /// `max_insertions` splits (then `complete` is false and the loop is partly constrained). Cost: a walk in the
  /// reference triangulation and one along the segment per segment tested.
  /// \throws Invalid_path_error for fewer than two points, a last point that is not a lift of the first (the
  ///         triangulation then keeps its vertex set), or two consecutive equal points (checked first);
  ///         Poincare_disk_domain_error for a point outside the open disk (checked first); Numerical_error if a
  ///         segment gets too short to be split in double precision.
  template <class PointRange>
  Feature_loop_result insert_feature_loop(const PointRange& lift, std::size_t max_insertions = 100000);

  /// Removes the vertex `v` (flips its edges until it has degree 3, removes its star, restores the Delaunay
  /// property). Returns false and leaves a Delaunay triangulation with `v` if this is not possible (the last
  /// vertex, a star that wraps onto itself: too few vertices around `v`, or a merged face that would not be
  /// counterclockwise in its rounded chart: a needle).
  bool remove(Vertex_index v);

  /// Flips edge i of f if the flip is valid (not constrained, two distinct faces, strictly convex lifted
  /// quadrilateral, both new faces counterclockwise in their rounded charts).
  /// Returns false otherwise. The two faces keep their indices: f gets corners (apex, source, neighbour apex),
  /// the neighbour gets (neighbour apex, target, apex). The triangulation may stop being Delaunay.
  bool flip(Face_index f, int i);

  /// Lawson's algorithm from the given edges (face, index): flips every non-Delaunay edge met, pushing the four
  /// outer edges of each flipped quadrilateral. Throws `Numerical_error` beyond 100 F + 10^5 flips.
  void restore_delaunay(std::vector<std::pair<Face_index, int> >& stack);
  /// Lawson's algorithm from every edge.
  void make_delaunay()
  {
    std::vector<std::pair<Face_index, int> > st;
    for(Face_index f = 0; f < faces_.size(); ++f) if(faces_[f].alive) for(int i = 0; i < 3; ++i) st.emplace_back(f, i);
    restore_delaunay(st);
  }

  /// Version stamp of face f (changes whenever the face is rebuilt): lets callers keep stale face handles.
  std::size_t version(Face_index f) const { return faces_[f].version; }

private:
  // The fields read by the edge tests of the Lawson flips and by the walk (chart, adjacency, flags, cached
  // transitions) come first, and a face is aligned to a cache line (256 bytes, 4 lines): the flips are bound by
  // the cache misses on neighbouring faces. The first line holds the chart, the flags and the version (the
  // refinement's queue checks `alive` and `version` of every face it pops, then reads the chart).
  struct alignas(64) Face
  {
    std::array<Point_2, 3> z;
    std::array<unsigned char, 3> ne;
    mutable unsigned char tr_ok = 0;
    unsigned char cons = 0;               // bit i: edge i is constrained
    bool alive = true;
    std::size_t version = 0;
    std::array<Face_index, 3> nb;
    mutable std::array<Isometry_2, 3> tr; // transition cache (see transition()); bit i of tr_ok: tr[i] valid
    std::array<Vertex_index, 3> v;
    Face_index ref = 0;
    Isometry_2 to_ref;
  };
  struct Vertex
  {
    Face_index face = null_index;
    unsigned char corner = 0;
    Reference_point refp;
    bool alive = true;
  };
  typedef std::pair<Face_index, int> Edge_ref;

  Delaunay_triangulation_on_surface() {}

  void build_from_polygon(const Fundamental_polygon<Kernel>& P, bool constrain_sides);
  void set_constrained(Face_index f, int i, bool c)
  { if(c) faces_[f].cons |= (unsigned char)(1u << i); else faces_[f].cons &= (unsigned char)~(1u << i); }
  template <class ST> void build_from_surface(const ST& st);
  void finish_construction();

  Face_index new_face()
  {
    ++nf_;
    if(!free_faces_.empty()) { const Face_index f = free_faces_.back(); free_faces_.pop_back(); faces_[f].alive = true; return f; }
    faces_.push_back(Face());
    return faces_.size() - 1;
  }
  void kill_face(Face_index f) { faces_[f].alive = false; ++faces_[f].version; free_faces_.push_back(f); --nf_; }
  Vertex_index new_vertex()
  {
    ++nv_;
    vertices_.push_back(Vertex());
    return vertices_.size() - 1;
  }

  /// hints the processor to fetch (for writing) the lines of face f that `link()` and `set_transition()` write
  /// (flags, adjacency, transition cache: the first three of its four lines); no effect on the result
  void prefetch_for_link(Face_index f) const
  {
#if defined(__GNUC__)
    const char* p = reinterpret_cast<const char*>(&faces_[f]);
    __builtin_prefetch(p, 1); __builtin_prefetch(p + 64, 1); __builtin_prefetch(p + 128, 1);
#else
    (void)f;
#endif
  }
  void link(Face_index a, int i, Face_index b, int j)
  {
    faces_[a].nb[i] = b; faces_[a].ne[i] = (unsigned char)j; faces_[a].tr_ok &= (unsigned char)~(1u << i);
    faces_[b].nb[j] = a; faces_[b].ne[j] = (unsigned char)i; faces_[b].tr_ok &= (unsigned char)~(1u << j);
  }
  /// the same Moebius map with its matrix scaled by a power of two (exact) so that its determinant is in
  /// [2^-4, 2^4]: products of recentrings (determinant 1 - |o|^2 each) neither underflow nor overflow, and no
  /// square root is needed (the maps are homogeneous in the matrix)
  static Isometry_2 rescaled(const Isometry_2& m)
  {
    const double d = m.determinant();
    if(d >= 0.0625 && d <= 16) return m;
    const int e = std::ilogb(d);
    const double s = std::ldexp(1.0, -e / 2);
    return Isometry_2(s * m.alpha_real(), s * m.alpha_imag(), s * m.beta_real(), s * m.beta_imag());
  }
  /// stores `m` (chart of f -> chart of neighbor(f, i)) as the transition of edge i of f, and its inverse on the
  /// other side. Used by the insertions and flips, whose new faces are cut out of one common chart: the
  /// transition between two new faces is the product of their recentrings, and the transition to an outer
  /// neighbour is the old transition times the inverse recentring, with no square root (a transition computed
  /// from the two charts by `isometry_from_pairs` needs four, and two exact disk checks)
  void set_transition(Face_index f, int i, const Isometry_2& m)
  {
    Face& F = faces_[f];
    F.tr[i] = rescaled(m);
    F.tr_ok |= (unsigned char)(1u << i);
    Face& G = faces_[F.nb[i]];
    const int j = F.ne[i];
    if(&G != &F || j != i) { G.tr[j] = F.tr[i].inverse(); G.tr_ok |= (unsigned char)(1u << j); }
  }
  const Isometry_2& cached_transition(Face_index f, int i) const
  {
    const Face& F = faces_[f];
    if(!((F.tr_ok >> i) & 1u)) {
      const Face& G = faces_[F.nb[i]];
      const int j = F.ne[i];
      F.tr[i] = Geometry::isometry_from_pairs(F.z[i], F.z[(i + 1) % 3], G.z[(j + 1) % 3], G.z[j]);
      F.tr_ok |= (unsigned char)(1u << i);
      if(&G != &F || j != i) { G.tr[j] = F.tr[i].inverse(); G.tr_ok |= (unsigned char)(1u << j); }
    }
    return F.tr[i];
  }
  /// a triangle (a, b, c) of a common chart moved to the chart centred at its barycentre `o` (rounded)
  struct Chart { std::array<Point_2, 3> z; Point_2 o; };
  Chart recentred(const Point_2& a, const Point_2& b, const Point_2& c) const;
  /// whether the rounded recentred triangle is counterclockwise (exact): every chart of the triangulation is
  bool is_ccw(const Chart& c) const;
  /// whether segment (a, b) of one chart and (a2, b2) of another have the same hyperbolic length up to
  /// 1e-7 (1 + length) (cheap: no transcendental function)
  static bool same_length(const Point_2& a, const Point_2& b, const Point_2& a2, const Point_2& b2);
  /// min over the edges of F of sinh^2(length / 2) (see `Geometry::sinh2_half_distance()`)
  static double shortest_edge_sinh2(const Face& F);
  /// sets face f to the recentred triangle `ch` of a common chart whose anchor is (ref, chart_to_ref).
  /// Returns the recentring isometry (common chart -> chart of f), from which the callers compose the new
  /// transitions (no square root: see `set_transition()`)
  Isometry_2 set_face(Face_index f, const Chart& ch,
                Vertex_index va, Vertex_index vb, Vertex_index vc, Face_index ref, const Isometry_2& chart_to_ref);
  /// reference position of a point q of the chart of face f
  Reference_point reference_of(Face_index f, const Point_2& q) const
  {
    Reference_point r;
    r.reference_face = faces_[f].ref;
    r.point = faces_[f].to_ref.apply_unchecked(q);
    Isometry_2 m;
    ref_.walk(r.reference_face, r.point, m);
    return r;
  }
  struct Loop_segment { Point_2 a, b; Vertex_index u, v; }; // a segment of a feature loop: frame ends, vertices
  /// how a segment meets the triangulation: it is an edge (face, index), it crosses a constrained edge (face,
  /// index) at `point` (chart) = `frame_point`, it runs through a vertex (face, corner) at `frame_point`, or
  /// it is not an edge (split it)
  struct Trace { enum Type { EDGE, CROSSING, VERTEX, NOT_AN_EDGE } type = NOT_AN_EDGE; Face_index face = null_index;
                 int index = -1; Point_2 point, frame_point; };
  Trace trace_segment(const Loop_segment& s) const;
  Vertex_index insert_loop_point(const Point_2& frame_point);
  Vertex_index insert_in_face(Face_index f, const Point_2& p);
  Vertex_index insert_on_edge(Face_index f, int i, const Point_2& p);
  bool merge_star_of_degree_3(Vertex_index v, const std::vector<Edge_ref>& st);
  bool quad_is_convex(Face_index f, int i) const;
  Location locate_in_frame_unchecked(const Point_2& p, Isometry_2* frame_to_chart) const;
  /// the hyperbolic distance from p to corner i of F if it is below max(separation, duplicate_distance *
  /// shortest edge of F), else a negative number; `s_min` = `shortest_edge_sinh2(F)`
  static double near_corner(const Face& F, int i, const Point_2& p, double separation, double s_min);
  /// whether p is within twice `tol` of the geodesic through edge i of F (chart of F)
  bool near_edge_line(const Face& F, int i, const Point_2& p, double tol) const;
  /// a point located in face r.face (or on one of its edges): located on the nearest vertex within the
  /// duplicate tolerance (see `locate()`) if there is one, a corner of r.face or, behind needles, of a face
  /// reached across edges whose geodesics pass that close to the point
  void snap_to_near_vertex(Location& r, Isometry_2* to_chart, double separation) const;
  static Point_2 moved_to_origin(const Point_2& o, const Point_2& z);

  Geom_traits gt_;
  std::vector<Face, internal::Large_block_allocator<Face> > faces_;
  std::vector<Vertex, internal::Large_block_allocator<Vertex> > vertices_;
  std::vector<Face_index> free_faces_;
  std::size_t nf_ = 0, nv_ = 0, flips_ = 0;
  internal::Reference_triangulation<Geom_traits> ref_;
  std::vector<Face_index> ref_hint_; // a live face anchored at each reference face (may be stale)
  std::vector<Edge_ref> scratch_;    // the flip stack of the insertions (reused)
};

} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#include <CGAL/Hyperbolic_surface_mesh_2/internal/Delaunay_triangulation_on_surface_impl.h>
#include <CGAL/Hyperbolic_surface_mesh_2/internal/feature_loops_impl.h>

#endif // CGAL_HYPERBOLIC_SURFACE_MESH_2_DELAUNAY_TRIANGULATION_ON_SURFACE_H
