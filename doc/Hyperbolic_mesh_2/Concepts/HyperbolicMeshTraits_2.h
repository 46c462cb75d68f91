/*!
\ingroup PkgHyperbolicMesh2Concepts
\cgalConcept

The geometric traits of the triangulation `CDT` refined by `CGAL::refine_hyperbolic_Ruppert_mesh_2()` and
`CGAL::refine_hyperbolic_Chew_mesh_2()` (`CDT::Geom_traits`). The triangulation itself is CGAL's
`Constrained_Delaunay_triangulation_2<Gt, Tds, Exact_predicates_tag>`, so `Gt` first of all models CGAL's
`ConstrainedDelaunayTriangulationTraits_2` with the Poincare-disk meaning of its predicates (geodesics straight in
the Klein model, the Euclidean in-circle test on Poincare coordinates). The refiners add the hyperbolic quality,
encroachment and Steiner-point constructions below; every decision is one of these exact predicates, every
Steiner point one of these (rounded) constructions. The criteria (`HyperbolicMeshRefinementCriteria_2`) use
`Compare_central_angle_2` and the circumradius polynomial of the traits' internal polynomials.

\cgalRefines `ConstrainedDelaunayTriangulationTraits_2`

\cgalHasModel `CGAL::Poincare_disk_traits_2<K>` (with `K::FT = double`, e.g. `Epick`)
*/
class HyperbolicMeshTraits_2
{
public:
  /// `K::Point_2`, Poincare coordinates, |z| < 1
  typedef unspecified_type Point_2;
  typedef unspecified_type FT;

  /// `Orientation_2(p, q, r)`: Klein orientation (side of the geodesic pq); also the CDT's
  typedef unspecified_type Orientation_2;
  /// `Side_of_oriented_circle_2(p, q, r, s)`: the CDT's in-circle test; also the refiner's exact test of the new
  /// edges from a rounded split point
  typedef unspecified_type Side_of_oriented_circle_2;
  /// `Is_Delaunay_hyperbolic(p, q, r)`: the circumcircle is compact (else the face has no hyperbolic
  /// circumcenter and its longest edge is split)
  typedef unspecified_type Is_Delaunay_hyperbolic;
  /// `Side_of_hyperbolic_diametral_circle_2(a, b, x)`: ON_BOUNDED_SIDE iff x encroaches the segment ab (inside its
  /// hyperbolic diametral disk: not the Thales angle test)
  typedef unspecified_type Side_of_hyperbolic_diametral_circle_2;
  /// `Compare_central_angle_2(p, q, r, sin2_half_alpha)`: Ruppert's shape criterion
  typedef unspecified_type Compare_central_angle_2;
  /// `Construct_hyperbolic_circumcenter_2(p, q, r)`: the Steiner point of a poor face (throws
  /// `CGAL::Poincare_disk_domain_error` if the circumcircle is not compact)
  typedef unspecified_type Construct_hyperbolic_circumcenter_2;
  /// `Construct_hyperbolic_midpoint_2(p, q)`: midpoint splits
  typedef unspecified_type Construct_hyperbolic_midpoint_2;
  /// `Construct_hyperbolic_point_on_segment_2(p, q, t)`: the point at distance t d(p, q) from p (corner lopping,
  /// Chew's one-third splits, off-centers)
  typedef unspecified_type Construct_hyperbolic_point_on_segment_2;

  Orientation_2 orientation_2_object() const;
  Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const;
  Is_Delaunay_hyperbolic is_Delaunay_hyperbolic_2_object() const;
  Side_of_hyperbolic_diametral_circle_2 side_of_hyperbolic_diametral_circle_2_object() const;
  Compare_central_angle_2 compare_central_angle_2_object() const;
  Construct_hyperbolic_circumcenter_2 construct_hyperbolic_circumcenter_2_object() const;
  Construct_hyperbolic_midpoint_2 construct_hyperbolic_midpoint_2_object() const;
  Construct_hyperbolic_point_on_segment_2 construct_hyperbolic_point_on_segment_2_object() const;
};
