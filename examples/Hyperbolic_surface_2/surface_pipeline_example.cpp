// The pipeline with public calls only: closed mesh -> Ricci-flow metric -> the shared surface layer ->
// embedding (deck transformations, canonical fundamental polygon) and shortest words of a loop.
//   surface_pipeline_example [mesh.off]      (default: CGAL's eight.off, genus 2)
// Writes surface_pipeline_domain.svg (the fundamental domain in the Poincare disk) to the current folder.
#include <CGAL/Discrete_Ricci_flow.h>
#include <CGAL/Surface_shortest_words.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

typedef CGAL::Epick::Point_3 Point_3;
namespace DRF = CGAL::Discrete_Ricci_flow;
namespace SSW = CGAL::Surface_shortest_words;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/eight.off";
  CGAL::Surface_mesh<Point_3> mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh)) { std::cerr << "cannot read " << file << std::endl; return EXIT_FAILURE; }
  if(!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  try {
    // 1. the uniformization metric, and the surface of the shared layer on it
    const auto metric = DRF::hyperbolic_uniformization(mesh);
    const auto surface = metric.hyperbolic_surface();
    std::cout << file << ": genus " << surface.genus() << ", area " << surface.area() << " (4 pi (g-1) = "
              << 4 * CGAL_PI * (surface.genus() - 1) << "), max angle defect " << surface.max_angle_defect() << "\n";

    // 2. the embedding: deck transformation i is the holonomy of the layer's basis loop i
    const auto base = *vertices(metric.intrinsic_mesh()).first;
    const DRF::Hyperbolic_embedding<Point_3> embedding(metric, base);
    for(std::size_t i = 0; i < embedding.number_of_generators(); ++i)
      std::cout << "  x" << i + 1 << ": " << embedding.basis().loop(i).size() << " edges, |trace| "
                << embedding.absolute_trace(i) << ", translation length " << embedding.translation_length(i) << "\n";
    std::cout << "relator defect " << embedding.relator_defect() << ", canonical relator defect "
              << embedding.canonical_relator_defect() << "\n";
    embedding.write_fundamental_domain_svg("surface_pipeline_domain.svg");

    // 3. words in the canonical system a1, b1, ... computed from the same basis
    typedef CGAL::Surface_mesh<Point_3> Mesh;
    typedef decltype(metric.edge_length_map()) Length_map;
    const SSW::Hyperbolic_surface<Mesh, Length_map> ssw(metric.intrinsic_mesh(), metric.edge_length_map());
    const SSW::Shortest_word_solver<Mesh, Length_map> solver(ssw, base);
    // a random closed walk of 200 edges from the base vertex, closed along the tree
    std::mt19937 rng(1);
    std::vector<Mesh::Halfedge_index> walk;
    Mesh::Vertex_index v = base;
    const Mesh& im = metric.intrinsic_mesh();
    for(int k = 0; k < 200; ++k) {
      std::vector<Mesh::Halfedge_index> out;
      for(auto h : CGAL::halfedges_around_source(v, im)) out.push_back(h);
      walk.push_back(out[rng() % out.size()]);
      v = im.target(walk.back());
    }
    const auto back = embedding.basis().tree_path(v);
    for(auto it = back.rbegin(); it != back.rend(); ++it) walk.push_back(im.opposite(*it));
    const auto result = solver.solve(ssw.path_from_halfedges(walk));
    std::cout << "a random loop of " << walk.size() << " edges is " << solver.word_to_string(result.word)
              << " (" << result.word.size() << " letters, shortest)";
    if(result.used_geometry) std::cout << "; its shortest representative through the base has length " << result.length;
    std::cout << "\nwrote surface_pipeline_domain.svg" << std::endl;
  } catch(const CGAL::Hyperbolic_geometry_error& e) {
    std::cerr << "error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
