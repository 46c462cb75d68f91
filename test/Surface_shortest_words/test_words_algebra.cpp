// Tests of the word algebra of Surface_shortest_words: geodesic words in the surface group and the cut and
// paste to a canonical system. Independent references:
//  - a faithful representation of the surface group <a1, b1, ... | [a1, b1] ... [ag, bg]> in PSU(1, 1): the
//    side pairings of the regular 4g-gon, computed here in quadruple precision (__float128) from the polygon
//    only; group elements are compared through the image of the origin (distinct elements of the orbit are
//    more than 1e-10 apart for the word lengths used, rounding errors are below 1e-20);
//  - shortest word lengths by breadth-first search in the Cayley graph (balls B_R), meet in the middle for
//    longer words: l(w) = k + min over x in the sphere S_k of l(x^-1 w);
//  - free-group identities for the cut and paste (the substitution must map the canonical relator onto R).
#include <CGAL/Hyperbolic_surface_2/internal/surface_group_words.h>

#include "cgal_hc_test.h"
#include "fuchsian_reference.h"


#include <algorithm>
#include <map>
#include <memory>
#include <cctype>
#include <functional>
#include <iostream>
#include <string>
#include <cmath>
#include <cstdint>
#include <deque>
#include <random>
#include <unordered_map>
#include <vector>

namespace W = CGAL::Hyperbolic_surface_2::internal;

using namespace ssw_test;

namespace {

Word random_reduced_word(int g, std::size_t n, std::mt19937& rng)
{
  Word w;
  while(w.size() < n) {
    int l = int(rng() % (2 * g)) + 1;
    if(rng() % 2) l = -l;
    if(!w.empty() && w.back() == -l) continue;
    w.push_back(l);
  }
  return w;
}

// the ccw cyclic order of the directions around a vertex of the Cayley graph, computed by brute force from
// the faces of the Cayley complex (independent of surface_relator_link): direction d is followed by d' iff
// some cyclic conjugate of R or R^-1 reads ... d'^-1 d ...
std::vector<int> ccw_next_directions(const Word& R)
{
  const int n = int(R.size()) / 2;
  std::vector<int> next(std::size_t(2 * n + 1), 0); // index l + n
  for(std::size_t i = 0; i < R.size(); ++i) next[std::size_t(R[(i + 1) % R.size()] + n)] = -R[i];
  return next;
}

// a word that runs along a chain of k tiles on the left or right (2g edges on the first and the last tile,
// 2g - 1 on the others), starting with the letter `first`
Word chain_word(const Word& R, int first, int k, bool left)
{
  const int n = int(R.size()) / 2, h = n;
  const std::vector<int> next = ccw_next_directions(R);
  std::vector<int> prev(next.size(), 0);
  for(int l = -n; l <= n; ++l) if(l) prev[std::size_t(next[std::size_t(l + n)] + n)] = l;
  // turn t on the left: y with t ccw steps from y to x^-1, i.e. y = prev^t(x^-1)
  auto step = [&](int x, int t) {
    int y = -x;
    for(int s = 0; s < t; ++s) y = left ? prev[std::size_t(y + n)] : next[std::size_t(y + n)];
    return y;
  };
  Word w{first};
  for(int j = 0; j < k; ++j) {
    const int edges = (j == 0 || j == k - 1) ? h : h - 1;
    for(int e = (j == 0 ? 1 : 0); e < edges; ++e) w.push_back(step(w.back(), e == 0 ? 2 : 1));
  }
  return w;
}

Word parse(const std::string& s) // "a1 b1^-1 ..." -> letters
{
  Word w;
  std::size_t i = 0;
  while(i < s.size()) {
    if(s[i] == ' ') { ++i; continue; }
    const bool a = s[i] == 'a';
    ++i;
    int k = 0;
    while(i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) k = 10 * k + (s[i++] - '0');
    int l = a ? 2 * k - 1 : 2 * k;
    if(s.compare(i, 3, "^-1") == 0) { l = -l; i += 3; }
    w.push_back(l);
  }
  return w;
}

} // namespace

