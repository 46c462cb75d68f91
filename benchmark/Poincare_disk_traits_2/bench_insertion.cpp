// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Range insertion of n uniform random points of the Poincare disk into
//   DT_poincare   Delaunay_triangulation_2<Poincare_disk_traits_2<Epick>>   (the hyperbolic Delaunay triangulation)
//   HDT_poincare  Hyperbolic_Delaunay_triangulation_2<Poincare_disk_traits_2<Epick>>
// against, on the same points and in the same run,
//   DT_epick      Delaunay_triangulation_2<Epick>                            (the Euclidean reference)
//   HDT_ck        Hyperbolic_Delaunay_triangulation_2<Hyperbolic_Delaunay_triangulation_CK_traits_2<>> (CGAL's)
// Three distributions: uniform in the hyperbolic disk of radius 5 (area measure), uniform in the Euclidean disk
// of radius 0.999, and a square grid of the disk of radius 0.99 (degenerate: many cocircular and collinear points). One machine-readable line per measurement:
//   name=<triangulation> dist=<distribution> n=<n> seconds=<best of reps> ratio_to_epick=<t / t(DT_epick)>
//   ratio_to_ck=<t / t(HDT_ck)> vertices=<number of vertices>
// Built with CGAL_POINCARE_DISK_TRAITS_2_STATISTICS (target bench_Poincare_disk_traits_2_filter_stats) it instead
// reports, for DT_poincare, how often the predicates counted by the traits (orientation, Klein comparisons and
// every predicate evaluated with the interval filter) could not be decided by the static filter and how often
// they fell back to exact rational arithmetic:
//   name=filter_stats dist=... n=... calls=... static_filter_failures=... exact_fallbacks=... exact_fraction=...
//
// Usage: bench_Poincare_disk_traits_2_insertion [n1 n2 ...]   (default: 100000 1000000)
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hyperbolic_Delaunay_triangulation_2.h>
#include <CGAL/Hyperbolic_Delaunay_triangulation_CK_traits_2.h>
#include <CGAL/Poincare_disk_traits_2.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::Poincare_disk_traits_2<K> Traits;
typedef CGAL::Delaunay_triangulation_2<Traits> DT_poincare;
typedef CGAL::Hyperbolic_Delaunay_triangulation_2<Traits> HDT_poincare;
typedef CGAL::Delaunay_triangulation_2<K> DT_epick;
typedef CGAL::Hyperbolic_Delaunay_triangulation_CK_traits_2<> CK_traits;
typedef CGAL::Hyperbolic_Delaunay_triangulation_2<CK_traits> HDT_ck;

static std::vector<Point> uniform_hyperbolic(std::size_t n, double R, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> v;
  v.reserve(n);
  const double c = std::cosh(R) - 1;
  for(std::size_t i = 0; i < n; ++i) {
    const double rho = std::acosh(1 + c * u(rng)), t = 2 * M_PI * u(rng), e = std::tanh(rho / 2);
    v.emplace_back(e * std::cos(t), e * std::sin(t));
  }
  return v;
}

/// about n points of a square grid of the disk of radius 0.99 (many cocircular and collinear subsets: degenerate)
static std::vector<Point> grid(std::size_t n)
{
  const double r = 0.99, step = std::sqrt(M_PI * r * r / double(n));
  std::vector<Point> v;
  const int m = int(r / step) + 1;
  for(int i = -m; i <= m; ++i)
    for(int j = -m; j <= m; ++j)
      if((i * step) * (i * step) + (j * step) * (j * step) < r * r) v.emplace_back(i * step, j * step);
  return v;
}

static std::vector<Point> uniform_euclidean(std::size_t n, double r, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-r, r);
  std::vector<Point> v;
  v.reserve(n);
  while(v.size() < n) {
    const double x = u(rng), y = u(rng);
    if(x * x + y * y < r * r) v.emplace_back(x, y);
  }
  return v;
}

template <class F>
static double best_time(int reps, std::size_t& vertices, const F& build)
{
  double best = 1e300;
  for(int i = 0; i < reps; ++i) {
    // process CPU time, so that the ratios of a row do not depend on what else the machine runs
    const std::clock_t t0 = std::clock();
    vertices = build();
    best = (std::min)(best, double(std::clock() - t0) / CLOCKS_PER_SEC);
  }
  return best;
}

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes;
  for(int i = 1; i < argc; ++i) sizes.push_back(std::strtoul(argv[i], nullptr, 10));
  if(sizes.empty()) sizes = {100000, 1000000};
  std::cout.precision(4);

  for(const std::string dist : {"hyperbolic_R5", "euclidean_r0.999", "grid_r0.99"}) {
    for(const std::size_t n : sizes) {
      const std::vector<Point> pts = dist == "hyperbolic_R5" ? uniform_hyperbolic(n, 5.0, 42)
                                   : dist == "grid_r0.99"    ? grid(n)
                                                             : uniform_euclidean(n, 0.999, 42);
      const int reps = n <= 200000 ? 3 : 1;
#ifdef CGAL_HC_BENCH_STATS_ONLY
      auto& st = CGAL::Poincare_disk_internal::Predicate_statistics::instance();
      st.reset();
      DT_poincare dt(pts.begin(), pts.end());
      const double calls = double(st.calls), sf = double(st.static_filter_failures), ex = double(st.interval_failures);
      std::cout << "name=filter_stats dist=" << dist << " n=" << pts.size() << " vertices=" << dt.number_of_vertices()
                << " calls=" << st.calls << " static_filter_failures=" << st.static_filter_failures
                << " exact_fallbacks=" << st.interval_failures << " static_failure_fraction=" << sf / calls
                << " exact_fraction=" << ex / calls << std::endl;
      (void)reps;
#else
      std::size_t nv_e = 0, nv_p = 0, nv_hp = 0, nv_ck = 0;
      const double t_e = best_time(reps, nv_e, [&] { DT_epick t(pts.begin(), pts.end()); return t.number_of_vertices(); });
      const double t_p = best_time(reps, nv_p, [&] { DT_poincare t(pts.begin(), pts.end()); return t.number_of_vertices(); });
      const double t_hp = best_time(reps, nv_hp, [&] { HDT_poincare t(pts.begin(), pts.end()); return t.number_of_vertices(); });
      std::vector<CK_traits::Point_2> pts_ck;
      pts_ck.reserve(n);
      for(const Point& p : pts) pts_ck.emplace_back(p.x(), p.y());
      const double t_ck = best_time(reps, nv_ck, [&] { HDT_ck t(pts_ck.begin(), pts_ck.end()); return t.number_of_vertices(); });
      auto line = [&](const char* name, double t, std::size_t nv) {
        std::cout << "name=" << name << " dist=" << dist << " n=" << pts.size() << " seconds=" << t
                  << " ratio_to_epick=" << t / t_e << " ratio_to_ck=" << t / t_ck << " vertices=" << nv << std::endl;
      };
      line("DT_epick", t_e, nv_e);
      line("DT_poincare", t_p, nv_p);
      line("HDT_poincare", t_hp, nv_hp);
      line("HDT_ck", t_ck, nv_ck);
#endif
    }
  }
  return EXIT_SUCCESS;
}
