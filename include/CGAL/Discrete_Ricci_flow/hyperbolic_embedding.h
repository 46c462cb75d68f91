// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Embedding of the universal cover of a uniformized surface (thesis Section 2.3.1): tree-cotree (greedy or compact)
// homotopy basis at a base vertex, cut to a topological disk, isometric layout of the fundamental domain in
// the Poincare disk (or the plane for a flat torus), deck transformations (holonomies of the basis loops),
// the relator, side pairings, a tiling of the disk by the group, and the flat-torus lattice parameter tau.
#ifndef CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H
#define CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H

#include <CGAL/Discrete_Ricci_flow/compute_metric.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_development.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_domain.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_exact.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_frame.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_motions.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_multiprecision.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_polish.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_svg.h>
#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hyperbolic_surface_2/Homotopy_basis.h>
#include <CGAL/Poincare_disk_isometry_2.h>

#include <algorithm>
#include <complex>
#include <initializer_list>
#include <memory>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Discrete_Ricci_flow {

/*!
  \ingroup PkgDiscreteRicciFlowRef
  The universal cover of a closed surface with a hyperbolic metric (genus >= 2) embedded in the Poincare disk,
  or of a flat torus (genus 1) embedded in the plane, computed from a `Discrete_metric` (thesis Section 2.3.1)
  with the shared surface layer `CGAL::Hyperbolic_surface_2`.

  Construction (cost O(n log n)):
  - the homotopy basis is the layer's `CGAL::Hyperbolic_surface_2::Homotopy_basis` at the base vertex (tree-cotree,
    loops x_1 .. x_2g sorted by length; `basis()`, `homotopy_basis()`), greedy by default: deck transformation
    i is the holonomy of loop i of that class, the same loop as generator i of `Surface_shortest_words`'
    solver with the same construction (`Surface_shortest_words::parameters::basis_construction`). The
    compact construction (`Basis_construction::COMPACT`) keeps the relator's partial products short, and with
    them the rounding error of the relator product (`best_conditioned()` chooses the base vertex and the
    construction);
  - the metric in long double: the lengths of `metric` have angle sums 2 pi only up to their rounding (max |K|
    about 1e-14, `input_max_curvature()`), and the relator amplifies that residual by its condition. A few
    Newton steps of vertex scaling with the angle sums in long double (systems solved in double) give lengths
    within about 1e-14 relative of the input whose angle sums are 2 pi to about 1e-18
    (`polished_max_curvature()`); the charts use them;
  - deck transformations: each loop is developed through the faces it turns around, with the layer's per-face
    charts (`Disk_geometry::triangle_chart()`: every chart has its face's barycentre at the origin) and
    transition isometries across the edges (`Disk_geometry::isometry_from_pairs()`), in long double
    (`Poincare_disk_isometry_2` over a long-double kernel); no point is ever laid out far from an origin;
  - the frame: the deck transformations are expressed in the frame of the chart of the face of
    `halfedge(base)`, moved so that the origin is the point c minimizing the largest cosh d(c, g c) over the
    generators g and the relator's partial products (a pattern search started at the base vertex): the
    matrices are then as small as they can be in any frame, which is what limits the accuracy of their
    products in double. The base vertex's lift is at `base_point()` (the origin only if that is optimal);
    they are rounded to double once, at the end. Their products in double have a floor of about
    1e-16 max_k cosh(translation length of the relator's partial product P_k) in every frame, which the
    rotation of the relator (below) makes as small as the basis allows, and `best_conditioned()` as small as
    16 base vertices and the two constructions of the basis allow (the manual's "Accuracy of the relator":
    double defect 3.5e-7 on turbine.off at vertex 0 with the greedy basis, 6.7e-10 for `best_conditioned()`;
    cheese.off not representable in double);
  - exact deck transformations (`deck_transformations_exact()`, on demand): the long-double ones converted
    exactly when their exact relator product is within 1e-10 of the identity, otherwise the same development
    in MPFR at a precision chosen from the measured condition, on the metric polished to that precision;
    `relator_defect_exact()` is their exact product's defect (<= 7.6e-12 on every closed demo mesh);
  - the relator: the boundary of the disk cut along the loops, read in the loops, starting at the corner (and
    in the direction) whose partial products have the smallest largest translation length (`relator()`, a
    cyclic rotation of `basis().relator()` or of its inverse); the product of
    the deck transformations in that order is the identity: `relator_defect()` measures it as a user does
    (double products of the returned matrices), `relator_defect_long_double()` before the rounding;
  - the canonical system a1, b1, ..., ag, bg (relator [a1, b1] ... [ag, bg]) from
    `Homotopy_basis::canonical_change()`: `canonical_deck_transformations()` are the products of the x_i's,
    `canonical_relator_defect()`, `canonical_polygon()`;
  - the fundamental domain D, for pictures and side pairings: the surface cut along a compact cut graph (the
    edges not crossed by a shortest-path tree of the dual graph grown from the base face), laid out chart by
    chart (`corner_position()`, `domain_boundary()`, `side_pairings()`, `write_tiling_svg()`).

  The deck transformation of a based loop maps the lift of its start to the lift of its end, and its
  translation length `2 acosh(|trace| / 2)` is the length of the closed geodesic freely homotopic to the loop.
*/
template <class Point_3>
class Hyperbolic_embedding
{
public:
  typedef Discrete_metric<Point_3> Metric;
  typedef typename Metric::Mesh Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Edge_index Edge_index;
  typedef typename Mesh::Face_index Face_index;
  typedef CGAL::Epick Kernel;
  typedef Kernel::Point_2 Point_2;
  /// SU(1,1) isometries of the Poincare disk in double precision
  typedef CGAL::Poincare_disk_isometry_2<Kernel> Isometry;
  typedef std::complex<double> Complex;
  typedef CGAL::Hyperbolic_surface_2::Homotopy_basis<Mesh> Basis;
  typedef CGAL::Hyperbolic_surface_2::Basis_construction Basis_construction;
  typedef CGAL::Hyperbolic_surface_2::Word Word;
  /// isometries in long double (the side pairings of a large domain have entries beyond double's range of
  /// accurate determinants)
  typedef CGAL::Poincare_disk_isometry_2<CGAL::Simple_cartesian<long double> > Long_isometry;
  /// exact isometries: entries `CGAL::Gmpzf` (dyadic rationals m 2^e with an arbitrary-length integer m), whose
  /// composition and inversion are exact (`deck_transformations_exact()`)
  typedef CGAL::Poincare_disk_isometry_2<CGAL::Simple_cartesian<CGAL::Gmpzf> > Exact_isometry;

