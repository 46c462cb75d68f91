// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: input checks, domain marking (seeds), hull constraints for point clouds, and approximate geometric
// quantities of the input (angles between geodesics, point-to-geodesic-segment distances).
#ifndef CGAL_HYPERBOLIC_MESH_2_INTERNAL_INPUT_ANALYSIS_H
#define CGAL_HYPERBOLIC_MESH_2_INTERNAL_INPUT_ANALYSIS_H

#include <CGAL/Hyperbolic_mesh_2/mesh_types.h>
#include <CGAL/Poincare_disk_traits_2/internal/checks.h>
#include <CGAL/Handle_hash_function.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_mesh_2 {
namespace internal {

/// Throws `CGAL::Poincare_disk_domain_error` unless p is a finite point with |p| < 1: the traits' exact check
/// (`Poincare_disk_internal::check_point_in_disk`), with the mesher's name for the point in the message.
template <class Point_2>
void check_point_in_open_disk(const Point_2& p, const char* what)
{
  Poincare_disk_internal::check_point_in_disk(p, (std::string("Hyperbolic_mesh_2: ") + what).c_str());
}

inline std::complex<double> to_origin(std::complex<double> z, std::complex<double> a)
{
  return (z - a) / (1.0 - std::conj(a) * z);
}

template <class Point_2>
std::complex<double> cplx(const Point_2& p) { return std::complex<double>(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

/// Direction (angle in (-pi, pi]) of the tangent at o of the geodesic from o to w. Isometries are conformal:
/// after the translation taking o to the origin the geodesic is a diameter.
template <class Point_2>
double tangent_direction(const Point_2& o, const Point_2& w)
{
  return std::arg(to_origin(cplx(w), cplx(o)));
}

/// Hyperbolic distance from v to the geodesic segment ab (approximate, double): after moving v to the origin,
/// hyperbolic distance from the origin is increasing in the Euclidean norm of the Klein image, and geodesics are
/// Klein straight segments; d = atanh(Euclidean distance from 0 to the Klein segment).
template <class Point_2>
double point_segment_distance(const Point_2& v, const Point_2& a, const Point_2& b)
{
  const std::complex<double> c = cplx(v);
  auto klein = [&](const Point_2& p) { const std::complex<double> z = to_origin(cplx(p), c);
                                       return 2.0 * z / (1.0 + std::norm(z)); };
  const std::complex<double> ka = klein(a), kb = klein(b), u = kb - ka;
  const double uu = std::norm(u);
  double t = uu > 0 ? -(ka.real() * u.real() + ka.imag() * u.imag()) / uu : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  const double delta = std::min(std::abs(ka + t * u), 1.0 - 1e-16);
  return std::atanh(delta);
}

/// If the triangulation has no constrained edge (a point cloud), constrains the edges of its convex hull, so that
/// the domain is the (hyperbolic) convex hull of the points.
template <class CDT>
void constrain_hull_if_no_constraint(CDT& cdt)
{
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if(cdt.is_constrained(*e)) return;
  std::vector<std::pair<typename CDT::Vertex_handle, typename CDT::Vertex_handle> > hull;
  auto fc = cdt.incident_faces(cdt.infinite_vertex()), done = fc;
  do {
    const int i = fc->index(cdt.infinite_vertex());
    hull.push_back(std::make_pair(fc->vertex(CDT::ccw(i)), fc->vertex(CDT::cw(i))));
  } while(++fc != done);
  for(const auto& h : hull) cdt.insert_constraint(h.first, h.second);
}

/// Marks the faces in the domain as `refine_Delaunay_mesh_2` does: the connected components of faces (across
/// unconstrained edges) not reachable from the infinite faces are in the domain; with seeds, the components that
/// contain a seed are removed from it (or, if `seeds_are_in_domain`, they are the domain). O(n).
/// Throws `CGAL::Poincare_disk_domain_error` if a seed is not inside the open unit disk.
template <class CDT, class Point_2>
void mark_domain(CDT& cdt, const std::vector<Point_2>& seeds, bool seeds_are_in_domain)
{
  typedef typename CDT::Face_handle Face_handle;
  std::unordered_map<Face_handle, int, Handle_hash_function> comp;
  std::vector<char> has_infinite;
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
    if(comp.count(f)) continue;
    const int c = int(has_infinite.size());
    has_infinite.push_back(0);
    std::vector<Face_handle> stack(1, f);
    comp[f] = c;
    while(!stack.empty()) {
      Face_handle g = stack.back(); stack.pop_back();
      if(cdt.is_infinite(g)) has_infinite[c] = 1;
      for(int i = 0; i < 3; ++i) {
        if(cdt.is_constrained(typename CDT::Edge(g, i))) continue;
        Face_handle n = g->neighbor(i);
        if(comp.count(n)) continue;
        comp[n] = c;
        stack.push_back(n);
      }
    }
  }
  std::vector<char> seeded(has_infinite.size(), 0);
  for(const Point_2& s : seeds) {
    check_point_in_open_disk(s, "a seed");
    Face_handle f = cdt.locate(s);
    if(f != Face_handle()) seeded[comp[f]] = 1;
  }
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
    const int c = comp[f];
    bool in = !has_infinite[c];
    if(!seeds.empty()) in = in && (seeds_are_in_domain ? seeded[c] != 0 : seeded[c] == 0);
    f->set_in_domain(in);
  }
}

} // namespace internal
} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_INTERNAL_INPUT_ANALYSIS_H
