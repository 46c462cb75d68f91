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

/// The connectivity change of a flip of edge e = (a b), faces (a b c) and (b a d), with h = halfedge(e): a -> b,
/// h1 = next(h), h2 = next(h1), o = opposite(h), o1 = next(o), o2 = next(o1). Afterwards h: d -> c and
/// o: c -> d; face(h) is (h, h2, o1) = (d c a) and face(o) is (o, o2, h1) = (c d b), with halfedge(face(h)) = h
/// and halfedge(face(o)) = o; no other element changes. Replaying a flip log with this function on a copy of
/// the mesh the log started from reproduces every intermediate mesh exactly (same indices).
template <class Mesh>
void flip_connectivity(Mesh& m, typename Mesh::Edge_index e)
{
  const auto h = m.halfedge(e), o = m.opposite(h);
  const auto h1 = m.next(h), h2 = m.next(h1), o1 = m.next(o), o2 = m.next(o1);
  const auto fh = m.face(h), fo = m.face(o);
  const auto a = m.target(o), b = m.target(h), c = m.target(h1), d = m.target(o1);
  if(m.halfedge(a) == o) m.set_halfedge(a, h2);
  if(m.halfedge(b) == h) m.set_halfedge(b, o2);
  m.set_target(h, c); m.set_target(o, d);
  m.set_next(h, h2); m.set_next(h2, o1); m.set_next(o1, h);
  m.set_next(o, o2); m.set_next(o2, h1); m.set_next(h1, o);
  m.set_face(o1, fh); m.set_face(h1, fo);
  m.set_halfedge(fh, h); m.set_halfedge(fo, o);
}

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
  // vertex scaling: per edge, x_e = lambda0_e e^{(u_a + u_b) / 2} (= sinh, sin (l_e / 2), l_e / 2), cached by
  // compute_lengths() and flip() so that the face functions take no exp. The lengths themselves are not cached
  // (`len` stays empty): `length()` takes them from x, and the face functions need them only for faces close
  // to degenerate (see `clearly_proper()`), which saves an asinh (asin) per edge and evaluation
  std::vector<double> x;
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
  // while `record_undo`: the flips made since, each with the edge's Penner coordinate and the halfedge anchors
  // of its two faces and two ends before it, so that `undo_flips()` can return to the triangulation of that
  // moment (a Newton step's start) exactly, face anchors included (they fix the corner order of the face
  // functions, hence their rounding)
  struct Undo_record { E e; double lambda; F f[2]; H fh[2]; V v[2]; H vh[2]; };
  bool record_undo = false;
  std::vector<Undo_record> undo_log;

  Flow_engine(Mesh& mesh, Background_geometry g, Scheme s, bool flips_on)
    : m(mesh), geo(g), scheme(s), use_flips(flips_on && s == Scheme::VERTEX_SCALING)
  {
    const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges();
    u.assign(nv, 0.0); target.assign(nv, 0.0); K.assign(nv, 0.0);
    if(scheme == Scheme::VERTEX_SCALING) x.assign(ne, 0.0); else len.assign(ne, 0.0);
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
  // vertex scaling: x_e at the current u (see `x`)
  double scaled_lambda(E e) const
  {
    return edge_data[e] * std::exp(0.5 * (u[m.vertex(e, 0)] + u[m.vertex(e, 1)]));
  }

  // x (vertex scaling) or len (circle packings) of edge e from the current u and edge_data
  void update_length(E e)
  {
    if(scheme == Scheme::VERTEX_SCALING) { x[e] = scaled_lambda(e); return; }
    const V a = m.vertex(e, 0), b = m.vertex(e, 1);
    double d1, d2;
    len[e] = circle_packing_length(geo, radius_from_u(geo, u[a]), radius_from_u(geo, u[b]), edge_data[e], d1, d2);
  }

  // the lengths (x) at the current u: after every change of u, before the face functions
  void compute_lengths()
  {
    for(E e : m.edges()) update_length(e);
  }

  // the length of edge e at the current u (after compute_lengths())
  double length(E e) const
  {
    return scheme == Scheme::VERTEX_SCALING ? length_from_lambda(geo, x[e]) : len[e];
  }

  // d l_e / d u_v for v = the source (first) and target (second) of halfedge h
  void length_derivatives(H h, double& d_source, double& d_target) const
  {
    const E e = m.edge(h);
    if(scheme == Scheme::VERTEX_SCALING) {
      d_source = d_target = vertex_scaling_length_derivative(geo, length(e));
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
    for(int i = 0; i < 3; ++i) { l[i] = length(m.edge(hs[i])); cs[i] = m.target(hs[(i + 1) % 3]); }
  }

  // the halfedges and corners of face_data(), without the lengths
  void face_corners(H h0, H hs[3], V cs[3]) const
  {
    hs[0] = h0; hs[1] = m.next(h0); hs[2] = m.next(hs[1]);
    for(int i = 0; i < 3; ++i) cs[i] = m.target(hs[(i + 1) % 3]);
  }

  // vertex scaling: whether the face with x and the Gram quantity Q of `algebraic_gram()` passes
  // `triangle_is_proper()` without computing its lengths. Q is a positive multiple of
  // sinh (sin, -) s sinh (s - l_0) sinh (s - l_1) sinh (s - l_2), s the half perimeter, so it vanishes when a
  // triangle inequality (or, S^2, perimeter < 2 pi) is tight; a face that fails the test in floating point
  // is within a few ulps of that, so its `properness_ratio()` is tiny: at most about 1e-11 by the rounding of
  // its lengths, at most 1.4e-14 measured (test `clearly_proper_faces_pass_the_length_test`, 600k
  // near-degenerate triangles of the three backgrounds). Faces with a ratio above 1e-8 pass; the others are
  // decided by their lengths, as before.
  static double properness_ratio(const double xs[3], double Q)
  {
    const double hi = (std::max)(xs[0], (std::max)(xs[1], xs[2])), p = xs[0] * xs[1] * xs[2];
    const double hi2 = hi * hi;
    return Q / (hi2 * hi2 + 4 * p * p);
  }
  static bool clearly_proper(const double xs[3], double Q) { return properness_ratio(xs, Q) > 1e-8; }

  // recompute the cached angles of face f. Vertex scaling: from x = sinh, sin (l / 2), l / 2 (see
  // face_hessian()), theta_i = atan2(sqrt(Q), 2 num_i) with num_i = (x_j^2 + x_k^2 - x_i^2) / 2 + kappa x_j^2 x_k^2,
  // the same angle as the half-angle formula of `triangle_angles_only()` (to a few ulps: Q and num_i have no
  // cancellation but the one of the angle itself, see `algebraic_gram()`) without its four sinh (sin), and
  // atan2 as `upper_half_plane_angle()`; degenerate faces (Luo's extension) and S^2 edges of length >= pi take
  // `triangle_angles_only()`
  void update_face_angles(F f)
  {
    H hs[3]; V cs[3]; double l[3], th[3];
    face_corners(m.halfedge(f), hs, cs);
    double x[3], Q = 0, num[3];
    if(scheme == Scheme::VERTEX_SCALING) {
      const bool algebraic = vertex_scaling_x(hs, x) && algebraic_gram(x, Q, num);
      bool proper = algebraic && clearly_proper(x, Q);
      if(!proper) {
        face_data(m.halfedge(f), hs, cs, l);
        proper = triangle_is_proper(l);
      }
      if(algebraic && proper) {
        const double sq = std::sqrt(Q);
        for(int i = 0; i < 3; ++i) angle[hs[i]] = upper_half_plane_angle(sq, 2 * num[i]);
        return;
      }
    } else
      face_data(m.halfedge(f), hs, cs, l);
    triangle_angles_only(geo, l, th);
    for(int i = 0; i < 3; ++i) angle[hs[i]] = th[i];
  }

  // the strict triangle inequalities (and, S^2, perimeter < 2 pi)
  bool triangle_is_proper(const double l[3]) const
  {
    for(int i = 0; i < 3; ++i) if(!(l[i] < l[(i + 1) % 3] + l[(i + 2) % 3])) return false;
    return geo != Background_geometry::SPHERICAL || l[0] + l[1] + l[2] < 2 * CGAL_PI;
  }

  // kappa = 1 (H^2), -1 (S^2), 0 (E^2)
  double kappa() const
  {
    return geo == Background_geometry::HYPERBOLIC ? 1.0 : (geo == Background_geometry::SPHERICAL ? -1.0 : 0.0);
  }

  // vertex scaling: x_j = lambda_j e^{(u_a + u_b) / 2} (the cached `x` of compute_lengths()) of the edges of
  // hs; false if some 1 + kappa x_j^2 <= 0 (S^2, l_j >= pi)
  bool vertex_scaling_x(const H hs[3], double xs[3]) const
  {
    const double k = kappa();
    bool ok = true;
    for(int j = 0; j < 3; ++j) {
      xs[j] = x[m.edge(hs[j])];
      if(!(1 + k * xs[j] * xs[j] > 0)) ok = false;
    }
    return ok;
  }

  // vertex_scaling_x() and c_j = sqrt(1 + kappa x_j^2) (cosh, cos (l_j / 2), 1)
  bool vertex_scaling_face(const H hs[3], double xs[3], double c[3]) const
  {
    const bool ok = vertex_scaling_x(hs, xs);
    const double k = kappa();
    for(int j = 0; j < 3; ++j) c[j] = std::sqrt((std::max)(0.0, 1 + k * xs[j] * xs[j]));
    return ok;
  }

  // Q = 16 area(x)^2 + 4 kappa (x_0 x_1 x_2)^2 (Kahan's stable Heron formula for the Euclidean triangle with
  // sides x) and num_i = (x_j^2 + x_k^2 - x_i^2) / 2 + kappa x_j^2 x_k^2; false unless Q is finite and > 0.
  // Test `needle_angles_match_an_exact_reference`: within 6e-16 of the exact formula on needles down to 1e-9
  // (H^2, E^2; S^2 needles with long sides of 1.5 to 2.5 radians: 5e-14, Q itself cancels there)
  bool algebraic_gram(const double x[3], double& Q, double num[3]) const
  {
    const double k = kappa();
    const double lo = (std::min)(x[0], x[1]), hi = (std::max)(x[0], x[1]);
    const double s[3] = {(std::min)(lo, x[2]), (std::max)(lo, (std::min)(hi, x[2])), (std::max)(hi, x[2])}; // sorted
    const double heron16 = (s[2] + (s[1] + s[0])) * (s[0] - (s[2] - s[1])) * (s[0] + (s[2] - s[1])) * (s[2] + (s[1] - s[0]));
    const double p = x[0] * x[1] * x[2];
    Q = heron16 + 4 * k * p * p;
    if(!(Q > 0) || !std::isfinite(Q)) return false;
    for(int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, kk = (i + 2) % 3;
      // x_j^2 + x_k^2 - x_i^2 = (a - x_i)(a + x_i) + b^2, a = max(x_j, x_k), b = min: a - x_i is exact when
      // x_i is close to a (the needle's long sides), where x_j^2 + x_k^2 - x_i^2 lost all the bits of
      // x_i^2 - a^2 (angle errors up to eps x_i / b at the short side's ends)
      const double a = (std::max)(x[j], x[kk]), b = (std::min)(x[j], x[kk]);
      num[i] = 0.5 * ((a - x[i]) * (a + x[i]) + b * b) + k * x[j] * x[j] * x[kk] * x[kk];
    }
    return std::isfinite(num[0]) && std::isfinite(num[1]) && std::isfinite(num[2]);
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
    // h1: b->c, h2: c->a, o1: a->d, o2: d->b
    const double lab = edge_data[e], lbc = edge_data[m.edge(h1)], lca = edge_data[m.edge(h2)],
                 lad = edge_data[m.edge(o1)], ldb = edge_data[m.edge(o2)];
    if(record_undo) {
      const V a = m.target(o), b = m.target(h);
      undo_log.push_back(Undo_record{e, lab, {fh, fo}, {m.halfedge(fh), m.halfedge(fo)}, {a, b}, {m.halfedge(a), m.halfedge(b)}});
    }
    if(geometric_flips) {
      // the diagonal c-d of the quad unfolded along a-b (lambda = l / 2 in E^2)
      edge_data[e] = 0.5 * euclidean_flip_diagonal(length(e), length(m.edge(h1)), length(m.edge(h2)),
                                                   length(m.edge(o1)), length(m.edge(o2)));
    } else
      edge_data[e] = (lca * ldb + lad * lbc) / lab;
    flip_log.push_back(e);
    flip_connectivity(m, e);
    update_length(e);
    update_face_angles(fh); update_face_angles(fo);
    ++flips; ++pattern_version;
  }

  // undoes the flips of `undo_log` (latest first): the connectivity (a flip has order 4: three more restore
  // each halfedge's next, target and face), the face and vertex anchors, the Penner coordinates exactly, and
  // `flip_log`; the derived caches (lengths, angles, curvatures) are left to the caller's next evaluation.
  // `flips` still counts them (work).
  void undo_flips()
  {
    for(auto it = undo_log.rbegin(); it != undo_log.rend(); ++it) {
      for(int k = 0; k < 3; ++k) flip_connectivity(m, it->e);
      for(int k = 0; k < 2; ++k) { m.set_halfedge(it->f[k], it->fh[k]); m.set_halfedge(it->v[k], it->vh[k]); }
      edge_data[it->e] = it->lambda;
      CGAL_assertion(!flip_log.empty() && flip_log.back() == it->e);
      flip_log.pop_back();
      ++pattern_version;
    }
    undo_log.clear();
  }
  // ends the recording and frees the log (at 2.6M faces a step's trials flip about 10^5 to 10^6 edges:
  // up to 48 MB that the next factorization, the flow's peak, would otherwise hold)
  void stop_recording_flips()
  {
    record_undo = false;
    std::vector<Undo_record>().swap(undo_log);
  }

  void push(E e) { if(!in_queue[e] && !e_is_border[e]) { in_queue[e] = 1; flip_queue.push_back(e); } }

  // flips until every edge is Delaunay; false if the flip budget is exhausted
  bool make_delaunay()
  {
    if(!use_flips) return true;
    // only the edges that are not Delaunay start in the queue (queueing all edges would keep a queue of the
    // size of the mesh alive)
    for(E e : m.edges()) if(!is_delaunay(e)) push(e);
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

  // The caches derived from (u, edge_data): x (lengths), corner angles, curvatures (more than half of the
  // engine's memory: 15 doubles per vertex at 2.6M faces). A large factorization frees them (the factor needs
  // the memory) and `restore_derived()` recomputes them from the same state, with the functions of an evaluation.
  void release_derived()
  {
    std::vector<double>().swap(len); std::vector<double>().swap(angle); std::vector<double>().swap(K);
    std::vector<double>().swap(x);
  }
  void restore_derived()
  {
    angle.assign(m.number_of_halfedges(), 0.0); K.assign(m.number_of_vertices(), 0.0);
    if(scheme == Scheme::VERTEX_SCALING) x.assign(m.number_of_edges(), 0.0); else len.assign(m.number_of_edges(), 0.0);
    compute_lengths();
    compute_angles();
    compute_curvature();
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

  // false if a length is below `min_usable_length`, not finite, or (H^2) so long that cosh overflows in the
  // angle formulas (vertex scaling H^2: 2 asinh(x) < 600, tested on x)
  bool lengths_are_usable() const
  {
    const bool hyperbolic = geo == Background_geometry::HYPERBOLIC;
    if(scheme == Scheme::VERTEX_SCALING && hyperbolic) {
      static const double x_limit = std::sinh(300.0);
      for(E e : m.edges()) if(!(x[e] >= min_usable_length && x[e] < x_limit)) return false;
      return true;
    }
    const double limit = hyperbolic ? 600.0 : HUGE_VAL;
    for(E e : m.edges()) { const double l = length(e); if(!(l >= min_usable_length && l < limit)) return false; }
    return true;
  }
  // The face formulas multiply up to four lengths (Heron's 16 area^2): below 1e-77 these products underflow,
  // and the angles of a face of such edges depend on the unit they are computed in. The flow runs in units of
  // about the mean length (H^2, S^2: absolute lengths of order 1), so a state with a shorter edge is no metric
  // it can continue from. Before (2026-12-07, night) only zero lengths were: elk.off stretched 1000 times,
  // flat metric, wandered into lengths of 1e-323, and its last iterate's angle sums from the returned lengths
  // (times the unit 2048) said max |K| 23.935 where the flow reported 23.946; now it stops at 5.63, which the
  // returned metric confirms to 1e-12 (test `failed_line_search_restores_its_start`). Every flow of the demo
  // meshes that converged still does; anchor_dense and femur stretched 1000 times (H^2) end with
  // LINE_SEARCH_FAILED at max |K| 4.6 and 5.9 instead of 27.5 (iteration bound) and 757 (flip bound)
  static constexpr double min_usable_length = 1e-77;

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

  // the 3 x 3 block d K_{cs[i]} / d u_{cs[a]} of face f (from the cached angles); false for a degenerate face
  // (extended angles pi, 0, 0), which contributes nothing
  bool face_hessian(F f, H hs[3], V cs[3], double d[3][3]) const
  {
    double l[3], th[3], dth[3][3];
    face_corners(m.halfedge(f), hs, cs);
    for(int i = 0; i < 3; ++i) th[i] = angle[hs[i]];
    // the lengths only where needed: faces that are not clearly proper (their triangle inequalities) and the
    // angle-formula fallback
    bool have_lengths = false;
    auto lengths = [&]() -> const double* {
      if(!have_lengths) { face_data(m.halfedge(f), hs, cs, l); have_lengths = true; }
      return l;
    };
    auto degenerate = [&]() {
      const double* ll = lengths();
      for(int i = 0; i < 3; ++i) if(!(ll[i] < ll[(i + 1) % 3] + ll[(i + 2) % 3])) return true;
      return false;
    };
    // dl[j][a]: d l_j / d u at corner a (source(h_j) = corner j+1, target(h_j) = corner j+2)
    double dl[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    if(scheme == Scheme::VERTEX_SCALING) {
      // With no transcendental function (the exp of each edge is taken once per evaluation, `x`), from
      // x_j = lambda_j e^{(u_a + u_b) / 2} = sinh(l_j / 2) (H^2), sin(l_j / 2) (S^2), l_j / 2 (E^2) and
      // c_j = sqrt(1 + kappa x_j^2) = cosh, cos (l_j / 2), 1 (kappa = 1, -1, 0): g(l_j) = sinh l_j, sin l_j,
      // l_j = 2 x_j c_j and d l_j / d u = x_j / c_j (tanh, tan (l_j / 2), l_j / 2). The laws of cosines in x
      // (cosh l = 1 + 2 x^2, cos l = 1 - 2 x^2) give
      //   cos theta_i = num_i / (x_j c_j x_k c_k),  num_i = (x_j^2 + x_k^2 - x_i^2) / 2 + kappa x_j^2 x_k^2,
      //   g_j g_k sin theta_i = 2 sqrt(Q),  Q = 16 area(x)^2 + 4 kappa (x_0 x_1 x_2)^2
      // (Q is the Gram determinant; area(x) the Euclidean triangle with sides x, by Kahan's stable Heron
      // formula), the same for the three corners (law of sines): `algebraic_gram()`, which also gives the
      // cached angles. It replaces 3 sinh (sin), 3 sin and 3 cos per face; an S^2 edge of length >= pi
      // (c = 0) and H^2 lengths beyond about 200 (x^6 overflows) take the angle formulas.
      double x[3], c[3], g[3], Q = 0, num[3];
      const bool algebraic = vertex_scaling_face(hs, x, c) && algebraic_gram(x, Q, num);
      if(!(algebraic && clearly_proper(x, Q)) && degenerate()) return false;
      for(int j = 0; j < 3; ++j) {
        g[j] = 2 * x[j] * c[j];
        const double d = c[j] > 0 ? x[j] / c[j] : 0.0;
        dl[j][(j + 1) % 3] = dl[j][(j + 2) % 3] = d;
      }
      if(algebraic) {
        const double A = 2 * std::sqrt(Q); // g_j g_k sin theta_i for every i
        for(int i = 0; i < 3; ++i) {
          const int j = (i + 1) % 3, k = (i + 2) % 3;
          const double gi = g[i] / A;
          // cos theta = num / (x c x c)
          dth[i][i] = gi;
          dth[i][j] = -gi * num[k] / (x[i] * c[i] * x[j] * c[j]);
          dth[i][k] = -gi * num[j] / (x[k] * c[k] * x[i] * c[i]);
        }
      } else
        triangle_angle_derivatives(geo, lengths(), th, dth);
    } else {
      if(degenerate()) return false;
      triangle_angle_derivatives(geo, l, th, dth);
      for(int j = 0; j < 3; ++j) {
        double ds, dt;
        length_derivatives(hs[j], ds, dt);
        dl[j][(j + 1) % 3] = ds;
        dl[j][(j + 2) % 3] = dt;
      }
    }
    for(int i = 0; i < 3; ++i)
      for(int a = 0; a < 3; ++a) {
        double s = 0;
        for(int j = 0; j < 3; ++j) s += dth[i][j] * dl[j][a];
        d[i][a] = -s;
      }
    return true;
  }

  // The lower triangle of dK/du as a compressed column-major matrix whose sparsity pattern depends only on the
  // connectivity (one entry per vertex and per pair of adjacent vertices, degenerate faces give explicit zeros):
  // the pattern and the position of each edge's entry are rebuilt only when `pattern_version` changes, the
  // values are accumulated in place (no triplets). Rows and columns of `fixed` vertices (if not empty) are
  // replaced by the identity. Equals the lower triangle of the matrix of `hessian_triplets()` (the solvers read
  // only that triangle).
  void hessian_lower(Eigen::SparseMatrix<double>& Hm, const std::vector<char>& fixed)
  {
    const int n = int(m.number_of_vertices());
    if(hessian_pattern_version_ != pattern_version || Hm.rows() != n || !Hm.isCompressed()) build_hessian_pattern(Hm);
    double* val = Hm.valuePtr();
    std::fill(val, val + Hm.nonZeros(), 0.0);
    const bool has_fixed = !fixed.empty();
    for(F f : m.faces()) {
      H hs[3]; V cs[3]; double d[3][3];
      if(!face_hessian(f, hs, cs, d)) continue;
      for(int i = 0; i < 3; ++i) {
        if(has_fixed && fixed[cs[i]]) continue;
        for(int a = 0; a < 3; ++a) {
          if(has_fixed && fixed[cs[a]]) continue;
          if(a == i || cs[i] == cs[a]) val[diagonal_position_[cs[i]]] += d[i][a];
          else if(cs[i] > cs[a]) val[edge_position_[m.edge(hs[3 - i - a])]] += d[i][a]; // edge joining corners i, a
        }
      }
    }
    if(has_fixed) for(int v = 0; v < n; ++v) if(fixed[v]) val[diagonal_position_[v]] = 1.0;
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

private:
  // the lower-triangular pattern of the Hessian for the current connectivity, and the entry of each edge
  void build_hessian_pattern(Eigen::SparseMatrix<double>& Hm)
  {
    const int n = int(m.number_of_vertices());
    std::vector<int> colptr(n + 1, 0);
    for(int v = 0; v < n; ++v) colptr[v + 1] = 1;
    for(E e : m.edges()) {
      const int a = int(m.vertex(e, 0)), b = int(m.vertex(e, 1));
      if(a != b) ++colptr[(std::min)(a, b) + 1];
    }
    for(int v = 0; v < n; ++v) colptr[v + 1] += colptr[v];
    std::vector<int> rows(colptr[n]), fill(colptr.begin(), colptr.end() - 1);
    for(int v = 0; v < n; ++v) rows[fill[v]++] = v;
    for(E e : m.edges()) {
      const int a = int(m.vertex(e, 0)), b = int(m.vertex(e, 1));
      if(a != b) rows[fill[(std::min)(a, b)]++] = (std::max)(a, b);
    }
    // sort each column and remove the repeated rows of multi-edges
    std::vector<int> start(n + 1, 0);
    int out = 0;
    for(int v = 0; v < n; ++v) {
      std::sort(rows.begin() + colptr[v], rows.begin() + colptr[v + 1]);
      start[v] = out;
      for(int k = colptr[v]; k < colptr[v + 1]; ++k)
        if(k == colptr[v] || rows[k] != rows[k - 1]) rows[out++] = rows[k];
    }
    start[n] = out;
    rows.resize(out);
    Hm.resize(n, n);
    Hm.resizeNonZeros(out);
    std::copy(start.begin(), start.end(), Hm.outerIndexPtr());
    std::copy(rows.begin(), rows.end(), Hm.innerIndexPtr());
    std::fill(Hm.valuePtr(), Hm.valuePtr() + out, 0.0);
    diagonal_position_.assign(n, 0);
    for(int v = 0; v < n; ++v) diagonal_position_[v] = start[v]; // the diagonal is the first row of its column
    edge_position_.assign(m.number_of_edges(), -1);
    for(E e : m.edges()) {
      const int a = int(m.vertex(e, 0)), b = int(m.vertex(e, 1));
      if(a == b) continue;
      const int c = (std::min)(a, b), r = (std::max)(a, b);
      edge_position_[e] = int(std::lower_bound(rows.begin() + start[c], rows.begin() + start[c + 1], r) - rows.begin());
    }
    hessian_pattern_version_ = pattern_version;
  }

  int hessian_pattern_version_ = -1;
  std::vector<int> diagonal_position_, edge_position_;
};

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_FLOW_ENGINE_H
