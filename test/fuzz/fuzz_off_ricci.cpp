// libFuzzer target of the Discrete_Ricci_flow package: OFF text -> mesh -> Ricci flow (hyperbolic, flat or
// spherical by genus) -> embedding. Contract checked: no crash, no hang (small meshes, bounded iterations), every
// output finite, and every exception one of the documented CGAL::Hyperbolic_geometry_error types.
// Build: clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -Iinclude -I/usr/include/eigen3
//        test/fuzz/fuzz_off_ricci.cpp -lgmp -lmpfr
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Discrete_Ricci_flow.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {
typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace RF = CGAL::Discrete_Ricci_flow;

void require(bool ok) { if(!ok) std::abort(); }

template <class Metric>
void check_metric(const Metric& r)
{
  for(auto e : r.intrinsic_mesh().edges()) require(std::isfinite(r.length(e)));
  require(std::isfinite(r.statistics().max_curvature_error) || !r.converged());
}

void run(const Mesh& m)
{
  const long chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  const auto np = CGAL::parameters::number_of_iterations(30);
  if(chi < 0) {
    const auto r = RF::hyperbolic_uniformization(m, np);
    check_metric(r);
    if(r.converged()) {
      const RF::Hyperbolic_embedding<K::Point_3> emb(r);
      for(std::size_t i = 0; i < emb.number_of_generators(); ++i) require(std::isfinite(emb.absolute_trace(i)));
      require(std::isfinite(emb.relator_defect()));
    }
  } else if(chi == 0) {
    const auto r = RF::flat_metric(m, np);
    check_metric(r);
    if(r.converged()) {
      const RF::Hyperbolic_embedding<K::Point_3> emb(r);
      const auto tau = emb.lattice_parameter();
      require(std::isfinite(tau.real()) && std::isfinite(tau.imag()));
    }
  } else {
    const auto s = RF::spherical_uniformization(m, np);
    for(const auto& p : s.sphere_points()) require(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
  }
}
} // namespace

// CGAL 5.5's OFF reader allocates what the file declares (a face "999999999993 3 8 ..." or "55555555555550.5 ..."
// asks for terabytes), which AddressSanitizer reports as a fatal allocation-size-too-big before std::bad_alloc
// could be caught. The reader is not under test: inputs with a token whose leading digits (after a sign) are more
// than 6, i.e. a count above 999,999 as the reader would parse it, are skipped. So are binary OFF files (a
// "BINARY" token in the header): their counts are raw integers, and the reader allocated 18 GB on the 33-byte
// `regression-binary-off-counts.off` of the seed corpus.
// Only the plain "OFF" header (after comment lines) is fed to the reader: with "COFF" and malformed colours CGAL 5.5's
// File_scanner_OFF::scan_color dereferences a null pointer (SIGSEGV on `regression-coff-colour-segv.off`, found
// after 146,874 runs; the 30-line test program reading it with CGAL::IO::read_OFF alone crashes the same way).
bool reader_cannot_take(const std::string& text)
{
  if(text.find("BINARY") != std::string::npos) return true;
  std::size_t h = 0; // the header: the first token after blank and '#' comment lines must be "OFF"
  while(h < text.size() && (std::isspace(static_cast<unsigned char>(text[h])) || text[h] == '#'))
    if(text[h] == '#') { while(h < text.size() && text[h] != '\n') ++h; } else ++h;
  if(text.compare(h, 3, "OFF") != 0 || h + 3 >= text.size() || !std::isspace(static_cast<unsigned char>(text[h + 3])))
    return true;
  std::size_t i = 0;
  while(i < text.size()) {
    while(i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if(i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t digits = 0;
    while(i < text.size() && text[i] >= '0' && text[i] <= '9') { ++digits; ++i; }
    if(digits > 6) return true;
    while(i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  }
  return false;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size > 20000) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if(reader_cannot_take(text)) return 0;
  std::istringstream in(text);
  Mesh m;
  try {
    if(!CGAL::IO::read_OFF(in, m) || m.number_of_faces() > 400 || m.number_of_vertices() > 400) return 0;
  } catch(...) { return 0; } // the reader is not under test
  for(const auto& p : m.points()) if(!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()))) return 0;
  try { run(m); }
  catch(const CGAL::Hyperbolic_geometry_error&) {} // documented: Invalid_mesh/metric/option/input, Numerical_error
  return 0;
}
