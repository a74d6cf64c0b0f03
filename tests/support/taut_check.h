// Is a path locally taut among polygonal obstacles? For tests of tightening (issue #5),
// independent of the triangulation and the funnel: it reads only the obstacle rings.
//
// At every interior vertex v of the path (prev u, next w) the path must turn strictly (no
// straight-through or reversing vertex), and the open sector on the inner side of the turn
// (between the two segments, less than 180 degrees) must meet the material of an obstacle at v:
// otherwise the corner could be cut inside free space and the path shortened. The material at v
// is, for every ring through v (outer rings counter-clockwise, holes clockwise, so the material
// lies left of each directed edge), the open counter-clockwise arc from the direction of the
// ring's next vertex to that of its previous one; the domain's outside counts as material at a
// domain corner (the domain boundary as a clockwise ring). For polygonal obstacles a path that
// stays in free space and is locally taut at every vertex is the shortest in its homotopy class.
// Exact: directions are compared by int64 cross and dot products.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "geom/types.h"

namespace taut::test {

namespace taut_detail {
using i64 = std::int64_t;
struct Dir {
  i64 x, y;
};
inline Dir dir(geom::Point a, geom::Point b) { return {i64{b.x} - a.x, i64{b.y} - a.y}; }
inline i64 cross(Dir a, Dir b) { return a.x * b.y - a.y * b.x; }
inline i64 dotp(Dir a, Dir b) { return a.x * b.x + a.y * b.y; }
inline bool same(Dir a, Dir b) { return cross(a, b) == 0 && dotp(a, b) > 0; }
// 0 when the counter-clockwise angle from a to u is in [0, pi), else 1.
inline int half(Dir a, Dir u) { return (cross(a, u) < 0 || (cross(a, u) == 0 && dotp(a, u) < 0)) ? 1 : 0; }
// The counter-clockwise angle from a to u is smaller than that from a to v.
inline bool less_from(Dir a, Dir u, Dir v) {
  const int hu = half(a, u), hv = half(a, v);
  if (hu != hv) return hu < hv;
  if (same(u, v)) return false;
  if (hu == 0 && same(a, u)) return !same(a, v);
  return cross(u, v) > 0;
}
// x strictly inside the open counter-clockwise arc from a to b (the whole circle but a when b
// has a's direction).
inline bool in_open(Dir x, Dir a, Dir b) {
  if (same(x, a)) return false;
  if (same(a, b)) return true;
  return less_from(a, x, b);
}
inline bool arcs_meet(Dir s1, Dir s2, Dir m1, Dir m2) {
  return in_open(m1, s1, s2) || in_open(s1, m1, m2) || same(s1, m1);
}
}  // namespace taut_detail

// Exact lengths of a polyline: L1 as an integer; octilinear as (a, b) meaning a + b*sqrt2.
inline std::int64_t l1_length(const std::vector<geom::Point>& p) {
  std::int64_t s = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const std::int64_t dx = std::int64_t{p[i].x} - p[i - 1].x, dy = std::int64_t{p[i].y} - p[i - 1].y;
    s += (dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy);
  }
  return s;
}
inline std::pair<std::int64_t, std::int64_t> oct_length(const std::vector<geom::Point>& p) {
  std::int64_t a = 0, b = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    std::int64_t dx = std::int64_t{p[i].x} - p[i - 1].x, dy = std::int64_t{p[i].y} - p[i - 1].y;
    dx = dx < 0 ? -dx : dx;
    dy = dy < 0 ? -dy : dy;
    a += (dx > dy ? dx - dy : dy - dx);
    b += dx < dy ? dx : dy;
  }
  return {a, b};
}

// The cyclically reduced word of a loop, and equality up to rotation: two loops are freely
// homotopic iff these agree (conjugate elements of a free group).
inline std::vector<int> cyclic_word(std::vector<int> w) {
  std::size_t lo = 0, hi = w.size();
  while (hi - lo >= 2 && w[lo] == -w[hi - 1]) {
    ++lo;
    --hi;
  }
  return std::vector<int>(w.begin() + static_cast<std::ptrdiff_t>(lo), w.begin() + static_cast<std::ptrdiff_t>(hi));
}
inline bool same_up_to_rotation(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t r = 0; r <= b.size(); ++r) {
    bool eq = true;
    for (std::size_t i = 0; i < a.size() && eq; ++i) eq = a[i] == b[(r + i) % b.size()];
    if (eq) return true;
  }
  return a.empty();
}
// A closed loop as a path whose every vertex, the base included, is interior.
inline std::vector<geom::Point> wrapped(const std::vector<geom::Point>& loop) {
  std::vector<geom::Point> p = loop;
  if (loop.size() >= 2) p.push_back(loop[1]);
  return p;
}
// Empty when `path` is locally taut, else what is wrong and where.
inline std::string taut_problem(const std::vector<geom::Point>& path, const geom::Box& domain,
                                const std::vector<geom::Polygon>& obstacles) {
  using namespace taut_detail;
  using geom::Point;
  std::vector<geom::Ring> rings;
  for (const geom::Polygon& p : obstacles) {
    rings.push_back(p.outer);
    for (const geom::Ring& h : p.holes) rings.push_back(h);
  }
  rings.push_back({domain.lo, {domain.lo.x, domain.hi.y}, domain.hi, {domain.hi.x, domain.lo.y}});
  auto at = [](Point p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; };
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const Point u = path[i - 1], v = path[i], w = path[i + 1];
    const Dir in = dir(u, v), out = dir(v, w), back = dir(v, u);
    const i64 turn = cross(in, out);
    if (turn == 0) return "vertex " + std::to_string(i) + " " + at(v) + " does not turn";
    const Dir s1 = turn > 0 ? out : back, s2 = turn > 0 ? back : out;  // the inner sector
    bool wrapped = false;
    for (const geom::Ring& r : rings)
      for (std::size_t k = 0; k < r.size() && !wrapped; ++k)
        if (r[k] == v) {
          const Point prev = r[(k + r.size() - 1) % r.size()], next = r[(k + 1) % r.size()];
          wrapped = arcs_meet(s1, s2, dir(v, next), dir(v, prev));
        }
    if (!wrapped)
      return "vertex " + std::to_string(i) + " " + at(v) + " bends without an obstacle on its inner side";
  }
  return {};
}

}  // namespace taut::test