  /// one side of the domain: the cut path as halfedges with D on their left, its twin side, and the map
  /// taking the twin copy onto this one (`pairing` for the hyperbolic background, the translation
  /// `translation` for the flat torus)
  struct Side
  {
    std::vector<Halfedge_index> halfedges; ///< consecutive halfedges along the boundary of D
    std::size_t twin = 0;                  ///< index of the paired side
    Long_isometry pairing;                 ///< maps the twin's copy onto this side's copy (hyperbolic)
    Complex translation;                   ///< the same for the flat torus (z -> z + translation)
  };

  /*!
    Builds the embedding (a copy of `metric` is kept, shared by copies of the embedding) with the homotopy
    basis at `base` built by `construction`. `metric` must be a converged (or stagnated below 1e-9) metric of a
    closed surface with a hyperbolic background (genus >= 2) or a Euclidean background (genus 1), with zero
    target curvature everywhere (no cones).
    \throws CGAL::Invalid_metric_error, CGAL::Invalid_mesh_error, CGAL::Invalid_option_error otherwise.
  */
  explicit Hyperbolic_embedding(const Metric& metric, Vertex_index base = Vertex_index(0),
                                Basis_construction construction = Basis_construction::GREEDY)
    : metric_ptr_(std::make_shared<const Metric>(metric)), metric_(*metric_ptr_), m_(metric_.intrinsic_mesh()),
      base_(base)
  {
    check_metric(metric);
    if(hyperbolic_) {
      std::vector<double> l(m_.number_of_edges());
      for(Edge_index e : m_.edges()) l[e] = metric_.length(e);
      const internal::Polished_lengths p = internal::polish_hyperbolic_lengths(m_, l);
      long_half_sinh_ = p.half_sinh;
      long_length_.resize(p.half_sinh.size());
      for(std::size_t e = 0; e < long_length_.size(); ++e) long_length_[e] = p.length(e);
      polish_before_ = double(p.max_curvature_before); polish_after_ = double(p.max_curvature_after);
      polish_steps_ = p.steps;
    }
    build(construction, true);
  }

