// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Words of loops in pi_1(S, p) with respect to a canonical system of loops (thesis Algorithm 4).
#ifndef CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_WORD_SOLVER_H
#define CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_WORD_SOLVER_H

#include <CGAL/Surface_shortest_words/Hyperbolic_surface.h>
#include <CGAL/Surface_shortest_words/shortest_homotopic_path.h>
#include <CGAL/Surface_shortest_words/internal/words.h>
#include <CGAL/Surface_shortest_words/internal/word_geodesic.h>
#include <CGAL/Hyperbolic_surface_2/Homotopy_basis.h>
#include <boost/property_map/function_property_map.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <set>
#include <sstream>
#include <type_traits>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_shortest_words {
namespace internal {
// halfedge -> int (absent: -1): a vector by index for Surface_mesh, a hash map for other graphs
template <class TriangleMesh>
class Halfedge_int_map
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor H;
  std::unordered_map<H, int> m_;
public:
  explicit Halfedge_int_map(const TriangleMesh&) {}
  void clear() { m_.clear(); }
  void set(H h, int v) { m_[h] = v; }
  int get(H h) const { auto it = m_.find(h); return it == m_.end() ? -1 : it->second; }
};
template <class P>
class Halfedge_int_map<CGAL::Surface_mesh<P> >
{
  typedef typename CGAL::Surface_mesh<P>::Halfedge_index H;
  std::vector<int> v_;
public:
  explicit Halfedge_int_map(const CGAL::Surface_mesh<P>& m) : v_(m.number_of_halfedges() + m.number_of_removed_halfedges(), -1) {}
  void clear() { std::fill(v_.begin(), v_.end(), -1); }
  void set(H h, int v) { v_.at(std::size_t(h)) = v; }
  int get(H h) const { return std::size_t(h) < v_.size() ? v_[std::size_t(h)] : -1; }
};
// a set of vertices: a vector of flags by index for Surface_mesh, a hash set for other graphs
template <class TriangleMesh>
class Vertex_flags
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor V;
  std::unordered_set<V> s_;
public:
  explicit Vertex_flags(const TriangleMesh&) {}
  void clear() { s_.clear(); }
  void set(V v) { s_.insert(v); }
  bool get(V v) const { return s_.count(v) > 0; }
};
template <class P>
class Vertex_flags<CGAL::Surface_mesh<P> >
{
  typedef typename CGAL::Surface_mesh<P>::Vertex_index V;
  std::vector<char> f_;
public:
  explicit Vertex_flags(const CGAL::Surface_mesh<P>& m) : f_(m.number_of_vertices() + m.number_of_removed_vertices(), 0) {}
  void clear() { std::fill(f_.begin(), f_.end(), char(0)); }
  void set(V v) { f_.at(std::size_t(v)) = 1; }
  bool get(V v) const { return std::size_t(v) < f_.size() && f_[std::size_t(v)] != 0; }
};
} // namespace internal

/// \ingroup PkgSurfaceShortestWordsRef
/// Thrown when the given loops are not a canonical system of loops through the base vertex (an
/// `CGAL::Invalid_input_error` of the common hierarchy).
class Invalid_generators_error : public CGAL::Invalid_input_error
{
public:
  explicit Invalid_generators_error(const std::string& w) : CGAL::Invalid_input_error(w) {}
};

/// \ingroup PkgSurfaceShortestWordsRef
/// A word in the generators a1, b1, ..., ag, bg: letter +(i+1) is generator i (a_{i/2+1} for even i,
/// b_{i/2+1} for odd i), -(i+1) its inverse.
typedef std::vector<int> Word;

/// \ingroup PkgSurfaceShortestWordsRef
/// "a1 b1 a1^-1 ..." ("1" for the empty word)
inline std::string to_string(const Word& w)
{
  if(w.empty()) return "1";
  std::ostringstream os;
  for(std::size_t i = 0; i < w.size(); ++i) {
    const int g = std::abs(w[i]) - 1;
    os << (i ? " " : "") << (g % 2 == 0 ? "a" : "b") << (g / 2 + 1) << (w[i] < 0 ? "^-1" : "");
  }
  return os.str();
}

/// \ingroup PkgSurfaceShortestWordsRef
/// the word as labels in the convention of CGAL's `Surface_mesh_topology::Polygonal_schema_with_combinatorial_map`
/// ("a1", "-a1" for the inverse), usable with `Path_on_surface::push_back_by_label`
inline std::vector<std::string> to_labels(const Word& w)
{
  std::vector<std::string> r;
  for(int l : w) {
    const int g = std::abs(l) - 1;
    r.push_back(std::string(l < 0 ? "-" : "") + (g % 2 == 0 ? "a" : "b") + std::to_string(g / 2 + 1));
  }
  return r;
}

/// \ingroup PkgSurfaceShortestWordsRef
/// Options of `Shortest_word_solver` as a struct. Deprecated: use the named parameters
/// (`Surface_shortest_words::parameters::use_geometry`, `shorten_generators`, `make_canonical`,
/// `max_lift_distance`, `vertex_snap`, CGAL's `callback`); kept for existing callers.
struct Shortest_word_options
{
  /// also compute the shortest loop through the base point in the class of the loop (Algorithm 2); the word
  /// does not depend on it
  bool use_geometry = true;
  /// shorten the generators at construction (their lengths and paths are then available)
  bool shorten_generators = true;
  /// for the computed basis: turn it into a canonical system by cut and paste on its relator
  bool make_canonical = true;
  /// for the computed basis: how the layer's `Homotopy_basis` builds it (greedy by default; with the same
  /// construction, base vertex and lengths, generator i is loop i of `Discrete_Ricci_flow::Hyperbolic_embedding`)
  CGAL::Hyperbolic_surface_2::Basis_construction basis_construction = CGAL::Hyperbolic_surface_2::Basis_construction::GREEDY;
  /// parameters of the shortest path computations
  Shortest_path_options path_options;
};

