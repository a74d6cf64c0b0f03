// geom/fixed_norm.h: the Farey norms' lengths against their definition (the least cost of
// writing v as a non-negative combination of the directions, by exhaustive search over pairs of
// directions: an optimal combination needs at most two, Caratheodory), the Euclidean bounds
// S |v| <= N(v) <= Lambda |v| on many vectors, and the direction sets themselves.
#include "geom/fixed_norm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <random>

namespace fixed_norm_test {

using i64 = std::int64_t;
using i128 = __int128;

// The least cost over pairs (i, j) with v = a d_i + b d_j, a, b >= 0, as an exact fraction
// num / den compared to an integer: returns true when some pair costs exactly `want` and none
// costs less.
template <class F>
bool least_cost_is(const F& f, i64 vx, i64 vy, i64 want) {
  bool hit = false;
  for (int i = 0; i < F::kDirs; ++i) {
    const auto di = f.dir[i];
    // a single direction: v = a d_i
    if (di.x * vy - di.y * vx == 0 && di.x * vx + di.y * vy > 0) {
      const i64 a_num = di.x != 0 ? vx : vy, a_den = di.x != 0 ? di.x : di.y;  // a = a_num / a_den
      const i128 c = i128{a_num} * f.weight[i] - i128{want} * a_den;            // cost - want
      if ((a_den > 0 ? c : -c) < 0) return false;
      if (c == 0) hit = true;
    }
    for (int j = 0; j < F::kDirs; ++j) {
      const auto dj = f.dir[j];
      const i64 det = di.x * dj.y - di.y * dj.x;
      if (det == 0) continue;
      // v = a d_i + b d_j: a = det(v, d_j) / det, b = det(d_i, v) / det
      i64 an = vx * dj.y - vy * dj.x, bn = di.x * vy - di.y * vx, dd = det;
      if (dd < 0) {
        an = -an;
        bn = -bn;
        dd = -dd;
      }
      if (an < 0 || bn < 0) continue;
      const i128 c = i128{an} * f.weight[i] + i128{bn} * f.weight[j] - i128{want} * dd;
      if (c < 0) return false;
      if (c == 0) hit = true;
    }
  }
  return hit;
}

template <class F>
void check_norm(const F& f) {
  std::mt19937_64 rng(20261123 + F::kOrder);
  const long double lambda = std::sqrt(static_cast<long double>(f.lambda_max_sq()));
  for (int k = 0; k < 20000; ++k) {
    const i64 span = k % 3 == 0 ? 12 : k % 3 == 1 ? 1000 : (i64{1} << 30);
    const i64 vx = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * span + 1)) - span;
    const i64 vy = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * span + 1)) - span;
    if (vx == 0 && vy == 0) continue;
    const i64 n = f.length(vx, vy);
    ASSERT_TRUE(least_cost_is(f, vx, vy, n)) << "order " << F::kOrder << " v = (" << vx << "," << vy << ") N = " << n;
    const long double e = std::sqrt(static_cast<long double>(vx) * vx + static_cast<long double>(vy) * vy);
    EXPECT_GE(static_cast<long double>(n), static_cast<long double>(taut::geom::kNormScale) * e * (1 - 1e-15L)) << vx << "," << vy;
    EXPECT_LE(static_cast<long double>(n), lambda * e * (1 + 1e-15L)) << vx << "," << vy;
  }
  // along each direction the cost is exactly the weight; every direction is primitive
  for (int i = 0; i < F::kDirs; ++i) {
    EXPECT_EQ(f.length(f.dir[i].x, f.dir[i].y), f.weight[i]);
    EXPECT_EQ(std::gcd(f.dir[i].x, f.dir[i].y), 1) << i;
  }
}

TEST(FixedNorm, LengthsAreTheLeastCombinations) {
  check_norm(taut::geom::kFarey1);
  check_norm(taut::geom::kFarey2);
  check_norm(taut::geom::kFarey3);
  check_norm(taut::geom::kFarey4);
}

TEST(FixedNorm, DirectionSets) {
  // order 2: the first quarter is (1,0), (2,1), (1,1), (1,2); every direction is primitive and
  // the set is symmetric under 90-degree turns
  const auto& f = taut::geom::kFarey2;
  EXPECT_EQ(f.dir[1].x, 2);
  EXPECT_EQ(f.dir[1].y, 1);
  EXPECT_EQ(f.dir[3].x, 1);
  EXPECT_EQ(f.dir[3].y, 2);
  EXPECT_EQ(f.weight[1], 9159);  // ceil(4096 sqrt5) = ceil(9158.9...)
  EXPECT_EQ(f.weight[2], 5793);  // ceil(4096 sqrt2) = ceil(5792.6...)
  for (int i = 0; i < f.kDirs; ++i) {
    const auto r = f.dir[(i + f.kDirs / 4) % f.kDirs];
    EXPECT_EQ(r.x, -f.dir[i].y);
    EXPECT_EQ(r.y, f.dir[i].x);
  }
  // the guaranteed relative widths of the Euclidean interval shrink with the order
  EXPECT_NEAR(static_cast<double>(taut::geom::fixed_norm_epsilon(2)), 0.0275, 0.0005);
  EXPECT_NEAR(static_cast<double>(taut::geom::fixed_norm_epsilon(3)), 0.0131, 0.0005);
  EXPECT_NEAR(static_cast<double>(taut::geom::fixed_norm_epsilon(4)), 0.0076, 0.0005);
}

}  // namespace fixed_norm_test
