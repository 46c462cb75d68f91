// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every predicate of Poincare_disk_traits_2, on Epick, Simple_cartesian<Gmpq> and
// Exact_predicates_exact_constructions_kernel_with_sqrt, against the independent rational reference of
// reference.h: random input, exactly degenerate input (cocircular, on a geodesic, on a horocycle, regular
// polygons, |p| = 1 - 2^-50), 1-ulp perturbations of it, and exact isometric images.
#include "cgal_hc_test.h"
#include "test_support.h"

#include <CGAL/Poincare_disk_isometry_2.h>
#include <CGAL/Poincare_disk_traits_2.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

using namespace pd_test;

namespace {

int sgn_of(CGAL::Sign s) { return int(s); }

std::string str3(const QP& p, const QP& q, const QP& r)
{
  return str(p) + " " + str(q) + " " + str(r);
}

/// Compares every predicate of the traits on kernel K with the reference on the points of `pts` (all triples /
/// quadruples when few, otherwise `samples` random ones). `set_name` tags failures.
template <class K>
void check_predicates(const std::vector<Tp<K> >& pts, const std::string& set_name, std::mt19937_64& rng,
                      std::size_t samples = 200)
{
  typedef CGAL::Poincare_disk_traits_2<K> Tr;
  typedef typename K::FT FT;
  const Tr tr;
  const std::string tag = std::string(Kio<K>::name()) + " / " + set_name + ": ";
  const std::size_t n = pts.size();
  if(n < 3) return;

  std::vector<std::array<std::size_t, 4> > tuples;
  if(n <= 9) {
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t k = 0; k < n; ++k)
          if(i != j && j != k && i != k) tuples.push_back({i, j, k, (i + j + k) % n});
  } else {
    std::uniform_int_distribution<std::size_t> u(0, n - 1);
    while(tuples.size() < samples) {
      const std::size_t i = u(rng), j = u(rng), k = u(rng), l = u(rng);
      if(i != j && j != k && i != k) tuples.push_back({i, j, k, l});
    }
  }

