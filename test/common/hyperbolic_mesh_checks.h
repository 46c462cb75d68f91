// Independent checks of Poincare-disk meshes, shared by the tests of Hyperbolic_mesh_2 and the PSLG fuzz target.
// Written here from the formulas (hyperboloid lifts, Euclidean in-circle determinants of the Poincare coordinates),
// never with the mesher's predicates. Every decision is exact: the formula is evaluated with interval arithmetic
// and, when the interval does not decide, with exact rationals (the inputs are doubles, hence exact rationals).
#ifndef CGAL_HC_TEST_HYPERBOLIC_MESH_CHECKS_H
#define CGAL_HC_TEST_HYPERBOLIC_MESH_CHECKS_H

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace hyperbolic_mesh_checks {

typedef CGAL::Exact_rational Q;

namespace detail {
// sign of f(NT) for NT = interval, else exact
template <class F>
int filtered_sign(const F& f)
{
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const CGAL::Uncertain<CGAL::Sign> s = CGAL::sign(f(CGAL::Interval_nt<false>()));
    if(CGAL::is_certain(s)) return int(CGAL::get_certain(s));
  }
  return int(CGAL::sign(f(Q())));
}
template <class NT, class P> NT X(const P& p) { return NT(CGAL::to_double(p.x())); }
template <class NT, class P> NT Y(const P& p) { return NT(CGAL::to_double(p.y())); }
} // namespace detail

/// Hyperboloid lift L(z) = (2x, 2y, 1 + |z|^2) / (1 - |z|^2).
template <class NT>
struct Lift { NT x, y, t; };
template <class NT, class P>
Lift<NT> lift(const P& p)
{
  const NT x = detail::X<NT>(p), y = detail::Y<NT>(p), n = NT(1) - x * x - y * y;
  return Lift<NT>{NT(2) * x / n, NT(2) * y / n, (NT(1) + x * x + y * y) / n};
}

/// sinh^2(d(p, q) / 2) = |p - q|^2 / ((1 - |p|^2)(1 - |q|^2))
template <class NT, class P>
NT A(const P& p, const P& q)
{
  const NT px = detail::X<NT>(p), py = detail::Y<NT>(p), qx = detail::X<NT>(q), qy = detail::Y<NT>(q);
  const NT dx = px - qx, dy = py - qy;
  return (dx * dx + dy * dy) / ((NT(1) - px * px - py * py) * (NT(1) - qx * qx - qy * qy));
}
template <class NT, class P>
NT min_A(const P& p, const P& q, const P& r) { return (std::min)({A<NT>(p, q), A<NT>(q, r), A<NT>(r, p)}); }

/// cosh^2 of the hyperbolic circumradius via the plane through the three hyperboloid lifts; false if the
/// circumcircle is not compact (the plane's Minkowski normal is not timelike). Exact with NT = Q.
template <class NT, class P>
bool cosh2_circumradius(const P& p, const P& q, const P& r, NT& c2)
{
  const Lift<NT> a = lift<NT>(p), b = lift<NT>(q), c = lift<NT>(r);
  const NT ux = b.x - a.x, uy = b.y - a.y, ut = b.t - a.t, vx = c.x - a.x, vy = c.y - a.y, vt = c.t - a.t;
  const NT nx = uy * vt - ut * vy, ny = ut * vx - ux * vt, nt = ux * vy - uy * vx;
  const NT NN = nx * nx + ny * ny - nt * nt;
  if(!(NN < NT(0))) return false;
  const NT nl = nx * a.x + ny * a.y + nt * a.t;
  c2 = nl * nl / (-NN);
  return true;
}

/// Orientation of the Klein images of p, q, r (the triangulation's orientation): the sign of the determinant of
/// the rows (2x, 2y, 1 + |z|^2), the lifts times the positive 1 - |z|^2 (division free).
template <class P>
int orient_klein(const P& p, const P& q, const P& r)
{
  return detail::filtered_sign([&](auto nt) -> decltype(nt) {
    typedef decltype(nt) NT;
    auto row = [](const P& z, NT& a, NT& b, NT& c) {
      const NT x = detail::X<NT>(z), y = detail::Y<NT>(z);
      a = NT(2) * x; b = NT(2) * y; c = NT(1) + x * x + y * y;
    };
    NT a1, b1, c1, a2, b2, c2, a3, b3, c3;
    row(p, a1, b1, c1); row(q, a2, b2, c2); row(r, a3, b3, c3);
    return a1 * (b2 * c3 - b3 * c2) - b1 * (a2 * c3 - a3 * c2) + c1 * (a2 * b3 - a3 * b2);
  });
}

/// The edge of the faces pqr and of the apex s opposite to it is locally Delaunay: s is not strictly inside the
/// circle (or horocycle / hypercycle) of p, q, r, i.e. the Euclidean in-circle determinant of the Poincare
/// coordinates times the Klein orientation of pqr is <= 0.
template <class P>
bool locally_Delaunay(const P& p, const P& q, const P& r, const P& s)
{
  const int det = detail::filtered_sign([&](auto nt) -> decltype(nt) {
    typedef decltype(nt) NT;
    const NT sx = detail::X<NT>(s), sy = detail::Y<NT>(s);
    const NT ax = detail::X<NT>(p) - sx, ay = detail::Y<NT>(p) - sy, bx = detail::X<NT>(q) - sx,
             by = detail::Y<NT>(q) - sy, cx = detail::X<NT>(r) - sx, cy = detail::Y<NT>(r) - sy;
    const NT aw = ax * ax + ay * ay, bw = bx * bx + by * by, cw = cx * cx + cy * cy;
    return ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx);
  });
  return det * orient_klein(p, q, r) <= 0;
}

/// Unconstrained edges between two finite faces that fail the exact local Delaunay test.
template <class CDT>
std::size_t non_Delaunay_edges(const CDT& cdt)
{
  std::size_t bad = 0;
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if(cdt.is_constrained(*e)) continue;
    const typename CDT::Face_handle f = e->first, g = f->neighbor(e->second);
    if(cdt.is_infinite(f) || cdt.is_infinite(g)) continue;
    if(!locally_Delaunay(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                         cdt.mirror_vertex(f, e->second)->point()))
      ++bad;
  }
  return bad;
}

namespace detail {
// the criteria with NT: Ruppert A_min >= B (cosh^2 h - 1), Chew (1 + 2 A_min)^2 >= cosh^2 h, h <= eps
template <class NT, class P>
CGAL::Uncertain<bool> meets(const P& p, const P& q, const P& r, bool chew, double B, double eps)
{
  NT c2;
  if(!cosh2_circumradius<NT>(p, q, r, c2)) return CGAL::Uncertain<bool>(false);
  const NT amin = min_A<NT>(p, q, r);
  CGAL::Uncertain<bool> ok = chew ? CGAL::Uncertain<bool>((NT(1) + NT(2) * amin) * (NT(1) + NT(2) * amin) >= c2)
                                  : CGAL::Uncertain<bool>(amin >= NT(B) * (c2 - NT(1)));
  if(std::isfinite(eps)) {
    const double ce = std::cosh(eps * (1 + 1e-12));
    ok = ok & CGAL::Uncertain<bool>(c2 <= NT(ce * ce));
  }
  return ok;
}
} // namespace detail

/// The face pqr meets the Ruppert criteria (central angle with sin^2(alpha/2) >= B, circumradius <= eps) or the
/// Chew criteria (shortest edge >= circumradius, circumradius <= eps); exact (interval filter, rational fallback).
template <class P>
bool meets_criteria(const P& p, const P& q, const P& r, bool chew, double B, double eps)
{
  {
    CGAL::Protect_FPU_rounding<true> guard;
    try {
      const CGAL::Uncertain<bool> u = detail::meets<CGAL::Interval_nt<false> >(p, q, r, chew, B, eps);
      if(CGAL::is_certain(u)) return CGAL::get_certain(u);
    } catch(const CGAL::Uncertain_conversion_exception&) {}
  }
  return CGAL::get_certain(detail::meets<Q>(p, q, r, chew, B, eps));
}
template <class P>
bool meets_Ruppert(const P& p, const P& q, const P& r, double B, double eps) { return meets_criteria(p, q, r, false, B, eps); }
template <class P>
bool meets_Chew(const P& p, const P& q, const P& r, double eps) { return meets_criteria(p, q, r, true, 0, eps); }

} // namespace hyperbolic_mesh_checks

#endif // CGAL_HC_TEST_HYPERBOLIC_MESH_CHECKS_H
