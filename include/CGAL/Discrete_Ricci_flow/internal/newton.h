// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Newton's method with line search on the convex discrete Ricci energy (thesis Algorithm 1), on a Flow_engine,
// with the sparse Cholesky factorization of CHOLMOD (supernodal, when configured with SuiteSparse) or Eigen's
// SimplicialLDLT; the symbolic analysis is reused until Ptolemy flips change the sparsity pattern, and the
// fill-reducing ordering is kept for the later patterns while their factors stay small.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_NEWTON_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_NEWTON_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/Discrete_Ricci_flow/internal/flow_engine.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_HC_HAS_CHOLMOD
#include <cholmod.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

/// `Sparse_solver::DEFAULT` for n unknowns: CHOLMOD's supernodal Cholesky from 100,000 vertices (when
/// configured), Eigen's `SimplicialLDLT` below. Measured on an idle machine (2026-12-03, CPU time of the whole
/// flow, `benchmark_Discrete_Ricci_flow`): `SimplicialLDLT` 1.2 to 1.8 times faster up to 89k faces (44k
/// vertices: the factors of these near-planar graphs are small, and the supernodal method's set-up dominates),
/// CHOLMOD 1.1 times faster at 0.36M faces (178k vertices) and 1.9 times at 1.4M faces. Since SimplicialLDLT
/// keeps its ordering (2026-12-06): the two within 15% of each other at 178k vertices, CHOLMOD 1.4 times
/// faster at 325k vertices and 1.4 times at 711k (the manual's table).
inline Sparse_solver default_solver(Sparse_solver s, std::size_t n)
{
  if(s != Sparse_solver::DEFAULT) return s;
  return has_cholmod() && n >= 100000 ? Sparse_solver::SUPERNODAL_CHOLMOD : Sparse_solver::SIMPLICIAL_LDLT;
}

/// The sparse Cholesky factorization of a symmetric matrix given by its lower triangle (compressed column
/// storage), with the chosen solver. The symbolic analysis is redone only when the pattern version changes;
/// both solvers keep the fill-reducing ordering for later patterns (Ptolemy flips usually change a few
/// entries: the ordering stays good, and computing one costs about a numeric factorization, more with the
/// nested dissection of large meshes) until the factor has grown by `refill_ratio` (many flips: noisy input).
/// CHOLMOD's LLT fails on an indefinite matrix: the factorization then falls back to LDLT.
class Sparse_cholesky
{
public:
  /// the solver `default_solver(s, n)` for matrices of n rows
  Sparse_cholesky(Sparse_solver s, std::size_t n)
  {
    kind_ = default_solver(s, n);
    if(kind_ == Sparse_solver::SUPERNODAL_CHOLMOD && !has_cholmod())
      throw_option_error("sparse_solver(SUPERNODAL_CHOLMOD): the library was configured without CHOLMOD");
#ifdef CGAL_HC_HAS_CHOLMOD
    if(kind_ == Sparse_solver::SUPERNODAL_CHOLMOD) {
      cholmod_start(&cm_);
      cm_.print = 0;               // an indefinite matrix is not an error here: LDLT takes over
      cm_.error_handler = nullptr;
      cm_.supernodal = CHOLMOD_SUPERNODAL;
      cm_.final_ll = 1;            // keep L L^T (the supernodal form)
      for(int k = 0; k < 3; ++k) default_zrelax_[k] = cm_.zrelax[k];
      started_ = true;
    }
#endif
  }
  Sparse_cholesky(const Sparse_cholesky&) = delete;
  Sparse_cholesky& operator=(const Sparse_cholesky&) = delete;
  ~Sparse_cholesky()
  {
#ifdef CGAL_HC_HAS_CHOLMOD
    if(started_) {
      free_cholmod_factor();
      if(x_) cholmod_free_dense(&x_, &cm_);
      if(y_) cholmod_free_dense(&y_, &cm_);
      if(e_) cholmod_free_dense(&e_, &cm_);
      cholmod_finish(&cm_);
    }
#endif
  }

  Sparse_solver kind() const { return kind_; }
  /// the solver of the last successful factorization
  Sparse_solver used() const { return used_; }
  bool has_factor() const { return has_factor_; }
  /// true if the last factorization is positive definite (it can precondition conjugate gradients)
  bool positive_definite() const { return has_factor_ && positive_definite_; }
  /// estimated cost of one factorization in units of one solve with the factor (floating-point operations
  /// of the factorization over those of a forward and backward substitution)
  double factorization_over_solve() const { return factorization_over_solve_; }
  /// wall-clock time of the last numeric factorization (without the symbolic analysis)
  double numeric_seconds() const { return numeric_seconds_; }

