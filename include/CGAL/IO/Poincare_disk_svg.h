// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SVG pictures of the Poincare disk: the unit circle, points, geodesic segments drawn as circular arcs
// (or diameters), geodesic polygons. Shared by the examples of all packages.
#ifndef CGAL_IO_POINCARE_DISK_SVG_H
#define CGAL_IO_POINCARE_DISK_SVG_H

#include <CGAL/Hyperbolic_geometry_named_parameters.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_image_size_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_zoom_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_view_center_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_stroke_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_stroke_width_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_fill_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_fill_opacity_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_radius_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER_TAG(pds_font_size_t)

namespace CGAL {
namespace Poincare_disk_svg {
/*!
  \ingroup PkgPoincareDiskTraits2Ref
  Named parameters of `Poincare_disk_svg_writer` (and of the SVG writers of the other packages that build on it).
  Each takes its value and, optionally, the chain it extends (`stroke("#036", stroke_width(1.6))`):
  - `image_size(double)`: width and height in pixels (default 800); `zoom(double)` (default 1) and
    `view_center(std::pair<double, double>)` (default (0, 0)): the view shows the square of half-width 1/zoom
    around the centre;
  - `stroke(std::string)`, `stroke_width(double)`, `fill(std::string)`, `fill_opacity(double)`: SVG styles;
  - `radius(double)`: the radius of a point in pixels; `font_size(double)`: text size in pixels.
*/
namespace parameters {
CGAL_HYPERBOLIC_NAMED_PARAMETER(image_size, pds_image_size_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(zoom, pds_zoom_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(view_center, pds_view_center_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(stroke, pds_stroke_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(stroke_width, pds_stroke_width_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(fill, pds_fill_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(fill_opacity, pds_fill_opacity_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(radius, pds_radius_t)
CGAL_HYPERBOLIC_NAMED_PARAMETER(font_size, pds_font_size_t)
} // namespace parameters

namespace internal {
// the value of a named parameter, or `def` (converted to the default's type)
template <class T, class NP, class Tag>
T get(const NP& np, Tag tag, const T& def)
{
  return T(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, tag), def));
}
template <class NP, class Tag>
std::string get(const NP& np, Tag tag, const char* def) { return get<std::string>(np, tag, std::string(def)); }
} // namespace internal
} // namespace Poincare_disk_svg

/*!
  \ingroup PkgPoincareDiskTraits2Ref
  Collects drawing commands in the Poincare disk and writes them as one SVG file. Coordinates are Poincare
  coordinates; geodesic segments become arcs of the circle through both ends orthogonal to the unit circle.
  Optionally a view transform (zoom, centre) magnifies a part of the disk.
*/
class Poincare_disk_svg_writer
{
public:
  /// `size_px`: width and height of the picture; `zoom`, `(cx, cy)`: the view shows the square of
  /// half-width 1/zoom around (cx, cy).
  /// \deprecated positional form of the named-parameter constructor below
  explicit Poincare_disk_svg_writer(double size_px = 800, double zoom = 1.0, double cx = 0.0, double cy = 0.0)
    : size_(size_px), zoom_(zoom), cx_(cx), cy_(cy)
  {
    os_.precision(7);
  }

  /// Named parameters (`CGAL::Poincare_disk_svg::parameters`): `image_size`, `zoom`, `view_center`.
  template <class T, class Tag, class Base>
  explicit Poincare_disk_svg_writer(const Named_function_parameters<T, Tag, Base>& np)
    : Poincare_disk_svg_writer(
          Poincare_disk_svg::internal::get(np, internal_np::pds_image_size_t_v, 800.0),
          Poincare_disk_svg::internal::get(np, internal_np::pds_zoom_t_v, 1.0),
          Poincare_disk_svg::internal::get(np, internal_np::pds_view_center_t_v, std::make_pair(0.0, 0.0)).first,
          Poincare_disk_svg::internal::get(np, internal_np::pds_view_center_t_v, std::make_pair(0.0, 0.0)).second)
  {}

  /// \name Drawing with named parameters
  /// The preferred forms: the style as `CGAL::Poincare_disk_svg::parameters` (`stroke`, `stroke_width`, `fill`,
  /// `fill_opacity`, `radius`, `font_size`), with the defaults of the positional forms, which are deprecated.
  /// @{
  template <class T, class Tag, class Base>
  void add_unit_circle(const Named_function_parameters<T, Tag, Base>& np)
  {
    using namespace Poincare_disk_svg::internal;
    add_unit_circle(get(np, internal_np::pds_stroke_t_v, "#000"), get(np, internal_np::pds_stroke_width_t_v, 1.5),
                    get(np, internal_np::pds_fill_t_v, "#fcfcff"));
  }
  template <class Point_2, class T, class Tag, class Base>
  void add_point(const Point_2& p, const Named_function_parameters<T, Tag, Base>& np)
  {
    using namespace Poincare_disk_svg::internal;
    add_point(p, get(np, internal_np::pds_fill_t_v, "#c00"), get(np, internal_np::pds_radius_t_v, 2.0));
  }
  template <class Point_2, class T, class Tag, class Base>
  void add_geodesic_segment(const Point_2& p, const Point_2& q, const Named_function_parameters<T, Tag, Base>& np)
  {
    using namespace Poincare_disk_svg::internal;
    add_geodesic_segment(p, q, get(np, internal_np::pds_stroke_t_v, "#036"),
                         get(np, internal_np::pds_stroke_width_t_v, 1.0));
  }
  template <class T, class Tag, class Base>
  void add_geodesic_polygon(const std::vector<double>& xy, const Named_function_parameters<T, Tag, Base>& np)
  {
    using namespace Poincare_disk_svg::internal;
    add_geodesic_polygon(xy, get(np, internal_np::pds_fill_t_v, "none"), get(np, internal_np::pds_stroke_t_v, "none"),
                         get(np, internal_np::pds_stroke_width_t_v, 0.5), get(np, internal_np::pds_fill_opacity_t_v, 1.0));
  }
  template <class T, class Tag, class Base>
  void add_euclidean_circle(double x, double y, double r, const Named_function_parameters<T, Tag, Base>& np)
  {
    using namespace Poincare_disk_svg::internal;
    add_euclidean_circle(x, y, r, get(np, internal_np::pds_stroke_t_v, "#080"),
                         get(np, internal_np::pds_stroke_width_t_v, 1.0));
  }
  template <class T, class Tag, class Base>
  void add_text(double x_px, double y_px, const std::string& text, const Named_function_parameters<T, Tag, Base>& np)
  {
    using namespace Poincare_disk_svg::internal;
    add_text(x_px, y_px, text, get(np, internal_np::pds_font_size_t_v, 14.0), get(np, internal_np::pds_fill_t_v, "#000"));
  }
  /// @}

  /// the boundary at infinity
  void add_unit_circle(const std::string& stroke = "#000", double width = 1.5, const std::string& fill = "#fcfcff")
  {
    os_ << "<circle cx=\"" << sx(0) << "\" cy=\"" << sy(0) << "\" r=\"" << 1.0 * scale()
        << "\" fill=\"" << fill << "\" stroke=\"" << stroke << "\" stroke-width=\"" << width << "\"/>\n";
  }

  void add_point(double x, double y, const std::string& fill = "#c00", double radius_px = 2.0)
  {
    os_ << "<circle cx=\"" << sx(x) << "\" cy=\"" << sy(y) << "\" r=\"" << radius_px << "\" fill=\"" << fill << "\"/>\n";
  }

  template <class Point_2>
  void add_point(const Point_2& p, const std::string& fill = "#c00", double radius_px = 2.0)
  {
    add_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), fill, radius_px);
  }

  /// the geodesic segment pq (an arc orthogonal to the unit circle, or a straight segment)
  void add_geodesic_segment(double px, double py, double qx, double qy,
                            const std::string& stroke = "#036", double width = 1.0)
  {
    os_ << "<path d=\"M " << sx(px) << " " << sy(py) << " ";
    arc_to(px, py, qx, qy);
    os_ << "\" fill=\"none\" stroke=\"" << stroke << "\" stroke-width=\"" << width << "\"/>\n";
  }

  template <class Point_2>
  void add_geodesic_segment(const Point_2& p, const Point_2& q, const std::string& stroke = "#036", double width = 1.0)
  {
    add_geodesic_segment(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(q.x()),
                         CGAL::to_double(q.y()), stroke, width);
  }

  /// a closed geodesic polygon given by its vertices (x0, y0, x1, y1, ...)
  void add_geodesic_polygon(const std::vector<double>& xy, const std::string& fill,
                            const std::string& stroke = "none", double width = 0.5, double fill_opacity = 1.0)
  {
    if(xy.size() < 6) return;
    const std::size_t n = xy.size() / 2;
    os_ << "<path d=\"M " << sx(xy[0]) << " " << sy(xy[1]) << " ";
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      arc_to(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1]);
    }
    os_ << "Z\" fill=\"" << fill << "\" fill-opacity=\"" << fill_opacity << "\" stroke=\"" << stroke
        << "\" stroke-width=\"" << width << "\"/>\n";
  }

