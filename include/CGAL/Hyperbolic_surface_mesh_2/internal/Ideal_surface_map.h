// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The map from the hyperbolic surface of a vertex-scaling Ricci-flow metric to its input mesh in R^3 through
// the decorated ideal hyperbolic surface (Gillespie-Springborn-Crane 2021), undoing the flow's flips.
//
// The flow (Discrete_Ricci_flow, vertex scaling, background H^2) has, per edge, a Penner coordinate lambda0 at
// u = 0 (half the input length) and final lengths sinh(l_ij / 2) = e^{(u_i + u_j) / 2} lambda0_ij. Model of a
// face abc:
// - the compact hyperbolic face (vertices p_i on the hyperboloid of R^{2,1}) and its chord triangle, the affine
//   triangle of p_a, p_b, p_c: |p_i - p_j|^2 = 2 cosh l_ij - 2 = (2 sinh(l_ij / 2))^2, a Euclidean triangle with
//   sides 2 lambda_ij. A point x of the face is x ~ sum beta_i p_i (beta >= 0: projective coordinates, the
//   same in every chart, as the hyperboloid lifts are linear images of each other);
// - the decorated ideal triangle with light-like v_i, <v_i, v_j> = -2 lambda_ij^2: its chord triangle is
//   the same Euclidean triangle, so the point with weights beta on v_i corresponds to x;
// - vertex scaling multiplies lambda_ij by e^{(u_i + u_j) / 2}, i.e. v_i by e^{u_i}: weights beta_i on the
//   final decoration are weights beta_i e^{u_i} on the decoration at u = 0;
// - a Ptolemy flip keeps the decorated ideal surface: a point given by weights on the corners of a face after
//   the flip is re-expressed on the corners of the face before the flip that contains it, with the Gram matrix
//   <v_i, v_j> of the quadrilateral (invertible on a face: [[0,x,y],[x,0,z],[y,z,0]] has determinant 2xyz);
// - at u = 0 on the input (or initially flipped) connectivity the chord triangle is the Euclidean triangle of
//   the input lengths: the normalized weights are its barycentric coordinates;
// - the initial geometric flips keep the piecewise-linear Euclidean metric: a point of the quadrilateral
//   unfolded in the plane is re-expressed in the face before the flip.
// The result is a point of an input face (convex combination of its corners) for every point of the surface.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_IDEAL_SURFACE_MAP_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_IDEAL_SURFACE_MAP_H

#include <CGAL/Discrete_Ricci_flow/compute_metric.h>
#include <CGAL/Discrete_Ricci_flow/internal/flow_engine.h>
#include <CGAL/Hyperbolic_geometry_errors.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace internal {

/// A point of a face: the face index and weights (not normalized, >= 0) on its corners in the order of the
/// sources of `halfedge(f)`, `next(halfedge(f))`, `next(next(halfedge(f)))`.
struct Face_point
{
  std::size_t face = 0;
  std::array<long double, 3> w{{1, 1, 1}};
};

/// The replayed flips of a metric and the map of points of its intrinsic faces back to the input faces.
/// `Point_3` is the point type of the metric's intrinsic mesh.
template <class Point_3>
class Ideal_surface_map
{
public:
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Edge_index Edge_index;
  typedef typename Mesh::Face_index Face_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;

