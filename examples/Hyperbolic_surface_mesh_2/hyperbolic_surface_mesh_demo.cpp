// The main job of Hyperbolic_surface_mesh_2: conformal remeshing of a closed genus-2 mesh.
// Usage: hyperbolic_surface_mesh_demo [mesh file] [epsilon] (default: CGAL's eight.off, 0.1)
// Ricci flow -> hyperbolic surface -> Delaunay refinement on the surface (generalized Ruppert, alpha = 30
// degrees) -> remeshed OFF in R^3, SVG pictures of the refined surface in the Poincare disk (a fundamental
// domain and its neighbouring copies, faces coloured by quality) and of the central angles, and a summary
// (sizes, angles in R^3 before and after, time per stage). Also the Bolza surface from its octagon.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Hyperbolic_surface_mesh_2.h>
#include <CGAL/Hyperbolic_surface_mesh_2/conformal_remesh.h>
#include <CGAL/Hyperbolic_surface_mesh_2/IO/write_surface_mesh_svg.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HSM = CGAL::Hyperbolic_surface_mesh_2;
namespace HSMP = CGAL::Hyperbolic_surface_mesh_2::parameters;

static void print_angles(const char* what, const Mesh& m)
{
  std::vector<double> a = HSM::corner_angles(m);
  std::sort(a.begin(), a.end());
  const double deg = 180 / CGAL_PI;
  std::size_t below30 = std::size_t(std::lower_bound(a.begin(), a.end(), 30 / deg) - a.begin());
  std::cout << "  " << std::setw(8) << what << ": " << m.number_of_vertices() << " vertices, " << m.number_of_faces()
            << " faces; R^3 angles min " << a.front() * deg << ", 5% " << a[a.size() / 20] * deg << ", median "
            << a[a.size() / 2] * deg << ", 95% " << a[a.size() * 19 / 20] * deg << ", max " << a.back() * deg
            << " degrees; below 30 degrees: " << 100.0 * double(below30) / double(a.size()) << "%\n";
}

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/eight.off";
  const double eps = argc > 2 ? std::atof(argv[2]) : 0.1;
  try {
    // ---- the Bolza surface from its octagon
    HSM::Delaunay_triangulation_on_surface<> bolza(HSM::Fundamental_polygon<K>::Bolza());
    const auto sb = HSM::refine_Ruppert(bolza, HSMP::maximum_circumradius(0.25));
    std::cout << "Bolza octagon, Ruppert epsilon 0.25: " << sb << "\n";
    HSM::write_surface_mesh_svg(bolza, "surface_mesh_bolza.svg", true, "Bolza surface, generalized Ruppert, epsilon 0.25");

    // ---- feature loops on the Bolza surface: the four axes of the side pairings (closed geodesics through the
    //      midpoints of paired sides) and a geodesic 12-gon about the midpoint of side 0 that crosses side 0
    {
      const auto P = HSM::Fundamental_polygon<K>::Bolza();
      HSM::Delaunay_triangulation_on_surface<> loops(P);
      const CGAL::Poincare_disk_traits_2<K> gt;
      auto mid = [&](std::size_t i) { return gt.construct_hyperbolic_midpoint_2_object()(P.vertex(i), P.vertex(i + 1)); };
      for(std::size_t i = 0; i < 4; ++i) loops.insert_feature_loop(std::vector<K::Point_2>{mid(i), mid(i + 4)});
      std::vector<K::Point_2> gon;
      const auto to_m0 = HSM::Delaunay_triangulation_on_surface<>::Isometry_2::translation_from_origin(mid(0));
      for(int k = 0; k <= 12; ++k) {
        const double a = 2 * CGAL_PI * (k % 12) / 12 + 0.1, e = std::tanh(0.35 / 2);
        gon.push_back(to_m0.apply_unchecked(K::Point_2(e * std::cos(a), e * std::sin(a))));
      }
      const auto res = loops.insert_feature_loop(gon);
      const auto sl = HSM::refine_Ruppert(loops, HSMP::maximum_circumradius(0.15, HSMP::minimum_central_angle(20 * CGAL_PI / 180)));
      std::cout << "Bolza surface with 5 feature loops (" << res.crossings << " crossings inserted), Ruppert epsilon 0.15, "
                << "alpha 20 degrees: " << sl << "\n";
      HSM::write_surface_mesh_svg(loops, "surface_mesh_loops.svg", true, "Bolza surface: 4 closed geodesics and a geodesic 12-gon as feature loops");
    }

    // ---- conformal remeshing of the input
    Mesh in;
    if(!CGAL::IO::read_polygon_mesh(file, in) || in.is_empty()) { std::cerr << "cannot read " << file << "\n"; return EXIT_FAILURE; }
    Mesh out;
    const auto rep = HSM::conformal_remesh(in, out, HSMP::maximum_circumradius(eps, HSMP::minimum_central_angle(30 * CGAL_PI / 180)));
    std::cout << file << ": genus " << rep.genus << "\n"
              << "  Ricci flow: " << rep.flow.iterations << " Newton iterations, max |K| " << rep.flow.max_curvature_error
              << (rep.flow_used_flips ? " (with intrinsic flips)" : " (input connectivity)") << ", " << rep.seconds_flow << " s\n"
              << "  Delaunay triangulation of the surface: " << rep.seconds_triangulation << " s\n"
              << "  refinement: " << rep.refinement << "\n"
              << "  output mesh: " << rep.seconds_output << " s\n";
    print_angles("input", in);
    print_angles("remesh", out);
    if(!CGAL::IO::write_polygon_mesh("surface_mesh_remeshed.off", out, CGAL::parameters::stream_precision(17))) {
      std::cerr << "cannot write surface_mesh_remeshed.off\n"; return EXIT_FAILURE;
    }
    HSM::write_surface_mesh_svg(*rep.surface, "surface_mesh_disk.svg", true, file + ": refined surface, epsilon " + std::to_string(eps));
    HSM::write_central_angle_histogram_svg(*rep.surface, "surface_mesh_central_angles.svg", 30, "remesh:");
    std::cout << "wrote surface_mesh_remeshed.off, surface_mesh_disk.svg, surface_mesh_central_angles.svg, surface_mesh_bolza.svg, surface_mesh_loops.svg\n";
    return rep.refinement.status == HSM::Refinement_status::SUCCESS ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
