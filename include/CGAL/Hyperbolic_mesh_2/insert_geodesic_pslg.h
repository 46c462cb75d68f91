// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// insert_geodesic_pslg(): checked insertion of a planar geodesic graph (points + geodesic segments) into a
// Constrained_Delaunay_triangulation_2 with Poincare_disk_traits_2.
#ifndef CGAL_HYPERBOLIC_MESH_2_INSERT_GEODESIC_PSLG_H
#define CGAL_HYPERBOLIC_MESH_2_INSERT_GEODESIC_PSLG_H

#include <CGAL/Hyperbolic_mesh_2/internal/input_analysis.h>
#include <CGAL/Hyperbolic_mesh_2/mesh_types.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_mesh_2 {

/*!
  \ingroup PkgHyperbolicMesh2Ref

  Inserts the planar geodesic graph (`points`, `segments`) into `cdt` after checking it, and returns the vertex
  handles of the points (in order).

  `segments` is a range of pairs of indices into `points`. The checks, all with the traits' exact predicates,
  throw with a message naming the offending items (both types are `Input_error` = `CGAL::Invalid_input_error`):
  - `CGAL::Poincare_disk_domain_error`: a point not strictly inside the unit disk, or not finite;
  - `Pslg_error`: two equal points;
  - a segment index out of range, or a segment from a point to itself;
  - two segments that cross, touch or overlap anywhere but at a common endpoint; a point in the interior of a
    segment.
  Cost: O(n log n + m^2 + n m) predicate calls for n points and m segments, plus the insertion.
*/
template <class CDT, class PointRange, class SegmentRange>
std::vector<typename CDT::Vertex_handle>
insert_geodesic_pslg(CDT& cdt, const PointRange& points, const SegmentRange& segments)
{
  typedef typename CDT::Geom_traits Gt;
  typedef typename CDT::Point Point;
  const Gt gt = cdt.geom_traits();
  std::vector<Point> pts(points.begin(), points.end());
  for(std::size_t i = 0; i < pts.size(); ++i)
    internal::check_point_in_open_disk(pts[i], ("point " + std::to_string(i)).c_str());
  {
    std::vector<std::size_t> order(pts.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return pts[a].x() < pts[b].x() || (pts[a].x() == pts[b].x() && pts[a].y() < pts[b].y());
    });
    for(std::size_t k = 1; k < order.size(); ++k)
      if(pts[order[k]] == pts[order[k - 1]])
        throw Pslg_error("duplicate points " + std::to_string(order[k - 1]) + " and " + std::to_string(order[k]));
  }
  std::vector<std::pair<std::size_t, std::size_t> > segs;
  for(const auto& s : segments) {
    const std::size_t a = std::size_t(s.first), b = std::size_t(s.second);
    if(a >= pts.size() || b >= pts.size())
      throw Pslg_error("segment (" + std::to_string(a) + ", " + std::to_string(b) + ") has an index out of range");
    if(a == b) throw Pslg_error("segment (" + std::to_string(a) + ", " + std::to_string(b) + ") has length 0");
    segs.push_back(std::make_pair(a, b));
  }
  auto orient = gt.orientation_2_object();
  auto klein = gt.construct_Klein_point_2_object();
  // c strictly between a and b on their common geodesic (precondition: collinear), via Klein coordinates
  auto strictly_between = [&](const Point& a, const Point& b, const Point& c) {
    const Point ka = klein(a), kb = klein(b), kc = klein(c);
    const auto d1 = (kc.x() - ka.x()) * (kb.x() - ka.x()) + (kc.y() - ka.y()) * (kb.y() - ka.y());
    const auto d2 = (kc.x() - kb.x()) * (ka.x() - kb.x()) + (kc.y() - kb.y()) * (ka.y() - kb.y());
    return d1 > 0 && d2 > 0;
  };
  auto name = [&](std::size_t k) {
    return "segment " + std::to_string(k) + " (" + std::to_string(segs[k].first) + ", " +
           std::to_string(segs[k].second) + ")";
  };
  for(std::size_t k = 0; k < segs.size(); ++k) {
    const Point &a = pts[segs[k].first], &b = pts[segs[k].second];
    for(std::size_t i = 0; i < pts.size(); ++i) {
      if(i == segs[k].first || i == segs[k].second) continue;
      if(orient(a, b, pts[i]) == COLLINEAR && strictly_between(a, b, pts[i]))
        throw Pslg_error("point " + std::to_string(i) + " lies in the interior of " + name(k));
    }
    for(std::size_t l = k + 1; l < segs.size(); ++l) {
      const std::size_t s0 = segs[l].first, s1 = segs[l].second;
      const Point &c = pts[s0], &d = pts[s1];
      const bool shares = s0 == segs[k].first || s0 == segs[k].second || s1 == segs[k].first || s1 == segs[k].second;
      const Orientation o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
      if(shares) {
        if((s0 == segs[k].first && s1 == segs[k].second) || (s1 == segs[k].first && s0 == segs[k].second))
          throw Pslg_error(name(k) + " and " + name(l) + " are the same segment");
        // common endpoint; the two other ends on the same ray of the common geodesic means overlap
        if(o1 == COLLINEAR && o2 == COLLINEAR) {
          const Point& o = (s0 == segs[k].first || s1 == segs[k].first) ? a : b;
          const Point& x = (&o == &a) ? b : a;
          const Point& y = (s0 == segs[k].first || s0 == segs[k].second) ? d : c;
          if(!strictly_between(x, y, o)) throw Pslg_error(name(k) + " and " + name(l) + " overlap");
        }
        continue;
      }
      if(o1 == COLLINEAR && o2 == COLLINEAR) {
        if(strictly_between(a, b, c) || strictly_between(a, b, d) || strictly_between(c, d, a) ||
           strictly_between(c, d, b))
          throw Pslg_error(name(k) + " and " + name(l) + " overlap");
        continue;
      }
      if(o1 != o2 && o3 != o4)
        throw Pslg_error(name(k) + " and " + name(l) + " cross (insert their intersection point as a vertex "
                          "and split them)");
    }
  }
  std::vector<typename CDT::Vertex_handle> vh;
  vh.reserve(pts.size());
  for(const Point& p : pts) vh.push_back(cdt.insert(p));
  for(const auto& s : segs) cdt.insert_constraint(vh[s.first], vh[s.second]);
  return vh;
}

} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_INSERT_GEODESIC_PSLG_H