  for(const auto& t : tuples) {
    const Tp<K> &P = pts[t[0]], &Qp = pts[t[1]], &R = pts[t[2]], &S = pts[t[3]];
    const QP &p = P.e, &q = Qp.e, &r = R.e, &s = S.e;
    const std::string where = tag + str3(p, q, r) + " s=" + str(s);

    // orientation and the predicates built on it
    const int o = pd_ref::orientation(p, q, r);
    CGAL_HC_CHECK_MSG(sgn_of(tr.orientation_2_object()(P.p, Qp.p, R.p)) == o, where);
    CGAL_HC_CHECK_MSG(tr.collinear_2_object()(P.p, Qp.p, R.p) == (o == 0), where);
    CGAL_HC_CHECK_MSG(int(tr.side_of_oriented_hyperbolic_segment_2_object()(P.p, Qp.p, R.p)) == o, where);
    CGAL_HC_CHECK_MSG(int(tr.compare_x_2_object()(P.p, Qp.p)) == pd_ref::compare_klein_x(p, q), where);
    CGAL_HC_CHECK_MSG(int(tr.compare_y_2_object()(P.p, Qp.p)) == pd_ref::compare_klein_y(p, q), where);
    CGAL_HC_CHECK_MSG(tr.less_x_2_object()(P.p, Qp.p) == (pd_ref::compare_klein_x(p, q) < 0), where);

    // in-circle = side of the lifted plane; for a positive triangle with a compact circle, "inside" is the side
    // of the origin of R^3 (the hyperbolic disk bounded by the circle)
    const int ic = pd_ref::side_of_lifted_plane(p, q, r, s);
    CGAL_HC_CHECK_MSG(int(tr.side_of_oriented_circle_2_object()(P.p, Qp.p, R.p, S.p)) == ic, where);
    const bool compact = pd_ref::is_compact(p, q, r);
    if(compact && o > 0 && ic != 0)
      CGAL_HC_CHECK_MSG((ic > 0) == pd_ref::same_side_as_origin(p, q, r, s), "reference self-check " << where);

    // compact circumcircle, by the Minkowski normal and by the Euclidean centre and radius
    CGAL_HC_CHECK_MSG(compact == pd_ref::is_compact_euclidean(p, q, r), "reference self-check " << where);
    CGAL_HC_CHECK_MSG(tr.is_Delaunay_hyperbolic_2_object()(P.p, Qp.p, R.p) == compact, where);
    if(!compact) {
      const QP v[3] = {p, q, r};
      const int expected = pd_ref::non_hyperbolic_edge(v);
      int ind = -1;
      const bool h = tr.is_Delaunay_hyperbolic_2_object()(P.p, Qp.p, R.p, ind);
      CGAL_HC_CHECK_MSG(!h, where);
      // (bug T1 of BUGS-traits.md, fixed: the index used to be computed from coordinates rounded to double)
      if(expected >= 0) CGAL_HC_CHECK_MSG(ind == expected, where << " ind=" << ind << " expected " << expected);
    }

    // encroachment (and the mesher's Angle_2)
    const int enc = pd_ref::encroachment(p, q, r);
    const CGAL::Bounded_side bs = tr.side_of_hyperbolic_diametral_circle_2_object()(P.p, Qp.p, R.p);
    CGAL_HC_CHECK_MSG(bs == (enc > 0 ? CGAL::ON_BOUNDED_SIDE : (enc == 0 ? CGAL::ON_BOUNDARY : CGAL::ON_UNBOUNDED_SIDE)),
                      where);
    const CGAL::Angle an = tr.angle_2_object()(P.p, R.p, Qp.p);
    CGAL_HC_CHECK_MSG(an == (enc > 0 ? CGAL::OBTUSE : (enc == 0 ? CGAL::RIGHT : CGAL::ACUTE)), where);

    // distances
    CGAL_HC_CHECK_MSG(int(tr.compare_distance_2_object()(P.p, Qp.p, R.p)) == pd_ref::compare_distance(p, q, p, r), where);
    CGAL_HC_CHECK_MSG(int(tr.compare_hyperbolic_distance_2_object()(P.p, Qp.p, R.p, S.p)) ==
                        pd_ref::compare_distance(p, q, r, s), where);

    // central angle and circumradius against fixed thresholds and against the exact value itself
    std::vector<Q> sin2s = {Q(1) / 1000, Q(1) / 10, Q(1) / 4, Q(3) / 4, Q(1)};
    std::vector<Q> cosh2s = {Q(1), Q(2), Q(10), Q(1000000)};
    if(compact) {
      const Q sv = pd_ref::sin2_half_central_angle(p, q, r), cv = pd_ref::cosh2_circumradius(p, q, r);
      if(Kio<K>::has_exact_value && std::is_same<FT, double>::value) {
        // thresholds representable in FT: the nearest doubles and their neighbours
        const double d = CGAL::to_double(sv), c = CGAL::to_double(cv);
        for(double x : {d, std::nextafter(d, 0.0), std::nextafter(d, 2.0)}) sin2s.push_back(Q(x));
        for(double x : {c, std::nextafter(c, 0.0), std::nextafter(c, 1e300)}) cosh2s.push_back(Q(x));
      } else {
        sin2s.push_back(sv); cosh2s.push_back(cv);  // exactly EQUAL expected
      }
    }
    for(const Q& th : sin2s) {
      const FT fth = Kio<K>::ft(th);
      const Q eth = Kio<K>::has_exact_value ? Q(CGAL::to_double(fth)) : th;
      const Q used = std::is_same<FT, double>::value ? eth : th;
      CGAL_HC_CHECK_MSG(int(tr.compare_central_angle_2_object()(P.p, Qp.p, R.p, fth)) ==
                          pd_ref::compare_central_angle(p, q, r, used), where << " sin2=" << CGAL::to_double(th));
    }
    for(const Q& th : cosh2s) {
      const FT fth = Kio<K>::ft(th);
      const Q used = std::is_same<FT, double>::value ? Q(CGAL::to_double(fth)) : th;
      CGAL_HC_CHECK_MSG(int(tr.compare_hyperbolic_circumradius_2_object()(P.p, Qp.p, R.p, fth)) ==
                          pd_ref::compare_circumradius(p, q, r, used), where << " cosh2=" << CGAL::to_double(th));
    }
  }
}

template <class K>
void check_all_sets(std::size_t samples, bool with_random)
{
  std::mt19937_64 rng(20260517);
  if(with_random) {
    check_predicates<K>(make_all<K>(random_euclidean(rng, 60, 0.999)), "random-euclidean", rng, samples);
    check_predicates<K>(make_all<K>(random_hyperbolic(rng, 60, 5.0)), "random-hyperbolic-R5", rng, samples);
    check_predicates<K>(make_all<K>(random_hyperbolic(rng, 60, 0.01)), "random-hyperbolic-tiny", rng, samples);
  }
  for(const Named_set& s : degenerate_sets(rng)) check_predicates<K>(make_all<K>(s.points), s.name, rng, samples);
}

} // namespace

