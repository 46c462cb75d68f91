// libFuzzer target: PSLG bytes -> insert_geodesic_pslg -> generalized Chew or Ruppert refinement.
// Input rejected by insert_geodesic_pslg (a CGAL::Invalid_input_error) is skipped; anything else must end in a
// valid constrained Delaunay triangulation (CDT::is_valid and an independent exact in-circle test on every
// unconstrained edge) and, if the status is SUCCESS, with every face of the domain meeting the criteria (exact
// rational test) but the counted protected faces. Any violation or other exception aborts. Input size and work
// are bounded (see below) so that one execution takes milliseconds: 10^6 executions are a few hours.
//
// Byte format (missing bytes read as 0):
//   0      flags: bit 0 Chew (else Ruppert), bit 1 corner lopping off, bit 2 off-centers, bit 3 raw doubles
//   1      Ruppert angle bound: 1 + b % 60 degrees
//   2      size bound: 0 -> none, else 0.05 + b / 64
//   3, 4   number of points 3 + b % 8 (at most 10), number of segments b % 11 (at most 10)
//   points raw: two little-endian doubles each; else two uint16: angle 2 pi a / 65536 and radius
//          r = 0.99 v / 32768 for v < 32768, 1 - 10^-(1 + (v - 32768) / 4096) above (up to 1 - 1e-9)
//   segments: two bytes each, point indices modulo the number of points
#include <CGAL/Hyperbolic_mesh_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "hyperbolic_mesh_checks.h"

namespace {

typedef CGAL::Poincare_disk_traits_2<> Gt;
typedef CGAL::Triangulation_vertex_base_2<Gt> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<Gt> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<Gt, Tds, CGAL::Exact_predicates_tag> CDT;
typedef Gt::Point_2 Point;
namespace HM = CGAL::Hyperbolic_mesh_2;

struct Reader
{
  const uint8_t* d; std::size_t n, i = 0;
  uint8_t byte() { return i < n ? d[i++] : 0; }
  uint16_t u16() { const uint16_t lo = byte(); return uint16_t(lo | (uint16_t(byte()) << 8)); }
  double f64() { uint64_t v = 0; for(int k = 0; k < 8; ++k) v |= uint64_t(byte()) << (8 * k); double x; std::memcpy(&x, &v, 8); return x; }
};

[[noreturn]] void violation(const char* what)
{
  std::fprintf(stderr, "fuzz_pslg_mesher: %s\n", what);
  std::abort();
}

// the independent exact checks (interval filter, rational fallback) shared with the tests
using hyperbolic_mesh_checks::locally_Delaunay;
using hyperbolic_mesh_checks::meets_criteria;

// Bounds that keep one execution cheap (a few milliseconds with the sanitizers): at most 10 points and 10
// segments, and a work bound of 120 insertions + removals (the refiner's own bound, checked below). The issue-12
// reproducers that need larger bounds are regression tests of test/Hyperbolic_mesh_2.
constexpr int max_points = 10, max_segments = 10;
constexpr double work_bound = 120;

} // namespace

// Most of an execution was AddressSanitizer's bookkeeping of the many small allocations (GMP rationals of the
// exact fallbacks, the refiner's sets): recording the allocation stack of each one. The reports still name the
// faulty access and its stack; the allocation stack of a reproducer is recovered with
// ASAN_OPTIONS=malloc_context_size=30 (the environment overrides these defaults).
extern "C" const char* __asan_default_options() { return "malloc_context_size=0"; }

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size)
{
  Reader in{data, size};
  const uint8_t flags = in.byte();
  const bool chew = flags & 1, lopping = !(flags & 2), off = (flags & 4) != 0, raw = (flags & 8) != 0;
  const double pi = std::acos(-1.0);
  const double alpha = (1 + in.byte() % 60) * pi / 180;
  const uint8_t eb = in.byte();
  const double eps = eb == 0 ? std::numeric_limits<double>::infinity() : 0.05 + eb / 64.0;
  const int n = 3 + in.byte() % (max_points - 2), m = in.byte() % (max_segments + 1);
  std::vector<Point> pts;
  for(int k = 0; k < n; ++k) {
    if(raw) { const double x = in.f64(), y = in.f64(); pts.push_back(Point(x, y)); continue; }
    const double t = 2 * pi * in.u16() / 65536.0;
    const uint16_t v = in.u16();
    const double r = v < 32768 ? 0.99 * v / 32768.0 : 1 - std::pow(10.0, -(1 + (v - 32768) / 4096.0));
    pts.push_back(Point(r * std::cos(t), r * std::sin(t)));
  }
  std::vector<std::pair<int, int> > segs;
  for(int k = 0; k < m; ++k) { const int a = in.byte() % n, b = in.byte() % n; segs.push_back(std::make_pair(a, b)); }

  CDT cdt;
  try { HM::insert_geodesic_pslg(cdt, pts, segs); } catch(const CGAL::Invalid_input_error&) { return 0; }
  if(cdt.dimension() < 2) return 0;
  const HM::Mesh_parameters<Point> prm =
      HM::Mesh_parameters<Point>().maximum_number_of_operations(work_bound).corner_lopping(lopping).off_centers(off);
  HM::Mesh_statistics st;
  double s2 = 0;
  try {
    if(chew) st = CGAL::refine_hyperbolic_Chew_mesh_2(cdt, CGAL::Hyperbolic_Chew_mesh_criteria_2<CDT>(eps), prm);
    else {
      const CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT> c(alpha, eps);
      s2 = c.sin2_half_alpha();
      st = CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, c, prm);
    }
  } catch(const std::exception& e) {
    std::fprintf(stderr, "exception: %s\n", e.what());
    violation("the refiner threw on input that insert_geodesic_pslg accepted");
  }
  bool valid = false;
  try { valid = cdt.is_valid(); } catch(...) { valid = false; }
  if(!valid) violation("invalid triangulation");
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if(cdt.is_constrained(*e)) continue;
    const CDT::Face_handle f = e->first, g = f->neighbor(e->second);
    if(cdt.is_infinite(f) || cdt.is_infinite(g)) continue;
    if(!locally_Delaunay(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                         cdt.mirror_vertex(f, e->second)->point()))
      violation("an unconstrained edge is not locally Delaunay");
  }
  if(double(st.operations) > work_bound) violation("the work bound was exceeded");
  if(st.status == HM::Refinement_status::SUCCESS) {
    std::size_t failing = 0;
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if(f->is_in_domain() && !meets_criteria(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                                              chew, s2, eps))
        ++failing;
    if(failing > st.protected_faces) violation("SUCCESS with faces failing the criteria (not protected)");
  }
  return 0;
}
