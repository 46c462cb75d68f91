/*!
\ingroup PkgHyperbolicMesh2Concepts
\cgalConcept

What the refiners of this package (`CGAL::refine_hyperbolic_Ruppert_mesh_2()`, `CGAL::refine_hyperbolic_Chew_mesh_2()`)
need from their criteria. It refines CGAL's `MeshingCriteria_2` (so the same object also drives CGAL's own
`refine_Delaunay_mesh_2()`), with three additions: an *exact* classification of a triangle given by its three
points, the size bound the refiner needs for its own computations (Chew's h*, Ruppert's termination report), and a
compile-time *refinement policy* that selects the algorithm.

Badness: `CGAL::Mesh_2::NOT_BAD` (the face meets the criteria), `CGAL::Mesh_2::BAD` (a shape violation: the central
angle of the shortest edge is too small; such faces may be left inside lopped corners, thesis Fig. 3.6),
`CGAL::Mesh_2::IMPERATIVELY_BAD` (a size violation: the hyperbolic circumradius exceeds `epsilon()`; never left).
The refiner decides with `badness()` only, every time it pops a face and once more for every face at the end (the
status `SUCCESS` is this final check); the `Quality` and `Is_bad` of `MeshingCriteria_2` are used by CGAL's mesher.

The policy (`Refinement_policy`) is a tag type and is the whole difference between the algorithms at compile time:
- `CGAL::Hyperbolic_mesh_2::Ruppert_policy` (thesis Algorithm 6): the edge level splits every constrained edge
  encroached by a vertex (hyperbolic diametral disk) at its midpoint; the face level rejects a Steiner point that
  encroaches a constrained edge of its conflict zone or lies beyond it and splits those edges instead; optional
  off-centers (they need `sin2_half_alpha()` and `is_skinny()`); termination reported from `termination_margin()`.
- `CGAL::Hyperbolic_mesh_2::Chew_policy` (thesis Algorithm 5): no encroachment queue; a circumcenter beyond a
  constrained edge splits it (midpoint or thirds, from Chew's h*, which uses `epsilon()`) and the nearby free
  Steiner points are removed.

\cgalRefines `MeshingCriteria_2`

\cgalHasModel `CGAL::Hyperbolic_Ruppert_mesh_criteria_2<CDT>` (`Refinement_policy` = `Ruppert_policy`)
\cgalHasModel `CGAL::Hyperbolic_Chew_mesh_criteria_2<CDT>` (`Refinement_policy` = `Chew_policy`)
*/
class HyperbolicMeshRefinementCriteria_2
{
public:
  /// `CDT::Geom_traits`, a `Poincare_disk_traits_2<K>`
  typedef unspecified_type Geom_traits;
  typedef unspecified_type Point_2;
  typedef unspecified_type Face_handle;
  /// `Hyperbolic_mesh_2::Ruppert_policy` or `Hyperbolic_mesh_2::Chew_policy`
  typedef unspecified_type Refinement_policy;
  /// from `MeshingCriteria_2`: the (approximate) priority of a face in CGAL's mesher; `q1 < q2` if q1 goes first
  typedef unspecified_type Quality;
  /// from `MeshingCriteria_2`: `Mesh_2::Face_badness operator()(const Quality&)` and
  /// `Mesh_2::Face_badness operator()(const Face_handle&, Quality&)`
  typedef unspecified_type Is_bad;
  /// from `MeshingCriteria_2`
  Is_bad is_bad_object() const;

  /// the exact classification of the triangle pqr (counterclockwise, in the open disk); the same answer as
  /// `Is_bad` for the face with these vertices
  CGAL::Mesh_2::Face_badness badness(const Point_2& p, const Point_2& q, const Point_2& r) const;
  /// `badness()` of the three vertices of `f`
  CGAL::Mesh_2::Face_badness badness(Face_handle f) const;
  /// the maximum hyperbolic circumradius (+infinity if none)
  double epsilon() const;
  bool has_size_bound() const;
  /// one line for the verbose report
  std::string description() const;

  /// \name Ruppert_policy only
  /// @{
  /// sin^2(alpha/2), alpha the central-angle bound (off-centers)
  double sin2_half_alpha() const;
  /// the shape test alone, exact (off-centers)
  bool is_skinny(const Point_2& p, const Point_2& q, const Point_2& r) const;
  /// 1 - rho(epsilon, alpha) rho(epsilon, pi/2) (thesis Theorem 3.2: termination if > 0)
  double termination_margin() const;
  bool termination_guaranteed() const;
  /// @}
};
