// Benchmark of Hyperbolic_mesh_2 (not run by CTest).
//
// 1. Throughput: output triangles per second of the generalized Ruppert and Chew algorithms on growing sizes
//    (up to ~1e6 triangles with the default max level), next to CGAL::refine_Delaunay_mesh_2 (Euclidean, B = 0.125)
//    on the Euclidean-limit version of the same PSLG, measured in the same run. The hyperbolic Ruppert run on the
//    Euclidean-limit PSLG (scaled into a disk of radius 1e-3) uses the same quality bound B = 0.125 and the
//    circumradius bound matching Mesh_2's edge bound, so the two do the same work.
// 2. Vertex counts at equal quality: Chew (central angle >= theta*(r), r <= eps) vs Ruppert and Ruppert with
//    off-centers (central angle >= theta*(eps), r <= eps).
//
// Usage: benchmark_hyperbolic_mesh [max_level (default 6)]
// Output: one line per measurement, "key=value" pairs.
#include <CGAL/Hyperbolic_mesh_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cstdlib>
#include <limits>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Poincare_disk_traits_2<> Gt;
typedef CGAL::Triangulation_vertex_base_2<Gt> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<Gt> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<Gt, Tds, CGAL::Exact_predicates_tag> CDT;
typedef Gt::Point_2 Point;
namespace HM = CGAL::Hyperbolic_mesh_2;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_2<K> EVb;
typedef CGAL::Delaunay_mesh_face_base_2<K> EFb;
typedef CGAL::Triangulation_data_structure_2<EVb, EFb> ETds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, ETds> ECDT;

static const double PI = std::acos(-1.0);

struct Pslg { std::vector<Point> points; std::vector<std::pair<int, int> > segments; std::vector<Point> seeds; };

// a regular octagon (Poincare radius 0.6) with a hexagonal hole, scaled by s
static Pslg octagon_with_hole(double s)
{
  Pslg g;
  for(int i = 0; i < 8; ++i) g.points.push_back(Point(s * 0.6 * std::cos(2 * PI * i / 8), s * 0.6 * std::sin(2 * PI * i / 8)));
  for(int i = 0; i < 8; ++i) g.segments.push_back(std::make_pair(i, (i + 1) % 8));
  for(int i = 0; i < 6; ++i)
    g.points.push_back(Point(s * 0.15 * std::cos(0.3 + 2 * PI * i / 6), s * 0.15 * std::sin(0.3 + 2 * PI * i / 6)));
  for(int i = 0; i < 6; ++i) g.segments.push_back(std::make_pair(8 + i, 8 + (i + 1) % 6));
  g.seeds.push_back(Point(0, 0));
  return g;
}

static std::size_t in_domain_faces(const CDT& cdt)
{
  std::size_t n = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) n += f->is_in_domain() ? 1 : 0;
  return n;
}

