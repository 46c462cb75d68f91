// Tests of the Discrete_Ricci_flow package, part 2: the PMP headers are included FIRST (issue 11: with
// <CGAL/Polygon_mesh_processing/repair.h> before the package, Boost's disjoint sets on raw pointers did not
// compile), and the handling of bad or unusual input: the component check comes first with its own message,
// quad meshes are told to triangulate, a zero-area face is flipped away.
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include "cgal_hc_test.h"

#include <string>

namespace {
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace RF = CGAL::Discrete_Ricci_flow;
namespace PMP = CGAL::Polygon_mesh_processing;

Mesh read(const std::string& name)
{
  Mesh m;
  const std::string path = std::string(CGAL_HC_CGAL_DATA_DIR) + "/meshes/" + name;
  if(!CGAL::IO::read_polygon_mesh(path, m)) throw std::runtime_error("cannot read " + path);
  return m;
}

template <class F>
std::string message_of(F f)
{
  try { f(); } catch(const CGAL::Invalid_mesh_error& e) { return e.what(); } catch(const std::exception& e) { return std::string("other exception: ") + e.what(); }
  return "no exception";
}

Mesh copies(const Mesh& m, int n)
{
  Mesh r;
  for(int i = 0; i < n; ++i) {
    Mesh c = m;
    for(auto v : c.vertices()) c.point(v) = c.point(v) + K::Vector_3(10.0 * i, 0, 0);
    CGAL::copy_face_graph(c, r);
  }
  return r;
}
} // namespace

// the PMP headers above come first: this translation unit compiling is the regression test; the calls check
// that the package still works next to them (and the alias namespace Ricci_flow is the same namespace)
CGAL_HC_TEST_CASE(include_order_pmp_first)
{
  Mesh m = read("eight.off");
  PMP::remove_isolated_vertices(m);
  auto r = CGAL::Ricci_flow::hyperbolic_uniformization(m);
  CGAL_HC_CHECK(r.converged());
  CGAL_HC_CHECK(std::abs(r.total_area() - 4 * CGAL_PI) < 1e-9);
  const RF::Hyperbolic_embedding<Point_3> emb(r);
  CGAL_HC_CHECK(emb.number_of_generators() == 4);
}

CGAL_HC_TEST_CASE(components_checked_first)
{
  // 26 components of genus 2: not "genus -25"
  const Mesh many = copies(read("eight.off"), 26);
  std::vector<std::size_t> component(many.number_of_faces());
  CGAL_HC_CHECK(PMP::connected_components(many, CGAL::make_property_map(component)) == 26);
  std::string w = message_of([&] { RF::hyperbolic_uniformization(many); });
  CGAL_HC_CHECK_MSG(w.find("26 connected components") != std::string::npos && w.find("genus") == std::string::npos, w);
  // two disjoint tori: not "genus 1"
  Mesh torus = read("pipe.off");
  const Mesh two = copies(torus, 2);
  w = message_of([&] { RF::flat_metric(two); });
  CGAL_HC_CHECK_MSG(w.find("2 connected components") != std::string::npos, w);
  w = message_of([&] { RF::hyperbolic_uniformization(two); });
  CGAL_HC_CHECK_MSG(w.find("2 connected components") != std::string::npos, w);
  std::vector<double> l(two.number_of_edges());
  CGAL_HC_CHECK_THROWS(RF::compute_metric(two, CGAL::Constant_property_map<Mesh::Vertex_index, double>(0.0), CGAL::make_property_map(l),
                                          RF::parameters::background_geometry(RF::Background_geometry::EUCLIDEAN)),
                       CGAL::Invalid_mesh_error);
  // the one-component torus gives the genus message for the hyperbolic uniformization
  w = message_of([&] { RF::hyperbolic_uniformization(torus); });
  CGAL_HC_CHECK_MSG(w.find("genus 1") != std::string::npos && w.find("genus >= 2") != std::string::npos, w);
}

CGAL_HC_TEST_CASE(quad_mesh_message)
{
  Mesh q = read("cube_quad.off");
  CGAL_HC_CHECK(!CGAL::is_triangle_mesh(q));
  const std::string w = message_of([&] { RF::hyperbolic_uniformization(q); });
  CGAL_HC_CHECK_MSG(w.find("CGAL::Polygon_mesh_processing::triangulate_faces") != std::string::npos, w);
  // Ricci_flow_error is the shared Invalid_input_error: it catches the mesh errors
  CGAL_HC_CHECK_THROWS(RF::hyperbolic_uniformization(q), RF::Ricci_flow_error);
  CGAL_HC_CHECK_THROWS(RF::hyperbolic_uniformization(q), CGAL::Hyperbolic_geometry_error);
}

