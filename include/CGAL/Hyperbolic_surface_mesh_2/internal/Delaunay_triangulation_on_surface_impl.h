// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Member functions of Delaunay_triangulation_on_surface (construction, location, insertion, flips, removal,
// checks). Included by <CGAL/Hyperbolic_surface_mesh_2/Delaunay_triangulation_on_surface.h>.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_DELAUNAY_TRIANGULATION_ON_SURFACE_IMPL_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_DELAUNAY_TRIANGULATION_ON_SURFACE_IMPL_H

#include <algorithm>
#include <deque>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace internal {
// the BGL free functions (the triangulation's members of the same names hide them)
template <class G> auto graph_vertices(const G& g) { return vertices(g); }
template <class G> auto graph_faces(const G& g) { return faces(g); }
} // namespace internal

#define CGAL_HSM2_DT Delaunay_triangulation_on_surface<Traits_>

// ---------------------------------------------------------------- construction

template <class Traits_>
typename CGAL_HSM2_DT::Chart CGAL_HSM2_DT::recentred(const Point_2& a, const Point_2& b, const Point_2& c) const
{
  Chart r;
  r.o = Geometry::barycenter(a, b, c); // in the disk: a barycentre of points of the disk
  r.z = {{moved_to_origin(r.o, a), moved_to_origin(r.o, b), moved_to_origin(r.o, c)}};
  return r;
}

template <class Traits_>
typename CGAL_HSM2_DT::Point_2 CGAL_HSM2_DT::moved_to_origin(const Point_2& o, const Point_2& z)
{
  // t(z) = (z - o) / (1 - conj(o) z), with one division per point (t.apply_unchecked divides twice)
  const double x = z.x(), y = z.y(), nr = x - o.x(), ni = y - o.y();
  const double dr = 1 - o.x() * x - o.y() * y, di = o.y() * x - o.x() * y;
  const double s = 1 / (dr * dr + di * di);
  return Point_2((nr * dr + ni * di) * s, (ni * dr - nr * di) * s);
}

template <class Traits_>
double CGAL_HSM2_DT::shortest_edge_sinh2(const Face& F)
{
  return (std::min)({Geometry::sinh2_half_distance(F.z[0], F.z[1]), Geometry::sinh2_half_distance(F.z[1], F.z[2]),
                     Geometry::sinh2_half_distance(F.z[2], F.z[0])});
}

template <class Traits_>
bool CGAL_HSM2_DT::same_length(const Point_2& a, const Point_2& b, const Point_2& a2, const Point_2& b2)
{
  // s = sinh^2(d / 2) = |x - y|^2 / ((1 - |x|^2)(1 - |y|^2)); d = 2 asinh(sqrt(s)), so |d1 - d2| <= 2 |sqrt(s1) -
  // sqrt(s2)| and d <= 2 sqrt(s): this asks |d1 - d2| <= 1e-7 (1 + d1), well inside is_valid()'s 1e-6
  const double r1 = std::sqrt(Geometry::sinh2_half_distance(a, b)), r2 = std::sqrt(Geometry::sinh2_half_distance(a2, b2));
  return 2 * std::abs(r1 - r2) <= 1e-7 * (1 + 2 * r1);
}

template <class Traits_>
bool CGAL_HSM2_DT::is_ccw(const Chart& c) const
{
  return gt_.orientation_2_object()(c.z[0], c.z[1], c.z[2]) == CGAL::LEFT_TURN;
}

template <class Traits_>
typename CGAL_HSM2_DT::Isometry_2 CGAL_HSM2_DT::set_face(Face_index f, const Chart& ch,
                            Vertex_index va, Vertex_index vb, Vertex_index vc, Face_index ref,
                            const Isometry_2& chart_to_ref)
{
  Face& F = faces_[f];
  const Isometry_2 t(1, 0, -ch.o.x(), -ch.o.y()); // translation_to_origin(o) without its disk check
  F.z = ch.z;
  F.v = {{va, vb, vc}};
  F.tr_ok = 0; // the callers relink all three edges (which drops the neighbours' cached transitions too)
  F.ref = ref;
  F.to_ref = rescaled(chart_to_ref * t.inverse());
  // keep the anchor near: walk the barycentre (the chart's origin) in the reference triangulation
  // the image of the origin, beta / conj(alpha) = beta alpha / |alpha|^2
  const double ar = F.to_ref.alpha_real(), ai = F.to_ref.alpha_imag(), br = F.to_ref.beta_real(), bi = F.to_ref.beta_imag();
  const double s = 1 / (ar * ar + ai * ai);
  Point_2 q((br * ar - bi * ai) * s, (bi * ar + br * ai) * s);
  ref_.walk(F.ref, q, F.to_ref, 64);
  ref_hint_[F.ref] = f;
  ++F.version;
  for(int k = 0; k < 3; ++k) { vertices_[F.v[k]].face = f; vertices_[F.v[k]].corner = (unsigned char)k; }
  return t;
}

