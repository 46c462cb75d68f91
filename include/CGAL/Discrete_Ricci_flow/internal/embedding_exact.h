// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact deck transformations of the embedding (`Hyperbolic_embedding::deck_transformations_exact()`, the
// manual's "Accuracy of the relator"): the long-double holonomies converted exactly when their exact relator
// product is close enough to the identity, otherwise the development of every loop in MPFR on the metric
// polished to that precision, on a ladder of precisions chosen from the measured condition of the relator.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_EXACT_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_EXACT_H

#include <CGAL/Discrete_Ricci_flow/internal/embedding_development.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_motions.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_multiprecision.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_polish.h>
#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

/// the exact deck transformations and how they were obtained
struct Exact_data
{
  unsigned bits = 64;
  double max_curvature = 0, log10_condition = 0, defect = std::numeric_limits<double>::infinity();
  int polish_steps = 0, attempts = 0;
  std::vector<Exact_isometry> deck;
};

/// The exact deck transformations of the loops of `basis` (a `CGAL::Hyperbolic_surface_2::Homotopy_basis` on
/// the closed mesh `m`, hyperbolic background) developed from the corner `root` (target(root) is the base
/// vertex) on the polished metric `half_sinh` (sinh(length / 2) by edge index, long double) and expressed in
/// `frame`, the frame of the long-double holonomies. The arguments must outlive the object.
template <class Mesh, class Basis>
class Exact_deck_transformations
{
public:
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Face_index Face_index;

  /// `relator`: the embedding's relator word (`basis.relator()` rotated, Hyperbolic_embedding::relator())
  Exact_deck_transformations(const Mesh& m, const Basis& basis, const std::vector<int>& relator, Halfedge_index root,
                             const Motion& frame, const std::vector<Real>& half_sinh)
    : m_(m), basis_(basis), relator_(relator), root_(root), frame_(frame), long_half_sinh_(half_sinh)
  {}

  /// the precision ladder, from the long-double holonomies `hol` (in `frame`), the relator's condition they
  /// give (`Hyperbolic_embedding::relator_condition()`: +infinity when long double could not measure it) and
  /// the max |K| and the number of steps of the long-double polish
  Exact_data compute(const std::vector<Motion>& hol, double condition, double polished_max_curvature,
                     int polish_steps) const
  {
    const double target = 1e-10; // 100 times below the embedding's goal of 1e-8
    Exact_data r;
    r.bits = 64; r.max_curvature = polished_max_curvature; r.polish_steps = polish_steps; r.attempts = 1;
    r.log10_condition = std::log10(condition);
    // a holonomy whose long-double normalization failed (|alpha|^2 beyond about 1e19, where |alpha|^2 - |beta|^2
    // = 1 is lost: the compact basis of cheese.off, loops up to 134 units long) has no exact value: MPFR
    // directly (before, to_exact() threw "a non-finite long-double value")
    bool finite = true;
    for(const Motion& h : hol) {
      const Long_isometry n = h.h.normalized();
      for(const Real x : {n.alpha_real(), n.alpha_imag(), n.beta_real(), n.beta_imag()}) finite = finite && std::isfinite(x);
      if(finite) r.deck.push_back(to_exact_isometry(n));
    }
    if(finite) r.defect = relator_defect(r.deck);
    else r.deck.clear();
    if(r.defect <= target) return r;
    unsigned bits = 128;
    for(int attempt = 2; attempt <= 6 && bits <= 4096; ++attempt) {
      Exact_data t = develop_multiprecision(bits, condition);
      t.attempts = attempt;
      if(t.defect <= r.defect || !(r.defect <= target)) r = t;
      if(t.defect <= target) break;
      const double needed = 64 + t.log10_condition * 3.3219280948873623 + 32;
      bits = (std::max)(bits + 64, 32 * unsigned(std::ceil(needed / 32)));
      condition = std::pow(10.0, t.log10_condition);
    }
    return r;
  }

private:
  double relator_defect(const std::vector<Exact_isometry>& d) const
  {
    return exact_defect(word_product(d, relator_, Exact_isometry()));
  }

