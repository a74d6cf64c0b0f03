// geom/root3.h and geom/root3_directions.h: exact a + b*sqrt(3) and the direction sets at
// multiples of 30 degrees.
// - The sign against GMP's integer square root (floor(|b| sqrt 3) = isqrt(3 b^2)), not squares
//   in __int128; near-ties from the Pell pairs p^2 - 3q^2 = 1 and -2 up to 2^61.
// - Cones against atan2 in long double, lengths against a brute force over every pair of the
//   set's unit vectors (cos, sin in long double), the rounding test (fits) against the angles of
//   the square's corners, and against segments made by rounding exact ones.
#include "geom/root3.h"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "geom/root3_directions.h"

namespace taut::geom {
namespace root3_test {

using i64 = std::int64_t;
using ld = long double;

// Sign of a + b sqrt(3) by r = floor(|b| sqrt 3): b > 0: positive iff r >= -a; b < 0: positive
// iff r + 1 <= a (|b| sqrt 3 is irrational, so strictly between r and r + 1).
int reference_sign(i64 a, i64 b) {
  if (b == 0) return a > 0 ? 1 : a < 0 ? -1 : 0;
  const mpz_class bb(std::to_string(b));
  const mpz_class r = sqrt(mpz_class(3 * bb * bb));
  const mpz_class A(std::to_string(a));
  if (b > 0) return r >= -A ? 1 : -1;
  return r + 1 <= A ? 1 : -1;
}

TEST(Root3, SignAgainstIntegerSquareRoots) {
  std::mt19937_64 rng(3301);
  int checked = 0;
  // Pell pairs: p^2 - 3q^2 = 1 from (2, 1), and = -2 from (1, 1); next (2p + 3q, p + 2q)
  for (const auto& start : {std::pair<i64, i64>{2, 1}, std::pair<i64, i64>{1, 1}}) {
    for (auto [p, q] = start; p < (i64{1} << 61); std::tie(p, q) = std::pair<i64, i64>{2 * p + 3 * q, p + 2 * q}) {
      for (const auto& [a, b] : {std::pair{p, -q}, std::pair{-p, q}, std::pair{p + 1, -q}, std::pair{p - 1, -q}}) {
        ASSERT_EQ((Root3{a, b}.sign()), reference_sign(a, b)) << a << " " << b;
        ++checked;
      }
    }
  }
  for (int i = 0; i < 20000; ++i) {
    const int bits = 1 + static_cast<int>(rng() % 61);
    const i64 m = i64{1} << bits;
    const i64 a = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * m)) - m;
    const i64 b = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * m)) - m;
    ASSERT_EQ((Root3{a, b}.sign()), reference_sign(a, b)) << a << " " << b;
    ++checked;
  }
  EXPECT_GT(checked, 20100);
  // 7 - 4 sqrt3 ~ 0.0718 > 0; 26 - 15 sqrt3 ~ 0.0192 > 0; 5 - 3 sqrt3 ~ -0.196 < 0
  EXPECT_GT((Root3{7, -4}), Root3{});
  EXPECT_GT((Root3{26, -15}), Root3{});
  EXPECT_LT((Root3{5, -3}), Root3{});
  EXPECT_EQ((Root3{1, 2} * Root3{3, -1}), (Root3{3 - 6, -1 + 6}));  // (1 + 2r)(3 - r) = -3 + 5r
}

TEST(Root3Directions, ParsesMultiplesOf30ThatAreNotLatticeSets) {
  EXPECT_EQ(Root3Directions::parse("c:0,60,120")->name(), "c:0,60,120");
  EXPECT_EQ(Root3Directions::parse("c:120,0,240,60")->name(), "c:0,60,120");
  EXPECT_EQ(Root3Directions::parse("c:30,90,150")->name(), "c:30,90,150");
  EXPECT_EQ(Root3Directions::parse("c:0,30,60,90,120,150")->steps().size(), 12u);
  EXPECT_EQ(Root3Directions::parse("c:0,60.0")->name(), "c:0,60");
  EXPECT_EQ(Root3Directions::parse("c:90,210")->name(), "c:30,90");
  EXPECT_EQ(Root3Directions::parse("c:0,60")->steps().size(), 4u);
  for (const char* no : {"c:0,90", "rectilinear", "octilinear", "any", "c:0,45,60", "c:60,240", "c:0,45", "c:0,22.5",
                         "c:0,60,", "c:-60,60", "c:0,60.5", ""})
    EXPECT_FALSE(Root3Directions::parse(no)) << no;
}

