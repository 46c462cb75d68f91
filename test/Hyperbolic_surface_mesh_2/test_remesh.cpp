// Conformal remeshing of CGAL's demo meshes of genus 2 to 4 and of surface-layer input: the remesh is a
// valid closed manifold of the same genus, its vertices lie on the input surface (with or without the flow's
// intrinsic flips: the map through the decorated ideal surface), the refined surface meets the criteria; bad
// input throws. `test_Hyperbolic_surface_mesh_2 --remesh-all-demo-meshes` (not run by CI) remeshes every closed
// demo mesh of genus >= 2 and prints the distances.
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
#include <CGAL/boost/graph/Euler_operations.h>

#include "../Discrete_Ricci_flow/demo_meshes.h"

#include <chrono>
#include <random>
#include <set>
#include <string>

using namespace hsm2_test;
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

typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;

double bbox_diagonal(const Mesh& m)
{
  const auto box = CGAL::bounding_box(m.points().begin(), m.points().end());
  return std::sqrt(CGAL::squared_distance(box.min(), box.max()));
}

/// the largest distance of a vertex of `out` to the surface of `in`, relative to the bounding box diagonal
double max_relative_distance(const Mesh& in, const Mesh& out)
{
  const Tree tree(faces(in).first, faces(in).second, in);
  double worst = 0;
  for(auto v : vertices(out)) worst = (std::max)(worst, std::sqrt(tree.squared_distance(out.point(v))));
  return worst / bbox_diagonal(in);
}

/// the point of `in` at a location (barycentric coordinates w.r.t. the sources of halfedge(f), next, prev)
K::Point_3 point_at(const Mesh& in, std::size_t face, const std::array<long double, 3>& w)
{
  const auto h = halfedge(*std::next(faces(in).begin(), long(face)), in);
  const K::Point_3 p[3] = {in.point(source(h, in)), in.point(source(next(h, in), in)), in.point(source(prev(h, in), in))};
  long double c[3] = {0, 0, 0}, s = w[0] + w[1] + w[2];
  for(int i = 0; i < 3; ++i) {
    c[0] += w[i] * p[i].x(); c[1] += w[i] * p[i].y(); c[2] += w[i] * p[i].z();
  }
  return K::Point_3(double(c[0] / s), double(c[1] / s), double(c[2] / s));
}

/// `m` with some edges flipped in R^3 (no flip that would create a multi-edge): a valid mesh of the same genus
/// whose triangulation is far from Delaunay, so that its flow needs Ptolemy flips
Mesh with_flipped_edges(Mesh m, std::size_t count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::size_t done = 0;
  for(std::size_t attempt = 0; done < count && attempt < 100 * count; ++attempt) {
    const auto e = *std::next(edges(m).begin(), long(rng() % m.number_of_edges()));
    const auto h = halfedge(e, m);
    const auto c = target(next(h, m), m), d = target(next(opposite(h, m), m), m);
    if(c == d || CGAL::halfedge(c, d, m).second || degree(source(h, m), m) < 4 || degree(target(h, m), m) < 4) continue;
    CGAL::Euler::flip_edge(h, m);
    ++done;
  }
  return m;
}

