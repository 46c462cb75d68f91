// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Delaunay refinement on a closed hyperbolic surface: the generalized Ruppert and Chew criteria of the thesis
// (chapter 3), circumcentres located by walking across the transitions, largest circumradius first, constrained
// edges (feature loops) split at midpoints when encroached, then refinement until the triangulation is a
// simplicial complex.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_REFINE_SURFACE_MESH_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_REFINE_SURFACE_MESH_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_geometry_named_parameters.h>
#include <CGAL/Hyperbolic_mesh_2/quality_bounds.h>
#include <CGAL/Hyperbolic_surface_mesh_2/Delaunay_triangulation_on_surface.h>
#include <CGAL/Hyperbolic_surface_mesh_2/internal/face_quality.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <ostream>
#include <string>
#include <vector>

CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hsm2_maximum_circumradius_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hsm2_minimum_central_angle_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hsm2_maximum_insertions_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hsm2_make_simplicial_t)

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace parameters {
/// `maximum_circumradius(epsilon [, chain])`: the size bound epsilon on the hyperbolic circumradius (required;
/// finite, in (0, 10])
CGAL_HYPERBOLIC_NAMED_PARAMETER(maximum_circumradius, hsm2_maximum_circumradius_t)
/// `minimum_central_angle(alpha [, chain])`: Ruppert's bound alpha in radians on the central angle of the
/// shortest edge (default 30 degrees = pi / 6; in (0, 2 pi / 3)); ignored by Chew (whose bound is theta*(r))
CGAL_HYPERBOLIC_NAMED_PARAMETER(minimum_central_angle, hsm2_minimum_central_angle_t)
/// `maximum_number_of_insertions(n [, chain])`: the work bound (default 2e7 Steiner points; >= 0, finite)
CGAL_HYPERBOLIC_NAMED_PARAMETER(maximum_number_of_insertions, hsm2_maximum_insertions_t)
/// `make_simplicial(bool [, chain])`: after the criteria hold, refine faces at loops and multiple edges until
/// the triangulation is a simplicial complex (default true)
CGAL_HYPERBOLIC_NAMED_PARAMETER(make_simplicial, hsm2_make_simplicial_t)
} // namespace parameters

/// \ingroup PkgHyperbolicSurfaceMesh2Ref
/// How a refinement ended.
enum class Refinement_status {
  SUCCESS,            ///< every face meets the criteria (and the result is a simplicial complex if requested)
  WORK_BOUND_REACHED, ///< stopped after `maximum_number_of_insertions` Steiner points
  CANCELLED,          ///< the callback returned false
  UNREFINABLE_FACES   ///< some faces fail the criteria: their Steiner point could not be inserted (rounding)
};

inline const char* to_string(Refinement_status s)
{
  switch(s) {
  case Refinement_status::SUCCESS: return "SUCCESS";
  case Refinement_status::WORK_BOUND_REACHED: return "WORK_BOUND_REACHED";
  case Refinement_status::CANCELLED: return "CANCELLED";
  case Refinement_status::UNREFINABLE_FACES: return "UNREFINABLE_FACES";
  }
  return "?";
}

/// \ingroup PkgHyperbolicSurfaceMesh2Ref
/// Progress snapshot given to the callback (`CGAL::parameters::callback`), every 4096 insertions and at the end.
struct Refinement_progress
{
  std::size_t insertions = 0;
  std::size_t number_of_vertices = 0;
  std::size_t queued_faces = 0;          ///< queue size (with stale entries)
  double current_circumradius = 0;       ///< circumradius of the face being refined
};

