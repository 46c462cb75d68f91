// Regression tests of issue 12 (reliability): the inputs of the issue, verbatim. Every property is checked with
// an independent exact computation (rationals), never with the mesher's own predicates or bookkeeping.
#include <CGAL/Hyperbolic_mesh_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include "cgal_hc_test.h"

#include <cmath>
#include <limits>
#include <vector>

namespace {

typedef CGAL::Poincare_disk_traits_2<> Gt;
typedef CGAL::Triangulation_vertex_base_2<Gt> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<Gt> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<Gt, Tds, CGAL::Exact_predicates_tag> CDT;
typedef Gt::Point_2 Point;
typedef CGAL::Exact_rational Q;
namespace HM = CGAL::Hyperbolic_mesh_2;
typedef HM::Mesh_statistics Stats;
typedef HM::Mesh_parameters<Point> Params;

const double PI = std::acos(-1.0);
double deg(double d) { return d * PI / 180; }

// Hyperboloid lift L(z) = (2x, 2y, 1 + |z|^2) / (1 - |z|^2), exact.
struct Lift { Q x, y, t; };
Lift lift(const Point& p)
{
  const Q x(p.x()), y(p.y()), n = 1 - x * x - y * y;
  return Lift{2 * x / n, 2 * y / n, (1 + x * x + y * y) / n};
}
// Klein orientation of p, q, r (the triangulation's orientation), exact.
int orient_klein(const Point& p, const Point& q, const Point& r)
{
  const Lift a = lift(p), b = lift(q), c = lift(r);
  // central projection to the Klein plane t = 1: orientation of (x/t, y/t); t > 0
  const Q d = (b.x / b.t - a.x / a.t) * (c.y / c.t - a.y / a.t) - (b.y / b.t - a.y / a.t) * (c.x / c.t - a.x / a.t);
  return CGAL::sign(d);
}
// number of unconstrained edges between two finite faces that fail the exact local Delaunay test
std::size_t non_Delaunay_edges(const CDT& cdt)
{
  std::size_t bad = 0;
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if(cdt.is_constrained(*e)) continue;
    const CDT::Face_handle f = e->first, g = f->neighbor(e->second);
    if(cdt.is_infinite(f) || cdt.is_infinite(g)) continue;
    const Point &p = f->vertex(0)->point(), &q = f->vertex(1)->point(), &r = f->vertex(2)->point();
    const Point& s = cdt.mirror_vertex(f, e->second)->point();
    // s strictly inside the circle (or horocycle / hypercycle) of p q r: the Euclidean in-circle determinant of
    // the Poincare coordinates (the side of the hyperboloid lift of s w.r.t. the plane of the lifts of p, q, r)
    // times the Klein orientation of p q r
    const Q ax = Q(p.x()) - Q(s.x()), ay = Q(p.y()) - Q(s.y()), bx = Q(q.x()) - Q(s.x()), by = Q(q.y()) - Q(s.y()),
            cx = Q(r.x()) - Q(s.x()), cy = Q(r.y()) - Q(s.y());
    const Q aw = ax * ax + ay * ay, bw = bx * bx + by * by, cw = cx * cx + cy * cy;
    const Q det = ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx);
    if(CGAL::sign(det) * orient_klein(p, q, r) > 0) ++bad;
  }
  return bad;
}

} // namespace

namespace {

CDT point_cloud(const std::vector<Point>& pts)
{
  CDT cdt;
  HM::insert_geodesic_pslg(cdt, pts, std::vector<std::pair<int, int> >());
  return cdt;
}

} // namespace

// Issue 12: Ruppert on point clouds (alpha = 5 degrees, corner lopping on) returned triangulations that were not
// Delaunay. Cause: a rounded split point of a constrained edge is off its geodesic, and CGAL's insertion into an
// edge does not test the new edges from the split point to the opposite vertices (exact-arithmetic reasoning:
// they are Delaunay when the point is on the edge). Now the split point is chosen among its floating-point
// neighbours so that these edges are Delaunay (exact test), or the subsegment is not split.
CGAL_HC_TEST_CASE(issue12_Ruppert_point_clouds_stay_Delaunay)
{
  const std::vector<Point> cloud1 = {Point(-0.62419468229402719, -0.16515895419380461), Point(0.24505982905982907, 0),
                                     Point(-0.40001208513208786, -0.105841301631241),
                                     Point(0.061020973828834667, 0.00075472880631091374), Point(0, 0)};
  const std::vector<Point> cloud2 = {Point(0.24649108628333516, 0.0015124693442873083),
                                     Point(0.51528673947803971, -0.30730856097070725), Point(0, 0),
                                     Point(0.30775489025278546, 0.0018883840551004647)};
  struct Run { const std::vector<Point>* pts; double eps; double ops; };
  const Run runs[] = {{&cloud1, 1.673529411764706, 200}, {&cloud1, 1.673529411764706, 1000},
                      {&cloud1, 1.673529411764706, 1e5}, {&cloud2, 1.1794117647058824, 200},
                      {&cloud2, 1.1794117647058824, 1e5}};
  for(const Run& r : runs) {
    CDT cdt = point_cloud(*r.pts);
    const Stats st = CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, CGAL::Hyperbolic_mesh_criteria_2<CDT>(deg(5), r.eps),
                                                            Params().maximum_number_of_operations(r.ops));
    CGAL_HC_CHECK_MSG(cdt.is_valid(), st);
    CGAL_HC_CHECK_MSG(non_Delaunay_edges(cdt) == 0, non_Delaunay_edges(cdt) << " non-Delaunay edges: " << st);
  }
}