namespace parameters {
/// named parameter of `Shortest_word_solver` (default true): also compute the shortest loop through the base
/// point in the class of every loop (`Word_result::loop`, `length`); the word does not depend on it
CGAL_HYPERBOLIC_NAMED_PARAMETER(use_geometry, ssw_use_geometry_t)
/// named parameter of `Shortest_word_solver` (default true): shorten the generators at construction
CGAL_HYPERBOLIC_NAMED_PARAMETER(shorten_generators, ssw_shorten_generators_t)
/// named parameter of the computed-basis constructor of `Shortest_word_solver` (default true): make the
/// computed basis canonical by cut and paste (false: words in x1, ..., x2g)
CGAL_HYPERBOLIC_NAMED_PARAMETER(make_canonical, ssw_make_canonical_t)
/// named parameter of the computed-basis constructor of `Shortest_word_solver` (default
/// `CGAL::Hyperbolic_surface_2::Basis_construction::GREEDY`): how the homotopy basis is built
CGAL_HYPERBOLIC_NAMED_PARAMETER(basis_construction, ssw_basis_construction_t)
} // namespace parameters

/// \ingroup PkgSurfaceShortestWordsRef
/// The solver options given by named parameters: `use_geometry`, `shorten_generators`, `make_canonical`
/// (booleans, default true), `basis_construction` (default greedy), and the path options of `path_options()`
/// (`max_lift_distance`, `vertex_snap`, CGAL's `callback`), checked. \throws CGAL::Invalid_option_error for a
/// path option out of its range
template <class NP>
Shortest_word_options word_options(const NP& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Shortest_word_options o;
  o.use_geometry = choose_parameter(get_parameter(np, internal_np::ssw_use_geometry_t_v), o.use_geometry);
  o.shorten_generators = choose_parameter(get_parameter(np, internal_np::ssw_shorten_generators_t_v), o.shorten_generators);
  o.make_canonical = choose_parameter(get_parameter(np, internal_np::ssw_make_canonical_t_v), o.make_canonical);
  o.basis_construction = choose_parameter(get_parameter(np, internal_np::ssw_basis_construction_t_v), o.basis_construction);
  o.path_options = path_options(np);
  return o;
}

/// \ingroup PkgSurfaceShortestWordsRef
/// detailed result of `Shortest_word_solver::solve()`
template <class TriangleMesh>
struct Word_result
{
  Word word;                              ///< the reduced word (the answer)
  Word crossing_word;                     ///< the word read from the crossings, before reduction
  Surface_path<TriangleMesh> loop;        ///< the loop whose crossings were read (shortest, if geometry was used)
  double length = 0;                      ///< its hyperbolic length (0 when `used_geometry` is false)
  bool used_geometry = false;             ///< true if the shortest loop was computed (`loop`, `length`)
  /// empty, or why the geometric shortening was not done (the word does not depend on it), or, with
  /// `used_geometry` true, why the shortest loop was traced from the input loop rather than from the word's
  /// deck transformations
  std::string geometry_status;
};

/*!
  \ingroup PkgSurfaceShortestWordsRef
  Words of loops in pi_1(S, p) in a canonical system of loops a1, b1, ..., ag, bg through a base vertex p
  (thesis section 2.3.2, Algorithm 4).

  The generators are edge loops of the mesh from p to p, simple and pairwise disjoint except at p, whose
  union cuts the surface into one disk (a 4g-gon). Walking around that disk with the interior on the left,
  starting along a1 from p, must read the canonical relator a1 b1 a1^-1 b1^-1 ... ag bg ag^-1 bg^-1 (this
  fixes the corner convention: the base corner is the corner of the disk between the end of bg^-1 and the
  start of a1, i.e. the face to the left of the first edge of a1). The constructor checks all of this and
  throws `Invalid_generators_error` otherwise. With `shorten_generators`, it also computes the shortest loops
  through p homotopic to the generators (Algorithm 2).

  `solve(loop)` (a loop based at p) reads the crossings of the loop with the generator loops in order:
  leaving the disk through the side s_k multiplies the current element by the side pairing
  h_k = (s_1 ... s_k)(s_1 ... s_{j-1})^-1, j the partner side of k (the thesis' rule "crossing a_i gives
  the letter b_i^+-1" up to conjugation by a prefix of the relator, needed since p is a corner of the disk).
  Where the loop passes through a vertex (in particular p) it is perturbed around the vertex on the side
  that crosses fewer generators; the start and the end are joined to the base corner the same way. This
  exact word is then made geodesic by `internal::Geodesic_word_reducer` (Birman and Series: a freely reduced
  word is geodesic iff it has no piece of more than half a relator and no chain of half-relators; see the
  user manual), so the word is a shortest word of the element, independently of floating point. With
  `use_geometry`, the shortest loop through p in the class (Algorithm 2) is computed as well.

  `TriangleMesh`, `EdgeLengthMap`: as for `Hyperbolic_surface`.
*/
template <class TriangleMesh, class EdgeLengthMap>
class Shortest_word_solver
{
public:
  typedef Hyperbolic_surface<TriangleMesh, EdgeLengthMap> Surface;
  typedef typename Surface::vertex_descriptor vertex_descriptor;
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  typedef typename Surface::face_descriptor face_descriptor;
  typedef typename Surface::Path Path;
  typedef typename Surface::Point Point;
  /// isometries of the Poincare disk (the deck transformations, `deck_transformation()`)
  typedef CGAL::Poincare_disk_isometry_2<CGAL::Epick> Isometry;
  static_assert(std::is_same<Isometry, internal::Isometry>::value, "the layout's isometry type");
  typedef typename Surface::Step Step;