/// The whole map check on a metric of `in` (hyperbolic, vertex scaling): every vertex of the refined surface
/// goes to a point of `in` within 1e-9 of the bounding box diagonal of the surface (AABB distance), and a point
/// on an edge of the intrinsic triangulation goes to the same point of `in` from both of its faces. Returns the
/// largest relative distance.
template <class Metric>
double check_map(const std::string& name, const Mesh& in, const Metric& metric, double epsilon)
{
  const auto st = metric.hyperbolic_surface();
  DT t = DT::from_surface_triangulation(st);
  const auto stats = HSM::refine_Ruppert(t, HSMP::maximum_circumradius(epsilon));
  CGAL_HC_CHECK_MSG(stats.status == HSM::Refinement_status::SUCCESS, name << ": " << stats);
  const std::vector<HSM::Mesh_location> loc = HSM::input_locations(t, in, metric);
  Mesh pts;
  for(std::size_t v : t.vertices())
    pts.add_vertex(point_at(in, loc[v].face, {{loc[v].barycentric[0], loc[v].barycentric[1], loc[v].barycentric[2]}}));
  const double worst = max_relative_distance(in, pts);
  CGAL_HC_CHECK_MSG(worst <= 1e-9, name << ": an output vertex is off the input surface by " << worst << " of the diagonal");
  // continuity across the edges of the intrinsic triangulation: the same projective coordinates on the two
  // corners of an edge, from either face (the lifts are chart independent)
  Mesh m0;
  const auto map = HSM::internal::ideal_surface_map(in, metric, m0);
  const auto& im = metric.intrinsic_mesh();
  std::vector<HSM::internal::Face_point> fp;
  std::vector<std::pair<std::size_t, std::size_t> > pairs;
  for(auto e : im.edges()) {
    const auto h = im.halfedge(e), o = im.opposite(h);
    auto corner = [&](Mesh::Halfedge_index g) { // index of the corner of source(g) in face(g)
      int i = 0;
      for(auto a = im.halfedge(im.face(g)); a != g; a = im.next(a)) ++i;
      return i;
    };
    for(long double t0 : {0.5L, 0.125L}) {
      // h: s -> t; in face(o) the corner of t is corner(o) and s is the next one
      std::array<long double, 3> bp{{0, 0, 0}}, bq{{0, 0, 0}};
      bp[corner(h)] = t0; bp[(corner(h) + 1) % 3] = 1 - t0;
      bq[(corner(o) + 1) % 3] = t0; bq[corner(o)] = 1 - t0;
      const HSM::internal::Face_point p = map.from_final(im.face(h), bp), q = map.from_final(im.face(o), bq);
      pairs.emplace_back(fp.size(), fp.size() + 1);
      fp.push_back(p); fp.push_back(q);
    }
  }
  map.to_input(fp);
  double gap = 0;
  for(const auto& pq : pairs)
    gap = (std::max)(gap, std::sqrt(CGAL::squared_distance(point_at(in, fp[pq.first].face, fp[pq.first].w),
                                                           point_at(in, fp[pq.second].face, fp[pq.second].w))));
  gap /= bbox_diagonal(in);
  CGAL_HC_CHECK_MSG(gap <= 1e-9, name << ": a point of an intrinsic edge has two images, " << gap << " apart");
  std::cout << "  " << name << ": " << metric.initial_flips().size() << " initial and " << metric.flips().size()
            << " Ptolemy flips, " << t.number_of_vertices() << " vertices: max distance / diagonal " << worst
            << ", max gap across intrinsic edges " << gap << std::endl;
  return worst;
}

