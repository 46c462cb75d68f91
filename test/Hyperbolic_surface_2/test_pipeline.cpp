// The pipeline mesh -> Ricci metric -> shared surface -> embedding / words, with public calls only, on every
// closed genus >= 2 mesh of CGAL's demo data (genus 2 to 133) and on elephant_cid.obj. Independent checks:
//  - Gauss-Bonnet (area 4 pi (g - 1)) on the layer's surface built from the metric;
//  - generator i of the word solver (computed basis, greedy and compact) is loop i of the embedding's basis
//    of the same construction, the same halfedges;
//  - with the canonical system: the word the solver reads for loop x_i, evaluated on the embedding's canonical
//    deck transformations, is the embedding's deck transformation of x_i (the two packages read the same
//    loops in the same group, with the same conventions).
#include <CGAL/Discrete_Ricci_flow.h>
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include "cgal_hc_test.h"

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace {

typedef CGAL::Epick::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Input_mesh;
namespace DRF = CGAL::Discrete_Ricci_flow;
namespace SSW = CGAL::Surface_shortest_words;

std::vector<std::string> genus_two_and_more_meshes()
{
  const std::string d = std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/";
  // every closed connected mesh of CGAL's demo data of genus >= 2 (found by computing the genus of all 131
  // OFF files of data/meshes), and the committed elephant_cid.obj
  return {d + "eight.off", d + "joint.off", d + "double-torus-example.off", d + "femur.off", d + "elephant.off",
          d + "helmet.off", d + "3torus.off", d + "anchor.off", d + "anchor_dense.off", d + "refined_elephant.off",
          d + "couplingdown.off", d + "turbine.off", d + "cheese.off",
          std::string(CGAL_HC_DATA_DIR) + "/meshes/elephant_cid.obj"};
}

template <class Isometry>
double relative_distance(const Isometry& a, const Isometry& b)
{
  const double scale = 1 + std::abs(a.normalized().alpha_real());
  return a.distance_to(b) / scale;
}

} // namespace

