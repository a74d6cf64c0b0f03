#include "geom/root3_directions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "geom/directions.h"

namespace taut::geom {

namespace {

using i64 = std::int64_t;
using Step = Root3Directions::Step;

// Twice the unit vectors at 30k degrees, k = 0..11.
constexpr std::array<Step, 12> kSteps = {{
    {{2, 0}, {0, 0}},    {{0, 1}, {1, 0}},   {{1, 0}, {0, 1}},   {{0, 0}, {2, 0}},
    {{-1, 0}, {0, 1}},   {{0, -1}, {1, 0}},  {{-2, 0}, {0, 0}},  {{0, -1}, {-1, 0}},
    {{-1, 0}, {0, -1}},  {{0, 0}, {-2, 0}},  {{1, 0}, {0, -1}},  {{0, 1}, {-1, 0}},
}};

Root3 cross(const Step& s, const Step& t) { return Root3Directions::cross(s, t); }

// 0 for the directions from +x (included) to -x (excluded), counter-clockwise; 1 for the rest.
int half(const Step& s) { return (s.y.sign() > 0 || (s.y.sign() == 0 && s.x.sign() > 0)) ? 0 : 1; }
// s before t counter-clockwise from +x (exact; not parallel and alike)
bool ccw_before(const Step& s, const Step& t) {
  const int hs = half(s), ht = half(t);
  return hs != ht ? hs < ht : cross(s, t).sign() > 0;
}

constexpr std::int64_t kStepMax = std::int64_t{1} << 24;
constexpr long double kMaxError = 1.0L / (std::int64_t{1} << 36);  // radians
constexpr std::size_t kMaxInexact = 8;  // orientations at other angles (RadicalSum's radicals)

struct Realized {
  Step step;
  std::int64_t norm2 = 0;
  bool exact = true;
  long double off = 0;  // radians (long double: a report)
};

// A direction of parse_any's sets as its step (the top of the header); nullopt when the step
// would be off it by more than kMaxError.
std::optional<Realized> realize(const WrittenDegrees& w) {
  if (w.fraction.empty() && w.whole % 30 == 0) return Realized{kSteps[static_cast<std::size_t>(w.whole / 30)], 4, true, 0};
  if (w.fraction.empty() && w.whole % 45 == 0)
    return Realized{{{w.whole == 45 ? 1 : -1, 0}, {1, 0}}, 2, true, 0};  // 45 or 135
  // The slope in 50-digit binary floating point (Boost.Multiprecision's cpp_bin_float, the same on
  // every machine, unlike long double): it chooses the step, nothing more (every later decision
  // is exact for the step).
  using F = boost::multiprecision::cpp_bin_float_50;
  F r;
  try {
    r = F(w.text()) * boost::math::constants::pi<F>() / 180;
  } catch (const std::exception&) {
    return std::nullopt;  // (not expected of digits and one '.')
  }
  const F c = cos(r), s = sin(r);  // s > 0: 0 < r < pi
  const bool steep = abs(s) > abs(c);
  const F t = steep ? F(abs(c) / s) : F(s / abs(c));  // in [0, 1]
  // the last convergent of t's continued fraction with numerator and denominator at most
  // kStepMax, and the semiconvergent past it with the largest allowed multiple: whichever is
  // nearer (the two best approximations round t within the bound)
  std::int64_t p0 = 0, q0 = 1, p1 = 1, q1 = 0, next_a = 0;
  F x = t;
  for (int i = 0; i < 200; ++i) {
    const F a = floor(x);
    if (a > kStepMax) {
      next_a = kStepMax + 1;
      break;
    }
    const auto ai = a.convert_to<std::int64_t>();
    const std::int64_t p2 = ai * p1 + p0, q2 = ai * q1 + q0;
    if (p2 > kStepMax || q2 > kStepMax) {
      next_a = ai;
      break;
    }
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    const F f = x - a;
    if (!(f > 0)) break;
    x = 1 / f;
  }
  std::vector<std::pair<std::int64_t, std::int64_t>> tries{{p1, q1}};
  if (next_a > 0 && q1 > 0) {
    const std::int64_t j = std::min((kStepMax - q0) / q1, p1 > 0 ? (kStepMax - p0) / p1 : kStepMax);
    if (j >= 1) tries.push_back({p0 + j * p1, q0 + j * q1});
  }
  std::optional<Realized> best;
  F best_error = 0;
  for (const auto& [p, q] : tries) {
    if (q == 0) continue;
    std::int64_t A = steep ? p : q, B = steep ? q : p;  // the step's |x| and y
    if (c < 0) A = -A;
    // along the x axis: +x is 0 degrees' step (a direction just above 0 may be taken as it, when
    // the set lacks 0); -x would be 180 degrees, out of the half turn the set is written in
    if (B == 0 && A < 0) continue;
    const F error = abs(atan2(F(B), F(A)) - r);
    if (!best || error < best_error) {
      best = Realized{{{A, 0}, {B, 0}}, A * A + B * B, false, error.convert_to<long double>()};
      best_error = error;
    }
  }
  if (!best || best_error > kMaxError) return std::nullopt;
  if (best->step.y.a == 0) best->step.x.a = 1, best->norm2 = 1;  // (1, 0)
  return best;
}

}  // namespace

Root3Directions::Root3Directions(unsigned mask) : mask_(mask) {
  for (unsigned k = 0; k < 12; ++k)
    if (mask_ & (1u << (k % 6))) {
      steps_.push_back(kSteps[k]);
      norm2_.push_back(4);
    }
  for (const int d : degrees()) orient_.push_back({std::to_string(d), true, 0});
}

std::optional<Root3Directions> Root3Directions::parse_any(std::string_view text) {
  std::string why;
  return parse_any(text, why);
}

std::optional<Root3Directions> Root3Directions::parse_any(std::string_view text, std::string& why) {
  why.clear();
  if (auto exact = parse(text)) return exact;
  if (LatticeDirections::parse(text)) {
    why = "a lattice set (geom::LatticeDirections)";
    return std::nullopt;
  }
  std::optional<std::vector<WrittenDegrees>> written = written_degrees(text);
  if (!written) {
    why = "not c: followed by directions in degrees (digits with at most one '.')";
    return std::nullopt;
  }
  std::sort(written->begin(), written->end());
  written->erase(std::unique(written->begin(), written->end()), written->end());
  if (written->size() < 2) {
    why = "fewer than two orientations modulo 180 degrees";
    return std::nullopt;
  }
  Root3Directions set;
  set.mask_ = 0;
  std::vector<Realized> half_steps;  // in the written directions' increasing order, from 0 to below 180
  std::size_t inexact = 0;
  for (const WrittenDegrees& w : *written) {
    const std::optional<Realized> r = realize(w);
    if (!r) {
      why = "no integer step of at most 2^24 lies within 2^-36 radians of " + w.text() +
            " degrees (it is about 10^-6 degrees off a slope of small integers, or a step of 180 degrees would be needed)";
      return std::nullopt;
    }
    // strictly counter-clockwise of the previous one (the written order): no two parallel, none
    // out of order
    if (!half_steps.empty() && !ccw_before(half_steps.back().step, r->step)) {
      why = set.orient_.back().text + " and " + w.text() + " degrees are too close to tell apart by integer steps of at most 2^24";
      return std::nullopt;
    }
    half_steps.push_back(*r);
    inexact += r->exact ? 0 : 1;
    set.orient_.push_back({w.text(), r->exact, r->off});
  }
  if (inexact > kMaxInexact) {  // (each one more square root in a length)
    why = std::to_string(inexact) + " directions at multiples of neither 30 nor 45 degrees (at most " +
          std::to_string(kMaxInexact) + ")";
    return std::nullopt;
  }
  for (int side = 0; side < 2; ++side)
    for (const Realized& r : half_steps) {
      set.steps_.push_back(side == 0 ? r.step : Step{-r.step.x, -r.step.y});
      set.norm2_.push_back(r.norm2);
    }
  return set;
}

std::optional<Root3Directions> Root3Directions::from_mask(unsigned mask) {
  mask &= 0b111111;
  int bits = 0;
  for (int k = 0; k < 6; ++k) bits += (mask >> k) & 1;
  if (bits < 2 || (mask & 0b110110) == 0) return std::nullopt;  // fewer than two, or 0 and 90 only
  return Root3Directions(mask);
}

std::optional<Root3Directions> Root3Directions::parse(std::string_view text) {
  const std::optional<std::vector<int>> degrees = whole_degrees(text);
  if (!degrees) return std::nullopt;
  unsigned mask = 0;
  for (const int deg : *degrees) {
    if (deg % 30 != 0) return std::nullopt;
    mask |= 1u << (deg / 30);
  }
  return from_mask(mask);
}

std::string Root3Directions::name() const {
  std::string s = "c:";
  for (const Orientation& o : orient_) s += (s.size() > 2 ? "," : "") + o.text;
  return s;
}

std::vector<int> Root3Directions::degrees() const {
  if (mask_ == 0) throw std::logic_error("Root3Directions::degrees: a set of parse_any at other angles");
  std::vector<int> out;
  for (int k = 0; k < 6; ++k)
    if (mask_ & (1u << k)) out.push_back(30 * k);
  return out;
}

int Root3Directions::step_along(i64 dx, i64 dy) const {
  for (std::size_t i = 0; i < steps_.size(); ++i)
    if (cross(steps_[i], dx, dy) == Root3{} && dot(steps_[i], dx, dy).sign() > 0) return static_cast<int>(i);
  return -1;
}

bool Root3Directions::cones_leave_box() const {
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    const Step& a = steps_[i];
    const Step& b = steps_[(i + 1) % steps_.size()];
    if (a.x.sign() * b.x.sign() < 0 || a.y.sign() * b.y.sign() < 0) return true;
  }
  return false;
}

