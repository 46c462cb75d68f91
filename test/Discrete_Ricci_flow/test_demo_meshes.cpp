// Tests of the Discrete_Ricci_flow package, part 3: every closed connected manifold mesh of CGAL's demo data
// (quad and polygon meshes triangulated first with CGAL::Polygon_mesh_processing::triangulate_faces):
//   genus >= 2: hyperbolic metric (max |K| <= 1e-10 recomputed by the shared layer, area 4 pi (g - 1)),
//               embedding with every |trace| > 2 and the relator defect <= 1e-8 where it is well conditioned;
//   genus 1:    flat metric (max |K| <= 1e-10) and its lattice parameter tau in the fundamental region;
//   genus 0:    spherical map: every mesh gives a valid map, each with its
//               points on the unit sphere, angle sums 2 pi, area 4 pi, no flipped face, centre of mass at the
//               origin and chords conformally consistent with the input lengths.
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include "cgal_hc_test.h"

#include <algorithm>
#include <map>
#include <set>
#include <filesystem>
#include <sstream>
#include <string>

#include "demo_meshes.h"

namespace {
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace RF = CGAL::Discrete_Ricci_flow;

// the closed connected manifold meshes of the demo data, triangulated; `genus` receives their genus
std::vector<std::pair<std::string, Mesh> > demo_meshes(long genus_min, long genus_max)
{
  return ricci_test::demo_meshes(genus_min, genus_max);
}

double max_abs_curvature(const RF::Discrete_metric<Point_3>& r)
{
  double k = 0;
  for(auto v : r.intrinsic_mesh().vertices()) k = (std::max)(k, std::abs(r.curvature(v)));
  return k;
}
} // namespace

CGAL_HC_TEST_CASE(demo_meshes_genus_at_least_2)
{
  const auto meshes = demo_meshes(2, 1000);
  CGAL_HC_CHECK(meshes.size() >= 12);
  for(const auto& nm : meshes) {
    const std::string& name = nm.first;
    auto r = RF::hyperbolic_uniformization(nm.second);
    CGAL_HC_CHECK_MSG(r.converged(), name << ": " << RF::to_string(r.statistics().status));
    if(!r.converged()) continue;
    const long g = r.genus();
    // the shared layer recomputes the angle sums and the area from the lengths (half-angle, l'Huilier)
    const auto surface = r.hyperbolic_surface();
    CGAL_HC_CHECK_MSG(surface.max_angle_defect() <= 1e-10, name << ": max |K| " << surface.max_angle_defect());
    CGAL_HC_CHECK_MSG(std::abs(surface.area() - 4 * CGAL_PI * (g - 1)) <= 1e-9 * (g - 1), name << ": area " << surface.area());
    const RF::Hyperbolic_embedding<Point_3> emb(r);
    double min_trace = 1e300;
    for(std::size_t i = 0; i < emb.number_of_generators(); ++i) min_trace = (std::min)(min_trace, emb.absolute_trace(i));
    CGAL_HC_CHECK_MSG(min_trace > 2, name << ": a generator is not hyperbolic (|trace| " << min_trace << ")");
    // the relator (the user's double products of the returned deck transformations): below 1e-8 when its
    // partial products stay within cosh d <= 1e5 of the frame's origin (defect / condition is at most 2e-14 on
    // the demo meshes: boeing.off, 1.7e-8 at 8.8e5); the accuracy on every mesh, the frame and the
    // best-conditioned base vertex are checked in test_embedding_accuracy.cpp
    const double defect = emb.relator_defect(), cond = emb.relator_condition();
    CGAL_HC_CHECK_MSG(!std::isnan(defect) && !std::isnan(cond), name); // an overflow is +infinity, never "0"
    if(cond <= 1e5) CGAL_HC_CHECK_MSG(defect <= 1e-8, name << ": relator defect " << defect << ", condition " << cond);
    // the cut and paste to a canonical system (the layer's) at every genus (it threw "a letter appears once
    // only" on turbine.off, genus 11, until the fix of make_canonical; 0.45 s on cheese.off, genus 133); its
    // double defect overflows where the canonical words are long (turbine, cheese: the products of up to
    // thousands of generators), so it is printed, not checked
    CGAL_HC_CHECK_MSG(emb.canonical_words().size() == std::size_t(2 * g), name);
    std::string canonical = "n/a";
    try { std::ostringstream os; os << emb.canonical_relator_defect(); canonical = os.str(); } catch(const CGAL::Numerical_error&) {}
    std::cout << "  " << name << ": genus " << g << ", " << r.statistics().iterations << " iterations, max |K| "
              << surface.max_angle_defect() << ", min |trace| " << min_trace << ", relator defect " << defect
              << " (condition " << cond << "), canonical relator defect " << canonical << std::endl;
  }
}

