// Thesis Theorem 2.6's setting (issue 10 item 4): the canonical system of shortest geodesic loops through p
// and the fundamental polygon they bound. Checked facts that could fail: every interior point of a loop has
// angle pi on both sides (a geodesic), the loops are simple and pairwise disjoint except at p, the polygon's
// angle sum is 2 pi and its area (a fan of l'Huilier triangles, independent of the angles) 4 pi (g - 1), its
// boundary reads the canonical relator with side k of the length of loop |r_k|, and (on the regular
// polygon surfaces) the loops are the polygon's sides, of the reference side length.
// The loops inserted into a surface triangulation (geodesic_system_triangulation()): each is a chain of
// constrained edges of the loop's length, the chains meet only at p, the cut surface is a disk
// (V - E + F = 1, one boundary cycle) whose boundary reads the canonical relator, and its faces developed
// into the polygon's frame lie inside the polygon, fill its area and agree across every uncut edge.
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Surface_shortest_words/geodesic_canonical_system.h>
#include <CGAL/Surface_shortest_words/geodesic_system_triangulation.h>
#include <CGAL/Surface_shortest_words/regular_polygon_surface.h>
#include <CGAL/Curves_on_surface_topology.h>
#if __has_include(<CGAL/Discrete_Ricci_flow.h>)
#include <CGAL/Discrete_Ricci_flow.h>
#endif

#include "cgal_hc_test.h"

#include <cmath>
#include <map>
#include <set>
#include <string>