// ------------------------------------------------------------------------------------------------ the sets

CGAL_HC_TEST_CASE(degenerate_sets_are_exactly_degenerate)
{
  // the inputs of the degenerate tests, checked in rationals (otherwise the tests would prove nothing)
  std::mt19937_64 rng(1);
  for(const Named_set& s : degenerate_sets(rng)) {
    if(s.name.find("ulp") != std::string::npos || s.name == "near-boundary") continue;
    CGAL_HC_CHECK_MSG(s.points.size() >= 4, s.name << " has " << s.points.size() << " points");
    for(const QP& p : s.points) CGAL_HC_CHECK(pd_ref::in_open_disk(p));
    for(std::size_t i = 3; i < s.points.size(); ++i) {
      const QP &a = s.points[0], &b = s.points[1], &c = s.points[2], &d = s.points[i];
      if(s.name.find("geodesic") == 0 || s.name == "diameter")
        CGAL_HC_CHECK_MSG(pd_ref::orientation(a, b, d) == 0, s.name);
      else
        CGAL_HC_CHECK_MSG(pd_ref::side_of_lifted_plane(a, b, c, d) == 0, s.name);
    }
    if(s.name.find("horocycle") == 0) {
      const QP &a = s.points[0], &b = s.points[1], &c = s.points[2];
      const pd_ref::V3 N = pd_ref::minkowski_normal(a, b, c);
      CGAL_HC_CHECK_MSG(pd_ref::mink(N, N) == 0, "a horocycle's plane has a lightlike normal");
    }
  }
  // geodesic circles are orthogonal to the unit circle: A^2 + B^2 = 4^m + H^2
  CGAL_HC_CHECK(676L * 676 + 835L * 835 == (1L << 20) + 325L * 325);
  CGAL_HC_CHECK(412L * 412 + 445L * 445 == (1L << 18) + 325L * 325);
  CGAL_HC_CHECK(325L * 325 + 1024L * 1024 == (1L << 20) + 325L * 325);
  const double r = 1.0 - std::ldexp(1.0, -50);
  CGAL_HC_CHECK(Q(r) == 1 - Q(std::ldexp(1.0, -50))); // |p| = 1 - 2^-50 is a double
}

// ------------------------------------------------------------------------------------------------ predicates

CGAL_HC_TEST_CASE(predicates_epick_vs_exact_reference) { check_all_sets<Epick>(400, true); }

CGAL_HC_TEST_CASE(predicates_gmpq_vs_exact_reference)
{
  check_all_sets<SC_gmpq>(150, true);
  // exactly degenerate rationals that are not doubles: rational isometric images of the degenerate sets and
  // regular quadrilaterals (cocircular) moved off the origin
  std::mt19937_64 rng(7);
  for(const Named_set& s : degenerate_sets(rng)) {
    if(s.name.find("ulp") != std::string::npos) continue;
    check_predicates<SC_gmpq>(make_all<SC_gmpq>(moved(s.points, 1, 0, Q(1, 3), Q(-2, 7))), s.name + "-moved", rng, 100);
  }
  std::vector<QP> squares = moved_square(Q(1, 2), Q(1, 5), Q(2, 7));
  for(const QP& p : moved_square(Q(9, 10), Q(-3, 11), Q(1, 13))) squares.push_back(p);
  check_predicates<SC_gmpq>(make_all<SC_gmpq>(squares), "regular-quadrilaterals", rng);
}

CGAL_HC_TEST_CASE(predicates_epeck_with_sqrt_vs_exact_reference)
{
  std::mt19937_64 rng(11);
  // fewer tuples: CORE::Expr is slow
  check_predicates<Epeck_sqrt>(make_all<Epeck_sqrt>(random_euclidean(rng, 12, 0.999)), "random-euclidean", rng, 40);
  check_predicates<Epeck_sqrt>(make_all<Epeck_sqrt>(moved_square(Q(1, 2), Q(1, 5), Q(2, 7))), "regular-quadrilateral", rng);
  for(const Named_set& s : degenerate_sets(rng)) {
    if(s.name.find("ulp") != std::string::npos) continue;
    std::vector<QP> pts(s.points.begin(), s.points.begin() + std::min<std::size_t>(5, s.points.size()));
    check_predicates<Epeck_sqrt>(make_all<Epeck_sqrt>(moved(pts, 3, 1, Q(1, 2), Q(1, 3))), s.name + "-moved", rng, 30);
  }
}

