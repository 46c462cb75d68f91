// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Conformal remeshing of a closed triangle mesh of genus >= 2: hyperbolic uniformization (discrete Ricci flow),
// Delaunay refinement on the hyperbolic surface, and the map of every output vertex back to a point of the
// input mesh (input face + barycentric coordinates of the straight Klein triangle).
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_CONFORMAL_REMESH_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_CONFORMAL_REMESH_H

#include <CGAL/Discrete_Ricci_flow.h>
#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_surface_2/Hyperbolic_surface_triangulation.h>
#include <CGAL/Hyperbolic_surface_mesh_2/Delaunay_triangulation_on_surface.h>
#include <CGAL/Hyperbolic_surface_mesh_2/refine_surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <chrono>
#include <memory>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hsm2_use_chew_t)

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace parameters {
/// `use_Chew(bool [, chain])`: generalized Chew instead of generalized Ruppert in `conformal_remesh()` (default false)
CGAL_HYPERBOLIC_NAMED_PARAMETER(use_Chew, hsm2_use_chew_t)
} // namespace parameters

/// \ingroup PkgHyperbolicSurfaceMesh2Ref
/// A point of an input mesh: the index of its face in `faces(mesh)` order and barycentric coordinates with
/// respect to the sources of `halfedge(f)`, `next(halfedge(f))`, `prev(halfedge(f))`.
struct Mesh_location
{
  std::size_t face = 0;
  std::array<double, 3> barycentric{{1.0 / 3, 1.0 / 3, 1.0 / 3}};
};

/// \ingroup PkgHyperbolicSurfaceMesh2Ref
/// The output of `conformal_remesh()`: the statistics of each stage and, per output vertex, its location on
/// the input mesh.
struct Remesh_report
{
  Ricci_flow::Flow_statistics flow;
  /// the flow needed intrinsic (Ptolemy) flips: the intrinsic faces are then not all input faces, and the
  /// output vertices lie on the straight triangles spanned by the intrinsic faces' vertices (near the input
  /// surface, not on it). False: every output vertex is a point of an input face.
  bool flow_used_flips = false;
  Refinement_statistics refinement;
  std::vector<Mesh_location> locations; ///< indexed like the vertices of the output mesh
  double seconds_flow = 0, seconds_triangulation = 0, seconds_refinement = 0, seconds_output = 0;
  int genus = 0;
  /// the refined triangulation of the hyperbolic surface (for pictures and further queries)
  std::shared_ptr<const Delaunay_triangulation_on_surface<> > surface;
};

/*!
  \ingroup PkgHyperbolicSurfaceMesh2Ref
  The location on the input mesh of every vertex of `t`, a triangulation built with
  `Delaunay_triangulation_on_surface::from_surface_triangulation(st)` from a surface triangulation on `mesh`:
  the reference face of the vertex is the input face (same index in `faces(mesh)`), and the point in its chart
  has barycentric coordinates in the straight Klein image of the chart's triangle (geodesic triangles are
  straight triangles in the Klein model, so these projective coordinates are the hyperbolic-to-Euclidean map:
  a geodesic of the hyperbolic face becomes a straight segment of the input face). Indexed by vertex index.
*/
template <class DT>
std::vector<Mesh_location> input_locations(const DT& t)
{
  std::vector<Mesh_location> r(t.vertex_capacity());
  for(std::size_t v : t.vertices()) {
    const auto& ref = t.vertex_reference(v);
    r[v].face = ref.reference_face;
    r[v].barycentric = t.reference().klein_barycentric(ref.reference_face, ref.point);
  }
  return r;
}

namespace internal {

template <class TriangleMesh>
void check_remesh_input(const TriangleMesh& tm)
{
  if(num_faces(tm) == 0) throw Invalid_mesh_error("conformal_remesh: empty mesh");
  if(!CGAL::is_triangle_mesh(tm)) throw Invalid_mesh_error("conformal_remesh: the mesh is not a triangle mesh");
  if(!CGAL::is_closed(tm)) throw Invalid_mesh_error("conformal_remesh: the mesh has a boundary (a closed surface is required)");
  if(!CGAL::is_valid_polygon_mesh(tm)) throw Invalid_mesh_error("conformal_remesh: the mesh is not a valid (manifold) polygon mesh");
  const long chi = long(num_vertices(tm)) - long(num_edges(tm)) + long(num_faces(tm));
  if(chi > -2) {
    std::ostringstream os;
    os << "conformal_remesh: Euler characteristic " << chi << " (genus " << (2 - chi) / 2
       << "): a closed surface of genus >= 2 is required";
    throw Invalid_mesh_error(os.str());
  }
}

template <class Metric>
bool satisfies_triangle_inequalities(const Metric& m)
{
  const auto& im = m.intrinsic_mesh();
  for(auto f : faces(im)) {
    const auto h = halfedge(f, im);
    if(!Hyperbolic_surface_2::is_hyperbolic_triangle(m.length(h), m.length(next(h, im)), m.length(prev(h, im)))) return false;
  }
  return true;
}

} // namespace internal

