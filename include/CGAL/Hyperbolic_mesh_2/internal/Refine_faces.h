// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: the face level of the hyperbolic Delaunay refiner (as Refine_faces in CGAL's Mesh_2): the Steiner point
// of a poor face (hyperbolic circumcenter, Ungor's off-center, or the midpoint of the longest edge when the
// circumcircle is not compact), its conflict zone and the policy's rule for Steiner points that encroach or lie
// beyond a constrained edge (Ruppert: rejected, the edges are split; Chew: the edge beyond is split), and the
// protected faces at small input angles.
#ifndef CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_FACES_H
#define CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_FACES_H

#include <CGAL/Hyperbolic_mesh_2/internal/Refine_edges.h>

#include <iterator>

// The names of Refine_faces (and of the levels below) in a derived level.
#define CGAL_HYPERBOLIC_MESH_2_REFINE_FACES_NAMES \
  CGAL_HYPERBOLIC_MESH_2_REFINE_EDGES_NAMES \
  using Base::refine_face; \
  using Base::off_center; \
  using Base::conflict_zone; \
  using Base::try_insert_steiner_fast; \
  using Base::after_steiner_insertion; \
  using Base::insert_steiner; \
  using Base::requeue_after; \
  using Base::is_protected; \
  using Base::reject_steiner;

namespace CGAL {
namespace Hyperbolic_mesh_2 {
namespace internal {

template <class CDT, class Criteria>
class Refine_faces : public Refine_edges<CDT, Criteria>
{
protected:
  typedef Refine_edges<CDT, Criteria> Base;
  CGAL_HYPERBOLIC_MESH_2_REFINE_EDGES_NAMES

  Refine_faces(CDT& cdt, const Criteria& criteria, const Mesh_parameters<Point>& prm) : Base(cdt, criteria, prm) {}

  // The Steiner point of a poor face: its hyperbolic circumcenter (or, for Ruppert with off-centers and a skinny
  // face, Ungor's off-center if closer to the shortest edge); the midpoint of the longest edge if the circumcircle
  // is not compact (no hyperbolic circumcenter exists).
  void refine_face(Face_handle f, Mesh_2::Face_badness badness)
  {
    const Point &p0 = f->vertex(0)->point(), &p1 = f->vertex(1)->point(), &p2 = f->vertex(2)->point();
    if(!gt_.is_Delaunay_hyperbolic_2_object()(p0, p1, p2)) {
      int i = longest_edge(f);
      Edge e(f, i);
      Vertex_handle a = f->vertex(CDT::ccw(i)), b = f->vertex(CDT::cw(i));
      if(cdt_.is_constrained(e)) { requeue_after(f, [&] { return split_encroached_segment(a, b); }); return; }
      insert_steiner(f, gt_.construct_hyperbolic_midpoint_2_object()(a->point(), b->point()), false);
      return;
    }
    Point c = gt_.construct_hyperbolic_circumcenter_2_object()(p0, p1, p2);
    bool off = false;
    if constexpr(!is_Chew) {
      if(prm_.off_centers() && (badness == Mesh_2::BAD || crit_.is_skinny(p0, p1, p2)))
        off = off_center(f, c);
    }
    insert_steiner(f, c, off);
  }

  // Ungor's off-center, hyperbolic version: on the bisector of the shortest edge pq (through its midpoint m and
  // the circumcenter c), the apex c' of the triangle p q c' whose shortest-edge central angle is exactly alpha:
  // its circumcenter o' is at distance R from p and q, sinh R = sinh(d/2) / sin(alpha/2), at distance t from m,
  // cosh R = cosh(d/2) cosh t, and c' is at distance t + R from m. Used when closer to m than c.
  template <class P = Policy> // Ruppert_policy only (needs sin2_half_alpha)
  bool off_center(Face_handle f, Point& c) const
  {
    const int i = shortest_edge(f);
    const Point &p = f->vertex(CDT::ccw(i))->point(), &q = f->vertex(CDT::cw(i))->point();
    const double d = approximate_distance(p, q);
    const double sh = std::sinh(d / 2) / std::sqrt(crit_.sin2_half_alpha());
    const double R = std::asinh(sh);
    const double ratio = std::cosh(R) / std::cosh(d / 2);
    if(!std::isfinite(ratio) || !std::isfinite(R)) return false;
    const double t = std::acosh(std::max(1.0, ratio));
    const Point m = gt_.construct_hyperbolic_midpoint_2_object()(p, q);
    const double dmc = approximate_distance(m, c);
    if(!(t + R < dmc) || !(dmc > 0)) return false;
    c = gt_.construct_hyperbolic_point_on_segment_2_object()(m, c, FT((t + R) / dmc));
    return true;
  }

