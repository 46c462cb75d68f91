// Benchmark of the hyperbolic uniformization: Newton iterations, total time, and the total time as a ratio to
// ONE sparse Cholesky factorization (Eigen::SimplicialLDLT, analyzePattern + factorize) of the Hessian of the
// final metric, measured in the same run (the physical limit of a Newton solver is a handful of them).
//
// Usage: benchmark_Discrete_Ricci_flow [max_faces]   (default 1500000)
// Meshes: CGAL's eight.off (genus 2), elephant.off (genus 3), shared elephant_cid.obj (genus 3, bad triangles),
// refined_elephant.off, and elephant.off refined by Loop subdivision (x4 faces per level) up to max_faces.
// Output: one line per mesh,
//   RICCI mesh=<name> faces=<F> vertices=<V> genus=<g> status=<s> iterations=<k> flips=<f> error=<e>
//         area_error=<a> total_s=<t> factorization_s=<c> total_over_factorization=<t/c> per_iteration_over_factorization=<t/(k c)>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include <Eigen/SparseCholesky>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace RF = CGAL::Ricci_flow;

// one analyzePattern + factorize of the Hessian of the final metric (Newton's matrix at the solution)
static double one_factorization_seconds(const RF::Discrete_metric<Point_3>& metric)
{
  Mesh m = metric.intrinsic_mesh();
  RF::internal::Flow_engine<Point_3> eng(m, RF::Background_geometry::HYPERBOLIC, RF::Scheme::VERTEX_SCALING, false);
  for(auto e : m.edges()) eng.edge_data[e] = std::sinh(0.5 * metric.length(e)); // u = 0 gives the final lengths
  eng.compute_lengths();
  eng.compute_angles();
  std::vector<Eigen::Triplet<double> > trip;
  eng.hessian_triplets(trip);
  Eigen::SparseMatrix<double> H(int(m.number_of_vertices()), int(m.number_of_vertices()));
  H.setFromTriplets(trip.begin(), trip.end());
  double best = 1e300;
  for(int rep = 0; rep < 2; ++rep) {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > solver;
    const auto t0 = std::chrono::steady_clock::now();
    solver.analyzePattern(H);
    solver.factorize(H);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if(solver.info() != Eigen::Success) std::cerr << "factorization failed" << std::endl;
    best = (std::min)(best, s);
  }
  return best;
}

static void run(const std::string& name, const Mesh& mesh)
{
  auto metric = RF::hyperbolic_uniformization(mesh);
  const auto& st = metric.statistics();
  const double fact = one_factorization_seconds(metric);
  const double area_error = metric.total_area() - 4 * CGAL_PI * (metric.genus() - 1);
  std::cout << "RICCI mesh=" << name << " faces=" << mesh.number_of_faces() << " vertices=" << mesh.number_of_vertices()
            << " genus=" << metric.genus() << " status=" << (st.converged() ? "converged" : "not_converged")
            << " iterations=" << st.iterations << " flips=" << st.number_of_flips
            << " symbolic=" << st.number_of_symbolic_factorizations << " error=" << st.max_curvature_error
            << " area_error=" << area_error << " total_s=" << st.time_seconds << " factorization_s=" << fact
            << " total_over_factorization=" << st.time_seconds / fact
            << " per_iteration_over_factorization=" << st.time_seconds / ((std::max)(1, st.iterations) * fact)
            << std::endl;
}

int main(int argc, char** argv)
{
  const std::size_t max_faces = argc > 1 ? std::size_t(std::atol(argv[1])) : 1500000;
  const std::string cgal = std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/";
  const std::string shared = std::string(CGAL_HC_DATA_DIR) + "/meshes/";
  try {
    for(const std::string& f : {cgal + "eight.off", cgal + "elephant.off", shared + "elephant_cid.obj", cgal + "refined_elephant.off"}) {
      Mesh m;
      if(!CGAL::IO::read_polygon_mesh(f, m)) { std::cerr << "cannot read " << f << std::endl; continue; }
      if(m.number_of_faces() > max_faces) continue;
      run(f.substr(f.find_last_of('/') + 1), m);
    }
    Mesh m;
    if(CGAL::IO::read_polygon_mesh(cgal + "elephant.off", m)) {
      for(int level = 1; m.number_of_faces() * 4 <= max_faces; ++level) {
        CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
        run("elephant_loop" + std::to_string(level), m);
      }
    }
  } catch(const std::exception& e) {
    std::cerr << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
