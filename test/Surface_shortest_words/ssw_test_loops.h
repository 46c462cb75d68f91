// Random loops for the Surface_shortest_words tests.
#ifndef CGAL_HC_SSW_TEST_LOOPS_H
#define CGAL_HC_SSW_TEST_LOOPS_H

#include <CGAL/boost/graph/iterator.h>

#include <map>
#include <queue>
#include <random>
#include <vector>

namespace ssw_test {

// random closed walk from `base`: `len` random steps along outgoing halfedges, then back to `base` along the
// tree of a breadth-first search from it
template <class Mesh>
std::vector<typename Mesh::Halfedge_index> random_loop(const Mesh& m, typename Mesh::Vertex_index base, std::size_t len,
                                                       std::mt19937& rng)
{
  typedef typename Mesh::Halfedge_index H;
  typedef typename Mesh::Vertex_index V;
  std::vector<H> hs;
  V v = base;
  for(std::size_t i = 0; i < len; ++i) {
    std::vector<H> out;
    for(H h : CGAL::halfedges_around_source(v, m)) out.push_back(h);
    hs.push_back(out[rng() % out.size()]);
    v = m.target(hs.back());
  }
  std::map<V, H> parent; // the halfedge reaching the vertex
  std::queue<V> q;
  q.push(base);
  parent[base] = Mesh::null_halfedge();
  while(!q.empty() && !parent.count(v)) {
    const V u = q.front(); q.pop();
    for(H h : CGAL::halfedges_around_source(u, m))
      if(!parent.count(m.target(h))) { parent[m.target(h)] = h; q.push(m.target(h)); }
  }
  std::vector<H> back;
  while(v != base) { const H h = parent[v]; back.push_back(m.opposite(h)); v = m.source(h); }
  hs.insert(hs.end(), back.begin(), back.end());
  return hs;
}

} // namespace ssw_test

#endif