/// \ingroup PkgHyperbolicSurfaceMesh2Ref
/// What a refinement did and reached. Angles in radians, lengths hyperbolic.
struct Refinement_statistics
{
  Refinement_status status = Refinement_status::SUCCESS;
  bool chew = false;                        ///< which criterion was used
  double epsilon = 0, alpha = 0;            ///< the bounds (alpha: Ruppert only)
  std::size_t initial_vertices = 0, final_vertices = 0, final_faces = 0;
  std::size_t circumcenters_inserted = 0;   ///< Steiner points for the criteria
  std::size_t simplicial_insertions = 0;    ///< Steiner points inserted to remove loops and multiple edges
  std::size_t barycenters_inserted = 0;     ///< faces with a non-compact circumcircle got their barycentre
  std::size_t segment_splits = 0;           ///< midpoints of encroached or blocking constrained edges
  std::size_t unrefinable_faces = 0;        ///< a Steiner point that could not be inserted (rounding)
  std::size_t faces_failing_criteria = 0;   ///< poor faces left at the end (0 unless the status says otherwise)
  std::size_t flips = 0;
  bool simplicial_complex = false;
  long euler_characteristic = 0;
  int genus = 0;
  double minimum_central_angle = 0;         ///< of the shortest edge, over all faces (double precision)
  double maximum_circumradius = 0;
  double minimum_angle = 0, maximum_angle = 0; ///< corner angles
  double h_star = 0;                        ///< Chew's h* = epsilon on a closed surface without segments
  double termination_margin = 0;            ///< Chew: 2.3101 - h*; Ruppert: 1 - rho(eps, alpha) rho(eps, pi/2)
  bool termination_guaranteed = false;      ///< the theorem's hypothesis holds (Chew: h* < 2.3101)
  double seconds = 0;

  friend std::ostream& operator<<(std::ostream& os, const Refinement_statistics& s)
  {
    const double deg = 180 / CGAL_PI;
    return os << (s.chew ? "Chew" : "Ruppert") << " status=" << to_string(s.status) << " epsilon=" << s.epsilon
              << (s.chew ? "" : " alpha_deg=" + std::to_string(s.alpha * deg)) << " vertices=" << s.initial_vertices
              << "->" << s.final_vertices << " faces=" << s.final_faces << " circumcenters=" << s.circumcenters_inserted
              << " simplicial_insertions=" << s.simplicial_insertions << " segment_splits=" << s.segment_splits << " barycenters=" << s.barycenters_inserted
              << " unrefinable=" << s.unrefinable_faces << " failing=" << s.faces_failing_criteria << " flips=" << s.flips
              << " simplicial=" << s.simplicial_complex << " chi=" << s.euler_characteristic << " genus=" << s.genus
              << " min_central_angle_deg=" << s.minimum_central_angle * deg << " max_circumradius=" << s.maximum_circumradius
              << " angles_deg=[" << s.minimum_angle * deg << ", " << s.maximum_angle * deg << "]"
              << " h*=" << s.h_star << " termination_guaranteed=" << s.termination_guaranteed
              << " (margin " << s.termination_margin << ") time=" << s.seconds << "s";
  }
};

namespace internal {

template <class DT>
class Surface_refiner
{
  typedef typename DT::Point_2 Point_2;
  typedef typename DT::Face_index Face_index;
  // a queued face in 16 bytes (the four children of a node of the 4-ary heap span one or two cache lines): the
  // key, the face index and the low 32 bits of its version (a stale entry is taken for current only if its face
  // index was rebuilt a multiple of 2^32 times meanwhile: then a face that may be good is refined, a harmless
  // extra Steiner point)
  struct Entry { double key; std::uint32_t f, version; };

public:
  Surface_refiner(DT& t, const Face_quality<DT>& q, std::size_t max_ins,
                  const std::function<bool(const Refinement_progress&)>& cb, bool verbose)
    : t_(t), q_(q), max_(max_ins), cb_(cb), verbose_(verbose) {}

  /// refines until no face is bad and no constrained edge is encroached; returns the status
  Refinement_status run(Refinement_statistics& st)
  {
    for(Face_index f : t_.faces()) {
      push(f);
      for(int i = 0; i < 3; ++i)
        if(t_.is_constrained(f, i)) { segments_.push_back(Segment{f, i, t_.version(f)}); has_constraints_ = true; }
    }
    for(;;) {
      const Refinement_status s = split_encroached_segments(st);
      if(s != Refinement_status::SUCCESS) return s;
      if(heap_.empty()) break;
      const Entry e = pop();
#if defined(__GNUC__)
      // the first line of the next entry's face (flags, version, chart; usually the next face refined) is
      // fetched during this step: the queue's cache miss per pop
      if(!heap_.empty() && heap_.front().f < t_.face_capacity()) __builtin_prefetch(&t_.lift(heap_.front().f));
#endif
      if(!t_.is_face(e.f) || std::uint32_t(t_.version(e.f)) != e.version) continue;
      const Refinement_status s2 = step(e, st);
      if(s2 != Refinement_status::SUCCESS) return s2;
    }
    return Refinement_status::SUCCESS;
  }

