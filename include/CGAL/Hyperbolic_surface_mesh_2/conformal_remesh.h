// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Conformal remeshing of a closed triangle mesh of genus >= 2: hyperbolic uniformization (discrete Ricci flow),
// Delaunay refinement on the hyperbolic surface, and the map of every output vertex back to a point of the
// input mesh (input face + barycentric coordinates), through the decorated ideal hyperbolic surface of the flow
// (internal/Ideal_surface_map.h), which undoes the flow's flips.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_CONFORMAL_REMESH_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_CONFORMAL_REMESH_H

#include <CGAL/Discrete_Ricci_flow.h>
#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_surface_2/Hyperbolic_surface_triangulation.h>
#include <CGAL/Hyperbolic_surface_mesh_2/Delaunay_triangulation_on_surface.h>
#include <CGAL/Hyperbolic_surface_mesh_2/refine_surface_mesh.h>
#include <CGAL/Hyperbolic_surface_mesh_2/internal/Ideal_surface_map.h>

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
  /// the flow needed intrinsic (Ptolemy) flips, so the intrinsic faces are not all input faces; the output
  /// vertices are mapped to the input faces through the flips all the same (see `input_locations()`)
  bool flow_used_flips = false;
  Refinement_statistics refinement;
  std::vector<Mesh_location> locations; ///< indexed like the vertices of the output mesh
  double seconds_flow = 0, seconds_triangulation = 0, seconds_refinement = 0, seconds_output = 0;
  int genus = 0;
  /// the refined triangulation of the hyperbolic surface (for pictures and further queries)
  std::shared_ptr<const Delaunay_triangulation_on_surface<> > surface;
};

namespace internal {

/// the map of `metric` (computed on `tm` with its default vertex point and index maps) back to `tm`; `m0`
/// receives the input connectivity as the flow copied it (faces in `faces(tm)` order)
template <class TriangleMesh, class Point_3>
Ideal_surface_map<Point_3> ideal_surface_map(const TriangleMesh& tm, const Discrete_Ricci_flow::Discrete_metric<Point_3>& metric,
                                             typename Discrete_Ricci_flow::Discrete_metric<Point_3>::Mesh& m0)
{
  typedef typename Discrete_Ricci_flow::Discrete_metric<Point_3>::Mesh Mesh;
  namespace DRF = Discrete_Ricci_flow::internal;
  if(metric.background_geometry() != Discrete_Ricci_flow::Background_geometry::HYPERBOLIC)
    throw Invalid_input_error("input_locations: the metric has no hyperbolic background");
  if(metric.scheme() != Discrete_Ricci_flow::Scheme::VERTEX_SCALING)
    throw Invalid_input_error("input_locations: the metric was computed with a circle-packing scheme; the map to the "
                              "input needs the vertex-scaling scheme (Scheme::VERTEX_SCALING)");
  const auto vpm = get_const_property_map(CGAL::vertex_point, tm);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<typename Mesh::Vertex_index> vmap;
  m0.clear();
  DRF::copy_connectivity(tm, vpm, vim, m0, vmap);
  const std::vector<double> len = DRF::input_lengths(tm, vpm, vim, CGAL::internal_np::Param_not_found(), m0, vmap);
  return Ideal_surface_map<Point_3>(m0, len, metric.initial_flips(), metric.flips(), metric.conformal_factors(),
                                    metric.intrinsic_mesh());
}

} // namespace internal