  /*!
    The base vertex, among `number_of_candidates` vertices spread over the index range (vertex 0 first), whose
    embedding with the basis built by `construction` has the smallest `relator_condition()`. The relator
    defect is about the rounding error times that condition (the relator's partial products amplify the
    errors by the distance of the relator polygon's corners from the origin), and the condition of the greedy
    relator varies by orders of magnitude with the base vertex (turbine.off: 1e8 to 6e12). Cost: one embedding,
    and the basis and holonomies at each other candidate (the metric's check and long-double polish are
    shared, as in `best_conditioned()`).
    \throws the exceptions of the constructor.
  */
  static Vertex_index best_conditioned_base_vertex(const Metric& metric, std::size_t number_of_candidates = 16,
                                                   Basis_construction construction = Basis_construction::GREEDY)
  {
    return best_conditioned_(metric, number_of_candidates, {construction}).base_vertex();
  }

  /*!
    The embedding with the smallest `relator_condition()` among those at `number_of_candidates` base vertices
    spread over the index range (vertex 0 first), each with the greedy and the compact basis (the greedy one
    first; the first minimum is kept): the embedding whose deck transformations are the most accurate in
    double for their relator (the manual's "Accuracy of the relator": on turbine.off, genus 11, the user's
    relator defect in double goes from 3.5e-7 at base vertex 0 with the greedy basis to 7e-10). Cost: one
    embedding, the bases and holonomies of the other candidates (they share the metric's check and long-double
    polish), and the fundamental domain of the chosen one: turbine.off, 16 candidates, 1.4 s against 0.13 s
    for one embedding.
    \throws the exceptions of the constructor.
  */
  static Hyperbolic_embedding best_conditioned(const Metric& metric, std::size_t number_of_candidates = 16)
  {
    return best_conditioned_(metric, number_of_candidates, {Basis_construction::GREEDY, Basis_construction::COMPACT});
  }

  /// the metric (the embedding's copy) and its intrinsic mesh, whose halfedges the loops refer to
  const Metric& metric() const { return metric_; }
  const Mesh& mesh() const { return m_; }
  Vertex_index base_vertex() const { return base_; }
  long genus() const { return metric_.genus(); }
  std::size_t number_of_generators() const { return basis_->number_of_generators(); }
  /// the layer's homotopy basis on `mesh()` (loop i is deck transformation i)
  const Basis& basis() const { return *basis_; }

  /// the 2g loops of the homotopy basis (`basis().loop(i)`): halfedges of `mesh()`, from `base_vertex()`
  std::vector<std::vector<Halfedge_index> > homotopy_basis() const
  {
    std::vector<std::vector<Halfedge_index> > r;
    for(std::size_t i = 0; i < number_of_generators(); ++i) r.push_back(basis_->loop(i));
    return r;
  }

  /// the length of loop i in the metric (at least its translation length)
  double loop_length(std::size_t i) const
  {
    double s = 0;
    for(Halfedge_index h : basis_->loop(i)) s += metric_.length(h);
    return s;
  }

  /// the deck transformation of loop i (hyperbolic background)
  Isometry deck_transformation(std::size_t i) const
  {
    if(!hyperbolic_) internal::throw_option_error("deck_transformation(): the flat torus has periods(), not isometries");
    return internal::to_double(hol_[i].h);
  }
  /// the deck transformations of the 2g loops as SU(1,1) isometries (hyperbolic background only)
  std::vector<Isometry> deck_transformations() const
  {
    std::vector<Isometry> r;
    for(std::size_t i = 0; i < hol_.size(); ++i) r.push_back(deck_transformation(i));
    return r;
  }

  /// translation length of the deck transformation of loop i: 2 acosh(|trace| / 2) (H^2), |period| (E^2);
  /// throws as `absolute_trace()`
  double translation_length(std::size_t i) const
  {
    if(!hyperbolic_) return double(std::abs(hol_[i].b));
    return 2 * std::acosh((std::max)(1.0, absolute_trace(i) / 2));
  }

