// Nearly flat ("cap") and needle triangles of the three background geometries, and their exact corner angles
// (MPFR at 320 bits, from the same double side lengths): the reference of the accuracy tests of the triangle
// formulas (the shared layer's `corner_angle()` / `triangle_area()`, the Ricci flow's `triangle_angles()`).
#ifndef CGAL_HC_TEST_FLAT_TRIANGLES_H
#define CGAL_HC_TEST_FLAT_TRIANGLES_H

#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace cgal_hc_test {

/// `n` triangles (side lengths) that satisfy the strict triangle inequalities in double (and, kappa = -1,
/// perimeter < 2 pi), for curvature kappa = 1 (H^2), 0 (E^2), -1 (S^2): even ones nearly flat (the longest
/// side shorter than the sum of the others by a relative 1e-16 to 1e-2), odd ones needles (shortest side
/// 1e-9 to 0.1 times the others); scales 1e-3 to 1e2 (S^2: 0.1 to 1.3), sides in random order
inline std::vector<std::array<double, 3> > flat_and_needle_triangles(int kappa, std::size_t n, unsigned seed)
{
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<std::array<double, 3> > out;
  while(out.size() < n) {
    const double scale = kappa < 0 ? 0.1 + 1.2 * U(gen) : std::pow(10.0, -3 + 5 * U(gen));
    std::array<double, 3> l;
    if(out.size() % 2 == 0) {
      const double b = scale * U(gen), c = scale * U(gen);
      l = {{(b + c) * (1 - std::pow(10.0, -16 + 14 * U(gen))), b, c}};
    } else {
      const double c = scale * std::pow(10.0, -1 - 8 * U(gen));
      l = {{scale, scale + c * (2 * U(gen) - 1) * 0.99, c}};
    }
    std::shuffle(l.begin(), l.end(), gen);
    bool ok = l[0] > 0 && l[1] > 0 && l[2] > 0;
    for(int i = 0; i < 3; ++i) ok = ok && l[i] < l[(i + 1) % 3] + l[(i + 2) % 3];
    if(kappa < 0) ok = ok && l[0] + l[1] + l[2] < 2 * 3.14159265358979323846;
    if(ok) out.push_back(l);
  }
  return out;
}

/// the exact corner angles (theta[i] opposite l[i]) of the triangle with these double sides, rounded to
/// double, by the half-angle formula in MPFR (320 bits: its cancellations cost at most about 110 bits here);
/// `pi_minus_sum` receives pi - (theta_0 + theta_1 + theta_2) (the H^2 area) rounded once
inline void exact_corner_angles(int kappa, const std::array<double, 3>& l, double theta[3], double& pi_minus_sum)
{
  mpfr_t L[3], s, d[3], f[3], fs, t, u, sum;
  for(int i = 0; i < 3; ++i) mpfr_inits2(320, L[i], d[i], f[i], (mpfr_ptr)0);
  mpfr_inits2(320, s, fs, t, u, sum, (mpfr_ptr)0);
  auto F = [kappa](mpfr_t out, mpfr_t x) {
    if(kappa > 0) mpfr_sinh(out, x, MPFR_RNDN);
    else if(kappa < 0) mpfr_sin(out, x, MPFR_RNDN);
    else mpfr_set(out, x, MPFR_RNDN);
  };
  for(int i = 0; i < 3; ++i) mpfr_set_d(L[i], l[i], MPFR_RNDN);
  mpfr_add(s, L[0], L[1], MPFR_RNDN); mpfr_add(s, s, L[2], MPFR_RNDN); mpfr_div_2ui(s, s, 1, MPFR_RNDN);
  F(fs, s);
  for(int i = 0; i < 3; ++i) { mpfr_sub(d[i], s, L[i], MPFR_RNDN); F(f[i], d[i]); }
  mpfr_set_zero(sum, 1);
  for(int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    mpfr_mul(t, f[j], f[k], MPFR_RNDN); mpfr_sqrt(t, t, MPFR_RNDN);
    mpfr_mul(u, fs, f[i], MPFR_RNDN); mpfr_sqrt(u, u, MPFR_RNDN);
    mpfr_atan2(t, t, u, MPFR_RNDN); mpfr_mul_2ui(t, t, 1, MPFR_RNDN);
    theta[i] = mpfr_get_d(t, MPFR_RNDN);
    mpfr_add(sum, sum, t, MPFR_RNDN);
  }
  mpfr_const_pi(t, MPFR_RNDN); mpfr_sub(t, t, sum, MPFR_RNDN);
  pi_minus_sum = mpfr_get_d(t, MPFR_RNDN);
  for(int i = 0; i < 3; ++i) mpfr_clears(L[i], d[i], f[i], (mpfr_ptr)0);
  mpfr_clears(s, fs, t, u, sum, (mpfr_ptr)0);
}

} // namespace cgal_hc_test

#endif // CGAL_HC_TEST_FLAT_TRIANGLES_H
