// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared helpers of the Poincare_disk_traits_2 tests: the three kernels, exact conversion between kernel points
// and the rational reference, and the (near-)degenerate point sets.
#ifndef CGAL_HC_TEST_POINCARE_DISK_SUPPORT_H
#define CGAL_HC_TEST_POINCARE_DISK_SUPPORT_H

#include "reference.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace pd_test {


using pd_ref::Q;
using pd_ref::QP;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> SC_gmpq;
typedef CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt Epeck_sqrt;

/// Conversion of a rational to the kernel's FT (exact for SC_gmpq and Epeck_sqrt, rounded to nearest for Epick)
/// and back (exact, for the kernels whose FT is rational or double).
template <class K> struct Kio;

template <> struct Kio<Epick>
{
  static const char* name() { return "Epick"; }
  static double ft(const Q& q) { return CGAL::to_double(q); }
  static Q exact(double v) { return Q(v); }
  static constexpr bool has_exact_value = true;
};

template <> struct Kio<SC_gmpq>
{
  static const char* name() { return "Simple_cartesian<Gmpq>"; }
  static CGAL::Gmpq ft(const Q& q) { return q; }
  static Q exact(const CGAL::Gmpq& v) { return v; }
  static constexpr bool has_exact_value = true;
};

template <> struct Kio<Epeck_sqrt>
{
  typedef Epeck_sqrt::FT FT;
  static const char* name() { return "Epeck_with_sqrt"; }
  static FT ft(const Q& q)
  {
    std::ostringstream os;
    os << q; // "num/den" or "num"
    return FT(CORE::Expr(CORE::BigRat(os.str())));
  }
  static constexpr bool has_exact_value = false; // use the rational the point was built from
};

/// a kernel point together with the exact rational coordinates of that very point
template <class K>
struct Tp
{
  typename K::Point_2 p;
  QP e;
};

template <class K>
Tp<K> make(const QP& q)
{
  Tp<K> t;
  t.p = typename K::Point_2(Kio<K>::ft(q.x), Kio<K>::ft(q.y));
  if constexpr(Kio<K>::has_exact_value) t.e = QP(Kio<K>::exact(t.p.x()), Kio<K>::exact(t.p.y()));
  else t.e = q;
  return t;
}

template <class K>
std::vector<Tp<K> > make_all(const std::vector<QP>& v)
{
  std::vector<Tp<K> > r;
  for(const QP& q : v) r.push_back(make<K>(q));
  return r;
}

inline QP qp(double x, double y) { return QP(Q(x), Q(y)); }

inline std::string str(const QP& p)
{
  std::ostringstream os;
  os.precision(17);
  os << "(" << p.dx() << ", " << p.dy() << ")";
  return os.str();
}

// ---------------------------------------------------------------- point sets

/// uniform in the Euclidean disk of radius r_max
inline std::vector<QP> random_euclidean(std::mt19937_64& rng, int n, double r_max)
{
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<QP> v;
  while(int(v.size()) < n) {
    const double x = u(rng) * r_max, y = u(rng) * r_max;
    if(x * x + y * y < r_max * r_max) v.push_back(qp(x, y));
  }
  return v;
}

/// uniform (area measure) in the hyperbolic disk of radius R around the origin
inline std::vector<QP> random_hyperbolic(std::mt19937_64& rng, int n, double R)
{
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<QP> v;
  const double c = std::cosh(R) - 1;
  for(int i = 0; i < n; ++i) {
    const double rho = std::acosh(1 + c * u(rng)); // P(rho < r) = (cosh r - 1) / (cosh R - 1)
    const double t = 2 * M_PI * u(rng), e = std::tanh(rho / 2);
    v.push_back(qp(e * std::cos(t), e * std::sin(t)));
  }
  return v;
}

/// integer points (X, Y) with X^2 + Y^2 = H^2
inline std::vector<std::pair<long, long> > pythagorean(long H)
{
  std::vector<std::pair<long, long> > r;
  for(long x = -H; x <= H; ++x) {
    const long y2 = H * H - x * x;
    const long y = std::lround(std::sqrt(double(y2)));
    if(y * y == y2) { r.emplace_back(x, y); if(y != 0) r.emplace_back(x, -y); }
  }
  return r;
}

/// exactly cocircular dyadic points (exact doubles): centre (cx, cy) / 2^m, radius H / 2^m
inline std::vector<QP> dyadic_circle(long cx, long cy, long H, int m)
{
  std::vector<QP> v;
  const double s = std::ldexp(1.0, -m);
  for(auto& xy : pythagorean(H)) {
    const QP p = qp((cx + xy.first) * s, (cy + xy.second) * s);
    if(pd_ref::in_open_disk(p)) v.push_back(p);
  }
  return v;
}

