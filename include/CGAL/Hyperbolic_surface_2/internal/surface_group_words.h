// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Free and Dehn reduction of words in a one-relator group (the surface group <a1,b1,...,ag,bg | R>).
// Letters are non-zero integers, -x is the inverse of x.
#ifndef CGAL_HYPERBOLIC_SURFACE_2_INTERNAL_SURFACE_GROUP_WORDS_H
#define CGAL_HYPERBOLIC_SURFACE_2_INTERNAL_SURFACE_GROUP_WORDS_H

#include <cstdlib>
#include <deque>
#include <stdexcept>
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
/// Stack based, linear in |w| (times |R|^2). The result represents the same group element.
inline std::vector<int> dehn_reduce(const std::vector<int>& w, const std::vector<int>& R)
{
  const std::size_t n = R.size();
  std::vector<std::vector<int> > rot;
  const std::vector<int> Ri = inverse(R);
  for(std::size_t r = 0; r < n; ++r) {
    std::vector<int> c1, c2;
    for(std::size_t i = 0; i < n; ++i) { c1.push_back(R[(r + i) % n]); c2.push_back(Ri[(r + i) % n]); }
    rot.push_back(c1); rot.push_back(c2);
  }
  std::vector<int> S;
  std::deque<int> todo(w.begin(), w.end());
  while(!todo.empty()) {
    const int x = todo.front(); todo.pop_front();
    if(!S.empty() && S.back() == -x) { S.pop_back(); continue; }
    S.push_back(x);
    bool replaced = false;
    for(const std::vector<int>& c : rot) {
      for(std::size_t L = n; L > n / 2 && !replaced; --L) {
        if(S.size() < L || S.back() != c[L - 1]) continue;
        bool match = true;
        for(std::size_t t = 0; t < L && match; ++t) match = S[S.size() - L + t] == c[t];
        if(!match) continue;
        S.resize(S.size() - L);
        // c[0..L) = (c[L..n))^-1
        std::vector<int> rep;
        for(std::size_t t = n; t > L; --t) rep.push_back(-c[t - 1]);
        todo.insert(todo.begin(), rep.begin(), rep.end());
        replaced = true;
      }
      if(replaced) break;
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

/// Cut and paste on the relator (classification of surfaces, done with Nielsen substitutions): turns a
/// relator R of an orientable closed surface of genus g (2g letters, each once with each sign) into the
/// canonical a1 b1 a1^-1 b1^-1 ... ag bg ag^-1 bg^-1. Throws std::invalid_argument if R is not of that kind.
inline Canonical_change make_canonical(const std::vector<int>& R)
{
  const int n = int(R.size()) / 2; // 2g letters
  // symbols: ids 1..; expr[id] = word in the old letters; W = relator in symbols; inv[i] = old letter i+1 in symbols
  std::vector<std::vector<int> > expr(static_cast<std::size_t>(n) + 1);
  for(int i = 1; i <= n; ++i) expr[std::size_t(i)] = std::vector<int>{i};
  std::vector<std::vector<int> > inv(static_cast<std::size_t>(n));
  for(int i = 1; i <= n; ++i) inv[std::size_t(i - 1)] = std::vector<int>{i};
  std::vector<int> W = R;
  auto expr_of = [&](const std::vector<int>& w) {
    std::vector<int> r;
    for(int l : w) append_reduced(r, l > 0 ? expr[std::size_t(l)] : inverse(expr[std::size_t(-l)]));
    return r;
  };
  auto new_symbol = [&](const std::vector<int>& e) { expr.push_back(e); return int(expr.size()) - 1; };
  // replaces symbol s (everywhere) by the word rep
  auto subst = [&](int s, const std::vector<int>& rep) {
    auto apply = [&](const std::vector<int>& w) {
      std::vector<int> r;
      for(int l : w) {
        if(std::abs(l) == s) append_reduced(r, l > 0 ? rep : inverse(rep));
        else append_reduced(r, std::vector<int>{l});
      }
      return r;
    };
    W = apply(W);
    for(auto& w : inv) w = apply(w);
  };
  auto sub = [](const std::vector<int>& w, std::size_t a, std::size_t b) {
    return std::vector<int>(w.begin() + std::ptrdiff_t(a), w.begin() + std::ptrdiff_t(b));
  };
  std::vector<int> a_sym, b_sym;
  for(int h = 0; h < n / 2; ++h) {
    const std::size_t k0 = 4 * std::size_t(h);
    if(W.size() < k0 + 4) throw std::invalid_argument("make_canonical: not a surface relator");
    std::vector<int> G = sub(W, k0, W.size());
    // find a rotation of G starting with a letter linked with another one
    std::size_t rot = G.size(), ix = 0, iy = 0, ixi = 0, iyi = 0;
    for(std::size_t r = 0; r < G.size() && rot == G.size(); ++r) {
      std::vector<int> Gr = sub(G, r, G.size()); Gr.insert(Gr.end(), G.begin(), G.begin() + std::ptrdiff_t(r));
      std::size_t xi = 0;
      while(xi < Gr.size() && Gr[xi] != -Gr[0]) ++xi;
      if(xi == Gr.size()) throw std::invalid_argument("make_canonical: a letter appears once only");
      for(std::size_t j = 1; j < xi; ++j) {
        std::size_t yj = xi + 1;
        while(yj < Gr.size() && Gr[yj] != -Gr[j]) ++yj;
        if(yj < Gr.size()) { rot = r; ix = 0; iy = j; ixi = xi; iyi = yj; break; }
      }
    }
    if(rot == G.size()) throw std::invalid_argument("make_canonical: no linked pair (not an orientable surface relator)");
    if(rot > 0) {
      // K X Y -> K' Y X with every earlier symbol s = X s' X^-1
      const std::vector<int> X = sub(G, 0, rot);
      for(std::size_t q = 0; q < a_sym.size(); ++q) {
        for(int* s : {&a_sym[q], &b_sym[q]}) {
          const int ns = new_symbol(expr_of([&] { std::vector<int> w = inverse(X); w.push_back(*s); append_reduced(w, X); return w; }()));
          std::vector<int> rep = X; rep.push_back(ns); append_reduced(rep, inverse(X));
          subst(*s, rep);
          *s = ns;
        }
      }
      // now W = K' X Y with K' = X^-1 K X written as K(s'): the relator X^-1 (K X Y) X = K' Y X
      std::vector<int> K = sub(W, 0, k0);
      W = K; append_reduced(W, sub(G, rot, G.size())); append_reduced(W, X);
      G = sub(W, k0, W.size());
    }
    (void)ix;
    const int x = G[0], y = G[iy];
    const std::vector<int> B = sub(G, 1, iy), C = sub(G, iy + 1, ixi), D = sub(G, ixi + 1, iyi), E = sub(G, iyi + 1, G.size());
    // step 1: y = B^-1 x^-1 y1
    {
      std::vector<int> xBy{x}; append_reduced(xBy, B); append_reduced(xBy, std::vector<int>{y});
      const int y1 = new_symbol(expr_of(xBy));
      std::vector<int> rep = inverse(B); append_reduced(rep, std::vector<int>{-x, y1});
      if(y > 0) subst(y, rep); else subst(-y, inverse(rep));
      // step 2: x = D v^-1 C with v = C x^-1 D
      std::vector<int> CxD = C; append_reduced(CxD, std::vector<int>{-x}); append_reduced(CxD, D);
      const int v = new_symbol(expr_of(CxD));
      std::vector<int> rep2 = D; append_reduced(rep2, std::vector<int>{-v}); append_reduced(rep2, C);
      if(x > 0) subst(x, rep2); else subst(-x, inverse(rep2));
      // step 3: y1 = D t^-1 with t = y1^-1 D
      std::vector<int> y1D{-y1}; append_reduced(y1D, D);
      const int t = new_symbol(expr_of(y1D));
      std::vector<int> rep3 = D; append_reduced(rep3, std::vector<int>{-t});
      subst(y1, rep3);
      // W = K D t^-1 v t v^-1 C B E: rotate D to the end (conjugating K)
      G = sub(W, k0, W.size());
      std::size_t dlen = D.size();
      if(dlen > 0) {
        const std::vector<int> X = sub(G, 0, dlen);
        for(std::size_t q = 0; q < a_sym.size(); ++q) {
          for(int* s : {&a_sym[q], &b_sym[q]}) {
            const int ns = new_symbol(expr_of([&] { std::vector<int> w = inverse(X); w.push_back(*s); append_reduced(w, X); return w; }()));
            std::vector<int> rep4 = X; rep4.push_back(ns); append_reduced(rep4, inverse(X));
            subst(*s, rep4);
            *s = ns;
          }
        }
        std::vector<int> K = sub(W, 0, k0);
        G = sub(W, k0, W.size());
        W = K; append_reduced(W, sub(G, dlen, G.size())); append_reduced(W, X);
      }
      // a = t^-1, b = v
      const int a = new_symbol(inverse(expr[std::size_t(t)]));
      subst(t, std::vector<int>{-a});
      a_sym.push_back(a); b_sym.push_back(v);
      (void)E;
    }
  }
  // check: W must read a1 b1 a1^-1 b1^-1 ...
  std::vector<int> canon;
  for(std::size_t q = 0; q < a_sym.size(); ++q) {
    canon.push_back(a_sym[q]); canon.push_back(b_sym[q]); canon.push_back(-a_sym[q]); canon.push_back(-b_sym[q]);
  }
  if(W != canon) throw std::invalid_argument("make_canonical: cut and paste failed");
  Canonical_change res;
  std::vector<int> id_of(expr.size(), 0);
  for(std::size_t q = 0; q < a_sym.size(); ++q) {
    id_of[std::size_t(a_sym[q])] = int(2 * q + 1); id_of[std::size_t(b_sym[q])] = int(2 * q + 2);
    res.new_in_old.push_back(expr[std::size_t(a_sym[q])]);
    res.new_in_old.push_back(expr[std::size_t(b_sym[q])]);
  }
  for(const auto& w : inv) {
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
