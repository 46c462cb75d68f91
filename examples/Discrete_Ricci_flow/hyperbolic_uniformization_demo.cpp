// Hyperbolic uniformization of a closed surface of genus >= 2 and the embedding of its universal cover in the
// Poincare disk. Usage: hyperbolic_uniformization_demo [mesh file] [tiling depth]
// (default: CGAL's eight.off). Writes ricci_fundamental_domain.svg and ricci_tiling.svg into the current
// directory and prints the iterations, curvature error, area vs 4 pi (g - 1), the traces of the deck
// transformations and the relator defects at vertex 0 and of the best-conditioned embedding.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace RF = CGAL::Ricci_flow;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/eight.off";
  const int depth = argc > 2 ? std::atoi(argv[2]) : 2;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh)) {
    std::cerr << "cannot read " << file << std::endl;
    return EXIT_FAILURE;
  }
  try {
    // Newton's method with Ptolemy flips; the callback reports progress
    auto metric = RF::hyperbolic_uniformization(mesh, CGAL::parameters::callback([](const RF::Flow_progress& p) {
      std::cout << "  iteration " << p.iteration << ": max |K| = " << p.max_curvature_error << ", step " << p.step_length
                << ", flips " << p.number_of_flips << std::endl;
      return true;
    }));
    const auto& st = metric.statistics();
    const double area = metric.total_area(), expected = 4 * CGAL_PI * (metric.genus() - 1);
    std::cout << file << ": " << mesh.number_of_vertices() << " vertices, genus " << metric.genus() << "\n"
              << "status: " << RF::to_string(st.status) << ", " << st.iterations << " Newton iterations, "
              << st.number_of_factorizations << " factorizations (" << st.number_of_symbolic_factorizations
              << " symbolic), " << st.number_of_flips << " Ptolemy flips, " << st.time_seconds << " s\n"
              << "max |K_i| = " << st.max_curvature_error << " rad\n"
              << "area = " << area << ", 4 pi (g - 1) = " << expected << ", difference " << area - expected << std::endl;
    if(!metric.converged()) return EXIT_FAILURE;

    RF::Hyperbolic_embedding<K::Point_3> embedding(metric);
    std::cout << "homotopy basis at vertex " << std::size_t(embedding.base_vertex()) << ": "
              << embedding.number_of_generators() << " loops" << std::endl;
    const auto deck = embedding.deck_transformations();
    for(std::size_t i = 0; i < deck.size(); ++i)
      std::cout << "  loop " << i << ": " << embedding.homotopy_basis()[i].size() << " edges, length "
                << embedding.loop_length(i) << ", |trace| = " << 2 * deck[i].half_trace()
                << ", translation length 2 acosh(|trace|/2) = " << embedding.translation_length(i) << std::endl;
    std::cout << "relator:";
    for(const auto& l : embedding.relator()) std::cout << " g" << l.first << (l.second > 0 ? "" : "^-1");
    std::cout << "\nrelator product distance to +-I: " << embedding.relator_defect() << std::endl;
    // the most accurate double matrices: the base vertex and the homotopy basis (greedy or compact) whose relator
    // has the smallest condition (high genus: turbine.off 3.5e-7 at vertex 0, 2.8e-10 with these 8 candidates)
    const auto best = RF::Hyperbolic_embedding<K::Point_3>::best_conditioned(metric, 8);
    std::cout << "best conditioned of 8 base vertices x 2 bases: vertex " << std::size_t(best.base_vertex())
              << (best.basis().construction() == CGAL::Hyperbolic_surface_2::Basis_construction::COMPACT ? ", compact" : ", greedy")
              << " basis, relator defect " << best.relator_defect() << std::endl;
    std::cout << "fundamental domain: " << embedding.domain_boundary().size() << " boundary edges, "
              << embedding.side_pairings().size() << " sides" << std::endl;
    embedding.write_fundamental_domain_svg("ricci_fundamental_domain.svg");
    const std::size_t tiles = embedding.write_tiling_svg("ricci_tiling.svg", depth);
    std::cout << "wrote ricci_fundamental_domain.svg and ricci_tiling.svg (" << tiles << " tiles)" << std::endl;
  } catch(const RF::Ricci_flow_error& e) {
    std::cerr << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