CGAL_HC_TEST_CASE(fuchsian_reference_satisfies_the_relator)
{
  for(int g : {2, 3, 4}) {
    Fuchsian_group G(g);
    const M r = G.word(W::canonical_relator(g));
    CGAL_HC_CHECK_MSG(norm2(r.origin_image()) < Q(1e-40), double(norm2(r.origin_image())));
    // and nothing short is trivial (a sanity check of faithfulness on the generators and their products)
    for(int l = 1; l <= 2 * g; ++l) CGAL_HC_CHECK(norm2(G.letter(l).origin_image()) > Q(0.1));
  }
}

// every freely reduced word up to length 7 (genus 2) / 5 (genus 3): the result is the same element and its
// length is the breadth-first-search distance
CGAL_HC_TEST_CASE(geodesic_words_exhaustive)
{
  for(int g : {2, 3}) {
    const int L = ball_radius(g);
    const Fuchsian_group& G = fuchsian(g);
    const Ball& ball = ball_of(g);
    const W::Geodesic_word_reducer red(W::canonical_relator(g));
    long words = 0, wrong_length = 0, wrong_element = 0;
    Word w;
    std::vector<M> pre{M()};
    // depth-first enumeration of the freely reduced words
    std::function<void()> rec = [&]() {
      if(!w.empty()) {
        ++words;
        const Word r = red.reduce(w);
        const int best = ball.length(pre.back(), 0);
        if(int(r.size()) != best) { if(++wrong_length < 5) std::cerr << "  length: " << W::free_reduce(w).size() << " -> " << r.size() << " vs " << best << std::endl; }
        if(!ball.same(G.word(r), pre.back())) ++wrong_element;
      }
      if(int(w.size()) == L) return;
      for(int l = -2 * g; l <= 2 * g; ++l) {
        if(l == 0 || (!w.empty() && w.back() == -l)) continue;
        w.push_back(l); pre.push_back(pre.back() * G.letter(l));
        rec();
        w.pop_back(); pre.pop_back();
      }
    };
    rec();
    std::cout << "  genus " << g << ": " << words << " words of length <= " << L << ", ball of " << ball.elems.size()
              << " elements, " << wrong_length << " not shortest, " << wrong_element << " wrong element" << std::endl;
    CGAL_HC_CHECK(wrong_length == 0);
    CGAL_HC_CHECK(wrong_element == 0);
  }
}

// random words of length up to 12 (genus 2) / 10 (genus 3), many of them built from pieces of tiles (where
// Dehn's algorithm is not enough): meet in the middle
CGAL_HC_TEST_CASE(geodesic_words_random_long)
{
  for(int g : {2, 3}) {
    const int R = ball_radius(g), L = g == 2 ? 12 : 10;
    const Fuchsian_group& G = fuchsian(g);
    const Ball& ball = ball_of(g);
    const Word Rel = W::canonical_relator(g);
    const W::Geodesic_word_reducer red(Rel);
    std::mt19937 rng(17 + g);
    long checked = 0, shorter_than_dehn = 0, failures = 0;
    for(int trial = 0; trial < (g == 2 ? 500 : 300); ++trial) {
      // uniform random words, and random words around a chain of 2 or 3 tiles (genus 2: 8 or 11 letters)
      const std::size_t n = std::size_t(L - int(rng() % 4));
      Word w;
      if(trial % 2 == 0 || g > 2) w = random_reduced_word(g, n, rng);
      else {
        int first = int(rng() % 4) + 1; if(rng() % 2) first = -first;
        const Word c = chain_word(Rel, first, 2 + int(rng() % 2), rng() % 2 == 0);
        const std::size_t extra = n > c.size() ? n - c.size() : 0, before = extra ? rng() % (extra + 1) : 0;
        W::append_reduced(w, random_reduced_word(g, before, rng));
        W::append_reduced(w, c);
        W::append_reduced(w, random_reduced_word(g, extra - before, rng));
      }
      const Word r = red.reduce(w);
      const M m = G.word(w);
      const int best = ball.length(m, L - R);
      ++checked;
      if(W::dehn_reduce(w, Rel).size() > r.size()) ++shorter_than_dehn;
      const bool ok = int(r.size()) == best && ball.same(G.word(r), m);
      if(!ok) ++failures;
      CGAL_HC_CHECK_MSG(ok, "genus " << g << " word of length " << w.size() << " -> " << r.size() << ", shortest " << best);
    }
    std::cout << "  genus " << g << ": " << checked << " words of length <= " << L << ", " << shorter_than_dehn
              << " shorter than Dehn's algorithm gives, " << failures << " failures" << std::endl;
    if(g == 2) CGAL_HC_CHECK(shorter_than_dehn > 20); // genus 3: chains have >= 12 letters
  }
}