ld angle_of(ld x, ld y) {
  ld a = std::atan2(y, x);
  if (a < 0) a += 2 * std::numbers::pi_v<ld>;
  return a;
}

const char* const kSets[] = {"c:0,60,120", "c:30,90,150", "c:0,30,60,90,120,150", "c:0,60", "c:30,90", "c:0,30",
                             "c:0,90,120", "c:60,150"};

// step_along's index and cones_leave_box against the set's degrees (since 2026-12-07; before,
// exercised only through the staircase builder): an axis vector lies along the step at its angle
// among the steps sorted counter-clockwise from 0 degrees, if the set has that angle; a cone
// leaves the box of its ends when its two steps' angles lie in no one closed quadrant.
TEST(Root3Directions, StepAlongAndConesLeavingTheBox) {
  int leave = 0, keep = 0, along = 0;
  for (unsigned mask = 0; mask < 64; ++mask) {
    const auto set = Root3Directions::from_mask(mask);
    if (!set) continue;
    SCOPED_TRACE(set->name());
    std::vector<int> deg;  // the steps' angles, counter-clockwise from 0
    for (const int d : set->degrees()) deg.push_back(d), deg.push_back(d + 180);
    std::sort(deg.begin(), deg.end());
    ASSERT_EQ(deg.size(), set->steps().size());
    bool wide = false;
    for (std::size_t k = 0; k < deg.size(); ++k) {
      const int lo = deg[k], hi = k + 1 < deg.size() ? deg[k + 1] : deg[0] + 360;
      wide = wide || hi > lo / 90 * 90 + 90;
    }
    EXPECT_EQ(set->cones_leave_box(), wide);
    (wide ? leave : keep) += 1;
    const struct {
      i64 dx, dy;
      int angle;
    } axes[] = {{1, 0, 0}, {0, 7, 90}, {-(i64{1} << 39), 0, 180}, {0, -3, 270}};
    for (const auto& a : axes) {
      const auto it = std::find(deg.begin(), deg.end(), a.angle);
      const int want = it == deg.end() ? -1 : static_cast<int>(it - deg.begin());
      EXPECT_EQ(set->step_along(a.dx, a.dy), want) << a.dx << "," << a.dy;
      along += want >= 0;
    }
    for (const auto& [dx, dy] : {std::pair<i64, i64>{1, 1}, {3, 5}, {-7, 4}, {1000, 1732}, {-1, -1}})
      EXPECT_EQ(set->step_along(dx, dy), -1) << dx << "," << dy;  // off the axes: irrational tangents
  }
  EXPECT_EQ(leave + keep, 56);  // every set: 64 masks, less 7 of fewer than two bits and 0/90 alone
  EXPECT_GT(leave, 0);
  EXPECT_GT(keep, 0);
  EXPECT_GT(along, 0);
}

TEST(Root3Directions, ConesAndLengthsAgainstFloatingReferences) {
  std::mt19937_64 rng(3302);
  int cones = 0, alongs = 0;
  for (const char* name : kSets) {
    SCOPED_TRACE(name);
    const auto set = Root3Directions::parse(name);
    ASSERT_TRUE(set);
    std::vector<ld> deg;  // the steps' angles, counter-clockwise
    for (const int d : set->degrees()) deg.push_back(d);
    for (const int d : set->degrees()) deg.push_back(d + 180);
    std::sort(deg.begin(), deg.end());
    for (int i = 0; i < 4000; ++i) {
      const i64 m = i % 4 == 0 ? 8 : i64{1} << 20;
      i64 dx = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * m + 1)) - m;
      i64 dy = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * m + 1)) - m;
      if (i % 50 == 0) dy = 0;  // along the x axis
      if (dx == 0 && dy == 0) dx = 1;
      // cone: the step angles bracketing atan2 (never equal off the axes: tangents irrational)
      const ld a = angle_of(static_cast<ld>(dx), static_cast<ld>(dy)) * 180 / std::numbers::pi_v<ld>;
      int want = -1;
      bool on_step = false;
      for (std::size_t k = 0; k < deg.size(); ++k) {
        const ld lo = deg[k], hi = k + 1 < deg.size() ? deg[k + 1] : deg[0] + 360;
        if (std::fabs(a - lo) < 1e-12L) on_step = true;
        if ((a > lo && a < hi) || (a + 360 > lo && a + 360 < hi)) want = static_cast<int>(k);
      }
      if (on_step) want = -1;
      ASSERT_EQ(set->cone(dx, dy), want) << dx << "," << dy;
      ASSERT_EQ(set->along(dx, dy), on_step) << dx << "," << dy;
      (on_step ? alongs : cones) += 1;
      // length: the least a + b over every pair of unit vectors u, w with v = a u + b w, a, b >= 0
      ld best = INFINITY;
      for (const ld du : deg)
        for (const ld dw : deg) {
          const ld ux = std::cos(du * std::numbers::pi_v<ld> / 180), uy = std::sin(du * std::numbers::pi_v<ld> / 180);
          const ld wx = std::cos(dw * std::numbers::pi_v<ld> / 180), wy = std::sin(dw * std::numbers::pi_v<ld> / 180);
          const ld det = ux * wy - uy * wx;
          if (std::fabs(det) < 1e-9L) {  // one direction alone
            if (std::fabs(ux * dy - uy * dx) < 1e-6L * (std::fabs(ld(dx)) + std::fabs(ld(dy))) && ux * dx + uy * dy > 0)
              best = std::min(best, std::hypot(ld(dx), ld(dy)));
            continue;
          }
          const ld p = (dx * wy - dy * wx) / det, q = (ux * dy - uy * dx) / det;
          if (p >= -1e-9L && q >= -1e-9L) best = std::min(best, p + q);
        }
      const Root3 l = set->length12(dx, dy);
      const ld got = (static_cast<ld>(l.a) + static_cast<ld>(l.b) * std::sqrt(3.0L)) / 12;
      ASSERT_NEAR(static_cast<double>(got), static_cast<double>(best), 1e-9 * static_cast<double>(best))
          << dx << "," << dy << " " << l;
    }
  }
  EXPECT_GT(cones, 30000);
  EXPECT_GT(alongs, 300);
}

// The square (dx, dy) + [-1, 1]^2 meets the ray along angle t (degrees), by the angles of its
// corners (it holds 0 only for |dx|, |dy| <= 1, and then spans less than 180 degrees otherwise);
// nullopt when t is within 1e-12 degrees of the span's ends.
std::optional<bool> reference_fits(i64 dx, i64 dy, ld t) {
  if (dx >= -1 && dx <= 1 && dy >= -1 && dy <= 1) return true;
  const ld c = angle_of(static_cast<ld>(dx), static_cast<ld>(dy)) * 180 / std::numbers::pi_v<ld>;
  ld lo = 1e9, hi = -1e9;
  for (const i64 ex : {-1, 1})
    for (const i64 ey : {-1, 1}) {
      ld a = angle_of(static_cast<ld>(dx + ex), static_cast<ld>(dy + ey)) * 180 / std::numbers::pi_v<ld>;
      while (a - c > 180) a -= 360;
      while (c - a > 180) a += 360;
      lo = std::min(lo, a), hi = std::max(hi, a);
    }
  while (t - c > 180) t -= 360;
  while (c - t > 180) t += 360;
  if (std::fabs(t - lo) < 1e-12L || std::fabs(t - hi) < 1e-12L) return std::nullopt;
  return t > lo && t < hi;
}

TEST(Root3Directions, RoundingTestAgainstCornerAnglesAndRoundedSegments) {
  std::mt19937_64 rng(3303);
  int fit = 0, misfit = 0, rounded = 0, moved = 0;
  for (const char* name : kSets) {
    SCOPED_TRACE(name);
    const auto set = Root3Directions::parse(name);
    std::vector<ld> deg;
    for (const int d : set->degrees()) deg.push_back(d), deg.push_back(d + 180);
    for (int i = 0; i < 5000; ++i) {
      const i64 m = i % 3 == 0 ? 6 : i % 3 == 1 ? 60 : i64{1} << 28;
      const i64 dx = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * m + 1)) - m;
      const i64 dy = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * m + 1)) - m;
      bool want = false, known = true;
      for (const ld t : deg) {
        const std::optional<bool> r = reference_fits(dx, dy, t);
        if (!r) {
          known = false;
        } else {
          want = want || *r;
        }
      }
      if (!known && !want) continue;  // a corner on a ray: the exact test decides, the reference cannot
      ASSERT_EQ(set->fits(dx, dy), want) << dx << "," << dy;
      (want ? fit : misfit) += 1;
    }
    // exact segments along a direction, their ends rounded: always fit; moved one more unit
    // sideways (perpendicular, long segments only), never
    for (int i = 0; i < 2000; ++i) {
      const ld t = deg[rng() % deg.size()] * std::numbers::pi_v<ld> / 180;
      const ld px = static_cast<ld>(static_cast<i64>(rng() % 2000001) - 1000000) + static_cast<ld>(rng() % 1000) / 1000;
      const ld py = static_cast<ld>(static_cast<i64>(rng() % 2000001) - 1000000) + static_cast<ld>(rng() % 1000) / 1000;
      const ld len = 3 + static_cast<ld>(rng() % 100000) / 7;
      const ld qx = px + len * std::cos(t), qy = py + len * std::sin(t);
      const i64 dx = std::llround(qx) - std::llround(px), dy = std::llround(qy) - std::llround(py);
      ASSERT_TRUE(set->fits(dx, dy)) << dx << "," << dy << " at " << t;
      ++rounded;
      if (len > 200) {
        // 6 units to the left of the direction: more than the rounding of the ends (up to sqrt 2
        // across), the square's half-diagonal (sqrt 2) and this move's own rounding together
        const i64 sx = std::llround(-6 * std::sin(t)), sy = std::llround(6 * std::cos(t));
        bool other = false;  // no direction of the set passes there, as the reference sees it too
        for (const ld u : deg) other = other || reference_fits(dx + sx, dy + sy, u).value_or(true);
        ASSERT_FALSE(other) << dx + sx << "," << dy + sy;
        ASSERT_FALSE(set->fits(dx + sx, dy + sy)) << dx + sx << "," << dy + sy;
        ++moved;
      }
    }
  }
  EXPECT_GT(fit, 3000);
  EXPECT_GT(misfit, 20000);
  EXPECT_EQ(rounded, 16000);
  EXPECT_GT(moved, 15000);
  // by hand: a vertical segment of length 5 is not hexagonal; 10,17 is 60 degrees within the
  // rounding (17.32), 10,22 is not; a segment touching the x axis with a corner fits 0 degrees exactly
  const auto hex = Root3Directions::parse("c:0,60,120");
  EXPECT_FALSE(hex->fits(0, 5));
  EXPECT_TRUE(hex->fits(10, 17));
  EXPECT_TRUE(hex->fits(-10, 17));
  EXPECT_TRUE(hex->fits(10, 15));   // 9 sqrt3 = 15.59: the square's corner 9,14..16 is crossed
  EXPECT_FALSE(hex->fits(10, 22));  // 11 sqrt3 = 19.05 < 21
  EXPECT_TRUE(hex->fits(50, 1));
  EXPECT_FALSE(hex->fits(50, 2));
  EXPECT_TRUE(hex->fits(-50, -1));
}

}  // namespace root3_test
}  // namespace taut::geom