int Root3Directions::box_growth() const {
  int g = 1;
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    const Step& a = steps_[i];
    const Step& b = steps_[(i + 1) % steps_.size()];
    const Root3 c = cross(a, b), d = a.x * b.x + a.y * b.y;  // c > 0: a cone is below 180 degrees
    if (!(d.sign() < 0 && (c + d).sign() < 0)) continue;    // at most 135 degrees
    const long double inv_sin = std::sqrt(static_cast<long double>(norm2_[i]) * static_cast<long double>(norm2_[(i + 1) % steps_.size()])) /
                                static_cast<long double>(c.to_double());
    g = std::max(g, static_cast<int>(std::ceil(inv_sin)));
  }
  return g;
}

int Root3Directions::cone(i64 dx, i64 dy) const {
  const std::size_t n = steps_.size();
  for (std::size_t i = 0; i < n; ++i)
    // strictly counter-clockwise of step i and clockwise of step i + 1 (every cone is below 180)
    if (cross(steps_[i], dx, dy).sign() > 0 && cross(steps_[(i + 1) % n], dx, dy).sign() < 0) return static_cast<int>(i);
  return -1;
}

Root3 Root3Directions::length12(i64 dx, i64 dy) const {
  if (mask_ == 0) throw std::logic_error("Root3Directions::length12: a set of parse_any at other angles");
  if (dx == 0 && dy == 0) return {};
  const int c = cone(dx, dy);
  if (c < 0) return {12 * (dx != 0 ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy)), 0};  // along an axis
  const Step& s1 = steps_[static_cast<std::size_t>(c)];
  const Step& s2 = steps_[(static_cast<std::size_t>(c) + 1) % steps_.size()];
  // v = a s1 + b s2 with a = cross(v, s2) / D, b = cross(s1, v) / D, D = cross(s1, s2) in {2,
  // 2 sqrt3, 4}; the length is 2 (a + b), and 12 / D is 6, 2 sqrt3 or 3
  const Root3 d = cross(s1, s2);
  const Root3 twelve_over_d = d == Root3{2, 0} ? Root3{6, 0} : d == Root3{0, 2} ? Root3{0, 2} : Root3{3, 0};
  return 2 * ((cross(s1, dx, dy) - cross(s2, dx, dy)) * twelve_over_d);
}

bool Root3Directions::runs_within(std::span<const Point> line) const {
  for (std::size_t j = 1; j < line.size(); ++j)
    if (!fits(i64{line[j].x} - line[j - 1].x, i64{line[j].y} - line[j - 1].y)) return false;
  return true;
}

bool Root3Directions::fits(i64 dx, i64 dy) const {
  // The set holds each step's opposite, so a ray meets the square iff the line through 0 along
  // it does: iff the square's corners are not all strictly on one side of that line (never when
  // the square holds 0). One line per orientation: the first half of the steps (0 to 150 degrees).
  for (std::size_t i = 0; i < steps_.size() / 2; ++i) {
    const Step& s = steps_[i];
    int pos = 0, neg = 0;
    for (const i64 ex : {-1, 1})
      for (const i64 ey : {-1, 1}) {
        const int o = cross(s, dx + ex, dy + ey).sign();
        pos += o > 0;
        neg += o < 0;
      }
    if (pos < 4 && neg < 4) return true;
  }
  return false;
}

}  // namespace taut::geom
