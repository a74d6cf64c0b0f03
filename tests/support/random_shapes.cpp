#include "support/random_shapes.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "geom/normalize.h"
#include "geom/predicates.h"

namespace taut::test {

std::vector<geom::Polygon> random_triangles(std::mt19937& rng, const geom::Box& domain, int max_count) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<geom::Polygon> out;
  const int n = uni(1, max_count);
  for (int i = 0; i < n; ++i) {
    geom::Ring r;
    for (int k = 0; k < 3; ++k) r.push_back({uni(domain.lo.x, domain.hi.x), uni(domain.lo.y, domain.hi.y)});
    const auto a = geom::twice_area(r);
    if (a == 0) continue;
    if (a < 0) std::reverse(r.begin(), r.end());
    out.push_back({r, {}});
  }
  return out;
}

namespace {

// Occupancy of a side x side grid padded by one empty cell on every side: cell (c, r) at
// (c + 1) * (side + 2) + r + 1.
struct CellGrid {
  int side;
  std::vector<char> on;
  explicit CellGrid(int s) : side(s), on(static_cast<std::size_t>((s + 2) * (s + 2)), 0) {}
  char& at(int c, int r) { return on[static_cast<std::size_t>((c + 1) * (side + 2) + r + 1)]; }  // -1 <= c, r <= side
};

// No hole (every empty cell reaches the padding through 4-neighbours) and no pinch (no 2 x 2
// block with exactly its two diagonal cells occupied).
bool simple_polyomino(CellGrid& g) {
  const int s = g.side;
  for (int c = -1; c < s; ++c)
    for (int r = -1; r < s; ++r) {
      const char a = g.at(c, r), b = g.at(c + 1, r), d = g.at(c, r + 1), e = g.at(c + 1, r + 1);
      if (a == e && b == d && a != b) return false;
    }
  std::vector<char> seen(g.on.size(), 0);
  std::vector<std::pair<int, int>> stack{{-1, -1}};
  seen[0] = 1;
  while (!stack.empty()) {
    const auto [c, r] = stack.back();
    stack.pop_back();
    const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int c2 = c + dc[k], r2 = r + dr[k];
      if (c2 < -1 || r2 < -1 || c2 > s || r2 > s || g.at(c2, r2)) continue;
      char& v = seen[static_cast<std::size_t>((c2 + 1) * (s + 2) + r2 + 1)];
      if (v) continue;
      v = 1;
      stack.push_back({c2, r2});
    }
  }
  for (std::size_t k = 0; k < g.on.size(); ++k)
    if (!g.on[k] && !seen[k]) return false;
  return true;
}

}  // namespace

geom::Ring union_ring(std::span<const geom::Box> boxes) {
  std::vector<geom::Polygon> inputs;
  for (const geom::Box& b : boxes)
    inputs.push_back({{b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}, {}});
  const geom::NormalizedObstacles n = geom::normalize_obstacles(inputs, std::nullopt);
  if (n.obstacles.size() != 1 || !n.obstacles[0].holes.empty())
    throw std::invalid_argument("union_ring: not one polygon without holes");
  const geom::Ring& ring = n.obstacles[0].outer;
  if (std::set<geom::Point>(ring.begin(), ring.end()).size() != ring.size())
    throw std::invalid_argument("union_ring: the ring repeats a vertex (a pinch)");
  if (geom::twice_area(ring) <= 0) throw std::invalid_argument("union_ring: not counter-clockwise");
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const std::size_t m = ring.size();
    const geom::Point p = ring[(i + m - 1) % m], v = ring[i], q = ring[(i + 1) % m];
    if ((p.x != v.x && p.y != v.y) || geom::orient(p, v, q) == 0)
      throw std::invalid_argument("union_ring: a sloped edge or a collinear vertex");
  }
  return ring;
}

RectilinearPolygonSample random_rectilinear_sample(std::mt19937& rng, int side, int cells, int max_stretch,
                                                   geom::Point origin) {
  if (side < 1 || cells < 1 || max_stretch < 1)
    throw std::invalid_argument("random_rectilinear_polygon: side, cells and max_stretch must be >= 1");
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<std::pair<int, int>> chosen;
  for (int attempt = 0;; ++attempt) {
    if (attempt == 100000)
      throw std::runtime_error("random_rectilinear_polygon: no simple polyomino in 100000 attempts (side " +
                               std::to_string(side) + ", cells " + std::to_string(cells) + ")");
    CellGrid g(side);
    chosen.assign(1, {uni(0, side - 1), uni(0, side - 1)});
    g.at(chosen[0].first, chosen[0].second) = 1;
    while (static_cast<int>(chosen.size()) < cells) {
      std::vector<std::pair<int, int>> candidates;  // in (c, r) order: deterministic
      for (int c = 0; c < side; ++c)
        for (int r = 0; r < side; ++r) {
          if (g.at(c, r)) continue;
          if (g.at(c - 1, r) || g.at(c + 1, r) || g.at(c, r - 1) || g.at(c, r + 1)) candidates.push_back({c, r});
        }
      if (candidates.empty()) break;
      const auto pick = candidates[static_cast<std::size_t>(uni(0, static_cast<int>(candidates.size()) - 1))];
      g.at(pick.first, pick.second) = 1;
      chosen.push_back(pick);
    }
    if (simple_polyomino(g)) break;
  }
  std::vector<geom::Coord> x(static_cast<std::size_t>(side) + 1, origin.x), y(static_cast<std::size_t>(side) + 1, origin.y);
  for (int c = 0; c < side; ++c) x[c + 1] = x[c] + uni(1, max_stretch);
  for (int r = 0; r < side; ++r) y[r + 1] = y[r] + uni(1, max_stretch);
  RectilinearPolygonSample out;
  std::sort(chosen.begin(), chosen.end());
  for (const auto& [c, r] : chosen) out.cells.push_back({{x[c], y[r]}, {x[c + 1], y[r + 1]}});
  out.ring = union_ring(out.cells);
  return out;
}

geom::Ring random_rectilinear_polygon(std::mt19937& rng, int side, int cells, int max_stretch, geom::Point origin) {
  return random_rectilinear_sample(rng, side, cells, max_stretch, origin).ring;
}

RectilinearPolygonSample random_thin_polygon(std::mt19937& rng, int max_stretch) {
  using geom::Coord;
  using geom::Point;
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  while (true) {
    std::vector<Point> cells{{0, 0}};
    const int walks = uni(1, 3);
    for (int w = 0; w < walks; ++w) {
      Point c = cells[static_cast<std::size_t>(uni(0, static_cast<int>(cells.size()) - 1))];
      int dir = uni(0, 3);
      for (int run = uni(2, 12); run > 0; --run) {
        for (int len = uni(1, 5); len > 0; --len) {
          c.x += dir == 0 ? 1 : dir == 2 ? -1 : 0;
          c.y += dir == 1 ? 1 : dir == 3 ? -1 : 0;
          cells.push_back(c);
        }
        dir = (dir + (uni(0, 1) ? 1 : 3)) % 4;
      }
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    Coord x0 = cells[0].x, y0 = cells[0].y, x1 = x0, y1 = y0;
    for (const Point& c : cells) {
      x0 = std::min(x0, c.x), y0 = std::min(y0, c.y), x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
    }
    std::vector<Coord> xs{0}, ys{0};  // stretched coordinate of column / row line x0 + i, y0 + j
    for (Coord x = x0; x <= x1; ++x) xs.push_back(xs.back() + uni(1, max_stretch));
    for (Coord y = y0; y <= y1; ++y) ys.push_back(ys.back() + uni(1, max_stretch));
    RectilinearPolygonSample out;
    for (const Point& c : cells)
      out.cells.push_back({{xs[static_cast<std::size_t>(c.x - x0)], ys[static_cast<std::size_t>(c.y - y0)]},
                           {xs[static_cast<std::size_t>(c.x - x0 + 1)], ys[static_cast<std::size_t>(c.y - y0 + 1)]}});
    try {
      out.ring = union_ring(out.cells);
      return out;
    } catch (const std::invalid_argument&) {
      // a hole or a pinch: another walk
    }
  }
}

std::vector<geom::Box> random_boxes_apart(std::mt19937& rng, int count, int lo, int span, int max_side) {
  std::vector<geom::Box> boxes;
  for (int k = 0; k < count; ++k) {
    const geom::Coord x = static_cast<geom::Coord>(lo + static_cast<int>(rng() % static_cast<unsigned>(span)));
    const geom::Coord y = static_cast<geom::Coord>(lo + static_cast<int>(rng() % static_cast<unsigned>(span)));
    const geom::Coord w = static_cast<geom::Coord>(1 + rng() % static_cast<unsigned>(max_side));
    const geom::Coord h = static_cast<geom::Coord>(1 + rng() % static_cast<unsigned>(max_side));
    const geom::Box b{{x, y}, {static_cast<geom::Coord>(x + w), static_cast<geom::Coord>(y + h)}};
    bool apart = true;
    for (const auto& o : boxes) apart = apart && (b.lo.x > o.hi.x || o.lo.x > b.hi.x || b.lo.y > o.hi.y || o.lo.y > b.hi.y);
    if (apart) boxes.push_back(b);
  }
  return boxes;
}

std::vector<geom::Polygon> box_polygons(std::span<const geom::Box> boxes) {
  std::vector<geom::Polygon> polys;
  for (const auto& b : boxes) polys.push_back({{b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}, {}});
  return polys;
}

}  // namespace taut::test
