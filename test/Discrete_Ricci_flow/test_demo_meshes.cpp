// Tests of the Discrete_Ricci_flow package, part 3: every closed connected manifold mesh of CGAL's demo data
// (quad and polygon meshes triangulated first with CGAL::Polygon_mesh_processing::triangulate_faces):
//   genus >= 2: hyperbolic metric (max |K| <= 1e-10 recomputed by the shared layer, area 4 pi (g - 1)),
//               embedding with every |trace| > 2 and the relator defect <= 1e-8 where it is well conditioned;
//   genus 1:    flat metric (max |K| <= 1e-10) and its lattice parameter tau in the fundamental region;
//   genus 0:    spherical map: every converged map has its points on the unit sphere, angle sums 2 pi,
//               area 4 pi, no flipped face, centre of mass at the origin; the number of converged maps has a
//               floor (the meshes that fail are listed, see the manual's limitations).
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include "cgal_hc_test.h"

#include <algorithm>
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
    // partial products stay within cosh d <= 1e6 of the frame's origin; the accuracy on every mesh, the frame
    // and the best-conditioned base vertex are checked in test_embedding_accuracy.cpp
    const double defect = emb.relator_defect(), cond = emb.relator_condition();
    CGAL_HC_CHECK_MSG(!std::isnan(defect) && !std::isnan(cond), name); // an overflow is +infinity, never "0"
    if(cond <= 1e6) CGAL_HC_CHECK_MSG(defect <= 1e-8, name << ": relator defect " << defect << ", condition " << cond);
    std::string canonical = "n/a";
    // (the cut and paste to a canonical system, owned by the layer, is slow at high genus: run up to genus 4 here)
    if(g <= 4) try { canonical = std::to_string(emb.canonical_relator_defect()); } catch(const CGAL::Numerical_error&) {}
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
    const auto per = emb.periods();
    CGAL_HC_CHECK_MSG(emb.relator_defect() < 1e-9 * (1 + std::abs(per.first) + std::abs(per.second)),
                      nm.first << ": relator defect " << emb.relator_defect() << " (periods " << per.first << ", " << per.second << ")");
    std::cout << "  " << nm.first << ": tau = " << tau << ", " << r.statistics().iterations << " iterations" << std::endl;
  }
}

CGAL_HC_TEST_CASE(demo_meshes_genus_0_spherical)
{
  const auto meshes = demo_meshes(0, 0);
  CGAL_HC_CHECK(meshes.size() >= 50);
  std::size_t converged = 0;
  std::string failed;
  for(const auto& nm : meshes) {
    try {
      const auto s = RF::spherical_uniformization(nm.second, CGAL::parameters::number_of_iterations(150));
      if(!s.converged()) { failed += " " + nm.first; continue; }
      ++converged;
      double on_sphere = 0;
      for(const auto& p : s.sphere_points()) on_sphere = (std::max)(on_sphere, std::abs(std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()) - 1));
      const double k = max_abs_curvature(s.metric()), area = s.metric().total_area();
      CGAL_HC_CHECK_MSG(on_sphere < 1e-12, nm.first << ": |X| - 1 = " << on_sphere);
      CGAL_HC_CHECK_MSG(k < 1e-8, nm.first << ": max |2 pi - angle sum| " << k);
      CGAL_HC_CHECK_MSG(std::abs(area - 4 * CGAL_PI) < 1e-8, nm.first << ": area " << area);
      CGAL_HC_CHECK(s.number_of_flipped_faces() == 0);
      CGAL_HC_CHECK(s.center_of_mass_norm() < 1e-10);
      CGAL_HC_CHECK(s.metric().intrinsic_mesh().number_of_vertices() == nm.second.number_of_vertices());
    } catch(const CGAL::Hyperbolic_geometry_error& e) {
      failed += " " + nm.first + "(" + e.what() + ")";
    }
  }
  std::cout << "  spherical maps: " << converged << " of " << meshes.size() << " converged; not:" << failed << std::endl;
  CGAL_HC_CHECK_MSG(converged >= 50, converged << " of " << meshes.size());
}