template <class Traits_>
void CGAL_HSM2_DT::build_from_polygon(const Fundamental_polygon<Kernel>& P, bool constrain_sides)
{
  const std::size_t n = P.size();
  for(int k = 0; k < P.number_of_vertex_cycles(); ++k) new_vertex();
  // fan from w_0: triangle t (t = 0..n-3) is (w_0, w_{t+1}, w_{t+2})
  ref_.faces.resize(n - 2);
  ref_hint_.assign(n - 2, 0);
  for(std::size_t t = 0; t + 2 < n; ++t) {
    const Face_index f = new_face();
    auto& R = ref_.faces[t];
    const Point_2 a = P.vertex(0), b = P.vertex(t + 1), c = P.vertex(t + 2);
    const Isometry_2 tr = Isometry_2::translation_to_origin(Geometry::barycenter(a, b, c));
    R.z = {{tr.apply_unchecked(a), tr.apply_unchecked(b), tr.apply_unchecked(c)}};
    R.to_frame = tr.inverse();
    Face& F = faces_[f];
    F.z = R.z;
    F.v = {{Vertex_index(P.vertex_cycle(0)), Vertex_index(P.vertex_cycle(t + 1)), Vertex_index(P.vertex_cycle(t + 2))}};
    F.ref = t;
    ref_hint_[t] = f;
    for(int k = 0; k < 3; ++k) { vertices_[F.v[k]].face = f; vertices_[F.v[k]].corner = (unsigned char)k; }
  }
  // the (face, edge) of polygon side s
  auto side = [&](std::size_t s) -> Edge_ref {
    if(s == 0) return {0, 0};
    if(s == n - 1) return {n - 3, 2};
    return {s - 1, 1};
  };
  for(std::size_t t = 0; t + 3 < n; ++t) link(t, 2, t + 1, 0); // diagonals
  for(std::size_t s = 0; s < n; ++s) {
    const std::size_t s2 = std::size_t(P.paired_side(s));
    if(s < s2) { const Edge_ref a = side(s), b = side(s2); link(a.first, a.second, b.first, b.second); }
    if(constrain_sides) set_constrained(side(s).first, side(s).second, true);
  }
  for(std::size_t t = 0; t + 2 < n; ++t) { ref_.faces[t].nb = faces_[t].nb; ref_.faces[t].ne = faces_[t].ne; }
  ref_.cache_transitions();
  finish_construction();
}

template <class Traits_>
template <class ST>
void CGAL_HSM2_DT::build_from_surface(const ST& st)
{
  typedef typename ST::Triangle_mesh TM;
  typedef typename boost::graph_traits<TM>::vertex_descriptor vd;
  typedef typename boost::graph_traits<TM>::face_descriptor fd;
  const TM& tm = st.mesh();
  std::unordered_map<vd, Vertex_index> vid;
  for(vd v : internal::graph_vertices(tm)) { const Vertex_index i = new_vertex(); vid[v] = i; }
  std::unordered_map<fd, Face_index> fid;
  std::vector<typename ST::Face_chart> charts;
  for(fd f : internal::graph_faces(tm)) { fid[f] = new_face(); charts.push_back(st.chart(f)); }
  ref_.faces.resize(charts.size());
  ref_hint_.assign(charts.size(), 0);
  for(Face_index f = 0; f < charts.size(); ++f) {
    Face& F = faces_[f];
    const auto& c = charts[f];
    for(int k = 0; k < 3; ++k) {
      F.z[k] = c.z[k];
      F.v[k] = vid[source(c.h[k], tm)];
      const auto o = opposite(c.h[k], tm);
      const Face_index g = fid[face(o, tm)];
      F.nb[k] = g;
      F.ne[k] = (unsigned char)charts[g].index(o);
      vertices_[F.v[k]].face = f; vertices_[F.v[k]].corner = (unsigned char)k;
    }
    F.ref = f;
    ref_hint_[f] = f;
    ref_.faces[f].z = F.z; ref_.faces[f].nb = F.nb; ref_.faces[f].ne = F.ne;
  }
  ref_.cache_transitions();
  // frames: development along a breadth-first spanning tree of the faces
  std::vector<char> seen(charts.size(), 0);
  std::deque<Face_index> queue(1, 0);
  seen[0] = 1;
  while(!queue.empty()) {
    const Face_index f = queue.front(); queue.pop_front();
    for(int i = 0; i < 3; ++i) {
      const Face_index g = ref_.faces[f].nb[i];
      if(seen[g]) continue;
      seen[g] = 1;
      ref_.faces[g].to_frame = (ref_.faces[f].to_frame * ref_.transition(f, i).inverse()).normalized();
      queue.push_back(g);
    }
  }
  finish_construction();
}

template <class Traits_>
void CGAL_HSM2_DT::finish_construction()
{
  for(Face_index f = 0; f < faces_.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      Vertex& V = vertices_[faces_[f].v[k]];
      if(V.refp.reference_face == null_index) { V.refp.reference_face = f; V.refp.point = faces_[f].z[k]; }
    }
  make_delaunay();
}

// ---------------------------------------------------------------- location