CGAL_HC_TEST_CASE(zero_area_face_is_flipped_away)
{
  // mpi_triang.off (genus 1) has a face with lengths 6.01607 + 8.03211 = 14.0482 (zero area)
  Mesh m = read("mpi_triang.off");
  auto r = RF::flat_metric(m);
  CGAL_HC_CHECK_MSG(r.converged(), RF::to_string(r.statistics().status));
  CGAL_HC_CHECK(r.statistics().number_of_initial_flips > 0);
  CGAL_HC_CHECK(r.statistics().max_curvature_error < 1e-10);
  const RF::Hyperbolic_embedding<Point_3> emb(r);
  const auto tau = emb.lattice_parameter();
  CGAL_HC_CHECK(std::isfinite(tau.real()) && tau.imag() >= std::sqrt(3.0) / 2 - 1e-12 && std::abs(tau.real()) <= 0.5 + 1e-12);
  std::cout << "  mpi_triang.off: " << r.statistics().number_of_initial_flips << " initial flips, " << r.statistics().iterations
            << " iterations, tau = " << tau << std::endl;
}

// a user's vertex_index_map is checked before anything depends on it (a repeated index would merge vertices
// in the component count), by every entry point; a valid permutation gives the same conformal factors
CGAL_HC_TEST_CASE(vertex_index_map_is_checked)
{
  const Mesh m = read("eight.off");
  const std::size_t n = m.number_of_vertices();
  std::vector<std::size_t> perm(n), repeated(n), out_of_range(n);
  for(std::size_t i = 0; i < n; ++i) { perm[i] = n - 1 - i; repeated[i] = i; out_of_range[i] = i; }
  repeated[5] = 7;         // two vertices with index 7, none with 5
  out_of_range[3] = n + 2; // beyond 0 .. n-1
  auto as_map = [](const std::vector<std::size_t>& v) { return CGAL::make_property_map(v); };
  auto expect_invalid_map = [&](auto f, const std::string& what) {
    std::string msg = "no exception";
    try { f(); } catch(const CGAL::Invalid_option_error& e) { msg = e.what(); } catch(const std::exception& e) { msg = std::string("other: ") + e.what(); }
    CGAL_HC_CHECK_MSG(msg.find("invalid vertex index map") != std::string::npos, what << ": " << msg);
  };
  for(const auto* bad : {&repeated, &out_of_range}) {
    expect_invalid_map([&] { RF::hyperbolic_uniformization(m, CGAL::parameters::vertex_index_map(as_map(*bad))); },
                       "hyperbolic_uniformization");
    expect_invalid_map([&] {
      std::vector<double> l(m.number_of_edges());
      RF::compute_metric(m, CGAL::Constant_property_map<Mesh::Vertex_index, double>(0.0), CGAL::make_property_map(l),
                         CGAL::parameters::vertex_index_map(as_map(*bad)));
    }, "compute_metric");
    const Mesh torus = read("hole.off"); // genus 1 (demo data)
    std::vector<std::size_t> bad_t(torus.number_of_vertices());
    for(std::size_t i = 0; i < bad_t.size(); ++i) bad_t[i] = i;
    bad_t[1] = bad == &repeated ? 0 : bad_t.size();
    expect_invalid_map([&] { RF::flat_metric(torus, CGAL::parameters::vertex_index_map(as_map(bad_t))); }, "flat_metric");
    const Mesh sphere = read("sphere.off");
    std::vector<std::size_t> bad_s(sphere.number_of_vertices());
    for(std::size_t i = 0; i < bad_s.size(); ++i) bad_s[i] = i;
    bad_s[1] = bad == &repeated ? 0 : bad_s.size();
    expect_invalid_map([&] { RF::spherical_uniformization(sphere, CGAL::parameters::vertex_index_map(as_map(bad_s))); },
                       "spherical_uniformization");
  }
  // every position of a repeated index (the old check counted "2 connected components" when the repeated
  // index was the union-find root: at vertex 312 of eight.off)
  std::size_t wrong = 0;
  for(std::size_t k = 0; k < n; ++k) {
    std::vector<std::size_t> r(n);
    for(std::size_t i = 0; i < n; ++i) r[i] = i;
    r[k] = (k + 2) % n;
    try { RF::hyperbolic_uniformization(m, CGAL::parameters::vertex_index_map(as_map(r))); ++wrong; }
    catch(const CGAL::Invalid_option_error&) {} catch(const std::exception&) { ++wrong; }
  }
  CGAL_HC_CHECK_MSG(wrong == 0, wrong << " repeated indices not reported as an invalid vertex index map");
  // a Surface_mesh with a removed vertex (its indices are no longer 0 .. n-1): the message says what to do
  Mesh g = m;
  CGAL::Euler::remove_center_vertex(g.halfedge(*g.vertices().begin()), g); // (leaves a polygon face and garbage)
  std::string msg = "no exception";
  try { RF::hyperbolic_uniformization(g); } catch(const std::exception& e) { msg = e.what(); }
  CGAL_HC_CHECK_MSG(msg.find("collect_garbage") != std::string::npos, msg);
  g.collect_garbage();
  CGAL_HC_CHECK_MSG(message_of([&] { RF::hyperbolic_uniformization(g); }).find("triangulate") != std::string::npos,
                    "after collect_garbage(): " << message_of([&] { RF::hyperbolic_uniformization(g); }));
  const auto ref = RF::hyperbolic_uniformization(m);
  const auto permuted = RF::hyperbolic_uniformization(m, CGAL::parameters::vertex_index_map(as_map(perm)));
  CGAL_HC_CHECK(ref.converged() && permuted.converged());
  double d = 0;
  for(std::size_t i = 0; i < n; ++i) d = (std::max)(d, std::abs(ref.conformal_factors()[i] - permuted.conformal_factors()[perm[i]]));
  CGAL_HC_CHECK_MSG(d < 1e-9, "conformal factors under a permuted vertex index map differ by " << d);
}

CGAL_HC_TEST_CASE(options_out_of_range)
{
  const Mesh m = read("eight.off");
  CGAL_HC_CHECK_THROWS(RF::hyperbolic_uniformization(m, CGAL::parameters::accuracy(-1.0)), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(RF::hyperbolic_uniformization(m, CGAL::parameters::number_of_iterations(-3)), CGAL::Invalid_option_error);
  if(!RF::has_cholmod())
    CGAL_HC_CHECK_THROWS(RF::hyperbolic_uniformization(m, RF::parameters::sparse_solver(RF::Sparse_solver::SUPERNODAL_CHOLMOD)),
                         CGAL::Invalid_option_error);
  else CGAL_HC_CHECK(RF::hyperbolic_uniformization(m, RF::parameters::sparse_solver(RF::Sparse_solver::SUPERNODAL_CHOLMOD)).converged());
}

// input_connectivity_is_valid() of the uniformization functions, which write the input lengths into a constant
// (write-only) map: it used to read those lengths back as 0 and be false on every mesh. It must agree with the
// same flow run with a real output map, whose lengths are checked here.
CGAL_HC_TEST_CASE(input_connectivity_validity_without_an_output_map)
{
  for(const std::string name : {"eight.off", "femur.off"}) {
    Mesh m = read(name);
    const auto r = RF::hyperbolic_uniformization(m);
    auto out = m.add_property_map<Mesh::Edge_index, double>("e:out2", 0.0).first;
    const auto r2 = RF::compute_metric(m, CGAL::Constant_property_map<Mesh::Vertex_index, double>(0.0), out);
    bool valid = true;
    for(auto f : m.faces()) {
      const auto h = m.halfedge(f);
      const double l[3] = {out[m.edge(h)], out[m.edge(m.next(h))], out[m.edge(m.prev(h))]};
      for(int i = 0; i < 3; ++i) valid = valid && l[i] < l[(i + 1) % 3] + l[(i + 2) % 3];
    }
    std::cout << "  " << name << ": " << r.statistics().number_of_flips << " flips, input connectivity "
              << (r.input_connectivity_is_valid() ? "valid" : "not valid") << std::endl;
    CGAL_HC_CHECK_MSG(r.converged() && r2.converged(), name);
    CGAL_HC_CHECK_MSG(r2.input_connectivity_is_valid() == valid, name);
    CGAL_HC_CHECK_MSG(r.input_connectivity_is_valid() == valid, name);
    if(r.statistics().number_of_flips == 0) CGAL_HC_CHECK_MSG(r.input_connectivity_is_valid(), name);
  }
  // the positive case: eight.off without flips converges on its own connectivity (see the next test case)
  const auto r = RF::hyperbolic_uniformization(read("eight.off"), CGAL::parameters::do_flip(false));
  CGAL_HC_CHECK(r.converged() && r.statistics().number_of_flips == 0);
  CGAL_HC_CHECK(r.input_connectivity_is_valid());
}

// do_flip(false): on these meshes the flow without flips reaches K = 0 only with triangles that violate a
// triangle inequality (Luo's extended angles): the status must say so (never CONVERGED), and the lengths
// written on the input connectivity must be reported invalid. The violations are recounted here from the
// returned lengths; eight.off, which needs no flip, is the positive control.
CGAL_HC_TEST_CASE(no_flip_degenerate_solution_is_not_converged)
{
  for(const std::string name : {"joint.off", "helmet.off", "anchor.off", "femur.off", "eight.off"}) {
    Mesh m = read(name);
    auto out = m.add_property_map<Mesh::Edge_index, double>("e:out", 0.0).first;
    const auto r = RF::compute_metric(m, CGAL::Constant_property_map<Mesh::Vertex_index, double>(0.0), out,
                                      CGAL::parameters::do_flip(false));
    std::size_t violations = 0;
    for(auto f : m.faces()) {
      const auto h = m.halfedge(f);
      const double l[3] = {out[m.edge(h)], out[m.edge(m.next(h))], out[m.edge(m.prev(h))]};
      for(int i = 0; i < 3; ++i) if(!(l[i] < l[(i + 1) % 3] + l[(i + 2) % 3])) ++violations;
    }
    std::cout << "  " << name << ": " << RF::to_string(r.statistics().status) << ", " << violations
              << " triangle-inequality violations" << std::endl;
    CGAL_HC_CHECK_MSG(r.input_connectivity_is_valid() == (violations == 0), name);
    if(violations > 0) CGAL_HC_CHECK_MSG(!r.converged() && r.statistics().status != RF::Flow_status::CONVERGED, name);
    if(name == "eight.off") CGAL_HC_CHECK(r.converged() && violations == 0);
    else CGAL_HC_CHECK_MSG(violations > 0, name << ": expected a degenerate solution without flips");
  }
}

// issue 12: eight.off with one vertex moved far away (+2 to +100 in x, the mesh is 0.5 across), or the whole
// mesh in units of 1e80 / 1e-80. The full Newton step from the uniform-scale start moved u by hundreds: lengths
// under- or overflowed, +10 and 1e80 ended NUMERICAL_FAILURE with every length 0, +5 and 1e-80 threw, +2 took
// 185,798 flips. Every run must converge to the metric of the same conformal class (scale-invariant), and a run
// stopped early must return its last accepted iterate: finite positive lengths whose curvature is the error
// the statistics report.
CGAL_HC_TEST_CASE(far_vertex_and_extreme_scales)
{
  const Mesh base = read("eight.off");
  const auto ref = RF::hyperbolic_uniformization(base);
  CGAL_HC_CHECK(ref.converged());
  auto max_error = [](const auto& r) {
    double e = 0;
    for(auto v : r.intrinsic_mesh().vertices()) e = (std::max)(e, std::abs(r.curvature(v) - r.target_curvatures()[v]));
    return e;
  };
  auto lengths_ok = [](const auto& r) {
    for(auto e : r.intrinsic_mesh().edges()) if(!(r.length(e) > 0 && std::isfinite(r.length(e)))) return false;
    return true;
  };
  // scales: the same lengths as the unscaled mesh, conformal factors shifted by -log(scale)
  for(const double scale : {1e80, 1e-80, 1e150, 1e-150}) {
    Mesh m = base;
    for(auto v : m.vertices()) m.point(v) = CGAL::ORIGIN + scale * (m.point(v) - CGAL::ORIGIN);
    const auto r = RF::hyperbolic_uniformization(m);
    CGAL_HC_CHECK_MSG(r.converged(), "scale " << scale << ": " << RF::to_string(r.statistics().status));
    CGAL_HC_CHECK_MSG(lengths_ok(r) && std::abs(r.total_area() - 4 * CGAL_PI) < 1e-9, "scale " << scale);
    double du = 0;
    for(std::size_t i = 0; i < r.conformal_factors().size(); ++i)
      du = (std::max)(du, std::abs(r.conformal_factors()[i] + std::log(scale) - ref.conformal_factors()[i]));
    CGAL_HC_CHECK_MSG(du < 1e-8, "scale " << scale << ": conformal factors differ by " << du);
    std::cout << "  eight.off x " << scale << ": " << RF::to_string(r.statistics().status) << ", "
              << r.statistics().iterations << " iterations, |u + log s - u_ref| = " << du << std::endl;
  }
  // the flat metric keeps the input's unit: a torus scaled by 2^266 (about 1e80; a power of two, so that the
  // input is exactly the scaled one) has lengths 2^266 times the unscaled ones
  {
    const double big_scale = std::ldexp(1.0, 266);
    const Mesh torus = read("mpi_triang.off");
    Mesh big = torus;
    for(auto v : big.vertices()) big.point(v) = CGAL::ORIGIN + big_scale * (big.point(v) - CGAL::ORIGIN);
    const auto r1 = RF::flat_metric(torus), r2 = RF::flat_metric(big);
    CGAL_HC_CHECK_MSG(r1.converged() && r2.converged(), RF::to_string(r1.statistics().status) << " / " << RF::to_string(r2.statistics().status) << ", errors " << r1.statistics().max_curvature_error << " / " << r2.statistics().max_curvature_error);
    double du = 0, max1 = 0, max2 = 0;
    for(std::size_t i = 0; i < r1.conformal_factors().size(); ++i)
      du = (std::max)(du, std::abs(r1.conformal_factors()[i] - r2.conformal_factors()[i]));
    for(auto e : r1.intrinsic_mesh().edges()) max1 = (std::max)(max1, r1.length(e));
    for(auto e : r2.intrinsic_mesh().edges()) max2 = (std::max)(max2, r2.length(e));
    CGAL_HC_CHECK_MSG(du < 1e-8 && std::abs(max2 / big_scale - max1) < 1e-8 * max1,
                      "flat metric at scale 2^266: conformal factors differ by " << du << ", longest edges " << max1
                                                                                 << " and " << max2 << " / 2^266");
  }
  // one vertex far away
  for(const double dx : {2.0, 5.0, 10.0, 100.0, 1e6}) {
    Mesh m = base;
    const auto v0 = *m.vertices().begin();
    m.point(v0) = m.point(v0) + K::Vector_3(dx, 0, 0);
    const auto r = RF::hyperbolic_uniformization(m);
    const auto& st = r.statistics();
    std::cout << "  eight.off, vertex 0 moved by " << dx << ": " << RF::to_string(st.status) << ", " << st.iterations
              << " iterations, " << st.number_of_flips << " flips" << std::endl;
    CGAL_HC_CHECK_MSG(r.converged() && st.max_curvature_error < 1e-10, "dx " << dx << ": " << RF::to_string(st.status));
    CGAL_HC_CHECK_MSG(lengths_ok(r) && std::abs(r.total_area() - 4 * CGAL_PI) < 1e-9, "dx " << dx);
    CGAL_HC_CHECK_MSG(st.number_of_flips < 10 * r.intrinsic_mesh().number_of_edges(), "dx " << dx << ": " << st.number_of_flips << " flips");
    // stopped early: the last accepted iterate, whose curvature error is the one reported
    for(const int n : {1, 2, 3}) {
      const auto s = RF::hyperbolic_uniformization(m, CGAL::parameters::number_of_iterations(n));
      CGAL_HC_CHECK_MSG(lengths_ok(s), "dx " << dx << ", " << n << " iterations: lengths not finite and positive");
      CGAL_HC_CHECK_MSG(std::abs(max_error(s) - s.statistics().max_curvature_error) < 1e-9 * (1 + max_error(s)),
                        "dx " << dx << ", " << n << " iterations: reported error " << s.statistics().max_curvature_error
                              << ", recomputed " << max_error(s));
    }
  }
}

// the defect of a motion is +infinity when its matrix is not finite or has a non-positive determinant (the
// relator's partial products of cheese.off lose their determinant, and the defect of NaN entries used to read
// as 0)
CGAL_HC_TEST_CASE(defect_of_non_finite_motion)
{
  typedef RF::internal::Long_isometry L;
  const long double inf = std::numeric_limits<long double>::infinity();
  CGAL_HC_CHECK(std::isinf(RF::internal::Motion::from(L(inf, 0, 0, 0)).defect()));             // inf / inf
  CGAL_HC_CHECK(std::isinf(RF::internal::Motion::from(L(inf, 0, 0, 0) * L(1, 0, 1e-3L, 0)).defect())); // det NaN
  CGAL_HC_CHECK(RF::internal::Motion::from(L(1, 0, 0, 0)).defect() == 0);
  CGAL_HC_CHECK(std::abs(RF::internal::Motion::from(L(1, 0, 1e-3L, 0)).defect() - 1e-3L) < 1e-9L);
}