// chains of half-relators of every length up to 40 (genus 2..4), on both sides and from every first letter:
// Dehn's algorithm leaves them, the geodesic reduction shortens them by 2; checked: same element (Dehn's
// algorithm decides the word problem), not longer than a short-word oracle allows on every window of the
// result, and for lengths <= 12 / 10 the exact length by meet in the middle
CGAL_HC_TEST_CASE(chains_of_half_relators)
{
  for(int g : {2, 3, 4}) {
    const Word Rel = W::canonical_relator(g);
    const W::Geodesic_word_reducer red(Rel);
    const Fuchsian_group& G = fuchsian(g);
    const Ball& ball = ball_of(g);
    const int R = ball_radius(g);
    long chains = 0;
    for(int k = 2; k * (2 * g - 1) + 2 <= 40; ++k)
      for(int first = -2 * g; first <= 2 * g; ++first) {
        if(first == 0) continue;
        for(bool left : {true, false}) {
          const Word w = chain_word(Rel, first, k, left);
          const Word r = red.reduce(w);
          ++chains;
          CGAL_HC_CHECK_MSG(W::dehn_reduce(w, Rel).size() == w.size(), "Dehn's algorithm shortens a chain?");
          CGAL_HC_CHECK_MSG(r.size() + 2 == w.size(), "genus " << g << " chain of " << k << " tiles, length " << w.size() << " -> " << r.size());
          Word check = r;
          W::append_reduced(check, W::inverse(w));
          CGAL_HC_CHECK(W::dehn_reduce(check, Rel).empty());
          // every window of R + 1 letters of the result is geodesic; whole words within reach: exact length
          for(std::size_t s = 0; s + std::size_t(R) + 1 <= r.size(); s += 2) {
            const Word win(r.begin() + std::ptrdiff_t(s), r.begin() + std::ptrdiff_t(s) + R + 1);
            CGAL_HC_CHECK(ball.length(G.word(win), 1) == R + 1);
          }
          if(int(w.size()) <= R + 5) CGAL_HC_CHECK(ball.length(G.word(w), int(w.size()) - R) == int(r.size()));
        }
      }
    std::cout << "  genus " << g << ": " << chains << " chains" << std::endl;
  }
}