  /// numeric factorization of the matrix whose lower triangle is `H` (compressed); false on failure
  bool factorize(const Sparse_matrix& H, int pattern_version, Flow_statistics& st)
  {
    has_factor_ = false;
#ifdef CGAL_HC_HAS_CHOLMOD
    if(kind_ == Sparse_solver::SUPERNODAL_CHOLMOD) {
      if(cholmod_factorize_(H, pattern_version, st)) return true;
      ++st.number_of_solver_fallbacks;
      free_cholmod_factor(); // do not keep two factorizations alive
    }
#endif
    // the fill-reducing ordering (AMD) is kept across pattern changes, as CHOLMOD's (`CHOLMOD_GIVEN`): Ptolemy
    // flips usually change a few entries, and Eigen's AMD with its symmetrization costs about a numeric
    // factorization on these matrices. When the flips have made the kept ordering's factor more than
    // `refill_ratio` times larger than it was for the pattern it was computed for, a new ordering is computed
    // (`amd_ordering_()`). The permuted upper triangle P H P^T is factorized with the natural ordering (what
    // SimplicialLDLT does internally after its own ordering)
    const bool fresh = ldlt_perm_.size() != H.rows();
    if(fresh) amd_ordering_(H, st);
    Sparse_matrix permuted(H.rows(), H.cols());
    permuted.selfadjointView<Eigen::Upper>() = H.selfadjointView<Eigen::Lower>().twistedBy(ldlt_perm_);
    if(fresh || ldlt_version_ != pattern_version) {
      ldlt_.analyzePattern(permuted); ldlt_version_ = pattern_version; ++st.number_of_symbolic_factorizations;
      const double lnz = double(ldlt_.matrixL().nestedExpression().nonZeros());
      if(!fresh && lnz > refill_ratio * ldlt_lnz_reference_) {
        amd_ordering_(H, st);
        permuted.selfadjointView<Eigen::Upper>() = H.selfadjointView<Eigen::Lower>().twistedBy(ldlt_perm_);
        ldlt_.analyzePattern(permuted); ++st.number_of_symbolic_factorizations;
        ldlt_lnz_reference_ = double(ldlt_.matrixL().nestedExpression().nonZeros());
      } else if(fresh)
        ldlt_lnz_reference_ = lnz;
    }
    const auto t0 = std::chrono::steady_clock::now();
    ldlt_.factorize(permuted);
    numeric_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++st.number_of_factorizations;
    if(ldlt_.info() != Eigen::Success) return false;
    used_ = Sparse_solver::SIMPLICIAL_LDLT;
    const Eigen::VectorXd D = ldlt_.vectorD();
    positive_definite_ = D.size() == 0 || D.minCoeff() > 0;
    double fl = 0, lnz = 0;
    for(Eigen::Index j = 0; j < ldlt_.matrixL().nestedExpression().outerSize(); ++j) {
      const double c = double(ldlt_.matrixL().nestedExpression().outerIndexPtr()[j + 1] -
                              ldlt_.matrixL().nestedExpression().outerIndexPtr()[j]);
      fl += c * c; lnz += c;
    }
    factorization_over_solve_ = fl / (4 * lnz + 4 * double(H.rows()) + 1);
    has_factor_ = true;
    return true;
  }

  /// x := A^{-1} x with the last factorization; false if the result is not finite
  bool solve_in_place(Eigen::VectorXd& x)
  {
    if(!has_factor_) return false;
#ifdef CGAL_HC_HAS_CHOLMOD
    if(used_ == Sparse_solver::SUPERNODAL_CHOLMOD) {
      cholmod_dense b;
      b.nrow = std::size_t(x.size()); b.ncol = 1; b.nzmax = b.nrow; b.d = b.nrow; b.x = x.data(); b.z = nullptr;
      b.xtype = CHOLMOD_REAL; b.dtype = CHOLMOD_DOUBLE;
      if(!cholmod_solve2(CHOLMOD_A, L_, &b, nullptr, &x_, nullptr, &y_, &e_, &cm_) || !x_) return false;
      std::copy(static_cast<const double*>(x_->x), static_cast<const double*>(x_->x) + x.size(), x.data());
      return x.allFinite();
    }
#endif
    Eigen::VectorXd y = ldlt_perm_ * x;
    y = ldlt_.solve(y);
    x = ldlt_perm_.transpose() * y;
    return x.allFinite();
  }

  /// factorizes and solves H x = b; true on success (kept for the benchmark's reference measurement)
  bool solve(const Sparse_matrix& H, int pattern_version, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             Flow_statistics& st)
  {
    if(!factorize(H, pattern_version, st)) return false;
    x = b;
    st.solver_used = used_;
    return solve_in_place(x);
  }

