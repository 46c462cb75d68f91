// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: the driver of the hyperbolic Delaunay refiner shared by the generalized Ruppert (thesis Algorithm 6)
// and generalized Chew (thesis Algorithm 5) algorithms on a Constrained_Delaunay_triangulation_2 with
// Poincare_disk_traits_2: set-up (frame, domain, input, corner lopping, Chew's h*), the main loop over the two
// levels (encroached segments first, then poor faces), the work bound, progress and the final exact check.
// The algorithm is the criteria's compile-time `Refinement_policy` (see Refine_context.h).
// Every decision (poor, encroached, side of a geodesic, in conflict) is an exact predicate of the traits;
// Steiner points are rounded constructions.
#ifndef CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINER_H
#define CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINER_H

#include <CGAL/Hyperbolic_mesh_2/internal/Refine_faces.h>

#include <chrono>
#include <iostream>

namespace CGAL {
namespace Hyperbolic_mesh_2 {
namespace internal {

template <class CDT, class Criteria>
class Refiner : public Refine_faces<CDT, Criteria>
{
  typedef Refine_faces<CDT, Criteria> Base;
  CGAL_HYPERBOLIC_MESH_2_REFINE_FACES_NAMES

public:
  Refiner(CDT& cdt, const Criteria& criteria, const Mesh_parameters<Point>& prm) : Base(cdt, criteria, prm) {}

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
};

} // namespace internal
} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINER_H
