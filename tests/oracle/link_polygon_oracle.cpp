#include "oracle/link_polygon_oracle.h"

#include <algorithm>
#include <utility>
#include <cstddef>
#include <deque>
#include <stdexcept>
#include <string>

#include "geom/predicates.h"

namespace taut::oracle {

namespace {

using geom::Coord;
using geom::Point;
using i64 = std::int64_t;

std::string str(Point p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

void sort_unique(std::vector<Coord>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

LinkPolygonReference::LinkPolygonReference(const geom::Ring& polygon) {
  // consecutive repeats (including a repeated closing vertex) are dropped; every edge must be
  // horizontal or vertical
  geom::Ring r;
  for (const Point& p : polygon)
    if (r.empty() || r.back() != p) r.push_back(p);
  while (r.size() > 1 && r.front() == r.back()) r.pop_back();
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[i], b = r[(i + 1) % r.size()];
    if (a.x != b.x && a.y != b.y)
      throw std::invalid_argument("LinkPolygonReference: sloped edge " + str(a) + " - " + str(b));
  }
  // collinear vertices dropped (a continuation); a reversal is not simple
  bool changed = true;
  while (changed && r.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < r.size() && r.size() >= 3; ++i) {
      const std::size_t n = r.size();
      const Point p = r[(i + n - 1) % n], v = r[i], q = r[(i + 1) % n];
      if (geom::orient(p, v, q) != 0) continue;
      if (geom::dot(p, v, v, q) < 0)
        throw std::invalid_argument("LinkPolygonReference: the ring turns back at " + str(v));
      r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
      changed = true;
      break;
    }
  }
  if (r.size() < 4) throw std::invalid_argument("LinkPolygonReference: fewer than 4 corners");
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share one corner only
      const geom::Segment s{r[i], r[(i + 1) % n]}, t{r[j], r[(j + 1) % n]};
      if (geom::intersect(s, t) != geom::SegmentIntersection::None)
        throw std::invalid_argument("LinkPolygonReference: not simple, edges at " + str(r[i]) + " and " +
                                    str(r[j]) + " meet");
    }
  ring_ = std::move(r);
  const int orientation = geom::sign(geom::twice_area(ring_));
  convex_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    convex_[i] = geom::orientation(ring_[(i + n - 1) % n], ring_[i], ring_[(i + 1) % n]) == orientation;
  std::vector<Coord> xs, ys;
  for (const Point& p : ring_) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  grid_ = make_grid(std::move(xs), std::move(ys));
}

bool LinkPolygonReference::contains2(i64 x2, i64 y2) const {
  // on an edge: closed; otherwise the crossings of the ray to +x with vertical edges, each edge
  // taken over the half-open y range [lo, hi) so that a ray through a corner counts once
  const std::size_t n = ring_.size();
  bool inside = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring_[i], b = ring_[(i + 1) % n];
    const i64 ax = 2 * i64{a.x}, ay = 2 * i64{a.y}, bx = 2 * i64{b.x}, by = 2 * i64{b.y};
    if (ay == by) {
      if (y2 == ay && std::min(ax, bx) <= x2 && x2 <= std::max(ax, bx)) return true;
    } else {
      const i64 lo = std::min(ay, by), hi = std::max(ay, by);
      if (x2 == ax && lo <= y2 && y2 <= hi) return true;
      if (ax > x2 && lo <= y2 && y2 < hi) inside = !inside;
    }
  }
  return inside;
}

bool LinkPolygonReference::contains(Point p) const { return contains2(2 * i64{p.x}, 2 * i64{p.y}); }

