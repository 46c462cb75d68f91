// Tests of Surface_shortest_words. Independent references:
//  - the regular 4g-gon surfaces have an exactly known geometry: positions of the polygon in the Poincare
//    disk and the side-pairing isometries (holonomy rho), computed from the polygon only;
//  - CGAL's Curves_on_surface_topology (are_base_point_homotopic, is_contractible) decides homotopy;
//  - shortest word lengths by breadth-first search in the Cayley graph, elements compared through the
//    quadruple-precision holonomy of fuchsian_reference.h.
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Surface_shortest_words/regular_polygon_surface.h>
#include <CGAL/Curves_on_surface_topology.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <boost/property_map/property_map.hpp>

#include "cgal_hc_test.h"
#include "fuchsian_reference.h"
#include "ssw_test_loops.h"

#include <cmath>
#include <map>
#include <queue>
#include <memory>
#include <random>

namespace SSW = CGAL::Surface_shortest_words;
typedef SSW::Regular_polygon_surface RPS;
typedef RPS::Mesh Mesh;
typedef Mesh::Property_map<RPS::Edge_index, double> Length_map;
typedef SSW::Hyperbolic_surface<Mesh, Length_map> Surface;
typedef SSW::Shortest_word_solver<Mesh, Length_map> Solver;
typedef Surface::Path Path;
typedef Surface::Point SPoint;
typedef RPS::Isometry Isometry;
typedef RPS::Cplx Cplx;
typedef CGAL::Surface_mesh_topology::Path_on_surface<Mesh> Path_on_surface;

namespace {

Cplx apply_iso(const Isometry& f, const Cplx& z) { return SSW::internal::apply_isometry(f, z); }
double dist(const Cplx& a, const Cplx& b) { return SSW::internal::hyperbolic_distance(a, b); }

Isometry rho_word(const RPS& S, const SSW::Word& w)
{
  Isometry r;
  for(int l : w) {
    const Isometry& g = S.rho_generator(std::abs(l) - 1);
    r = (r * (l > 0 ? g : g.inverse())).normalized();
  }
  return r;
}

Path vertex_path(const Surface& s, const std::vector<Mesh::Halfedge_index>& hs) { return s.path_from_halfedges(hs); }

Path_on_surface pos(const Mesh& m, const std::vector<Mesh::Halfedge_index>& hs)
{
  Path_on_surface p(m);
  for(auto h : hs) p.push_back(h);
  return p;
}

std::vector<Mesh::Halfedge_index> random_loop(const Mesh& m, Mesh::Vertex_index base, std::size_t len, std::mt19937& rng)
{
  return ssw_test::random_loop(m, base, len, rng);
}

std::vector<Mesh::Halfedge_index> realize(const RPS& S, const SSW::Word& w)
{
  std::vector<Mesh::Halfedge_index> r;
  for(int l : w) {
    const auto& g = S.generators[std::size_t(std::abs(l) - 1)];
    if(l > 0) r.insert(r.end(), g.begin(), g.end());
    else for(auto it = g.rbegin(); it != g.rend(); ++it) r.push_back(S.mesh.opposite(*it));
  }
  return r;
}

SSW::Word random_word(int g, int length, std::mt19937& rng)
{
  SSW::Word w;
  while(int(w.size()) < length) {
    int l = int(rng() % (2 * g)) + 1;
    if(rng() % 2) l = -l;
    if(!w.empty() && w.back() == -l) continue;
    w.push_back(l);
  }
  return w;
}

} // namespace

CGAL_HC_TEST_CASE(regular_polygon_surfaces_are_hyperbolic)
{
  for(int g : {2, 3}) {
    RPS S(g, 4);
    Surface s(S.mesh, S.length);
    CGAL_HC_CHECK(s.genus() == g);
    CGAL_HC_CHECK_MSG(s.max_angle_defect() < 1e-10, s.max_angle_defect());
    // total area: sum of the angle defects pi - (alpha + beta + gamma) = 4 pi (g - 1) (Gauss-Bonnet)
    double area = 0;
    for(auto f : faces(S.mesh)) {
      auto h = S.mesh.halfedge(f);
      area += CGAL_PI - s.angle_at_target(h) - s.angle_at_target(S.mesh.next(h)) - s.angle_at_target(S.mesh.prev(h));
    }
    CGAL_HC_CHECK_MSG(std::abs(area - 4 * CGAL_PI * (g - 1)) < 1e-9, area);
    // the holonomy: rho(s_1 ... s_4g) = identity, rho(a1) V_0 = V_1, generators hyperbolic
    SSW::Word rel;
    for(int i = 0; i < g; ++i) { rel.push_back(2 * i + 1); rel.push_back(2 * i + 2); rel.push_back(-(2 * i + 1)); rel.push_back(-(2 * i + 2)); }
    CGAL_HC_CHECK(rho_word(S, rel).distance_to(Isometry()) < 1e-9);
    CGAL_HC_CHECK(std::abs(apply_iso(S.rho_generator(0), S.polygon[0]) - S.polygon[1]) < 1e-12);
    CGAL_HC_CHECK(std::abs(apply_iso(S.rho_generator(1), S.polygon[0]) - S.polygon[1]) > 1e-3);
    for(int i = 0; i < 2 * g; ++i) CGAL_HC_CHECK(S.rho_generator(i).half_trace() > 1);
    // the pairing of sides k and k+2 is the product of the reflections in side k and in a diameter at angle
    // pi/2g from the side's perpendicular: cosh(l/2) = cosh(inradius) sin(pi/2g) = 2 cos^2(pi/4g)
    for(int i = 0; i < 2 * g; ++i)
      CGAL_HC_CHECK(std::abs(S.rho_generator(i).half_trace() - 2 * std::pow(std::cos(CGAL_PI / (4 * g)), 2)) < 1e-9);
  }
}

