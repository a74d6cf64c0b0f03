#include "geom/root3_directions.h"

#include <array>
#include <cstdint>

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

// cross(s, v) = s.x v.y - s.y v.x and dot(s, v) for an integer v.
Root3 cross(const Step& s, i64 dx, i64 dy) { return dy * s.x - dx * s.y; }
Root3 dot(const Step& s, i64 dx, i64 dy) { return dx * s.x + dy * s.y; }
Root3 cross(const Step& s, const Step& t) { return s.x * t.y - s.y * t.x; }

}  // namespace

Root3Directions::Root3Directions(unsigned mask) : mask_(mask) {
  for (unsigned k = 0; k < 12; ++k)
    if (mask_ & (1u << (k % 6))) steps_.push_back(kSteps[k]);
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
  for (const int d : degrees()) s += (s.size() > 2 ? "," : "") + std::to_string(d);
  return s;
}

std::vector<int> Root3Directions::degrees() const {
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

int Root3Directions::cone(i64 dx, i64 dy) const {
  const std::size_t n = steps_.size();
  for (std::size_t i = 0; i < n; ++i)
    // strictly counter-clockwise of step i and clockwise of step i + 1 (every cone is below 180)
    if (cross(steps_[i], dx, dy).sign() > 0 && cross(steps_[(i + 1) % n], dx, dy).sign() < 0) return static_cast<int>(i);
  return -1;
}

Root3 Root3Directions::length12(i64 dx, i64 dy) const {
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
