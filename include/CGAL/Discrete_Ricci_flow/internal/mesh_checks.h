// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Validation of user meshes for the discrete Ricci flow: every failure throws CGAL::Invalid_mesh_error (also
// in release builds). The checks run in a fixed order so that the message names the first problem: empty,
// invalid, several connected components, not triangulated, non-manifold; the entry points then check
// closedness and genus.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_MESH_CHECKS_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_MESH_CHECKS_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <numeric>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

/// A union-find on 0 .. n-1 with path halving (no property maps: Boost's disjoint_sets on raw pointers
/// relies on an unqualified `get` that other CGAL headers can hide).
class Union_find
{
public:
  explicit Union_find(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }
  std::size_t find(std::size_t x)
  {
    while(parent_[x] != x) { parent_[x] = parent_[parent_[x]]; x = parent_[x]; }
    return x;
  }
  /// false if already in the same set
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a); b = find(b);
    if(a == b) return false;
    parent_[a] = b;
    return true;
  }
private:
  std::vector<std::size_t> parent_;
};

/// Topology of a mesh: connected components, boundary loops, Euler characteristic, genus.
struct Mesh_topology
{
  std::size_t components = 0, boundary_loops = 0;
  long euler_characteristic = 0;
  long genus = 0;
  bool closed() const { return boundary_loops == 0; }
};

/// components (through the edges), boundary loops, chi and genus of a FaceGraph; `vim` must map the vertices
/// one to one onto 0 .. n-1 (`CGAL::Invalid_option_error` otherwise: the components would be miscounted)
template <class FaceGraph, class VertexIndexMap>
Mesh_topology mesh_topology(const FaceGraph& g, VertexIndexMap vim)
{
  typedef typename boost::graph_traits<FaceGraph>::halfedge_descriptor halfedge_descriptor;
  Mesh_topology t;
  const std::size_t nv = vertices(g).size();
  std::vector<char> used(nv, 0);
  for(auto v : vertices(g)) {
    const std::size_t i = get(vim, v);
    if(i >= nv || used[i])
      throw_option_error("invalid vertex index map (not one to one onto 0 .. n-1; a Surface_mesh with removed "
                         "elements needs collect_garbage() first)");
    used[i] = 1;
  }
  Union_find uf(nv);
  for(auto e : edges(g)) uf.unite(get(vim, source(e, g)), get(vim, target(e, g)));
  for(auto v : vertices(g)) if(uf.find(get(vim, v)) == get(vim, v)) ++t.components;
  const auto him = CGAL::get_initialized_halfedge_index_map(g);
  std::vector<char> seen(halfedges(g).size(), 0);
  for(halfedge_descriptor h : halfedges(g)) {
    if(!is_border(h, g) || seen[get(him, h)]) continue;
    ++t.boundary_loops;
    std::size_t guard = 0;
    for(halfedge_descriptor k : CGAL::halfedges_around_face(h, g)) {
      seen[get(him, k)] = 1;
      if(++guard > halfedges(g).size()) throw_mesh_error("the mesh is not a valid polygon mesh");
    }
  }
  t.euler_characteristic = long(nv) - long(edges(g).size()) + long(faces(g).size());
  t.genus = (2 - t.euler_characteristic - long(t.boundary_loops)) / 2;
  return t;
}

/// the message for a mesh of several components (checked before anything that depends on the topology)
inline std::string components_message(std::size_t n)
{
  std::ostringstream os;
  os << "the mesh has " << n << " connected components (one is needed; process each component separately, "
     << "e.g. after CGAL::Polygon_mesh_processing::split_connected_components())";
  return os.str();
}

/// Throws `CGAL::Invalid_mesh_error` unless `tm` is a non-empty, valid, connected, pure triangle, manifold
/// mesh (a FaceGraph can only represent manifold edges; non-manifold vertices, i.e. several umbrellas at one
/// vertex, are detected here). Returns its topology.
template <class TriangleMesh, class VertexIndexMap>
Mesh_topology check_triangle_mesh(const TriangleMesh& tm, VertexIndexMap vim)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  if(faces(tm).size() == 0) throw_mesh_error("the mesh has no face");
  if(!CGAL::is_valid_polygon_mesh(tm)) throw_mesh_error("the mesh is not a valid polygon mesh");
  for(vertex_descriptor v : vertices(tm))
    if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      throw_mesh_error("the mesh has an isolated vertex");
  const Mesh_topology topo = mesh_topology(tm, vim);
  if(topo.components != 1) throw_mesh_error(components_message(topo.components));
  if(!CGAL::is_triangle_mesh(tm)) {
    std::size_t degree = 3;
    for(face_descriptor f : faces(tm)) {
      const std::size_t d = CGAL::halfedges_around_face(halfedge(f, tm), tm).size();
      if(d != 3) { degree = d; break; }
    }
    std::ostringstream os;
    os << "the mesh is not a pure triangle mesh (it has a face of degree " << degree
       << "); triangulate it first with CGAL::Polygon_mesh_processing::triangulate_faces()";
    throw_mesh_error(os.str());
  }
  // each vertex must have a single umbrella: the number of incoming halfedges equals the size of the cycle
  // around halfedge(v); a manifold vertex has at most one border halfedge entering it (a "bow tie" has more)
  std::size_t incoming = halfedges(tm).size(), around = 0;
  for(vertex_descriptor v : vertices(tm)) {
    std::size_t border_in = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm)) {
      ++around;
      if(CGAL::is_border(h, tm)) ++border_in;
    }
    if(border_in > 1) throw_mesh_error("the mesh has a non-manifold vertex");
  }
  if(around != incoming) throw_mesh_error("the mesh has a non-manifold vertex");
  return topo;
}

/// checks for the closed-surface entry points: a valid mesh (see above), closed, of a genus accepted by
/// `genus_ok`; `what` names the entry point and `needs` the accepted genus in the messages
template <class TriangleMesh, class VertexIndexMap, class GenusOk>
Mesh_topology check_closed_surface(const TriangleMesh& tm, VertexIndexMap vim, const std::string& what,
                                   const std::string& needs, GenusOk genus_ok)
{
  const Mesh_topology t = check_triangle_mesh(tm, vim);
  if(!t.closed()) {
    std::ostringstream os;
    os << what << " needs a closed surface (this mesh has " << t.boundary_loops << " boundary loop"
       << (t.boundary_loops > 1 ? "s" : "") << ")";
    throw_mesh_error(os.str());
  }
  if(!genus_ok(t.genus)) {
    std::ostringstream os;
    os << what << " needs " << needs << " (this surface has genus " << t.genus << ")";
    throw_mesh_error(os.str());
  }
  return t;
}

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_MESH_CHECKS_H