  /// `generators[2i]` = a_{i+1}, `generators[2i+1]` = b_{i+1}, as halfedge loops from `base` to `base`.
  /// Cost: O(total generator length) plus the shortening of the generators.
  Shortest_word_solver(const Surface& surface, vertex_descriptor base,
                       const std::vector<std::vector<halfedge_descriptor> >& generators,
                       const Shortest_word_options& options = Shortest_word_options())
    : s_(surface), tm_(surface.mesh()), p_(base), gens_(generators), opt_(options), exit_side_(surface.mesh()), on_cut_(surface.mesh())
  {
    check_base();
    check_options(opt_.path_options);
    validate();
    canonical_ = true;
    std::unordered_map<halfedge_descriptor, int> labels;
    for(std::size_t i = 0; i < gens_.size(); ++i)
      for(std::size_t k = 0; k < gens_[i].size(); ++k) {
        labels[gens_[i][k]] = k == 0 ? int(i) + 1 : 0;
        labels[opposite(gens_[i][k], tm_)] = k == 0 ? -(int(i) + 1) : 0;
      }
    build_cut_system(labels, gens_[0].front());
    Word canonical;
    for(int i = 0; i < g_; ++i) {
      canonical.push_back(2 * i + 1); canonical.push_back(2 * i + 2);
      canonical.push_back(-(2 * i + 1)); canonical.push_back(-(2 * i + 2));
    }
    if(relator_ != canonical)
      throw Invalid_generators_error("Shortest_word_solver: not a canonical system: the boundary of the cut disk reads " +
                                     to_string(relator_) + " instead of " + to_string(canonical));
    make_reducer();
    compute_deck();
    shorten();
  }

  /// the same with named parameters (`word_options()`): `use_geometry`, `shorten_generators`,
  /// `max_lift_distance`, `vertex_snap`, CGAL's `callback`, e.g.
  /// `Shortest_word_solver(surface, p, gens, SSW::parameters::use_geometry(false))`
  template <class T, class Tag, class B>
  Shortest_word_solver(const Surface& surface, vertex_descriptor base,
                       const std::vector<std::vector<halfedge_descriptor> >& generators,
                       const CGAL::Named_function_parameters<T, Tag, B>& np)
    : Shortest_word_solver(surface, base, generators, word_options(np))
  {
    static_assert(CGAL::parameters::is_default_parameter<CGAL::Named_function_parameters<T, Tag, B>,
                                                         internal_np::ssw_make_canonical_t>::value &&
                  CGAL::parameters::is_default_parameter<CGAL::Named_function_parameters<T, Tag, B>,
                                                         internal_np::ssw_basis_construction_t>::value,
                  "make_canonical and basis_construction apply to the computed system only");
  }

  /// the computed system with named parameters (`word_options()`): `make_canonical` in addition
  template <class T, class Tag, class B>
  Shortest_word_solver(const Surface& surface, vertex_descriptor base, const CGAL::Named_function_parameters<T, Tag, B>& np)
    : Shortest_word_solver(surface, base, word_options(np))
  {}

  /*!
    Computes a system of loops itself: the layer's `CGAL::Hyperbolic_surface_2::Homotopy_basis` for the
    hyperbolic edge lengths, by default the greedy basis of Erickson and Whittlesey (the tree of shortest
    paths from `base`, a maximum spanning tree of the dual graph for the lengths of the loops of the remaining
    edges, and the 2g loops of the edges in neither tree); `options.basis_construction` (named parameter
    `basis_construction`) chooses the compact one instead.
    The loops x1, ..., x_{2g} (tree path, edge, tree path back) generate pi_1(S, p); their relator (read
    around the cut disk) is in general not the canonical one. With `options.make_canonical` (default) the
    classical cut and paste (Nielsen substitutions on the relator) gives a canonical system a1, b1, ...,
    ag, bg as words in the x's, realized as edge loops by concatenation (they are not simple, not
    disjoint and not shortest, so the words are exact but shortness is not guaranteed); the crossings are
    still read with the cut graph of the x's and the words rewritten in the a's and b's. Without it,
    `is_canonical()` is false and words are in x1, ..., x_{2g}, Dehn-reduced for their relator.
    Cost: O(n log n) for a mesh of size n.
  */
  Shortest_word_solver(const Surface& surface, vertex_descriptor base,
                       const Shortest_word_options& options = Shortest_word_options())
    : s_(surface), tm_(surface.mesh()), p_(base), opt_(options), exit_side_(surface.mesh()), on_cut_(surface.mesh())
  {
    check_base();
    check_options(opt_.path_options);
    g_ = s_.genus();
    canonical_ = false;
    std::unordered_map<halfedge_descriptor, int> labels;
    halfedge_descriptor first = computed_basis(labels);
    build_cut_system(labels, first);
    if(opt_.make_canonical) {
      try {
        const internal::Canonical_change change = internal::make_canonical(cut_relator_);
        gens_.clear();
        for(const Word& w : change.new_in_old) gens_.push_back(realize_with(cut_gens_, w));
        x_to_gen_ = change.old_in_new;
        relator_.clear();
        for(int i = 0; i < g_; ++i) {
          relator_.push_back(2 * i + 1); relator_.push_back(2 * i + 2);
          relator_.push_back(-(2 * i + 1)); relator_.push_back(-(2 * i + 2));
        }
        canonical_ = true;
      } catch(const std::invalid_argument& e) {
        throw Invalid_generators_error(std::string("Shortest_word_solver: cannot make the computed basis canonical: ") + e.what());
      }
    }
    make_reducer();
    compute_deck();
    shorten();
  }

  /// true for a user-given canonical system a1, b1, ..., false for the computed basis x1, x2, ...
  bool is_canonical() const { return canonical_; }

