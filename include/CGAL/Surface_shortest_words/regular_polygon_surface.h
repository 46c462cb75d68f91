// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A closed hyperbolic surface of genus g built from the regular hyperbolic 4g-gon with angles pi/(2g), its
// sides glued by the canonical pairing a1 b1 a1^-1 b1^-1 ... ag bg ag^-1 bg^-1, triangulated geodesically.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_REGULAR_POLYGON_SURFACE_H
#define CGAL_SURFACE_SHORTEST_WORDS_REGULAR_POLYGON_SURFACE_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Surface_shortest_words/internal/layout.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_shortest_words {

/*!
  \ingroup PkgSurfaceShortestWordsRef
  A closed hyperbolic surface with an exactly known geometry, for tests, examples and benchmarks.

  The regular hyperbolic 4g-gon P with interior angles pi/(2g) (cosh R = cot^2(pi/4g) for its circumradius
  R; side s with cosh(s/2) = cot(pi/4g)) has its sides s_1 ... s_4g (counterclockwise, s_k from V_{k-1} to
  V_k) glued by the canonical pairing: s_{4i-3} = a_i, s_{4i-2} = b_i, s_{4i-1} = a_i^-1, s_{4i} = b_i^-1.
  Every fan triangle (centre, V_k, V_{k+1}) is subdivided into m^2 triangles by an affine grid in Klein
  coordinates (straight lines are geodesics there); edge lengths are hyperbolic distances. All 4g corners
  become one vertex p (angle sum 4g * pi/(2g) = 2 pi), so the metric is hyperbolic at every vertex up to
  rounding. The sides are edge loops through p forming a canonical system of loops with relator
  [a1,b1]...[ag,bg] in the convention of `Shortest_word_solver`.

  The side-pairing isometries give the holonomy `rho` of pi_1(S, p) in the Poincare disk, an independent
  representation used by the tests (`rho_generator(2i)` = rho(a_{i+1}), `rho_generator(2i+1)` = rho(b_{i+1});
  the lift of p at V_0 is the base of the lifts).

  The mesh has 4g m^2 faces; `m >= 3` is required (for a simplicial mesh). Cost: O(g m^2 log(g m^2)).
*/
class Regular_polygon_surface
{
public:
  typedef CGAL::Epick::Point_3 Point_3;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef Mesh::Vertex_index Vertex_index;
  typedef Mesh::Halfedge_index Halfedge_index;
  typedef Mesh::Face_index Face_index;
  typedef Mesh::Edge_index Edge_index;
  typedef CGAL::Poincare_disk_isometry_2<CGAL::Epick> Isometry; ///< isometries of the Poincare disk
  typedef std::complex<double> Cplx;                           ///< points of the Poincare disk

  Mesh mesh;
  Mesh::Property_map<Edge_index, double> length;
  Vertex_index base;                                  ///< the vertex p (all polygon corners)
  std::vector<std::vector<Halfedge_index> > generators; ///< a1, b1, a2, b2, ... as halfedge loops from p
  std::vector<Cplx> polygon;                          ///< V_0 ... V_{4g-1} in the Poincare disk
  std::map<Face_index, std::array<Cplx, 3> > face_positions; ///< positions of source(halfedge(f)), target, next target

  /// builds the surface of genus `g >= 2` with subdivision `m >= 3`; throws `CGAL::Invalid_option_error` otherwise
  Regular_polygon_surface(int g, int m) : g_(g), m_(m)
  {
    if(g < 2) throw CGAL::Invalid_option_error("Regular_polygon_surface: genus must be >= 2");
    if(m < 3) throw CGAL::Invalid_option_error("Regular_polygon_surface: subdivision must be >= 3");
    const int n = 4 * g;
    const double coshR = std::pow(1.0 / std::tan(CGAL_PI / n), 2);
    const double r = std::tanh(std::acosh(coshR) / 2.0);
    for(int k = 0; k < n; ++k) polygon.push_back(std::polar(r, 2.0 * CGAL_PI * k / n));
    length = mesh.add_property_map<Edge_index, double>("e:hyperbolic_length", 0.0).first;
    build();
    build_holonomy();
  }

  int genus() const { return g_; }
  int subdivision() const { return m_; }

  /// side length of the polygon (length of every generator loop): cosh(s/2) = cot(pi/4g)
  double side_length() const { return 2.0 * std::acosh(1.0 / std::tan(CGAL_PI / (4 * g_))); }

  /// the side-pairing isometry T_k (k = 1..4g) taking the partner side of s_k onto s_k, P to its neighbour
  const Isometry& side_pairing(int k) const { return pairings_[k - 1]; }

  /// rho(a_{i/2+1}) for even i, rho(b_{i/2+1}) for odd i: the deck transformation of the generator loop
  const Isometry& rho_generator(int i) const { return rho_[i]; }

  /// index (1-based) of the partner side of side k
  int partner(int k) const
  {
    const int r = (k - 1) % 4;
    return r < 2 ? k + 2 : k - 2;
  }

private:
  static Cplx klein_grid(const Cplx& A, const Cplx& B, int a, int b, int m)
  { return (double(a) / m) * A + (double(b) / m) * B; }

  // canonical vertex key of grid point (a, b) of fan triangle k (centre, V_k, V_{k+1})
  std::tuple<int, int, int> key(int k, int a, int b) const
  {
    const int n = 4 * g_, m = m_;
    if(a == 0 && b == 0) return std::make_tuple(-1, 0, 0);            // centre
    if((a == m && b == 0) || (a == 0 && b == m)) return std::make_tuple(-2, 0, 0); // a corner: p
    if(b == 0) return std::make_tuple(-3, k, a);                        // ray to V_k
    if(a == 0) return std::make_tuple(-3, (k + 1) % n, b);              // ray to V_{k+1}
    if(a + b == m) {
      // side s_q, q = k + 1, from V_k to V_{k+1}; index b from V_k
      const int q = k + 1, j = partner(q);
      if(q < j) return std::make_tuple(-4, q, b);
      return std::make_tuple(-4, j, m - b);
    }
    return std::make_tuple(k, a, b);
  }