  /*!
    `input` is the input connectivity as the flow copied it (vertex i = the i-th input vertex, faces in input
    order), `input_lengths` its Euclidean edge lengths (indexed by edge), `initial_flips` the metric-preserving
    flips and `flips` the Ptolemy flips, in order, `u` the final conformal factors, `final_mesh` the flow's
    intrinsic triangulation. Replays the flips on a copy of `input` and checks that they end at `final_mesh`
    (`CGAL::Invalid_input_error` otherwise, as for sizes that do not match).
  */
  Ideal_surface_map(const Mesh& input, const std::vector<double>& input_lengths,
                    const std::vector<Edge_index>& initial_flips, const std::vector<Edge_index>& flips,
                    const std::vector<double>& u, const Mesh& final_mesh)
    : u_(u)
  {
    Mesh m = input; // the replay
    if(input_lengths.size() != m.number_of_edges() || u.size() != m.number_of_vertices())
      throw Invalid_input_error("Ideal_surface_map: sizes of the lengths or conformal factors do not match the mesh");
    std::vector<double> len = input_lengths;
    steps_.reserve(initial_flips.size() + flips.size());
    for(int stage = 0; stage < 2; ++stage) {
      const bool euclidean = stage == 0;
      if(!euclidean) for(double& l : len) l *= 0.5; // Penner coordinates at u = 0
      for(Edge_index e : euclidean ? initial_flips : flips) {
        if(std::size_t(e) >= m.number_of_edges() || m.is_border(e))
          throw Invalid_input_error("Ideal_surface_map: a flipped edge is not an interior edge of the mesh");
        const Halfedge_index h = m.halfedge(e), o = m.opposite(h);
        const Halfedge_index h1 = m.next(h), h2 = m.next(h1), o1 = m.next(o), o2 = m.next(o1);
        Step s;
        s.euclidean = euclidean;
        s.fh = m.face(h); s.fo = m.face(o);
        if(s.fh == s.fo) throw Invalid_input_error("Ideal_surface_map: a flipped edge has the same face on both sides");
        // corners of the faces before the flip, as quad labels a = 0, b = 1, c = 2, d = 3, in halfedge order
        const Halfedge_index fh0 = m.halfedge(Face_index(s.fh)), fo0 = m.halfedge(Face_index(s.fo));
        s.before_h = fh0 == h ? Labels{{0, 1, 2}} : (fh0 == h1 ? Labels{{1, 2, 0}} : Labels{{2, 0, 1}});
        s.before_o = fo0 == o ? Labels{{1, 0, 3}} : (fo0 == o1 ? Labels{{0, 3, 1}} : Labels{{3, 1, 0}});
        s.l = {{len[e], len[m.edge(h1)], len[m.edge(h2)], len[m.edge(o1)], len[m.edge(o2)], 0.0}};
        double& lcd = s.l[CD];
        if(euclidean) {
          lcd = Discrete_Ricci_flow::internal::euclidean_flip_diagonal(s.l[AB], s.l[BC], s.l[CA], s.l[AD], s.l[DB]);
        } else
          lcd = (s.l[CA] * s.l[DB] + s.l[AD] * s.l[BC]) / s.l[AB];
        if(!(lcd > 0) || !std::isfinite(lcd))
          throw Numerical_error("Ideal_surface_map: a replayed flip gives a non-positive or non-finite length");
        len[e] = lcd;
        steps_.push_back(s);
        Discrete_Ricci_flow::internal::flip_connectivity(m, e);
      }
    }
    // the replay must end at the flow's triangulation (same corners in the same order): otherwise the metric
    // is not one of this mesh
    const char* other = "Ideal_surface_map: the flips replayed on the input do not give the metric's triangulation "
                        "(the metric was not computed on this mesh)";
    if(m.number_of_faces() != final_mesh.number_of_faces()) throw Invalid_input_error(other);
    for(Face_index f : m.faces()) {
      Halfedge_index a = m.halfedge(f), b = final_mesh.halfedge(f);
      for(int i = 0; i < 3; ++i, a = m.next(a), b = final_mesh.next(b))
        if(std::size_t(m.source(a)) != std::size_t(final_mesh.source(b))) throw Invalid_input_error(other);
    }
    final_corners_.resize(m.number_of_faces());
    for(Face_index f : m.faces()) {
      Halfedge_index a = m.halfedge(f);
      for(int i = 0; i < 3; ++i, a = m.next(a)) final_corners_[f][i] = std::size_t(m.source(a));
    }
    faces_ = m.number_of_faces();
  }

  std::size_t number_of_flips() const { return steps_.size(); }

