// Delaunay refinement on closed surfaces: every output face meets the criterion (exact predicates), the
// output is Delaunay, simplicial, of the right Euler characteristic, area and angle sums; bad options throw.
#include "test_support.h"

#include <CGAL/Hyperbolic_surface_mesh_2/internal/Large_block_allocator.h>

#include <cstdint>
#include <string>
#include <vector>

#include <CGAL/Random.h>

using namespace hsm2_test;

namespace {

/// every face meets the criterion, decided independently here with the traits' predicates
void check_criteria(const DT& t, bool chew, double eps, double alpha)
{
  const CGAL::Poincare_disk_traits_2<K> gt;
  const double c = std::cosh(eps), s = std::sin(alpha / 2);
  std::size_t too_big = 0, skinny = 0;
  for(std::size_t f : t.faces()) {
    const auto& z = t.lift(f);
    if(gt.compare_hyperbolic_circumradius_2_object()(z[0], z[1], z[2], c * c) == CGAL::LARGER) ++too_big;
    if(chew) {
      const K::Point_2 o = gt.construct_hyperbolic_circumcenter_2_object()(z[0], z[1], z[2]);
      const double r = DT::Geometry::distance(o, z[0]);
      const double d = (std::min)({t.edge_length(f, 0), t.edge_length(f, 1), t.edge_length(f, 2)});
      if(d < r * (1 - 1e-9)) ++skinny;
    } else if(gt.compare_central_angle_2_object()(z[0], z[1], z[2], s * s) == CGAL::SMALLER) ++skinny;
  }
  CGAL_HC_CHECK_MSG(too_big == 0 && skinny == 0, too_big << " faces too big, " << skinny << " skinny");
}

void check_refined(const DT& t, const HSM::Refinement_statistics& st, int genus, bool chew, double eps, double alpha)
{
  CGAL_HC_CHECK_MSG(st.status == HSM::Refinement_status::SUCCESS, st);
  check_triangulation(t, genus);
  check_criteria(t, chew, eps, alpha);
  CGAL_HC_CHECK(t.is_simplicial_complex() && st.simplicial_complex);
  CGAL_HC_CHECK(st.euler_characteristic == 2 - 2 * genus && st.genus == genus);
  CGAL_HC_CHECK(st.maximum_circumradius <= eps * (1 + 1e-9));
  if(!chew) CGAL_HC_CHECK(st.minimum_central_angle >= alpha * (1 - 1e-9));
  else CGAL_HC_CHECK(st.minimum_central_angle >= CGAL::Hyperbolic_mesh_2::theta_star(eps) * (1 - 1e-6));
  CGAL_HC_CHECK(st.final_vertices == t.number_of_vertices());
}

} // namespace

// The face array of a refinement past 4 MiB (16k faces) comes from the large-block allocator (aligned to
// 2 MiB, huge pages advised): the refined triangulation, a copy of it, and a copy refined further are valid.
CGAL_HC_TEST_CASE(large_face_arrays_and_copies)
{
  {
    std::vector<double, HSM::internal::Large_block_allocator<double> > v(std::size_t(1) << 20), w(100);
    CGAL_HC_CHECK(reinterpret_cast<std::uintptr_t>(v.data()) % (std::uintptr_t(1) << 21) == 0);
    for(std::size_t i = 0; i < v.size(); ++i) v[i] = double(i);
    v.resize(v.size() * 3 + 1, -1.0); // moves the block to a larger one
    bool same = true;
    for(std::size_t i = 0; i < (std::size_t(1) << 20); ++i) same = same && v[i] == double(i);
    CGAL_HC_CHECK(same && v.back() == -1.0 && w.size() == 100);
  }
  DT t(Polygon::regular(2));
  const double eps = 0.03;
  const auto st = HSM::refine_Chew(t, HSMP::maximum_circumradius(eps));
  CGAL_HC_CHECK(t.number_of_faces() > 16384);
  check_refined(t, st, 2, true, eps, 0);
  DT u = t;
  CGAL_HC_CHECK(u.number_of_faces() == t.number_of_faces() && u.number_of_vertices() == t.number_of_vertices());
  const auto su = HSM::refine_Chew(u, HSMP::maximum_circumradius(0.8 * eps));
  check_refined(u, su, 2, true, 0.8 * eps, 0);
  CGAL_HC_CHECK(u.number_of_faces() > t.number_of_faces());
  std::string why;
  CGAL_HC_CHECK_MSG(t.is_valid(&why), why);
}

