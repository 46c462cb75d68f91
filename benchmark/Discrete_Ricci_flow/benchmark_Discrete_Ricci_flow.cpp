// Benchmark of the hyperbolic uniformization with both sparse solvers in the same run: CHOLMOD's supernodal
// Cholesky (when the library was configured with SuiteSparse) and Eigen's SimplicialLDLT, each with the default
// inexact Newton (conjugate gradients preconditioned by an earlier factorization, `reuse_factorization(true)`),
// and the reference "ldlt_ref": SimplicialLDLT with one factorization per Newton step (`reuse_factorization(false)`,
// the flow as it was before). For each mesh and variant: Newton iterations, factorizations, CG iterations, total
// time (wall and CPU), ONE factorization (analysis + numeric factorization + solve) of the Hessian of the final
// metric with the same solver (wall and CPU; the analysis and the numeric part also separately), the ratios total
// / one factorization, and the peak resident memory of the flow. Every (mesh, variant) run is a child process
// (fork) of a parent that holds only the current mesh (and returns its freed heap to the system before the
// fork: `malloc_trim`), so its peak memory is its own plus that mesh; `input_MB` is the parent's resident memory
// at the fork.
//
// Usage: benchmark_Discrete_Ricci_flow [max_faces [ldlt_max_faces [min_faces]]]   (defaults 3000000, 1500000, 0)
// Meshes: CGAL's eight.off (genus 2), elephant.off (genus 3), data/meshes/elephant_cid.obj (genus 3, bad
// triangles), refined_elephant.off, elephant.off Loop-subdivided (x4 faces per level, CGAL::Subdivision_method_3)
// and eight.off Loop-subdivided 6 times (2.6M faces), from min_faces up to max_faces; the SimplicialLDLT
// variants only up to ldlt_max_faces.
// Output: one line per (mesh, variant),
//   RICCI mesh=<name> faces=<F> solver=<cholmod|ldlt|ldlt_ref> status=<s> iterations=<k> ... total_s=<t> cpu_s=<c>
//         factorization_s=<f> factorization_cpu_s=<fc> total_over_factorization=<t/f> cpu_over_factorization=<c/fc>
//         peak_MB=<m> input_MB=<parent>
// and per mesh `RATIO mesh=<name> ldlt_ref_over_cholmod=<r> ldlt_over_cholmod=<r'>` (wall and CPU).
//
// Usage: benchmark_Discrete_Ricci_flow spherical [max_faces]   (default 100000)
// Spherical uniformization (`spherical_uniformization()`, default options) of every closed connected genus-0
// demo mesh (the test suite's loop, `test/Discrete_Ricci_flow/demo_meshes.h`: quads triangulated, soups
// repaired), in this process, one line per mesh:
//   SPHERE mesh=<name> faces=<F> valid=<0|1> flow=<status> iterations=<k> flips=<f> factorizations=<n>
//          puncture=<p> total_s=<t> cpu_s=<c> factorization_s=<f1> total_over_factorization=<t/f1>
// with the reference f1 = one analysis + factorization + solve, with the default solver for that size, of the
// Hessian of the Euclidean flow at the input lengths (the cotangent Laplacian) with vertex 0 fixed, best of two:
// the system the disk flow solves, at the scale of the whole mesh. Then a `SPHERE_SUMMARY` line.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include "../../test/Discrete_Ricci_flow/demo_meshes.h"

#include <algorithm>
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace RF = CGAL::Discrete_Ricci_flow;

