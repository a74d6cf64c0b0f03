// geom/root2.h: exact a + b*sqrt(2) against an independent GMP reference that decides the sign
// of A + B*sqrt(2) through the integer square root floor(|B|*sqrt(2)) = isqrt(2*B*B), not
// through squares compared in __int128. Near-ties come from the convergents of sqrt(2) (Pell
// pairs p^2 - 2q^2 = +-1), where p - q*sqrt(2) is about 1/(2p): beyond 2^26 double can no
// longer tell the two apart.
#include "geom/root2.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

namespace taut::geom {
namespace root2_test {

using i64 = std::int64_t;
constexpr i64 kBound = (i64{1} << 62) - 1;  // the magnitude root2.h promises exactness for

mpz_class Z(i64 v) { return mpz_class(static_cast<long>(v)); }

// Sign of A + B*sqrt(2). For B != 0, B*sqrt(2) is irrational, r = floor(|B| sqrt(2)) and
// r < |B| sqrt(2) < r + 1. B > 0: A + B sqrt(2) > 0 iff B sqrt(2) > -A iff r >= -A.
// B < 0: A - |B| sqrt(2) > 0 iff |B| sqrt(2) < A iff r + 1 <= A.
int gmp_sign(const mpz_class& A, const mpz_class& B) {
  if (B == 0) return sgn(A);
  const mpz_class r = sqrt(mpz_class(2 * B * B));  // floor of the square root
  if (B > 0) return r >= -A ? 1 : -1;
  return r + 1 <= A ? 1 : -1;
}
int gmp_compare(Root2 x, Root2 y) { return gmp_sign(Z(x.a) - Z(y.a), Z(x.b) - Z(y.b)); }
int sign_of(std::strong_ordering o) { return o < 0 ? -1 : (o > 0 ? 1 : 0); }

// Convergents p/q of sqrt(2) with p < 2^62: (1,1), (3,2), (7,5), (17,12), ... p^2 - 2q^2
// alternates -1, +1.
std::vector<std::pair<i64, i64>> convergents() {
  std::vector<std::pair<i64, i64>> out;
  i64 p = 1, q = 1;
  while (p < kBound / 3) {
    out.push_back({p, q});
    const i64 np = p + 2 * q, nq = p + q;
    p = np, q = nq;
  }
  return out;
}

TEST(Root2, ConvergentsOfSqrt2) {
  // By hand: 99^2 = 9801 = 2 * 70^2 + 1, 577^2 = 332929 = 2 * 408^2 + 1, 41^2 = 2 * 29^2 - 1.
  EXPECT_GT((Root2{99, 0}), (Root2{0, 70}));
  EXPECT_LT((Root2{99, -70}), (Root2{1, 0}));  // 99 - 70 sqrt(2) = 1/(99 + 70 sqrt(2)) < 1
  EXPECT_GT((Root2{99, -70}), (Root2{}));
  EXPECT_GT((Root2{577, 0}), (Root2{0, 408}));
  EXPECT_LT((Root2{41, 0}), (Root2{0, 29}));
  EXPECT_LT((Root2{-99, 70}), (Root2{}));
  EXPECT_GT((Root2{-41, 29}), (Root2{}));
  EXPECT_EQ((Root2{577, -408}.sign()), 1);
  EXPECT_EQ((Root2{-577, 408}.sign()), -1);

  const auto cv = convergents();
  ASSERT_GT(cv.size(), 40u);
  int double_wrong = 0;
  for (std::size_t i = 0; i < cv.size(); ++i) {
    const auto [p, q] = cv[i];
    SCOPED_TRACE("p " + std::to_string(p) + " q " + std::to_string(q));
    const int want = i % 2 == 0 ? -1 : 1;  // sign of p^2 - 2 q^2 = sign of p - q sqrt(2)
    ASSERT_EQ(gmp_sign(Z(p), Z(-q)), want);
    EXPECT_EQ(sign_of(Root2{p, 0} <=> Root2{0, q}), want);
    EXPECT_EQ(sign_of(Root2{0, q} <=> Root2{p, 0}), -want);
    EXPECT_EQ((Root2{p, -q}.sign()), want);
    EXPECT_EQ((Root2{-p, q}.sign()), -want);
    // Shifted by a common offset, and with the pair on both sides.
    EXPECT_EQ(sign_of(Root2{p + 5, 7} <=> Root2{5, q + 7}), want);
    EXPECT_EQ(sign_of(Root2{-p, 3} <=> Root2{0, 3 - q}), -want);
    EXPECT_NE((Root2{p, 0}), (Root2{0, q}));
    const double dp = static_cast<double>(p), dq = static_cast<double>(q) * std::sqrt(2.0);
    double_wrong += (dp < dq ? -1 : (dp > dq ? 1 : 0)) != want;
  }
  // Above ~2^26 double cannot separate p from q sqrt(2): the exact order is needed.
  EXPECT_GT(double_wrong, 10);
  // A pair below 2^30 (the coordinates' scale) that double calls equal:
  // 768398401^2 - 2 * 543339720^2 = +1, so 768398401 - 543339720 sqrt(2) ~ 6.5e-10.
  const Root2 p{768398401, 0}, q{0, 543339720};
  EXPECT_EQ(gmp_compare(p, q), 1);
  EXPECT_GT(p, q);
  EXPECT_NE(p, q);
  EXPECT_EQ(p.to_double(), q.to_double());
}

TEST(Root2, ExtremesOfTheBound) {
  const Root2 big{kBound, kBound}, neg{-kBound, -kBound};
  EXPECT_GT(big, neg);
  EXPECT_LT((Root2{kBound, -kBound}), (Root2{}));  // (1 - sqrt 2) * bound
  EXPECT_GT((Root2{-kBound, kBound}), (Root2{}));
  // (sqrt 2 - 1) K ~ 0.414 K against (1 - sqrt(2) / 2) K ~ 0.293 K, operands at the bound.
  EXPECT_GT((Root2{-kBound, kBound}), (Root2{kBound, -(kBound / 2)}));
  EXPECT_EQ(gmp_compare(Root2{-kBound, kBound}, Root2{kBound, -(kBound / 2)}), 1);
  EXPECT_EQ(gmp_compare(Root2{kBound, -kBound}, Root2{-kBound, kBound}), -1);
  EXPECT_EQ(sign_of(Root2{kBound, -kBound} <=> Root2{-kBound, kBound}), -1);
  EXPECT_EQ(sign_of(Root2{-kBound, kBound} <=> Root2{kBound, -kBound}), 1);
  EXPECT_EQ(sign_of(Root2{kBound, 0} <=> Root2{-kBound, 0}), 1);
}

TEST(Root2, Arithmetic) {
  const Root2 x{3, -2}, y{-5, 7};
  EXPECT_EQ(x + y, (Root2{-2, 5}));
  EXPECT_EQ(x - y, (Root2{8, -9}));
  EXPECT_EQ(-x, (Root2{-3, 2}));
  Root2 z = x;
  z += y;
  EXPECT_EQ(z, x + y);
  EXPECT_EQ(x - x, Root2{});
  EXPECT_EQ((Root2{}.sign()), 0);
  EXPECT_EQ(sign_of(x <=> x), 0);
  std::ostringstream os;
  os << Root2{1, -2};
  EXPECT_EQ(os.str().substr(0, 9), "1-2*sqrt2");
}

TEST(Root2, OctilinearLength) {
  EXPECT_EQ(octilinear_length(0, 0), Root2{});
  EXPECT_EQ(octilinear_length(5, 0), (Root2{5, 0}));
  EXPECT_EQ(octilinear_length(0, -5), (Root2{5, 0}));
  EXPECT_EQ(octilinear_length(3, 3), (Root2{0, 3}));
  EXPECT_EQ(octilinear_length(-3, 7), (Root2{4, 3}));
  EXPECT_EQ(octilinear_length(7, -3), (Root2{4, 3}));
  const i64 m = (i64{1} << 31) - 2;  // the largest coordinate difference
  EXPECT_EQ(octilinear_length(-m, m - 1), (Root2{1, m - 1}));
  // Between L-infinity and L1, and never shorter than the Euclidean length: check on a sweep.
  for (i64 dx = -9; dx <= 9; ++dx)
    for (i64 dy = -9; dy <= 9; ++dy) {
      const Root2 d = octilinear_length(dx, dy);
      const i64 ax = dx < 0 ? -dx : dx, ay = dy < 0 ? -dy : dy;
      EXPECT_LE((Root2{std::max(ax, ay), 0}), d);
      EXPECT_LE(d, (Root2{ax + ay, 0}));
      EXPECT_GE(d.to_double() + 1e-9, std::sqrt(static_cast<double>(ax * ax + ay * ay)));
      // Triangle inequality through a fixed point (a norm).
      EXPECT_LE(d, octilinear_length(dx - 2, dy + 5) + octilinear_length(2, -5));
    }
}

// Random pairs against GMP: magnitudes of every size up to the bound, and near-ties (a
// convergent scaled and nudged, so A + B*sqrt(2) is tiny against |A|).
TEST(Root2, RandomPairsMatchGmp) {
  const std::uint64_t seed = 20250611;
  std::mt19937_64 rng(seed);
  const auto cv = convergents();
  auto value = [&](int bits) -> i64 {
    const i64 v = static_cast<i64>(rng() >> (64 - bits));  // 0 <= v < 2^bits, bits <= 62
    return (rng() & 1) ? -v : v;
  };
  int less = 0, greater = 0, equal = 0, near_ties = 0;
  for (int it = 0; it < 100000; ++it) {
    Root2 x, y;
    if (it % 4 == 3) {
      // y = x +- k (p - q sqrt 2), |k (p - q sqrt 2)| < k / (2p): a near tie (|p k| <= 2^60
      // keeps everything bounded); sometimes nudged by a small integer.
      const auto [p, q] = cv[rng() % cv.size()];
      const i64 kmax = std::min<i64>(1000, std::max<i64>(1, (i64{1} << 60) / p));
      const i64 k = 1 + static_cast<i64>(rng() % static_cast<std::uint64_t>(kmax));
      const i64 sg = (rng() & 1) ? 1 : -1;
      x = {value(58), value(58)};
      y = x + Root2{sg * p * k, -sg * q * k} + Root2{rng() % 4 == 0 ? value(2) : 0, 0};
      ++near_ties;
    } else {
      const int ba = 1 + static_cast<int>(rng() % 62), bb = 1 + static_cast<int>(rng() % 62);
      x = {value(ba), value(bb)};
      y = (it % 4 == 2) ? Root2{x.a + value(3), x.b + value(2)} : Root2{value(ba), value(bb)};
    }
    const int want = gmp_compare(x, y);
    const int got = sign_of(x <=> y);
    ASSERT_EQ(got, want) << "seed " << seed << " iteration " << it << ": " << x << " vs " << y;
    ASSERT_EQ(x == y, want == 0) << "seed " << seed << " iteration " << it;
    ASSERT_EQ(sign_of(y <=> x), -want) << "seed " << seed << " iteration " << it;
    ASSERT_EQ((x - y).sign(), want) << "seed " << seed << " iteration " << it;
    less += want < 0, greater += want > 0, equal += want == 0;
  }
  EXPECT_GT(less, 10000);
  EXPECT_GT(greater, 10000);
  EXPECT_GT(equal, 10);
  EXPECT_GT(near_ties, 20000);
}

}  // namespace root2_test
}  // namespace taut::geom