  /// the word as text: "a1 b1 a1^-1 ..." for a canonical system, "x1 x3^-1 ..." otherwise
  std::string word_to_string(const Word& w) const
  {
    if(canonical_) return to_string(w);
    if(w.empty()) return "1";
    std::ostringstream os;
    for(std::size_t i = 0; i < w.size(); ++i) os << (i ? " " : "") << "x" << std::abs(w[i]) << (w[i] < 0 ? "^-1" : "");
    return os.str();
  }

private:
  void check_base() const
  {
    bool ok = internal::is_valid_handle(tm_, p_) && p_ != boost::graph_traits<TriangleMesh>::null_vertex();
    if(ok) {
      ok = false;
      for(vertex_descriptor v : vertices(tm_)) if(v == p_) { ok = true; break; }
    }
    if(!ok) throw Invalid_generators_error("Shortest_word_solver: the base vertex is not a vertex of the mesh");
  }

  void make_reducer()
  {
    try {
      reducer_ = std::make_shared<const internal::Geodesic_word_reducer>(relator_);
    } catch(const std::invalid_argument& e) {
      throw Invalid_generators_error(std::string("Shortest_word_solver: the relator is not a one-vertex surface relator: ") + e.what());
    }
  }

  // the deck transformation of every generator in the base chart (`deck_transformation()`); without them
  // (a generator lifted beyond double precision) solve() shortens the input loop itself
  void compute_deck()
  {
    deck_.clear();
    if(!opt_.use_geometry) return;
    try {
      for(const auto& g : gens_) deck_.push_back(lift_deck_transformation(s_.path_from_halfedges(g)));
    } catch(const Precision_error&) {
      deck_.clear();
    }
    deck_moves_.clear();
    for(const internal::Isometry& D : deck_)
      deck_moves_.push_back(internal::distance_to_origin(internal::apply_isometry(D, internal::Cplx(0, 0))));
  }

  // The base chart: the layer's chart of the base face recentred at the base corner (p at the origin). The
  // isometry D that maps it onto its lift at the end of the lift of `loop` (a loop at p, closed by the turn to
  // the base corner): the lift of the loop ends at D(0), and loops compose: D(uv) = D(u) D(v).
  internal::Isometry lift_deck_transformation(const Path& loop) const
  {
    const std::vector<Step> st = s_.steps(loop);
    Step base;
    base.face = base_face_; base.in = base.out = base_corner_;
    internal::Crossing_reducer<TriangleMesh> reducer(tm_);
    auto out = boost::make_function_output_iterator([&reducer](halfedge_descriptor h) { reducer.push(h); });
    if(!st.empty()) {
      s_.crossings_at(loop.front(), base, st.front(), out);
      for(std::size_t i = 1; i < st.size(); ++i) s_.crossings_at(loop[i], st[i - 1], st[i], out);
      s_.crossings_at(loop.back(), st.back(), base, out);
    }
    const Point p = s_.corner(base_corner_);
    internal::Transient_chart<Surface> start(s_);
    start.set_face(base_face_);
    start.recentre(s_.position(p, base_corner_, start.face_chart()));
    const internal::Transient_chart<Surface> end =
      internal::develop_crossings(s_, base_face_, p, base_corner_, reducer.result(), opt_.path_options);
    CGAL_assertion(end.current_face() == base_face_);
    const internal::Isometry back = end.accumulated().inverse();
    return internal::Disk::isometry_from_pairs(internal::to_point(start.z()[0]), internal::to_point(start.z()[1]),
                                               internal::to_point(internal::apply_isometry(back, end.z()[0])),
                                               internal::to_point(internal::apply_isometry(back, end.z()[1])));
  }

  // the end mismatch accepted without straightening: 1e-9 relative. (It was also accepted up to 1e-15 e^length,
  // the rounding of a lift in one chart; but the straightening, by chart chaining where one chart is not
  // accurate enough, does better: on the genus-3 one-vertex surface with edge lengths moved by one ulp, the
  // product traces accepted that way were up to 1.4e-7 relative too long, the straightened loops 5.5e-10.)
  static double mismatch_tolerance(double length)
  {
    return 1e-9 * (1 + length);
  }

  // The shortest loop through p of the element of the (geodesic) word w: w is cut into pieces whose deck
  // transformation moves p by at most `reach` (one isometry product per letter); the geodesic of their
  // product is located piece by piece in the frames of the lattice points between the pieces, from its two
  // end points known there to double precision, and traced between anchors
  // (`internal::geodesic_of_deck_product()`): no lift of a path, no iterative straightening.
  // Cost: O(|w| + m), m the faces crossed by the result.
  // Conditioning: a product of letters that move p by d_1, ..., d_k whose product moves p by d cancels
  // c = d_1 + ... + d_k - d units, and the errors of the factors are amplified by about e^c. Measured on the
  // Ricci metrics of elephant and anchor (a1 b1 a1^-1 at all 3,294 base vertices, generators of 5 to 23
  // units, against the loop's own development): relative length errors below 4e-15 for c < 10, 3.5e-10 for c
  // in [10, 15), 2e-7 in [15, 20), 3e-6 in [20, 25), 9e-3 at c = 43. The trace then ends away from the lift
  // it aimed at, and solve() checks that (`end_mismatch`). Several pieces need lattice points near the
  // geodesic, which holds for generators that move p by at most `reach` (the lattice points of a geodesic
  // word fellow-travel its geodesic); with longer generators `Precision_error` is thrown (cutting such
  // pieces shorter left the lattice points far from the geodesic and gave wrong lengths).
  Shortest_path_result<TriangleMesh> word_geodesic(const Word& w) const
  {
    const Shortest_path_options& o = opt_.path_options;
    const double reach = 0.4 * o.max_lift_distance;
    std::vector<internal::Isometry> pieces;
    internal::Isometry D;
    {
      // the whole word in one piece when its lift of p is within `reach` (a lift at distance d carries errors
      // of about 1e-14 e^d: 1e-10 at 10 units, 1e-5 at 22)
      int since = 0;
      double longest = 0; // the largest move of a letter
      for(int l : w) {
        const std::size_t i = std::size_t(std::abs(l) - 1);
        D = D * (l > 0 ? deck_[i] : deck_[i].inverse());
        longest = (std::max)(longest, deck_moves_[i]);
        if(++since >= 8) { D = D.normalized(); since = 0; }
      }
      if(internal::distance_to_origin(internal::apply_isometry(D, internal::Cplx(0, 0))) <= reach)
        return internal::geodesic_of_deck_product(s_, base_face_, base_corner_, std::vector<internal::Isometry>(1, D), o);
      if(w.size() > 1 && longest > reach)
        throw Precision_error("Shortest_word_solver: a generator moves p farther than 0.4 max_lift_distance");
      D = internal::Isometry();
    }
    for(std::size_t j = 0, since = 0; j < w.size(); ++j) {
      const internal::Isometry& g = deck_[std::size_t(std::abs(w[j]) - 1)];
      internal::Isometry n = D * (w[j] > 0 ? g : g.inverse());
      if(++since >= 8) { n = n.normalized(); since = 0; }
      if(j > 0 && internal::distance_to_origin(internal::apply_isometry(n, internal::Cplx(0, 0))) > reach) {
        pieces.push_back(D.normalized());
        D = (w[j] > 0 ? g : g.inverse());
        since = 0;
      } else {
        D = n;
      }
    }
    pieces.push_back(D.normalized());
    return internal::geodesic_of_deck_product(s_, base_face_, base_corner_, pieces, o);
  }