  /// inserts circumcentres of faces at loops and multiple edges until the triangulation is simplicial
  Refinement_status make_simplicial(Refinement_statistics& st)
  {
    for(std::size_t round = 0; round < 64; ++round) {
      const std::vector<Face_index> faces = q_.faces_at_non_simplicial_edges();
      if(faces.empty()) { simplicial_ = 1; return Refinement_status::SUCCESS; } // (unchanged since: no second test)
      for(Face_index f : faces) {
        if(!t_.is_face(f)) continue;
        Entry e{Face_quality<DT>::key_of_circumradius(q_.circumradius(f)), index32(f), std::uint32_t(t_.version(f))};
        const Refinement_status s = step(e, st, true);
        if(s != Refinement_status::SUCCESS) return s;
      }
      const Refinement_status s = run(st); // the new faces may be poor, the new vertices may encroach
      if(s != Refinement_status::SUCCESS) return s;
    }
    return Refinement_status::WORK_BOUND_REACHED;
  }

  /// 1 if `make_simplicial()` ended with a simplicial complex (the triangulation is unchanged since), else -1
  int known_simplicial() const { return simplicial_; }

private:
  struct Segment { Face_index f; int i; std::size_t version; };

  static std::uint32_t index32(Face_index f)
  {
    if(f > Face_index(0xffffffffu)) throw Numerical_error("refine_surface_mesh: more than 2^32 faces");
    return std::uint32_t(f);
  }
  void push(Face_index f)
  {
    const auto ev = q_.evaluate(f);
    if(!ev.bad) return;
    // 4-ary max-heap on the key (largest circumradius first): sift up
    const Entry e{ev.key, index32(f), std::uint32_t(t_.version(f))};
    std::size_t i = heap_.size();
    heap_.push_back(e);
    while(i > 0) {
      const std::size_t p = (i - 1) / 4;
      if(!(heap_[p].key < e.key)) break;
      heap_[i] = heap_[p];
      i = p;
    }
    heap_[i] = e;
  }
  /// removes and returns the entry of largest key (the heap is not empty)
  Entry pop()
  {
    const Entry top = heap_.front(), last = heap_.back();
    heap_.pop_back();
    const std::size_t n = heap_.size();
    if(n == 0) return top;
    std::size_t i = 0;
    for(;;) {
      const std::size_t c = 4 * i + 1;
      if(c >= n) break;
      std::size_t best = c;
      const std::size_t end = (std::min)(c + 4, n);
      for(std::size_t k = c + 1; k < end; ++k) if(heap_[best].key < heap_[k].key) best = k;
      if(!(last.key < heap_[best].key)) break;
      heap_[i] = heap_[best];
      i = best;
    }
    heap_[i] = last;
    return top;
  }

  /// a constrained edge with a vertex strictly inside its hyperbolic diametral disk (the apex of either face)
  bool encroached(Face_index f, int i) const
  {
    const auto& z = t_.lift(f);
    const auto side = t_.geom_traits().side_of_hyperbolic_diametral_circle_2_object();
    const Point_2 &a = z[i], &b = z[(i + 1) % 3];
    return side(a, b, z[(i + 2) % 3]) == CGAL::ON_BOUNDED_SIDE || side(a, b, t_.neighbor_apex(f, i)) == CGAL::ON_BOUNDED_SIDE;
  }

  Refinement_status split_encroached_segments(Refinement_statistics& st)
  {
    while(!segments_.empty()) {
      const Segment s = segments_.back(); segments_.pop_back();
      if(!t_.is_face(s.f) || t_.version(s.f) != s.version || !t_.is_constrained(s.f, s.i) || !encroached(s.f, s.i)) continue;
      const Refinement_status r = split(s.f, s.i, st);
      if(r != Refinement_status::SUCCESS) return r;
    }
    return Refinement_status::SUCCESS;
  }

  /// a vertex where more than two constrained edges meet (a corner of the feature loops)
  bool is_corner(typename DT::Vertex_index v) const
  {
    std::size_t n = 0;
    for(const auto& c : t_.star(v)) if(t_.is_constrained(c.first, c.second)) ++n;
    return n > 2;
  }

