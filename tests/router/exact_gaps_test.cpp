// router::NetRouterOptions::exact_gaps (issues #7 and #5): gaps of exactly the clearance, and
// tracks at exactly the pitch, take wires. Judged by an independent reference and by the
// independent checker (router/check.h):
//   - a net alone among rectangles on a coarse lattice (so that gaps of exactly 2a, blockages
//     that touch and pins at exactly a from a blockage are common) gets the exact L1 shortest
//     length in the closed free space: the domain minus the open rectangles grown by a (outside
//     the pins' access squares), which a Hanan-grid Dijkstra written here computes (it shares
//     nothing with the router); the router
//     without exact_gaps is longer or fails on a share of the same instances, so the comparison
//     can tell the two apart;
//   - many nets with rules on random layouts (sloped blockages and pads included) and under the
//     bend-aware metrics pass the checker with exact_gaps;
//   - hand-made cases: a gap of exactly 2a, two wires at exactly the pitch, and a domain too
//     large for a scale (exact_gaps then does nothing).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <queue>
#include <random>

#include "geom/normalize.h"
#include "router/bend_router.h"
#include "router/check.h"
#include "router/l1_router.h"
#include "router/net_router.h"
#include "router/oct_router.h"
#include "router/tighten_nets.h"
#include "oracle/oct_steiner_oracle.h"
#include "support/net_layouts.h"
#include "support/random_shapes.h"
#include "support/sanitized.h"

