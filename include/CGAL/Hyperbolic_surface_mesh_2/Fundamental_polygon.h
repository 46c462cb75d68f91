// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fundamental polygon of a closed hyperbolic surface in the Poincare disk: a convex geodesic polygon whose
// sides are glued in pairs by orientation-preserving isometries. Checked: paired sides of equal length, angle
// sum 2 pi at every vertex cycle, Gauss-Bonnet area 4 pi (g - 1), g >= 2.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_FUNDAMENTAL_POLYGON_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_FUNDAMENTAL_POLYGON_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>
#include <CGAL/Hyperbolic_surface_2/hyperbolic_triangle.h>
#include <CGAL/Poincare_disk_traits_2.h>
#include <CGAL/Hyperbolic_surface_mesh_2/internal/Reference_triangulation.h>

#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {

/*!
  \ingroup PkgHyperbolicSurfaceMesh2Ref
  A fundamental polygon: vertices `w_0, ..., w_{n-1}` of a strictly convex geodesic polygon in the Poincare
  disk (counterclockwise) and an involution `pairing` of the sides without fixed point. Side `i` runs from
  `w_i` to `w_{i+1}`; it is glued to side `j = pairing[i]` reversed: the side pairing isometry `side_pairing(i)`
  maps `w_j` to `w_{i+1}` and `w_{j+1}` to `w_i`.

  The constructor checks, in release builds too (tolerance `tol` on lengths and angles):
  - every vertex is a finite point of the open disk (`CGAL::Poincare_disk_domain_error`);
  - n >= 3, the pairing is an involution without fixed point, the polygon is strictly convex (Klein
    orientation, exact) (`CGAL::Invalid_input_error`);
  - paired sides have equal hyperbolic lengths, the angles at every vertex cycle sum to 2 pi, the genus
    (from the Euler characteristic of the glued surface) is at least 2 and the area is 4 pi (g - 1)
    (`CGAL::Invalid_metric_error`; `CGAL::Invalid_mesh_error` for genus < 2).
  Cost: O(n).
*/
template <class Kernel = CGAL::Exact_predicates_inexact_constructions_kernel>
class Fundamental_polygon
{
public:
  typedef typename Kernel::Point_2 Point_2;
  typedef CGAL::Poincare_disk_isometry_2<Kernel> Isometry_2;
  typedef Hyperbolic_surface_2::Disk_geometry<Kernel> Geometry;

  Fundamental_polygon(const std::vector<Point_2>& vertices, const std::vector<int>& pairing, double tol = 1e-9)
    : w_(vertices), pairing_(pairing)
  {
    check_combinatorics();
    check_geometry(tol);
  }

  /// The regular 4g-gon with interior angles pi / (2g), opposite sides glued (side i with side i + 2g): a
  /// genus-g surface with one vertex cycle. Vertex k is at angle (2k + 1) pi / (4g); for g = 2 this is the
  /// Bolza octagon of CGAL's `Periodic_4_hyperbolic_Delaunay_triangulation_2` (sides centred at the angles
  /// k pi / 4, side pairings the translations along those directions). Throws `Invalid_input_error` if g < 2.
  static Fundamental_polygon regular(int g)
  {
    if(g < 2) throw Invalid_input_error("Fundamental_polygon::regular: the genus must be at least 2");
    const int n = 4 * g;
    // circumradius R of the regular n-gon with interior angle beta: cosh R = cot(pi / n) cot(beta / 2)
    const double beta = CGAL_PI / (2 * g);
    const double coshR = 1.0 / std::tan(CGAL_PI / n) / std::tan(beta / 2);
    const double r = std::tanh(std::acosh(coshR) / 2);
    std::vector<Point_2> w;
    std::vector<int> pairing;
    for(int k = 0; k < n; ++k) {
      const double t = (2 * k + 1) * CGAL_PI / n;
      w.push_back(Point_2(r * std::cos(t), r * std::sin(t)));
      pairing.push_back((k + 2 * g) % n);
    }
    return Fundamental_polygon(w, pairing);
  }

  /// the Bolza surface: `regular(2)`
  static Fundamental_polygon Bolza() { return regular(2); }

  std::size_t size() const { return w_.size(); }
  const std::vector<Point_2>& vertices() const { return w_; }
  const Point_2& vertex(std::size_t i) const { return w_[i % w_.size()]; }
  int paired_side(std::size_t i) const { return pairing_[i]; }
  /// the vertex cycle (a vertex of the glued surface) of polygon vertex i, numbered 0, 1, ...
  int vertex_cycle(std::size_t i) const { return cycle_[i]; }
  int number_of_vertex_cycles() const { return ncycles_; }
  int genus() const { return genus_; }
  double area() const { return area_; }