  /// a kept fill-reducing ordering is recomputed when the factor of the current pattern has more than this
  /// many times the nonzeros it had for the pattern the ordering was computed for. Measured (2026-12-06,
  /// refined_elephant.off with Gaussian vertex noise of 0.3 mean edge lengths: 32,892 Ptolemy flips, most of
  /// them in the first Newton step): the first ordering kept, the flow took 4.2 s (SimplicialLDLT) and 3.1 s
  /// (CHOLMOD) against 1.6 s with a new ordering at every pattern change; with this ratio 1.7 s and 2.7 s
  static constexpr double refill_ratio = 1.2;

private:
  void amd_ordering_(const Sparse_matrix& H, Flow_statistics& st)
  {
    Sparse_matrix C;
    C = H.selfadjointView<Eigen::Lower>();
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::AMDOrdering<int>()(C, inverse);
    ldlt_perm_ = inverse.inverse();
    ++st.number_of_orderings;
  }
#ifdef CGAL_HC_HAS_CHOLMOD
  bool cholmod_factorize_(const Sparse_matrix& H, int pattern_version, Flow_statistics& st)
  {
    cholmod_sparse A;
    A.nrow = std::size_t(H.rows()); A.ncol = std::size_t(H.cols()); A.nzmax = std::size_t(H.nonZeros());
    A.p = const_cast<int*>(H.outerIndexPtr()); A.i = const_cast<int*>(H.innerIndexPtr()); A.nz = nullptr;
    A.x = const_cast<double*>(H.valuePtr()); A.z = nullptr;
    A.stype = -1; A.itype = CHOLMOD_INT; A.xtype = CHOLMOD_REAL; A.dtype = CHOLMOD_DOUBLE; A.sorted = 1; A.packed = 1;
    if(!L_ || cholmod_version_ != pattern_version) {
      std::vector<int> perm;
      if(L_ && L_->Perm && L_->n == A.nrow) // reuse the ordering of the last fresh analysis
        perm.assign(static_cast<const int*>(L_->Perm), static_cast<const int*>(L_->Perm) + L_->n);
      // large matrices: no relaxed amalgamation with explicit zeros (CHOLMOD's default admits 80%, 10%, 5%
      // zeros in small, medium and large supernodes). Measured 2026-12-03 (idle machine): at 2.6M faces
      // (1.3M vertices) the factor takes 112 MB less (1.61 GB peak instead of 1.72 GB) in the same time
      // (35.7 s against 35.2 s); at 89k faces the flow took 20% longer without it, so smaller matrices keep
      // CHOLMOD's default
      for(int k = 0; k < 3; ++k) cm_.zrelax[k] = A.nrow >= 1000000 ? 0.0 : default_zrelax_[k];
      free_cholmod_factor();
      for(int attempt = 0; attempt < 2; ++attempt) {
        if(!perm.empty()) { cm_.nmethods = 1; cm_.method[0].ordering = CHOLMOD_GIVEN; }
        else cm_.nmethods = 0; // CHOLMOD's default: AMD, and METIS when AMD's fill is poor (large meshes)
        L_ = cholmod_analyze_p(&A, perm.empty() ? nullptr : perm.data(), nullptr, 0, &cm_);
        ++st.number_of_symbolic_factorizations;
        if(!L_ || cm_.status < CHOLMOD_OK) { cholmod_version_ = -1; return false; }
        if(perm.empty()) { ++st.number_of_orderings; cholmod_lnz_reference_ = cm_.lnz; break; }
        if(cm_.lnz <= refill_ratio * cholmod_lnz_reference_) break;
        free_cholmod_factor(); perm.clear(); // the kept ordering has grown too much fill: a new one
      }
      cholmod_version_ = pattern_version;
      factorization_over_solve_ = cm_.fl / (4 * cm_.lnz + 4 * double(A.nrow) + 1);
      // the analysis' workspace (6n integers) is larger than the numeric factorization's: freed, so that the
      // factorization allocates only what it needs
      cholmod_free_work(&cm_);
    }
    const auto t0 = std::chrono::steady_clock::now();
    cholmod_factorize(&A, L_, &cm_);
    const int status = cm_.status;
    cholmod_free_work(&cm_); // (the factorization's workspace, 14 bytes per row: not needed by the solves)
    numeric_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++st.number_of_factorizations;
    if(status != CHOLMOD_OK || L_->minor < L_->n) return false;
    used_ = Sparse_solver::SUPERNODAL_CHOLMOD; positive_definite_ = true; has_factor_ = true;
    return true;
  }
  void free_cholmod_factor()
  {
    if(L_) cholmod_free_factor(&L_, &cm_);
    L_ = nullptr; cholmod_version_ = -1;
  }
  cholmod_common cm_;
  cholmod_factor* L_ = nullptr;
  cholmod_dense *x_ = nullptr, *y_ = nullptr, *e_ = nullptr;
  int cholmod_version_ = -1;
  double cholmod_lnz_reference_ = 0; // nonzeros of the factor for the pattern the ordering was computed for
  double default_zrelax_[3] = {}; // CHOLMOD's defaults, read in the constructor
  bool started_ = false;
#endif
  Sparse_solver kind_, used_ = Sparse_solver::SIMPLICIAL_LDLT;
  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Upper, Eigen::NaturalOrdering<int> > ldlt_; // of P H P^T
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> ldlt_perm_;           // P (AMD)
  double ldlt_lnz_reference_ = 0; // nonzeros of the factor for the pattern P was computed for
  int ldlt_version_ = -1;
  bool has_factor_ = false, positive_definite_ = false;
  double factorization_over_solve_ = 1, numeric_seconds_ = 0;
};