CGAL_HC_TEST_CASE(issue_examples)
{
  {
    const Word Rel = W::canonical_relator(3);
    const Word w = parse("a1 b1 a1^-1 b1^-1 a2 b2 b2 a2^-1 b2^-1 a3 b3 a3^-1");
    const Word s = parse("b3 a3 b3^-1 a3^-1 b2 b1 a1 b1^-1 a1^-1 b3");
    const Word r = W::geodesic_reduce(w, Rel);
    CGAL_HC_CHECK(r.size() == 10);
    Word c = r; W::append_reduced(c, W::inverse(s));
    CGAL_HC_CHECK(W::dehn_reduce(c, Rel).empty());
    CGAL_HC_CHECK(ball_of(3).length(fuchsian(3).word(w), 5) == 10);
  }
  {
    const Word Rel = W::canonical_relator(2);
    const Word w = parse("b2^-1 a1 b1 a1^-1 a1^-1 b1^-1 a2 b2");
    const Word r = W::geodesic_reduce(w, Rel);
    CGAL_HC_CHECK(r.size() == 6);
    Word c = r; W::append_reduced(c, W::inverse(parse("a2 b2^-1 a2^-1 a1^-1 b2 a2")));
    CGAL_HC_CHECK(W::dehn_reduce(c, Rel).empty());
  }
}

// ------------------------------------------------------------------------- cut and paste

namespace {

// a random one-vertex orientable gluing of the 4g-gon: random pairing of the sides with opposite
// orientations, kept if the vertex link is one cycle (counted here by union-find on the corners)
Word random_one_vertex_relator(int g, std::mt19937& rng)
{
  const int m = 4 * g, n = 2 * g;
  for(;;) {
    std::vector<int> sides(static_cast<std::size_t>(m));
    for(int i = 0; i < m; ++i) sides[std::size_t(i)] = i;
    std::shuffle(sides.begin(), sides.end(), rng);
    Word R(static_cast<std::size_t>(m), 0);
    std::vector<int> perm(static_cast<std::size_t>(n));
    for(int i = 0; i < n; ++i) perm[std::size_t(i)] = i + 1;
    std::shuffle(perm.begin(), perm.end(), rng);
    for(int i = 0; i < n; ++i) {
      const int sgn = rng() % 2 ? 1 : -1;
      R[std::size_t(sides[std::size_t(2 * i)])] = sgn * perm[std::size_t(i)];
      R[std::size_t(sides[std::size_t(2 * i + 1)])] = -sgn * perm[std::size_t(i)];
    }
    // corners: corner i is between side i-1 and side i (vertex = start of side i). Gluing side x (i) with
    // X (j, traversed backwards): start(i) ~ end(j) = start(j+1), end(i) = start(i+1) ~ start(j)
    std::vector<int> uf(static_cast<std::size_t>(m));
    for(int i = 0; i < m; ++i) uf[std::size_t(i)] = i;
    std::function<int(int)> find = [&](int x) { return uf[std::size_t(x)] == x ? x : uf[std::size_t(x)] = find(uf[std::size_t(x)]); };
    for(int i = 0; i < m; ++i)
      for(int j = 0; j < m; ++j)
        if(R[std::size_t(i)] > 0 && R[std::size_t(j)] == -R[std::size_t(i)]) {
          uf[std::size_t(find(i))] = find((j + 1) % m);
          uf[std::size_t(find((i + 1) % m))] = find(j);
        }
    int classes = 0;
    for(int i = 0; i < m; ++i) if(find(i) == i) ++classes;
    if(classes == 1) return R;
  }
}

} // namespace

