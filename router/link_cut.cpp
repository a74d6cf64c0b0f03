#include "router/link_cut.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "geom/index.h"
#include "geom/predicates.h"
#include "router/link_polygon.h"

namespace taut::router {

namespace {

using geom::Point;
using geom::Ring;
using i64 = std::int64_t;

using link_steps::neg;
using link_steps::ray_of;
using link_steps::unit;

// One candidate: the extension from vertex i in direction d, meeting the boundary at `to`, which
// is vertex j (at_vertex) or inside the edge from vertex j to j + 1.
struct Candidate {
  std::size_t i = 0, j = 0;
  Point d, to;
  bool at_vertex = false;
  std::size_t left = 0, right = 0;  // vertices of the two parts after cleaning
};

}  // namespace

std::optional<PolygonCut> balanced_cut(const Ring& polygon) {
  const std::size_t n = polygon.size();
  if (n < 4) throw std::invalid_argument("balanced_cut: a polygon needs at least 4 vertices");
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = polygon[(i + n - 1) % n], v = polygon[i], b = polygon[(i + 1) % n];
    if (v.x != b.x && v.y != b.y) throw std::invalid_argument("balanced_cut: an edge is not axis-parallel");
    if (geom::orientation(a, v, b) == 0) throw std::invalid_argument("balanced_cut: a repeated or straight vertex");
  }
  const geom::Polygon poly{polygon, {}};
  const geom::ObstacleIndex index({&poly, 1});
  std::optional<Candidate> best;
  for (std::size_t i = 0; i < n; ++i) {
    const Point prev = polygon[(i + n - 1) % n], v = polygon[i], next = polygon[(i + 1) % n];
    if (geom::orientation(prev, v, next) >= 0) continue;  // convex (counter-clockwise ring)
    const Point din = unit(prev, v), dout = unit(v, next);
    for (const Point d : {din, neg(dout)}) {
      const geom::RayHit h = index.shoot(v, ray_of(d), {.ignore_edges_at_start = true});
      if (!h.hit()) throw std::invalid_argument("balanced_cut: a reflex vertex's extension leaves the polygon (not simple, or clockwise)");
      const i64 t = static_cast<i64>(h.t.num / h.t.den);
      Candidate c;
      c.i = i;
      c.d = d;
      c.to = {static_cast<geom::Coord>(v.x + d.x * t), static_cast<geom::Coord>(v.y + d.y * t)};
      for (const std::uint32_t id : h.edges) {
        const geom::EdgeRef& ref = index.edge_ref(id);
        const std::size_t a = ref.vertex, b = (ref.vertex + 1) % n;
        if (polygon[a] == c.to) c.at_vertex = true, c.j = a;
        else if (polygon[b] == c.to) c.at_vertex = true, c.j = b;
        else if (!c.at_vertex) c.j = a;
      }
      // vertex counts of the parts (see PolygonCut): v and `to` are in both; v goes straight on
      // in the part holding the edge the cut extends; at a vertex `to`, the part whose edge into
      // (or out of) it runs along the cut loses it; inside an edge, `to` is a corner of both
      // (left: vertices i .. j, and `to` when it is inside edge j; right: `to` or vertex j, then
      // j + 1 .. i)
      const std::size_t steps = (c.j + n - i) % n;
      c.left = steps + 1 + (c.at_vertex ? 0 : 1) - (d == neg(dout) ? 1 : 0);
      c.right = n - steps + 1 - (d == din ? 1 : 0);
      if (c.at_vertex) {
        const Point pj = polygon[(c.j + n - 1) % n], vj = polygon[c.j], nj = polygon[(c.j + 1) % n];
        c.left -= unit(pj, vj) == neg(d) ? 1 : 0;
        c.right -= unit(vj, nj) == d ? 1 : 0;
      }
      if (!best || std::max(c.left, c.right) < std::max(best->left, best->right)) best = c;
    }
  }
  if (!best) return std::nullopt;
  const Candidate& c = *best;
  PolygonCut out;
  out.from = polygon[c.i];
  out.to = c.to;
  out.vertex = c.i;
  Ring left, right;
  for (std::size_t k = c.i;; k = (k + 1) % n) {
    left.push_back(polygon[k]);
    if (k == c.j) break;
  }
  if (!c.at_vertex) left.push_back(c.to), right.push_back(c.to);
  for (std::size_t k = c.at_vertex ? c.j : (c.j + 1) % n;; k = (k + 1) % n) {
    right.push_back(polygon[k]);
    if (k == c.i) break;
  }
  out.left = clean_ring(left);
  out.right = clean_ring(right);
  if (out.left.size() != c.left || out.right.size() != c.right || out.left.size() < 4 || out.right.size() < 4)
    throw std::logic_error("balanced_cut: the parts' vertex counts differ from the count that chose the cut");
  return out;
}

CutTree::CutTree(const Ring& polygon) {
  nodes_.push_back({polygon, std::nullopt, -1, -1, -1, 0});
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    std::optional<PolygonCut> cut = balanced_cut(nodes_[k].polygon);
    if (!cut) continue;
    const int depth = nodes_[k].depth + 1;
    depth_ = std::max(depth_, depth);
    const auto self = static_cast<std::int32_t>(k);
    Node l{std::move(cut->left), std::nullopt, self, -1, -1, depth};
    Node r{std::move(cut->right), std::nullopt, self, -1, -1, depth};
    cut->left.clear();
    cut->right.clear();
    nodes_[k].cut = std::move(cut);
    nodes_[k].left = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back(std::move(l));
    nodes_[k].right = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back(std::move(r));
  }
}

}  // namespace taut::router
