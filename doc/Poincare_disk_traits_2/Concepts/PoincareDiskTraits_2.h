/*!
\ingroup PkgPoincareDiskTraits2Concepts
\cgalConcept

The geometric traits of the hyperbolic plane in the Poincare disk: points are `Point_2` of a CGAL kernel with
|z| < 1, and every predicate CGAL's 2D triangulation packages ask for has its hyperbolic meaning, decided exactly
(the sign of a polynomial in the Poincare coordinates: static filter, interval arithmetic, exact rational fallback):
- `Orientation_2` is the orientation of the Klein images (a geodesic is straight in the Klein model), and
  `Side_of_oriented_circle_2` the Euclidean in-circle test of the Poincare coordinates (hyperbolic circles,
  horocycles and hypercycles are Euclidean circles in the disk): with them CGAL's `Delaunay_triangulation_2`
  computes the hyperbolic Delaunay triangulation (**`DelaunayTriangulationTraits_2`**);
- `Intersect_2` and `Compute_squared_distance_2` intersect geodesic constraints in the Klein model
  (**`ConstrainedDelaunayTriangulationTraits_2`**, with `Exact_predicates_tag`);
- `Is_Delaunay_hyperbolic`, `Construct_hyperbolic_bisector_2`, `Construct_hyperbolic_circumcenter_2` (the Voronoi
  point), `Hyperbolic_segment_2` for CGAL's `Hyperbolic_Delaunay_triangulation_2`
  (**`HyperbolicDelaunayTriangulationTraits_2`**);
- `Construct_circumcenter_2`, `Construct_midpoint_2` (the hyperbolic ones), `Angle_2` (the hyperbolic
  diametral-disk encroachment test, not Thales), `Compute_area_2` for CGAL's `refine_Delaunay_mesh_2`
  (**`DelaunayMeshTraits_2`**, with the criteria of `Hyperbolic_mesh_2`).

Beyond CGAL's concepts (the hyperbolic functors): `Side_of_hyperbolic_diametral_circle_2`,
`Compare_hyperbolic_distance_2`, `Compare_central_angle_2`, `Compare_hyperbolic_circumradius_2`,
`Compute_hyperbolic_distance_2`, `Construct_hyperbolic_midpoint_2`, `Construct_hyperbolic_point_on_segment_2`,
`Construct_hyperbolic_segment_2`, `Construct_hyperbolic_circle_2`, `Construct_hyperbolic_circle_from_Euclidean_2`,
the model conversions (`Construct_Klein_point_2`, hyperboloid, upper half-plane) and the isometries
(`Isometry_2` = `Poincare_disk_isometry_2<K>`, `Construct_hyperbolic_translation_2`). Every public functor checks
its points and throws `CGAL::Poincare_disk_domain_error` for a point not in the open disk or not finite.

\cgalRefines `DelaunayTriangulationTraits_2`, `ConstrainedDelaunayTriangulationTraits_2`,
`HyperbolicDelaunayTriangulationTraits_2`, `DelaunayMeshTraits_2`

\cgalHasModel `CGAL::Poincare_disk_traits_2<Kernel>` (any CGAL kernel; exact predicates on double and on rational
coordinates)
*/
class PoincareDiskTraits_2
{
public:
  typedef unspecified_type Kernel;
  typedef unspecified_type FT;
  /// Poincare coordinates, |z| < 1
  typedef unspecified_type Point_2;
  /// a geodesic segment (circular arc orthogonal to the unit circle, or a piece of a diameter)
  typedef unspecified_type Hyperbolic_segment_2;
  /// `Poincare_disk_isometry_2<Kernel>`
  typedef unspecified_type Isometry_2;

  /// \name Predicates (exact)
  /// @{
  typedef unspecified_type Orientation_2;
  typedef unspecified_type Side_of_oriented_circle_2;
  typedef unspecified_type Is_Delaunay_hyperbolic;
  /// `(a, b, x)`: ON_BOUNDED_SIDE iff x is inside the hyperbolic diametral disk of ab
  typedef unspecified_type Side_of_hyperbolic_diametral_circle_2;
  /// `(p, q, r, s)`: compares d(p, q) with d(r, s)
  typedef unspecified_type Compare_hyperbolic_distance_2;
  /// `(p, q, r, sin2_half_theta)`: central angle of the shortest edge of pqr vs theta
  typedef unspecified_type Compare_central_angle_2;
  /// `(p, q, r, cosh2_bound)`: hyperbolic circumradius vs the bound
  typedef unspecified_type Compare_hyperbolic_circumradius_2;
  /// @}

  /// \name Constructions (rounded unless FT has exact square roots)
  /// @{
  typedef unspecified_type Construct_hyperbolic_circumcenter_2;
  typedef unspecified_type Construct_hyperbolic_midpoint_2;
  typedef unspecified_type Construct_hyperbolic_point_on_segment_2;
  typedef unspecified_type Construct_hyperbolic_segment_2;
  typedef unspecified_type Construct_hyperbolic_bisector_2;
  typedef unspecified_type Construct_hyperbolic_circle_2;
  typedef unspecified_type Compute_hyperbolic_distance_2;
  typedef unspecified_type Construct_Klein_point_2;
  typedef unspecified_type Construct_point_from_Klein_2;
  /// @}
};