LinkPolygonReference::Grid LinkPolygonReference::make_grid(std::vector<Coord> xs, std::vector<Coord> ys) const {
  sort_unique(xs);
  sort_unique(ys);
  Grid g;
  g.xs = std::move(xs);
  g.ys = std::move(ys);
  const int nx = g.nx(), ny = g.ny();
  const std::size_t size = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  g.point.assign(size, 0);
  g.hstep.assign(size, 0);
  g.vstep.assign(size, 0);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const std::size_t k = static_cast<std::size_t>(i) * ny + j;
      const i64 x2 = 2 * i64{g.xs[i]}, y2 = 2 * i64{g.ys[j]};
      g.point[k] = contains2(x2, y2);
      if (i + 1 < nx) g.hstep[k] = contains2(i64{g.xs[i]} + g.xs[i + 1], y2);
      if (j + 1 < ny) g.vstep[k] = contains2(x2, i64{g.ys[j]} + g.ys[j + 1]);
    }
  return g;
}

std::vector<int> LinkPolygonReference::bfs(const Grid& g, int source) const {
  const std::vector<int> cost = bfs_states(g, source);
  std::vector<int> links(g.point.size(), -1);
  for (std::size_t k = 0; k < links.size(); ++k) {
    if (!g.point[k]) continue;
    const int best = std::min(cost[2 * k], cost[2 * k + 1]);
    if (best >= kUnreached) throw std::logic_error("LinkPolygonReference: a point of P is unreachable");
    links[k] = best;
  }
  links[static_cast<std::size_t>(source)] = 0;
  return links;
}

std::vector<LinkPolygonReference::Arrival> LinkPolygonReference::arrival_links(Point a, Point e0, Point e1) const {
  if (e0.x != e1.x && e0.y != e1.y) throw std::invalid_argument("arrival_links: the segment is not axis-parallel");
  if (!contains(a) || !contains(e0) || !contains(e1)) throw std::invalid_argument("arrival_links: outside P");
  std::vector<Coord> xs = grid_.xs, ys = grid_.ys;
  xs.insert(xs.end(), {a.x, e0.x, e1.x});
  ys.insert(ys.end(), {a.y, e0.y, e1.y});
  const Grid g = make_grid(std::move(xs), std::move(ys));
  auto index = [&](Point p) {
    const auto i = std::lower_bound(g.xs.begin(), g.xs.end(), p.x) - g.xs.begin();
    const auto j = std::lower_bound(g.ys.begin(), g.ys.end(), p.y) - g.ys.begin();
    return static_cast<int>(i * g.ny() + j);
  };
  const std::vector<int> cost = bfs_states(g, index(a));
  const bool vertical = e0.x == e1.x;  // then the last link is horizontal (o = 0)
  std::vector<Arrival> out;
  auto visit = [&](Point x) {
    const auto k = static_cast<std::size_t>(2 * index(x));
    const int perp = x == a ? 0 : cost[k + (vertical ? 0 : 1)], along = x == a ? 0 : cost[k + (vertical ? 1 : 0)];
    out.push_back({x, perp >= kUnreached ? -1 : perp, along >= kUnreached ? -1 : along});
  };
  if (vertical) {
    const int step = e1.y >= e0.y ? 1 : -1;
    auto j = std::lower_bound(g.ys.begin(), g.ys.end(), std::min(e0.y, e1.y));
    std::vector<Coord> along;
    for (; j != g.ys.end() && *j <= std::max(e0.y, e1.y); ++j) along.push_back(*j);
    if (step < 0) std::reverse(along.begin(), along.end());
    for (const Coord y : along) visit({e0.x, y});
  } else {
    const int step = e1.x >= e0.x ? 1 : -1;
    auto i = std::lower_bound(g.xs.begin(), g.xs.end(), std::min(e0.x, e1.x));
    std::vector<Coord> along;
    for (; i != g.xs.end() && *i <= std::max(e0.x, e1.x); ++i) along.push_back(*i);
    if (step < 0) std::reverse(along.begin(), along.end());
    for (const Coord x : along) visit({x, e0.y});
  }
  return out;
}

