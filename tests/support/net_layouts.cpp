#include "support/net_layouts.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <random>
#include <string>

#include "router/bend_router.h"
#include "router/l1_router.h"
#include "support/random_shapes.h"

namespace taut::test {

using geom::Point;
using geom::Polygon;

// Rectangles that touch and pinch (and, for some seeds, sloped triangles), nets of 2-4 point
// pins, some pins on blockage edges and corners.
RandomLayout random_layout(int seed) {
  std::mt19937 rng(static_cast<unsigned>(seed));
  RandomLayout L;
  const geom::Box domain{{0, 0}, {120, 120}};
  std::vector<Polygon> polys;
  const int kind = seed % 4;
  if (kind == 3) {
    polys = random_triangles(rng, domain, 4);
  } else {
    const std::vector<geom::Box> boxes = random_boxes_apart(rng, static_cast<int>(rng() % 9), 4, 100, 22);
    polys = box_polygons(boxes);
    if (kind == 1 && !boxes.empty()) {  // a box touching one at a corner: a pinch
      const geom::Box o = boxes[rng() % boxes.size()];
      const geom::Box c = corner_box(o, 8, 6, static_cast<int>(rng() % 4));
      if (c.lo.x >= 0 && c.lo.y >= 0 && c.hi.x <= 120 && c.hi.y <= 120) polys.push_back(box_polygons(std::vector<geom::Box>{c})[0]);
    }
  }
  L.norm = geom::normalize_obstacles(polys, domain);
  L.rules.wire_width = static_cast<std::int64_t>(rng() % 4) * (seed % 5 == 0 ? 0 : 1);
  L.rules.spacing = static_cast<std::int64_t>(rng() % 3);
  router::L1Router plain(L.norm.domain, L.norm.obstacles);
  std::vector<Point> used;
  auto pin = [&]() -> Point {
    for (int tries = 0; tries < 200; ++tries) {
      Point p{static_cast<geom::Coord>(rng() % 121), static_cast<geom::Coord>(rng() % 121)};
      if (rng() % 3 == 0 && !L.norm.obstacles.empty()) {  // on a blockage's boundary
        const geom::Ring& r = L.norm.obstacles[rng() % L.norm.obstacles.size()].outer;
        const Point u = r[rng() % r.size()], v = r[rng() % r.size()];
        p = rng() % 2 ? u : Point{static_cast<geom::Coord>((u.x + v.x) / 2), static_cast<geom::Coord>((u.y + v.y) / 2)};
      }
      bool dup = false;
      for (const Point q : used) dup = dup || q == p;
      if (!dup && plain.is_free(p)) return p;
    }
    return Point{0, 0};
  };
  // a rectangular pad at p (free inside; it may touch blockages), or nothing
  auto pad = [&](Point p) -> std::optional<Polygon> {
    const geom::Coord w = static_cast<geom::Coord>(2 + rng() % 6), h = static_cast<geom::Coord>(2 + rng() % 6);
    if (p.x + w > 120 || p.y + h > 120) return std::nullopt;
    Polygon g{{p, {static_cast<geom::Coord>(p.x + w), p.y}, {static_cast<geom::Coord>(p.x + w), static_cast<geom::Coord>(p.y + h)},
               {p.x, static_cast<geom::Coord>(p.y + h)}},
              {}};
    if (plain.pin_meets_obstacle(g)) return std::nullopt;
    for (const Point q : used)
      if (q.x >= p.x - 1 && q.x <= p.x + w + 1 && q.y >= p.y - 1 && q.y <= p.y + h + 1) return std::nullopt;
    return g;
  };
  const int n = 1 + static_cast<int>(rng() % 6);
  for (int i = 0; i < n; ++i) {
    router::NetPins net;
    net.name = "n" + std::to_string(i);
    const int k = 2 + static_cast<int>(rng() % (seed % 2 ? 3 : 1));
    for (int j = 0; j < k; ++j) {
      const Point p = pin();
      std::optional<Polygon> g = seed % 3 == 2 && rng() % 3 == 0 ? pad(p) : std::nullopt;
      if (g) {
        for (const Point v : g->outer) used.push_back(v);
        net.pins.push_back(*g);
      } else {
        net.pins.push_back(Polygon{{p}, {}});
      }
      used.push_back(p);
    }
    L.nets.push_back(std::move(net));
  }
  return L;
}

std::vector<router::CheckNet> check_nets(std::span<const router::NetPins> ns,
                                         std::span<const std::vector<std::vector<Point>>> wires) {
  std::vector<router::CheckNet> nets;
  for (std::size_t i = 0; i < ns.size(); ++i) {
    router::CheckNet cn;
    cn.name = ns[i].name;
    for (std::size_t j = 0; j < ns[i].pins.size(); ++j) {
      const Polygon& g = ns[i].pins[j];
      if (g.outer.size() == 1)
        cn.pins.push_back({"p" + std::to_string(j), g.outer[0], std::nullopt, 0});
      else
        cn.pins.push_back({"p" + std::to_string(j), std::nullopt, g, 0});
    }
    cn.routed = !wires[i].empty();
    for (const auto& w : wires[i]) cn.wires.push_back({w, static_cast<int>(i)});
    nets.push_back(std::move(cn));
  }
  return nets;
}

std::vector<router::CheckNet> check_nets(std::span<const router::NetPins> ns, const router::NetRouter& nr) {
  std::vector<std::vector<std::vector<Point>>> wires;
  for (const router::NetOutcome& o : nr.outcomes()) wires.push_back(o.routed ? o.wires : std::vector<std::vector<Point>>{});
  return check_nets(ns, wires);
}

std::optional<std::vector<Point>> way_between(const std::vector<std::vector<Point>>& pieces, Point a, Point b) {
  if (a == b) return std::vector<Point>{a, b};
  std::map<Point, std::optional<std::pair<Point, std::size_t>>> from;  // node -> (previous node, piece)
  std::vector<Point> queue{a};
  from[a] = std::nullopt;
  for (std::size_t q = 0; q < queue.size() && !from.count(b); ++q) {
    const Point u = queue[q];
    for (std::size_t k = 0; k < pieces.size(); ++k)
      for (const auto& [x, y] : {std::pair{pieces[k].front(), pieces[k].back()}, std::pair{pieces[k].back(), pieces[k].front()}})
        if (x == u && !from.count(y)) {
          from[y] = std::pair{u, k};
          queue.push_back(y);
        }
  }
  if (!from.count(b)) return std::nullopt;
  std::vector<Point> out{b};
  for (Point v = b; from[v];) {
    const auto [u, k] = *from[v];
    std::vector<Point> p = pieces[k];
    if (p.front() != u) std::reverse(p.begin(), p.end());
    out.insert(out.end(), p.rbegin() + 1, p.rend());
    v = u;
  }
  std::reverse(out.begin(), out.end());
  return out;
}

std::int64_t l1_len(const router::NetOutcome& o) {
  std::int64_t n = 0;
  for (const auto& w : o.wires)
    for (std::size_t i = 1; i < w.size(); ++i) n += std::abs(w[i].x - w[i - 1].x) + std::abs(w[i].y - w[i - 1].y);
  return n;
}

BendRun bend_run(const RandomLayout& layout, int seed) {
  BendRun r;
  r.covered = geom::normalize_obstacles(router::rectilinear_cover(layout.norm.obstacles), layout.norm.domain);
  const bool link = seed % 5 == 0;
  const std::int64_t c = std::vector<std::int64_t>{0, 1, 7, 1000}[static_cast<std::size_t>(seed) % 4];
  r.options.cost = link ? router::NetRouterOptions::Cost::Link : router::NetRouterOptions::Cost::Combined;
  r.options.bend_cost = c;
  r.rules = layout.rules;
  r.rules.cover_pieces = router::kDefaultCoverPieces;
  r.route = router::NetRouter::bend_router(link ? router::BendMetric::Link : router::BendMetric::Combined, c);
  r.options.blockages_covered = r.covered.obstacles != layout.norm.obstacles;  // (as taut route says)
  r.label = link ? "link" : "C " + std::to_string(c);
  return r;
}

}  // namespace taut::test