/*!
  \ingroup PkgHyperbolicSurfaceMesh2Ref
  The location on the input mesh `tm` of every vertex of `t`, a triangulation built with
  `Delaunay_triangulation_on_surface::from_surface_triangulation()` from the surface triangulation of
  `metric = CGAL::Ricci_flow::hyperbolic_uniformization(tm, ...)` (vertex scaling, its intrinsic mesh and edge
  lengths; with or without flips, default vertex point and index maps of `tm`). Indexed by vertex index.

  The map is the one of the flow's discrete conformal equivalence (Gillespie, Springborn and Crane 2021): a
  point of an intrinsic face with projective coordinates beta with respect to the hyperboloid lifts of its
  corners is the point with weights beta_i e^{u_i} on the corners of the decorated ideal triangle at u = 0
  (`metric.conformal_factors()`); the Ptolemy flips of the flow (`metric.flips()`), which keep that ideal
  surface, are undone in reverse order with the Gram matrix of the light-like vectors of each flipped
  quadrilateral; on the input connectivity the normalized weights are the barycentric coordinates of the
  input face (whose chord triangle at u = 0 is the input triangle); the initial geometric flips
  (`metric.initial_flips()`) are undone by unfolding. Every location is a convex combination of the corners of
  an input face, so every output vertex lies on the input surface, whether the flow flipped or not.
  The map reads `conformal_factors()` as the vertex-scaling factors u_i (lambda_ij multiplied by
  e^{(u_i + u_j) / 2}): `metric` must have been computed with `Discrete_Ricci_flow::Scheme::VERTEX_SCALING` (the
  default of `hyperbolic_uniformization()` and the scheme `conformal_remesh()` uses; `metric.scheme()`). A
  metric of a circle-packing scheme (tangential, Thurston, inversive distance) relates its lengths to the input
  through radii, not through this decoration, and is rejected.
  \throws CGAL::Invalid_input_error if `metric` is not a hyperbolic metric of the vertex-scaling scheme computed on
  `tm` (another scheme, its flips do not lead from `tm` to its intrinsic mesh, or the sizes differ) or `t` is not
  a triangulation of its surface.
*/
template <class DT, class TriangleMesh, class Point_3>
std::vector<Mesh_location> input_locations(const DT& t, const TriangleMesh& tm,
                                           const Discrete_Ricci_flow::Discrete_metric<Point_3>& metric)
{
  typedef typename Discrete_Ricci_flow::Discrete_metric<Point_3>::Mesh Mesh;
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  Mesh m0;
  const internal::Ideal_surface_map<Point_3> map = internal::ideal_surface_map(tm, metric, m0);
  // projective coordinates: Klein barycentric coordinates k_i of the chart divided by the hyperboloid height
  // (1 + |z_i|^2) / (1 - |z_i|^2) of the corner's Poincare lift z_i
  std::vector<internal::Face_point> pts;
  const std::vector<std::size_t> vs = t.vertices();
  pts.reserve(vs.size());
  for(std::size_t v : vs) {
    const auto& ref = t.vertex_reference(v);
    const auto k = t.reference().klein_barycentric(ref.reference_face, ref.point);
    const auto& z = t.reference().faces[ref.reference_face].z;
    std::array<long double, 3> beta;
    for(int i = 0; i < 3; ++i) {
      const long double n = (long double)(CGAL::to_double(z[i].x())) * CGAL::to_double(z[i].x()) +
                            (long double)(CGAL::to_double(z[i].y())) * CGAL::to_double(z[i].y());
      beta[i] = k[i] * (1 - n) / (1 + n);
    }
    pts.push_back(map.from_final(ref.reference_face, beta));
  }
  map.to_input(pts);
  // barycentric coordinates with respect to the corners of halfedge(f) in tm (the copy has the same corners)
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> fs;
  for(auto f : faces(tm)) fs.push_back(f);
  std::vector<Mesh_location> r(t.vertex_capacity());
  for(std::size_t i = 0; i < vs.size(); ++i) {
    const std::size_t f = pts[i].face;
    std::size_t c0[3], c1[3];
    auto a = m0.halfedge(typename Mesh::Face_index(typename Mesh::size_type(f)));
    auto b = halfedge(fs[f], tm);
    for(int j = 0; j < 3; ++j, a = m0.next(a), b = next(b, tm)) { c0[j] = std::size_t(m0.source(a)); c1[j] = get(vim, source(b, tm)); }
    Mesh_location& l = r[vs[i]];
    l.face = f;
    for(int k = 0; k < 3; ++k) {
      int j = 0;
      while(j < 3 && c0[j] != c1[k]) ++j;
      if(j == 3) throw Numerical_error("input_locations: the copied input face has other corners than the input face");
      l.barycentric[k] = double(pts[i].w[j]);
    }
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
     Ptolemy flips (`report.flow_used_flips`);
  2. the Delaunay triangulation of the hyperbolic surface with the input vertices, then generalized Ruppert
     (default) or Chew refinement (`parameters::use_Chew(true)`) with the options of `refine_Ruppert()`
     (`maximum_circumradius` required);
  3. every output vertex mapped to a point of an input face (`input_locations()`, which undoes the flips of
     the flow), the output faces added to `out` (a `CGAL::Surface_mesh<Point_3>`, cleared first).
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
  const std::vector<Mesh_location> loc = input_locations(t, tm, metric);
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> input_faces;
  for(auto f : faces(tm)) input_faces.push_back(f);
  const auto vpm = get_const_property_map(CGAL::vertex_point, tm);
  out.clear();
  std::vector<typename Mesh::Vertex_index> vmap(t.vertex_capacity());
  for(std::size_t v : t.vertices()) {
    const auto h0 = halfedge(input_faces[loc[v].face], tm);
    const Point_3 p[3] = {get(vpm, source(h0, tm)), get(vpm, source(next(h0, tm), tm)), get(vpm, source(prev(h0, tm), tm))};
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