CGAL_HC_TEST_CASE(bad_metrics_throw)
{
  RPS S(2, 3);
  { Surface s(S.mesh, S.length); CGAL_HC_CHECK(s.genus() == 2); }
  Mesh m = S.mesh;
  auto len = m.property_map<RPS::Edge_index, double>("e:hyperbolic_length").first;
  auto e0 = *edges(m).begin();
  const double l0 = len[e0];
  len[e0] = l0 * 1.01; // angle sums change: not hyperbolic any more
  CGAL_HC_CHECK_THROWS(Surface(m, len), SSW::Invalid_metric_error);
  len[e0] = 100.0;     // triangle inequality violated
  CGAL_HC_CHECK_THROWS(Surface(m, len), SSW::Invalid_metric_error);
  len[e0] = l0;
  CGAL_HC_CHECK(Surface(m, len).genus() == 2);
  // an open mesh
  Mesh open = S.mesh;
  open.remove_face(*faces(open).begin());
  open.collect_garbage();
  auto len2 = open.property_map<RPS::Edge_index, double>("e:hyperbolic_length").first;
  // (the layer's exception for a mesh that is not a closed surface, the same in every package)
  CGAL_HC_CHECK_THROWS(Surface(open, len2), CGAL::Invalid_mesh_error);
}

CGAL_HC_TEST_CASE(shortest_path_inside_the_polygon_is_the_hyperbolic_segment)
{
  RPS S(2, 6);
  Surface s(S.mesh, S.length);
  std::mt19937 rng(7);
  // interior vertices (not on the polygon boundary) have a unique position; a path through them stays in
  // the polygon, which is simply connected, so its homotopy class contains the hyperbolic segment
  std::vector<Mesh::Vertex_index> interior;
  for(auto v : vertices(S.mesh)) {
    const auto& p = S.mesh.point(v);
    const Cplx z(p.x(), p.y());
    bool boundary = false;
    for(auto h : CGAL::halfedges_around_target(v, S.mesh)) {
      const auto& q = S.mesh.point(S.mesh.source(h));
      if(dist(z, Cplx(q.x(), q.y())) > 3 * s.length(h)) boundary = true; // neighbour copied elsewhere
    }
    if(v != S.base && !boundary && std::abs(z) < 0.6) interior.push_back(v);
  }
  CGAL_HC_CHECK(interior.size() > 10);
  int tested = 0;
  for(int trial = 0; trial < 30; ++trial) {
    Path path;
    Mesh::Vertex_index v = interior[rng() % interior.size()];
    path.push_back(SPoint::vertex(v));
    for(int k = 0; k < 12; ++k) {
      std::vector<Mesh::Vertex_index> nb;
      for(auto h : CGAL::halfedges_around_source(v, S.mesh))
        if(std::find(interior.begin(), interior.end(), S.mesh.target(h)) != interior.end()) nb.push_back(S.mesh.target(h));
      if(nb.empty()) break;
      v = nb[rng() % nb.size()];
      path.push_back(SPoint::vertex(v));
    }
    const auto& a = S.mesh.point(path.front().v); const auto& b = S.mesh.point(path.back().v);
    const double expected = dist(Cplx(a.x(), a.y()), Cplx(b.x(), b.y()));
    auto r = SSW::shortest_homotopic_path(s, path);
    CGAL_HC_CHECK_MSG(std::abs(r.length - expected) < 1e-9, r.length << " vs " << expected);
    CGAL_HC_CHECK(std::abs(s.path_length(r.path) - r.length) < 1e-9);
    CGAL_HC_CHECK(r.length <= s.path_length(path) + 1e-12);
    CGAL_HC_CHECK(s.same_point(r.path.front(), path.front()) && s.same_point(r.path.back(), path.back()));
    ++tested;
  }
  CGAL_HC_CHECK(tested == 30);
}

CGAL_HC_TEST_CASE(shortest_loops_match_the_holonomy)
{
  for(int g : {2, 3}) {
    RPS S(g, 4);
    Surface s(S.mesh, S.length);
    std::mt19937 rng(11 + g);
    for(int trial = 0; trial < 12; ++trial) {
      const SSW::Word w = random_word(g, 1 + trial % 4, rng);
      const Path loop = vertex_path(s, realize(S, w));
      const Isometry r = rho_word(S, w);
      // through the base point: the distance from V_0 to rho(w) V_0
      auto based = SSW::shortest_loop_through_base(s, loop);
      const double d0 = dist(S.polygon[0], apply_iso(r, S.polygon[0]));
      CGAL_HC_CHECK_MSG(std::abs(based.length - d0) < 1e-7, SSW::to_string(w) << ": " << based.length << " vs " << d0);
      // free: the translation length 2 acosh(|tr|/2) of the deck transformation
      auto free_loop = SSW::shortest_homotopic_loop(s, loop);
      const double tl = 2 * std::acosh(r.half_trace());
      CGAL_HC_CHECK_MSG(std::abs(free_loop.length - tl) < 1e-6, SSW::to_string(w) << ": " << free_loop.length << " vs " << tl
                        << " after " << free_loop.iterations << " iterations");
      CGAL_HC_CHECK(free_loop.converged);
      // the named-parameter form: number_of_iterations bounds the re-basing
      auto one = SSW::shortest_homotopic_loop(s, loop, CGAL::parameters::number_of_iterations(1));
      CGAL_HC_CHECK(one.iterations == 1 && std::abs(one.length - based.length) < 1e-9);
    }
  }
}

CGAL_HC_TEST_CASE(relator_is_contractible_with_the_cgal_oracle)
{
  for(int g : {2, 3}) {
    RPS S(g, 3);
    Surface s(S.mesh, S.length);
    Solver solver(s, S.base, S.generators);
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
    CGAL_HC_CHECK(cst.is_contractible(pos(S.mesh, solver.realize(solver.relator()))));
    CGAL_HC_CHECK(!cst.is_contractible(pos(S.mesh, solver.realize(SSW::Word{1}))));
    // swapping a1 and b1 is not canonical in this convention
    std::vector<std::vector<Mesh::Halfedge_index> > gens = S.generators;
    std::swap(gens[0], gens[1]);
    CGAL_HC_CHECK_THROWS(Solver(s, S.base, gens), SSW::Invalid_generators_error);
    gens = S.generators; gens.pop_back();
    CGAL_HC_CHECK_THROWS(Solver(s, S.base, gens), SSW::Invalid_generators_error);
    gens = S.generators; gens[1] = gens[0];
    CGAL_HC_CHECK_THROWS(Solver(s, S.base, gens), SSW::Invalid_generators_error);
    gens = S.generators; gens[0].pop_back();
    CGAL_HC_CHECK_THROWS(Solver(s, S.base, gens), SSW::Invalid_generators_error);
  }
}

