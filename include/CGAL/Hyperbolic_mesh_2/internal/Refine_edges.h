// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: the edge level of the hyperbolic Delaunay refiner (as Refine_edges in CGAL's Mesh_2): the frame around
// the convex hull, the input segments and their small angles, corner lopping (thesis Fig. 3.6), encroachment and
// the splits of constrained edges (Ruppert: midpoint; Chew: midpoint or thirds, then removal of the free Steiner
// vertices nearby), with the exact choice of the rounded split point.
#ifndef CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_EDGES_H
#define CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_EDGES_H

#include <CGAL/Hyperbolic_mesh_2/internal/Refine_context.h>

#include <complex>
#include <limits>

// The names of Refine_edges (and Refine_context) in a derived level.
#define CGAL_HYPERBOLIC_MESH_2_REFINE_EDGES_NAMES \
  CGAL_HYPERBOLIC_MESH_2_REFINE_CONTEXT_NAMES \
  using Base::add_frame_if_needed; \
  using Base::frame_point; \
  using Base::collect_input; \
  using Base::wedge_in_domain; \
  using Base::lop_corners; \
  using Base::local_feature_size; \
  using Base::split_encroached_segment; \
  using Base::split_segment; \
  using Base::choose_split_point; \
  using Base::new_edges_are_Delaunay; \
  using Base::insertable_in_edge; \
  using Base::collect_free_near; \
  using Base::remove_free_vertex; \
  using Base::encroached_segments_left; \
  using Base::push_forced;

namespace CGAL {
namespace Hyperbolic_mesh_2 {
namespace internal {

template <class CDT, class Criteria>
class Refine_edges : public Refine_context<CDT, Criteria>
{
protected:
  typedef Refine_context<CDT, Criteria> Base;
  CGAL_HYPERBOLIC_MESH_2_REFINE_CONTEXT_NAMES

  Refine_edges(CDT& cdt, const Criteria& criteria, const Mesh_parameters<Point>& prm) : Base(cdt, criteria, prm) {}

  // ------------------------------------------------------------------ input
  // Rounded Steiner points on a constrained edge of the convex hull would make the hull non-convex (invalid
  // triangulation), and a hull edge has no opposite vertex to test encroachment against. So every constrained
  // edge on the hull gets one frame vertex just beyond it (between the edge and the circle at infinity, exactly
  // on the other side of its geodesic than the triangulation): the edge is then interior, between the domain and
  // one out-of-domain face. The frame is outside the domain, never encroaches, is not an input feature, and
  // counts in the work bound (one operation per vertex). At most one vertex per hull edge, whatever the distance
  // to the circle at infinity; an edge for which no such point is representable keeps no frame vertex (its
  // split points are then kept on the hull by `choose_split_point`).
  void add_frame_if_needed()
  {
    struct Hull_edge { Point a, b, x; };
    std::vector<Hull_edge> edges;
    auto fc = cdt_.incident_faces(cdt_.infinite_vertex()), done = fc;
    do {
      const int i = fc->index(cdt_.infinite_vertex());
      if(!cdt_.is_constrained(Edge(fc, i))) continue;
      const Face_handle g = fc->neighbor(i);
      const int j = cdt_.mirror_index(fc, i);
      edges.push_back(Hull_edge{g->vertex(CDT::ccw(j))->point(), g->vertex(CDT::cw(j))->point(), g->vertex(j)->point()});
    } while(++fc != done);
    for(const Hull_edge& e : edges) {
      if(st_.operations >= prm_.maximum_number_of_operations()) break; // the rest stays unframed (see above)
      Point p;
      if(!frame_point(e.a, e.b, e.x, p)) continue;
      frame_.insert(cdt_.insert(p));
      ++st_.frame_vertices; ++st_.operations;
    }
  }