static double cpu_now()
{
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
static double wall_now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Factorization_time { double wall = 1e300, cpu = 1e300, analysis = 0, numeric = 0; };

// one analysis + numeric factorization + solve of the lower triangle H with solver s (a fresh solver each time,
// best of two), and the numeric part alone (a second factorization with the same pattern)
static Factorization_time solve_time(const Eigen::SparseMatrix<double>& H, RF::Sparse_solver s)
{
  const int n = int(H.rows());
  Eigen::VectorXd b = Eigen::VectorXd::Ones(n), x(n);
  Factorization_time best;
  for(int rep = 0; rep < 2; ++rep) {
    RF::internal::Sparse_cholesky solver(s, std::size_t(n));
    RF::Flow_statistics st;
    const double w0 = wall_now(), c0 = cpu_now();
    if(!solver.solve(H, 0, b, x, st)) std::cerr << "factorization failed" << std::endl;
    const double w = wall_now() - w0, c = cpu_now() - c0;
    if(w < best.wall) best.wall = w;
    if(c < best.cpu) best.cpu = c;
    // the numeric part alone: a second factorization with the same pattern
    const double w1 = wall_now();
    solver.factorize(H, 0, st);
    const double numeric = wall_now() - w1;
    if(rep == 0 || numeric < best.numeric) { best.numeric = numeric; best.analysis = (std::max)(0.0, w - numeric); }
  }
  return best;
}

// one analysis + numeric factorization + solve of the Hessian of the final metric (Newton's matrix at the
// solution) with the flow's own assembly and solver class; the best of two
static Factorization_time one_factorization(const RF::Discrete_metric<Point_3>& metric, RF::Sparse_solver s)
{
  Mesh m = metric.intrinsic_mesh();
  RF::internal::Flow_engine<Point_3> eng(m, RF::Background_geometry::HYPERBOLIC, RF::Scheme::VERTEX_SCALING, false);
  for(auto e : m.edges()) eng.edge_data[e] = std::sinh(0.5 * metric.length(e)); // u = 0 gives the final lengths
  eng.compute_lengths();
  eng.compute_angles();
  Eigen::SparseMatrix<double> H;
  eng.hessian_lower(H, std::vector<char>());
  return solve_time(H, s);
}

enum class Variant { CHOLMOD, LDLT, LDLT_REFERENCE };

struct Run_time { double wall = -1, cpu = -1; };

// the resident memory of this process (MB), from /proc/self/status
static double resident_MB()
{
  std::ifstream f("/proc/self/status");
  std::string line;
  while(std::getline(f, line))
    if(line.rfind("VmRSS:", 0) == 0) return std::atof(line.c_str() + 6) / 1024;
  return -1;
}

// runs the flow in a child process; returns its total times (or -1)
static Run_time run(const std::string& name, const Mesh& mesh, Variant v)
{
  int fd[2];
  Run_time result;
  if(pipe(fd) != 0) return result;
  std::cout.flush();
  malloc_trim(0); // (the meshes built and freed before, e.g. the subdivision levels, would count in the child)
  const double input_mb = resident_MB();
  const pid_t pid = fork();
  if(pid == 0) {
    close(fd[0]);
    const RF::Sparse_solver s = v == Variant::CHOLMOD ? RF::Sparse_solver::SUPERNODAL_CHOLMOD : RF::Sparse_solver::SIMPLICIAL_LDLT;
    const double c0 = cpu_now();
    auto metric = RF::hyperbolic_uniformization(mesh, RF::parameters::reuse_factorization(v != Variant::LDLT_REFERENCE, RF::parameters::sparse_solver(s)));
    Run_time t;
    t.cpu = cpu_now() - c0;
    struct rusage ru; getrusage(RUSAGE_SELF, &ru); // the peak of the flow (before the reference factorization)
    const auto& st = metric.statistics();
    t.wall = st.time_seconds;
    const Factorization_time f = one_factorization(metric, s);
    std::ostringstream os;
    os << "RICCI mesh=" << name << " faces=" << mesh.number_of_faces()
       << " solver=" << (v == Variant::CHOLMOD ? "cholmod" : v == Variant::LDLT ? "ldlt" : "ldlt_ref")
       << " status=" << (st.converged() ? "converged" : "not_converged") << " iterations=" << st.iterations
       << " polishing=" << st.polishing_iterations << " flips=" << st.number_of_flips
       << " symbolic=" << st.number_of_symbolic_factorizations << " factorizations=" << st.number_of_factorizations
       << " cg_iterations=" << st.number_of_cg_iterations << " error=" << st.max_curvature_error
       << " total_s=" << t.wall << " cpu_s=" << t.cpu << " factorizations_s=" << st.factorization_seconds
       << " cg_s=" << st.cg_seconds << " hessian_s=" << st.hessian_seconds
       << " factorization_s=" << f.wall << " (analysis " << f.analysis << " numeric " << f.numeric << ")"
       << " factorization_cpu_s=" << f.cpu << " total_over_factorization=" << t.wall / f.wall
       << " cpu_over_factorization=" << t.cpu / f.cpu << " total_over_numeric=" << t.wall / f.numeric
       << " peak_MB=" << double(ru.ru_maxrss) / 1024 << " input_MB=" << input_mb << "\n";
    const std::string line = os.str();
    std::fwrite(line.data(), 1, line.size(), stdout);
    std::fflush(stdout);
    if(write(fd[1], &t, sizeof t) != sizeof t) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  if(read(fd[0], &result, sizeof result) != sizeof result) result = Run_time();
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return result;
}

static void run_all(const std::string& name, const Mesh& mesh, std::size_t ldlt_max_faces)
{
  const Run_time tc = RF::has_cholmod() ? run(name, mesh, Variant::CHOLMOD) : Run_time();
  const bool ldlt = mesh.number_of_faces() <= ldlt_max_faces;
  const Run_time tl = ldlt ? run(name, mesh, Variant::LDLT) : Run_time();
  const Run_time tr = ldlt ? run(name, mesh, Variant::LDLT_REFERENCE) : Run_time();
  if(tc.wall > 0 && tr.wall > 0)
    std::cout << "RATIO mesh=" << name << " faces=" << mesh.number_of_faces() << " ldlt_ref_over_cholmod=" << tr.wall / tc.wall
              << " (cpu " << tr.cpu / tc.cpu << ") ldlt_over_cholmod=" << tl.wall / tc.wall << " (cpu " << tl.cpu / tc.cpu
              << ")" << std::endl;
}

// one analysis + factorization + solve of the cotangent Laplacian of `mesh` (vertex 0 fixed) with the default
// solver for its size, best of two (wall seconds)
static double cotangent_laplacian_factorization(const Mesh& mesh)
{
  Mesh m = mesh;
  RF::internal::Flow_engine<Point_3> eng(m, RF::Background_geometry::EUCLIDEAN, RF::Scheme::VERTEX_SCALING, false);
  for(auto e : m.edges()) eng.edge_data[e] = 0.5 * std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  eng.compute_lengths();
  eng.compute_angles();
  const int n = int(m.number_of_vertices());
  std::vector<char> fixed(std::size_t(n), 0);
  fixed[0] = 1;
  Eigen::SparseMatrix<double> H;
  eng.hessian_lower(H, fixed);
  return solve_time(H, RF::Sparse_solver::DEFAULT).wall;
}

static int spherical_benchmark(std::size_t max_faces)
{
  std::size_t maps = 0, valid = 0;
  double total = 0;
  std::vector<double> ratios;
  for(const auto& nm : ricci_test::demo_meshes(0, 0)) {
    const Mesh& mesh = nm.second;
    if(mesh.number_of_faces() > max_faces) continue;
    std::string name = nm.first;
    std::replace(name.begin(), name.end(), ' ', '_');
    ++maps;
    const double w0 = wall_now(), c0 = cpu_now();
    try {
      const auto s = RF::spherical_uniformization(mesh);
      const double w = wall_now() - w0, c = cpu_now() - c0;
      const double f = cotangent_laplacian_factorization(mesh);
      const auto& st = s.statistics();
      valid += s.converged() ? 1 : 0;
      total += w;
      ratios.push_back(w / f);
      std::cout << "SPHERE mesh=" << name << " faces=" << mesh.number_of_faces() << " valid=" << s.converged()
                << " flow=" << RF::to_string(st.status) << " iterations=" << st.iterations << " flips=" << st.number_of_flips
                << " factorizations=" << st.number_of_factorizations << " puncture=" << s.puncture_vertex()
                << " total_s=" << w << " cpu_s=" << c << " factorization_s=" << f << " total_over_factorization=" << w / f
                << std::endl;
    } catch(const std::exception& e) {
      std::cout << "SPHERE mesh=" << name << " faces=" << mesh.number_of_faces() << " valid=0 error=\"" << e.what() << "\"" << std::endl;
    }
  }
  std::sort(ratios.begin(), ratios.end());
  std::cout << "SPHERE_SUMMARY maps=" << maps << " valid=" << valid << " total_s=" << total << " median_total_over_factorization="
            << (ratios.empty() ? 0.0 : ratios[ratios.size() / 2]) << " max_total_over_factorization="
            << (ratios.empty() ? 0.0 : ratios.back()) << std::endl;
  return valid == maps ? EXIT_SUCCESS : EXIT_FAILURE;
}

int main(int argc, char** argv)
{
  if(argc > 1 && std::string(argv[1]) == "spherical")
    return spherical_benchmark(argc > 2 ? std::size_t(std::atol(argv[2])) : 100000);
  const std::size_t max_faces = argc > 1 ? std::size_t(std::atol(argv[1])) : 3000000;
  const std::size_t ldlt_max = argc > 2 ? std::size_t(std::atol(argv[2])) : 1500000;
  const std::size_t min_faces = argc > 3 ? std::size_t(std::atol(argv[3])) : 0;
  const std::string cgal = std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/";
  const std::string shared = std::string(CGAL_HC_DATA_DIR) + "/meshes/";
  std::cout << "CHOLMOD available: " << (RF::has_cholmod() ? "yes" : "no") << std::endl;
  auto in_range = [&](const Mesh& m) { return m.number_of_faces() >= min_faces && m.number_of_faces() <= max_faces; };
  try {
    for(const std::string& f : {cgal + "eight.off", cgal + "elephant.off", shared + "elephant_cid.obj", cgal + "refined_elephant.off"}) {
      Mesh m;
      if(!CGAL::IO::read_polygon_mesh(f, m)) { std::cerr << "cannot read " << f << std::endl; continue; }
      if(in_range(m)) run_all(f.substr(f.find_last_of('/') + 1), m, ldlt_max);
    }
    {
      Mesh m;
      if(CGAL::IO::read_polygon_mesh(cgal + "elephant.off", m)) {
        for(int level = 1; m.number_of_faces() * 4 <= max_faces; ++level) {
          CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
          if(in_range(m)) run_all("elephant_loop" + std::to_string(level), m, ldlt_max);
        }
      }
    } // the parent holds one mesh at a time (the children's peak memory includes it)
    Mesh e;
    if(CGAL::IO::read_polygon_mesh(cgal + "eight.off", e) && e.number_of_faces() * 4096 <= max_faces &&
       e.number_of_faces() * 4096 >= min_faces) {
      CGAL::Subdivision_method_3::Loop_subdivision(e, CGAL::parameters::number_of_iterations(6));
      run_all("eight_loop6", e, ldlt_max);
    }
  } catch(const std::exception& ex) {
    std::cerr << ex.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
