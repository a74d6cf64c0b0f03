// Exact sums of square roots with coefficients in Q(sqrt3): the lengths of wires in a direction
// set at other angles (geom::Root3Directions::parse_any), whose steps differ in length (2, sqrt 2,
// sqrt(A^2 + B^2)), so a length is sum_i c_i sqrt(n_i) with c_i in Q(sqrt3) (the coefficients
// over a cone's two steps are quotients of cross products in Z[sqrt3]). NetsTightener compares two
// wires' lengths with it.
//
//   RadicalSum x({2, 101});       // radicals sqrt2 and sqrt101
//   x.add(0b01, R3(Rational(3)));  // 3 sqrt2
//   x.add(0b10, R3(Rational(-1))); // - sqrt101
//   x.sign();                      // 3 sqrt2 = 4.24 < 10.05: -1
//
// Representation. A value is sum over the subsets S of the radicals of c_S sqrt(prod_{i in S} n_i)
// (a product of two radicals is one more such term: sqrt n sqrt n = n), held as 2^k coefficients
// for k radicals (k is at most the set's orientations; a set has a few). The n_i need not be
// square-free nor independent: the sign below holds for real numbers whatever the relations.
//
// Exact sign, by the last radical: x = alpha + beta sqrt n with alpha and beta free of it. When
// they do not have opposite signs, x has theirs. Otherwise x has alpha's sign iff alpha^2 > n
// beta^2, the sign of alpha^2 - n beta^2 (a value with one radical fewer, so the recursion ends
// at Q(sqrt3), RationalRoot3::sign); equal means x = 0. No floating point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include <cmath>
#include <span>

#include "geom/root3_directions.h"
#include "geom/types.h"
#include "router/rational_root.h"

namespace taut::router {

class RadicalSum {
 public:
  using R3 = RationalRoot3;
  RadicalSum() = default;
  // n_i >= 1 (at most 16 of them)
  explicit RadicalSum(std::vector<std::int64_t> radicals) : n_(std::move(radicals)) {
    if (n_.size() > 16) throw std::invalid_argument("RadicalSum: more than 16 radicals");
    for (const std::int64_t n : n_)
      if (n < 1) throw std::invalid_argument("RadicalSum: a radical below 1");
    c_.assign(std::size_t{1} << n_.size(), R3());
  }
  const std::vector<std::int64_t>& radicals() const { return n_; }
  // Adds v sqrt(prod_{i in mask} n_i).
  void add(std::size_t mask, const R3& v) { c_.at(mask) = c_[mask] + v; }
  const R3& coefficient(std::size_t mask) const { return c_.at(mask); }

  int sign() const { return sign_of(c_, n_.size()); }

  // Over the same radicals.
  friend RadicalSum operator+(const RadicalSum& x, const RadicalSum& y) {
    if (x.n_ != y.n_) throw std::invalid_argument("RadicalSum: different radicals");
    RadicalSum d = x;
    for (std::size_t s = 0; s < d.c_.size(); ++s) d.c_[s] = d.c_[s] + y.c_[s];
    return d;
  }
  friend RadicalSum operator-(const RadicalSum& x, const RadicalSum& y) {
    if (x.n_ != y.n_) throw std::invalid_argument("RadicalSum: different radicals");
    RadicalSum d = x;
    for (std::size_t s = 0; s < d.c_.size(); ++s) d.c_[s] = d.c_[s] - y.c_[s];
    return d;
  }
  friend bool operator==(const RadicalSum& x, const RadicalSum& y) { return (x - y).sign() == 0; }
  friend bool operator<(const RadicalSum& x, const RadicalSum& y) { return (x - y).sign() < 0; }
  friend bool operator<=(const RadicalSum& x, const RadicalSum& y) { return (x - y).sign() <= 0; }

