// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The metric of the embedding in extended precision: the converged double-precision lengths of the flow have
// angle sums 2 pi only up to their rounding (max |K| about 1e-14), and the relator of the deck
// transformations amplifies that residual curvature by the relator's condition (the manual's "Accuracy of
// the relator"). A few Newton steps of vertex scaling on top of those lengths, with the angle sums evaluated
// in long double (the layer's half-angle formula) and the linear systems solved in double (iterative
// refinement: the Jacobian's own rounding only slows the convergence down), bring the residual to the
// long-double level (about 1e-18) and change the lengths by about the initial residual (1e-14 relative).
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_POLISH_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_POLISH_H

#include <CGAL/Discrete_Ricci_flow/internal/triangle_geometry.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_motions.h>
#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

/// the result of `polish_hyperbolic_lengths()`: the metric as sinh(length / 2) by edge index (vertex scaling
/// multiplies these, so no transcendental function is evaluated per edge), and the max |K| before and after
template <class FT>
struct Polished_lengths_t
{
  std::vector<FT> half_sinh;
  FT max_curvature_before = 0, max_curvature_after = 0;
  int steps = 0;
  FT length(std::size_t e) const { using std::asinh; return 2 * asinh(half_sinh[e]); }
};
typedef Polished_lengths_t<Real> Polished_lengths;

/// max over the vertices of |K_v| = |2 pi - angle sum| for the metric given by x_e = sinh(l_e / 2) (by edge
/// index) on the closed triangle mesh `m`, in the precision of `FT` (long double, or `Mp_real` at the
/// precision of `x`), for |K_v| < pi; `K` receives the curvatures by vertex index. Returns +infinity for a
/// broken triangle (triangle inequality violated).
/// The half-angle formula tan(alpha / 2) = sqrt(sinh(s-b) sinh(s-c) / (sinh(s) sinh(s-a))) (the layer's
/// `CGAL::Hyperbolic_surface_2::corner_angle()`), s = (a + b + c) / 2, with the four sinh expanded in
/// sinh(l / 2) and cosh(l / 2) = sqrt(1 + sinh^2(l / 2)), and each angle as the unit complex number
/// e^{i alpha} = (S S_a - S_b S_c + 2 i sqrt(S S_a S_b S_c)) / (S S_a + S_b S_c): the angle sum at a vertex is
/// the argument of the product of its corners' numbers, so each vertex costs one atan2 and a face one square
/// root, and the rest is arithmetic (in MPFR, transcendental functions dominate).
template <class FT, class Mesh>
FT curvatures(const Mesh& m, const std::vector<FT>& x, std::vector<FT>& K)
{
  using std::sqrt; using std::atan2; using std::abs;
  const std::size_t nv = m.number_of_vertices();
  std::vector<FT> c(x.size());
  for(std::size_t e = 0; e < x.size(); ++e) c[e] = sqrt(1 + x[e] * x[e]);
  std::vector<FT> re(nv, FT(1)), im(nv, FT(0));
  auto turn = [&](std::size_t v, const FT& a, const FT& b) { // (re, im) *= (a + i b)
    const FT r = re[v] * a - im[v] * b;
    im[v] = re[v] * b + im[v] * a;
    re[v] = r;
  };
  for(auto f : m.faces()) {
    const auto h0 = m.halfedge(f), h1 = m.next(h0), h2 = m.next(h1);
    const std::size_t e0 = m.edge(h0), e1 = m.edge(h1), e2 = m.edge(h2);
    const FT &sa = x[e0], &sb = x[e1], &sc = x[e2], &ca = c[e0], &cb = c[e1], &cc = c[e2];
    const FT t1 = sa * cb * cc, t2 = ca * sb * cc, t3 = ca * cb * sc, t4 = sa * sb * sc;
    const FT S = t1 + t2 + t3 + t4, Sa = t2 + t3 - t1 - t4, Sb = t1 + t3 - t2 - t4, Sc = t1 + t2 - t3 - t4;
    if(!(Sa >= 0 && Sb >= 0 && Sc >= 0)) { K.assign(nv, std::numeric_limits<FT>::infinity()); return std::numeric_limits<FT>::infinity(); }
    const FT P2 = 2 * sqrt(S * Sa * Sb * Sc);
    // the corner opposite edge(h0) is at target(h1), opposite edge(h1) at target(h2), opposite edge(h2) at target(h0)
    const FT na = S * Sa + Sb * Sc, nb = S * Sb + Sa * Sc, nc = S * Sc + Sa * Sb;
    turn(std::size_t(m.target(h1)), (S * Sa - Sb * Sc) / na, P2 / na);
    turn(std::size_t(m.target(h2)), (S * Sb - Sa * Sc) / nb, P2 / nb);
    turn(std::size_t(m.target(h0)), (S * Sc - Sa * Sb) / nc, P2 / nc);
  }
  K.resize(nv);
  FT mx = 0;
  for(std::size_t v = 0; v < nv; ++v) {
    K[v] = -atan2(im[v], re[v]); // e^{i angle sum} = e^{i (2 pi - K)}
    if(abs(K[v]) > mx) mx = abs(K[v]);
  }
  return mx;
}

