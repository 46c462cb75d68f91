// Flat metric of a torus and its lattice parameter tau. Usage: flat_torus_example [R r]
// (a torus of revolution with radii R > r, generated here; its conformal modulus is
// tau = i sqrt(R^2 - r^2) / r).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace RF = CGAL::Ricci_flow;

int main(int argc, char** argv)
{
  const double R = argc > 2 ? std::atof(argv[1]) : 3.0, r = argc > 2 ? std::atof(argv[2]) : 1.0;
  const int n = 120, m = 40;
  Mesh torus;
  std::vector<Mesh::Vertex_index> v(n * m);
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j) {
      const double phi = 2 * CGAL_PI * i / n, theta = 2 * CGAL_PI * j / m;
      v[i * m + j] = torus.add_vertex(K::Point_3((R + r * std::cos(theta)) * std::cos(phi),
                                                 (R + r * std::cos(theta)) * std::sin(phi), r * std::sin(theta)));
    }
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j) {
      const auto a = v[i * m + j], b = v[((i + 1) % n) * m + j], c = v[((i + 1) % n) * m + (j + 1) % m],
                 d = v[i * m + (j + 1) % m];
      torus.add_face(a, b, c);
      torus.add_face(a, c, d);
    }
  try {
    auto metric = RF::flat_metric(torus);
    std::cout << "flat metric: " << RF::to_string(metric.statistics().status) << " after "
              << metric.statistics().iterations << " iterations, max |K| = " << metric.statistics().max_curvature_error
              << std::endl;
    RF::Hyperbolic_embedding<K::Point_3> embedding(metric);
    const auto tau = embedding.lattice_parameter();
    std::cout << "tau = " << tau.real() << " + " << tau.imag() << " i; smooth torus of revolution: "
              << std::sqrt(R * R - r * r) / r << " i" << std::endl;
  } catch(const RF::Ricci_flow_error& e) {
    std::cerr << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
