// The Bolza surface as the double cover of a subdivided octahedron branched at its 6 vertices (genus 2).
// By uniqueness of the discrete uniformization the result has the 48 symmetries of the mesh, so it is the
// Bolza surface: the greedy generators at a branch point are systoles, |trace| = 2 + 2 sqrt 2, translation
// length 2 acosh(1 + sqrt 2) = 3.0571 (the side of the regular octagon with angles pi/4).
// Usage: bolza_surface_example [n] (each octahedron face is cut into n^2 triangles; default 6).
// Writes bolza_fundamental_domain.svg and bolza_tiling.svg into the current directory.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>

typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace RF = CGAL::Ricci_flow;

// vertices have integer coordinates n * p on the octahedron |x| + |y| + |z| = n; the three branch cuts
// +x..+y, -x..+z, -y..-z are crossed by switching sheets
Mesh bolza_mesh(int n)
{
  Mesh m;
  typedef std::array<int, 3> IP;
  const IP X{n, 0, 0}, mX{-n, 0, 0}, Y{0, n, 0}, mY{0, -n, 0}, Z{0, 0, n}, mZ{0, 0, -n};
  const IP faces[8][3] = {{X, Y, Z}, {Y, mX, Z}, {mX, mY, Z}, {mY, X, Z}, {Y, X, mZ}, {mX, Y, mZ}, {mY, mX, mZ}, {X, mY, mZ}};
  auto is_branch = [&](const IP& p) { return ((p[0] != 0) + (p[1] != 0) + (p[2] != 0)) == 1; };
  auto cut_of = [&](const IP& p) { // index of the coordinate whose sign gives the bank of the cut, or -1
    if(is_branch(p)) return -1;
    if(p[2] == 0 && p[0] > 0 && p[1] > 0) return 2;
    if(p[1] == 0 && p[0] < 0 && p[2] > 0) return 1;
    if(p[0] == 0 && p[1] < 0 && p[2] < 0) return 0;
    return -1;
  };
  std::map<std::pair<IP, int>, Mesh::Vertex_index> ids;
  auto vid = [&](const IP& p, int sheet) {
    const int s = is_branch(p) ? 0 : sheet;
    auto it = ids.find({p, s});
    if(it != ids.end()) return it->second;
    const double len = std::sqrt(double(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    return ids[{p, s}] = m.add_vertex(Point_3(p[0] / len, p[1] / len, p[2] / len));
  };
  for(int sheet = 0; sheet < 2; ++sheet)
    for(const auto& F : faces) {
      auto P = [&](int i, int j) { IP r; for(int k = 0; k < 3; ++k) r[k] = (F[0][k] * (n - i - j) + F[1][k] * i + F[2][k] * j) / n; return r; };
      auto add = [&](const IP& a, const IP& b, const IP& c) {
        const int centroid[3] = {a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]};
        const IP* pts[3] = {&a, &b, &c};
        Mesh::Vertex_index v[3];
        for(int k = 0; k < 3; ++k) {
          const int cut = cut_of(*pts[k]);
          v[k] = vid(*pts[k], sheet ^ (cut >= 0 && centroid[cut] > 0 ? 1 : 0));
        }
        m.add_face(v[0], v[1], v[2]);
      };
      for(int i = 0; i < n; ++i)
        for(int j = 0; i + j < n; ++j) {
          add(P(i, j), P(i + 1, j), P(i, j + 1));
          if(i + j + 2 <= n) add(P(i + 1, j), P(i + 1, j + 1), P(i, j + 1));
        }
    }
  return m;
}

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 6;
  if(n < 1) { std::cerr << "n must be positive" << std::endl; return EXIT_FAILURE; }
  const Mesh mesh = bolza_mesh(n);
  try {
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
  } catch(const RF::Ricci_flow_error& e) {
    std::cerr << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
