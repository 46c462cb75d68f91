// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An exact rational reference for the predicates of Poincare_disk_traits_2, written independently of the
// package's headers (it does not include them): every quantity is computed in CGAL::Gmpq from the
// hyperboloid lift L(z) = (2x, 2y, 1 + |z|^2) / (1 - |z|^2), the Minkowski product <X,Y> = x1x2 + y1y2 - t1t2,
// cosh d(p,q) = -<L(p), L(q)>, and plain cofactor determinants, following DESIGN.md ("Predicates") and the
// thesis (ch. 3). The traits use a different algebraic route (homogeneous Klein determinant, circle
// coefficients A, B, C, G): agreement of the two is what the tests check.
#ifndef CGAL_HC_TEST_POINCARE_DISK_REFERENCE_H
#define CGAL_HC_TEST_POINCARE_DISK_REFERENCE_H

#include <CGAL/Gmpq.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <array>
#include <utility>

namespace pd_ref {

typedef CGAL::Gmpq Q;

struct QP
{
  Q x, y;
  QP() {}
  QP(const Q& a, const Q& b) : x(a), y(b) {}
  double dx() const { return CGAL::to_double(x); }
  double dy() const { return CGAL::to_double(y); }
};

typedef std::array<Q, 3> V3;

inline Q sq_norm(const QP& p) { return p.x * p.x + p.y * p.y; }
inline bool in_open_disk(const QP& p) { return sq_norm(p) < 1; }

/// hyperboloid lift (2x, 2y, 1 + |z|^2) / (1 - |z|^2)
inline V3 lift(const QP& p)
{
  const Q s = sq_norm(p), n = 1 - s;
  return V3{{2 * p.x / n, 2 * p.y / n, (1 + s) / n}};
}

/// Minkowski product
inline Q mink(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] - a[2] * b[2]; }

inline Q det2(const Q& a, const Q& b, const Q& c, const Q& d) { return a * d - b * c; }

inline Q det3(const V3& a, const V3& b, const V3& c)
{
  return a[0] * det2(b[1], b[2], c[1], c[2]) - a[1] * det2(b[0], b[2], c[0], c[2]) + a[2] * det2(b[0], b[1], c[0], c[1]);
}

/// det of the 4x4 matrix with rows (a, 1), (b, 1), (c, 1), (d, 1) = det3(b - a, c - a, d - a)
inline Q det4_affine(const V3& a, const V3& b, const V3& c, const V3& d)
{
  auto sub = [](const V3& u, const V3& v) { return V3{{u[0] - v[0], u[1] - v[1], u[2] - v[2]}}; };
  return -det3(sub(b, a), sub(c, a), sub(d, a));
}

/// Euclidean cross product
inline V3 cross(const V3& a, const V3& b)
{
  return V3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

inline int sgn(const Q& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

/// Klein orientation: sign of det[L(p), L(q), L(r)] (the three lifts seen from the origin).
inline int orientation(const QP& p, const QP& q, const QP& r) { return sgn(det3(lift(p), lift(q), lift(r))); }

/// Klein coordinates 2z / (1 + |z|^2)
inline QP klein(const QP& p) { const Q w = 1 + sq_norm(p); return QP(2 * p.x / w, 2 * p.y / w); }

inline int compare_klein_x(const QP& p, const QP& q) { return sgn(klein(p).x - klein(q).x); }
inline int compare_klein_y(const QP& p, const QP& q) { return sgn(klein(p).y - klein(q).y); }

/// side of L(s) w.r.t. the plane through L(p), L(q), L(r): sign of det[(L(.), 1)] (4x4). Equal to the oriented
/// in-circle sign (positive: s inside the circle of a positively oriented p, q, r).
inline int side_of_lifted_plane(const QP& p, const QP& q, const QP& r, const QP& s)
{
  return sgn(det4_affine(lift(p), lift(q), lift(r), lift(s)));
}

/// true iff s and the origin of R^3 lie strictly on the same side of the plane through the three lifts
/// ("s inside the hyperbolic circle" when that circle is compact)
inline bool same_side_as_origin(const QP& p, const QP& q, const QP& r, const QP& s)
{
  const V3 lp = lift(p), lq = lift(q), lr = lift(r), ls = lift(s);
  const V3 n = cross(V3{{lq[0] - lp[0], lq[1] - lp[1], lq[2] - lp[2]}}, V3{{lr[0] - lp[0], lr[1] - lp[1], lr[2] - lp[2]}});
  const Q off = n[0] * lp[0] + n[1] * lp[1] + n[2] * lp[2];
  const Q vs = n[0] * ls[0] + n[1] * ls[1] + n[2] * ls[2] - off, vo = -off;
  return sgn(vs) * sgn(vo) > 0;
}

/// Minkowski normal N of the plane through the lifts: <N, X> = n . X with n the Euclidean normal.
inline V3 minkowski_normal(const QP& p, const QP& q, const QP& r)
{
  const V3 lp = lift(p), lq = lift(q), lr = lift(r);
  const V3 n = cross(V3{{lq[0] - lp[0], lq[1] - lp[1], lq[2] - lp[2]}}, V3{{lr[0] - lp[0], lr[1] - lp[1], lr[2] - lp[2]}});
  return V3{{n[0], n[1], -n[2]}};
}

/// compact circumcircle (a hyperbolic circle): the plane through the lifts has a timelike normal
inline bool is_compact(const QP& p, const QP& q, const QP& r)
{
  const V3 N = minkowski_normal(p, q, r);
  return mink(N, N) < 0;
}

/// the same, the Euclidean way: the Euclidean circumcircle (centre c, radius R) satisfies |c| + R < 1
/// (decided exactly by squaring).
inline bool is_compact_euclidean(const QP& p, const QP& q, const QP& r)
{
  // circumcentre by the perpendicular-bisector equations 2 (q - p).c = |q|^2 - |p|^2, 2 (r - p).c = |r|^2 - |p|^2
  const Q a11 = 2 * (q.x - p.x), a12 = 2 * (q.y - p.y), a21 = 2 * (r.x - p.x), a22 = 2 * (r.y - p.y);
  const Q b1 = sq_norm(q) - sq_norm(p), b2 = sq_norm(r) - sq_norm(p);
  const Q d = det2(a11, a12, a21, a22);
  if(d == 0) return false; // Euclidean-collinear: a straight line, never inside the disk
  const QP c(det2(b1, a12, b2, a22) / d, det2(a11, b1, a21, b2) / d);
  const Q R2 = (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y), c2 = sq_norm(c);
  if(!(R2 < 1)) return false;
  const Q u = 1 + R2 - c2; // (1 - R)^2 > |c|^2  <=>  u > 2R
  return u > 0 && u * u > 4 * R2;
}

/// cosh of the hyperbolic distance, as -<L(p), L(q)>
inline Q cosh_d(const QP& p, const QP& q) { return -mink(lift(p), lift(q)); }

/// sinh^2(d/2) = (cosh d - 1) / 2
inline Q sinh2_half_d(const QP& p, const QP& q) { return (cosh_d(p, q) - 1) / 2; }

/// encroachment: +1 iff s strictly inside the hyperbolic disk with diameter pq (cosh d(s,p) + cosh d(s,q) <
/// 1 + cosh d(p,q)), 0 on its circle, -1 outside
inline int encroachment(const QP& p, const QP& q, const QP& s)
{
  return sgn(1 + cosh_d(p, q) - cosh_d(s, p) - cosh_d(s, q));
}

/// sign of d(p,q) - d(r,s)
inline int compare_distance(const QP& p, const QP& q, const QP& r, const QP& s) { return sgn(cosh_d(p, q) - cosh_d(r, s)); }

/// cosh^2 of the hyperbolic circumradius (precondition: compact): the centre is M = N / sqrt(-<N,N>) and
/// cosh h = |<L(p), M>|
inline Q cosh2_circumradius(const QP& p, const QP& q, const QP& r)
{
  const V3 N = minkowski_normal(p, q, r);
  const Q ip = mink(lift(p), N);
  return ip * ip / (-mink(N, N));
}

/// sin^2(alpha/2) of the central angle alpha of the shortest edge (law of sines in the circumcircle:
/// sinh(d/2) = sinh h sin(alpha/2)); precondition: compact
inline Q sin2_half_central_angle(const QP& p, const QP& q, const QP& r)
{
  Q a = sinh2_half_d(p, q);
  const Q b = sinh2_half_d(q, r), c = sinh2_half_d(r, p);
  if(b < a) a = b;
  if(c < a) a = c;
  return a / (cosh2_circumradius(p, q, r) - 1);
}

/// expected Compare_central_angle_2(p, q, r, sin2): SMALLER (-1) iff the angle is below the threshold; the
/// central angle of a non-compact circumcircle is 0
inline int compare_central_angle(const QP& p, const QP& q, const QP& r, const Q& sin2)
{
  if(!is_compact(p, q, r)) return -1;
  return sgn(sin2_half_central_angle(p, q, r) - sin2);
}

/// expected Compare_hyperbolic_circumradius_2(p, q, r, cosh2): non-compact circumcircles are LARGER
inline int compare_circumradius(const QP& p, const QP& q, const QP& r, const Q& cosh2)
{
  if(!is_compact(p, q, r)) return 1;
  return sgn(cosh2_circumradius(p, q, r) - cosh2);
}

/// sign of X + t Y for t = sqrt(t2) > 0, decided exactly
inline int sign_plus_sqrt(const Q& X, const Q& Y, const Q& t2)
{
  const int sx = sgn(X), sy = sgn(Y);
  if(sx == 0) return sy;
  if(sy == 0 || sx == sy) return sx;
  const Q d = X * X - t2 * Y * Y;
  return sgn(d) * sx;
}

/// for a non-compact circumcircle of (v0, v1, v2) (not Euclidean-collinear and centre != 0): the index i of the
/// vertex opposite the edge whose arc (the one not containing v_i) contains the farthest point F of the
/// Euclidean circumcircle from the origin, F = c + R c / |c|. -1 if undecidable (F on a chord line).
inline int non_hyperbolic_edge(const QP v[3])
{
  const QP &p = v[0], &q = v[1], &r = v[2];
  const Q a11 = 2 * (q.x - p.x), a12 = 2 * (q.y - p.y), a21 = 2 * (r.x - p.x), a22 = 2 * (r.y - p.y);
  const Q b1 = sq_norm(q) - sq_norm(p), b2 = sq_norm(r) - sq_norm(p);
  const Q d = det2(a11, a12, a21, a22);
  if(d == 0) return -1;
  const QP c(det2(b1, a12, b2, a22) / d, det2(a11, b1, a21, b2) / d);
  const Q c2 = sq_norm(c);
  if(c2 == 0) return -1;
  const Q R2 = (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
  const Q t2 = R2 / c2; // F = c + t c, t = R / |c|
  for(int i = 0; i < 3; ++i) {
    const QP &a = v[(i + 1) % 3], &b = v[(i + 2) % 3], &o = v[i];
    // orient(a, b, X) = cross(b - a, X - a); for X = F: cross(b - a, c - a) + t cross(b - a, c)
    const Q ex = b.x - a.x, ey = b.y - a.y;
    const Q X = ex * (c.y - a.y) - ey * (c.x - a.x), Y = ex * c.y - ey * c.x;
    const int sF = sign_plus_sqrt(X, Y, t2);
    const int so = sgn(ex * (o.y - a.y) - ey * (o.x - a.x));
    if(sF == 0) return -1;
    if(sF == -so) return i;
  }
  return -1;
}

/// exact Moebius isometry z -> (alpha z + beta) / (conj(beta) z + conj(alpha)), written out here
inline QP moebius(const QP& z, const Q& ar, const Q& ai, const Q& br, const Q& bi)
{
  const Q nr = ar * z.x - ai * z.y + br, ni = ar * z.y + ai * z.x + bi;
  const Q dr = br * z.x + bi * z.y + ar, di = br * z.y - bi * z.x - ai;
  const Q d2 = dr * dr + di * di;
  return QP((nr * dr + ni * di) / d2, (ni * dr - nr * di) / d2);
}

} // namespace pd_ref

#endif
