// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shared hyperbolic-surface layer: a closed triangulated surface (any FaceGraph, loops and multi-edges
// allowed) with hyperbolic edge lengths, and on it corner angles, angle-sum defects, area, a chart per face
// (the lift of its three vertices near the origin of the Poincare disk), the transition isometry across each
// edge and the development of a sequence of faces as a chain of charts.
#ifndef CGAL_HYPERBOLIC_SURFACE_2_HYPERBOLIC_SURFACE_TRIANGULATION_H
#define CGAL_HYPERBOLIC_SURFACE_2_HYPERBOLIC_SURFACE_TRIANGULATION_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_geometry_named_parameters.h>
#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>
#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>
#include <CGAL/Poincare_disk_traits_2.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hs2_angle_tolerance_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hs2_require_hyperbolic_t)

namespace CGAL {
namespace Hyperbolic_surface_2 {
namespace parameters {
/// named parameter `angle_tolerance(double [, chain])`: largest accepted |angle sum - 2 pi| at a vertex
/// (default 1e-6; non-negative and finite)
CGAL_HYPERBOLIC_NAMED_PARAMETER(angle_tolerance, hs2_angle_tolerance_t)
/// named parameter `require_smooth_metric(bool [, chain])`: check that every angle sum is 2 pi and the genus
/// is at least 2 (default true). With false, cone metrics (and intermediate flow states) are accepted.
CGAL_HYPERBOLIC_NAMED_PARAMETER(require_smooth_metric, hs2_require_hyperbolic_t)
} // namespace parameters

/*!
  \ingroup PkgHyperbolicSurface2Ref
  A model of `HyperbolicSurfaceTriangulation_2`: a closed orientable triangulated surface with a hyperbolic
  metric given by its edge lengths.

  `TriangleMesh` is a model of `FaceGraph` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, ...): closed, every
  face a triangle, connected. Faces may use a vertex more than once and two vertices may be joined by several
  edges (a Delta-complex, as intrinsic triangulations are). `EdgeLengthMap` is a readable property map from
  `edge_descriptor` to `double`. `Traits` is `CGAL::Poincare_disk_traits_2<K>` for a kernel with double
  coordinates: lifted points are `Traits::Point_2`, isometries `Traits::Isometry_2`
  (`CGAL::Poincare_disk_isometry_2<K>`), so the traits' exact predicates apply to lifted configurations.

  Every geometric quantity is computed from the lengths in a cancellation-free form (half-angle formula for
  corner angles, l'Huilier for areas). A *chart* of a face is the lift of its three corners with the face's
  hyperbolic barycentre at the origin; the *transition* across a halfedge h is the isometry that maps the
  chart of `face(h)` to the chart of `face(opposite(h))` (both lifts of the common edge coincide after it).
  Long objects (paths, fundamental domains) are developed as chains of charts (`develop()`), so no point
  needs to be represented far from the origin.

  The constructor checks, in release builds too: the mesh is non-empty, closed, triangulated and connected
  (`CGAL::Invalid_mesh_error`), every length is finite and positive and every face satisfies the strict
  triangle inequality, and (unless `require_smooth_metric(false)`) every angle sum is 2 pi up to
  `angle_tolerance` and the genus is at least 2 (`CGAL::Invalid_metric_error`, `CGAL::Invalid_mesh_error`).
  Cost: linear in the size of the mesh.

  The object keeps a reference to the mesh and a copy of the map: both must outlive it and not change.
*/
template <class TriangleMesh, class EdgeLengthMap,
          class Traits = CGAL::Poincare_disk_traits_2<CGAL::Exact_predicates_inexact_constructions_kernel> >
class Hyperbolic_surface_triangulation
{
public:
  typedef TriangleMesh Triangle_mesh;
  typedef Traits Geom_traits;
  typedef typename Traits::Kernel Kernel;
  typedef typename Traits::Point_2 Point_2;
  typedef CGAL::Poincare_disk_isometry_2<Kernel> Isometry_2;
  typedef Disk_geometry<Kernel> Geometry;
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor   vertex_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Graph_traits::edge_descriptor     edge_descriptor;
  typedef typename Graph_traits::face_descriptor     face_descriptor;

  /// The lift of a face: `z[i]` is the position of `source(h[i])`, with `h[0] = halfedge(f)`,
  /// `h[1] = next(h[0])`, `h[2] = next(h[1])`, counterclockwise, barycentre at the origin.
  struct Face_chart
  {
    face_descriptor face;
    std::array<halfedge_descriptor, 3> h;
    std::array<Point_2, 3> z;
    /// the index i with h[i] == g (g must be a halfedge of the face)
    int index(halfedge_descriptor g) const { return g == h[0] ? 0 : (g == h[1] ? 1 : 2); }
    /// position of source(g) and of target(g) for a halfedge g of the face
    const Point_2& source_point(halfedge_descriptor g) const { return z[index(g)]; }
    const Point_2& target_point(halfedge_descriptor g) const { return z[(index(g) + 1) % 3]; }
  };

  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  Hyperbolic_surface_triangulation(const TriangleMesh& tm, EdgeLengthMap lengths,
                                   const NamedParameters& np = CGAL::parameters::default_values())
    : tm_(tm), lengths_(lengths)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    tolerance_ = choose_parameter(get_parameter(np, CGAL::internal_np::hs2_angle_tolerance_t_v), 1e-6);
    smooth_ = choose_parameter(get_parameter(np, CGAL::internal_np::hs2_require_hyperbolic_t_v), true);
    if(!(tolerance_ >= 0) || !std::isfinite(tolerance_))
      throw Invalid_option_error("Hyperbolic_surface_triangulation: angle_tolerance must be finite and >= 0");
    check_mesh();
    check_metric();
  }

  // ---------------------------------------------------------------- mesh and lengths
  const TriangleMesh& mesh() const { return tm_; }
  const EdgeLengthMap& edge_length_map() const { return lengths_; }
  /// hyperbolic length of the edge of `h`
  double length(halfedge_descriptor h) const { return get(lengths_, edge(h, tm_)); }
  double length(edge_descriptor e) const { return get(lengths_, e); }
  /// genus g (from the Euler characteristic 2 - 2g)
  int genus() const { return genus_; }

