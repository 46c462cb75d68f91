// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact evaluation of predicate polynomials on any number type:
//   - double coordinates: interval arithmetic first (Interval_nt_advanced under Protect_FPU_rounding), and the
//     exact rational fallback (CGAL::Exact_rational, built exactly from the doubles) when the interval sign
//     is uncertain. The hot predicates also have a static filter in front (see Poincare_disk_traits_2.h).
//   - any other number type (Gmpq, Lazy_exact_nt, Epeck_with_sqrt's FT): the polynomial is evaluated directly,
//     which is exact (lazy numbers filter internally).
// Optional counters (compile with CGAL_POINCARE_DISK_TRAITS_2_STATISTICS) report how often each stage decides.
#ifndef CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_FILTERED_EVALUATION_H
#define CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_FILTERED_EVALUATION_H

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>
#include <CGAL/number_utils.h>

#include <atomic>
#include <type_traits>

namespace CGAL {
namespace Poincare_disk_internal {

/// How often each stage of the predicates decided (only counted with CGAL_POINCARE_DISK_TRAITS_2_STATISTICS).
struct Predicate_statistics
{
  std::atomic<unsigned long long> calls{0};          // predicate calls on double input
  std::atomic<unsigned long long> static_filter_failures{0}; // static filter could not decide
  std::atomic<unsigned long long> interval_failures{0};      // interval arithmetic could not decide (exact used)

  static Predicate_statistics& instance() { static Predicate_statistics s; return s; }
  void reset() { calls = 0; static_filter_failures = 0; interval_failures = 0; }
};

#ifdef CGAL_POINCARE_DISK_TRAITS_2_STATISTICS
#  define CGAL_PD_COUNT(field) (++CGAL::Poincare_disk_internal::Predicate_statistics::instance().field)
#else
#  define CGAL_PD_COUNT(field) ((void)0)
#endif

template <class T> struct Certain_type { typedef T type; };
template <class T> struct Certain_type<Uncertain<T> > { typedef T type; };

/// Evaluates `f(xs...)` exactly where `f` is a generic callable computing a sign / comparison / bool of a
/// polynomial in its arguments. Generic version: the number type is exact, evaluate directly.
template <class NT>
struct Exact_evaluator
{
  template <class F, class... Args>
  static auto eval(const F& f, const Args&... xs) -> typename Certain_type<decltype(f(xs...))>::type
  {
    return make_certain(f(xs...));
  }
};

/// double: interval arithmetic, then exact rationals.
template <>
struct Exact_evaluator<double>
{
  template <class F, class... Args>
  static auto eval(const F& f, const Args&... xs)
      -> typename Certain_type<decltype(f(Interval_nt_advanced(xs)...))>::type
  {
    CGAL_PD_COUNT(calls);
    return interval_then_exact(f, xs...);
  }

  /// same, for callers whose static filter already failed (they counted the call)
  template <class F, class... Args>
  static auto eval_after_static_filter(const F& f, const Args&... xs)
      -> typename Certain_type<decltype(f(Interval_nt_advanced(xs)...))>::type
  {
    CGAL_PD_COUNT(static_filter_failures);
    return interval_then_exact(f, xs...);
  }

private:
  template <class F, class... Args>
  static auto interval_then_exact(const F& f, const Args&... xs)
      -> typename Certain_type<decltype(f(Interval_nt_advanced(xs)...))>::type
  {
    {
      Protect_FPU_rounding<true> guard;
      try {
        const auto r = f(Interval_nt_advanced(xs)...);
        if(is_certain(r)) return get_certain(r);
      } catch(Uncertain_conversion_exception&) {
      }
    }
    CGAL_PD_COUNT(interval_failures);
    return make_certain(f(Exact_rational(xs)...));
  }
};

} // namespace Poincare_disk_internal
} // namespace CGAL

#endif