  // A point strictly beyond the geodesic ab from x (exact orientation), inside the disk: on the Klein normal
  // through the midpoint of the Klein chord ab, half-way (then a quarter, ...) to the circle at infinity.
  bool frame_point(const Point& a, const Point& b, const Point& x, Point& out) const
  {
    auto klein = [](const Point& z) { const std::complex<double> c = cplx(z); return 2.0 * c / (1.0 + std::norm(c)); };
    const std::complex<double> ka = klein(a), kb = klein(b), kx = klein(x), m = 0.5 * (ka + kb);
    std::complex<double> n = (kb - ka) * std::complex<double>(0, 1);
    if(!(std::abs(n) > 0)) return false;
    n /= std::abs(n);
    if((n.real() * (kx - m).real() + n.imag() * (kx - m).imag()) > 0) n = -n;
    const double mn = m.real() * n.real() + m.imag() * n.imag();
    const double reach = -mn + std::sqrt(std::max(0.0, mn * mn + (1.0 - std::norm(m))));
    const Orientation inner = gt_.orientation_2_object()(a, b, x);
    double t = 0.5 * reach;
    for(int k = 0; k < 60 && t > 0; ++k, t *= 0.5) {
      const std::complex<double> kp = m + t * n;
      const double k2 = std::norm(kp);
      if(!(k2 < 1)) continue;
      const std::complex<double> z = kp / (1.0 + std::sqrt(1.0 - k2));
      const Point p(FT(z.real()), FT(z.imag()));
      if(!Poincare_disk_internal::is_in_open_disk(p)) continue;
      const Orientation o = gt_.orientation_2_object()(a, b, p);
      if(o == COLLINEAR || o == inner) continue;
      out = p;
      return true;
    }
    return false;
  }

  void collect_input()
  {
    for(auto e = cdt_.finite_edges_begin(); e != cdt_.finite_edges_end(); ++e) {
      if(!cdt_.is_constrained(*e)) continue;
      Vertex_handle a = e->first->vertex(CDT::ccw(e->second)), b = e->first->vertex(CDT::cw(e->second));
      input_seg_id_[key(a, b)] = int(input_segs_.size());
      input_segs_.push_back(std::make_pair(a, b));
    }
    // input angles below pi/2 between consecutive constrained edges around a vertex
    std::map<Vertex_handle, std::vector<int> > incident;
    for(std::size_t s = 0; s < input_segs_.size(); ++s) {
      incident[input_segs_[s].first].push_back(int(s));
      incident[input_segs_[s].second].push_back(int(s));
    }
    for(auto& kv : incident) {
      if(kv.second.size() < 2) continue;
      Vertex_handle o = kv.first;
      std::vector<std::pair<double, int> > dirs;
      for(int s : kv.second) {
        Vertex_handle w = input_segs_[s].first == o ? input_segs_[s].second : input_segs_[s].first;
        dirs.push_back(std::make_pair(tangent_direction(o->point(), w->point()), s));
      }
      std::sort(dirs.begin(), dirs.end());
      const double pi = std::acos(-1.0);
      for(std::size_t k = 0; k < dirs.size(); ++k) {
        const std::size_t l = (k + 1) % dirs.size();
        double gap = dirs[l].first - dirs[k].first;
        if(l == 0) gap += 2 * pi;
        if(gap < pi / 2 - small_angle_tolerance && wedge_in_domain(o, dirs[k].second)) {
          small_angle_pairs_.insert(std::minmax(dirs[k].second, dirs[l].second));
          apexes_.insert(o);
          ++st_.small_input_angles;
        }
      }
    }
  }

  // Is the wedge counterclockwise after input segment s at its endpoint o in the domain? (the face on the left of
  // the oriented edge o -> other end)
  bool wedge_in_domain(Vertex_handle o, int s) const
  {
    Vertex_handle w = input_segs_[std::size_t(s)].first == o ? input_segs_[std::size_t(s)].second
                                                              : input_segs_[std::size_t(s)].first;
    Face_handle f; int i;
    if(!cdt_.is_edge(o, w, f, i)) return true;
    for(Face_handle g : {f, f->neighbor(i)}) {
      if(cdt_.is_infinite(g)) continue;
      const Vertex_handle x = g->vertex(3 - g->index(o) - g->index(w));
      if(gt_.orientation_2_object()(o->point(), w->point(), x->point()) == LEFT_TURN) return g->is_in_domain();
    }
    return false;
  }