/*!
  \ingroup PkgHyperbolicSurfaceMesh2Ref
  Conformal remeshing of a closed, connected, manifold triangle mesh `tm` of genus g >= 2 into `out`:
  1. the hyperbolic uniformization metric (`CGAL::Ricci_flow::hyperbolic_uniformization`), first without
     intrinsic flips (so that the intrinsic faces are the input faces); if that flow does not converge, with
     Ptolemy flips (`report.flow_used_flips`: the output vertices then lie on the straight triangles spanned
     by the vertices of the intrinsic faces, not exactly on the input surface);
  2. the Delaunay triangulation of the hyperbolic surface with the input vertices, then generalized Ruppert
     (default) or Chew refinement (`parameters::use_Chew(true)`) with the options of `refine_Ruppert()`
     (`maximum_circumradius` required);
  3. every output vertex mapped to the input surface (`input_locations()`), the output faces added to `out`
     (a `CGAL::Surface_mesh<Point_3>`, cleared first).
  The output is a closed manifold mesh of genus g whose vertices lie on the input surface when the refinement
  ended with a simplicial complex (`report.refinement.simplicial_complex`); otherwise `CGAL::Numerical_error`.
  Throws `CGAL::Invalid_mesh_error` for an open, non-manifold, non-triangle or genus < 2 input.
*/
template <class TriangleMesh, class Point_3, class NamedParameters>
Remesh_report conformal_remesh(const TriangleMesh& tm, CGAL::Surface_mesh<Point_3>& out, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::chrono::steady_clock Clock;
  auto seconds = [](Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); };
  internal::check_remesh_input(tm);
  Remesh_report rep;
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  auto t0 = Clock::now();
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  // 1. the metric on the input connectivity
  auto metric = Ricci_flow::hyperbolic_uniformization(tm, CGAL::parameters::do_flip(false));
  // (a converged flow without flips may still have a face violating the triangle inequality: then flips)
  if(!metric.converged() || !internal::satisfies_triangle_inequalities(metric)) {
    if(verbose) std::cerr << "  flow without flips: " << Ricci_flow::to_string(metric.statistics().status) << "; with flips" << std::endl;
    metric = Ricci_flow::hyperbolic_uniformization(tm);
    if(!metric.converged()) throw Numerical_error("conformal_remesh: the Ricci flow did not converge");
  }
  rep.flow_used_flips = metric.statistics().number_of_flips > 0;
  const Mesh& im = metric.intrinsic_mesh();
  const auto lengths = metric.edge_length_map();
  rep.flow = metric.statistics();
  rep.seconds_flow = seconds(t0);
  // 2. triangulation and refinement
  t0 = Clock::now();
  const Hyperbolic_surface_2::Hyperbolic_surface_triangulation<Mesh, typename std::decay<decltype(lengths)>::type> st(im, lengths);
  rep.genus = st.genus();
  auto tp = std::make_shared<Delaunay_triangulation_on_surface<> >(Delaunay_triangulation_on_surface<>::from_surface_triangulation(st));
  Delaunay_triangulation_on_surface<>& t = *tp;
  rep.surface = tp;
  rep.seconds_triangulation = seconds(t0);
  t0 = Clock::now();
  const bool chew = choose_parameter(get_parameter(np, CGAL::internal_np::hsm2_use_chew_t_v), false);
  rep.refinement = chew ? refine_Chew(t, np) : refine_Ruppert(t, np);
  rep.seconds_refinement = seconds(t0);
  if(!t.is_simplicial_complex())
    throw Numerical_error("conformal_remesh: the refined triangulation is not a simplicial complex (status " +
                          std::string(to_string(rep.refinement.status)) + ")");
  // 3. output
  t0 = Clock::now();
  const std::vector<Mesh_location> loc = input_locations(t);
  std::vector<typename Mesh::Face_index> input_faces;
  for(auto f : faces(im)) input_faces.push_back(f);
  out.clear();
  std::vector<typename Mesh::Vertex_index> vmap(t.vertex_capacity());
  for(std::size_t v : t.vertices()) {
    const auto h0 = halfedge(input_faces[loc[v].face], im);
    const Point_3 p[3] = {im.point(source(h0, im)), im.point(source(next(h0, im), im)), im.point(source(prev(h0, im), im))};
    const auto& b = loc[v].barycentric;
    vmap[v] = out.add_vertex(Point_3(b[0] * p[0].x() + b[1] * p[1].x() + b[2] * p[2].x(),
                                     b[0] * p[0].y() + b[1] * p[1].y() + b[2] * p[2].y(),
                                     b[0] * p[0].z() + b[1] * p[1].z() + b[2] * p[2].z()));
    rep.locations.push_back(loc[v]);
  }
  for(std::size_t f : t.faces())
    if(out.add_face(vmap[t.vertex(f, 0)], vmap[t.vertex(f, 1)], vmap[t.vertex(f, 2)]) == Mesh::null_face())
      throw Numerical_error("conformal_remesh: a face could not be added to the output mesh");
  rep.seconds_output = seconds(t0);
  return rep;
}

/// \ingroup PkgHyperbolicSurfaceMesh2Ref
/// The corner angles (radians) of a triangle mesh in R^3, for angle distributions.
template <class TriangleMesh>
std::vector<double> corner_angles(const TriangleMesh& tm)
{
  std::vector<double> r;
  const auto vpm = get(CGAL::vertex_point, tm);
  for(auto f : faces(tm))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const auto &a = get(vpm, source(h, tm)), &b = get(vpm, target(h, tm)), &c = get(vpm, target(next(h, tm), tm));
      const auto u = a - b, w = c - b;
      const double num = std::sqrt(CGAL::to_double(CGAL::cross_product(u, w).squared_length()));
      r.push_back(std::atan2(num, CGAL::to_double(u * w)));
    }
  return r;
}

} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_MESH_2_CONFORMAL_REMESH_H
