// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Multiprecision support of the embedding (the manual's "Accuracy of the relator"): an MPFR floating-point
// type with a run-time precision (Boost.Multiprecision's mpfr_float_backend over the MPFR library that CGAL
// already requires) made usable as the FT of a CGAL kernel, so that the layer's Disk_geometry and
// Poincare_disk_isometry_2 run unchanged in any precision; exact dyadic isometries (CGAL::Gmpzf entries) for
// the returned deck transformations, whose products are exact.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_MULTIPRECISION_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_MULTIPRECISION_H

#include <CGAL/boost_mp.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Poincare_disk_isometry_2.h>

#include <boost/multiprecision/mpfr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

/// MPFR floating point with the precision of its creation (`Mp_precision_guard`); no expression templates
typedef boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, boost::multiprecision::et_off> Mp_real;

} // namespace internal
} // namespace Discrete_Ricci_flow

// the traits a CGAL kernel and Poincare_disk_isometry_2 need (CGAL 5.5's boost_mp.h covers only the integer and
// rational Boost types): a field with square root, real embeddable, not exact
template <>
class Algebraic_structure_traits<Discrete_Ricci_flow::internal::Mp_real>
  : public Algebraic_structure_traits_base<Discrete_Ricci_flow::internal::Mp_real, Field_with_sqrt_tag>
{
public:
  typedef Tag_false Is_exact;
  typedef Tag_true Is_numerical_sensitive;
  struct Sqrt : public CGAL::cpp98::unary_function<Type, Type>
  {
    Type operator()(const Type& x) const { return boost::multiprecision::sqrt(x); }
  };
};

template <>
class Real_embeddable_traits<Discrete_Ricci_flow::internal::Mp_real>
  : public INTERN_RET::Real_embeddable_traits_base<Discrete_Ricci_flow::internal::Mp_real, CGAL::Tag_true>
{
public:
  struct To_double : public CGAL::cpp98::unary_function<Type, double>
  {
    double operator()(const Type& x) const { return x.convert_to<double>(); }
  };
  struct To_interval : public CGAL::cpp98::unary_function<Type, std::pair<double, double> >
  {
    std::pair<double, double> operator()(const Type& x) const
    {
      // rounded down and up by MPFR: an enclosure (the nearest double plus a denormal was none)
      return std::make_pair(mpfr_get_d(x.backend().data(), MPFR_RNDD), mpfr_get_d(x.backend().data(), MPFR_RNDU));
    }
  };
  struct Is_finite : public CGAL::cpp98::unary_function<Type, bool>
  {
    bool operator()(const Type& x) const { return boost::multiprecision::isfinite(x); }
  };
};

namespace Discrete_Ricci_flow {
namespace internal {

typedef CGAL::Simple_cartesian<Mp_real> Mp_kernel;
typedef CGAL::Poincare_disk_isometry_2<Mp_kernel> Mp_isometry;
typedef CGAL::Simple_cartesian<CGAL::Gmpzf> Exact_kernel;
typedef CGAL::Poincare_disk_isometry_2<Exact_kernel> Exact_isometry;

/// sets the precision (in bits) of the Mp_real numbers created in its scope, restores the previous one
class Mp_precision_guard
{
public:
  explicit Mp_precision_guard(unsigned bits) : old_(Mp_real::default_precision())
  {
    // Boost counts decimal digits: d digits give at least d log2(10) + 1 bits
    Mp_real::default_precision(static_cast<unsigned>(std::ceil(bits * 0.30102999566398120)) + 1);
  }
  ~Mp_precision_guard() { Mp_real::default_precision(old_); }
  Mp_precision_guard(const Mp_precision_guard&) = delete;
  Mp_precision_guard& operator=(const Mp_precision_guard&) = delete;

private:
  unsigned old_;
};

/// x * 2^e, exactly
inline CGAL::Gmpzf times_power_of_two(CGAL::Gmpzf x, long e)
{
  while(e != 0) {
    const long s = e > 512 ? 512 : (e < -512 ? -512 : e);
    x = x * CGAL::Gmpzf(std::ldexp(1.0, int(s)));
    e -= s;
  }
  return x;
}

/// the exact value of an MPFR number (a dyadic rational)
inline CGAL::Gmpzf to_exact(const Mp_real& x)
{
  if(!boost::multiprecision::isfinite(x)) throw CGAL::Numerical_error("Hyperbolic_embedding: a non-finite multiprecision value");
  if(x == 0) return CGAL::Gmpzf(0);
  mpz_t z;
  mpz_init(z);
  const long e = long(mpfr_get_z_2exp(z, x.backend().data()));
  const CGAL::Gmpzf m(z);
  mpz_clear(z);
  return times_power_of_two(m, e);
}

/// the exact value of a long double (a dyadic rational): its two halves are doubles
inline CGAL::Gmpzf to_exact(long double x)
{
  if(!std::isfinite(x)) throw CGAL::Numerical_error("Hyperbolic_embedding: a non-finite long-double value");
  const double hi = double(x), lo = double(x - (long double)hi);
  return CGAL::Gmpzf(hi) + CGAL::Gmpzf(lo);
}

template <class Isometry>
Exact_isometry to_exact_isometry(const Isometry& g)
{
  return Exact_isometry(to_exact(g.alpha_real()), to_exact(g.alpha_imag()), to_exact(g.beta_real()), to_exact(g.beta_imag()));
}

/// the distance to +-identity of the normalized matrix of an exact isometry: max entry difference of
/// M / sqrt(det M) to +-I, evaluated in double from the exact entries (relative error about 1e-16)
inline double exact_defect(const Exact_isometry& m)
{
  const CGAL::Gmpzf det = m.determinant();
  if(!(det > CGAL::Gmpzf(0))) return std::numeric_limits<double>::infinity();
  // scale by a power of two to bring det near 1 before the conversion (the entries may exceed double's range)
  const std::pair<double, long> de = det.to_double_exp();
  const long half = de.second / 2;
  const double d = std::ldexp(de.first, int(de.second - 2 * half)); // det / 2^(2 half)
  const double s = std::sqrt(d);
  auto entry = [&](const CGAL::Gmpzf& x) {
    const std::pair<double, long> xe = x.to_double_exp();
    return std::ldexp(xe.first, int(xe.second - half)) / s; // x / 2^half / sqrt(det / 2^(2 half))
  };
  const double a[4] = {entry(m.alpha_real()), entry(m.alpha_imag()), entry(m.beta_real()), entry(m.beta_imag())};
  double dp = std::abs(a[0] - 1), dm = std::abs(a[0] + 1);
  for(int i = 1; i < 4; ++i) { dp = (std::max)(dp, std::abs(a[i])); dm = (std::max)(dm, std::abs(a[i])); }
  return (std::min)(dp, dm);
}

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_MULTIPRECISION_H
