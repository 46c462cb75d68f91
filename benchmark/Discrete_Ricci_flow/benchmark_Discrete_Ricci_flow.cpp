// Benchmark of the hyperbolic uniformization with both sparse solvers in the same run: CHOLMOD's supernodal
// Cholesky (when the library was configured with SuiteSparse) and Eigen's SimplicialLDLT. For each mesh and
// solver: Newton iterations, total time, the total time as a ratio to ONE factorization (analyzePattern +
// factorize + solve) of the Hessian of the final metric with the same solver, the same-run ratio
// LDLT total / CHOLMOD total, and the peak resident memory. Every (mesh, solver) run is a child process
// (fork), so its peak memory is its own.
//
// Usage: benchmark_Discrete_Ricci_flow [max_faces [ldlt_max_faces]]   (defaults 3000000 and 1500000)
// Meshes: CGAL's eight.off (genus 2), elephant.off (genus 3), data/meshes/elephant_cid.obj (genus 3, bad
// triangles), refined_elephant.off, elephant.off Loop-subdivided (x4 faces per level, CGAL::Subdivision_method_3)
// and eight.off Loop-subdivided 6 times (2.6M faces), up to max_faces; SimplicialLDLT only up to ldlt_max_faces.
// Output: one line per (mesh, solver),
//   RICCI mesh=<name> faces=<F> solver=<cholmod|ldlt> status=<s> iterations=<k> error=<e> total_s=<t>
//         factorization_s=<c> total_over_factorization=<t/c> peak_MB=<m>
// and per mesh `RATIO mesh=<name> ldlt_over_cholmod=<r>`.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace RF = CGAL::Discrete_Ricci_flow;

// one analyzePattern + factorize + solve of the Hessian of the final metric (Newton's matrix at the solution)
static double one_factorization_seconds(const RF::Discrete_metric<Point_3>& metric, RF::Sparse_solver s)
{
  Mesh m = metric.intrinsic_mesh();
  RF::internal::Flow_engine<Point_3> eng(m, RF::Background_geometry::HYPERBOLIC, RF::Scheme::VERTEX_SCALING, false);
  for(auto e : m.edges()) eng.edge_data[e] = std::sinh(0.5 * metric.length(e)); // u = 0 gives the final lengths
  eng.compute_lengths();
  eng.compute_angles();
  std::vector<Eigen::Triplet<double> > trip;
  eng.hessian_triplets(trip);
  const int n = int(m.number_of_vertices());
  Eigen::SparseMatrix<double> H(n, n);
  H.setFromTriplets(trip.begin(), trip.end());
  Eigen::VectorXd b = Eigen::VectorXd::Ones(n), x(n);
  double best = 1e300;
  for(int rep = 0; rep < 2; ++rep) {
    RF::internal::Sparse_cholesky solver(s);
    RF::Flow_statistics st;
    const auto t0 = std::chrono::steady_clock::now();
    if(!solver.solve(H, 0, b, x, st)) std::cerr << "factorization failed" << std::endl;
    best = (std::min)(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

// runs the flow in a child process; returns its total time (or -1)
static double run(const std::string& name, const Mesh& mesh, RF::Sparse_solver s)
{
  int fd[2];
  if(pipe(fd) != 0) return -1;
  const pid_t pid = fork();
  if(pid == 0) {
    close(fd[0]);
    auto metric = RF::hyperbolic_uniformization(mesh, RF::parameters::sparse_solver(s));
    const auto& st = metric.statistics();
    const double fact = one_factorization_seconds(metric, s);
    struct rusage ru; getrusage(RUSAGE_SELF, &ru);
    std::ostringstream os;
    os << "RICCI mesh=" << name << " faces=" << mesh.number_of_faces()
       << " solver=" << (s == RF::Sparse_solver::SUPERNODAL_CHOLMOD ? "cholmod" : "ldlt")
       << " status=" << (st.converged() ? "converged" : "not_converged") << " iterations=" << st.iterations
       << " polishing=" << st.polishing_iterations << " flips=" << st.number_of_flips
       << " symbolic=" << st.number_of_symbolic_factorizations << " error=" << st.max_curvature_error
       << " total_s=" << st.time_seconds << " newton_solves_s=" << st.factorization_seconds << " factorization_s=" << fact
       << " total_over_factorization=" << st.time_seconds / fact << " peak_MB=" << double(ru.ru_maxrss) / 1024 << "\n";
    const std::string line = os.str();
    std::fwrite(line.data(), 1, line.size(), stdout);
    std::fflush(stdout);
    const double t = st.time_seconds;
    if(write(fd[1], &t, sizeof t) != sizeof t) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  double t = -1;
  if(read(fd[0], &t, sizeof t) != sizeof t) t = -1;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return t;
}

static void run_both(const std::string& name, const Mesh& mesh, std::size_t ldlt_max_faces)
{
  const double tc = RF::has_cholmod() ? run(name, mesh, RF::Sparse_solver::SUPERNODAL_CHOLMOD) : -1;
  const double tl = mesh.number_of_faces() <= ldlt_max_faces ? run(name, mesh, RF::Sparse_solver::SIMPLICIAL_LDLT) : -1;
  if(tc > 0 && tl > 0) std::cout << "RATIO mesh=" << name << " faces=" << mesh.number_of_faces() << " ldlt_over_cholmod=" << tl / tc << std::endl;
}

int main(int argc, char** argv)
{
  const std::size_t max_faces = argc > 1 ? std::size_t(std::atol(argv[1])) : 3000000;
  const std::size_t ldlt_max = argc > 2 ? std::size_t(std::atol(argv[2])) : 1500000;
  const std::string cgal = std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/";
  const std::string shared = std::string(CGAL_HC_DATA_DIR) + "/meshes/";
  std::cout << "CHOLMOD available: " << (RF::has_cholmod() ? "yes" : "no") << std::endl;
  try {
    for(const std::string& f : {cgal + "eight.off", cgal + "elephant.off", shared + "elephant_cid.obj", cgal + "refined_elephant.off"}) {
      Mesh m;
      if(!CGAL::IO::read_polygon_mesh(f, m)) { std::cerr << "cannot read " << f << std::endl; continue; }
      if(m.number_of_faces() > max_faces) continue;
      run_both(f.substr(f.find_last_of('/') + 1), m, ldlt_max);
    }
    Mesh m;
    if(CGAL::IO::read_polygon_mesh(cgal + "elephant.off", m)) {
      for(int level = 1; m.number_of_faces() * 4 <= max_faces; ++level) {
        CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
        run_both("elephant_loop" + std::to_string(level), m, ldlt_max);
      }
    }
    Mesh e;
    if(CGAL::IO::read_polygon_mesh(cgal + "eight.off", e) && e.number_of_faces() * 4096 <= max_faces) {
      CGAL::Subdivision_method_3::Loop_subdivision(e, CGAL::parameters::number_of_iterations(6));
      run_both("eight_loop6", e, ldlt_max);
    }
  } catch(const std::exception& ex) {
    std::cerr << ex.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