  /// a Euclidean circle (e.g. a hyperbolic circle, given by its Euclidean centre and radius)
  void add_euclidean_circle(double x, double y, double r, const std::string& stroke = "#080", double width = 1.0)
  {
    os_ << "<circle cx=\"" << sx(x) << "\" cy=\"" << sy(y) << "\" r=\"" << r * scale()
        << "\" fill=\"none\" stroke=\"" << stroke << "\" stroke-width=\"" << width << "\"/>\n";
  }

  /// text at a position in pixels from the top-left corner
  void add_text(double x_px, double y_px, const std::string& text, double font_px = 14, const std::string& fill = "#000")
  {
    os_ << "<text x=\"" << x_px << "\" y=\"" << y_px << "\" font-family=\"sans-serif\" font-size=\"" << font_px
        << "\" fill=\"" << fill << "\">" << escape(text) << "</text>\n";
  }

  /// raw SVG elements (for legends, histograms, ...)
  void add_raw(const std::string& svg_elements) { os_ << svg_elements << "\n"; }

  double size() const { return size_; }

  /// writes the file; throws `std::runtime_error` if it cannot be written.
  void write(const std::string& filename) const
  {
    std::ofstream out(filename);
    if(!out) throw std::runtime_error("Poincare_disk_svg_writer: cannot write " + filename);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size_ << "\" height=\"" << size_
        << "\" viewBox=\"0 0 " << size_ << " " << size_ << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << os_.str() << "</svg>\n";
    if(!out) throw std::runtime_error("Poincare_disk_svg_writer: error while writing " + filename);
  }