/// true if the two faces of e unfold into a strictly convex quadrilateral (positions of m as lengths)
bool convex_quad(const Mesh& m, Mesh::Edge_index e)
{
  const auto h = m.halfedge(e), o = m.opposite(h);
  const K::Point_3 &a = m.point(m.source(h)), &b = m.point(m.target(h)), &c = m.point(m.target(m.next(h))),
                   &d = m.point(m.target(m.next(o)));
  auto angle = [](const K::Point_3& p, const K::Point_3& q, const K::Point_3& r) { // at q
    const auto u = p - q, w = r - q;
    return std::atan2(std::sqrt(CGAL::cross_product(u, w).squared_length()), u * w);
  };
  return angle(c, a, b) + angle(b, a, d) < CGAL_PI - 1e-3 && angle(c, b, a) + angle(a, b, d) < CGAL_PI - 1e-3;
}

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
      // distance of the output vertices to the input surface, relative to the bounding box diagonal, with or
      // without flips (the chord triangles of the intrinsic faces gave 2.5e-3 to 8.2e-2 with flips)
      {
        const double worst = max_relative_distance(in, out);
        std::cout << "  " << name << (chew ? " Chew" : " Ruppert") << ": flow with flips " << rep.flow_used_flips
                  << ", max distance of an output vertex to the input surface / bbox diagonal " << worst << std::endl;
        CGAL_HC_CHECK_MSG(worst <= 1e-9, name << ": " << worst);
      }
      {
        // the input vertices are kept (same positions) and every location is on an input face
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

CGAL_HC_TEST_CASE(remesh_map_with_forced_flips)
{
  // eight.off with 40 edges flipped in R^3: the flow needs Ptolemy flips (checked), and with
  // geometric_initial_flips(true) also Euclidean flips of the input first
  const Mesh in = with_flipped_edges(read("eight.off"), 40, 7);
  CGAL_HC_CHECK(genus_of(in) == 2 && in.is_valid(false));
  const auto metric = CGAL::Ricci_flow::hyperbolic_uniformization(in);
  CGAL_HC_CHECK(metric.converged());
  CGAL_HC_CHECK_MSG(metric.flips().size() > 0 && metric.flips().size() == metric.statistics().number_of_flips,
                    metric.flips().size() << " flips recorded, " << metric.statistics().number_of_flips << " counted");
  check_map("eight.off with 40 flipped edges", in, metric, 0.25);
  const auto geo = CGAL::Ricci_flow::hyperbolic_uniformization(in, CGAL::Ricci_flow::parameters::geometric_initial_flips(true));
  CGAL_HC_CHECK(geo.converged());
  CGAL_HC_CHECK(geo.initial_flips().size() > 0 && geo.initial_flips().size() == geo.statistics().number_of_initial_flips);
  check_map("eight.off with 40 flipped edges, geometric initial flips", in, geo, 0.25);
  // the flow's own flips on a demo mesh that needs them
  const Mesh joint = read("joint.off");
  const auto mj = CGAL::Ricci_flow::hyperbolic_uniformization(joint);
  CGAL_HC_CHECK(mj.converged() && mj.flips().size() > 0);
  check_map("joint.off", joint, mj, 0.25);
  // the locations need the mesh the metric was computed on
  const DT tj = DT::from_surface_triangulation(mj.hyperbolic_surface());
  CGAL_HC_CHECK_THROWS(HSM::input_locations(tj, in, mj), CGAL::Invalid_input_error);
  Mesh joint_flipped = with_flipped_edges(joint, 1, 5);
  CGAL_HC_CHECK_THROWS(HSM::input_locations(tj, joint_flipped, mj), CGAL::Invalid_input_error);
  CGAL_HC_CHECK(joint_flipped.number_of_faces() == joint.number_of_faces());
  // a metric of a circle-packing scheme: its conformal factors are not the vertex-scaling decoration
  const Mesh eight = read("eight.off");
  std::vector<double> cp_lengths(eight.number_of_edges());
  const auto cp = CGAL::Ricci_flow::compute_metric(eight, CGAL::Constant_property_map<Mesh::Vertex_index, double>(0.0),
                                                   CGAL::make_property_map(cp_lengths),
                                                   CGAL::Ricci_flow::parameters::scheme(CGAL::Ricci_flow::Scheme::TANGENTIAL_CIRCLE_PACKING));
  CGAL_HC_CHECK(cp.converged() && cp.scheme() == CGAL::Ricci_flow::Scheme::TANGENTIAL_CIRCLE_PACKING);
  const DT tcp = DT::from_surface_triangulation(cp.hyperbolic_surface());
  CGAL_HC_CHECK_THROWS(HSM::input_locations(tcp, eight, cp), CGAL::Invalid_input_error);
}

CGAL_HC_TEST_CASE(ideal_map_flip_twice_is_identity)
{
  // flipping an edge twice gives back the triangulation (other face and halfedge indices) and, Ptolemy or
  // Euclidean, the same lengths: the map must be the identity of the surface
  typedef HSM::internal::Ideal_surface_map<K::Point_3> Map;
  const Mesh in = read("eight.off");
  std::vector<double> len(in.number_of_edges());
  for(auto e : in.edges()) len[e] = std::sqrt(CGAL::squared_distance(in.point(in.vertex(e, 0)), in.point(in.vertex(e, 1))));
  const std::vector<double> u(in.number_of_vertices(), 0.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unif(0, 1);
  double worst = 0;
  for(int trial = 0; trial < 20; ++trial) {
    std::vector<Mesh::Edge_index> twice;
    Mesh fin = in;
    const bool euclidean = trial % 2 == 0;
    for(int k = 0; k < 3; ++k) {
      Mesh::Edge_index e(std::uint32_t(rng() % in.number_of_edges()));
      // a Euclidean (metric-preserving) flip needs a convex quadrilateral: the angles at a and b below pi
      while(euclidean && !convex_quad(fin, e)) e = Mesh::Edge_index(std::uint32_t(rng() % in.number_of_edges()));
      twice.push_back(e); twice.push_back(e);
      CGAL::Discrete_Ricci_flow::internal::flip_connectivity(fin, e);
      CGAL::Discrete_Ricci_flow::internal::flip_connectivity(fin, e);
    }
    const Map map(in, len, euclidean ? twice : std::vector<Mesh::Edge_index>(), euclidean ? std::vector<Mesh::Edge_index>() : twice, u, fin);
    CGAL_HC_CHECK(map.number_of_flips() == 6);
    std::vector<HSM::internal::Face_point> p;
    for(int k = 0; k < 200; ++k) {
      HSM::internal::Face_point q;
      q.face = rng() % fin.number_of_faces();
      q.w = {{unif(rng), unif(rng), k % 4 == 0 ? 0.0 : unif(rng)}}; // some on an edge
      p.push_back(q);
    }
    std::vector<HSM::internal::Face_point> mapped = p;
    map.to_input(mapped);
    for(std::size_t k = 0; k < p.size(); ++k) {
      // the point in R^3 from the corners of the final face
      auto h = fin.halfedge(Mesh::Face_index(std::uint32_t(p[k].face)));
      long double c[3] = {0, 0, 0}, s = 0;
      for(int i = 0; i < 3; ++i, h = fin.next(h)) {
        const K::Point_3& a = in.point(fin.source(h));
        c[0] += p[k].w[i] * a.x(); c[1] += p[k].w[i] * a.y(); c[2] += p[k].w[i] * a.z(); s += p[k].w[i];
      }
      const K::Point_3 expected(double(c[0] / s), double(c[1] / s), double(c[2] / s));
      worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(expected, point_at(in, mapped[k].face, mapped[k].w))));
    }
  }
  worst /= bbox_diagonal(in);
  std::cout << "  flipping twice: largest displacement / diagonal " << worst << std::endl;
  CGAL_HC_CHECK_MSG(worst < 1e-12, "flipping twice moves a point by " << worst << " of the diagonal");
  // a replay that does not end at the given triangulation is refused
  std::vector<Mesh::Edge_index> once(1, Mesh::Edge_index(0));
  CGAL_HC_CHECK_THROWS(Map(in, len, std::vector<Mesh::Edge_index>(), once, u, in), CGAL::Invalid_input_error);
}