  /// |trace| of the normalized deck transformation of loop i (> 2 for a hyperbolic translation).
  /// \throws CGAL::Numerical_error if the long-double holonomy of the loop is not finite (a loop so long that
  /// the normalization of its matrix fails, e.g. 134 units on cheese.off's compact basis;
  /// `deck_transformations_exact()` has it)
  double absolute_trace(std::size_t i) const
  {
    if(!hyperbolic_) return 2.0;
    const double t = double(std::sqrt(hol_[i].h.squared_normalized_trace()));
    if(!std::isfinite(t))
      throw CGAL::Numerical_error("Hyperbolic_embedding: the long-double deck transformation of loop " + std::to_string(i) +
                                  " is not finite (the loop is " + std::to_string(basis_->loop_length(i)) +
                                  " long); deck_transformations_exact() has it");
    return t;
  }

  /// the relator: the boundary of the cut disk read as letters (loop index, +1 or -1): `basis().relator()`, and
  /// in the hyperbolic background the cyclic rotation of it or of its inverse (the same relation) whose partial
  /// products have the smallest largest translation length: no frame takes the squared norms of the partial
  /// products below cosh of that length, which bounds the rounding floor of the product in double (turbine.off,
  /// base vertex 0: condition 7e10 -> 7e7, double defect 6e-3 -> 5e-7; the manual's "Accuracy of the relator")
  const std::vector<std::pair<std::size_t, int> >& relator() const { return relator_; }

  /// the product of the deck transformations along `relator()` (the identity up to rounding)
  Isometry relator_product() const { return internal::to_double(product(relator_word()).h); }

  /// distance of the relator product to the identity as a user measures it: the product of the returned
  /// `deck_transformations()` (double) in the order of `relator()`, multiplied in double, normalized, and the
  /// largest entry difference to the identity matrix up to sign (`Poincare_disk_isometry_2::distance_to`);
  /// +infinity if the product has a non-positive determinant. For the torus |rotation - 1| + |translation| /
  /// (the longer period's length) of the product of the periods' translations (long double): relative, so that
  /// it does not depend on the mesh's scale (before 2026-12-07 the translation was absolute: about 1e137 for a
  /// torus of size 1e150).
  double relator_defect() const
  {
    if(!hyperbolic_) return defect(product(relator_word()));
    std::vector<Isometry> d;
    try { d = deck_transformations(); } catch(const CGAL::Numerical_error&) { return std::numeric_limits<double>::infinity(); }
    const Isometry m = internal::word_product(d, relator_word(), Isometry());
    const double det = CGAL::to_double(m.determinant());
    if(!(det > 0) || !std::isfinite(det)) return std::numeric_limits<double>::infinity();
    return m.distance_to(Isometry());
  }

  /// the same distance for the product of the long-double holonomies, multiplied in long double (what the
  /// embedding's own computation achieves before the rounding of the deck transformations to double)
  double relator_defect_long_double() const { return defect(product(relator_word())); }

