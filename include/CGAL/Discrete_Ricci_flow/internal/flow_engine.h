// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Newton solver of the discrete Ricci flow (thesis Algorithm 1) on an intrinsic triangulation stored in a
// CGAL::Surface_mesh, with Ptolemy flips keeping it intrinsically Delaunay (Gu-Guo-Luo-Sun-Wu 2018,
// Springborn 2020) and a line search on the convex energy.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_FLOW_ENGINE_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_FLOW_ENGINE_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/Discrete_Ricci_flow/internal/triangle_geometry.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

template <class Point_3>
class Flow_engine
{
public:
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Vertex_index V;
  typedef typename Mesh::Halfedge_index H;
  typedef typename Mesh::Edge_index E;
  typedef typename Mesh::Face_index F;

  Mesh& m;
  Background_geometry geo;
  Scheme scheme;
  bool use_flips;
  // vertex scaling: Penner coordinate lambda0 of each edge at u = 0 (changed only by Ptolemy flips);
  // circle packings: inversive distance I of each edge.
  std::vector<double> edge_data;
  std::vector<double> u, target, len, K;
  std::vector<double> angle; // per halfedge: the corner angle opposite to it in its face (cache)
  std::vector<char> v_is_border, e_is_border;
  std::size_t flips = 0, max_flips = 0;
  int pattern_version = 0;
  std::vector<E> flip_queue;
  // geometric mode (E^2, vertex scaling, u = 0): flips keep the piecewise-linear metric (the new diagonal of the
  // unfolded quad, law of cosines) instead of applying Ptolemy; used to make the input intrinsically Delaunay
  bool geometric_flips = false;
  std::vector<E> flip_log; // edges flipped, in order
  std::vector<char> in_queue;

  Flow_engine(Mesh& mesh, Background_geometry g, Scheme s, bool flips_on)
    : m(mesh), geo(g), scheme(s), use_flips(flips_on && s == Scheme::VERTEX_SCALING)
  {
    const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges();
    u.assign(nv, 0.0); target.assign(nv, 0.0); K.assign(nv, 0.0); len.assign(ne, 0.0);
    edge_data.assign(ne, 0.0);
    v_is_border.assign(nv, 0); e_is_border.assign(ne, 0);
    for(E e : m.edges()) if(m.is_border(e)) {
      e_is_border[e] = 1; v_is_border[m.vertex(e, 0)] = 1; v_is_border[m.vertex(e, 1)] = 1;
    }
    in_queue.assign(ne, 0);
    angle.assign(m.number_of_halfedges(), 0.0);
    max_flips = 200 * ne + 1000;
  }

  // ------------------------------------------------------------ lengths
  double edge_length(E e) const
  {
    const V a = m.vertex(e, 0), b = m.vertex(e, 1);
    if(scheme == Scheme::VERTEX_SCALING)
      return length_from_lambda(geo, std::exp(0.5 * (u[a] + u[b])) * edge_data[e]);
    double d1, d2;
    return circle_packing_length(geo, radius_from_u(geo, u[a]), radius_from_u(geo, u[b]), edge_data[e], d1, d2);
  }

  void compute_lengths()
  {
    for(E e : m.edges()) len[e] = edge_length(e);
  }

  // d l_e / d u_v for v = the source (first) and target (second) of halfedge h
  void length_derivatives(H h, double& d_source, double& d_target) const
  {
    const E e = m.edge(h);
    if(scheme == Scheme::VERTEX_SCALING) {
      d_source = d_target = vertex_scaling_length_derivative(geo, len[e]);
      return;
    }
    const V a = m.source(h), b = m.target(h);
    const double ra = radius_from_u(geo, u[a]), rb = radius_from_u(geo, u[b]);
    double dla, dlb;
    circle_packing_length(geo, ra, rb, edge_data[e], dla, dlb);
    d_source = dla * radius_derivative(geo, ra);
    d_target = dlb * radius_derivative(geo, rb);
  }

