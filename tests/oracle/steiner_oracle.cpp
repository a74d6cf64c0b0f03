#include "oracle/steiner_oracle.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <vector>

#include "oracle/l1_oracle.h"

namespace taut::oracle {

std::optional<std::int64_t> steiner_minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                    std::span<const geom::Point> terminals) {
  std::vector<geom::Box> boxes;
  for (const geom::Point t : terminals) boxes.push_back({t, t});
  return steiner_minimal_length(domain, obstacles, std::span<const geom::Box>(boxes));
}

std::optional<std::int64_t> steiner_minimal_length(const geom::Box& domain, std::span<const geom::Polygon> obstacles,
                                                    std::span<const geom::Box> terminals) {
  const std::size_t k = terminals.size();
  if (k > 10) throw std::invalid_argument("steiner_minimal_length: at most 10 terminals");
  if (k <= 1) return 0;
  std::vector<geom::Coord> xs{domain.lo.x, domain.hi.x}, ys{domain.lo.y, domain.hi.y};
  auto add_ring = [&](const geom::Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      const geom::Point a = r[i], b = r[(i + 1) % r.size()];
      if (a.x != b.x && a.y != b.y) throw std::invalid_argument("steiner_minimal_length: a sloped obstacle edge");
      xs.push_back(a.x);
      ys.push_back(a.y);
    }
  };
  for (const geom::Polygon& p : obstacles) {
    add_ring(p.outer);
    for (const geom::Ring& h : p.holes) add_ring(h);
  }
  for (const geom::Box& t : terminals) {
    xs.insert(xs.end(), {t.lo.x, t.hi.x});
    ys.insert(ys.end(), {t.lo.y, t.hi.y});
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  const L1Reference ref(domain, obstacles);
  const std::size_t nx = xs.size(), ny = ys.size(), n = nx * ny;
  auto id = [&](std::size_t i, std::size_t j) { return i * ny + j; };
  auto at = [&](std::size_t v) { return geom::Point{xs[v / ny], ys[v % ny]}; };
  std::vector<char> free(n);
  for (std::size_t v = 0; v < n; ++v) free[v] = ref.is_free(at(v));
  struct Arc {
    std::size_t to;
    std::int64_t w;
  };
  std::vector<std::vector<Arc>> adj(n);
  auto join = [&](std::size_t u, std::size_t v) {
    if (!free[u] || !free[v] || !ref.visible(at(u), at(v))) return;
    const geom::Point a = at(u), b = at(v);
    const std::int64_t w = std::abs(std::int64_t{a.x} - b.x) + std::abs(std::int64_t{a.y} - b.y);
    adj[u].push_back({v, w});
    adj[v].push_back({u, w});
  };
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j) {
      if (i + 1 < nx) join(id(i, j), id(i + 1, j));
      if (j + 1 < ny) join(id(i, j), id(i, j + 1));
    }
  // Each terminal is one node: a point's grid node, or for a pad a node of its own joined at no
  // cost to every free grid node in its closed box (the pad's metal carries a connection across
  // it: a tree may reach a pad at one point and go on from another).
  std::vector<std::size_t> term(k);
  std::size_t total = n;
  for (std::size_t t = 0; t < k; ++t) {
    const auto x0 = std::lower_bound(xs.begin(), xs.end(), terminals[t].lo.x) - xs.begin();
    const auto x1 = std::upper_bound(xs.begin(), xs.end(), terminals[t].hi.x) - xs.begin();
    const auto y0 = std::lower_bound(ys.begin(), ys.end(), terminals[t].lo.y) - ys.begin();
    const auto y1 = std::upper_bound(ys.begin(), ys.end(), terminals[t].hi.y) - ys.begin();
    std::vector<std::size_t> in;
    for (auto i = x0; i < x1; ++i)
      for (auto j = y0; j < y1; ++j)
        if (free[id(static_cast<std::size_t>(i), static_cast<std::size_t>(j))])
          in.push_back(id(static_cast<std::size_t>(i), static_cast<std::size_t>(j)));
    if (in.empty()) return std::nullopt;
    if (terminals[t].lo == terminals[t].hi) {
      term[t] = in[0];
      continue;
    }
    term[t] = total++;
    adj.emplace_back();
    for (const std::size_t v : in) {
      adj[term[t]].push_back({v, 0});
      adj[v].push_back({term[t], 0});
    }
  }
  constexpr std::int64_t kInf = std::numeric_limits<std::int64_t>::max() / 4;
  auto relax = [&](std::vector<std::int64_t>& d) {  // Dijkstra from every node at its value
    using Item = std::pair<std::int64_t, std::size_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
    for (std::size_t v = 0; v < d.size(); ++v)
      if (d[v] < kInf) q.push({d[v], v});
    while (!q.empty()) {
      const auto [dv, v] = q.top();
      q.pop();
      if (dv != d[v]) continue;
      for (const Arc& a : adj[v])
        if (dv + a.w < d[a.to]) {
          d[a.to] = dv + a.w;
          q.push({d[a.to], a.to});
        }
    }
  };
  const std::size_t full = (std::size_t{1} << k) - 1;
  std::vector<std::vector<std::int64_t>> dp(full + 1);
  for (std::size_t mask = 1; mask <= full; ++mask) {
    std::vector<std::int64_t>& d = dp[mask];
    d.assign(total, kInf);
    if ((mask & (mask - 1)) == 0) {
      d[term[static_cast<std::size_t>(__builtin_ctzll(mask))]] = 0;
    } else {
      const std::size_t low = mask & (~mask + 1);
      for (std::size_t sub = (mask - 1) & mask; sub > 0; sub = (sub - 1) & mask) {
        if (!(sub & low)) continue;  // each split once
        const std::vector<std::int64_t>&a = dp[sub], &b = dp[mask ^ sub];
        for (std::size_t v = 0; v < total; ++v)
          if (a[v] < kInf && b[v] < kInf) d[v] = std::min(d[v], a[v] + b[v]);
      }
    }
    relax(d);
  }
  const std::int64_t best = dp[full][term[0]];
  if (best >= kInf) return std::nullopt;
  return best;
}

}  // namespace taut::oracle
