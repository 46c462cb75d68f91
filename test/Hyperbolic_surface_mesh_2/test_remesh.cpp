// Conformal remeshing of CGAL's demo meshes of genus 2 to 4 and of surface-layer input: the remesh is a
// valid closed manifold of the same genus, its vertices lie on the input faces (when the flow needed no
// intrinsic flips), the refined surface meets the criteria; bad input throws.
#include "test_support.h"

#include <CGAL/Hyperbolic_surface_mesh_2/conformal_remesh.h>
#include <CGAL/Discrete_Ricci_flow/Bolza_surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/bounding_box.h>

#include <set>
#include <string>

using namespace hsm2_test;
namespace HSM = CGAL::Hyperbolic_surface_mesh_2;
namespace HSMP = CGAL::Hyperbolic_surface_mesh_2::parameters;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

Mesh read(const std::string& name)
{
  Mesh m;
  const std::string path = std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/" + name;
  CGAL_HC_CHECK_MSG(CGAL::IO::read_polygon_mesh(path, m) && !m.is_empty(), "cannot read " << path);
  return m;
}

long genus_of(const Mesh& m) { return (2 - (long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces()))) / 2; }

} // namespace

CGAL_HC_TEST_CASE(remesh_demo_meshes)
{
  for(const char* name : {"eight.off", "joint.off", "femur.off", "helmet.off", "elephant.off", "anchor.off"}) {
    const Mesh in = read(name);
    const long g = genus_of(in);
    for(bool chew : {false, true}) {
      Mesh out;
      const auto rep = HSM::conformal_remesh(in, out, HSMP::maximum_circumradius(0.25, HSMP::use_Chew(chew)));
      CGAL_HC_CHECK_MSG(rep.refinement.status == HSM::Refinement_status::SUCCESS, name << ": " << rep.refinement);
      CGAL_HC_CHECK(rep.genus == g && rep.refinement.genus == g);
      CGAL_HC_CHECK_MSG(out.is_valid(false) && CGAL::is_closed(out) && CGAL::is_triangle_mesh(out), name);
      CGAL_HC_CHECK_MSG(genus_of(out) == g, name << ": output genus " << genus_of(out));
      std::vector<std::size_t> cc(out.number_of_faces());
      CGAL_HC_CHECK(CGAL::Polygon_mesh_processing::connected_components(out,
                      CGAL::make_property_map(cc)) == 1);
      CGAL_HC_CHECK(rep.locations.size() == out.number_of_vertices());
      CGAL_HC_CHECK(rep.refinement.maximum_circumradius <= 0.25 * (1 + 1e-9));
      // every output vertex is a convex combination of the corners of its face
      std::size_t outside = 0;
      for(const auto& l : rep.locations) {
        const double s = l.barycentric[0] + l.barycentric[1] + l.barycentric[2];
        if(!(std::abs(s - 1) < 1e-12 && l.barycentric[0] >= 0 && l.barycentric[1] >= 0 && l.barycentric[2] >= 0)) ++outside;
      }
      CGAL_HC_CHECK(outside == 0);
      // distance of the output vertices to the input surface, relative to the bounding box diagonal: 0 up to
      // rounding without flips; with flips (the fallback) the new vertices lie on chords (reported, documented)
      {
        typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
        typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
        const Tree tree(faces(in).first, faces(in).second, in);
        const auto box = CGAL::bounding_box(in.points().begin(), in.points().end());
        const double diag = std::sqrt(CGAL::squared_distance(box.min(), box.max()));
        double worst = 0;
        for(auto v : vertices(out)) worst = (std::max)(worst, std::sqrt(tree.squared_distance(out.point(v))) / diag);
        std::cout << "  " << name << (chew ? " Chew" : " Ruppert") << ": flow with flips " << rep.flow_used_flips
                  << ", max distance of an output vertex to the input surface / bbox diagonal " << worst << std::endl;
        if(!rep.flow_used_flips) CGAL_HC_CHECK_MSG(worst < 1e-12, name << ": " << worst);
      }
      if(!rep.flow_used_flips) {
        // the input vertices are kept (same positions) and the faces of the metric are the input faces
        std::size_t moved = 0;
        std::size_t i = 0;
        for(auto v : vertices(in)) {
          if(CGAL::squared_distance(in.point(v), out.point(Mesh::Vertex_index(std::uint32_t(i)))) > 1e-24) ++moved;
          ++i;
        }
        CGAL_HC_CHECK_MSG(moved == 0, name << ": " << moved << " input vertices moved");
        // and every output vertex is the point of its input face (faces(in) order) with its coordinates
        std::vector<Mesh::Face_index> fs(faces(in).begin(), faces(in).end());
        double worst = 0;
        i = 0;
        for(const auto& l : rep.locations) {
          const auto h = halfedge(fs[l.face], in);
          const K::Point_3 a = in.point(source(h, in)), b = in.point(source(next(h, in), in)), c = in.point(source(prev(h, in), in));
          const auto& w = l.barycentric;
          const K::Point_3 p(w[0] * a.x() + w[1] * b.x() + w[2] * c.x(), w[0] * a.y() + w[1] * b.y() + w[2] * c.y(),
                             w[0] * a.z() + w[1] * b.z() + w[2] * c.z());
          worst = (std::max)(worst, CGAL::squared_distance(p, out.point(Mesh::Vertex_index(std::uint32_t(i++)))));
        }
        CGAL_HC_CHECK_MSG(worst < 1e-20, name << ": an output vertex is not on its input face, " << worst);
      }
    }
  }
}