  /*!
    The deck transformations of the 2g loops as exact isometries (hyperbolic background), in the frame of
    `deck_transformations()`, accurate enough for their relator product to be the identity to 1e-10
    (`relator_defect_exact()`): the double matrices cannot be (their floor is about 1e-16 times
    `relator_condition()`, see the manual's "Accuracy of the relator"). The precision is chosen from the
    conditioning (`exact_precision()`):
    - the long-double development, converted exactly, when the exact product of those is within 1e-10 of
      the identity (64 bits);
    - otherwise an MPFR development of the same charts and transitions (`Disk_geometry` over MPFR numbers) at
      b bits, on the metric polished to that precision (angle sums in MPFR, Newton systems in double as
      iterative refinement) until max |K| <= max(2^-(b - 16), 1e-12 / condition); b starts at 128 and grows to
      64 + log2(condition) + 32 bits (condition = max_k cosh d(0, P_k 0) over the relator's partial products,
      measured in MPFR) and by at least 64 bits per retry while the defect is above 1e-10 (at most 6 rungs,
      4096 bits); the values are then exact dyadic numbers.
    Computed on the first call of one of the `*_exact` functions (not thread-safe: call one before sharing
    the embedding between threads). Cost on the demo meshes: see the manual.
  */
  std::vector<Exact_isometry> deck_transformations_exact() const
  {
    if(!hyperbolic_) internal::throw_option_error("deck_transformations_exact(): the flat torus has periods(), not isometries");
    return exact_data().deck;
  }
  /// the distance to the identity of the exact product of `deck_transformations_exact()` in the order of
  /// `relator()` (the largest entry difference of the normalized matrix to +-I, evaluated in double from the
  /// exact product: about 1e-16 absolute); hyperbolic background
  double relator_defect_exact() const
  {
    if(!hyperbolic_) internal::throw_option_error("relator_defect_exact(): hyperbolic background only");
    return exact_data().defect;
  }
  /// the number of bits of the development behind `deck_transformations_exact()` (64: long double)
  unsigned exact_precision() const { return exact_data().bits; }
  /// max |K| of the metric that development used (the long-double polish at 64 bits)
  double exact_polished_max_curvature() const { return exact_data().max_curvature; }
  /// log10 of max_k cosh d(0, P_k 0) over the relator's partial products, measured at `exact_precision()`
  /// (finite where `relator_condition()` overflows long double's determinant)
  double exact_relator_condition_log10() const { return exact_data().log10_condition; }
  /// the number of precision rungs tried (1: long double sufficed)
  int exact_attempts() const { return exact_data().attempts; }

  /// max |2 pi - angle sum| of the metric as given and after the long-double polish of the lengths that the
  /// charts use (hyperbolic background; see the class description), and the number of polish steps
  double input_max_curvature() const { return polish_before_; }
  double polished_max_curvature() const { return polish_after_; }
  int polish_steps() const { return polish_steps_; }

  /// the conditioning of the relator product: max_k cosh d(0, P_k(0)) over the partial products P_k of
  /// `relator()` in the frame of the deck transformations (the squared norm |alpha|^2 + |beta|^2 of the
  /// matrices). Rounding errors are amplified by it: the measured `relator_defect()` is 1e-16 to 3e-13 times
  /// this value on the demo meshes, and no frame makes it smaller than cosh of the largest
  /// translation length of the partial products.
  double relator_condition() const
  {
    double c = 1;
    internal::Motion m = internal::Motion::identity(hyperbolic_);
    for(const int l : relator_word()) {
      m = (m * letter(l)).normalized();
      if(!hyperbolic_) continue;
      const double ck = double(internal::squared_norm(m.h));
      if(!std::isfinite(ck)) return std::numeric_limits<double>::infinity();
      c = (std::max)(c, ck);
    }
    return c;
  }

  /// The relator polygon: the 4g lifts of the base vertex P_k = w_1 ... w_k (b), k = 0 .. 4g-1, for the letters
  /// w_k of `relator()` and the base vertex's lift b = `base_point()`.
  std::vector<Complex> relator_polygon() const { return polygon(hol_, relator_word()); }

  /// the lift of the base vertex in the frame of the deck transformations (see the class description)
  Complex base_point() const { return Complex(double(base_point_.real()), double(base_point_.imag())); }

  /// the canonical generators a1, b1, ..., ag, bg as words in the loops (`Homotopy_basis::canonical_change()`)
  const std::vector<Word>& canonical_words() const { return basis_->canonical_change().new_in_old; }
  /// their deck transformations (products of the x_i's deck transformations), hyperbolic background
  std::vector<Isometry> canonical_deck_transformations() const
  {
    std::vector<Isometry> r;
    for(const Word& w : canonical_words()) r.push_back(internal::to_double(product_in_loops(w).h));
    return r;
  }
  /// the defect of [a1, b1] ... [ag, bg] evaluated on `canonical_deck_transformations()`
  double canonical_relator_defect() const { return defect(canonical_product()); }
  /// the canonical fundamental polygon: the 4g lifts of the base vertex P_k = w_1 ... w_k (b) along
  /// a1 b1 a1^-1 b1^-1 ..., b = `base_point()`
  std::vector<Complex> canonical_polygon() const { return polygon(canonical_motions(), canonical_relator()); }

