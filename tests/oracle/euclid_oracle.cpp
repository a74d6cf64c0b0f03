#include "oracle/euclid_oracle.h"

#include <cmath>

namespace taut::oracle {

using geom::Point;

long double euclid(Point a, Point b) {
  const long double dx = static_cast<long double>(a.x) - b.x, dy = static_cast<long double>(a.y) - b.y;
  return std::sqrt(dx * dx + dy * dy);
}

std::optional<EuclidPath> euclid_shortest(const L1Reference& ref, const std::vector<Point>& vertices, Point s,
                                          Point t) {
  if (s == t) return EuclidPath{0.0L, {s}};
  std::vector<Point> nodes{s, t};
  for (Point v : vertices)
    if (v != s && v != t && ref.is_free(v)) nodes.push_back(v);
  const std::size_t n = nodes.size();
  std::vector<long double> dist(n, INFINITY);
  std::vector<std::size_t> parent(n, n);
  std::vector<bool> done(n, false);
  dist[0] = 0;
  for (std::size_t it = 0; it < n; ++it) {  // dense Dijkstra: the graph is complete-ish
    std::size_t u = n;
    for (std::size_t i = 0; i < n; ++i)
      if (!done[i] && std::isfinite(dist[i]) && (u == n || dist[i] < dist[u])) u = i;
    if (u == n) break;
    done[u] = true;
    if (u == 1) {
      EuclidPath p{dist[1], {}};
      for (std::size_t v = 1; v != n; v = parent[v]) p.points.insert(p.points.begin(), nodes[v]);
      return p;
    }
    for (std::size_t v = 0; v < n; ++v)
      if (!done[v] && nodes[v] != nodes[u] && dist[u] + euclid(nodes[u], nodes[v]) < dist[v] &&
          ref.visible(nodes[u], nodes[v])) {
        dist[v] = dist[u] + euclid(nodes[u], nodes[v]);
        parent[v] = u;
      }
  }
  return std::nullopt;
}

}  // namespace taut::oracle