// ------------------------------------------------------------------------------------------------ isometries

/// Every isometry-invariant predicate gives the same answer on double input (Epick traits) and on its exact
/// image by a rational Moebius isometry (Simple_cartesian<Gmpq> traits); the images are computed with the
/// package's Poincare_disk_isometry_2 on Gmpq and cross-checked against the reference's own formula.
CGAL_HC_TEST_CASE(predicates_are_isometry_invariant)
{
  typedef CGAL::Poincare_disk_traits_2<Epick> Tr_d;
  typedef CGAL::Poincare_disk_traits_2<SC_gmpq> Tr_q;
  typedef CGAL::Poincare_disk_isometry_2<SC_gmpq> Iso;
  const Tr_d td;
  const Tr_q tq;
  std::mt19937_64 rng(99);
  std::vector<Named_set> sets = degenerate_sets(rng);
  sets.push_back({"random", random_euclidean(rng, 30, 0.999)});
  sets.push_back({"square", moved_square(Q(1, 2), Q(0), Q(0))});
  const Q maps[3][4] = {{1, 0, Q(1, 2), Q(-1, 3)}, {3, 4, Q(-2, 5), Q(1, 7)}, {Q(5, 4), Q(-1, 2), Q(1, 10), Q(9, 10)}};
  for(const auto& m : maps) {
    const Iso f{m[0], m[1], m[2], m[3]};
    for(const Named_set& s : sets) {
      std::vector<Epick::Point_2> a;
      std::vector<SC_gmpq::Point_2> b;
      for(const QP& p : s.points) {
        a.push_back(Epick::Point_2(p.dx(), p.dy()));
        b.push_back(f(SC_gmpq::Point_2(p.x, p.y)));
        const QP ref = pd_ref::moebius(p, m[0], m[1], m[2], m[3]);
        CGAL_HC_CHECK_MSG(b.back().x() == ref.x && b.back().y() == ref.y, "isometry image " << s.name);
      }
      const std::size_t n = a.size();
      std::uniform_int_distribution<std::size_t> u(0, n - 1);
      for(int t = 0; t < 60; ++t) {
        const std::size_t i = u(rng), j = u(rng), k = u(rng), l = u(rng);
        if(i == j || j == k || i == k) continue;
        const std::string w = s.name + " " + str(s.points[i]);
        CGAL_HC_CHECK_MSG(td.orientation_2_object()(a[i], a[j], a[k]) == tq.orientation_2_object()(b[i], b[j], b[k]), w);
        CGAL_HC_CHECK_MSG(td.side_of_oriented_circle_2_object()(a[i], a[j], a[k], a[l]) ==
                            tq.side_of_oriented_circle_2_object()(b[i], b[j], b[k], b[l]), w);
        CGAL_HC_CHECK_MSG(td.is_Delaunay_hyperbolic_2_object()(a[i], a[j], a[k]) ==
                            tq.is_Delaunay_hyperbolic_2_object()(b[i], b[j], b[k]), w);
        CGAL_HC_CHECK_MSG(td.side_of_hyperbolic_diametral_circle_2_object()(a[i], a[j], a[k]) ==
                            tq.side_of_hyperbolic_diametral_circle_2_object()(b[i], b[j], b[k]), w);
        CGAL_HC_CHECK_MSG(td.compare_distance_2_object()(a[i], a[j], a[k]) == tq.compare_distance_2_object()(b[i], b[j], b[k]), w);
        CGAL_HC_CHECK_MSG(td.compare_hyperbolic_distance_2_object()(a[i], a[j], a[k], a[l]) ==
                            tq.compare_hyperbolic_distance_2_object()(b[i], b[j], b[k], b[l]), w);
        for(double th : {0.01, 0.25, 0.75}) // exact doubles, the same threshold on both sides
          CGAL_HC_CHECK_MSG(td.compare_central_angle_2_object()(a[i], a[j], a[k], th) ==
                              tq.compare_central_angle_2_object()(b[i], b[j], b[k], CGAL::Gmpq(th)), w);
        for(double th : {1.5, 4.0, 1e4})
          CGAL_HC_CHECK_MSG(td.compare_hyperbolic_circumradius_2_object()(a[i], a[j], a[k], th) ==
                              tq.compare_hyperbolic_circumradius_2_object()(b[i], b[j], b[k], CGAL::Gmpq(th)), w);
      }
    }
  }
}