  /// Splits constrained edge i of f (both halves stay constrained): at its hyperbolic midpoint, or, for an edge
  /// from a corner to a non-corner, at the power of two closest to half its length from the corner (Ruppert's
  /// concentric shells, as in the plane: the edges at a corner get equal lengths, so the refinement does not
  /// cascade towards a small corner angle)
  Refinement_status split(Face_index f, int i, Refinement_statistics& st)
  {
    const auto& z = t_.lift(f);
    const int j = (i + 1) % 3;
    // a constrained edge far below the size bound is not split further: at a tiny angle between two loops the
    // splits cascade (each half encroached by the other loop) into faces too thin for double precision
    if(t_.edge_length(f, i) < 1e-6 * q_.epsilon()) { ++st.unrefinable_faces; return Refinement_status::SUCCESS; }
    const bool ca = is_corner(t_.vertex(f, i)), cb = is_corner(t_.vertex(f, j));
    typename DT::Location loc;
    loc.type = DT::Location::ON_EDGE; loc.face = f; loc.index = i;
    if(ca != cb) {
      const double len = t_.edge_length(f, i), d = std::exp2(std::round(std::log2(len / 2)));
      loc.point = ca ? DT::Geometry::point_along(z[i], z[j], d) : DT::Geometry::point_along(z[j], z[i], d);
    } else {
      loc.point = t_.geom_traits().construct_hyperbolic_midpoint_2_object()(z[i], z[j]);
    }
    return inserted(loc, st, Kind::SEGMENT, 0);
  }

  enum class Kind { CIRCUMCENTER, BARYCENTER, SIMPLICIAL, SEGMENT };

  Refinement_status step(const Entry& e, Refinement_statistics& st, bool simplicial = false)
  {
    if(inserted_ >= max_) return Refinement_status::WORK_BOUND_REACHED;
    bool barycentre = false;
    const Point_2 c = q_.steiner_point(e.f, barycentre);
    typename DT::Location loc;
    std::pair<Face_index, int> blocking;
    try { loc = t_.locate(c, e.f, &blocking); }
    catch(const Poincare_disk_domain_error&) { ++st.unrefinable_faces; return Refinement_status::SUCCESS; }
    // not visible inside the feature loops: split the constrained edge in the way instead
    // (the face is queued again only if the split inserted a vertex: a split refused as too short, counted
    // unrefinable, would otherwise bring the same face back forever without counting towards the work bound)
    const std::size_t before = inserted_;
    if(blocking.first != DT::null_index) {
      const Refinement_status s = split(blocking.first, blocking.second, st);
      if(inserted_ > before && t_.is_face(e.f) && t_.version(e.f) == e.version) push(e.f); // untouched: still poor
      return s;
    }
    // Ruppert: a Steiner point that would encroach a constrained edge is not inserted; the edge is split instead
    std::pair<Face_index, int> enc;
    if(has_constraints_ && encroaches_segment(loc, enc)) {
      const Refinement_status s = split(enc.first, enc.second, st);
      if(inserted_ > before && t_.is_face(e.f) && t_.version(e.f) == e.version) push(e.f);
      return s;
    }
    return inserted(loc, st, simplicial ? Kind::SIMPLICIAL : (barycentre ? Kind::BARYCENTER : Kind::CIRCUMCENTER), e.key);
  }

  /// true (and the edge in `enc`) if the located point lies strictly inside the diametral disk of a constrained
  /// edge on the boundary of its cavity (the faces whose circumcircle contains it, not crossing constraints):
  /// in a constrained Delaunay triangulation the edges it encroaches are there (work bound: 256 faces)
  bool encroaches_segment(const typename DT::Location& loc, std::pair<Face_index, int>& enc) const
  {
    const auto& gt = t_.geom_traits();
    const auto side = gt.side_of_hyperbolic_diametral_circle_2_object();
    const auto incircle = gt.side_of_oriented_circle_2_object();
    cavity_.clear();
    cavity_.push_back(std::make_pair(loc.face, loc.point));
    for(std::size_t k = 0; k < cavity_.size() && k < 256; ++k) {
      const Face_index f = cavity_[k].first;
      const Point_2 c = cavity_[k].second;
      const auto& z = t_.lift(f);
      for(int i = 0; i < 3; ++i) {
        if(t_.is_constrained(f, i)) {
          if(side(z[i], z[(i + 1) % 3], c) == CGAL::ON_BOUNDED_SIDE) { enc = std::make_pair(f, i); return true; }
          continue;
        }
        const Face_index g = t_.neighbor(f, i);
        bool seen = false;
        for(const auto& x : cavity_) if(x.first == g) { seen = true; break; }
        if(seen) continue;
        const Point_2 cg = t_.transition(f, i).apply_unchecked(c);
        const auto& w = t_.lift(g);
        if(incircle(w[0], w[1], w[2], cg) == CGAL::ON_POSITIVE_SIDE) cavity_.push_back(std::make_pair(g, cg));
      }
    }
    return false;
  }

  Refinement_status inserted(const typename DT::Location& loc, Refinement_statistics& st, Kind kind, double key)
  {
    if(inserted_ >= max_) return Refinement_status::WORK_BOUND_REACHED;
    const std::size_t nv = t_.number_of_vertices();
    const typename DT::Vertex_index w = t_.insert(loc);
    if(w == DT::null_index || t_.number_of_vertices() == nv) { ++st.unrefinable_faces; return Refinement_status::SUCCESS; }
    ++inserted_;
    switch(kind) {
    case Kind::SIMPLICIAL: ++st.simplicial_insertions; break;
    case Kind::BARYCENTER: ++st.barycenters_inserted; break;
    case Kind::SEGMENT: ++st.segment_splits; break;
    default: ++st.circumcenters_inserted;
    }
    t_.star(w, star_);
    for(const auto& corner : star_) {
      push(corner.first);
      // the constrained edges around w (opposite w, and the halves at w) may be encroached now
      for(int i = 0; i < 3; ++i)
        if(t_.is_constrained(corner.first, i)) segments_.push_back(Segment{corner.first, i, t_.version(corner.first)});
    }
    if(inserted_ % 4096 == 0) {
      Refinement_progress p;
      p.insertions = inserted_; p.number_of_vertices = t_.number_of_vertices(); p.queued_faces = heap_.size();
      p.current_circumradius = Face_quality<DT>::circumradius_of_key(key);
      if(verbose_) std::cerr << "  refinement: " << p.insertions << " insertions, " << p.number_of_vertices
                             << " vertices, circumradius " << p.current_circumradius << std::endl;
      if(cb_ && !cb_(p)) return Refinement_status::CANCELLED;
    }
    return Refinement_status::SUCCESS;
  }

  DT& t_;
  const Face_quality<DT>& q_;
  std::size_t max_, inserted_ = 0;
  std::function<bool(const Refinement_progress&)> cb_;
  bool verbose_;
  std::vector<Entry> heap_; // the poor faces (4-ary max-heap on the key; stale entries skipped when popped)
  std::vector<Segment> segments_; // constrained edges to test for encroachment (stale entries skipped)
  bool has_constraints_ = false;
  int simplicial_ = -1;
  mutable std::vector<std::pair<Face_index, Point_2> > cavity_;
  std::vector<std::pair<Face_index, int> > star_; // the star of the last inserted vertex (reused: no allocation)
};

template <class DT, class NamedParameters>
Refinement_statistics refine(DT& t, bool chew, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  const auto t0 = std::chrono::steady_clock::now();
  if(is_default_parameter<NamedParameters, CGAL::internal_np::hsm2_maximum_circumradius_t>::value)
    throw Invalid_option_error("refine_surface_mesh: maximum_circumradius(epsilon) is required");
  Refinement_statistics st;
  st.chew = chew;
  st.epsilon = double(choose_parameter(get_parameter(np, CGAL::internal_np::hsm2_maximum_circumradius_t_v), 0.0));
  st.alpha = double(choose_parameter(get_parameter(np, CGAL::internal_np::hsm2_minimum_central_angle_t_v), CGAL_PI / 6));
  const double max_ins = double(choose_parameter(get_parameter(np, CGAL::internal_np::hsm2_maximum_insertions_t_v), 2e7));
  const bool simplicial = choose_parameter(get_parameter(np, CGAL::internal_np::hsm2_make_simplicial_t_v), true);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const std::function<bool(const Refinement_progress&)> cb =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(const Refinement_progress&)>());
  if(!(st.epsilon > 0 && st.epsilon <= 10))
    throw Invalid_option_error("refine_surface_mesh: maximum_circumradius must be in (0, 10]");
  if(!(st.alpha > 0 && st.alpha < 2 * CGAL_PI / 3))
    throw Invalid_option_error("refine_surface_mesh: minimum_central_angle must be in (0, 2 pi / 3) radians");
  if(!(max_ins >= 0 && std::isfinite(max_ins)))
    throw Invalid_option_error("refine_surface_mesh: maximum_number_of_insertions must be finite and >= 0");
  st.initial_vertices = t.number_of_vertices();
  const std::size_t flips0 = t.number_of_flips();
  // room for the expected output (the faces have circumradius about epsilon / sqrt 2 to epsilon, area about
  // 0.76 epsilon^2 measured; area 4 pi (g - 1)): the face array is not copied on growth
  {
    const double expected = 4 * CGAL_PI * (std::max)(1, t.genus() - 1) / (0.7 * st.epsilon * st.epsilon);
    const double cap = (std::min)(double(1 << 22), double(t.number_of_faces()) + 2 * max_ins);
    const double n = (std::min)(expected, cap);
    t.reserve(std::size_t(n), std::size_t(n / 2) + t.number_of_vertices());
  }
  const Face_quality<DT> q(t, chew, st.epsilon, st.alpha);
  Surface_refiner<DT> r(t, q, std::size_t(max_ins), cb, verbose);
  st.status = r.run(st);
  if(st.status == Refinement_status::SUCCESS && simplicial) st.status = r.make_simplicial(st);
  q.measure(st, r.known_simplicial()); // (and st.faces_failing_criteria)
  if(st.status == Refinement_status::SUCCESS && st.faces_failing_criteria > 0) st.status = Refinement_status::UNREFINABLE_FACES;
  st.flips = t.number_of_flips() - flips0;
  if(chew) {
    st.h_star = st.epsilon;
    st.termination_margin = Hyperbolic_mesh_2::Chew_termination_bound - st.h_star;
  } else {
    st.termination_margin = Hyperbolic_mesh_2::Ruppert_termination_margin(st.epsilon, st.alpha);
  }
  st.termination_guaranteed = st.termination_margin > 0;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if(verbose) std::cerr << st << std::endl;
  return st;
}

} // namespace internal