/// the options of a Newton run
struct Newton_options
{
  int max_iterations = 100;
  double accuracy = 1e-11;
  /// after reaching `accuracy`, keep taking Newton steps while the error at least halves and is above
  /// `polishing_floor` (at most `max_polishing_steps`): the default "iterate to the rounding level". With
  /// `reuse_factorization`, a polishing step from an error of at most `polishing_factorizes_above` takes its
  /// direction from conjugate gradients preconditioned by the kept factorization only: when they miss their
  /// tolerance the polishing ends instead of paying a factorization for a digit or two of rounding level
  bool polish = true;
  int max_polishing_steps = 4;
  /// the error above which a polishing step may still factorize (what the embedding's relator needs)
  double polishing_factorizes_above = 1e-12;
  /// the error below which a polishing step gains nothing that can be told from rounding (the curvature of a
  /// vertex is 2 pi minus a sum of rounded angles: the demo meshes' floors are 5e-15 to 1.5e-13)
  double polishing_floor = 1e-13;
  bool verbose = false;
  Sparse_solver solver = Sparse_solver::DEFAULT;
  std::function<bool(const Flow_progress&)> callback; ///< false stops (CANCELLED)
  /// vertices whose conformal factor is held (Dirichlet condition, or the gauge of the Euclidean closed case)
  std::vector<char> fixed;
  /// whether the curvature error of fixed vertices counts (true for the gauge vertex)
  bool fixed_in_error = true;
  /// from this number of vertices the engine's derived caches are freed during a factorization (peak memory)
  std::size_t release_caches_from = 500000;
  /// inexact Newton: solve the Newton system by conjugate gradients preconditioned with the last Cholesky
  /// factorization (of an earlier Hessian), and factorize again only when they do not reach the forcing
  /// tolerance within their budget; false: one factorization per Newton step (the reference)
  bool reuse_factorization = true;
  /// the largest change of a conformal factor in the first trial of a line search (see `line_search`)
  double max_step = 8.0;
  /// a step that fails returns to its start exactly, the last accepted iterate (see `return_to_start()`);
  /// false: the flow ends in the state of its last restore (the rounds of the disk flow of
  /// `spherical_uniformization()`, each a warm start of the next)
  bool return_to_start_on_failure = true;
};

template <class Point_3>
class Newton_solver
{
public:
  Newton_solver(Flow_engine<Point_3>& eng, const Newton_options& o, Flow_statistics& st)
    : eng_(eng), o_(o), st_(st), n_(int(eng.u.size())), g_(eng.u.size()), chol_(o.solver, eng.u.size()),
      H_(n_, n_), delta_(n_)
  {
    if(o_.fixed.empty()) o_.fixed.assign(eng.u.size(), 0);
  }

  /// runs the flow; the statistics receive status, iterations, errors and energies
  void run()
  {
    double err = 0;
    if(!evaluate(err)) { // (the flip bound: the error of the state reached, as returned)
      st_.status = Flow_status::FLIP_LIMIT_REACHED;
      evaluate(err, false);
    } else if(!std::isfinite(err)) st_.status = Flow_status::NUMERICAL_FAILURE;
    else st_.status = Flow_status::MAXIMUM_ITERATIONS;
    st_.error_history.push_back(err);
    st_.energy_history.push_back(0.0);
    double best_err = err;
    int without_progress = 0;
    while(st_.status == Flow_status::MAXIMUM_ITERATIONS) {
      if(err < o_.accuracy) { st_.status = Flow_status::CONVERGED; break; }
      if(st_.iterations >= o_.max_iterations) break;
      if(without_progress >= 5) { st_.status = Flow_status::STAGNATED; break; }
      double t = 1;
      if(!step(err, t, false)) break;
      ++st_.iterations;
      // stagnation is only declared in the rounding regime (far from the solution Newton may need several
      // iterations before the max error drops)
      if(err < 0.5 * best_err) { best_err = err; without_progress = 0; }
      else if(best_err < 1e-6) ++without_progress;
      if(!report(err, t)) { st_.status = err < o_.accuracy ? Flow_status::CONVERGED : Flow_status::CANCELLED; break; }
    }
    if(st_.status == Flow_status::CONVERGED && o_.polish) polish(err);
    // a solution (or the rounding floor) reached only with degenerate triangles is not a metric
    if((st_.status == Flow_status::CONVERGED || st_.status == Flow_status::STAGNATED) && eng_.has_degenerate_face())
      st_.status = Flow_status::DEGENERATE_TRIANGLES;
    st_.max_curvature_error = err;
    st_.number_of_flips = eng_.flips;
  }

private:
  // lengths, angles, flips (unless `flips` is false), curvature and the gradient g = K - target at the
  // current u
  bool evaluate(double& max_err, bool flips = true)
  {
    eng_.compute_lengths();
    eng_.compute_angles();
    if(flips && !eng_.make_delaunay()) return false;
    eng_.compute_curvature();
    max_err = 0;
    for(int i = 0; i < n_; ++i) {
      g_[i] = eng_.K[i] - eng_.target[i];
      if(o_.fixed[i] && !o_.fixed_in_error) continue;
      if(!std::isfinite(g_[i])) { max_err = std::numeric_limits<double>::infinity(); return true; }
      max_err = (std::max)(max_err, std::abs(g_[i]));
    }
    // a state with a zero, non-finite or (H^2) overflowing length is not a metric the flow can continue from:
    // its error counts as infinite, so that the line search never accepts it
    if(!eng_.lengths_are_usable()) max_err = std::numeric_limits<double>::infinity();
    return true;
  }

