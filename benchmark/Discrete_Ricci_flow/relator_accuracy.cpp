// What dominates the relator defect of Hyperbolic_embedding (issue 11 item 2): for each mesh (default: the
// ill-conditioned demo meshes turbine.off, couplingdown.off, cheese.off),
//  1. the flow stopped at several accuracies (and at the default rounding level), embedding at base vertex 0:
//     the embedding polishes the metric in long double, so the defect no longer follows the flow's max |K|;
//  2. `number_of_bases` base vertices spread over the index range: the user's defect (double products of the
//     returned deck transformations), the long-double defect, the relator condition and the ratio
//     defect / condition (about 1e-15 if rounding in double dominates, as the manual says);
//  3. for each embedding, the exact deck transformations (deck_transformations_exact()): their relator defect,
//     the precision the embedding chose, the max |K| of the metric it used, log10 of the condition measured at
//     that precision, and the time of that path as a ratio to the time of the embedding's construction.
// Usage: relator_accuracy [number_of_bases [mesh ...]]
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace RF = CGAL::Discrete_Ricci_flow;

template <class Metric>
void line(const std::string& what, const Metric& r, std::size_t base)
{
  const auto t0 = std::chrono::steady_clock::now();
  const RF::Hyperbolic_embedding<K::Point_3> e(r, Mesh::Vertex_index(static_cast<Mesh::size_type>(base)));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double min_trace = 1e300;
  for(std::size_t i = 0; i < e.number_of_generators(); ++i) min_trace = (std::min)(min_trace, e.absolute_trace(i));
  const double d = e.relator_defect(), c = e.relator_condition();
  const auto t1 = std::chrono::steady_clock::now();
  const double exact = e.relator_defect_exact();
  const double exact_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  std::cout << "  " << what << " base " << base << ": max |K| " << e.input_max_curvature() << " -> " << e.polished_max_curvature()
            << ", defect " << d << " (long double " << e.relator_defect_long_double() << "), condition " << c
            << ", defect / condition " << d / c << ", min |trace| " << min_trace << ", " << seconds << " s" << std::endl
            << "    exact: defect " << exact << " at " << e.exact_precision() << " bits (" << e.exact_attempts()
            << " rungs), max |K| " << e.exact_polished_max_curvature() << ", log10 condition " << e.exact_relator_condition_log10()
            << ", time " << exact_seconds / seconds << " x the embedding's construction" << std::endl;
}

int main(int argc, char** argv)
{
  const std::size_t nb = argc > 1 ? std::size_t(std::atoi(argv[1])) : 16;
  std::vector<std::string> files;
  for(int a = 2; a < argc; ++a) files.push_back(argv[a]);
  if(files.empty())
    for(const char* n : {"turbine.off", "couplingdown.off", "cheese.off"})
      files.push_back(std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/" + n);
  for(const std::string& f : files) {
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(f, m)) { std::cerr << "cannot read " << f << std::endl; continue; }
    if(!CGAL::is_triangle_mesh(m)) CGAL::Polygon_mesh_processing::triangulate_faces(m);
    std::cout << f << " (" << m.number_of_faces() << " faces)" << std::endl;
    try {
      for(double acc : {1e-9, 1e-11, 1e-13}) {
        const auto r = RF::hyperbolic_uniformization(m, CGAL::parameters::accuracy(acc));
        std::ostringstream os; os << "accuracy " << acc;
        if(r.converged()) line(os.str(), r, 0);
      }
      const auto r = RF::hyperbolic_uniformization(m); // default: the rounding level
      for(std::size_t i = 0; i < nb; ++i) line("default", r, (i * r.intrinsic_mesh().number_of_vertices()) / nb);
    } catch(const CGAL::Hyperbolic_geometry_error& e) { std::cout << "  " << e.what() << std::endl; }
  }
}
