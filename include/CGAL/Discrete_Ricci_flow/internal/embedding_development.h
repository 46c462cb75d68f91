// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The developing map of the embedding: the chart of every face of the intrinsic mesh in the model plane (the
// layer's Disk_geometry in long double on the polished lengths for the hyperbolic background, a Euclidean
// chart for the flat torus), the transition isometries between the charts of adjacent faces, and the walk
// along a based loop that composes those transitions (in any precision).
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_DEVELOPMENT_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_DEVELOPMENT_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_motions.h>
#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

/// the index of g in its face: 0 for halfedge(face(g)), 1 for its next, 2 for its prev
template <class Mesh>
int index_in_face(const Mesh& m, typename Mesh::Halfedge_index g)
{
  const typename Mesh::Halfedge_index h0 = m.halfedge(m.face(g));
  return g == h0 ? 0 : (g == m.next(h0) ? 1 : 2);
}

/// The face charts of a `Discrete_metric` and the transitions between them (a view on the metric and on the
/// polished long-double lengths `long_length`, by edge index, which must outlive it).
template <class Metric>
class Face_charts
{
public:
  typedef typename Metric::Mesh Mesh;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Face_index Face_index;
  typedef CGAL::Hyperbolic_surface_2::Disk_geometry<Long_kernel> Long_geometry;

  Face_charts(const Metric& metric, bool hyperbolic, const std::vector<Real>& long_length)
    : metric_(metric), m_(metric.intrinsic_mesh()), hyperbolic_(hyperbolic), long_length_(long_length)
  {}

  bool hyperbolic() const { return hyperbolic_; }

  // the chart of f: z[i] is the position of source(h_i), h_0 = halfedge(f), h_{i+1} = next(h_i)
  std::array<Cplx, 3> chart(Face_index f) const
  {
    if(hyperbolic_) { // the layer's chart construction, in long double on the polished lengths
      const Halfedge_index h = m_.halfedge(f);
      const std::array<Long_kernel::Point_2, 3> c = Long_geometry::triangle_chart(
        long_length_[m_.edge(h)], long_length_[m_.edge(m_.next(h))], long_length_[m_.edge(m_.prev(h))]);
      std::array<Cplx, 3> z;
      for(int i = 0; i < 3; ++i) z[i] = Cplx(c[i].x(), c[i].y());
      return z;
    }
    const Halfedge_index h = m_.halfedge(f);
    return euclidean_chart(metric_.length(h), metric_.length(m_.next(h)), metric_.length(m_.prev(h)));
  }

  // maps the chart of face(h) to the chart of face(opposite(h))
  Motion transition(Halfedge_index h) const
  {
    const Halfedge_index o = m_.opposite(h);
    const std::array<Cplx, 3> cf = chart(m_.face(h)), cg = chart(m_.face(o));
    const int ih = index_in_face(m_, h), io = index_in_face(m_, o);
    if(hyperbolic_) { // the layer's transition (Surface::transition) in long double
      auto P = [](const Cplx& z) { return Long_kernel::Point_2(z.real(), z.imag()); };
      return Motion::from(Long_geometry::isometry_from_pairs(P(cf[ih]), P(cf[(ih + 1) % 3]), P(cg[(io + 1) % 3]), P(cg[io])));
    }
    // source(h) = target(o), target(h) = source(o)
    return euclidean_from_pairs(cf[ih], cf[(ih + 1) % 3], cg[(io + 1) % 3], cg[io]);
  }

private:
  const Metric& metric_;
  const Mesh& m_;
  bool hyperbolic_;
  const std::vector<Real>& long_length_;
};

// Developing along a loop: the current corner c (a halfedge entering the current vertex, in the current face);
// rotating counterclockwise to the next corner crosses edge(next(c)) into face(opposite(next(c))). M maps the
// chart of the current face to the chart of the root face's first copy.
// The same walk in every precision: `M` is a motion type (internal::Motion, internal::Mp_isometry) starting
// at `identity`, `transition_of(h)` its transition across h; the loop starts and ends at target(root).
template <class Mesh, class M_type, class Transition>
M_type develop_loop(const Mesh& m, typename Mesh::Halfedge_index root,
                    const std::vector<typename Mesh::Halfedge_index>& loop, const M_type& identity,
                    const Transition& transition_of)
{
  typedef typename Mesh::Halfedge_index Halfedge_index;
  M_type M = identity;
  Halfedge_index c = root;
  const std::size_t guard_max = m.number_of_halfedges();
  auto rotate = [&]() {
    const Halfedge_index g = m.next(c);
    M = M * transition_of(g).inverse();
    c = m.opposite(g);
  };
  for(Halfedge_index h : loop) {
    std::size_t guard = 0;
    while(m.next(c) != h) {
      rotate();
      if(++guard > guard_max) throw_mesh_error("develop: invalid loop");
    }
    c = h;
  }
  std::size_t guard = 0;
  while(c != root) {
    rotate();
    if(++guard > guard_max) throw_mesh_error("develop: invalid loop");
  }
  return M;
}

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_DEVELOPMENT_H