  /// position of `target(h)` in the copy of `face(h)` laid out in the fundamental domain
  Complex corner_position(Halfedge_index h) const { return domain_.corner(h); }
  Point_2 corner_point(Halfedge_index h) const { const Complex z = domain_.corner(h); return Point_2(z.real(), z.imag()); }

  /// true if the edge is on the cut (on the boundary of the fundamental domain)
  bool is_cut(Edge_index e) const { return domain_.is_cut(e); }

  /// the boundary of the fundamental domain: cut halfedges with the domain on their left, in
  /// counterclockwise order; vertex k of the polygon is `corner_position(domain_boundary()[k])`
  const std::vector<Halfedge_index>& domain_boundary() const { return domain_.boundary(); }

  /// the sides of the domain (maximal cut paths), each paired with its twin
  const std::vector<Side>& side_pairings() const { return domain_.sides(); }

  /// the flat torus only: the two periods (translations of the two loops)
  std::pair<Complex, Complex> periods() const
  {
    if(hyperbolic_ || hol_.size() != 2) internal::throw_option_error("periods() is for the flat torus");
    const internal::Cplx p0 = hol_[0].b, p1 = hol_[1].b;
    return {Complex(double(p0.real()), double(p0.imag())), Complex(double(p1.real()), double(p1.imag()))};
  }

  /// the lattice parameter tau = period_2 / period_1 reduced to the fundamental region of SL(2,Z)
  /// (Im tau > 0, |Re tau| <= 1/2, |tau| >= 1)
  Complex lattice_parameter() const
  {
    const auto p = periods();
    Complex tau = p.second / p.first;
    if(tau.imag() < 0) tau = -tau;
    for(int it = 0; it < 1000; ++it) {
      tau = Complex(tau.real() - std::floor(tau.real() + 0.5), tau.imag());
      if(std::norm(tau) < 1 - 1e-14) tau = -1.0 / tau;
      else break;
    }
    return tau;
  }

  /// SVG picture of the fundamental domain: triangles and the cut in red
  void write_fundamental_domain_svg(const std::string& filename, double size_px = 900) const
  {
    internal::write_fundamental_domain_svg(m_, domain_, filename, size_px);
  }

  /// SVG picture of the tiling: the images of the fundamental domain under the group elements given by
  /// words of length <= `max_word_length` in the side pairings (breadth-first from the domain across its sides,
  /// duplicates removed; tiles smaller than about two pixels are drawn but not expanded; at most `max_tiles`).
  /// Returns the number of tiles drawn.
  std::size_t write_tiling_svg(const std::string& filename, int max_word_length = 3, double size_px = 900,
                               std::size_t max_tiles = 4000) const
  {
    return internal::write_tiling_svg(m_, domain_, filename, max_word_length, size_px, max_tiles);
  }

private:
  void check_metric(const Metric& metric)
  {
    hyperbolic_ = metric.background_geometry() == Background_geometry::HYPERBOLIC;
    if(metric.background_geometry() == Background_geometry::SPHERICAL)
      internal::throw_metric_error("no embedding for the spherical background (see spherical_uniformization())");
    if(!CGAL::is_closed(m_)) internal::throw_mesh_error("the embedding needs a closed surface");
    if(std::size_t(base_) >= m_.number_of_vertices()) internal::throw_option_error("invalid base vertex");
    for(double k : metric.target_curvatures())
      if(k != 0) internal::throw_metric_error("the embedding needs zero target curvature at every vertex (no cone points)");
    const long g = metric.genus();
    if(hyperbolic_ && g < 2) internal::throw_mesh_error("a hyperbolic embedding needs genus >= 2");
    if(!hyperbolic_ && g != 1) internal::throw_mesh_error("a Euclidean embedding needs genus 1");
    if(!metric.converged() && !(metric.statistics().status == Flow_status::STAGNATED &&
                                metric.statistics().max_curvature_error < 1e-9))
      internal::throw_metric_error("the metric did not converge");
  }

  typedef internal::Fundamental_domain<Mesh, Side> Domain;

  // the face charts and their transitions (a view on the metric and the polished lengths)
  internal::Face_charts<Metric> charts() const { return internal::Face_charts<Metric>(metric_, hyperbolic_, long_length_); }

