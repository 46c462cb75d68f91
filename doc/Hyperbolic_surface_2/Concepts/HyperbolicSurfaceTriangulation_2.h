/*!
\ingroup PkgHyperbolicSurface2Concepts
\cgalConcept

A closed orientable triangulated surface with a hyperbolic metric given by its edge lengths, together with the
local geometry every algorithm on such a surface needs, computed once and in numerically stable forms.

The combinatorics is a model of `FaceGraph` (`Triangle_mesh`): closed, connected, every face a triangle. Faces
may use a vertex more than once and two vertices may be joined by several edges (a Delta-complex: intrinsic
triangulations produced by edge flips are of this kind). Lifted points and isometries are the types of
`CGAL::Poincare_disk_traits_2<K>`, so that its exact predicates apply to lifted configurations without
conversion.

\cgalHasModel `CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<TriangleMesh, EdgeLengthMap, Traits>`

Produced by `CGAL::Discrete_Ricci_flow` (the uniformization metric of a mesh), read by
`CGAL::Surface_shortest_words` (shortest paths, loops and words) and by `CGAL::Hyperbolic_surface_mesh_2`
(Delaunay triangulation and refinement of the surface).
*/
class HyperbolicSurfaceTriangulation_2
{
public:
  /// \name Types
  /// @{
  /// a model of `FaceGraph`
  typedef unspecified_type Triangle_mesh;
  /// `CGAL::Poincare_disk_traits_2<K>`
  typedef unspecified_type Geom_traits;
  /// `Geom_traits::Point_2`: a point of the Poincare disk
  typedef unspecified_type Point_2;
  /// `CGAL::Poincare_disk_isometry_2<K>`
  typedef unspecified_type Isometry_2;
  typedef unspecified_type vertex_descriptor;
  typedef unspecified_type halfedge_descriptor;
  typedef unspecified_type edge_descriptor;
  typedef unspecified_type face_descriptor;
  /// the lift of a face: its halfedges `h[0] = halfedge(f)`, `h[1]`, `h[2]` and the positions `z[i]` of
  /// `source(h[i])` in the disk, counterclockwise, with the face's hyperbolic barycentre at the origin;
  /// `source_point(h)`, `target_point(h)` and `index(h)` for a halfedge of the face
  typedef unspecified_type Face_chart;
  /// one face of a development: its chart, the isometry `to_frame` from the chart to the current frame, and
  /// the frame index
  typedef unspecified_type Development_step;
  /// @}

  /// \name Combinatorics and metric
  /// @{
  const Triangle_mesh& mesh() const;
  /// the hyperbolic length of an edge
  double length(halfedge_descriptor h) const;
  /// the genus g >= 2 (Euler characteristic 2 - 2g)
  int genus() const;
  /// @}

  /// \name Angles, curvature and area (from the lengths alone)
  /// @{
  /// the corner angle at `target(h)` in `face(h)`, by the half-angle formula
  double angle_at_target(halfedge_descriptor h) const;
  /// the corner angle opposite to `h` in `face(h)`
  double angle_opposite(halfedge_descriptor h) const;
  /// the angle sum at `v`; `angle_defect(v)` is 2 pi minus it, `max_angle_defect()` the largest |defect|
  double angle_sum(vertex_descriptor v) const;
  double angle_defect(vertex_descriptor v) const;
  double max_angle_defect() const;
  /// the area of a face and of the surface (4 pi (g - 1) for a smooth metric)
  double face_area(face_descriptor f) const;
  double area() const;
  /// whether the edge of `h` is intrinsically Delaunay (opposite angles sum to at most pi)
  bool is_delaunay(halfedge_descriptor h) const;
  /// @}

  /// \name Charts, transitions and developments
  /// @{
  /// the chart of a face (its lift near the origin)
  Face_chart chart(face_descriptor f) const;
  /// the isometry from the chart of `face(h)` to the chart of `face(opposite(h))`
  Isometry_2 transition(halfedge_descriptor h) const;
  /// the apex of `face(opposite(h))` when `source(h)` and `target(h)` are lifted at `zs` and `zt`
  Point_2 neighbor_apex(halfedge_descriptor h, const Point_2& zs, const Point_2& zt) const;
  /// the development of a corridor of faces as a chain of charts, re-centred so that no lifted point is
  /// farther than `recenter_distance` from the origin of its frame
  std::vector<Development_step> develop(face_descriptor start, const std::vector<halfedge_descriptor>& crossed,
                                        double recenter_distance) const;
  /// @}
};