template <class Traits_>
typename CGAL_HSM2_DT::Location CGAL_HSM2_DT::locate(const Point_2& p0, Face_index start, Edge_ref* blocking,
                                                    Isometry_2* to_chart, double separation) const
{
  if(blocking) *blocking = Edge_ref(null_index, -1);
  internal::check_in_disk(p0, "Delaunay_triangulation_on_surface::locate");
  if(!is_face(start)) throw Invalid_input_error("Delaunay_triangulation_on_surface::locate: not a face");
  const auto orient = gt_.orientation_2_object();
  Location r;
  Point_2 p = p0;
  Face_index f = start;
  int came_from = -1;
  const std::size_t bound = 10 * nf_ + 1000;
  for(std::size_t step = 0; step < bound; ++step) {
    const Face& F = faces_[f];
    int cross = -1, zeros = 0, zero_edge = -1;
    for(int k = 0; k < 3; ++k) {
      const int i = (k + int(step)) % 3; // rotate the first edge tried: no cycling in the visibility walk
      if(i == came_from) continue;
      const CGAL::Orientation o = orient(F.z[i], F.z[(i + 1) % 3], p);
      if(o == CGAL::RIGHT_TURN) { cross = i; break; }
    }
    if(cross >= 0 && blocking && is_constrained(f, cross)) { *blocking = Edge_ref(f, cross); r.face = f; r.point = p; return r; }
    if(cross >= 0) {
      // a lift of an end of the edge up to rounding (right of it by 1e-17): the walk would turn around that
      // vertex forever (every face of its star sees the point across one of its two edges at the vertex)
      for(int e = cross; e <= cross + 1; ++e) {
        const int i = e % 3;
        const double dx = F.z[i].x() - p.x(), dy = F.z[i].y() - p.y();
        if(dx * dx + dy * dy < 1e-20 && near_corner(F, i, p, separation, shortest_edge_sinh2(F)) >= 0) { r.face = f; r.point = p; r.type = Location::ON_VERTEX; r.index = i; return r; }
      }
      p = transition(f, cross).apply_unchecked(p);
      if(to_chart) *to_chart = rescaled(transition(f, cross) * *to_chart);
      came_from = F.ne[cross];
      f = F.nb[cross];
      continue;
    }
    // inside or on the boundary (the edge we came from is on the left by construction, test it again)
    for(int i = 0; i < 3; ++i) {
      const CGAL::Orientation o = orient(F.z[i], F.z[(i + 1) % 3], p);
      // right of the edge we came through (rounding of the transition): on that edge
      if(o == CGAL::RIGHT_TURN && i != came_from) { cross = i; break; }
      if(o != CGAL::LEFT_TURN) { ++zeros; zero_edge = i; }
    }
    if(cross >= 0 && blocking && is_constrained(f, cross)) { *blocking = Edge_ref(f, cross); r.face = f; r.point = p; return r; }
    if(cross >= 0) {
      p = transition(f, cross).apply_unchecked(p);
      if(to_chart) *to_chart = rescaled(transition(f, cross) * *to_chart);
      came_from = F.ne[cross]; f = F.nb[cross]; continue;
    }
    r.face = f; r.point = p;
    for(int i = 0; i < 3; ++i)
      if(F.z[i] == p) { r.type = Location::ON_VERTEX; r.index = i; return r; }
    // a lift of a vertex, up to the rounding of the transitions crossed (relative to the face's size)
    if(zeros == 0) r.type = Location::IN_FACE;
    if(zeros == 1) { r.type = Location::ON_EDGE; r.index = zero_edge; }
    if(zeros <= 1) { snap_to_near_vertex(r, to_chart, separation); return r; }
    // on two supporting geodesics but not a vertex: rounding of p; take the nearest corner
    int best = 0;
    for(int i = 1; i < 3; ++i) if(Geometry::distance(F.z[i], p) < Geometry::distance(F.z[best], p)) best = i;
    r.type = Location::ON_VERTEX; r.index = best; return r;
  }
  throw Numerical_error("Delaunay_triangulation_on_surface::locate: the walk exceeded its work bound");
}

template <class Traits_>
bool CGAL_HSM2_DT::near_edge_line(const Face& F, int i, const Point_2& p, double tol) const
{
  // hyperbolic distance d from p to the geodesic through edge i below 2 tol: with the edge's source moved to
  // the origin (b its target, w the image of p), the geodesic is the diameter through b and
  // sinh d = 2 |Im(w conj(b))| / (|b| (1 - |w|^2))
  const Point_2 b = moved_to_origin(F.z[i], F.z[(i + 1) % 3]), w = moved_to_origin(F.z[i], p);
  const double im = w.y() * b.x() - w.x() * b.y();
  const double nb = std::sqrt(b.x() * b.x() + b.y() * b.y()), nw = 1 - w.x() * w.x() - w.y() * w.y();
  return 2 * std::abs(im) < 2 * tol * nb * nw;
}

template <class Traits_>
void CGAL_HSM2_DT::snap_to_near_vertex(Location& r, Isometry_2* to_chart, double separation) const
{
  double best = -1;
  int best_corner = -1;
  const Face& R = faces_[r.face];
  const double s_min = shortest_edge_sinh2(R);
  for(int c = 0; c < 3; ++c) {
    const double d = near_corner(R, c, r.point, separation, s_min);
    if(d >= 0 && (best < 0 || d < best)) { best = d; best_corner = c; }
  }
  // Points given in a chart (separation 0: the refiner's circumcentres, on the hot path) stop here.
  if(best_corner >= 0 || separation <= 0) { if(best_corner >= 0) { r.type = Location::ON_VERTEX; r.index = best_corner; } return; }
  // a vertex behind needles: a search over the faces reached across edges whose geodesics pass within the
  // tolerance of p (usually none). On this path of every location the tolerance is bounded without a
  // transcendental function: d = 2 asinh(sqrt(s)) <= 2 sqrt(s), s = sinh^2(d / 2) (a larger bound only widens
  // the search; near_corner() decides exactly)
  const double tol = (std::max)(separation, duplicate_distance * 2 * std::sqrt(s_min));
  bool any = false;
  for(int i = 0; i < 3 && !any; ++i) any = near_edge_line(faces_[r.face], i, r.point, tol);
  if(any) {
    struct Item { Face_index f; Point_2 p; Isometry_2 m; }; // m: chart of r.face -> chart of f
    std::vector<Item> items{Item{r.face, r.point, Isometry_2()}};
    std::size_t best_item = 0;
    for(std::size_t k = 0; k < items.size() && k < 64; ++k) {
      const Item it = items[k];
      const Face& F = faces_[it.f];
      if(k > 0) { // (r.face: tested above)
        const double s_f = shortest_edge_sinh2(F);
        for(int c = 0; c < 3; ++c) {
          const double d = near_corner(F, c, it.p, separation, s_f);
          if(d >= 0 && (best < 0 || d < best)) { best = d; best_corner = c; best_item = k; }
        }
      }
      for(int i = 0; i < 3; ++i) {
        const Face_index g = F.nb[i];
        if(!near_edge_line(F, i, it.p, tol) ||
           std::find_if(items.begin(), items.end(), [g](const Item& x) { return x.f == g; }) != items.end()) continue;
        const Isometry_2 t = transition(it.f, i);
        items.push_back(Item{g, t.apply_unchecked(it.p), rescaled(t * it.m)});
      }
    }
    if(best_corner >= 0 && best_item > 0) {
      const Item& it = items[best_item];
      if(to_chart) *to_chart = rescaled(it.m * *to_chart);
      r.face = it.f; r.point = it.p;
    }
  }
  if(best_corner >= 0) { r.type = Location::ON_VERTEX; r.index = best_corner; }
}

