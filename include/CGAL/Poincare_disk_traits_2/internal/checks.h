// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input validation shared by the Poincare disk packages: bad user data reaches the caller as an exception,
// in release builds too.
#ifndef CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_CHECKS_H
#define CGAL_POINCARE_DISK_TRAITS_2_INTERNAL_CHECKS_H

#include <CGAL/Hyperbolic_geometry_errors.h>
#include <CGAL/number_utils.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {

namespace Poincare_disk_internal {

template <class FT>
bool is_finite_coordinate(const FT& v)
{
  return std::isfinite(CGAL::to_double(v));
}

/// true iff x^2 + y^2 < 1, decided exactly (double input: interval arithmetic, then rationals).
inline bool is_in_open_disk_xy(double x, double y)
{
  if(!std::isfinite(x) || !std::isfinite(y)) return false;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const CGAL::Interval_nt<false> ix(x), iy(y);
    const CGAL::Uncertain<bool> r = (ix * ix + iy * iy < 1);
    if(CGAL::is_certain(r)) return CGAL::get_certain(r);
  }
  const CGAL::Exact_rational ex(x), ey(y);
  return ex * ex + ey * ey < 1;
}

template <class FT>
bool is_in_open_disk_xy(const FT& x, const FT& y)
{
  if(!is_finite_coordinate(x) || !is_finite_coordinate(y)) return false;
  return x * x + y * y < FT(1);
}

/// true iff p is a finite point of the open unit disk (decided exactly).
template <class Point_2>
bool is_in_open_disk(const Point_2& p)
{
  return is_in_open_disk_xy(p.x(), p.y());
}

/// the exact part of `check_point_in_disk()` (out of line: rarely reached with double coordinates)
template <class Point_2>
#if defined(__GNUC__)
__attribute__((noinline, cold))
#endif
void check_point_in_disk_exactly(const Point_2& p, const char* where)
{
  if(!is_in_open_disk(p)) {
    std::ostringstream os;
    os.precision(17);
    os << where << ": point (" << CGAL::to_double(p.x()) << ", " << CGAL::to_double(p.y())
       << ") is not in the open unit disk (|p| < 1 and finite coordinates are required)";
    throw Poincare_disk_domain_error(os.str());
  }
}

/// throws `Poincare_disk_domain_error` (naming `where` and the point) unless p is a finite point of the open unit
/// disk (decided exactly); for double coordinates well inside the disk one comparison decides
/// (1 + |p|^2 < 2 - 1e-13 in floating point implies |p| < 1 and finite coordinates). That comparison is inlined
/// into every predicate, the exact decision is not.
template <class Point_2>
inline void check_point_in_disk(const Point_2& p, const char* where)
{
  if constexpr(std::is_same<typename std::decay<decltype(p.x())>::type, double>::value) {
    const double w = 1.0 + p.x() * p.x() + p.y() * p.y();
    if(w < 1.9999999999999) return;
  }
  check_point_in_disk_exactly(p, where);
}

} // namespace Poincare_disk_internal
} // namespace CGAL

#endif