CGAL_HC_TEST_CASE(words_are_base_point_homotopic_cgal_oracle)
{
  for(int g : {2, 3}) {
    RPS S(g, 4);
    Surface s(S.mesh, S.length);
    Solver solver(s, S.base, S.generators);
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
    std::mt19937 rng(100 + g);
    int geometric = 0, total = 0;
    for(std::size_t len : {10, 30, 100, 300, 1000, 3000, 10000}) {
      for(int trial = 0; trial < 3; ++trial) {
        const auto hs = random_loop(S.mesh, S.base, len, rng);
        const auto res = solver.solve(vertex_path(s, hs));
        geometric += res.used_geometry; ++total;
        // (CGAL's oracle compares paths with the same end points: the empty word is checked by contractibility)
        const bool ok = res.word.empty() ? cst.is_contractible(pos(S.mesh, hs))
                                         : cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver.realize(res.word)));
        CGAL_HC_CHECK_MSG(ok, "g " << g << " length " << len << " word " << SSW::to_string(res.word));
        // the raw crossing word is correct too, and the word represents the same element under rho
        CGAL_HC_CHECK(SSW::internal::free_reduce(res.word) == res.word);
        if(res.crossing_word.size() <= 30) {
          const Isometry a = rho_word(S, res.word), b = rho_word(S, res.crossing_word);
          const double scale = 1 + std::abs(b.normalized().alpha_real()) + std::abs(b.normalized().alpha_imag());
          CGAL_HC_CHECK(a.distance_to(b) < 1e-10 * scale * scale);
        }
      }
    }
    CGAL_HC_CHECK(geometric == total); // chart chaining: no length limit
    std::cout << "  genus " << g << ": " << geometric << " of " << total << " loops shortened geometrically" << std::endl;
  }
}

CGAL_HC_TEST_CASE(words_are_shortest_cayley_bfs)
{
  for(int g : {2, 3}) {
    RPS S(g, 3);
    Surface s(S.mesh, S.length);
    Solver solver(s, S.base, S.generators);
    // the reference: the quadruple-precision holonomy of the same polygon and its Cayley ball (radius 7 / 5);
    // shortest lengths up to radius + 3 by meet in the middle (the double-precision holonomy rho loses the
    // element for some 10-letter genus-3 words)
    const ssw_test::Fuchsian_group& G = ssw_test::fuchsian(g);
    const ssw_test::Ball& ball = ssw_test::ball_of(g);
    std::mt19937 rng(5 + g);
    int compared = 0, mismatched = 0;
    for(int trial = 0; trial < (g == 2 ? 150 : 60); ++trial) {
      const SSW::Word w = random_word(g, 1 + int(rng() % 10), rng);
      const SSW::Word res = solver.word(vertex_path(s, realize(S, w)));
      const ssw_test::M target = G.word(w);
      CGAL_HC_CHECK_MSG(ball.same(G.word(res), target), SSW::to_string(w) << " -> " << SSW::to_string(res));
      const int best = ball.length(target, 3);
      if(best >= 0) {
        ++compared;
        if(int(res.size()) != best) ++mismatched;
        CGAL_HC_CHECK_MSG(int(res.size()) == best, "genus " << g << ": " << SSW::to_string(w) << " -> "
                          << SSW::to_string(res) << " but the shortest word has length " << best);
      }
      CGAL_HC_CHECK(SSW::internal::free_reduce(res) == res);
      CGAL_HC_CHECK(SSW::internal::dehn_reduce(res, solver.relator()).size() == res.size());
    }
    // random loops on the mesh (not concatenations of generators): homotopy by CGAL's oracle, length by BFS
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
    int loops_compared = 0;
    for(int trial = 0; trial < (g == 2 ? 120 : 50); ++trial) {
      const auto hs = random_loop(S.mesh, S.base, 20 + rng() % 100, rng);
      const SSW::Word res = solver.word(vertex_path(s, hs));
      CGAL_HC_CHECK(res.empty() ? cst.is_contractible(pos(S.mesh, hs))
                                : cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver.realize(res))));
      const int best = ball.length(G.word(res), 3);
      if(best >= 0) {
        ++loops_compared;
        if(int(res.size()) != best) ++mismatched;
        CGAL_HC_CHECK_MSG(int(res.size()) == best, "genus " << g << ": loop word " << SSW::to_string(res) << " but the shortest word has length " << best);
      }
    }
    std::cout << "  genus " << g << ": " << compared << " words and " << loops_compared << " random loops compared with BFS, "
              << mismatched << " longer" << std::endl;
    CGAL_HC_CHECK(compared > 20 && loops_compared > 20);
  }
}

CGAL_HC_TEST_CASE(near_degenerate_loops)
{
  RPS S(2, 3);
  Surface s(S.mesh, S.length);
  Solver solver(s, S.base, S.generators);
  CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
  const ssw_test::Ball& ball = ssw_test::ball_of(2);
  // along a generator: the shortest loop is the generator itself (it runs along edges)
  for(int i = 0; i < 4; ++i) {
    const SSW::Word w{i + 1};
    CGAL_HC_CHECK_MSG(solver.word(vertex_path(s, S.generators[std::size_t(i)])) == w, i);
    const SSW::Word wi{-(i + 1)};
    CGAL_HC_CHECK(solver.word(vertex_path(s, realize(S, wi))) == wi);
    CGAL_HC_CHECK(std::abs(solver.shortened_generator_length(std::size_t(i)) - S.side_length()) < 1e-9);
  }
  // through the base point in the middle: products of generators, the relator, powers
  const std::vector<SSW::Word> words = {{1, 1}, {1, 2}, {1, 3}, {1, -2, -1}, {1, 2, -1, -2}, {1, 2, -1, -2, 3, 4, -3}, {4, 4, 4}, {}};
  for(const SSW::Word& w : words) {
    const auto hs = realize(S, w);
    if(hs.empty()) continue;
    const SSW::Word res = solver.word(vertex_path(s, hs));
    CGAL_HC_CHECK_MSG(res.empty() ? cst.is_contractible(pos(S.mesh, hs))
                                  : cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver.realize(res))), SSW::to_string(w));
    CGAL_HC_CHECK_MSG(res.size() <= w.size(), SSW::to_string(w) << " -> " << SSW::to_string(res));
    const int best = ball.length(ssw_test::fuchsian(2).word(w), 3);
    CGAL_HC_CHECK_MSG(best >= 0 && int(res.size()) == best, SSW::to_string(w) << " -> " << SSW::to_string(res) << " shortest " << best);
  }
  // the relator gives the empty word
  CGAL_HC_CHECK(solver.word(vertex_path(s, realize(S, solver.relator()))).empty());
}