  // Corner lopping (thesis Fig. 3.6): every constrained edge at an apex of a small angle is split at distance
  // lfs(apex) / 3 from the apex, so all of them get equal first subsegments (the innermost shell); later midpoint
  // splits keep them equal (concentric shells).
  void lop_corners()
  {
    std::map<Vertex_handle, double> radius;
    for(Vertex_handle o : apexes_) {
      const double lfs = local_feature_size(o);
      if(lfs > 0 && std::isfinite(lfs)) radius[o] = lfs / 3;
    }
    lop_radius_ = radius;
    for(const auto& s : input_segs_) {
      if(st_.operations + 2 > prm_.maximum_number_of_operations()) break;
      const Vertex_handle a = s.first, b = s.second;
      const Point pa = a->point(), pb = b->point();
      const double d = approximate_distance(pa, pb);
      Vertex_handle from = a;
      auto ia = radius.find(a), ib = radius.find(b);
      if(ia != radius.end() && ia->second < d / 3 + 1e-300) {
        Point p;
        try { p = gt_.construct_hyperbolic_point_on_segment_2_object()(pa, pb, FT(ia->second / d)); }
        catch(const Poincare_disk_domain_error&) { continue; }
        Vertex_handle v = split_segment(a, b, p);
        if(v != Vertex_handle()) { from = v; ++st_.lopping_vertices; ++st_.operations; }
      }
      if(ib != radius.end() && ib->second < d / 3 + 1e-300) {
        Point p;
        try { p = gt_.construct_hyperbolic_point_on_segment_2_object()(pa, pb, FT(1.0 - ib->second / d)); }
        catch(const Poincare_disk_domain_error&) { continue; }
        if(split_segment(from, b, p) != Vertex_handle()) { ++st_.lopping_vertices; ++st_.operations; }
      }
    }
  }

  double local_feature_size(Vertex_handle o) const
  {
    double best = std::numeric_limits<double>::infinity();
    for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
      if(Vertex_handle(v) != o && !frame_.count(v)) best = std::min(best, approximate_distance(o->point(), v->point()));
    for(const auto& s : input_segs_) {
      if(s.first == o || s.second == o) continue;
      best = std::min(best, point_segment_distance(o->point(), s.first->point(), s.second->point()));
    }
    return best;
  }

  // ------------------------------------------------------------------ segment splits
  // Splits the constrained edge ab by the policy's rule; false if it cannot be split (see split_segment).
  bool split_encroached_segment(Vertex_handle a, Vertex_handle b) { return split_encroached_segment(a, b, Policy()); }

  // Ruppert (Algorithm 6): at the hyperbolic midpoint.
  bool split_encroached_segment(Vertex_handle a, Vertex_handle b, Ruppert_policy)
  {
    Vertex_handle v = split_segment(a, b, gt_.construct_hyperbolic_midpoint_2_object()(a->point(), b->point()));
    if(v == Vertex_handle()) return false;
    ++st_.midpoint_splits; ++st_.operations;
    post_insert(v);
    return true;
  }

  // Chew (Algorithm 5): into thirds if the length is in [2 rho(h*) h*, 4 h*] (then the free Steiner vertices closer
  // than a third of the length to a new vertex are removed), else at the midpoint (then those inside the diametral
  // disk are removed).
  bool split_encroached_segment(Vertex_handle a, Vertex_handle b, Chew_policy)
  {
    const Point a_pt = a->point(), b_pt = b->point();
    const double L = approximate_distance(a_pt, b_pt);
    std::vector<Vertex_handle> doomed, created;
    if(L >= 2 * rho(h_star_) * h_star_ && L <= 4 * h_star_) {
      const Point p1 = gt_.construct_hyperbolic_point_on_segment_2_object()(a_pt, b_pt, FT(1.0 / 3));
      const Point p2 = gt_.construct_hyperbolic_point_on_segment_2_object()(a_pt, b_pt, FT(2.0 / 3));
      Vertex_handle v1 = split_segment(a, b, p1);
      if(v1 == Vertex_handle()) return false;
      Vertex_handle v2 = budget_left(1) ? split_segment(v1, b, p2) : Vertex_handle();
      ++st_.one_third_splits; st_.operations += (v2 == Vertex_handle() ? 1 : 2);
      const double r = L / 3;
      created.push_back(v1);
      if(v2 != Vertex_handle()) created.push_back(v2);
      for(Vertex_handle v : created)
        collect_free_near(v, [&](Vertex_handle x) { return approximate_distance(x->point(), v->point()) < r; }, doomed);
    } else {
      Vertex_handle v = split_segment(a, b, gt_.construct_hyperbolic_midpoint_2_object()(a_pt, b_pt));
      if(v == Vertex_handle()) return false;
      ++st_.midpoint_splits; ++st_.operations;
      created.push_back(v);
      collect_free_near(v, [&](Vertex_handle x) {
        return gt_.side_of_hyperbolic_diametral_circle_2_object()(a_pt, b_pt, x->point()) == ON_BOUNDED_SIDE;
      }, doomed);
    }
    for(Vertex_handle x : doomed) if(budget_left()) remove_free_vertex(x); // the run ends at the bound
    for(Vertex_handle v : created) post_insert(v);
    return true;
  }

