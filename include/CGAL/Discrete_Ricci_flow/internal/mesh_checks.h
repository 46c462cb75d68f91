// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Validation of user meshes for the discrete Ricci flow: every failure is reported as a Ricci_flow_error
// (also in release builds).
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_MESH_CHECKS_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_MESH_CHECKS_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Surface_mesh.h>

#include <boost/pending/disjoint_sets.hpp>

#include <sstream>
#include <vector>

namespace CGAL {
namespace Ricci_flow {
namespace internal {

/// Topology of a Surface_mesh: connected components, boundary loops, Euler characteristic, genus.
struct Mesh_topology
{
  std::size_t components = 0, boundary_loops = 0;
  long euler_characteristic = 0;
  long genus = 0;
  bool closed() const { return boundary_loops == 0; }
};

template <class Mesh>
Mesh_topology mesh_topology(const Mesh& m)
{
  typedef typename Mesh::Vertex_index V;
  Mesh_topology t;
  const std::size_t nv = m.number_of_vertices();
  std::vector<std::size_t> rank(nv, 0), parent(nv);
  boost::disjoint_sets<std::size_t*, std::size_t*> ds(rank.data(), parent.data());
  for(V v : m.vertices()) ds.make_set(std::size_t(v));
  for(auto e : m.edges()) ds.union_set(std::size_t(m.vertex(e, 0)), std::size_t(m.vertex(e, 1)));
  for(V v : m.vertices()) if(ds.find_set(std::size_t(v)) == std::size_t(v)) ++t.components;
  std::vector<char> seen(m.number_of_halfedges(), 0);
  for(auto h : m.halfedges()) {
    if(!m.is_border(h) || seen[h]) continue;
    ++t.boundary_loops;
    for(auto g : CGAL::halfedges_around_face(h, m)) seen[g] = 1;
  }
  t.euler_characteristic = long(nv) - long(m.number_of_edges()) + long(m.number_of_faces());
  t.genus = (2 - t.euler_characteristic - long(t.boundary_loops)) / 2;
  return t;
}

/// Throws unless `tm` is a pure, manifold triangle mesh (a FaceGraph can only represent manifold edges;
/// non-manifold vertices, i.e. several umbrellas at one vertex, are detected here).
template <class TriangleMesh>
void check_triangle_mesh(const TriangleMesh& tm)
{
  if(faces(tm).size() == 0) throw Ricci_flow_error("the mesh has no face");
  if(!CGAL::is_triangle_mesh(tm)) throw Ricci_flow_error("the mesh is not a pure triangle mesh");
  if(!CGAL::is_valid_polygon_mesh(tm)) throw Ricci_flow_error("the mesh is not a valid polygon mesh");
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  // each vertex must have a single umbrella: the number of incoming halfedges equals the size of the cycle
  // around halfedge(v)
  std::size_t incoming = 0, around = 0;
  for(halfedge_descriptor h : halfedges(tm)) { (void)h; ++incoming; }
  for(vertex_descriptor v : vertices(tm)) {
    if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      throw Ricci_flow_error("the mesh has an isolated vertex");
    // a manifold vertex has at most one border halfedge entering it; several umbrellas joined through the
    // border (a "bow tie") have more
    std::size_t border_in = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm)) {
      ++around;
      if(CGAL::is_border(h, tm)) ++border_in;
    }
    if(border_in > 1) throw Ricci_flow_error("the mesh has a non-manifold vertex");
  }
  if(around != incoming) throw Ricci_flow_error("the mesh has a non-manifold vertex");
}

} // namespace internal
} // namespace Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_MESH_CHECKS_H
