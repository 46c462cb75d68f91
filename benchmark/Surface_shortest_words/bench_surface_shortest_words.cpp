// Benchmark of Surface_shortest_words against CGAL's homotopy test, on regular-octagon genus-2 surfaces of
// growing size and random loops of growing length.
//
// For each mesh (subdivision m: 8 m^2 faces) and loop length n (random walk from p closed by a shortest
// edge path), it prints one line
//   SSW faces=F edges_in_loop=N word_ms=.. crossing_ms=.. path_ms=.. cgal_ms=.. ratio_word_cgal=.. ...
// word_ms:     Shortest_word_solver::solve with the default options: the exact crossing word of the loop,
//              its geodesic reduction, and the shortest loop through p (Algorithm 2) when the lift fits in
//              double precision;
// exact_ms:    Shortest_word_solver::solve with use_geometry = false: the same word, no shortest loop;
// crossing_ms: the exact crossing word alone (no reduction);
// path_ms:     shortest_homotopic_path on a path of the same number of edges that walks out and back (its
//              lift stays within reach of double precision: measures the linear lifting and tracing);
// free_loop_ms: shortest_homotopic_loop (Algorithm 3) on the loop, when its shortest loop fits in one chart;
// cgal_ms:     CGAL Curves_on_surface_topology::are_base_point_homotopic(loop, word realized on the
//              generators) in the same run (the quadrangulation is built once per mesh, cgal_build_ms).
// word_ms, exact_ms, crossing_ms and cgal_ms are CPU times, the minimum of 5 calls below 10 ms (min_ms()).
// Usage: bench_surface_shortest_words [max_faces = 1000000] [max_loop_edges = 1000000]
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Surface_shortest_words/regular_polygon_surface.h>
#include <CGAL/Curves_on_surface_topology.h>

#include <chrono>
#include <ctime>
#include <cstdlib>
#include <iostream>
#include <queue>
#include <random>

namespace SSW = CGAL::Surface_shortest_words;
typedef SSW::Regular_polygon_surface RPS;
typedef RPS::Mesh Mesh;
typedef Mesh::Property_map<RPS::Edge_index, double> Length_map;
typedef SSW::Hyperbolic_surface<Mesh, Length_map> Surface;
typedef SSW::Shortest_word_solver<Mesh, Length_map> Solver;
typedef CGAL::Surface_mesh_topology::Path_on_surface<Mesh> Path_on_surface;

// CPU time of this (single-threaded) process: the project machine is shared (load average above 10 on 2
// cores), where wall-clock times of a few milliseconds are dominated by preemption
struct Cpu_clock
{
  typedef std::clock_t time_point;
  static time_point now() { return std::clock(); }
};
static double ms_since(Cpu_clock::time_point t0) { return 1000.0 * double(std::clock() - t0) / CLOCKS_PER_SEC; }

// The CPU time of fn(): the minimum over 5 calls when a call takes less than 10 ms (else one call). A single
// call of a short loop is dominated by cache misses on the mesh along the loop, paid by whichever method
// touches it first (measured on 100-edge loops: a first crossing word 0.05-0.07 ms, the same after a solve
// 0.01-0.02 ms); repeating gives every method the same warm caches.
template <class Function>
static double min_ms(const Function& fn)
{
  auto t0 = Cpu_clock::now();
  fn();
  double best = ms_since(t0);
  for(int k = 1; k < 5 && best < 10; ++k) {
    t0 = Cpu_clock::now();
    fn();
    best = (std::min)(best, ms_since(t0));
  }
  return best;
}