  // Inserts p (a rounded point of the geodesic ab) into the constrained edge ab; sets the in-domain marks of the
  // new faces from the two old sides. Returns the new vertex (null if ab is not a constrained edge).
  Vertex_handle split_segment(Vertex_handle a, Vertex_handle b, const Point& p)
  {
    Face_handle f; int i;
    if(!cdt_.is_edge(a, b, f, i) || !cdt_.is_constrained(Edge(f, i))) return Vertex_handle();
    Face_handle g = f->neighbor(i);
    const bool in_f = !cdt_.is_infinite(f) && f->is_in_domain(), in_g = !cdt_.is_infinite(g) && g->is_in_domain();
    // the apexes of the two sides: CGAL's insertion into the edge joins them to the new vertex, and its
    // flip_around only flips edges opposite the new vertex, so both stay neighbours of it
    const Vertex_handle apex_f = f->vertex(i), apex_g = cdt_.mirror_vertex(f, i);
    if(stuck_.count(key(a, b))) return Vertex_handle();
    const int seg = segment_id(a, b);
    // Resolution guard: a subsegment with a Euclidean length below 1e-11 is not split (its rounded split points
    // are a few ulps from its endpoints).
    const Point pa = a->point(), pb = b->point();
    const double ex = CGAL::to_double(pa.x()) - CGAL::to_double(pb.x()), ey = CGAL::to_double(pa.y()) - CGAL::to_double(pb.y());
    Point q;
    if(ex * ex + ey * ey < 1e-22 || !choose_split_point(p, f, i, q)) {
      stuck_.insert(key(a, b)); ++st_.unsplittable_segments; return Vertex_handle();
    }
    Vertex_handle v = cdt_.insert(q, CDT::EDGE, f, i);
    dead_.erase(v);
    mark_sides_of_split(v, apex_f, in_f, apex_g, in_g);
    if(seg >= 0) seg_of_[v] = seg;
    return v;
  }

  // The in-domain marks of the faces around a new vertex v of a split constrained edge: the two constrained
  // subsegments at v cut its star into the two old sides; each side is the set of faces reachable, around v
  // without crossing a constrained edge, from a face that has the old side's apex as a vertex. (Deciding a
  // face's side by the orientation of one of its vertices w.r.t. the old geodesic is wrong for a face whose only
  // other vertex is a rounded split point of the same geodesic, a few ulps off it: such faces exist after
  // flip_around, and frame faces marked in the domain made Ruppert runs of issue 12 leak out of the hull.)
  void mark_sides_of_split(Vertex_handle v, Vertex_handle apex_f, bool in_f, Vertex_handle apex_g, bool in_g)
  {
    std::vector<Face_handle> star;
    { auto fc = cdt_.incident_faces(v), done = fc; do { star.push_back(fc); } while(++fc != done); }
    std::unordered_map<Face_handle, int, Handle_hash_function> side; // 1: f's side, 2: g's side
    std::vector<Face_handle> stack;
    for(Face_handle h : star) {
      if(h->has_vertex(apex_f)) { side[h] = 1; stack.push_back(h); }
      else if(h->has_vertex(apex_g)) { side[h] = 2; stack.push_back(h); }
    }
    while(!stack.empty()) {
      const Face_handle h = stack.back(); stack.pop_back();
      const int k = h->index(v);
      for(int j : {CDT::ccw(k), CDT::cw(k)}) { // the two edges of h through v
        if(cdt_.is_constrained(Edge(h, j))) continue;
        const Face_handle n = h->neighbor(j);
        if(side.emplace(n, side[h]).second) stack.push_back(n);
      }
    }
    for(Face_handle h : star) {
      auto it = side.find(h);
      h->set_in_domain(!cdt_.is_infinite(h) && it != side.end() && (it->second == 1 ? in_f : in_g));
    }
  }

