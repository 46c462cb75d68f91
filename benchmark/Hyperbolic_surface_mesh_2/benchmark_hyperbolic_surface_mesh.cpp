// Benchmark of Hyperbolic_surface_mesh_2, with references measured in the same run:
//  1. refinement throughput (output triangles per second) on genus 2 and genus 4 surfaces, next to CGAL's
//     refine_Delaunay_mesh_2 on a planar square of about the same output size;
//  2. Bolza point insertion: the same N random points into this package and into CGAL's
//     Periodic_4_hyperbolic_Delaunay_triangulation_2;
//  3. vertex counts at epsilon = 0.1, 0.05, 0.01 on genus-2 surfaces (Bolza octagon, eight.off), size only
//     (alpha = 1e-6), alpha = 30 degrees, and Chew.
// Usage: benchmark_hyperbolic_surface_mesh [--large]   (--large: 1e6 triangles and 3e5, 1e6 points)
//        benchmark_hyperbolic_surface_mesh --refine GENUS EPSILON   (our Chew refinement only, for profilers)
//        benchmark_hyperbolic_surface_mesh --insert N               (the Bolza insertion comparison only)
//        benchmark_hyperbolic_surface_mesh --throughput GENUS EPSILON (one throughput row, with Mesh_2's side)
// Output: one "key value ..." line per measurement.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Hyperbolic_octagon_translation.h>
#include <CGAL/Periodic_4_hyperbolic_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_4_hyperbolic_Delaunay_triangulation_traits_2.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Hyperbolic_surface_mesh_2.h>
#include <CGAL/Hyperbolic_surface_mesh_2/conformal_remesh.h>

#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Epick K;
namespace HSM = CGAL::Hyperbolic_surface_mesh_2;
namespace HSMP = CGAL::Hyperbolic_surface_mesh_2::parameters;
typedef HSM::Delaunay_triangulation_on_surface<> DT;

// CPU time of the process (both sides of every ratio are measured the same way; wall-clock time on a machine
// shared with other builds mostly measured the other processes)
static double now()
{
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// CGAL Mesh_2 on the unit square with a size bound chosen for about n triangles (shape bound 0.125)
static void mesh2_reference(double n_target, std::size_t& faces, double& seconds)
{
  typedef CGAL::Triangulation_vertex_base_2<K> Vb;
  typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
  typedef CGAL::Delaunay_mesh_size_criteria_2<CDT> Criteria;
  CDT cdt;
  const K::Point_2 a(0, 0), b(1, 0), c(1, 1), d(0, 1);
  cdt.insert_constraint(a, b); cdt.insert_constraint(b, c); cdt.insert_constraint(c, d); cdt.insert_constraint(d, a);
  const double size = std::sqrt(1.0 / (0.2 * n_target)); // about n_target triangles in the unit square
  const double t0 = now();
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, size));
  seconds = now() - t0;
  faces = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) if(f->is_in_domain()) ++faces;
}

static void throughput(int genus, double eps)
{
  DT t(HSM::Fundamental_polygon<K>::regular(genus));
  const double t0 = now();
  const auto st = HSM::refine_Chew(t, HSMP::maximum_circumradius(eps));
  const double seconds = now() - t0;
  std::size_t mf = 0; double ms = 0;
  mesh2_reference(double(st.final_faces), mf, ms);
  const double ours = double(st.final_faces) / seconds, ref = double(mf) / ms;
  std::cout << "refinement_throughput genus " << genus << " epsilon " << eps << " faces " << st.final_faces
            << " cpu_seconds " << seconds << " wall_seconds " << st.seconds << " triangles_per_s " << ours << " mesh2_faces " << mf << " mesh2_seconds " << ms
            << " mesh2_triangles_per_s " << ref << " ratio " << ours / ref << " status " << HSM::to_string(st.status) << std::endl;
}