/*!
  \ingroup PkgHyperbolicSurfaceMesh2Ref
  Generalized Ruppert refinement on the surface (thesis Algorithm 6, without input segments): while a face has
  a circumradius above epsilon or a central angle of its shortest edge below alpha (both decided by the traits'
  exact predicates `Compare_hyperbolic_circumradius_2`, `Compare_central_angle_2` in the face's chart), insert
  its circumcentre, located by walking from the face across the transitions; faces are refined largest
  circumradius first. Then (option `make_simplicial`) faces at loops and multiple edges are refined until the
  triangulation is a simplicial complex. Constrained edges (feature loops, see
  `Delaunay_triangulation_on_surface(polygon, true)`) are split at their hyperbolic midpoint when a vertex lies
  strictly inside their diametral disk, or when they block the walk to a circumcentre (which is then not inserted).

  Named parameters: `parameters::maximum_circumradius(epsilon)` (required), `parameters::minimum_central_angle(alpha)`,
  `parameters::maximum_number_of_insertions(n)`, `parameters::make_simplicial(b)`, and CGAL's
  `callback(std::function<bool(const Refinement_progress&)>)` and `verbose(bool)`. Options out of range throw
  `CGAL::Invalid_option_error`. The thesis' termination hypothesis (1 - rho(epsilon, alpha) rho(epsilon, pi/2) > 0)
  is reported in the statistics, not required: the work bound stops every run.
  Cost: O(log n) per Steiner point plus the flips and the walk (O(1) expected each).
*/
template <class DT, class NamedParameters = CGAL::parameters::Default_named_parameters>
Refinement_statistics refine_Ruppert(DT& t, const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::refine(t, false, np);
}

/*!
  \ingroup PkgHyperbolicSurfaceMesh2Ref
  Generalized Chew refinement on the surface (thesis Algorithm 5, without input segments): a face is poor if its
  circumradius r exceeds epsilon (exact predicate) or the central angle of its shortest edge is below theta*(r),
  i.e. its shortest edge is shorter than r (exact: the sign of a polynomial in the chart's coordinates,
  `internal::Chew_shape_polynomial`, filtered, with an exact rational fallback).
  Termination is guaranteed for h* = epsilon < 2.3101 (thesis Theorem 3.1); the statistics report it. The rest
  as `refine_Ruppert()` (alpha is ignored).
*/
template <class DT, class NamedParameters = CGAL::parameters::Default_named_parameters>
Refinement_statistics refine_Chew(DT& t, const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::refine(t, true, np);
}

} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_MESH_2_REFINE_SURFACE_MESH_H