  // The split point actually inserted into the constrained edge (f, i) = ab: p (the rounded point of the geodesic
  // ab) or one of the floating-point neighbours of p (up to 2 ulps per coordinate, nearest first), the first one
  // such that (exact predicates)
  // - the four new faces are positively oriented (`insertable_in_edge`);
  // - on a convex-hull edge, it is not strictly inside the hull (the hull would stop being convex at it), and not
  //   so far outside that the hull stops being convex at a or b;
  // - the two new unconstrained edges from it to the opposite vertices x are locally Delaunay.
  // The last condition is the one CGAL's insertion into an edge does not restore: `flip_around` only tests the
  // link edges of the new vertex, because the edges x q are Delaunay when q is exactly on ab. A rounded q is
  // off the geodesic; with a short subsegment and a far apex x, the circle through x, a, q can contain b (the
  // Ruppert outputs that were not Delaunay). False if no candidate qualifies (the segment is then unsplittable).
  bool choose_split_point(const Point& p, Face_handle f, int i, Point& out) const
  {
    const Point &pa = f->vertex(CDT::ccw(i))->point(), &pb = f->vertex(CDT::cw(i))->point();
    const Face_handle g = f->neighbor(i);
    const bool hull = cdt_.is_infinite(f) || cdt_.is_infinite(g);
    Orientation inner = COLLINEAR;
    Point z, w; // the hull neighbours of a (other than b) and of b (other than a)
    if(hull) {
      const Face_handle fin = cdt_.is_infinite(f) ? g : f, inf = cdt_.is_infinite(f) ? f : g;
      const int j = fin == f ? i : cdt_.mirror_index(f, i);
      inner = gt_.orientation_2_object()(pa, pb, fin->vertex(j)->point());
      const Vertex_handle va = f->vertex(CDT::ccw(i)), vb = f->vertex(CDT::cw(i));
      auto other = [&](Vertex_handle across, Vertex_handle keep) { // third vertex of the infinite face beyond `across`
        const Face_handle h = inf->neighbor(inf->index(across));
        for(int k = 0; k < 3; ++k)
          if(!cdt_.is_infinite(h->vertex(k)) && h->vertex(k) != keep) return h->vertex(k)->point();
        return keep->point();
      };
      z = other(vb, va);
      w = other(va, vb);
    }
    const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
    if(!std::isfinite(px) || !std::isfinite(py)) return false;
    auto step = [](double v, int k) {
      for(; k > 0; --k) v = std::nextafter(v, std::numeric_limits<double>::infinity());
      for(; k < 0; ++k) v = std::nextafter(v, -std::numeric_limits<double>::infinity());
      return v;
    };
    static const int offsets[25][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1},
                                       {2, 0}, {-2, 0}, {0, 2}, {0, -2}, {2, 1}, {2, -1}, {-2, 1}, {-2, -1},
                                       {1, 2}, {1, -2}, {-1, 2}, {-1, -2}, {2, 2}, {2, -2}, {-2, 2}, {-2, -2}};
    for(const auto& o : offsets) {
      const Point q = (o[0] == 0 && o[1] == 0) ? p : Point(FT(step(px, o[0])), FT(step(py, o[1])));
      if(q == pa || q == pb) continue;
      // on the hull: not strictly inside, and the hull stays convex at a and b
      if(hull && (gt_.orientation_2_object()(pa, pb, q) == inner ||
                  (z != pb && gt_.orientation_2_object()(z, pa, q) == -inner) ||
                  (w != pa && gt_.orientation_2_object()(q, pb, w) == -inner)))
        continue;
      if(!insertable_in_edge(q, f, i) || !new_edges_are_Delaunay(q, f, i)) continue;
      out = q;
      return true;
    }
    return false;
  }

  // After inserting q into the edge (f, i) = uw, the edge from q to the opposite vertex x of each finite side is
  // locally Delaunay: w is not inside (nor on) the circle through x, u, q (positively oriented), exactly.
  bool new_edges_are_Delaunay(const Point& q, Face_handle f, int i) const
  {
    for(Face_handle g : {f, f->neighbor(i)}) {
      if(cdt_.is_infinite(g)) continue;
      const int j = (g == f) ? i : cdt_.mirror_index(f, i);
      const Point &x = g->vertex(j)->point(), &u = g->vertex(CDT::ccw(j))->point(), &w = g->vertex(CDT::cw(j))->point();
      if(gt_.side_of_oriented_circle_2_object()(x, u, q, w) != ON_NEGATIVE_SIDE) return false;
    }
    return true;
  }