  // The shortest loop through p of the element w (`loop`: a loop in its class, or null for the loop along
  // the generators, built only if needed): from the product of
  // the deck transformations along w (the word is geodesic: no wandering). That product is ill-conditioned
  // when long generators cancel (see word_geodesic()); its trace then ends away from the lift it aimed at
  // (`end_mismatch`). Above `mismatch_tolerance()` the product's traced loop (a loop in the class near the
  // geodesic) is straightened by `shortest_homotopic_path()`, and if that is still not accepted, or without
  // deck transformations, the loop itself is traced (chart chaining: every point near the origin of its
  // chart, consistent with the faces it crosses). Of the candidates the one with the smallest length + end
  // mismatch is kept: each is a loop in the class whose length is within its end mismatch of the reported one,
  // so that sum bounds the shortest length from above (the end mismatch alone does not bound the length
  // error: on a genus-3 one-vertex surface with the computed system, a product's trace ending 1.5e-6 from its
  // aim was 1.8e-4 too long, its straightening 2e-10). `status` says which was kept and why (empty if the
  // product's trace was accepted, or if there are no deck transformations). Throws `Precision_error` if none
  // can be traced.
  Shortest_path_result<TriangleMesh> geodesic_loop(const Word& w, const Path* loop, std::string& status) const
  {
    std::string why;
    Shortest_path_result<TriangleMesh> best;
    bool have = false;
    if(!deck_.empty()) {
      try {
        best = word_geodesic(w);
        have = true;
        if(best.end_mismatch <= mismatch_tolerance(best.length)) return best;
        std::ostringstream os;
        os << "product of the deck transformations: trace ends " << best.end_mismatch << " from its aim; ";
        // farther than 1e-3: it ended at another lift of p (lifts of p are a closed geodesic apart), so the
        // traced loop is in another class and neither it nor its straightening is a candidate (fuzz_words,
        // one-vertex genus-3 surface: a product's trace ended 5.27 from its aim, its straightening 1.6e-5 from
        // its own aim, in the wrong class, and was kept)
        if(!(best.end_mismatch <= internal::other_lift_mismatch)) { have = false; os << "another lift of p, discarded; "; }
        why = os.str();
      } catch(const Precision_error& e) {
        why = std::string("product of the deck transformations: ") + e.what() + "; ";
      }
    }
    // the upper bound on the shortest length that a candidate gives
    auto bound = [](const Shortest_path_result<TriangleMesh>& r) { return r.length + r.end_mismatch; };
    if(have) {
      try {
        Shortest_path_result<TriangleMesh> sp = shortest_homotopic_path(s_, best.path, opt_.path_options);
        std::ostringstream os;
        os << "its straightening ends " << sp.end_mismatch << " from its aim";
        if(bound(sp) < bound(best)) { best = std::move(sp); os << " and was kept; "; }
        else os << ", not kept; ";
        why += os.str();
        if(best.end_mismatch <= mismatch_tolerance(best.length)) { status = why; return best; }
      } catch(const Precision_error& e) {
        why += std::string("its straightening: ") + e.what() + "; ";
      }
    }
    try {
      const Path along = loop ? Path() : s_.path_from_halfedges(realize(w));
      Shortest_path_result<TriangleMesh> sp = shortest_homotopic_path(s_, loop ? *loop : along, opt_.path_options);
      if(!have || bound(sp) < bound(best)) { best = std::move(sp); why += "traced from the loop instead"; }
      else why += "the loop's own trace gave a larger length + end mismatch";
    } catch(const Precision_error& e) {
      if(!have) throw Precision_error(why + "the loop: " + e.what());
      why += std::string("the loop: ") + e.what() + "; the product's trace kept";
    }
    // a candidate ending farther than 1e-3 from its aim ended at another lift of p (lifts of p are a closed
    // geodesic apart): another homotopy class, not a loop of the element (found by fuzz_words on the one-vertex
    // genus-3 surface: a product's trace and its straightening ended 3.98 from their aim, one side of the
    // polygon, and were kept as the shortest loop)
    if(!(best.end_mismatch <= internal::other_lift_mismatch)) {
      std::ostringstream os;
      os << why << "; no candidate ends within 1e-3 of its aim (best: " << best.end_mismatch << ")";
      throw Precision_error(os.str());
    }
    if(!deck_.empty()) status = why;
    return best;
  }

