// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SVG output of a hyperbolic mesh: the faces of the domain as geodesic triangles coloured by quality, the
// constrained edges, and a histogram of the central angles of the shortest edges.
#ifndef CGAL_HYPERBOLIC_MESH_2_IO_WRITE_HYPERBOLIC_MESH_SVG_H
#define CGAL_HYPERBOLIC_MESH_2_IO_WRITE_HYPERBOLIC_MESH_SVG_H

#include <CGAL/Hyperbolic_geometry_named_parameters.h>
#include <CGAL/Hyperbolic_mesh_2/internal/exact_quality.h>
#include <CGAL/IO/Poincare_disk_svg.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_target_angle_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_good_angle_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_title_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_marks_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(hm2_bins_t)

namespace CGAL {
namespace Hyperbolic_mesh_2 {
/// \ingroup PkgHyperbolicMesh2Ref
/// Named parameters of the SVG writers: `target_angle(double)`, `good_angle(double)`, `title(std::string)`,
/// `marks(std::vector<double>)`, `bins(int)`, and the view of `CGAL::Poincare_disk_svg::parameters`
/// (`image_size`, `zoom`, `view_center`), also available here.
namespace parameters {
CGAL_HYPERBOLIC_NAMED_PARAMETER(target_angle, hm2_target_angle_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(good_angle, hm2_good_angle_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(title, hm2_title_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(marks, hm2_marks_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(bins, hm2_bins_t)
using CGAL::Poincare_disk_svg::parameters::image_size;
using CGAL::Poincare_disk_svg::parameters::zoom;
using CGAL::Poincare_disk_svg::parameters::view_center;
} // namespace parameters

/// \ingroup PkgHyperbolicMesh2Ref
/// The central angle (radians) of the shortest edge of every face of the domain, in face iteration order.
template <class CDT>
std::vector<double> central_angles(const CDT& cdt)
{
  std::vector<double> a;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->is_in_domain())
      a.push_back(internal::approximate_central_angle(f->vertex(0)->point(), f->vertex(1)->point(),
                                                      f->vertex(2)->point()));
  return a;
}

/*!
  \ingroup PkgHyperbolicMesh2Ref
  Writes the mesh as an SVG picture of the Poincare disk: faces of the domain filled with a colour ramp of the
  central angle of their shortest edge (red: 0, blue: `good_angle` radians or more; faces below `target_angle`
  get a black outline), other edges thin grey, constrained edges dark and thick. `zoom`, `(cx, cy)`: view of the
  square of half-width 1/zoom around (cx, cy). Throws `std::runtime_error` if the file cannot be written.
  Cost O(n).
  \deprecated This positional form (up to 9 arguments) is kept for existing callers; prefer the named-parameter
  overload below.
*/
template <class CDT>
void write_hyperbolic_mesh_svg(const CDT& cdt, const std::string& filename, double target_angle = 0.0,
                               double good_angle = 2.0 * std::acos(-1.0) / 3.0, const std::string& title = "",
                               double size_px = 800, double zoom = 1.0, double cx = 0.0, double cy = 0.0)
{
  Poincare_disk_svg_writer svg(size_px, zoom, cx, cy);
  svg.add_unit_circle();
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    std::vector<double> xy;
    for(int i = 0; i < 3; ++i) {
      xy.push_back(CGAL::to_double(f->vertex(i)->point().x()));
      xy.push_back(CGAL::to_double(f->vertex(i)->point().y()));
    }
    const double a = internal::approximate_central_angle(f->vertex(0)->point(), f->vertex(1)->point(),
                                                         f->vertex(2)->point());
    const bool below = a < target_angle;
    svg.add_geodesic_polygon(xy, Poincare_disk_svg_writer::color_ramp(1.0 - a / good_angle),
                             below ? "#000" : "#888", below ? 0.8 : 0.25, 0.85);
  }
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if(!cdt.is_constrained(*e)) continue;
    svg.add_geodesic_segment(e->first->vertex(CDT::ccw(e->second))->point(),
                             e->first->vertex(CDT::cw(e->second))->point(), "#036", 1.6);
  }
  if(!title.empty()) svg.add_text(10, 20, title, 14);
  svg.write(filename);
}

/*!
  \ingroup PkgHyperbolicMesh2Ref
  Same as above with the options as named parameters (`CGAL::Hyperbolic_mesh_2::parameters`):
  \cgalNamedParamsBegin
    \cgalParamNBegin{target_angle} `double`, radians: faces below get a black outline; default 0 \cgalParamNEnd
    \cgalParamNBegin{good_angle} `double`, radians: the blue end of the colour ramp; default 2 pi / 3 \cgalParamNEnd
    \cgalParamNBegin{title} `std::string`, default none \cgalParamNEnd
    \cgalParamNBegin{image_size} `double`, pixels, default 800 \cgalParamNEnd
    \cgalParamNBegin{zoom} `double`, default 1 \cgalParamNEnd
    \cgalParamNBegin{view_center} `std::pair<double, double>`, default (0, 0) \cgalParamNEnd
  \cgalNamedParamsEnd
*/
template <class CDT, class T, class Tag, class Base>
void write_hyperbolic_mesh_svg(const CDT& cdt, const std::string& filename,
                               const Named_function_parameters<T, Tag, Base>& np)
{
  using Poincare_disk_svg::internal::get;
  const std::pair<double, double> c = get(np, internal_np::pds_view_center_t_v, std::make_pair(0.0, 0.0));
  write_hyperbolic_mesh_svg(cdt, filename, get(np, internal_np::hm2_target_angle_t_v, 0.0),
                            get(np, internal_np::hm2_good_angle_t_v, 2.0 * std::acos(-1.0) / 3.0),
                            get(np, internal_np::hm2_title_t_v, ""), get(np, internal_np::pds_image_size_t_v, 800.0),
                            get(np, internal_np::pds_zoom_t_v, 1.0), c.first, c.second);
}

/*!
  \ingroup PkgHyperbolicMesh2Ref
  Writes an SVG bar chart of the central angles of the shortest edges of the faces of the domain (degrees,
  `bins` bins over [0, 120]); vertical lines at `marks` (degrees, e.g. the bound alpha). Throws
  `std::runtime_error` if the file cannot be written.
  \deprecated positional form; prefer the named-parameter overload below.
*/
template <class CDT>
void write_central_angle_histogram_svg(const CDT& cdt, const std::string& filename,
                                       const std::vector<double>& marks = std::vector<double>(),
                                       const std::string& title = "", int bins = 60)
{
  const std::vector<double> a = central_angles(cdt);
  std::vector<std::size_t> h(std::size_t(std::max(1, bins)), 0);
  for(double x : a) {
    const double deg = x * 180 / std::acos(-1.0);
    const int b = std::min(int(h.size()) - 1, std::max(0, int(deg / 120.0 * h.size())));
    ++h[std::size_t(b)];
  }
  const std::size_t hmax = std::max<std::size_t>(1, *std::max_element(h.begin(), h.end()));
  const double W = 640, H = 360, L = 50, B = 40, T = 30, R = 20;
  const double pw = W - L - R, ph = H - T - B;
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W
     << "\" height=\"" << H << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for(std::size_t i = 0; i < h.size(); ++i) {
    const double x = L + pw * double(i) / double(h.size()), w = pw / double(h.size());
    const double y = T + ph * (1.0 - double(h[i]) / double(hmax));
    os << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << w * 0.9 << "\" height=\"" << T + ph - y
       << "\" fill=\"" << Poincare_disk_svg_writer::color_ramp(1.0 - (i + 0.5) / double(h.size())) << "\"/>\n";
  }
  for(double m : marks) {
    const double x = L + pw * m / 120.0;
    os << "<line x1=\"" << x << "\" y1=\"" << T << "\" x2=\"" << x << "\" y2=\"" << T + ph
       << "\" stroke=\"#c00\" stroke-dasharray=\"4,3\"/>\n";
  }
  os << "<line x1=\"" << L << "\" y1=\"" << T + ph << "\" x2=\"" << L + pw << "\" y2=\"" << T + ph
     << "\" stroke=\"#000\"/>\n";
  for(int d = 0; d <= 120; d += 20)
    os << "<text x=\"" << L + pw * d / 120.0 - 8 << "\" y=\"" << H - 18 << "\" font-family=\"sans-serif\" "
       << "font-size=\"12\">" << d << "</text>\n";
  os << "<text x=\"" << L << "\" y=\"" << H - 3 << "\" font-family=\"sans-serif\" font-size=\"12\">central angle "
     << "of the shortest edge (degrees); " << a.size() << " faces, tallest bar " << hmax << "</text>\n";
  if(!title.empty())
    os << "<text x=\"" << L << "\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">" << title << "</text>\n";
  os << "</svg>\n";
  std::ofstream out(filename);
  if(!out) throw std::runtime_error("write_central_angle_histogram_svg: cannot write " + filename);
  out << os.str();
}

/*!
  \ingroup PkgHyperbolicMesh2Ref
  Same as above with the options as named parameters: `marks` (`std::vector<double>`, degrees, default none),
  `title` (`std::string`), `bins` (`int`, default 60).
*/
template <class CDT, class T, class Tag, class Base>
void write_central_angle_histogram_svg(const CDT& cdt, const std::string& filename,
                                       const Named_function_parameters<T, Tag, Base>& np)
{
  using Poincare_disk_svg::internal::get;
  write_central_angle_histogram_svg(cdt, filename, get(np, internal_np::hm2_marks_t_v, std::vector<double>()),
                                    get(np, internal_np::hm2_title_t_v, ""), get(np, internal_np::hm2_bins_t_v, 60));
}

} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_IO_WRITE_HYPERBOLIC_MESH_SVG_H