template <class F>
static double seconds_of(const F& f)
{
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int main(int argc, char** argv)
{
  const int max_level = argc > 1 ? std::atoi(argv[1]) : 6;
  std::cout.precision(6);

  // ---------------------------------------------------------------- 1. throughput
  for(int level = 0; level <= max_level; ++level) {
    const double S_e = 0.1 / std::pow(2.0, level);  // Mesh_2 edge bound, Euclidean PSLG at scale 1
    // Mesh_2 (Euclidean, B = 0.125, edge <= S_e)
    const Pslg ge = octagon_with_hole(1.0);
    ECDT e;
    std::vector<ECDT::Vertex_handle> vh;
    for(const Point& p : ge.points) vh.push_back(e.insert(K::Point_2(p.x(), p.y())));
    for(const auto& s : ge.segments) e.insert_constraint(vh[s.first], vh[s.second]);
    std::vector<K::Point_2> eseeds(1, K::Point_2(0, 0));
    const double t_mesh2 = seconds_of([&] {
      CGAL::refine_Delaunay_mesh_2(e, eseeds.begin(), eseeds.end(), CGAL::Delaunay_mesh_size_criteria_2<ECDT>(0.125, S_e));
    });
    std::size_t tri_mesh2 = 0;
    for(auto f = e.finite_faces_begin(); f != e.finite_faces_end(); ++f) tri_mesh2 += f->is_in_domain() ? 1 : 0;
    const double tps_mesh2 = double(tri_mesh2) / t_mesh2;
    std::cout << "bench=throughput level=" << level << " method=Mesh_2_euclidean triangles=" << tri_mesh2
              << " vertices=" << e.number_of_vertices() << " seconds=" << t_mesh2
              << " triangles_per_second=" << tps_mesh2 << " ratio_to_Mesh_2=1\n";

    // hyperbolic Ruppert on the Euclidean-limit PSLG: scale 1e-3; circumradius bound: Mesh_2's edge bound S is
    // reached by triangles with circumradius about S / sqrt(3); hyperbolic lengths near 0 are 2x Euclidean ones
    const double s = 1e-3;
    auto run_h = [&](const Pslg& g, const std::string& method, auto&& refine) {
      CDT cdt;
      HM::insert_geodesic_pslg(cdt, g.points, g.segments);
      HM::Mesh_statistics st;
      const double t = seconds_of([&] { st = refine(cdt, g); });
      const std::size_t tri = in_domain_faces(cdt);
      std::cout << "bench=throughput level=" << level << " method=" << method << " triangles=" << tri
                << " vertices=" << cdt.number_of_vertices() - st.frame_vertices << " seconds=" << t
                << " triangles_per_second=" << double(tri) / t << " ratio_to_Mesh_2=" << (double(tri) / t) / tps_mesh2
                << " status=" << HM::to_string(st.status) << "\n";
    };
    const Pslg gl = octagon_with_hole(s);
    run_h(gl, "Ruppert_euclidean_limit", [&](CDT& cdt, const Pslg& g) {
      return CGAL::refine_hyperbolic_Ruppert_mesh_2(
          cdt, CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>::from_sin2_half_angle(0.125, 2 * s * S_e / std::sqrt(3.0)),
          HM::Mesh_parameters<Point>().seeds(g.seeds.begin(), g.seeds.end()).maximum_number_of_operations(2e7));
    });
    // genuinely hyperbolic runs on the PSLG at scale 1, with a hyperbolic circumradius bound eps
    const double eps = 2 * S_e / std::sqrt(3.0);
    const Pslg gh = octagon_with_hole(1.0);
    run_h(gh, "Ruppert_hyperbolic_B0.125", [&](CDT& cdt, const Pslg& g) {
      return CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>::from_sin2_half_angle(0.125, eps),
                                                    HM::Mesh_parameters<Point>().seeds(g.seeds.begin(), g.seeds.end()).maximum_number_of_operations(2e7));
    });
    run_h(gh, "Chew_hyperbolic", [&](CDT& cdt, const Pslg& g) {
      return CGAL::refine_hyperbolic_Chew_mesh_2(cdt, CGAL::Hyperbolic_Chew_mesh_criteria_2<CDT>(eps),
                                                 HM::Mesh_parameters<Point>().seeds(g.seeds.begin(), g.seeds.end()).maximum_number_of_operations(2e7));
    });
  }

  // ---------------------------------------------------------------- 2. vertex counts at equal quality
  for(double eps : {0.2, 0.1, 0.05, 0.025}) {
    const double alpha = HM::theta_star(eps); // Chew's guaranteed central angle
    const Pslg g = octagon_with_hole(1.0);
    auto count = [&](const std::string& method, auto&& refine) {
      CDT cdt;
      HM::insert_geodesic_pslg(cdt, g.points, g.segments);
      HM::Mesh_statistics st;
      const double t = seconds_of([&] { st = refine(cdt); });
      std::cout << "bench=equal_quality eps=" << eps << " alpha_deg=" << alpha * 180 / PI << " method=" << method
                << " vertices=" << st.final_vertices - st.frame_vertices << " triangles=" << in_domain_faces(cdt)
                << " min_central_angle_deg=" << st.minimum_central_angle * 180 / PI
                << " max_circumradius=" << st.maximum_circumradius << " seconds=" << t
                << " status=" << HM::to_string(st.status) << "\n";
    };
    const auto prm = HM::Mesh_parameters<Point>().seeds(g.seeds.begin(), g.seeds.end());
    count("Chew", [&](CDT& cdt) {
      return CGAL::refine_hyperbolic_Chew_mesh_2(cdt, CGAL::Hyperbolic_Chew_mesh_criteria_2<CDT>(eps), prm);
    });
    count("Ruppert", [&](CDT& cdt) {
      return CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>(alpha, eps), prm);
    });
    count("Ruppert_off_centers", [&](CDT& cdt) {
      auto p = prm; p.off_centers(true);
      return CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>(alpha, eps), p);
    });
  }

  // ---------------------------------------------------------------- 3. angle only: circumcenters vs off-centers
  Pslg cloud;
  {
    std::srand(11);
    while(cloud.points.size() < 3000) {
      const double x = 1.6 * std::rand() / RAND_MAX - 0.8, y = 1.6 * std::rand() / RAND_MAX - 0.8;
      if(x * x + y * y < 0.64) cloud.points.push_back(Point(x, y));
    }
  }
  for(double alpha_deg : {40.0, 50.0, 60.0, 66.0})
  for(int input = 0; input < 2; ++input) {
    const Pslg g = input == 0 ? octagon_with_hole(1.0) : cloud;
    const double eps = input == 0 ? 0.05 : std::numeric_limits<double>::infinity();
    for(int off = 0; off < 2; ++off) {
      CDT cdt;
      HM::insert_geodesic_pslg(cdt, g.points, g.segments);
      HM::Mesh_statistics st;
      const double t = seconds_of([&] {
        st = CGAL::refine_hyperbolic_Ruppert_mesh_2(
            cdt, CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>(alpha_deg * PI / 180, eps),
            HM::Mesh_parameters<Point>().seeds(g.seeds.begin(), g.seeds.end()).off_centers(off == 1).maximum_number_of_operations(2e6));
      });
      std::cout << "bench=off_centers input=" << (input == 0 ? "octagon_with_hole" : "cloud_3000") << " alpha_deg="
                << alpha_deg << " eps=" << eps << " method=" << (off ? "Ruppert_off_centers" : "Ruppert")
                << " vertices=" << st.final_vertices - st.frame_vertices << " off_centers=" << st.off_centers_inserted
                << " min_central_angle_deg=" << st.minimum_central_angle * 180 / PI << " seconds=" << t
                << " status=" << HM::to_string(st.status) << "\n";
    }
  }
  return 0;
}