  // halfedges h0, h1, h2 of a face, lengths l[i] = len(h_i), corner i (opposite h_i) = target(h_{i+1})
  void face_data(H h0, H hs[3], V cs[3], double l[3]) const
  {
    hs[0] = h0; hs[1] = m.next(h0); hs[2] = m.next(hs[1]);
    for(int i = 0; i < 3; ++i) { l[i] = len[m.edge(hs[i])]; cs[i] = m.target(hs[(i + 1) % 3]); }
  }

  // recompute the cached angles of face f
  void update_face_angles(F f)
  {
    H hs[3]; V cs[3]; double l[3], th[3];
    face_data(m.halfedge(f), hs, cs, l);
    triangle_angles_only(geo, l, th);
    for(int i = 0; i < 3; ++i) angle[hs[i]] = th[i];
  }

  void compute_angles()
  {
    for(F f : m.faces()) update_face_angles(f);
  }

  // ------------------------------------------------------------ intrinsic Delaunay flips
  // angle at the corner opposite to halfedge h, and the two angles at the ends of h, in face(h)
  void angles_at(H h, double& opposite, double& at_ends) const
  {
    opposite = angle[h]; at_ends = angle[m.next(h)] + angle[m.prev(h)];
  }

  // edge ij is Delaunay iff a + a' <= b + c + b' + c' (a, a' the angles facing the edge; b, c, b', c' the other
  // angles of both triangles); in E^2 this is a + a' <= pi (GGLSW 2018, Definition 1.1).
  bool is_delaunay(E e) const
  {
    if(e_is_border[e]) return true;
    const H h = m.halfedge(e), o = m.opposite(h);
    if(m.face(h) == m.face(o)) return true; // cannot flip an edge with the same face on both sides
    double a1, b1, a2, b2;
    angles_at(h, a1, b1);
    angles_at(o, a2, b2);
    return a1 + a2 <= b1 + b2 + 1e-12;
  }

  // Ptolemy flip of edge e = (a b), faces (a b c) and (b a d): new edge (c d) with
  // lambda_cd lambda_ab = lambda_ac lambda_bd + lambda_ad lambda_bc (lambda0 suffices: the relation is
  // equivariant under vertex scaling).
  void flip(E e)
  {
    const H h = m.halfedge(e), o = m.opposite(h);
    const H h1 = m.next(h), h2 = m.next(h1), o1 = m.next(o), o2 = m.next(o1);
    const F fh = m.face(h), fo = m.face(o);
    const V a = m.target(o), b = m.target(h), c = m.target(h1), d = m.target(o1);
    // h1: b->c, h2: c->a, o1: a->d, o2: d->b
    const double lab = edge_data[e], lbc = edge_data[m.edge(h1)], lca = edge_data[m.edge(h2)],
                 lad = edge_data[m.edge(o1)], ldb = edge_data[m.edge(o2)];
    if(geometric_flips) {
      // the diagonal c-d of the quad unfolded along a-b: angle at a = angle(c a b) + angle(b a d)
      const double theta_a = angle[h1] + angle[o2];
      const double lac = len[m.edge(h2)], lad_ = len[m.edge(o1)];
      const double lcd2 = lac * lac + lad_ * lad_ - 2 * lac * lad_ * std::cos(theta_a);
      edge_data[e] = 0.5 * std::sqrt(lcd2 > 0 ? lcd2 : 0.0);
    } else
      edge_data[e] = (lca * ldb + lad * lbc) / lab;
    flip_log.push_back(e);
    // rewire: h: d->c in face (h, h2, o1); o: c->d in face (o, o2, h1)
    if(m.halfedge(a) == o) m.set_halfedge(a, h2);
    if(m.halfedge(b) == h) m.set_halfedge(b, o2);
    m.set_target(h, c); m.set_target(o, d);
    m.set_next(h, h2); m.set_next(h2, o1); m.set_next(o1, h);
    m.set_next(o, o2); m.set_next(o2, h1); m.set_next(h1, o);
    m.set_face(o1, fh); m.set_face(h1, fo);
    m.set_halfedge(fh, h); m.set_halfedge(fo, o);
    len[e] = edge_length(e);
    update_face_angles(fh); update_face_angles(fo);
    ++flips; ++pattern_version;
  }

  void push(E e) { if(!in_queue[e] && !e_is_border[e]) { in_queue[e] = 1; flip_queue.push_back(e); } }