  // the development of every loop in MPFR at `bits` bits on the metric polished to that precision, in the frame
  // of the long-double development (frame_ is an exact isometry in any precision)
  Exact_data develop_multiprecision(unsigned bits, double condition) const
  {
    typedef Mp_real R;
    typedef CGAL::Hyperbolic_surface_2::Disk_geometry<Mp_kernel> Mp_geometry;
    typedef Mp_kernel::Point_2 P;
    const Mp_precision_guard guard(bits);
    Exact_data r;
    r.bits = bits;
    // the long-double polished metric (exactly) as the start
    std::vector<R> x0(long_half_sinh_.size());
    for(std::size_t e = 0; e < x0.size(); ++e) x0[e] = R(long_half_sinh_[e]);
    using std::ldexp;
    R k_target = ldexp(R(1), -int(bits) + 16);
    if(std::isfinite(condition) && condition > 0 && R(1e-12 / condition) > k_target) k_target = R(1e-12 / condition);
    const Polished_lengths_t<R> pl = polish_hyperbolic_lengths<R>(m_, x0, 16, k_target);
    r.max_curvature = pl.max_curvature_after.template convert_to<double>();
    r.polish_steps = pl.steps;
    std::vector<R> L(x0.size()); // lengths 2 asinh(x), on the edges of the charts used
    std::vector<char> has_length(x0.size(), 0);
    auto length_of = [&](Halfedge_index h) -> const R& {
      const std::size_t e = m_.edge(h);
      if(!has_length[e]) { L[e] = pl.length(e); has_length[e] = 1; }
      return L[e];
    };
    std::vector<std::array<P, 3> > charts(m_.number_of_faces());
    std::vector<char> has_chart(m_.number_of_faces(), 0);
    auto chart_of = [&](Face_index f) -> const std::array<P, 3>& {
      if(!has_chart[f]) {
        const Halfedge_index h = m_.halfedge(f);
        charts[f] = Mp_geometry::triangle_chart(length_of(h), length_of(m_.next(h)), length_of(m_.prev(h)));
        has_chart[f] = 1;
      }
      return charts[f];
    };
    std::vector<Mp_isometry> transitions(m_.number_of_halfedges());
    std::vector<char> has_transition(m_.number_of_halfedges(), 0);
    auto transition_of = [&](Halfedge_index h) -> const Mp_isometry& {
      if(!has_transition[h]) { // as Face_charts::transition(h) in long double
        const Halfedge_index o = m_.opposite(h);
        const std::array<P, 3>& cf = chart_of(m_.face(h));
        const std::array<P, 3>& cg = chart_of(m_.face(o));
        const int ih = index_in_face(m_, h), io = index_in_face(m_, o);
        transitions[h] = Mp_geometry::isometry_from_pairs(cf[ih], cf[(ih + 1) % 3], cg[(io + 1) % 3], cg[io]);
        has_transition[h] = 1;
      }
      return transitions[h];
    };
    const Mp_isometry F(R(frame_.h.alpha_real()), R(frame_.h.alpha_imag()), R(frame_.h.beta_real()), R(frame_.h.beta_imag()));
    std::vector<Mp_isometry> hol;
    for(std::size_t i = 0; i < basis_.number_of_generators(); ++i)
      hol.push_back((F * develop_loop(m_, root_, basis_.loop(i), Mp_isometry(), transition_of) * F.inverse()).normalized());
    // the condition: max over the partial products of |alpha|^2 + |beta|^2 = cosh d(0, P_k 0)
    Mp_isometry m;
    R c = 1;
    for(const int l : relator_) {
      m = (m * letter(hol, l)).normalized();
      const R q = squared_norm(m);
      if(q > c) c = q;
    }
    r.log10_condition = boost::multiprecision::log10(c).template convert_to<double>();
    for(const Mp_isometry& h : hol) r.deck.push_back(to_exact_isometry(h));
    r.defect = relator_defect(r.deck);
    return r;
  }

  const Mesh& m_;
  const Basis& basis_;
  const std::vector<int>& relator_;
  Halfedge_index root_;
  const Motion& frame_;
  const std::vector<Real>& long_half_sinh_;
};

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_EXACT_H
