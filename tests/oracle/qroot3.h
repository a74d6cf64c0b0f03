// Exact numbers a + b sqrt3 (a, b rational, gmpxx) for the references: the bends of paths in a
// direction set at multiples of 30 degrees lie in Q(sqrt3). Written here, not taken from the
// router (router::RationalRoot3), so the references share only geom's types with the code they
// check. Sign: a + b sqrt3 with a and b of opposite signs has a's sign iff a^2 > 3 b^2 (never
// equal: sqrt3 is irrational).
#pragma once

#include <gmpxx.h>

#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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
inline Q3 cross(const Q3Point& a, const Q3Point& b) { return a.x * b.y - a.y * b.x; }
inline Q3 dot(const Q3Point& a, const Q3Point& b) { return a.x * b.x + a.y * b.y; }
inline Q3Point minus(const Q3Point& a, const Q3Point& b) { return {a.x - b.x, a.y - b.y}; }

// Lengths in a direction set whose steps (vectors with coordinates in Z[sqrt3]) may differ in
// length, for the references (written apart from router/radical_sum.h): a length is held as
// coefficients in Q(sqrt3) of the square roots of the steps' squared lengths n (a square folded
// into n = 1), each segment the shortest path in the set between its ends (H&S Lemma 6.1: along a
// step s, |v| = (dot(v, s) / n) sqrt n; in the cone of steps s1, s2, a sqrt n1 + b sqrt n2 with v =
// a s1 + b s2 by Cramer's rule). Two lengths are compared by the sign of their difference,
// decided by squaring; at most two radicals other than 1 (the test sets have one or two).
class SetLengths {
 public:
  using Len = std::map<long, Q3>;
  // every step of the set, counter-clockwise (a step's opposite included)
  explicit SetLengths(std::vector<Q3Point> steps) : steps_(std::move(steps)) {
    for (const Q3Point& u : steps_) {
      const Q3 n2 = dot(u, u);
      if (sgn(n2.b) != 0 || n2.a.get_den() != 1) throw std::logic_error("SetLengths: a squared length is not an integer");
      const long n = n2.a.get_num().get_si();
      const long r = mpz_class(sqrt(n2.a.get_num())).get_si();
      norms_.push_back(r * r == n ? Norm{n, 1, r} : Norm{n, n, 1});
    }
  }
  Len length(std::span<const Q3Point> line) const {
    Len sum;
    auto put = [&](std::size_t k, const Q3& t) { sum[norms_[k].key] = sum[norms_[k].key] + t * Q3(norms_[k].scale); };
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const Q3Point v = minus(line[i + 1], line[i]);
      if (v.x.sign() == 0 && v.y.sign() == 0) continue;
      bool done = false;
      for (std::size_t k = 0; k < steps_.size() && !done; ++k)
        if (cross(steps_[k], v).sign() == 0 && dot(steps_[k], v).sign() > 0) {
          put(k, dot(steps_[k], v) / Q3(norms_[k].n));
          done = true;
        }
      for (std::size_t k = 0; k < steps_.size() && !done; ++k) {
        const std::size_t l = (k + 1) % steps_.size();
        const Q3 d = cross(steps_[k], steps_[l]), a = cross(v, steps_[l]) / d, b = cross(steps_[k], v) / d;
        if (a.sign() > 0 && b.sign() > 0) {
          put(k, a);  // a |s1| = a sqrt n1
          put(l, b);
          done = true;
        }
      }
      if (!done) throw std::logic_error("SetLengths: a segment in no cone");
    }
    return sum;
  }
  Len length(std::span<const geom::Point> line) const {
    std::vector<Q3Point> q;
    for (const geom::Point p : line) q.push_back(q3(p));
    return length(std::span<const Q3Point>(q));
  }
  static Len plus(Len a, const Len& b) {
    for (const auto& [n, c] : b) a[n] = a[n] + c;
    return a;
  }
  // The sign of a - b.
  static int compare(const Len& a, const Len& b) {
    Len d = a;
    for (const auto& [n, c] : b) d[n] = d[n] - c;
    std::vector<std::pair<long, Q3>> roots;
    for (const auto& [n, c] : d)
      if (n != 1 && c.sign() != 0) roots.push_back({n, c});
    const Q3 r = d.count(1) ? d[1] : Q3(0);
    if (roots.empty()) return r.sign();
    if (roots.size() == 1) return sign_root(r, roots[0].second, roots[0].first);
    if (roots.size() > 2) throw std::logic_error("SetLengths: more than two radicals");
    // r + y sqrt m + z sqrt n: (r + y sqrt m) against -z sqrt n, by squares when of opposite signs
    const auto& [m, y] = roots[0];
    const auto& [n, z] = roots[1];
    const int s1 = sign_root(r, y, m), sz = z.sign();
    if (s1 == 0) return sz;
    if (sz == 0 || s1 == sz) return s1;
    return s1 * sign_root(r * r + Q3(m) * y * y - Q3(n) * z * z, Q3(2) * r * y, m);
  }

 private:
  static int sign_root(const Q3& x, const Q3& y, long m) {  // x + y sqrt m, m not a square
    const int sx = x.sign(), sy = y.sign();
    if (sx == 0) return sy;
    if (sy == 0 || sx == sy) return sx;
    return sx * (x * x - Q3(m) * y * y).sign();
  }
  struct Norm {
    long n, key, scale;  // a step's squared length; sqrt n = scale sqrt key (key 1 for a square)
  };
  std::vector<Q3Point> steps_;
  std::vector<Norm> norms_;
};

}  // namespace taut::oracle