/// points of the geodesic supported by the circle of centre (A, B) / 2^m, radius H / 2^m, orthogonal to the
/// unit circle iff A^2 + B^2 = 4^m + H^2 (checked by the caller); exact doubles
inline std::vector<QP> dyadic_geodesic(long A, long B, long H, int m) { return dyadic_circle(A, B, H, m); }

/// points of the horocycle tangent to the unit circle at (1, 0): centre (2^m - H) / 2^m, radius H / 2^m
inline std::vector<QP> dyadic_horocycle(long H, int m) { return dyadic_circle((1L << m) - H, 0, H, m); }

/// points on a diameter (exact doubles)
inline std::vector<QP> diameter_points()
{
  return {qp(-0.625, -0.625), qp(-0.5, -0.5), qp(0.125, 0.125), qp(0.25, 0.25), qp(0.6875, 0.6875), qp(0, 0)};
}

/// vertices of a regular hyperbolic quadrilateral centred at the origin, moved by the rational isometry
/// z -> (z + a) / (1 + conj(a) z): exactly cocircular rationals (a regular polygon of the hyperbolic circle)
inline std::vector<QP> moved_square(const Q& r, const Q& ax, const Q& ay)
{
  std::vector<QP> v = {QP(r, 0), QP(0, r), QP(-r, 0), QP(0, -r)};
  for(QP& p : v) p = pd_ref::moebius(p, 1, 0, ax, ay);
  return v;
}

/// the images of a point set by a rational isometry (exact)
inline std::vector<QP> moved(const std::vector<QP>& v, const Q& ar, const Q& ai, const Q& br, const Q& bi)
{
  std::vector<QP> r;
  for(const QP& p : v) r.push_back(pd_ref::moebius(p, ar, ai, br, bi));
  return r;
}

/// 1-ulp perturbations: each point of v, one coordinate moved to the next double up or down (kept in the disk)
inline std::vector<QP> ulp_perturbed(const std::vector<QP>& v, std::mt19937_64& rng)
{
  std::vector<QP> r;
  for(const QP& p : v) {
    double x = p.dx(), y = p.dy();
    switch(rng() % 4) {
      case 0: x = std::nextafter(x, 2.0); break;
      case 1: x = std::nextafter(x, -2.0); break;
      case 2: y = std::nextafter(y, 2.0); break;
      default: y = std::nextafter(y, -2.0); break;
    }
    const QP q = qp(x, y);
    r.push_back(pd_ref::in_open_disk(q) ? q : qp(p.dx(), p.dy()));
  }
  return r;
}

/// points with |p| = 1 - 2^-50 (on the axes exactly; elsewhere rounded, then kept if in the disk)
inline std::vector<QP> near_boundary(std::mt19937_64& rng, int n)
{
  const double r = 1.0 - std::ldexp(1.0, -50);
  std::vector<QP> v = {qp(r, 0), qp(0, r), qp(-r, 0), qp(0, -r)};
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  while(int(v.size()) < n) {
    const double t = u(rng);
    const QP p = qp(r * std::cos(t), r * std::sin(t));
    if(pd_ref::in_open_disk(p)) v.push_back(p);
  }
  return v;
}

struct Named_set
{
  std::string name;
  std::vector<QP> points;
};

/// the degenerate and near-degenerate sets shared by the predicate and triangulation tests (exact doubles)
inline std::vector<Named_set> degenerate_sets(std::mt19937_64& rng)
{
  std::vector<Named_set> s;
  s.push_back({"circle-centred", dyadic_circle(0, 0, 325, 10)});
  s.push_back({"circle-off-centre", dyadic_circle(256, -384, 325, 10)});
  s.push_back({"circle-near-boundary", dyadic_circle(2700, 2600, 325, 12)});
  s.push_back({"circle-crossing-boundary", dyadic_circle(2900, 2700, 325, 12)});
  s.push_back({"geodesic-1", dyadic_geodesic(676, 835, 325, 10)});
  s.push_back({"geodesic-2", dyadic_geodesic(412, 445, 325, 9)});
  s.push_back({"geodesic-3", dyadic_geodesic(325, 1024, 325, 10)});
  s.push_back({"diameter", diameter_points()});
  s.push_back({"horocycle", dyadic_horocycle(325, 10)});
  s.push_back({"horocycle-small", dyadic_horocycle(325, 12)});
  s.push_back({"near-boundary", near_boundary(rng, 12)});
  const std::size_t n = s.size();
  for(std::size_t i = 0; i < n; ++i)
    if(s[i].name != "near-boundary") s.push_back({s[i].name + "+1ulp", ulp_perturbed(s[i].points, rng)});
  return s;
}

} // namespace pd_test

#endif
