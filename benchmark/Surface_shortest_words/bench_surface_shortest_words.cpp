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
// based_loop_ms: shortest_loop_through_base on the loop (Algorithm 2 on the path, chart chaining; one call);
// free_loop_ms: shortest_homotopic_loop (Algorithm 3) on the loop (one call);
// cgal_ms:     CGAL Curves_on_surface_topology::are_base_point_homotopic(loop, word realized on the
//              generators) in the same run (the quadrangulation is built once per mesh, cgal_build_ms).
// word_ms, exact_ms, crossing_ms and cgal_ms are CPU times, each the minimum over several calls after a warm-up
// call of every method, the four methods called in interleaved, rotated order (interleaved_min_ms()).
// Usage: bench_surface_shortest_words [max_faces = 1000000] [max_loop_edges = 1000000]
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Surface_shortest_words/regular_polygon_surface.h>
#include <CGAL/Curves_on_surface_topology.h>

#include <chrono>
#include <ctime>
#include <cstdlib>
#include <functional>
#include <limits>
#include <vector>
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

// The CPU times of several methods on the same input, each the minimum over several calls, the calls
// interleaved: one warm-up call of every method first (a single call of a short loop is dominated by cache
// misses on the mesh along the loop, paid by whichever method touches it first: measured on 100-edge loops, a
// first crossing word 0.05-0.07 ms, the same after a solve 0.01-0.02 ms), then rounds in which every method is
// called once, the order rotated from round to round (so that no method always runs right after another one
// or first). 9 rounds when the slowest warm-up call took less than 10 ms, 5 below 100 ms, else 3.
static std::vector<double> interleaved_min_ms(const std::vector<std::function<void()> >& fns)
{
  std::vector<double> best(fns.size(), std::numeric_limits<double>::infinity());
  double slowest = 0;
  for(std::size_t i = 0; i < fns.size(); ++i) {
    const auto t0 = Cpu_clock::now();
    fns[i]();
    slowest = (std::max)(slowest, ms_since(t0));
  }
  const int rounds = slowest < 10 ? 9 : (slowest < 100 ? 5 : 3);
  for(int r = 0; r < rounds; ++r)
    for(std::size_t j = 0; j < fns.size(); ++j) {
      const std::size_t i = (j + std::size_t(r)) % fns.size();
      const auto t0 = Cpu_clock::now();
      fns[i]();
      best[i] = (std::min)(best[i], ms_since(t0));
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
      SSW::Word raw;
      Path_on_surface p1(S.mesh), p2(S.mesh);
      for(auto h : hs) p1.push_back(h);
      res = solver.solve(loop);
      for(auto h : solver.realize(res.word)) p2.push_back(h);
      bool same = false;
      const std::vector<double> ms = interleaved_min_ms({
        [&] { res = solver.solve(loop); },
        [&] { exact_res = exact.solve(loop); },
        [&] { raw = solver.crossing_word(loop); },
        [&] { same = res.word.empty() ? cst.is_contractible(p1) : cst.are_base_point_homotopic(p1, p2); }});
      const double word_ms = ms[0], exact_ms = ms[1], crossing_ms = ms[2], cgal_ms = ms[3];
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

      // Algorithm 2 on the loop itself (no word: the path lifted by chart chaining), and Algorithm 3
      t0 = Cpu_clock::now();
      double based_length = -1;
      try { based_length = SSW::shortest_loop_through_base(surface, loop).length; } catch(const SSW::Precision_error&) {}
      const double based_ms = ms_since(t0);
      double loop_ms = -1, loop_length = -1; std::size_t loop_iterations = 0; bool loop_converged = false;
      if(!res.word.empty()) {
        t0 = Cpu_clock::now();
        try {
          const auto fl = SSW::shortest_homotopic_loop(surface, loop);
          loop_length = fl.length; loop_iterations = fl.iterations; loop_converged = fl.converged;
        } catch(const SSW::Precision_error&) {}
        loop_ms = ms_since(t0);
      }

      std::cout << "SSW faces=" << num_faces(S.mesh) << " edges_in_loop=" << hs.size() << " word_ms=" << word_ms
                << " exact_ms=" << exact_ms << " crossing_ms=" << crossing_ms << " path_ms=" << path_ms << " cgal_ms=" << cgal_ms
                << " ratio_word_cgal=" << word_ms / cgal_ms << " ratio_exact_cgal=" << exact_ms / cgal_ms
                << " ratio_crossing_cgal=" << crossing_ms / cgal_ms << " same_word=" << (exact_res.word == res.word)
                << " geometric=" << res.used_geometry << " shortest_loop_length=" << res.length << " word_length=" << res.word.size()
                << " raw_word_length=" << raw.size() << " dehn_of_input_length=" << reduced.size()
                << " cgal_agrees=" << same << " path_faces=" << faces_met << " path_length=" << path_len
                << " based_loop_ms=" << based_ms << " based_loop_length=" << based_length << " free_loop_ms=" << loop_ms << " free_loop_length=" << loop_length << " free_loop_iterations=" << loop_iterations << " free_loop_converged=" << loop_converged << std::endl;
    }
  }
  return EXIT_SUCCESS;
}
