// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fundamental domain D of the embedding, for pictures and side pairings: the surface cut along a compact
// cut graph, laid out chart by chart from the root face, its boundary walk and the pairing of its sides.
#ifndef CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_DOMAIN_H
#define CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_DOMAIN_H

#include <CGAL/Discrete_Ricci_flow/flow_types.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_motions.h>
#include <CGAL/Hyperbolic_surface_2/internal/dual_shortest_path_tree.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <complex>
#include <cstddef>
#include <deque>
#include <utility>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {
namespace internal {

/// The fundamental domain of a closed triangle mesh `Mesh` in the model plane. `Side` is the public
/// `Hyperbolic_embedding::Side` (members `halfedges`, `twin`, `pairing`, `translation`).
template <class Mesh, class Side>
class Fundamental_domain
{
public:
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Edge_index Edge_index;
  typedef typename Mesh::Face_index Face_index;

  Fundamental_domain() = default;

  /// the domain grown from face(root), whose chart is placed by `frame`; `charts` gives the face charts and
  /// their transitions (`Face_charts`), `length(h)` the length of edge(h) that weighs the growth of D
  template <class Charts, class Length>
  Fundamental_domain(const Mesh& m, Halfedge_index root, const Motion& frame, const Charts& charts, const Length& length)
    : hyperbolic_(charts.hyperbolic()), root_(root)
  {
    build_cut(m, length);
    std::vector<Motion> place; // the placement of each face's chart in D
    layout(m, frame, charts, place);
    compute_boundary(m, charts, place);
  }

  bool hyperbolic() const { return hyperbolic_; }
  Halfedge_index root() const { return root_; }
  bool is_cut(Edge_index e) const { return cut_[e] != 0; }
  /// position of `target(h)` in the copy of `face(h)` laid out in D
  const Cplx& position(Halfedge_index h) const { return pos_[h]; }
  std::complex<double> corner(Halfedge_index h) const { return std::complex<double>(double(pos_[h].real()), double(pos_[h].imag())); }
  /// the positions of all corners, by halfedge index
  const std::vector<Cplx>& positions() const { return pos_; }
  /// the cut halfedges with D on their left, in counterclockwise order
  const std::vector<Halfedge_index>& boundary() const { return boundary_; }
  /// the sides of D (maximal cut paths), each paired with its twin, and those pairings as motions
  const std::vector<Side>& sides() const { return sides_; }
  const std::vector<Motion>& pairings() const { return pairings_; }

private:
  // ---------------------------------------------------------------- a compact cut for the layout
  // The domain D is grown from the root face by a shortest-path tree of the dual graph (each step weighted by
  // a third of the two perimeters), so that every face of D is close to the base. The cut is the set of edges
  // not crossed by that dual tree, pruned of its dangling trees.
  template <class Length>
  void build_cut(const Mesh& m, const Length& len)
  {
    const std::size_t nf = m.number_of_faces(), ne = m.number_of_edges();
    std::vector<Face_index> faces(nf);
    std::vector<double> perim(nf, 0), fd;
    for(Face_index f : m.faces()) {
      const Halfedge_index h = m.halfedge(f);
      faces[f] = f;
      perim[f] = len(h) + len(m.next(h)) + len(m.prev(h));
    }
    std::vector<Halfedge_index> via;
    CGAL::Hyperbolic_surface_2::internal::dual_shortest_path_tree(
      m, faces, [](Face_index f) { return std::size_t(f); }, perim, std::size_t(m.face(root_)),
      [](Halfedge_index) { return true; }, fd, via);
    std::vector<char> crossed(ne, 0);
    for(Face_index f : m.faces()) if(via[f] != Mesh::null_halfedge()) crossed[m.edge(via[f])] = 1;
    cut_.assign(ne, 0);
    std::vector<std::size_t> degree(m.number_of_vertices(), 0);
    for(Edge_index e : m.edges())
      if(!crossed[e]) { cut_[e] = 1; ++degree[m.vertex(e, 0)]; ++degree[m.vertex(e, 1)]; }
    // prune: remove cut edges at vertices of cut-degree 1, repeatedly (a loop edge counts twice)
    std::vector<Vertex_index> stack;
    for(Vertex_index v : m.vertices()) if(degree[v] == 1) stack.push_back(v);
    while(!stack.empty()) {
      const Vertex_index v = stack.back(); stack.pop_back();
      if(degree[v] != 1) continue;
      for(Halfedge_index h : CGAL::halfedges_around_source(v, m)) {
        if(!cut_[m.edge(h)]) continue;
        cut_[m.edge(h)] = 0;
        --degree[v];
        const Vertex_index w = m.target(h);
        if(--degree[w] == 1) stack.push_back(w);
        break;
      }
    }
  }

  // ---------------------------------------------------------------- layout of the disk D, chart by chart
  template <class Charts>
  void layout(const Mesh& m, const Motion& frame, const Charts& charts, std::vector<Motion>& place)
  {
    pos_.assign(m.number_of_halfedges(), Cplx(0));
    place.assign(m.number_of_faces(), Motion::identity(hyperbolic_));
    std::vector<char> placed(m.number_of_faces(), 0);
    const Face_index f0 = m.face(root_);
    place[f0] = frame;
    placed[f0] = 1;
    std::deque<Face_index> queue(1, f0);
    while(!queue.empty()) {
      const Face_index f = queue.front(); queue.pop_front();
      const Halfedge_index h0 = m.halfedge(f);
      const std::array<Cplx, 3> z = charts.chart(f);
      const Halfedge_index hs[3] = {h0, m.next(h0), m.prev(h0)};
      for(int i = 0; i < 3; ++i) pos_[hs[i]] = place[f](z[(i + 1) % 3]); // target(h_i) = source(h_{i+1})
      for(Halfedge_index h : hs) {
        if(cut_[m.edge(h)]) continue;
        const Face_index g = m.face(m.opposite(h));
        if(placed[g]) continue;
        place[g] = place[f] * charts.transition(h).inverse();
        placed[g] = 1;
        queue.push_back(g);
      }
    }
    for(Face_index f : m.faces())
      if(!placed[f]) throw_mesh_error("the cut does not leave a disk (layout incomplete)");
  }

  // ---------------------------------------------------------------- boundary and sides
  // the face walk of the ribbon graph formed by the cut edges: from a cut halfedge h, rotate around target(h)
  // (crossing non-cut edges) to the next cut halfedge. For a cut graph this walks once around the disk.
  static std::vector<Halfedge_index> boundary_walk(const Mesh& m, const std::vector<char>& cut)
  {
    Halfedge_index start = Mesh::null_halfedge();
    for(Halfedge_index h : m.halfedges()) if(cut[m.edge(h)]) { start = h; break; }
    std::vector<Halfedge_index> walk;
    const std::size_t ncut = std::size_t(std::count(cut.begin(), cut.end(), char(1)));
    Halfedge_index h = start;
    do {
      walk.push_back(h);
      Halfedge_index g = m.next(h);
      while(!cut[m.edge(g)]) g = m.next(m.opposite(g));
      h = g;
      if(walk.size() > 2 * ncut) throw_mesh_error("boundary walk does not close");
    } while(h != start);
    if(walk.size() != 2 * ncut) throw_mesh_error("the cut graph does not bound a single disk");
    return walk;
  }

  template <class Charts>
  void compute_boundary(const Mesh& m, const Charts& charts, const std::vector<Motion>& place)
  {
    boundary_ = boundary_walk(m, cut_);
    std::vector<std::size_t> index_of(m.number_of_halfedges(), std::size_t(-1));
    for(std::size_t k = 0; k < boundary_.size(); ++k) index_of[boundary_[k]] = k;
    const std::size_t nb = boundary_.size();
    auto twin_index = [&](std::size_t k) { return index_of[m.opposite(boundary_[k])]; };
    // a side starts at k if the twin of k-1 is not the successor of the twin of k
    std::vector<char> starts(nb, 0);
    for(std::size_t k = 0; k < nb; ++k) starts[k] = twin_index((k + nb - 1) % nb) != (twin_index(k) + 1) % nb;
    sides_.clear();
    std::vector<std::size_t> side_of(nb, 0);
    std::size_t k0 = 0;
    while(k0 < nb && !starts[k0]) ++k0;
    if(k0 == nb) k0 = 0;
    for(std::size_t t = 0; t < nb; ++t) {
      const std::size_t k = (k0 + t) % nb;
      if(starts[k] || sides_.empty()) sides_.push_back(Side());
      sides_.back().halfedges.push_back(boundary_[k]);
      side_of[k] = sides_.size() - 1;
    }
    pairings_.clear();
    for(std::size_t s = 0; s < sides_.size(); ++s) {
      const Halfedge_index g = sides_[s].halfedges.front(), o = m.opposite(g);
      sides_[s].twin = side_of[index_of[o]];
      // the copy of face(o) adjacent to the copy of face(g) across g, from the domain's copy of face(o)
      const Motion p = (place[m.face(g)] * charts.transition(g).inverse() * place[m.face(o)].inverse()).normalized();
      pairings_.push_back(p);
      if(hyperbolic_) sides_[s].pairing = p.h;
      else sides_[s].translation = std::complex<double>(double(p.b.real()), double(p.b.imag()));
    }
  }

  bool hyperbolic_ = true;
  Halfedge_index root_;
  std::vector<char> cut_;
  std::vector<Cplx> pos_;
  std::vector<Motion> pairings_;
  std::vector<Halfedge_index> boundary_;
  std::vector<Side> sides_;
};

} // namespace internal
} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_INTERNAL_EMBEDDING_DOMAIN_H
