// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Newton's method with line search on the convex discrete Ricci energy (thesis Algorithm 1), on a Flow_engine,
// with the sparse Cholesky factorization of CHOLMOD (supernodal, when configured with SuiteSparse) or Eigen's
// SimplicialLDLT; the symbolic analysis is reused until Ptolemy flips change the sparsity pattern.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_NEWTON_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_NEWTON_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/Discrete_Ricci_flow/internal/flow_engine.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_HC_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
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

/// Factorizes and solves H x = b with the chosen solver, reusing the symbolic analysis while the pattern
/// version does not change. CHOLMOD's LLT fails on an indefinite matrix: the call then falls back to LDLT.
class Sparse_cholesky
{
public:
  explicit Sparse_cholesky(Sparse_solver s)
  {
    kind_ = s == Sparse_solver::DEFAULT ? (has_cholmod() ? Sparse_solver::SUPERNODAL_CHOLMOD : Sparse_solver::SIMPLICIAL_LDLT) : s;
    if(kind_ == Sparse_solver::SUPERNODAL_CHOLMOD && !has_cholmod())
      throw_option_error("sparse_solver(SUPERNODAL_CHOLMOD): the library was configured without CHOLMOD");
  }

  /// true on success; `used` receives the solver that produced x
  bool solve(const Sparse_matrix& H, int pattern_version, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             Flow_statistics& st)
  {
#ifdef CGAL_HC_HAS_CHOLMOD
    if(kind_ == Sparse_solver::SUPERNODAL_CHOLMOD) {
      if(!cholmod_) {
        cholmod_.reset(new Eigen::CholmodSupernodalLLT<Sparse_matrix>());
        cholmod_->cholmod().print = 0;               // an indefinite matrix is not an error here: LDLT takes over
        cholmod_->cholmod().error_handler = nullptr;
      }
      if(cholmod_version_ != pattern_version) {
        cholmod_->analyzePattern(H); cholmod_version_ = pattern_version; ++st.number_of_symbolic_factorizations;
      }
      cholmod_->factorize(H);
      ++st.number_of_factorizations;
      if(cholmod_->info() == Eigen::Success) {
        x = cholmod_->solve(b);
        if(cholmod_->info() == Eigen::Success && x.allFinite()) { st.solver_used = kind_; return true; }
      }
      ++st.number_of_solver_fallbacks;
    }
#endif
    if(ldlt_version_ != pattern_version) {
      ldlt_.analyzePattern(H); ldlt_version_ = pattern_version; ++st.number_of_symbolic_factorizations;
    }
    ldlt_.factorize(H);
    ++st.number_of_factorizations;
    st.solver_used = Sparse_solver::SIMPLICIAL_LDLT;
    if(ldlt_.info() != Eigen::Success) return false;
    x = ldlt_.solve(b);
    return x.allFinite();
  }

private:
  Sparse_solver kind_;
  Eigen::SimplicialLDLT<Sparse_matrix> ldlt_;
  int ldlt_version_ = -1;
#ifdef CGAL_HC_HAS_CHOLMOD
  std::unique_ptr<Eigen::CholmodSupernodalLLT<Sparse_matrix> > cholmod_;
  int cholmod_version_ = -1;
#endif
};

/// the options of a Newton run
struct Newton_options
{
  int max_iterations = 100;
  double accuracy = 1e-11;
  /// after reaching `accuracy`, keep taking Newton steps while the error at least halves (at most
  /// `max_polishing_steps`): the default "iterate to the rounding level"
  bool polish = true;
  int max_polishing_steps = 4;
  bool verbose = false;
  Sparse_solver solver = Sparse_solver::DEFAULT;
  std::function<bool(const Flow_progress&)> callback; ///< false stops (CANCELLED)
  /// vertices whose conformal factor is held (Dirichlet condition, or the gauge of the Euclidean closed case)
  std::vector<char> fixed;
  /// whether the curvature error of fixed vertices counts (true for the gauge vertex)
  bool fixed_in_error = true;
};

template <class Point_3>
class Newton_solver
{
public:
  Newton_solver(Flow_engine<Point_3>& eng, const Newton_options& o, Flow_statistics& st)
    : eng_(eng), o_(o), st_(st), n_(int(eng.u.size())), g_(eng.u.size()), chol_(o.solver), H_(n_, n_), rhs_(n_), delta_(n_)
  {
    if(o_.fixed.empty()) o_.fixed.assign(eng.u.size(), 0);
  }