CGAL_HC_TEST_CASE(refine_regular_polygons)
{
  for(int g : {2, 3, 4}) {
    for(bool chew : {false, true}) {
      for(double eps : {0.6, 0.3}) {
        DT t(Polygon::regular(g));
        const double alpha = 30 * CGAL_PI / 180;
        const auto st = chew ? HSM::refine_Chew(t, HSMP::maximum_circumradius(eps))
                             : HSM::refine_Ruppert(t, HSMP::maximum_circumradius(eps, HSMP::minimum_central_angle(alpha)));
        check_refined(t, st, g, chew, eps, alpha);
        CGAL_HC_CHECK(st.termination_guaranteed);
        CGAL_HC_CHECK(st.h_star == (chew ? eps : 0.0));
      }
    }
  }
}

CGAL_HC_TEST_CASE(refine_from_random_points)
{
  // a triangulation with random points first (not the symmetric one-vertex start); large central-angle bound
  DT t(Polygon::Bolza());
  CGAL::Random rng(11);
  for(int k = 0; k < 50; ++k) t.insert_in_frame(K::Point_2(rng.get_double(-0.7, 0.7), rng.get_double(-0.7, 0.7)));
  const double alpha = 40 * CGAL_PI / 180;
  const auto st = HSM::refine_Ruppert(t, HSMP::maximum_circumradius(0.25, HSMP::minimum_central_angle(alpha)));
  check_refined(t, st, 2, false, 0.25, alpha);
  CGAL_HC_CHECK(st.initial_vertices == 51 && st.circumcenters_inserted > 0);
}

CGAL_HC_TEST_CASE(refine_simplicial_from_coarse)
{
  // epsilon larger than a quarter of the systole (3.057 / 4): the criteria alone may leave loops; the
  // simplicial phase removes them
  DT t(Polygon::Bolza());
  const auto st = HSM::refine_Chew(t, HSMP::maximum_circumradius(2.0));
  CGAL_HC_CHECK_MSG(st.status == HSM::Refinement_status::SUCCESS, st);
  CGAL_HC_CHECK(t.is_simplicial_complex());
  check_triangulation(t, 2);
  // without the simplicial phase: the criteria hold, the result may be a Delta-complex
  DT u(Polygon::Bolza());
  const auto su = HSM::refine_Chew(u, HSMP::maximum_circumradius(2.0, HSMP::make_simplicial(false)));
  CGAL_HC_CHECK(su.status == HSM::Refinement_status::SUCCESS);
  check_criteria(u, true, 2.0, 0);
  CGAL_HC_CHECK(su.simplicial_complex == u.is_simplicial_complex());
}

CGAL_HC_TEST_CASE(refine_options_work_bound_callback)
{
  DT t(Polygon::Bolza());
  CGAL_HC_CHECK_THROWS(HSM::refine_Ruppert(t), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(HSM::refine_Ruppert(t, HSMP::maximum_circumradius(-1.0)), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(HSM::refine_Ruppert(t, HSMP::maximum_circumradius(std::nan(""))), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(HSM::refine_Chew(t, HSMP::maximum_circumradius(20.0)), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(HSM::refine_Ruppert(t, HSMP::maximum_circumradius(0.5, HSMP::minimum_central_angle(0.0))), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(HSM::refine_Ruppert(t, HSMP::maximum_circumradius(0.5, HSMP::minimum_central_angle(2.5))), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(HSM::refine_Ruppert(t, HSMP::maximum_circumradius(0.5, HSMP::maximum_number_of_insertions(-3.0))), CGAL::Invalid_option_error);
  CGAL_HC_CHECK(t.number_of_vertices() == 1); // nothing was modified
  // the work bound stops with a status and a valid Delaunay triangulation
  const auto st = HSM::refine_Ruppert(t, HSMP::maximum_circumradius(0.05, HSMP::maximum_number_of_insertions(500)));
  CGAL_HC_CHECK(st.status == HSM::Refinement_status::WORK_BOUND_REACHED);
  CGAL_HC_CHECK(t.number_of_vertices() == 501);
  check_triangulation(t, 2);
  // the callback is called every 4096 insertions and can cancel
  DT u(Polygon::Bolza());
  std::size_t calls = 0;
  const std::function<bool(const HSM::Refinement_progress&)> cb = [&](const HSM::Refinement_progress& p) {
    ++calls; return p.insertions < 8192;
  };
  const auto su = HSM::refine_Chew(u, HSMP::maximum_circumradius(0.02, CGAL::parameters::callback(cb)));
  CGAL_HC_CHECK(su.status == HSM::Refinement_status::CANCELLED && calls == 2);
  check_triangulation(u, 2);
  // Ruppert beyond the termination hypothesis is reported, not refused
  DT w(Polygon::Bolza());
  const auto sw = HSM::refine_Ruppert(w, HSMP::maximum_circumradius(0.5, HSMP::minimum_central_angle(50 * CGAL_PI / 180)));
  CGAL_HC_CHECK(!sw.termination_guaranteed);
}
