// geom/root3.h and geom/root3_directions.h: exact a + b*sqrt(3) and the direction sets at
// multiples of 30 degrees.
// - parse_any's sets at other angles (since 2026-12-07): steps counter-clockwise and within 2^-36
//   radians of the written angles, cones and fits against long double references at the steps'
//   own angles, rounded segments along a step.
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
#include <numeric>
#include <optional>
#include <stdexcept>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "geom/directions.h"
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

namespace taut::geom {
namespace root3_test {

// The angle of a step in degrees, counter-clockwise in [0, 360) (long double: a reference).
ld step_degrees(const Root3Directions::Step& s) {
  return angle_of(s.x.to_double() + 0.0L, s.y.to_double() + 0.0L) * 180 / std::numbers::pi_v<ld>;
}

// parse_any (since 2026-12-07): the sets at other angles, each direction an exact step (multiples
// of 30 and 45 degrees) or the integer step of at most 2^24 nearest it.
TEST(Root3Directions, ParseAnyRealizesOtherAngles) {
  // parse()'s sets, the same
  for (unsigned mask = 0; mask < 64; ++mask) {
    const auto set = Root3Directions::from_mask(mask);
    if (!set) continue;
    const auto any = Root3Directions::parse_any(set->name());
    ASSERT_TRUE(any) << set->name();
    EXPECT_TRUE(*any == *set) << set->name();
    EXPECT_TRUE(any->exact());
    EXPECT_EQ(any->mask(), mask);
  }
  // refused: lattice sets, one orientation, bad text, directions that realize to one step or
  // within 2^-36 radians of none
  for (const char* no : {"rectilinear", "octilinear", "c:0,45", "c:0,90", "any", "c:10", "c:10,190", "c:10,10.0", "c:-10,10",
                         "c:0,10,", "c:0,1..5", "c:0,0.0000000001", "c:0,0.000001", "c:0,45.000001", "", "c:"})
    EXPECT_FALSE(Root3Directions::parse_any(no)) << no;
  // mixed multiples of 30 and 45: exact, steps of lengths 2 and sqrt 2
  const auto mixed = Root3Directions::parse_any("c:60,45,0");
  ASSERT_TRUE(mixed);
  EXPECT_EQ(mixed->name(), "c:0,45,60");
  EXPECT_TRUE(mixed->exact());
  EXPECT_EQ(mixed->mask(), 0u);
  ASSERT_EQ(mixed->steps().size(), 6u);
  EXPECT_EQ(mixed->steps()[1].x, (Root3{1, 0}));
  EXPECT_EQ(mixed->steps()[1].y, (Root3{1, 0}));
  EXPECT_EQ(mixed->norm2(1), 2);
  EXPECT_EQ(mixed->norm2(2), 4);
  EXPECT_EQ(mixed->step_along(5, 5), 1);
  EXPECT_EQ(mixed->step_along(-5, -5), 4);
  EXPECT_THROW(mixed->degrees(), std::logic_error);
  EXPECT_THROW(mixed->length12(3, 1), std::logic_error);
  // c:0,10: 10 degrees as an integer step; two directions 10^-6 degrees apart are two steps
  ASSERT_TRUE(Root3Directions::parse_any("c:10,10.000001"));
  EXPECT_EQ(Root3Directions::parse_any("c:10,10.000001")->steps().size(), 4u);
  const auto ten = Root3Directions::parse_any("c:10.000,190,0");
  ASSERT_TRUE(ten);
  EXPECT_EQ(ten->name(), "c:0,10");
  EXPECT_FALSE(ten->exact());
  ASSERT_EQ(ten->steps().size(), 4u);
  const Root3Directions::Step s = ten->steps()[1];
  EXPECT_EQ(s.x.b, 0);
  EXPECT_EQ(s.y.b, 0);
  EXPECT_TRUE(s.x.a > 0 && s.y.a > 0 && s.x.a <= (1 << 24) && s.y.a <= (1 << 24)) << s.x.a << "," << s.y.a;
  EXPECT_EQ(std::gcd(s.x.a, s.y.a), 1);
  EXPECT_EQ(ten->norm2(1), s.x.a * s.x.a + s.y.a * s.y.a);
  EXPECT_LT(std::fabs(step_degrees(s) - 10) * std::numbers::pi_v<ld> / 180, 1.0L / (1LL << 36));
  EXPECT_EQ(ten->steps()[3].x, -s.x);
  EXPECT_TRUE(ten == *Root3Directions::parse_any("c:0,10"));
  EXPECT_FALSE(ten == *Root3Directions::parse_any("c:0,10.5"));
  ASSERT_TRUE(Root3Directions::parse_any("c:22.50,0"));
  EXPECT_EQ(Root3Directions::parse_any("c:22.50,0")->name(), "c:0,22.5");
  // near a slope of small numbers: that slope when within 2^-36 radians (atan(1/2) is
  // 26.56505117707799 degrees), else a step of the largest size
  const auto half = Root3Directions::parse_any("c:0,26.5650511771");
  ASSERT_TRUE(half);
  EXPECT_EQ(half->steps()[1].x, (Root3{2, 0}));
  EXPECT_EQ(half->steps()[1].y, (Root3{1, 0}));
  EXPECT_FALSE(half->exact());  // (the slope's step, but the written angle is not its)
  const auto tiny = Root3Directions::parse_any("c:0,0.00001");
  ASSERT_TRUE(tiny);
  EXPECT_EQ(tiny->steps()[1].x, (Root3{5729578, 0}));
  EXPECT_EQ(tiny->steps()[1].y, (Root3{1, 0}));
  ASSERT_TRUE(Root3Directions::parse_any("c:100,10,0"));
  EXPECT_EQ(Root3Directions::parse_any("c:100,10,0")->steps().size(), 6u);
  // the semiconvergent: slope 8388609/16777217 = [0; 1, 1, 2^23] (its denominator past 2^24), whose
  // convergent 1/2 is 1.5e-8 radians off, is (16777215, 8388608), 3.6e-15 off
  const auto semi = Root3Directions::parse_any("c:0,26.565052543115726");
  ASSERT_TRUE(semi);
  EXPECT_EQ(semi->steps()[1].x, (Root3{16777215, 0}));
  EXPECT_EQ(semi->steps()[1].y, (Root3{8388608, 0}));
  EXPECT_LT(semi->off_radians(1), 1e-13L);
  // just above 0 degrees, a set without 0: the x axis's step (1, 0); just below 180: refused
  // (-x would be 180 degrees, outside the half turn the set is written in)
  const auto above = Root3Directions::parse_any("c:0.0000000001,90");
  ASSERT_TRUE(above);
  EXPECT_EQ(above->steps()[0].x, (Root3{1, 0}));
  EXPECT_EQ(above->steps()[0].y, (Root3{0, 0}));
  EXPECT_FALSE(Root3Directions::parse_any("c:90,179.9999999999"));
  // at most eight directions at other angles (each a square root more in a length)
  EXPECT_TRUE(Root3Directions::parse_any("c:1,2,3,4,5,6,7,8"));
  EXPECT_FALSE(Root3Directions::parse_any("c:1,2,3,4,5,6,7,8,9"));
  EXPECT_TRUE(Root3Directions::parse_any("c:0,1,2,3,4,5,6,7,8,30,45"));
  // how far a staircase reaches out of its link's box: 1 up to 135-degree cones, else 1 / sin
  EXPECT_EQ(Root3Directions::parse("c:0,60,120")->box_growth(), 1);
  EXPECT_EQ(Root3Directions::parse("c:0,30")->box_growth(), 2);     // 150 degrees: 1 / sin = 2
  EXPECT_EQ(Root3Directions::parse_any("c:0,10")->box_growth(), 6);  // 170 degrees: 5.76
  EXPECT_EQ(Root3Directions::parse_any("c:0,45,60")->box_growth(), 1);  // 120 degrees at most
}

// Random sets at other angles (whole degrees and up to three decimals, two to five
// orientations): the steps counter-clockwise, each within 2^-36 radians of its written angle,
// cones and along() against atan2, fits() against the corner angles of the square taken at the
// steps' own angles, and segments made by rounding the ends of exact ones along a step always fit.
TEST(Root3Directions, ParseAnyRandomSetsAgainstFloatingReferences) {
  std::mt19937_64 rng(3304);
  int sets = 0, inexact = 0, cones = 0, alongs = 0, fit = 0, misfit = 0, rounded = 0;
  std::vector<ld> errors;  // of the integer steps, radians
  for (int round = 0; round < 300; ++round) {
    const int n = 2 + static_cast<int>(rng() % 4);
    std::string text = "c:";
    for (int k = 0; k < n; ++k) {
      const int places = static_cast<int>(rng() % 4);
      std::string d = std::to_string(rng() % 360);
      if (places > 0) {
        d += ".";
        for (int p = 0; p < places; ++p) d += static_cast<char>('0' + rng() % 10);
      }
      text += (k ? "," : "") + d;
    }
    SCOPED_TRACE(text);
    const auto set = Root3Directions::parse_any(text);
    if (!set) {
      // only a lattice set, or one orientation, may be refused here
      const auto w = written_degrees(text);
      ASSERT_TRUE(w);
      std::vector<WrittenDegrees> u = *w;
      std::sort(u.begin(), u.end());
      u.erase(std::unique(u.begin(), u.end()), u.end());
      EXPECT_TRUE(u.size() < 2 || LatticeDirections::parse(text));
      continue;
    }
    ++sets;
    inexact += !set->exact();
    const auto& steps = set->steps();
    ASSERT_EQ(steps.size(), 2 * set->orientation_texts().size());
    std::vector<ld> deg;
    for (const auto& st : steps) deg.push_back(step_degrees(st));
    for (std::size_t k = 0; k < deg.size(); ++k) {
      if (k > 0) {
        ASSERT_LT(deg[k - 1], deg[k]);
      }
      if (k < deg.size() / 2) {
        const ld want = std::stold(set->orientation_texts()[k]);
        const ld error = std::fabs(deg[k] - want) * std::numbers::pi_v<ld> / 180;
        ASSERT_LT(error, 1.0L / (1LL << 36)) << k;
        if (!steps[k].x.b && !steps[k].y.b && std::fmod(want, 45) != 0) errors.push_back(error);
        ASSERT_LE(std::max(std::fabs(steps[k].x.to_double()), std::fabs(steps[k].y.to_double())), 1 << 24);
      }
    }
    for (int i = 0; i < 300; ++i) {
      const i64 m = i % 3 == 0 ? 8 : i % 3 == 1 ? 1000 : i64{1} << 30;
      i64 dx = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * m + 1)) - m;
      i64 dy = static_cast<i64>(rng() % static_cast<std::uint64_t>(2 * m + 1)) - m;
      if (dx == 0 && dy == 0) dx = 1;
      const ld a = angle_of(static_cast<ld>(dx), static_cast<ld>(dy)) * 180 / std::numbers::pi_v<ld>;
      int want = -1;
      bool on_step = false, near = false;
      for (std::size_t k = 0; k < deg.size(); ++k) {
        const ld lo = deg[k], hi = k + 1 < deg.size() ? deg[k + 1] : deg[0] + 360;
        if (std::fabs(a - lo) < 1e-13L) on_step = true;
        else if (std::fabs(a - lo) < 1e-9L) near = true;
        if ((a > lo && a < hi) || (a + 360 > lo && a + 360 < hi)) want = static_cast<int>(k);
      }
      if (near) continue;  // the exact test decides; long double cannot
      if (on_step) want = -1;
      ASSERT_EQ(set->cone(dx, dy), want) << dx << "," << dy;
      ASSERT_EQ(set->along(dx, dy), on_step) << dx << "," << dy;
      (on_step ? alongs : cones) += 1;
      bool fits = false, known = true;
      for (const ld t : deg) {
        const std::optional<bool> r = reference_fits(dx, dy, t);
        if (!r) known = false;
        else fits = fits || *r;
      }
      if (!known && !fits) continue;
      ASSERT_EQ(set->fits(dx, dy), fits) << dx << "," << dy;
      (fits ? fit : misfit) += 1;
    }
    // exact segments p + t s (p integer, t = j / 8), both ends rounded half up, exactly in integers
    for (int i = 0; i < 100; ++i) {
      const auto& st = steps[rng() % steps.size()];
      if (st.x.b != 0 || st.y.b != 0) continue;  // a Z[sqrt3] step: the test above has those
      const i64 px = static_cast<i64>(rng() % 2001) - 1000, py = static_cast<i64>(rng() % 2001) - 1000;
      const i64 j = 1 + static_cast<i64>(rng() % 4000);
      auto round8 = [](i64 v8) { return (v8 + 4) >= 0 ? (v8 + 4) / 8 : -((-(v8 + 4) + 7) / 8); };  // floor((v8 + 4) / 8)
      const i64 qx = round8(8 * px + j * st.x.a), qy = round8(8 * py + j * st.y.a);
      ASSERT_TRUE(set->fits(qx - px, qy - py)) << px << "," << py << " + " << j << "/8 step";
      ++rounded;
    }
  }
  std::sort(errors.begin(), errors.end());
  std::printf("%d sets (%d not exact): %d cones, %d along, %d fit, %d do not, %d rounded segments; integer steps off "
              "their angle by 2^%.1f (median), 2^%.1f (largest) radians\n",
              sets, inexact, cones, alongs, fit, misfit, rounded,
              errors.empty() ? 0.0 : static_cast<double>(std::log2(errors[errors.size() / 2])),
              errors.empty() ? 0.0 : static_cast<double>(std::log2(errors.back())));
  EXPECT_GT(sets, 250);
  EXPECT_GT(inexact, 200);
  EXPECT_GT(cones, 50000);
  EXPECT_GT(alongs, 0);
  EXPECT_GT(fit, 1000);
  EXPECT_GT(misfit, 20000);
  EXPECT_GT(rounded, 10000);
}

}  // namespace root3_test
}  // namespace taut::geom