CGAL_HC_TEST_CASE(remesh_bad_input)
{
  Mesh out;
  // genus 0 and genus 1
  Mesh sphere = read("sphere.off");
  CGAL_HC_CHECK_THROWS(HSM::conformal_remesh(sphere, out, HSMP::maximum_circumradius(0.2)), CGAL::Invalid_mesh_error);
  // an open mesh: remove one face of eight.off
  Mesh open = read("eight.off");
  CGAL::Euler::remove_face(halfedge(*faces(open).begin(), open), open);
  CGAL_HC_CHECK_THROWS(HSM::conformal_remesh(open, out, HSMP::maximum_circumradius(0.2)), CGAL::Invalid_mesh_error);
  Mesh empty;
  CGAL_HC_CHECK_THROWS(HSM::conformal_remesh(empty, out, HSMP::maximum_circumradius(0.2)), CGAL::Invalid_mesh_error);
  // options
  const Mesh eight = read("eight.off");
  CGAL_HC_CHECK_THROWS(HSM::conformal_remesh(eight, out, HSMP::maximum_circumradius(0.0)), CGAL::Invalid_option_error);
}

CGAL_HC_TEST_CASE(surface_layer_input_Bolza)
{
  // the Ricci-flow metric of the Bolza mesh (genus 2, 48 symmetries) through the shared layer: the refined
  // surface has area 4 pi and the Bolza systole bounds every loop from below
  const Mesh m = CGAL::Ricci_flow::make_Bolza_surface_mesh<K::Point_3>(2);
  const auto metric = CGAL::Ricci_flow::hyperbolic_uniformization(m);
  CGAL_HC_CHECK(metric.converged());
  const CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<Mesh, Mesh::Property_map<Mesh::Edge_index, double> >
    st(metric.intrinsic_mesh(), metric.edge_length_map());
  DT t = DT::from_surface_triangulation(st);
  check_triangulation(t, 2);
  CGAL_HC_CHECK(t.number_of_vertices() == m.number_of_vertices());
  const auto s = HSM::refine_Chew(t, HSMP::maximum_circumradius(0.2));
  CGAL_HC_CHECK(s.status == HSM::Refinement_status::SUCCESS);
  check_triangulation(t, 2);
  CGAL_HC_CHECK(t.is_simplicial_complex());
}
