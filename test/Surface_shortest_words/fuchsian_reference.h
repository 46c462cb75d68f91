// A faithful representation of the surface group <a1, b1, ... | [a1, b1] ... [ag, bg]> in PSU(1, 1) for the
// tests: the side pairings of the regular 4g-gon (letter k = a_{(k+1)/2} for odd k, b_{k/2} for even k, the
// convention of Shortest_word_solver and Regular_polygon_surface), in quadruple precision (__float128), and
// balls of its Cayley graph by breadth-first search. Group elements are compared through the image of the
// origin: for the radii used, distinct orbit points are more than 1e-10 apart and rounding errors stay
// below 1e-20.
#ifndef SSW_TEST_FUCHSIAN_REFERENCE_H
#define SSW_TEST_FUCHSIAN_REFERENCE_H

#include <quadmath.h>

#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

namespace ssw_test {

typedef std::vector<int> Word;
typedef __float128 Q;
struct C { Q re = 0, im = 0; };
inline C operator+(C a, C b) { return {a.re + b.re, a.im + b.im}; }
inline C operator-(C a, C b) { return {a.re - b.re, a.im - b.im}; }
inline C operator*(C a, C b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
inline C conj(C a) { return {a.re, -a.im}; }
inline Q norm2(C a) { return a.re * a.re + a.im * a.im; }
inline C div(C a, C b) { const Q n = norm2(b); const C c = a * conj(b); return {c.re / n, c.im / n}; }
inline C polar(Q r, Q t) { return {r * cosq(t), r * sinq(t)}; }

// Moebius map z -> (a z + b) / (c z + d), kept with a d - b c = 1
struct M
{
  C a{1, 0}, b{0, 0}, c{0, 0}, d{1, 0};
  C apply(C z) const { return div(a * z + b, c * z + d); }
  M operator*(const M& o) const { M r; r.a = a * o.a + b * o.c; r.b = a * o.b + b * o.d; r.c = c * o.a + d * o.c; r.d = c * o.b + d * o.d; return r; }
  M inverse() const { M r; r.a = d; r.b = {-b.re, -b.im}; r.c = {-c.re, -c.im}; r.d = a; return r; }
  C origin_image() const { return div(b, d); }
};

inline M to_origin(C p) // z -> (z - p) / (1 - conj(p) z), scaled to determinant 1
{
  const Q s = 1 / sqrtq(1 - norm2(p));
  M m; m.a = {s, 0}; m.b = {-p.re * s, -p.im * s}; m.c = {-p.re * s, p.im * s}; m.d = {s, 0};
  return m;
}
inline M rotation(C u) // z -> u z, |u| = 1
{
  const Q t = atan2q(u.im, u.re) / 2;
  M m; m.a = polar(1, t); m.d = polar(1, -t);
  return m;
}
inline M frame(C p, C q) // p -> 0, q -> positive real axis
{
  const M t = to_origin(p);
  const C qq = t.apply(q);
  const Q r = sqrtq(norm2(qq));
  return rotation({qq.re / r, -qq.im / r}) * t;
}

// the holonomy of the regular 4g-gon with sides s_k = V_{k-1} V_k paired as a_i = s_{4i-3}, b_i = s_{4i-2}
struct Fuchsian_group
{
  int g;
  std::vector<M> gen; // gen[i] = rho(letter i+1)
  explicit Fuchsian_group(int g_) : g(g_)
  {
    const int n = 4 * g;
    const Q pi = acosq(Q(-1));
    const Q cot = 1 / tanq(pi / n);
    const Q r = tanhq(acoshq(cot * cot) / 2);
    auto V = [&](int k) { return polar(r, 2 * pi * (((k % n) + n) % n) / n); };
    auto partner = [](int k) { const int q = (k - 1) % 4; return q < 2 ? k + 2 : k - 2; };
    std::vector<M> T;
    for(int k = 1; k <= n; ++k) {
      const int j = partner(k);
      T.push_back(frame(V(k - 1), V(k)).inverse() * frame(V(j), V(j - 1)));
    }
    std::vector<M> E(std::size_t(n) + 1);
    for(int i = 1; i <= g; ++i) {
      E[std::size_t(4 * i - 1)] = T[std::size_t(4 * i - 2)] * E[std::size_t(4 * i - 4)];
      E[std::size_t(4 * i - 2)] = T[std::size_t(4 * i - 3)] * E[std::size_t(4 * i - 1)];
      E[std::size_t(4 * i - 3)] = T[std::size_t(4 * i - 4)] * E[std::size_t(4 * i - 2)];
      E[std::size_t(4 * i)] = T[std::size_t(4 * i - 1)] * E[std::size_t(4 * i - 3)];
    }
    for(int i = 1; i <= g; ++i) {
      gen.push_back(E[std::size_t(4 * i - 4)].inverse() * E[std::size_t(4 * i - 3)]);
      gen.push_back(E[std::size_t(4 * i - 3)].inverse() * E[std::size_t(4 * i - 2)]);
    }
  }
  M letter(int l) const { return l > 0 ? gen[std::size_t(l - 1)] : gen[std::size_t(-l - 1)].inverse(); }
  M word(const Word& w) const { M m; for(int l : w) m = m * letter(l); return m; }
};

// ball B_R of the Cayley graph by breadth-first search, elements identified by the image of the origin
struct Ball
{
  const Fuchsian_group& G;
  int R;
  std::vector<M> elems;
  std::vector<C> key;
  std::vector<int> len;
  std::vector<std::size_t> sphere_begin; // sphere_begin[k] = first element of length k
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t> > cells;
  static constexpr double cell = 1e-13, tol = 1e-16;

  static std::int64_t cell_of(Q x) { return std::int64_t(floorq(x / Q(cell))); }
  static std::uint64_t hash(std::int64_t i, std::int64_t j) { return std::uint64_t(i) * 0x9E3779B97F4A7C15ull ^ std::uint64_t(j); }
  long find(const C& z) const
  {
    const std::int64_t i = cell_of(z.re), j = cell_of(z.im);
    for(std::int64_t di = -1; di <= 1; ++di)
      for(std::int64_t dj = -1; dj <= 1; ++dj) {
        auto it = cells.find(hash(i + di, j + dj));
        if(it == cells.end()) continue;
        for(std::uint32_t e : it->second)
          if(norm2(key[e] - z) < Q(tol) * Q(tol)) return long(e);
      }
    return -1;
  }
  void add(const M& m, const C& z, int l)
  {
    cells[hash(cell_of(z.re), cell_of(z.im))].push_back(std::uint32_t(elems.size()));
    elems.push_back(m); key.push_back(z); len.push_back(l);
  }
  Ball(const Fuchsian_group& G_, int R_) : G(G_), R(R_)
  {
    add(M(), M().origin_image(), 0);
    sphere_begin.push_back(0);
    std::size_t begin = 0;
    for(int r = 1; r <= R; ++r) {
      const std::size_t end = elems.size();
      sphere_begin.push_back(end);
      for(std::size_t i = begin; i < end; ++i)
        for(int l = -2 * G.g; l <= 2 * G.g; ++l) {
          if(l == 0) continue;
          const M e = elems[i] * G.letter(l);
          const C z = e.origin_image();
          if(find(z) < 0) add(e, z, r);
        }
      begin = end;
    }
    sphere_begin.push_back(elems.size());
  }
  // the length of the shortest word of m if it is <= R + k (meet in the middle over S_k), else -1
  int length(const M& m, int k) const
  {
    const long j = find(m.origin_image());
    if(j >= 0) return len[std::size_t(j)];
    for(int s = 1; s <= k; ++s) {
      for(std::size_t i = sphere_begin[std::size_t(s)]; i < sphere_begin[std::size_t(s) + 1]; ++i) {
        const long t = find((elems[i].inverse() * m).origin_image());
        if(t >= 0 && len[std::size_t(t)] == R) return s + R; // l(m) > R: a geodesic passes through S_s and B_R
      }
    }
    return -1;
  }
  bool same(const M& a, const M& b) const { return norm2(a.origin_image() - b.origin_image()) < Q(tol) * Q(tol); }
};

// one ball per genus, shared by the cases: radius 7 (genus 2), 5 (genus 3), 4 (genus 4)
inline const Fuchsian_group& fuchsian(int g)
{
  static std::map<int, std::unique_ptr<Fuchsian_group> > groups;
  auto& p = groups[g];
  if(!p) p.reset(new Fuchsian_group(g));
  return *p;
}
inline int ball_radius(int g) { return g == 2 ? 7 : (g == 3 ? 5 : 4); }
inline const Ball& ball_of(int g)
{
  static std::map<int, std::unique_ptr<Ball> > balls;
  auto& p = balls[g];
  if(!p) p.reset(new Ball(fuchsian(g), ball_radius(g)));
  return *p;
}

// the length d(V_0, rho(w) V_0) of the shortest loop through the polygon's corner V_0 in the class of w (2 acosh
// |a| of the SU(1,1) matrix of rho(w) conjugated to move V_0 to the origin), and the translation length
// 2 acosh(|tr rho(w)| / 2) (the closed geodesic), in quadruple precision
inline Q acosh_q(Q x) { return x > Q(1e30) ? logq(2 * x) : acoshq(x); }
inline double based_length_q(int g, const Word& w)
{
  const Fuchsian_group& G = fuchsian(g);
  const Q pi = acosq(Q(-1)), n = 4 * g, cot = 1 / tanq(pi / n);
  const M t = to_origin(polar(tanhq(acoshq(cot * cot) / 2), 0));
  const M m = t * G.word(w) * t.inverse();
  return double(2 * acosh_q(sqrtq(norm2(m.a))));
}
inline double free_length_q(int g, const Word& w)
{
  const M m = fuchsian(g).word(w);
  const C tr = m.a + m.d;
  return double(2 * acosh_q(sqrtq(norm2(tr)) / 2));
}

} // namespace ssw_test

#endif // SSW_TEST_FUCHSIAN_REFERENCE_H