CGAL_HC_TEST_CASE(demo_meshes_genus_1)
{
  const auto meshes = demo_meshes(1, 1);
  CGAL_HC_CHECK(meshes.size() >= 10);
  for(const auto& nm : meshes) {
    auto r = RF::flat_metric(nm.second);
    CGAL_HC_CHECK_MSG(r.converged(), nm.first << ": " << RF::to_string(r.statistics().status));
    if(!r.converged()) continue;
    CGAL_HC_CHECK_MSG(max_abs_curvature(r) <= 1e-10, nm.first << ": max |K| " << max_abs_curvature(r));
    const RF::Hyperbolic_embedding<Point_3> emb(r);
    const auto tau = emb.lattice_parameter();
    CGAL_HC_CHECK_MSG(std::isfinite(tau.real()) && std::abs(tau.real()) <= 0.5 + 1e-12 && std::abs(tau) >= 1 - 1e-12 && tau.imag() > 0,
                      nm.first << ": tau " << tau);
    CGAL_HC_CHECK_MSG(emb.relator_defect() < 1e-11, nm.first << ": relator defect " << emb.relator_defect()
                      << " (periods " << emb.periods().first << ", " << emb.periods().second << ")");
    std::cout << "  " << nm.first << ": tau = " << tau << ", " << r.statistics().iterations << " iterations" << std::endl;
  }
}

// The flat torus' relator defect is relative to its periods: the same for every scale of the mesh. Each demo
// torus scaled by 2^-400, 2^400 (the flow divides lengths by a power of two: the same computation, periods
// scaled exactly; at 2^-500 the squared input lengths are subnormal) and 1e150: the defect stays at the
// unscaled value (exactly for the powers of two) and below 1e-11; before 2026-12-07 it was the absolute
// translation, about 1e137 at scale 1e150.
CGAL_HC_TEST_CASE(flat_relator_defect_is_scale_invariant)
{
  const auto meshes = demo_meshes(1, 1);
  CGAL_HC_CHECK(meshes.size() >= 10);
  double worst = 0;
  for(const auto& nm : meshes) {
    double d0 = -1;
    for(const double s : {1.0, std::ldexp(1.0, -400), std::ldexp(1.0, 400), 1e150}) {
      Mesh m = nm.second;
      for(auto v : m.vertices()) { const Point_3 p = m.point(v); m.point(v) = Point_3(s * p.x(), s * p.y(), s * p.z()); }
      const auto r = RF::flat_metric(m);
      CGAL_HC_CHECK_MSG(r.converged(), nm.first << " x " << s << ": " << RF::to_string(r.statistics().status));
      if(!r.converged()) continue;
      const RF::Hyperbolic_embedding<Point_3> emb(r);
      const double d = emb.relator_defect();
      worst = (std::max)(worst, d);
      CGAL_HC_CHECK_MSG(d < 1e-11, nm.first << " x " << s << ": relator defect " << d);
      if(s == 1.0) d0 = d;
      else if(s != 1e150) CGAL_HC_CHECK_MSG(d == d0, nm.first << " x " << s << ": relator defect " << d << ", unscaled " << d0);
    }
  }
  std::cout << "  flat tori at scales 1, 2^-400, 2^400, 1e150: relator defect at most " << worst << std::endl;
}

