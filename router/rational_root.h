// Exact numbers a + b sqrt(N) with rational a and b (the field Q(sqrt N), N = 2 or 3, not a
// square): the octilinear map's cell vertices (N = 2: bisectors whose slopes lie in Q(sqrt2)
// meet there; router/spm.h) and the staircases of direction sets at multiples of 30 degrees
// (N = 3; router/root3_staircase.h). Signs are exact: a + b sqrt N with a and b of opposite signs
// has a's sign iff a^2 > N b^2 (never equal: sqrt N is irrational).
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

#include <boost/multiprecision/gmp.hpp>

#include "geom/root2.h"
#include "geom/root3.h"

namespace taut::router {

// Exact rationals: bisectors sit at half-integers and meet sloped blockage edges at rationals
// whose numerators pass 2^64, so no fixed-width integer pair holds them. Boost.Multiprecision over
// GMP's mpq (always reduced) keeps them exact; its header-only cpp_rational was 4x slower here.
using Rational = boost::multiprecision::mpq_rational;

template <int N>
struct RationalRoot {
  Rational a, b;
  RationalRoot() = default;
  RationalRoot(Rational a_, Rational b_ = 0) : a(std::move(a_)), b(std::move(b_)) {}
  explicit RationalRoot(const geom::Root2& r)
    requires(N == 2)
      : a(r.a), b(r.b) {}
  explicit RationalRoot(const geom::Root3& r)
    requires(N == 3)
      : a(r.a), b(r.b) {}
  int sign() const {
    const int sa = a.sign(), sb = b.sign();
    if (sa >= 0 && sb >= 0) return (sa > 0 || sb > 0) ? 1 : 0;
    if (sa <= 0 && sb <= 0) return (sa < 0 || sb < 0) ? -1 : 0;
    const Rational d = a * a - N * b * b;
    return sa > 0 ? d.sign() : -d.sign();
  }
  friend RationalRoot operator+(const RationalRoot& x, const RationalRoot& y) {
    if (x.b.sign() == 0 && y.b.sign() == 0) return RationalRoot(x.a + y.a);
    return {x.a + y.a, x.b + y.b};
  }
  friend RationalRoot operator-(const RationalRoot& x, const RationalRoot& y) {
    if (x.b.sign() == 0 && y.b.sign() == 0) return RationalRoot(x.a - y.a);
    return {x.a - y.a, x.b - y.b};
  }
  friend RationalRoot operator-(const RationalRoot& x) { return {-x.a, -x.b}; }
  // Rational operands (b = 0: most points and parameters are) skip the products with b: the same
  // exact values with fewer GMP operations (since 2026-12-07).
  friend RationalRoot operator*(const RationalRoot& x, const RationalRoot& y) {
    if (y.b.sign() == 0) return x.b.sign() == 0 ? RationalRoot(x.a * y.a) : RationalRoot(x.a * y.a, x.b * y.a);
    if (x.b.sign() == 0) return {x.a * y.a, x.a * y.b};
    return {x.a * y.a + N * x.b * y.b, x.a * y.b + x.b * y.a};
  }
  // y != 0
  friend RationalRoot operator/(const RationalRoot& x, const RationalRoot& y) {
    if (y.b.sign() == 0) return {x.a / y.a, x.b / y.a};
    const Rational n = y.a * y.a - N * y.b * y.b;  // nonzero: sqrt N is irrational
    return {(x.a * y.a - N * x.b * y.b) / n, (x.b * y.a - x.a * y.b) / n};
  }
  friend bool operator==(const RationalRoot&, const RationalRoot&) = default;
  // x - y's sign (rational x and y: their a's compared directly)
  friend int compare(const RationalRoot& x, const RationalRoot& y) {
    if (x.b.sign() == 0 && y.b.sign() == 0) return x.a < y.a ? -1 : (y.a < x.a ? 1 : 0);
    return (x - y).sign();
  }
  friend bool operator<(const RationalRoot& x, const RationalRoot& y) { return compare(x, y) < 0; }
  friend bool operator<=(const RationalRoot& x, const RationalRoot& y) { return compare(x, y) <= 0; }
  friend bool operator>(const RationalRoot& x, const RationalRoot& y) { return compare(x, y) > 0; }
  friend bool operator>=(const RationalRoot& x, const RationalRoot& y) { return compare(x, y) >= 0; }
  // For pictures and messages, and as the estimate floor() corrects.
  double to_double() const { return a.template convert_to<double>() + b.template convert_to<double>() * std::sqrt(double(N)); }
  // The largest integer not above it (exact: a floating estimate, then exact signs with steps
  // that double, then halve, so an estimate far off, as when a and b nearly cancel, costs a
  // logarithm of the error; the value must lie within the int64 range).
  std::int64_t floor() const {
    const double d = std::floor(to_double());
    std::int64_t f = std::isfinite(d) && std::fabs(d) < 4e18 ? static_cast<std::int64_t>(d) : 0;
    auto below = [&](std::int64_t g) { return (*this - RationalRoot(Rational(g))).sign() < 0; };  // value < g
    // an interval [lo, hi) holding the floor, found by doubling steps from f
    std::int64_t lo = f, hi = f + 1;
    for (std::int64_t step = 1; below(lo); step *= 2) hi = lo, lo -= step;
    for (std::int64_t step = 1; !below(hi); step *= 2) lo = hi, hi += step;
    while (hi - lo > 1) {
      const std::int64_t mid = lo + (hi - lo) / 2;
      (below(mid) ? hi : lo) = mid;
    }
    return lo;
  }
};
using RationalRoot2 = RationalRoot<2>;
using RationalRoot3 = RationalRoot<3>;

// A point in Q(sqrt3)^2: the exact vertices of wires in a set at multiples of 30 degrees.
struct R3Point {
  RationalRoot3 x, y;
  friend bool operator==(const R3Point&, const R3Point&) = default;
};

// An __int128 as a GMP integer (two 64-bit halves: mpz has no __int128 constructor).
inline boost::multiprecision::mpz_int to_mpz(__int128 v) {
  const bool neg = v < 0;
  const unsigned __int128 u = neg ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
  boost::multiprecision::mpz_int z = static_cast<std::uint64_t>(u >> 64);
  z <<= 64;
  z += static_cast<std::uint64_t>(u);
  return neg ? boost::multiprecision::mpz_int(-z) : z;
}

// Sign (-1, 0, 1) of a + b sqrt N for any __int128 a and b (sums of many lengths in Z[sqrt N], as
// NetsTightener compares wires in a set at multiples of 30 degrees): a^2 against N b^2 in GMP
// integers, which hold them at any size.
template <int N>
int sign_wide(__int128 a, __int128 b) {
  if (a >= 0 && b >= 0) return (a > 0 || b > 0) ? 1 : 0;
  if (a <= 0 && b <= 0) return (a < 0 || b < 0) ? -1 : 0;
  constexpr __int128 kSmall = __int128{1} << 61;  // a^2 and N b^2 fit in __int128
  if (a > -kSmall && a < kSmall && b > -kSmall && b < kSmall) return (a > 0) == (a * a > N * (b * b)) ? 1 : -1;
  const boost::multiprecision::mpz_int A = to_mpz(a), B = to_mpz(b);
  return (a > 0) == (A * A > N * B * B) ? 1 : -1;
}

}  // namespace taut::router
