// Copyright (c) 2026 CGAL Hyperbolic Conformal Geometry project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Free and Dehn reduction of words in a one-relator group (the surface group <a1,b1,...,ag,bg | R>).
// Letters are non-zero integers, -x is the inverse of x.
#ifndef CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORDS_H
#define CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORDS_H

#include <deque>
#include <vector>

namespace CGAL {
namespace Surface_shortest_words {
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

} // namespace internal
} // namespace Surface_shortest_words
} // namespace CGAL

#endif // CGAL_SURFACE_SHORTEST_WORDS_INTERNAL_WORDS_H