CGAL_HC_TEST_CASE(bad_paths_throw)
{
  RPS S(2, 3);
  Surface s(S.mesh, S.length);
  Solver solver(s, S.base, S.generators);
  // open path where a loop is needed
  Path open = vertex_path(s, S.generators[0]);
  open.pop_back();
  CGAL_HC_CHECK_THROWS(SSW::shortest_loop_through_base(s, open), SSW::Invalid_path_error);
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_loop(s, open), SSW::Invalid_path_error);
  CGAL_HC_CHECK_THROWS(solver.word(open), SSW::Invalid_path_error);
  // not a path on the mesh: two vertices that share no face
  Path jump{SPoint::vertex(S.base), SPoint::vertex(*std::next(vertices(S.mesh).begin(), 5))};
  Path far_away;
  for(auto v : vertices(S.mesh)) {
    bool adjacent = v == S.base;
    for(auto h : CGAL::halfedges_around_source(S.base, S.mesh)) if(S.mesh.target(h) == v) adjacent = true;
    if(!adjacent) { far_away = {SPoint::vertex(S.base), SPoint::vertex(v), SPoint::vertex(S.base)}; break; }
  }
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_path(s, far_away), SSW::Invalid_path_error);
  CGAL_HC_CHECK_THROWS(solver.word(far_away), SSW::Invalid_path_error);
  // a vertex or halfedge that is not on the mesh
  Path ghost{SPoint::vertex(S.base), SPoint::vertex(Mesh::Vertex_index(Mesh::size_type(num_vertices(S.mesh) + 10)))};
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_path(s, ghost), SSW::Invalid_path_error);
  CGAL_HC_CHECK_THROWS(s.path_from_halfedges({Mesh::Halfedge_index(Mesh::size_type(10 * num_halfedges(S.mesh)))}), SSW::Invalid_path_error);
  // edge point with a bad parameter
  Path bad_t{SPoint::vertex(S.base), SPoint::on_edge(S.generators[0][0], 1.5)};
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_path(s, bad_t), SSW::Invalid_path_error);
  // a loop not through the base vertex
  const auto v1 = S.mesh.target(S.generators[0][0]);
  Path other;
  for(auto h : CGAL::halfedges_around_source(v1, S.mesh)) {
    other = {SPoint::vertex(v1), SPoint::vertex(S.mesh.target(h)), SPoint::vertex(v1)};
    break;
  }
  CGAL_HC_CHECK_THROWS(solver.word(other), SSW::Invalid_path_error);
  // longer than one chart of double precision: chart chaining (lengths checked in issue10_no_precision_limit)
  SSW::Word longw;
  for(int i = 0; i < 12; ++i) { longw.push_back(1); longw.push_back(3); }
  CGAL_HC_CHECK(SSW::shortest_loop_through_base(s, vertex_path(s, realize(S, longw))).length > 25);
  (void)jump;
}

CGAL_HC_TEST_CASE(greedy_basis_words_cgal_oracle)
{
  for(int g : {2, 3}) {
    for(bool canonical : {false, true}) {
      RPS S(g, 4);
      Surface s(S.mesh, S.length);
      SSW::Shortest_word_options opt;
      opt.make_canonical = canonical;
      Solver solver(s, S.base, opt); // computed greedy homotopy basis (made canonical or not)
      CGAL_HC_CHECK(solver.is_canonical() == canonical);
      CGAL_HC_CHECK(solver.relator().size() == std::size_t(4 * g));
      if(canonical) {
        SSW::Word can;
        for(int i = 0; i < g; ++i) { can.push_back(2 * i + 1); can.push_back(2 * i + 2); can.push_back(-(2 * i + 1)); can.push_back(-(2 * i + 2)); }
        CGAL_HC_CHECK(solver.relator() == can);
      }
      CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
      // the relator of the (computed) generators is contractible, the generators are not
      CGAL_HC_CHECK(cst.is_contractible(pos(S.mesh, solver.realize(solver.relator()))));
      for(int i = 0; i < 2 * g; ++i) {
        CGAL_HC_CHECK(!cst.is_contractible(pos(S.mesh, solver.generator(std::size_t(i)))));
        const SSW::Word w = solver.word(vertex_path(s, solver.generator(std::size_t(i))));
        CGAL_HC_CHECK_MSG(w == SSW::Word{i + 1}, solver.word_to_string(w));
      }
      std::mt19937 rng(77 + g);
      for(std::size_t len : {10, 100, 1000, 10000}) {
        for(int trial = 0; trial < 2; ++trial) {
          const auto hs = random_loop(S.mesh, S.base, len, rng);
          const SSW::Word w = solver.word(vertex_path(s, hs));
          CGAL_HC_CHECK_MSG(w.empty() ? cst.is_contractible(pos(S.mesh, hs))
                                      : cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver.realize(w))),
                            "genus " << g << " length " << len << " word " << solver.word_to_string(w));
        }
      }
    }
  }
}

