// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Free and Dehn reduction of words in a one-relator group (the surface group <a1,b1,...,ag,bg | R>).
// Letters are non-zero integers, -x is the inverse of x.
#ifndef CGAL_HYPERBOLIC_SURFACE_2_INTERNAL_SURFACE_GROUP_WORDS_H
#define CGAL_HYPERBOLIC_SURFACE_2_INTERNAL_SURFACE_GROUP_WORDS_H

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <initializer_list>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hyperbolic_surface_2 {
namespace internal {

/// appends `x` to the freely reduced word `w`, keeping it freely reduced
inline void append_reduced(std::vector<int>& w, const std::vector<int>& x)
{
  for(int l : x) {
    if(!w.empty() && w.back() == -l) w.pop_back();
    else w.push_back(l);
  }
}

inline std::vector<int> free_reduce(const std::vector<int>& w)
{
  std::vector<int> r;
  append_reduced(r, w);
  return r;
}

inline std::vector<int> inverse(const std::vector<int>& w)
{
  std::vector<int> r(w.rbegin(), w.rend());
  for(int& l : r) l = -l;
  return r;
}

/// Dehn's algorithm: free reduction, and every subword that is a piece of length > |R|/2 of a cyclic
/// conjugate of R or R^-1 is replaced by the inverse of the complementary piece (strictly shorter).
/// Stack based. The cyclic conjugates are tried in the order R_0, R_0^-1, R_1, R_1^-1, ... (R_r: R rotated by r)
/// and, in each, the longest piece first; only the pieces that end with the letter just pushed are looked at,
/// found through an index built once per call (O(|R|^2)), so that a letter costs O(|R|) candidates, not
/// O(|R|^2) (genus 133: 532 instead of 283,000). The result represents the same group element.
inline std::vector<int> dehn_reduce(const std::vector<int>& w, const std::vector<int>& R)
{
  const std::size_t n = R.size();
  if(n == 0) return free_reduce(w);
  const std::vector<int> Ri = inverse(R);
  // letter t of the cyclic conjugate k: k = 2r (R rotated by r) or 2r + 1 (R^-1 rotated by r)
  auto letter = [&](std::size_t k, std::size_t t) { return (k % 2 == 0 ? R : Ri)[(k / 2 + t) % n]; };
  int max_abs = 0;
  for(int l : R) max_abs = (std::max)(max_abs, std::abs(l));
  for(int l : w) max_abs = (std::max)(max_abs, std::abs(l));
  // candidates[x + max_abs]: the pieces (k, L) with last letter x, L > n/2, ordered by k, then by L decreasing
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > candidates(std::size_t(2 * max_abs + 1));
  for(std::size_t k = 0; k < 2 * n; ++k)
    for(std::size_t L = n; L > n / 2; --L)
      candidates[std::size_t(letter(k, L - 1) + max_abs)].emplace_back(k, L);
  std::vector<int> S;
  std::deque<int> todo(w.begin(), w.end());
  while(!todo.empty()) {
    const int x = todo.front(); todo.pop_front();
    if(!S.empty() && S.back() == -x) { S.pop_back(); continue; }
    S.push_back(x);
    for(const auto& kl : candidates[std::size_t(x + max_abs)]) {
      const std::size_t k = kl.first, L = kl.second;
      if(S.size() < L) continue;
      bool match = true;
      for(std::size_t t = 0; t < L && match; ++t) match = S[S.size() - L + t] == letter(k, t);
      if(!match) continue;
      S.resize(S.size() - L);
      // the piece c[0..L) equals (c[L..n))^-1
      std::vector<int> rep;
      for(std::size_t t = n; t > L; --t) rep.push_back(-letter(k, t - 1));
      todo.insert(todo.begin(), rep.begin(), rep.end());
      break;
    }
  }
  return S;
}


/// Result of `make_canonical()`: new generators a1, b1, ..., ag, bg (letters 1..2g) as words in the old
/// letters, and the old letters as words in the new ones.
struct Canonical_change
{
  std::vector<std::vector<int> > new_in_old; ///< new_in_old[i]: generator i+1 (a1, b1, a2, ...) in the old letters
  std::vector<std::vector<int> > old_in_new; ///< old_in_new[i]: old letter i+1 in the new generators
};

inline std::vector<int> substitute(const std::vector<int>& w, const std::vector<std::vector<int> >& image)
{
  std::vector<int> r;
  for(int l : w) {
    const std::vector<int>& x = image[std::size_t(std::abs(l) - 1)];
    append_reduced(r, l > 0 ? x : inverse(x));
  }
  return r;
}

/// Checks that `R` is the relator of a one-vertex cell structure of a closed orientable surface of genus >= 1:
/// letters +-1..+-2g, each generator once with each sign, and the link of the vertex one cycle of length 4g.
/// Returns the link as `ccw[k]` = position (0..4g-1) of the direction `k` in the cyclic order around a vertex of
/// the Cayley graph, direction `k` = letter index `k` (see `letter_index()`). Throws std::invalid_argument.
inline std::size_t letter_index(int l, int n) { return l > 0 ? std::size_t(l - 1) : std::size_t(n - l - 1); }

inline std::vector<int> surface_relator_link(const std::vector<int>& R)
{
  const int n = int(R.size()) / 2; // number of generators
  if(R.size() < 4 || R.size() % 4 != 0) throw std::invalid_argument("not a surface relator (length not a positive multiple of 4)");
  std::vector<int> seen(2 * std::size_t(n), 0);
  for(int l : R) {
    if(l == 0 || std::abs(l) > n) throw std::invalid_argument("not a surface relator (letter out of range)");
    if(seen[letter_index(l, n)]++) throw std::invalid_argument("not a surface relator (a letter appears twice with the same sign)");
  }
  // the face has its corner between R[i] (incoming, direction R[i]^-1) and R[i+1] (outgoing): these two
  // directions are consecutive around the vertex, next_ccw(R[i+1]) = R[i]^-1
  const std::size_t m = R.size();
  std::vector<int> next(m, -1);
  for(std::size_t i = 0; i < m; ++i) next[letter_index(R[(i + 1) % m], n)] = int(letter_index(-R[i], n));
  std::vector<int> pos(m, -1);
  std::size_t d = 0;
  for(std::size_t k = 0; k < m; ++k) {
    if(pos[d] >= 0) throw std::invalid_argument("not a one-vertex surface relator (the vertex link is not one cycle)");
    pos[d] = int(k);
    d = std::size_t(next[d]);
  }
  if(d != 0) throw std::invalid_argument("not a one-vertex surface relator (the vertex link is not one cycle)");
  return pos;
}

/// counts of one `Geodesic_word_reducer::reduce()` call (the quantities of its cost proof)
struct Reduction_statistics
{
  std::size_t input_letters = 0;          ///< letters of w
  std::size_t pushes = 0;                 ///< letters pushed (w's and the replacements')
  std::size_t free_cancellations = 0, dehn_rules = 0, chain_rules = 0;
  std::size_t replaced_letters = 0;       ///< letters removed by Dehn and chain rules
  std::size_t marks_created = 0;          ///< stack positions where a valid chain prefix ends (per side)
  std::size_t max_rules_per_input_letter = 0;
  std::size_t max_marks_per_replacement = 0; ///< marks created by the pushes of one rule's replacement
  /// total work: pushes, free cancellations, removed letters and the chain's tile count (at most its length)
  std::size_t work() const { return pushes + free_cancellations + 2 * replaced_letters; }
  /// the bound of the proof (`Geodesic_word_reducer`): (3 (14 g + 1) + 2) |w|
  static std::size_t bound(int genus, std::size_t n) { return (3 * (14 * std::size_t(genus) + 1) + 2) * n; }
};


/*!
  Geodesic (shortest) words in the surface group G = < x_1, ..., x_2g | R >, R a one-vertex surface relator of
  genus g >= 2 (e.g. the canonical [a1, b1] ... [ag, bg]): returns a shortest word representing the same
  element as `w`.

  The Cayley graph of G is the 1-skeleton of the tiling of the hyperbolic plane by 4g-gons, 4g around each
  vertex (the universal cover of the one-vertex cell structure). A word is an edge path; at each inner
  vertex its turn t (1..4g-1) is the number of tiles on its left. A maximal run of turns 1 (resp. 4g-1) is a
  piece of the boundary of one tile on the left (right). Birman and Series (Dehn's algorithm revisited, with
  applications to simple curves on surfaces, 1987; see also Hermiller, Rewriting systems for surface groups)
  show that a freely reduced word is geodesic if and only if it contains
   - no piece of more than 2g consecutive edges of a tile (Dehn's rule), and
   - no chain: consecutive pieces of tiles T_1, ..., T_k (k >= 2) on the same side, T_j and T_j+1 sharing
     the edge between the two pieces (turn 2, resp. 4g-2, at the junction), with 2g edges on T_1 and T_k and
     2g-1 on T_2 ... T_k-1.
  A chain of length L is replaced by the path on the other side of T_1 ... T_k, which has L - 2 edges; a
  piece of m > 2g edges by the 4g - m others. The reduction is done by a stack: each letter is pushed, and
  the turn, run and chain state of the top are updated in O(1); a rule that applies to a suffix of the stack
  is applied and the replacement is pushed again. The result contains no pattern (each letter was checked
  with the final stack below it), so it is geodesic by the theorem.

  Cost: O(g |w|) (linear in |w| for a fixed genus). Proof, with the counts of `Reduction_statistics`:
  1. *At most one rule (free cancellation, Dehn or chain) per letter of w.* After each letter of w the stack
     is geodesic (above). Every relator has even length, so |u x| = |u| +- 1 for every word u and letter x:
     if the geodesic stack u followed by x is not geodesic, the element has length |u| - 1. Every rule
     shortens by exactly 2 (a piece reaches 2g + 1 edges one letter at a time, and 2(2g + 1) - 4g = 2), so
     exactly one rule applies before the stack is geodesic again; the replacement's letters apply none.
  2. *Marks.* Call a stack position marked on a side when a valid chain prefix ends there (`chain[side]`:
     the last letter of a complete first piece of 2g edges, or of a middle piece of 2g - 1 edges after a
     junction). Marks never change while their letter is on the stack. A chain of k tiles has
     L = 4g + (k - 2)(2g - 1) <= 4g (k - 1) letters and k - 1 marks, all removed by the rule.
  3. *A replacement creates at most 1 mark.* No pattern ends at any stack letter (a push that completes one
     is removed). A rule's replacement lies on the other side of the rule's tiles: pieces of 2g - 1 edges
     (one for a Dehn rule, k for a chain) joined by junctions; let z be the stack letter below it. Its first
     piece cannot contain z (the turn from z would be 0, a cancellation), and it is not a middle piece: z
     would be marked on that side with the rule's first letter continuing its piece (turn 1 from z), so that
     letter would have completed a Dehn piece or a chain when it was pushed. So no mark on that side. On the
     rule's side the replacement turns by 4g - 1 or 4g - 2, so its pieces there have one edge, except the
     first letter's, which may continue z's piece: at most 1 mark.
  Work = pushes + free cancellations + 2 x removed letters (the letters and the chain's tile count), with
  pushes <= |w| + removed letters. By 1, Dehn rules remove at most (2g + 1) |w| letters; by 2 and 3 chains
  remove at most 4g times the marks created, at most 2 per letter of w and 1 per rule: 12 g |w|. Hence
  work <= (3 (14 g + 1) + 2) |w| (`Reduction_statistics::bound()`); the test `reduction_work_is_linear`
  checks statements 1 and 3 and the bound on every word it reduces. Throws std::invalid_argument if R is not
  a one-vertex surface relator of genus >= 2.
*/
class Geodesic_word_reducer
{
public:
  explicit Geodesic_word_reducer(const std::vector<int>& R)
    : n_(int(R.size()) / 2), p_(int(R.size())), h_(int(R.size()) / 2), pos_(surface_relator_link(R))
  {
    if(R.size() < 8) throw std::invalid_argument("geodesic words: the surface group must have genus >= 2");
    dir_.assign(std::size_t(p_), 0);
    for(int l = -n_; l <= n_; ++l) if(l != 0) dir_[std::size_t(pos_[letter_index(l, n_)])] = l;
  }

  std::vector<int> reduce(const std::vector<int>& w, Reduction_statistics* stats = nullptr) const
  {
    std::vector<Entry> S;
    std::vector<int> todo(w.rbegin(), w.rend()); // a stack: back() is the next letter
    S.reserve(w.size());
    Reduction_statistics local;
    Reduction_statistics& st = stats ? *stats : local;
    st = Reduction_statistics();
    st.input_letters = w.size();
    // todo = the unread letters of w (bottom) and the pending replacement letters (top)
    std::size_t unread = w.size(), rules_now = 0, marks_now = 0;
    while(!todo.empty()) {
      const bool from_input = todo.size() == unread;
      const int x = todo.back(); todo.pop_back();
      if(x == 0 || std::abs(x) > n_) throw std::invalid_argument("geodesic words: letter out of range");
      if(from_input) { --unread; rules_now = 0; }
      const std::size_t pending = todo.size();
      const std::size_t rules_before = st.free_cancellations + st.dehn_rules + st.chain_rules;
      push(S, x, todo, st);
      if(st.free_cancellations + st.dehn_rules + st.chain_rules != rules_before) {
        st.max_rules_per_input_letter = (std::max)(st.max_rules_per_input_letter, ++rules_now);
        marks_now = 0;
      } else if(!from_input && todo.size() == pending) {
        marks_now += std::size_t((S.back().chain[0] >= 0) + (S.back().chain[1] >= 0));
        st.max_marks_per_replacement = (std::max)(st.max_marks_per_replacement, marks_now);
      }
    }
    std::vector<int> r;
    r.reserve(S.size());
    for(const Entry& e : S) r.push_back(e.letter);
    return r;
  }

  /// true iff `w` is freely reduced and contains no long piece and no chain (i.e. is geodesic)
  bool is_geodesic(const std::vector<int>& w) const { return reduce(w).size() == w.size(); }

private:
  struct Entry
  {
    int letter;
    int turn;       // turn from the previous letter (-1 at the bottom)
    int run[2];     // number of consecutive turns 1 (side 0, left) / p-1 (side 1, right) ending here
    long chain[2];  // start of a valid chain prefix whose last piece ends here, or -1
  };

  int position(int l) const { return pos_[letter_index(l, n_)]; }
  int direction(int k) const { return dir_[std::size_t(((k % p_) + p_) % p_)]; }
  // number of tiles on the left of the path x then y (0: y = x^-1)
  int turn(int x, int y) const { return (((position(-x) - position(y)) % p_) + p_) % p_; }

  void push(std::vector<Entry>& S, int x, std::vector<int>& todo, Reduction_statistics& st) const
  {
    if(!S.empty() && S.back().letter == -x) { S.pop_back(); ++st.free_cancellations; return; }
    ++st.pushes;
    Entry e;
    e.letter = x;
    e.turn = S.empty() ? -1 : turn(S.back().letter, x);
    S.push_back(e);
    const long i = long(S.size()) - 1;
    for(int side = 0; side < 2; ++side) {
      const int one = side == 0 ? 1 : p_ - 1, two = side == 0 ? 2 : p_ - 2;
      Entry& t = S.back();
      t.run[side] = (i > 0 && t.turn == one) ? S[std::size_t(i - 1)].run[side] + 1 : 0;
      const int edges = t.run[side] + 1;           // edges of the current piece
      const long s = i - t.run[side];              // first letter of the piece
      const bool after_junction = s > 0 && S[std::size_t(s)].turn == two && S[std::size_t(s - 1)].chain[side] >= 0;
      if(edges > h_) { ++st.dehn_rules; replace(S, s, 1, side, todo, st); return; } // more than half a tile
      if(edges == h_ && after_junction) {                                  // a chain ends here
        const long c = S[std::size_t(s - 1)].chain[side];
        int tiles = 1;
        for(long j = c + 1; j <= i; ++j) if(S[std::size_t(j)].turn == two) ++tiles;
        ++st.chain_rules;
        replace(S, c, tiles, side, todo, st);
        return;
      }
      t.chain[side] = edges == h_ ? s : (edges == h_ - 1 && after_junction ? S[std::size_t(s - 1)].chain[side] : -1);
      if(t.chain[side] >= 0) ++st.marks_created;
    }
  }

  // replaces S[c..] (pieces of `tiles` consecutive tiles on `side`) by the path on the other side of them:
  // 4g - m edges for one tile with a piece of m edges, 2g - 1 edges per tile for a chain
  void replace(std::vector<Entry>& S, long c, int tiles, int side, std::vector<int>& todo, Reduction_statistics& st) const
  {
    const long m = long(S.size()) - c;
    st.replaced_letters += std::size_t(m);
    const int step = side == 0 ? 1 : -1; // the other side of a tile on the left starts one step ccw
    std::vector<int> rep;
    rep.push_back(direction(position(S[std::size_t(c)].letter) + step));
    const long per_tile = tiles == 1 ? p_ - m : h_ - 1;
    for(int k = 0; k < tiles; ++k)
      for(long j = (k == 0 ? 1 : 0); j < per_tile; ++j) {
        const int back = position(-rep.back());
        rep.push_back(direction(back + (j == 0 ? 2 * step : step)));
      }
    S.resize(std::size_t(c));
    todo.insert(todo.end(), rep.rbegin(), rep.rend());
  }

  int n_, p_, h_;
  std::vector<int> pos_, dir_;
};

/// shortest word of the element `w` of < letters | R > (see `Geodesic_word_reducer`)
inline std::vector<int> geodesic_reduce(const std::vector<int>& w, const std::vector<int>& R)
{
  return Geodesic_word_reducer(R).reduce(w);
}

/// the canonical relator a1 b1 a1^-1 b1^-1 ... ag bg ag^-1 bg^-1 (a_i = 2i-1, b_i = 2i)
inline std::vector<int> canonical_relator(int g)
{
  std::vector<int> R;
  for(int i = 0; i < g; ++i) { R.push_back(2 * i + 1); R.push_back(2 * i + 2); R.push_back(-(2 * i + 1)); R.push_back(-(2 * i + 2)); }
  return R;
}

namespace canonical_detail {

// the state of the cut and paste: a relator W in symbols (ids 1..), expr[id] = the symbol as a word in the
// old letters, inv[i] = old letter i+1 as a word in the symbols. Every change is a Nielsen substitution
// s = A s' B (A, B free of s), so W stays equal, in the free group, to R written in the symbols.
struct State
{
  std::vector<std::vector<int> > expr;
  std::vector<std::vector<int> > inv;
  std::vector<int> W;

  std::vector<int> expr_of(const std::vector<int>& w) const
  {
    std::vector<int> r;
    for(int l : w) append_reduced(r, l > 0 ? expr[std::size_t(l)] : inverse(expr[std::size_t(-l)]));
    return r;
  }
  // s = A s' B: creates s' (its expression A^-1 s B^-1) and rewrites W and inv; returns s'
  int substitute(int s, const std::vector<int>& A, const std::vector<int>& B)
  {
    std::vector<int> e = inverse(A); e.push_back(s); append_reduced(e, inverse(B));
    expr.push_back(expr_of(e));
    const int t = int(expr.size()) - 1;
    std::vector<int> rep = A; rep.push_back(t); append_reduced(rep, B);
    const std::vector<int> irep = inverse(rep);
    auto apply = [&](const std::vector<int>& w) {
      std::vector<int> r;
      for(int l : w) {
        if(l == s) append_reduced(r, rep);
        else if(l == -s) append_reduced(r, irep);
        else append_reduced(r, std::vector<int>{l});
      }
      return r;
    };
    W = apply(W);
    for(auto& w : inv) w = apply(w);
    return t;
  }
};

inline std::vector<int> slice(const std::vector<int>& w, std::size_t a, std::size_t b)
{
  return std::vector<int>(w.begin() + std::ptrdiff_t(a), w.begin() + std::ptrdiff_t(b));
}

inline std::vector<int> concat(std::initializer_list<std::vector<int> > parts)
{
  std::vector<int> r;
  for(const auto& p : parts) append_reduced(r, p);
  return r;
}

// W = D T with D = [x1, y1] ... [xk, yk] (k0 = 4k letters): turns T into [x, y] T' with T' free of x, y
inline void extract_handle(State& st, std::size_t k0, std::vector<int>& a_sym, std::vector<int>& b_sym)
{
  // a linked pair in T: positions i1 < j1 < i2 < j2 of the symbols u (i1, i2) and v (j1, j2)
  const std::size_t m = st.W.size();
  std::size_t i1 = m, j1 = m, i2 = m, j2 = m;
  std::vector<std::size_t> other(m, m);
  for(std::size_t i = k0; i < m; ++i)
    for(std::size_t j = k0; j < m; ++j)
      if(i != j && st.W[j] == -st.W[i]) other[i] = j;
  for(std::size_t i = k0; i < m && i1 == m; ++i) {
    if(other[i] == m) throw std::invalid_argument("make_canonical: a letter appears once only");
    if(other[i] < i) continue;
    for(std::size_t j = i + 1; j < other[i]; ++j)
      if(other[j] > other[i]) { i1 = i; j1 = j; i2 = other[i]; j2 = other[j]; break; }
  }
  if(i1 == m) throw std::invalid_argument("make_canonical: no linked pair (not a one-vertex orientable surface relator)");
  // make the first occurrences positive
  for(std::size_t q : {i1, j1})
    if(st.W[q] < 0) { // rename: s = (s')^-1
      const int s = -st.W[q];
      st.expr.push_back(inverse(st.expr[std::size_t(s)]));
      const int t = int(st.expr.size()) - 1;
      auto rename = [&](std::vector<int>& w) { for(int& l : w) if(std::abs(l) == s) l = l > 0 ? -t : t; };
      rename(st.W);
      for(auto& w : st.inv) rename(w);
    }
  const int x = st.W[i1], y = st.W[j1];
  const std::vector<int> U = slice(st.W, k0, i1), P = slice(st.W, i1 + 1, j1), Q = slice(st.W, j1 + 1, i2),
                         R = slice(st.W, i2 + 1, j2), V = slice(st.W, j2 + 1, m);
  // T = U x P y Q X R Y V
  const int x1 = st.substitute(x, {}, inverse(P));                     // T = U x1 y Q P X1 R Y V
  const int y1 = st.substitute(y, {}, inverse(concat({Q, P})));        // T = U x1 y1 X1 R Q P Y1 V
  const int x2 = st.substitute(x1, concat({R, Q, P}), {});             // T = U R Q P x2 y1 X2 Y1 V
  const std::vector<int> M = concat({U, R, Q, P});
  const int x3 = st.substitute(x2, inverse(M), M);                     // T = x3 y3 X3 Y3 M V
  const int y3 = st.substitute(y1, inverse(M), M);
  a_sym.push_back(x3); b_sym.push_back(y3);
}

} // namespace canonical_detail

/// Cut and paste on the relator (the classification of surfaces by Nielsen substitutions): turns a relator R
/// of a one-vertex cell structure of a closed orientable surface of genus g (2g letters, each once with
/// each sign, one vertex) into the canonical a1 b1 a1^-1 b1^-1 ... ag bg ag^-1 bg^-1. Each of the g steps
/// takes a linked pair x ... y ... x^-1 ... y^-1 of the part not yet canonical, U x P y Q X R Y V, and applies
/// x = x1 P^-1, y = y1 P^-1 Q^-1, x1 = (R Q P) x2, then conjugates x2, y1 by M = U R Q P: the part becomes
/// [x3, y3] M V, M V free of x3, y3. Each substitution is a free-group automorphism, so the canonical relator
/// written with `new_in_old` is R itself (after free reduction), and `old_in_new` is the inverse
/// automorphism. Throws std::invalid_argument if R is not a one-vertex orientable surface relator.
inline Canonical_change make_canonical(const std::vector<int>& R)
{
  surface_relator_link(R); // validates
  const int n = int(R.size()) / 2;
  canonical_detail::State st;
  st.expr.resize(std::size_t(n) + 1);
  for(int i = 1; i <= n; ++i) st.expr[std::size_t(i)] = std::vector<int>{i};
  for(int i = 1; i <= n; ++i) st.inv.push_back(std::vector<int>{i});
  st.W = R;
  std::vector<int> a_sym, b_sym;
  for(std::size_t k0 = 0; k0 < R.size(); k0 += 4) canonical_detail::extract_handle(st, k0, a_sym, b_sym);
  std::vector<int> canon;
  for(std::size_t q = 0; q < a_sym.size(); ++q) {
    canon.push_back(a_sym[q]); canon.push_back(b_sym[q]); canon.push_back(-a_sym[q]); canon.push_back(-b_sym[q]);
  }
  if(st.W != canon || st.expr_of(canon) != free_reduce(R)) throw std::invalid_argument("make_canonical: cut and paste failed");
  Canonical_change res;
  std::vector<int> id_of(st.expr.size(), 0);
  for(std::size_t q = 0; q < a_sym.size(); ++q) {
    id_of[std::size_t(a_sym[q])] = int(2 * q + 1); id_of[std::size_t(b_sym[q])] = int(2 * q + 2);
    res.new_in_old.push_back(st.expr[std::size_t(a_sym[q])]);
    res.new_in_old.push_back(st.expr[std::size_t(b_sym[q])]);
  }
  for(const auto& w : st.inv) {
    std::vector<int> r;
    for(int l : w) {
      const int id = id_of[std::size_t(std::abs(l))];
      if(id == 0) throw std::invalid_argument("make_canonical: leftover symbol");
      r.push_back(l > 0 ? id : -id);
    }
    res.old_in_new.push_back(free_reduce(r));
  }
  return res;
}

} // namespace internal
} // namespace Hyperbolic_surface_2
} // namespace CGAL

#endif // CGAL_HYPERBOLIC_SURFACE_2_INTERNAL_SURFACE_GROUP_WORDS_H
