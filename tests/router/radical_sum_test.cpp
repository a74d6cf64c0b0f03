// router/radical_sum.h: exact signs of sums of square roots with coefficients in Q(sqrt3), and
// set_length, a polyline's length in a direction set at other angles.
// - The sign against the value in 200-bit binary floating point (Boost.Multiprecision's
//   cpp_bin_float, written apart from the code under test), where the value is not within 2^-150
//   of zero; exact zeros built from relations among the radicals (sqrt8 = 2 sqrt2, sqrt2 sqrt3 =
//   sqrt6, sqrt12 = 2 sqrt3 against Q(sqrt3)'s own sqrt3, a radical 4 = 2) must give 0, and
//   near-ties from Pell pairs (p^2 - n q^2 = +-1) their sign.
// - set_length against the least a |u| + b |w| over every pair of the set's steps u, w with v = a u
//   + b w, a, b >= 0 (long double), for random integer vectors in random sets of parse_any.
#include "router/radical_sum.h"

#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "geom/root3_directions.h"

namespace taut::router {
namespace radical_sum_test {

using Big = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<200, boost::multiprecision::digit_base_2>>;
using R3 = RationalRoot3;
using i64 = std::int64_t;

Big big(const Rational& q) {
  return Big(boost::multiprecision::numerator(q).str()) / Big(boost::multiprecision::denominator(q).str());
}
Big value(const RadicalSum& x) {
  const auto& n = x.radicals();
  Big v = 0;
  for (std::size_t s = 0; s < (std::size_t{1} << n.size()); ++s) {
    Big p = 1;
    for (std::size_t i = 0; i < n.size(); ++i)
      if (s >> i & 1) p *= Big(n[i]);
    const R3& c = x.coefficient(s);
    v += (big(c.a) + big(c.b) * sqrt(Big(3))) * sqrt(p);
  }
  return v;
}

TEST(RadicalSum, SignAgainstHighPrecision) {
  std::mt19937_64 rng(4401);
  int checked = 0, zero = 0;
  const Big tiny = pow(Big(2), -150);
  for (int i = 0; i < 4000; ++i) {
    const std::size_t k = rng() % 5;
    std::vector<i64> n;
    for (std::size_t j = 0; j < k; ++j) {
      const int kind = static_cast<int>(rng() % 4);
      const i64 m = 1 + static_cast<i64>(rng() % 60);
      n.push_back(kind == 0 ? m * m : kind == 1 ? 3 * m * m : kind == 2 ? 2 + static_cast<i64>(rng() % 1000)
                                                                       : (i64{1} << 40) + static_cast<i64>(rng() % 1000));
    }
    RadicalSum x(n);
    for (std::size_t s = 0; s < (std::size_t{1} << k); ++s) {
      if (rng() % 3 == 0) continue;
      auto r = [&] { return Rational(static_cast<i64>(rng() % 41) - 20, 1 + static_cast<i64>(rng() % 7)); };
      x.add(s, R3(r(), rng() % 2 ? r() : Rational(0)));
    }
    const Big v = value(x);
    if (abs(v) < tiny) {
      EXPECT_EQ(x.sign(), 0) << i;  // (only exact zeros come this near, at these sizes)
      ++zero;
      continue;
    }
    ASSERT_EQ(x.sign(), v > 0 ? 1 : -1) << i << ": " << v.str(30);
    ++checked;
  }
  std::printf("%d signs checked, %d zero\n", checked, zero);
  EXPECT_GT(checked, 3500);
  EXPECT_GT(zero, 10);  // the empty sums and those that cancel
}

TEST(RadicalSum, ExactZerosAndNearTies) {
  auto one = [](std::vector<i64> n, std::vector<std::pair<std::size_t, R3>> terms) {
    RadicalSum x(std::move(n));
    for (const auto& [s, c] : terms) x.add(s, c);
    return x;
  };
  const R3 r1(Rational(1)), r2(Rational(2)), m1(Rational(-1)), m2(Rational(-2));
  EXPECT_EQ(one({8, 2}, {{0b01, r1}, {0b10, m2}}).sign(), 0);                      // sqrt8 - 2 sqrt2
  EXPECT_EQ(one({2, 3, 6}, {{0b011, r1}, {0b100, m1}}).sign(), 0);                 // sqrt2 sqrt3 - sqrt6
  EXPECT_EQ(one({12}, {{0b1, r1}, {0, R3(Rational(0), Rational(-2))}}).sign(), 0);  // sqrt12 - 2 sqrt3
  EXPECT_EQ(one({4}, {{0b1, r1}, {0, m2}}).sign(), 0);                             // sqrt4 - 2
  EXPECT_EQ(one({2, 8}, {{0b11, r1}, {0, R3(Rational(-4))}}).sign(), 0);           // sqrt2 sqrt8 - 4
  // 99/70 > sqrt2 (99^2 - 2 70^2 = 1), 140/99 < sqrt2 (140^2 - 2 99^2 = -2)
  EXPECT_EQ(one({2}, {{0, R3(Rational(99, 70))}, {0b1, m1}}).sign(), 1);
  EXPECT_EQ(one({2}, {{0, R3(Rational(140, 99))}, {0b1, m1}}).sign(), -1);
  EXPECT_EQ(one({2, 101}, {{0b01, R3(Rational(3))}, {0b10, m1}}).sign(), -1);  // 4.24 - 10.05
  // sqrt3 in the coefficients: sqrt3 sqrt2 = sqrt6 = 2.44949 against 2.45 and 2.449
  EXPECT_EQ(one({2}, {{0b1, R3(Rational(0), Rational(1))}, {0, R3(Rational(-49, 20))}}).sign(), -1);
  EXPECT_EQ(one({2}, {{0b1, R3(Rational(0), Rational(1))}, {0, R3(Rational(-2449, 1000))}}).sign(), 1);
  // large near-ties: sqrt(n) against p/q with p^2 - n q^2 = 1 (n = a^2 + 1: p = 2a^2 + 1, q = 2a)
  for (const i64 a : {i64{10}, i64{1000}, i64{100000}}) {
    const i64 n = a * a + 1, p = 2 * a * a + 1, q = 2 * a;
    EXPECT_EQ(one({n}, {{0, R3(Rational(p, q))}, {0b1, m1}}).sign(), 1) << a;
    EXPECT_EQ(one({n}, {{0, R3(Rational(-p, q))}, {0b1, r1}}).sign(), -1) << a;
  }
  EXPECT_EQ(RadicalSum().sign(), 0);
  EXPECT_THROW(RadicalSum({0}), std::invalid_argument);
}

// The least a |u| + b |w| over the pairs of steps that hold v (long double).
long double reference_length(const geom::Root3Directions& set, i64 dx, i64 dy) {
  long double best = INFINITY;
  const auto& st = set.steps();
  for (std::size_t i = 0; i < st.size(); ++i)
    for (std::size_t j = 0; j < st.size(); ++j) {
      const long double ux = st[i].x.to_double(), uy = st[i].y.to_double(), wx = st[j].x.to_double(),
                        wy = st[j].y.to_double();
      const long double lu = std::sqrt(ux * ux + uy * uy), lw = std::sqrt(wx * wx + wy * wy);
      const long double det = ux * wy - uy * wx;
      if (i == j) {
        const long double t = (ux * dx + uy * dy) / (lu * lu);
        if (std::fabs(ux * dy - uy * dx) <= 1e-9L * lu * (std::fabs(1.0L * dx) + std::fabs(1.0L * dy)) && t > 0)
          best = std::min(best, t * lu);
        continue;
      }
      if (std::fabs(det) < 1e-12L * lu * lw) continue;
      const long double a = (dx * wy - dy * wx) / det, b = (ux * dy - uy * dx) / det;
      if (a >= -1e-12L && b >= -1e-12L) best = std::min(best, a * lu + b * lw);
    }
  return best;
}

TEST(RadicalSum, SetLengthAgainstBruteForce) {
  std::mt19937_64 rng(4402);
  int checked = 0;
  const char* const sets[] = {"c:0,10", "c:0,45,60", "c:22.5,90,157.5", "c:0,36.87,90", "c:15,75,135", "c:0,60,120",
                              "c:5,50,95,140"};
  for (const char* name : sets) {
    SCOPED_TRACE(name);
    const auto set = geom::Root3Directions::parse_any(name);
    ASSERT_TRUE(set);
    for (int i = 0; i < 2000; ++i) {
      const i64 m = i % 2 ? 20 : i64{1} << 28;
      const geom::Point a{static_cast<geom::Coord>(rng() % (2 * m + 1)) - static_cast<geom::Coord>(m), 0};
      const geom::Point b{static_cast<geom::Coord>(rng() % (2 * m + 1)) - static_cast<geom::Coord>(m),
                          static_cast<geom::Coord>(rng() % (2 * m + 1)) - static_cast<geom::Coord>(m)};
      const std::vector<geom::Point> line{a, b};
      const long double want = reference_length(*set, i64{b.x} - a.x, i64{b.y} - a.y);
      const Big got = value(set_length(*set, line));
      ASSERT_NEAR(static_cast<double>(got), static_cast<double>(want), 1e-12 * static_cast<double>(want) + 1e-12)
          << a.x << "," << a.y << " " << b.x << "," << b.y;
      ++checked;
    }
    // a polyline's is the sum of its segments'
    const std::vector<geom::Point> poly{{0, 0}, {7, 3}, {7, 10}, {-4, 12}};
    RadicalSum sum = set_length(*set, std::vector<geom::Point>{poly[0], poly[1]});
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) sum = sum + set_length(*set, std::vector<geom::Point>{poly[k], poly[k + 1]});
    EXPECT_TRUE(sum == set_length(*set, poly));
    EXPECT_NEAR(static_cast<double>(value(sum)),
                static_cast<double>(reference_length(*set, 7, 3) + reference_length(*set, 0, 7) + reference_length(*set, -11, 2)),
                1e-9);
  }
  EXPECT_EQ(checked, 14000);
}

}  // namespace radical_sum_test
}  // namespace taut::router