template <class Traits_>
double CGAL_HSM2_DT::near_corner(const Face& F, int i, const Point_2& p, double separation, double s_min)
{
  // d(z_i, p) < max(duplicate_distance * (shortest edge), separation). With s(x, y) = sinh^2(d(x, y) / 2)
  // and asinh(t x) >= t asinh(x) for t in [0, 1]: s(z_i, p) >= 1e-12 s_min implies d >= 1e-6 d_min, and
  // s >= separation^2 implies d >= 2 separation: no duplicate; the distances (transcendental) are computed
  // only below that (d is monotone in s: the shortest edge is 2 asinh sqrt(s_min))
  const double sp = Geometry::sinh2_half_distance(F.z[i], p);
  if(sp >= 1e-12 * s_min && sp >= separation * separation) return -1;
  const double d = 2 * std::asinh(std::sqrt(sp));
  const double tol = (std::max)(separation, duplicate_distance * 2 * std::asinh(std::sqrt(s_min)));
  return d < tol ? d : -1;
}

template <class Traits_>
typename CGAL_HSM2_DT::Location CGAL_HSM2_DT::locate_in_frame(const Point_2& p, Isometry_2* frame_to_chart) const
{
  internal::check_in_disk(p, "Delaunay_triangulation_on_surface::locate_in_frame");
  // p is in the disk: an image of it rounded out of the disk on the way (a point within about 1e-11 of the
  // circle at infinity; found by a test) is a precision limit, not bad input
  try { return locate_in_frame_unchecked(p, frame_to_chart); }
  catch(const Poincare_disk_domain_error& e) {
    throw Numerical_error(std::string("Delaunay_triangulation_on_surface::locate_in_frame: the point is too close to "
                                      "the circle at infinity to be located in double precision (") + e.what() + ")");
  }
}

template <class Traits_>
typename CGAL_HSM2_DT::Location CGAL_HSM2_DT::locate_in_frame_unchecked(const Point_2& p, Isometry_2* frame_to_chart) const
{
  std::size_t o = 0;
  Isometry_2 phi = ref_.faces[0].to_frame.inverse(); // frame -> chart of the current face
  Point_2 q = phi.apply_unchecked(p);
  Isometry_2 m;
  ref_.walk(o, q, m, 100000);
  // A point near the circle at infinity (found by the fuzzer: (1 - 1.1e-16, 0)) is reduced into the domain by
  // an isometry moving points by its distance d from the origin: |alpha|^2 + |beta|^2 = cosh(d) |det|, and
  // det = |alpha|^2 - |beta|^2 loses all its digits beyond d = 23.7 (cosh d = 1e10), i.e. |p| > 1 - 1e-10.
  auto conditioned = [](const Isometry_2& t) {
    const double a = t.alpha_real() * t.alpha_real() + t.alpha_imag() * t.alpha_imag();
    const double b = t.beta_real() * t.beta_real() + t.beta_imag() * t.beta_imag();
    return std::isfinite(a) && std::isfinite(b) && a - b > 1e-10 * (a + b);
  };
  auto refuse = []() {
    throw Numerical_error("Delaunay_triangulation_on_surface::locate_in_frame: the point is too close to the circle "
                          "at infinity (|p| > 1 - 1e-10) to be mapped into the fundamental domain in double precision");
  };
  const Isometry_2 mp = m * phi;
  if(!conditioned(mp) || !std::isfinite(q.x()) || !std::isfinite(q.y())) refuse();
  phi = rescaled(mp);
  // a live face anchored at o (or near it)
  Face_index f = ref_hint_[o];
  if(!is_face(f) || faces_[f].ref != o) {
    f = null_index;
    for(Face_index g = 0; g < faces_.size(); ++g) if(faces_[g].alive && faces_[g].ref == o) { f = g; break; }
    if(f == null_index) { // no face anchored at o: express q in the chart of any face's anchor
      for(Face_index g = 0; g < faces_.size() && f == null_index; ++g)
        if(faces_[g].alive) {
          // map q from o to faces_[g].ref through frames (both are charts of the same domain development)
          const Isometry_2 o_to_g = ref_.faces[faces_[g].ref].to_frame.inverse() * ref_.faces[o].to_frame;
          q = o_to_g.apply_unchecked(q); phi = rescaled(o_to_g * phi); f = g;
        }
    }
  }
  const Isometry_2 to_f = faces_[f].to_ref.inverse();
  if(!conditioned(to_f * phi)) refuse();
  phi = rescaled(to_f * phi);
  const double separation = frame_resolution(p);
  Location r = locate(to_f.apply_unchecked(q), f, nullptr, &phi, separation);
  // The walk composed transitions, which are inaccurate across tiny edges (their rotation is known to the
  // rounding over the edge length: 1e-6 for edges of 1e-10). The anchor of the face found maps p directly (to
  // rounding); when it gives the same lift (the two images within 1e-6), a second, local walk starts from there.
  // Found by a test: points 1e-14 apart were located 1e-9 apart, so a point given again made a new vertex.
  // (the anchor of a face may be in another lift, far away: its isometry is then not used, and not rescaled)
  const Isometry_2 direct = to_frame(r.face).inverse();
  const Point_2 pd = direct.apply_unchecked(p);
  if(std::isfinite(pd.x()) && std::isfinite(pd.y()) && pd.x() * pd.x() + pd.y() * pd.y() < 1 &&
     Geometry::distance(pd, r.point) < 1e-6) {
    phi = rescaled(direct);
    r = locate(pd, r.face, nullptr, &phi, separation);
  }
  if(frame_to_chart) *frame_to_chart = phi;
  return r;
}