CGAL_HC_TEST_CASE(ideal_map_circumcircle_to_circumcircle)
{
  // The map of a final face to its input face is the radial projection between their chord planes in R^{2,1},
  // which keeps the light cone: it maps the circumcircle of the final chord triangle (sides 2 sinh(l / 2) from
  // the metric's lengths) to the circumcircle of the input triangle (the input lengths). A wrong power of
  // e^{u_i} in the weights breaks this. Points of the circumcircle in barycentric coordinates:
  // (a^2 / t1, b^2 / t2, c^2 / t3) with t1 + t2 + t3 = 0 (a, b, c the sides opposite the corners).
  const Mesh in = read("eight.off");
  const auto metric = CGAL::Ricci_flow::hyperbolic_uniformization(in, CGAL::parameters::do_flip(false));
  CGAL_HC_CHECK(metric.converged() && metric.flips().empty());
  Mesh m0;
  const auto map = HSM::internal::ideal_surface_map(in, metric, m0);
  const auto& im = metric.intrinsic_mesh();
  double worst = 0, spread = 0;
  for(auto f : im.faces()) {
    // side opposite corner i: the halfedge from corner i+1 to corner i+2
    Mesh::Halfedge_index hs[3];
    hs[0] = im.halfedge(f); hs[1] = im.next(hs[0]); hs[2] = im.next(hs[1]);
    long double chord2[3], input2[3];
    for(int i = 0; i < 3; ++i) {
      const auto h = hs[(i + 1) % 3];
      const long double c = 2 * std::sinh(0.5L * metric.length(h));
      chord2[i] = c * c;
      input2[i] = CGAL::squared_distance(in.point(im.source(h)), in.point(im.target(h)));
    }
    for(long double s : {0.5L, 2.0L, -3.0L}) {
      const long double t[3] = {1, s, -1 - s};
      std::array<long double, 3> beta;
      for(int i = 0; i < 3; ++i) beta[i] = chord2[i] / t[i];
      const auto w = map.from_final(std::size_t(f), beta).w;
      // the circumcircle equation of the input triangle, relative to its terms
      long double e = 0, scale = 0;
      for(int i = 0; i < 3; ++i) {
        const long double term = input2[i] * w[(i + 1) % 3] * w[(i + 2) % 3];
        e += term; scale += std::abs(term);
      }
      worst = (std::max)(worst, double(std::abs(e) / scale));
      // without e^{u_i} the weights would be beta: how far that is from the input circumcircle (the test's power)
      long double e0 = 0, scale0 = 0;
      for(int i = 0; i < 3; ++i) {
        const long double term = input2[i] * beta[(i + 1) % 3] * beta[(i + 2) % 3];
        e0 += term; scale0 += std::abs(term);
      }
      spread = (std::max)(spread, double(std::abs(e0) / scale0));
    }
  }
  std::cout << "  circumcircle equation of the input faces at the images: " << worst
            << " (weights without e^u: " << spread << ")" << std::endl;
  CGAL_HC_CHECK_MSG(worst < 1e-12, "the circumcircle of a final face is not mapped to the input circumcircle: " << worst);
  CGAL_HC_CHECK_MSG(spread > 1e-3, "the conformal factors of eight.off are too uniform for this check: " << spread);
}

/// `test_Hyperbolic_surface_mesh_2 --remesh-all-demo-meshes`: every closed demo mesh of genus >= 2 (not run by
/// CI: minutes); returns non-zero if a remesh fails or a vertex is off the surface by more than 1e-9
int remesh_all_demo_meshes()
{
  int bad = 0;
  for(const auto& nm : ricci_test::demo_meshes(2, 1000)) {
    const auto t0 = std::chrono::steady_clock::now();
    Mesh out;
    try {
      const auto rep = HSM::conformal_remesh(nm.second, out, HSMP::maximum_circumradius(0.25));
      const double worst = max_relative_distance(nm.second, out);
      std::cout << nm.first << ": genus " << rep.genus << ", " << nm.second.number_of_faces() << " faces, "
                << rep.flow.number_of_flips << " Ptolemy and " << rep.flow.number_of_initial_flips << " initial flips, "
                << out.number_of_vertices() << " output vertices, max distance / diagonal " << worst << ", "
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s" << std::endl;
      if(!(worst <= 1e-9)) ++bad;
    } catch(const std::exception& e) {
      std::cout << nm.first << ": " << e.what() << std::endl;
      ++bad;
    }
  }
  return bad;
}