// Conformal consistency of a spherical map: the chords 2 sin(l / 2) of `metric()` are a vertex scaling of the
// input lengths on the input edges that are still edges (Ptolemy flips keep the Penner coordinates of the
// other arcs): chord_ij = e^{(u_i + u_j) / 2} |P_i - P_j|. Each input face whose three edges are still edges
// gives u_i = r_ij + r_ik - r_jk (r = log(chord / length)); returns the largest spread of these estimates of
// one vertex, and in `faces` the number of such faces. Faces with a chord below `min_chord` are left out (the
// long double points resolve a chord of 1e-13 to about 1e-6 only)
double conformal_factor_spread(const Mesh& input, const RF::Spherical_map<Point_3>& s, double min_chord, std::size_t& faces)
{
  const auto& sm = s.metric().intrinsic_mesh();
  std::map<std::pair<std::size_t, std::size_t>, int> count;
  std::map<std::pair<std::size_t, std::size_t>, double> chord;
  for(auto e : sm.edges()) {
    std::size_t a = sm.vertex(e, 0), b = sm.vertex(e, 1);
    if(a > b) std::swap(a, b);
    ++count[{a, b}];
    chord[{a, b}] = 2 * std::sin(0.5 * s.metric().length(e));
  }
  auto r = [&](std::size_t a, std::size_t b, bool& ok) {
    if(a > b) std::swap(a, b);
    const auto it = count.find({a, b});
    if(it == count.end() || it->second != 1) { ok = false; return 0.0; }
    const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(input.point(Mesh::Vertex_index(Mesh::size_type(a))),
                                                                        input.point(Mesh::Vertex_index(Mesh::size_type(b))))));
    return std::log(chord[{a, b}] / len);
  };
  std::vector<double> lo(input.number_of_vertices(), 1e300), hi(input.number_of_vertices(), -1e300);
  faces = 0;
  for(auto f : input.faces()) {
    const auto h = input.halfedge(f);
    const std::size_t v[3] = {input.source(h), input.target(h), input.target(input.next(h))};
    bool ok = true;
    const double r01 = r(v[0], v[1], ok), r12 = r(v[1], v[2], ok), r20 = r(v[2], v[0], ok);
    if(!ok) continue;
    auto c = [&](std::size_t a, std::size_t b) { return chord[{(std::min)(a, b), (std::max)(a, b)}]; };
    if((std::min)({c(v[0], v[1]), c(v[1], v[2]), c(v[2], v[0])}) < min_chord) continue;
    ++faces;
    const double u[3] = {r01 + r20 - r12, r01 + r12 - r20, r12 + r20 - r01};
    for(int i = 0; i < 3; ++i) { lo[v[i]] = (std::min)(lo[v[i]], u[i]); hi[v[i]] = (std::max)(hi[v[i]], u[i]); }
  }
  double spread = 0;
  for(std::size_t i = 0; i < lo.size(); ++i) if(hi[i] >= lo[i]) spread = (std::max)(spread, hi[i] - lo[i]);
  return spread;
}

