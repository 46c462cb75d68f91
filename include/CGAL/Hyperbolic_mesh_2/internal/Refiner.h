// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: the refinement engine shared by the generalized Ruppert (thesis Algorithm 6) and generalized Chew
// (thesis Algorithm 5) algorithms on a Constrained_Delaunay_triangulation_2 with Poincare_disk_traits_2.
//
// Data: a max-heap of poor faces keyed by (approximate) circumradius, largest first (Chew's order, also used for
// Ruppert); a FIFO of encroached constrained edges (Ruppert); the set of free Steiner vertices (circumcenters,
// removable by Chew); the input segment each segment vertex lies on (for the small-angle rules).
// Every decision (poor, encroached, side of a geodesic, in conflict) is an exact predicate of the traits;
// Steiner points are rounded constructions.
#ifndef CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINER_H
#define CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINER_H

#include <CGAL/Hyperbolic_mesh_2/internal/exact_quality.h>
#include <CGAL/Hyperbolic_mesh_2/internal/input_analysis.h>
#include <CGAL/Hyperbolic_mesh_2/mesh_types.h>
#include <CGAL/Hyperbolic_mesh_2/quality_bounds.h>
#include <CGAL/Hyperbolic_mesh_criteria_2.h>
#include <CGAL/Handle_hash_function.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <iostream>
#include <map>
#include <queue>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_mesh_2 {
namespace internal {

template <class CDT, class Criteria,
          bool is_Chew = std::is_same<typename Criteria::Refinement_policy, Chew_policy>::value>
class Refiner
{
  typedef typename CDT::Geom_traits Gt;
  typedef typename Gt::FT FT;
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Edge Edge;
  typedef typename CDT::Locate_type Locate_type;
  typedef std::unordered_set<Face_handle, Handle_hash_function> Face_set;

  struct Queued_face
  {
    double key; // approximate cosh^2 of the circumradius: largest first
    Vertex_handle v0, v1, v2;
    bool operator<(const Queued_face& o) const { return key < o.key; }
  };

public:
  Refiner(CDT& cdt, const Criteria& criteria, const Mesh_parameters<Point>& prm)
    : cdt_(cdt), crit_(criteria), prm_(prm), gt_(cdt.geom_traits())
  {}

  Mesh_statistics run()
  {
    const auto t0 = std::chrono::steady_clock::now();
    if(cdt_.dimension() != 2)
      throw Pslg_error("the triangulation must have dimension 2 (at least 3 points not on one geodesic)");
    for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
      check_point_in_open_disk(v->point(), "a vertex of the triangulation");
    st_.initial_vertices = cdt_.number_of_vertices();

    constrain_hull_if_no_constraint(cdt_);
    add_frame_if_needed();
    mark_domain(cdt_, prm_.seeds(), prm_.seeds_are_in_domain());
    collect_input();
    if(prm_.corner_lopping()) lop_corners();
    compute_h_star();
    set_termination_report();

    // initial queues
    for(auto e = cdt_.finite_edges_begin(); e != cdt_.finite_edges_end(); ++e)
      if(!is_Chew) check_encroached(e->first, e->second);
    for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) consider_face(f);

    st_.status = refine();
    finish_statistics();
    if(st_.status == Refinement_status::SUCCESS && (st_.faces_failing_criteria > 0 || encroached_segments_left() > 0))
      st_.status = Refinement_status::UNREFINED_FACES_LEFT;
    st_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if(prm_.verbose()) std::cerr << "[Hyperbolic_mesh_2] " << crit_.description() << ": " << st_ << std::endl;
    return st_;
  }

private:
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

