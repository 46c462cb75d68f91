// Meshes a planar geodesic graph in the Poincare disk with the generalized Ruppert and Chew algorithms and writes
// SVG pictures (faces coloured by the central angle of their shortest edge) and histograms of the central angles.
//
// Usage: hyperbolic_mesh_demo [input.pslg] [epsilon]
//   input.pslg (optional): "n m" then n lines "x y" (|(x, y)| < 1), then m lines "i j" (geodesic segments), then
//   optionally "k" and k seed lines "x y" (holes). Default: a regular hyperbolic octagon with a square hole, a slit
//   and a 5 degree corner.
#include <CGAL/Hyperbolic_mesh_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Poincare_disk_traits_2<> Gt;
typedef CGAL::Triangulation_vertex_base_2<Gt> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<Gt> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<Gt, Tds, CGAL::Exact_predicates_tag> CDT;
typedef Gt::Point_2 Point;
namespace HM = CGAL::Hyperbolic_mesh_2;

struct Input
{
  std::vector<Point> points;
  std::vector<std::pair<int, int> > segments;
  std::vector<Point> seeds;
};

static Input default_input()
{
  const double pi = std::acos(-1.0);
  Input in;
  // regular hyperbolic octagon, Poincare radius 0.62 (interior angles about 95 degrees)
  for(int i = 0; i < 8; ++i)
    in.points.push_back(Point(0.62 * std::cos(2 * pi * i / 8), 0.62 * std::sin(2 * pi * i / 8)));
  for(int i = 0; i < 8; ++i) in.segments.push_back(std::make_pair(i, (i + 1) % 8));
  // square hole around (-0.2, 0)
  const int h = int(in.points.size());
  const double hx = -0.25, hy = 0.0, r = 0.08;
  in.points.push_back(Point(hx - r, hy - r)); in.points.push_back(Point(hx + r, hy - r));
  in.points.push_back(Point(hx + r, hy + r)); in.points.push_back(Point(hx - r, hy + r));
  for(int i = 0; i < 4; ++i) in.segments.push_back(std::make_pair(h + i, h + (i + 1) % 4));
  in.seeds.push_back(Point(hx, hy));
  // a 5 degree corner: two segments from (0.15, -0.25)
  const int c = int(in.points.size());
  in.points.push_back(Point(0.15, -0.25));
  in.points.push_back(Point(0.15 + 0.3 * std::cos(0.3), -0.25 + 0.3 * std::sin(0.3)));
  in.points.push_back(Point(0.15 + 0.3 * std::cos(0.3 + 5 * pi / 180), -0.25 + 0.3 * std::sin(0.3 + 5 * pi / 180)));
  in.segments.push_back(std::make_pair(c, c + 1));
  in.segments.push_back(std::make_pair(c, c + 2));
  // a slit
  const int s = int(in.points.size());
  in.points.push_back(Point(0.05, 0.25)); in.points.push_back(Point(0.3, 0.3));
  in.segments.push_back(std::make_pair(s, s + 1));
  return in;
}

static Input read_input(const std::string& file)
{
  std::ifstream is(file);
  if(!is) throw std::runtime_error("cannot open " + file);
  Input in;
  std::size_t n = 0, m = 0, k = 0;
  if(!(is >> n >> m)) throw std::runtime_error("bad header in " + file);
  for(std::size_t i = 0; i < n; ++i) { double x, y; if(!(is >> x >> y)) throw std::runtime_error("bad point"); in.points.push_back(Point(x, y)); }
  for(std::size_t i = 0; i < m; ++i) { int a, b; if(!(is >> a >> b)) throw std::runtime_error("bad segment"); in.segments.push_back(std::make_pair(a, b)); }
  if(is >> k)
    for(std::size_t i = 0; i < k; ++i) { double x, y; if(!(is >> x >> y)) throw std::runtime_error("bad seed"); in.seeds.push_back(Point(x, y)); }
  return in;
}

int main(int argc, char** argv)
{
  try {
    const Input in = argc > 1 ? read_input(argv[1]) : default_input();
    const double eps = argc > 2 ? std::stod(argv[2]) : 0.25;
    const double pi = std::acos(-1.0);

    // generalized Ruppert: central angle >= 35 degrees, circumradius <= eps
    {
      CDT cdt;
      HM::insert_geodesic_pslg(cdt, in.points, in.segments);
      const CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT> criteria(35 * pi / 180, eps);
      const HM::Mesh_statistics st = CGAL::refine_hyperbolic_Ruppert_mesh_2(
          cdt, criteria,
          HM::parameters::seeds(in.seeds, HM::parameters::maximum_number_of_operations(2e6)));
      std::cout << "Ruppert: " << st << "\n";
      namespace HP = HM::parameters;
      HM::write_hyperbolic_mesh_svg(cdt, "hyperbolic_mesh_Ruppert.svg",
          HP::target_angle(criteria.alpha(),
                           HP::title("generalized Ruppert, alpha = 35 deg, eps = " + std::to_string(eps))));
      HM::write_hyperbolic_mesh_svg(cdt, "hyperbolic_mesh_Ruppert_corner_zoom.svg",
          HP::target_angle(criteria.alpha(), HP::title(std::string("zoom x6 on the lopped 5 degree corner"),
                           HP::zoom(6.0, HP::view_center(std::make_pair(0.25, -0.2))))));
      HM::write_central_angle_histogram_svg(cdt, "hyperbolic_mesh_Ruppert_histogram.svg",
          HP::marks(std::vector<double>{35.0}, HP::title(std::string("Ruppert: central angles of the shortest edges"))));
    }
    // generalized Chew: central angle >= theta*(r), circumradius <= eps
    {
      CDT cdt;
      HM::insert_geodesic_pslg(cdt, in.points, in.segments);
      const CGAL::Hyperbolic_Chew_mesh_criteria_2<CDT> criteria(eps);
      const HM::Mesh_statistics st = CGAL::refine_hyperbolic_Chew_mesh_2(
          cdt, criteria, HM::parameters::seeds(in.seeds));
      std::cout << "Chew:    " << st << "\n";
      const double theta = criteria.minimum_central_angle();
      namespace HP = HM::parameters;
      HM::write_hyperbolic_mesh_svg(cdt, "hyperbolic_mesh_Chew.svg",
          HP::target_angle(theta, HP::title("generalized Chew, eps = " + std::to_string(eps))));
      HM::write_central_angle_histogram_svg(cdt, "hyperbolic_mesh_Chew_histogram.svg",
          HP::marks(std::vector<double>{theta * 180 / pi},
                    HP::title(std::string("Chew: central angles of the shortest edges (line: theta*(eps))"))));
    }
    std::cout << "wrote hyperbolic_mesh_{Ruppert,Chew}.svg and *_histogram.svg\n";
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
