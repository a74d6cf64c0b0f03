// Nets with a known legal routing ("planted"), for the net router's completion target (issue
// #7: 10^4 nets of two to five pins on a 10^5-vertex layout, >= 99 % routed when a legal routing
// exists). Each net is drawn as its wires first: a first pin at a free point, then each further
// pin at a random point within `reach` (L-infinity) of it, joined to a random vertex of the net's
// wires so far by an L (horizontal then vertical, or the other way, at random). A leg is kept
// only when its box grown by a = ceil(w/2) + s meets no blockage's interior and stays in the
// domain, and grown by b = max(w + s, 1) meets no other net's planted leg (open boxes: touching
// at exactly the clearance is allowed). An L-infinity gap of at least d keeps a Euclidean gap of
// at least d, so the planted wires keep the clearance the checker asks for; a net that cannot get
// all its pins in a few tries is dropped. The routing is then checked by router::check_routes
// (the independent checker, with the rules), and any net it finds a problem with is dropped too,
// so the nets returned have a legal routing: their planted wires.
//
// The blockage test needs axis-parallel blockage edges (the benchmark's `rects` layouts; a
// sloped edge throws std::invalid_argument).
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "geom/normalize.h"
#include "geom/types.h"
#include "router/check.h"
#include "router/net_router.h"
#include "router/spm.h"
#include "support/net_layouts.h"