int main(int argc, char** argv)
{
  const double max_faces = argc > 1 ? std::atof(argv[1]) : 1e6;
  const double max_edges = argc > 2 ? std::atof(argv[2]) : 1e6;
  std::mt19937 rng(1);
  for(int m : {12, 112, 354}) {
    if(8.0 * m * m > max_faces * 1.01) break;
    auto t0 = Cpu_clock::now();
    RPS S(2, m);
    const double build_ms = ms_since(t0);
    t0 = Cpu_clock::now();
    Surface surface(S.mesh, S.length);
    Solver solver(surface, S.base, S.generators);
    const double solver_ms = ms_since(t0);
    Solver exact(surface, S.base, S.generators,
                 SSW::parameters::use_geometry(false, SSW::parameters::shorten_generators(false)));
    t0 = Cpu_clock::now();
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
    {
      // force the construction of CGAL's minimal quadrangulation
      Path_on_surface tiny(S.mesh); tiny.push_back(S.generators[0][0]);
      Path_on_surface gen(S.mesh); for(auto h : S.generators[0]) gen.push_back(h);
      (void)cst.is_contractible(gen);
    }
    const double cgal_build_ms = ms_since(t0);
    std::cout << "SSW_MESH faces=" << num_faces(S.mesh) << " build_ms=" << build_ms << " solver_setup_ms=" << solver_ms
              << " cgal_build_ms=" << cgal_build_ms << std::endl;
    // BFS tree from p (to close random walks)
    std::vector<Mesh::Halfedge_index> parent(num_vertices(S.mesh), Mesh::null_halfedge());
    {
      std::vector<bool> seen(num_vertices(S.mesh), false);
      std::queue<Mesh::Vertex_index> q; q.push(S.base); seen[S.base] = true;
      while(!q.empty()) {
        auto u = q.front(); q.pop();
        for(auto h : CGAL::halfedges_around_source(u, S.mesh))
          if(!seen[S.mesh.target(h)]) { seen[S.mesh.target(h)] = true; parent[S.mesh.target(h)] = h; q.push(S.mesh.target(h)); }
      }
    }
    for(double n = 100; n <= max_edges * 1.01; n *= 10) {
      std::vector<Mesh::Halfedge_index> hs;
      Mesh::Vertex_index v = S.base;
      for(std::size_t i = 0; i < std::size_t(n); ++i) {
        std::vector<Mesh::Halfedge_index> out;
        for(auto h : CGAL::halfedges_around_source(v, S.mesh)) out.push_back(h);
        hs.push_back(out[rng() % out.size()]);
        v = S.mesh.target(hs.back());
      }
      std::vector<Mesh::Halfedge_index> back;
      while(v != S.base) { auto h = parent[v]; back.push_back(S.mesh.opposite(h)); v = S.mesh.source(h); }
      hs.insert(hs.end(), back.begin(), back.end());
      const Surface::Path loop = surface.path_from_halfedges(hs);

      SSW::Word_result<Mesh> res, exact_res;
      const double word_ms = min_ms([&] { res = solver.solve(loop); });
      const double exact_ms = min_ms([&] { exact_res = exact.solve(loop); });
      SSW::Word raw;
      const double crossing_ms = min_ms([&] { raw = solver.crossing_word(loop); });
      const SSW::Word reduced = SSW::internal::dehn_reduce(raw, solver.relator());

      // out-and-back path of about n edges: half a random walk, then back along it, then one more edge
      std::vector<Mesh::Halfedge_index> ob(hs.begin(), hs.begin() + std::ptrdiff_t(hs.size() / 2));
      for(std::size_t i = ob.size(); i-- > 0;) ob.push_back(S.mesh.opposite(ob[i]));
      ob.push_back(hs.front());
      const Surface::Path out_back = surface.path_from_halfedges(ob);
      t0 = Cpu_clock::now();
      double path_len = -1;
      std::size_t faces_met = 0;
      try {
        const auto sp = SSW::shortest_homotopic_path(surface, out_back);
        path_len = sp.length; faces_met = sp.embedded_faces;
      } catch(const SSW::Precision_error&) {}
      const double path_ms = ms_since(t0);

      // Algorithm 3 (free shortest loop) when the loop is short enough for one chart
      double loop_ms = -1, loop_length = -1; std::size_t loop_iterations = 0;
      if(res.used_geometry && !res.word.empty() && res.length < 0.9 * SSW::Shortest_path_options().max_lift_distance) {
        t0 = Cpu_clock::now();
        const auto fl = SSW::shortest_homotopic_loop(surface, loop);
        loop_ms = ms_since(t0); loop_length = fl.length; loop_iterations = fl.iterations;
      }

      Path_on_surface p1(S.mesh), p2(S.mesh);
      for(auto h : hs) p1.push_back(h);
      for(auto h : solver.realize(res.word)) p2.push_back(h);
      bool same = false;
      const double cgal_ms = min_ms([&] { same = res.word.empty() ? cst.is_contractible(p1) : cst.are_base_point_homotopic(p1, p2); });
      std::cout << "SSW faces=" << num_faces(S.mesh) << " edges_in_loop=" << hs.size() << " word_ms=" << word_ms
                << " exact_ms=" << exact_ms << " crossing_ms=" << crossing_ms << " path_ms=" << path_ms << " cgal_ms=" << cgal_ms
                << " ratio_word_cgal=" << word_ms / cgal_ms << " ratio_exact_cgal=" << exact_ms / cgal_ms
                << " ratio_crossing_cgal=" << crossing_ms / cgal_ms << " same_word=" << (exact_res.word == res.word)
                << " geometric=" << res.used_geometry << " shortest_loop_length=" << res.length << " word_length=" << res.word.size()
                << " raw_word_length=" << raw.size() << " dehn_of_input_length=" << reduced.size()
                << " cgal_agrees=" << same << " path_faces=" << faces_met << " path_length=" << path_len
                << " free_loop_ms=" << loop_ms << " free_loop_length=" << loop_length << " free_loop_iterations=" << loop_iterations << std::endl;
    }
  }
  return EXIT_SUCCESS;
}