// Every closed genus-0 demo mesh (55) gives a valid spherical map; each map is checked: points on the unit sphere, angle sums
// of the metric 2 pi, area 4 pi, no flipped face (exact orientation of the double points), centre of mass at
// the origin, conformal consistency with the input lengths. Regression for cow, dino, man (the metric computed
// from the rounded points: angle errors 5e-7 to 2e-6) and camel (the first puncture's flow converged with a
// map of 3156 flipped faces, its limbs compressed below the layout's resolution, and the other punctures were
// not tried) and dragknob (every puncture's flow stagnates at its rounding floor, max |K| 1e-10 to 1e-9, or
// fails: now accepted when stagnated below 1e-8).
CGAL_HC_TEST_CASE(demo_meshes_genus_0_spherical)
{
  const auto meshes = demo_meshes(0, 0);
  CGAL_HC_CHECK(meshes.size() >= 55);
  std::size_t converged = 0;
  std::string failed;
  for(const auto& nm : meshes) {
    try {
      const auto s = RF::spherical_uniformization(nm.second, CGAL::parameters::number_of_iterations(150));
      CGAL_HC_CHECK_MSG(s.converged(), nm.first << ": flow " << RF::to_string(s.statistics().status) << ", max |K| "
                                   << s.statistics().max_curvature_error << ", flipped faces " << s.number_of_flipped_faces()
                                   << ", angle sum error " << s.max_angle_sum_error());
      if(!s.converged()) { failed += " " + nm.first; continue; }
      ++converged;
      double on_sphere = 0;
      for(const auto& p : s.sphere_points()) on_sphere = (std::max)(on_sphere, std::abs(std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()) - 1));
      const double k = max_abs_curvature(s.metric()), area = s.metric().total_area();
      CGAL_HC_CHECK_MSG(on_sphere < 1e-12, nm.first << ": |X| - 1 = " << on_sphere);
      CGAL_HC_CHECK_MSG(k < 1e-8, nm.first << ": max |2 pi - angle sum| " << k);
      CGAL_HC_CHECK_MSG(std::abs(area - 4 * CGAL_PI) < 1e-8, nm.first << ": area " << area);
      CGAL_HC_CHECK_MSG(s.number_of_flipped_faces() == 0, nm.first);
      CGAL_HC_CHECK_MSG(s.center_of_mass_norm() < 1e-10, nm.first);
      CGAL_HC_CHECK(s.metric().intrinsic_mesh().number_of_vertices() == nm.second.number_of_vertices());
      std::size_t faces = 0;
      // measured (2026-12-07): below 1e-9 on most meshes, 1.6e-6 on diplodocus, 9.4e-6 on camel (the flow's
      // residual curvature amplified by the layout across scales of 1e8); a map inconsistent with the input is
      // off by far more
      const double spread = conformal_factor_spread(nm.second, s, 1e-8, faces);
      CGAL_HC_CHECK_MSG(spread < 1e-4, nm.first << ": conformal factors disagree by " << spread << " over " << faces << " faces");
      CGAL_HC_CHECK_MSG(faces > 0, nm.first);
    } catch(const CGAL::Hyperbolic_geometry_error& e) {
      CGAL_HC_CHECK_MSG(false, nm.first << ": " << e.what());
      failed += " " + nm.first + "(" + e.what() + ")";
    }
  }
  std::cout << "  spherical maps: " << converged << " of " << meshes.size() << " valid; not:" << failed << std::endl;
}

namespace {
// deterministic uniform numbers in [-0.5, 0.5) (a 64-bit linear congruential generator: the same on every platform)
struct Uniform
{
  unsigned long long state;
  double operator()()
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / 9007199254740992.0 - 0.5;
  }
};

double mean_edge_length(const Mesh& m)
{
  double mean = 0;
  for(auto e : m.edges()) mean += std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  return mean / double(m.number_of_edges());
}

// m stretched 1000 times along x and shrunk 1000 times along z (triangles with angles down to about 1e-7)
Mesh stretched_1000(Mesh m)
{
  for(auto v : m.vertices()) { const Point_3 p = m.point(v); m.point(v) = Point_3(1000 * p.x(), p.y(), 0.001 * p.z()); }
  return m;
}

// variant 0: scaled by 1e-150; 1: uniform vertex noise of up to 0.3 mean edge lengths per coordinate; 2: stretched
// 30 times along x
Mesh perturbed(const Mesh& m0, int variant, unsigned long long seed)
{
  Mesh m = m0;
  const double mean = mean_edge_length(m0);
  Uniform uniform{seed};
  for(auto v : m.vertices()) {
    const Point_3 p = m.point(v);
    if(variant == 0) m.point(v) = Point_3(1e-150 * p.x(), 1e-150 * p.y(), 1e-150 * p.z());
    if(variant == 1) m.point(v) = Point_3(p.x() + 0.6 * mean * uniform(), p.y() + 0.6 * mean * uniform(), p.z() + 0.6 * mean * uniform());
    if(variant == 2) m.point(v) = Point_3(30 * p.x(), p.y(), p.z());
  }
  return m;
}
} // namespace