  // ---------------------------------------------------------------- holonomies of the loops
  internal::Motion develop(const std::vector<Halfedge_index>& loop) const
  {
    const internal::Face_charts<Metric> c = charts();
    const internal::Motion M = internal::develop_loop(m_, root_, loop, internal::Motion::identity(hyperbolic_),
                                                      [&c](Halfedge_index h) { return c.transition(h); });
    return (frame_ * M * frame_.inverse()).normalized();
  }

  void compute_holonomies()
  {
    hol_.clear();
    for(std::size_t i = 0; i < number_of_generators(); ++i) hol_.push_back(develop(basis_->loop(i)));
  }

  // the embedding of `polished`'s metric with the basis at `base` built by `construction`: the metric's check
  // and its long-double polish (which do not depend on the basis) are taken from `polished`; the fundamental
  // domain is laid out only if `with_domain` (the candidates of best_conditioned_() need the relator only)
  Hyperbolic_embedding(const Hyperbolic_embedding& polished, Vertex_index base, Basis_construction construction,
                       bool with_domain)
    : metric_ptr_(polished.metric_ptr_), metric_(*metric_ptr_), m_(metric_.intrinsic_mesh()), base_(base),
      hyperbolic_(polished.hyperbolic_), long_length_(polished.long_length_), long_half_sinh_(polished.long_half_sinh_),
      polish_before_(polished.polish_before_), polish_after_(polished.polish_after_), polish_steps_(polished.polish_steps_)
  {
    build(construction, with_domain);
  }

  // the basis, the holonomies of its loops in their frame, the relator and the fundamental domain
  void build(Basis_construction construction, bool with_domain)
  {
    basis_ = std::make_shared<const Basis>(m_, base_, metric_.edge_length_map(), construction);
    root_ = m_.halfedge(base_); // target(root_) == base
    const std::array<internal::Cplx, 3> z = charts().chart(m_.face(root_));
    const internal::Cplx zb = z[internal::index_in_face(m_, m_.next(root_))]; // source(next(root)) = base
    frame_ = hyperbolic_ ? internal::Motion::translation_to_origin(zb) : internal::Motion::euclidean(1, -zb);
    relator_word_ = basis_->relator();
    compute_holonomies();
    if(hyperbolic_) {
      relator_word_ = internal::best_relator_rotation(hol_, relator_word_);
      recentre();
    }
    relator_.clear();
    for(const int l : relator_word_) relator_.push_back({std::size_t(std::abs(l) - 1), l > 0 ? 1 : -1});
    if(with_domain) domain_ = Domain(m_, root_, frame_, charts(), [this](Halfedge_index h) { return metric_.length(h); });
  }

  // the candidates share the check and the polish of the metric (the embedding at vertex 0 with the first
  // construction); the chosen one is built again with its fundamental domain
  static Hyperbolic_embedding best_conditioned_(const Metric& metric, std::size_t number_of_candidates,
                                                std::initializer_list<Basis_construction> constructions)
  {
    const std::size_t n = metric.intrinsic_mesh().number_of_vertices();
    const std::size_t k = (std::max)(std::size_t(1), (std::min)(number_of_candidates, n));
    const Hyperbolic_embedding first(metric, Vertex_index(0), *constructions.begin());
    Vertex_index best_base(0);
    Basis_construction best_construction = *constructions.begin();
    double best_condition = first.relator_condition();
    for(std::size_t i = 0; i < k; ++i) {
      const Vertex_index v(static_cast<typename Vertex_index::size_type>((i * n) / k));
      for(const Basis_construction c : constructions) {
        if(i == 0 && c == *constructions.begin()) continue; // `first`
        const double condition = Hyperbolic_embedding(first, v, c, false).relator_condition();
        if(condition < best_condition) { best_condition = condition; best_base = v; best_construction = c; }
      }
    }
    if(best_base == Vertex_index(0) && best_construction == *constructions.begin()) return first;
    return Hyperbolic_embedding(first, best_base, best_construction, true);
  }