  /// runs the flow; the statistics receive status, iterations, errors and energies
  void run()
  {
    double err = 0;
    if(!evaluate(err)) st_.status = Flow_status::FLIP_LIMIT_REACHED;
    else if(!std::isfinite(err)) st_.status = Flow_status::NUMERICAL_FAILURE;
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
  // lengths, angles, flips, curvature and the gradient g = K - target at the current u
  bool evaluate(double& max_err)
  {
    eng_.compute_lengths();
    eng_.compute_angles();
    if(!eng_.make_delaunay()) return false;
    eng_.compute_curvature();
    max_err = 0;
    for(int i = 0; i < n_; ++i) {
      g_[i] = eng_.K[i] - eng_.target[i];
      if(o_.fixed[i] && !o_.fixed_in_error) continue;
      if(!std::isfinite(g_[i])) { max_err = std::numeric_limits<double>::infinity(); return true; }
      max_err = (std::max)(max_err, std::abs(g_[i]));
    }
    return true;
  }

  // the Newton direction at the current state (false: numerical failure)
  bool direction()
  {
    eng_.hessian_triplets(trip_);
    trip_.erase(std::remove_if(trip_.begin(), trip_.end(), [&](const Eigen::Triplet<double>& t) {
                  return o_.fixed[t.row()] || o_.fixed[t.col()]; }), trip_.end());
    for(int i = 0; i < n_; ++i) if(o_.fixed[i]) trip_.emplace_back(i, i, 1.0);
    H_.setFromTriplets(trip_.begin(), trip_.end());
    for(int i = 0; i < n_; ++i) rhs_[i] = o_.fixed[i] ? 0.0 : -g_[i];
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = chol_.solve(H_, eng_.pattern_version, rhs_, delta_, st_);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if(st_.first_factorization_seconds == 0) st_.first_factorization_seconds = dt;
    st_.factorization_seconds += dt;
    return ok;
  }

  // one damped Newton step; on failure sets the status and restores the previous state. `strict`: accept
  // only a decrease of the max error (polishing)
  bool step(double& err, double& t, bool strict)
  {
    if(!direction()) { st_.status = Flow_status::NUMERICAL_FAILURE; return false; }
    double slope0 = 0;
    for(int i = 0; i < n_; ++i) slope0 += g_[i] * delta_[i];
    u_old_ = eng_.u; g_old_ = g_;
    const double err_old = err;
    t = 1.0;
    // accept t when the energy decreases (trapezoidal estimate from the directional derivatives; the energy
    // is convex for E^2 / H^2) or the max error decreases
    while(t > 1e-12) {
      for(int i = 0; i < n_; ++i) eng_.u[i] = u_old_[i] + t * delta_[i];
      double e2 = 0;
      if(!evaluate(e2)) { st_.status = Flow_status::FLIP_LIMIT_REACHED; restore(err, err_old); return false; }
      if(std::isfinite(e2)) {
        double slope_t = 0;
        for(int i = 0; i < n_; ++i) slope_t += g_[i] * delta_[i];
        const double de = 0.5 * t * (slope0 + slope_t);
        const bool ok = strict ? e2 < err_old
                               : ((slope0 < 0 && de <= 1e-4 * t * slope0) || e2 < err_old * (1 - 1e-4 * t));
        if(ok) { err = e2; energy_ += de; return true; }
      }
      if(strict) break;
      t *= 0.5;
    }
    restore(err, err_old);
    if(!strict) st_.status = Flow_status::LINE_SEARCH_FAILED;
    return false;
  }

  void restore(double& err, double err_old)
  {
    eng_.u = u_old_;
    double e2 = 0;
    evaluate(e2);
    err = std::isfinite(e2) ? e2 : err_old;
  }

  bool report(double err, double t)
  {
    st_.error_history.push_back(err);
    st_.energy_history.push_back(energy_);
    Flow_progress pr;
    pr.iteration = st_.iterations; pr.max_curvature_error = err; pr.step_length = t; pr.number_of_flips = eng_.flips;
    if(o_.verbose)
      std::cerr << "Ricci flow: iteration " << st_.iterations << "  max |K - target| = " << err
                << "  step = " << t << "  flips = " << eng_.flips << std::endl;
    return !o_.callback || o_.callback(pr);
  }

  // Newton converges quadratically: a few more steps reach the rounding level of double arithmetic
  void polish(double& err)
  {
    for(int k = 0; k < o_.max_polishing_steps && err > 0; ++k) {
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
  std::vector<double> g_, u_old_, g_old_;
  Sparse_cholesky chol_;
  std::vector<Eigen::Triplet<double> > trip_;
  Sparse_matrix H_;
  Eigen::VectorXd rhs_, delta_;
  double energy_ = 0;
};

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_NEWTON_H