// Spherical uniformization of perturbed genus-0 demo meshes (up to 1500 faces): scaled by 1e-150, with vertex
// noise, stretched 30 times along x. Before 2026-12-07 (later),
// 18 of the 114 maps up to 3000 faces failed: the scaled handle.off (no normalization of the input's scale:
// the flow underflowed), the stretched boxes (cheese-box, cube, ...: "the Moebius normalization did not
// converge": with two antipodal clusters of points its scalar step converged by 1% per iteration), corner,
// cross, tripod stretched ("the star of the puncture vertex is not a disk": a Ptolemy flip at the puncture made
// a multi-edge, or a disk flow ended with NUMERICAL_FAILURE on a singular Hessian). Then 4 failed, the stretched
// cross.off, cross_quad.off, dragknob.off and part.off (and corner_with_sharp_edge.off, repaired, when the
// loop took the repaired meshes): their flows reached the iteration bound at every puncture tried, one disk
// flow with a wrong boundary using the whole bound. Since the disk flow of a round is cut at 30 iterations and
// the next round starts warm, every map is valid.
CGAL_HC_TEST_CASE(demo_meshes_genus_0_perturbed)
{
  const auto meshes = demo_meshes(0, 0);
  std::size_t maps = 0, valid = 0;
  for(const auto& nm : meshes) {
    if(nm.second.number_of_faces() > 1500) continue;
    for(int variant = 0; variant < 3; ++variant) {
      const Mesh m = perturbed(nm.second, variant, 12345);
      ++maps;
      try {
        const auto s = RF::spherical_uniformization(m, CGAL::parameters::number_of_iterations(150));
        if(s.converged()) ++valid;
        CGAL_HC_CHECK_MSG(s.converged(), nm.first << " variant " << variant << ": flow " << RF::to_string(s.statistics().status)
                                     << ", flipped faces " << s.number_of_flipped_faces() << ", angle sum error "
                                     << s.max_angle_sum_error() << ", centre " << s.center_of_mass_norm());
        CGAL_HC_CHECK_MSG(!s.converged() || std::abs(s.metric().total_area() - 4 * CGAL_PI) < 1e-8, nm.first << " variant " << variant);
      } catch(const CGAL::Hyperbolic_geometry_error& e) {
        CGAL_HC_CHECK_MSG(false, nm.first << " variant " << variant << ": " << e.what());
      }
    }
  }
  CGAL_HC_CHECK(maps >= 90);
  std::cout << "  perturbed genus-0 meshes: " << valid << " of " << maps << " valid maps" << std::endl;
}

// beam.off (8 vertices, 12 faces) with vertex noise of up to 0.3 mean edge lengths, 40 seeds: every one gives a
// valid spherical map. Before 2026-12-07 (later) 5 of the 40 threw (every candidate puncture failed: the disk
// flow's Hessian was singular, an interior vertex with only degenerate triangles, and the flow ended with
// NUMERICAL_FAILURE, after which the flips at the puncture made its star a multi-edge); the convex flows now
// take a Levenberg-Marquardt shift there (Flow_statistics::number_of_shifted_factorizations: 38 over the 40
// maps; none since a round's disk flow is cut at 30 iterations), the flips at the puncture keep its star a
// disk, and small meshes try more punctures
CGAL_HC_TEST_CASE(noisy_beam_spherical_maps)
{
  const Mesh mesh = ricci_test::demo_mesh("beam.off");
  CGAL_HC_CHECK(!mesh.is_empty());
  if(mesh.is_empty()) return;
  std::size_t shifted = 0;
  for(unsigned long long seed = 1; seed <= 40; ++seed) {
    const Mesh m = perturbed(mesh, 1, seed);
    try {
      const auto s = RF::spherical_uniformization(m);
      CGAL_HC_CHECK_MSG(s.converged(), "seed " << seed << ": " << RF::to_string(s.statistics().status));
      shifted += s.statistics().number_of_shifted_factorizations;
    } catch(const CGAL::Hyperbolic_geometry_error& e) {
      CGAL_HC_CHECK_MSG(false, "seed " << seed << ": " << e.what());
    }
  }
  std::cout << "  noisy beam.off: " << shifted << " shifted factorizations over 40 maps" << std::endl;
}