namespace taut::bench {

struct PlantedNets {
  std::vector<router::NetPins> nets;
  std::vector<std::vector<std::vector<geom::Point>>> wires;  // per net, its planted wires
  std::size_t drawn = 0;         // nets attempted
  std::size_t checker_drops = 0; // nets dropped because the checker found a problem (expected 0)
};

inline PlantedNets planted_nets(const geom::NormalizedObstacles& norm, std::size_t m, std::int64_t w, std::int64_t s,
                                std::int64_t reach, std::uint64_t seed, std::size_t max_pins = 5) {
  namespace bg = boost::geometry;
  namespace bgi = boost::geometry::index;
  using BPoint = bg::model::point<std::int64_t, 2, bg::cs::cartesian>;
  using BBox = bg::model::box<BPoint>;
  struct Seg {
    std::int64_t x0, y0, x1, y1;  // x0 <= x1, y0 <= y1 (axis-parallel: one range is a point)
  };
  const std::int64_t a = (w + 1) / 2 + s, b = std::max<std::int64_t>(w + s, 1);
  const geom::Box& dom = norm.domain;
  auto seg_of = [](geom::Point p, geom::Point q) {
    return Seg{std::min<std::int64_t>(p.x, q.x), std::min<std::int64_t>(p.y, q.y), std::max<std::int64_t>(p.x, q.x),
               std::max<std::int64_t>(p.y, q.y)};
  };
  auto box_of = [](const Seg& g) { return BBox(BPoint(g.x0, g.y0), BPoint(g.x1, g.y1)); };
  // blockage edges
  std::vector<std::pair<BBox, Seg>> edges;
  for (const geom::Polygon& o : norm.obstacles) {
    auto ring = [&](const std::vector<geom::Point>& r) {
      for (std::size_t i = 0; i < r.size(); ++i) {
        const geom::Point p = r[i], q = r[(i + 1) % r.size()];
        if (p.x != q.x && p.y != q.y) throw std::invalid_argument("planted_nets: a sloped blockage edge");
        const Seg g = seg_of(p, q);
        edges.emplace_back(box_of(g), g);
      }
    };
    ring(o.outer);
    for (const auto& h : o.holes) ring(h);
  }
  bgi::rtree<std::pair<BBox, Seg>, bgi::quadratic<16>> blockage_edges(edges.begin(), edges.end());
  bgi::rtree<std::pair<BBox, std::pair<Seg, std::size_t>>, bgi::quadratic<16>> planted;  // legs, with their net
  // Does the closed segment g meet the open box (x0, x1) x (y0, y1)?
  auto meets_open = [](const Seg& g, std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
    return g.x1 > x0 && g.x0 < x1 && g.y1 > y0 && g.y0 < y1;
  };
  // Whether a point is free (one point location in a source-less shortest path map).
  const router::L1Map probe(dom, norm.obstacles, {});
  auto leg_ok = [&](geom::Point p, geom::Point q, std::size_t net) {
    const Seg g = seg_of(p, q);
    if (g.x0 - a < dom.lo.x || g.y0 - a < dom.lo.y || g.x1 + a > dom.hi.x || g.y1 + a > dom.hi.y) return false;
    const BBox ga(BPoint(g.x0 - a, g.y0 - a), BPoint(g.x1 + a, g.y1 + a));
    for (auto it = blockage_edges.qbegin(bgi::intersects(ga)); it != blockage_edges.qend(); ++it)
      if (meets_open(it->second, g.x0 - a, g.y0 - a, g.x1 + a, g.y1 + a)) return false;
    // no edge meets the open grown box, so it lies in one face: free when p is
    if (!probe.is_free(p)) return false;
    const BBox gb(BPoint(g.x0 - b, g.y0 - b), BPoint(g.x1 + b, g.y1 + b));
    for (auto it = planted.qbegin(bgi::intersects(gb)); it != planted.qend(); ++it)
      if (it->second.second != net && meets_open(it->second.first, g.x0 - b, g.y0 - b, g.x1 + b, g.y1 + b)) return false;
    return true;
  };
  std::mt19937_64 rng(seed);
  auto coord = [&](std::int64_t lo, std::int64_t hi) { return lo + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
  PlantedNets out;
  for (std::size_t tries = 0; out.nets.size() < m && tries < 50 * m; ++tries) {
    ++out.drawn;
    const std::size_t id = out.nets.size();
    const std::size_t k = 2 + id % (max_pins - 1);
    const geom::Point p0{static_cast<geom::Coord>(coord(dom.lo.x + a, dom.hi.x - a)), static_cast<geom::Coord>(coord(dom.lo.y + a, dom.hi.y - a))};
    if (!leg_ok(p0, p0, id)) continue;
    std::vector<geom::Point> pins{p0}, verts{p0};
    std::vector<std::vector<geom::Point>> wires;
    for (int attempt = 0; pins.size() < k && attempt < 20 * static_cast<int>(k); ++attempt) {
      const geom::Point t{static_cast<geom::Coord>(std::clamp<std::int64_t>(coord(p0.x - reach, p0.x + reach), dom.lo.x + a, dom.hi.x - a)),
                          static_cast<geom::Coord>(std::clamp<std::int64_t>(coord(p0.y - reach, p0.y + reach), dom.lo.y + a, dom.hi.y - a))};
      const geom::Point v = verts[rng() % verts.size()];
      if (t == v || std::find(pins.begin(), pins.end(), t) != pins.end()) continue;
      const geom::Point c = rng() % 2 ? geom::Point{t.x, v.y} : geom::Point{v.x, t.y};
      if (!leg_ok(v, c, id) || !leg_ok(c, t, id)) continue;
      std::vector<geom::Point> wire{v};
      if (c != v && c != t) wire.push_back(c);
      wire.push_back(t);
      wires.push_back(wire);
      pins.push_back(t);
      verts.push_back(t);
      if (c != v && c != t) verts.push_back(c);
    }
    if (pins.size() < k) continue;
    for (const auto& wire : wires)
      for (std::size_t i = 0; i + 1 < wire.size(); ++i) {
        const Seg g = seg_of(wire[i], wire[i + 1]);
        planted.insert({box_of(g), {g, id}});
      }
    router::NetPins np;
    np.name = "n" + std::to_string(id);
    for (const geom::Point p : pins) np.pins.push_back(geom::Polygon{{p}, {}});
    out.nets.push_back(std::move(np));
    out.wires.push_back(std::move(wires));
  }
  // the independent checker on the planted routing; nets with a problem are dropped
  const router::CheckResult r =
      router::check_routes(norm, test::check_nets(out.nets, out.wires), router::CheckRules{w, s});
  std::vector<char> bad(out.nets.size(), 0);
  for (const router::CheckProblem& p : r.problems) bad[p.net] = 1;
  PlantedNets kept;
  kept.drawn = out.drawn;
  for (std::size_t i = 0; i < out.nets.size(); ++i) {
    if (bad[i]) {
      ++kept.checker_drops;
      continue;
    }
    kept.nets.push_back(std::move(out.nets[i]));
    kept.wires.push_back(std::move(out.wires[i]));
  }
  return kept;
}

}  // namespace taut::bench
