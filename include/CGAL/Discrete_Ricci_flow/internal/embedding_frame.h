// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The frame of the deck transformations (the class description of Hyperbolic_embedding, the manual's "Accuracy
// of the relator"): the point of the Poincare disk from which a set of isometries moves points least, found by
// a pattern search.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_FRAME_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_FRAME_H

#include <CGAL/Discrete_Ricci_flow/internal/embedding_motions.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

// The frame of the deck transformations: the origin is moved to the point c that minimizes
//   F(c) = max over the generators g_i and the relator's partial products P_k of cosh d(c, g c)
// (the squared norm of the matrix in the frame centred at c, which bounds the amplification of rounding
// errors when the matrices are multiplied: see relator_condition()), by a pattern search from the base
// vertex (step halved from 4 down to 1e-3 in hyperbolic distance, at most 2000 evaluations). The holonomies
// and the frame are conjugated by the translation T taking c to the origin; the base vertex's lift is then
// at T(0) (`base_point()`).

/// F(c) for the hyperbolic motions `elements`
inline Real frame_cost(const std::vector<Motion>& elements, const Cplx& c)
{
  const Motion T = Motion::translation_to_origin(c);
  const Motion Ti = T.inverse();
  Real worst = 1;
  for(const Motion& g : elements) {
    const Real q = squared_norm((T * g * Ti).h.normalized());
    if(!std::isfinite(q)) return std::numeric_limits<Real>::infinity();
    worst = (std::max)(worst, q);
  }
  return worst;
}

/// the point c found by the pattern search on F from the origin (the origin itself if no step improved F)
inline Cplx frame_centre(const std::vector<Motion>& elements)
{
  Cplx c(0);
  Real best = frame_cost(elements, c);
  int evaluations = 0;
  for(Real step = 4; step > Real(1e-3) && evaluations < 2000; ) {
    bool moved = false;
    // the 8 points at hyperbolic distance `step` from c
    const Motion from_c = Motion::from(Long_isometry::translation_from_origin(Long_kernel::Point_2(c.real(), c.imag())));
    for(int k = 0; k < 8 && evaluations < 2000; ++k) {
      const Real t = std::tanh(step / 2), phi = k * std::acos(Real(-1)) / 4;
      const Cplx q = from_c(Cplx(t * std::cos(phi), t * std::sin(phi)));
      if(!(std::abs(q) < 1)) continue;
      const Real f = frame_cost(elements, q);
      ++evaluations;
      if(f < best) { best = f; c = q; moved = true; break; }
    }
    if(!moved) step /= 2;
  }
  return c;
}

/// The cyclic rotation of the relator word w, or of its inverse, whose partial products P_1 .. P_{n-1} over the
/// hyperbolic motions g have the smallest largest |trace| (the first such in the order j = 0 .. n-1, w before its
/// inverse). A rotation is a conjugate of the same relation; the trace of a partial product does not depend on
/// the frame, and cosh of its translation length is the least squared norm the product has in any frame, so
/// this is the rotation whose rounding floor in double is lowest (the manual's "Accuracy of the relator").
/// O(n^2) products of 2 x 2 matrices.
inline std::vector<int> best_relator_rotation(const std::vector<Motion>& g, const std::vector<int>& w)
{
  const std::size_t n = w.size();
  std::vector<int> best = w;
  Real best_cost = std::numeric_limits<Real>::infinity();
  for(int inv = 0; inv < 2; ++inv)
    for(std::size_t j = 0; j < n; ++j) {
      Motion m = Motion::identity(true);
      Real cost = 0; // max over k of trace^2 / (4 det), i.e. cosh^2 of half the translation length
      for(std::size_t k = 0; k + 1 < n && cost < best_cost; ++k) {
        m = m * letter(g, inv ? -w[(j + n - k) % n] : w[(j + k) % n]);
        const Real det = m.h.determinant();
        const Real c = m.h.alpha_real() * m.h.alpha_real() / det;
        cost = std::isfinite(c) ? (std::max)(cost, c) : std::numeric_limits<Real>::infinity();
      }
      if(cost < best_cost) {
        best_cost = cost;
        for(std::size_t k = 0; k < n; ++k) best[k] = inv ? -w[(j + n - k) % n] : w[(j + k) % n];
      }
    }
  return best;
}

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_FRAME_H