  // ---------------------------------------------------------------- angles, curvature, area
  /// the corner angle at `target(h)` in `face(h)` (between `h` and `next(h)`), half-angle formula
  double angle_at_target(halfedge_descriptor h) const
  {
    return corner_angle(length(next(next(h, tm_), tm_)), length(h), length(next(h, tm_)));
  }
  /// the corner angle opposite to `h` in `face(h)` (at `target(next(h))`)
  double angle_opposite(halfedge_descriptor h) const { return angle_at_target(next(h, tm_)); }
  /// the sum of the corner angles at `v`
  double angle_sum(vertex_descriptor v) const
  {
    double s = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm_)) s += angle_at_target(h);
    return s;
  }
  /// 2 pi minus the angle sum at `v` (the discrete Gaussian curvature; 0 for a smooth metric)
  double angle_defect(vertex_descriptor v) const { return 2 * CGAL_PI - angle_sum(v); }
  /// largest |angle_defect(v)| (measured at construction)
  double max_angle_defect() const { return max_defect_; }
  /// hyperbolic area of a face (l'Huilier)
  double face_area(face_descriptor f) const
  {
    const halfedge_descriptor h = halfedge(f, tm_);
    return triangle_area(length(h), length(next(h, tm_)), length(prev(h, tm_)));
  }
  /// total hyperbolic area, summed over the faces (4 pi (g - 1) for a smooth metric, by Gauss-Bonnet)
  double area() const { double a = 0; for(face_descriptor f : faces(tm_)) a += face_area(f); return a; }
  /// true if the edge of `h` is intrinsically Delaunay: the circumcircle of one of its faces does not contain
  /// the opposite vertex of the other. For hyperbolic triangles this is: the two angles opposite to the edge
  /// sum to at most the four other corner angles of the quadrilateral (the sums are equal on a circle; the
  /// Euclidean rule "at most pi" is weaker, since a hyperbolic quadrilateral's angles sum to less than 2 pi).
  /// Decided in floating point, up to 1e-12 relative: for an exact decision use the traits' in-circle
  /// predicate on the lifted quadrilateral (`chart()` and `neighbor_apex()`).
  bool is_delaunay(halfedge_descriptor h) const
  {
    const halfedge_descriptor o = opposite(h, tm_);
    const double opposite_sum = angle_opposite(h) + angle_opposite(o);
    const double other_sum = angle_at_target(h) + angle_at_target(prev(h, tm_)) +
                             angle_at_target(o) + angle_at_target(prev(o, tm_));
    return opposite_sum <= other_sum + 1e-12 * (opposite_sum + other_sum);
  }

  // ---------------------------------------------------------------- charts and transitions
  /// the chart of `f` (see `Face_chart`). Cost: O(1).
  Face_chart chart(face_descriptor f) const
  {
    Face_chart c;
    c.face = f;
    c.h[0] = halfedge(f, tm_); c.h[1] = next(c.h[0], tm_); c.h[2] = next(c.h[1], tm_);
    c.z = Geometry::triangle_chart(length(c.h[0]), length(c.h[1]), length(c.h[2]));
    return c;
  }

  /// the isometry mapping the chart of `face(h)` to the chart of `face(opposite(h))`: it maps the lift of
  /// the edge of `h` in the first chart onto its lift in the second. Cost: O(1).
  Isometry_2 transition(halfedge_descriptor h) const
  {
    const halfedge_descriptor o = opposite(h, tm_);
    const Face_chart cf = chart(face(h, tm_)), cg = chart(face(o, tm_));
    return transition(h, cf, cg);
  }
  /// the same from charts already computed (`cf` of `face(h)`, `cg` of `face(opposite(h))`)
  Isometry_2 transition(halfedge_descriptor h, const Face_chart& cf, const Face_chart& cg) const
  {
    const halfedge_descriptor o = opposite(h, tm_);
    // source(h) = target(o), target(h) = source(o)
    return Geometry::isometry_from_pairs(cf.source_point(h), cf.target_point(h), cg.target_point(o), cg.source_point(o));
  }

  /// the lift of the apex of `face(opposite(h))` (the corner not on the edge) when the edge of `h` is lifted
  /// with `source(h)` at `zs` and `target(h)` at `zt` (the neighbour face is laid out on the right of h)
  Point_2 neighbor_apex(halfedge_descriptor h, const Point_2& zs, const Point_2& zt) const
  {
    const halfedge_descriptor o = opposite(h, tm_);
    // triangle (target(h), source(h), apex) counterclockwise: sides |source-apex| = length(next(o)),
    // |apex-target| = length(prev(o))
    return Geometry::apex(zt, zs, length(next(o, tm_)), length(prev(o, tm_)), length(h));
  }

  /// One step of a development: a face, its chart, and the isometry `to_frame` that maps the chart into the
  /// frame of the development's current piece (`frame` counts how often the development was re-centred).
  struct Development_step
  {
    Face_chart chart;
    Isometry_2 to_frame;
    std::size_t frame = 0;
  };

  /// Develops the faces crossed by the halfedges `crossed` (each a halfedge of the current face, crossed into
  /// `face(opposite)`), starting in `face(start)`: the chain of charts of the corridor. The first chart's
  /// frame is its own; whenever the lifted current face lies farther than `recenter_distance` from the
  /// origin of the current frame, a new frame is started at the current face (frame index + 1), so every
  /// point is stored within that distance of an origin. Throws `Invalid_path_error` if a halfedge is not in
  /// the current face. Cost: linear in the number of crossings.
  std::vector<Development_step> develop(face_descriptor start, const std::vector<halfedge_descriptor>& crossed,
                                        double recenter_distance = 8.0) const
  {
    std::vector<Development_step> r;
    Development_step s; s.chart = chart(start);
    r.push_back(s);
    for(halfedge_descriptor h : crossed) {
      const Development_step& cur = r.back();
      if(face(h, tm_) != cur.chart.face)
        throw Invalid_path_error("Hyperbolic_surface_triangulation::develop: a crossed halfedge is not in the current face");
      Development_step n;
      n.chart = chart(face(opposite(h, tm_), tm_));
      n.to_frame = cur.to_frame * transition(h, cur.chart, n.chart).inverse();
      n.frame = cur.frame;
      if(Geometry::distance_to_origin(n.to_frame.apply_unchecked(Point_2(0, 0))) > recenter_distance) {
        n.to_frame = Isometry_2(); ++n.frame;
      }
      r.push_back(n);
    }
    return r;
  }