// ---------------------------------------------------------------- insertion

template <class Traits_>
typename CGAL_HSM2_DT::Vertex_index CGAL_HSM2_DT::insert(const Location& loc)
{
  if(loc.type == Location::ON_VERTEX) return faces_[loc.face].v[loc.index];
  if(loc.type == Location::ON_EDGE) return insert_on_edge(loc.face, loc.index, loc.point);
  return insert_in_face(loc.face, loc.point);
}

template <class Traits_>
typename CGAL_HSM2_DT::Vertex_index CGAL_HSM2_DT::insert_in_face(Face_index f, const Point_2& p)
{
  for(int k = 0; k < 3; ++k) prefetch_for_link(faces_[f].nb[k]); // (see flip())
  // the transitions to the outer neighbours, before f is rebuilt (an edge glued to f itself is recomputed later)
  const Isometry_2 T[3] = {cached_transition(f, 0), cached_transition(f, 1), cached_transition(f, 2)};
  const Face F = faces_[f];
  // the three new charts must be counterclockwise after their recentring (exact test on the rounded points: a
  // point next to an edge of a needle, a rounding away from it, would fold a chart; such a point is not inserted)
  const Chart ch[3] = {recentred(F.z[0], F.z[1], p), recentred(F.z[1], F.z[2], p), recentred(F.z[2], F.z[0], p)};
  if(!is_ccw(ch[0]) || !is_ccw(ch[1]) || !is_ccw(ch[2])) return null_index;
  const Vertex_index w = new_vertex();
  vertices_[w].refp = reference_of(f, p);
  const Face_index f1 = new_face(), f2 = new_face();
  const Face_index nf[3] = {f, f1, f2};
  const Isometry_2 t[3] = {set_face(f, ch[0], F.v[0], F.v[1], w, F.ref, F.to_ref),
                           set_face(f1, ch[1], F.v[1], F.v[2], w, F.ref, F.to_ref),
                           set_face(f2, ch[2], F.v[2], F.v[0], w, F.ref, F.to_ref)};
  auto remap = [&](Edge_ref e) -> Edge_ref {
    if(e.first != f) return e;
    return e.second == 0 ? Edge_ref(f, 0) : (e.second == 1 ? Edge_ref(f1, 0) : Edge_ref(f2, 0));
  };
  const Edge_ref L[3] = {remap({F.nb[0], F.ne[0]}), remap({F.nb[1], F.ne[1]}), remap({F.nb[2], F.ne[2]})};
  link(f, 0, L[0].first, L[0].second);
  link(f1, 0, L[1].first, L[1].second);
  link(f2, 0, L[2].first, L[2].second);
  link(f, 1, f1, 2); link(f1, 1, f2, 2); link(f2, 1, f, 2);
  for(int k = 0; k < 3; ++k) {
    if(F.nb[k] != f) set_transition(nf[k], 0, T[k] * t[k].inverse());
    set_transition(nf[k], 1, t[(k + 1) % 3] * t[k].inverse());
  }
  faces_[f].cons = F.cons & 1u; faces_[f1].cons = (F.cons >> 1) & 1u; faces_[f2].cons = (F.cons >> 2) & 1u;
  std::vector<Edge_ref>& st = scratch_; // no allocation per insertion
  st.clear(); st.emplace_back(f, 0); st.emplace_back(f1, 0); st.emplace_back(f2, 0);
  restore_delaunay(st);
  return w;
}