  // the Newton direction at the current state, for the current max error `err` (false: numerical failure).
  // Inexact Newton (Dembo-Eisenstat-Steihaug): the relative residual of the direction is at most
  // eta = min(0.1, max(err, 1e-8)), which keeps the convergence quadratic (the residual is of the order of the
  // quadratic term) down to the rounding level; `fresh` forces a new factorization. A `polishing` step needs
  // its direction only to the accuracy that takes the error to a tenth of the polishing floor: eta is at
  // least min(0.1, polishing_floor / (10 err)) (from 6.4e-12: 1.6e-3 instead of 1e-8), and it factorizes only
  // when its conjugate gradients miss that, not because the step before needed many of them (elephant.off
  // Loop x1, 22k faces: 4 -> 3 factorizations, the same final error to 1e-16)
  bool direction(double err, bool fresh, bool may_factorize = true, double min_shift = 0, bool polishing = false)
  {
    const auto t0 = std::chrono::steady_clock::now();
    eng_.hessian_lower(H_, o_.fixed);
    double eta = (std::min)(0.1, (std::max)(err, 1e-8));
    if(polishing) eta = (std::max)(eta, (std::min)(0.1, 0.1 * o_.polishing_floor / err));
    const auto t1 = std::chrono::steady_clock::now();
    st_.hessian_seconds += std::chrono::duration<double>(t1 - t0).count();
    // the cost of a numeric factorization in CG iterations, estimated from the operation counts of the factor
    // (an estimate, not a timing, so that the flow is deterministic): CHOLMOD's supernodal factorization runs
    // about 4 times more flops per second than the memory-bound solves, SimplicialLDLT's scalar one about 2
    // times (2026-12-07, 22k to 89k faces: with 4 for both, 3 to 5 factorizations and 9 to 16 CG iterations
    // per flow; with 2, one or two factorizations fewer and 10 to 13% less CPU below 50k faces, the same at
    // 89k). The budget of a step is about one factorization, and after a step that needed more than half of
    // one the factorization is renewed (the Hessian has moved away from the factorized one)
    const double flop_rate_ratio = chol_.used() == Sparse_solver::SUPERNODAL_CHOLMOD ? 4.0 : 2.0;
    const double ratio = chol_.factorization_over_solve() / flop_rate_ratio;
    if(last_cg_iterations_ > 0.5 * ratio && may_factorize && !polishing) fresh = true;
    if(!fresh && o_.reuse_factorization && chol_.positive_definite()) {
      const int budget = int((std::max)(2.0, (std::min)(30.0, ratio)));
      int iterations = 0;
      const bool ok = conjugate_gradients(eta, budget, iterations);
      const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      st_.cg_seconds += dt;
      last_cg_iterations_ = ok ? iterations : 0;
      if(ok) { from_cg_ = true; return true; }
    }
    if(!may_factorize && o_.reuse_factorization) return false;
    last_cg_iterations_ = 0;
    from_cg_ = false;
    const auto t2 = std::chrono::steady_clock::now();
    // large meshes: the factorization holds the peak memory of the flow; the engine's derived caches are
    // freed meanwhile and recomputed after (at 2.6M faces: 103 MB, for about one evaluation's time)
    const bool release = std::size_t(n_) >= o_.release_caches_from;
    if(release) eng_.release_derived();
    bool ok = factorize_and_solve(min_shift);
    if(release) eng_.restore_derived();
    st_.solver_used = chol_.used();
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
    if(st_.first_factorization_seconds == 0) st_.first_factorization_seconds = dt;
    st_.factorization_seconds += dt;
    return ok;
  }