// corner_with_sharp_edge.off (a soup of 18 polygons that stitches into a closed genus-0 mesh of 17 vertices)
// stretched 30 times along x: before the disk flow of a round was cut at 30 iterations, every one of the 17
// punctures failed (iteration bound, or a triangulation that is not simplicial). Then the default map and 2
// others were valid, among them puncture vertex 2's. Since the line search rejects overshooting trial points
// (2026-12-07, evening) 16 of the 17 are. Some of these disk flows have singular Hessians (an interior vertex
// with only degenerate triangles) and take Levenberg-Marquardt shifts: the only demo input of the suite that
// exercises them since the round limit (noisy beam.off needed 38 before it), so a valid map that took shifts
// is required. Every puncture gives a map or a Numerical_error.
CGAL_HC_TEST_CASE(stretched_corner_every_puncture)
{
  const Mesh mesh = ricci_test::demo_mesh("corner_with_sharp_edge.off"); // repaired: it is a soup
  CGAL_HC_CHECK(!mesh.is_empty());
  if(mesh.is_empty()) return;
  const Mesh m = perturbed(mesh, 2, 0);
  const auto d = RF::spherical_uniformization(m, CGAL::parameters::number_of_iterations(150));
  CGAL_HC_CHECK_MSG(d.converged(), RF::to_string(d.statistics().status) << ", flipped faces " << d.number_of_flipped_faces());
  std::size_t valid = 0, errors = 0, shifted = 0, valid_shifted = 0;
  std::string shifted_punctures;
  for(std::size_t p = 0; p < m.number_of_vertices(); ++p) {
    try {
      const auto s = RF::spherical_uniformization(m, RF::parameters::puncture_vertex(p, CGAL::parameters::number_of_iterations(150)));
      if(s.converged()) ++valid;
      if(p == 2) CGAL_HC_CHECK_MSG(s.converged(), "puncture 2: " << RF::to_string(s.statistics().status));
      const std::size_t k = s.statistics().number_of_shifted_factorizations;
      if(k > 0) shifted_punctures += " " + std::to_string(p) + (s.converged() ? "" : "(invalid)");
      if(k > 0 && s.converged()) ++valid_shifted;
      shifted += k;
    } catch(const CGAL::Numerical_error&) { ++errors; }
  }
  std::cout << "  stretched corner_with_sharp_edge.off: " << valid << " of " << m.number_of_vertices() << " punctures valid, "
            << errors << " numerical errors, " << shifted << " shifted factorizations (punctures" << shifted_punctures << ")" << std::endl;
  CGAL_HC_CHECK_MSG(valid_shifted > 0, "no valid map took a shifted factorization");
}

// triceratops.off stretched 30 times along x, puncture vertex 0: the disk flow converges (max |K| 1e-11), but
// the map shrinks the limbs to edges of 1e-26 at coordinates of 1. The layout fitted each face's chart to two
// parent points that coincide there and threw "non-finite layout"; it now composes chart transitions, so the
// points are finite and on the sphere, and the map reports that it is not valid (flipped faces).
CGAL_HC_TEST_CASE(stretched_triceratops_layout_is_finite)
{
  const Mesh mesh = ricci_test::demo_mesh("triceratops.off");
  CGAL_HC_CHECK(!mesh.is_empty());
  if(mesh.is_empty()) return;
  const Mesh m = perturbed(mesh, 2, 0);
  try {
    const auto s = RF::spherical_uniformization(m, RF::parameters::puncture_vertex(0, CGAL::parameters::number_of_iterations(150)));
    CGAL_HC_CHECK_MSG(s.statistics().status == RF::Flow_status::CONVERGED, RF::to_string(s.statistics().status));
    double on_sphere = 0;
    for(const auto& p : s.sphere_points()) {
      const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
      on_sphere = std::isfinite(r) ? (std::max)(on_sphere, std::abs(r - 1)) : HUGE_VAL;
    }
    CGAL_HC_CHECK_MSG(on_sphere < 1e-12, "|X| - 1 = " << on_sphere);
    CGAL_HC_CHECK_MSG(s.converged() == (s.number_of_flipped_faces() == 0 && s.max_angle_sum_error() < 1e-8),
                      "converged() " << s.converged() << " with " << s.number_of_flipped_faces() << " flipped faces");
    std::cout << "  stretched triceratops.off, puncture 0: converged() " << s.converged() << ", " << s.number_of_flipped_faces()
              << " flipped faces" << std::endl;
  } catch(const CGAL::Hyperbolic_geometry_error& e) {
    CGAL_HC_CHECK_MSG(false, e.what());
  }
}