  void shorten()
  {
    if(opt_.shorten_generators) {
      for(std::size_t i = 0; i < gens_.size(); ++i) {
        try {
          Shortest_path_result<TriangleMesh> r =
            shortest_loop_through_base(s_, s_.path_from_halfedges(gens_[i]), opt_.path_options);
          short_gens_.push_back(r.path);
          short_lengths_.push_back(r.length);
          short_status_.push_back(std::string());
        } catch(const Precision_error& e) {
          // a long computed generator (a concatenation of greedy loops): its shortest loop is beyond double
          // precision; the words do not need it
          short_gens_.push_back(Path());
          short_lengths_.push_back(std::numeric_limits<double>::quiet_NaN());
          short_status_.push_back(e.what());
        }
      }
    }
  }

public:

  int genus() const { return g_; }
  vertex_descriptor base() const { return p_; }
  const std::vector<halfedge_descriptor>& generator(std::size_t i) const { return gens_[i]; }
  /// true if the shortest loop through p homotopic to generator i was computed (`shorten_generators`, and
  /// within double precision; otherwise `shortened_generator_status(i)` says why)
  /// the base corner: the corner of the cut disk at p (a halfedge of `base_face()` with target p)
  halfedge_descriptor base_corner() const { return base_corner_; }
  face_descriptor base_face() const { return base_face_; }
  /// true if the deck transformations of the generators are known (`use_geometry`, within double precision)
  bool has_deck_transformations() const { return !deck_.empty(); }
  /// the deck transformation of generator i in the base frame (the layer's chart of `base_face()`
  /// recentred at p): the lift from the origin of the loop of generator i ends at its image of the origin.
  /// \throws Precision_error if `has_deck_transformations()` is false
  const Isometry& deck_transformation(std::size_t i) const
  {
    if(deck_.empty()) throw Precision_error("Shortest_word_solver: the deck transformations were not computed");
    return deck_.at(i);
  }
  /// the shortest loop through p of the element `w` (a word in the generators), traced from the deck
  /// transformations at any length, or, where their product is ill-conditioned (long generators, see
  /// `solve()`), by `shortest_homotopic_path()` on the loop along the generators. \throws Precision_error if
  /// it cannot be traced
  Shortest_path_result<TriangleMesh> shortest_loop_of_word(const Word& w) const
  {
    if(deck_.empty()) throw Precision_error("Shortest_word_solver: the deck transformations were not computed");
    for(int l : w)
      if(l == 0 || std::size_t(std::abs(l)) > gens_.size()) throw Invalid_path_error("Shortest_word_solver: not a letter of the generators");
    std::string status;
    return geodesic_loop(w, nullptr, status);
  }
  bool has_shortened_generator(std::size_t i) const { return i < short_gens_.size() && short_status_[i].empty(); }
  const std::string& shortened_generator_status(std::size_t i) const { return short_status_.at(i); }
  /// the shortest loop through p homotopic to generator i. \throws Precision_error if it was not computed
  const Path& shortened_generator(std::size_t i) const
  {
    if(!has_shortened_generator(i)) throw Precision_error("Shortest_word_solver: shortened generator not available");
    return short_gens_[i];
  }
  /// its length (NaN if not computed)
  double shortened_generator_length(std::size_t i) const { return short_lengths_.at(i); }
  /// the relator read around the disk (a1 b1 a1^-1 b1^-1 ... by the check in the constructor)
  const Word& relator() const { return relator_; }

  /// the reduced word of a loop based at p. \throws Invalid_path_error if the loop is not closed at p
  Word word(const Path& loop) const { return solve(loop).word; }

  /// the word of a CGAL `Path_on_surface` (a closed path through p)
  Word word(const CGAL::Surface_mesh_topology::Path_on_surface<TriangleMesh>& loop) const
  { return word(s_.path_from_path_on_surface(loop)); }

  /// Algorithm 4 with its intermediate results. The word is the geodesic reduction (`geodesic_reduce()`,
  /// shortest by the theorem of Birman and Series) of the exact crossing word of the given loop: it does not
  /// depend on floating point. With `use_geometry`, the shortest loop through p in the class is computed as
  /// well (`loop`, `length`): traced from the product of the generators' deck transformations along the word
  /// (`has_deck_transformations()`), and if that trace misses p or the deck transformations are not known, by
  /// `shortest_homotopic_path()` on the loop itself, at any length (chart chaining); only if both throw
  /// `Precision_error` (a trace lost near a vertex, the round bound exceeded) is `used_geometry` false, with
  /// `geometry_status` saying why.
  Word_result<TriangleMesh> solve(const Path& loop) const
  {
    if(loop.empty()) throw Invalid_path_error("Shortest_word_solver: empty loop");
    s_.check_point(loop.front()); s_.check_point(loop.back()); // the others: checked by crossing_word()
    if(!loop.front().on_vertex || loop.front().v != p_ || !loop.back().on_vertex || loop.back().v != p_)
      throw Invalid_path_error("Shortest_word_solver: the loop must start and end at the base vertex");
    Word_result<TriangleMesh> r;
    const Path single = loop.size() == 1 ? Path(2, loop.front()) : Path(); // a one-point loop, as a path
    const Path& in = loop.size() == 1 ? single : loop;
    r.crossing_word = crossing_word(in);
    r.word = reducer_->reduce(r.crossing_word);
    if(opt_.use_geometry && loop.size() > 1) {
      try {
        Shortest_path_result<TriangleMesh> sp = geodesic_loop(r.word, &loop, r.geometry_status);
        r.loop = std::move(sp.path); r.length = sp.length; r.used_geometry = true;
      } catch(const Precision_error& e) {
        r.geometry_status = e.what();
      }
    }
    if(!r.used_geometry) r.loop = in; // (the input loop is copied only when it is the result)
    return r;
  }