  // Chew's h*: min of (1) the smallest distance between non-incident input features (vertex-vertex over the CDT
  // edges, where the closest pair of vertices always is; vertex-segment over all pairs, a lower bound of the
  // line-of-sight distance), (2) half the shortest input segment, (3) epsilon.
  void compute_h_star()
  {
    double h = crit_.has_size_bound() ? crit_.epsilon() : std::numeric_limits<double>::infinity();
    double h_feat = std::numeric_limits<double>::infinity(); // distances between non-incident features only
    std::vector<std::pair<Vertex_handle, Vertex_handle> > segs;
    for(auto e = cdt_.finite_edges_begin(); e != cdt_.finite_edges_end(); ++e) {
      Vertex_handle a = e->first->vertex(CDT::ccw(e->second)), b = e->first->vertex(CDT::cw(e->second));
      if(frame_.count(a) || frame_.count(b)) continue;
      const double d = approximate_distance(a->point(), b->point());
      if(cdt_.is_constrained(*e)) { segs.push_back(std::make_pair(a, b)); h = std::min(h, d / 2); }
      else h_feat = std::min(h_feat, d);
    }
    const std::size_t n = cdt_.number_of_vertices();
    if(double(n) * double(segs.size()) <= 2e7) {
      for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
        if(!frame_.count(v))
        for(const auto& s : segs)
          if(Vertex_handle(v) != s.first && Vertex_handle(v) != s.second)
            h_feat = std::min(h_feat, point_segment_distance(v->point(), s.first->point(), s.second->point()));
    } else {
      // large inputs: segments of the faces around each vertex only (documented approximation)
      for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v) {
        if(frame_.count(v)) continue;
        auto fc = cdt_.incident_faces(v), done = fc;
        do {
          if(cdt_.is_infinite(fc)) continue;
          const int i = fc->index(v);
          if(cdt_.is_constrained(Edge(fc, i)))
            h_feat = std::min(h_feat, point_segment_distance(v->point(), fc->vertex(CDT::ccw(i))->point(),
                                                             fc->vertex(CDT::cw(i))->point()));
        } while(++fc != done);
      }
    }
    h_star_ = std::min(h, h_feat);
    if constexpr(is_Chew) st_.h_star = h_star_;
  }

  void set_termination_report()
  {
    if constexpr(is_Chew) {
      st_.termination_margin = Chew_termination_bound - h_star_;
      st_.termination_guaranteed = h_star_ < Chew_termination_bound && st_.small_input_angles == 0;
      st_.termination_note = "Theorem 3.1: h* = " + std::to_string(h_star_) +
                             (h_star_ < Chew_termination_bound ? " < 2.3101" : " >= 2.3101: no guarantee");
    } else {
      st_.termination_margin = crit_.termination_margin();
      st_.termination_guaranteed = crit_.termination_guaranteed() && st_.small_input_angles == 0;
      st_.termination_note = "Theorem 3.2: 1 - rho(eps, alpha) rho(eps, pi/2) = " +
                             std::to_string(st_.termination_margin) +
                             (st_.termination_margin > 0 ? " > 0" : " <= 0: no guarantee");
    }
    if(st_.small_input_angles > 0)
      st_.termination_note += "; " + std::to_string(st_.small_input_angles) +
                              " input angle(s) < pi/2 (corner lopping " +
                              (prm_.corner_lopping() ? "on" : "off") + ", outside the theorem's hypothesis)";
  }

  // ------------------------------------------------------------------ queues
  void consider_face(Face_handle f)
  {
    if(cdt_.is_infinite(f) || !f->is_in_domain()) return;
    if(crit_.badness(f) == Mesh_2::NOT_BAD) return;
    bad_.push(Queued_face{approximate_cosh2_circumradius(f->vertex(0)->point(), f->vertex(1)->point(),
                                                         f->vertex(2)->point()),
                          f->vertex(0), f->vertex(1), f->vertex(2)});
  }

  bool encroaches(Vertex_handle a, Vertex_handle b, Vertex_handle x) const
  {
    if(cdt_.is_infinite(x) || frame_.count(x)) return false;
    return gt_.side_of_hyperbolic_diametral_circle_2_object()(a->point(), b->point(), x->point()) == ON_BOUNDED_SIDE;
  }

  void check_encroached(Face_handle f, int i)
  {
    if(!cdt_.is_constrained(Edge(f, i))) return;
    Vertex_handle a = f->vertex(CDT::ccw(i)), b = f->vertex(CDT::cw(i));
    if(cdt_.is_infinite(a) || cdt_.is_infinite(b)) return;
    if(encroaches(a, b, f->vertex(i)) || encroaches(a, b, cdt_.mirror_vertex(f, i)))
      encroached_.push_back(std::make_pair(a, b));
  }

  void post_insert(Vertex_handle v)
  {
#ifdef CGAL_HYPERBOLIC_MESH_2_DEBUG_VALIDITY
    if(!cdt_.is_valid()) throw std::logic_error("invalid after inserting " + std::to_string(CGAL::to_double(v->point().x())) +
                                                " " + std::to_string(CGAL::to_double(v->point().y())) +
                                                (seg_of_.count(v) ? " on a segment" : " in a face") + " nearest " +
                                                [&] { double m = 1e300; auto vc = cdt_.incident_vertices(v), d = vc;
                                                      do { if(!cdt_.is_infinite(vc)) m = std::min(m, std::sqrt(CGAL::to_double(CGAL::squared_distance(v->point(), vc->point())))); } while(++vc != d);
                                                      return std::to_string(m); }());
#endif
    auto fc = cdt_.incident_faces(v), done = fc;
    do {
      if(cdt_.is_infinite(fc)) continue;
      consider_face(fc);
      if(!is_Chew)
        for(int i = 0; i < 3; ++i) check_encroached(fc, i);
    } while(++fc != done);
  }

  // ------------------------------------------------------------------ main loop
  Refinement_status refine()
  {
    std::size_t iterations = 0;
    while(true) {
      if(st_.operations >= prm_.maximum_number_of_operations()) return Refinement_status::WORK_BOUND_REACHED;
      // every iteration either inserts/removes a vertex or discards a queue entry; this guard bounds the
      // (never observed) case of entries that are re-queued without progress
      if(++iterations > 8 * prm_.maximum_number_of_operations() + 100000) return Refinement_status::WORK_BOUND_REACHED;
      if(st_.operations >= next_report_) {
        next_report_ = st_.operations + 4096;
        if(!report()) return Refinement_status::CANCELLED;
      }
      if(!encroached_.empty()) {
        const std::pair<Vertex_handle, Vertex_handle> s = encroached_.front();
        encroached_.pop_front();
        Face_handle f; int i;
        if(!cdt_.is_edge(s.first, s.second, f, i) || !cdt_.is_constrained(Edge(f, i))) continue;
        if(!encroaches(s.first, s.second, f->vertex(i)) && !encroaches(s.first, s.second, cdt_.mirror_vertex(f, i)) &&
           !forced_.count(key(s.first, s.second)))
          continue; // no longer encroached
        forced_.erase(key(s.first, s.second));
        // constructions come before any change of the triangulation: a rounded point that leaves the disk
        // (segments near the circle at infinity) only makes this segment unsplittable
        try { split_encroached_segment(s.first, s.second); }
        catch(const Poincare_disk_domain_error&) { stuck_.insert(key(s.first, s.second)); ++st_.unsplittable_segments; }
        continue;
      }
      if(bad_.empty()) return Refinement_status::SUCCESS;
      const Queued_face q = bad_.top();
      bad_.pop();
      Face_handle f;
      if(!dead_.empty() && (dead_.count(q.v0) || dead_.count(q.v1) || dead_.count(q.v2))) continue; // removed
      if(!cdt_.is_face(q.v0, q.v1, q.v2, f) || !f->is_in_domain()) continue;
      const Mesh_2::Face_badness b = crit_.badness(f);
      if(b == Mesh_2::NOT_BAD) continue;
      if(b == Mesh_2::BAD && is_protected(f)) continue; // thesis Fig. 3.6: left to the lopped corner
      try { refine_face(f, b); }
      catch(const Poincare_disk_domain_error&) { ++st_.unrefinable_faces; } // a constructed point left the disk
    }
  }

  // true while the work bound allows `n` more operations after the current one(s)
  bool budget_left(std::size_t n = 0) const { return st_.operations + n < prm_.maximum_number_of_operations(); }

  bool report()
  {
    Progress p;
    p.operations = st_.operations;
    p.number_of_vertices = cdt_.number_of_vertices();
    p.bad_faces_queued = bad_.size();
    p.encroached_segments_queued = encroached_.size();
    if(prm_.verbose())
      std::cerr << "[Hyperbolic_mesh_2] operations " << p.operations << ", vertices " << p.number_of_vertices
                << ", queued faces " << p.bad_faces_queued << std::endl;
    if(prm_.callback()) return prm_.callback()(p);
    return true;
  }

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

  int longest_edge(Face_handle f) const
  {
    int best = 0; double d = -1;
    for(int i = 0; i < 3; ++i) {
      const double di = approximate_sinh2_half_distance(f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point());
      if(di > d) { d = di; best = i; }
    }
    return best;
  }
  int shortest_edge(Face_handle f) const
  {
    int best = 0; double d = std::numeric_limits<double>::infinity();
    for(int i = 0; i < 3; ++i) {
      const double di = approximate_sinh2_half_distance(f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point());
      if(di < d) { d = di; best = i; }
    }
    return best;
  }

  // Ungor's off-center, hyperbolic version: on the bisector of the shortest edge pq (through its midpoint m and
  // the circumcenter c), the apex c' of the triangle p q c' whose shortest-edge central angle is exactly alpha:
  // its circumcenter o' is at distance R from p and q, sinh R = sinh(d/2) / sin(alpha/2), at distance t from m,
  // cosh R = cosh(d/2) cosh t, and c' is at distance t + R from m. Used when closer to m than c.
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
        if(is_Chew) continue; // Chew only rejects circumcenters beyond a segment; c is inside the zone here
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
    if(is_Chew) {
      if(!beyond.empty()) {
        Edge s = beyond.front();
        for(const Edge& e : beyond)
          if(std::find(diametral.begin(), diametral.end(), e) != diametral.end()) { s = e; break; }
        ++st_.rejected_circumcenters;
        Vertex_handle a = s.first->vertex(CDT::ccw(s.second)), b = s.first->vertex(CDT::cw(s.second));
        requeue_after(f, [&] { return split_encroached_segment(a, b); });
        return;
      }
    } else if(!diametral.empty() || !beyond.empty()) {
      if(is_off_center) {
        // an off-center that encroaches: fall back to the circumcenter (Ungor's rule), which then decides
        const Point& p0 = f->vertex(0)->point(); const Point& p1 = f->vertex(1)->point();
        const Point& p2 = f->vertex(2)->point();
        insert_steiner(f, gt_.construct_hyperbolic_circumcenter_2_object()(p0, p1, p2), false);
        return;
      }
      bool any = false;
      for(const Edge& e : diametral) any = push_forced(e) || any;
      for(const Edge& e : beyond) any = push_forced(e) || any;
      if(!any) { ++st_.unrefinable_faces; return; } // only unsplittable segments: give up on f
      ++st_.rejected_circumcenters;
      consider_face(f); // re-queued: it is refined again once the segments are split
      return;
    }
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

  bool push_forced(const Edge& e)
  {
    Vertex_handle a = e.first->vertex(CDT::ccw(e.second)), b = e.first->vertex(CDT::cw(e.second));
    if(stuck_.count(key(a, b))) return false;
    forced_.insert(key(a, b));
    encroached_.push_back(std::make_pair(a, b));
    return true;
  }

  // ------------------------------------------------------------------ segment splits
  bool split_encroached_segment(Vertex_handle a, Vertex_handle b)
  {
    const Point &pa = a->point(), &pb = b->point();
    if(!is_Chew) {
      Vertex_handle v = split_segment(a, b, gt_.construct_hyperbolic_midpoint_2_object()(pa, pb));
      if(v == Vertex_handle()) return false;
      ++st_.midpoint_splits; ++st_.operations;
      post_insert(v);
      return true;
    }
    const double L = approximate_distance(pa, pb);
    const Point a_pt = pa, b_pt = pb;
    if(L >= 2 * rho(h_star_) * h_star_ && L <= 4 * h_star_) {
      // one-third split
      const Point p1 = gt_.construct_hyperbolic_point_on_segment_2_object()(a_pt, b_pt, FT(1.0 / 3));
      const Point p2 = gt_.construct_hyperbolic_point_on_segment_2_object()(a_pt, b_pt, FT(2.0 / 3));
      Vertex_handle v1 = split_segment(a, b, p1);
      if(v1 == Vertex_handle()) return false;
      Vertex_handle v2 = budget_left(1) ? split_segment(v1, b, p2) : Vertex_handle();
      ++st_.one_third_splits; st_.operations += (v2 == Vertex_handle() ? 1 : 2);
      const double r = L / 3;
      std::vector<Vertex_handle> doomed;
      collect_free_near(v1, [&](Vertex_handle x) { return approximate_distance(x->point(), v1->point()) < r; }, doomed);
      if(v2 != Vertex_handle())
        collect_free_near(v2, [&](Vertex_handle x) { return approximate_distance(x->point(), v2->point()) < r; },
                          doomed);
      for(Vertex_handle x : doomed) if(budget_left()) remove_free_vertex(x); // the run ends at the bound
      post_insert(v1);
      if(v2 != Vertex_handle()) post_insert(v2);
      return true;
    } else {
      Vertex_handle v = split_segment(a, b, gt_.construct_hyperbolic_midpoint_2_object()(a_pt, b_pt));
      if(v == Vertex_handle()) return false;
      ++st_.midpoint_splits; ++st_.operations;
      std::vector<Vertex_handle> doomed;
      collect_free_near(v, [&](Vertex_handle x) {
        return gt_.side_of_hyperbolic_diametral_circle_2_object()(a_pt, b_pt, x->point()) == ON_BOUNDED_SIDE;
      }, doomed);
      for(Vertex_handle x : doomed) if(budget_left()) remove_free_vertex(x); // the run ends at the bound
      post_insert(v);
      return true;
    }
  }

  // Inserts p (a rounded point of the geodesic ab) into the constrained edge ab; sets the in-domain marks of the
  // new faces from the two old sides. Returns the new vertex (null if ab is not a constrained edge).
  Vertex_handle split_segment(Vertex_handle a, Vertex_handle b, const Point& p)
  {
    Face_handle f; int i;
    if(!cdt_.is_edge(a, b, f, i) || !cdt_.is_constrained(Edge(f, i))) return Vertex_handle();
    Face_handle g = f->neighbor(i);
    const bool in_f = !cdt_.is_infinite(f) && f->is_in_domain(), in_g = !cdt_.is_infinite(g) && g->is_in_domain();
    const Point pa = a->point(), pb = b->point();
    // orientation of f's side w.r.t. the oriented geodesic ab
    Orientation side_f;
    if(!cdt_.is_infinite(f->vertex(i))) side_f = gt_.orientation_2_object()(pa, pb, f->vertex(i)->point());
    else side_f = Orientation(-int(gt_.orientation_2_object()(pa, pb, cdt_.mirror_vertex(f, i)->point())));
    if(stuck_.count(key(a, b))) return Vertex_handle();
    const int seg = segment_id(a, b);
    // Resolution guard: a subsegment with a Euclidean length below 1e-11 is not split (its rounded split points
    // are a few ulps from its endpoints).
    const double ex = CGAL::to_double(pa.x()) - CGAL::to_double(pb.x()), ey = CGAL::to_double(pa.y()) - CGAL::to_double(pb.y());
    Point q;
    if(ex * ex + ey * ey < 1e-22 || !choose_split_point(p, f, i, q)) {
      stuck_.insert(key(a, b)); ++st_.unsplittable_segments; return Vertex_handle();
    }
    Vertex_handle v = cdt_.insert(q, CDT::EDGE, f, i);
    dead_.erase(v);
    auto fc = cdt_.incident_faces(v), done = fc;
    do {
      if(cdt_.is_infinite(fc)) { fc->set_in_domain(false); continue; }
      bool set = false;
      for(int k = 0; k < 3 && !set; ++k) {
        Vertex_handle x = fc->vertex(k);
        if(x == v || x == a || x == b) continue;
        const Orientation o = gt_.orientation_2_object()(pa, pb, x->point());
        if(o == COLLINEAR) continue;
        fc->set_in_domain(o == side_f ? in_f : in_g);
        set = true;
      }
      if(!set) fc->set_in_domain(false);
    } while(++fc != done);
    if(seg >= 0) seg_of_[v] = seg;
    return v;
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

  // A constructed point is usable if it is finite and strictly inside the disk.
  static bool is_usable(const Point& p)
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    return std::isfinite(x) && std::isfinite(y) && x * x + y * y < 1.0 - 1e-15;
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

  // ------------------------------------------------------------------ small angles
  int segment_id(Vertex_handle a, Vertex_handle b) const
  {
    auto it = seg_of_.find(a);
    if(it != seg_of_.end()) return it->second;
    it = seg_of_.find(b);
    if(it != seg_of_.end()) return it->second;
    auto jt = input_seg_id_.find(key(a, b));
    return jt == input_seg_id_.end() ? -1 : jt->second;
  }

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

  // ------------------------------------------------------------------ statistics
  void finish_statistics()
  {
    st_.final_vertices = cdt_.number_of_vertices();
    double amin = std::numeric_limits<double>::infinity(), amin_u = amin, rmax = 0;
    for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      ++st_.in_domain_faces;
      const Point &p = f->vertex(0)->point(), &q = f->vertex(1)->point(), &r = f->vertex(2)->point();
      const double a = approximate_central_angle(p, q, r);
      amin = std::min(amin, a);
      const Mesh_2::Face_badness b = crit_.badness(f);
      const bool prot = b == Mesh_2::BAD && is_protected(f);
      if(prot) ++st_.protected_faces; else amin_u = std::min(amin_u, a);
      if(b != Mesh_2::NOT_BAD && !prot) ++st_.faces_failing_criteria;
      rmax = std::max(rmax, approximate_circumradius(p, q, r));
    }
    st_.minimum_central_angle = std::isfinite(amin) ? amin : 0;
    st_.minimum_central_angle_unprotected = std::isfinite(amin_u) ? amin_u : 0;
    st_.maximum_circumradius = rmax;
    Progress p; p.operations = st_.operations; p.number_of_vertices = cdt_.number_of_vertices();
    if(prm_.callback()) prm_.callback()(p);
  }

  // Ruppert: constrained edges still encroached by a vertex (not a frame vertex) at the end
  std::size_t encroached_segments_left() const
  {
    if(is_Chew) return 0;
    std::size_t n = 0;
    for(auto e = cdt_.finite_edges_begin(); e != cdt_.finite_edges_end(); ++e) {
      if(!cdt_.is_constrained(*e)) continue;
      const Vertex_handle a = e->first->vertex(CDT::ccw(e->second)), b = e->first->vertex(CDT::cw(e->second));
      if(encroaches(a, b, e->first->vertex(e->second)) || encroaches(a, b, cdt_.mirror_vertex(e->first, e->second))) ++n;
    }
    return n;
  }

  // Angles within this much of pi/2 are not lopped: the angle sum defect of a tiny input (Euclidean limit) makes
  // right angles slightly acute, and Ruppert's analysis is not sharp there.
  static constexpr double small_angle_tolerance = 1e-4;

  static std::pair<Vertex_handle, Vertex_handle> key(Vertex_handle a, Vertex_handle b)
  { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

  CDT& cdt_;
  const Criteria& crit_;
  const Mesh_parameters<Point>& prm_;
  Gt gt_;
  Mesh_statistics st_;
  double h_star_ = 0;
  std::size_t next_report_ = 4096;

  std::priority_queue<Queued_face> bad_;
  std::deque<std::pair<Vertex_handle, Vertex_handle> > encroached_;
  std::set<std::pair<Vertex_handle, Vertex_handle> > forced_; // split even if no vertex encroaches (circumcenter did)
  std::unordered_set<Vertex_handle, Handle_hash_function> free_steiner_;
  std::unordered_map<Vertex_handle, int, Handle_hash_function> seg_of_;
  std::map<std::pair<Vertex_handle, Vertex_handle>, int> input_seg_id_;
  std::vector<std::pair<Vertex_handle, Vertex_handle> > input_segs_;
  std::set<std::pair<int, int> > small_angle_pairs_;
  std::set<Vertex_handle> apexes_;
  std::map<Vertex_handle, double> lop_radius_;
  std::unordered_set<Vertex_handle, Handle_hash_function> frame_;
  std::unordered_set<Vertex_handle, Handle_hash_function> dead_; // removed vertices (queued handles may name them)
  std::set<std::pair<Vertex_handle, Vertex_handle> > stuck_;       // segments whose split point is unusable
  std::vector<Face_handle> fast_faces_;                             // scratch of try_insert_steiner_fast
  std::vector<Edge> fast_edges_;
};

} // namespace internal
} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINER_H