  // whether the energy is convex (E^2, H^2: its Hessian is positive semi-definite; the S^2 energy is not)
  bool convex() const { return eng_.geo != Background_geometry::SPHERICAL; }

  // factorizes H_ and solves the Newton system into delta_. A convex energy whose Hessian is singular (an
  // interior vertex all of whose triangles are degenerate, Luo's extension: e.g. a disk flow whose boundary
  // triangle must degenerate) gets the factorization of H + mu I instead (Levenberg-Marquardt): mu from
  // max(1e-10 mean |H_ii|, min_shift), times 1000 until positive definite (`shift_` receives it, 0 without);
  // before, the flow ended with NUMERICAL_FAILURE
  bool factorize_and_solve(double min_shift)
  {
    shift_ = 0;
    bool ok = false;
    if(min_shift == 0) {
      ok = chol_.factorize(H_, eng_.pattern_version, st_);
      if(ok) { right_hand_side(delta_); ok = chol_.solve_in_place(delta_); }
      if((ok && chol_.positive_definite()) || !convex()) return ok;
    }
    // (the fixed vertices' rows and columns are the identity, with a zero right-hand side: shifting them too
    // leaves their zero step unchanged)
    const double mean_diag = (std::max)(n_ > 0 ? double(H_.diagonal().cwiseAbs().mean()) : 0.0, 1e-300);
    double applied = 0;
    for(double mu = (std::max)(1e-10 * mean_diag, min_shift); mu <= 10 * mean_diag; mu *= 1e3) {
      H_.diagonal().array() += mu - applied;
      applied = mu;
      ok = chol_.factorize(H_, eng_.pattern_version, st_);
      if(ok) { right_hand_side(delta_); ok = chol_.solve_in_place(delta_); }
      if(ok && chol_.positive_definite()) { shift_ = mu; ++st_.number_of_shifted_factorizations; return true; }
    }
    return false;
  }

  // the right-hand side of the Newton system, -g (0 at fixed vertices), into b
  void right_hand_side(Eigen::VectorXd& b) const
  {
    b.resize(n_);
    for(int i = 0; i < n_; ++i) b[i] = o_.fixed[i] ? 0.0 : -g_[i];
  }

  // preconditioned conjugate gradients on H delta = rhs from delta = 0, the preconditioner being the last
  // factorization; true when ||residual|| <= eta ||rhs|| within `budget` iterations. Three vectors besides
  // delta: the preconditioned residual z and the product q = H p share one (z is dead once p is formed)
  bool conjugate_gradients(double eta, int budget, int& iterations)
  {
    Eigen::VectorXd& r = cg_r_; Eigen::VectorXd& w = cg_w_; Eigen::VectorXd& p = cg_p_;
    right_hand_side(r);
    const double bnorm = r.norm();
    delta_.setZero();
    iterations = 0;
    if(bnorm == 0) return true;
    w = r; // z
    if(!chol_.solve_in_place(w)) return false;
    p = w;
    double rz = r.dot(w);
    for(int k = 0; k < budget; ++k) {
      w.noalias() = H_.selfadjointView<Eigen::Lower>() * p; // q
      const double pq = p.dot(w);
      if(!(pq > 0) || !(rz > 0)) return false;
      const double alpha = rz / pq;
      delta_ += alpha * p; r -= alpha * w;
      ++st_.number_of_cg_iterations; ++iterations;
      if(r.norm() <= eta * bnorm) return delta_.allFinite();
      w = r; // z
      if(!chol_.solve_in_place(w)) return false;
      const double rz_new = r.dot(w);
      p = w + (rz_new / rz) * p;
      rz = rz_new;
    }
    return false;
  }

  // one damped Newton step; on failure sets the status and returns to the state it started from, exactly.
  // `strict`: accept only a decrease of the max error (polishing)
  bool step(double& err, double& t, bool strict)
  {
    // a polishing step (strict) near the rounding level only with the kept factorization (Newton_options::polish)
    if(!direction(err, false, !strict || err > o_.polishing_factorizes_above, 0, strict)) {
      if(!strict) st_.status = Flow_status::NUMERICAL_FAILURE;
      return false;
    }
    // every flip from here on is recorded (the line searches' trials and the flips back of their restores),
    // so that a step that fails returns to its start (`return_to_start()`)
    eng_.undo_log.clear(); eng_.record_undo = true;
    if(line_search(err, t, strict)) return true;
    // an inexact direction that the line search rejects: once more with a new factorization
    if(from_cg_ && !strict && st_.status == Flow_status::LINE_SEARCH_FAILED) {
      st_.status = Flow_status::MAXIMUM_ITERATIONS;
      if(!direction(err, true)) { st_.status = Flow_status::NUMERICAL_FAILURE; return return_to_start(err); }
      if(line_search(err, t, strict)) return true;
    }
    // a shifted (Levenberg-Marquardt) direction that the line search rejects: the Hessian missed the
    // curvature of the degenerate triangles, which grows fast as they open; a larger shift (shorter step)
    while(shift_ > 0 && !strict && st_.status == Flow_status::LINE_SEARCH_FAILED) {
      st_.status = Flow_status::MAXIMUM_ITERATIONS;
      if(!direction(err, true, true, 1e3 * shift_)) { st_.status = Flow_status::LINE_SEARCH_FAILED; return return_to_start(err); }
      if(line_search(err, t, strict)) return true;
    }
    return return_to_start(err);
  }