CGAL_HC_TEST_CASE(make_canonical_random_relators)
{
  std::mt19937 rng(2026);
  for(int g = 2; g <= 8; ++g) {
    long ok = 0, failed = 0;
    const int trials = 1000;
    for(int t = 0; t < trials; ++t) {
      const Word R = random_one_vertex_relator(g, rng);
      bool good = true;
      try {
        const W::Canonical_change c = W::make_canonical(R);
        // the canonical relator written in the old letters is R (a conjugate of R in the free group)
        const Word img = W::substitute(W::canonical_relator(g), c.new_in_old);
        Word cyc = img;
        while(cyc.size() >= 2 && cyc.front() == -cyc.back()) { cyc.erase(cyc.begin()); cyc.pop_back(); }
        bool conj = false;
        for(std::size_t s = 0; s < R.size() && !conj && cyc.size() == R.size(); ++s) {
          conj = true;
          for(std::size_t i = 0; i < R.size() && conj; ++i) conj = cyc[(i + s) % R.size()] == R[i];
        }
        good = conj && c.new_in_old.size() == std::size_t(2 * g) && c.old_in_new.size() == std::size_t(2 * g);
        // the two substitutions are inverse automorphisms of the free group
        for(int i = 1; good && i <= 2 * g; ++i) {
          good = W::substitute(W::substitute(Word{i}, c.old_in_new), c.new_in_old) == Word{i} &&
                 W::substitute(W::substitute(Word{i}, c.new_in_old), c.old_in_new) == Word{i};
        }
      } catch(const std::exception& e) {
        good = false;
        if(failed < 3) std::cerr << "  genus " << g << ": " << e.what() << std::endl;
      }
      (good ? ok : failed)++;
    }
    std::cout << "  genus " << g << ": " << ok << " of " << trials << " random relators made canonical" << std::endl;
    CGAL_HC_CHECK(failed == 0);
  }
  // the issue's example, and invalid relators throw
  const Word ex{-3, 4, 6, 5, -1, 2, 3, -5, -4, 1, -6, -2};
  CGAL_HC_CHECK(W::substitute(W::canonical_relator(3), W::make_canonical(ex).new_in_old).size() == ex.size());
  CGAL_HC_CHECK_THROWS(W::make_canonical(Word{1, 2, 1, 2}), std::invalid_argument);     // Klein bottle-like
  CGAL_HC_CHECK_THROWS(W::make_canonical(Word{1, -1, 2, -2}), std::invalid_argument);   // two vertices
  CGAL_HC_CHECK_THROWS(W::make_canonical(Word{1, 2, -1, 3}), std::invalid_argument);
  CGAL_HC_CHECK_THROWS(W::Geodesic_word_reducer(Word{1, 2, -1, -2}), std::invalid_argument); // genus 1
}

namespace {
// Dehn's algorithm as it was written before the candidate index (all 2n cyclic conjugates and every piece length
// tried for each pushed letter): the reference of the indexed version, which must return the very same word.
Word dehn_reduce_reference(const Word& w, const Word& R)
{
  const std::size_t n = R.size();
  std::vector<Word> rot;
  const Word Ri = W::inverse(R);
  for(std::size_t r = 0; r < n; ++r) {
    Word c1, c2;
    for(std::size_t i = 0; i < n; ++i) { c1.push_back(R[(r + i) % n]); c2.push_back(Ri[(r + i) % n]); }
    rot.push_back(c1); rot.push_back(c2);
  }
  Word S;
  std::deque<int> todo(w.begin(), w.end());
  while(!todo.empty()) {
    const int x = todo.front(); todo.pop_front();
    if(!S.empty() && S.back() == -x) { S.pop_back(); continue; }
    S.push_back(x);
    bool replaced = false;
    for(const Word& c : rot) {
      for(std::size_t L = n; L > n / 2 && !replaced; --L) {
        if(S.size() < L || S.back() != c[L - 1]) continue;
        bool match = true;
        for(std::size_t t = 0; t < L && match; ++t) match = S[S.size() - L + t] == c[t];
        if(!match) continue;
        S.resize(S.size() - L);
        Word rep;
        for(std::size_t t = n; t > L; --t) rep.push_back(-c[t - 1]);
        todo.insert(todo.begin(), rep.begin(), rep.end());
        replaced = true;
      }
      if(replaced) break;
    }
  }
  return S;
}
} // namespace

