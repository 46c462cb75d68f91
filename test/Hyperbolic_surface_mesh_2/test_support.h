// Shared checks of the Hyperbolic_surface_mesh_2 tests: validity of every triangulation produced.
#ifndef CGAL_HSM2_TEST_SUPPORT_H
#define CGAL_HSM2_TEST_SUPPORT_H

#include "cgal_hc_test.h"

#include <CGAL/Hyperbolic_surface_mesh_2.h>

#include <cmath>
#include <string>

namespace HSM = CGAL::Hyperbolic_surface_mesh_2;
namespace HSMP = CGAL::Hyperbolic_surface_mesh_2::parameters;

namespace hsm2_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::Hyperbolic_surface_mesh_2::Delaunay_triangulation_on_surface<> DT;
typedef CGAL::Hyperbolic_surface_mesh_2::Fundamental_polygon<K> Polygon;

/// Every check of the issue on one triangulation: valid structure, every edge locally Delaunay (exact
/// in-circle), angle sum 2 pi at every vertex, area 4 pi (g - 1), Euler characteristic 2 - 2g.
inline void check_triangulation(const DT& t, int genus, bool require_delaunay = true, double angle_tol = 1e-7)
{
  std::string why;
  CGAL_HC_CHECK_MSG(t.is_valid(&why), why);
  if(require_delaunay) CGAL_HC_CHECK(t.is_delaunay());
  CGAL_HC_CHECK_MSG(t.euler_characteristic() == 2 - 2 * genus, "chi = " << t.euler_characteristic());
  const double expected = 4 * CGAL_PI * (genus - 1);
  CGAL_HC_CHECK_MSG(std::abs(t.area() - expected) < 1e-8 * expected, "area " << t.area() << " vs " << expected);
  double worst = 0;
  for(std::size_t v : t.vertices()) worst = (std::max)(worst, std::abs(t.angle_sum(v) - 2 * CGAL_PI));
  CGAL_HC_CHECK_MSG(worst < angle_tol, "angle sum defect " << worst);
}

/// For cocircular point sets the exact in-circle of rounded lifts may go either way: every edge that is not
/// locally Delaunay must then have a cocircular quadrilateral (the neighbour's apex on the face's circumcircle
/// up to 1e-9).
inline void check_delaunay_up_to_rounding(const DT& t)
{
  const CGAL::Poincare_disk_traits_2<K> gt;
  std::size_t bad = 0;
  double worst = 0;
  for(std::size_t f : t.faces())
    for(int i = 0; i < 3; ++i) {
      if(t.is_locally_delaunay(f, i)) continue;
      const auto& z = t.lift(f);
      const Point c = gt.construct_hyperbolic_circumcenter_2_object()(z[0], z[1], z[2]);
      const double r = DT::Geometry::distance(c, z[0]), d = DT::Geometry::distance(c, t.neighbor_apex(f, i));
      worst = (std::max)(worst, std::abs(r - d));
      if(!(std::abs(r - d) < 1e-9 * (1 + r))) ++bad;
    }
  CGAL_HC_CHECK_MSG(bad == 0, bad << " non-Delaunay edges are not cocircular, worst |r - d| = " << worst);
}

} // namespace hsm2_test

#endif
