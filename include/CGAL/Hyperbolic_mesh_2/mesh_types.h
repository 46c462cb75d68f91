// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Parameters, progress report, status and statistics of the hyperbolic Delaunay refinement entry points
// (refine_hyperbolic_Ruppert_mesh_2, refine_hyperbolic_Chew_mesh_2).
#ifndef CGAL_HYPERBOLIC_MESH_2_MESH_TYPES_H
#define CGAL_HYPERBOLIC_MESH_2_MESH_TYPES_H

#include <CGAL/Hyperbolic_geometry_errors.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <functional>
#include <iterator>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Hyperbolic_mesh_2 {

/// \ingroup PkgHyperbolicMesh2Ref
/// Thrown for a planar geodesic graph or a triangulation the refiners cannot take: duplicate points, crossing or
/// overlapping segments, a segment index out of range, a triangulation of dimension < 2.
class Pslg_error : public CGAL::Invalid_input_error
{
public:
  explicit Pslg_error(const std::string& what) : CGAL::Invalid_input_error("Hyperbolic_mesh_2: " + what) {}
};

/// \ingroup PkgHyperbolicMesh2Ref
/// Every input error of the package (the shared `CGAL::Invalid_input_error`): `Pslg_error`,
/// `CGAL::Poincare_disk_domain_error` for a point, vertex or seed not in the open unit disk,
/// `CGAL::Invalid_option_error` for an option out of its range.
typedef CGAL::Invalid_input_error Input_error;

/// \ingroup PkgHyperbolicMesh2Ref
/// How the refinement ended.
enum class Refinement_status {
  SUCCESS,            ///< every face of the domain meets the criteria, except the protected faces at input angles
                      ///< below pi/2 (`Mesh_statistics::protected_faces`, by design: thesis Fig. 3.6); no
                      ///< encroached segment is left. Checked with the exact criteria on every face at the end.
  WORK_BOUND_REACHED, ///< stopped after `maximum_number_of_operations()` insertions + removals
  CANCELLED,          ///< the progress callback returned false
  UNREFINED_FACES_LEFT ///< no work is left, but `Mesh_statistics::faces_failing_criteria` faces of the domain fail
                      ///< the criteria and are not protected: their Steiner points or split points could not be
                      ///< inserted in double precision (`unrefinable_faces`, `unsplittable_segments`)
};

inline const char* to_string(Refinement_status s)
{
  switch(s) {
  case Refinement_status::SUCCESS: return "SUCCESS";
  case Refinement_status::WORK_BOUND_REACHED: return "WORK_BOUND_REACHED";
  case Refinement_status::CANCELLED: return "CANCELLED";
  case Refinement_status::UNREFINED_FACES_LEFT: return "UNREFINED_FACES_LEFT";
  }
  return "?";
}

/// \ingroup PkgHyperbolicMesh2Ref
/// Progress snapshot passed to the callback (every 4096 operations and at the end).
struct Progress
{
  std::size_t operations = 0;       ///< insertions + removals so far
  std::size_t number_of_vertices = 0;
  std::size_t bad_faces_queued = 0; ///< queue sizes (with stale entries)
  std::size_t encroached_segments_queued = 0;
};

/*!
  \ingroup PkgHyperbolicMesh2Ref
  \deprecated Use CGAL named parameters instead (`CGAL::Hyperbolic_mesh_2::parameters::seeds(...)`, ...,
  see `mesh_named_parameters.h`); the named-parameter overloads fill this struct and call the same code.
  Options of the refinement entry points, set with chained calls:
  \code
  auto stats = CGAL::refine_hyperbolic_Ruppert_mesh_2(cdt, criteria,
      CGAL::Hyperbolic_mesh_2::Mesh_parameters<Point>().seeds(holes.begin(), holes.end()).maximum_number_of_operations(1e6));
  \endcode
  (The former shorthand function `Hyperbolic_mesh_2::parameters<Point>()` is gone: that name is now the
  namespace of the named parameters.)
*/
/// \ingroup PkgHyperbolicMesh2Ref
/// The default work bound of the refiners (see `Mesh_parameters::maximum_number_of_operations`).
constexpr std::size_t default_maximum_number_of_operations = 1000000;

template <class Point_2>
class Mesh_parameters
{
public:
  /// Seeds as in `refine_Delaunay_mesh_2`: the connected components (separated by constrained edges) that contain
  /// a seed are outside the domain (or, with `seeds_are_in_domain(true)`, they are the domain).
  template <class InputIterator>
  Mesh_parameters& seeds(InputIterator begin, InputIterator end) { seeds_.assign(begin, end); return *this; }
  Mesh_parameters& seeds_are_in_domain(bool b) { seeds_in_ = b; return *this; }
  /// Work bound: the refinement stops with `WORK_BOUND_REACHED` after this many vertex insertions + removals
  /// (frame and corner-lopping vertices included). Default `default_maximum_number_of_operations` = 1 000 000:
  /// at 10^5 to 10^6 operations per second on well-shaped input that is 1 to 10 seconds; on degenerate input
  /// (near the circle at infinity, tiny input angles) where most operations fail or are undone, at worst about
  /// 1000 operations per second, i.e. 15 minutes. Values above 10^15 (and +infinity) are clamped to 10^15.
  /// Throws `CGAL::Invalid_option_error` for a negative value or NaN.
  Mesh_parameters& maximum_number_of_operations(double n)
  {
    if(!(n >= 0)) throw CGAL::Invalid_option_error("Hyperbolic_mesh_2: maximum_number_of_operations must be >= 0");
    max_ops_ = n >= 1e15 ? std::size_t(1000000000000000ull) : static_cast<std::size_t>(n);
    return *this;
  }
  /// Corner lopping (thesis Fig. 3.6) at input angles below pi/2 (default on).
  Mesh_parameters& corner_lopping(bool b) { lopping_ = b; return *this; }
  /// Off-center Steiner points (Ungor 2004) instead of circumcenters for skinny faces (Ruppert only; default off).
  Mesh_parameters& off_centers(bool b) { off_centers_ = b; return *this; }
  /// Called every 4096 operations; return false to stop (status `CANCELLED`).
  Mesh_parameters& callback(std::function<bool(const Progress&)> f) { callback_ = std::move(f); return *this; }
  /// Prints a one-line summary and progress lines to `std::cerr`.
  Mesh_parameters& verbose(bool b) { verbose_ = b; return *this; }