 private:
  // The sign of the value with coefficients c over the first k radicals (c.size() == 2^k).
  int sign_of(std::span<const R3> c, std::size_t k) const {
    if (k == 0) return c[0].sign();
    const std::size_t h = std::size_t{1} << (k - 1);
    const std::span<const R3> alpha = c.first(h), beta = c.subspan(h);
    const int sa = sign_of(alpha, k - 1), sb = sign_of(beta, k - 1);
    if (sa == 0) return sb;
    if (sb == 0 || sa == sb) return sa;
    // alpha^2 - n beta^2 over the first k - 1 radicals
    std::vector<R3> a2 = square(alpha, k - 1);
    const std::vector<R3> b2 = square(beta, k - 1);
    const R3 n(Rational(n_[k - 1]));
    for (std::size_t s = 0; s < h; ++s) a2[s] = a2[s] - n * b2[s];
    return sa * sign_of(a2, k - 1);
  }
  // x^2 for x with coefficients over the first k radicals: sqrt(P_S) sqrt(P_T) = P_{S and T}
  // sqrt(P_{S xor T}).
  std::vector<R3> square(std::span<const R3> x, std::size_t k) const {
    std::vector<R3> out(x.size(), R3());
    for (std::size_t s = 0; s < x.size(); ++s) {
      if (x[s].sign() == 0) continue;
      for (std::size_t t = 0; t < x.size(); ++t) {
        if (x[t].sign() == 0) continue;
        Rational both(1);
        for (std::size_t i = 0; i < k; ++i)
          if ((s & t) >> i & 1) both *= n_[i];
        out[s ^ t] = out[s ^ t] + x[s] * x[t] * R3(both);
      }
    }
    return out;
  }

  std::vector<std::int64_t> n_;
  std::vector<R3> c_{R3()};
};

// A polyline's length in the convex distance of a direction set (H&S Lemma 6.1: each segment's,
// the length of the shortest path in the set between its ends; the sets of
// Root3Directions::parse_any, whose steps differ in length), over the set's radicals: the
// squared step lengths that are not squares, each once (the table made once per set). A segment
// along step s is t s with t = dot(v, s) / |s|^2, of length t |s|; one in the cone of steps s1, s2
// is a s1 + b s2 with a = cross(v, s2) / D, b = cross(s1, v) / D, D = cross(s1, s2), of length
// a |s1| + b |s2|.
class SetLength {
 public:
  explicit SetLength(const geom::Root3Directions& set) : set_(set), mask_(set.steps().size()), root_(set.steps().size(), 1) {
    for (std::size_t i = 0; i < set.steps().size(); ++i) {
      const std::int64_t n = set.norm2(i);
      auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(n)));  // (then exact)
      while (r > 0 && r * r > n) --r;
      while ((r + 1) * (r + 1) <= n) ++r;
      if (r * r == n) {
        root_[i] = r;
        continue;
      }
      std::size_t k = 0;
      while (k < radicals_.size() && radicals_[k] != n) ++k;
      if (k == radicals_.size()) radicals_.push_back(n);
      mask_[i] = std::size_t{1} << k;
    }
  }
  RadicalSum operator()(std::span<const geom::Point> line) const {
    using R3 = RationalRoot3;
    const auto& steps = set_.steps();
    RadicalSum sum(radicals_);
    auto put = [&](std::size_t i, const R3& t) { sum.add(mask_[i], t * R3(Rational(root_[i]))); };
    for (std::size_t j = 1; j < line.size(); ++j) {
      const std::int64_t dx = std::int64_t{line[j].x} - line[j - 1].x, dy = std::int64_t{line[j].y} - line[j - 1].y;
      if (dx == 0 && dy == 0) continue;
      if (const int s = set_.step_along(dx, dy); s >= 0) {
        const auto i = static_cast<std::size_t>(s);
        put(i, R3(geom::Root3Directions::dot(steps[i], dx, dy)) / R3(Rational(set_.norm2(i))));
        continue;
      }
      const auto c = static_cast<std::size_t>(set_.cone(dx, dy)), c2 = (c + 1) % steps.size();
      const R3 d(geom::Root3Directions::cross(steps[c], steps[c2]));
      put(c, R3(geom::Root3Directions::cross(dx, dy, steps[c2])) / d);
      put(c2, R3(geom::Root3Directions::cross(steps[c], dx, dy)) / d);
    }
    return sum;
  }

 private:
  geom::Root3Directions set_;
  std::vector<std::int64_t> radicals_;
  std::vector<std::size_t> mask_;   // each step's radical (a bit), 0 for a square
  std::vector<std::int64_t> root_;  // the square's root, 1 for a radical
};
inline RadicalSum set_length(const geom::Root3Directions& set, std::span<const geom::Point> line) {
  return SetLength(set)(line);
}

}  // namespace taut::router