  /// an RGB colour "#rrggbb" from a value in [0,1] along a blue-green-yellow-red ramp
  static std::string color_ramp(double t)
  {
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    const double r = t < 0.5 ? 2 * t : 1.0, g = t < 0.5 ? 0.4 + 1.2 * t : 1.0 - 1.6 * (t - 0.5),
                 b = t < 0.5 ? 1.0 - 2 * t : 0.0;
    char buf[8];
    std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", int(255 * r), int(255 * (g < 0 ? 0 : g)), int(255 * b));
    return buf;
  }

private:
  double scale() const { return 0.48 * size_ * zoom_; }
  double sx(double x) const { return 0.5 * size_ + (x - cx_) * scale(); }
  double sy(double y) const { return 0.5 * size_ - (y - cy_) * scale(); }

  static std::string escape(const std::string& s)
  {
    std::string r;
    for(char c : s) {
      if(c == '<') r += "&lt;"; else if(c == '>') r += "&gt;"; else if(c == '&') r += "&amp;"; else r += c;
    }
    return r;
  }

  // appends the path command drawing the geodesic from p to q (the current point is p)
  void arc_to(double px, double py, double qx, double qy)
  {
    // circle x^2 + y^2 + D x + E y + 1 = 0 through p and q (orthogonal to the unit circle)
    const double det = px * qy - py * qx;
    const double np = 1 + px * px + py * py, nq = 1 + qx * qx + qy * qy;
    const double scale_len = std::sqrt((px - qx) * (px - qx) + (py - qy) * (py - qy));
    if(std::abs(det) <= 1e-12 * (1 + scale_len)) { // 0, p, q collinear: a diameter
      os_ << "L " << sx(qx) << " " << sy(qy) << " ";
      return;
    }
    const double D = (-np * qy + nq * py) / det, E = (np * qx - nq * px) / det;
    const double cx = -D / 2, cy = -E / 2, r = std::sqrt((std::max)(0.0, cx * cx + cy * cy - 1));
    if(r * scale() > 1e6) { os_ << "L " << sx(qx) << " " << sy(qy) << " "; return; }
    // The geodesic is the minor arc, counterclockwise around the centre iff cross > 0. The picture shows the
    // disk as seen in math coordinates (y up), so a counterclockwise turn is drawn counterclockwise, which is
    // SVG's negative-angle direction (sweep-flag 0; SVG's y axis points down).
    const double cross = (px - cx) * (qy - cy) - (py - cy) * (qx - cx);
    const int sweep = cross > 0 ? 0 : 1;
    os_ << "A " << r * scale() << " " << r * scale() << " 0 0 " << sweep << " " << sx(qx) << " " << sy(qy) << " ";
  }

  double size_, zoom_, cx_, cy_;
  std::ostringstream os_;
};

} // namespace CGAL

#endif // CGAL_IO_POINCARE_DISK_SVG_H