namespace {
namespace SSW = CGAL::Surface_shortest_words;

// point z inside the geodesic polygon P (convex: every angle below pi) or outside by at most tol (hyperbolic
// distance to the supporting geodesic of a side, on its outer side)
bool in_polygon(const std::vector<CGAL::Epick::Point_2>& P, const CGAL::Epick::Point_2& z, double orient, double tol)
{
  for(std::size_t i = 0; i < P.size(); ++i) {
    // the side from a to b on the positive real axis: the signed distance to it is asinh(2 Im w / (1 - |w|^2))
    const auto w = SSW::internal::apply_isometry(SSW::internal::frame(SSW::internal::to_cplx(P[i]), SSW::internal::to_cplx(P[(i + 1) % P.size()])),
                                                 SSW::internal::to_cplx(z));
    const double d = std::asinh(2 * w.imag() / (1 - std::norm(w)));
    if((orient > 0 ? d : -d) < -tol) return false;
  }
  return true;
}

template <class Surface, class Solver, class System>
void check_triangulation(const Surface& s, const Solver& solver, const System& sys, const SSW::Word& canonical,
                         const std::string& name)
{
  const SSW::Geodesic_system_triangulation gt = SSW::geodesic_system_triangulation(s, solver, sys);
  const auto& t = gt.triangulation;
  std::string why;
  CGAL_HC_CHECK_MSG(t.is_valid(&why), name << ": " << why);
  const std::size_t n = sys.loops.size();
  CGAL_HC_CHECK(gt.loop_edges.size() == n);
  std::size_t chain_edges = 0;
  std::set<std::size_t> inner; // vertices of the chains other than p: pairwise distinct
  for(std::size_t i = 0; i < n; ++i) {
    CGAL_HC_CHECK_MSG(std::abs(gt.loop_lengths[i] - sys.lengths[i]) <= 1e-9 * sys.lengths[i],
                      name << ": chain " << i << " " << gt.loop_lengths[i] << " vs loop " << sys.lengths[i]);
    // the chain is a path of constrained edges from p to p
    const auto& E = gt.loop_edges[i];
    const auto& V = gt.loop_vertices[i];
    CGAL_HC_CHECK(!E.empty() && V.size() == E.size() + 1 && V.front() == gt.base && V.back() == gt.base);
    double len = 0;
    for(std::size_t k = 0; k < E.size(); ++k) {
      CGAL_HC_CHECK(t.is_constrained(E[k].first, E[k].second));
      CGAL_HC_CHECK(t.vertex(E[k].first, E[k].second) == V[k] && t.vertex(E[k].first, (E[k].second + 1) % 3) == V[k + 1]);
      len += t.edge_length(E[k].first, E[k].second);
    }
    CGAL_HC_CHECK(std::abs(len - gt.loop_lengths[i]) <= 1e-12 * len);
    for(std::size_t k = 1; k + 1 < V.size(); ++k) CGAL_HC_CHECK_MSG(inner.insert(V[k]).second, name << ": chains meet away from p");
    chain_edges += E.size();
  }
  CGAL_HC_CHECK(t.number_of_constrained_edges() == chain_edges);
  CGAL_HC_CHECK_MSG(gt.cut_euler_characteristic == 1, name << ": cut surface V - E + F = " << gt.cut_euler_characteristic);
  CGAL_HC_CHECK(gt.cut_boundary_cycles == 1 && gt.cut_components == 1);
  CGAL_HC_CHECK_MSG(gt.boundary_word == canonical, name << ": boundary word " << SSW::to_string(gt.boundary_word));
  // the developed faces: every face once, inside the polygon, of total area the polygon's, agreeing across uncut edges
  CGAL_HC_CHECK(gt.polygon_faces.size() == t.number_of_faces());
  double orient = 0;
  for(std::size_t k = 0; k < sys.polygon.size(); ++k)
    orient += SSW::internal::cross(SSW::internal::to_klein(SSW::internal::to_cplx(sys.polygon[k])),
                                   SSW::internal::to_klein(SSW::internal::to_cplx(sys.polygon[(k + 1) % sys.polygon.size()])));
  std::map<std::size_t, std::size_t> at;
  double area = 0;
  std::size_t outside = 0;
  for(std::size_t k = 0; k < gt.polygon_faces.size(); ++k) {
    CGAL_HC_CHECK(at.emplace(gt.polygon_faces[k], k).second);
    const auto& z = gt.polygon_face_points[k];
    area += CGAL::Hyperbolic_surface_2::triangle_area(SSW::internal::hyperbolic_distance(SSW::internal::to_cplx(z[0]), SSW::internal::to_cplx(z[1])),
                                                      SSW::internal::hyperbolic_distance(SSW::internal::to_cplx(z[1]), SSW::internal::to_cplx(z[2])),
                                                      SSW::internal::hyperbolic_distance(SSW::internal::to_cplx(z[2]), SSW::internal::to_cplx(z[0])));
    for(int c = 0; c < 3; ++c) if(!in_polygon(sys.polygon, z[c], orient, 1e-7)) ++outside;
  }
  // the corners at p land on the polygon's vertices
  double corner = 0;
  for(std::size_t k = 0; k < gt.polygon_faces.size(); ++k)
    for(int c = 0; c < 3; ++c) {
      if(t.vertex(gt.polygon_faces[k], c) != gt.base) continue;
      double d = 1e300;
      for(const auto& P : sys.polygon)
        d = (std::min)(d, SSW::internal::hyperbolic_distance(SSW::internal::to_cplx(P), SSW::internal::to_cplx(gt.polygon_face_points[k][c])));
      corner = (std::max)(corner, d);
    }
  CGAL_HC_CHECK_MSG(outside == 0, name << ": " << outside << " developed corners outside the polygon");
  CGAL_HC_CHECK_MSG(std::abs(area - sys.area) < 1e-6, name << ": developed area " << area << " vs polygon " << sys.area);
  // (positions at distance R from the origin carry about 1e-16 e^R / (edge length) per transition: R < 9 here)
  CGAL_HC_CHECK_MSG(gt.max_development_error < 1e-7, name << ": developed faces disagree across an edge by " << gt.max_development_error);
  CGAL_HC_CHECK_MSG(corner < 1e-7, name << ": a corner at p is " << corner << " from the polygon's vertices");
  std::cout << "  " << name << ": triangulation with the loops as " << chain_edges << " constrained edges ("
            << gt.vertices_inserted << " vertices inserted, " << t.number_of_faces() << " faces), cut surface V-E+F = "
            << gt.cut_euler_characteristic << ", boundary word " << SSW::to_string(gt.boundary_word) << std::endl;
}

template <class Surface, class Solver>
void check_system(const Surface& s, const Solver& solver, const std::string& name)
{
  const int g = solver.genus();
  const auto sys = SSW::geodesic_canonical_system(solver);
  const SSW::Geodesic_system_report rep = SSW::check_geodesic_system(s, solver.base(), sys.loops);
  CGAL_HC_CHECK_MSG(rep.simple_and_disjoint, name << ": " << rep.intersections << " intersections");
  CGAL_HC_CHECK_MSG(rep.min_side_angle >= CGAL_PI - 1e-6, name << ": side angle " << rep.min_side_angle);
  CGAL_HC_CHECK_MSG(std::abs(sys.angle_sum - 2 * CGAL_PI) < 1e-6, name << ": angle sum " << sys.angle_sum);
  CGAL_HC_CHECK_MSG(std::abs(sys.area - 4 * CGAL_PI * (g - 1)) < 1e-6, name << ": area " << sys.area);
  SSW::Word canonical;
  for(int i = 0; i < g; ++i) for(int l : {2 * i + 1, 2 * i + 2, -(2 * i + 1), -(2 * i + 2)}) canonical.push_back(l);
  CGAL_HC_CHECK(sys.relator == canonical);
  const std::size_t m = sys.polygon.size();
  CGAL_HC_CHECK(m == 4 * std::size_t(g));
  for(std::size_t k = 0; k < m; ++k) {
    const double side = SSW::internal::hyperbolic_distance(SSW::internal::to_cplx(sys.polygon[k]), SSW::internal::to_cplx(sys.polygon[(k + 1) % m]));
    CGAL_HC_CHECK_MSG(std::abs(side - sys.lengths[std::size_t(std::abs(sys.relator[k]) - 1)]) < 1e-7 * (1 + side),
                      name << ": side " << k << " " << side);
    CGAL_HC_CHECK(sys.polygon_angles[k] > 0);
  }
  check_triangulation(s, solver, sys, canonical, name);
  // each loop is in the class of its generator
  for(std::size_t i = 0; i < sys.loops.size(); ++i) CGAL_HC_CHECK(solver.word(sys.loops[i]) == SSW::Word(1, int(i) + 1));
  std::cout << "  " << name << ": " << sys.loops.size() << " geodesic loops, " << rep.interior_points
            << " interior points (min side angle " << rep.min_side_angle << "), simple and disjoint, polygon angle sum "
            << sys.angle_sum << ", area " << sys.area << std::endl;
}
} // namespace