  // flips until every edge is Delaunay; false if the flip budget is exhausted
  bool make_delaunay()
  {
    if(!use_flips) return true;
    for(E e : m.edges()) push(e);
    while(!flip_queue.empty()) {
      const E e = flip_queue.back(); flip_queue.pop_back(); in_queue[e] = 0;
      if(is_delaunay(e)) continue;
      if(flips >= max_flips) { flip_queue.clear(); std::fill(in_queue.begin(), in_queue.end(), 0); return false; }
      flip(e);
      const H h = m.halfedge(e), o = m.opposite(h);
      push(m.edge(m.next(h))); push(m.edge(m.prev(h))); push(m.edge(m.next(o))); push(m.edge(m.prev(o)));
    }
    return true;
  }

  // ------------------------------------------------------------ curvature and Hessian
  // K_i = 2 pi - sum of angles (interior), pi - sum of angles (border: geodesic curvature)
  void compute_curvature()
  {
    // uses the cached angles (compute_angles() or the flips keep them up to date)
    for(V v : m.vertices()) K[v] = v_is_border[v] ? CGAL_PI : 2 * CGAL_PI;
    for(H h : m.halfedges())
      if(!m.is_border(h)) K[m.target(m.next(h))] -= angle[h];
  }

  // true if a face violates a triangle inequality (its angles are Luo's extension (pi, 0, 0))
  bool has_degenerate_face() const
  {
    for(F f : m.faces()) {
      H hs[3]; V cs[3]; double l[3];
      face_data(m.halfedge(f), hs, cs, l);
      for(int i = 0; i < 3; ++i) if(!(l[i] < l[(i + 1) % 3] + l[(i + 2) % 3])) return true;
      if(geo == Background_geometry::SPHERICAL && !(l[0] + l[1] + l[2] < 2 * CGAL_PI)) return true;
    }
    return false;
  }

  double total_area() const
  {
    double a = 0;
    for(F f : m.faces()) {
      H hs[3]; V cs[3]; double l[3], th[3], dth[3][3];
      face_data(m.halfedge(f), hs, cs, l);
      triangle_angles(geo, l, th, dth);
      a += triangle_area(geo, l, th);
    }
    return a;
  }

  // triplets of dK/du (symmetric positive semi-definite for E^2 / H^2 vertex scaling); needs the cached
  // angles (compute_angles())
  void hessian_triplets(std::vector<Eigen::Triplet<double> >& t) const
  {
    t.clear();
    t.reserve(9 * m.number_of_faces());
    for(F f : m.faces()) {
      // uses the cached angles; a degenerate triangle (extended angles pi, 0, 0) contributes nothing
      H hs[3]; V cs[3]; double l[3], th[3], dth[3][3];
      face_data(m.halfedge(f), hs, cs, l);
      bool degenerate = false;
      for(int i = 0; i < 3; ++i) { th[i] = angle[hs[i]]; if(!(l[i] < l[(i + 1) % 3] + l[(i + 2) % 3])) degenerate = true; }
      // a degenerate triangle contributes explicit zeros: the sparsity pattern depends only on the connectivity
      // (the symbolic analysis is reused until a flip changes it)
      if(degenerate) { for(int i = 0; i < 3; ++i) for(int a = 0; a < 3; ++a) t.emplace_back(int(cs[i]), int(cs[a]), 0.0); continue; }
      triangle_angle_derivatives(geo, l, th, dth);
      // dl[j][a]: d l_j / d u at corner a (edge j joins corners j+1 = source(h_j)... see face_data)
      double dl[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      for(int j = 0; j < 3; ++j) {
        double ds, dt;
        length_derivatives(hs[j], ds, dt);
        dl[j][(j + 1) % 3] = ds; // source(h_j) = corner j+1
        dl[j][(j + 2) % 3] = dt; // target(h_j) = corner j+2
      }
      for(int i = 0; i < 3; ++i)
        for(int a = 0; a < 3; ++a) {
          double d = 0;
          for(int j = 0; j < 3; ++j) d += dth[i][j] * dl[j][a];
          t.emplace_back(int(cs[i]), int(cs[a]), -d);
        }
    }
  }
};

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_FLOW_ENGINE_H
