#include "oracle/bend_oracle.h"

#include <algorithm>
#include <array>
#include <functional>
#include <queue>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace taut::oracle {

using geom::Coord;
using geom::Point;
using geom::Polygon;
using geom::Ring;

namespace {

// Directions E, N, W, S (counter-clockwise); the reverse of d is (d + 2) % 4.
constexpr std::array<int, 4> kDx = {1, 0, -1, 0};
constexpr std::array<int, 4> kDy = {0, 1, 0, -1};
constexpr int kNone = 4;  // the start state: no direction yet

int sign(std::int64_t v) { return (v > 0) - (v < 0); }

// Some wedge of `ws` holds both directions (dx1, dy1) and (dx2, dy2).
bool one_wedge(const std::vector<Wedge>& ws, int dx1, int dy1, int dx2, int dy2) {
  return std::any_of(ws.begin(), ws.end(),
                     [&](const Wedge& w) { return w.contains(dx1, dy1) && w.contains(dx2, dy2); });
}

}  // namespace

BendReference::BendReference(const geom::Box& domain, std::span<const Polygon> obstacles)
    : domain_(domain), ref_(domain, obstacles) {
  xs_ = {domain.lo.x, domain.hi.x};
  ys_ = {domain.lo.y, domain.hi.y};
  auto add_ring = [&](const Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Point a = r[i], b = r[(i + 1) % r.size()];
      if (a.x != b.x && a.y != b.y)
        throw std::invalid_argument("BendReference: an obstacle edge is neither horizontal nor vertical");
      xs_.push_back(a.x);
      ys_.push_back(a.y);
    }
  };
  for (const Polygon& poly : obstacles) {
    add_ring(poly.outer);
    for (const Ring& h : poly.holes) add_ring(h);
  }
  std::sort(xs_.begin(), xs_.end());
  xs_.erase(std::unique(xs_.begin(), xs_.end()), xs_.end());
  std::sort(ys_.begin(), ys_.end());
  ys_.erase(std::unique(ys_.begin(), ys_.end()), ys_.end());
}

const std::vector<Wedge>& BendReference::wedges_at(Point p) const {
  auto it = wedges_.find(p);
  if (it == wedges_.end()) it = wedges_.emplace(p, ref_.wedges_at(p)).first;
  return it->second;
}

bool BendReference::step_free(Point a, Point b) const {
  const auto k = std::minmax(a, b);  // visible() is symmetric
  auto it = steps_.find(k);
  if (it == steps_.end()) it = steps_.emplace(k, ref_.visible(a, b)).first;
  return it->second;
}

std::optional<BendAnswer> BendReference::best(Point s, Point t, bool link, std::int64_t C) const {
  return search({&s, 1}, {&t, 1}, link, C, false);
}

std::optional<BendAnswer> BendReference::best_on_lattice(Point s, Point t, bool link,
                                                         std::int64_t C) const {
  return search({&s, 1}, {&t, 1}, link, C, true);
}

std::optional<BendAnswer> BendReference::best_between_on_lattice(std::span<const Point> S,
                                                                 std::span<const Point> T, bool link,
                                                                 std::int64_t C) const {
  return search(S, T, link, C, true);
}