CGAL_HC_TEST_CASE(issue10_theorem_2_6_geodesic_canonical_system)
{
  typedef SSW::Regular_polygon_surface RPS;
  typedef SSW::Hyperbolic_surface<RPS::Mesh, RPS::Mesh::Property_map<RPS::Edge_index, double> > Surface;
  typedef SSW::Shortest_word_solver<RPS::Mesh, RPS::Mesh::Property_map<RPS::Edge_index, double> > Solver;
  for(int g : {2, 3, 4}) {
    const RPS S(g, 4);
    const Surface s(S.mesh, S.length);
    const Solver given(s, S.base, S.generators);
    check_system(s, given, "regular " + std::to_string(4 * g) + "-gon, its sides");
    const auto sys = SSW::geodesic_canonical_system(given);
    for(double l : sys.lengths) CGAL_HC_CHECK_MSG(std::abs(l - S.side_length()) < 1e-9, l << " vs " << S.side_length());
    const Solver computed(s, S.base);
    check_system(s, computed, "regular " + std::to_string(4 * g) + "-gon, computed canonical system");
    if(g == 2) {
      // bad input: a system that is not the solver's, a work bound too small for the midpoint splits
      auto partial = SSW::geodesic_canonical_system(computed);
      partial.loops.pop_back();
      CGAL_HC_CHECK_THROWS(SSW::geodesic_system_triangulation(s, computed, partial), CGAL::Invalid_input_error);
      const auto csys = SSW::geodesic_canonical_system(computed);
      CGAL_HC_CHECK_THROWS(SSW::geodesic_system_triangulation(s, computed, csys,
                             CGAL::Hyperbolic_surface_mesh_2::parameters::maximum_number_of_insertions(0)),
                           CGAL::Numerical_error);
      CGAL_HC_CHECK_THROWS(SSW::geodesic_system_triangulation(s, computed, csys,
                             CGAL::Hyperbolic_surface_mesh_2::parameters::maximum_number_of_insertions(-1.0)),
                           CGAL::Invalid_input_error);
    }
  }
#if __has_include(<CGAL/Discrete_Ricci_flow.h>)
  typedef CGAL::Ricci_flow::Discrete_metric<CGAL::Epick::Point_3> Metric;
  typedef Metric::Mesh IMesh;
  for(const char* name : {"/meshes/eight.off", "/meshes/elephant.off"}) {
    IMesh input;
    CGAL_HC_CHECK(CGAL::IO::read_polygon_mesh(std::string(CGAL_HC_CGAL_DATA_DIR) + name, input));
    const Metric metric = CGAL::Ricci_flow::hyperbolic_uniformization(input);
    CGAL_HC_CHECK(metric.converged());
    const SSW::Hyperbolic_surface<IMesh, Metric::Edge_length_map> s(metric.intrinsic_mesh(), metric.edge_length_map(), 1e-6);
    for(std::size_t k : {std::size_t(0), std::size_t(7)}) {
      const auto p = *std::next(vertices(metric.intrinsic_mesh()).begin(), std::ptrdiff_t(k));
      const SSW::Shortest_word_solver<IMesh, Metric::Edge_length_map> solver(s, p);
      check_system(s, solver, std::string(name + 8) + " (Ricci), base vertex " + std::to_string(k));
    }
  }
#endif
}