private:
  [[noreturn]] static void fail_mesh(const std::string& m)
  { throw Invalid_mesh_error("Hyperbolic_surface_triangulation: " + m); }
  [[noreturn]] static void fail_metric(const std::string& m)
  { throw Invalid_metric_error("Hyperbolic_surface_triangulation: " + m); }

  void check_mesh()
  {
    if(num_faces(tm_) == 0) fail_mesh("empty mesh");
    for(halfedge_descriptor h : halfedges(tm_)) {
      if(is_border(h, tm_)) fail_mesh("the mesh has a boundary (a closed surface is required)");
      if(next(next(next(h, tm_), tm_), tm_) != h) fail_mesh("the mesh has a non-triangular face");
    }
    // connectivity through the faces (one component)
    std::unordered_map<face_descriptor, char> seen;
    std::vector<face_descriptor> stack(1, *faces(tm_).first);
    seen[stack.back()] = 1;
    while(!stack.empty()) {
      const face_descriptor f = stack.back(); stack.pop_back();
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm_), tm_)) {
        const face_descriptor g = face(opposite(h, tm_), tm_);
        if(seen.emplace(g, 1).second) stack.push_back(g);
      }
    }
    if(seen.size() != std::size_t(num_faces(tm_))) {
      std::ostringstream os;
      os << "the mesh is not connected (" << seen.size() << " of " << num_faces(tm_)
         << " faces reached from the first one)";
      fail_mesh(os.str());
    }
    const long chi = long(num_vertices(tm_)) - long(num_edges(tm_)) + long(num_faces(tm_));
    if(chi % 2 != 0) fail_mesh("odd Euler characteristic (non-orientable or not a surface)");
    genus_ = int((2 - chi) / 2);
    if(smooth_ && genus_ < 2) {
      std::ostringstream os;
      os << "genus " << genus_ << " < 2 has no hyperbolic metric";
      fail_mesh(os.str());
    }
  }

  void check_metric()
  {
    for(face_descriptor f : faces(tm_)) {
      const halfedge_descriptor h0 = halfedge(f, tm_), h1 = next(h0, tm_), h2 = next(h1, tm_);
      if(!is_hyperbolic_triangle(length(h0), length(h1), length(h2))) {
        std::ostringstream os;
        os.precision(17);
        os << "edge lengths " << length(h0) << ", " << length(h1) << ", " << length(h2)
           << " of a face are not those of a hyperbolic triangle (positive, finite, strict triangle inequality)";
        fail_metric(os.str());
      }
    }
    max_defect_ = 0;
    for(vertex_descriptor v : vertices(tm_)) {
      const double sum = angle_sum(v), defect = std::abs(sum - 2 * CGAL_PI);
      max_defect_ = (std::max)(max_defect_, defect);
      if(smooth_ && !(defect <= tolerance_)) {
        std::ostringstream os;
        os.precision(12);
        os << "the metric is not a smooth hyperbolic metric: angle sum " << sum << " at a vertex differs from 2 pi by "
           << defect << " (tolerance " << tolerance_ << ")";
        fail_metric(os.str());
      }
    }
  }

  const TriangleMesh& tm_;
  EdgeLengthMap lengths_;
  double tolerance_ = 1e-6;
  bool smooth_ = true;
  int genus_ = 0;
  double max_defect_ = 0;
};

} // namespace Hyperbolic_surface_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_2_HYPERBOLIC_SURFACE_TRIANGULATION_H