// A convex flow never accepts a step that its energy estimate (the trapezoidal rule on the gradients) says
// increased the energy. joint.off stretched 1000 times along x and shrunk 1000 times along z (triangles with
// angles down to 4e-8): before 2026-12-07 (later) the line search accepted such steps when the max error
// decreased, and the flow cycled through the same 10 iterates until MAXIMUM_ITERATIONS (max |K| 3.3); now it
// reaches its rounding floor (STAGNATED, max |K| about 3e-8). The checks are the outcome: the final max |K| and
// a status other than the iteration bound. (The recorded `energy_history` is the sum of the accepted estimates,
// each <= 0 by the acceptance rule: it cannot increase by construction, so it is no check.)
CGAL_HC_TEST_CASE(stretched_joint_reaches_its_rounding_floor)
{
  const Mesh m = stretched_1000(ricci_test::demo_mesh("joint.off"));
  CGAL_HC_CHECK(!m.is_empty());
  if(m.is_empty()) return;
  const auto r = RF::hyperbolic_uniformization(m);
  const auto& st = r.statistics();
  CGAL_HC_CHECK_MSG(st.max_curvature_error < 1e-6, RF::to_string(st.status) << ", max |K| " << st.max_curvature_error);
  CGAL_HC_CHECK_MSG(st.status != RF::Flow_status::MAXIMUM_ITERATIONS, RF::to_string(st.status));
  std::cout << "  joint.off stretched: " << RF::to_string(st.status) << " after " << st.iterations << " iterations, max |K| "
            << st.max_curvature_error << std::endl;
}

namespace {
// `file` stretched 1000 times along x and shrunk 1000 times along z, then `flow`: the state a flow that did
// not converge returns must have finite positive lengths; its angle sums (Discrete_metric::curvature(), from
// the returned lengths) give the reported error; and after a failed line search it is the last accepted
// iterate, whose error is the last of `error_history`
template <class Flow>
void check_stretched_flow_returns_its_state(const std::string& file, Flow flow)
{
  const Mesh m = stretched_1000(ricci_test::demo_mesh(file));
  CGAL_HC_CHECK(!m.is_empty());
  if(m.is_empty()) return;
  try {
    const RF::Discrete_metric<Point_3> r = flow(m);
    const auto& st = r.statistics();
    std::cout << "  " << file << " stretched: " << RF::to_string(st.status) << " after " << st.iterations
              << " iterations, max |K| " << st.max_curvature_error << ", " << st.number_of_flips << " flips" << std::endl;
    CGAL_HC_CHECK_MSG(std::isfinite(st.max_curvature_error), st.max_curvature_error);
    double lmin = HUGE_VAL, lmax = 0;
    for(auto e : r.intrinsic_mesh().edges()) { lmin = (std::min)(lmin, r.length(e)); lmax = (std::max)(lmax, r.length(e)); }
    CGAL_HC_CHECK_MSG(lmin > 0 && std::isfinite(lmax), "lengths in [" << lmin << ", " << lmax << "]");
    const double k = max_abs_curvature(r);
    CGAL_HC_CHECK_MSG(std::abs(k - st.max_curvature_error) <= 1e-9 * (1 + k), "max |K| " << k << ", reported " << st.max_curvature_error);
    if(st.status == RF::Flow_status::LINE_SEARCH_FAILED) {
      CGAL_HC_CHECK(!st.error_history.empty());
      if(!st.error_history.empty())
        CGAL_HC_CHECK_MSG(st.max_curvature_error == st.error_history.back(),
                          "reported " << st.max_curvature_error << ", last accepted iterate " << st.error_history.back());
    }
  } catch(const CGAL::Numerical_error& e) {
    CGAL_HC_CHECK_MSG(false, e.what());
  }
}
} // namespace

