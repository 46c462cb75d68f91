// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A test surface whose faces use a vertex three times: the regular 4g-gon of a Regular_polygon_surface with
// all its corners identified, fanned from one corner (one vertex, 6g - 3 edges, all of them loops, 4g - 2
// faces). Used by test_one_vertex_surfaces.cpp and by the fuzz target fuzz_words.
#ifndef CGAL_HC_TEST_SSW_ONE_VERTEX_POLYGON_H
#define CGAL_HC_TEST_SSW_ONE_VERTEX_POLYGON_H

#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Surface_shortest_words/regular_polygon_surface.h>

#include <map>
#include <utility>
#include <vector>

namespace ssw_test {

// the one-vertex triangulation of the regular 4g-gon of `P` (triangles (V_0, V_k, V_k+1)), built with
// Surface_mesh's low-level functions (add_face(u, v, w) refuses faces using a vertex twice)
struct One_vertex_polygon
{
  typedef CGAL::Surface_shortest_words::Regular_polygon_surface RPS;
  typedef RPS::Mesh Mesh;
  typedef Mesh::Halfedge_index H;
  typedef Mesh::Property_map<RPS::Edge_index, double> Length_map;
  Mesh mesh;
  Length_map length;
  Mesh::Vertex_index base;
  std::vector<std::vector<H> > generators; // a1, b1, ...: the sides s_{4i-3}, s_{4i-2} (counterclockwise)

  explicit One_vertex_polygon(const RPS& P)
  {
    const int n = 4 * P.genus();
    length = mesh.add_property_map<RPS::Edge_index, double>("e:hyperbolic_length", 0.0).first;
    base = mesh.add_vertex(RPS::Point_3(0, 0, 0));
    std::map<std::pair<int, int>, H> seg; // directed polygon segment (i, j) -> halfedge (interior side)
    auto set_len = [&](H h, int i, int j) {
      length[mesh.edge(h)] = CGAL::Surface_shortest_words::internal::hyperbolic_distance(P.polygon[std::size_t(i)], P.polygon[std::size_t(j)]);
    };
    for(int k = 2; k <= n - 2; ++k) { // diagonals
      const H h = mesh.add_edge();
      seg[{0, k}] = h; seg[{k, 0}] = mesh.opposite(h); set_len(h, 0, k);
    }
    for(int q = 1; q <= n; ++q) { // sides, glued to their partners with the opposite orientation
      const int j = P.partner(q);
      if(j < q) continue;
      const H h = mesh.add_edge();
      seg[{q - 1, q % n}] = h; seg[{j - 1, j % n}] = mesh.opposite(h); set_len(h, q - 1, q % n);
    }
    for(int k = 1; k <= n - 2; ++k) {
      const H s[3] = {seg.at({0, k}), seg.at({k, k + 1}), seg.at({k + 1, 0})};
      const Mesh::Face_index f = mesh.add_face();
      for(int i = 0; i < 3; ++i) {
        mesh.set_next(s[i], s[(i + 1) % 3]);
        mesh.set_face(s[i], f);
        mesh.set_target(s[i], base);
      }
      mesh.set_halfedge(f, s[0]);
    }
    mesh.set_halfedge(base, seg.at({0, 1}));
    for(int i = 1; i <= P.genus(); ++i)
      for(int q : {4 * i - 3, 4 * i - 2}) generators.push_back(std::vector<H>(1, seg.at({q - 1, q})));
  }
};

} // namespace ssw_test

#endif // CGAL_HC_TEST_SSW_ONE_VERTEX_POLYGON_H