  void build()
  {
    const int n = 4 * g_, m = m_;
    std::map<std::tuple<int, int, int>, Vertex_index> ids;
    auto vid = [&](int k, int a, int b) {
      const auto kk = key(k, a, b);
      auto it = ids.find(kk);
      if(it != ids.end()) return it->second;
      const Cplx z = internal::from_klein(klein_grid(internal::to_klein(polygon[k]), internal::to_klein(polygon[(k + 1) % n]), a, b, m));
      const Vertex_index v = mesh.add_vertex(Point_3(z.real(), z.imag(), 0));
      ids.emplace(kk, v);
      return v;
    };
    for(int k = 0; k < n; ++k) {
      const Cplx A = internal::to_klein(polygon[k]), B = internal::to_klein(polygon[(k + 1) % n]);
      auto pos = [&](int a, int b) { return internal::from_klein(klein_grid(A, B, a, b, m)); };
      auto add = [&](int a0, int b0, int a1, int b1, int a2, int b2) {
        const Vertex_index v0 = vid(k, a0, b0), v1 = vid(k, a1, b1), v2 = vid(k, a2, b2);
        const Face_index f = mesh.add_face(v0, v1, v2);
        if(f == Mesh::null_face()) throw std::runtime_error("Regular_polygon_surface: non-manifold construction");
        const Cplx z[3] = {pos(a0, b0), pos(a1, b1), pos(a2, b2)};
        // store positions in the order of halfedge(f)
        Halfedge_index h = mesh.halfedge(f);
        std::array<Cplx, 3> fp;
        for(int i = 0; i < 3; ++i, h = mesh.next(h)) {
          const Vertex_index s = mesh.source(h);
          fp[i] = s == v0 ? z[0] : (s == v1 ? z[1] : z[2]);
          const Vertex_index t = mesh.target(h);
          const Cplx zt = t == v0 ? z[0] : (t == v1 ? z[1] : z[2]);
          length[mesh.edge(h)] = internal::hyperbolic_distance(fp[i], zt);
        }
        face_positions[f] = fp;
      };
      for(int a = 0; a < m; ++a)
        for(int b = 0; a + b < m; ++b) {
          add(a, b, a + 1, b, a, b + 1);
          if(a + b + 2 <= m) add(a + 1, b, a + 1, b + 1, a, b + 1);
        }
    }
    base = ids.at(std::make_tuple(-2, 0, 0));
    // generators: a_i = s_{4i-3}, b_i = s_{4i-2}, traversed from V_{q-1} to V_q
    for(int i = 1; i <= g_; ++i)
      for(int q : {4 * i - 3, 4 * i - 2}) {
        const int k = q - 1; // fan triangle k holds side q: grid points (m - b, b), b = 0..m
        std::vector<Halfedge_index> loop;
        for(int b = 0; b < m; ++b) {
          const Vertex_index u = vid(k, m - b, b), v = vid(k, m - b - 1, b + 1);
          const Halfedge_index h = mesh.halfedge(u, v);
          if(h == Mesh::null_halfedge()) throw std::runtime_error("Regular_polygon_surface: missing side edge");
          loop.push_back(h);
        }
        generators.push_back(loop);
      }
  }

  // isometry taking the oriented geodesic segment (a -> b) to (c -> d) (equal lengths)
  static Isometry segment_map(const Cplx& a, const Cplx& b, const Cplx& c, const Cplx& d)
  {
    return internal::frame(c, d).inverse() * internal::frame(a, b);
  }

  void build_holonomy()
  {
    const int n = 4 * g_;
    auto V = [&](int k) { return polygon[((k % n) + n) % n]; };
    for(int k = 1; k <= n; ++k) {
      const int j = partner(k);
      // side j runs from V_{j-1} to V_j backwards along the loop: V_j -> V_{j-1} maps onto V_{k-1} -> V_k
      pairings_.push_back(segment_map(V(j), V(j - 1), V(k - 1), V(k)).normalized());
    }
    // prefixes E_k = rho(s_1 ... s_k): E_{4i-1} = T_{4i-1} E_{4i-4}, E_{4i-2} = T_{4i-2} E_{4i-1},
    // E_{4i-3} = T_{4i-3} E_{4i-2}, E_{4i} = T_{4i} E_{4i-3}
    std::vector<Isometry> E(n + 1);
    for(int i = 1; i <= g_; ++i) {
      E[4 * i - 1] = (pairings_[4 * i - 2] * E[4 * i - 4]).normalized();
      E[4 * i - 2] = (pairings_[4 * i - 3] * E[4 * i - 1]).normalized();
      E[4 * i - 3] = (pairings_[4 * i - 4] * E[4 * i - 2]).normalized();
      E[4 * i] = (pairings_[4 * i - 1] * E[4 * i - 3]).normalized();
    }
    for(int i = 1; i <= g_; ++i) {
      rho_.push_back((E[4 * i - 4].inverse() * E[4 * i - 3]).normalized()); // a_i = s_{4i-3}
      rho_.push_back((E[4 * i - 3].inverse() * E[4 * i - 2]).normalized()); // b_i = s_{4i-2}
    }
    prefix_ = E;
  }

  int g_, m_;
  std::vector<Isometry> pairings_, rho_, prefix_;
};

} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_REGULAR_POLYGON_SURFACE_H