  /// The point of the final face `f` with projective coordinates `beta` with respect to the hyperboloid lifts
  /// of its corners (in halfedge order), as weights beta_i e^{u_i} on the decoration at u = 0, scaled so that
  /// the largest is 1 in absolute value (signs kept: a point outside the face has a negative coordinate;
  /// `to_input()` takes points of the face).
  Face_point from_final(std::size_t f, const std::array<long double, 3>& beta) const
  {
    if(f >= faces_) throw Invalid_input_error("Ideal_surface_map: a point is not in a face of the mesh");
    Face_point p;
    p.face = f;
    long double lg[3], mx = -std::numeric_limits<long double>::infinity();
    for(int i = 0; i < 3; ++i) {
      lg[i] = beta[i] != 0 ? std::log(std::abs(beta[i])) + (long double)(u_[final_corners_[f][i]]) : -std::numeric_limits<long double>::infinity();
      mx = (std::max)(mx, lg[i]);
    }
    if(!std::isfinite(mx)) return p; // no non-zero coordinate: the centre of the face
    for(int i = 0; i < 3; ++i) p.w[i] = std::isfinite(lg[i]) ? (beta[i] < 0 ? -1 : 1) * std::exp(lg[i] - mx) : 0.0L;
    return p;
  }

  /// Maps points of final faces (weights at u = 0) to points of input faces (normalized weights: barycentric
  /// coordinates of the input face), undoing the flips in reverse order; in place.
  void to_input(std::vector<Face_point>& pts) const
  {
    std::vector<std::vector<std::size_t> > in_face(faces_);
    for(std::size_t i = 0; i < pts.size(); ++i) {
      if(pts[i].face >= faces_) throw Invalid_input_error("Ideal_surface_map: a point is not in a face of the mesh");
      in_face[pts[i].face].push_back(i);
    }
    std::vector<std::size_t> todo;
    for(auto it = steps_.rbegin(); it != steps_.rend(); ++it) {
      const Step& s = *it;
      todo.clear();
      todo.swap(in_face[s.fh]);
      todo.insert(todo.end(), in_face[s.fo].begin(), in_face[s.fo].end());
      in_face[s.fo].clear();
      for(std::size_t i : todo) {
        unflip(s, pts[i]);
        in_face[pts[i].face].push_back(i);
      }
    }
    for(Face_point& p : pts) normalize(p.w);
  }

private:
  typedef std::array<unsigned char, 3> Labels;
  enum { AB = 0, BC = 1, CA = 2, AD = 3, DB = 4, CD = 5 };
  struct Step
  {
    std::size_t fh = 0, fo = 0; // face(h) and face(opposite(h)), the same indices before and after the flip
    Labels before_h{{0, 1, 2}}, before_o{{1, 0, 3}};
    std::array<double, 6> l{{0, 0, 0, 0, 0, 0}}; // ab, bc, ca, ad, db, cd: lengths (Euclidean) or Penner coordinates
    bool euclidean = false;
  };

  static int pair_index(int i, int j)
  {
    static const int t[4][4] = {{-1, AB, CA, AD}, {AB, -1, BC, DB}, {CA, BC, -1, CD}, {AD, DB, CD, -1}};
    return t[i][j];
  }

  static void normalize(std::array<long double, 3>& w)
  {
    long double s = 0;
    for(long double& x : w) { if(!(x > 0)) x = 0; s += x; }
    if(!(s > 0)) { w = {{1.0L / 3, 1.0L / 3, 1.0L / 3}}; return; }
    for(long double& x : w) x /= s;
  }

  // the quadrilateral a b c d in the plane (Euclidean lengths): a at the origin, b on the positive x-axis, c to
  // the left of a -> b, d to the right
  static std::array<std::array<long double, 2>, 4> unfold(const std::array<double, 6>& l)
  {
    return Discrete_Ricci_flow::internal::unfold_euclidean_quadrilateral(l[AB], l[BC], l[CA], l[AD], l[DB]);
  }

