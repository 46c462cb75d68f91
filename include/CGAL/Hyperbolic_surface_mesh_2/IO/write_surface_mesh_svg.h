// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SVG pictures of a surface triangulation lifted to the Poincare disk (a fundamental domain and neighbouring
// copies, faces coloured by quality) and a histogram of central angles.
#ifndef CGAL_HYPERBOLIC_SURFACE_MESH_2_IO_WRITE_SURFACE_MESH_SVG_H
#define CGAL_HYPERBOLIC_SURFACE_MESH_2_IO_WRITE_SURFACE_MESH_SVG_H

#include <CGAL/IO/Poincare_disk_svg.h>
#include <CGAL/Hyperbolic_surface_mesh_2/internal/face_quality.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_surface_mesh_2 {

/// \ingroup PkgHyperbolicSurfaceMesh2Ref
/// The gluing isometries of the fundamental domain of `t`'s reference triangulation (the development of its
/// faces along a spanning tree, or the fundamental polygon): each maps the domain onto a neighbouring copy
/// across one of its boundary edges. Duplicates (up to 1e-9) removed.
template <class DT>
std::vector<typename DT::Isometry_2> domain_gluings(const DT& t)
{
  typedef typename DT::Isometry_2 Iso;
  std::vector<Iso> r;
  const auto& ref = t.reference();
  for(std::size_t f = 0; f < ref.faces.size(); ++f)
    for(int i = 0; i < 3; ++i) {
      const std::size_t g = ref.faces[f].nb[i];
      // copy of g adjacent to f across edge i: frame(f) o T(f->g)^-1, versus g's own frame
      const Iso d = (ref.faces[f].to_frame * ref.transition(f, int(i)).inverse() * ref.faces[g].to_frame.inverse()).normalized();
      if(d.distance_to(Iso()) < 1e-9) continue; // a tree edge (the two lay-outs agree)
      bool dup = false;
      for(const Iso& e : r) if(e.distance_to(d) < 1e-9) { dup = true; break; }
      if(!dup) r.push_back(d);
    }
  return r;
}

/*!
  \ingroup PkgHyperbolicSurfaceMesh2Ref
  Writes the faces of `t` in the frame of its fundamental domain, and their images under the domain gluings
  (lighter), as an SVG picture of the Poincare disk. Faces are coloured by the central angle of their shortest
  edge (red 0 degrees ... blue 60 degrees and above); constrained edges (feature loops) are drawn dark red. Throws `std::runtime_error` if the file cannot be written.
*/
template <class DT>
void write_surface_mesh_svg(const DT& t, const std::string& filename, bool neighbouring_copies = true,
                            const std::string& title = "")
{
  CGAL::Poincare_disk_svg_writer svg(900);
  svg.add_unit_circle();
  const internal::Face_quality<DT> q(t, false, 1, CGAL_PI / 6);
  std::vector<typename DT::Isometry_2> copies(1);
  if(neighbouring_copies) { const auto g = domain_gluings(t); copies.insert(copies.end(), g.begin(), g.end()); }
  for(std::size_t c = 0; c < copies.size(); ++c)
    for(std::size_t f : t.faces()) {
      const auto m = copies[c] * t.to_frame(f);
      std::vector<double> xy;
      bool ok = true;
      for(const auto& z : t.lift(f)) {
        const auto p = m.apply_unchecked(z);
        if(!(p.x() * p.x() + p.y() * p.y() < 0.9999)) ok = false;
        xy.push_back(p.x()); xy.push_back(p.y());
      }
      if(!ok) continue;
      const double a = q.central_angle(f) / (CGAL_PI / 3);
      svg.add_geodesic_polygon(xy, CGAL::Poincare_disk_svg_writer::color_ramp(1 - a), c == 0 ? "#222" : "#777",
                               c == 0 ? 0.3 : 0.15, c == 0 ? 1.0 : 0.45);
    }
  // the constrained edges (feature loops) on top, dark red
  for(std::size_t c = 0; c < copies.size(); ++c)
    for(std::size_t f : t.faces())
      for(int i = 0; i < 3; ++i) {
        if(!t.is_constrained(f, i) || t.neighbor(f, i) < f) continue;
        const auto m = copies[c] * t.to_frame(f);
        const auto p = m.apply_unchecked(t.lift(f)[i]), r = m.apply_unchecked(t.lift(f)[(i + 1) % 3]);
        if(p.x() * p.x() + p.y() * p.y() < 0.9999 && r.x() * r.x() + r.y() * r.y() < 0.9999)
          svg.add_geodesic_segment(p, r, c == 0 ? "#a00" : "#d88", c == 0 ? 1.6 : 0.8);
      }
  if(!title.empty()) svg.add_text(10, 20, title);
  svg.write(filename);
}

/// \ingroup PkgHyperbolicSurfaceMesh2Ref
/// Writes a histogram (SVG, 1-degree bins from 0 to 120) of the central angles of the shortest edges of `t`'s
/// faces, with the bound `bound_deg` marked.
template <class DT>
void write_central_angle_histogram_svg(const DT& t, const std::string& filename, double bound_deg, const std::string& title = "")
{
  const internal::Face_quality<DT> q(t, false, 1, CGAL_PI / 6);
  std::vector<std::size_t> bins(120, 0);
  for(std::size_t f : t.faces()) {
    const int b = int(q.central_angle(f) * 180 / CGAL_PI);
    ++bins[std::size_t((std::min)(119, (std::max)(0, b)))];
  }
  const std::size_t top = *std::max_element(bins.begin(), bins.end());
  std::ostringstream os;
  const double W = 720, H = 300, x0 = 60, y0 = 340;
  os << "<rect x=\"0\" y=\"0\" width=\"800\" height=\"400\" fill=\"white\"/>\n";
  for(std::size_t i = 0; i < bins.size(); ++i) {
    const double h = top ? H * double(bins[i]) / double(top) : 0;
    os << "<rect x=\"" << x0 + W * i / 120.0 << "\" y=\"" << y0 - h << "\" width=\"" << W / 120.0 - 0.5
       << "\" height=\"" << h << "\" fill=\"#36c\"/>\n";
  }
  os << "<line x1=\"" << x0 + W * bound_deg / 120 << "\" y1=\"" << y0 - H - 10 << "\" x2=\"" << x0 + W * bound_deg / 120
     << "\" y2=\"" << y0 << "\" stroke=\"#c00\" stroke-width=\"2\"/>\n";
  for(int d = 0; d <= 120; d += 20)
    os << "<text x=\"" << x0 + W * d / 120 - 8 << "\" y=\"" << y0 + 18 << "\" font-size=\"13\" font-family=\"sans-serif\">" << d << "</text>\n";
  os << "<text x=\"" << x0 << "\" y=\"25\" font-size=\"15\" font-family=\"sans-serif\">" << title
     << " central angle of the shortest edge (degrees), " << t.number_of_faces() << " faces, max bin " << top << "</text>\n";
  std::ofstream out(filename);
  if(!out) throw std::runtime_error("write_central_angle_histogram_svg: cannot write " + filename);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"400\">\n"
      << os.str() << "</svg>\n";
}

} // namespace Hyperbolic_surface_mesh_2
} // namespace CGAL

#endif