/// Newton's method on the vertex-scaling factors u (hyperbolic: sinh(L_ij / 2) = e^{(u_i + u_j) / 2}
/// sinh(l_ij / 2)) from u = 0 on the metric x_e = sinh(l_e / 2) (by edge index) of the closed triangle mesh
/// `m`, with the residuals (angle sums, `curvatures()`) in the precision of `FT` and the Jacobian in double,
/// factorized once at `x` (iterative refinement: each step multiplies the residual by about 1e-16 cond(J)
/// plus the Jacobian's change, which is of the order of the residual). Stops after `max_steps` steps, when
/// max |K| <= `target`, or when a step does not reduce max |K|; returns the best metric (the input when no
/// step helps or the factorization fails).
template <class FT, class Mesh>
Polished_lengths_t<FT> polish_hyperbolic_lengths(const Mesh& m, const std::vector<FT>& x, int max_steps = 4,
                                                 const FT& target = FT(0))
{
  using std::exp; using std::isfinite;
  const std::size_t nv = m.number_of_vertices();
  Polished_lengths_t<FT> r;
  r.half_sinh = x;
  std::vector<FT> K, u(nv, FT(0));
  r.max_curvature_before = r.max_curvature_after = curvatures(m, x, K);
  if(!isfinite(r.max_curvature_before) || !(r.max_curvature_before > target) || max_steps <= 0) return r;
  // the Jacobian of the angle sums in double: J_vw = d(angle sum at v)/du_w = -dK_v/du_w (negative
  // semi-definite for vertex scaling): solve (-J) delta = -K for K(u + delta) = 0
  std::vector<Eigen::Triplet<double> > trip;
  for(auto f : m.faces()) {
    const auto h0 = m.halfedge(f);
    const decltype(h0) hs[3] = {h0, m.next(h0), m.prev(h0)};
    // corner i = source(hs[i]); l[i] = the side opposite corner i = edge of hs[i + 1]
    double l[3], th[3], dth[3][3];
    std::size_t v[3];
    for(int i = 0; i < 3; ++i) { l[i] = 2 * std::asinh(CGAL::to_double(x[m.edge(hs[(i + 1) % 3])])); v[i] = std::size_t(m.source(hs[i])); }
    if(!triangle_angles(Background_geometry::HYPERBOLIC, l, th, dth)) return r;
    double dl[3]; // d l_j / d u_k for either endpoint k != j
    for(int j = 0; j < 3; ++j) dl[j] = vertex_scaling_length_derivative(Background_geometry::HYPERBOLIC, l[j]);
    for(int i = 0; i < 3; ++i)
      for(int k = 0; k < 3; ++k) {
        double d = 0; // d theta_i / d u_k = sum over the sides j not opposite k
        for(int j = 0; j < 3; ++j) if(j != k) d += dth[i][j] * dl[j];
        trip.emplace_back(int(v[i]), int(v[k]), -d);
      }
  }
  Eigen::SparseMatrix<double> A(static_cast<int>(nv), static_cast<int>(nv));
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > solver(A);
  if(solver.info() != Eigen::Success) return r;
  std::vector<FT> y = x, scale(nv);
  for(int step = 0; step < max_steps; ++step) {
    Eigen::VectorXd rhs(static_cast<int>(nv));
    for(std::size_t i = 0; i < nv; ++i) rhs[int(i)] = -CGAL::to_double(K[i]);
    const Eigen::VectorXd delta = solver.solve(rhs);
    if(!delta.allFinite()) break;
    for(std::size_t i = 0; i < nv; ++i) { u[i] += FT(delta[int(i)]); scale[i] = exp(u[i] / 2); }
    for(auto e : m.edges()) y[e] = scale[std::size_t(m.vertex(e, 0))] * scale[std::size_t(m.vertex(e, 1))] * x[e];
    const FT k = curvatures(m, y, K);
    if(!(k < r.max_curvature_after)) break;
    r.half_sinh = y; r.max_curvature_after = k; r.steps = step + 1;
    if(k <= target) break;
  }
  return r;
}

/// the long-double polish of the flow's double lengths (by edge index)
template <class Mesh>
Polished_lengths polish_hyperbolic_lengths(const Mesh& m, const std::vector<double>& len, int max_steps = 4)
{
  std::vector<Real> x(len.size());
  for(std::size_t e = 0; e < len.size(); ++e) x[e] = std::sinh(Real(len[e]) / 2);
  return polish_hyperbolic_lengths<Real>(m, x, max_steps);
}

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_POLISH_H