  // weights on the corners `lab` (quad labels) of a face before the flip of the point with quad weights q;
  // returns min / sum of the coordinates (>= 0 inside the face; -infinity for a degenerate face)
  static long double coordinates(const Step& s, const std::array<long double, 4>& q, const Labels& lab,
                                 std::array<long double, 3>& w)
  {
    if(s.euclidean) {
      const auto p = unfold(s.l);
      long double x = 0, y = 0, sq = 0;
      for(int i = 0; i < 4; ++i) { x += q[i] * p[i][0]; y += q[i] * p[i][1]; sq += q[i]; }
      x /= sq; y /= sq;
      const auto &A = p[lab[0]], &B = p[lab[1]], &C = p[lab[2]];
      auto cross = [](long double ax, long double ay, long double bx, long double by, long double cx, long double cy) {
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
      };
      const long double d = cross(A[0], A[1], B[0], B[1], C[0], C[1]);
      if(!(d > 0)) return -std::numeric_limits<long double>::infinity();
      w = {{cross(x, y, B[0], B[1], C[0], C[1]) / d, cross(A[0], A[1], x, y, C[0], C[1]) / d,
            cross(A[0], A[1], B[0], B[1], x, y) / d}};
    } else {
      // Gram matrix of the light-like vectors, <v_i, v_j> = -2 lambda_ij^2 (the constant factor cancels: -lambda^2)
      auto g = [&](int i, int j) -> long double {
        if(i == j) return 0;
        const long double lam = s.l[pair_index(i, j)];
        return -lam * lam;
      };
      long double r[3];
      for(int k = 0; k < 3; ++k) {
        r[k] = 0;
        for(int i = 0; i < 4; ++i) if(q[i] != 0) r[k] += q[i] * g(i, lab[k]);
      }
      const long double x = g(lab[0], lab[1]), y = g(lab[0], lab[2]), z = g(lab[1], lab[2]);
      // inverse of [[0,x,y],[x,0,z],[y,z,0]] = [[-z^2, yz, xz], [yz, -y^2, xy], [xz, xy, -x^2]] / (2xyz)
      const long double d = 2 * x * y * z;
      w = {{(-z * z * r[0] + y * z * r[1] + x * z * r[2]) / d, (y * z * r[0] - y * y * r[1] + x * y * r[2]) / d,
            (x * z * r[0] + x * y * r[1] - x * x * r[2]) / d}};
    }
    const long double sum = std::abs(w[0]) + std::abs(w[1]) + std::abs(w[2]);
    if(!(sum > 0) || !std::isfinite(sum)) return -std::numeric_limits<long double>::infinity();
    return (std::min)({w[0], w[1], w[2]}) / sum;
  }

  void unflip(const Step& s, Face_point& p) const
  {
    // after the flip: face(h) = (d c a), face(o) = (c d b) in halfedge order
    static const Labels after_h{{3, 2, 0}}, after_o{{2, 3, 1}};
    const Labels& lab = p.face == s.fh ? after_h : after_o;
    std::array<long double, 4> q{{0, 0, 0, 0}};
    normalize(p.w);
    for(int i = 0; i < 3; ++i) q[lab[i]] += p.w[i];
    std::array<long double, 3> wh, wo;
    const long double sh = coordinates(s, q, s.before_h, wh), so = coordinates(s, q, s.before_o, wo);
    if(!(sh > -std::numeric_limits<long double>::infinity()) && !(so > -std::numeric_limits<long double>::infinity()))
      throw Numerical_error("Ideal_surface_map: a point cannot be expressed in the faces before a flip");
    if(sh >= so) { p.face = s.fh; p.w = wh; } else { p.face = s.fo; p.w = wo; }
    normalize(p.w); // clamps the rounding-level negatives of points on the diagonal
  }

  std::vector<double> u_;
  std::vector<Step> steps_;
  std::vector<std::array<std::size_t, 3> > final_corners_;
  std::size_t faces_ = 0;
};

} // namespace internal
} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_IDEAL_SURFACE_MAP_H