  const std::vector<Point_2>& seeds() const { return seeds_; }
  bool seeds_are_in_domain() const { return seeds_in_; }
  std::size_t maximum_number_of_operations() const { return max_ops_; }
  bool corner_lopping() const { return lopping_; }
  bool off_centers() const { return off_centers_; }
  const std::function<bool(const Progress&)>& callback() const { return callback_; }
  bool verbose() const { return verbose_; }

private:
  std::vector<Point_2> seeds_;
  bool seeds_in_ = false;
  std::size_t max_ops_ = default_maximum_number_of_operations;
  bool lopping_ = true, off_centers_ = false, verbose_ = false;
  std::function<bool(const Progress&)> callback_;
};

/// \ingroup PkgHyperbolicMesh2Ref
/// What a refinement did and what it reached. Angles in radians, lengths hyperbolic.
struct Mesh_statistics
{
  Refinement_status status = Refinement_status::SUCCESS;
  std::size_t initial_vertices = 0, final_vertices = 0;
  std::size_t circumcenters_inserted = 0;   ///< Steiner points inside faces (circumcenters / off-centers)
  std::size_t off_centers_inserted = 0;     ///< of which off-centers
  std::size_t midpoint_splits = 0;          ///< segment splits at the hyperbolic midpoint
  std::size_t one_third_splits = 0;         ///< Chew's one-third splits (2 vertices each)
  std::size_t lopping_vertices = 0;         ///< vertices inserted by corner lopping
  std::size_t frame_vertices = 0;           ///< out-of-domain frame around the convex hull (see the manual)
  std::size_t removals = 0;                 ///< circumcenters removed (Chew)
  std::size_t rejected_circumcenters = 0;   ///< circumcenters that encroached a segment (split instead)
  std::size_t operations = 0;               ///< insertions + removals
  std::size_t small_input_angles = 0;       ///< input corners with angle < pi/2
  std::size_t protected_faces = 0;          ///< poor faces left at small input angles (by design, thesis Fig 3.6)
  std::size_t unrefinable_faces = 0;        ///< poor faces whose Steiner point could not be inserted (rounding)
  std::size_t unsplittable_segments = 0;    ///< subsegments without a usable rounded split point (an inverted face
                                            ///< or a non-Delaunay edge in every candidate)
  std::size_t faces_failing_criteria = 0;   ///< in-domain faces that fail the criteria and are not protected
  std::size_t in_domain_faces = 0;
  double minimum_central_angle = 0;         ///< over in-domain faces (approximate, double)
  double minimum_central_angle_unprotected = 0; ///< same, ignoring the protected faces at small input angles
  double maximum_circumradius = 0;          ///< over in-domain faces (+inf if one is not compact)
  double h_star = 0;                        ///< Chew's h* (0 for Ruppert)
  double termination_margin = 0;            ///< Ruppert: 1 - rho(eps, alpha) rho(eps, pi/2); Chew: 2.3101 - h*
  bool termination_guaranteed = false;      ///< the theorem's hypothesis holds for the given parameters
  std::string termination_note;             ///< why (not)
  double seconds = 0;

  /// Steiner vertices in the output (frame excluded)
  std::size_t vertices_inserted() const { return final_vertices - initial_vertices - frame_vertices; }

  friend std::ostream& operator<<(std::ostream& os, const Mesh_statistics& s)
  {
    return os << "status=" << to_string(s.status) << " vertices=" << s.initial_vertices << "->" << s.final_vertices
              << " circumcenters=" << s.circumcenters_inserted << " offcenters=" << s.off_centers_inserted
              << " midpoint_splits=" << s.midpoint_splits << " one_third_splits=" << s.one_third_splits
              << " lopping=" << s.lopping_vertices << " frame=" << s.frame_vertices << " removals=" << s.removals
              << " rejected=" << s.rejected_circumcenters << " faces=" << s.in_domain_faces
              << " min_central_angle_deg=" << s.minimum_central_angle * 57.29577951308232
              << " (unprotected " << s.minimum_central_angle_unprotected * 57.29577951308232 << ")"
              << " max_circumradius=" << s.maximum_circumradius << " protected=" << s.protected_faces
              << " failing=" << s.faces_failing_criteria << " unrefinable=" << s.unrefinable_faces << " unsplittable=" << s.unsplittable_segments << " h*=" << s.h_star
              << " termination_guaranteed=" << s.termination_guaranteed << " (" << s.termination_note << ")"
              << " time=" << s.seconds << "s";
  }
};

} // namespace Hyperbolic_mesh_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_MESH_2_MESH_TYPES_H
