// Fixed-orientation norms with integer lengths, for epsilon-approximate Euclidean distances
// (Mitchell, "L1 shortest paths among polygonal obstacles", §6: fixed orientations).
//
// A path that may only run in a set of directions d_0 .. d_{m-1} (counter-clockwise, both senses
// of each orientation), paying w_i per unit of d_i, gives every vector v the length
//     N(v) = least sum of c_i w_i over the ways v = sum of c_i d_i, c_i >= 0,
// a norm whose unit ball is the convex hull of the points d_i / w_i. When every d_i / w_i is a
// vertex of that hull (strictly convex), the least way uses the two directions bracketing v, and
// on the cone between d_i and d_{i+1} N is the linear functional lambda_i with
// lambda_i . d_i = w_i and lambda_i . d_{i+1} = w_{i+1}; over all v, N(v) = max_i lambda_i . v.
//
// The sets here (FareyNorm<n>) make everything integral:
//   - directions: the fractions a/b of the Farey sequence of order n in [0, 1] give (b, a) in
//     the first octant, mirrored into the second ((a, b)) and turned by 90 degrees three times.
//     Neighbours in a Farey sequence have determinant 1, so consecutive directions here do too:
//     the frame (d_i, d_{i+1}) is unimodular and lambda_i is an integer vector;
//   - weights: w_i = ceil(kNormScale * |d_i|), the Euclidean length scaled and rounded up (exact
//     integer square root), so N(v) >= kNormScale * |v|;
//   - N(v) is an integer for every integer vector v.
// Strict convexity is checked at compile time (static_assert below).
//
// The bound (why the Euclidean geodesic distance d_E is bracketed): N >= S |.| with S =
// kNormScale, and N(v) = lambda_i . v <= |lambda_i| |v| on cone i, so S |v| <= N(v) <= Lambda |v|
// with Lambda = max_i |lambda_i|. For the geodesic distances among obstacles: the N-shortest
// path is a real path, so d_N >= S * (its Euclidean length) >= S d_E; the Euclidean-shortest
// path has N-length <= Lambda d_E, so d_N <= Lambda d_E. Hence d_E is in [d_N / Lambda, d_N / S],
// a relative width epsilon = Lambda / S - 1 (euclidean_epsilon()).
//   order 1: 8 directions (octilinear, but with the weight of a diagonal rounded up)
//   order 2: 16 directions (k = 8 orientations), order 3: 32 (k = 16), order 4: 48 (k = 24).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "geom/types.h"

namespace taut::geom {

inline constexpr std::int64_t kNormScale = 4096;

namespace fixed_norm_detail {
// ceil(sqrt(v)) for v >= 0, exact.
constexpr std::int64_t ceil_sqrt(std::int64_t v) {
  std::int64_t r = 0;
  std::int64_t bit = std::int64_t{1} << 31;
  while (bit > 0) {  // floor sqrt, one bit at a time
    const std::int64_t t = r + bit;
    if (t * t <= v) r = t;
    bit >>= 1;
  }
  return r * r == v ? r : r + 1;
}
constexpr int farey_count(int n) {  // fractions a/b in [0, 1] with b <= n, gcd 1
  int c = 0;
  for (int b = 1; b <= n; ++b)
    for (int a = 0; a <= b; ++a)
      if (std::gcd(a, b) == 1) ++c;
  return c;
}
}  // namespace fixed_norm_detail

template <int N>
struct FareyNorm {
  static constexpr int kOrder = N;
  static constexpr int kPerOctant = fixed_norm_detail::farey_count(N) - 1;
  static constexpr int kDirs = 8 * kPerOctant;  // directions; orientations: kDirs / 2

  struct Vec {
    std::int64_t x, y;
  };
  std::array<Vec, kDirs> dir{};
  std::array<std::int64_t, kDirs> weight{};
  std::array<Vec, kDirs> lambda{};  // cone i: from dir[i] to dir[(i + 1) % kDirs]