template <class Traits_>
typename CGAL_HSM2_DT::Vertex_index CGAL_HSM2_DT::insert_on_edge(Face_index f, int i, const Point_2& p)
{
  const Face_index g = faces_[f].nb[i];
  if(g == f) return null_index;
  const int j = faces_[f].ne[i];
  const Face F = faces_[f], G = faces_[g];
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
  const Point_2 a = F.z[i], b = F.z[i1], c = F.z[i2], d = neighbor_apex(f, i);
  // the four new faces must be counterclockwise in the common chart (exact): a split point off the edge by
  // rounding, next to a tiny angle, would fold one of them (found by the fuzzer: cascading splits of a feature
  // loop at a small crossing angle). Such a point is not inserted.
  const auto orient = gt_.orientation_2_object();
  if(orient(a, p, c) != CGAL::LEFT_TURN || orient(p, b, c) != CGAL::LEFT_TURN ||
     orient(b, p, d) != CGAL::LEFT_TURN || orient(p, a, d) != CGAL::LEFT_TURN) return null_index;
  // and after their recentring (see insert_in_face())
  const Chart ch[4] = {recentred(a, p, c), recentred(p, b, c), recentred(b, p, d), recentred(p, a, d)};
  for(const Chart& x : ch) if(!is_ccw(x)) return null_index;
  const Vertex_index va = F.v[i], vb = F.v[i1], vc = F.v[i2], vd = G.v[j2];
  const Vertex_index w = new_vertex();
  vertices_[w].refp = reference_of(f, p);
  const Face_index f1 = new_face(), g1 = new_face();
  set_face(f, ch[0], va, w, vc, F.ref, F.to_ref);
  set_face(f1, ch[1], w, vb, vc, F.ref, F.to_ref);
  set_face(g, ch[2], vb, w, vd, F.ref, F.to_ref);
  set_face(g1, ch[3], w, va, vd, F.ref, F.to_ref);
  auto remap = [&](Edge_ref e) -> Edge_ref {
    if(e.first == f && e.second == i1) return {f1, 1};
    if(e.first == f && e.second == i2) return {f, 2};
    if(e.first == g && e.second == j1) return {g1, 1};
    if(e.first == g && e.second == j2) return {g, 2};
    return e;
  };
  const Edge_ref Lbc = remap({F.nb[i1], F.ne[i1]}), Lca = remap({F.nb[i2], F.ne[i2]}),
                 Lad = remap({G.nb[j1], G.ne[j1]}), Ldb = remap({G.nb[j2], G.ne[j2]});
  link(f1, 1, Lbc.first, Lbc.second);
  link(f, 2, Lca.first, Lca.second);
  link(g1, 1, Lad.first, Lad.second);
  link(g, 2, Ldb.first, Ldb.second);
  link(f, 0, g1, 0); link(f, 1, f1, 2); link(f1, 0, g, 0); link(g, 1, g1, 2);
  // constraints: the halves of a constrained edge stay constrained, the outer edges keep theirs
  const unsigned h = (F.cons >> i) & 1u;
  faces_[f].cons = (unsigned char)(h | (((F.cons >> i2) & 1u) << 2));
  faces_[f1].cons = (unsigned char)(h | (((F.cons >> i1) & 1u) << 1));
  faces_[g].cons = (unsigned char)(h | (((G.cons >> j2) & 1u) << 2));
  faces_[g1].cons = (unsigned char)(h | (((G.cons >> j1) & 1u) << 1));
  std::vector<Edge_ref>& st = scratch_;
  st.clear(); st.emplace_back(f, 2); st.emplace_back(f1, 1); st.emplace_back(g, 2); st.emplace_back(g1, 1);
  restore_delaunay(st);
  return w;
}

// ---------------------------------------------------------------- flips

template <class Traits_>
bool CGAL_HSM2_DT::quad_is_convex(Face_index f, int i) const
{
  const Face& F = faces_[f];
  if(F.nb[i] == f || ((F.cons >> i) & 1u)) return false;
  const auto orient = gt_.orientation_2_object();
  const Point_2 &a = F.z[i], &b = F.z[(i + 1) % 3], &c = F.z[(i + 2) % 3];
  const Point_2 d = neighbor_apex(f, i);
  return orient(b, a, d) == CGAL::LEFT_TURN && orient(d, b, c) == CGAL::LEFT_TURN && orient(c, a, d) == CGAL::LEFT_TURN;
}

template <class Traits_>
bool CGAL_HSM2_DT::flip(Face_index f, int i)
{
  if(!quad_is_convex(f, i)) return false;
  const Face_index g = faces_[f].nb[i];
  const int j = faces_[f].ne[i];
  // the four outer neighbours get new adjacency and transitions: their cache lines are fetched while the two
  // faces are rebuilt (the flips are bound by these misses)
  prefetch_for_link(faces_[f].nb[(i + 1) % 3]); prefetch_for_link(faces_[f].nb[(i + 2) % 3]);
  prefetch_for_link(faces_[g].nb[(j + 1) % 3]); prefetch_for_link(faces_[g].nb[(j + 2) % 3]);
  const Face F = faces_[f], G = faces_[g];
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
  const Point_2 a = F.z[i], b = F.z[i1], c = F.z[i2], d = neighbor_apex(f, i);
  // the two new charts must stay counterclockwise after their recentring (a flat quadrilateral, convex by a
  // rounding, would fold one): else no flip
  const Chart chf = recentred(c, a, d), chg = recentred(d, b, c);
  if(!is_ccw(chf) || !is_ccw(chg)) return false;
  // and d, mapped across edge i, must give g's outer edges their lengths (a transition across a tiny edge has
  // its rotation known only to the rounding over the edge's length: a far apex may move; found by the fuzzer)
  if(!same_length(a, d, G.z[j1], G.z[j2]) || !same_length(d, b, G.z[j2], G.z[j])) return false;
  const Vertex_index va = F.v[i], vb = F.v[i1], vc = F.v[i2], vd = G.v[j2];
  // the transitions of the quadrilateral's outer edges from the chart of f (composed through g's chart), before
  // the rebuild; an outer edge glued to f or g is recomputed later from the new charts
  auto outer = [&](const Face& X, int k) { return X.nb[k] != f && X.nb[k] != g; };
  const Isometry_2 Tfg = cached_transition(f, i);
  const Isometry_2 Tca = cached_transition(f, i2), Tbc = cached_transition(f, i1);
  const Isometry_2 Tad = cached_transition(g, j1) * Tfg, Tdb = cached_transition(g, j2) * Tfg;
  const Isometry_2 tf = set_face(f, chf, vc, va, vd, F.ref, F.to_ref);
  const Isometry_2 tg = set_face(g, chg, vd, vb, vc, F.ref, F.to_ref);
  auto remap = [&](Edge_ref e) -> Edge_ref {
    if(e.first == f && e.second == i1) return {g, 1};
    if(e.first == f && e.second == i2) return {f, 0};
    if(e.first == g && e.second == j1) return {f, 1};
    if(e.first == g && e.second == j2) return {g, 0};
    return e;
  };
  const Edge_ref Lbc = remap({F.nb[i1], F.ne[i1]}), Lca = remap({F.nb[i2], F.ne[i2]}),
                 Lad = remap({G.nb[j1], G.ne[j1]}), Ldb = remap({G.nb[j2], G.ne[j2]});
  link(f, 0, Lca.first, Lca.second);
  link(f, 1, Lad.first, Lad.second);
  link(g, 0, Ldb.first, Ldb.second);
  link(g, 1, Lbc.first, Lbc.second);
  link(f, 2, g, 2);
  const Isometry_2 tfi = tf.inverse(), tgi = tg.inverse();
  if(outer(F, i2)) set_transition(f, 0, Tca * tfi);
  if(outer(G, j1)) set_transition(f, 1, Tad * tfi);
  if(outer(G, j2)) set_transition(g, 0, Tdb * tgi);
  if(outer(F, i1)) set_transition(g, 1, Tbc * tgi);
  set_transition(f, 2, tg * tfi);
  faces_[f].cons = (unsigned char)(((F.cons >> i2) & 1u) | (((G.cons >> j1) & 1u) << 1));
  faces_[g].cons = (unsigned char)(((G.cons >> j2) & 1u) | (((F.cons >> i1) & 1u) << 1));
  ++flips_;
  return true;
}