  /// the isometry mapping side `pairing(i)` onto side `i` (reversed; see the class documentation)
  Isometry_2 side_pairing(std::size_t i) const
  {
    const std::size_t j = std::size_t(pairing_[i]);
    return Geometry::isometry_from_pairs(vertex(j), vertex(j + 1), vertex(i + 1), vertex(i));
  }

private:
  [[noreturn]] static void fail(const std::string& m) { throw Invalid_input_error("Fundamental_polygon: " + m); }

  void check_combinatorics()
  {
    const std::size_t n = w_.size();
    if(n < 3) fail("fewer than 3 vertices");
    if(pairing_.size() != n) fail("the pairing must have one entry per side");
    for(const Point_2& p : w_) internal::check_in_disk(p, "Fundamental_polygon");
    for(std::size_t i = 0; i < n; ++i) {
      const int j = pairing_[i];
      if(j < 0 || std::size_t(j) >= n || std::size_t(j) == i || pairing_[std::size_t(j)] != int(i))
        fail("the side pairing is not an involution without fixed point");
    }
    const CGAL::Poincare_disk_traits_2<Kernel> gt;
    for(std::size_t i = 0; i < n; ++i)
      if(gt.orientation_2_object()(vertex(i), vertex(i + 1), vertex(i + 2)) != CGAL::LEFT_TURN)
        fail("the polygon is not strictly convex and counterclockwise");
    // vertex cycles: side i glued to side j reversed identifies w_i ~ w_{j+1} and w_{i+1} ~ w_j
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) { while(parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = std::size_t(pairing_[i]);
      parent[find(int(i))] = find(int((j + 1) % n));
      parent[find(int((i + 1) % n))] = find(int(j));
    }
    cycle_.assign(n, -1);
    std::vector<int> id(n, -1);
    ncycles_ = 0;
    for(std::size_t i = 0; i < n; ++i) {
      const int r = find(int(i));
      if(id[r] < 0) id[r] = ncycles_++;
      cycle_[i] = id[r];
    }
    const long chi = long(ncycles_) - long(n / 2) + 1;
    if(chi % 2 != 0) fail("odd Euler characteristic");
    genus_ = int((2 - chi) / 2);
    if(genus_ < 2) {
      std::ostringstream os;
      os << "Fundamental_polygon: the glued surface has genus " << genus_ << " < 2 (no hyperbolic metric)";
      throw Invalid_mesh_error(os.str());
    }
  }

  void check_geometry(double tol)
  {
    const std::size_t n = w_.size();
    std::ostringstream os;
    os.precision(12);
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = std::size_t(pairing_[i]);
      const double li = Geometry::distance(vertex(i), vertex(i + 1)), lj = Geometry::distance(vertex(j), vertex(j + 1));
      if(!(std::abs(li - lj) <= tol * (1 + li))) {
        os << "paired sides " << i << " and " << j << " have different lengths " << li << " and " << lj;
        throw Invalid_metric_error("Fundamental_polygon: " + os.str());
      }
    }
    std::vector<double> sums(std::size_t(ncycles_), 0.0);
    double angle_total = 0;
    for(std::size_t i = 0; i < n; ++i) {
      // interior angle at w_i between w_{i-1} and w_{i+1}
      const Point_2 &a = vertex(i + n - 1), &b = vertex(i), &c = vertex(i + 1);
      const double theta = Hyperbolic_surface_2::corner_angle(Geometry::distance(a, c), Geometry::distance(a, b),
                                                              Geometry::distance(b, c));
      sums[std::size_t(cycle_[i])] += theta;
      angle_total += theta;
    }
    for(int k = 0; k < ncycles_; ++k)
      if(!(std::abs(sums[std::size_t(k)] - 2 * CGAL_PI) <= tol * 2 * CGAL_PI)) {
        os << "the angles at vertex cycle " << k << " sum to " << sums[std::size_t(k)] << ", not 2 pi: the side pairings do not close up";
        throw Invalid_metric_error("Fundamental_polygon: " + os.str());
      }
    area_ = double(n - 2) * CGAL_PI - angle_total;
    const double expected = 4 * CGAL_PI * (genus_ - 1);
    if(!(std::abs(area_ - expected) <= tol * expected)) {
      os << "area " << area_ << " differs from 4 pi (g - 1) = " << expected;
      throw Invalid_metric_error("Fundamental_polygon: " + os.str());
    }
  }

  std::vector<Point_2> w_;
  std::vector<int> pairing_;
  std::vector<int> cycle_;
  int ncycles_ = 0, genus_ = 0;
  double area_ = 0;
};

} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_MESH_2_FUNDAMENTAL_POLYGON_H