  // N(v) = max_i lambda_i . v (exact: |lambda| < 2^16 here, |v| < 2^32).
  constexpr std::int64_t length(std::int64_t dx, std::int64_t dy) const {
    std::int64_t best = lambda[0].x * dx + lambda[0].y * dy;
    for (const Vec& l : lambda) best = std::max(best, l.x * dx + l.y * dy);
    return best;
  }
  // Lambda^2 = max_i |lambda_i|^2.
  constexpr std::int64_t lambda_max_sq() const {
    std::int64_t m = 0;
    for (const Vec& l : lambda) m = std::max(m, l.x * l.x + l.y * l.y);
    return m;
  }
  // Lambda / S - 1, rounded up: the long double square root is off by about 2^-64 Lambda, so a
  // margin of 10^-15 keeps it above the true value (also after conversion to double).
  long double euclidean_epsilon() const {
    return std::sqrt(static_cast<long double>(lambda_max_sq())) / kNormScale - 1 + 1e-15L;
  }
  static constexpr FareyNorm make() {
    FareyNorm f;
    // Farey fractions of order N in [0, 1], ascending (by the standard next-term recurrence).
    std::array<Vec, kPerOctant + 1> frac{};  // (a, b) = a / b
    {
      std::int64_t a = 0, b = 1, c = 1, d = N;
      int i = 0;
      frac[i++] = {a, b};
      while (c <= N && i <= kPerOctant) {
        const std::int64_t k = (N + b) / d;
        const std::int64_t na = c, nb = d, nc = k * c - a, nd = k * d - b;
        a = na;
        b = nb;
        c = nc;
        d = nd;
        frac[i++] = {a, b};
        if (a == 1 && b == 1) break;
      }
    }
    int k = 0;
    std::array<Vec, 2 * kPerOctant> quarter{};
    for (int i = 0; i < kPerOctant; ++i) quarter[k++] = {frac[i].y, frac[i].x};  // (b, a)
    for (int i = kPerOctant; i > 0; --i) quarter[k++] = {frac[i].x, frac[i].y};  // (a, b)
    for (int r = 0; r < 4; ++r)
      for (int i = 0; i < 2 * kPerOctant; ++i) {
        Vec v = quarter[i];
        for (int t = 0; t < r; ++t) v = {-v.y, v.x};
        f.dir[r * 2 * kPerOctant + i] = v;
      }
    for (int i = 0; i < kDirs; ++i)
      f.weight[i] = fixed_norm_detail::ceil_sqrt(kNormScale * kNormScale *
                                                 (f.dir[i].x * f.dir[i].x + f.dir[i].y * f.dir[i].y));
    for (int i = 0; i < kDirs; ++i) {
      const Vec e = f.dir[i], g = f.dir[(i + 1) % kDirs];
      const std::int64_t we = f.weight[i], wg = f.weight[(i + 1) % kDirs];
      f.lambda[i] = {we * g.y - wg * e.y, -we * g.x + wg * e.x};  // det(e, g) == 1
    }
    return f;
  }

  // Consecutive directions have determinant 1, lambda_i meets its two weights, and the norm is
  // strictly convex: lambda_i . d_j < w_j for every other direction j.
  constexpr bool consistent() const {
    for (int i = 0; i < kDirs; ++i) {
      const Vec e = dir[i], g = dir[(i + 1) % kDirs];
      if (e.x * g.y - e.y * g.x != 1) return false;
      const Vec l = lambda[i];
      if (l.x * e.x + l.y * e.y != weight[i]) return false;
      if (l.x * g.x + l.y * g.y != weight[(i + 1) % kDirs]) return false;
      for (int j = 0; j < kDirs; ++j) {
        if (j == i || j == (i + 1) % kDirs) continue;
        if (l.x * dir[j].x + l.y * dir[j].y >= weight[j]) return false;
      }
    }
    return true;
  }
};

inline constexpr FareyNorm<1> kFarey1 = FareyNorm<1>::make();
inline constexpr FareyNorm<2> kFarey2 = FareyNorm<2>::make();
inline constexpr FareyNorm<3> kFarey3 = FareyNorm<3>::make();
inline constexpr FareyNorm<4> kFarey4 = FareyNorm<4>::make();
static_assert(kFarey1.consistent() && kFarey2.consistent() && kFarey3.consistent() &&
              kFarey4.consistent());
static_assert(FareyNorm<1>::kDirs == 8 && FareyNorm<2>::kDirs == 16 && FareyNorm<3>::kDirs == 32 &&
              FareyNorm<4>::kDirs == 48);

// The norm of order 1 to 4 chosen at run time: N(dx, dy), and epsilon (see above).
inline std::int64_t fixed_norm_length(int order, std::int64_t dx, std::int64_t dy) {
  switch (order) {
    case 1: return kFarey1.length(dx, dy);
    case 2: return kFarey2.length(dx, dy);
    case 3: return kFarey3.length(dx, dy);
    default: return kFarey4.length(dx, dy);
  }
}
inline long double fixed_norm_epsilon(int order) {
  switch (order) {
    case 1: return kFarey1.euclidean_epsilon();
    case 2: return kFarey2.euclidean_epsilon();
    case 3: return kFarey3.euclidean_epsilon();
    default: return kFarey4.euclidean_epsilon();
  }
}
inline std::int64_t fixed_norm_lambda_max_sq(int order) {
  switch (order) {
    case 1: return kFarey1.lambda_max_sq();
    case 2: return kFarey2.lambda_max_sq();
    case 3: return kFarey3.lambda_max_sq();
    default: return kFarey4.lambda_max_sq();
  }
}

}  // namespace taut::geom