std::vector<int> LinkPolygonReference::bfs_states(const Grid& g, int source) const {
  // states 2 * point + o, o = 0 horizontal, 1 vertical; cost = links so far
  const int ny = g.ny();
  const int states = 2 * g.nx() * ny;
  constexpr int kInf = kUnreached;
  std::vector<int> cost(static_cast<std::size_t>(states), kInf);
  std::deque<int> queue;
  cost[2 * source] = cost[2 * source + 1] = 1;
  queue.push_back(2 * source);
  queue.push_back(2 * source + 1);
  while (!queue.empty()) {
    const int s = queue.front();
    queue.pop_front();
    const int c = cost[s];
    const int k = s / 2, o = s % 2;
    auto relax = [&](int t, int w) {
      if (c + w < cost[t]) {
        cost[t] = c + w;
        if (w == 0) queue.push_front(t);
        else queue.push_back(t);
      }
    };
    relax(2 * k + (1 - o), 1);
    const int i = k / ny, j = k % ny;
    if (o == 0) {
      if (i > 0 && g.hstep[k - ny]) relax(2 * (k - ny), 0);
      if (i + 1 < g.nx() && g.hstep[k]) relax(2 * (k + ny), 0);
    } else {
      if (j > 0 && g.vstep[k - 1]) relax(2 * (k - 1) + 1, 0);
      if (j + 1 < ny && g.vstep[k]) relax(2 * (k + 1) + 1, 0);
    }
  }
  return cost;
}

std::optional<int> LinkPolygonReference::distance(Point a, Point b) const {
  if (!contains(a) || !contains(b)) return std::nullopt;
  if (a == b) return 0;
  std::vector<Coord> xs = grid_.xs, ys = grid_.ys;
  xs.insert(xs.end(), {a.x, b.x});
  ys.insert(ys.end(), {a.y, b.y});
  const Grid g = make_grid(std::move(xs), std::move(ys));
  auto index = [&](Point p) {
    const auto i = std::lower_bound(g.xs.begin(), g.xs.end(), p.x) - g.xs.begin();
    const auto j = std::lower_bound(g.ys.begin(), g.ys.end(), p.y) - g.ys.begin();
    return static_cast<int>(i * g.ny() + j);
  };
  return bfs(g, index(a))[static_cast<std::size_t>(index(b))];
}

LinkPolygonReference::Diameter LinkPolygonReference::diameter() const {
  Diameter best;
  bool found = false;
  const int ny = grid_.ny();
  for (std::size_t s = 0; s < grid_.point.size(); ++s) {
    if (!grid_.point[s]) continue;
    const std::vector<int> links = bfs(grid_, static_cast<int>(s));
    for (std::size_t t = 0; t < links.size(); ++t) {
      if (links[t] < 0 || (found && links[t] <= best.links)) continue;
      found = true;
      best.links = links[t];
      best.a = {grid_.xs[s / ny], grid_.ys[s % ny]};
      best.b = {grid_.xs[t / ny], grid_.ys[t % ny]};
    }
  }
  return best;
}

int LinkPolygonReference::index_of(Point p) const {
  const auto i = std::lower_bound(grid_.xs.begin(), grid_.xs.end(), p.x) - grid_.xs.begin();
  const auto j = std::lower_bound(grid_.ys.begin(), grid_.ys.end(), p.y) - grid_.ys.begin();
  return static_cast<int>(i * grid_.ny() + j);
}

int LinkPolygonReference::max_over(const std::vector<Point>& sources) const {
  int best = 0;
  for (const Point& s : sources) {
    const std::vector<int> links = bfs(grid_, index_of(s));
    for (const Point& t : sources) best = std::max(best, links[static_cast<std::size_t>(index_of(t))]);
  }
  return best;
}

int LinkPolygonReference::vertex_diameter() const { return max_over(ring_); }

int LinkPolygonReference::convex_vertex_diameter() const {
  std::vector<Point> convex;
  for (std::size_t i = 0; i < ring_.size(); ++i)
    if (convex_[i]) convex.push_back(ring_[i]);
  return max_over(convex);
}

}  // namespace taut::oracle