// The indexed Dehn reduction returns exactly the reference's word: random words and words built from long
// relator pieces (which trigger replacements, cascading), canonical and random one-vertex relators, genus 2 to 8
// and 133 (cheese.off's genus, where the index is what makes the pipeline take seconds).
CGAL_HC_TEST_CASE(dehn_reduce_matches_reference)
{
  std::mt19937 rng(133);
  long compared = 0, replaced = 0;
  for(int g : {2, 3, 4, 5, 8, 133}) {
    for(int variant = 0; variant < (g > 8 ? 1 : 2); ++variant) {
      const Word R = variant == 0 ? W::canonical_relator(g) : random_one_vertex_relator(g, rng);
      const std::size_t n = R.size();
      const int trials = g > 8 ? 8 : 300;
      for(int t = 0; t < trials; ++t) {
        Word w;
        const int parts = 1 + int(rng() % 6);
        for(int p = 0; p < parts; ++p) {
          if(rng() % 2) { // a piece of a cyclic conjugate of R or R^-1, longer than half
            const Word c = rng() % 2 ? R : W::inverse(R);
            const std::size_t r = rng() % n, L = n / 2 + 1 + rng() % (n - n / 2);
            for(std::size_t i = 0; i < L; ++i) w.push_back(c[(r + i) % n]);
          } else {
            const int len = int(rng() % 12);
            for(int i = 0; i < len; ++i) { const int l = 1 + int(rng() % (2 * g)); w.push_back(rng() % 2 ? l : -l); }
          }
        }
        const Word a = W::dehn_reduce(w, R), b = dehn_reduce_reference(w, R);
        CGAL_HC_CHECK_MSG(a == b, "genus " << g << ": indexed Dehn reduction differs from the reference");
        ++compared;
        if(b.size() < W::free_reduce(w).size()) ++replaced;
      }
    }
  }
  std::cout << "  " << compared << " words compared, " << replaced << " shortened by a relator piece" << std::endl;
  CGAL_HC_CHECK(replaced > compared / 4);
}

namespace {
// the word with first letter `first` and then the given turns (number of tiles on the left, 1 .. 4g - 1)
Word word_from_turns(const Word& R, int first, const std::vector<int>& turns)
{
  const int n = int(R.size()) / 2;
  const std::vector<int> next = ccw_next_directions(R);
  std::vector<int> prev(next.size(), 0);
  for(int l = -n; l <= n; ++l) if(l) prev[std::size_t(next[std::size_t(l + n)] + n)] = l;
  Word w{first};
  for(int t : turns) {
    int y = -w.back();
    for(int s = 0; s < t; ++s) y = prev[std::size_t(y + n)];
    w.push_back(y);
  }
  return w;
}
} // namespace