CGAL_HC_TEST_CASE(pipeline_on_every_closed_genus_at_least_two_mesh)
{
  for(const std::string& file : genus_two_and_more_meshes()) {
    const auto t0 = std::chrono::steady_clock::now();
    Input_mesh input;
    CGAL_HC_CHECK_MSG(CGAL::IO::read_polygon_mesh(file, input), file);
    if(!CGAL::is_triangle_mesh(input)) CGAL::Polygon_mesh_processing::triangulate_faces(input);

    // mesh -> metric -> surface
    const auto metric = DRF::hyperbolic_uniformization(input);
    CGAL_HC_CHECK_MSG(metric.converged(), file);
    const auto surface = metric.hyperbolic_surface();
    const int g = surface.genus();
    CGAL_HC_CHECK_MSG(g >= 2, file);
    CGAL_HC_CHECK_MSG(std::abs(surface.area() - 4 * CGAL_PI * (g - 1)) < 1e-8 * (g - 1), file << ": area " << surface.area());
    CGAL_HC_CHECK_MSG(surface.max_angle_defect() < 1e-10, file << ": defect " << surface.max_angle_defect());

    // -> embedding (deck transformations of the layer's basis loops)
    const auto base = *vertices(metric.intrinsic_mesh()).first;
    const DRF::Hyperbolic_embedding<Point_3> embedding(metric, base);
    CGAL_HC_CHECK(embedding.number_of_generators() == std::size_t(2 * g));
    bool hyperbolic = true;
    for(std::size_t i = 0; i < embedding.number_of_generators(); ++i) hyperbolic = hyperbolic && embedding.absolute_trace(i) > 2;
    CGAL_HC_CHECK_MSG(hyperbolic, file << ": a generator is not hyperbolic");

    // -> words, in the computed basis of each construction: generator i is the embedding's loop i
    typedef typename std::remove_const<typename std::remove_reference<decltype(metric.intrinsic_mesh())>::type>::type Mesh;
    typedef decltype(metric.edge_length_map()) Length_map;
    const SSW::Hyperbolic_surface<Mesh, Length_map> ssw_surface(metric.intrinsic_mesh(), metric.edge_length_map());
    double worst = 0;
    for(const auto construction : {CGAL::Hyperbolic_surface_2::Basis_construction::GREEDY,
                                   CGAL::Hyperbolic_surface_2::Basis_construction::COMPACT}) {
      const bool greedy = construction == CGAL::Hyperbolic_surface_2::Basis_construction::GREEDY;
      const DRF::Hyperbolic_embedding<Point_3> e = greedy ? embedding : DRF::Hyperbolic_embedding<Point_3>(metric, base, construction);
      const std::string what = file + (greedy ? " (greedy basis)" : " (compact basis)");
      // (the named parameters here, the options struct below)
      const SSW::Shortest_word_solver<Mesh, Length_map> computed(
        ssw_surface, base,
        SSW::parameters::basis_construction(construction, SSW::parameters::use_geometry(false,
          SSW::parameters::shorten_generators(false, SSW::parameters::make_canonical(false)))));
      CGAL_HC_CHECK(!computed.is_canonical());
      bool same_loops = true;
      for(std::size_t i = 0; i < e.number_of_generators(); ++i) same_loops = same_loops && computed.generator(i) == e.basis().loop(i);
      CGAL_HC_CHECK_MSG(same_loops, what << ": generator i of the word solver is not loop i of the embedding");

      // -> words in the canonical system. Exact: the word the solver reads for loop x_i and the basis' own
      // expression of x_i in a1, b1, ... (Homotopy_basis::canonical_change) are the same element (their
      // quotient reduces to the empty word). Numerical, where products of deck transformations are well
      // conditioned (genus <= 4): the word evaluated on the canonical deck transformations is x_i's.
      SSW::Shortest_word_options options;
      options.use_geometry = false;
      options.shorten_generators = false;
      options.basis_construction = construction; // (make_canonical: true by default)
      const SSW::Shortest_word_solver<Mesh, Length_map> canonical(ssw_surface, base, options);
      CGAL_HC_CHECK(canonical.is_canonical());
      const auto& change = e.basis().canonical_change();
      bool same_elements = true;
      double worst_here = 0;
      std::vector<typename DRF::Hyperbolic_embedding<Point_3>::Isometry> rho;
      if(g <= 4) rho = e.canonical_deck_transformations();
      for(std::size_t i = 0; i < e.number_of_generators(); ++i) {
        const SSW::Word w = canonical.word(ssw_surface.path_from_halfedges(e.basis().loop(i)));
        SSW::Word quotient = w;
        for(auto it = change.old_in_new[i].rbegin(); it != change.old_in_new[i].rend(); ++it) quotient.push_back(-*it);
        same_elements = same_elements && canonical.reduce(quotient).empty();
        if(rho.empty()) continue;
        typename DRF::Hyperbolic_embedding<Point_3>::Isometry m;
        for(int l : w) m = m * (l > 0 ? rho[std::size_t(l - 1)] : rho[std::size_t(-l - 1)].inverse());
        worst_here = (std::max)(worst_here, relative_distance(m, e.deck_transformation(i)));
      }
      CGAL_HC_CHECK_MSG(same_elements, what << ": the solver's word of x_i is not the basis' x_i in the canonical generators");
      CGAL_HC_CHECK_MSG(worst_here < 1e-6, what << ": word of x_i evaluated on the canonical deck transformations is off by " << worst_here);
      worst = (std::max)(worst, worst_here);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "  " << file.substr(file.find_last_of('/') + 1) << ": genus " << g << ", relator defect "
              << embedding.relator_defect() << ", words vs deck transformations " << worst << ", " << seconds << " s" << std::endl;
  }
}