  // Conflict zone of c grown from the poor face f (across unconstrained edges only), and its boundary edges.
  void conflict_zone(Face_handle f, const Point& c, std::vector<Face_handle>& zone, Face_set& in_zone,
                     std::vector<Edge>& boundary) const
  {
    zone.push_back(f); in_zone.insert(f);
    for(std::size_t k = 0; k < zone.size(); ++k) {
      Face_handle g = zone[k];
      for(int i = 0; i < 3; ++i) {
        Face_handle n = g->neighbor(i);
        if(in_zone.count(n)) continue;
        if(cdt_.is_constrained(Edge(g, i)) || !cdt_.test_conflict(c, n)) { boundary.push_back(Edge(g, i)); continue; }
        zone.push_back(n); in_zone.insert(n);
      }
    }
  }

  // Fast path (the common case, as in Mesh_2): locate c from f, take CGAL's conflict zone of c (ordered
  // boundary), and if f is in it (c visible from f), c is in the domain and c encroaches no constrained edge of
  // the zone boundary, insert c with star_hole() on that zone (no second conflict computation). Returns false
  // when the general path below must decide.
  bool try_insert_steiner_fast(Face_handle f, const Point& c, bool is_off_center)
  {
    Locate_type lt; int li;
    Face_handle loc = cdt_.locate(c, lt, li, f);
    if(lt != CDT::FACE || cdt_.is_infinite(loc) || !loc->is_in_domain()) return false;
    fast_faces_.clear(); fast_edges_.clear();
    cdt_.get_conflicts_and_boundary(c, std::back_inserter(fast_faces_), std::back_inserter(fast_edges_), loc);
    if(std::find(fast_faces_.begin(), fast_faces_.end(), f) == fast_faces_.end()) return false;
    for(const Edge& e : fast_edges_) {
      if(!cdt_.is_constrained(e)) continue;
      const Point &a = e.first->vertex(CDT::ccw(e.second))->point(), &b = e.first->vertex(CDT::cw(e.second))->point();
      if(gt_.side_of_hyperbolic_diametral_circle_2_object()(a, b, c) != ON_UNBOUNDED_SIDE) {
        if constexpr(is_Chew) continue; // Chew only rejects circumcenters beyond a segment; c is inside the zone here
        return false;
      }
    }
    after_steiner_insertion(
        cdt_.star_hole(c, fast_edges_.begin(), fast_edges_.end(), fast_faces_.begin(), fast_faces_.end()),
        is_off_center);
    return true;
  }

  // bookkeeping after a circumcenter / off-center v was inserted in the domain
  void after_steiner_insertion(Vertex_handle v, bool is_off_center)
  {
    dead_.erase(v); // its memory may be a removed vertex's: queue entries naming it are alive (and re-checked)
    ++st_.operations; ++st_.circumcenters_inserted;
    if(is_off_center) ++st_.off_centers_inserted;
    auto fc = cdt_.incident_faces(v), done = fc;
    do { fc->set_in_domain(true); } while(++fc != done);
    free_steiner_.insert(v);
    post_insert(v);
  }

  // The Steiner point c of the poor face f: inserted if it lies in the conflict zone grown from f and the policy
  // accepts it; otherwise the policy splits constrained edges (or f is counted as unrefinable).
  void insert_steiner(Face_handle f, const Point& c, bool is_off_center)
  {
    if(!is_usable(c)) { ++st_.unrefinable_faces; return; }
    if(try_insert_steiner_fast(f, c, is_off_center)) return;
    std::vector<Face_handle> zone; Face_set in_zone; std::vector<Edge> boundary;
    conflict_zone(f, c, zone, in_zone, boundary);
    // constrained boundary edges that c encroaches (Ruppert: diametral disk) or lies beyond (Chew: Lemma 3.5)
    std::vector<Edge> diametral, beyond;
    for(const Edge& e : boundary) {
      if(!cdt_.is_constrained(e)) continue;
      Face_handle g = e.first; const int i = e.second;
      Vertex_handle a = g->vertex(CDT::ccw(i)), b = g->vertex(CDT::cw(i));
      const Orientation oc = gt_.orientation_2_object()(a->point(), b->point(), c);
      const Orientation og = gt_.orientation_2_object()(a->point(), b->point(), g->vertex(i)->point());
      const bool in_disk = gt_.side_of_hyperbolic_diametral_circle_2_object()(a->point(), b->point(), c) != ON_UNBOUNDED_SIDE;
      if(oc != og) beyond.push_back(e);
      if(in_disk) diametral.push_back(e);
    }
    if(reject_steiner(f, is_off_center, diametral, beyond, Policy())) return;
    Locate_type lt; int li;
    Face_handle loc = cdt_.locate(c, lt, li, f);
    bool inside = false;
    if(lt == CDT::FACE) inside = in_zone.count(loc) > 0;
    else if(lt == CDT::EDGE) {
      if(cdt_.is_constrained(Edge(loc, li))) {
        ++st_.rejected_circumcenters;
        Vertex_handle a = loc->vertex(CDT::ccw(li)), b = loc->vertex(CDT::cw(li));
        requeue_after(f, [&] { return split_encroached_segment(a, b); });
        return;
      }
      inside = in_zone.count(loc) > 0 || in_zone.count(loc->neighbor(li)) > 0;
    }
    if(!inside) { ++st_.unrefinable_faces; return; } // on a vertex, or not visible after rounding
    after_steiner_insertion(cdt_.insert(c, lt, loc, li), is_off_center);
  }