template <class Traits_>
void CGAL_HSM2_DT::restore_delaunay(std::vector<Edge_ref>& st)
{
  const std::size_t bound = 100 * nf_ + 100000;
  std::size_t done = 0;
  while(!st.empty()) {
    const Edge_ref e = st.back(); st.pop_back();
    if(!is_face(e.first) || is_locally_delaunay(e.first, e.second)) continue; // (constrained: Delaunay)
    const Face_index g = faces_[e.first].nb[e.second];
    if(!flip(e.first, e.second)) continue;
    if(++done > bound) throw Numerical_error("Delaunay_triangulation_on_surface: Lawson flips exceeded their work bound");
    st.emplace_back(e.first, 0); st.emplace_back(e.first, 1); st.emplace_back(g, 0); st.emplace_back(g, 1);
  }
}

// ---------------------------------------------------------------- removal

template <class Traits_>
std::vector<std::pair<std::size_t, int> > CGAL_HSM2_DT::star(Vertex_index v) const
{
  std::vector<Edge_ref> r;
  star(v, r);
  return r;
}

template <class Traits_>
void CGAL_HSM2_DT::star(Vertex_index v, std::vector<Edge_ref>& r) const
{
  r.clear();
  Edge_ref c(vertices_[v].face, vertices_[v].corner);
  const std::size_t bound = 3 * nf_ + 3;
  do {
    r.push_back(c);
    const Face& F = faces_[c.first];
    const int e = (c.second + 2) % 3; // edge (corner before v -> v); the next face counterclockwise
    c = Edge_ref(F.nb[e], F.ne[e]);
    if(r.size() > bound) throw Numerical_error("Delaunay_triangulation_on_surface::star: broken adjacency");
  } while(c != r.front());
}

template <class Traits_>
bool CGAL_HSM2_DT::remove(Vertex_index v)
{
  if(!is_vertex(v) || nv_ <= 1) return false;
  for(const Edge_ref& c : star(v)) // a vertex of a feature loop stays
    if(is_constrained(c.first, c.second) || is_constrained(c.first, (c.second + 2) % 3)) return false;
  std::vector<Face_index> touched; // faces rebuilt by the degree-reducing flips: their edges are tested after
  bool done = false;
  for(std::size_t round = 0; round < 4 * nf_ + 16 && !done; ++round) {
    const std::vector<Edge_ref> st = star(v);
    if(st.size() == 3 && merge_star_of_degree_3(v, st)) { done = true; break; }
    bool flipped = false;
    for(const Edge_ref& c : st) {
      const Face& F = faces_[c.first];
      const Face_index g = F.nb[c.second];
      if(g == c.first) continue;
      // the flip must not create another edge at v
      if(F.v[(c.second + 2) % 3] == v || faces_[g].v[(F.ne[c.second] + 2) % 3] == v) continue;
      if(flip(c.first, c.second)) { touched.push_back(c.first); touched.push_back(g); flipped = true; break; }
    }
    if(!flipped) break;
  }
  std::vector<Edge_ref> stack;
  for(Face_index f : touched) if(is_face(f)) for(int i = 0; i < 3; ++i) stack.emplace_back(f, i);
  restore_delaunay(stack);
  return done;
}