namespace taut::test {
namespace exact_gaps_test {

using geom::Point;
using geom::Polygon;

struct Rect {
  std::int64_t x0, y0, x1, y1;
};

// The L1 distance between the pins p and q of a net, by the checker's rules (router/check.h): a
// wire stays in the closed domain minus the interior of the union of the blockages (so not along
// an edge two blockages share), passes a point only within one free wedge there (not through a
// point where two blockages touch corner to corner), and keeps L-inf distance >= a from every
// blockage, that is, stays out of the open rectangles `grown` (each blockage grown by a square of
// half-side a), except inside the closed squares of half-side a round a point pin (its pin
// access). A pin is a point (a rectangle of no extent) or a pad (a rectangle with area): a wire
// touches a pad anywhere, and keeps the clearance up to its end there (pads get no access zone).
// Dijkstra over (grid node, direction of arrival) on the Hanan grid of every rectangle's sides,
// the domain's and the pins': every L1 shortest path among axis-parallel rectangles can be moved
// onto that grid (its last point on the first pad and first point on the second lie on a pad's
// side, so at grid nodes), all sides are grid lines, so an edge's midpoint decides its clearance,
// and the material round a node is read in its four quadrants. Every grid node on the first pin
// is a source. The cost: the L1 length, or (since 2026-12-05) under the bend-aware metrics the
// length + C x bends (Combined; a path moved onto the grid keeps its bends, or loses some where
// segments merge), or bends x kLinkWeight + length (Link: fewest bends, then shortest).
struct RefCost {
  router::NetRouterOptions::Cost kind = router::NetRouterOptions::Cost::Length;
  std::int64_t bend_cost = 0;
};
constexpr std::int64_t kLinkWeight = std::int64_t{1} << 40;
std::optional<std::int64_t> hanan_distance(const Rect& domain, const std::vector<Rect>& blockages, const std::vector<Rect>& grown,
                                           std::int64_t a, const Rect& p, const Rect& q, RefCost cost = {}) {
  const std::int64_t turn = cost.kind == router::NetRouterOptions::Cost::Link     ? kLinkWeight
                            : cost.kind == router::NetRouterOptions::Cost::Combined ? cost.bend_cost
                                                                                    : 0;
  auto is_point = [](const Rect& r) { return r.x0 == r.x1 && r.y0 == r.y1; };
  std::vector<std::int64_t> xs{domain.x0, domain.x1, p.x0, p.x1, q.x0, q.x1}, ys{domain.y0, domain.y1, p.y0, p.y1, q.y0, q.y1};
  std::vector<Rect> squares;
  for (const Rect& r : {p, q})
    if (is_point(r)) squares.push_back({r.x0 - a, r.y0 - a, r.x0 + a, r.y0 + a});
  std::vector<Rect> all = grown;
  all.insert(all.end(), blockages.begin(), blockages.end());
  all.insert(all.end(), squares.begin(), squares.end());
  for (const Rect& r : all) {
    for (std::int64_t x : {r.x0, r.x1})
      if (x >= domain.x0 && x <= domain.x1) xs.push_back(x);
    for (std::int64_t y : {r.y0, r.y1})
      if (y >= domain.y0 && y <= domain.y1) ys.push_back(y);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  // Quadrupled coordinates (grid nodes and edge midpoints are multiples of 2; a node's or a
  // midpoint's neighbourhood is sampled at +-1, strictly inside the cells round it).
  auto in_open = [](const Rect& r, std::int64_t x4, std::int64_t y4) {
    return 4 * r.x0 < x4 && x4 < 4 * r.x1 && 4 * r.y0 < y4 && y4 < 4 * r.y1;
  };
  auto in_closed = [](const Rect& r, std::int64_t x4, std::int64_t y4) {
    return 4 * r.x0 <= x4 && x4 <= 4 * r.x1 && 4 * r.y0 <= y4 && y4 <= 4 * r.y1;
  };
  // material: outside the domain, or inside a blockage
  auto material = [&](std::int64_t x4, std::int64_t y4) {
    if (!in_open(domain, x4, y4)) return true;
    for (const Rect& r : blockages)
      if (in_open(r, x4, y4)) return true;
    return false;
  };
  // closer than a to a blockage, outside the pin access
  auto too_close = [&](std::int64_t x4, std::int64_t y4) {
    for (const Rect& sq : squares)
      if (in_closed(sq, x4, y4)) return false;
    for (const Rect& r : grown)
      if (in_open(r, x4, y4)) return true;
    return false;
  };
  // directions E, N, W, S (counter-clockwise); quadrant k lies between directions k and k + 1
  const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
  auto quadrants = [&](std::int64_t x4, std::int64_t y4) {
    std::array<bool, 4> m{};
    for (int k = 0; k < 4; ++k) m[k] = material(x4 + (dx[k] + dx[(k + 1) % 4]), y4 + (dy[k] + dy[(k + 1) % 4]));
    return m;
  };
  // an edge from a node in direction k is free when it is not flush between material on both
  // sides and keeps the clearance (its midpoint decides both)
  auto edge_free = [&](std::int64_t mx4, std::int64_t my4, int k) {
    const int lx = dx[(k + 1) % 4], ly = dy[(k + 1) % 4];  // its left side
    if (material(mx4 + lx, my4 + ly) && material(mx4 - lx, my4 - ly)) return false;
    return !too_close(mx4, my4);
  };
  const std::size_t nx = xs.size(), ny = ys.size();
  const auto ix = [&](std::int64_t v, const std::vector<std::int64_t>& arr) {
    return static_cast<std::size_t>(std::lower_bound(arr.begin(), arr.end(), v) - arr.begin());
  };
  // a pin's grid nodes where a wire may end: not walled in by material, and keeping the clearance
  auto ends = [&](const Rect& r) {
    std::vector<std::pair<std::size_t, std::size_t>> e;
    for (std::size_t i = ix(r.x0, xs); i < nx && xs[i] <= r.x1; ++i)
      for (std::size_t j = ix(r.y0, ys); j < ny && ys[j] <= r.y1; ++j) {
        const std::array<bool, 4> m = quadrants(4 * xs[i], 4 * ys[j]);
        if (!(m[0] && m[1] && m[2] && m[3]) && !too_close(4 * xs[i], 4 * ys[j])) e.push_back({i, j});
      }
    return e;
  };
  const auto from = ends(p), to = ends(q);
  if (from.empty() || to.empty()) return std::nullopt;
  std::vector<char> target(nx * ny, 0);
  for (const auto& [i, j] : to) target[i * ny + j] = 1;
  // state: node * 5 + the direction it was entered by (4: a start)
  auto state = [&](std::size_t i, std::size_t j, int k) { return (i * ny + j) * 5 + static_cast<std::size_t>(k); };
  std::vector<std::int64_t> dist(nx * ny * 5, std::numeric_limits<std::int64_t>::max());
  using Item = std::pair<std::int64_t, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
  for (const auto& [i, j] : from) {
    dist[state(i, j, 4)] = 0;
    pq.push({0, state(i, j, 4)});
  }
  while (!pq.empty()) {
    const auto [d, u] = pq.top();
    pq.pop();
    if (d != dist[u]) continue;
    const int in_dir = static_cast<int>(u % 5);
    const std::size_t node = u / 5, i = node / ny, j = node % ny;
    if (target[i * ny + j]) return d;
    const std::int64_t x4 = 4 * xs[i], y4 = 4 * ys[j];
    const std::array<bool, 4> m = quadrants(x4, y4);
    for (int k = 0; k < 4; ++k) {
      if (in_dir != 4) {
        // leaving by k after arriving along in_dir: the way back points to in_dir + 2; one of
        // the two arcs between the two directions must be free quadrants only
        const int back = (in_dir + 2) % 4;
        if (k == back) continue;
        bool ccw = true, cw = true;
        for (int t = back; t != k; t = (t + 1) % 4) ccw &= !m[t];
        for (int t = k; t != back; t = (t + 1) % 4) cw &= !m[t];
        if (!ccw && !cw) continue;
      }
      const std::int64_t i2 = static_cast<std::int64_t>(i) + dx[k], j2 = static_cast<std::int64_t>(j) + dy[k];
      if (i2 < 0 || j2 < 0 || i2 >= static_cast<std::int64_t>(nx) || j2 >= static_cast<std::int64_t>(ny)) continue;
      const std::size_t a2 = static_cast<std::size_t>(i2), b2 = static_cast<std::size_t>(j2);
      const std::int64_t mx4 = 2 * (xs[i] + xs[a2]), my4 = 2 * (ys[j] + ys[b2]);
      if (!edge_free(mx4, my4, k) || too_close(4 * xs[a2], 4 * ys[b2])) continue;
      const std::int64_t nd = d + std::abs(xs[a2] - xs[i]) + std::abs(ys[b2] - ys[j]) + (in_dir != 4 && k != in_dir ? turn : 0);
      if (nd < dist[state(a2, b2, k)]) {
        dist[state(a2, b2, k)] = nd;
        pq.push({nd, state(a2, b2, k)});
      }
    }
  }
  return std::nullopt;
}


Polygon rect_polygon(const Rect& r) {
  const auto c = [](std::int64_t v) { return static_cast<geom::Coord>(v); };
  return Polygon{{{c(r.x0), c(r.y0)}, {c(r.x1), c(r.y0)}, {c(r.x1), c(r.y1)}, {c(r.x0), c(r.y1)}}, {}};
}

// One instance: rectangles with corners on the lattice of a (now and then one unit off it),
// rules with that a, two pins in the closed free space of the grown blockages, or for a quarter
// of the instances anywhere off the open blockages: point pins (most on the lattice too), or with
// `pads` for two thirds of the pins pads, rectangles 1 to 2a wide and high (most with corners on
// the lattice), so pads touch blockages, lie at exactly a from them or within a.
struct Instance {
  Rect domain;
  std::vector<Rect> blockages;
  router::NetRules rules;
  Rect p, q;  // a point pin: x0 == x1, y0 == y1
};

std::optional<Instance> random_instance(std::uint32_t seed, bool pads = false) {
  std::mt19937 rng(seed);
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  Instance in;
  in.rules.wire_width = pick(0, 4);
  in.rules.spacing = pick(0, 2);
  // a >= 1: with a = 0 nothing is grown, and the reference's closed space would let a wire
  // through a point where two blockages touch, which is not free
  if (in.rules.wire_width == 0 && in.rules.spacing == 0) in.rules.spacing = 1;
  const std::int64_t a = std::max<std::int64_t>((in.rules.wire_width + 1) / 2 + in.rules.spacing, 1);
  const int cells = pick(8, 24);
  in.domain = {0, 0, cells * a, cells * a};
  const int n = pick(2, 14);
  for (int k = 0; k < n; ++k) {
    std::int64_t x0 = pick(0, cells - 1) * a, y0 = pick(0, cells - 1) * a;
    std::int64_t x1 = x0 + pick(1, 6) * a, y1 = y0 + pick(1, 6) * a;
    if (pick(0, 9) == 0) x0 += pick(-1, 1);  // a gap one unit off 2a now and then
    if (pick(0, 9) == 0) y1 += pick(-1, 1);
    x1 = std::min(x1, in.domain.x1);
    y1 = std::min(y1, in.domain.y1);
    if (x0 < 0) x0 = 0;
    if (x1 <= x0 || y1 <= y0) continue;
    in.blockages.push_back({x0, y0, x1, y1});
  }
  std::vector<Rect> grown;
  for (const Rect& r : in.blockages) grown.push_back({r.x0 - a, r.y0 - a, r.x1 + a, r.y1 + a});
  // most pins in the closed free space of the grown blockages, the rest anywhere off the closed
  // blockages (point pins within a of one: the pin access) or off the open ones (pads)
  const bool near = pick(0, 3) == 0;
  auto free_point = [&]() -> std::optional<Rect> {
    for (int tries = 0; tries < 50; ++tries) {
      const bool lattice = pick(0, 3) != 0;
      const std::int64_t x = lattice ? pick(0, cells) * a : pick(0, static_cast<int>(cells * a));
      const std::int64_t y = lattice ? pick(0, cells) * a : pick(0, static_cast<int>(cells * a));
      bool inside = false;
      for (const Rect& g : near ? in.blockages : grown)
        inside |= near ? g.x0 <= x && x <= g.x1 && g.y0 <= y && y <= g.y1 : g.x0 < x && x < g.x1 && g.y0 < y && y < g.y1;
      if (!inside) return Rect{x, y, x, y};
    }
    return std::nullopt;
  };
  auto free_pad = [&]() -> std::optional<Rect> {
    for (int tries = 0; tries < 50; ++tries) {
      const bool lattice = pick(0, 3) != 0;
      const std::int64_t w = lattice ? pick(1, 2) * a : pick(1, static_cast<int>(2 * a));
      const std::int64_t h = lattice ? pick(1, 2) * a : pick(1, static_cast<int>(2 * a));
      const std::int64_t x = lattice ? pick(0, cells) * a : pick(0, static_cast<int>(cells * a));
      const std::int64_t y = lattice ? pick(0, cells) * a : pick(0, static_cast<int>(cells * a));
      const Rect r{x, y, x + w, y + h};
      if (r.x1 > in.domain.x1 || r.y1 > in.domain.y1) continue;
      bool meets = false;  // the open rectangles meet
      for (const Rect& g : near ? in.blockages : grown) meets |= g.x0 < r.x1 && r.x0 < g.x1 && g.y0 < r.y1 && r.y0 < g.y1;
      if (!meets) return r;
    }
    return std::nullopt;
  };
  const auto p = pads && pick(0, 2) != 0 ? free_pad() : free_point();
  const auto q = pads && pick(0, 2) != 0 ? free_pad() : free_point();
  if (!p || !q) return std::nullopt;
  // pins that share a point are joined without a wire (the router writes a wire of one point
  // there, which is not what this test is about)
  if (p->x0 <= q->x1 && q->x0 <= p->x1 && p->y0 <= q->y1 && q->y0 <= p->y1) return std::nullopt;
  in.p = *p;
  in.q = *q;
  return in;
}

Polygon pin_polygon(const Rect& r) {
  if (r.x0 == r.x1 && r.y0 == r.y1) return Polygon{{Point{static_cast<geom::Coord>(r.x0), static_cast<geom::Coord>(r.y0)}}, {}};
  return rect_polygon(r);
}

struct AloneTotals {
  int failed = 0, compared = 0, with_pad = 0, routed = 0, closed_longer = 0, closed_unrouted = 0, proven = 0, spiked = 0;
};

// A net alone: with exact_gaps the router's length is the reference's, and it is routed exactly
// when the reference finds a way; the wire passes the checker; the claim of shortest length
// (NetOutcome::shortest) is made on most routed nets, never on a wire with a spike or without a
// distance, and never with the gaps closed; with the gaps closed the net is never shorter.
void judge_alone(std::uint32_t seed, bool pads, AloneTotals& t, RefCost cost = {}) {
  using Cost = router::NetRouterOptions::Cost;
  const bool bends = cost.kind != Cost::Length;
  const std::optional<Instance> in = random_instance(seed, pads);
  if (!in) return;
  int& failed = t.failed;
  const std::int64_t a = (in->rules.wire_width + 1) / 2 + in->rules.spacing;
  std::vector<Rect> grown;
  std::vector<Polygon> polys;
  for (const Rect& r : in->blockages) {
    grown.push_back({r.x0 - a, r.y0 - a, r.x1 + a, r.y1 + a});
    polys.push_back(rect_polygon(r));
  }
  const geom::Box domain{{static_cast<geom::Coord>(in->domain.x0), static_cast<geom::Coord>(in->domain.y0)},
                         {static_cast<geom::Coord>(in->domain.x1), static_cast<geom::Coord>(in->domain.y1)}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(polys, domain);
  const std::vector<router::NetPins> nets{{"n", {pin_polygon(in->p), pin_polygon(in->q)}}};
  const std::optional<std::int64_t> ref = hanan_distance(in->domain, in->blockages, grown, a, in->p, in->q, cost);
  // an outcome's cost as the reference measures it
  auto cost_of = [&](const router::NetOutcome& o) {
    std::int64_t bent = 0;
    for (const auto& w : o.wires) bent += geom::count_bends(w);
    return l1_len(o) + bent * (cost.kind == Cost::Link ? kLinkWeight : cost.kind == Cost::Combined ? cost.bend_cost : 0);
  };
  auto rect_str = [](const Rect& r) {
    return "(" + std::to_string(r.x0) + "," + std::to_string(r.y0) + ")-(" + std::to_string(r.x1) + "," + std::to_string(r.y1) + ")";
  };
  const std::string at = "seed " + std::to_string(seed) + (pads ? " with pads" : "") +
                         (cost.kind == Cost::Link ? " link" : bends ? " C " + std::to_string(cost.bend_cost) : "") + " (w " +
                         std::to_string(in->rules.wire_width) + ", s " + std::to_string(in->rules.spacing) + ", pins " +
                         rect_str(in->p) + " " + rect_str(in->q) + ")";
  router::NetRouterOptions opt;
  opt.exact_gaps = true;
  opt.cost = cost.kind;
  opt.bend_cost = cost.bend_cost;
  router::NetRules rules = in->rules;
  rules.cover_pieces = router::kDefaultCoverPieces;
  const router::NetRouteFn plain =
      bends ? router::NetRouter::bend_router(cost.kind == Cost::Link ? router::BendMetric::Link : router::BendMetric::Combined,
                                             cost.bend_cost)
            : router::NetRouter::l1_router(false);
  router::NetRouter nr(norm.domain, norm.obstacles, nets, rules, opt);
  if (nr.scale() < 8 && failed++ < 8) ADD_FAILURE() << at << ": scale " << nr.scale();
  nr.run(plain);
  const router::NetOutcome& o = nr.outcomes()[0];
  ++t.compared;
  t.with_pad += in->p.x0 != in->p.x1 || in->q.x0 != in->q.x1;
  if (nr.stats().snap_far > 0 && failed++ < 8) ADD_FAILURE() << at << ": a wire snapped from afar";
  if (o.routed != ref.has_value()) {
    if (failed++ < 8)
      ADD_FAILURE() << at << ": routed " << o.routed << " (" << o.code << " " << o.reason << "), reference "
                    << (ref ? std::to_string(*ref) : "none");
    return;
  }
  if (!o.routed) return;
  ++t.routed;
  if (cost_of(o) != *ref && failed++ < 8) ADD_FAILURE() << at << ": cost " << cost_of(o) << ", reference " << *ref;
  t.proven += o.shortest;  // (a claim on a length other than the reference's fails just above)
  // the certificate is withheld from a wire a little longer than the distance its route
  // function reports (a spike of one layout unit, K in the scaled plane, at its far end) and
  // from a route function that reports none (the bend-aware ones must report their costs)
  if (seed % 5 == 0 || (bends && seed % 3 == 0)) {
    const std::int64_t k = nr.scale();
    for (const bool spike : {true, false}) {
      if (bends && !spike) continue;
      router::NetRouter m(norm.domain, norm.obstacles, nets, rules, opt);
      m.run([&](std::size_t i, const router::NetPins& pins, const geom::NormalizedObstacles& obs) {
        router::NetAttempt a = plain(i, pins, obs);
        if (!a.routed) return a;
        if (!spike) {
          a.distance.reset();
        } else {
          const Point q = a.wires[0].back(), up{q.x, static_cast<geom::Coord>(q.y + k)};
          a.wires[0].insert(a.wires[0].end(), {up, q});
        }
        return a;
      });
      // (a spike on a pad is trimmed with the wire's stretch there: the wire is then no longer)
      const router::NetOutcome& mo = m.outcomes()[0];
      if (mo.routed && (!spike || cost_of(mo) > *ref)) {
        t.spiked += spike;
        if (mo.shortest && failed++ < 8) ADD_FAILURE() << at << ": claimed " << (spike ? "with a spike" : "without a distance");
      }
    }
  }
  const router::CheckResult r = router::check_routes(norm, check_nets(nets, nr), {in->rules.wire_width, in->rules.spacing});
  for (const auto& pr : r.problems)
    if (failed++ < 8) ADD_FAILURE() << at << ": " << pr.message;
  // the same net with the gaps closed: never shorter, and on a share of the instances longer
  // or not routed (which is what exact_gaps is for)
  opt.exact_gaps = false;
  router::NetRouter closed(norm.domain, norm.obstacles, nets, rules, opt);
  closed.run(plain);
  const router::NetOutcome& c = closed.outcomes()[0];
  if (c.shortest && failed++ < 8) ADD_FAILURE() << at << ": claimed with the gaps closed";
  if (!c.routed) ++t.closed_unrouted;
  else if (cost_of(c) > *ref) ++t.closed_longer;
  else if (cost_of(c) < *ref && failed++ < 8) ADD_FAILURE() << at << ": closed gaps gave " << cost_of(c) << " < " << *ref;
}

void expect_alone(const AloneTotals& t, const char* what) {
  std::printf("%d instances (%s; %d with a pad), %d routed with exact gaps at the reference's length, %d of them proven shortest "
              "(NetOutcome::shortest; withheld from %d spiked wires); with the gaps closed %d longer, %d not routed\n",
              t.compared, what, t.with_pad, t.routed, t.proven, t.spiked, t.closed_longer, t.closed_unrouted);
  EXPECT_EQ(t.failed, 0);
  EXPECT_GE(10 * t.proven, 9 * t.routed);
  EXPECT_GT(t.spiked, 0);
  EXPECT_GT(t.routed, t.compared / 3);
  EXPECT_GT(t.closed_longer + t.closed_unrouted, 0);
}

TEST(ExactGaps, ANetAloneIsShortestInTheClosedGrownSpace) {
  AloneTotals t;
  for (std::uint32_t seed = 1; seed <= static_cast<std::uint32_t>(sanitized_share(3000, 30)); ++seed) judge_alone(910000 + seed, false, t);
  expect_alone(t, "point pins");
}

// The same with pads (since 2026-12-05: the claim of shortest length covers two-pin nets whose
// pins are shapes; a pad gets no access zone, so its wire keeps the clearance up to its end).
TEST(ExactGaps, ANetWithPadsAloneIsShortestInTheClosedGrownSpace) {
  AloneTotals t;
  for (std::uint32_t seed = 1; seed <= static_cast<std::uint32_t>(sanitized_share(2000, 30)); ++seed) judge_alone(920000 + seed, true, t);
  expect_alone(t, "pads and point pins");
}

// The same under the bend-aware metrics (since 2026-12-05 the claim covers them): length + C x
// bends for C in {0, 1, 7, 1000}, and fewest bends then shortest, point pins and pads.
TEST(ExactGaps, ANetAloneHasTheLeastCostInTheClosedGrownSpace) {
  using Cost = router::NetRouterOptions::Cost;
  AloneTotals combined, link;
  for (std::uint32_t seed = 1; seed <= static_cast<std::uint32_t>(sanitized_share(1500, 30)); ++seed) {
    const bool is_link = seed % 5 == 2;
    const RefCost cost{is_link ? Cost::Link : Cost::Combined, std::vector<std::int64_t>{0, 1, 7, 1000}[(seed / 2) % 4]};
    judge_alone(960000 + seed, seed % 2 == 0, is_link ? link : combined, cost);
  }
  expect_alone(combined, "length + C x bends, C in 0, 1, 7, 1000");
  expect_alone(link, "fewest bends, then shortest");
}

// The octilinear length of a routed net's wires.
geom::Root2 oct_length(const router::NetOutcome& o) {
  geom::Root2 l{0, 0};
  for (const auto& w : o.wires)
    for (std::size_t k = 1; k < w.size(); ++k) l += geom::octilinear_length(w[k].x - w[k - 1].x, w[k].y - w[k - 1].y);
  return l;
}

// NetOutcome::shortest against the space at the end (the router's own space, with every other
// net's final wires): a net still claimed shortest is as short as the exact distance between its
// pins there, D, scaled: K R < D + K in L1, K R = D octilinear. A claim made before another net's
// wire left its window, and not withdrawn, can fail this (ExactGaps.ClaimsAreWithdrawnWhenAWayOpens).
// This shares the router's space and wavefronts: it checks the withdrawal's bookkeeping, not the
// geometry of a claim, which the Hanan-grid reference checks for single nets above.
// Returns the claims that fail (each reported); `claims` counts those checked.
// Net i's claim against `space` (the plane scaled by k, every other net's final wires in it): its
// wires `o` (in the layout's units) of length R have K R < D + K in L1, K R = D octilinear, for the
// exact distance D between its pins there.
bool claim_holds(const router::NetSpace& space, std::size_t i, std::int64_t k, bool octilinear, const router::NetOutcome& o) {
  const geom::NormalizedObstacles fin = space.obstacles(i, router::NetSpaceLevel::Full, std::nullopt, {}, false, nullptr);
  const Polygon& p = space.net(i).pins[0];
  const Polygon& q = space.net(i).pins[1];
  if (octilinear) {
    router::OctRouter rt(fin.domain, fin.obstacles);
    rt.set_lattice(k);
    const auto d = rt.shortest(p, q);
    const geom::Root2 oct = oct_length(o);
    return d.length && *d.length == geom::Root2{k * oct.a, k * oct.b};
  }
  router::L1Router rt(fin.domain, fin.obstacles);
  const auto d = rt.shortest(p, q);
  return d.length && k * l1_len(o) < *d.length + k;
}

int broken_claims(const router::NetRouter& nr, bool octilinear, const std::string& at, std::int64_t& claims) {
  int failed = 0;
  for (std::size_t i = 0; i < nr.outcomes().size(); ++i) {
    const router::NetOutcome& o = nr.outcomes()[i];
    if (!o.shortest) continue;
    ++claims;
    const bool ok = claim_holds(nr.space(), i, nr.scale(), octilinear, o);
    if (!ok && failed++ < 8) ADD_FAILURE() << at << ": net " << i << " claimed shortest, but a shorter way is free at the end";
  }
  return failed;
}

// Many nets with rules (random_layout: rectangles that touch and pinch, sloped triangles, pads,
// pins on blockage edges and corners), L1 and octilinear, Steiner trees for a third: every
// routed net passes the checker with exact_gaps. (Layouts with an edge at another angle than a
// multiple of 45 degrees are not scaled: before that rule, 4 of 600 layouts failed here, all
// octilinear, wires snapped into the clearance of a sloped edge.)
TEST(ExactGaps, ManyNetsPassTheChecker) {
  int failed = 0, scaled = 0, snap_far = 0;
  std::int64_t nets = 0, routed = 0, routed_closed = 0, claims = 0, withdrawn = 0;
  for (int seed = 1; seed <= sanitized_share(400, 20); ++seed) {  // 600 until 2026-12-06 (make test's time on CI)
    const RandomLayout L = random_layout(930000 + seed);
    router::NetRouterOptions opt;
    opt.octilinear = seed % 4 == 3;
    const router::NetRouteFn fn =
        opt.octilinear ? router::NetRouter::oct_router(seed % 3 == 0) : router::NetRouter::l1_router(seed % 3 == 0);
    router::NetRouter closed(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    closed.run(fn);
    opt.exact_gaps = true;
    router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    nr.run(fn);
    scaled += nr.scale() > 1;
    if (nr.stats().snap_far > 0) {  // the caller routes again without exact_gaps
      ++snap_far;
      continue;
    }
    const std::string at = "seed " + std::to_string(930000 + seed) + (opt.octilinear ? " octilinear" : "") + " (w " +
                           std::to_string(L.rules.wire_width) + ", s " + std::to_string(L.rules.spacing) + ", scale " +
                           std::to_string(nr.scale()) + ")";
    const router::CheckResult r = router::check_routes(L.norm, check_nets(L.nets, nr), {L.rules.wire_width, L.rules.spacing});
    for (const auto& p : r.problems)
      if (failed++ < 8) ADD_FAILURE() << at << ": " << p.message;
    // every segment in the run's directions (the checker does not look at directions)
    for (std::size_t i = 0; i < L.nets.size(); ++i)
      for (const auto& w : nr.outcomes()[i].wires)
        for (std::size_t k = 1; k < w.size(); ++k) {
          const std::int64_t dx = w[k].x - w[k - 1].x, dy = w[k].y - w[k - 1].y;
          const bool ok = dx == 0 || dy == 0 || (opt.octilinear && (dx == dy || dx == -dy));
          if (!ok && failed++ < 8) ADD_FAILURE() << at << ": net " << i << " has a segment " << dx << "," << dy;
        }
    withdrawn += nr.stats().shortest_withdrawn;
    failed += broken_claims(nr, opt.octilinear, at, claims);
    nets += static_cast<std::int64_t>(L.nets.size());
    for (std::size_t i = 0; i < L.nets.size(); ++i) {
      routed += nr.outcomes()[i].routed;
      routed_closed += closed.outcomes()[i].routed;
      if (!nr.outcomes()[i].routed && nr.outcomes()[i].reason.empty() && failed++ < 8) ADD_FAILURE() << at << ": no reason";
    }
  }
  std::printf("%d layouts scaled (the rest have sloped edges), %d of them with a wire snapped from afar (left out), %lld "
              "nets: %lld routed with exact gaps, %lld with the gaps closed; %lld proven shortest at the end, %lld claims "
              "withdrawn\n",
              scaled, snap_far, static_cast<long long>(nets), static_cast<long long>(routed), static_cast<long long>(routed_closed),
              static_cast<long long>(claims), static_cast<long long>(withdrawn));
  EXPECT_EQ(failed, 0);
  EXPECT_GT(routed, nets / 2);
  EXPECT_GT(scaled, sanitized_share(400, 20) / 3);
  EXPECT_LT(snap_far * 10, scaled);
}

// The withdrawal of NetOutcome::shortest: layouts (found among random_layout's seeds 931 .. 936k,
// 2026-12-04) where a net was claimed shortest and a wire of another net later left its window,
// opening a shorter way: with the withdrawal taken out of NetRouter::run, each of them fails
// broken_claims (8 of 5,400 layouts did). Here every claim left passes, and each layout withdraws
// at least one. (With the window limit they were found with, 2: with 1, the default since
// 2026-12-06, the nets take other ways in two of them and no claim is withdrawn there;
// ManyNetsPassTheChecker checks the claims with the default.) Seed 931616 withdraws none since the
// later changes of 2026-12-06 (a pad partly under a blockage, or partly covered by other nets'
// grown wires, is reached from its clear part with no claim made, where the attempt was refused
// before): the claim it withdrew is no longer made there; the other seven still withdraw.
TEST(ExactGaps, ClaimsAreWithdrawnWhenAWayOpens) {
  std::int64_t claims = 0;
  for (const int seed : {856, 1257, 1273, 1616, 2112, 2118, 3274, 5482}) {
    const RandomLayout L = random_layout(930000 + seed);
    router::NetRouterOptions opt;
    opt.search_windows = 2;
    opt.octilinear = seed % 4 == 3;
    opt.exact_gaps = true;
    router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    nr.run(opt.octilinear ? router::NetRouter::oct_router(seed % 3 == 0) : router::NetRouter::l1_router(seed % 3 == 0));
    const std::string at = "seed " + std::to_string(930000 + seed);
    ASSERT_GT(nr.scale(), 1) << at;
    EXPECT_EQ(broken_claims(nr, opt.octilinear, at, claims), 0);
    if (seed != 1616) {
      EXPECT_GT(nr.stats().shortest_withdrawn, 0) << at;
    }
  }
  EXPECT_GT(claims, 0);
}

// taut route --tighten with exact gaps (since 2026-12-05): the nets routed, then tightened together
// in the layout's units (router::NetsTightener: a wire in a gap of exactly the clearance is kept as
// routed), and NetRouter::withdraw_claims called with the old wires of every net that moved. Each
// claim left is checked against the final space, built here: the plane scaled by K with every
// net's final wires in it; the net's final wire, of length R, has K R < D + K (L1) or K R = D
// (octilinear) for the exact distance D between its pins there. Without the withdrawal (run the
// test with TAUT_TEST_NO_WITHDRAWAL set) it fails: among the 600 layouts, seeds 42, 50, 98, 160,
// 164, 184, 210, 236 and more (a wire tightened away from where it ran opened a shorter way),
// which a sanitizer run, with fewer layouts, takes too.
struct TightenedClaims {
  int failed = 0;
  std::int64_t claims = 0, withdrawn = 0, moved = 0, kept = 0, scaled = 0;
};

// One layout routed with exact gaps, its claims checked at the end of the run (broken_claims),
// then tightened together as taut route --tighten does: with `scaled` in the router's scaled
// plane (router::tighten_scaled, taken when the checker passes it), else, or when that fails, in
// the layout's units (router::NetsTightener); NetRouter::withdraw_claims called for every net
// that moved (unless no_withdrawal), and each claim left checked against the final space built
// here.
void judge_tightened_claims(const RandomLayout& L, bool octilinear, const std::string& at, bool no_withdrawal, TightenedClaims& t,
                            bool scaled = false) {
  router::NetRouterOptions opt;
  opt.octilinear = octilinear;
  opt.exact_gaps = true;
  router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
  nr.run(opt.octilinear ? router::NetRouter::oct_router() : router::NetRouter::l1_router(false));
  const std::int64_t k = nr.scale();
  if (k == 1 || nr.stats().snap_far > 0) return;
  std::int64_t routed_claims = 0;
  if (!no_withdrawal) t.failed += broken_claims(nr, opt.octilinear, at + " (after routing)", routed_claims);
  // tightened together as taut route --tighten does
  std::vector<router::NetLines> wires(L.nets.size());
  for (std::size_t i = 0; i < L.nets.size(); ++i)
    if (nr.outcomes()[i].routed) wires[i] = nr.outcomes()[i].wires;
  router::NetsTightenOptions o;
  o.orientations = opt.octilinear ? router::TightenOrientations::Octilinear : router::TightenOrientations::Rectilinear;
  std::optional<std::vector<router::NetLines>> back;
  router::NetsTightenStats kst;
  if (scaled) back = router::tighten_scaled(L.norm.domain, L.norm.obstacles, L.nets, L.rules, k, wires, {}, o, &kst);
  if (back && router::check_routes(L.norm, check_nets(L.nets, *back), {L.rules.wire_width, L.rules.spacing}).problems.empty()) {
    wires = std::move(*back);
    t.kept += kst.kept;
    ++t.scaled;
  } else {
    router::NetSpace ts(L.norm.domain, L.norm.obstacles, L.nets, L.rules);
    router::NetsTightener nt(ts, o);
    (void)nt.run(wires);
    t.kept += nt.stats().kept;
  }
  for (std::size_t i = 0; i < L.nets.size(); ++i)
    if (nr.outcomes()[i].routed && wires[i] != nr.outcomes()[i].wires) {
      ++t.moved;
      if (!no_withdrawal) t.withdrawn += static_cast<std::int64_t>(nr.withdraw_claims(i, nr.outcomes()[i].wires, wires[i]));
    }
  // the final space, scaled
  router::NetSpace fin(geom::Box{router::scaled(L.norm.domain.lo, k), router::scaled(L.norm.domain.hi, k)},
                       router::scaled(L.norm.obstacles, k), router::scaled(L.nets, k), router::with_scale(L.rules, k));
  for (std::size_t i = 0; i < L.nets.size(); ++i) fin.set_wires(i, router::scaled_wires(wires[i], k));
  for (std::size_t i = 0; i < L.nets.size(); ++i) {
    if (!nr.outcomes()[i].shortest) continue;
    ++t.claims;
    router::NetOutcome now;
    now.wires = wires[i];
    if (!claim_holds(fin, i, k, opt.octilinear, now) && t.failed++ < 8)
      ADD_FAILURE() << at << ": net " << i << " claimed shortest, but a shorter way is free after tightening";
  }
}

// taut route --tighten with exact gaps (since 2026-12-05): judge_tightened_claims on random_layout's
// layouts (pads for a third of them). Without the withdrawal (run the test with
// TAUT_TEST_NO_WITHDRAWAL set) it fails: among the 600 layouts, seeds 42, 50, 98, 160, 164, 184,
// 210, 236 and more (a wire tightened away from where it ran opened a shorter way), which a
// sanitizer run, with fewer layouts, takes too.
TEST(ExactGaps, ClaimsStandAfterTightening) {
  TightenedClaims t;
  std::vector<int> seeds;
  for (int seed = 1; seed <= sanitized_share(600, 20); ++seed) seeds.push_back(seed);
  for (const int b : {42, 50, 98, 160})
    if (b > sanitized_share(600, 20)) seeds.push_back(b);
  const bool no_withdrawal = std::getenv("TAUT_TEST_NO_WITHDRAWAL") != nullptr;
  for (const int seed : seeds) {
    const bool octilinear = seed % 4 == 3;
    judge_tightened_claims(random_layout(940000 + seed), octilinear,
                           "seed " + std::to_string(940000 + seed) + (octilinear ? " octilinear" : "") + (seed % 2 ? "" : " scaled"),
                           no_withdrawal, t, seed % 2 == 0);
  }
  std::printf("%lld claims stand after tightening (%lld withdrawn where %lld moved wires had run; %lld wires kept as "
              "routed; %lld layouts tightened in the scaled plane)\n",
              static_cast<long long>(t.claims), static_cast<long long>(t.withdrawn), static_cast<long long>(t.moved),
              static_cast<long long>(t.kept), static_cast<long long>(t.scaled));
  EXPECT_GT(t.scaled, 0);
  EXPECT_EQ(t.failed, 0);
  EXPECT_GT(t.claims, static_cast<std::int64_t>(seeds.size()));  // (825 over 604 layouts)
  EXPECT_GT(t.withdrawn + no_withdrawal, 0);
  EXPECT_GT(t.moved, 0);
  EXPECT_GT(t.kept, 0);
}

// Layouts of two-pin nets whose pins are mostly large pads (3 to 24 units a side) among boxes 1
// apart, for the claims on pads (since 2026-12-05): the region test of the claims' withdrawal
// (NetRouter::may_open) must measure from the pads' boxes. With it measuring from each pad's
// first vertex instead (a mutation tried on 2026-12-05), seeds 46, 102, 138, 178, 222 of the 300
// fail (a claim broken at the end of the run or after tightening), and 2000 seeds then passed
// with the boxes; without the withdrawal (TAUT_TEST_NO_WITHDRAWAL) seeds 24, 43, 46, 51, 86, ...
// fail. A sanitizer run, with fewer layouts, takes four of them too.
RandomLayout pad_layout(int seed) {
  std::mt19937 rng(static_cast<unsigned>(seed));
  RandomLayout L;
  const geom::Box domain{{0, 0}, {120, 120}};
  const std::vector<geom::Box> boxes = random_boxes_apart(rng, static_cast<int>(rng() % 7), 4, 100, 22);
  L.norm = geom::normalize_obstacles(box_polygons(boxes), domain);
  L.rules.wire_width = static_cast<std::int64_t>(rng() % 4);
  L.rules.spacing = static_cast<std::int64_t>(rng() % 3);
  router::L1Router plain(L.norm.domain, L.norm.obstacles);
  std::vector<geom::Box> used;
  auto apart = [&](const geom::Box& b) {
    return std::none_of(used.begin(), used.end(), [&](const geom::Box& u) {
      return b.lo.x <= u.hi.x + 1 && u.lo.x <= b.hi.x + 1 && b.lo.y <= u.hi.y + 1 && u.lo.y <= b.hi.y + 1;
    });
  };
  auto pin = [&]() -> std::optional<Polygon> {
    for (int tries = 0; tries < 200; ++tries) {
      const Point p{static_cast<geom::Coord>(rng() % 121), static_cast<geom::Coord>(rng() % 121)};
      if (rng() % 4 == 0) {
        const geom::Box b{p, p};
        if (plain.is_free(p) && apart(b)) {
          used.push_back(b);
          return Polygon{{p}, {}};
        }
        continue;
      }
      const geom::Coord w = static_cast<geom::Coord>(3 + rng() % 22), h = static_cast<geom::Coord>(3 + rng() % 22);
      const geom::Box b{p, {static_cast<geom::Coord>(p.x + w), static_cast<geom::Coord>(p.y + h)}};
      if (b.hi.x > 120 || b.hi.y > 120 || !apart(b)) continue;
      const Polygon g = box_polygons(std::vector<geom::Box>{b})[0];
      if (plain.pin_meets_obstacle(g)) continue;
      used.push_back(b);
      return g;
    }
    return std::nullopt;
  };
  const int n = 3 + static_cast<int>(rng() % 6);
  for (int i = 0; i < n; ++i) {
    router::NetPins net;
    net.name = "n" + std::to_string(i);
    for (int j = 0; j < 2; ++j)
      if (const auto g = pin()) net.pins.push_back(*g);
    if (net.pins.size() == 2) L.nets.push_back(std::move(net));
  }
  return L;
}

TEST(ExactGaps, ClaimsOnPadsStand) {
  TightenedClaims t;
  const bool no_withdrawal = std::getenv("TAUT_TEST_NO_WITHDRAWAL") != nullptr;
  const int n = std::getenv("TAUT_PAD_SEEDS") ? std::atoi(std::getenv("TAUT_PAD_SEEDS")) : sanitized_share(300, 20);
  std::vector<int> seeds;
  for (int seed = 1; seed <= n; ++seed) seeds.push_back(seed);
  for (const int b : {46, 102, 138, 222})
    if (b > n) seeds.push_back(b);
  for (const int seed : seeds)
    judge_tightened_claims(pad_layout(950000 + seed), false, "pad layout seed " + std::to_string(950000 + seed), no_withdrawal, t,
                           seed % 2 == 0);
  std::printf("%lld claims stand (%lld withdrawn after tightening where %lld moved wires had run)\n",
              static_cast<long long>(t.claims), static_cast<long long>(t.withdrawn), static_cast<long long>(t.moved));
  EXPECT_EQ(t.failed, 0);
  EXPECT_GT(t.claims, 0);
}

// The bend-aware metrics (bend_router: its bend cost is weighed by the scale) with exact_gaps:
// every routed net passes the checker.
// Net i's claim (NetOutcome::shortest) under a bend-aware cost against the space at the end (the
// router's own, every other net's final wires in it, scaled by k): its wires `o` of length R and
// b' bends against the optimal path there (router::BendRouter), of scaled length L and b bends:
// K R + K C b' < L + K C b + K (Combined), b' = b and K R < L + K (Link). As claim_holds, this
// checks the withdrawal's bookkeeping; the Hanan-grid reference checks single nets.
bool bend_claim_holds(const router::NetSpace& space, std::size_t i, std::int64_t k, const router::NetRouterOptions& opt,
                      const router::NetOutcome& o) {
  const geom::NormalizedObstacles fin = space.obstacles(i, router::NetSpaceLevel::Full, std::nullopt, {}, false, nullptr);
  const router::BendRouter br(fin.domain, fin.obstacles);
  const bool link = opt.cost == router::NetRouterOptions::Cost::Link;
  const router::BendPath p = br.path(space.net(i).pins[0], space.net(i).pins[1],
                                     link ? router::BendMetric::Link : router::BendMetric::Combined, opt.bend_cost * k);
  if (p.status != router::WireStatus::Ok) return false;
  std::int64_t bends = 0;
  for (const auto& w : o.wires) bends += geom::count_bends(w);
  const __int128 kr = __int128{k} * l1_len(o), kc = __int128{k} * opt.bend_cost;
  return link ? bends == p.bends && kr < p.length + k : kr + kc * bends < p.length + kc * p.bends + k;
}

// Many nets under the bend-aware metrics with exact gaps: every routed net passes the checker,
// and every claim of least cost left at the end (since 2026-12-05) passes bend_claim_holds.
// (bend_run marks layouts with sloped blockages as covered: no claims there.)
void judge_bend_claims(const std::function<RandomLayout(int)>& layout, int n, int base, std::vector<int> also = {}) {
  int failed = 0;
  std::int64_t nets = 0, routed = 0, claims = 0, withdrawn = 0;
  std::vector<int> seeds;
  for (int seed = 1; seed <= n; ++seed) seeds.push_back(seed);
  for (const int b : also)
    if (b > n) seeds.push_back(b);
  for (const int seed : seeds) {
    const RandomLayout L = layout(base + seed);
    BendRun b = bend_run(L, seed);
    b.options.exact_gaps = true;
    router::NetRouter nr(b.covered.domain, b.covered.obstacles, L.nets, b.rules, b.options);
    nr.run(b.route);
    const std::string at = "seed " + std::to_string(base + seed) + " " + b.label;
    if (nr.stats().snap_far > 0 && failed++ < 8) ADD_FAILURE() << at << ": a wire snapped from afar";
    const router::CheckResult r = router::check_routes(L.norm, check_nets(L.nets, nr), {L.rules.wire_width, L.rules.spacing});
    for (const auto& p : r.problems)
      if (failed++ < 8) ADD_FAILURE() << at << ": " << p.message;
    nets += static_cast<std::int64_t>(L.nets.size());
    for (const auto& o : nr.outcomes()) routed += o.routed;
    withdrawn += nr.stats().shortest_withdrawn;
    for (std::size_t i = 0; i < L.nets.size(); ++i) {
      if (!nr.outcomes()[i].shortest) continue;
      ++claims;
      if (b.options.blockages_covered && failed++ < 8) ADD_FAILURE() << at << ": net " << i << " claimed among covers";
      if (!bend_claim_holds(nr.space(), i, nr.scale(), b.options, nr.outcomes()[i]) && failed++ < 8)
        ADD_FAILURE() << at << ": net " << i << " claimed, but a cheaper way is free at the end";
    }
  }
  std::printf("%lld nets: %lld routed; %lld claims of least cost left, %lld withdrawn\n", static_cast<long long>(nets),
              static_cast<long long>(routed), static_cast<long long>(claims), static_cast<long long>(withdrawn));
  EXPECT_EQ(failed, 0);
  EXPECT_GT(routed, nets / 2);
  EXPECT_GT(claims, 0);
}

TEST(ExactGaps, BendMetricsPassTheChecker) {
  const int n = std::getenv("TAUT_BEND_SEEDS") ? std::atoi(std::getenv("TAUT_BEND_SEEDS")) : sanitized_share(300, 15);
  judge_bend_claims(random_layout, n, 950000, {101});
}

// The same on pad_layout's layouts (large pads). The withdrawal's region must be measured by the
// cost, not the length: with may_open given the claimed wire's length under Combined, and the
// region test under Link (where a wire of fewer bends is better however long), seeds 66 and 554
// (C 7), 1015 (Link) and 2391 (C 1000) of 3,000 fail (a mutation tried on 2026-12-05); 3,000 pass
// with the cost. Without the withdrawal in NetRouter::run, random_layout's seeds 101, 1228, 1937
// and 2106 fail BendMetricsPassTheChecker.
TEST(ExactGaps, BendClaimsOnPadsStand) {
  const int n = std::getenv("TAUT_BEND_SEEDS") ? std::atoi(std::getenv("TAUT_BEND_SEEDS")) : sanitized_share(300, 15);
  judge_bend_claims(pad_layout, n, 970000, {66, 554, 1015, 2391});
}

// The claims and the windows' proof read the options' cost, so run() refuses bend_router with
// another metric or bend cost (since 2026-12-05), with the scale and without.
TEST(ExactGaps, BendRouterMustMatchTheOptionsCost) {
  const RandomLayout L = random_layout(950001);
  BendRun b = bend_run(L, 1);  // Combined, C 1
  for (const bool exact : {true, false}) {
    b.options.exact_gaps = exact;
    {
      router::NetRouter nr(b.covered.domain, b.covered.obstacles, L.nets, b.rules, b.options);
      EXPECT_NO_THROW(nr.run(b.route));
    }
    router::NetRouter other_cost(b.covered.domain, b.covered.obstacles, L.nets, b.rules, b.options);
    EXPECT_THROW(other_cost.run(router::NetRouter::bend_router(router::BendMetric::Combined, 7)), std::invalid_argument);
    router::NetRouter other_metric(b.covered.domain, b.covered.obstacles, L.nets, b.rules, b.options);
    EXPECT_THROW(other_metric.run(router::NetRouter::bend_router(router::BendMetric::Link, 1)), std::invalid_argument);
  }
}

// Under Combined, the bend cost is weighed like the scaled lengths: a net alone with rules that
// grow nothing (w = s = 0: a = 0, so the scaled space is exactly K times the plain one) gets
// the same length + C x bends with exact_gaps as without, for C from 1 to 1000 (were C not
// multiplied by K, a scaled length would outweigh every bend and the costs would differ).
TEST(ExactGaps, BendCostIsWeighedLikeTheLengths) {
  int failed = 0, compared = 0, bent = 0;
  for (int seed = 1; seed <= sanitized_share(400, 20); ++seed) {
    RandomLayout L = random_layout(970000 + seed);
    L.nets.resize(1);
    L.nets[0].pins.resize(2);
    for (Polygon& g : L.nets[0].pins) g = Polygon{{g.outer[0]}, {}};
    const geom::NormalizedObstacles covered = geom::normalize_obstacles(router::rectilinear_cover(L.norm.obstacles), L.norm.domain);
    const std::int64_t c = std::vector<std::int64_t>{1, 7, 50, 1000}[static_cast<std::size_t>(seed) % 4];
    std::vector<std::optional<std::int64_t>> costs;
    for (const bool exact : {false, true}) {
      router::NetRouterOptions opt;
      opt.cost = router::NetRouterOptions::Cost::Combined;
      opt.bend_cost = c;
      opt.exact_gaps = exact;
      router::NetRules rules{0, 0};
      rules.cover_pieces = router::kDefaultCoverPieces;
      router::NetRouter nr(covered.domain, covered.obstacles, L.nets, rules, opt);
      nr.run(router::NetRouter::bend_router(router::BendMetric::Combined, c));
      const router::NetOutcome& o = nr.outcomes()[0];
      if (!o.routed) {
        costs.push_back(std::nullopt);
        continue;
      }
      std::int64_t bends = 0;
      for (const auto& w : o.wires)
        for (std::size_t i = 1; i + 1 < w.size(); ++i) {
          const std::int64_t ux = w[i].x - w[i - 1].x, uy = w[i].y - w[i - 1].y, vx = w[i + 1].x - w[i].x, vy = w[i + 1].y - w[i].y;
          bends += ux * vy - uy * vx != 0;
        }
      costs.push_back(l1_len(o) + c * bends);
      bent += exact && bends > 1;
    }
    ++compared;
    if (costs[0] != costs[1] && failed++ < 8)
      ADD_FAILURE() << "seed " << 970000 + seed << ", C " << c << ": cost " << (costs[0] ? std::to_string(*costs[0]) : "none")
                    << " with the gaps closed, " << (costs[1] ? std::to_string(*costs[1]) : "none") << " with exact gaps";
  }
  std::printf("%d nets compared, %d with more than one bend\n", compared, bent);
  EXPECT_EQ(failed, 0);
  EXPECT_GT(bent, 0);
}

// A gap of exactly 2a between two blockages: closed without exact_gaps (ROUTE-0010), open with
// it (the straight wire at exactly a from both), and the checker passes it.
TEST(ExactGaps, AGapOfExactlyTwiceTheClearanceTakesAWire) {
  const geom::Box domain{{0, 0}, {100, 100}};
  const std::vector<Polygon> walls{{{{0, 40}, {47, 40}, {47, 60}, {0, 60}}, {}}, {{{53, 40}, {100, 40}, {100, 60}, {53, 60}}, {}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(walls, domain);
  const std::vector<router::NetPins> nets{{"x", {Polygon{{{50, 10}}, {}}, Polygon{{{50, 90}}, {}}}}};
  const router::NetRules rules{2, 2};  // a = 3: the gap of 6 is exactly 2a
  {
    router::NetRouter nr(norm.domain, norm.obstacles, nets, rules);
    nr.run(router::NetRouter::l1_router(false));
    EXPECT_FALSE(nr.outcomes()[0].routed);
    EXPECT_EQ(nr.outcomes()[0].code, "ROUTE-0010");
  }
  for (const bool oct : {false, true}) {
    router::NetRouterOptions opt;
    opt.exact_gaps = true;
    opt.octilinear = oct;
    router::NetRouter nr(norm.domain, norm.obstacles, nets, rules, opt);
    EXPECT_GE(nr.scale(), 8);
    nr.run(oct ? router::NetRouter::oct_router(false) : router::NetRouter::l1_router(false));
    ASSERT_TRUE(nr.outcomes()[0].routed) << nr.outcomes()[0].reason;
    EXPECT_EQ(nr.outcomes()[0].wires, (std::vector<std::vector<Point>>{{{50, 10}, {50, 90}}}));
    EXPECT_TRUE(router::check_routes(norm, check_nets(nets, nr), {2, 2}).problems.empty());
  }
  {
    // a gap of 5 stays closed: the grown blockages overlap
    const std::vector<Polygon> narrow{{{{0, 40}, {47, 40}, {47, 60}, {0, 60}}, {}}, {{{52, 40}, {100, 40}, {100, 60}, {52, 60}}, {}}};
    const geom::NormalizedObstacles nn = geom::normalize_obstacles(narrow, domain);
    router::NetRouterOptions opt;
    opt.exact_gaps = true;
    router::NetRouter nr(nn.domain, nn.obstacles, nets, rules, opt);
    nr.run(router::NetRouter::l1_router(false));
    EXPECT_FALSE(nr.outcomes()[0].routed);
    EXPECT_EQ(nr.outcomes()[0].code, "ROUTE-0010");
    EXPECT_NE(nr.outcomes()[0].reason.find("narrower than 6 DBU"), std::string::npos) << nr.outcomes()[0].reason;
  }
}

// Three wires at exactly the pitch w + s in a band (net_router_test's gap of width zero between
// grown wires): with exact_gaps the middle one routes straight.
TEST(ExactGaps, TracksAtExactlyThePitchTakeWires) {
  const geom::Box domain{{0, 0}, {100, 100}};
  const std::vector<Polygon> walls{{{{0, 0}, {100, 0}, {100, 47}, {0, 47}}, {}}, {{{0, 53}, {100, 53}, {100, 100}, {0, 100}}, {}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(walls, domain);
  std::vector<router::NetPins> nets(3);
  nets[0] = {"a", {Polygon{{{20, 49}}, {}}, Polygon{{{80, 49}}, {}}}};
  nets[1] = {"c", {Polygon{{{30, 51}}, {}}, Polygon{{{70, 51}}, {}}}};
  nets[2] = {"b", {Polygon{{{5, 50}}, {}}, Polygon{{{95, 50}}, {}}}};
  router::NetRouterOptions opt;
  opt.exact_gaps = true;
  router::NetRouter nr(norm.domain, norm.obstacles, nets, {0, 1}, opt);
  nr.run(router::NetRouter::l1_router(false));
  for (std::size_t i = 0; i < 3; ++i) ASSERT_TRUE(nr.outcomes()[i].routed) << nets[i].name << ": " << nr.outcomes()[i].reason;
  EXPECT_EQ(nr.outcomes()[2].wires, (std::vector<std::vector<Point>>{{{5, 50}, {95, 50}}}));
  EXPECT_TRUE(router::check_routes(norm, check_nets(nets, nr), {0, 1}).problems.empty());
}

// Octilinear Steiner trees in the scaled plane (a review's case: a pin joined a diagonal at
// (1.5, 1.5) x K, and before BasicRouter::set_lattice 16 of these 404 trees had a vertex that far
// from a multiple of the scale, so snapping turned a diagonal off its direction): every tree,
// with point pins and with diamond pads (45-degree edges), snaps from near, keeps its directions,
// passes the checker and is at least the exact minimum among trees with integer vertices
// (tests/oracle's Dreyfus-Wagner), not far above it; rectilinear trees on the same pins too.
TEST(ExactGaps, OctilinearSteinerTreesSnapFromNear) {
  const geom::Box domain{{0, 0}, {40, 40}};
  std::vector<std::vector<Polygon>> cases, blocks;  // a case's pins, and its blockages
  for (const std::vector<Point>& pins : std::vector<std::vector<Point>>{{{0, 0}, {2, 2}, {3, 0}},
                                                                      {{10, 10}, {20, 20}, {25, 10}},
                                                                      {{5, 5}, {15, 15}, {17, 6}, {9, 30}},
                                                                      {{0, 3}, {3, 0}, {1, 1}}}) {
    cases.emplace_back();
    for (const Point p : pins) cases.back().push_back(Polygon{{p}, {}});
    blocks.emplace_back();
  }
  std::mt19937 rng(990001);
  auto coord = [&](int lo, int hi) { return std::uniform_int_distribution<geom::Coord>(lo, hi)(rng); };
  for (int n = 0; n < sanitized_share(400, 20); ++n) {  // and random nets of 3-6 pins, a third with pads
    // half of them among 1-4 rectangles (which may touch); a pin keeps 4 clear of them
    blocks.emplace_back();
    std::vector<geom::Box> boxes;
    for (int k = n % 2 ? std::uniform_int_distribution<int>(1, 4)(rng) : 0; k > 0; --k) {
      const geom::Coord x = coord(0, 34), y = coord(0, 34);
      boxes.push_back({{x, y}, {static_cast<geom::Coord>(x + coord(2, 6)), static_cast<geom::Coord>(y + coord(2, 6))}});
      const geom::Box& b = boxes.back();
      blocks.back().push_back(Polygon{{b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}, {}});
    }
    auto clear_of_blocks = [&](Point p) {
      return std::all_of(boxes.begin(), boxes.end(), [&](const geom::Box& b) {
        return p.x < b.lo.x - 4 || p.x > b.hi.x + 4 || p.y < b.lo.y - 4 || p.y > b.hi.y + 4;
      });
    };
    std::vector<Point> pins;
    const int m = std::uniform_int_distribution<int>(3, 6)(rng);
    for (int tries = 0; static_cast<int>(pins.size()) < m && tries < 1000; ++tries) {
      const Point p{coord(0, 40), coord(0, 40)};
      if (std::find(pins.begin(), pins.end(), p) == pins.end() && clear_of_blocks(p)) pins.push_back(p);
    }
    if (pins.size() < 3) {  // no room: a net without blockages
      blocks.back().clear();
      while (pins.size() < 3) {
        const Point p{coord(0, 40), coord(0, 40)};
        if (std::find(pins.begin(), pins.end(), p) == pins.end()) pins.push_back(p);
      }
    }
    cases.emplace_back();
    for (const Point p : pins) {
      // a diamond of radius r around p when it stays in the domain and clear of the other pins
      const geom::Coord r = n % 3 == 0 ? coord(1, 3) : 0;
      bool clear = r > 0 && p.x - r >= 0 && p.y - r >= 0 && p.x + r <= 40 && p.y + r <= 40;
      for (const Point q : pins)
        if (q != p && std::abs(q.x - p.x) + std::abs(q.y - p.y) <= 2 * r + 1) clear = false;
      cases.back().push_back(clear ? Polygon{{{p.x - r, p.y}, {p.x, p.y - r}, {p.x + r, p.y}, {p.x, p.y + r}}, {}}
                                   : Polygon{{p}, {}});
    }
  }
  int failed = 0, pads = 0, minimal = 0, blocked = 0, unreachable = 0;
  double excess_sum = 0, excess_worst = 0, closed_sum = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const std::string at = "case " + std::to_string(c);
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(blocks[c], domain);
    const std::vector<Polygon>& obs = norm.obstacles;
    const std::optional<geom::Root2> best = oracle::oct_steiner_minimal_length(domain, obs, std::span<const Polygon>(cases[c]));
    if (!best) {  // walled apart by the rectangles
      ++unreachable;
      continue;
    }
    blocked += !obs.empty();
    std::vector<router::NetPins> nets(1);
    nets[0].name = "t";
    nets[0].pins = cases[c];
    pads += std::any_of(cases[c].begin(), cases[c].end(), [](const Polygon& p) { return p.outer.size() > 1; });
    router::NetRouterOptions opt;
    opt.exact_gaps = true;
    {
      // rectilinear Steiner trees meet only on horizontal and vertical lines through pins and
      // corners: never far
      router::NetRouter l1(domain, obs, nets, {0, 0}, opt);
      l1.run(router::NetRouter::l1_router(true));
      ASSERT_TRUE(l1.outcomes()[0].routed) << at;
      if (l1.stats().snap_far > 0 && failed++ < 8) ADD_FAILURE() << at << ": a rectilinear tree snapped from afar";
    }
    opt.octilinear = true;
    router::NetRouter nr(domain, obs, nets, {0, 0}, opt);
    ASSERT_GT(nr.scale(), 1) << at;
    nr.run(router::NetRouter::oct_router(true));
    ASSERT_TRUE(nr.outcomes()[0].routed) << at;
    if (nr.stats().snap_far > 0 && failed++ < 8) ADD_FAILURE() << at << ": an octilinear tree snapped from afar";
    for (const auto& w : nr.outcomes()[0].wires)
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::int64_t dx = w[k].x - w[k - 1].x, dy = w[k].y - w[k - 1].y;
        if (!(dx == 0 || dy == 0 || dx == dy || dx == -dy) && failed++ < 8) ADD_FAILURE() << at << ": a segment " << dx << "," << dy;
      }
    for (const auto& p : router::check_routes(norm, check_nets(nets, nr), {0, 0}).problems)
      if (failed++ < 8) ADD_FAILURE() << at << ": " << p.message;
    const geom::Root2 len = oct_length(nr.outcomes()[0]);
    if (len < *best && failed++ < 8) ADD_FAILURE() << at << ": " << len << " is below the minimum " << *best;
    const double excess = best->to_double() > 0 ? len.to_double() / best->to_double() - 1 : 0;
    excess_sum += excess;
    excess_worst = std::max(excess_worst, excess);
    minimal += len == *best;
    // the same tree in the plane of integers (no scale), for the record
    router::NetRouterOptions plain = opt;
    plain.exact_gaps = false;
    router::NetRouter closed(domain, obs, nets, {0, 0}, plain);
    closed.run(router::NetRouter::oct_router(true));
    ASSERT_TRUE(closed.outcomes()[0].routed) << at;
    closed_sum += best->to_double() > 0 ? oct_length(closed.outcomes()[0]).to_double() / best->to_double() - 1 : 0;
  }
  const double trees = static_cast<double>(cases.size() - static_cast<std::size_t>(unreachable));
  std::printf("%zu octilinear trees (%d with pads, %d among blockages; %d more walled apart) in the scaled plane: %d "
              "minimal, mean excess %.3f %%, worst %.2f %% (without the scale: mean %.3f %%)\n",
              cases.size() - static_cast<std::size_t>(unreachable), pads, blocked, unreachable, minimal,
              100 * excess_sum / trees, 100 * excess_worst, 100 * closed_sum / trees);
  EXPECT_EQ(failed, 0);
  EXPECT_GT(pads, 0);
  EXPECT_GT(blocked, 0);
  EXPECT_LT(excess_sum / trees, 0.02);  // issue #7's Steiner targets: mean under 2 %, worst under 10 %
  EXPECT_LT(excess_worst, 0.10);
}

// The scale: a power of two of at least 8 whose plane stays within 2^29; a domain too large
// for 8, or an edge at another angle than a multiple of 45 degrees, gets none (1), and the
// router is then the one without exact_gaps.
TEST(ExactGaps, TheScaleKeepsThePlaneWithinTheLimit) {
  const std::vector<Polygon> none;
  const std::vector<router::NetPins> nets{{"n", {Polygon{{{0, 0}}, {}}, Polygon{{{10, 10}}, {}}}}};
  router::NetRouterOptions opt;
  opt.exact_gaps = true;
  {
    // an edge at 45 degrees keeps the scale, a sloped one (1:2) or a sloped pad edge does not
    const geom::Box domain{{0, 0}, {100, 100}};
    const std::vector<Polygon> diagonal{{{{40, 40}, {60, 40}, {60, 60}}, {}}}, sloped{{{{40, 40}, {60, 40}, {60, 50}}, {}}};
    EXPECT_EQ(router::NetRouter(domain, diagonal, nets, {2, 2}, opt).scale(), 8192);
    EXPECT_EQ(router::NetRouter(domain, sloped, nets, {2, 2}, opt).scale(), 1);
    std::vector<router::NetPins> pad = nets;
    pad[0].pins[1] = Polygon{{{10, 10}, {14, 10}, {14, 12}}, {}};
    EXPECT_EQ(router::NetRouter(domain, none, pad, {2, 2}, opt).scale(), 1);
    // under Combined the bend cost times the scale stays within the bend router's 2^31
    router::NetRouterOptions bends = opt;
    bends.cost = router::NetRouterOptions::Cost::Combined;
    router::NetRules covered{2, 2};
    covered.cover_pieces = router::kDefaultCoverPieces;
    for (const auto& [c, k] : std::vector<std::pair<std::int64_t, std::int64_t>>{
             {1000, 8192}, {300000, 4096}, {std::int64_t{1} << 28, 8}, {(std::int64_t{1} << 28) + 1, 1}, {(std::int64_t{1} << 30) - 1, 1}}) {
      bends.bend_cost = c;
      router::NetRouter nr(domain, none, nets, covered, bends);
      EXPECT_EQ(nr.scale(), k) << c;
      nr.run(router::NetRouter::bend_router(router::BendMetric::Combined, c));  // does not throw
      EXPECT_TRUE(nr.outcomes()[0].routed) << c;
    }
  }
  for (const geom::Coord reach : {100, 50000, 1 << 20, 1 << 25, 1 << 29}) {
    const geom::Box domain{{0, 0}, {reach, reach}};
    router::NetRouter nr(domain, none, nets, {200, 200}, opt);
    const std::int64_t k = nr.scale();
    EXPECT_TRUE(k == 1 || (k >= 8 && k <= 8192 && (k & (k - 1)) == 0)) << reach << ": " << k;
    if (k > 1) {
      EXPECT_LE(k * (reach + 300 + 400), std::int64_t{1} << 29) << reach;
    }
    if (reach == 100) {
      EXPECT_EQ(k, 8192);
    }
    if (reach == (1 << 29)) {
      EXPECT_EQ(k, 1);
    }
    nr.run(router::NetRouter::l1_router(false));
    ASSERT_TRUE(nr.outcomes()[0].routed) << reach;
    EXPECT_EQ(l1_len(nr.outcomes()[0]), 20);
  }
}

}  // namespace exact_gaps_test
}  // namespace taut::test
