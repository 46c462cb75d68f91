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

/// the result of `polish_hyperbolic_lengths()`: the lengths by edge index and the max |K| before and after
struct Polished_lengths
{
  std::vector<Real> length;
  Real max_curvature_before = 0, max_curvature_after = 0;
  int steps = 0;
};

/// max over the vertices of |2 pi - angle sum| for the lengths `L` (by edge index) of the closed triangle
/// mesh `m`, in long double; `K` receives the curvatures by vertex index (NaN for a broken triangle)
template <class Mesh>
Real long_double_curvatures(const Mesh& m, const std::vector<Real>& L, std::vector<Real>& K)
{
  const Real two_pi = 2 * std::acos(Real(-1));
  K.assign(m.number_of_vertices(), two_pi);
  for(auto f : m.faces()) {
    const auto h0 = m.halfedge(f), h1 = m.next(h0), h2 = m.next(h1);
    const Real a = L[m.edge(h0)], b = L[m.edge(h1)], c = L[m.edge(h2)];
    // the corner at target(h0) is between h0 and h1, opposite h2 (and cyclically)
    K[m.target(h0)] -= CGAL::Hyperbolic_surface_2::corner_angle(c, a, b);
    K[m.target(h1)] -= CGAL::Hyperbolic_surface_2::corner_angle(a, b, c);
    K[m.target(h2)] -= CGAL::Hyperbolic_surface_2::corner_angle(b, c, a);
  }
  Real mx = 0;
  for(const Real k : K) { if(!(std::abs(k) <= mx)) mx = std::isnan(k) ? std::numeric_limits<Real>::infinity() : std::abs(k); }
  return mx;
}

/// Newton's method on the vertex-scaling factors u (hyperbolic: sinh(L_ij / 2) = e^{(u_i + u_j) / 2}
/// sinh(l_ij / 2)) from u = 0 on the lengths `len` (by edge index) of the closed triangle mesh `m`, with
/// residuals in long double. Stops after `max_steps` steps or when a step does not reduce max |K|; returns
/// the best lengths (the input's when no step helps or a factorization fails).
template <class Mesh>
Polished_lengths polish_hyperbolic_lengths(const Mesh& m, const std::vector<double>& len, int max_steps = 4)
{
  const std::size_t nv = m.number_of_vertices();
  Polished_lengths r;
  r.length.assign(len.begin(), len.end());
  std::vector<Real> K, u(nv, Real(0));
  r.max_curvature_before = r.max_curvature_after = long_double_curvatures(m, r.length, K);
  if(!std::isfinite(double(r.max_curvature_before))) return r;
  std::vector<Real> L = r.length;
  for(int step = 0; step < max_steps; ++step) {
    // the Jacobian of the angle sums in double: J_vw = d(angle sum at v)/du_w = -dK_v/du_w (negative
    // semi-definite for vertex scaling): solve (-J) delta = -K for K(u + delta) = 0
    std::vector<Eigen::Triplet<double> > trip;
    for(auto f : m.faces()) {
      const auto h0 = m.halfedge(f);
      const decltype(h0) hs[3] = {h0, m.next(h0), m.prev(h0)};
      // corner i = source(hs[i]); l[i] = the side opposite corner i = edge of hs[i + 1]
      double l[3], th[3], dth[3][3];
      std::size_t v[3];
      for(int i = 0; i < 3; ++i) { l[i] = double(L[m.edge(hs[(i + 1) % 3])]); v[i] = std::size_t(m.source(hs[i])); }
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
    if(solver.info() != Eigen::Success) break;
    Eigen::VectorXd rhs(static_cast<int>(nv));
    for(std::size_t i = 0; i < nv; ++i) rhs[int(i)] = -double(K[i]);
    const Eigen::VectorXd delta = solver.solve(rhs);
    if(!delta.allFinite()) break;
    for(std::size_t i = 0; i < nv; ++i) u[i] += Real(delta[int(i)]);
    for(auto e : m.edges()) {
      const std::size_t a = std::size_t(m.vertex(e, 0)), b = std::size_t(m.vertex(e, 1));
      L[e] = 2 * std::asinh(std::exp((u[a] + u[b]) / 2) * std::sinh(Real(len[e]) / 2));
    }
    const Real k = long_double_curvatures(m, L, K);
    if(!(k < r.max_curvature_after)) break;
    r.length = L; r.max_curvature_after = k; r.steps = step + 1;
  }
  return r;
}

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_POLISH_H
