// libFuzzer target of Hyperbolic_surface_mesh_2: bytes -> genus, points of the disk (any lift), removals, for
// odd data[0] / 3 a feature loop through the first points (closed by the first point again), and a small
// refinement; every run must end with a valid triangulation or a documented exception.
#include <CGAL/Hyperbolic_surface_mesh_2.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace HSM = CGAL::Hyperbolic_surface_mesh_2;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 2) return 0;
  const int genus = 2 + data[0] % 3;
  const double eps = 0.2 + (data[1] % 64) / 32.0; // 0.2 .. 2.2
  std::vector<double> v;
  for(std::size_t i = 2; i + 8 <= size && v.size() < 400; i += 8) {
    double d; std::memcpy(&d, data + i, 8); v.push_back(d);
  }
  try {
    HSM::Delaunay_triangulation_on_surface<> t(HSM::Fundamental_polygon<K>::regular(genus));
    std::vector<std::size_t> inserted;
    const bool with_loop = (data[0] / 3) % 2 == 1 && v.size() >= 4;
    if(with_loop) { // a feature loop: up to 6 points of the disk, then the first again
      std::vector<K::Point_2> loop;
      for(std::size_t i = 0; i + 1 < v.size() && loop.size() < 2 + std::size_t(data[1] % 5); i += 2) loop.push_back(K::Point_2(v[i], v[i + 1]));
      loop.push_back(loop.front());
      try {
        const auto res = t.insert_feature_loop(loop, 300);
        if(res.complete && t.number_of_constrained_edges() == 0) __builtin_trap();
      }
      catch(const CGAL::Invalid_path_error&) {}       // equal consecutive points
      catch(const CGAL::Poincare_disk_domain_error&) {} // points outside the disk, NaN, infinities
    }
    for(std::size_t i = 0; i + 1 < v.size(); i += 2) {
      try { inserted.push_back(t.insert_in_frame(K::Point_2(v[i], v[i + 1]))); }
      catch(const CGAL::Poincare_disk_domain_error&) {} // points outside the disk, NaN, infinities
    }
    for(std::size_t i = 0; i < inserted.size(); i += 3)
      if(inserted[i] != HSM::Delaunay_triangulation_on_surface<>::null_index && t.is_vertex(inserted[i])) t.remove(inserted[i]);
    // (with a loop fewer insertions: loops crossing at tiny angles run to the work bound, slowly under ASan)
    const HSM::Refinement_statistics st =
      HSM::refine_Chew(t, HSM::parameters::maximum_circumradius(eps, HSM::parameters::maximum_number_of_insertions(with_loop ? 400 : 2000)));
    std::string why;
    if(!t.is_valid(&why, 1e-6) || t.euler_characteristic() != 2 - 2 * genus) __builtin_trap();
    if(st.status == HSM::Refinement_status::SUCCESS) {
      // SUCCESS means what it says (issue 12): a simplicial complex whose every face has a circumradius <= eps,
      // decided by the traits' exact predicate, independently of the refiner's own statistics
      if(!t.is_simplicial_complex() || st.faces_failing_criteria != 0) __builtin_trap();
      const CGAL::Poincare_disk_traits_2<K> gt;
      const double c = std::cosh(eps);
      for(std::size_t f : t.faces()) {
        const auto& z = t.lift(f);
        if(gt.compare_hyperbolic_circumradius_2_object()(z[0], z[1], z[2], c * c) == CGAL::LARGER) __builtin_trap();
      }
    }
  } catch(const CGAL::Numerical_error&) {
    // a documented outcome (a work bound of the walk or of the flips)
  }
  return 0;
}
