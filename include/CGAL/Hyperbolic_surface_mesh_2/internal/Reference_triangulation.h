// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reference triangulation of a surface triangulation: a frozen copy of its initial triangulation (charts,
// adjacency, and the frame of a fundamental domain). Every face of the live triangulation is anchored to a
// reference face (an isometry from its chart into the reference chart), which maps its points back to the
// input (a polygon frame, or an input mesh face with barycentric coordinates).
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_REFERENCE_TRIANGULATION_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_INTERNAL_REFERENCE_TRIANGULATION_H

#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>
#include <CGAL/Poincare_disk_traits_2.h>

#include <CGAL/Hyperbolic_geometry_errors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {
namespace internal {

/// throws `Poincare_disk_domain_error` unless p is a finite point of the open unit disk
template <class Point_2>
void check_in_disk(const Point_2& p, const char* where)
{
  const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
  if(!(std::isfinite(x) && std::isfinite(y) && x * x + y * y < 1.0))
    throw Poincare_disk_domain_error(std::string(where) + ": the point is not in the open Poincare disk");
}

template <class Traits>
struct Reference_triangulation
{
  typedef typename Traits::Kernel Kernel;
  typedef typename Traits::Point_2 Point_2;
  typedef CGAL::Poincare_disk_isometry_2<Kernel> Isometry_2;
  typedef Hyperbolic_surface_2::Disk_geometry<Kernel> Geometry;

  struct Face
  {
    std::array<Point_2, 3> z;          // chart (barycentre near the origin)
    std::array<std::size_t, 3> nb;     // neighbour across edge i (z[i] -> z[i+1])
    std::array<unsigned char, 3> ne;   // index of the same edge in the neighbour
    Isometry_2 to_frame;               // chart -> frame of the fundamental domain
    std::array<Isometry_2, 3> tr;      // transitions (after cache_transitions())
    double inner2 = 0;                 // a Klein disk about the origin inside the face: |k(q)|^2 < inner2
  };
  std::vector<Face> faces;
  bool cached = false;

  /// computes every transition once (the reference triangulation is frozen after construction)
  void cache_transitions()
  {
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int i = 0; i < 3; ++i) faces[f].tr[i] = compute_transition(f, i);
    for(Face& F : faces) {
      // squared Euclidean distance from the origin to the Klein lines of the edges, with a 1e-6 relative margin
      double m = 1;
      for(int i = 0; i < 3; ++i) {
        const Point_2 a = Geometry::to_klein(F.z[i]), b = Geometry::to_klein(F.z[(i + 1) % 3]);
        const double ex = b.x() - a.x(), ey = b.y() - a.y(), c = a.x() * b.y() - a.y() * b.x();
        m = (std::min)(m, c * c / (ex * ex + ey * ey));
      }
      F.inner2 = m * (1 - 1e-6);
    }
    cached = true;
  }

  /// the isometry from the chart of `f` to the chart of its neighbour across edge `i`
  Isometry_2 transition(std::size_t f, int i) const { return cached ? faces[f].tr[i] : compute_transition(f, i); }

  Isometry_2 compute_transition(std::size_t f, int i) const
  {
    const Face& F = faces[f];
    const Face& G = faces[F.nb[i]];
    const int j = F.ne[i];
    return Geometry::isometry_from_pairs(F.z[i], F.z[(i + 1) % 3], G.z[(j + 1) % 3], G.z[j]);
  }

  /// Walks from face `f` to the face containing `q` (given in the chart of `f`); on return `f` is that face,
  /// `q` is in its chart and `m` was composed with the transitions crossed. Returns false if `max_steps` was
  /// not enough (the last face is kept: still a valid anchor, only farther away).
  bool walk(std::size_t& f, Point_2& q, Isometry_2& m, std::size_t max_steps = 256) const
  {
    if(cached) { // inside the inner Klein disk of the face: no orientation test needed
      const double n = q.x() * q.x() + q.y() * q.y(), w = 4 / ((1 + n) * (1 + n));
      if(n * w < faces[f].inner2) return true;
    }
    const Traits gt;
    const auto orient = gt.orientation_2_object();
    int came_from = -1;
    for(std::size_t step = 0; step < max_steps; ++step) {
      const Face& F = faces[f];
      int cross = -1;
      for(int k = 0; k < 3; ++k) {
        const int i = (k + int(step)) % 3;
        if(i == came_from) continue;
        if(orient(F.z[i], F.z[(i + 1) % 3], q) == CGAL::RIGHT_TURN) { cross = i; break; }
      }
      if(cross < 0) return true;
      const Isometry_2 t = transition(f, cross);
      q = t.apply_unchecked(q);
      m = (t * m).normalized();
      came_from = F.ne[cross];
      f = F.nb[cross];
    }
    return false;
  }

  /// barycentric coordinates of `q` (chart of `f`) in the straight Klein triangle of `f`
  std::array<double, 3> klein_barycentric(std::size_t f, const Point_2& q) const
  {
    const Face& F = faces[f];
    const Point_2 k0 = Geometry::to_klein(F.z[0]), k1 = Geometry::to_klein(F.z[1]), k2 = Geometry::to_klein(F.z[2]);
    const Point_2 kq = Geometry::to_klein(q);
    auto cross = [](const Point_2& a, const Point_2& b, const Point_2& c) {
      return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    };
    const double d = cross(k0, k1, k2);
    std::array<double, 3> l{{cross(kq, k1, k2) / d, cross(k0, kq, k2) / d, cross(k0, k1, kq) / d}};
    double s = 0;
    for(double& x : l) { if(!(x > 0)) x = 0; s += x; }
    if(!(s > 0)) return {{1.0 / 3, 1.0 / 3, 1.0 / 3}};
    for(double& x : l) x /= s;
    return l;
  }
};

} // namespace internal
} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif
