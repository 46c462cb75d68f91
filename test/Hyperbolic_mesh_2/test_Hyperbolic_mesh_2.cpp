// Tests of the Hyperbolic_mesh_2 package. Every property of the output is checked with an independent exact
// computation written here (hyperboloid lifts with rationals, Euclidean in-circle determinants), never with the
// mesher's own predicates or bookkeeping.
#include <CGAL/Hyperbolic_mesh_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include "cgal_hc_test.h"
#include "hyperbolic_mesh_checks.h"

#include <cmath>
#include <random>
#include <set>
#include <type_traits>
#include <vector>

typedef CGAL::Poincare_disk_traits_2<> Gt;
typedef CGAL::Triangulation_vertex_base_2<Gt> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<Gt> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<Gt, Tds, CGAL::Exact_predicates_tag> CDT;
typedef Gt::Point_2 Point;
typedef CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT> Ruppert_criteria;
typedef CGAL::Hyperbolic_Chew_mesh_criteria_2<CDT> Chew_criteria;
typedef CGAL::Hyperbolic_mesh_2::Mesh_statistics Stats;
typedef CGAL::Hyperbolic_mesh_2::Mesh_parameters<Point> Params;
typedef CGAL::Exact_rational Q;
namespace HM = CGAL::Hyperbolic_mesh_2;

static const double PI = std::acos(-1.0);
static double deg(double d) { return d * PI / 180; }

// ------------------------------------------------------------------ PSLGs
struct Pslg
{
  std::string name;
  std::vector<Point> points;
  std::vector<std::pair<int, int> > segments;
  std::vector<Point> seeds;
};

static void add_polygon(Pslg& g, int n, double r, double phase = 0, double cx = 0, double cy = 0)
{
  const int base = int(g.points.size());
  for(int i = 0; i < n; ++i) {
    const double t = phase + 2 * PI * i / n;
    g.points.push_back(Point(cx + r * std::cos(t), cy + r * std::sin(t)));
    g.segments.push_back(std::make_pair(base + i, base + (i + 1) % n));
  }
}

static Pslg ngon_with_centre()
{
  Pslg g; g.name = "regular 8-gon with its centre";
  add_polygon(g, 8, 0.5);
  g.points.push_back(Point(0, 0));
  return g;
}
static Pslg square_with_slit()
{
  Pslg g; g.name = "square with a geodesic slit";
  g.points = {Point(-0.3, -0.3), Point(0.3, -0.3), Point(0.3, 0.3), Point(-0.3, 0.3), Point(-0.1, 0), Point(0.1, 0.05)};
  g.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}};
  return g;
}
static Pslg domain_with_hole()
{
  Pslg g; g.name = "octagon with a hexagonal hole";
  add_polygon(g, 8, 0.6);
  add_polygon(g, 6, 0.15, 0.3);
  g.seeds = {Point(0, 0)};
  return g;
}
static Pslg comb()
{
  Pslg g; g.name = "comb of near-boundary segments";
  add_polygon(g, 12, 0.985);
  for(int k = 0; k < 12; ++k) {
    const double t = 2 * PI * (k + 0.5) / 12;
    const int b = int(g.points.size());
    g.points.push_back(Point(0.9 * std::cos(t), 0.9 * std::sin(t)));
    g.points.push_back(Point(0.98 * std::cos(t), 0.98 * std::sin(t)));
    g.segments.push_back(std::make_pair(b, b + 1));
  }
  return g;
}
static Pslg five_degree_corner()
{
  Pslg g; g.name = "5 degree corner";
  g.points = {Point(0, 0), Point(0.5, 0), Point(0.55, 0.3), Point(0.5 * std::cos(deg(5)), 0.5 * std::sin(deg(5)))};
  g.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return g;
}
static Pslg point_cloud()
{
  Pslg g; g.name = "point cloud";
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  while(g.points.size() < 150) {
    const double x = u(rng), y = u(rng);
    if(x * x + y * y < 0.64) g.points.push_back(Point(x, y));
  }
  return g;
}

static Pslg irregular_polygon_with_chain()
{
  Pslg g; g.name = "irregular 24-gon with an interior chain and points";
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> t;
  double acc = 0;
  for(int i = 0; i < 24; ++i) { acc += 0.4 + u(rng); t.push_back(acc); }
  for(int i = 0; i < 24; ++i) {
    const double a = 2 * PI * t[std::size_t(i)] / acc;
    g.points.push_back(Point(0.6 * std::cos(a), 0.6 * std::sin(a)));
    g.segments.push_back(std::make_pair(i, (i + 1) % 24));
  }
  const int b = 24;
  const double chain[5][2] = {{-0.3, -0.1}, {-0.15, 0.05}, {0.0, 0.0}, {0.12, 0.12}, {0.3, 0.1}};
  for(int i = 0; i < 5; ++i) g.points.push_back(Point(chain[i][0], chain[i][1]));
  for(int i = 0; i < 4; ++i) g.segments.push_back(std::make_pair(b + i, b + i + 1));
  while(g.points.size() < 45) {
    const double x = 0.9 * u(rng) - 0.45, y = 0.9 * u(rng) - 0.45;
    if(x * x + y * y < 0.2 && std::abs(y - 0.3 * x) > 0.1) g.points.push_back(Point(x, y));
  }
  return g;
}

static void build(CDT& cdt, const Pslg& g) { HM::insert_geodesic_pslg(cdt, g.points, g.segments); }

// ------------------------------------------------------------------ independent exact geometry
static Q qx(const Point& p) { return Q(p.x()); }
static Q qy(const Point& p) { return Q(p.y()); }
// independent exact geometry shared with the other tests and the fuzz target (test/common/hyperbolic_mesh_checks.h)
static Q A(const Point& p, const Point& q) { return hyperbolic_mesh_checks::A<Q>(p, q); }
using hyperbolic_mesh_checks::meets_Ruppert;
using hyperbolic_mesh_checks::meets_Chew;
// Euclidean orientation and in-circle on Poincare coordinates (exact)
static int orient_e(const Point& p, const Point& q, const Point& r)
{
  const Q d = (qx(q) - qx(p)) * (qy(r) - qy(p)) - (qy(q) - qy(p)) * (qx(r) - qx(p));
  return CGAL::sign(d);
}
static int incircle_e(const Point& p, const Point& q, const Point& r, const Point& s)
{
  auto row = [&](const Point& a, Q& x, Q& y, Q& w) { x = qx(a) - qx(s); y = qy(a) - qy(s); w = x * x + y * y; };
  Q ax, ay, aw, bx, by, bw, cx, cy, cw;
  row(p, ax, ay, aw); row(q, bx, by, bw); row(r, cx, cy, cw);
  const Q d = ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx);
  return CGAL::sign(d);
}
// Distance of z from the Klein line through a, b (approximate, for the "on its geodesic" check)
static void klein(const Point& p, double& x, double& y)
{
  const double w = 1 + p.x() * p.x() + p.y() * p.y();
  x = 2 * p.x() / w; y = 2 * p.y() / w;
}
static bool on_geodesic_segment(const Point& a, const Point& b, const Point& z, double& t)
{
  double ax, ay, bx, by, zx, zy;
  klein(a, ax, ay); klein(b, bx, by); klein(z, zx, zy);
  const double ux = bx - ax, uy = by - ay, L2 = ux * ux + uy * uy;
  t = ((zx - ax) * ux + (zy - ay) * uy) / L2;
  const double dist = std::abs((zx - ax) * uy - (zy - ay) * ux) / std::sqrt(L2);
  return dist < 1e-9 && t > -1e-12 && t < 1 + 1e-12;
}

// ------------------------------------------------------------------ checks on an output
struct Check_options
{
  bool chew = false;
  double B = 0, eps = std::numeric_limits<double>::infinity();
  const Pslg* input = nullptr;
  bool allow_small_angle_corners = false; // faces whose shortest edge joins two segments of a small input angle
};

// faces whose shortest edge joins two different input segments meeting at an angle < 90 degrees
static bool across_small_corner(const Pslg& g, const Point& u, const Point& w)
{
  for(std::size_t i = 0; i < g.segments.size(); ++i)
    for(std::size_t j = 0; j < g.segments.size(); ++j) {
      if(i == j) continue;
      const auto &si = g.segments[i], &sj = g.segments[j];
      int apex = -1;
      if(si.first == sj.first || si.first == sj.second) apex = si.first;
      if(si.second == sj.first || si.second == sj.second) apex = si.second;
      if(apex < 0) continue;
      double t;
      if(!on_geodesic_segment(g.points[si.first], g.points[si.second], u, t)) continue;
      if(!on_geodesic_segment(g.points[sj.first], g.points[sj.second], w, t)) continue;
      // angle at the apex (conformal: translate the apex to the origin)
      auto dir = [&](int other) {
        const std::complex<double> a(g.points[apex].x(), g.points[apex].y()), z(g.points[other].x(), g.points[other].y());
        return std::arg((z - a) / (1.0 - std::conj(a) * z));
      };
      const int oi = si.first == apex ? si.second : si.first, oj = sj.first == apex ? sj.second : sj.first;
      double ang = std::abs(dir(oi) - dir(oj));
      if(ang > PI) ang = 2 * PI - ang;
      if(ang < PI / 2) return true;
    }
  return false;
}

static void check_output(const CDT& cdt, const Stats& st, const Check_options& o)
{
  CGAL_HC_CHECK_MSG(cdt.is_valid(), "invalid triangulation");
  CGAL_HC_CHECK_MSG(st.status == HM::Refinement_status::SUCCESS, HM::to_string(st.status));
  std::size_t in_domain = 0, failing = 0, allowed = 0, non_delaunay = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    ++in_domain;
    const Point &p = f->vertex(0)->point(), &q = f->vertex(1)->point(), &r = f->vertex(2)->point();
    const bool ok = o.chew ? meets_Chew(p, q, r, o.eps) : meets_Ruppert(p, q, r, o.B, o.eps);
    if(!ok) {
      // the only allowed exception: shortest edge across a small input angle (thesis Fig. 3.6)
      const Point* e[3][2] = {{&q, &r}, {&r, &p}, {&p, &q}};
      int s = 0; Q best = A(q, r);
      if(A(r, p) < best) { best = A(r, p); s = 1; }
      if(A(p, q) < best) { s = 2; }
      if(o.allow_small_angle_corners && o.input && across_small_corner(*o.input, *e[s][0], *e[s][1])) ++allowed;
      else ++failing;
    }
    // constrained Delaunay: no neighbour across an unconstrained edge is inside the circumcircle
    for(int i = 0; i < 3; ++i) {
      if(cdt.is_constrained(CDT::Edge(f, i))) continue;
      auto n = f->neighbor(i);
      if(cdt.is_infinite(n)) continue;
      const Point& s = cdt.mirror_vertex(f, i)->point();
      if(incircle_e(p, q, r, s) * orient_e(p, q, r) > 0) ++non_delaunay;
    }
  }
  CGAL_HC_CHECK(in_domain > 0);
  CGAL_HC_CHECK(in_domain == st.in_domain_faces);
  CGAL_HC_CHECK_MSG(failing == 0, failing << " of " << in_domain << " faces fail the criteria");
  CGAL_HC_CHECK_MSG(non_delaunay == 0, non_delaunay << " non-Delaunay edges");
  CGAL_HC_CHECK_MSG(allowed <= 4 * st.small_input_angles, allowed << " faces at small corners");
  if(o.input) {
    // every input segment is the union of constrained output edges lying on its geodesic
    for(const auto& s : o.input->segments) {
      const Point &a = o.input->points[s.first], &b = o.input->points[s.second];
      std::vector<std::pair<double, CDT::Vertex_handle> > on;
      for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        double t;
        if(on_geodesic_segment(a, b, v->point(), t)) on.push_back(std::make_pair(t, CDT::Vertex_handle(v)));
      }
      std::sort(on.begin(), on.end());
      bool chain = on.size() >= 2 && on.front().second->point() == a && on.back().second->point() == b;
      for(std::size_t k = 0; chain && k + 1 < on.size(); ++k) {
        CDT::Face_handle f; int i;
        chain = cdt.is_edge(on[k].second, on[k + 1].second, f, i) && cdt.is_constrained(CDT::Edge(f, i));
      }
      CGAL_HC_CHECK_MSG(chain, "input segment (" << s.first << ", " << s.second << ") is not a chain of constrained edges");
    }
    // seeds are outside the domain
    for(const Point& sd : o.input->seeds) {
      CGAL_HC_CHECK(!cdt.locate(sd)->is_in_domain());
    }
  }
}

// ------------------------------------------------------------------ quality bounds
CGAL_HC_TEST_CASE(quality_bounds_thesis_values)
{
  CGAL_HC_CHECK(std::abs(HM::theta_star(2.3101) * 180 / PI - 33.3) < 0.05);
  CGAL_HC_CHECK(std::abs(HM::rho(2.3101) - 1.5) < 1e-3);
  CGAL_HC_CHECK(std::abs(HM::theta_star(1e-9) - PI / 3) < 1e-9);
  CGAL_HC_CHECK(std::abs(HM::rho(1e-9) - std::sqrt(3.0)) < 1e-9);
  CGAL_HC_CHECK(std::abs(HM::rho(1e-3) - std::sqrt(3.0)) < 1e-5);
  CGAL_HC_CHECK(HM::rho(1000) > 1 && HM::rho(1000) < 1.01);
  // theta*(h) is the angle of the equilateral triangle of side h: build it and measure the angle at the origin
  for(double h : {0.1, 1.0, 2.3101, 5.0}) {
    const double t = std::tanh(h / 2);                           // Poincare radius of a point at distance h
    const std::complex<double> a(t, 0);
    // third vertex c = t e^{i phi}, d(a, c) = h: cosh h = 1 + 2 |a - c|^2 / (1 - t^2)^2
    const double target = (std::cosh(h) - 1) * (1 - t * t) * (1 - t * t) / 2;   // |a - c|^2
    const double phi = std::acos(1 - target / (2 * t * t));
    CGAL_HC_CHECK_MSG(std::abs(phi - HM::theta_star(h)) < 1e-9, "h = " << h);
    // rho(h): chord of central angle 2 theta* in a circle of radius h
    const std::complex<double> c = std::polar(t, 2 * phi);
    const double chord = 2 * std::asinh(std::abs(a - c) / (1 - t * t));
    CGAL_HC_CHECK_MSG(std::abs(chord / h - HM::rho(h)) < 1e-9, "h = " << h);
    // rho(r, theta) is the same chord for theta = 2 theta*
    CGAL_HC_CHECK(std::abs(HM::rho(h, 2 * phi) - chord / h) < 1e-9);
  }
  // Ruppert: Euclidean limit 1 - 2 sqrt(2) sin(alpha/2); alpha = 41.41 deg is the limit
  CGAL_HC_CHECK(std::abs(HM::Ruppert_termination_margin(1e-9, deg(30)) - (1 - 2 * std::sqrt(2.0) * std::sin(deg(15)))) < 1e-9);
  CGAL_HC_CHECK(HM::Ruppert_maximum_circumradius(deg(41.5)) == 0);
  const double rb = HM::Ruppert_maximum_circumradius(deg(30));
  CGAL_HC_CHECK(rb > 0.5 && rb < 2);
  CGAL_HC_CHECK(HM::Ruppert_termination_margin(0.99 * rb, deg(30)) > 0);
  CGAL_HC_CHECK(HM::Ruppert_termination_margin(1.01 * rb, deg(30)) < 0);
  CGAL_HC_CHECK_THROWS(HM::theta_star(-1), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(HM::rho(1, 4), CGAL::Invalid_option_error);
}

// ------------------------------------------------------------------ Ruppert
static Stats run_Ruppert(CDT& cdt, const Pslg& g, const Ruppert_criteria& c, Params prm = Params())
{
  build(cdt, g);
  prm.seeds(g.seeds.begin(), g.seeds.end());
  return CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, c, prm);
}

CGAL_HC_TEST_CASE(Ruppert_on_the_pslg_set)
{
  struct Case { Pslg g; double alpha_deg, eps; bool small; };
  const std::vector<Case> cases = {
    {ngon_with_centre(), 40, std::numeric_limits<double>::infinity(), false},
    {ngon_with_centre(), 35, 0.3, false},
    {square_with_slit(), 40, 0.5, true},
    {domain_with_hole(), 40, std::numeric_limits<double>::infinity(), false},
    {domain_with_hole(), 30, 0.25, false},
    {comb(), 30, std::numeric_limits<double>::infinity(), true},
    {five_degree_corner(), 40, std::numeric_limits<double>::infinity(), true},
    {point_cloud(), 40, 0.6, true}};
  for(const Case& k : cases) {
    CDT cdt;
    const Ruppert_criteria c(deg(k.alpha_deg), k.eps);
    const Stats st = run_Ruppert(cdt, k.g, c);
    std::cout << "  Ruppert " << k.g.name << ": " << st << std::endl;
    Check_options o; o.B = std::pow(std::sin(deg(k.alpha_deg) / 2), 2); o.eps = k.eps; o.input = &k.g;
    o.allow_small_angle_corners = k.small;
    check_output(cdt, st, o);
    CGAL_HC_CHECK(st.final_vertices == cdt.number_of_vertices());
    CGAL_HC_CHECK(st.minimum_central_angle_unprotected >= deg(k.alpha_deg) - 1e-9);
    if(std::isfinite(k.eps)) CGAL_HC_CHECK(st.maximum_circumradius <= k.eps * (1 + 1e-9));
  }
}

CGAL_HC_TEST_CASE(Ruppert_termination_report)
{
  CDT cdt;
  // alpha = 30 deg with the automatic maximum circumradius: the theorem applies (no small input angle)
  const Ruppert_criteria c = Ruppert_criteria::with_automatic_circumradius(deg(30));
  CGAL_HC_CHECK(c.termination_guaranteed());
  CGAL_HC_CHECK(c.epsilon() < HM::Ruppert_maximum_circumradius(deg(30)));
  const Pslg g = domain_with_hole();
  const Stats st = run_Ruppert(cdt, g, c);
  CGAL_HC_CHECK(st.termination_guaranteed);
  CGAL_HC_CHECK(st.termination_margin > 0);
  Check_options o; o.B = std::pow(std::sin(deg(15)), 2); o.eps = c.epsilon(); o.input = &g;
  check_output(cdt, st, o);
  // alpha = 41.5 deg: no radius works
  CGAL_HC_CHECK_THROWS(Ruppert_criteria::with_automatic_circumradius(deg(41.5)), CGAL::Invalid_option_error);
  CGAL_HC_CHECK(!Ruppert_criteria(deg(41.5), 0.1).termination_guaranteed());
}

CGAL_HC_TEST_CASE(Ruppert_off_centers)
{
  for(int off = 0; off < 2; ++off) {
    CDT cdt;
    const Pslg g = point_cloud();
    const Ruppert_criteria c(deg(40));
    const Stats st = run_Ruppert(cdt, g, c, Params().off_centers(off == 1));
    std::cout << "  off_centers=" << off << ": " << st << std::endl;
    Check_options o; o.B = std::pow(std::sin(deg(20)), 2); o.input = &g;
    check_output(cdt, st, o);
    if(off) CGAL_HC_CHECK(st.off_centers_inserted > 0);
  }
}

// ------------------------------------------------------------------ Chew
CGAL_HC_TEST_CASE(Chew_on_the_pslg_set)
{
  struct Case { Pslg g; double eps; bool small; };
  const std::vector<Case> cases = {
    {ngon_with_centre(), 0.4, false},
    {ngon_with_centre(), std::numeric_limits<double>::infinity(), false},
    {square_with_slit(), 0.5, true},
    {domain_with_hole(), 0.3, false},
    {comb(), std::numeric_limits<double>::infinity(), true},
    {five_degree_corner(), 0.5, true},
    {point_cloud(), 0.6, true}};
  for(const Case& k : cases) {
    CDT cdt;
    build(cdt, k.g);
    const Chew_criteria c(k.eps);
    const Stats st = CGAL::refine_hyperbolic_Chew_mesh_2(cdt, c, Params().seeds(k.g.seeds.begin(), k.g.seeds.end()));
    std::cout << "  Chew " << k.g.name << ": " << st << std::endl;
    Check_options o; o.chew = true; o.eps = k.eps; o.input = &k.g; o.allow_small_angle_corners = k.small;
    check_output(cdt, st, o);
    CGAL_HC_CHECK(st.h_star > 0);
    if(std::isfinite(k.eps)) {
      CGAL_HC_CHECK(st.h_star <= k.eps);
      // Chew's output meets the minimum central angle theta*(eps)
      CGAL_HC_CHECK(st.minimum_central_angle_unprotected >= HM::theta_star(k.eps) - 1e-9);
      CGAL_HC_CHECK(st.maximum_circumradius <= k.eps * (1 + 1e-9));
    }
    if(!k.small) CGAL_HC_CHECK(st.termination_guaranteed == (st.h_star < 2.3101));
  }
}

CGAL_HC_TEST_CASE(Chew_without_termination_guarantee_is_bounded)
{
  // a pentagon near the circle at infinity, corner lopping off: h* = half the side, about 3.66 > 2.3101
  Pslg g; add_polygon(g, 5, 0.97);
  for(double bound : {3.0, 20000.0}) {
    CDT cdt; build(cdt, g);
    const Stats st = CGAL::refine_hyperbolic_Chew_mesh_2(cdt, Chew_criteria(3.0),
                                                         Params().corner_lopping(false).maximum_number_of_operations(bound));
    std::cout << "  bound " << bound << ": " << st << std::endl;
    CGAL_HC_CHECK(st.h_star > 2.3101);
    CGAL_HC_CHECK(!st.termination_guaranteed);
    CGAL_HC_CHECK(st.operations <= std::size_t(bound));
    CGAL_HC_CHECK(st.status == HM::Refinement_status::SUCCESS || st.status == HM::Refinement_status::WORK_BOUND_REACHED);
    if(bound == 3.0) CGAL_HC_CHECK(st.status == HM::Refinement_status::WORK_BOUND_REACHED);
    CGAL_HC_CHECK(cdt.is_valid());
  }
}

// ------------------------------------------------------------------ 5 degree corner in detail
CGAL_HC_TEST_CASE(small_angle_corner_lopping)
{
  const Pslg g = five_degree_corner();
  CDT cdt; build(cdt, g);
  const Stats st = CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, Ruppert_criteria(deg(40), 0.2));
  CGAL_HC_CHECK(st.status == HM::Refinement_status::SUCCESS);
  CGAL_HC_CHECK(st.small_input_angles >= 1);
  CGAL_HC_CHECK(st.lopping_vertices >= 2);
  CGAL_HC_CHECK(!st.termination_guaranteed);
  // the two lopping vertices next to the 5 degree apex are at equal distance from it
  std::vector<double> d;
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    double t0, t1;
    const bool s0 = on_geodesic_segment(g.points[0], g.points[1], v->point(), t0);
    const bool s1 = on_geodesic_segment(g.points[3], g.points[0], v->point(), t1);
    if((s0 || s1) && v->point() != g.points[0]) {
      // nearest vertex to the apex on each side
      const double dist = 2 * std::atanh(std::sqrt(v->point().x() * v->point().x() + v->point().y() * v->point().y()));
      d.push_back(s0 ? dist : -dist);
    }
  }
  double near0 = 1e9, near1 = 1e9;
  for(double x : d) { if(x > 0) near0 = std::min(near0, x); else near1 = std::min(near1, -x); }
  CGAL_HC_CHECK_MSG(std::abs(near0 - near1) < 1e-9 * near0, near0 << " vs " << near1);
  Check_options o; o.B = std::pow(std::sin(deg(20)), 2); o.eps = 0.2; o.input = &g; o.allow_small_angle_corners = true;
  check_output(cdt, st, o);
}

// ------------------------------------------------------------------ Euclidean limit
CGAL_HC_TEST_CASE(Euclidean_limit_against_Mesh_2)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_vertex_base_2<K> EVb;
  typedef CGAL::Delaunay_mesh_face_base_2<K> EFb;
  typedef CGAL::Triangulation_data_structure_2<EVb, EFb> ETds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, ETds> ECDT;
  typedef CGAL::Delaunay_mesh_size_criteria_2<ECDT> ECriteria;
  const double s = 1e-3;
  for(const Pslg& g0 : {domain_with_hole(), irregular_polygon_with_chain(), square_with_slit()}) {
    Pslg g = g0;
    for(Point& p : g.points) p = Point(s * p.x(), s * p.y());
    for(Point& p : g.seeds) p = Point(s * p.x(), s * p.y());
    CDT cdt; build(cdt, g);
    const Stats st = CGAL::refine_hyperbolic_Ruppert_mesh_2(
        cdt, Ruppert_criteria::from_sin2_half_angle(0.125), Params().seeds(g.seeds.begin(), g.seeds.end()));
    ECDT e;
    std::vector<ECDT::Vertex_handle> vh;
    for(const Point& p : g0.points) vh.push_back(e.insert(K::Point_2(p.x(), p.y())));
    for(const auto& sg : g0.segments) e.insert_constraint(vh[sg.first], vh[sg.second]);
    std::vector<K::Point_2> seeds;
    for(const Point& p : g0.seeds) seeds.push_back(K::Point_2(p.x(), p.y()));
    CGAL::refine_Delaunay_mesh_2(e, seeds.begin(), seeds.end(), ECriteria(0.125, 0));
    const double nh = double(st.final_vertices - st.frame_vertices), ne = double(e.number_of_vertices());
    std::cout << "  " << g.name << ": hyperbolic " << nh << " vertices, Mesh_2 " << ne << std::endl;
    CGAL_HC_CHECK_MSG(std::abs(nh - ne) <= 0.25 * ne, nh << " vs " << ne);
    CGAL_HC_CHECK(st.status == HM::Refinement_status::SUCCESS);
  }
}

// ------------------------------------------------------------------ bad input
CGAL_HC_TEST_CASE(invalid_input_is_rejected)
{
  CDT cdt;
  std::vector<std::pair<int, int> > none;
  CGAL_HC_CHECK_THROWS(HM::insert_geodesic_pslg(cdt, std::vector<Point>{Point(0, 0), Point(1.0, 0), Point(0, 0.5)}, none),
                       HM::Input_error);
  CGAL_HC_CHECK_THROWS(HM::insert_geodesic_pslg(cdt, std::vector<Point>{Point(0, 0), Point(0.2, 0), Point(0, 0)}, none),
                       HM::Input_error);
  CGAL_HC_CHECK_THROWS(HM::insert_geodesic_pslg(cdt, std::vector<Point>{Point(0, 0), Point(std::nan(""), 0)}, none),
                       HM::Input_error);
  // crossing segments
  const std::vector<Point> x = {Point(-0.5, 0), Point(0.5, 0), Point(0, -0.5), Point(0, 0.5)};
  CGAL_HC_CHECK_THROWS(HM::insert_geodesic_pslg(cdt, x, std::vector<std::pair<int, int> >{{0, 1}, {2, 3}}), HM::Input_error);
  // overlapping segments on one geodesic (a diameter), and a point inside a segment
  const std::vector<Point> y = {Point(-0.5, 0), Point(0.5, 0), Point(0.1, 0), Point(0.7, 0)};
  CGAL_HC_CHECK_THROWS(HM::insert_geodesic_pslg(cdt, y, std::vector<std::pair<int, int> >{{0, 1}, {2, 3}}), HM::Input_error);
  CGAL_HC_CHECK_THROWS(HM::insert_geodesic_pslg(cdt, y, std::vector<std::pair<int, int> >{{0, 1}}), HM::Input_error);
  CGAL_HC_CHECK_THROWS(HM::insert_geodesic_pslg(cdt, y, std::vector<std::pair<int, int> >{{0, 7}}), HM::Input_error);
  CGAL_HC_CHECK_THROWS(HM::insert_geodesic_pslg(cdt, y, std::vector<std::pair<int, int> >{{1, 1}}), HM::Input_error);
  CGAL_HC_CHECK(cdt.number_of_vertices() == 0); // nothing inserted on failure
  // criteria out of range
  CGAL_HC_CHECK_THROWS(Ruppert_criteria(0.0), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(Ruppert_criteria(deg(130)), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(Ruppert_criteria(deg(30), -1.0), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(Ruppert_criteria(deg(30), std::nan("")), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(Chew_criteria(0.0), CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(Ruppert_criteria::from_sin2_half_angle(0.9), CGAL::Invalid_option_error);
  // a triangulation of dimension < 2, a seed outside the disk
  CDT small; small.insert(Point(0, 0)); small.insert(Point(0.1, 0));
  CGAL_HC_CHECK_THROWS(CGAL::refine_hyperbolic_Ruppert_mesh_2(small, Ruppert_criteria(deg(30))), HM::Input_error);
  CDT t; build(t, ngon_with_centre());
  std::vector<Point> bad_seed = {Point(2, 0)};
  CGAL_HC_CHECK_THROWS(CGAL::refine_hyperbolic_Ruppert_mesh_2(t, Ruppert_criteria(deg(30)),
                                                              Params().seeds(bad_seed.begin(), bad_seed.end())),
                       HM::Input_error);
  // cancellation through the callback
  CDT u; build(u, domain_with_hole());
  std::size_t calls = 0;
  const Stats st = CGAL::refine_hyperbolic_Ruppert_mesh_2(u, Ruppert_criteria(deg(40), 0.02),
      Params().callback([&](const HM::Progress&) { ++calls; return false; }));
  CGAL_HC_CHECK(st.status == HM::Refinement_status::CANCELLED);
  CGAL_HC_CHECK(calls >= 1);
  CGAL_HC_CHECK(u.is_valid());
}

CGAL_HC_TEST_CASE(svg_output)
{
  CDT cdt; const Pslg g = domain_with_hole(); build(cdt, g);
  CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, Ruppert_criteria(deg(40), 0.3), Params().seeds(g.seeds.begin(), g.seeds.end()));
  const std::string f1 = std::string(CGAL_HC_OUTPUT_DIR) + "/test_hyperbolic_mesh.svg";
  const std::string f2 = std::string(CGAL_HC_OUTPUT_DIR) + "/test_hyperbolic_mesh_histogram.svg";
  bool ok = true;
  try {
    HM::write_hyperbolic_mesh_svg(cdt, f1, deg(40));
    HM::write_central_angle_histogram_svg(cdt, f2, {40.0});
  } catch(const std::runtime_error&) { ok = false; } // output dir may not exist when the test runs alone
  if(ok) {
    std::ifstream in(f1); std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t paths = 0;
    for(std::size_t pos = all.find("<path"); pos != std::string::npos; pos = all.find("<path", pos + 1)) ++paths;
    CGAL_HC_CHECK(paths >= HM::central_angles(cdt).size());
  }
  CGAL_HC_CHECK_THROWS(HM::write_hyperbolic_mesh_svg(cdt, "/nonexistent_dir/x.svg"), std::runtime_error);
  // issue 8: the named-parameter writers write the same files as the (deprecated) positional ones
  if(ok) {
    auto read = [](const std::string& f) {
      std::ifstream in(f);
      return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    namespace HP = HM::parameters;
    const std::string f3 = f1 + ".np.svg", f4 = f2 + ".np.svg";
    HM::write_hyperbolic_mesh_svg(cdt, f1, deg(40), deg(100), "title", 600, 3.0, 0.1, -0.2);
    HM::write_hyperbolic_mesh_svg(cdt, f3, HP::target_angle(deg(40), HP::good_angle(deg(100), HP::title(std::string("title"),
                                      HP::image_size(600.0, HP::zoom(3.0, HP::view_center(std::make_pair(0.1, -0.2))))))));
    CGAL_HC_CHECK(read(f1).size() > 1000 && read(f1) == read(f3));
    HM::write_central_angle_histogram_svg(cdt, f2, {40.0, 50.0}, "h", 30);
    HM::write_central_angle_histogram_svg(cdt, f4, HP::bins(30, HP::title(std::string("h"), HP::marks(std::vector<double>{40.0, 50.0}))));
    CGAL_HC_CHECK(read(f2).size() > 500 && read(f2) == read(f4));
    // and the picture writer of the traits package, drawing call by drawing call
    namespace SP = CGAL::Poincare_disk_svg::parameters;
    CGAL::Poincare_disk_svg_writer w1(500, 2.0, 0.1, 0.0), w2(SP::image_size(500.0, SP::zoom(2.0, SP::view_center(std::make_pair(0.1, 0.0)))));
    const Point p(0.1, 0.2), q(-0.3, 0.4);
    w1.add_unit_circle("#111", 2.0, "#eee"); w2.add_unit_circle(SP::stroke("#111", SP::stroke_width(2.0, SP::fill("#eee"))));
    w1.add_point(p, "#00f", 3.0); w2.add_point(p, SP::fill("#00f", SP::radius(3.0)));
    w1.add_geodesic_segment(p, q, "#0a0", 1.5); w2.add_geodesic_segment(p, q, SP::stroke("#0a0", SP::stroke_width(1.5)));
    w1.add_geodesic_polygon({0.1, 0.2, -0.3, 0.4, 0.0, -0.5}, "#abc", "#000", 0.7, 0.5);
    w2.add_geodesic_polygon({0.1, 0.2, -0.3, 0.4, 0.0, -0.5},
                            SP::fill("#abc", SP::stroke("#000", SP::stroke_width(0.7, SP::fill_opacity(0.5)))));
    w1.add_euclidean_circle(0.1, 0.1, 0.2, "#f00", 0.4); w2.add_euclidean_circle(0.1, 0.1, 0.2, SP::stroke("#f00", SP::stroke_width(0.4)));
    w1.add_text(5, 6, "x<y", 11, "#333"); w2.add_text(5, 6, "x<y", SP::font_size(11.0, SP::fill("#333")));
    w1.write(f3); w2.write(f4);
    CGAL_HC_CHECK(read(f3).size() > 300 && read(f3) == read(f4));
  }
  const std::vector<double> a = HM::central_angles(cdt);
  CGAL_HC_CHECK(!a.empty());
  CGAL_HC_CHECK(*std::min_element(a.begin(), a.end()) >= deg(40) - 1e-9);
}

// Random star polygons (some near the circle at infinity, with sharp angles) with interior points and segments,
// random criteria and algorithm: never an exception, a hang or an invalid triangulation; the run ends with a
// status, and every poor face left is counted (protected or unrefinable).
CGAL_HC_TEST_CASE(random_inputs_robustness)
{
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  int runs = 0;
  for(int it = 0; it < 60; ++it) {
    const int n = 3 + int(rng() % 12);
    const double R = 0.3 + 0.69 * std::abs(u(rng));
    Pslg g;
    std::vector<double> ang;
    for(int i = 0; i < n; ++i) ang.push_back(PI * (u(rng) + 1));
    std::sort(ang.begin(), ang.end());
    for(int i = 0; i < n; ++i) {
      const double r = R * (0.5 + 0.5 * std::abs(u(rng)));
      g.points.push_back(Point(r * std::cos(ang[std::size_t(i)]), r * std::sin(ang[std::size_t(i)])));
      g.segments.push_back(std::make_pair(i, (i + 1) % n));
    }
    const int extra = int(rng() % 5);
    for(int k = 0; k < extra; ++k) {
      g.points.push_back(Point(0.3 * R * u(rng), 0.3 * R * u(rng)));
      if(k % 2 == 1) g.segments.push_back(std::make_pair(int(g.points.size()) - 2, int(g.points.size()) - 1));
    }
    CDT cdt;
    try { build(cdt, g); } catch(const HM::Input_error&) { continue; } // random crossings are rejected: fine
    if(cdt.dimension() < 2) continue;
    const bool chew = rng() % 2 == 0;
    const double eps = rng() % 2 ? std::numeric_limits<double>::infinity() : 0.05 + std::abs(u(rng));
    const double alpha = deg(20 + 45 * std::abs(u(rng)));
    const Params prm = Params().maximum_number_of_operations(20000).off_centers(rng() % 2 == 0);
    Stats st;
    bool thrown = false;
    try {
      st = chew ? CGAL::refine_hyperbolic_Chew_mesh_2(cdt, Chew_criteria(eps), prm)
                : CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, Ruppert_criteria(alpha, eps), prm);
    } catch(const std::exception& e) { thrown = true; std::cerr << "  run " << it << ": " << e.what() << std::endl; }
    ++runs;
    CGAL_HC_CHECK_MSG(!thrown, "run " << it);
    CGAL_HC_CHECK_MSG(cdt.is_valid(), "run " << it << ": " << st);
    CGAL_HC_CHECK(st.operations <= 20000);
    CGAL_HC_CHECK(st.status != HM::Refinement_status::CANCELLED);
  }
  CGAL_HC_CHECK(runs >= 30);
}

// ------------------------------------------------------------------ named parameters
// Every option given as a CGAL named parameter has the same effect as through the (deprecated) Mesh_parameters
// struct: identical statistics and output vertex count; and each option changes the result against the default
// run, so an option dropped by the named-parameter overload makes a check fail.
static bool same_stats(const Stats& a, const Stats& b)
{
  return a.status == b.status && a.initial_vertices == b.initial_vertices && a.final_vertices == b.final_vertices &&
         a.circumcenters_inserted == b.circumcenters_inserted && a.off_centers_inserted == b.off_centers_inserted &&
         a.midpoint_splits == b.midpoint_splits && a.one_third_splits == b.one_third_splits &&
         a.lopping_vertices == b.lopping_vertices && a.frame_vertices == b.frame_vertices &&
         a.removals == b.removals && a.rejected_circumcenters == b.rejected_circumcenters &&
         a.operations == b.operations && a.small_input_angles == b.small_input_angles &&
         a.protected_faces == b.protected_faces && a.in_domain_faces == b.in_domain_faces &&
         a.faces_failing_criteria == b.faces_failing_criteria &&
         a.minimum_central_angle == b.minimum_central_angle && a.maximum_circumradius == b.maximum_circumradius &&
         a.h_star == b.h_star && a.termination_guaranteed == b.termination_guaranteed;
}

struct Np_run { Stats st; std::size_t vertices; };

template <class Criteria, class Options>
static Np_run run_with(const Pslg& g, const Criteria& c, const Options& opt)
{
  CDT cdt; build(cdt, g);
  Np_run r;
  if constexpr(std::is_same<Criteria, Chew_criteria>::value) r.st = CGAL::refine_hyperbolic_Chew_mesh_2(cdt, c, opt);
  else r.st = CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, c, opt);
  r.vertices = cdt.number_of_vertices();
  CGAL_HC_CHECK(cdt.is_valid());
  return r;
}

template <class Criteria, class NP>
static void check_same(const char* what, const Pslg& g, const Criteria& c, const NP& np, const Params& prm,
                       bool must_differ_from_default)
{
  const Np_run a = run_with(g, c, np), b = run_with(g, c, prm);
  std::cout << "  " << what << ": " << a.st << std::endl;
  CGAL_HC_CHECK(same_stats(a.st, b.st));
  CGAL_HC_CHECK(a.vertices == b.vertices);
  if(must_differ_from_default) {
    const Np_run d = run_with(g, c, CGAL::parameters::default_values());
    CGAL_HC_CHECK(!same_stats(a.st, d.st));
  }
}

CGAL_HC_TEST_CASE(named_parameters_match_the_struct)
{
  namespace HP = CGAL::Hyperbolic_mesh_2::parameters;
  const Ruppert_criteria rc(deg(30), 0.3);
  const Chew_criteria cc(0.3);
  const Pslg hole = domain_with_hole(), corner = five_degree_corner(), cloud = point_cloud();
  // defaults: no option, the empty chain, the default struct
  {
    CDT t; build(t, hole);
    const Stats s0 = CGAL::refine_hyperbolic_Ruppert_mesh_2(t, rc);
    CGAL_HC_CHECK(same_stats(s0, run_with(hole, rc, Params()).st));
    check_same("Ruppert defaults", hole, rc, CGAL::parameters::default_values(), Params(), false);
    check_same("Chew defaults", hole, cc, CGAL::parameters::default_values(), Params(), false);
  }
  const Params seeded = Params().seeds(hole.seeds.begin(), hole.seeds.end());
  check_same("Ruppert seeds", hole, rc, HP::seeds(hole.seeds), seeded, true);
  check_same("Chew seeds", hole, cc, HP::seeds(hole.seeds), seeded, true);
  check_same("seeds_are_in_domain", hole, rc, HP::seeds_are_in_domain(true, HP::seeds(hole.seeds)),
             Params().seeds(hole.seeds.begin(), hole.seeds.end()).seeds_are_in_domain(true), true);
  check_same("maximum_number_of_operations", hole, rc, HP::maximum_number_of_operations(20),
             Params().maximum_number_of_operations(20), true);
  CGAL_HC_CHECK(run_with(hole, rc, HP::maximum_number_of_operations(20)).st.status ==
                HM::Refinement_status::WORK_BOUND_REACHED);
  check_same("Chew maximum_number_of_operations", hole, cc, HP::maximum_number_of_operations(20),
             Params().maximum_number_of_operations(20), true);
  check_same("corner_lopping", corner, rc, HP::corner_lopping(false), Params().corner_lopping(false), true);
  CGAL_HC_CHECK(run_with(corner, rc, HP::corner_lopping(false)).st.lopping_vertices == 0);
  check_same("off_centers", cloud, Ruppert_criteria(deg(40)), HP::off_centers(true), Params().off_centers(true), true);
  CGAL_HC_CHECK(run_with(cloud, Ruppert_criteria(deg(40)), HP::off_centers(true)).st.off_centers_inserted > 0);
  check_same("verbose", hole, rc, CGAL::parameters::verbose(true), Params().verbose(true), false);
  // CGAL's own callback tag: same calls, same cancellation
  {
    std::size_t calls_np = 0, calls_struct = 0;
    auto stop_np = [&](const HM::Progress&) { ++calls_np; return false; };
    auto stop_struct = [&](const HM::Progress&) { ++calls_struct; return false; };
    const Np_run a = run_with(hole, Ruppert_criteria(deg(40), 0.02), CGAL::parameters::callback(stop_np));
    const Np_run b = run_with(hole, Ruppert_criteria(deg(40), 0.02), Params().callback(stop_struct));
    CGAL_HC_CHECK(a.st.status == HM::Refinement_status::CANCELLED);
    CGAL_HC_CHECK(same_stats(a.st, b.st) && a.vertices == b.vertices);
    CGAL_HC_CHECK(calls_np >= 1 && calls_np == calls_struct);
  }
  // everything at once, CGAL's tags chained as members after the package's free functions
  check_same("all options", hole, rc,
             HP::off_centers(true, HP::corner_lopping(false, HP::maximum_number_of_operations(
                 1e5, HP::seeds(hole.seeds, CGAL::parameters::verbose(false))))),
             Params().seeds(hole.seeds.begin(), hole.seeds.end()).off_centers(true).corner_lopping(false)
                 .maximum_number_of_operations(1e5), true);
  // out-of-range values throw as the struct does, before anything is changed
  CDT t; build(t, hole);
  const std::size_t n0 = t.number_of_vertices();
  CGAL_HC_CHECK_THROWS(CGAL::refine_hyperbolic_Ruppert_mesh_2(t, rc, HP::maximum_number_of_operations(-1)),
                       CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(CGAL::refine_hyperbolic_Chew_mesh_2(t, cc, HP::maximum_number_of_operations(std::nan(""))),
                       CGAL::Invalid_option_error);
  CGAL_HC_CHECK_THROWS(Params().maximum_number_of_operations(-1), CGAL::Invalid_option_error);
  CGAL_HC_CHECK(t.number_of_vertices() == n0);
  const std::vector<Point> bad_seed = {Point(2, 0)};
  CGAL_HC_CHECK_THROWS(CGAL::refine_hyperbolic_Ruppert_mesh_2(t, rc, HP::seeds(bad_seed)),
                       CGAL::Poincare_disk_domain_error);
}

int main(int argc, char** argv) { return cgal_hc_test::run_all(argc, argv); }
