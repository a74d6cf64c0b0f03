// Exact numbers a + b*sqrt(3) with integer a and b: the coordinates of direction sets at multiples
// of 30 degrees (geom/root3_directions.h), whose unit vectors (cos, sin) are (1, 0), (sqrt3/2,
// 1/2), (1/2, sqrt3/2), ..., and the cross products and lengths formed from them, compared
// without floating point.
//
// Representation. sqrt(3) is irrational, so a + b*sqrt(3) == c + d*sqrt(3) only when a == c and
// b == d: the pair is unique, == is memberwise, and the number is zero only for a == b == 0.
//
// Exact sign. When a and b have the same sign (or one is 0) the sign is immediate. Otherwise
// a + b*sqrt(3) has the sign of a iff |a| > |b|*sqrt(3), i.e. iff a*a > 3*b*b (never equal, as
// sqrt(3) is irrational). sign_of needs |a|, |b| < 2^62 (3 b^2 in __int128), so comparisons
// (which take differences) need |a|, |b| < 2^61; operator* needs its result's coefficients below
// 2^63. Every value formed here stays below 2^57: coordinates are below 2^30 (vectors below
// 2^32), a step's coefficients at most 2 (multiples of 30 degrees) or 2^24 (the integer steps of
// Root3Directions::parse_any), and length12 multiplies a cross product (below 2^34, its sets'
// steps being of the first kind) by at most 12.
#pragma once

#include <cmath>
#include <compare>
#include <cstdint>
#include <ostream>

namespace taut::geom {

struct Root3 {
  std::int64_t a = 0, b = 0;  // a + b * sqrt(3)

  // Sign (-1, 0, 1) of a + b*sqrt(3) for |a|, |b| < 2^62.
  static constexpr int sign_of(__int128 a, __int128 b) {
    if (a >= 0 && b >= 0) return (a > 0 || b > 0) ? 1 : 0;
    if (a <= 0 && b <= 0) return (a < 0 || b < 0) ? -1 : 0;
    const bool a_wins = a * a > 3 * (b * b);  // |a| > |b| * sqrt(3)
    return (a > 0) == a_wins ? 1 : -1;
  }
  constexpr int sign() const { return sign_of(a, b); }

  friend constexpr Root3 operator+(Root3 x, Root3 y) { return {x.a + y.a, x.b + y.b}; }
  friend constexpr Root3 operator-(Root3 x, Root3 y) { return {x.a - y.a, x.b - y.b}; }
  friend constexpr Root3 operator-(Root3 x) { return {-x.a, -x.b}; }
  friend constexpr Root3 operator*(Root3 x, Root3 y) { return {x.a * y.a + 3 * x.b * y.b, x.a * y.b + x.b * y.a}; }
  friend constexpr Root3 operator*(std::int64_t k, Root3 y) { return {k * y.a, k * y.b}; }
  constexpr Root3& operator+=(Root3 y) { return *this = *this + y; }
  friend constexpr bool operator==(const Root3&, const Root3&) = default;
  friend constexpr std::strong_ordering operator<=>(const Root3& x, const Root3& y) {
    return sign_of(__int128{x.a} - y.a, __int128{x.b} - y.b) <=> 0;
  }

  // For printing only: comparisons never go through it.
  double to_double() const { return static_cast<double>(a) + static_cast<double>(b) * std::sqrt(3.0); }

  friend std::ostream& operator<<(std::ostream& os, const Root3& x) {
    return os << x.a << (x.b < 0 ? "-" : "+") << (x.b < 0 ? -x.b : x.b) << "*sqrt3 (~" << x.to_double() << ")";
  }
};

}  // namespace taut::geom
