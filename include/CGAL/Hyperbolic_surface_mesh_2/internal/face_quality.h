// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality of a face of a surface triangulation in its chart: circumradius, central angle of the shortest
// edge, the Ruppert / Chew poor-face tests (exact predicates of the traits where the criterion is a fixed
// bound), the Steiner point, and the measures reported in the statistics.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_FACE_QUALITY_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_FACE_QUALITY_H

#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>
#include <CGAL/Hyperbolic_surface_mesh_2/internal/Bounded_double.h>
#include <CGAL/Poincare_disk_traits_2/internal/filtered_evaluation.h>
#include <CGAL/Poincare_disk_traits_2/internal/polynomials.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

#if defined(__GNUC__)
#define CGAL_HSM2_FLATTEN __attribute__((flatten))
#else
#define CGAL_HSM2_FLATTEN
#endif

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace internal {

/// The quantities of a triangle (p, q, r) of Poincare coordinates that the criteria compare, for any number type
/// of the evaluation stages (Bounded_double, Interval_nt, exact rationals): the circle coefficients (traits'
/// `Circle_coefficients`: the circle is compact iff delta > 0, sinh^2 h = sinh2 / delta, cosh^2 h =
/// (A - G)^2 / delta), nn = (1 - |p|^2)(1 - |q|^2)(1 - |r|^2) and, per edge, a[i] = sinh^2(d_i / 2) nn.
/// Both shape tests hold for the shortest edge iff they hold for some edge (the central angle grows with the
/// edge length on a given circle), so no shortest edge is chosen: isosceles faces (many, on symmetric
/// surfaces) would be undecided ties.
template <class NT>
struct Triangle_terms
{
  Poincare_disk_internal::Circle_coefficients<NT> cc;
  NT delta, sinh2, nn;
  std::array<NT, 3> a;
  Triangle_terms() : cc(NT(0), NT(0), NT(0), NT(0), NT(0), NT(0)) {}
  Triangle_terms(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry)
    : Triangle_terms(Poincare_disk_internal::Circle_coefficients<NT>(px, py, qx, qy, rx, ry), px, py, qx, qy, rx, ry) {}
  /// the same from the circle coefficients already computed (the size test needs only those)
  Triangle_terms(const Poincare_disk_internal::Circle_coefficients<NT>& c, const NT& px, const NT& py,
                 const NT& qx, const NT& qy, const NT& rx, const NT& ry)
    : cc(c), delta(cc.delta()), sinh2(cc.sinh2_numerator())
  {
    using namespace Poincare_disk_internal;
    const NT np = lift_n(px, py), nq = lift_n(qx, qy), nr = lift_n(rx, ry);
    nn = np * nq * nr;
    // sinh^2(d/2) = |x - y|^2 / (n_x n_y): times nn, the edge pq gives |p - q|^2 n_r
    a = {{squared_euclidean(px, py, qx, qy) * nr, squared_euclidean(qx, qy, rx, ry) * np,
          squared_euclidean(rx, ry, px, py) * nq}};
  }
};

/// `s[i]` are the signs of a per-edge test (POSITIVE: the edge is poor): POSITIVE if some edge is certainly
/// poor, NEGATIVE if no edge is, else throws `Uncertain_conversion_exception` (the caller's next stage decides)
template <class S>
Sign any_edge_poor(const S& s0, const S& s1, const S& s2)
{
  if(certainly(s0 == POSITIVE) || certainly(s1 == POSITIVE) || certainly(s2 == POSITIVE)) return POSITIVE;
  if(certainly(s0 != POSITIVE) && certainly(s1 != POSITIVE) && certainly(s2 != POSITIVE)) return NEGATIVE;
  throw Uncertain_conversion_exception("any_edge_poor: undecided");
}

/// Chew's shape test, exact: POSITIVE iff the shortest edge d_min is shorter than the circumradius h (the
/// central angle of the shortest edge is below theta*(h)), for a compact circumcircle (else NEGATIVE: no
/// circumradius; the size test already calls the face poor). With cosh d = 1 + 2 a / nn, per edge:
///   d < h  <=>  (2 a + nn)^2 / nn^2 < (A - G)^2 / delta  <=>  (A - G)^2 nn^2 - (2 a + nn)^2 delta > 0.
template <class NT>
Sign chew_shape_sign(const Triangle_terms<NT>& t)
{
  if(!bool(sign_of(t.delta) == POSITIVE)) return NEGATIVE;
  const NT amg = t.cc.A - t.cc.G, lhs = amg * amg * t.nn * t.nn;
  auto edge = [&](const NT& a) { const NT w = NT(2) * a + t.nn; return sign_of(lhs - w * w * t.delta); };
  return any_edge_poor(edge(t.a[0]), edge(t.a[1]), edge(t.a[2]));
}
struct Chew_shape_polynomial
{
  template <class NT>
  Sign operator()(const NT& px, const NT& py, const NT& qx, const NT& qy, const NT& rx, const NT& ry) const
  { return chew_shape_sign(Triangle_terms<NT>(px, py, qx, qy, rx, ry)); }
};

/// Ruppert's shape test on the same terms: POSITIVE iff the central angle of the shortest edge is below alpha,
/// sin^2(theta_i / 2) = a_i delta / (sinh2 nn) < sin^2(alpha / 2) for some edge (the traits'
/// `Compare_central_angle_2` polynomial, per edge); for a compact circumcircle only.
template <class NT>
Sign ruppert_shape_sign(const Triangle_terms<NT>& t, const NT& sin2_half_alpha)
{
  const NT b = sin2_half_alpha * t.sinh2 * t.nn;
  auto edge = [&](const NT& a) { return sign_of(b - a * t.delta); };
  return any_edge_poor(edge(t.a[0]), edge(t.a[1]), edge(t.a[2]));
}

/// the exact Chew shape test on double coordinates: interval arithmetic, then exact rationals
template <class Point_2>
bool chew_shape_is_poor(const Point_2& p, const Point_2& q, const Point_2& r)
{
  return Poincare_disk_internal::Exact_evaluator<double>::eval(Chew_shape_polynomial(), p.x(), p.y(), q.x(), q.y(),
                                                               r.x(), r.y()) == POSITIVE;
}

template <class DT>
class Face_quality
{
  typedef typename DT::Point_2 Point_2;
  typedef typename DT::Face_index Face_index;
  typedef typename DT::Vertex_index Vertex_index;
  typedef typename DT::Geometry Geometry;

public:
  Face_quality(const DT& t, bool chew, double epsilon, double alpha)
    : t_(t), chew_(chew), epsilon_(epsilon), alpha_(alpha)
  {
    const double c = std::cosh(epsilon);
    cosh2_eps_ = c * c;
    const double s = std::sin(alpha / 2);
    sin2_half_alpha_ = s * s;
  }

  double epsilon() const { return epsilon_; }
  /// true if the circumcircle of f is compact (a hyperbolic circle)
  bool is_compact(Face_index f) const
  {
    const auto& z = t_.lift(f);
    return t_.geom_traits().is_Delaunay_hyperbolic_2_object()(z[0], z[1], z[2]);
  }
  /// hyperbolic circumradius (+infinity if the circumcircle is not compact)
  double circumradius(Face_index f) const
  {
    if(!is_compact(f)) return std::numeric_limits<double>::infinity();
    const auto& z = t_.lift(f);
    const Point_2 c = t_.geom_traits().construct_hyperbolic_circumcenter_2_object()(z[0], z[1], z[2]);
    return Geometry::distance(c, z[0]);
  }
  double shortest_edge(Face_index f) const
  {
    return (std::min)({t_.edge_length(f, 0), t_.edge_length(f, 1), t_.edge_length(f, 2)});
  }
  /// central angle of the shortest edge in the circumcircle: sin(theta / 2) = sinh(d / 2) / sinh(r)
  double central_angle(Face_index f) const
  {
    const double r = circumradius(f);
    if(!std::isfinite(r)) return 0;
    const double s = std::sinh(shortest_edge(f) / 2) / std::sinh(r);
    return 2 * std::asin((std::min)(1.0, s));
  }

  /// The poor-face test and the queue key (the circumradius, +infinity if not compact) of f, in one pass:
  /// first in Bounded_double arithmetic (a rigorous error bound, no rounding-mode switch), and where that
  /// cannot decide, by `is_bad_exact()` (the traits' predicates, interval then exact). Every decision is exact.
  /// The key is sinh^2 of the circumradius (increasing in it; +infinity if the circle is not compact): the
  /// queue needs only the order, so no transcendental function is evaluated per face (`circumradius_of_key()`).
  struct Evaluation { bool bad; double key; };
  Evaluation evaluate(Face_index f) const
  {
    const auto& z = t_.lift(f);
    Evaluation r;
    if(fast_evaluate(z[0], z[1], z[2], r)) return r;
    return {is_bad_exact(z[0], z[1], z[2]), key_of_circumradius(circumradius(f))};
  }
  static double key_of_circumradius(double h) { const double s = std::sinh(h); return s * s; }
  static double circumradius_of_key(double k) { return std::asinh(std::sqrt(k)); }
  /// `evaluate().bad` on a triangle of the disk
  bool evaluate_points(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    Evaluation ev;
    return fast_evaluate(p, q, r, ev) ? ev.bad : is_bad_exact(p, q, r);
  }
  /// the Bounded_double stage of `evaluate()` on a triangle of the disk: false if it cannot decide
  /// (everything inlined: the rounding counts of Bounded_double are then constants of the compiled code)
  CGAL_HSM2_FLATTEN bool fast_evaluate(const Point_2& p, const Point_2& q, const Point_2& r, Evaluation& ev) const
  {
    typedef Bounded_double BD;
    const BD px(p.x()), py(p.y()), qx(q.x()), qy(q.y()), rx(r.x()), ry(r.y());
    try {
      // the size test first, on the circle coefficients alone; the edge terms only for the shape test
      const Poincare_disk_internal::Circle_coefficients<BD> cc(px, py, qx, qy, rx, ry);
      const BD delta = cc.delta(), sinh2 = cc.sinh2_numerator();
      if(!bool(delta.sign() == POSITIVE)) { ev = {true, std::numeric_limits<double>::infinity()}; return true; }
      ev.key = (std::max)(0.0, sinh2.v / delta.v);
      // size: cosh^2 h > cosh^2 eps  <=>  sinh2 - (cosh^2 eps - 1) delta > 0 (the traits' polynomial)
      if(bool((sinh2 - (BD(cosh2_eps_) - BD(1)) * delta).sign() == POSITIVE)) { ev.bad = true; return true; }
      const Triangle_terms<BD> t(cc, px, py, qx, qy, rx, ry);
      if(chew_) ev.bad = chew_shape_sign(t) == POSITIVE;
      else ev.bad = ruppert_shape_sign(t, BD(sin2_half_alpha_)) == POSITIVE;
      return true;
    } catch(Uncertain_conversion_exception&) {
      return false;
    }
  }
  /// `fast_evaluate()`'s test (then the exact stage if needed) and the double-precision terms of the same
  /// triangle, in one pass (the statistics): the terms are the values of the Bounded_double evaluation, i.e.
  /// the double evaluation of the same expressions
  CGAL_HSM2_FLATTEN bool is_bad_with_terms(const Point_2& p, const Point_2& q, const Point_2& r, Triangle_terms<double>& td) const
  {
    typedef Bounded_double BD;
    const BD px(p.x()), py(p.y()), qx(q.x()), qy(q.y()), rx(r.x()), ry(r.y());
    const Triangle_terms<BD> t(px, py, qx, qy, rx, ry);
    td.cc.A = t.cc.A.v; td.cc.B = t.cc.B.v; td.cc.C = t.cc.C.v; td.cc.G = t.cc.G.v;
    td.delta = t.delta.v; td.sinh2 = t.sinh2.v; td.nn = t.nn.v;
    td.a = {{t.a[0].v, t.a[1].v, t.a[2].v}};
    try {
      if(!bool(t.delta.sign() == POSITIVE)) return true;
      if(bool((t.sinh2 - (BD(cosh2_eps_) - BD(1)) * t.delta).sign() == POSITIVE)) return true;
      return chew_ ? chew_shape_sign(t) == POSITIVE : ruppert_shape_sign(t, BD(sin2_half_alpha_)) == POSITIVE;
    } catch(Uncertain_conversion_exception&) {
      return is_bad_exact(p, q, r);
    }
  }
  /// the poor-face test of the criterion
  bool is_bad(Face_index f) const { return evaluate(f).bad; }
  /// the same test decided by the traits' predicates (and, for Chew, `chew_shape_is_poor()`) only
  bool is_bad_exact(Face_index f) const { const auto& z = t_.lift(f); return is_bad_exact(z[0], z[1], z[2]); }
  bool is_bad_exact(const Point_2& p, const Point_2& q, const Point_2& r) const
  {
    const auto& gt = t_.geom_traits();
    if(gt.compare_hyperbolic_circumradius_2_object()(p, q, r, cosh2_eps_) == CGAL::LARGER) return true;
    if(chew_) return chew_shape_is_poor(p, q, r); // central angle < theta*(r): shortest edge < r
    return gt.compare_central_angle_2_object()(p, q, r, sin2_half_alpha_) == CGAL::SMALLER;
  }

  /// the circumcentre of f in its chart (or the chart's origin, the barycentre, if the circle is not compact)
  Point_2 steiner_point(Face_index f, bool& barycentre) const
  {
    const auto& z = t_.lift(f);
    barycentre = false;
    try { return t_.geom_traits().construct_hyperbolic_circumcenter_2_object()(z[0], z[1], z[2]); } // checks compactness
    catch(const Poincare_disk_domain_error&) { barycentre = true; return Point_2(0, 0); }
  }

  /// faces incident to a loop edge or to a copy of a multiple edge, or (two faces only) with the vertex triple
  /// of the other face (see `is_simplicial_complex()`)
  std::vector<Face_index> faces_at_non_simplicial_edges() const
  {
    std::vector<Face_index> r;
    t_.for_each_non_simplicial_edge([&](Face_index f, int i) { r.push_back(f); r.push_back(t_.neighbor(f, i)); return true; });
    if(r.empty() && t_.number_of_faces() == 2 && !t_.is_simplicial_complex()) for(Face_index f : t_.faces()) r.push_back(f);
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    return r;
  }

  /// fills the measured fields of the statistics, and `faces_failing_criteria` (the poor-face test of every
  /// face, exact, in the same pass)
  /// `known_simplicial`: 1 or 0 if the caller has just tested it (-1: test here)
  template <class Statistics>
  void measure(Statistics& st, int known_simplicial = -1) const
  {
    st.faces_failing_criteria = 0;
    st.final_vertices = t_.number_of_vertices();
    st.final_faces = t_.number_of_faces();
    st.simplicial_complex = known_simplicial >= 0 ? known_simplicial == 1 : t_.is_simplicial_complex();
    st.euler_characteristic = t_.euler_characteristic();
    st.genus = t_.genus();
    st.minimum_central_angle = CGAL_PI;
    st.maximum_circumradius = 0;
    st.minimum_angle = CGAL_PI; st.maximum_angle = 0;
    // corner angles: a cheap proxy per face (the cosine law on the same terms, cos A_i = (2 (s_j + s_k - s_i) +
    // 4 s_j s_k) / (4 sqrt(s_j (1 + s_j) s_k (1 + s_k))) with s = sinh^2(d / 2) = a / nn, no transcendental
    // function) selects the faces within 1e-6 of the extreme cosines; only those get the layer's corner_angle
    // (the proxy's rounding is far below the margin, so the extremes are those of corner_angle on every face)
    const std::vector<Face_index> fs = t_.faces();
    std::vector<std::pair<double, double> > cosines(fs.size()); // (largest, smallest) cosine of each face
    double cmax = -2, cmin = 2, max_sinh2 = 0, min_sin2 = 1;
    for(std::size_t k = 0; k < fs.size(); ++k) {
      const auto& z = t_.lift(fs[k]);
      Triangle_terms<double> tt;
      if(is_bad_with_terms(z[0], z[1], z[2], tt)) ++st.faces_failing_criteria;
      if(!(tt.delta > 0)) { st.minimum_central_angle = 0; st.maximum_circumradius = std::numeric_limits<double>::infinity(); }
      else {
        // circumradius and central angle in double precision (statistics only): sinh^2 h = sinh2 / delta,
        // sin^2(theta / 2) = a_min delta / (sinh2 nn)
        // (both monotone: the extremes of the squared sines, then one transcendental function each)
        const double a_min = (std::min)({tt.a[0], tt.a[1], tt.a[2]});
        max_sinh2 = (std::max)(max_sinh2, tt.sinh2 / tt.delta);
        min_sin2 = (std::min)(min_sin2, a_min * tt.delta / (tt.nn * tt.sinh2));
      }
      const double sh[3] = {tt.a[0] / tt.nn, tt.a[1] / tt.nn, tt.a[2] / tt.nn};
      double hi = -2, lo = 2;
      for(int i = 0; i < 3; ++i) {
        const double sj = sh[(i + 1) % 3], sk = sh[(i + 2) % 3];
        const double c = (2 * (sj + sk - sh[i]) + 4 * sj * sk) / (4 * std::sqrt(sj * (1 + sj) * sk * (1 + sk)));
        hi = (std::max)(hi, c); lo = (std::min)(lo, c);
      }
      cosines[k] = {hi, lo};
      cmax = (std::max)(cmax, hi); cmin = (std::min)(cmin, lo);
    }
    if(st.maximum_circumradius == 0) {
      st.maximum_circumradius = std::asinh(std::sqrt(max_sinh2));
      st.minimum_central_angle = 2 * std::asin(std::sqrt((std::min)(1.0, min_sin2)));
    }
    for(std::size_t k = 0; k < fs.size(); ++k) {
      if(!(cosines[k].first >= cmax - 1e-6 || cosines[k].second <= cmin + 1e-6)) continue;
      const Face_index f = fs[k];
      const double l[3] = {t_.edge_length(f, 0), t_.edge_length(f, 1), t_.edge_length(f, 2)};
      for(int i = 0; i < 3; ++i) {
        const double a = Hyperbolic_surface_2::corner_angle(l[(i + 1) % 3], l[i], l[(i + 2) % 3]);
        st.minimum_angle = (std::min)(st.minimum_angle, a);
        st.maximum_angle = (std::max)(st.maximum_angle, a);
      }
    }
  }

private:
  const DT& t_;
  bool chew_;
  double epsilon_, alpha_, cosh2_eps_ = 1, sin2_half_alpha_ = 0;
};

} // namespace internal
} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif
