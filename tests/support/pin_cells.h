// Brute force for the staircase of a shape pin (router::pad_staircase: how the routers reach a pin
// with an edge at another angle than 0, 45 or 90 degrees, and under the bend-aware metrics a pad
// with a 45-degree edge in a blockage's clearance), sharing only geom with the router.
//
//   std::set<Cell> all = cells_in_pin(pin, 1, box);          // every lattice cell in the pin
//   auto [cells, whole] = expected_staircase_cells(all, 1);  // the staircase's cells
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "geom/types.h"
#include "geom/validate.h"

namespace taut::test {

// A cell of the lattice of `step`: its lower-left corner in steps.
using Cell = std::pair<int, int>;

// Calls f(a, b) for every edge of the polygon's rings (closing edges included).
template <class F>
void for_each_ring_edge(const geom::Polygon& p, F f) {
  auto ring = [&](const geom::Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i) f(r[i], r[(i + 1) % r.size()]);
  };
  ring(p.outer);
  for (const geom::Ring& h : p.holes) ring(h);
}

// Does the closed segment ab meet the open cell [lo, hi]? Separating axes, exact: the cell's two
// axes and the segment's normal (all four corners on one closed side of its line).
inline bool segment_meets_open_cell(geom::Point a, geom::Point b, geom::Point lo, geom::Point hi) {
  if (std::max(a.x, b.x) <= lo.x || std::min(a.x, b.x) >= hi.x) return false;
  if (std::max(a.y, b.y) <= lo.y || std::min(a.y, b.y) >= hi.y) return false;
  bool left = false, right = false;
  for (const geom::Point c : {lo, geom::Point{hi.x, lo.y}, hi, geom::Point{lo.x, hi.y}}) {
    const int o = geom::orientation(a, b, c);
    left = left || o > 0;
    right = right || o < 0;
  }
  return left && right;
}

// Does the cell (x, y) of the lattice of `step` lie in the closed polygon? When no edge meets the
// open cell and its centre lies inside (tested on the polygon doubled, `twice`, where the centre
// is an integer point). The corners alone do not tell: a sliver of outside between two edges at
// another angle than 0, 45 or 90 degrees can cross a cell whose four corners lie in the polygon.
inline bool cell_in(const geom::Polygon& p, const geom::Polygon& twice, int x, int y, std::int64_t step) {
  const auto c = [](std::int64_t v) { return static_cast<geom::Coord>(v); };
  const geom::Point lo{c(x * step), c(y * step)}, hi{c((x + 1) * step), c((y + 1) * step)};
  bool cut = false;
  for_each_ring_edge(p, [&](geom::Point a, geom::Point b) { cut = cut || segment_meets_open_cell(a, b, lo, hi); });
  return !cut && geom::locate(geom::Point{c((2 * x + 1) * step), c((2 * y + 1) * step)}, twice) == geom::Location::Inside;
}

// The polygon with every coordinate doubled.
inline geom::Polygon doubled(geom::Polygon p) {
  auto ring = [](geom::Ring& r) {
    for (geom::Point& v : r) v = {static_cast<geom::Coord>(2 * v.x), static_cast<geom::Coord>(2 * v.y)};
  };
  ring(p.outer);
  for (geom::Ring& h : p.holes) ring(h);
  return p;
}

// Does the open cell (x, y) of the lattice of `step` meet the interior of polygon o (`twice`: o
// doubled)? When an edge of o meets it, else when its centre lies inside o (the open cell then
// lies wholly inside or wholly outside).
inline bool cell_meets_interior(const geom::Polygon& o, const geom::Polygon& twice, int x, int y, std::int64_t step) {
  const auto c = [](std::int64_t v) { return static_cast<geom::Coord>(v); };
  const geom::Point lo{c(x * step), c(y * step)}, hi{c((x + 1) * step), c((y + 1) * step)};
  bool cut = false;
  for_each_ring_edge(o, [&](geom::Point a, geom::Point b) { cut = cut || segment_meets_open_cell(a, b, lo, hi); });
  return cut || geom::locate(geom::Point{c((2 * x + 1) * step), c((2 * y + 1) * step)}, twice) == geom::Location::Inside;
}

// Every cell of the lattice of `step` in the closed polygon whose lower-left corner (in steps)
// lies in [x0, x1) x [y0, y1), and that meets the interior of none of `cuts` (the blockages a
// pin lies partly under).
inline std::set<Cell> cells_in_pin(const geom::Polygon& p, std::int64_t step, int x0, int y0, int x1, int y1,
                                   const std::vector<geom::Polygon>& cuts = {}) {
  const geom::Polygon twice = doubled(p);
  std::vector<geom::Polygon> cuts_twice;
  for (const geom::Polygon& c : cuts) cuts_twice.push_back(doubled(c));
  std::set<Cell> out;
  for (int x = x0; x < x1; ++x)
    for (int y = y0; y < y1; ++y) {
      if (!cell_in(p, twice, x, y, step)) continue;
      bool free = true;
      for (std::size_t k = 0; k < cuts.size() && free; ++k) free = !cell_meets_interior(cuts[k], cuts_twice[k], x, y, step);
      if (free) out.insert({x, y});
    }
  return out;
}

// The cells pad_staircase must give, from the cells of the lattice that lie in the pin (`all`):
// all of them when their union is one valid polygon (then `whole`); else (a part too thin for a
// cell: a diagonal bar, a neck) the largest part joined along cell edges whose union is (ties:
// the part with the lowest (x, y) cell), found by a flood fill; empty when there is none.
inline std::pair<std::set<Cell>, bool> expected_staircase_cells(const std::set<Cell>& all, std::int64_t step) {
  auto union_of = [&](const std::set<Cell>& cs) {
    const auto c = [&](int v) { return static_cast<geom::Coord>(v * step); };
    std::vector<geom::Polygon> ps;
    for (const auto& [x, y] : cs) ps.push_back(geom::Polygon{{{c(x), c(y)}, {c(x + 1), c(y)}, {c(x + 1), c(y + 1)}, {c(x), c(y + 1)}}, {}});
    const geom::NormalizedObstacles u = geom::normalize_obstacles(ps, std::nullopt);
    return u.obstacles.size() == 1 && geom::validate_polygon(u.obstacles[0]).empty();
  };
  if (!all.empty() && union_of(all)) return {all, true};
  std::vector<std::set<Cell>> comps;
  std::set<Cell> seen;
  for (const Cell& c0 : all) {
    if (seen.count(c0)) continue;
    std::set<Cell> comp;
    std::vector<Cell> todo{c0};
    seen.insert(c0);
    while (!todo.empty()) {
      const auto [x, y] = todo.back();
      todo.pop_back();
      comp.insert({x, y});
      for (const Cell& nb : {Cell{x + 1, y}, Cell{x - 1, y}, Cell{x, y + 1}, Cell{x, y - 1}})
        if (all.count(nb) && !seen.count(nb)) seen.insert(nb), todo.push_back(nb);
    }
    comps.push_back(std::move(comp));
  }
  std::stable_sort(comps.begin(), comps.end(), [](const auto& a, const auto& b) {
    return a.size() != b.size() ? a.size() > b.size() : *a.begin() < *b.begin();
  });
  for (const auto& comp : comps)
    if (union_of(comp)) return {comp, false};
  return {{}, false};
}

// A random pin in [0, 14] x [0, 14] with an edge at an angle other than 0, 45 or 90 degrees, valid
// (geom::validate_polygon; no vertex repeated): a triangle, a rectangle turned by (a, b) (sides
// (a, b) u and (-b, a) v), or a star-shaped polygon round (7, 7) (vertices at increasing angles,
// rounded); one in `hole_one_in` gets a triangular hole round (7, 7) when the pin stays valid
// with it.
inline geom::Polygon random_sloped_pin(std::mt19937& rng, int hole_one_in) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  for (;;) {
    geom::Ring r;
    switch (uni(0, 2)) {
      case 0:
        for (int k = 0; k < 3; ++k) r.push_back({uni(0, 14), uni(0, 14)});
        break;
      case 1: {
        const int a = uni(1, 5), b = uni(-4, 4), u = uni(1, 2), v = uni(1, 2), x = uni(4, 9), y = uni(0, 3);
        r = {{x, y}, {x + a * u, y + b * u}, {x + a * u - b * v, y + b * u + a * v}, {x - b * v, y + a * v}};
        break;
      }
      default: {
        const int k = uni(4, 8);
        std::vector<double> ang;
        for (int i = 0; i < k; ++i) ang.push_back(std::uniform_real_distribution<double>(0, 6.283185307179586)(rng));
        std::sort(ang.begin(), ang.end());
        for (const double t : ang) {
          const double rad = uni(2, 7);
          r.push_back({static_cast<geom::Coord>(std::lround(7 + rad * std::cos(t))), static_cast<geom::Coord>(std::lround(7 + rad * std::sin(t)))});
        }
      }
    }
    r.erase(std::unique(r.begin(), r.end()), r.end());
    while (r.size() > 1 && r.front() == r.back()) r.pop_back();
    bool inside = true;
    for (const geom::Point p : r) inside = inside && p.x >= 0 && p.x <= 14 && p.y >= 0 && p.y <= 14;
    if (!inside) continue;
    geom::Polygon pin{r, {}};
    if (uni(1, hole_one_in) == 1) {
      pin.holes.push_back({{uni(4, 6), uni(4, 6)}, {uni(8, 10), uni(4, 6)}, {uni(6, 8), uni(8, 10)}});
      if (!geom::validate_polygon(pin).empty()) pin.holes.clear();
    }
    if (!geom::validate_polygon(pin).empty()) continue;
    bool other = false;
    for_each_ring_edge(pin, [&](geom::Point a, geom::Point b) {
      const int dx = std::abs(b.x - a.x), dy = std::abs(b.y - a.y);
      other = other || (dx != 0 && dy != 0 && dx != dy);
    });
    if (other) return pin;
  }
}

}  // namespace taut::test
