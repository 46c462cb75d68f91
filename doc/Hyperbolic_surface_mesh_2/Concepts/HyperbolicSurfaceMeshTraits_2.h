/*!
\ingroup PkgHyperbolicSurfaceMesh2Concepts
\cgalConcept

The geometric traits of `CGAL::Hyperbolic_surface_mesh_2::Delaunay_triangulation_on_surface`: points of the
Poincare disk with double coordinates, the exact predicates that decide location, edge flips and the quality
criteria, and the constructions of Steiner points. Every predicate is evaluated on the lifts of one face (and
of the neighbour's apex) in a single chart.

\cgalHasModel `CGAL::Poincare_disk_traits_2<CGAL::Exact_predicates_inexact_constructions_kernel>`
*/
class HyperbolicSurfaceMeshTraits_2
{
public:
  /// a CGAL kernel with `FT = double`
  typedef unspecified_type Kernel;
  /// `Kernel::Point_2`: Poincare coordinates, |z| < 1
  typedef unspecified_type Point_2;

  /// `Orientation_2(p, q, r)`: LEFT_TURN iff r is left of the geodesic pq (Klein orientation); used by the
  /// walk, the flip validity and the checks
  typedef unspecified_type Orientation_2;
  /// `Side_of_oriented_circle_2(p, q, r, s)`: ON_POSITIVE_SIDE iff s is strictly inside the generalized
  /// circle through the counterclockwise p, q, r (the Euclidean in-circle of the Poincare coordinates, i.e. the
  /// side of the hyperboloid lift of s w.r.t. the plane through the lifts of p, q, r); the edge test
  typedef unspecified_type Side_of_oriented_circle_2;
  /// `Is_Delaunay_hyperbolic(p, q, r)`: true iff the circumcircle is compact
  typedef unspecified_type Is_Delaunay_hyperbolic;
  /// `Compare_hyperbolic_circumradius_2(p, q, r, cosh2_bound)`: the size criterion
  typedef unspecified_type Compare_hyperbolic_circumradius_2;
  /// `Compare_central_angle_2(p, q, r, sin2_half_theta)`: Ruppert's shape criterion
  typedef unspecified_type Compare_central_angle_2;
  /// `Construct_hyperbolic_circumcenter_2(p, q, r)`: the Steiner point (compact circumcircles only)
  typedef unspecified_type Construct_hyperbolic_circumcenter_2;

  Orientation_2 orientation_2_object() const;
  Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const;
  Is_Delaunay_hyperbolic is_Delaunay_hyperbolic_2_object() const;
  Compare_hyperbolic_circumradius_2 compare_hyperbolic_circumradius_2_object() const;
  Compare_central_angle_2 compare_central_angle_2_object() const;
  Construct_hyperbolic_circumcenter_2 construct_hyperbolic_circumcenter_2_object() const;
};