  // a step failed: back to the state it started from (the last accepted iterate, which the flow returns), by
  // undoing every flip since (`Flow_engine::undo_flips()`), evaluated without flips; returns false. The
  // restores between the step's line searches take the flips back instead (`restore()`), and in the disk
  // flows of `spherical_uniformization()` (degenerate boundary triangles) those regularly end in another
  // state (43 restores of 5 genus-0 demo meshes stretched 30 times: errors 1.03 to 39 times the start's); the
  // retries start from there, and returning them to the exact start instead made dragknob.off stretched 30
  // times fail. So only the end of a failed step is exact: before, the flow returned the last restored state
  // (anchor.off stretched 1000 times, H^2: its last line search started at max |K| 24.8, and the flow returned
  // a state at 84.4; test `failed_line_search_returns_the_last_iterate`). The disk flow's rounds keep the last
  // restored state (`Newton_options::return_to_start_on_failure`): a round's end is the warm start of the
  // next, not a result, and with the exact start dragknob.off stretched 30 times failed there too (scratch
  // sweep, 2026-12-07)
  bool return_to_start(double& err)
  {
    if(!o_.return_to_start_on_failure) { eng_.stop_recording_flips(); return false; }
    eng_.u = u_old_;
    eng_.undo_flips();
    eng_.stop_recording_flips();
    evaluate(err, false);
    return false;
  }

  bool line_search(double& err, double& t, bool strict)
  {
    double slope0 = 0;
    for(int i = 0; i < n_; ++i) slope0 += g_[i] * delta_[i];
    u_old_ = eng_.u;
    const double err_old = err;
    // far from the solution (e.g. a vertex far from the others, lengths spread over orders of magnitude) the
    // Newton direction can change u by hundreds: lengths under- or overflow, and the flips at such a trial
    // point leave Penner coordinates that no later state can use. The first trial moves no u_i by more than
    // `max_step` (a factor e^max_step on the lengths); near the solution the full step is taken.
    double dmax = 0;
    for(int i = 0; i < n_; ++i) dmax = (std::max)(dmax, std::abs(delta_[i]));
    t = dmax > o_.max_step ? o_.max_step / dmax : 1.0;
    // accept t when the energy decreases (trapezoidal estimate from the directional derivatives; the energy
    // is convex for E^2 / H^2) or the max error decreases, the latter for a convex energy only where the
    // estimate does not say that the energy grew: steps accepted for their max error alone made flows of
    // meshes with very thin triangles cycle (joint.off stretched 1000 times along x: the same 10 iterates
    // again and again, MAXIMUM_ITERATIONS).
    // A convex energy's directional derivative grows along the step; the trapezoid is exact when it grows
    // linearly, but flips make it kink (the Hessian jumps), and past the minimum on the line (derivative
    // slope_t > 0) the true change lies anywhere in [t slope0, t slope_t]. Mesh stretched 1000 times
    // (mpi_triang.off, flat metric; the true change integrated on 64 pieces of the step): 8 of the first 30
    // accepted steps had a negative trapezoid and a positive true change (-0.27 against +6.3), and the flow
    // wandered at max errors 12 to 24 until MAXIMUM_ITERATIONS. So a convex energy's trial point whose slope
    // exceeds a quarter of the initial descent rate, `overshoot_ratio`, is rejected like one whose energy grew:
    // a quadratic energy (Newton near the solution) has slope_t = 0 at t = 1 and is never rejected by this.
    // With it that flow descends to its rounding floor (4.5e-7 after 187 iterations, more than the default
    // 100), and the hyperbolic demo meshes and their perturbed copies take fewer iterations (scratch sweep of
    // 76 flows: 754 -> 650 in all; 3 of them take 1 to 6 more)
    const double overshoot_ratio = 0.25;
    while(t > 1e-12) {
      for(int i = 0; i < n_; ++i) eng_.u[i] = u_old_[i] + t * delta_[i];
      double e2 = 0;
      if(!evaluate(e2)) { st_.status = Flow_status::FLIP_LIMIT_REACHED; restore(err, err_old); return false; }
      if(std::isfinite(e2)) {
        double slope_t = 0;
        for(int i = 0; i < n_; ++i) slope_t += g_[i] * delta_[i];
        const double de = 0.5 * t * (slope0 + slope_t);
        const bool overshoot = convex() && slope0 < 0 && slope_t > -overshoot_ratio * slope0;
        const bool ok = strict ? e2 < err_old
                               : !overshoot && ((slope0 < 0 && de <= 1e-4 * t * slope0) ||
                                                (e2 < err_old * (1 - 1e-4 * t) && !(convex() && de > 0)));
        if(ok) { err = e2; energy_ += de; eng_.stop_recording_flips(); return true; }
      }
      if(strict) break;
      t *= 0.5;
    }
    restore(err, err_old);
    if(!strict) st_.status = Flow_status::LINE_SEARCH_FAILED;
    return false;
  }

