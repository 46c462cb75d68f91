// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shortest paths in the dual graph of a closed triangle mesh, for cut graphs that leave a compact disk: the
// fundamental domain of the Ricci-flow embedding and the compact homotopy basis of the layer grow their disk
// with this tree.
#ifndef CGAL_HYPERBOLIC_SURFACE_2_INTERNAL_DUAL_SHORTEST_PATH_TREE_H
#define CGAL_HYPERBOLIC_SURFACE_2_INTERNAL_DUAL_SHORTEST_PATH_TREE_H

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_surface_2 {
namespace internal {

/// Dijkstra on the dual graph of the closed triangle mesh `tm` from face `faces[source]`. Two faces f and g
/// adjacent across the edge of a halfedge h with `allowed(h)` are (perimeter(f) + perimeter(g)) / 6 apart (about
/// the distance of their barycentres), the perimeters being `perimeter[face_id(f)]`. `faces[i]` is the face
/// with `face_id(faces[i]) == i`. Fills `distance` (infinity for the faces not reached) and `via`: the
/// halfedge of the face's parent through which the tree reaches it (null for the source and the faces not
/// reached). Ties are broken by the face id. Cost O(n log n).
template <class TriangleMesh, class FaceId, class Allowed>
void dual_shortest_path_tree(const TriangleMesh& tm,
                             const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
                             const FaceId& face_id, const std::vector<double>& perimeter, std::size_t source,
                             const Allowed& allowed, std::vector<double>& distance,
                             std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& via)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const std::size_t nf = faces.size();
  distance.assign(nf, std::numeric_limits<double>::infinity());
  via.assign(nf, GT::null_halfedge());
  std::vector<char> done(nf, 0);
  typedef std::pair<double, std::size_t> QE;
  std::priority_queue<QE, std::vector<QE>, std::greater<QE> > pq;
  distance[source] = 0;
  pq.push(QE(0.0, source));
  while(!pq.empty()) {
    const QE top = pq.top(); pq.pop();
    const std::size_t f = top.second;
    if(done[f]) continue;
    done[f] = 1;
    for(typename GT::halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(faces[f], tm), tm)) {
      if(!allowed(h)) continue;
      const std::size_t g = face_id(face(opposite(h, tm), tm));
      const double d = distance[f] + (perimeter[f] + perimeter[g]) / 6;
      if(!done[g] && d < distance[g]) { distance[g] = d; via[g] = h; pq.push(QE(d, g)); }
    }
  }
}

} // namespace internal
} // namespace Hyperbolic_surface_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_2_INTERNAL_DUAL_SHORTEST_PATH_TREE_H