  /// the shortest word of the element `w` (a word in the generators) for the relator `relator()`
  Word reduce(const Word& w) const { return reducer_->reduce(w); }

  /// the word realized as an edge loop: the concatenation of the generator loops (inverse letters
  /// traversed backwards)
  std::vector<halfedge_descriptor> realize(const Word& w) const { return realize_with(gens_, w); }

  /// the raw word read from the crossings of a loop based at p with the generators (no geometry, no
  /// reduction): exact and linear in the loop size
  Word crossing_word(const Path& loop) const
  {
    Word w;
    const std::vector<Step> st = s_.steps(loop);
    if(st.empty()) return w;
    Step base;
    base.face = base_face_; base.in = base.out = base_corner_;
    move(loop.front(), base, st.front(), w);
    for(std::size_t i = 1; i < st.size(); ++i) move(loop[i], st[i - 1], st[i], w);
    move(loop.back(), st.back(), base, w);
    w = internal::free_reduce(w);
    if(!x_to_gen_.empty()) w = internal::substitute(internal::dehn_reduce(w, cut_relator_), x_to_gen_);
    return w;
  }

private:
  // concatenation of loops (inverse letters traversed backwards), immediate backtracks removed
  std::vector<halfedge_descriptor> realize_with(const std::vector<std::vector<halfedge_descriptor> >& loops, const Word& w) const
  {
    std::vector<halfedge_descriptor> r;
    auto push = [&](halfedge_descriptor h) {
      if(!r.empty() && r.back() == opposite(h, tm_)) r.pop_back(); else r.push_back(h);
    };
    for(int l : w) {
      const std::vector<halfedge_descriptor>& g = loops.at(std::size_t(std::abs(l) - 1));
      if(l > 0) for(halfedge_descriptor h : g) push(h);
      else for(auto it = g.rbegin(); it != g.rend(); ++it) push(opposite(*it, tm_));
    }
    return r;
  }

private:
  // ---------------------------------------------------------------- letters
  void emit_crossing(halfedge_descriptor h, Word& w) const
  {
    const int k = exit_side_.get(h);
    if(k >= 0) internal::append_reduced(w, side_words_[std::size_t(k)]);
  }

  // moves at the path point p from the step `from` to the step `to`, emitting the letters of the generators
  // crossed: across the edge of an edge point, or around a vertex the way that crosses fewer generators
  void move(const Point& p, const Step& from, const Step& to, Word& w) const
  {
    if(!p.on_vertex) {
      s_.crossings_at(p, from, to, boost::make_function_output_iterator([&](halfedge_descriptor h) { emit_crossing(h, w); }));
      return;
    }
    if(from.out == to.in) return;
    if(!on_cut_.get(p.v)) return; // no edge with a letter at the vertex: none crossed either way (most vertices)
    std::size_t n[2] = {0, 0}, steps[2] = {0, 0};
    for(int k = 0; k < 2; ++k)
      steps[k] = s_.turn(from.out, to.in, k == 0, boost::make_function_output_iterator([&](halfedge_descriptor h) {
        if(exit_side_.get(h) >= 0) ++n[k]; }));
    const bool ccw = n[0] < n[1] || (n[0] == n[1] && steps[0] <= steps[1]);
    s_.turn(from.out, to.in, ccw, boost::make_function_output_iterator([&](halfedge_descriptor h) { emit_crossing(h, w); }));
  }

  // ---------------------------------------------------------------- validation
  void validate()
  {
    g_ = s_.genus();
    if(gens_.size() != std::size_t(2 * g_)) {
      std::ostringstream os;
      os << "Shortest_word_solver: " << gens_.size() << " loops given, a canonical system of a genus " << g_
         << " surface has " << 2 * g_;
      throw Invalid_generators_error(os.str());
    }
    std::set<vertex_descriptor> used_vertices;
    std::set<typename Surface::edge_descriptor> used_edges;
    for(std::size_t i = 0; i < gens_.size(); ++i) {
      const std::vector<halfedge_descriptor>& g = gens_[i];
      std::ostringstream name; name << (i % 2 == 0 ? "a" : "b") << (i / 2 + 1);
      if(g.empty()) throw Invalid_generators_error("Shortest_word_solver: generator " + name.str() + " is empty");
      for(halfedge_descriptor h : g)
        if(!internal::is_valid_handle(tm_, h) || h == boost::graph_traits<TriangleMesh>::null_halfedge())
          throw Invalid_generators_error("Shortest_word_solver: generator " + name.str() + " has a halfedge that is not on the mesh");
      if(source(g.front(), tm_) != p_ || target(g.back(), tm_) != p_)
        throw Invalid_generators_error("Shortest_word_solver: generator " + name.str() + " is not a loop through the base vertex");
      for(std::size_t k = 0; k < g.size(); ++k) {
        if(k > 0 && source(g[k], tm_) != target(g[k - 1], tm_))
          throw Invalid_generators_error("Shortest_word_solver: generator " + name.str() + " is not a connected halfedge path");
        if(!used_edges.insert(edge(g[k], tm_)).second)
          throw Invalid_generators_error("Shortest_word_solver: generator " + name.str() + " reuses an edge (loops must be simple and disjoint)");
        if(k + 1 < g.size()) {
          const vertex_descriptor v = target(g[k], tm_);
          if(v == p_ || !used_vertices.insert(v).second)
            throw Invalid_generators_error("Shortest_word_solver: generator " + name.str() + " meets itself or another loop away from the base vertex");
        }
      }
    }
  }

