// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: the state shared by the levels of the hyperbolic Delaunay refiner (thesis chapter 3) and the few
// operations every level uses: the queues of poor faces and encroached segments, the bookkeeping after an insertion.
//
// Data: a max-heap of poor faces keyed by (approximate) circumradius, largest first (Chew's order, also used for
// Ruppert); a FIFO of encroached constrained edges (Ruppert); the set of free Steiner vertices (circumcenters,
// removable by Chew); the input segment each segment vertex lies on (for the small-angle rules).
// The levels, as in CGAL's Mesh_2 (Refine_edges, Refine_faces): Refine_context <- Refine_edges (encroachment,
// segment splits, frame, corner lopping) <- Refine_faces (poor faces, circumcenter / off-center insertion) <- Refiner
// (the driver: queues, work bound, statistics). Ruppert and Chew are the compile-time policies
// `Criteria::Refinement_policy` (Ruppert_policy / Chew_policy), chosen by the criteria type.
#ifndef CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_CONTEXT_H
#define CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_CONTEXT_H

#include <CGAL/Hyperbolic_mesh_2/internal/exact_quality.h>
#include <CGAL/Hyperbolic_mesh_2/internal/input_analysis.h>
#include <CGAL/Hyperbolic_mesh_2/mesh_types.h>
#include <CGAL/Hyperbolic_mesh_2/quality_bounds.h>
#include <CGAL/Hyperbolic_mesh_criteria_2.h>
#include <CGAL/Handle_hash_function.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <queue>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

// The names of Refine_context in a derived level (Base = the direct base; dependent base classes hide them).
#define CGAL_HYPERBOLIC_MESH_2_REFINE_CONTEXT_NAMES \
  typedef typename Base::Gt Gt; \
  typedef typename Base::FT FT; \
  typedef typename Base::Point Point; \
  typedef typename Base::Vertex_handle Vertex_handle; \
  typedef typename Base::Face_handle Face_handle; \
  typedef typename Base::Edge Edge; \
  typedef typename Base::Locate_type Locate_type; \
  typedef typename Base::Face_set Face_set; \
  typedef typename Base::Policy Policy; \
  typedef typename Base::Queued_face Queued_face; \
  using Base::is_Chew; \
  using Base::cdt_; \
  using Base::crit_; \
  using Base::prm_; \
  using Base::gt_; \
  using Base::st_; \
  using Base::h_star_; \
  using Base::next_report_; \
  using Base::bad_; \
  using Base::encroached_; \
  using Base::forced_; \
  using Base::free_steiner_; \
  using Base::seg_of_; \
  using Base::input_seg_id_; \
  using Base::input_segs_; \
  using Base::small_angle_pairs_; \
  using Base::apexes_; \
  using Base::lop_radius_; \
  using Base::frame_; \
  using Base::dead_; \
  using Base::stuck_; \
  using Base::fast_faces_; \
  using Base::fast_edges_; \
  using Base::small_angle_tolerance; \
  using Base::key; \
  using Base::consider_face; \
  using Base::encroaches; \
  using Base::check_encroached; \
  using Base::post_insert; \
  using Base::budget_left; \
  using Base::longest_edge; \
  using Base::shortest_edge; \
  using Base::is_usable; \
  using Base::segment_id; \
  using Base::queued;

namespace CGAL {
namespace Hyperbolic_mesh_2 {
namespace internal {

template <class CDT, class Criteria>
class Refine_context
{
protected:
  typedef typename CDT::Geom_traits Gt;
  typedef typename Gt::FT FT;
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Edge Edge;
  typedef typename CDT::Locate_type Locate_type;
  typedef std::unordered_set<Face_handle, Handle_hash_function> Face_set;
  typedef typename Criteria::Refinement_policy Policy;
  static constexpr bool is_Chew = std::is_same<Policy, Chew_policy>::value;

  struct Queued_face
  {
    double key; // approximate cosh^2 of the circumradius: largest first
    Vertex_handle v0, v1, v2;
    bool operator<(const Queued_face& o) const { return key < o.key; }
  };

  Refine_context(CDT& cdt, const Criteria& criteria, const Mesh_parameters<Point>& prm)
    : cdt_(cdt), crit_(criteria), prm_(prm), gt_(cdt.geom_traits())
  {}

  // the queue entry of face f (its vertex triple: f may be destroyed before it is popped)
  Queued_face queued(Face_handle f) const
  {
    return Queued_face{approximate_cosh2_circumradius(f->vertex(0)->point(), f->vertex(1)->point(),
                                                      f->vertex(2)->point()),
                       f->vertex(0), f->vertex(1), f->vertex(2)};
  }

  void consider_face(Face_handle f)
  {
    if(cdt_.is_infinite(f) || !f->is_in_domain()) return;
    if(crit_.badness(f) == Mesh_2::NOT_BAD) return;
    bad_.push(queued(f));
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
      if constexpr(!is_Chew)
        for(int i = 0; i < 3; ++i) check_encroached(fc, i);
    } while(++fc != done);
  }

  // true while the work bound allows `n` more operations after the current one(s)
  bool budget_left(std::size_t n = 0) const { return st_.operations + n < prm_.maximum_number_of_operations(); }

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

  // A constructed point is usable if it is finite and strictly inside the disk.
  static bool is_usable(const Point& p)
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    return std::isfinite(x) && std::isfinite(y) && x * x + y * y < 1.0 - 1e-15;
  }

  int segment_id(Vertex_handle a, Vertex_handle b) const
  {
    auto it = seg_of_.find(a);
    if(it != seg_of_.end()) return it->second;
    it = seg_of_.find(b);
    if(it != seg_of_.end()) return it->second;
    auto jt = input_seg_id_.find(key(a, b));
    return jt == input_seg_id_.end() ? -1 : jt->second;
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

#endif // CGAL_HYPERBOLIC_MESH_2_INTERNAL_REFINE_CONTEXT_H