// The cost proof of Geodesic_word_reducer (O(g |w|)), checked on every word: at most one rule per letter of
// w, at most one chain mark created by a replacement, and the total work within the proven bound. Words made to
// stress chains: long chains, chains glued to chains of the other side, turn sequences of pieces of 2g - 1 and
// 2g edges with junctions (both sides, random), the half relator repeated, random words; genus 2 to 8, the
// canonical relator and random one-vertex relators; lengths up to 10^5.
CGAL_HC_TEST_CASE(reduction_work_is_linear)
{
  std::mt19937 rng(4242);
  long words = 0, rules = 0, chain_rules = 0;
  for(int g = 2; g <= 8; ++g) {
    const int p = 4 * g, h = 2 * g;
    double worst_ratio = 0;
    std::size_t most_replaced = 0, most_marks = 0;
    for(int relator = 0; relator < 3; ++relator) {
      const Word Rel = relator == 0 ? W::canonical_relator(g) : random_one_vertex_relator(g, rng);
      const W::Geodesic_word_reducer red(Rel);
      auto check = [&](const Word& w, const char* family) {
        W::Reduction_statistics st;
        const Word r = red.reduce(w, &st);
        ++words;
        rules += long(st.free_cancellations + st.dehn_rules + st.chain_rules);
        chain_rules += long(st.chain_rules);
        most_replaced = (std::max)(most_replaced, st.replaced_letters);
        most_marks = (std::max)(most_marks, st.max_marks_per_replacement);
        CGAL_HC_CHECK_MSG(st.max_rules_per_input_letter <= 1, family << ", genus " << g << ", |w| = " << w.size()
                          << ": " << st.max_rules_per_input_letter << " rules for one letter");
        CGAL_HC_CHECK_MSG(st.max_marks_per_replacement <= 1, family << ", genus " << g << ": a replacement created "
                          << st.max_marks_per_replacement << " marks");
        CGAL_HC_CHECK_MSG(st.work() <= W::Reduction_statistics::bound(g, w.size()), family << ", genus " << g
                          << ": work " << st.work() << " above the bound for |w| = " << w.size());
        CGAL_HC_CHECK(st.pushes >= r.size() && (w.size() - r.size()) % 2 == 0);
        CGAL_HC_CHECK(red.reduce(r).size() == r.size());
        if(w.size() <= 20000) { // the same element (Dehn's algorithm decides the word problem)
          Word q = r;
          W::append_reduced(q, W::inverse(w));
          CGAL_HC_CHECK_MSG(W::dehn_reduce(q, Rel).empty(), family << ": reduced word is another element");
        }
        if(!w.empty()) worst_ratio = (std::max)(worst_ratio, double(st.work()) / double(w.size()));
      };
      auto random_letter = [&]() { int l = int(rng() % unsigned(2 * g)) + 1; return rng() % 2 ? l : -l; };
      for(std::size_t n : {1000, 20000, 100000}) {
        check(random_reduced_word(g, n, rng), "random");
        // one long chain, on each side, alone and glued at both ends to random letters
        const int k = int(n / std::size_t(h - 1));
        for(bool left : {true, false}) {
          Word c = chain_word(Rel, random_letter(), k, left);
          check(c, "one chain");
          Word w = random_reduced_word(g, 5, rng);
          W::append_reduced(w, c);
          W::append_reduced(w, random_reduced_word(g, 5, rng));
          check(w, "chain with random ends");
        }
        // chains of random lengths glued to each other (either side), with 0 to 2 random letters between
        Word glued;
        while(glued.size() < n) {
          W::append_reduced(glued, chain_word(Rel, random_letter(), 2 + int(rng() % 40), rng() % 2 == 0));
          W::append_reduced(glued, random_reduced_word(g, rng() % 3, rng));
        }
        check(glued, "glued chains");
        // turn sequences made of pieces of 2g - 1 or 2g edges and junctions, on a random side per piece
        for(int variant = 0; variant < 3; ++variant) {
          std::vector<int> turns;
          bool left = true;
          while(turns.size() < n) {
            if(variant == 1 || rng() % 8 == 0) left = !left;
            const int edges = rng() % 4 == 0 ? h : h - 1;
            for(int e = 1; e < edges; ++e) turns.push_back(left ? 1 : p - 1);
            turns.push_back(variant == 2 && rng() % 5 == 0 ? (left ? 3 : p - 3) : (left ? 2 : p - 2));
          }
          check(word_from_turns(Rel, random_letter(), turns), "piece turns");
        }
        // the half relator repeated (a Dehn piece at every period), and half relator plus one letter
        Word half(Rel.begin(), Rel.begin() + h), rep;
        while(rep.size() < n) W::append_reduced(rep, half);
        check(rep, "half relator power");
        Word more(Rel.begin(), Rel.begin() + h + 1), rep2;
        while(rep2.size() < n) W::append_reduced(rep2, more);
        check(rep2, "long piece power");
      }
    }
    std::cout << "  genus " << g << ": work / |w| at most " << worst_ratio << " (bound "
              << double(W::Reduction_statistics::bound(g, 1)) << "), most letters replaced in one word "
              << most_replaced << ", most marks created by one replacement " << most_marks << std::endl;
  }
  std::cout << "  " << words << " words, " << rules << " rules (" << chain_rules << " chains)" << std::endl;
  CGAL_HC_CHECK(chain_rules > 1000);
}
