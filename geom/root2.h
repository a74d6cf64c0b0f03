// Exact numbers a + b*sqrt(2) with integer a and b: octilinear lengths (segments at 0, 45, 90
// and 135 degrees) and their sums, compared without floating point.
//
// Representation. sqrt(2) is irrational, so a + b*sqrt(2) == c + d*sqrt(2) only when a == c and
// b == d: the pair is a unique representation, == is memberwise, and a + b*sqrt(2) is zero
// only for a == b == 0.
//
// Exact order. x <=> y is the sign of (x.a - y.a) + (x.b - y.b)*sqrt(2) = A + B*sqrt(2), with A
// and B formed in __int128. When A and B have the same sign (or one is 0) the sign is immediate.
// Otherwise both are non-zero and A + B*sqrt(2) has the sign of A iff |A| > |B|*sqrt(2), i.e.
// iff A*A > 2*B*B (both sides non-negative; never equal, since sqrt(2) is irrational).
//
// Magnitude bounds. The order is exact for |a|, |b| < 2^62: then |A|, |B| < 2^63, A*A < 2^126
// and 2*B*B < 2^127, inside __int128. + and - do not check for overflow; the bound is met by
// every length the routers and oracles form: a coordinate is below 2^30 in absolute value
// (geom/types.h), so a segment has |dx|, |dy| < 2^31 and octilinear_length gives
// a = max - min, b = min with a + b = max(|dx|, |dy|) < 2^31. A path of N segments has
// 0 <= a, b < N * 2^31, below 2^62 for every N <= 2^31 (10^7 segments: below 2^55; and the
// difference of two such lengths stays within the bound as well).
#pragma once

#include <cmath>
#include <compare>
#include <cstdint>
#include <ostream>

namespace taut::geom {

struct Root2 {
  std::int64_t a = 0, b = 0;  // a + b * sqrt(2)

  // Sign (-1, 0, 1) of a + b*sqrt(2) for |a|, |b| < 2^63 (the squares below fit in __int128).
  static constexpr int sign_of(__int128 a, __int128 b) {
    if (a >= 0 && b >= 0) return (a > 0 || b > 0) ? 1 : 0;
    if (a <= 0 && b <= 0) return (a < 0 || b < 0) ? -1 : 0;
    bool a_wins;  // |a| > |b| * sqrt(2)
    if (a == static_cast<std::int64_t>(a) && b == static_cast<std::int64_t>(b)) {
      // the usual case (differences of numbers below 2^62): one 64 x 64 -> 128-bit product each
      const std::int64_t a64 = static_cast<std::int64_t>(a), b64 = static_cast<std::int64_t>(b);
      a_wins = __int128{a64} * a64 > 2 * (__int128{b64} * b64);
    } else {
      a_wins = a * a > 2 * b * b;
    }
    return (a > 0) == a_wins ? 1 : -1;
  }
  constexpr int sign() const { return sign_of(a, b); }

  friend constexpr Root2 operator+(Root2 x, Root2 y) { return {x.a + y.a, x.b + y.b}; }
  friend constexpr Root2 operator-(Root2 x, Root2 y) { return {x.a - y.a, x.b - y.b}; }
  friend constexpr Root2 operator-(Root2 x) { return {-x.a, -x.b}; }
  constexpr Root2& operator+=(Root2 y) { return *this = *this + y; }
  friend constexpr bool operator==(const Root2&, const Root2&) = default;
  friend constexpr std::strong_ordering operator<=>(const Root2& x, const Root2& y) {
    return sign_of(__int128{x.a} - y.a, __int128{x.b} - y.b) <=> 0;
  }

  // For printing only: comparisons never go through it.
  double to_double() const {
    return static_cast<double>(a) + static_cast<double>(b) * std::sqrt(2.0);
  }

  friend std::ostream& operator<<(std::ostream& os, const Root2& x) {
    return os << x.a << (x.b < 0 ? "-" : "+") << (x.b < 0 ? -x.b : x.b) << "*sqrt2 (~"
              << x.to_double() << ")";
  }
};

// The octilinear length of (dx, dy): the shortest path using only the four orientations runs
// min(|dx|, |dy|) diagonally and the rest straight. Needs |dx|, |dy| < 2^62.
constexpr Root2 octilinear_length(std::int64_t dx, std::int64_t dy) {
  const std::int64_t x = dx < 0 ? -dx : dx, y = dy < 0 ? -dy : dy;
  const std::int64_t lo = x < y ? x : y, hi = x < y ? y : x;
  return {hi - lo, lo};
}

}  // namespace taut::geom