// any FaceGraph: the same surface as a Polyhedron_3 with lengths in an associative property map
CGAL_HC_TEST_CASE(polyhedron_3_face_graph)
{
  typedef CGAL::Polyhedron_3<CGAL::Epick> Poly;
  typedef boost::graph_traits<Poly>::edge_descriptor PE;
  typedef boost::graph_traits<Poly>::halfedge_descriptor PH;
  RPS S(2, 4);
  Poly P;
  std::map<Mesh::Halfedge_index, PH> h2h;
  std::map<Mesh::Vertex_index, boost::graph_traits<Poly>::vertex_descriptor> v2v;
  CGAL::copy_face_graph(S.mesh, P, CGAL::parameters::vertex_to_vertex_output_iterator(std::inserter(v2v, v2v.end()))
                                     .halfedge_to_halfedge_output_iterator(std::inserter(h2h, h2h.end())));
  std::map<PE, double> lengths;
  for(auto e : edges(S.mesh)) lengths[edge(h2h[halfedge(e, S.mesh)], P)] = S.length[e];
  boost::associative_property_map<std::map<PE, double> > lm(lengths);
  typedef SSW::Hyperbolic_surface<Poly, decltype(lm)> PSurface;
  PSurface s(P, lm);
  CGAL_HC_CHECK(s.genus() == 2);
  std::vector<std::vector<PH> > gens;
  for(const auto& g : S.generators) { gens.emplace_back(); for(auto h : g) gens.back().push_back(h2h[h]); }
  SSW::Shortest_word_solver<Poly, decltype(lm)> solver(s, v2v[S.base], gens);
  CGAL_HC_CHECK(solver.word(s.path_from_halfedges(solver.realize(SSW::Word{1, 2, -1}))) == (SSW::Word{1, 2, -1}));
  SSW::Shortest_word_solver<Poly, decltype(lm)> computed(s, v2v[S.base]);
  CGAL_HC_CHECK(computed.is_canonical());
  const auto r = SSW::shortest_homotopic_loop(s, s.path_from_halfedges(gens[0]));
  CGAL_HC_CHECK(std::abs(r.length - 2 * std::acosh(S.rho_generator(0).half_trace())) < 1e-6);
}

// issue 10: words of loops along the polygon sides (where Dehn's algorithm is not enough) are shortest, and
// loops along a generator at the base point, from both sides, give the right element (CGAL's oracle)
CGAL_HC_TEST_CASE(issue10_words_along_generators_shortest_and_right)
{
  {
    RPS S(3, 3);
    Surface s(S.mesh, S.length);
    Solver solver(s, S.base, S.generators);
    // a1 b1 a1^-1 b1^-1 a2 b2 b2 a2^-1 b2^-1 a3 b3 a3^-1 (the 12-gon's own sides): a 10-letter word
    const SSW::Word w{1, 2, -1, -2, 3, 4, 4, -3, -4, 5, 6, -5};
    const auto hs = realize(S, w);
    const auto res = solver.solve(vertex_path(s, hs));
    CGAL_HC_CHECK_MSG(res.word.size() == 10, SSW::to_string(res.word));
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
    CGAL_HC_CHECK(cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver.realize(res.word))));
    const SSW::Word ten{6, 5, -6, -5, 4, 2, 1, -2, -1, 6}; // the issue's 10-letter word: the same element
    CGAL_HC_CHECK(cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, realize(S, ten))));
  }
  for(int g : {2, 3}) {
    RPS S(g, 3);
    Surface s(S.mesh, S.length);
    for(bool computed : {false, true}) {
      std::unique_ptr<Solver> solver(computed ? new Solver(s, S.base) : new Solver(s, S.base, S.generators));
      CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
      std::mt19937 rng(300 + g);
      int n = 0, geometric = 0, geometric_reading_differs = 0;
      for(int i = 0; i < 2 * g; ++i)
        for(int sign : {1, -1}) {
          // along generator i (forwards or backwards), then a random loop, then along generator i again
          std::vector<Mesh::Halfedge_index> hs;
          const auto& gi = solver->generator(std::size_t(i));
          auto along = [&](int sg) {
            if(sg > 0) hs.insert(hs.end(), gi.begin(), gi.end());
            else for(auto it = gi.rbegin(); it != gi.rend(); ++it) hs.push_back(S.mesh.opposite(*it));
          };
          along(sign);
          const auto mid = random_loop(S.mesh, S.base, 5 + rng() % 40, rng);
          hs.insert(hs.end(), mid.begin(), mid.end());
          along(rng() % 2 ? 1 : -1);
          const auto res = solver->solve(vertex_path(s, hs));
          CGAL_HC_CHECK_MSG(res.word.empty() ? cst.is_contractible(pos(S.mesh, hs))
                                             : cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver->realize(res.word))),
                            "genus " << g << " generator " << i << " word " << solver->word_to_string(res.word));
          CGAL_HC_CHECK(solver->reduce(res.word) == res.word);
          // diagnostic: the word read from the crossings of the shortest loop (issue 10's elephant case)
          CGAL_HC_CHECK_MSG(res.used_geometry, res.geometry_status);
          if(res.used_geometry) {
            ++geometric;
            const SSW::Word gw = solver->reduce(solver->crossing_word(res.loop));
            if(gw != res.word) ++geometric_reading_differs;
          }
          ++n;
        }
      CGAL_HC_CHECK(n == 4 * g);
      std::cout << "  genus " << g << (computed ? " computed" : " given") << " system: " << geometric
                << " shortest loops, the crossing reading of " << geometric_reading_differs
                << " of them differs from the word (the word is read from the input loop)" << std::endl;
    }
  }
}

