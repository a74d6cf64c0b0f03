#include "geom/directions.h"

#include <cstdint>

namespace taut::geom {

namespace {

using i64 = std::int64_t;
using i128 = __int128;

// The eight unit lattice steps counter-clockwise from +x; step k is at k * 45 degrees.
constexpr Point kSteps[8] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};

i128 cross(Point a, i64 dx, i64 dy) { return i128{a.x} * dy - i128{a.y} * dx; }

}  // namespace

LatticeDirections::LatticeDirections(unsigned mask) : mask_(mask) {
  for (int k = 0; k < 8; ++k)
    if (mask_ & (1u << (k % 4))) steps_.push_back(kSteps[k]);
}

std::optional<LatticeDirections> LatticeDirections::from_mask(unsigned mask) {
  mask &= 0b1111;
  int bits = 0;
  for (int k = 0; k < 4; ++k) bits += (mask >> k) & 1;
  if (bits < 2) return std::nullopt;
  return LatticeDirections(mask);
}

std::optional<std::vector<WrittenDegrees>> written_degrees(std::string_view text) {
  if (text.substr(0, 2) != "c:") return std::nullopt;
  std::string_view rest = text.substr(2);
  std::vector<WrittenDegrees> out;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view tok = rest.substr(0, comma);
    // digits with at most one '.' (as the CLI's other commands read them: "90", "090", "90.",
    // ".5"), the integer part taken modulo 180 digit by digit (any length, no overflow)
    const std::size_t dot = tok.find('.');
    const std::string_view ip = tok.substr(0, dot);
    const std::string_view fp = dot == std::string_view::npos ? std::string_view{} : tok.substr(dot + 1);
    if (ip.empty() && fp.empty()) return std::nullopt;
    WrittenDegrees w;
    for (const char c : ip) {
      if (c < '0' || c > '9') return std::nullopt;
      w.whole = (w.whole * 10 + (c - '0')) % 180;
    }
    for (const char c : fp)
      if (c < '0' || c > '9') return std::nullopt;  // a second '.', or a sign
    w.fraction = std::string(fp.substr(0, fp.find_last_not_of('0') + 1));  // (npos + 1 == 0: all zeros)
    out.push_back(std::move(w));
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  return out;
}

std::optional<std::vector<int>> whole_degrees(std::string_view text) {
  const std::optional<std::vector<WrittenDegrees>> w = written_degrees(text);
  if (!w) return std::nullopt;
  std::vector<int> out;
  for (const WrittenDegrees& d : *w) {
    if (!d.fraction.empty()) return std::nullopt;  // a fraction that is not zero
    out.push_back(d.whole);
  }
  return out;
}

std::optional<LatticeDirections> LatticeDirections::parse(std::string_view text) {
  if (text == "rectilinear") return rectilinear();
  if (text == "octilinear") return octilinear();
  const std::optional<std::vector<int>> degrees = whole_degrees(text);
  if (!degrees) return std::nullopt;
  unsigned mask = 0;
  for (const int deg : *degrees) {
    if (deg % 45 != 0) return std::nullopt;
    mask |= 1u << (deg / 45);
  }
  return from_mask(mask);
}

std::string LatticeDirections::name() const {
  if (is_rectilinear()) return "rectilinear";
  if (is_octilinear()) return "octilinear";
  std::string s = "c:";
  for (const int d : degrees()) s += (s.size() > 2 ? "," : "") + std::to_string(d);
  return s;
}

std::vector<int> LatticeDirections::degrees() const {
  std::vector<int> out;
  for (int k = 0; k < 4; ++k)
    if (mask_ & (1u << k)) out.push_back(45 * k);
  return out;
}

bool LatticeDirections::along(i64 dx, i64 dy) const {
  for (const Point s : steps_)
    if (cross(s, dx, dy) == 0 && i128{s.x} * dx + i128{s.y} * dy > 0) return true;
  return false;
}

bool LatticeDirections::runs_along(std::span<const Point> line) const {
  for (std::size_t j = 0; j + 1 < line.size(); ++j) {
    const i64 dx = i64{line[j + 1].x} - line[j].x, dy = i64{line[j + 1].y} - line[j].y;
    if ((dx != 0 || dy != 0) && !along(dx, dy)) return false;
  }
  return true;
}

bool LatticeDirections::cones_leave_box() const {
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    const Point a = steps_[i], b = steps_[(i + 1) % steps_.size()];
    if (std::int64_t{a.x} * b.x < 0 || std::int64_t{a.y} * b.y < 0) return true;
  }
  return false;
}

int LatticeDirections::cone(i64 dx, i64 dy) const {
  const std::size_t n = steps_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = steps_[i], b = steps_[(i + 1) % n];
    // strictly counter-clockwise of a and clockwise of b (every cone is below 180 degrees)
    if (cross(a, dx, dy) > 0 && cross(b, dx, dy) < 0) return static_cast<int>(i);
  }
  return -1;
}

Root2 LatticeDirections::length2(i64 dx, i64 dy) const {
  if (dx == 0 && dy == 0) return {0, 0};
  const i64 ax = dx < 0 ? -dx : dx, ay = dy < 0 ? -dy : dy;
  const i64 t = ax > ay ? ax : ay;
  if (along(dx, dy)) return (dx == 0 || dy == 0) ? Root2{2 * t, 0} : Root2{0, 2 * t};
  const auto [d1, d2] = cone_steps(cone(dx, dy));
  const i64 det = i64{d1.x} * d2.y - i64{d1.y} * d2.x;  // 1 or 2
  // v = a d1 + b d2: a = cross(v, d2) / det, b = cross(d1, v) / det; twice them are integers
  const i64 a2 = static_cast<i64>(-cross(d2, dx, dy) * 2 / det), b2 = static_cast<i64>(cross(d1, dx, dy) * 2 / det);
  Root2 r{0, 0};
  const bool diag1 = d1.x != 0 && d1.y != 0, diag2 = d2.x != 0 && d2.y != 0;
  (diag1 ? r.b : r.a) += a2;
  (diag2 ? r.b : r.a) += b2;
  return r;
}

Root2 LatticeDirections::length2(std::span<const Point> path) const {
  Root2 r{0, 0};
  for (std::size_t i = 1; i < path.size(); ++i) r += length2(i64{path[i].x} - path[i - 1].x, i64{path[i].y} - path[i - 1].y);
  return r;
}

}  // namespace taut::geom
