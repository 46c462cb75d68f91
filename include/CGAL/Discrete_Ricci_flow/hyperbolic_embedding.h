// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Embedding of the universal cover of a uniformized surface (thesis Section 2.3.1): greedy tree-cotree
// homotopy basis at a base vertex, cut to a topological disk, isometric layout of the fundamental domain in
// the Poincare disk (or the plane for a flat torus), deck transformations (holonomies of the basis loops),
// the relator, side pairings, a tiling of the disk by the group, and the flat-torus lattice parameter tau.
#ifndef CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H
#define CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H

#include <CGAL/Discrete_Ricci_flow/compute_metric.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_motions.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_multiprecision.h>
#include <CGAL/Discrete_Ricci_flow/internal/embedding_polish.h>
#include <CGAL/Hyperbolic_surface_2/disk_geometry.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hyperbolic_surface_2/Homotopy_basis.h>
#include <CGAL/Hyperbolic_surface_2/Hyperbolic_surface_triangulation.h>
#include <CGAL/IO/Poincare_disk_svg.h>
#include <CGAL/Poincare_disk_isometry_2.h>

#include <algorithm>
#include <complex>
#include <deque>
#include <functional>
#include <memory>
#include <limits>
#include <queue>
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
  - the homotopy basis is the layer's `CGAL::Hyperbolic_surface_2::Homotopy_basis` at the base vertex (greedy
    tree-cotree, loops x_1 .. x_2g sorted by length; `basis()`, `homotopy_basis()`): deck transformation i is
    the holonomy of loop i of that class, the same loop as generator i of `Surface_shortest_words`;
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
    1e-16 max_k cosh(translation length of the relator's partial product P_k) in every frame (turbine.off:
    1e-8 at best, cheese.off: 3e5; the manual's "Accuracy of the relator");
  - exact deck transformations (`deck_transformations_exact()`, on demand): the long-double ones converted
    exactly when their exact relator product is within 1e-10 of the identity, otherwise the same development
    in MPFR at a precision chosen from the measured condition, on the metric polished to that precision;
    `relator_defect_exact()` is their exact product's defect (<= 1.1e-12 on every closed demo mesh);
  - the relator: the boundary of the disk cut along the loops, read in the loops (`relator()`); the product of
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
  typedef CGAL::Hyperbolic_surface_2::Hyperbolic_surface_triangulation<Mesh, typename Metric::Edge_length_map> Surface;
  typedef CGAL::Hyperbolic_surface_2::Word Word;
  typedef CGAL::Hyperbolic_surface_2::Disk_geometry<internal::Long_kernel> Long_geometry;
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
    Builds the embedding (a copy of `metric` is kept, shared by copies of the embedding). `metric` must be a
    converged (or stagnated below 1e-9) metric of a closed surface with a hyperbolic background
    (genus >= 2) or a Euclidean background (genus 1), with zero target curvature everywhere (no cones).
    \throws CGAL::Invalid_metric_error, CGAL::Invalid_mesh_error, CGAL::Invalid_option_error otherwise.
  */
  explicit Hyperbolic_embedding(const Metric& metric, Vertex_index base = Vertex_index(0))
    : metric_ptr_(std::make_shared<const Metric>(metric)), metric_(*metric_ptr_), m_(metric_.intrinsic_mesh()),
      base_(base)
  {
    check_metric(metric);
    if(hyperbolic_) {
      surface_ = std::make_shared<const Surface>(metric_.hyperbolic_surface(
        CGAL::Hyperbolic_surface_2::parameters::require_smooth_metric(false)));
      std::vector<double> l(m_.number_of_edges());
      for(Edge_index e : m_.edges()) l[e] = metric_.length(e);
      const internal::Polished_lengths p = internal::polish_hyperbolic_lengths(m_, l);
      long_half_sinh_ = p.half_sinh;
      long_length_.resize(p.half_sinh.size());
      for(std::size_t e = 0; e < long_length_.size(); ++e) long_length_[e] = p.length(e);
      polish_before_ = double(p.max_curvature_before); polish_after_ = double(p.max_curvature_after);
      polish_steps_ = p.steps;
    }
    basis_ = std::make_shared<const Basis>(m_, base_, metric_.edge_length_map());
    root_ = m_.halfedge(base_); // target(root_) == base
    const std::array<internal::Cplx, 3> z = chart(m_.face(root_));
    const internal::Cplx zb = z[index_in_face(m_.next(root_))]; // source(next(root)) = base
    frame_ = hyperbolic_ ? internal::Motion::from(internal::Long_isometry::translation_to_origin(
                             internal::Long_kernel::Point_2(zb.real(), zb.imag())))
                         : internal::Motion::euclidean(1, -zb);
    for(const int l : basis_->relator()) relator_.push_back({std::size_t(std::abs(l) - 1), l > 0 ? 1 : -1});
    compute_holonomies();
    if(hyperbolic_) recentre();
    build_domain_cut();
    layout();
    compute_boundary();
  }

  /*!
    The base vertex, among `number_of_candidates` vertices spread over the index range (vertex 0 first), whose
    embedding has the smallest `relator_condition()`. The relator defect is about the rounding error times
    that condition (the relator's partial products amplify the errors by the distance of the
    relator polygon's corners from the origin), and the condition of the greedy relator varies by orders of
    magnitude with the base vertex (turbine.off: 1e8 to 6e12). Cost: `number_of_candidates` embeddings.
    \throws the exceptions of the constructor.
  */
  static Vertex_index best_conditioned_base_vertex(const Metric& metric, std::size_t number_of_candidates = 16)
  {
    const std::size_t n = metric.intrinsic_mesh().number_of_vertices();
    const std::size_t k = (std::max)(std::size_t(1), (std::min)(number_of_candidates, n));
    Vertex_index best(0);
    double best_condition = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < k; ++i) {
      const Vertex_index v(static_cast<typename Vertex_index::size_type>((i * n) / k));
      const double c = Hyperbolic_embedding(metric, v).relator_condition();
      if(c < best_condition) { best_condition = c; best = v; }
    }
    return best;
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

  /// translation length of the deck transformation of loop i: 2 acosh(|trace| / 2) (H^2), |period| (E^2)
  double translation_length(std::size_t i) const
  {
    if(!hyperbolic_) return double(std::abs(hol_[i].b));
    return 2 * std::acosh((std::max)(1.0, absolute_trace(i) / 2));
  }

  /// |trace| of the normalized deck transformation of loop i (> 2 for a hyperbolic translation)
  double absolute_trace(std::size_t i) const
  {
    if(!hyperbolic_) return 2.0;
    return double(std::sqrt(hol_[i].h.squared_normalized_trace()));
  }

  /// the relator: the boundary of the cut disk read as letters (loop index, +1 or -1): `basis().relator()`
  const std::vector<std::pair<std::size_t, int> >& relator() const { return relator_; }

  /// the product of the deck transformations along `relator()` (the identity up to rounding)
  Isometry relator_product() const { return internal::to_double(product(relator_word()).h); }

  /// distance of the relator product to the identity as a user measures it: the product of the returned
  /// `deck_transformations()` (double) in the order of `relator()`, multiplied in double, normalized, and the
  /// largest entry difference to the identity matrix up to sign (`Poincare_disk_isometry_2::distance_to`);
  /// +infinity if the product has a non-positive determinant. For the torus |rotation - 1| + |translation|
  /// of the product of the periods' translations (long double).
  double relator_defect() const
  {
    if(!hyperbolic_) return double(product(relator_word()).defect());
    std::vector<Isometry> d;
    try { d = deck_transformations(); } catch(const CGAL::Numerical_error&) { return std::numeric_limits<double>::infinity(); }
    Isometry m;
    for(const int l : relator_word()) m = m * (l > 0 ? d[l - 1] : d[-l - 1].inverse());
    const double det = CGAL::to_double(m.determinant());
    if(!(det > 0) || !std::isfinite(det)) return std::numeric_limits<double>::infinity();
    return m.distance_to(Isometry());
  }

  /// the same distance for the product of the long-double holonomies, multiplied in long double (what the
  /// embedding's own computation achieves before the rounding of the deck transformations to double)
  double relator_defect_long_double() const { return double(product(relator_word()).defect()); }

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
      const double ck = double(m.h.alpha_real() * m.h.alpha_real() + m.h.alpha_imag() * m.h.alpha_imag() +
                               m.h.beta_real() * m.h.beta_real() + m.h.beta_imag() * m.h.beta_imag());
      if(!std::isfinite(ck)) return std::numeric_limits<double>::infinity();
      c = (std::max)(c, ck);
    }
    return c;
  }

  /// The relator polygon: the 4g lifts of the base vertex P_k = w_1 ... w_k (b), k = 0 .. 4g-1, for the letters
  /// w_k of `relator()` and the base vertex's lift b = `base_point()`.
  std::vector<Complex> relator_polygon() const { return polygon(relator_word()); }

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
  double canonical_relator_defect() const { return double(canonical_product().defect()); }
  /// the canonical fundamental polygon: the 4g lifts of the base vertex P_k = w_1 ... w_k (b) along
  /// a1 b1 a1^-1 b1^-1 ..., b = `base_point()`
  std::vector<Complex> canonical_polygon() const
  {
    std::vector<Complex> p;
    internal::Motion m = internal::Motion::identity(hyperbolic_);
    const std::vector<internal::Motion> c = canonical_motions();
    for(const int l : canonical_relator()) {
      const internal::Cplx z = m(base_point_);
      p.push_back(Complex(double(z.real()), double(z.imag())));
      m = m * (l > 0 ? c[l - 1] : c[-l - 1].inverse());
    }
    return p;
  }

  /// position of `target(h)` in the copy of `face(h)` laid out in the fundamental domain
  Complex corner_position(Halfedge_index h) const { return Complex(double(pos_[h].real()), double(pos_[h].imag())); }
  Point_2 corner_point(Halfedge_index h) const { return Point_2(double(pos_[h].real()), double(pos_[h].imag())); }

  /// true if the edge is on the cut (on the boundary of the fundamental domain)
  bool is_cut(Edge_index e) const { return cut_[e] != 0; }

  /// the boundary of the fundamental domain: cut halfedges with the domain on their left, in
  /// counterclockwise order; vertex k of the polygon is `corner_position(domain_boundary()[k])`
  const std::vector<Halfedge_index>& domain_boundary() const { return boundary_; }

  /// the sides of the domain (maximal cut paths), each paired with its twin
  const std::vector<Side>& side_pairings() const { return sides_; }

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
    CGAL::Poincare_disk_svg_writer w(size_px, hyperbolic_ ? 1.0 : view_zoom(), 0, 0);
    if(hyperbolic_) w.add_unit_circle();
    const internal::Motion t = view_transform();
    for(Face_index f : m_.faces()) {
      const Halfedge_index h = m_.halfedge(f);
      std::vector<double> xy;
      for(Halfedge_index g : {h, m_.next(h), m_.prev(h)}) { const internal::Cplx z = t(pos_[g]); xy.push_back(double(z.real())); xy.push_back(double(z.imag())); }
      w.add_geodesic_polygon(xy, "#cfe0f5", "#7a8ea8", 0.3);
    }
    for(Halfedge_index h : boundary_) {
      const internal::Cplx a = t(pos_[m_.prev(h)]), b = t(pos_[h]);
      w.add_geodesic_segment(double(a.real()), double(a.imag()), double(b.real()), double(b.imag()), "#c00", 1.6);
    }
    const internal::Cplx o = t(internal::Cplx(0));
    w.add_point(double(o.real()), double(o.imag()), "#000", 3);
    w.write(filename);
  }

  /// SVG picture of the tiling: the images of the fundamental domain under the group elements given by
  /// words of length <= `max_word_length` in the side pairings (breadth-first from the domain across its sides,
  /// duplicates removed; tiles smaller than about two pixels are drawn but not expanded; at most `max_tiles`).
  /// Returns the number of tiles drawn.
  std::size_t write_tiling_svg(const std::string& filename, int max_word_length = 3, double size_px = 900,
                               std::size_t max_tiles = 4000) const
  {
    CGAL::Poincare_disk_svg_writer w(size_px, hyperbolic_ ? 1.0 : view_zoom() / (1 + max_word_length), 0, 0);
    if(hyperbolic_) w.add_unit_circle();
    const internal::Motion view = view_transform();
    struct Node { internal::Motion g; int len; };
    std::deque<Node> queue;
    queue.push_back({internal::Motion::identity(hyperbolic_), 0});
    std::vector<internal::Cplx> seen;
    const internal::Cplx probe = internal::Real(0.5) * pos_[m_.next(root_)];
    std::size_t drawn = 0;
    while(!queue.empty() && drawn < max_tiles) {
      const Node nd = queue.front(); queue.pop_front();
      const internal::Cplx c = view(nd.g(probe));
      bool dup = false;
      for(const internal::Cplx& s : seen) if(std::abs(s - c) < 1e-9) { dup = true; break; }
      if(dup) continue;
      seen.push_back(c);
      std::vector<double> xy;
      double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
      for(Halfedge_index h : boundary_) {
        const internal::Cplx zl = view(nd.g(pos_[h]));
        const double zx = double(zl.real()), zy = double(zl.imag());
        xy.push_back(zx); xy.push_back(zy);
        xmin = (std::min)(xmin, zx); xmax = (std::max)(xmax, zx);
        ymin = (std::min)(ymin, zy); ymax = (std::max)(ymax, zy);
      }
      const double t = double(nd.len) / (max_word_length + 1);
      w.add_geodesic_polygon(xy, CGAL::Poincare_disk_svg_writer::color_ramp(0.15 + 0.7 * t), "#333",
                             nd.len == 0 ? 1.2 : 0.4, nd.len == 0 ? 0.9 : 0.6);
      ++drawn;
      const bool tiny = hyperbolic_ && (xmax - xmin) + (ymax - ymin) < 4.0 / size_px;
      if(nd.len >= max_word_length || tiny) continue;
      for(const internal::Motion& p : pairings_) queue.push_back({nd.g * p, nd.len + 1});
    }
    w.write(filename);
    return drawn;
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

  double len(Halfedge_index h) const { return metric_.length(h); }

  int index_in_face(Halfedge_index g) const
  {
    const Halfedge_index h0 = m_.halfedge(m_.face(g));
    return g == h0 ? 0 : (g == m_.next(h0) ? 1 : 2);
  }

  // ---------------------------------------------------------------- charts and transitions
  // the chart of f: z[i] is the position of source(h_i), h_0 = halfedge(f), h_{i+1} = next(h_i)
  std::array<internal::Cplx, 3> chart(Face_index f) const
  {
    if(hyperbolic_) { // the layer's chart construction, in long double on the polished lengths
      const Halfedge_index h = m_.halfedge(f);
      const std::array<internal::Long_kernel::Point_2, 3> c = Long_geometry::triangle_chart(
        long_length_[m_.edge(h)], long_length_[m_.edge(m_.next(h))], long_length_[m_.edge(m_.prev(h))]);
      std::array<internal::Cplx, 3> z;
      for(int i = 0; i < 3; ++i) z[i] = internal::Cplx(c[i].x(), c[i].y());
      return z;
    }
    const Halfedge_index h = m_.halfedge(f);
    return internal::euclidean_chart(len(h), len(m_.next(h)), len(m_.prev(h)));
  }

  // maps the chart of face(h) to the chart of face(opposite(h))
  internal::Motion transition(Halfedge_index h) const
  {
    const Halfedge_index o = m_.opposite(h);
    const std::array<internal::Cplx, 3> cf = chart(m_.face(h)), cg = chart(m_.face(o));
    const int ih = index_in_face(h), io = index_in_face(o);
    if(hyperbolic_) { // the layer's transition (Surface::transition) in long double
      auto P = [](const internal::Cplx& z) { return internal::Long_kernel::Point_2(z.real(), z.imag()); };
      return internal::Motion::from(Long_geometry::isometry_from_pairs(P(cf[ih]), P(cf[(ih + 1) % 3]), P(cg[(io + 1) % 3]), P(cg[io])));
    }
    // source(h) = target(o), target(h) = source(o)
    return internal::euclidean_from_pairs(cf[ih], cf[(ih + 1) % 3], cg[(io + 1) % 3], cg[io]);
  }

  // ---------------------------------------------------------------- holonomies of the loops
  // Developing along a loop: the current corner c (a halfedge entering the current vertex, in the current face);
  // rotating counterclockwise to the next corner crosses edge(next(c)) into face(opposite(next(c))). M maps the
  // chart of the current face to the chart of the root face's first copy.
  // The same walk in every precision: `M` is a motion type (internal::Motion, internal::Mp_isometry) starting
  // at `identity`, `transition_of(h)` its transition across h.
  template <class M_type, class Transition>
  M_type develop_with(const std::vector<Halfedge_index>& loop, const M_type& identity, const Transition& transition_of) const
  {
    M_type M = identity;
    Halfedge_index c = root_;
    const std::size_t guard_max = m_.number_of_halfedges();
    auto rotate = [&]() {
      const Halfedge_index g = m_.next(c);
      M = M * transition_of(g).inverse();
      c = m_.opposite(g);
    };
    for(Halfedge_index h : loop) {
      std::size_t guard = 0;
      while(m_.next(c) != h) {
        rotate();
        if(++guard > guard_max) internal::throw_mesh_error("develop: invalid loop");
      }
      c = h;
    }
    std::size_t guard = 0;
    while(c != root_) {
      rotate();
      if(++guard > guard_max) internal::throw_mesh_error("develop: invalid loop");
    }
    return M;
  }

  internal::Motion develop(const std::vector<Halfedge_index>& loop) const
  {
    const internal::Motion M = develop_with(loop, internal::Motion::identity(hyperbolic_),
                                            [this](Halfedge_index h) { return transition(h); });
    return (frame_ * M * frame_.inverse()).normalized();
  }

  void compute_holonomies()
  {
    hol_.clear();
    for(std::size_t i = 0; i < number_of_generators(); ++i) hol_.push_back(develop(basis_->loop(i)));
  }

  // The frame of the deck transformations: the origin is moved to the point c that minimizes
  //   F(c) = max over the generators g_i and the relator's partial products P_k of cosh d(c, g c)
  // (the squared norm of the matrix in the frame centred at c, which bounds the amplification of rounding
  // errors when the matrices are multiplied: see relator_condition()), by a pattern search from the base
  // vertex (step halved from 4 down to 1e-3 in hyperbolic distance, at most 2000 evaluations). The holonomies
  // and the frame are conjugated by the translation T taking c to the origin; the base vertex's lift is then
  // at T(0) (`base_point()`).
  internal::Real frame_cost(const std::vector<internal::Motion>& elements, const internal::Cplx& c) const
  {
    const internal::Motion T = internal::Motion::from(
      internal::Long_isometry::translation_to_origin(internal::Long_kernel::Point_2(c.real(), c.imag())));
    const internal::Motion Ti = T.inverse();
    internal::Real worst = 1;
    for(const internal::Motion& g : elements) {
      const Long_isometry n = (T * g * Ti).h.normalized();
      const internal::Real q = n.alpha_real() * n.alpha_real() + n.alpha_imag() * n.alpha_imag() +
                               n.beta_real() * n.beta_real() + n.beta_imag() * n.beta_imag();
      if(!std::isfinite(q)) return std::numeric_limits<internal::Real>::infinity();
      worst = (std::max)(worst, q);
    }
    return worst;
  }

  void recentre()
  {
    std::vector<internal::Motion> elements(hol_.begin(), hol_.end());
    internal::Motion m = internal::Motion::identity(true);
    for(const int l : relator_word()) { m = (m * letter(l)).normalized(); elements.push_back(m); }
    internal::Cplx c(0);
    internal::Real best = frame_cost(elements, c);
    int evaluations = 0;
    for(internal::Real step = 4; step > internal::Real(1e-3) && evaluations < 2000; ) {
      bool moved = false;
      // the 8 points at hyperbolic distance `step` from c
      const internal::Motion from_c = internal::Motion::from(
        internal::Long_isometry::translation_from_origin(internal::Long_kernel::Point_2(c.real(), c.imag())));
      for(int k = 0; k < 8 && evaluations < 2000; ++k) {
        const internal::Real t = std::tanh(step / 2), phi = k * std::acos(internal::Real(-1)) / 4;
        const internal::Cplx q = from_c(internal::Cplx(t * std::cos(phi), t * std::sin(phi)));
        if(!(std::abs(q) < 1)) continue;
        const internal::Real f = frame_cost(elements, q);
        ++evaluations;
        if(f < best) { best = f; c = q; moved = true; break; }
      }
      if(!moved) step /= 2;
    }
    if(c == internal::Cplx(0)) return;
    const internal::Motion T = internal::Motion::from(
      internal::Long_isometry::translation_to_origin(internal::Long_kernel::Point_2(c.real(), c.imag())));
    for(internal::Motion& h : hol_) h = (T * h * T.inverse()).normalized();
    frame_ = T * frame_;
    base_point_ = T(internal::Cplx(0));
  }

  // ---------------------------------------------------------------- exact (multiprecision) deck transformations
  struct Exact_data
  {
    unsigned bits = 64;
    double max_curvature = 0, log10_condition = 0, defect = std::numeric_limits<double>::infinity();
    int polish_steps = 0, attempts = 0;
    std::vector<Exact_isometry> deck;
  };

  const Exact_data& exact_data() const
  {
    if(!exact_) exact_ = std::make_shared<const Exact_data>(compute_exact());
    return *exact_;
  }

  double exact_relator_defect(const std::vector<Exact_isometry>& d) const
  {
    Exact_isometry m;
    for(const int l : relator_word()) m = m * (l > 0 ? d[l - 1] : d[-l - 1].inverse());
    return internal::exact_defect(m);
  }

  Exact_data compute_exact() const
  {
    const double target = 1e-10; // 100 times below the embedding's goal of 1e-8
    Exact_data r;
    r.bits = 64; r.max_curvature = polish_after_; r.polish_steps = polish_steps_; r.attempts = 1;
    for(const internal::Motion& h : hol_) r.deck.push_back(internal::to_exact_isometry(h.h.normalized()));
    r.defect = exact_relator_defect(r.deck);
    r.log10_condition = std::log10(relator_condition());
    if(r.defect <= target) return r;
    double condition = relator_condition(); // +infinity when long double could not measure it
    unsigned bits = 128;
    for(int attempt = 2; attempt <= 6 && bits <= 4096; ++attempt) {
      Exact_data t = develop_multiprecision(bits, condition);
      t.attempts = attempt;
      if(t.defect <= r.defect || !(r.defect <= target)) r = t;
      if(t.defect <= target) break;
      const double needed = 64 + t.log10_condition * 3.3219280948873623 + 32;
      bits = (std::max)(bits + 64, 32 * unsigned(std::ceil(needed / 32)));
      condition = std::pow(10.0, t.log10_condition);
    }
    return r;
  }

  // the development of every loop in MPFR at `bits` bits on the metric polished to that precision, in the frame
  // of the long-double development (frame_ is an exact isometry in any precision)
  Exact_data develop_multiprecision(unsigned bits, double condition) const
  {
    typedef internal::Mp_real R;
    typedef CGAL::Hyperbolic_surface_2::Disk_geometry<internal::Mp_kernel> Mp_geometry;
    typedef internal::Mp_kernel::Point_2 P;
    const internal::Mp_precision_guard guard(bits);
    Exact_data r;
    r.bits = bits;
    // the long-double polished metric (exactly) as the start
    std::vector<R> x0(long_half_sinh_.size());
    for(std::size_t e = 0; e < x0.size(); ++e) x0[e] = R(long_half_sinh_[e]);
    using std::ldexp;
    R k_target = ldexp(R(1), -int(bits) + 16);
    if(std::isfinite(condition) && condition > 0 && R(1e-12 / condition) > k_target) k_target = R(1e-12 / condition);
    const internal::Polished_lengths_t<R> pl = internal::polish_hyperbolic_lengths<R>(m_, x0, 16, k_target);
    r.max_curvature = pl.max_curvature_after.template convert_to<double>();
    r.polish_steps = pl.steps;
    std::vector<R> L(x0.size()); // lengths 2 asinh(x), on the edges of the charts used
    std::vector<char> has_length(x0.size(), 0);
    auto length_of = [&](Halfedge_index h) -> const R& {
      const std::size_t e = m_.edge(h);
      if(!has_length[e]) { L[e] = pl.length(e); has_length[e] = 1; }
      return L[e];
    };
    std::vector<std::array<P, 3> > charts(m_.number_of_faces());
    std::vector<char> has_chart(m_.number_of_faces(), 0);
    auto chart_of = [&](Face_index f) -> const std::array<P, 3>& {
      if(!has_chart[f]) {
        const Halfedge_index h = m_.halfedge(f);
        charts[f] = Mp_geometry::triangle_chart(length_of(h), length_of(m_.next(h)), length_of(m_.prev(h)));
        has_chart[f] = 1;
      }
      return charts[f];
    };
    std::vector<internal::Mp_isometry> transitions(m_.number_of_halfedges());
    std::vector<char> has_transition(m_.number_of_halfedges(), 0);
    auto transition_of = [&](Halfedge_index h) -> const internal::Mp_isometry& {
      if(!has_transition[h]) { // as transition(h) in long double
        const Halfedge_index o = m_.opposite(h);
        const std::array<P, 3>& cf = chart_of(m_.face(h));
        const std::array<P, 3>& cg = chart_of(m_.face(o));
        const int ih = index_in_face(h), io = index_in_face(o);
        transitions[h] = Mp_geometry::isometry_from_pairs(cf[ih], cf[(ih + 1) % 3], cg[(io + 1) % 3], cg[io]);
        has_transition[h] = 1;
      }
      return transitions[h];
    };
    const internal::Mp_isometry F(R(frame_.h.alpha_real()), R(frame_.h.alpha_imag()), R(frame_.h.beta_real()), R(frame_.h.beta_imag()));
    std::vector<internal::Mp_isometry> hol;
    for(std::size_t i = 0; i < number_of_generators(); ++i)
      hol.push_back((F * develop_with(basis_->loop(i), internal::Mp_isometry(), transition_of) * F.inverse()).normalized());
    // the condition: max over the partial products of |alpha|^2 + |beta|^2 = cosh d(0, P_k 0)
    internal::Mp_isometry m;
    R c = 1;
    for(const int l : relator_word()) {
      m = (m * (l > 0 ? hol[l - 1] : hol[-l - 1].inverse())).normalized();
      const R q = m.alpha_real() * m.alpha_real() + m.alpha_imag() * m.alpha_imag() + m.beta_real() * m.beta_real() + m.beta_imag() * m.beta_imag();
      if(q > c) c = q;
    }
    r.log10_condition = boost::multiprecision::log10(c).template convert_to<double>();
    for(const internal::Mp_isometry& h : hol) r.deck.push_back(internal::to_exact_isometry(h));
    r.defect = exact_relator_defect(r.deck);
    return r;
  }

  Word relator_word() const { return basis_->relator(); }
  internal::Motion letter(int l) const { return l > 0 ? hol_[l - 1] : hol_[-l - 1].inverse(); }
  internal::Motion product(const Word& w) const
  {
    internal::Motion m = internal::Motion::identity(hyperbolic_);
    for(const int l : w) m = m * letter(l);
    return m;
  }
  internal::Motion product_in_loops(const Word& w) const { return product(w).normalized(); }
  std::vector<Complex> polygon(const Word& w) const
  {
    std::vector<Complex> p;
    internal::Motion m = internal::Motion::identity(hyperbolic_);
    for(const int l : w) {
      const internal::Cplx z = m(base_point_);
      p.push_back(Complex(double(z.real()), double(z.imag())));
      m = m * letter(l);
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
  internal::Motion canonical_product() const
  {
    const std::vector<internal::Motion> c = canonical_motions();
    internal::Motion m = internal::Motion::identity(hyperbolic_);
    for(const int l : canonical_relator()) m = m * (l > 0 ? c[l - 1] : c[-l - 1].inverse());
    return m;
  }

  // ---------------------------------------------------------------- a compact cut for the layout
  // The domain D is grown from the root face by a shortest-path tree of the dual graph (each step weighted by
  // a third of the two perimeters), so that every face of D is close to the base. The cut is the set of edges
  // not crossed by that dual tree, pruned of its dangling trees.
  void build_domain_cut()
  {
    const std::size_t nf = m_.number_of_faces(), ne = m_.number_of_edges();
    std::vector<double> perim(nf, 0), fd(nf, std::numeric_limits<double>::infinity());
    for(Face_index f : m_.faces()) {
      const Halfedge_index h = m_.halfedge(f);
      perim[f] = len(h) + len(m_.next(h)) + len(m_.prev(h));
    }
    std::vector<char> crossed(ne, 0), done(nf, 0);
    std::vector<Halfedge_index> via(nf, Mesh::null_halfedge());
    typedef std::pair<double, std::size_t> QE;
    std::priority_queue<QE, std::vector<QE>, std::greater<QE> > pq;
    const Face_index f0 = m_.face(root_);
    fd[f0] = 0; pq.push({0.0, std::size_t(f0)});
    while(!pq.empty()) {
      const QE top = pq.top(); pq.pop();
      const Face_index f(static_cast<typename Face_index::size_type>(top.second));
      if(done[f]) continue;
      done[f] = 1;
      if(via[f] != Mesh::null_halfedge()) crossed[m_.edge(via[f])] = 1;
      const Halfedge_index h0 = m_.halfedge(f);
      for(Halfedge_index h : {h0, m_.next(h0), m_.prev(h0)}) {
        const Face_index g = m_.face(m_.opposite(h));
        const double d = fd[f] + (perim[f] + perim[g]) / 6;
        if(!done[g] && d < fd[g]) { fd[g] = d; via[g] = h; pq.push({d, std::size_t(g)}); }
      }
    }
    cut_.assign(ne, 0);
    std::vector<std::size_t> degree(m_.number_of_vertices(), 0);
    for(Edge_index e : m_.edges())
      if(!crossed[e]) { cut_[e] = 1; ++degree[m_.vertex(e, 0)]; ++degree[m_.vertex(e, 1)]; }
    // prune: remove cut edges at vertices of cut-degree 1, repeatedly (a loop edge counts twice)
    std::vector<Vertex_index> stack;
    for(Vertex_index v : m_.vertices()) if(degree[v] == 1) stack.push_back(v);
    while(!stack.empty()) {
      const Vertex_index v = stack.back(); stack.pop_back();
      if(degree[v] != 1) continue;
      for(Halfedge_index h : CGAL::halfedges_around_source(v, m_)) {
        if(!cut_[m_.edge(h)]) continue;
        cut_[m_.edge(h)] = 0;
        --degree[v];
        const Vertex_index w = m_.target(h);
        if(--degree[w] == 1) stack.push_back(w);
        break;
      }
    }
  }

  // ---------------------------------------------------------------- layout of the disk D, chart by chart
  void layout()
  {
    pos_.assign(m_.number_of_halfedges(), internal::Cplx(0));
    place_.assign(m_.number_of_faces(), internal::Motion::identity(hyperbolic_));
    std::vector<char> placed(m_.number_of_faces(), 0);
    const Face_index f0 = m_.face(root_);
    place_[f0] = frame_;
    placed[f0] = 1;
    std::deque<Face_index> queue(1, f0);
    while(!queue.empty()) {
      const Face_index f = queue.front(); queue.pop_front();
      const Halfedge_index h0 = m_.halfedge(f);
      const std::array<internal::Cplx, 3> z = chart(f);
      const Halfedge_index hs[3] = {h0, m_.next(h0), m_.prev(h0)};
      for(int i = 0; i < 3; ++i) pos_[hs[i]] = place_[f](z[(i + 1) % 3]); // target(h_i) = source(h_{i+1})
      for(Halfedge_index h : hs) {
        if(cut_[m_.edge(h)]) continue;
        const Face_index g = m_.face(m_.opposite(h));
        if(placed[g]) continue;
        place_[g] = place_[f] * transition(h).inverse();
        placed[g] = 1;
        queue.push_back(g);
      }
    }
    for(Face_index f : m_.faces())
      if(!placed[f]) internal::throw_mesh_error("the cut does not leave a disk (layout incomplete)");
  }

  // ---------------------------------------------------------------- boundary and sides
  // the face walk of the ribbon graph formed by the cut edges: from a cut halfedge h, rotate around target(h)
  // (crossing non-cut edges) to the next cut halfedge. For a cut graph this walks once around the disk.
  std::vector<Halfedge_index> boundary_walk(const std::vector<char>& cut) const
  {
    Halfedge_index start = Mesh::null_halfedge();
    for(Halfedge_index h : m_.halfedges()) if(cut[m_.edge(h)]) { start = h; break; }
    std::vector<Halfedge_index> walk;
    const std::size_t ncut = std::size_t(std::count(cut.begin(), cut.end(), char(1)));
    Halfedge_index h = start;
    do {
      walk.push_back(h);
      Halfedge_index g = m_.next(h);
      while(!cut[m_.edge(g)]) g = m_.next(m_.opposite(g));
      h = g;
      if(walk.size() > 2 * ncut) internal::throw_mesh_error("boundary walk does not close");
    } while(h != start);
    if(walk.size() != 2 * ncut) internal::throw_mesh_error("the cut graph does not bound a single disk");
    return walk;
  }

  void compute_boundary()
  {
    boundary_ = boundary_walk(cut_);
    std::vector<std::size_t> index_of(m_.number_of_halfedges(), std::size_t(-1));
    for(std::size_t k = 0; k < boundary_.size(); ++k) index_of[boundary_[k]] = k;
    const std::size_t nb = boundary_.size();
    auto twin_index = [&](std::size_t k) { return index_of[m_.opposite(boundary_[k])]; };
    // a side starts at k if the twin of k-1 is not the successor of the twin of k
    std::vector<char> starts(nb, 0);
    for(std::size_t k = 0; k < nb; ++k) starts[k] = twin_index((k + nb - 1) % nb) != (twin_index(k) + 1) % nb;
    sides_.clear();
    std::vector<std::size_t> side_of(nb, 0);
    std::size_t k0 = 0;
    while(k0 < nb && !starts[k0]) ++k0;
    if(k0 == nb) k0 = 0;
    for(std::size_t t = 0; t < nb; ++t) {
      const std::size_t k = (k0 + t) % nb;
      if(starts[k] || sides_.empty()) sides_.push_back(Side());
      sides_.back().halfedges.push_back(boundary_[k]);
      side_of[k] = sides_.size() - 1;
    }
    pairings_.clear();
    for(std::size_t s = 0; s < sides_.size(); ++s) {
      const Halfedge_index g = sides_[s].halfedges.front(), o = m_.opposite(g);
      sides_[s].twin = side_of[index_of[o]];
      // the copy of face(o) adjacent to the copy of face(g) across g, from the domain's copy of face(o)
      const internal::Motion p = (place_[m_.face(g)] * transition(g).inverse() * place_[m_.face(o)].inverse()).normalized();
      pairings_.push_back(p);
      if(hyperbolic_) sides_[s].pairing = p.h;
      else sides_[s].translation = Complex(double(p.b.real()), double(p.b.imag()));
    }
  }

  // the isometry moving the (Euclidean) mean of the domain's corners to the origin, for pictures
  internal::Motion view_transform() const
  {
    internal::Cplx c(0);
    for(const internal::Cplx& z : pos_) c += z;
    c /= internal::Real(pos_.empty() ? 1 : pos_.size());
    if(!hyperbolic_) return internal::Motion::euclidean(1, -c);
    if(!(std::abs(c) < 1)) return internal::Motion::identity(true);
    return internal::Motion::from(internal::Long_isometry::translation_to_origin(internal::Long_kernel::Point_2(c.real(), c.imag())));
  }

  double view_zoom() const
  {
    double r = 1e-300;
    const internal::Motion t = view_transform();
    for(const internal::Cplx& z : pos_) r = (std::max)(r, double(std::abs(t(z))));
    return 0.9 / r;
  }

  std::shared_ptr<const Metric> metric_ptr_;
  const Metric& metric_;
  const Mesh& m_;
  Vertex_index base_;
  bool hyperbolic_ = true;
  std::shared_ptr<const Surface> surface_;
  std::vector<internal::Real> long_length_, long_half_sinh_; // the polished metric: lengths, sinh(length / 2)
  double polish_before_ = 0, polish_after_ = 0;
  int polish_steps_ = 0;
  std::shared_ptr<const Basis> basis_;
  Halfedge_index root_;
  internal::Motion frame_;
  internal::Cplx base_point_ = internal::Cplx(0);
  std::vector<char> cut_;
  std::vector<internal::Cplx> pos_;
  std::vector<internal::Motion> place_, hol_, pairings_;
  std::vector<Halfedge_index> boundary_;
  std::vector<std::pair<std::size_t, int> > relator_;
  std::vector<Side> sides_;
  mutable std::shared_ptr<const Exact_data> exact_; // computed on demand (exact_data())
};

} // namespace Discrete_Ricci_flow
} // namespace CGAL

#endif // CGAL_DISCRETE_RICCI_FLOW_HYPERBOLIC_EMBEDDING_H