  // the frame of the deck transformations (internal::frame_centre()): the generators and the relator's partial
  // products move the points near the new origin least
  void recentre()
  {
    std::vector<internal::Motion> elements(hol_.begin(), hol_.end());
    internal::Motion m = internal::Motion::identity(true);
    for(const int l : relator_word()) { m = (m * letter(l)).normalized(); elements.push_back(m); }
    const internal::Cplx c = internal::frame_centre(elements);
    if(c == internal::Cplx(0)) return;
    const internal::Motion T = internal::Motion::translation_to_origin(c);
    for(internal::Motion& h : hol_) h = (T * h * T.inverse()).normalized();
    frame_ = T * frame_;
    base_point_ = T(internal::Cplx(0));
  }

  // ---------------------------------------------------------------- exact (multiprecision) deck transformations
  const internal::Exact_data& exact_data() const
  {
    if(!exact_)
      exact_ = std::make_shared<const internal::Exact_data>(
        internal::Exact_deck_transformations<Mesh, Basis>(m_, *basis_, relator_word_, root_, frame_, long_half_sinh_)
          .compute(hol_, relator_condition(), polish_after_, polish_steps_));
    return *exact_;
  }

  const Word& relator_word() const { return relator_word_; }
  internal::Motion letter(int l) const { return internal::letter(hol_, l); }
  // the product of the letters of w over the generators g (the deck transformations by default)
  internal::Motion product(const Word& w) const { return product(hol_, w); }
  // the distance of m to the identity (internal::Motion::defect()); for the flat torus with the translation
  // measured in units of the longer period
  double defect(const internal::Motion& m) const
  {
    if(hyperbolic_ || hol_.size() != 2) return double(m.defect());
    const internal::Real scale = (std::max)(std::abs(hol_[0].b), std::abs(hol_[1].b));
    if(!(scale > 0) || !std::isfinite(scale)) return std::numeric_limits<double>::infinity();
    return double(internal::Motion::euclidean(m.a, m.b / scale).defect());
  }
  internal::Motion product(const std::vector<internal::Motion>& g, const Word& w) const
  {
    return internal::word_product(g, w, internal::Motion::identity(hyperbolic_));
  }
  internal::Motion product_in_loops(const Word& w) const { return product(w).normalized(); }
  // the lifts of the base vertex P_k = w_1 ... w_k (b) along the word w over the generators g
  std::vector<Complex> polygon(const std::vector<internal::Motion>& g, const Word& w) const
  {
    std::vector<Complex> p;
    internal::Motion m = internal::Motion::identity(hyperbolic_);
    for(const int l : w) {
      const internal::Cplx z = m(base_point_);
      p.push_back(Complex(double(z.real()), double(z.imag())));
      m = m * internal::letter(g, l);
    }
    return p;
  }
  static Word canonical_relator_of(std::size_t g)
  {
    Word r;
    for(int k = 0; k < int(g); ++k) { const int a = 2 * k + 1, b = 2 * k + 2; r.insert(r.end(), {a, b, -a, -b}); }
    return r;
  }
  Word canonical_relator() const { return canonical_relator_of(number_of_generators() / 2); }
  std::vector<internal::Motion> canonical_motions() const
  {
    std::vector<internal::Motion> c;
    for(const Word& w : canonical_words()) c.push_back(product_in_loops(w));
    return c;
  }
  internal::Motion canonical_product() const { return product(canonical_motions(), canonical_relator()); }

  std::shared_ptr<const Metric> metric_ptr_;
  const Metric& metric_;
  const Mesh& m_;
  Vertex_index base_;
  bool hyperbolic_ = true;
  std::vector<internal::Real> long_length_, long_half_sinh_; // the polished metric: lengths, sinh(length / 2)
  double polish_before_ = 0, polish_after_ = 0;
  int polish_steps_ = 0;
  std::shared_ptr<const Basis> basis_;
  Halfedge_index root_;
  internal::Motion frame_;
  internal::Cplx base_point_ = internal::Cplx(0);
  std::vector<internal::Motion> hol_;
  Word relator_word_; // basis().relator(), rotated (hyperbolic background: internal::best_relator_rotation())
  std::vector<std::pair<std::size_t, int> > relator_;
  Domain domain_; // the fundamental domain for pictures and side pairings
  mutable std::shared_ptr<const internal::Exact_data> exact_; // computed on demand (exact_data())
};

} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H
