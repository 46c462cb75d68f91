// hyperbolic_remesh: conformal remeshing of a closed triangle mesh of genus >= 2 by Delaunay refinement of its
// hyperbolic uniformization.
//   hyperbolic_remesh input.(off|obj|ply) -o remeshed.off [--epsilon 0.1] [--alpha 30] [--chew|--ruppert]
//                     [--svg mesh.svg] [--histogram angles.svg] [--max-insertions N] [--quiet]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Hyperbolic_surface_mesh_2.h>
#include <CGAL/Hyperbolic_surface_mesh_2/conformal_remesh.h>
#include <CGAL/Hyperbolic_surface_mesh_2/IO/write_surface_mesh_svg.h>

#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HSM = CGAL::Hyperbolic_surface_mesh_2;
namespace HSMP = CGAL::Hyperbolic_surface_mesh_2::parameters;

static int usage(const char* msg)
{
  if(msg) std::cerr << "hyperbolic_remesh: " << msg << "\n";
  std::cerr << "usage: hyperbolic_remesh input.(off|obj|ply) -o output.off [--epsilon E] [--alpha DEG] [--chew|--ruppert]\n"
               "                         [--svg disk.svg] [--histogram angles.svg] [--max-insertions N] [--quiet]\n";
  return 2;
}

int main(int argc, char** argv)
{
  std::string in_file, out_file, svg_file, hist_file;
  double eps = 0.1, alpha_deg = 30, max_ins = 2e7;
  bool chew = false, quiet = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if(i + 1 >= argc) { usage((std::string("missing value after ") + name).c_str()); std::exit(2); }
      return argv[++i];
    };
    auto number = [&](const char* name) {
      const std::string v = value(name);
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      if(end == v.c_str() || *end != 0) { usage((std::string("not a number after ") + name + ": " + v).c_str()); std::exit(2); }
      return d;
    };
    if(a == "-o" || a == "--output") out_file = value("-o");
    else if(a == "--epsilon") eps = number("--epsilon");
    else if(a == "--alpha") alpha_deg = number("--alpha");
    else if(a == "--max-insertions") max_ins = number("--max-insertions");
    else if(a == "--svg") svg_file = value("--svg");
    else if(a == "--histogram") hist_file = value("--histogram");
    else if(a == "--chew") chew = true;
    else if(a == "--ruppert") chew = false;
    else if(a == "--quiet") quiet = true;
    else if(a == "-h" || a == "--help") return usage(nullptr);
    else if(!a.empty() && a[0] == '-') return usage(("unknown option " + a).c_str());
    else if(in_file.empty()) in_file = a;
    else return usage("more than one input file");
  }
  if(in_file.empty() || out_file.empty()) return usage("an input file and -o output are required");
  Mesh in;
  if(!CGAL::IO::read_polygon_mesh(in_file, in) || in.is_empty()) {
    std::cerr << "hyperbolic_remesh: cannot read a polygon mesh from " << in_file << "\n";
    return 1;
  }
  const std::function<bool(const HSM::Refinement_progress&)> progress = [&](const HSM::Refinement_progress& p) {
    if(!quiet) std::cerr << "\r  refinement: " << p.number_of_vertices << " vertices, circumradius " << p.current_circumradius << "      " << std::flush;
    return true;
  };
  try {
    if(!quiet) std::cerr << in_file << ": " << in.number_of_vertices() << " vertices, " << in.number_of_faces() << " faces\n";
    Mesh out;
    const auto rep = HSM::conformal_remesh(in, out,
        HSMP::maximum_circumradius(eps, HSMP::minimum_central_angle(alpha_deg * CGAL_PI / 180,
        HSMP::use_Chew(chew, HSMP::maximum_number_of_insertions(max_ins, CGAL::parameters::callback(progress))))));
    if(!quiet) std::cerr << "\n";
    std::cout << "genus " << rep.genus << "; Ricci flow " << rep.seconds_flow << " s ("
              << (rep.flow_used_flips ? "with intrinsic flips" : "input connectivity")
              << "); refinement " << rep.seconds_refinement << " s\n" << rep.refinement << "\n";
    if(!CGAL::IO::write_polygon_mesh(out_file, out, CGAL::parameters::stream_precision(17))) {
      std::cerr << "hyperbolic_remesh: cannot write " << out_file << "\n";
      return 1;
    }
    if(!svg_file.empty()) HSM::write_surface_mesh_svg(*rep.surface, svg_file, true, in_file);
    if(!hist_file.empty()) HSM::write_central_angle_histogram_svg(*rep.surface, hist_file, chew ? 60 : alpha_deg, in_file);
    std::cout << "wrote " << out_file << " (" << out.number_of_vertices() << " vertices, " << out.number_of_faces() << " faces)\n";
    return rep.refinement.status == HSM::Refinement_status::SUCCESS ? 0 : 3;
  } catch(const CGAL::Invalid_option_error& e) {
    std::cerr << "hyperbolic_remesh: invalid option: " << e.what() << "\n"; return 2;
  } catch(const CGAL::Invalid_input_error& e) {
    std::cerr << "hyperbolic_remesh: invalid input mesh: " << e.what() << "\n"; return 1;
  } catch(const std::exception& e) {
    std::cerr << "hyperbolic_remesh: " << e.what() << "\n"; return 1;
  }
}