  // The cut graph G (halfedges in `labels`, label 0 or +-(i+1)) cuts the surface into one disk D. Walk
  // around D with D on the left, starting along `first` (the base corner is the corner of D at p on the
  // left of `first`); position k has halfedge beta_k, c_k = number of labels read in positions 1..k. Leaving
  // D across beta_k (from face(beta_k)) moves to the neighbouring copy of D, i.e. multiplies by
  // h_k = W_k W_{j-1}^-1 (W_k = the labels read so far, j the position of opposite(beta_k)).
  void build_cut_system(const std::unordered_map<halfedge_descriptor, int>& labels, halfedge_descriptor first)
  {
    std::unordered_map<halfedge_descriptor, std::size_t> pos;
    std::vector<std::size_t> count(1, 0); // count[k] = c_k
    cut_relator_.clear();
    halfedge_descriptor beta = first;
    const std::size_t n = labels.size();
    for(std::size_t k = 1; k <= n; ++k) {
      if(!pos.emplace(beta, k).second) break;
      const int l = labels.at(beta);
      if(l != 0) cut_relator_.push_back(l);
      count.push_back(cut_relator_.size());
      // next: the first halfedge of G clockwise from opposite(beta) around target(beta)
      const halfedge_descriptor back = opposite(beta, tm_);
      halfedge_descriptor o = back;
      do { o = next(opposite(o, tm_), tm_); } while(o != back && !labels.count(o));
      beta = o;
    }
    if(pos.size() != n || beta != first)
      throw Invalid_generators_error("Shortest_word_solver: the loops do not cut the surface into one disk (boundary word " +
                                     to_string(cut_relator_) + ")");
    if(cut_relator_.size() != 4 * std::size_t(g_))
      throw Invalid_generators_error("Shortest_word_solver: the cut disk has " + std::to_string(cut_relator_.size()) +
                                     " labelled sides instead of 4g");
    const std::size_t m = cut_relator_.size() + 1;
    side_words_.assign(m * m, Word());
    for(std::size_t a = 0; a < m; ++a)
      for(std::size_t b = 0; b < m; ++b) {
        Word w(cut_relator_.begin(), cut_relator_.begin() + std::ptrdiff_t(a));
        internal::append_reduced(w, internal::inverse(Word(cut_relator_.begin(), cut_relator_.begin() + std::ptrdiff_t(b))));
        side_words_[a * m + b] = w;
      }
    exit_side_.clear();
    on_cut_.clear();
    for(const auto& hp : pos) {
      const std::size_t k = hp.second, j = pos.at(opposite(hp.first, tm_));
      const std::size_t a = count[k], b = count[j - 1];
      if(a != b) { // a == b: the trivial element
        exit_side_.set(hp.first, int(a * m + b));
        on_cut_.set(source(hp.first, tm_)); on_cut_.set(target(hp.first, tm_));
      }
    }
    base_face_ = face(first, tm_);
    base_corner_ = prev(first, tm_); // the corner of D at p on the left of `first`
    relator_ = cut_relator_;
    cut_gens_ = gens_;
    x_to_gen_.clear();
  }

  // the homotopy basis of the shared layer (Hyperbolic_surface_2::Homotopy_basis, opt_.basis_construction):
  // generator i is its loop i; fills the labels of the cut graph (tree edges 0, generator edge i +-(i+1))
  halfedge_descriptor computed_basis(std::unordered_map<halfedge_descriptor, int>& labels)
  {
    const Surface& s = s_;
    auto weight = boost::make_function_property_map<typename Surface::edge_descriptor, double>(
      [&s](typename Surface::edge_descriptor e) { return s.length(halfedge(e, s.mesh())); });
    const CGAL::Hyperbolic_surface_2::Homotopy_basis<TriangleMesh> basis(tm_, p_, weight, opt_.basis_construction);
    if(basis.number_of_generators() != 2 * std::size_t(g_))
      throw Invalid_generators_error("Shortest_word_solver: the homotopy basis has " + std::to_string(basis.number_of_generators()) +
                                     " loops instead of 2g");
    gens_.clear();
    for(std::size_t i = 0; i < basis.number_of_generators(); ++i) gens_.push_back(basis.loop(i));
    for(typename Surface::edge_descriptor e : edges(tm_)) {
      if(!basis.is_cut_edge(e)) continue;
      const halfedge_descriptor h = halfedge(e, tm_);
      labels[h] = basis.label(h);
      labels[opposite(h, tm_)] = basis.label(opposite(h, tm_));
    }
    // start along a halfedge of the cut graph leaving p
    for(halfedge_descriptor h : CGAL::halfedges_around_source(p_, tm_))
      if(labels.count(h)) return h;
    throw Invalid_generators_error("Shortest_word_solver: isolated base vertex");
  }

  const Surface& s_;
  const TriangleMesh& tm_;
  vertex_descriptor p_;
  std::vector<std::vector<halfedge_descriptor> > gens_;
  Shortest_word_options opt_;
  int g_ = 0;
  Word relator_;      // relator of the generators (canonical when canonical_)
  Word cut_relator_;  // relator of the cut system the crossings are read with
  std::vector<std::vector<halfedge_descriptor> > cut_gens_;
  std::vector<Word> x_to_gen_; // cut-system letters as words in the generators (empty: identical)
  std::vector<Word> side_words_;
  internal::Halfedge_int_map<TriangleMesh> exit_side_;
  internal::Vertex_flags<TriangleMesh> on_cut_; // the ends of the halfedges of exit_side_
  bool canonical_ = true;
  face_descriptor base_face_{};
  halfedge_descriptor base_corner_{};
  std::vector<Path> short_gens_;
  std::vector<double> short_lengths_;
  std::vector<std::string> short_status_;
  std::shared_ptr<const internal::Geodesic_word_reducer> reducer_;
  std::vector<internal::Isometry> deck_; // deck transformation of generator i in the base chart
  std::vector<double> deck_moves_;       // the distance by which it moves p
};

} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_SHORTEST_WORD_SOLVER_H
