// The Bolza surface as the double cover of a subdivided octahedron branched at its 6 vertices (genus 2).
// By uniqueness of the discrete uniformization the result has the 48 symmetries of the mesh, so it is the
// Bolza surface: the greedy generators at a branch point are systoles, |trace| = 2 + 2 sqrt 2, translation
// length 2 acosh(1 + sqrt 2) = 3.0571 (the side of the regular octagon with angles pi/4).
// Usage: bolza_surface_example [n] (each octahedron face is cut into n^2 triangles; default 6).
// Writes bolza_fundamental_domain.svg and bolza_tiling.svg into the current directory.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Discrete_Ricci_flow.h>
#include <CGAL/Discrete_Ricci_flow/Bolza_surface_mesh.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace RF = CGAL::Ricci_flow;

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 6;
  try {
    const Mesh mesh = RF::make_Bolza_surface_mesh<Point_3>(n);
    const auto metric = RF::hyperbolic_uniformization(mesh);
    std::cout << mesh.number_of_faces() << " faces, genus " << metric.genus() << ", " << RF::to_string(metric.statistics().status)
              << " after " << metric.statistics().iterations << " iterations, area " << metric.total_area() << std::endl;
    RF::Hyperbolic_embedding<Point_3> embedding(metric, Mesh::Vertex_index(0)); // vertex 0: the branch point +x
    for(std::size_t i = 0; i < embedding.number_of_generators(); ++i)
      std::cout << "  generator " << i << ": |trace| = " << embedding.absolute_trace(i) << ", translation length "
                << embedding.translation_length(i) << std::endl;
    std::cout << "2 + 2 sqrt 2 = " << 2 + 2 * std::sqrt(2.0) << ", regular octagon side 2 acosh(cot(pi/8)) = "
              << 2 * std::acosh(1 / std::tan(CGAL_PI / 8)) << std::endl;
    embedding.write_fundamental_domain_svg("bolza_fundamental_domain.svg");
    embedding.write_tiling_svg("bolza_tiling.svg", 2);
  } catch(const std::exception& e) {
    std::cerr << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
