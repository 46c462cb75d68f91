// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A symmetric genus-2 test mesh: the Bolza surface.
#ifndef CGAL_DISCRETE_RICCI_FLOW_BOLZA_SURFACE_MESH_H
#define CGAL_DISCRETE_RICCI_FLOW_BOLZA_SURFACE_MESH_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <utility>

namespace CGAL {
namespace Discrete_Ricci_flow {

/*!
  \ingroup PkgDiscreteRicciFlowRef
  The double cover of the octahedron (each face cut into n^2 triangles) branched at its 6 vertices: a closed
  genus-2 triangle mesh with 16 n^2 faces. The discrete hyperbolic uniformization is unique, hence invariant
  under the 48 automorphisms of the mesh; the only genus-2 surface with 48 orientation-preserving automorphisms
  is the Bolza surface: systole 2 acosh(1 + sqrt 2) = 3.0571..., |trace| of a systole 2 + 2 sqrt 2 (the side of
  the regular octagon with angles pi/4, cosh(s/2) = cot(pi/8)). Vertices have integer coordinates n p on the
  octahedron |x| + |y| + |z| = n (vertex 0 is the branch point +x); the three branch cuts +x..+y, -x..+z,
  -y..-z are crossed by switching sheets; positions are projected to the unit sphere (both sheets alike).
  Throws `CGAL::Invalid_option_error` if n < 1.
*/
template <class Point_3>
CGAL::Surface_mesh<Point_3> make_Bolza_surface_mesh(int n)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  if(n < 1) throw CGAL::Invalid_option_error("make_Bolza_surface_mesh: n must be positive");
  Mesh m;
  typedef std::array<int, 3> IP; // integer coordinates n * p
  const IP X{n, 0, 0}, mX{-n, 0, 0}, Y{0, n, 0}, mY{0, -n, 0}, Z{0, 0, n}, mZ{0, 0, -n};
  const IP faces[8][3] = {{X, Y, Z}, {Y, mX, Z}, {mX, mY, Z}, {mY, X, Z}, {Y, X, mZ}, {mX, Y, mZ}, {mY, mX, mZ}, {X, mY, mZ}};
  auto is_branch = [&](const IP& p) { return std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]) == n &&
                                             ((p[0] != 0) + (p[1] != 0) + (p[2] != 0)) == 1; };
  // the three cuts: +x..+y (plane z = 0), -x..+z (plane y = 0), -y..-z (plane x = 0)
  auto cut_of = [&](const IP& p) {
    if(is_branch(p)) return -1;
    if(p[2] == 0 && p[0] > 0 && p[1] > 0) return 2;
    if(p[1] == 0 && p[0] < 0 && p[2] > 0) return 1;
    if(p[0] == 0 && p[1] < 0 && p[2] < 0) return 0;
    return -1;
  };
  std::map<std::pair<IP, int>, typename Mesh::Vertex_index> ids;
  auto vid = [&](const IP& p, int sheet) {
    const int s = is_branch(p) ? 0 : sheet;
    auto it = ids.find({p, s});
    if(it != ids.end()) return it->second;
    const double len = std::sqrt(double(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    // positions on the unit sphere (symmetric); the two sheets get the same positions
    auto v = m.add_vertex(Point_3(p[0] / len, p[1] / len, p[2] / len));
    ids[{p, s}] = v;
    return v;
  };
  for(int sheet = 0; sheet < 2; ++sheet)
    for(const auto& F : faces) {
      auto P = [&](int i, int j) { IP r; for(int k = 0; k < 3; ++k) r[k] = (F[0][k] * (n - i - j) + F[1][k] * i + F[2][k] * j) / n; return r; };
      auto add = [&](const IP& a, const IP& b, const IP& c) {
        const int cx = a[0] + b[0] + c[0], cy = a[1] + b[1] + c[1], cz = a[2] + b[2] + c[2];
        const int centroid[3] = {cx, cy, cz};
        std::array<typename Mesh::Vertex_index, 3> v;
        const IP* pts[3] = {&a, &b, &c};
        for(int k = 0; k < 3; ++k) {
          const int cut = cut_of(*pts[k]);
          const int bank = cut < 0 ? 0 : (centroid[cut] > 0 ? 1 : 0);
          v[k] = vid(*pts[k], sheet ^ bank);
        }
        if(m.add_face(v[0], v[1], v[2]) == Mesh::null_face()) throw std::logic_error("make_Bolza_surface_mesh: add_face failed");
      };
      for(int i = 0; i < n; ++i)
        for(int j = 0; i + j < n; ++j) {
          add(P(i, j), P(i + 1, j), P(i, j + 1));
          if(i + j + 2 <= n) add(P(i + 1, j), P(i + 1, j + 1), P(i, j + 1));
        }
    }
  return m;
}

} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif
