// Exact numbers a + b sqrt3 (a, b rational, gmpxx) for the references: the bends of paths in a
// direction set at multiples of 30 degrees lie in Q(sqrt3). Written here, not taken from the
// router (router::RationalRoot3), so the references share only geom's types with the code they
// check. Sign: a + b sqrt3 with a and b of opposite signs has a's sign iff a^2 > 3 b^2 (never
// equal: sqrt3 is irrational).
#pragma once

#include <gmpxx.h>

#include <string>

#include "geom/types.h"

namespace taut::oracle {

struct Q3 {
  mpq_class a, b;
  Q3() = default;
  Q3(long v) : a(v), b(0) {}  // NOLINT: integers and rationals are numbers of the field
  Q3(const mpq_class& a_, const mpq_class& b_ = 0) : a(a_), b(b_) {}  // NOLINT
  int sign() const {
    const int sa = sgn(a), sb = sgn(b);
    if (sa >= 0 && sb >= 0) return (sa > 0 || sb > 0) ? 1 : 0;
    if (sa <= 0 && sb <= 0) return (sa < 0 || sb < 0) ? -1 : 0;
    const mpq_class d = a * a - 3 * b * b;
    return sa > 0 ? sgn(d) : -sgn(d);
  }
  friend Q3 operator+(const Q3& x, const Q3& y) { return {x.a + y.a, x.b + y.b}; }
  friend Q3 operator-(const Q3& x, const Q3& y) { return {x.a - y.a, x.b - y.b}; }
  friend Q3 operator-(const Q3& x) { return {-x.a, -x.b}; }
  friend Q3 operator*(const Q3& x, const Q3& y) { return {x.a * y.a + 3 * x.b * y.b, x.a * y.b + x.b * y.a}; }
  friend Q3 operator/(const Q3& x, const Q3& y) {  // y != 0
    const mpq_class n = y.a * y.a - 3 * y.b * y.b;
    return {(x.a * y.a - 3 * x.b * y.b) / n, (x.b * y.a - x.a * y.b) / n};
  }
  friend bool operator==(const Q3& x, const Q3& y) { return x.a == y.a && x.b == y.b; }
  friend bool operator!=(const Q3& x, const Q3& y) { return !(x == y); }
  friend bool operator<(const Q3& x, const Q3& y) { return (x - y).sign() < 0; }
  friend bool operator>(const Q3& x, const Q3& y) { return (x - y).sign() > 0; }
  friend bool operator<=(const Q3& x, const Q3& y) { return (x - y).sign() <= 0; }
  friend bool operator>=(const Q3& x, const Q3& y) { return (x - y).sign() >= 0; }
  std::string str() const { return a.get_str() + (sgn(b) < 0 ? "" : "+") + b.get_str() + "r3"; }
};

struct Q3Point {
  Q3 x, y;
  friend bool operator==(const Q3Point& p, const Q3Point& q) { return p.x == q.x && p.y == q.y; }
};

inline Q3Point q3(geom::Point p) { return {Q3(static_cast<long>(p.x)), Q3(static_cast<long>(p.y))}; }

}  // namespace taut::oracle
