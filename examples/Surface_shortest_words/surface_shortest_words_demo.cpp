// Demo of Surface_shortest_words on a bundled genus-2 surface (the regular hyperbolic octagon with its
// sides glued by a1 b1 a1^-1 b1^-1 a2 b2 a2^-1 b2^-1, triangulated geodesically):
//  - the canonical system of loops (the octagon's sides) is checked and shortened (Algorithm 2),
//  - a random loop through the base point is shortened (Algorithm 2) and its word computed (Algorithm 4),
//  - its free shortest loop (Algorithm 3) is computed,
//  - the picture surface_shortest_words_demo.svg shows the lift of the shortest loop in the Poincare disk,
//    the tiling by lifts of the fundamental octagon and the generators;
//  - on eight.off with the Ricci flow metric (if that package is present): the canonical system of shortest
//    geodesic loops through p (thesis Theorem 2.6) and the fundamental polygon they bound, drawn in
//    CGAL_HC_OUTPUT_DIR/geodesic_fundamental_polygon_eight.svg with its neighbouring translates; the loops
//    inserted into a triangulation of the surface as chains of edges and the fundamental polygon as the
//    faces of the cut surface, drawn in CGAL_HC_OUTPUT_DIR/geodesic_polygon_triangulation_eight.svg.
// Usage: surface_shortest_words_demo [loop_steps] [seed]
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Surface_shortest_words/geodesic_canonical_system.h>
#if __has_include(<CGAL/Discrete_Ricci_flow.h>)
#include <CGAL/Surface_shortest_words/geodesic_system_triangulation.h>
#endif
#include <CGAL/Surface_shortest_words/regular_polygon_surface.h>
#include <CGAL/IO/Poincare_disk_svg.h>
#include <CGAL/Poincare_disk_traits_2.h>
#if __has_include(<CGAL/Discrete_Ricci_flow.h>)
#include <CGAL/Discrete_Ricci_flow.h>
#define SSW_DEMO_RICCI_FLOW 1
#endif

#include <cstdlib>
#include <iostream>
#include <map>
#include <queue>
#include <random>
#include <set>

namespace SSW = CGAL::Surface_shortest_words;
typedef SSW::Regular_polygon_surface RPS;
typedef RPS::Mesh Mesh;
typedef Mesh::Property_map<RPS::Edge_index, double> Length_map;
typedef SSW::Hyperbolic_surface<Mesh, Length_map> Surface;
typedef SSW::Shortest_word_solver<Mesh, Length_map> Solver;
typedef RPS::Isometry Isometry;
typedef RPS::Cplx Cplx;
typedef CGAL::Epick::Point_2 Point_2;

// the pictures use the public Poincare-disk types only: points as std::complex for drawing, isometries as
// CGAL::Poincare_disk_isometry_2, the hyperbolic midpoint of Poincare_disk_traits_2
static Point_2 to_point(const Cplx& z) { return Point_2(z.real(), z.imag()); }
static Cplx to_cplx(const Point_2& p) { return Cplx(p.x(), p.y()); }
static Cplx image(const Isometry& t, const Cplx& z) { return to_cplx(t(to_point(z))); }
// the view centred at the hyperbolic midpoint of a and b
static Isometry view_between(const Cplx& a, const Cplx& b)
{
  const CGAL::Poincare_disk_traits_2<CGAL::Epick> disk;
  return Isometry::translation_to_origin(disk.construct_hyperbolic_midpoint_2_object()(to_point(a), to_point(b)));
}