// issue 12: bad generators and base vertices throw; the loop iteration reports convergence honestly
CGAL_HC_TEST_CASE(issue12_bad_solver_input_and_false_convergence)
{
  RPS S(2, 3);
  Surface s(S.mesh, S.length);
  std::vector<std::vector<Mesh::Halfedge_index> > gens = S.generators;
  gens[0][0] = Mesh::Halfedge_index(1000000);
  CGAL_HC_CHECK_THROWS(Solver(s, S.base, gens), SSW::Invalid_generators_error);
  CGAL_HC_CHECK_THROWS(Solver(s, S.base, gens), CGAL::Invalid_input_error);
  CGAL_HC_CHECK_THROWS(Solver(s, Mesh::null_vertex(), S.generators), CGAL::Invalid_input_error);
  CGAL_HC_CHECK_THROWS(Solver(s, Mesh::Vertex_index(1000000)), CGAL::Invalid_input_error);
  CGAL_HC_CHECK_THROWS(Solver(s, Mesh::null_vertex()), CGAL::Invalid_input_error);
  // two disjoint genus-2 surfaces in one mesh are not a genus-3 surface
  {
    Mesh two = S.mesh;
    two.join(S.mesh);
    auto len2 = two.property_map<RPS::Edge_index, double>("e:hyperbolic_length").first;
    CGAL_HC_CHECK(two.number_of_faces() == 2 * S.mesh.number_of_faces());
    CGAL_HC_CHECK_THROWS(Surface(two, len2), CGAL::Invalid_input_error);
  }
  // a loop through a non-base vertex, shortened freely: 2 iterations are not enough to converge
  std::mt19937 rng(9);
  const auto hs = random_loop(S.mesh, S.base, 60, rng);
  const Path loop = vertex_path(s, hs);
  const auto full = SSW::shortest_homotopic_loop(s, loop, CGAL::parameters::number_of_iterations(200));
  const auto two = SSW::shortest_homotopic_loop(s, loop, CGAL::parameters::number_of_iterations(2));
  CGAL_HC_CHECK(two.iterations <= 2);
  if(two.converged) CGAL_HC_CHECK_MSG(std::abs(two.length - full.length) <= 1e-9 * (1 + full.length), two.length << " " << full.length);
  if(std::abs(two.length - full.length) > 1e-9 * (1 + full.length)) CGAL_HC_CHECK(!two.converged);
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_loop(s, loop, std::nan("")), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_loop(s, loop, SSW::parameters::tolerance(std::nan(""))), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_loop(s, loop, CGAL::parameters::number_of_iterations(0)), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_path(s, loop, SSW::parameters::vertex_snap(0.3)), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_path(s, loop, SSW::parameters::max_lift_distance(-1.0)), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(SSW::shortest_homotopic_path(s, loop, SSW::parameters::max_lift_distance(1e6)), CGAL::Invalid_option_error);
  // the named parameters reach the computation: a tiny lift bound makes the single chart impossible
  const auto a = SSW::shortest_homotopic_loop(s, loop, SSW::parameters::tolerance(1e-6, CGAL::parameters::number_of_iterations(50)));
  CGAL_HC_CHECK(a.iterations <= 50);
  CGAL_HC_CHECK(std::abs(a.length - full.length) <= 1e-4 * (1 + full.length));
}

// words of random loops of 10 to 10^5 edges: geodesic (independent check: not longer than a word from
// Dehn's algorithm, fixed by the reducer's own acceptor on windows) and the right element (CGAL's oracle)
CGAL_HC_TEST_CASE(long_random_loops_right_element)
{
  RPS S(2, 4);
  Surface s(S.mesh, S.length);
  Solver solver(s, S.base, S.generators);
  CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
  std::mt19937 rng(4242);
  for(std::size_t len : {10, 1000, 100000}) {
    const auto hs = random_loop(S.mesh, S.base, len, rng);
    const auto res = solver.solve(vertex_path(s, hs));
    CGAL_HC_CHECK(res.word.empty() ? cst.is_contractible(pos(S.mesh, hs))
                                   : cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver.realize(res.word))));
    CGAL_HC_CHECK(SSW::internal::dehn_reduce(res.word, solver.relator()).size() == res.word.size());
    CGAL_HC_CHECK_MSG(res.used_geometry, res.geometry_status);
    std::cout << "  loop of " << len << " edges: word of " << res.word.size() << " letters, geometry "
              << (res.used_geometry ? "used" : "not used (" + res.geometry_status + ")") << std::endl;
  }
}

// issue 10 item 5: geometry at any length (chart chaining). References in quadruple precision, independent
// of the package: the based length d(V_0, rho(w) V_0) = 2 acosh |a| of the SU(1,1) matrix of rho(w)
// conjugated to move V_0 to the origin, and the free length 2 acosh(|tr rho(w)| / 2).
namespace {
using ssw_test::based_length_q;
using ssw_test::free_length_q;
} // namespace

CGAL_HC_TEST_CASE(issue10_no_precision_limit)
{
  for(int g : {2, 3}) {
    RPS S(g, 3);
    Surface s(S.mesh, S.length);
    Solver solver(s, S.base, S.generators);
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
    // the quadruple-precision reference agrees with the package's holonomy on a short word
    {
      const SSW::Word w{1, 2, -3};
      const Isometry r = rho_word(S, w);
      CGAL_HC_CHECK(std::abs(based_length_q(g, w) - dist(S.polygon[0], apply_iso(r, S.polygon[0]))) < 1e-9);
      CGAL_HC_CHECK(std::abs(free_length_q(g, w) - 2 * std::acosh(r.half_trace())) < 1e-9);
    }
    // high powers of generators and of a product: shortest representatives of 10^2 to more than 10^4 units
    std::vector<SSW::Word> words;
    words.push_back(SSW::Word(40, 1));
    words.push_back(SSW::Word(500, 2));
    if(g == 2) words.push_back(SSW::Word(4500, 1)); // 10,157 units
    { SSW::Word w; for(int i = 0; i < 900; ++i) { w.push_back(1); w.push_back(-4); } if(g == 2) words.push_back(w); }
    for(const SSW::Word& w : words) {
      const Path loop = vertex_path(s, realize(S, w));
      const double d_ref = based_length_q(g, w), l_ref = free_length_q(g, w);
      if(w.size() == 4500) CGAL_HC_CHECK(d_ref > 1e4);
      const auto based = SSW::shortest_loop_through_base(s, loop);
      CGAL_HC_CHECK_MSG(std::abs(based.length - d_ref) <= 1e-9 * (1 + d_ref),
                        "g " << g << " |w| " << w.size() << ": based " << based.length << " vs " << d_ref);
      const SSW::Word wb = solver.word(based.path);
      CGAL_HC_CHECK(wb.size() == solver.reduce(w).size());
      CGAL_HC_CHECK(cst.are_base_point_homotopic(pos(S.mesh, solver.realize(wb)), pos(S.mesh, realize(S, w))));
      const auto freel = SSW::shortest_homotopic_loop(s, loop);
      CGAL_HC_CHECK_MSG(std::abs(freel.length - l_ref) <= 1e-9 * (1 + l_ref),
                        "g " << g << " |w| " << w.size() << ": free " << freel.length << " vs " << l_ref);
      CGAL_HC_CHECK(freel.converged);
      const auto res = solver.solve(loop);
      CGAL_HC_CHECK(res.used_geometry && std::abs(res.length - d_ref) <= 1e-9 * (1 + d_ref));
      std::cout << "  genus " << g << ", |w| = " << w.size() << ": based loop " << based.length << " (reference " << d_ref
                << "), closed geodesic " << freel.length << " (reference " << l_ref << ")" << std::endl;
    }
    // random loops of 1,000 and 10,000 edges: geometry always, the right element, the right length
    std::mt19937 rng(77 + g);
    for(std::size_t len : {1000, 10000}) {
      const auto hs = random_loop(S.mesh, S.base, len, rng);
      const auto res = solver.solve(vertex_path(s, hs));
      CGAL_HC_CHECK_MSG(res.used_geometry, res.geometry_status);
      CGAL_HC_CHECK(res.word.empty() ? cst.is_contractible(pos(S.mesh, hs))
                                     : cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver.realize(res.word))));
      // the traced geodesic's own word is a geodesic word of the same element (geodesic words are not
      // unique: half-relators can be swapped), by CGAL's homotopy test
      const SSW::Word wl = solver.word(res.loop);
      CGAL_HC_CHECK(wl.size() == res.word.size());
      CGAL_HC_CHECK(cst.are_base_point_homotopic(pos(S.mesh, solver.realize(wl)), pos(S.mesh, solver.realize(res.word))));
      const double d_ref = based_length_q(g, res.word);
      CGAL_HC_CHECK_MSG(std::abs(res.length - d_ref) <= 1e-9 * (1 + d_ref), res.length << " vs " << d_ref);
      std::cout << "  genus " << g << ", random loop of " << len << " edges: word of " << res.word.size()
                << " letters, shortest loop " << res.length << " (reference " << d_ref << ")" << std::endl;
    }
  }
}