static void bolza_insertion(std::size_t n)
{
  typedef CGAL::Periodic_4_hyperbolic_Delaunay_triangulation_traits_2<> P4Traits;
  typedef CGAL::Periodic_4_hyperbolic_Delaunay_triangulation_2<P4Traits> P4T;
  CGAL::Random rng(static_cast<unsigned int>(n));
  std::vector<K::Point_2> pts;
  while(pts.size() < n) {
    const double x = rng.get_double(-0.85, 0.85), y = rng.get_double(-0.85, 0.85);
    if(x * x + y * y < 0.7) pts.push_back(K::Point_2(x, y));
  }
  std::vector<P4Traits::Point_2> p4pts;
  for(const auto& p : pts) p4pts.push_back(P4Traits::Point_2(p.x(), p.y()));
  // the points P4HT2 accepts (its half-open octagon), found in a first, untimed pass
  std::vector<K::Point_2> acc;
  {
    P4T probe;
    for(std::size_t i = 0; i < n; ++i) if(probe.insert(p4pts[i]) != P4T::Vertex_handle()) acc.push_back(pts[i]);
  }
  const std::size_t accepted = acc.size();
  // timed: P4HT2's range insertion (spatial sort, dummy points removed) and ours (Hilbert order, then the
  // polygon vertex removed)
  double t0 = now();
  P4T p4;
  p4.insert(p4pts.begin(), p4pts.end());
  const double tp4 = now() - t0;
  t0 = now();
  DT t(HSM::Fundamental_polygon<K>::Bolza());
  const std::size_t polygon_vertex = t.vertices().front();
  t.insert_in_frame(acc.begin(), acc.end());
  t.remove(polygon_vertex);
  const double tours = now() - t0;
  std::cout << "bolza_insertion points " << accepted << " ours_seconds " << tours << " p4ht2_seconds " << tp4
            << " ratio " << tours / tp4 << " ours_vertices " << t.number_of_vertices() << " p4ht2_vertices "
            << p4.number_of_vertices() << std::endl;
}

static void counts(const char* name, DT t0)
{
  for(double eps : {0.1, 0.05, 0.01}) {
    struct Run { const char* what; bool chew; double alpha; };
    for(const Run& r : {Run{"size_only", false, 1e-6}, Run{"ruppert_alpha30", false, 30 * CGAL_PI / 180}, Run{"chew", true, 0.5}}) {
      DT t = t0;
      const double c0 = now();
      const auto st = r.chew ? HSM::refine_Chew(t, HSMP::maximum_circumradius(eps))
                             : HSM::refine_Ruppert(t, HSMP::maximum_circumradius(eps, HSMP::minimum_central_angle(r.alpha)));
      std::cout << "vertex_count surface " << name << " epsilon " << eps << " criterion " << r.what << " vertices "
                << st.final_vertices << " min_central_angle_deg " << st.minimum_central_angle * 180 / CGAL_PI
                << " min_angle_deg " << st.minimum_angle * 180 / CGAL_PI << " cpu_seconds " << now() - c0 << std::endl;
    }
  }
}

int main(int argc, char** argv)
{
  if(argc > 3 && std::strcmp(argv[1], "--refine") == 0) {
    DT t(HSM::Fundamental_polygon<K>::regular(std::atoi(argv[2])));
    const double t0 = now();
    const auto st = HSM::refine_Chew(t, HSMP::maximum_circumradius(std::atof(argv[3])));
    const double seconds = now() - t0;
    std::cout << "refine faces " << st.final_faces << " cpu_seconds " << seconds << " triangles_per_s "
              << double(st.final_faces) / seconds << " status " << HSM::to_string(st.status) << std::endl;
    return 0;
  }
  if(argc > 3 && std::strcmp(argv[1], "--throughput") == 0) { throughput(std::atoi(argv[2]), std::atof(argv[3])); return 0; }
  if(argc > 2 && std::strcmp(argv[1], "--insert") == 0) { bolza_insertion(std::size_t(std::atof(argv[2]))); return 0; }
  const bool large = argc > 1 && std::strcmp(argv[1], "--large") == 0;
  // 1. throughput
  for(double eps : {0.02, 0.01}) throughput(2, eps);
  for(double eps : {0.02, 0.0125}) throughput(4, eps);
  if(large) { throughput(2, 0.004); throughput(4, 0.007); }
  // 2. Bolza insertion
  // n random points of a square, of which about 69.5% fall in the octagon (the accepted points are inserted)
  for(std::size_t n : {std::size_t(1000), std::size_t(10000), std::size_t(144000)}) bolza_insertion(n);
  if(large) { bolza_insertion(432000); bolza_insertion(1440000); }
  // 3. vertex counts, Chew versus Ruppert
  counts("bolza", DT(HSM::Fundamental_polygon<K>::Bolza()));
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  Mesh eight;
  if(CGAL::IO::read_polygon_mesh(std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/eight.off", eight)) {
    const auto metric = CGAL::Ricci_flow::hyperbolic_uniformization(eight, CGAL::parameters::do_flip(false));
    const CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<Mesh, Mesh::Property_map<Mesh::Edge_index, double> >
      st(metric.intrinsic_mesh(), metric.edge_length_map());
    counts("eight.off", DT::from_surface_triangulation(st));
  }
  return 0;
}