int main(int argc, char** argv)
{
  const std::size_t steps = argc > 1 ? std::size_t(std::atol(argv[1])) : 150;
  const unsigned seed = argc > 2 ? unsigned(std::atol(argv[2])) : 3;
  try {
    RPS S(2, 6);
    Surface surface(S.mesh, S.length);
    std::cout << "surface: genus " << surface.genus() << ", " << num_faces(S.mesh) << " faces, max |angle sum - 2pi| = "
              << surface.max_angle_defect() << "\n";
    Solver solver(surface, S.base, S.generators);
    std::cout << "canonical system: relator " << SSW::to_string(solver.relator()) << "\n";
    for(int i = 0; i < 4; ++i)
      std::cout << "  generator " << SSW::to_string(SSW::Word{i + 1}) << ": " << S.generators[std::size_t(i)].size()
                << " edges, shortest loop through p has length " << solver.shortened_generator_length(std::size_t(i)) << "\n";

    // a random loop through p: a random walk, closed by a shortest edge path back to p
    std::mt19937 rng(seed);
    std::vector<Mesh::Halfedge_index> hs;
    Mesh::Vertex_index v = S.base;
    for(std::size_t i = 0; i < steps; ++i) {
      std::vector<Mesh::Halfedge_index> out;
      for(auto h : CGAL::halfedges_around_source(v, S.mesh)) out.push_back(h);
      hs.push_back(out[rng() % out.size()]);
      v = S.mesh.target(hs.back());
    }
    std::map<Mesh::Vertex_index, Mesh::Halfedge_index> parent;
    std::queue<Mesh::Vertex_index> q; q.push(S.base); parent[S.base] = Mesh::null_halfedge();
    while(!q.empty()) {
      auto u = q.front(); q.pop();
      for(auto h : CGAL::halfedges_around_source(u, S.mesh))
        if(!parent.count(S.mesh.target(h))) { parent[S.mesh.target(h)] = h; q.push(S.mesh.target(h)); }
    }
    std::vector<Mesh::Halfedge_index> back;
    while(v != S.base) { auto h = parent[v]; back.push_back(S.mesh.opposite(h)); v = S.mesh.source(h); }
    hs.insert(hs.end(), back.begin(), back.end());
    const Surface::Path loop = surface.path_from_halfedges(hs);

    const auto res = solver.solve(loop);
    std::cout << "random loop: " << hs.size() << " edges, length " << surface.path_length(loop) << "\n";
    std::cout << "shortest loop through p: length " << res.length << ", " << res.loop.size() << " points"
              << (res.used_geometry ? "" : " (too long for the geometric step: crossings of the input loop)") << "\n";
    std::cout << "word read from the crossings: " << SSW::to_string(res.crossing_word) << "\n";
    std::cout << "shortest word: " << SSW::to_string(res.word) << "  (length " << res.word.size() << ")\n";
    std::cout << "CGAL labels:";
    for(const std::string& l : SSW::to_labels(res.word)) std::cout << " " << l;
    std::cout << "\n";
    if(!res.word.empty()) {
      const auto free_loop = SSW::shortest_homotopic_loop(surface, loop);
      std::cout << "shortest freely homotopic loop: length " << free_loop.length << " after " << free_loop.iterations
                << " re-basing iterations (" << (free_loop.converged ? "converged" : "not converged") << ")\n";
    }

    // picture, centred at the midpoint of the lifted shortest loop: tiles rho(x) P near the loop, the word's
    // path along generator lifts (coloured by generator), the lifted shortest loop (black)
    std::vector<Isometry> prefixes{Isometry()};
    for(int l : res.word) {
      const Isometry& g = S.rho_generator(std::abs(l) - 1);
      prefixes.push_back((prefixes.back() * (l > 0 ? g : g.inverse())).normalized());
    }
    const Cplx start = S.polygon[0], end = image(prefixes.back(), start);
    const Isometry view = view_between(start, end);
    auto V = [&](const Cplx& z) { return image(view, z); };
    CGAL::Poincare_disk_svg_writer svg(900);
    svg.add_unit_circle();
    std::vector<Isometry> tiles;
    std::set<std::pair<long long, long long> > seen;
    auto add_tile = [&](const Isometry& t) {
      const Cplx c = V(image(t, Cplx(0, 0)));
      if(seen.insert(std::make_pair(std::llround(c.real() * 1e5), std::llround(c.imag() * 1e5))).second) tiles.push_back(t);
    };
    for(const Isometry& pre : prefixes) {
      std::vector<Isometry> ball{pre};
      for(int r = 0; r < 2; ++r) {
        const std::size_t n = ball.size();
        for(std::size_t i = 0; i < n; ++i)
          for(int l = -4; l <= 4; ++l)
            if(l != 0) {
              const Isometry& g = S.rho_generator(std::abs(l) - 1);
              ball.push_back((ball[i] * (l > 0 ? g : g.inverse())).normalized());
            }
      }
      for(const Isometry& t : ball) add_tile(t);
    }
    for(const Isometry& t : tiles) {
      std::vector<double> xy;
      for(const Cplx& z : S.polygon) { const Cplx w = V(image(t, z)); xy.push_back(w.real()); xy.push_back(w.imag()); }
      svg.add_geodesic_polygon(xy, "none", "#bbbbbb", 0.6);
    }
    const char* colours[4] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd"};
    for(std::size_t i = 0; i < res.word.size(); ++i) {
      const Cplx a = V(image(prefixes[i], start)), b = V(image(prefixes[i + 1], start));
      svg.add_geodesic_segment(a.real(), a.imag(), b.real(), b.imag(), colours[std::abs(res.word[i]) - 1], 3.0);
    }
    const Cplx vs = V(start), ve = V(end);
    svg.add_geodesic_segment(vs.real(), vs.imag(), ve.real(), ve.imag(), "#000000", 2.0);
    svg.add_point(vs.real(), vs.imag(), "#000", 4);
    svg.add_point(ve.real(), ve.imag(), "#000", 4);
    svg.add_text(20, 30, "shortest word: " + SSW::to_string(res.word), 18);
    svg.add_text(20, 55, "black: lift of the shortest loop through p; colours: the word along lifts of", 14);
    svg.add_text(20, 75, "a1 (red), b1 (blue), a2 (green), b2 (purple); grey: lifts of the fundamental octagon", 14);
    svg.write("surface_shortest_words_demo.svg");
    std::cout << "wrote surface_shortest_words_demo.svg\n";

#ifdef SSW_DEMO_RICCI_FLOW
    // CGAL's eight.off with the hyperbolic metric of the Ricci flow and a computed canonical system
    {
      typedef CGAL::Ricci_flow::Discrete_metric<CGAL::Epick::Point_3> Metric;
      typedef Metric::Mesh IMesh;
      IMesh input;
      const std::string file = std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/eight.off";
      if(!CGAL::IO::read_polygon_mesh(file, input)) throw std::runtime_error("cannot read " + file);
      const Metric metric = CGAL::Ricci_flow::hyperbolic_uniformization(input);
      const IMesh& m = metric.intrinsic_mesh();
      SSW::Hyperbolic_surface<IMesh, Metric::Edge_length_map> s8(m, metric.edge_length_map());
      const IMesh::Vertex_index p8(0);
      SSW::Shortest_word_solver<IMesh, Metric::Edge_length_map> solver8(s8, p8);
      std::cout << "\neight.off (" << num_faces(m) << " faces, Ricci flow metric, max |angle sum - 2pi| = "
                << s8.max_angle_defect() << "): computed canonical system, generator lengths";
      for(int i = 0; i < 4; ++i) std::cout << " " << solver8.shortened_generator_length(std::size_t(i));
      std::cout << "\n";
      std::vector<IMesh::Halfedge_index> walk;
      IMesh::Vertex_index u = p8;
      for(std::size_t i = 0; i < 100; ++i) {
        std::vector<IMesh::Halfedge_index> out;
        for(auto h : CGAL::halfedges_around_source(u, m)) out.push_back(h);
        walk.push_back(out[rng() % out.size()]);
        u = m.target(walk.back());
      }
      std::map<IMesh::Vertex_index, IMesh::Halfedge_index> par;
      std::queue<IMesh::Vertex_index> qq; qq.push(p8); par[p8] = IMesh::null_halfedge();
      while(!qq.empty()) {
        auto x = qq.front(); qq.pop();
        for(auto h : CGAL::halfedges_around_source(x, m))
          if(!par.count(m.target(h))) { par[m.target(h)] = h; qq.push(m.target(h)); }
      }
      while(u != p8) { auto h = par[u]; walk.push_back(m.opposite(h)); u = m.source(h); }
      const auto r8 = solver8.solve(s8.path_from_halfedges(walk));
      std::cout << "random loop of " << walk.size() << " edges: shortest loop through p " << r8.length
                << ", word " << solver8.word_to_string(r8.word) << "\n";

      // Theorem 2.6: the shortest geodesic loops of the canonical system and their fundamental polygon
      const auto sys = SSW::geodesic_canonical_system(solver8);
      const SSW::Geodesic_system_report rep = SSW::check_geodesic_system(s8, p8, sys.loops);
      std::cout << "geodesic canonical system: lengths";
      for(double l : sys.lengths) std::cout << " " << l;
      std::cout << "; simple and disjoint except at p: " << (rep.simple_and_disjoint ? "yes" : "NO")
                << ", min angle at interior points " << rep.min_side_angle << "; polygon angle sum " << sys.angle_sum
                << " (2 pi), area " << sys.area << " (4 pi (g-1) = " << 4 * CGAL_PI << ")\n";
      CGAL::Poincare_disk_svg_writer psvg(900);
      psvg.add_unit_circle();
      // view centred at the midpoint of the diagonal P_0 P_2g
      const Isometry pview = view_between(to_cplx(sys.polygon[0]), to_cplx(sys.polygon[sys.polygon.size() / 2]));
      auto polygon_xy = [&](const Isometry& t) {
        std::vector<double> xy;
        for(const auto& z : sys.polygon) {
          const Cplx w = to_cplx((pview * t)(z));
          xy.push_back(w.real()); xy.push_back(w.imag());
        }
        return xy;
      };
      for(int a = -4; a <= 4; ++a)
        for(int b = -4; b <= 4; ++b) {
          if(a == 0) continue;
          if(b == -a) continue;
          Isometry t = a > 0 ? solver8.deck_transformation(std::size_t(a - 1)) : solver8.deck_transformation(std::size_t(-a - 1)).inverse();
          if(b != 0) t = t * (b > 0 ? solver8.deck_transformation(std::size_t(b - 1)) : solver8.deck_transformation(std::size_t(-b - 1)).inverse());
          psvg.add_geodesic_polygon(polygon_xy(t.normalized()), "none", "#bbbbbb", 0.6);
        }
      psvg.add_geodesic_polygon(polygon_xy(Isometry()), "#fff3d6", "#000000", 0.8);
      const char* side_colours[4] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd"};
      for(std::size_t k = 0; k < sys.polygon.size(); ++k) {
        const Cplx z0 = to_cplx(pview(sys.polygon[k]));
        const Cplx z1 = to_cplx(pview(sys.polygon[(k + 1) % sys.polygon.size()]));
        psvg.add_geodesic_segment(z0.real(), z0.imag(), z1.real(), z1.imag(), side_colours[std::abs(sys.relator[k]) - 1], 3.0);
      }
      for(const auto& z : sys.polygon) {
        const Cplx w = to_cplx(pview(z));
        psvg.add_point(w.real(), w.imag(), "#000", 3);
      }
      psvg.add_text(20, 30, "eight.off (Ricci flow): fundamental polygon bounded by the shortest geodesic loops", 16);
      psvg.add_text(20, 52, "a1 (red), b1 (blue), a2 (green), b2 (purple); black: the lifts of p; grey: translates", 14);
      const std::string svg_file = std::string(CGAL_HC_OUTPUT_DIR) + "/geodesic_fundamental_polygon_eight.svg";
      psvg.write(svg_file);
      std::cout << "wrote " << svg_file << "\n";

      // the loops as edges of a triangulation of the surface, the polygon as the faces of the cut surface
      const SSW::Geodesic_system_triangulation gt = SSW::geodesic_system_triangulation(s8, solver8, sys);
      const auto& tr = gt.triangulation;
      std::cout << "loops inserted as edges: " << tr.number_of_faces() << " faces (" << gt.vertices_inserted
                << " vertices inserted); chain edges / lengths:";
      for(std::size_t i = 0; i < gt.loop_edges.size(); ++i) std::cout << " " << gt.loop_edges[i].size() << " / " << gt.loop_lengths[i];
      std::cout << "; cut surface V-E+F = " << gt.cut_euler_characteristic << ", boundary word "
                << SSW::to_string(gt.boundary_word) << "\n";
      std::map<std::pair<std::size_t, int>, std::size_t> loop_of; // edge (either side) -> loop
      for(std::size_t i = 0; i < gt.loop_edges.size(); ++i)
        for(const auto& e : gt.loop_edges[i]) {
          loop_of[e] = i;
          loop_of[std::make_pair(tr.neighbor(e.first, e.second), tr.mirror_index(e.first, e.second))] = i;
        }
      CGAL::Poincare_disk_svg_writer tsvg(900);
      tsvg.add_unit_circle();
      auto V = [&](const Point_2& z) { return to_cplx(pview(z)); };
      for(const auto& z : gt.polygon_face_points) {
        std::vector<double> xy;
        for(int c = 0; c < 3; ++c) { const Cplx w = V(z[c]); xy.push_back(w.real()); xy.push_back(w.imag()); }
        tsvg.add_geodesic_polygon(xy, "#fff3d6", "#999999", 0.3);
      }
      for(std::size_t k = 0; k < gt.polygon_faces.size(); ++k)
        for(int c = 0; c < 3; ++c) {
          const auto it = loop_of.find(std::make_pair(gt.polygon_faces[k], c));
          if(it == loop_of.end()) continue;
          const Cplx z0 = V(gt.polygon_face_points[k][c]), z1 = V(gt.polygon_face_points[k][(c + 1) % 3]);
          tsvg.add_geodesic_segment(z0.real(), z0.imag(), z1.real(), z1.imag(), side_colours[it->second], 2.5);
        }
      for(const auto& z : sys.polygon) { const Cplx w = V(z); tsvg.add_point(w.real(), w.imag(), "#000", 3); }
      tsvg.add_text(20, 30, "eight.off (Ricci flow): the shortest geodesic loops as edges of the surface triangulation", 16);
      tsvg.add_text(20, 52, "the faces of the surface cut along them: the fundamental polygon; a1 red, b1 blue, a2 green, b2 purple", 14);
      const std::string tsvg_file = std::string(CGAL_HC_OUTPUT_DIR) + "/geodesic_polygon_triangulation_eight.svg";
      tsvg.write(tsvg_file);
      std::cout << "wrote " << tsvg_file << "\n";
    }
#endif
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