  // Inserting q into edge (f, i) keeps the triangulation valid iff the four new faces are positively oriented
  // (q is rounded: on a very thin face it may fall on the wrong side of an old edge). Exact predicates.
  bool insertable_in_edge(const Point& q, Face_handle f, int i) const
  {
    if(!is_usable(q)) return false;
    for(Face_handle g : {f, f->neighbor(i)}) {
      if(cdt_.is_infinite(g)) continue;
      const int j = (g == f) ? i : cdt_.mirror_index(f, i);
      const Point &x = g->vertex(j)->point(), &u = g->vertex(CDT::ccw(j))->point(), &w = g->vertex(CDT::cw(j))->point();
      if(gt_.orientation_2_object()(x, u, q) != LEFT_TURN || gt_.orientation_2_object()(x, q, w) != LEFT_TURN)
        return false;
    }
    return true;
  }

  template <class Pred>
  void collect_free_near(Vertex_handle start, const Pred& in_region, std::vector<Vertex_handle>& out) const
  {
    std::unordered_set<Vertex_handle, Handle_hash_function> seen;
    std::vector<Vertex_handle> stack(1, start);
    seen.insert(start);
    while(!stack.empty()) {
      Vertex_handle v = stack.back(); stack.pop_back();
      auto vc = cdt_.incident_vertices(v), done = vc;
      do {
        Vertex_handle w = vc;
        if(cdt_.is_infinite(w) || seen.count(w)) continue;
        seen.insert(w);
        if(!in_region(w)) continue;
        if(free_steiner_.count(w)) out.push_back(w);
        stack.push_back(w);
      } while(++vc != done);
    }
  }

  void remove_free_vertex(Vertex_handle x)
  {
    if(!free_steiner_.count(x)) return; // already removed (listed twice) or not a free Steiner vertex
    if(cdt_.are_there_incident_constraints(x)) return;
    std::vector<Vertex_handle> link;
    bool status = true;
    {
      auto fc = cdt_.incident_faces(x), done = fc;
      do { if(!cdt_.is_infinite(fc)) status = fc->is_in_domain(); } while(++fc != done);
      auto vc = cdt_.incident_vertices(x), vdone = vc;
      do { if(!cdt_.is_infinite(vc)) link.push_back(vc); } while(++vc != vdone);
    }
    Face_set old;
    for(Vertex_handle w : link) {
      auto fc = cdt_.incident_faces(w), done = fc;
      do { if(!fc->has_vertex(x)) old.insert(fc); } while(++fc != done);
    }
    free_steiner_.erase(x);
    dead_.insert(x);
    cdt_.remove(x);
    ++st_.removals; ++st_.operations;
    for(Vertex_handle w : link) {
      auto fc = cdt_.incident_faces(w), done = fc;
      do {
        if(cdt_.is_infinite(fc) || old.count(fc)) continue;
        fc->set_in_domain(status);
        consider_face(fc);
      } while(++fc != done);
    }
  }

  // Ruppert: constrained edges still encroached by a vertex (not a frame vertex) at the end
  std::size_t encroached_segments_left() const
  {
    if constexpr(is_Chew) return 0;
    std::size_t n = 0;
    for(auto e = cdt_.finite_edges_begin(); e != cdt_.finite_edges_end(); ++e) {
      if(!cdt_.is_constrained(*e)) continue;
      const Vertex_handle a = e->first->vertex(CDT::ccw(e->second)), b = e->first->vertex(CDT::cw(e->second));
      if(encroaches(a, b, e->first->vertex(e->second)) || encroaches(a, b, cdt_.mirror_vertex(e->first, e->second))) ++n;
    }
    return n;
  }

  bool push_forced(const Edge& e)
  {
    Vertex_handle a = e.first->vertex(CDT::ccw(e.second)), b = e.first->vertex(CDT::cw(e.second));
    if(stuck_.count(key(a, b))) return false;
    forced_.insert(key(a, b));
    encroached_.push_back(std::make_pair(a, b));
    return true;
  }
};

} // namespace internal
} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_EDGES_H