// The word solver and shortest_loop_through_base() on the loop `hs` at the base point of the regular-polygon
// surface S, checked against the quadruple-precision based length of the solver's word (beyond about 11,000
// units cosh overflows even in quadruple precision: then the solver's shortest loop of the word, made of deck
// transformations of the word and not a lift of the path, is the reference) and CGAL's homotopy test on the
// word read from the based loop. Returns the reference length.
static double check_based_loop(int g, const RPS& S, const Surface& s, const Solver& solver,
                               const CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh>& cst,
                               const std::vector<Mesh::Halfedge_index>& hs, SSW::Word_result<Mesh>& res,
                               SSW::Shortest_path_result<Mesh>& based)
{
  const Path loop = vertex_path(s, hs);
  res = solver.solve(loop);
  CGAL_HC_CHECK_MSG(res.used_geometry, res.geometry_status);
  const double q_ref = based_length_q(g, res.word);
  const double d_ref = std::isfinite(q_ref) ? q_ref : res.length;
  if(std::isfinite(q_ref)) CGAL_HC_CHECK_MSG(std::abs(res.length - q_ref) <= 1e-9 * (1 + q_ref), res.length << " vs " << q_ref);
  based = SSW::shortest_loop_through_base(s, loop);
  CGAL_HC_CHECK_MSG(std::abs(based.length - d_ref) <= 1e-9 * (1 + d_ref), based.length << " vs " << d_ref);
  CGAL_HC_CHECK(std::abs(s.path_length(based.path) - based.length) <= 1e-9 * (1 + d_ref));
  const SSW::Word wb = solver.word(based.path);
  CGAL_HC_CHECK(wb.size() == res.word.size());
  CGAL_HC_CHECK(wb.empty() ? cst.is_contractible(pos(S.mesh, hs))
                           : cst.are_base_point_homotopic(pos(S.mesh, hs), pos(S.mesh, solver.realize(wb))));
  return d_ref;
}