  // Chew (Algorithm 5): a circumcenter beyond a constrained edge of its zone (Lemma 3.5) is not inserted; that
  // edge (preferably one it also encroaches) is split. True if c is not to be inserted.
  bool reject_steiner(Face_handle f, bool, const std::vector<Edge>& diametral, const std::vector<Edge>& beyond,
                      Chew_policy)
  {
    if(beyond.empty()) return false;
    Edge s = beyond.front();
    for(const Edge& e : beyond)
      if(std::find(diametral.begin(), diametral.end(), e) != diametral.end()) { s = e; break; }
    ++st_.rejected_circumcenters;
    Vertex_handle a = s.first->vertex(CDT::ccw(s.second)), b = s.first->vertex(CDT::cw(s.second));
    requeue_after(f, [&] { return split_encroached_segment(a, b); });
    return true;
  }

  // Ruppert (Algorithm 6): a Steiner point that encroaches a constrained edge of its zone or lies beyond it is
  // rejected; those edges are queued for splitting and f again. An encroaching off-center falls back to the
  // circumcenter (Ungor's rule), which then decides.
  bool reject_steiner(Face_handle f, bool is_off_center, const std::vector<Edge>& diametral,
                      const std::vector<Edge>& beyond, Ruppert_policy)
  {
    if(diametral.empty() && beyond.empty()) return false;
    if(is_off_center) {
      const Point &p0 = f->vertex(0)->point(), &p1 = f->vertex(1)->point(), &p2 = f->vertex(2)->point();
      insert_steiner(f, gt_.construct_hyperbolic_circumcenter_2_object()(p0, p1, p2), false);
      return true;
    }
    bool any = false;
    for(const Edge& e : diametral) any = push_forced(e) || any;
    for(const Edge& e : beyond) any = push_forced(e) || any;
    if(!any) { ++st_.unrefinable_faces; return true; } // only unsplittable segments: give up on f
    ++st_.rejected_circumcenters;
    consider_face(f); // re-queued: it is refined again once the segments are split
    return true;
  }


  // runs `split` (which may destroy f) and queues f's vertex triple again: f is re-examined if it survived
  template <class F>
  void requeue_after(Face_handle f, const F& split)
  {
    const Queued_face q{approximate_cosh2_circumradius(f->vertex(0)->point(), f->vertex(1)->point(),
                                                       f->vertex(2)->point()),
                        f->vertex(0), f->vertex(1), f->vertex(2)};
    if(split()) bad_.push(q);
    else ++st_.unrefinable_faces; // the segment cannot be split (see split_segment): give up on f
  }

  // ------------------------------------------------------------------ small angles
  // A poor face whose shortest edge joins two segments meeting at a small input angle is left alone: it lies in
  // the lopped corner (Fig. 3.6), where no Delaunay refinement can reach the angle bound.
  bool is_protected(Face_handle f) const
  {
    if(small_angle_pairs_.empty()) return false;
    const int i = shortest_edge(f);
    Vertex_handle u = f->vertex(CDT::ccw(i)), w = f->vertex(CDT::cw(i));
    auto iu = seg_of_.find(u), iw = seg_of_.find(w);
    int su = iu == seg_of_.end() ? -1 : iu->second, sw = iw == seg_of_.end() ? -1 : iw->second;
    // an apex itself: the edge lies along one of its segments, not across the corner
    if(su < 0 || sw < 0 || su == sw) return false;
    if(small_angle_pairs_.count(std::minmax(su, sw)) == 0) return false;
    // only inside the lopping circle C of the common apex (the surgery region of Fig. 3.6)
    const auto &s1 = input_segs_[std::size_t(su)], &s2 = input_segs_[std::size_t(sw)];
    const Vertex_handle o = (s1.first == s2.first || s1.first == s2.second) ? s1.first : s1.second;
    auto it = lop_radius_.find(o);
    if(it == lop_radius_.end()) return !prm_.corner_lopping();
    const double lim = it->second * (1 + 1e-6);
    return approximate_distance(o->point(), u->point()) <= lim && approximate_distance(o->point(), w->point()) <= lim;
  }
};

} // namespace internal
} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_FACES_H
