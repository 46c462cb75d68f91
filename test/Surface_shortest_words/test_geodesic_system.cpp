// Thesis Theorem 2.6's setting (issue 10 item 4): the canonical system of shortest geodesic loops through p
// and the fundamental polygon they bound. Checked facts that could fail: every interior point of a loop has
// angle pi on both sides (a geodesic), the loops are simple and pairwise disjoint except at p, the polygon's
// angle sum is 2 pi and its area (a fan of l'Huilier triangles, independent of the angles) 4 pi (g - 1), its
// boundary reads the canonical relator with side k of the length of loop |r_k|, and (on the regular
// polygon surfaces) the loops are the polygon's sides, of the reference side length.
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Surface_shortest_words/geodesic_canonical_system.h>
#include <CGAL/Surface_shortest_words/regular_polygon_surface.h>
#include <CGAL/Curves_on_surface_topology.h>
#if __has_include(<CGAL/Discrete_Ricci_flow.h>)
#include <CGAL/Discrete_Ricci_flow.h>
#endif

#include "cgal_hc_test.h"

#include <cmath>
#include <string>

namespace {
namespace SSW = CGAL::Surface_shortest_words;

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