  // back to the line search's start u_old: the Delaunay flips at u_old take the rejected trials' flips back
  // (Ptolemy: the same Penner coordinates up to rounding; on meshes stretched 1000 times not quite the same
  // state: femur.off's error went 706 -> 757). Where that fails, every flip since the step's start (the same
  // u_old for all its line searches) is undone exactly (`Flow_engine::undo_flips()`):
  // - the trials' Penner coordinates under- or overflowed, and the lengths at u_old are lost (elk.off stretched
  //   1000 times along x and shrunk along z, flat metric: u in [-1118, 162] at a trial point, lambda0 from 0
  //   to 6e307; after 165 iterations the flow threw "the initial state ... has zero, non-finite or
  //   overflowing edge lengths" instead of ending with LINE_SEARCH_FAILED at its last accepted iterate);
  // - the flip bound stops the flips back (femur.off stretched: FLIP_LIMIT_REACHED reported max error 0).
  //   (Since the usable-length bound, `Flow_engine::min_usable_length`, those two flows stop earlier; test
  //   `undo_flips_restores_the_triangulation` exhausts the flip bound in a first trial.)
  // Undoing always, instead of the flips back, changes the state the step's next line search starts from: on
  // the demo meshes it made more stretched genus-0 maps fail (dragknob.off stretched 30 times, 3 punctures of
  // the stretched corner), so it is the fallback only; a step that fails in the end returns to its start
  // exactly (`return_to_start()`).
  void restore(double& err, double err_old)
  {
    eng_.u = u_old_;
    double e2 = 0;
    if(!evaluate(e2) || !std::isfinite(e2)) { // (u is still u_old)
      eng_.undo_flips();
      // the start's own triangulation, evaluated without flips: it was accepted after its Delaunay flips, but
      // an edge just flipped is not tested again (near-degenerate triangles would flip it back and forth), so
      // a few edges can miss the flip test by rounding. Flipping them here could run into the flip bound
      // (anchor.off stretched 1000 times, 1500 iterations: 16 such edges, the bound reached in a line search,
      // and the flow reported FLIP_LIMIT_REACHED with max error 0 instead of its start's)
      e2 = 0;
      evaluate(e2, false);
    }
    err = std::isfinite(e2) ? e2 : err_old; // (the recording goes on: the step may end in return_to_start())
  }

  bool report(double err, double t)
  {
    st_.error_history.push_back(err);
    st_.energy_history.push_back(energy_);
    Flow_progress pr;
    pr.iteration = st_.iterations; pr.max_curvature_error = err; pr.step_length = t; pr.number_of_flips = eng_.flips;
    if(o_.verbose)
      std::cerr << "Ricci flow: iteration " << st_.iterations << "  max |K - target| = " << err
                << "  step = " << t << "  flips = " << eng_.flips << "  factorizations = "
                << st_.number_of_factorizations << "  CG iterations = " << st_.number_of_cg_iterations << std::endl;
    return !o_.callback || o_.callback(pr);
  }

  // Newton converges quadratically: a few more steps reach the rounding level of double arithmetic
  void polish(double& err)
  {
    for(int k = 0; k < o_.max_polishing_steps && err > o_.polishing_floor; ++k) {
      const double before = err;
      double t = 1;
      if(!step(err, t, true)) { st_.status = Flow_status::CONVERGED; break; }
      ++st_.iterations; ++st_.polishing_iterations;
      st_.error_history.push_back(err);
      st_.energy_history.push_back(energy_);
      if(!(err < 0.5 * before)) break;
    }
  }

  Flow_engine<Point_3>& eng_;
  Newton_options o_;
  Flow_statistics& st_;
  int n_;
  std::vector<double> g_, u_old_;
  Sparse_cholesky chol_;
  Sparse_matrix H_;
  Eigen::VectorXd delta_, cg_r_, cg_w_, cg_p_;
  bool from_cg_ = false;
  double shift_ = 0;                // the Levenberg-Marquardt shift of the last factorization (0: none)
  int last_cg_iterations_ = 0;      // CG iterations of the last accepted inexact direction
  double energy_ = 0;
};

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_NEWTON_H