std::optional<BendAnswer> BendReference::search(std::span<const Point> S_all, std::span<const Point> T_all,
                                                bool link, std::int64_t C, bool lattice) const {
  std::vector<Point> S, T;
  for (const Point p : S_all)
    if (ref_.is_free(p)) S.push_back(p);
  for (const Point p : T_all)
    if (ref_.is_free(p)) T.push_back(p);
  if (S.empty() || T.empty()) return std::nullopt;
  for (const Point p : S)
    if (std::find(T.begin(), T.end(), p) != T.end()) return BendAnswer{0, 0};

  std::vector<Coord> xs = xs_, ys = ys_;
  for (const Point p : S) xs.push_back(p.x), ys.push_back(p.y);
  for (const Point p : T) xs.push_back(p.x), ys.push_back(p.y);
  if (lattice) {
    for (Coord x = domain_.lo.x; x <= domain_.hi.x; ++x) xs.push_back(x);
    for (Coord y = domain_.lo.y; y <= domain_.hi.y; ++y) ys.push_back(y);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  const int nx = static_cast<int>(xs.size()), ny = static_cast<int>(ys.size());
  auto at = [&](const std::vector<Coord>& v, Coord c) {
    return static_cast<int>(std::lower_bound(v.begin(), v.end(), c) - v.begin());
  };
  const std::size_t points = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  auto point_index = [&](int ix, int iy) { return static_cast<std::size_t>(iy) * nx + ix; };

  auto wedges_of = [&](int ix, int iy) -> const std::vector<Wedge>& { return wedges_at({xs[ix], ys[iy]}); };
  auto step_ok = [&](int ix, int iy, int d) {
    const int jx = ix + kDx[d], jy = iy + kDy[d];
    return jx >= 0 && jx < nx && jy >= 0 && jy < ny && step_free({xs[ix], ys[iy]}, {xs[jx], ys[jy]});
  };

  // States: point_index * 5 + arriving direction (kNone only at s, the start).
  struct Cost {
    std::int64_t length = 0, bends = 0;
  };
  using Key = std::pair<__int128, __int128>;
  auto key = [&](const Cost& c) -> Key {
    if (link) return {c.bends, c.length};
    return {__int128{c.length} + __int128{C} * c.bends, c.bends};
  };
  const std::size_t states = points * 5;
  std::vector<std::optional<Cost>> dist(states);
  std::vector<bool> done(states, false);
  using Item = std::pair<Key, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  std::vector<char> target(points, 0);
  for (const Point p : T) target[point_index(at(xs, p.x), at(ys, p.y))] = 1;
  for (const Point p : S) {
    const std::size_t start = point_index(at(xs, p.x), at(ys, p.y)) * 5 + kNone;
    dist[start] = Cost{};
    queue.push({key(Cost{}), start});
  }
  while (!queue.empty()) {
    const std::size_t st = queue.top().second;
    queue.pop();
    if (done[st]) continue;
    done[st] = true;
    const Cost c = *dist[st];
    const int din = static_cast<int>(st % 5);
    const std::size_t pi = st / 5;
    const int ix = static_cast<int>(pi % nx), iy = static_cast<int>(pi / nx);
    if (target[pi]) return BendAnswer{c.length, c.bends};  // the first settled at a target
    for (int d = 0; d < 4; ++d) {
      if (din != kNone && d == (din + 2) % 4) continue;  // no reversal
      if (!step_ok(ix, iy, d)) continue;
      // Passing or turning at p: back along the path and on, in one wedge of p.
      if (din != kNone && !one_wedge(wedges_of(ix, iy), -kDx[din], -kDy[din], kDx[d], kDy[d]))
        continue;
      const int jx = ix + kDx[d], jy = iy + kDy[d];
      const Cost n{c.length + std::abs(std::int64_t{xs[jx]} - xs[ix]) + std::abs(std::int64_t{ys[jy]} - ys[iy]),
                   c.bends + (din != kNone && d != din ? 1 : 0)};
      const std::size_t ns = point_index(jx, jy) * 5 + static_cast<std::size_t>(d);
      if (!dist[ns] || key(n) < key(*dist[ns])) {
        dist[ns] = n;
        queue.push({key(n), ns});
      }
    }
  }
  return std::nullopt;
}

std::optional<BendAnswer> BendReference::check_path(std::span<const Point> path) const {
  std::vector<Point> p;
  for (const Point q : path)
    if (p.empty() || p.back() != q) p.push_back(q);
  if (p.empty() || !ref_.is_free(p.front())) return std::nullopt;
  std::int64_t bends = 0;
  int prev = kNone;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const std::int64_t dx = std::int64_t{p[i + 1].x} - p[i].x, dy = std::int64_t{p[i + 1].y} - p[i].y;
    if (dx != 0 && dy != 0) return std::nullopt;  // not axis-parallel
    int d = 0;
    while (kDx[d] != sign(dx) || kDy[d] != sign(dy)) ++d;
    if (prev != kNone && d == (prev + 2) % 4) return std::nullopt;  // reverses on itself
    if (prev != kNone && d != prev) ++bends;
    prev = d;
  }
  // Every segment free, and at every inner point the two directions in one wedge.
  const std::optional<std::int64_t> length = ref_.check_path(p);
  if (!length) return std::nullopt;
  return BendAnswer{*length, bends};
}

}  // namespace taut::oracle
