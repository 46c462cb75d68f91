// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one exception hierarchy of the hyperbolic and conformal geometry packages. Bad user data (points not in
// the open disk, meshes that are open, non-manifold, of several components or of the wrong genus, metrics that
// are not hyperbolic, paths that are not paths, PSLGs that cross) and numerical limits reach the caller as one
// of these exceptions, in release builds too. The same condition throws the same type in every package;
// programmer errors (contract violations) are CGAL_precondition's instead.
#ifndef CGAL_HYPERBOLIC_GEOMETRY_ERRORS_H
#define CGAL_HYPERBOLIC_GEOMETRY_ERRORS_H

#include <stdexcept>
#include <string>

namespace CGAL {

/*!
  \ingroup PkgPoincareDiskTraits2Ref
  Base of every exception thrown by the hyperbolic and conformal geometry packages.

  \code
  Hyperbolic_geometry_error                 (std::runtime_error)
  +-- Invalid_input_error                   bad user data
  |   +-- Poincare_disk_domain_error        a point not in the open unit disk (|p| >= 1, NaN, infinity)
  |   +-- Invalid_mesh_error                a mesh that is empty, open, not triangulated, non-manifold,
  |   |                                     of several components, of the wrong genus, with degenerate faces
  |   +-- Invalid_metric_error              edge lengths that are not a (hyperbolic) metric of the surface
  |   +-- Invalid_path_error                a path or loop that is not one on the surface
  |   +-- Invalid_option_error              an option (named parameter) out of its range
  +-- Numerical_error                       a computation that needs more precision or more work than allowed
  \endcode
  Packages derive their own types from these (e.g. the mesher's PSLG errors from `Invalid_input_error`).
*/
class Hyperbolic_geometry_error : public std::runtime_error
{
public:
  explicit Hyperbolic_geometry_error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgPoincareDiskTraits2Ref
/// Bad user data.
class Invalid_input_error : public Hyperbolic_geometry_error
{
public:
  explicit Invalid_input_error(const std::string& what) : Hyperbolic_geometry_error(what) {}
};

/// \ingroup PkgPoincareDiskTraits2Ref
/// A point given as a point of the Poincare disk is not in the open unit disk (|p| >= 1) or has a non-finite
/// coordinate.
class Poincare_disk_domain_error : public Invalid_input_error
{
public:
  explicit Poincare_disk_domain_error(const std::string& what) : Invalid_input_error(what) {}
};

/// \ingroup PkgPoincareDiskTraits2Ref
/// A mesh that the algorithm cannot take: empty, open where a closed surface is needed, not triangulated,
/// non-manifold, of several connected components, of the wrong genus, with degenerate faces.
class Invalid_mesh_error : public Invalid_input_error
{
public:
  explicit Invalid_mesh_error(const std::string& what) : Invalid_input_error(what) {}
};

/// \ingroup PkgPoincareDiskTraits2Ref
/// Edge lengths that do not define the required metric (triangle inequality violated, angle sum at a vertex
/// different from 2 pi for a smooth hyperbolic metric, non-finite length).
class Invalid_metric_error : public Invalid_input_error
{
public:
  explicit Invalid_metric_error(const std::string& what) : Invalid_input_error(what) {}
};

/// \ingroup PkgPoincareDiskTraits2Ref
/// A path that is not a path on the surface (consecutive points not in a common face, invalid handle), or an
/// open path where a loop is required.
class Invalid_path_error : public Invalid_input_error
{
public:
  explicit Invalid_path_error(const std::string& what) : Invalid_input_error(what) {}
};

/// \ingroup PkgPoincareDiskTraits2Ref
/// An option out of its range (a negative tolerance, an angle bound for which refinement cannot terminate,
/// a non-finite work bound, ...).
class Invalid_option_error : public Invalid_input_error
{
public:
  explicit Invalid_option_error(const std::string& what) : Invalid_input_error(what) {}
};

/// \ingroup PkgPoincareDiskTraits2Ref
/// A computation that needs more precision than it has, or more work than its bound allows, where no status
/// can report it.
class Numerical_error : public Hyperbolic_geometry_error
{
public:
  explicit Numerical_error(const std::string& what) : Hyperbolic_geometry_error(what) {}
};

} // namespace CGAL

#endif // CGAL_HYPERBOLIC_GEOMETRY_ERRORS_H