template <class Traits_>
bool CGAL_HSM2_DT::merge_star_of_degree_3(Vertex_index v, const std::vector<Edge_ref>& st)
{
  const Face_index f1 = st[0].first, f2 = st[1].first, f3 = st[2].first;
  if(f1 == f2 || f2 == f3 || f1 == f3) return false;
  const int c1 = st[0].second, c2 = st[1].second, c3 = st[2].second;
  const Face F1 = faces_[f1], F2 = faces_[f2], F3 = faces_[f3];
  const Point_2 x1 = F1.z[(c1 + 1) % 3], x2 = F1.z[(c1 + 2) % 3], x3 = neighbor_apex(f1, (c1 + 2) % 3);
  const Chart ch = recentred(x1, x2, x3); // counterclockwise after the recentring (see insert_in_face())
  if(gt_.orientation_2_object()(x1, x2, x3) != CGAL::LEFT_TURN || !is_ccw(ch)) return false;
  // x3 comes across an edge at v (tiny in a cluster): the merged face's outer edges must keep their lengths
  // (see flip(); found by the fuzzer: a removal left glued edges of different lengths)
  {
    const int k2 = (c2 + 1) % 3, k3 = (c3 + 1) % 3; // the outer edges (v2, v3) of f2 and (v3, v1) of f3
    if(!same_length(x2, x3, F2.z[k2], F2.z[(k2 + 1) % 3]) || !same_length(x3, x1, F3.z[k3], F3.z[(k3 + 1) % 3]))
      return false;
  }
  const Vertex_index v1 = F1.v[(c1 + 1) % 3], v2 = F1.v[(c1 + 2) % 3], v3 = F2.v[(c2 + 2) % 3];
  if(v1 == v || v2 == v || v3 == v) return false;
  auto remap = [&](Edge_ref e) -> Edge_ref {
    if(e == Edge_ref(f1, (c1 + 1) % 3)) return {f1, 0};
    if(e == Edge_ref(f2, (c2 + 1) % 3)) return {f1, 1};
    if(e == Edge_ref(f3, (c3 + 1) % 3)) return {f1, 2};
    return e;
  };
  const int e1 = (c1 + 1) % 3, e2 = (c2 + 1) % 3, e3 = (c3 + 1) % 3;
  const Edge_ref L1 = remap({F1.nb[e1], F1.ne[e1]}), L2 = remap({F2.nb[e2], F2.ne[e2]}), L3 = remap({F3.nb[e3], F3.ne[e3]});
  kill_face(f2); kill_face(f3);
  set_face(f1, ch, v1, v2, v3, F1.ref, F1.to_ref);
  // the outer edges keep their constraints (the edges at v have none: checked by remove())
  faces_[f1].cons = (unsigned char)(((F1.cons >> e1) & 1u) | (((F2.cons >> e2) & 1u) << 1) | (((F3.cons >> e3) & 1u) << 2));
  link(f1, 0, L1.first, L1.second);
  link(f1, 1, L2.first, L2.second);
  link(f1, 2, L3.first, L3.second);
  vertices_[v].alive = false; --nv_;
  std::vector<Edge_ref> s{{f1, 0}, {f1, 1}, {f1, 2}};
  restore_delaunay(s);
  return true;
}

// ---------------------------------------------------------------- checks and measures

template <class Traits_>
std::size_t CGAL_HSM2_DT::number_of_non_simplicial_edges() const
{
  std::map<std::pair<Vertex_index, Vertex_index>, int> count;
  std::size_t loops = 0, extra = 0;
  for(Face_index f = 0; f < faces_.size(); ++f) {
    if(!faces_[f].alive) continue;
    for(int i = 0; i < 3; ++i) {
      const Face_index g = faces_[f].nb[i];
      if(!(f < g || (f == g && i < faces_[f].ne[i]))) continue;
      const Vertex_index a = faces_[f].v[i], b = faces_[f].v[(i + 1) % 3];
      if(a == b) { ++loops; continue; }
      if(++count[{(std::min)(a, b), (std::max)(a, b)}] > 1) ++extra;
    }
  }
  return loops + extra;
}

template <class Traits_>
bool CGAL_HSM2_DT::is_valid(std::string* why, double tol) const
{
  auto fail = [&](const std::string& m) { if(why) *why = m; return false; };
  std::size_t nf = 0, nv = 0;
  for(Face_index f = 0; f < faces_.size(); ++f) {
    const Face& F = faces_[f];
    if(!F.alive) continue;
    ++nf;
    if(gt_.orientation_2_object()(F.z[0], F.z[1], F.z[2]) != CGAL::LEFT_TURN) return fail("a chart is not counterclockwise");
    for(int i = 0; i < 3; ++i) {
      if(!is_face(F.nb[i])) return fail("a neighbour is not a face");
      const Face& G = faces_[F.nb[i]];
      const int j = F.ne[i];
      if(G.nb[j] != f || G.ne[j] != i) return fail("adjacency is not symmetric");
      if(G.v[j] != F.v[(i + 1) % 3] || G.v[(j + 1) % 3] != F.v[i]) return fail("glued edges have different vertices");
      if(is_constrained(f, i) != is_constrained(F.nb[i], j)) return fail("an edge is constrained on one side only");
      const double l1 = edge_length(f, i), l2 = Geometry::distance(G.z[j], G.z[(j + 1) % 3]);
      if(!(std::abs(l1 - l2) <= tol * (1 + l1))) return fail("glued edges have different lengths in their charts");
      if(!is_vertex(F.v[i])) return fail("a corner is not a vertex");
    }
  }
  for(Vertex_index v = 0; v < vertices_.size(); ++v) {
    if(!vertices_[v].alive) continue;
    ++nv;
    const Vertex& V = vertices_[v];
    if(!is_face(V.face) || faces_[V.face].v[V.corner] != v) return fail("a vertex record points to a wrong corner");
  }
  if(nf != nf_ || nv != nv_) return fail("wrong counts");
  if(nf % 2 != 0) return fail("odd number of faces");
  return true;
}

template <class Traits_>
double CGAL_HSM2_DT::angle_sum(Vertex_index v) const
{
  double s = 0;
  for(const Edge_ref& c : star(v)) {
    const auto& z = faces_[c.first].z;
    const int i = c.second;
    s += Hyperbolic_surface_2::corner_angle(Geometry::distance(z[(i + 1) % 3], z[(i + 2) % 3]),
                                            Geometry::distance(z[i], z[(i + 1) % 3]),
                                            Geometry::distance(z[i], z[(i + 2) % 3]));
  }
  return s;
}

template <class Traits_>
double CGAL_HSM2_DT::area() const
{
  double a = 0;
  for(Face_index f = 0; f < faces_.size(); ++f)
    if(faces_[f].alive) a += Hyperbolic_surface_2::triangle_area(edge_length(f, 0), edge_length(f, 1), edge_length(f, 2));
  return a;
}

#undef CGAL_HSM2_DT

} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif
