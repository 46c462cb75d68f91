// libFuzzer target: random loops -> Shortest_word_solver, checked with CGAL's homotopy test; random words ->
// geodesic reduction, checked with Dehn's algorithm (same element) and idempotence (the result is accepted).
// Build: clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -Iinclude test/fuzz/fuzz_words.cpp -lgmp -lmpfr
// Run:   ./a.out test/fuzz/corpus/words -max_total_time=60
// Input: byte 0 selects the genus (bit 0: 2 or 3), the system (bit 1: given / computed canonical) and the surface
// (bit 2: the regular polygon surface / the one-vertex polygon, every face using its vertex three times); the other bytes are
// the steps of a walk from the base vertex (outgoing halfedge index), closed by a shortest edge path.
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Surface_shortest_words/regular_polygon_surface.h>
#include <CGAL/Curves_on_surface_topology.h>

#include "../Surface_shortest_words/one_vertex_polygon.h"

#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <queue>

namespace SSW = CGAL::Surface_shortest_words;
typedef SSW::Regular_polygon_surface RPS;
typedef RPS::Mesh Mesh;
typedef Mesh::Property_map<RPS::Edge_index, double> Length_map;
typedef SSW::Hyperbolic_surface<Mesh, Length_map> Surface;
typedef SSW::Shortest_word_solver<Mesh, Length_map> Solver;
namespace W = CGAL::Hyperbolic_surface_2::internal;

namespace {

// the surface: the regular 4g-gon surface of Regular_polygon_surface, or (one_vertex) its polygon with all
// corners identified (one vertex, every face using it three times; ../Surface_shortest_words/one_vertex_polygon.h)
struct Setup
{
  RPS S;
  std::unique_ptr<ssw_test::One_vertex_polygon> O;
  const Mesh& mesh;
  Mesh::Vertex_index base;
  Surface s;
  Solver given, computed;
  Solver plain; // the given system without geometry: reads the word of a traced loop
  CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst;
  Setup(int g, bool one_vertex)
    : S(g, 3), O(one_vertex ? new ssw_test::One_vertex_polygon(S) : nullptr), mesh(O ? O->mesh : S.mesh),
      base(O ? O->base : S.base), s(mesh, O ? O->length : S.length),
      given(s, base, O ? O->generators : S.generators), computed(s, base),
      plain(s, base, O ? O->generators : S.generators, SSW::parameters::use_geometry(false)), cst(mesh) {}
};

Setup& setup(int g, bool one_vertex)
{
  static std::map<std::pair<int, bool>, std::unique_ptr<Setup> > m;
  auto& p = m[std::make_pair(g, one_vertex)];
  if(!p) p.reset(new Setup(g, one_vertex));
  return *p;
}

CGAL::Surface_mesh_topology::Path_on_surface<Mesh> pos(const Mesh& m, const std::vector<Mesh::Halfedge_index>& hs)
{
  CGAL::Surface_mesh_topology::Path_on_surface<Mesh> p(m);
  for(auto h : hs) p.push_back(h);
  return p;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1 || size > 4096) return 0;
  const int g = 2 + (data[0] & 1);
  Setup& st = setup(g, (data[0] & 4) != 0);
  const Solver& solver = (data[0] & 2) ? st.computed : st.given;
  const Mesh& m = st.mesh;
  // the word algebra on the raw bytes
  {
    std::vector<int> w;
    for(std::size_t i = 1; i < size; ++i) { const int l = int(data[i] % (2 * g)) + 1; w.push_back((data[i] & 0x80) ? -l : l); }
    const std::vector<int> r = solver.reduce(w);
    std::vector<int> c = r;
    W::append_reduced(c, W::inverse(w));
    if(!W::dehn_reduce(c, solver.relator()).empty() || r.size() > w.size() || solver.reduce(r) != r) std::abort();
    // the statements of the reduction's linear cost proof (Geodesic_word_reducer)
    W::Reduction_statistics rs;
    if(W::Geodesic_word_reducer(solver.relator()).reduce(w, &rs) != r || rs.max_rules_per_input_letter > 1 ||
       rs.max_marks_per_replacement > 1 || rs.work() > W::Reduction_statistics::bound(g, w.size()))
      std::abort();
  }
  // a loop on the mesh
  std::vector<Mesh::Halfedge_index> hs;
  Mesh::Vertex_index v = st.base;
  for(std::size_t i = 1; i < size; ++i) {
    std::vector<Mesh::Halfedge_index> out;
    for(auto h : CGAL::halfedges_around_source(v, m)) out.push_back(h);
    const auto h = out[data[i] % out.size()];
    hs.push_back(h);
    v = m.target(h);
  }
  std::map<Mesh::Vertex_index, Mesh::Halfedge_index> parent;
  std::queue<Mesh::Vertex_index> q; q.push(st.base); parent[st.base] = Mesh::null_halfedge();
  while(!q.empty()) {
    const auto u = q.front(); q.pop();
    for(auto h : CGAL::halfedges_around_source(u, m))
      if(!parent.count(m.target(h))) { parent[m.target(h)] = h; q.push(m.target(h)); }
  }
  std::vector<Mesh::Halfedge_index> back;
  while(v != st.base) { const auto h = parent.at(v); back.push_back(m.opposite(h)); v = m.source(h); }
  hs.insert(hs.end(), back.begin(), back.end());
  if(hs.empty()) return 0;
  const auto res = solver.solve(st.s.path_from_halfedges(hs));
  const bool ok = res.word.empty() ? st.cst.is_contractible(pos(m, hs))
                                   : st.cst.are_base_point_homotopic(pos(m, hs), pos(m, solver.realize(res.word)));
  if(!ok || solver.reduce(res.word) != res.word) std::abort();
  // the traced shortest loop is in the class (a trace that ends at another lift of p changes it): its word in
  // the given system is the element of the input loop's word there
  if(res.used_geometry) {
    const std::vector<int> wl = st.plain.word(res.loop), wi = st.plain.word(st.s.path_from_halfedges(hs));
    std::vector<int> c = wl;
    W::append_reduced(c, W::inverse(wi));
    if(!W::dehn_reduce(c, st.plain.relator()).empty()) std::abort();
    // and it is not longer than the input loop
    if(!(res.length <= st.s.path_length(st.s.path_from_halfedges(hs)) * (1 + 1e-9) + 1e-9)) std::abort();
  }
  return 0;
}