// A failed line search returns to its start, triangulation included: the rejected trials' Ptolemy flips are
// undone (`Flow_engine::undo_flips()`), not flipped back at the start's u. elk.off (genus 1) stretched 1000
// times along x and shrunk 1000 times along z, flat metric: far from any solution (u from -1118 to 162 at a
// trial point) those flips left Penner coordinates from 0 to 6e307, the start's lengths were lost, and after
// 165 iterations the flow threw "the initial state of the scheme has zero, non-finite or overflowing edge
// lengths", which was not the cause. It now ends with a failure status and its last accepted iterate: finite,
// positive lengths whose angle sums are the reported error (LINE_SEARCH_FAILED at max |K| 5.6: the flow is far
// from a metric double arithmetic can represent, and says so by its status).
CGAL_HC_TEST_CASE(failed_line_search_restores_its_start)
{
  // (before the usable-length bound the returned metric's angle sums gave 23.935 against a reported 23.946)
  check_stretched_flow_returns_its_state("elk.off", [](const Mesh& m) { return RF::flat_metric(m, CGAL::parameters::number_of_iterations(400)); });
}

// The flips back at the start of a failed line search can end in another state: anchor.off (genus 4) stretched
// 1000 times, hyperbolic, ended its last line search (from max |K| 24.8) in a state at 84.4 and returned that.
// A step that fails now returns to its start exactly (`Newton_solver::return_to_start()`)
CGAL_HC_TEST_CASE(failed_line_search_returns_the_last_iterate)
{
  check_stretched_flow_returns_its_state("anchor.off", [](const Mesh& m) { return RF::hyperbolic_uniformization(m); });
}

// The trapezoid can say that the energy fell where it rose: past the minimum on the line, across flips, the
// gradient grows in kinks. mpi_triang.off (genus 1) stretched 1000 times along x and shrunk 1000 times along z:
// before the line search rejected trial points whose slope exceeds a quarter of the initial descent rate
// (`Newton_solver::line_search()`), the flat flow wandered at max |K| 12 to 24 (a scratch driver reading the
// file directly: FLIP_LIMIT_REACHED after 129 iterations; now STAGNATED at 4.5e-7 after 187). With this test's
// loader (another vertex order) it now reaches max |K| about 1.4e-6 in 400 iterations; the default bound of 100
// iterations is not enough for this mesh. (The recorded energy, the sum of the accepted trapezoidal estimates,
// cannot increase by construction, so it is no check here; the final max |K| is.)
CGAL_HC_TEST_CASE(stretched_torus_rejects_overshooting_steps)
{
  const Mesh m = stretched_1000(ricci_test::demo_mesh("mpi_triang.off"));
  CGAL_HC_CHECK(!m.is_empty());
  if(m.is_empty()) return;
  const auto r = RF::flat_metric(m, CGAL::parameters::number_of_iterations(400));
  const auto& st = r.statistics();
  std::cout << "  mpi_triang.off stretched: " << RF::to_string(st.status) << " after " << st.iterations
            << " iterations, max |K| " << st.max_curvature_error << ", " << st.number_of_flips << " flips" << std::endl;
  CGAL_HC_CHECK_MSG(st.max_curvature_error < 1e-5, RF::to_string(st.status) << ", max |K| " << st.max_curvature_error);
  CGAL_HC_CHECK_MSG(st.status != RF::Flow_status::FLIP_LIMIT_REACHED, RF::to_string(st.status));
}