// issue 10, the path functions at any length without rounds: shortest_loop_through_base(),
// shortest_homotopic_path() and shortest_homotopic_loop() on long inputs (chart chaining and the geodesic of
// the universal cover). References independent of the path code: the quadruple-precision based and free
// lengths of the solver's word, CGAL's homotopy test on the words read from the results.
CGAL_HC_TEST_CASE(issue10_long_paths_and_loops_linear)
{
  const int g = 2;
  RPS S(g, 3);
  Surface s(S.mesh, S.length);
  Solver solver(s, S.base, S.generators);
  CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(S.mesh);
  std::mt19937 rng(2026);
  // loops along a generator at the base point, from both sides (the geodesic runs along the generator's
  // geodesic and through p), short and long
  for(int l = 1; l <= 2 * g; ++l)
    for(int sign : {1, -1})
      for(std::size_t k : {std::size_t(1), std::size_t(3), std::size_t(400)}) {
        const SSW::Word w(k, sign * l);
        const Path loop = vertex_path(s, realize(S, w));
        const double d_ref = based_length_q(g, w), l_ref = free_length_q(g, w);
        const auto based = SSW::shortest_loop_through_base(s, loop);
        CGAL_HC_CHECK_MSG(std::abs(based.length - d_ref) <= 1e-9 * (1 + d_ref),
                          SSW::to_string(w).substr(0, 20) << " x" << k << ": based " << based.length << " vs " << d_ref);
        CGAL_HC_CHECK(std::abs(s.path_length(based.path) - based.length) <= 1e-9 * (1 + d_ref));
        const SSW::Word wb = solver.word(based.path);
        CGAL_HC_CHECK(wb.size() == k);
        CGAL_HC_CHECK(cst.are_base_point_homotopic(pos(S.mesh, solver.realize(wb)), pos(S.mesh, realize(S, w))));
        const auto freel = SSW::shortest_homotopic_loop(s, loop);
        CGAL_HC_CHECK(freel.converged);
        CGAL_HC_CHECK_MSG(std::abs(freel.length - l_ref) <= 1e-9 * (1 + l_ref), freel.length << " vs " << l_ref);
      }
  // on the 1152-face surface the geodesic of a1^k runs through mesh vertices: anchors at vertices (the former
  // chart chaining lost the geodesic there). Its middle converges exponentially to the axis of a1, which runs
  // through mesh vertices: in the solver's frames (the lattice points) it passes them within 1e-12 to 1e-6,
  // where the anchor used to be refused or its walk to turn around the vertex forever (no geometry for a1^40
  // and a1^400 before)
  {
    RPS F(g, 12);
    Surface fs(F.mesh, F.length);
    Solver fsolver(fs, F.base, F.generators);
    for(int sign : {1, -1})
      for(std::size_t k : {std::size_t(40), std::size_t(400)}) {
        const SSW::Word w(k, sign);
        const Path loop = vertex_path(fs, realize(F, w));
        const double d_ref = based_length_q(g, w), l_ref = free_length_q(g, w);
        const auto based = SSW::shortest_loop_through_base(fs, loop);
        CGAL_HC_CHECK_MSG(std::abs(based.length - d_ref) <= 1e-9 * (1 + d_ref), based.length << " vs " << d_ref);
        CGAL_HC_CHECK(std::abs(fs.path_length(based.path) - based.length) <= 1e-9 * (1 + d_ref));
        const auto freel = SSW::shortest_homotopic_loop(fs, loop);
        CGAL_HC_CHECK(freel.converged);
        CGAL_HC_CHECK_MSG(std::abs(freel.length - l_ref) <= 1e-9 * (1 + l_ref), freel.length << " vs " << l_ref);
        // the solver's own shortest loop of the word (issue 10 item 5: no fallback at any length)
        const auto res = fsolver.solve(loop);
        CGAL_HC_CHECK(res.word == w);
        CGAL_HC_CHECK_MSG(res.used_geometry, "a1^" << sign * int(k) << ": " << res.geometry_status);
        CGAL_HC_CHECK_MSG(std::abs(res.length - d_ref) <= 1e-9 * (1 + d_ref), res.length << " vs " << d_ref);
      }
  }
  // a fine mesh (12,800 faces, edges of about 0.05 units): random loops long enough for chart chaining,
  // whose raw walk wanders over many charts' reach. The work is linear with a small constant: every face of
  // the loop is developed a bounded number of times (the former fixed chunks of 256 points re-traced each
  // merged piece of up to 10 units, about 20 faces embedded per loop edge on this mesh)
  {
    RPS F(g, 40);
    Surface fs(F.mesh, F.length);
    Solver fsolver(fs, F.base, F.generators);
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> fcst(F.mesh);
    std::mt19937 frng(4040);
    for(std::size_t len : {100000, 300000}) {
      const auto hs = random_loop(F.mesh, F.base, len, frng);
      SSW::Word_result<Mesh> res;
      SSW::Shortest_path_result<Mesh> based;
      const double d_ref = check_based_loop(g, F, fs, fsolver, fcst, hs, res, based);
      CGAL_HC_CHECK_MSG(d_ref > 25, "the loop fits one chart: " << d_ref);
      CGAL_HC_CHECK_MSG(based.embedded_faces <= 2 * hs.size(), based.embedded_faces << " faces embedded for " << hs.size() << " edges");
      // out and back along the walk, then one more edge: homotopic to that edge, a geodesic
      std::vector<Mesh::Halfedge_index> ob(hs.begin(), hs.begin() + std::ptrdiff_t(len / 2));
      for(std::size_t i = ob.size(); i-- > 0;) ob.push_back(F.mesh.opposite(ob[i]));
      ob.push_back(hs.front());
      const auto sp = SSW::shortest_homotopic_path(fs, vertex_path(fs, ob));
      const double edge = F.length[F.mesh.edge(hs.front())];
      CGAL_HC_CHECK_MSG(std::abs(sp.length - edge) <= 1e-9, sp.length << " vs the edge " << edge);
      CGAL_HC_CHECK_MSG(sp.embedded_faces <= 2 * ob.size(), sp.embedded_faces << " faces embedded for " << ob.size() << " edges");
      std::cout << "  12,800 faces, random loop of " << hs.size() << " edges: based loop " << based.length << " (reference "
                << d_ref << "), " << based.embedded_faces << " faces embedded; out and back: " << sp.embedded_faces
                << " faces" << std::endl;
    }
  }
  // random loops of 10^4 and 10^5 edges at the base point
  for(std::size_t len : {10000, 100000}) {
    const auto hs = random_loop(S.mesh, S.base, len, rng);
    const Path loop = vertex_path(s, hs);
    SSW::Word_result<Mesh> res;
    SSW::Shortest_path_result<Mesh> based;
    const double d_ref = check_based_loop(g, S, s, solver, cst, hs, res, based);
    const bool quadruple_reference = std::isfinite(based_length_q(g, res.word));
    if(len == 10000) {
      const double l_ref = free_length_q(g, res.word);
      const auto freel = SSW::shortest_homotopic_loop(s, loop);
      CGAL_HC_CHECK(freel.converged);
      CGAL_HC_CHECK_MSG(std::abs(freel.length - l_ref) <= 1e-9 * (1 + l_ref), freel.length << " vs " << l_ref);
      std::cout << "  random loop of " << hs.size() << " edges: free loop " << freel.length << " (reference " << l_ref
                << ") after " << freel.iterations << " iterations" << std::endl;
    }
    // an open path: the walk without its way back; closed by the same way back, the result is the same
    // element as the input
    std::vector<Mesh::Halfedge_index> walk(hs.begin(), hs.begin() + std::ptrdiff_t(len));
    std::vector<Mesh::Halfedge_index> back(hs.begin() + std::ptrdiff_t(len), hs.end());
    const Path open = vertex_path(s, walk);
    const auto sp = SSW::shortest_homotopic_path(s, open);
    CGAL_HC_CHECK(s.same_point(sp.path.front(), open.front()) && s.same_point(sp.path.back(), open.back()));
    CGAL_HC_CHECK(std::abs(s.path_length(sp.path) - sp.length) <= 1e-9 * (1 + sp.length));
    CGAL_HC_CHECK(sp.length <= s.path_length(open));
    Path closed = sp.path;
    if(!back.empty()) { const Path b = vertex_path(s, back); closed.insert(closed.end(), b.begin() + 1, b.end()); }
    const SSW::Word wc = solver.word(closed);
    CGAL_HC_CHECK(wc.size() == res.word.size());
    CGAL_HC_CHECK(wc.empty() ? res.word.empty()
                             : cst.are_base_point_homotopic(pos(S.mesh, solver.realize(wc)), pos(S.mesh, solver.realize(res.word))));
    std::cout << "  random walk of " << len << " edges: based loop " << based.length << " (reference " << d_ref
              << (quadruple_reference ? ", quadruple holonomy" : ", the solver's loop of the word") << "), open path " << sp.length << ", " << sp.embedded_faces << " faces embedded" << std::endl;
  }
}

int main(int argc, char** argv) { return cgal_hc_test::run_all(argc, argv); }
