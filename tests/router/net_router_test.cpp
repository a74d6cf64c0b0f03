// router::NetRouter (many nets with width and spacing, rip-up; issue #7) judged by the independent
// checker (router/check.h, which shares only geom with it): on thousands of random layouts
// (rectangles that touch and pinch, sloped triangles, pins on blockage edges and corners) every
// net it routes is in free space, joins its pins, and keeps w/2 + s from blockages and w + s
// from every other net, for w and s drawn with odd widths and zero rules included. A net alone
// with w = s = 0 gets the exact L1 shortest length (the L1 reference). And geom::convex_minus_box,
// its pin-access cut, against a lattice brute force in doubled coordinates.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <random>
#include <set>

#include "bench/planted_nets.h"
#include "geom/normalize.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "io/movingai.h"
#include "geom/predicates.h"
#include "geom/validate.h"
#include "oracle/l1_oracle.h"
#include "router/bend_router.h"
#include "router/check.h"
#include "router/l1_router.h"
#include "router/net_router.h"
#include "router/oct_router.h"
#include "support/net_layouts.h"
#include "support/pin_cells.h"
#include "support/wavefront_hand.h"
#include "support/random_shapes.h"
#include "support/run.h"
#include "support/sanitized.h"

namespace taut::test {
namespace net_router_test {

using geom::Point;
using geom::Polygon;

// closed convex counter-clockwise ring contains p (doubled coordinates: p2 = 2p)
bool in_convex2(const geom::Ring& c, std::int64_t x2, std::int64_t y2) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Point a = c[i], b = c[(i + 1) % c.size()];
    const std::int64_t o = (2 * std::int64_t{b.x} - 2 * a.x) * (y2 - 2 * std::int64_t{a.y}) -
                           (2 * std::int64_t{b.y} - 2 * a.y) * (x2 - 2 * std::int64_t{a.x});
    if (o < 0) return false;
  }
  return true;
}

// the open convex counter-clockwise ring contains p (doubled coordinates, as in_convex2)
bool strictly_in_convex2(const geom::Ring& c, std::int64_t x2, std::int64_t y2) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Point u = c[i], v = c[(i + 1) % c.size()];
    if ((2 * std::int64_t{v.x} - 2 * u.x) * (y2 - 2 * std::int64_t{u.y}) -
            (2 * std::int64_t{v.y} - 2 * u.y) * (x2 - 2 * std::int64_t{u.x}) <=
        0)
      return false;
  }
  return true;
}

// p (doubled coordinates) lies within L-infinity 1 of the closed convex ring
bool near_convex2(const geom::Ring& c, std::int64_t x2, std::int64_t y2) {
  for (int dx = -2; dx <= 2; ++dx)
    for (int dy = -2; dy <= 2; ++dy)
      if (in_convex2(c, x2 + dx, y2 + dy)) return true;
  return false;
}

TEST(ConvexMinusBox, CoversTheDifferenceAndStaysOutOfTheBox) {
  int failed = 0, cut = 0;
  for (int seed = 1; seed <= sanitized_share(3000, 5); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(4100 + seed));
    auto coord = [&](int lo, int hi) { return static_cast<geom::Coord>(lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1))); };
    const Point a{coord(0, 20), coord(0, 20)}, b{coord(0, 20), coord(0, 20)};
    const geom::Ring c = geom::square_grown_segment(a, b, coord(1, 4));
    const Point s0{coord(-2, 22), coord(-2, 22)};
    const geom::Box s{s0, {static_cast<geom::Coord>(s0.x + coord(1, 9)), static_cast<geom::Coord>(s0.y + coord(1, 9))}};
    const std::vector<geom::Ring> parts = geom::convex_minus_box(c, s);
    cut += parts.size() != 1 || parts[0] != c;
    const std::string at = "seed " + std::to_string(seed);
    for (const auto& p : parts)
      if (geom::orient(p[0], p[1], p[2]) <= 0 && failed++ < 5) ADD_FAILURE() << at << ": a part is not counter-clockwise";
    for (std::int64_t x2 = -12; x2 <= 60; ++x2)
      for (std::int64_t y2 = -12; y2 <= 60; ++y2) {
        const bool in_box_open = x2 > 2 * s.lo.x && x2 < 2 * s.hi.x && y2 > 2 * s.lo.y && y2 < 2 * s.hi.y;
        bool covered = false;
        for (const auto& p : parts) covered = covered || in_convex2(p, x2, y2);
        // a part's interior point in the open box: a half-lattice point strictly inside both
        bool enters = false;
        for (const auto& p : parts) enters = enters || (strictly_in_convex2(p, x2, y2) && in_box_open);
        // points on the box's boundary may be left out (a part of zero area there is dropped:
        // it has no interior, so it blocks nothing)
        const bool in_box_closed = x2 >= 2 * s.lo.x && x2 <= 2 * s.hi.x && y2 >= 2 * s.lo.y && y2 <= 2 * s.hi.y;
        if (in_convex2(c, x2, y2) && !in_box_closed && !covered && failed++ < 5)
          ADD_FAILURE() << at << ": (" << x2 << "/2, " << y2 << "/2) of the polygon outside the box is not covered";
        if (enters && failed++ < 5) ADD_FAILURE() << at << ": a part enters the open box at (" << x2 << "/2, " << y2 << "/2)";
        // no more than 1 beyond c: a covered point within L-infinity 1 of c
        if (covered && !in_convex2(c, x2, y2) && !near_convex2(c, x2, y2) && failed++ < 5)
          ADD_FAILURE() << at << ": a part reaches more than 1 beyond the polygon";
      }
  }
  EXPECT_EQ(failed, 0);
  EXPECT_GT(cut, 100);
}

// geom::convex_minus_pad, as convex_minus_box above, for pads that are not rectangles (diamonds,
// octagons, boxes with one corner cut, at random places against grown segments of any slope):
// every half-lattice point of the polygon outside the closed pad is covered, no part's interior
// enters the open pad, and no part reaches more than 1 beyond the polygon. And
// geom::octilinear_convex_ring: repeated and straight-on vertices allowed, other shapes refused.
TEST(ConvexMinusPad, CoversTheDifferenceAndStaysOutOfThePad) {
  using geom::Ring;
  EXPECT_EQ(geom::octilinear_convex_ring(Ring{{0, 0}, {0, 0}, {2, 0}, {4, 0}, {4, 2}, {2, 4}, {0, 4}}),
            (Ring{{0, 0}, {4, 0}, {4, 2}, {2, 4}, {0, 4}}));
  EXPECT_EQ(geom::octilinear_convex_ring(Ring{{0, 2}, {2, 4}, {4, 2}, {2, 0}}), (Ring{{2, 0}, {4, 2}, {2, 4}, {0, 2}}));
  EXPECT_FALSE(geom::octilinear_convex_ring(Ring{{0, 0}, {4, 0}, {4, 1}, {0, 3}}));            // a sloped edge
  EXPECT_FALSE(geom::octilinear_convex_ring(Ring{{0, 0}, {4, 0}, {4, 4}, {2, 2}, {0, 4}}));    // not convex
  EXPECT_FALSE(geom::octilinear_convex_ring(Ring{{0, 0}, {4, 0}, {6, 0}, {4, 0}, {4, 4}}));    // a spike
  int failed = 0, cut = 0;
  for (int seed = 1; seed <= sanitized_share(3000, 5); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(9100 + seed));
    auto coord = [&](int lo, int hi) { return static_cast<geom::Coord>(lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1))); };
    const Point a{coord(0, 20), coord(0, 20)}, b{coord(0, 20), coord(0, 20)};
    const Ring c = geom::square_grown_segment(a, b, coord(1, 4));
    const int x0 = coord(-2, 18), y0 = coord(-2, 18), k = coord(1, 4), e = coord(1, k), kind = coord(0, 2);
    const int x1 = x0 + 2 * k, y1 = y0 + 2 * k;
    Ring pad = kind == 0   ? Ring{{x0, y0 + k}, {x0 + k, y0}, {x1, y0 + k}, {x0 + k, y1}}
               : kind == 1 ? Ring{{x0 + e, y0}, {x1 - e, y0}, {x1, y0 + e}, {x1, y1 - e}, {x1 - e, y1}, {x0 + e, y1}, {x0, y1 - e}, {x0, y0 + e}}
                           : Ring{{x0, y0}, {x1, y0}, {x1, y1 - e}, {x1 - e, y1}, {x0, y1}};
    const auto ring = geom::octilinear_convex_ring(pad);
    ASSERT_TRUE(ring) << "seed " << seed;
    pad = *ring;
    const std::vector<Ring> parts = geom::convex_minus_pad(c, pad);
    cut += parts.size() != 1 || parts[0] != c;
    const std::string at = "seed " + std::to_string(seed);
    for (const auto& p : parts)
      if (geom::orient(p[0], p[1], p[2]) <= 0 && failed++ < 5) ADD_FAILURE() << at << ": a part is not counter-clockwise";
    for (std::int64_t x2 = -12; x2 <= 60; ++x2)
      for (std::int64_t y2 = -12; y2 <= 60; ++y2) {
        bool covered = false, enters = false;
        for (const auto& p : parts) {
          covered = covered || in_convex2(p, x2, y2);
          enters = enters || (strictly_in_convex2(p, x2, y2) && strictly_in_convex2(pad, x2, y2));
        }
        if (in_convex2(c, x2, y2) && !in_convex2(pad, x2, y2) && !covered && failed++ < 5)
          ADD_FAILURE() << at << ": (" << x2 << "/2, " << y2 << "/2) of the polygon outside the pad is not covered";
        if (enters && failed++ < 5) ADD_FAILURE() << at << ": a part enters the open pad at (" << x2 << "/2, " << y2 << "/2)";
        if (covered && !in_convex2(c, x2, y2) && !near_convex2(c, x2, y2) && failed++ < 5)
          ADD_FAILURE() << at << ": a part reaches more than 1 beyond the polygon";
      }
  }
  EXPECT_EQ(failed, 0);
  EXPECT_GT(cut, sanitized_share(300, 5));
}

// The layouts of the window and thread tests: 60-120 rectangles apart on 2,000 x 2,000.
struct BoxLayout {
  std::vector<geom::Box> boxes;
  geom::NormalizedObstacles norm;
};
BoxLayout box_layout(std::mt19937& rng) {
  BoxLayout L;
  L.boxes = random_boxes_apart(rng, 60 + static_cast<int>(rng() % 60), 10, 1900, 120);
  L.norm = geom::normalize_obstacles(box_polygons(L.boxes), geom::Box{{0, 0}, {2000, 2000}});
  return L;
}

// A free point of a box_layout drawn within r of c (along each axis, clamped to the layout), in
// at most `tries` draws.
std::optional<Point> free_near(std::mt19937& rng, const router::L1Router& plain, Point c, int r, int tries) {
  for (int t = 0; t < tries; ++t) {
    const Point p{static_cast<geom::Coord>(std::clamp<int>(c.x - r + static_cast<int>(rng() % static_cast<unsigned>(2 * r + 1)), 0, 2000)),
                  static_cast<geom::Coord>(std::clamp<int>(c.y - r + static_cast<int>(rng() % static_cast<unsigned>(2 * r + 1)), 0, 2000))};
    if (plain.is_free(p)) return p;
  }
  return std::nullopt;
}


// NetAttempt::sink_distances: a tree is proven in its window sink by sink (each sink's distance
// below the least, over the window's inner sides, of the first pin's and the sink's distances
// from that side, less 4), which the radius alone (below the first pin's distance from every
// inner side) does not prove. Walls on a coarse grid (shared coordinates, walls crossing and
// touching) make detours; every tree proven in its window, with or without the sink-by-sink
// proof, has the whole domain's distance at every sink, in L1 and octilinear, and the sink-by-
// sink proof is needed for some (fewer windows).
TEST(NetRouter, TreesProvenSinkBySinkHaveTheWholeLayoutsDistances) {
  int failed = 0, trees = 0, fewer = 0;
  for (int seed = 1; seed <= sanitized_share(200, 4); ++seed) {  // 25 under the sanitizers: 44 trees, 13 fewer
    std::mt19937 rng(static_cast<unsigned>(770000 + seed));
    const geom::Box domain{{0, 0}, {2000, 2000}};
    std::vector<Polygon> walls;
    for (int k = 0, n = 15 + static_cast<int>(rng() % 20); k < n; ++k) {
      const geom::Coord x = static_cast<geom::Coord>(50 * (rng() % 40)), y = static_cast<geom::Coord>(50 * (rng() % 40));
      const geom::Coord len = static_cast<geom::Coord>(50 * (4 + rng() % 20)), t = static_cast<geom::Coord>(10 * (1 + rng() % 3));
      const geom::Coord w = rng() % 2 ? len : t, h = w == len ? t : len;
      walls.push_back(Polygon{{{x, y}, {std::min<geom::Coord>(x + w, 2000), y}, {std::min<geom::Coord>(x + w, 2000), std::min<geom::Coord>(y + h, 2000)},
                                {x, std::min<geom::Coord>(y + h, 2000)}}, {}});
    }
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(walls, domain);
    const router::L1Router plain(norm.domain, norm.obstacles);
    const Point c{static_cast<geom::Coord>(rng() % 2001), static_cast<geom::Coord>(rng() % 2001)};
    std::vector<router::NetPins> tree{{"t", {}}};
    for (int j = 0, pins = 3 + static_cast<int>(rng() % 4); j < pins; ++j)
      if (const auto p = free_near(rng, plain, c, 250, 1000)) tree[0].pins.push_back(Polygon{{*p}, {}});
    if (tree[0].pins.size() < 3) continue;
    const router::NetRules rules{static_cast<std::int64_t>(rng() % 3), static_cast<std::int64_t>(rng() % 3)};
    for (const bool oct : {false, true}) {
      std::vector<geom::Root2> got;
      const auto fn = [&](bool sinks) {
        return [&, sinks](std::size_t, const router::NetPins& net, const geom::NormalizedObstacles& obs) {
          router::NetAttempt at;
          auto take = [&](const auto& t) {
            got.clear();
            at.routed = t.status == router::WireStatus::Ok;
            at.code = at.routed ? "" : t.status == router::WireStatus::Unreachable ? "ROUTE-0002" : "ROUTE-0001";
            if (!at.routed) return;
            at.wires = t.wires;
            at.radius = router::tree_radius(t);
            got = *router::tree_sink_distances(t);
            if (sinks) at.sink_distances = got;
          };
          if (oct) take(router::OctRouter(obs.domain, obs.obstacles).tree(net.pins[0], std::span<const Polygon>(net.pins).subspan(1)));
          else take(router::L1Router(obs.domain, obs.obstacles).tree(net.pins[0], std::span<const Polygon>(net.pins).subspan(1)));
          return at;
        };
      };
      router::NetRouterOptions o;
      o.octilinear = oct;
      router::NetRouterOptions whole_o = o;
      whole_o.windows = false;
      router::NetRouter all(norm.domain, norm.obstacles, tree, rules, whole_o);
      all.run(fn(false));
      const std::vector<geom::Root2> whole = got;
      std::int64_t windows[2] = {0, 0};
      for (const bool sinks : {false, true}) {
        router::NetRouter tw(norm.domain, norm.obstacles, tree, rules, o);
        tw.run(fn(sinks));
        windows[sinks] = tw.stats().windows;
        if ((tw.outcomes()[0].routed != all.outcomes()[0].routed || got != whole) && failed++ < 5)
          ADD_FAILURE() << "seed " << 770000 + seed << (oct ? " octilinear" : " L1") << (sinks ? ", sink by sink" : "")
                        << ": the tree's distances differ from the whole domain's";
      }
      trees += all.outcomes()[0].routed;
      fewer += windows[1] < windows[0];
      if (windows[1] > windows[0] && failed++ < 5) ADD_FAILURE() << "seed " << 770000 + seed << ": more windows sink by sink";
    }
  }
  std::printf("%d trees compared, %d proven in fewer windows sink by sink\n", trees, fewer);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(trees, sanitized_share(260, 8));
  EXPECT_GE(fewer, sanitized_share(12, 6));
}

// router::uncovered_segments (what a net's changed wires freed; the claims' withdrawal) against a
// brute force on the lattice: a segment pq of length > 0 runs through the lattice points
// p + k (q - p) / g (g the gcd of its coordinate differences), and since every segment of `after`
// ends on lattice points, a collinear one that covers part of a piece between two consecutive
// ones covers the whole piece; so pq is covered exactly when each piece has one segment of
// `after` through both its ends (a point on a segment: the cross product zero, inside its box).
// `after` is `before` rewritten (wires cut at vertices or inside segments at lattice points,
// reversed, joined, segments split) with some changes (a vertex moved, a segment dropped, a
// segment or point added), in any direction.
TEST(UncoveredSegments, MatchALatticeBruteForce) {
  using Lines = std::vector<std::vector<Point>>;
  auto on = [](Point x, Point a, Point b) {
    const std::int64_t cr = (std::int64_t{b.x} - a.x) * (std::int64_t{x.y} - a.y) - (std::int64_t{b.y} - a.y) * (std::int64_t{x.x} - a.x);
    return cr == 0 && std::min(a.x, b.x) <= x.x && x.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= x.y && x.y <= std::max(a.y, b.y);
  };
  auto segments = [](const Lines& ls) {
    std::vector<std::pair<Point, Point>> out;
    for (const auto& l : ls) {
      if (l.size() == 1) out.push_back({l[0], l[0]});
      for (std::size_t i = 0; i + 1 < l.size(); ++i) out.push_back({l[i], l[i + 1]});
    }
    return out;
  };
  int failed = 0;
  long long covered = 0, uncovered = 0, whole_same = 0;
  for (int seed = 1; seed <= sanitized_share(4000, 10); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(960000 + seed));
    auto c = [&] { return static_cast<geom::Coord>(rng() % 9); };
    Lines before;
    for (int w = 0, k = 1 + static_cast<int>(rng() % 3); w < k; ++w) {
      std::vector<Point> l{{c(), c()}};
      for (int v = 0, n = static_cast<int>(rng() % 4); v < n; ++v) {
        const int kind = static_cast<int>(rng() % 3);  // axis-parallel, diagonal, any
        Point p = l.back();
        if (kind == 0) (rng() % 2 ? p.x : p.y) = c();
        else if (kind == 1) {
          const int d = static_cast<int>(rng() % 5) - 2;
          p = {static_cast<geom::Coord>(p.x + d), static_cast<geom::Coord>(p.y + (rng() % 2 ? d : -d))};
        } else p = {c(), c()};
        if (p != l.back()) l.push_back(p);
      }
      before.push_back(l);
    }
    // after: before's segments rewritten, then changed
    std::vector<std::pair<Point, Point>> pieces;
    for (const auto& [a, b] : segments(before)) {
      // split at a lattice point inside, sometimes
      const int g = std::gcd(std::abs(b.x - a.x), std::abs(b.y - a.y));
      if (g > 1 && rng() % 2) {
        const int k = 1 + static_cast<int>(rng() % (g - 1));
        const Point m{static_cast<geom::Coord>(a.x + (b.x - a.x) / g * k), static_cast<geom::Coord>(a.y + (b.y - a.y) / g * k)};
        pieces.push_back({a, m});
        pieces.push_back({m, b});
      } else {
        pieces.push_back({a, b});
      }
    }
    const int change = static_cast<int>(rng() % 4);  // 0: none; 1: drop one; 2: move an end; 3: add one
    if (change == 1 && !pieces.empty()) pieces.erase(pieces.begin() + static_cast<long>(rng() % pieces.size()));
    if (change == 2 && !pieces.empty()) {
      auto& [a, b] = pieces[rng() % pieces.size()];
      (rng() % 2 ? a : b) = {c(), c()};
    }
    if (change == 3) pieces.push_back({{c(), c()}, {c(), c()}});
    std::shuffle(pieces.begin(), pieces.end(), rng);
    Lines after;
    for (auto [a, b] : pieces) {
      if (rng() % 2) std::swap(a, b);
      if (!after.empty() && after.back().back() == a && rng() % 2) after.back().push_back(b);  // joined
      else if (a == b) after.push_back({a});
      else after.push_back({a, b});
    }
    // the brute force
    const auto after_segs = segments(after);
    auto held = [&](Point u, Point v) {
      return std::any_of(after_segs.begin(), after_segs.end(), [&](const auto& s) { return on(u, s.first, s.second) && on(v, s.first, s.second); });
    };
    std::vector<std::pair<Point, Point>> want;
    for (const auto& [p, q] : segments(before)) {
      const int g = std::gcd(std::abs(q.x - p.x), std::abs(q.y - p.y));
      bool ok = true;
      if (g == 0) ok = held(p, p);
      for (int k = 0; k < g && ok; ++k) {
        const Point u{static_cast<geom::Coord>(p.x + (q.x - p.x) / g * k), static_cast<geom::Coord>(p.y + (q.y - p.y) / g * k)};
        const Point v{static_cast<geom::Coord>(p.x + (q.x - p.x) / g * (k + 1)), static_cast<geom::Coord>(p.y + (q.y - p.y) / g * (k + 1))};
        ok = held(u, v);
      }
      if (!ok) want.push_back({p, q});
      (ok ? covered : uncovered) += 1;
    }
    const auto got = router::uncovered_segments(before, after);
    whole_same += change == 0 && got.empty();
    if (got != want && failed++ < 8) {
      std::string text;
      for (const auto& l : before) {
        text += "  before:";
        for (const Point p : l) text += " " + std::to_string(p.x) + "," + std::to_string(p.y);
        text += "\n";
      }
      for (const auto& l : after) {
        text += "  after:";
        for (const Point p : l) text += " " + std::to_string(p.x) + "," + std::to_string(p.y);
        text += "\n";
      }
      ADD_FAILURE() << "seed " << 960000 + seed << ": " << got.size() << " uncovered, the brute force " << want.size() << "\n" << text;
    }
  }
  std::printf("%lld segments covered, %lld not; %lld rewritten wires freed nothing\n", covered, uncovered, whole_same);
  EXPECT_EQ(failed, 0);
  EXPECT_GT(uncovered, sanitized_share(1000, 10));
  EXPECT_GT(covered, sanitized_share(4000, 10));
  EXPECT_GT(whole_same, sanitized_share(800, 10));
}


TEST(NetRouter, EveryRoutedNetPassesTheChecker) {
  int failed = 0, layouts = 0;
  std::int64_t nets = 0, routed = 0, ripped = 0, first = 0, pads = 0, octilinear = 0, undone = 0, around = 0, last = 0,
               final_gain = 0;
  std::map<std::string, int> reasons;
  for (int seed = 1; seed <= sanitized_share(2000, 24); ++seed) {
    const RandomLayout L = random_layout(700000 + seed);
    // every fifth layout octilinear; a third of them all with Steiner trees
    router::NetRouterOptions opt;
    opt.octilinear = seed % 5 == 4;
    octilinear += opt.octilinear;
    router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    nr.run(opt.octilinear ? router::NetRouter::oct_router(seed % 3 == 0) : router::NetRouter::l1_router(seed % 3 == 0));
    for (std::size_t i = 0; i < L.nets.size(); ++i)
      for (const Polygon& g : L.nets[i].pins) pads += g.outer.size() > 1 && nr.outcomes()[i].routed;
    ++layouts;
    const std::string at = "seed " + std::to_string(700000 + seed) + " (w " + std::to_string(L.rules.wire_width) + ", s " +
                           std::to_string(L.rules.spacing) + ")";
    router::CheckRules rules;
    rules.wire_width = L.rules.wire_width;
    rules.spacing = L.rules.spacing;
    const router::CheckResult r = router::check_routes(L.norm, check_nets(L.nets, nr), rules);
    for (const auto& p : r.problems)
      if (failed++ < 8) ADD_FAILURE() << at << ": " << p.message;
    nets += static_cast<std::int64_t>(L.nets.size());
    first += static_cast<std::int64_t>(nr.stats().first_pass);
    ripped += nr.stats().rips;
    undone += nr.stats().undone;
    around += nr.stats().around_fixed;
    last += static_cast<std::int64_t>(nr.stats().last_pass_routed);
    final_gain += static_cast<std::int64_t>(nr.stats().final_round_routed);
    for (const auto& o : nr.outcomes()) {
      routed += o.routed;
      if (!o.routed) {
        ++reasons[o.code];
        if (o.reason.empty() && failed++ < 8) ADD_FAILURE() << at << ": a net not routed has no reason";
      }
    }
  }
  std::printf("%d layouts (%lld octilinear), %lld nets: %lld routed (%lld by the first pass, %lld by the final round, %lld by "
              "the last pass, %lld pads reached), %lld rip-ups (%lld undone, %lld planned round nets at the rip limit); "
              "unrouted by code:",
              layouts, static_cast<long long>(octilinear), static_cast<long long>(nets), static_cast<long long>(routed),
              static_cast<long long>(first), static_cast<long long>(final_gain), static_cast<long long>(last),
              static_cast<long long>(pads),
              static_cast<long long>(ripped), static_cast<long long>(undone), static_cast<long long>(around));
  for (const auto& [code, n] : reasons) std::printf(" %s %d", code.c_str(), n);
  std::printf("\n");
  EXPECT_EQ(failed, 0);
  EXPECT_GT(routed, nets / 2);
  EXPECT_GT(routed, first);  // rip-up routes nets the first pass did not
  // the checker has seen states after undone rip-ups, after ways round nets at the rip limit and
  // after the final round's rip-ups (all 2,000 layouts: 643, 58 and 2 nets gained; the sanitizer
  // tree's sample need not hold them)
  if (!kSanitized) {
    EXPECT_GT(undone, 0);
    EXPECT_GT(around, 0);
    EXPECT_GT(final_gain, 0);
  }
  EXPECT_GT(pads, sanitized_share(100, 4));
}

// One net alone with no rules: the exact L1 shortest length of the reference (the other nets'
// and the clearance's growth does not apply, so the net space is the blockages' own).
TEST(NetRouter, ANetAloneWithoutRulesIsShortest) {
  int failed = 0, compared = 0;
  for (int seed = 1; seed <= sanitized_share(600, 6); ++seed) {
    RandomLayout L = random_layout(800000 + seed);
    L.nets.resize(1);
    L.nets[0].pins.resize(2);
    for (Polygon& g : L.nets[0].pins) g = Polygon{{g.outer[0]}, {}};  // point pins (a pad's first corner)
    L.rules = {};
    router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules);
    nr.run(router::NetRouter::l1_router(false));
    const oracle::L1Reference ref(L.norm.domain, L.norm.obstacles);
    const Point p = L.nets[0].pins[0].outer[0], q = L.nets[0].pins[1].outer[0];
    const auto d = ref.distance(p, q);
    // the plain router decides whether an integer staircase exists (sloped blockages can pinch
    // every one: router/staircase.h); the net router must agree with it
    router::L1Router plain(L.norm.domain, L.norm.obstacles);
    const bool staircase = plain.shortest(p, q).status == router::WireStatus::Ok;
    const router::NetOutcome& o = nr.outcomes()[0];
    if (o.routed != (d.has_value() && staircase) && failed++ < 5) {
      ADD_FAILURE() << "seed " << 800000 + seed << ": routed " << o.routed << ", reference " << d.has_value() << " "
                    << o.code << " " << o.reason;
      continue;
    }
    if (!o.routed) continue;
    const std::int64_t len = l1_len(o);
    ++compared;
    if (len != *d && failed++ < 5) ADD_FAILURE() << "seed " << 800000 + seed << ": length " << len << ", reference " << *d;
  }
  EXPECT_EQ(failed, 0);
  EXPECT_GT(compared, sanitized_share(300, 6));
}

// Windows: on layouts much larger than the nets (many small rectangles, pins on their edges),
// a two-pin net alone gets the same length in its window as on the whole domain (the window is
// kept only when no way out of it can be shorter), with rules; and many nets routed in windows
// pass the checker.
TEST(NetRouter, WindowsGiveTheWholeLayoutsLengths) {
  int failed = 0, compared = 0, widened = 0, trees = 0, tree_windows = 0;
  for (int seed = 1; seed <= sanitized_share(60, 8); ++seed) {  // 3 there: a Steiner tree too
    std::mt19937 rng(static_cast<unsigned>(900000 + seed));
    const auto [boxes, norm] = box_layout(rng);
    router::L1Router plain(norm.domain, norm.obstacles);
    auto free_point = [&](Point c, int r) {
      for (int t = 0; t < 1000; ++t) {
        Point p{static_cast<geom::Coord>(std::clamp<int>(c.x - r + static_cast<int>(rng() % static_cast<unsigned>(2 * r + 1)), 0, 2000)),
                static_cast<geom::Coord>(std::clamp<int>(c.y - r + static_cast<int>(rng() % static_cast<unsigned>(2 * r + 1)), 0, 2000))};
        if (rng() % 4 == 0 && !boxes.empty()) {  // on a rectangle's edge
          const geom::Box& b = boxes[rng() % boxes.size()];
          p = {b.lo.x, static_cast<geom::Coord>(b.lo.y + static_cast<int>(rng() % static_cast<unsigned>(b.hi.y - b.lo.y + 1)))};
        }
        if (plain.is_free(p)) return p;
      }
      return c;
    };
    const router::NetRules rules{static_cast<std::int64_t>(rng() % 5), static_cast<std::int64_t>(rng() % 4)};
    // one net alone: windowed and whole
    const Point c{static_cast<geom::Coord>(rng() % 2001), static_cast<geom::Coord>(rng() % 2001)};
    std::vector<router::NetPins> one{{"n", {Polygon{{free_point(c, 10)}, {}}, Polygon{{free_point(c, 300)}, {}}}}};
    router::NetRouter win(norm.domain, norm.obstacles, one, rules);
    win.run(router::NetRouter::l1_router(false));
    router::NetRouterOptions whole_opt;
    whole_opt.windows = false;
    router::NetRouter whole(norm.domain, norm.obstacles, one, rules, whole_opt);
    whole.run(router::NetRouter::l1_router(false));
    widened += win.stats().windows > win.stats().attempts;
    const auto& a = win.outcomes()[0];
    const auto& b = whole.outcomes()[0];
    const auto len = l1_len;
    if (a.routed != b.routed || (a.routed && len(a) != len(b))) {
      if (failed++ < 5)
        ADD_FAILURE() << "seed " << 900000 + seed << ": window " << a.routed << " " << len(a) << ", whole " << b.routed << " " << len(b);
      continue;
    }
    compared += a.routed;
    // one net of 3-6 pins alone, a shortest-path tree from its first pin, proven in its window
    // by its radius (NetAttempt::radius): every pin's distance from the first is the whole
    // domain's (measured by the route function on the space it was given, last call kept)
    {
      std::vector<router::NetPins> tree{{"t", {}}};
      for (int j = 0, pins = 3 + static_cast<int>(rng() % 4); j < pins; ++j)
        if (const auto p = free_near(rng, plain, c, 100, 1000)) tree[0].pins.push_back(Polygon{{*p}, {}});
      std::vector<std::optional<std::int64_t>> got;
      const auto fn = [&](std::size_t, const router::NetPins& net, const geom::NormalizedObstacles& obs) {
        router::L1Router r(obs.domain, obs.obstacles);
        const auto t = r.tree(net.pins[0], std::span<const Polygon>(net.pins).subspan(1));
        got = t.distance;
        router::NetAttempt at;
        at.routed = t.status == router::WireStatus::Ok;
        at.wires = t.wires;
        at.code = at.routed ? "" : t.status == router::WireStatus::Unreachable ? "ROUTE-0002" : "ROUTE-0001";
        if (at.routed) {
          std::int64_t rad = 0;
          for (const auto& d : t.distance) rad = std::max(rad, *d);
          at.radius = geom::Root2{rad, 0};
        }
        return at;
      };
      router::NetRouter tw(norm.domain, norm.obstacles, tree, rules);
      tw.run(fn);
      const auto windowed = got;
      router::NetRouter tall(norm.domain, norm.obstacles, tree, rules, whole_opt);
      tall.run(fn);
      const bool differ = tw.outcomes()[0].routed != tall.outcomes()[0].routed || (tall.outcomes()[0].routed && windowed != got);
      if (differ && failed++ < 5) ADD_FAILURE() << "seed " << 900000 + seed << ": a tree's distances differ in its window";
      trees += tw.outcomes()[0].routed;
      tree_windows += tw.stats().whole == 0 && tw.outcomes()[0].routed;
    }
    // many local nets in windows: legal
    std::vector<router::NetPins> many;
    for (int k = 0; k < 12; ++k) {
      const Point cc{static_cast<geom::Coord>(rng() % 2001), static_cast<geom::Coord>(rng() % 2001)};
      router::NetPins np;
      np.name = "m" + std::to_string(k);
      for (int j = 0, pins = 2 + static_cast<int>(rng() % 3); j < pins; ++j) np.pins.push_back(Polygon{{free_point(cc, 150)}, {}});
      many.push_back(std::move(np));
    }
    router::NetRouter nr(norm.domain, norm.obstacles, many, rules);
    nr.run(router::NetRouter::l1_router(seed % 2 == 0));
    for (const auto& p : router::check_routes(norm, check_nets(many, nr), {rules.wire_width, rules.spacing}).problems)
      if (failed++ < 5) ADD_FAILURE() << "seed " << 900000 + seed << ": " << p.message;
  }
  std::printf("%d nets alone compared, %d needed a wider window; %d trees compared, %d of them decided in a window\n",
              compared, widened, trees, tree_windows);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(compared, sanitized_share(40, 8));
  EXPECT_GE(trees, sanitized_share(40, 8));
  EXPECT_GE(tree_windows * 4, trees * 3);  // most decided in a window, not on the whole domain
  // a wall between two close pins: the way round is far longer than the first window allows, so
  // the window widens until it is proven (or whole), with the whole domain's length
  const geom::Box domain{{0, 0}, {4000, 4000}};
  const std::vector<Polygon> wall{{{{200, 1995}, {3800, 1995}, {3800, 2005}, {200, 2005}}, {}}};
  const geom::NormalizedObstacles wn = geom::normalize_obstacles(wall, domain);
  const std::vector<router::NetPins> net{{"w", {Polygon{{{2000, 1990}}, {}}, Polygon{{{2000, 2010}}, {}}}}};
  router::NetRouter win(wn.domain, wn.obstacles, net, {2, 1});
  win.run(router::NetRouter::l1_router(false));
  router::NetRouterOptions whole_opt;
  whole_opt.windows = false;
  router::NetRouter whole(wn.domain, wn.obstacles, net, {2, 1}, whole_opt);
  whole.run(router::NetRouter::l1_router(false));
  ASSERT_TRUE(win.outcomes()[0].routed && whole.outcomes()[0].routed);
  EXPECT_GT(win.stats().windows, win.stats().attempts);
  const auto len = l1_len;
  EXPECT_EQ(len(win.outcomes()[0]), len(whole.outcomes()[0]));
  EXPECT_EQ(len(whole.outcomes()[0]), 20 + 2 * (2000 - 200 + 2));  // round the wall's end, a = 2 clear of it
  // a pin shut in a ring of blockage, far from the domain's sides: unrouted in its first window
  // (the pin's component in the window reaches no side), as on the whole domain
  const std::vector<Polygon> ring{{{{1900, 1900}, {2100, 1900}, {2100, 2100}, {1900, 2100}}, {{{1950, 1950}, {1950, 2050}, {2050, 2050}, {2050, 1950}}}}};
  const geom::NormalizedObstacles rn = geom::normalize_obstacles(ring, domain);
  const std::vector<router::NetPins> shut{{"s", {Polygon{{{2000, 2000}}, {}}, Polygon{{{2300, 2000}}, {}}}}};
  router::NetRouter rw(rn.domain, rn.obstacles, shut, {2, 1});
  rw.run(router::NetRouter::l1_router(false));
  router::NetRouter rwhole(rn.domain, rn.obstacles, shut, {2, 1}, whole_opt);
  rwhole.run(router::NetRouter::l1_router(false));
  EXPECT_FALSE(rw.outcomes()[0].routed);
  EXPECT_FALSE(rwhole.outcomes()[0].routed);
  EXPECT_EQ(rw.outcomes()[0].code, "ROUTE-0002");
  EXPECT_EQ(rw.stats().whole, 0);
  // the same ring with a gap in its wall: the pin gets out, in a window
  std::vector<Polygon> parts;
  for (const geom::Box b : {geom::Box{{1900, 1900}, {2100, 1950}}, geom::Box{{1900, 2050}, {2100, 2100}}, geom::Box{{1900, 1950}, {1950, 2050}},
                            geom::Box{{2050, 1950}, {2100, 1990}}, geom::Box{{2050, 2010}, {2100, 2050}}})
    parts.push_back(box_polygons(std::vector<geom::Box>{b})[0]);
  const geom::NormalizedObstacles gn = geom::normalize_obstacles(parts, domain);
  router::NetRouter gw(gn.domain, gn.obstacles, shut, {2, 1});
  gw.run(router::NetRouter::l1_router(false));
  EXPECT_TRUE(gw.outcomes()[0].routed);
  EXPECT_EQ(gw.stats().whole, 0);
}

// The bend-aware metrics routed together (NetRouterOptions::cost, NetRouter::bend_router): on the
// random layouts of EveryRoutedNetPassesTheChecker, their blockages replaced by the rectilinear
// cover (sloped triangles for a quarter of the seeds), with C in {0, 1, 7, 1000} and the link
// metric, every routed net passes the checker against the real blockages with the rules.
TEST(NetRouter, BendMetricsPassTheChecker) {
  int failed = 0, layouts = 0;
  std::int64_t nets = 0, routed = 0, ripped = 0;
  for (int seed = 1; seed <= sanitized_share(600, 16); ++seed) {
    RandomLayout L = random_layout(760000 + seed);
    const BendRun b = bend_run(L, seed);
    router::NetRouter nr(b.covered.domain, b.covered.obstacles, L.nets, b.rules, b.options);
    nr.run(b.route);
    ++layouts;
    const router::CheckResult r = router::check_routes(L.norm, check_nets(L.nets, nr), {L.rules.wire_width, L.rules.spacing});
    for (const auto& p : r.problems)
      if (failed++ < 8) ADD_FAILURE() << "seed " << 760000 + seed << " " << b.label << ": " << p.message;
    nets += static_cast<std::int64_t>(L.nets.size());
    ripped += nr.stats().rips;
    for (const auto& o : nr.outcomes()) {
      routed += o.routed;
      if (!o.routed && o.reason.empty() && failed++ < 8) ADD_FAILURE() << "seed " << 760000 + seed << ": a net not routed has no reason";
    }
  }
  std::printf("%d layouts, %lld nets: %lld routed, %lld rip-ups\n", layouts, static_cast<long long>(nets), static_cast<long long>(routed),
              static_cast<long long>(ripped));
  EXPECT_EQ(failed, 0);
  EXPECT_GT(routed, nets / 2);
  EXPECT_GT(ripped, 0);
}

// Windows under the bend-aware metrics: on layouts much larger than the nets, one net alone (two
// point pins, or 3-6 pins as a tree from the first) gets in its window the same cost for every
// sink as on the whole domain (the window is kept only when no way out of it can cost less),
// with rules; C in {0, 1, 7, 1000} and the link metric.
TEST(NetRouter, BendMetricsInWindowsGiveTheWholeLayoutsCosts) {
  int failed = 0, compared = 0, in_window = 0, widened = 0;
  for (int seed = 1; seed <= sanitized_share(150, 5); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(910000 + seed));
    const auto [boxes, norm] = box_layout(rng);
    router::L1Router plain(norm.domain, norm.obstacles);
    const router::NetRules rules{static_cast<std::int64_t>(rng() % 5), static_cast<std::int64_t>(rng() % 4), router::kDefaultCoverPieces};
    const bool link = seed % 5 == 0;
    const std::int64_t c = std::vector<std::int64_t>{0, 1, 7, 1000}[static_cast<std::size_t>(seed) % 4];
    const router::BendMetric metric = link ? router::BendMetric::Link : router::BendMetric::Combined;
    const Point cc{static_cast<geom::Coord>(rng() % 2001), static_cast<geom::Coord>(rng() % 2001)};
    std::vector<router::NetPins> one{{"n", {}}};
    for (int j = 0, pins = seed % 2 ? 2 : 3 + static_cast<int>(rng() % 4); j < pins; ++j)
      if (const auto p = free_near(rng, plain, cc, j == 0 ? 10 : 300, 1000)) one[0].pins.push_back(Polygon{{*p}, {}});
    if (one[0].pins.size() < 2) continue;
    // the costs of the last call (the window kept, or the whole domain)
    std::vector<std::pair<std::int64_t, std::int64_t>> got;
    const router::NetRouteFn inner = router::NetRouter::bend_router(metric, c);
    const auto fn = [&](std::size_t i, const router::NetPins& net, const geom::NormalizedObstacles& obs) {
      router::NetAttempt a = inner(i, net, obs);
      got = a.sink_costs;
      return a;
    };
    router::NetRouterOptions opt;
    opt.cost = link ? router::NetRouterOptions::Cost::Link : router::NetRouterOptions::Cost::Combined;
    opt.bend_cost = c;
    router::NetRouter win(norm.domain, norm.obstacles, one, rules, opt);
    win.run(fn);
    const auto windowed = got;
    router::NetRouterOptions whole_opt = opt;
    whole_opt.windows = false;
    router::NetRouter whole(norm.domain, norm.obstacles, one, rules, whole_opt);
    whole.run(fn);
    const bool a = win.outcomes()[0].routed, b = whole.outcomes()[0].routed;
    auto cost = [&](const std::pair<std::int64_t, std::int64_t>& lb) {
      return link ? std::pair{lb.second, lb.first} : std::pair{lb.first + c * lb.second, std::int64_t{0}};
    };
    bool same = a == b;
    if (same && a) {
      same = windowed.size() == got.size();
      for (std::size_t k = 0; same && k < got.size(); ++k) same = cost(windowed[k]) == cost(got[k]);
    }
    if (!same) {
      if (failed++ < 5)
        ADD_FAILURE() << "seed " << 910000 + seed << (link ? " link" : " C " + std::to_string(c)) << ": window " << a << ", whole " << b
                      << ": a sink's cost differs";
      continue;
    }
    compared += a;
    in_window += a && win.stats().whole == 0;
    widened += win.stats().windows > win.stats().attempts;
  }
  std::printf("%d nets compared, %d decided in a window (%d of them after widening it)\n", compared, in_window, widened);
  EXPECT_EQ(failed, 0);
  EXPECT_GT(compared, sanitized_share(100, 5));
  EXPECT_GT(in_window, compared / 2);
  // Two pins either side of a long wall with a Z-shaped tunnel by them: through the tunnel, 152
  // long with 4 bends; round the wall's end, 1,700 long with 2. With C = 7 the tunnel is best and
  // proven in the first window; with C = 1000 (4,152 against 3,700) and with the link metric the
  // way round is, which leaves every window: the window must not be kept.
  const geom::Box domain{{0, 0}, {2000, 2000}};
  std::vector<geom::Box> wall{{{1040, 200}, {1060, 980}},  {{1040, 1020}, {1060, 1800}}, {{1040, 980}, {1048, 1013}},
                              {{1040, 1017}, {1060, 1020}}, {{1052, 987}, {1060, 1017}},  {{1040, 980}, {1060, 983}}};
  const geom::NormalizedObstacles wn = geom::normalize_obstacles(box_polygons(wall), domain);
  const std::vector<router::NetPins> net{{"z", {Polygon{{{1000, 1000}}, {}}, Polygon{{{1100, 1000}}, {}}}}};
  struct Case {
    bool link;
    std::int64_t c, length, bends;
    bool whole;
  };
  for (const Case k : {Case{false, 7, 152, 4, false}, Case{false, 1000, 1700, 2, true}, Case{true, 0, 1700, 2, true}}) {
    router::NetRouterOptions opt;
    opt.cost = k.link ? router::NetRouterOptions::Cost::Link : router::NetRouterOptions::Cost::Combined;
    opt.bend_cost = k.c;
    router::NetRouter nr(wn.domain, wn.obstacles, net, {0, 0, router::kDefaultCoverPieces}, opt);
    nr.run(router::NetRouter::bend_router(k.link ? router::BendMetric::Link : router::BendMetric::Combined, k.c));
    const router::NetOutcome& o = nr.outcomes()[0];
    ASSERT_TRUE(o.routed) << o.reason;
    std::int64_t bends = 0;
    for (const auto& w : o.wires) bends += geom::count_bends(w);
    EXPECT_EQ(l1_len(o), k.length) << (k.link ? "link" : "C " + std::to_string(k.c));
    EXPECT_EQ(bends, k.bends) << (k.link ? "link" : "C " + std::to_string(k.c));
    EXPECT_EQ(nr.stats().whole > 0, k.whole) << (k.link ? "link" : "C " + std::to_string(k.c));
  }
}

// A shape pin with sloped edges is an obstacle to the other nets by its rectilinear cover
// (NetRules::cover_pieces; the bend-aware router takes rectilinear obstacles only): a net
// passing a diamond keeps the clearance from it, and the diamond's net is routed too.
TEST(NetRouter, BendMetricsRouteRoundADiamondPin) {
  const geom::NormalizedObstacles none = geom::normalize_obstacles({}, geom::Box{{0, 0}, {100, 100}});
  const std::vector<router::NetPins> nets{
      {"d", {Polygon{{{45, 50}, {50, 45}, {55, 50}, {50, 55}}, {}}, Polygon{{{10, 50}}, {}}}},
      {"x", {Polygon{{{50, 10}}, {}}, Polygon{{{50, 90}}, {}}}}};
  for (const bool link : {false, true}) {
    router::NetRouterOptions opt;
    opt.cost = link ? router::NetRouterOptions::Cost::Link : router::NetRouterOptions::Cost::Combined;
    opt.bend_cost = 7;
    router::NetRouter nr(none.domain, none.obstacles, nets, {2, 2, router::kDefaultCoverPieces}, opt);
    nr.run(router::NetRouter::bend_router(link ? router::BendMetric::Link : router::BendMetric::Combined, 7));
    EXPECT_TRUE(nr.outcomes()[0].routed && nr.outcomes()[1].routed) << nr.outcomes()[1].reason;
    EXPECT_TRUE(router::check_routes(none, check_nets(nets, nr), {2, 2}).problems.empty());
  }
  // the bend-aware costs refuse a sloped blockage (its cover is the caller's) and no cover of pins
  const geom::NormalizedObstacles tri = geom::normalize_obstacles(std::vector<Polygon>{Polygon{{{20, 20}, {40, 20}, {40, 40}}, {}}},
                                                                  geom::Box{{0, 0}, {100, 100}});
  router::NetRouterOptions opt;
  opt.cost = router::NetRouterOptions::Cost::Combined;
  EXPECT_THROW(router::NetRouter(tri.domain, tri.obstacles, nets, {2, 2, router::kDefaultCoverPieces}, opt), std::invalid_argument);
  EXPECT_THROW(router::NetRouter(none.domain, none.obstacles, nets, {2, 2, 0}, opt), std::invalid_argument);
  EXPECT_NO_THROW(router::NetRouter(tri.domain, tri.obstacles, nets, {2, 2, 0}));  // L1: sloped blockages are fine
}

// Found by review, kept: (1) an octilinear net whose window was kept by the L1 bound although a
// way out of the window was shorter (9,784 against the whole layout's 9,598); (2) a pad touching
// a blockage and a pad next to another net's wire, both refused as "under a blockage"; (3) a
// second run() starting from the first run's wires.
TEST(NetRouter, ReviewCases) {
  {
    const geom::Box domain{{-6000, -6000}, {7000, 7000}};
    const std::vector<Polygon> blocks{
        box_polygons(std::vector<geom::Box>{{{-6000, -6000}, {7000, -3905}}})[0],
        box_polygons(std::vector<geom::Box>{{{-6000, -3905}, {-5, 7000}}})[0],
        Polygon{{{-5, 4112}, {1005, 5122}, {1005, 7000}, {-5, 7000}}, {}},
        box_polygons(std::vector<geom::Box>{{{1005, -3905}, {7000, 7000}}})[0],
        Polygon{{{5, -3895}, {995, -3895}, {995, 5092}, {5, 4102}}, {}}};
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(blocks, domain);
    const std::vector<router::NetPins> net{{"n", {Polygon{{{0, 0}}, {}}, Polygon{{{1000, 1000}}, {}}}}};
    router::NetRouterOptions opt;
    opt.octilinear = true;
    router::NetRouter win(norm.domain, norm.obstacles, net, {}, opt);
    win.run(router::NetRouter::oct_router());
    opt.windows = false;
    router::NetRouter whole(norm.domain, norm.obstacles, net, {}, opt);
    whole.run(router::NetRouter::oct_router());
    ASSERT_TRUE(win.outcomes()[0].routed && whole.outcomes()[0].routed);
    auto oct = [](const router::NetOutcome& o) {  // (axis, diagonal) parts of the length
      std::pair<std::int64_t, std::int64_t> l{0, 0};
      for (const auto& w : o.wires)
        for (std::size_t i = 1; i < w.size(); ++i) {
          const std::int64_t ux = std::abs(w[i].x - w[i - 1].x), uy = std::abs(w[i].y - w[i - 1].y);
          l.first += std::max(ux, uy) - std::min(ux, uy);
          l.second += std::min(ux, uy);
        }
      return l;
    };
    EXPECT_EQ(oct(win.outcomes()[0]), oct(whole.outcomes()[0]));
  }
  {
    const geom::Box domain{{-200, -200}, {200, 200}};
    const geom::NormalizedObstacles norm =
        geom::normalize_obstacles(box_polygons(std::vector<geom::Box>{{{20, 0}, {40, 20}}}), domain);
    const Polygon pad = box_polygons(std::vector<geom::Box>{{{0, 0}, {20, 20}}})[0];
    // the pad touches the blockage; a second net's wire runs 3 above the pad
    const std::vector<router::NetPins> nets{{"n", {pad, Polygon{{{10, -100}}, {}}}}, {"m", {Polygon{{{-50, 24}}, {}}, Polygon{{{60, 24}}, {}}}}};
    router::NetRouter nr(norm.domain, norm.obstacles, nets, {2, 2});
    nr.run(router::NetRouter::l1_router(false));
    EXPECT_TRUE(nr.outcomes()[0].routed) << nr.outcomes()[0].code << " " << nr.outcomes()[0].reason;
    EXPECT_TRUE(nr.outcomes()[1].routed) << nr.outcomes()[1].code << " " << nr.outcomes()[1].reason;
    EXPECT_TRUE(router::check_routes(norm, check_nets(nets, nr), {2, 2}).problems.empty());
    const std::size_t first = nr.stats().first_pass;
    nr.run(router::NetRouter::l1_router(false));
    EXPECT_EQ(nr.stats().first_pass, first);
  }
}

// router::pad_staircase (NetSpace::reach, the bend-aware metrics' way onto a pad with a 45-degree
// edge) against brute force on 3,000 random octilinear pins (boxes with their four corners cut
// by 0 up to the shorter side: diamonds, octagons, right triangles, cut corners, pentagons; a
// third with a V notch in the top side, some with a diamond hole), on the integer lattice and on
// the lattice of 8 (a scaled plane): the staircase is a valid polygon (geom::validate_polygon)
// with horizontal and vertical edges, it is the union of the lattice's cells that lie in the
// pin (the same cells lie in each), so it holds exactly the pin's lattice points that are a
// corner of such a cell; for a convex pin those are all but the peaks (vertices whose inner
// angle holds no quadrant of the axes: 45 degrees, or 90 between two 45-degree edges). Pins it
// refuses: with a vertex off the lattice, too thin (a diagonal strip one step wide), rectilinear
// ones.
TEST(NetRouter, PadStaircasesAreTheCellsInThePin) {
  std::mt19937 rng(7101);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int made = 0, refused = 0, peaks = 0, points = 0, holes = 0, notches = 0, thin = 0, parts = 0;
  for (int n = 0; n < sanitized_share(3000, 5); ++n) {
    const std::int64_t step = n % 2 ? 8 : 1;
    const int w = uni(1, 12), h = uni(1, 12), x0 = uni(-20, 20), y0 = uni(-20, 20), m = std::min(w, h);
    int c[4];  // the cuts at the bottom-left, bottom-right, top-right and top-left corners
    do {
      for (int& k : c) k = uni(0, 3) == 0 ? m : uni(0, m);
    } while (c[0] + c[1] > w || c[1] + c[2] > h || c[2] + c[3] > w || c[3] + c[0] > h);
    const int x1 = x0 + w, y1 = y0 + h;
    std::vector<Point> v{{x0 + c[0], y0}, {x1 - c[1], y0}, {x1, y0 + c[1]}, {x1, y1 - c[2]}, {x1 - c[2], y1}};
    // a third get a V notch of depth d in the top side (concave pins)
    const int top = (x1 - c[2]) - (x0 + c[3]);
    bool notched = false;
    if (n % 3 == 1 && top >= 2 && h >= 2) {
      const int d = uni(1, std::min(top / 2, h - 1)), mx = uni(x0 + c[3] + d, x1 - c[2] - d);
      if (d < h - std::max(c[0], c[1])) {  // the notch's bottom stays clear of the bottom cuts
        v.insert(v.end(), {Point{mx + d, y1}, Point{mx, y1 - d}, Point{mx - d, y1}});
        notched = true;
      }
    }
    v.insert(v.end(), {Point{x0 + c[3], y1}, Point{x0, y1 - c[3]}, Point{x0, y0 + c[0]}});
    geom::Ring r;
    for (const Point p : v)
      if (r.empty() || r.back() != p) r.push_back(p);
    while (r.size() > 1 && r.front() == r.back()) r.pop_back();
    for (Point& p : r) p = {static_cast<geom::Coord>(p.x * step), static_cast<geom::Coord>(p.y * step)};
    // drop the middle of collinear vertices (two cuts that meet on a side)
    for (bool again = true; again && r.size() > 3;) {
      again = false;
      for (std::size_t i = 0; i < r.size(); ++i)
        if (geom::orient(r[(i + r.size() - 1) % r.size()], r[i], r[(i + 1) % r.size()]) == 0) {
          r.erase(r.begin() + static_cast<std::ptrdiff_t>(i));
          again = true;
          break;
        }
    }
    Polygon pin{r, {}};
    // and a sixth of the others a diamond hole (clockwise) at the box's centre, when it lies inside
    if (n % 6 == 2 && w >= 6 && h >= 6) {
      const geom::Coord cx = static_cast<geom::Coord>((x0 + w / 2) * step), cy = static_cast<geom::Coord>((y0 + h / 2) * step),
                        hr = static_cast<geom::Coord>(uni(1, 2) * step);
      const geom::Ring hole{{cx - hr, cy}, {cx, cy + hr}, {cx + hr, cy}, {cx, cy - hr}};
      bool inside = true;
      for (const Point q : hole) inside = inside && geom::locate(q, Polygon{r, {}}) == geom::Location::Inside;
      if (inside) pin.holes.push_back(hole);
    }
    if (!geom::validate_polygon(pin).empty()) continue;  // a notch that met a cut
    const std::string at = "case " + std::to_string(n);
    // the cells of the lattice that lie in the pin: all four corners and the centre in it (both
    // doubled, so the centre is an integer point; the pin's edges run through lattice points at
    // 0, 45 and 90 degrees, so one that cut the cell would leave a corner or the centre out)
    auto doubled = [](Polygon q) {
      for (Point& v2 : q.outer) v2 = {static_cast<geom::Coord>(2 * v2.x), static_cast<geom::Coord>(2 * v2.y)};
      for (geom::Ring& rg : q.holes)
        for (Point& v2 : rg) v2 = {static_cast<geom::Coord>(2 * v2.x), static_cast<geom::Coord>(2 * v2.y)};
      return q;
    };
    const Polygon twice_pin = doubled(pin);
    auto at_lattice = [&](int x, int y) { return Point{static_cast<geom::Coord>(x * step), static_cast<geom::Coord>(y * step)}; };
    auto cell_in = [&](const Polygon& q, const Polygon& q2, int x, int y) {  // the cell with lower-left corner (x, y) in q
      const Point centre{static_cast<geom::Coord>((2 * x + 1) * step), static_cast<geom::Coord>((2 * y + 1) * step)};
      return router::in_pin(centre, q2) && router::in_pin(at_lattice(x, y), q) && router::in_pin(at_lattice(x + 1, y), q) &&
             router::in_pin(at_lattice(x, y + 1), q) && router::in_pin(at_lattice(x + 1, y + 1), q);
    };
    const std::optional<Polygon> st = router::pad_staircase(pin, step);
    bool sloped = false;
    router::for_each_pin_edge(pin, [&](Point a, Point b) { sloped = sloped || (a.x != b.x && a.y != b.y); });
    if (!sloped) {
      EXPECT_FALSE(st.has_value()) << at << ": a rectilinear pin needs no staircase";
      continue;
    }
    std::set<std::pair<int, int>> all;
    for (int x = x0; x < x1; ++x)
      for (int y = y0; y < y1; ++y)
        if (cell_in(pin, twice_pin, x, y)) all.insert({x, y});
    const auto [expect, whole] = expected_staircase_cells(all, step);
    if (expect.empty()) {  // no cell of the lattice in the pin: no staircase
      EXPECT_FALSE(st.has_value()) << at;
      ++refused;
      continue;
    }
    ASSERT_TRUE(st.has_value()) << at << ": " << all.size() << " cells in the pin";
    parts += !whole;
    ++made;
    ASSERT_TRUE(geom::validate_polygon(*st).empty()) << at << ": " << geom::validate_polygon(*st)[0].message;
    router::for_each_pin_edge(*st, [&](Point a, Point b) {
      EXPECT_TRUE(a.x == b.x || a.y == b.y) << at;
      EXPECT_TRUE(router::in_pin(a, pin)) << at;
    });
    ASSERT_FALSE(::testing::Test::HasFailure()) << at;
    holes += !pin.holes.empty();
    notches += notched;
    // the peaks: the inner angle at b (counter-clockwise from the edge out to the edge in) as a
    // multiple of 45 degrees, by the directions' indices (0 east, 1 north-east, ... 7)
    auto dir = [](Point from, Point to) {
      const int sx = (to.x > from.x) - (to.x < from.x), sy = (to.y > from.y) - (to.y < from.y);
      static const int index[3][3] = {{5, 4, 3}, {6, -1, 2}, {7, 0, 1}};  // [sx + 1][sy + 1]
      return index[sx + 1][sy + 1];
    };
    // (the outer ring counter-clockwise, holes clockwise: the pin lies to the left of each)
    std::vector<Point> peak;
    std::vector<const geom::Ring*> rings{&pin.outer};
    for (const geom::Ring& hr : pin.holes) rings.push_back(&hr);
    for (const geom::Ring* rg : rings)
      for (std::size_t i = 0; i < rg->size(); ++i) {
        const Point a = (*rg)[(i + rg->size() - 1) % rg->size()], b = (*rg)[i], c2 = (*rg)[(i + 1) % rg->size()];
        const int out = dir(b, c2), in = dir(b, a), angle = ((in - out) % 8 + 8) % 8;  // in 45 degrees
        if (angle == 1 || (angle == 2 && out % 2 == 1)) peak.push_back(b);
      }
    peaks += static_cast<int>(peak.size());
    const Polygon twice = doubled(*st);
    const bool convex = pin.holes.empty() && !notched;
    for (int x = x0 - 1; x <= x1 + 1; ++x)
      for (int y = y0 - 1; y <= y1 + 1; ++y) {
        // the staircase is the union of the expected cells: the same cells, and a lattice point
        // is held exactly when it is a corner of one of them
        ASSERT_EQ(cell_in(*st, twice, x, y), expect.count({x, y}) == 1) << at << ": the cell at " << x << "," << y;
        const Point p = at_lattice(x, y);
        const bool in = router::in_pin(p, pin), held = router::in_pin(p, *st);
        const bool corner = expect.count({x, y}) || expect.count({x - 1, y}) || expect.count({x, y - 1}) || expect.count({x - 1, y - 1});
        ASSERT_EQ(held, corner) << at << ": " << p.x << "," << p.y;
        const bool is_peak = std::find(peak.begin(), peak.end(), p) != peak.end();
        points += held;
        thin += whole && in && !held && !is_peak;
        // a convex pin: every lattice point but the peaks
        if (convex && whole) {
          ASSERT_EQ(held, in && !is_peak) << at << ": " << p.x << "," << p.y;
        }
      }
  }
  // a diagonal strip one step wide, and a diamond one step from centre to corner (its centre
  // has no room): no staircase; a diamond with vertices off the lattice of 8: none; two steps: one
  EXPECT_FALSE(router::pad_staircase(Polygon{{{0, 0}, {1, 0}, {11, 10}, {10, 10}}, {}}, 1).has_value());
  EXPECT_FALSE(router::pad_staircase(Polygon{{{0, 8}, {8, 0}, {16, 8}, {8, 16}}, {}}, 8).has_value());
  EXPECT_FALSE(router::pad_staircase(Polygon{{{4, 16}, {16, 4}, {28, 16}, {16, 28}}, {}}, 8).has_value());
  EXPECT_TRUE(router::pad_staircase(Polygon{{{4, 16}, {16, 4}, {28, 16}, {16, 28}}, {}}, 4).has_value());
  EXPECT_TRUE(router::pad_staircase(Polygon{{{0, 16}, {16, 0}, {32, 16}, {16, 32}}, {}}, 8).has_value());
  std::printf("%d staircases (%d with a V notch, %d with a hole; %d peaks left out, %d lattice points held, %d more left "
              "out in necks thinner than a step; %d of them the largest part of cells too thin to be one polygon), %d "
              "pins without a cell\n",
              made, notches, holes, peaks, points, thin, parts, refused);
  EXPECT_GT(made, sanitized_share(3000, 5) / 2);
  EXPECT_GT(notches, 0);
  EXPECT_GT(holes, 0);
  EXPECT_GT(parts, 0);
}

// router::pad_staircase on pins with edges at any angle (since 2026-12-06: route, path and the
// net router reach such a pin as its staircase; before, ROUTE-0005 refused it), against brute
// force on random pins with integer vertices: triangles, rotated rectangles and star-shaped
// polygons in a 14 x 14 box, some with a triangular hole, on the integer lattice and on the
// lattice of 8. The brute force: a cell lies in the pin when no pin edge meets the open cell
// (separating axes: the cell's two axes and the edge's normal, exact) and its centre lies in the
// pin; the corners alone do not tell (a sliver of outside between two edges of a slope can cross
// a cell whose four corners are in the pin). The staircase is the union of those cells, or the
// largest part that is one valid polygon (expected_staircase_cells), with horizontal and vertical
// edges and vertices in the pin.
TEST(NetRouter, StaircasesOfPinsAtAnyAngleAreTheCellsInThePin) {
  std::mt19937 rng(7211);
  int made = 0, none = 0, parts = 0, holes = 0, slivers = 0, tried = 0;
  const int want = sanitized_share(3000, 5);
  for (int n = 0; tried < want; ++n) {
    const std::int64_t step = n % 3 == 2 ? 8 : 1;
    Polygon pin = random_sloped_pin(rng, 5);
    auto scale = [&](geom::Ring& rg) {
      for (Point& p : rg) p = {static_cast<geom::Coord>(p.x * step), static_cast<geom::Coord>(p.y * step)};
    };
    scale(pin.outer);
    for (geom::Ring& h : pin.holes) scale(h);
    ++tried;
    holes += !pin.holes.empty();
    const std::string at = "case " + std::to_string(n);
    auto at_lattice = [&](int x, int y) { return Point{static_cast<geom::Coord>(x * step), static_cast<geom::Coord>(y * step)}; };
    const Polygon twice_pin = doubled(pin);
    const std::set<Cell> all = cells_in_pin(pin, step, -1, -1, 16, 16);
    for (int x = -1; x <= 15; ++x)
      for (int y = -1; y <= 15; ++y) {
        bool corners = true;
        for (const Point c : {at_lattice(x, y), at_lattice(x + 1, y), at_lattice(x, y + 1), at_lattice(x + 1, y + 1)})
          corners = corners && router::in_pin(c, pin);
        if (all.count({x, y})) {
          EXPECT_TRUE(corners) << at;
        }
        // (cells whose corners and centre are in the pin while a sliver of outside crosses them)
        const Point centre{static_cast<geom::Coord>((2 * x + 1) * step), static_cast<geom::Coord>((2 * y + 1) * step)};
        slivers += corners && router::in_pin(centre, twice_pin) && !all.count({x, y});
      }
    const auto [expect, whole] = expected_staircase_cells(all, step);
    const std::optional<Polygon> st = router::pad_staircase(pin, step);
    if (expect.empty()) {
      EXPECT_FALSE(st.has_value()) << at << ": " << all.size() << " cells";
      ++none;
      continue;
    }
    ASSERT_TRUE(st.has_value()) << at << ": " << all.size() << " cells in the pin " << [&] {
      std::string t;
      router::for_each_pin_edge(pin, [&](Point a, Point) { t += std::to_string(a.x) + "," + std::to_string(a.y) + " "; });
      return t;
    }();
    ++made;
    parts += !whole;
    ASSERT_TRUE(geom::validate_polygon(*st).empty()) << at;
    router::for_each_pin_edge(*st, [&](Point a, Point b) {
      EXPECT_TRUE(a.x == b.x || a.y == b.y) << at;
      EXPECT_TRUE(router::in_pin(a, pin)) << at;
    });
    ASSERT_EQ(cells_in_pin(*st, step, -1, -1, 16, 16), expect) << at;
  }
  std::printf("%d pins at other angles: %d staircases (%d the largest part), %d without a cell; %d with a hole; %d cells "
              "whose corners and centre lie in a pin but a sliver of outside crosses\n",
              tried, made, parts, none, holes, slivers);
  EXPECT_GT(made, want / 2);
  EXPECT_GT(none, 0);
  EXPECT_GT(parts, 0);
  EXPECT_GT(holes, 0);
}

// router::pad_staircase with cuts (since 2026-12-06: a pad partly under a blockage is reached as
// its part outside the blockages): random pins (rectangles, and pins with edges at other angles)
// with one or two random cuts (rectangles and triangles, on the lattice), on the lattices of 1
// and 8, against brute force: the cells in the pin that meet no cut's interior
// (tests/support/pin_cells.h), or the largest part of them that is one valid polygon.
TEST(NetRouter, StaircasesOfPinsUnderBlockagesAreTheCellsOutsideThem) {
  std::mt19937 rng(7311);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int made = 0, none = 0, parts = 0, rectilinear = 0, exact = 0;
  const int want = sanitized_share(1500, 5);
  for (int n = 0; n < want; ++n) {
    const std::int64_t step = n % 3 == 2 ? 8 : 1;
    const auto c = [&](int v) { return static_cast<geom::Coord>(v * step); };
    auto scaled = [&](Polygon q) {
      for (Point& p : q.outer) p = {c(p.x), c(p.y)};
      for (geom::Ring& h : q.holes)
        for (Point& p : h) p = {c(p.x), c(p.y)};
      return q;
    };
    auto rect = [&](int x0, int y0, int x1, int y1) { return Polygon{{{c(x0), c(y0)}, {c(x1), c(y0)}, {c(x1), c(y1)}, {c(x0), c(y1)}}, {}}; };
    Polygon pin;
    const bool rect_pin = n % 2 == 0;
    if (rect_pin) {
      const int x0 = uni(0, 8), y0 = uni(0, 8);
      pin = rect(x0, y0, x0 + uni(2, 6), y0 + uni(2, 6));
    } else {
      pin = scaled(random_sloped_pin(rng, 6));
    }
    std::vector<Polygon> cuts;
    for (int k = uni(1, 2); k > 0; --k) {
      Polygon cut;
      do {
        if (uni(0, 1)) {
          const int x0 = uni(-2, 12), y0 = uni(-2, 12);
          cut = rect(x0, y0, x0 + uni(1, 6), y0 + uni(1, 6));
        } else {
          cut = Polygon{{{c(uni(-2, 16)), c(uni(-2, 16))}, {c(uni(-2, 16)), c(uni(-2, 16))}, {c(uni(-2, 16)), c(uni(-2, 16))}}, {}};
        }
      } while (!geom::validate_polygon(cut).empty());
      cuts.push_back(cut);
    }
    const std::string at = "case " + std::to_string(n);
    const auto [expect, whole] = expected_staircase_cells(cells_in_pin(pin, step, -3, -3, 18, 18, cuts), step);
    const std::optional<Polygon> st = router::pad_staircase(pin, step, {}, cuts);
    rectilinear += rect_pin;
    if (expect.empty()) {
      EXPECT_FALSE(st.has_value()) << at;
      ++none;
      continue;
    }
    ASSERT_TRUE(st.has_value()) << at << ": " << expect.size() << " cells";
    ++made;
    parts += !whole;
    ASSERT_TRUE(geom::validate_polygon(*st).empty()) << at;
    ASSERT_EQ(cells_in_pin(*st, step, -3, -3, 18, 18), expect) << at;
    // a rectangle less rectangles: the staircase is the part outside them, exactly
    exact += rect_pin && whole && std::all_of(cuts.begin(), cuts.end(), [](const Polygon& q) { return q.outer.size() == 4; });
  }
  // Pins wider than NetSpace::kMaxStaircaseColumns steps take columns of several steps, split at
  // the pin's vertices and the cuts' (else a cut's side inside a column leaves no edge spanning it,
  // and the cells under the cut would be taken): a rectangle 600 wide under rectangles at any x,
  // whose free part the staircase must be exactly, when it is one piece.
  int wide = 0;
  for (int n = 0; n < sanitized_share(40, 4); ++n) {
    const Polygon pin{{{0, 0}, {600, 0}, {600, 12}, {0, 12}}, {}};
    std::vector<Polygon> cuts;
    for (int k = uni(1, 3); k > 0; --k) {
      const int x0 = uni(1, 580), y0 = uni(-4, 8);
      const int x1 = x0 + uni(1, 15), y1 = y0 + uni(1, 12);
      cuts.push_back(Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}});
    }
    const auto [expect, whole] = expected_staircase_cells(cells_in_pin(pin, 1, -1, -5, 601, 20, cuts), 1);
    if (!whole) continue;
    const std::optional<Polygon> st = router::pad_staircase(pin, 1, {}, cuts);
    ASSERT_TRUE(st.has_value()) << "wide case " << n;
    ASSERT_EQ(cells_in_pin(*st, 1, -1, -5, 601, 20), expect) << "wide case " << n;
    ++wide;
  }
  std::printf("%d pins with cuts (%d rectangles): %d staircases (%d the largest part; %d rectangles less rectangles), %d "
              "with no cell left; %d pins 600 wide under rectangles, each exactly its free part\n",
              want, rectilinear, made, parts, exact, none, wide);
  EXPECT_GT(made, want / 2);
  EXPECT_GT(none, 0);
  EXPECT_GT(parts, 0);
  EXPECT_GT(exact, 0);
  EXPECT_GT(wide, 0);
}

// Pins more than NetSpace::kMaxStaircaseColumns (256) steps wide (refused over 4,096 until
// 2026-12-04: such a net was ROUTE-0010 under the bend-aware metrics when its pin met a
// blockage's clearance; on the old code the staircases here are refused, and the last part's net
// is ROUTE-0010) get columns of m steps, the fewest that make
// at most that many, split at the pin's vertices.
// Diamonds 20,002 wide on the integer lattice (m = 79) and 80,032 wide on the lattice of 8 (m = 40),
// each with its centre's x off the multiples of m steps, so a column is split there. Each
// staircase is a valid polygon with horizontal and vertical edges and its vertices in the pin;
// the columns are worked out here (the multiples of m steps from the left end, and the
// diamond's three vertex x's), and over each column [xa, xb] the staircase holds exactly the y's
// that both of the column's sides hold in the diamond (the half-height R - |x - cx|, the smaller
// of the two, from the diamond's formula), probed at the column's middle half a step inside and
// outside each bound. An octagon 30,000 wide: valid, inside, at most 256 columns plus its
// vertices. A diagonal bar 4 high and 400 wide, whose columns of 2 steps would meet only at
// corners, takes columns of one step; one 10,000 wide is refused (over 4,096 columns of one step).
// Then a net with the first diamond as a pad whose right corner lies 2 DBU from a
// blockage (inside its clearance of 3) routes under length + 7 x bends and under the link metric,
// and passes the checker.
// The nets routed together under length + 7 x bends (or the link metric), w = s = 2, on the
// rectilinear cover `covered` (the bend-aware routers' obstacles).
std::unique_ptr<router::NetRouter> route_with_bends(const geom::NormalizedObstacles& covered, const std::vector<router::NetPins>& nets,
                                                    bool link) {
  router::NetRouterOptions opt;
  opt.cost = link ? router::NetRouterOptions::Cost::Link : router::NetRouterOptions::Cost::Combined;
  opt.bend_cost = 7;
  auto nr = std::make_unique<router::NetRouter>(covered.domain, covered.obstacles, nets,
                                                router::NetRules{2, 2, router::kDefaultCoverPieces}, opt);
  nr->run(router::NetRouter::bend_router(link ? router::BendMetric::Link : router::BendMetric::Combined, 7));
  return nr;
}

TEST(NetRouter, WidePadStaircasesTakeCoarserColumns) {
  struct Diamond {
    std::int64_t cx, cy, r, step;
  };
  auto ring_of = [](const Diamond& d) {
    auto c = [](std::int64_t v) { return static_cast<geom::Coord>(v); };
    return Polygon{{{c(d.cx - d.r), c(d.cy)}, {c(d.cx), c(d.cy - d.r)}, {c(d.cx + d.r), c(d.cy)}, {c(d.cx), c(d.cy + d.r)}}, {}};
  };
  auto doubled = [](Polygon q) {
    for (Point& v : q.outer) v = {static_cast<geom::Coord>(2 * v.x), static_cast<geom::Coord>(2 * v.y)};
    return q;
  };
  auto check_shape = [](const Polygon& pin, const Polygon& st, std::int64_t step, std::int64_t most_columns) {
    ASSERT_TRUE(geom::validate_polygon(st).empty()) << geom::validate_polygon(st)[0].message;
    std::set<geom::Coord> xs;
    router::for_each_pin_edge(st, [&](Point a, Point b) {
      EXPECT_TRUE(a.x == b.x || a.y == b.y);
      EXPECT_TRUE(router::in_pin(a, pin)) << a.x << "," << a.y;
      EXPECT_EQ(a.x % step, 0);
      EXPECT_EQ(a.y % step, 0);
      xs.insert(a.x);
    });
    std::size_t pin_vertices = 0;
    router::for_each_pin_edge(pin, [&](Point, Point) { ++pin_vertices; });
    EXPECT_LE(xs.size(), static_cast<std::size_t>(most_columns) + 1 + pin_vertices);
  };
  const std::int64_t most = router::NetSpace::kMaxStaircaseColumns;
  for (const Diamond d : {Diamond{0, 0, 10001, 1}, Diamond{800, -1600, 8 * 5002, 8}}) {
    SCOPED_TRACE("diamond of radius " + std::to_string(d.r) + " on the lattice of " + std::to_string(d.step));
    const Polygon pin = ring_of(d);
    const std::optional<Polygon> st = router::pad_staircase(pin, d.step);
    ASSERT_TRUE(st.has_value());
    check_shape(pin, *st, d.step, most);
    const std::int64_t x0 = d.cx - d.r, x1 = d.cx + d.r;
    const std::int64_t m = ((x1 - x0) / d.step + most - 1) / most, w = m * d.step;  // the fewest steps per column
    ASSERT_GT(m, 1);
    EXPECT_NE((d.cx - x0) % w, 0);  // the centre splits a column
    std::vector<std::int64_t> xs{x1, d.cx};
    for (std::int64_t x = x0; x < x1; x += w) xs.push_back(x);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    const Polygon twice = doubled(*st);
    int columns = 0, failed = 0;
    for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
      const std::int64_t xa = xs[k], xb = xs[k + 1];
      const std::int64_t h = std::min(d.r - std::abs(xa - d.cx), d.r - std::abs(xb - d.cx));
      const geom::Coord mid = static_cast<geom::Coord>(xa + xb);  // doubled
      auto in = [&](std::int64_t y2) { return router::in_pin(Point{mid, static_cast<geom::Coord>(y2)}, twice); };
      ++columns;
      if (h <= 0) {
        failed += in(2 * d.cy);
        continue;
      }
      const std::int64_t lo = 2 * (d.cy - h), hi = 2 * (d.cy + h);
      const bool ok = in(lo + d.step) && !in(lo - d.step) && in(hi - d.step) && !in(hi + d.step);
      if (!ok && failed++ < 5) ADD_FAILURE() << "the column [" << xa << ", " << xb << "]: not the y's [" << lo / 2 << ", " << hi / 2 << "]";
    }
    EXPECT_EQ(failed, 0);
    EXPECT_GT(columns, 200);
  }
  {
    const Polygon octagon{{{3000, 0}, {27000, 0}, {30000, 3000}, {30000, 6000}, {27000, 9000}, {3000, 9000}, {0, 6000}, {0, 3000}}, {}};
    const std::optional<Polygon> st = router::pad_staircase(octagon, 1);
    ASSERT_TRUE(st.has_value());
    check_shape(octagon, *st, 1, router::NetSpace::kMaxStaircaseColumns);
  }
  // diagonal bars 4 high: 400 wide, whose columns of 2 steps meet only at corners, takes columns
  // of one step (as every pin up to 4,096 wide did before); 10,000 wide would need more than
  // 4,096 columns of one step: refused
  {
    const Polygon bar{{{0, 0}, {400, 400}, {400, 404}, {0, 4}}, {}};
    const std::optional<Polygon> st = router::pad_staircase(bar, 1);
    ASSERT_TRUE(st.has_value());
    check_shape(bar, *st, 1, router::NetSpace::kMaxUnitStaircaseColumns);
    std::set<geom::Coord> xs;
    router::for_each_pin_edge(*st, [&](Point a, Point) { xs.insert(a.x); });
    EXPECT_EQ(xs.size(), 401u);  // every x from 0 to 400: columns of one step
    EXPECT_FALSE(router::pad_staircase(Polygon{{{0, 0}, {10000, 10000}, {10000, 10004}, {0, 4}}, {}}, 1).has_value());
  }
  // routed: the diamond's right corner (10001, 0) lies 2 DBU from the blockage, inside its
  // clearance ceil(2 / 2) + 2 = 3
  const geom::Box domain{{-30000, -30000}, {30000, 30000}};
  const geom::NormalizedObstacles norm =
      geom::normalize_obstacles(box_polygons(std::vector<geom::Box>{{{10003, -500}, {12000, 500}}}), domain);
  const geom::NormalizedObstacles covered = geom::normalize_obstacles(router::rectilinear_cover(norm.obstacles), norm.domain);
  const std::vector<router::NetPins> nets{{"wide", {ring_of({0, 0, 10001, 1}), Polygon{{{15000, 3000}}, {}}}}};
  for (const bool link : {false, true}) {
    SCOPED_TRACE(link ? "link" : "combined");
    const std::unique_ptr<router::NetRouter> routed = route_with_bends(covered, nets, link);
    const router::NetRouter& nr = *routed;
    EXPECT_TRUE(nr.outcomes()[0].routed) << nr.outcomes()[0].code << " " << nr.outcomes()[0].reason;
    const router::CheckResult cr = router::check_routes(norm, check_nets(nets, nr), {2, 2});
    EXPECT_TRUE(cr.problems.empty()) << cr.problems[0].message;
  }
}

// A diagonal bar two units high (between y = x and y = x + 2) whose upper end lies inside a
// blockage's clearance: its lattice cells touch only at corners, so no staircase of it is one
// polygon. Before 2026-12-05 the pin was left as it is and the net was ROUTE-0010 under the
// bend-aware metrics (cover_pieces > 0); now it is reached as its largest part (one cell here:
// the first from the left, [0, 1] x [1, 2]), and the net routes and passes the checker under
// length + 7 x bends and under the link metric, its wire ending on that cell; with the blockage
// at the bar's lower end instead, on a cell clear of the blockage's clearance.
TEST(NetRouter, ThinDiagonalPadsAreReachedByTheirLargestPart) {
  const Polygon bar{{{0, 0}, {40, 40}, {40, 42}, {0, 2}}, {}};
  {
    const std::optional<Polygon> st = router::pad_staircase(bar, 1);
    EXPECT_TRUE(st.has_value());
    if (st) {
      EXPECT_EQ(geom::normalize_polygon(*st), geom::normalize_polygon(Polygon{{{0, 1}, {1, 1}, {1, 2}, {0, 2}}, {}}));
    }
  }
  const geom::Box domain{{-200, -200}, {200, 200}};
  // a blockage 2 right of the bar's upper end, then one 1 left of its lower end, where the
  // first cell from the left lies inside the clearance, no side of it on the clearance's edge
  // (the part taken is then another cell, clear of it: found by a seeded search, 2026-12-05,
  // where such a net was ROUTE-0010)
  for (const geom::Box blockage : {geom::Box{{42, 20}, {80, 60}}, geom::Box{{-40, -20}, {-1, 20}}}) {
    const bool left = blockage.hi.x < 0;
    SCOPED_TRACE(left ? "blockage at the lower end" : "blockage at the upper end");
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(box_polygons(std::vector<geom::Box>{blockage}), domain);
    const std::vector<router::NetPins> nets{{"bar", {bar, Polygon{{{-100, -100}}, {}}}}};
    const geom::NormalizedObstacles covered = geom::normalize_obstacles(router::rectilinear_cover(norm.obstacles), norm.domain);
    for (const bool link : {false, true}) {
      SCOPED_TRACE(link ? "link" : "combined");
      const std::unique_ptr<router::NetRouter> routed = route_with_bends(covered, nets, link);
      const router::NetRouter& nr = *routed;
      const router::NetOutcome& o = nr.outcomes()[0];
      ASSERT_TRUE(o.routed) << o.code << " " << o.reason;
      EXPECT_TRUE(router::check_routes(norm, check_nets(nets, nr), {2, 2}).problems.empty());
      // the wire ends on a cell of the bar: the first, [0, 1] x [1, 2], when it is clear of the
      // blockage's clearance (3); else one clear of it
      bool on_cell = false;
      for (const auto& w : o.wires)
        for (const Point e : {w.front(), w.back()})
          on_cell = on_cell || (left ? router::in_pin(e, bar) && e.x >= 2 : e.x >= 0 && e.x <= 1 && e.y >= 1 && e.y <= 2);
      EXPECT_TRUE(on_cell);
    }
  }
}

// Pads that are not rectangles (diamonds, octagons, boxes with a cut corner: convex, edges at 0,
// 45 and 90 degrees; since 2026-12-03 concave ones too, L-shapes and squares with a V notch, as
// convex pieces) are cut out of their net's grown blockages like rectangular ones
// (geom::convex_minus_pad), so a pad touching or near a blockage is reached: a diamond whose tip
// touches a blockage by hand, then random layouts where every pad touches or nearly touches a
// blockage (sloped triangles too); every routed net passes the independent checker, and the cut
// routes more nets than the same layouts without it (NetRules::cover_pieces > 0 turns it off for
// pads with a 45-degree edge, as for the bend-aware metrics). The same layouts with octilinear
// wires (pads with 45-degree edges are taken since 2026-12-03; Steiner trees on every other
// layout): every routed net passes the checker, and at least 60 more route than the rectilinear
// run without the cut; of the V-notched pads, at least 10 more route with the cut than without.
// Since 2026-12-04 the rectilinear ones (the L-shapes) are cut with cover_pieces > 0 too, so the
// bend-aware metrics reach them: the same layouts under length + 7 x bends or the link metric
// (among the blockages' rectilinear covers) pass the checker, and route at least 9 in 10 of the
// L-shaped pads the rectilinear run with the cut routes (before: 2 of the 54 L-shaped pads here,
// against 53 with the cut).
TEST(NetRouter, OctilinearPadsNearBlockagesAreReached) {
  {
    const geom::Box domain{{-200, -200}, {200, 200}};
    const geom::NormalizedObstacles norm =
        geom::normalize_obstacles(box_polygons(std::vector<geom::Box>{{{20, -40}, {60, 40}}}), domain);
    const Polygon diamond{{{0, 0}, {10, -10}, {20, 0}, {10, 10}}, {}};  // its right tip on the blockage
    const std::vector<router::NetPins> nets{{"n", {diamond, Polygon{{{-100, -100}}, {}}}}};
    // (cover 16: not cut, reached as its staircase since 2026-12-04, NetSpace::reach)
    for (const int cover : {0, 16}) {
      router::NetRouter nr(norm.domain, norm.obstacles, nets, {2, 2, cover});
      nr.run(router::NetRouter::l1_router(false));
      EXPECT_TRUE(nr.outcomes()[0].routed) << cover << ": " << nr.outcomes()[0].code << " " << nr.outcomes()[0].reason;
      EXPECT_TRUE(router::check_routes(norm, check_nets(nets, nr), {2, 2}).problems.empty());
    }
    {
      // the staircase: in the pin, horizontal and vertical edges, every lattice point of the
      // diamond but its four peaks (vertices between two 45-degree edges)
      const router::NetSpace space(norm.domain, norm.obstacles, nets, {2, 2, 16});
      const Polygon& st = space.reach(0).pins[0];
      ASSERT_NE(st.outer.size(), 4u);
      for (std::size_t i = 0; i < st.outer.size(); ++i) {
        const Point a = st.outer[i], b = st.outer[(i + 1) % st.outer.size()];
        EXPECT_TRUE(a.x == b.x || a.y == b.y);
        EXPECT_TRUE(router::in_pin(a, diamond));
      }
      int held = 0, lattice = 0;
      for (int x = 0; x <= 20; ++x)
        for (int y = -10; y <= 10; ++y)
          if (router::in_pin({x, y}, diamond)) {
            ++lattice;
            const bool tip = ((x == 0 || x == 20) && y == 0) || (x == 10 && (y == -10 || y == 10));
            EXPECT_EQ(router::in_pin({x, y}, st), !tip) << x << "," << y;
            held += router::in_pin({x, y}, st);
          }
      EXPECT_EQ(held, lattice - 4);
      // a pin far from the blockages stays as it is
      const std::vector<router::NetPins> far{{"f", {Polygon{{{-100, 0}, {-90, -10}, {-80, 0}, {-90, 10}}, {}}, Polygon{{{-100, -100}}, {}}}}};
      EXPECT_EQ(router::NetSpace(norm.domain, norm.obstacles, far, {2, 2, 16}).reach(0).pins[0].outer.size(), 4u);
    }
  }
  long long layouts = 0, pads = 0, with_cut = 0, without = 0, checked = 0, oct_routed = 0;
  long long notch_pads = 0, notch_cut = 0, notch_without = 0;
  long long l_pads = 0, l_cut = 0, l_cover = 0, l_bend = 0, bend_routed = 0;
  long long convex45_pads = 0, convex45_cut = 0, convex45_bend = 0, notch_bend = 0;  // diamonds, octagons, cut corners
  const int n = static_cast<int>(sanitized_share(120, 4));
  for (int seed = 1; seed <= n; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed) * 7919u);
    auto uni = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1)); };
    const geom::Box domain{{0, 0}, {200, 200}};
    std::vector<geom::Box> rects;
    for (int i = 0, k = uni(3, 7); i < k; ++i) {
      const int x = uni(10, 160), y = uni(10, 160);
      rects.push_back({{x, y}, {x + uni(8, 30), y + uni(8, 30)}});
    }
    std::vector<Polygon> blocks = box_polygons(rects);
    if (seed % 3 == 0) blocks.push_back(Polygon{{{uni(0, 60), uni(0, 60)}, {uni(100, 190), uni(0, 40)}, {uni(60, 150), uni(60, 120)}}, {}});
    geom::NormalizedObstacles norm;
    try {
      norm = geom::normalize_obstacles(blocks, domain);
    } catch (const std::exception&) {
      continue;
    }
    const router::L1Router plain(norm.domain, norm.obstacles);
    const int w = uni(1, 4), s = uni(1, 3);
    std::vector<router::NetPins> nets;
    std::vector<int> kinds;  // per net: its pad's kind (3: an L, 4: a V notch)
    std::vector<geom::Box> taken;  // every pin's box grown by w + s: pins of different nets stay apart
    auto free_box = [&](const geom::Box& b) {
      for (const geom::Box& t : taken)
        if (geom::boxes_meet(geom::grown_box(b, w + s + 1), t)) return false;
      return true;
    };
    for (int i = 0, k = uni(2, 4); i < k; ++i) {
      // a pad just right of (or above) a blockage rectangle's side: gap 0..2
      const geom::Box& r = rects[rng() % rects.size()];
      const int size = uni(3, 8), gap = uni(0, 2), kind = uni(0, 4);  // c < size: no repeated vertex
      const bool right = rng() % 2;
      const int x0 = right ? r.hi.x + gap : uni(r.lo.x - size, r.hi.x), y0 = right ? uni(r.lo.y - size, r.hi.y) : r.hi.y + gap;
      const int x1 = x0 + 2 * size, y1 = y0 + 2 * size, c = uni(1, size - 1);
      Polygon pad;
      if (kind == 0) pad = Polygon{{{x0, y0 + size}, {x0 + size, y0}, {x1, y0 + size}, {x0 + size, y1}}, {}};  // diamond
      else if (kind == 1) pad = Polygon{{{x0 + c, y0}, {x1 - c, y0}, {x1, y0 + c}, {x1, y1 - c}, {x1 - c, y1}, {x0 + c, y1}, {x0, y1 - c}, {x0, y0 + c}}, {}};
      else if (kind == 2) pad = Polygon{{{x0, y0}, {x1, y0}, {x1, y1 - c}, {x1 - c, y1}, {x0, y1}}, {}};  // one corner cut
      else if (kind == 3) pad = Polygon{{{x0, y0}, {x1, y0}, {x1, y0 + c}, {x0 + c, y0 + c}, {x0 + c, y1}, {x0, y1}}, {}};  // an L
      else pad = Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0 + size, y0 + size}, {x0, y1}}, {}};  // a V notch from the top
      const geom::Box pb{{x0, y0}, {x1, y1}};
      if (x0 < 0 || y0 < 0 || x1 > 200 || y1 > 200 || plain.pin_meets_obstacle(pad) || !free_box(pb)) continue;
      Point q{};
      bool found = false;
      for (int t = 0; t < 50 && !found; ++t) {
        q = {uni(0, 200), uni(0, 200)};
        found = plain.is_free(q) && free_box({q, q});
      }
      if (!found) continue;
      taken.push_back(pb);
      taken.push_back({q, q});
      nets.push_back({"n" + std::to_string(i), {pad, Polygon{{q}, {}}}});
      kinds.push_back(kind);
    }
    if (nets.empty()) continue;
    ++layouts;
    pads += static_cast<long long>(nets.size());
    notch_pads += std::count(kinds.begin(), kinds.end(), 4);
    l_pads += std::count(kinds.begin(), kinds.end(), 3);
    convex45_pads += std::count_if(kinds.begin(), kinds.end(), [](int k) { return k <= 2; });
    for (const int cover : {0, 16}) {
      router::NetRouter nr(norm.domain, norm.obstacles, nets, {w, s, cover});
      nr.run(router::NetRouter::l1_router(false));
      long long routed = 0;
      for (std::size_t i = 0; i < nets.size(); ++i) {
        routed += nr.outcomes()[i].routed;
        if (kinds[i] == 4) (cover == 0 ? notch_cut : notch_without) += nr.outcomes()[i].routed;
        if (kinds[i] == 3) (cover == 0 ? l_cut : l_cover) += nr.outcomes()[i].routed;
        if (kinds[i] <= 2 && cover == 0) convex45_cut += nr.outcomes()[i].routed;
      }
      (cover == 0 ? with_cut : without) += routed;
      if (cover == 0) {
        const router::CheckResult cr = router::check_routes(norm, check_nets(nets, nr), {w, s});
        EXPECT_TRUE(cr.problems.empty()) << "seed " << seed << ": " << cr.problems[0].message;
        ++checked;
      }
    }
    // octilinear wires to the same pads (45-degree edges taken since 2026-12-03), with Steiner
    // trees on every other layout
    {
      router::NetRouter nr(norm.domain, norm.obstacles, nets, {w, s, 0});
      nr.run(router::NetRouter::oct_router(seed % 2 == 0));
      for (const router::NetOutcome& o : nr.outcomes()) oct_routed += o.routed;
      const router::CheckResult cr = router::check_routes(norm, check_nets(nets, nr), {w, s});
      EXPECT_TRUE(cr.problems.empty()) << "seed " << seed << " octilinear: " << cr.problems[0].message;
    }
    // the bend-aware metrics (among the blockages' rectilinear covers), checked against the real
    // blockages
    {
      const geom::NormalizedObstacles covered =
          geom::normalize_obstacles(router::rectilinear_cover(norm.obstacles), norm.domain);
      const bool link = seed % 2 == 1;
      router::NetRouterOptions opt;
      opt.cost = link ? router::NetRouterOptions::Cost::Link : router::NetRouterOptions::Cost::Combined;
      opt.bend_cost = 7;
      router::NetRules rules{w, s, router::kDefaultCoverPieces};
      router::NetRouter nr(covered.domain, covered.obstacles, nets, rules, opt);
      nr.run(router::NetRouter::bend_router(link ? router::BendMetric::Link : router::BendMetric::Combined, 7));
      for (std::size_t i = 0; i < nets.size(); ++i) {
        bend_routed += nr.outcomes()[i].routed;
        if (kinds[i] == 3) l_bend += nr.outcomes()[i].routed;
        if (kinds[i] <= 2) convex45_bend += nr.outcomes()[i].routed;
        if (kinds[i] == 4) notch_bend += nr.outcomes()[i].routed;
      }
      const router::CheckResult cr = router::check_routes(norm, check_nets(nets, nr), {w, s});
      EXPECT_TRUE(cr.problems.empty()) << "seed " << seed << (link ? " link" : " combined") << ": " << cr.problems[0].message;
    }
    ASSERT_FALSE(::testing::Test::HasFailure()) << "seed " << seed;
  }
  std::printf("%lld layouts, %lld pads near blockages: %lld nets routed with the pad cut (all passing the checker), %lld "
              "without it; octilinear wires: %lld routed (all passing the checker); of those pads %lld V-notched: %lld routed "
              "with the cut, %lld without it; %lld L-shaped: %lld routed with the cut, %lld with cover_pieces > 0, %lld "
              "by the bend-aware metrics (%lld nets in all, passing the checker)\n",
              layouts, pads, with_cut, without, oct_routed, notch_pads, notch_cut, notch_without, l_pads, l_cut, l_cover,
              l_bend, bend_routed);
  std::printf("%lld convex pads with a 45-degree edge: %lld routed with the cut (L1), %lld by the bend-aware metrics (as "
              "their staircases); the V-notched ones: %lld by those metrics\n",
              convex45_pads, convex45_cut, convex45_bend, notch_bend);
  // (before the staircases the V-notched pads routed 0 times without the cut, and this read
  // notch_cut >= notch_without + 10; the staircases now route about as many as the cut)
  EXPECT_GE(10 * notch_without, 9 * notch_cut);
  EXPECT_GE(10 * notch_bend, 9 * notch_cut);
  EXPECT_GE(10 * l_bend, 9 * l_cut);
  EXPECT_GE(10 * convex45_bend, 9 * convex45_cut);
  EXPECT_GT(convex45_cut, 0);
  EXPECT_GE(10 * l_cover, 9 * l_cut);
  // (before the staircases, 2026-12-04, the run with cover_pieces > 0 left every pad with a
  // 45-degree edge near a blockage unreached, and these two read "at least 60 more"; now the
  // staircases reach about as many as the cut)
  EXPECT_GE(10 * without, 9 * with_cut);
  EXPECT_GE(10 * oct_routed, 9 * with_cut);
  EXPECT_GE(checked, sanitized_share(100, 4));
}

// The union of a window's pieces rounds sloped crossings outward (geom/normalize.h): that growth
// must not enter a component of the grown blockages passed through unchanged (NetSpace::obstacles).
// Here net a's grown pin square on the corner (55,40) of a thin triangle swings its long edge
// from (55,40)-(9,91) to (55,41)-(9,91), over the vertex (37,60) of the next triangle, 0.04 from
// it, whose box meets no other piece: the two obstacles overlapped and the wavefront threw "no
// free wedge of (33,53) holds the wave" (random seed 901347, reduced). The net space's obstacles
// are disjoint (normalizing them again merges nothing) and both random seeds route and check.
TEST(NetRouter, RoundedUnionStaysApartFromPassedComponents) {
  const geom::Box domain{{0, 0}, {120, 120}};
  const std::vector<Polygon> blocks{Polygon{{{9, 91}, {34, 54}, {55, 40}}, {}}, Polygon{{{33, 76}, {37, 60}, {58, 72}}, {}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(blocks, domain);
  ASSERT_EQ(norm.obstacles.size(), 2u);
  const std::vector<router::NetPins> nets{{"a", {Polygon{{{55, 40}}, {}}, Polygon{{{67, 0}}, {}}}},
                                          {"b", {Polygon{{{91, 42}}, {}}, Polygon{{{66, 110}}, {}}}}};
  const router::NetSpace space(norm.domain, norm.obstacles, nets, {});
  for (const std::optional<geom::Box> window : {std::optional<geom::Box>{}, std::optional<geom::Box>{geom::Box{{0, 0}, {110, 112}}}}) {
    const geom::NormalizedObstacles obs = space.obstacles(1, router::NetSpaceLevel::Pins, window);
    EXPECT_EQ(geom::normalize_obstacles(obs.obstacles, obs.domain).obstacles.size(), obs.obstacles.size());
    router::L1Router r(obs.domain, obs.obstacles);
    EXPECT_EQ(r.shortest(Point{91, 42}, Point{66, 110}).status, router::WireStatus::Ok);
  }
  for (const int seed : {901347}) {
    const RandomLayout L = random_layout(seed);
    router::NetRouterOptions opt;
    opt.octilinear = seed % 5 == 4;
    router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    nr.run(opt.octilinear ? router::NetRouter::oct_router(seed % 3 == 0) : router::NetRouter::l1_router(seed % 3 == 0));
    router::CheckRules rules;
    rules.wire_width = L.rules.wire_width;
    rules.spacing = L.rules.spacing;
    const router::CheckResult r = router::check_routes(L.norm, check_nets(L.nets, nr), rules);
    EXPECT_TRUE(r.problems.empty()) << "seed " << seed << ": " << r.problems[0].message;
  }
}

// The progress callback hears every net of the first pass in order, with the routed count never
// above the nets tried; a stop callback that says yes ends the run with NetRouterStopped.
TEST(NetRouter, ProgressAndStop) {
  const RandomLayout L = random_layout(700007);
  std::vector<router::NetRouterProgress> heard;
  router::NetRouterOptions opt;
  opt.progress = [&](const router::NetRouterProgress& p) { heard.push_back(p); };
  router::NetRouter nr(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
  nr.run(router::NetRouter::l1_router(false));
  ASSERT_GE(heard.size(), L.nets.size());
  for (std::size_t i = 0; i < L.nets.size(); ++i) {
    EXPECT_EQ(heard[i].phase, router::NetRouterProgress::Phase::FirstPass);
    EXPECT_EQ(heard[i].tried, i + 1);
    EXPECT_LE(heard[i].routed, heard[i].tried);
    EXPECT_EQ(heard[i].nets, L.nets.size());
  }
  EXPECT_EQ(heard[L.nets.size() - 1].routed, nr.stats().first_pass);
  int asked = 0;
  router::NetRouterOptions stop;
  stop.stop = [&] { return ++asked > 2; };
  router::NetRouter ns(L.norm.domain, L.norm.obstacles, L.nets, L.rules, stop);
  EXPECT_THROW(ns.run(router::NetRouter::l1_router(false)), router::NetRouterStopped);
  EXPECT_EQ(asked, 3);
}

// `count` local nets of 2-4 point pins: each pin a free point near a random centre in [0, 2000]^2.
std::vector<router::NetPins> local_nets(std::mt19937& rng, const router::L1Router& plain, int count, int reach) {
  std::vector<router::NetPins> nets;
  for (int k = 0; k < count; ++k) {
    const Point c{static_cast<geom::Coord>(rng() % 2001), static_cast<geom::Coord>(rng() % 2001)};
    router::NetPins np;
    np.name = "m" + std::to_string(k);
    for (int j = 0, pins = 2 + static_cast<int>(rng() % 3); j < pins; ++j)
      if (const auto p = free_near(rng, plain, c, reach, 100)) np.pins.push_back(Polygon{{*p}, {}});
    nets.push_back(std::move(np));
  }
  return nets;
}

// Dense local nets among rectangles from one seed: box_layout, local_nets (lo..hi nets) and
// random rules (w, s in 0..8), drawn in that order.
struct LocalLayout {
  geom::NormalizedObstacles norm;
  std::vector<router::NetPins> nets;
  router::NetRules rules;
};
LocalLayout local_layout(unsigned seed, int lo, int hi) {
  std::mt19937 rng(seed);
  LocalLayout L;
  L.norm = box_layout(rng).norm;
  const router::L1Router plain(L.norm.domain, L.norm.obstacles);
  L.nets = local_nets(rng, plain, lo, hi);
  L.rules = router::NetRules{static_cast<std::int64_t>(rng() % 9), static_cast<std::int64_t>(rng() % 9)};
  return L;
}

// --threads: the outcomes, and the counts that do not depend on timing, are the same for every
// thread count, bit for bit. Small crowded layouts (windows the whole domain: every speculative
// attempt meets every change, rip-ups) and larger ones of local nets (windows apart: most
// speculative attempts and rip-ups worked out ahead are kept), with 2 to 5 threads against one;
// and crowded ones without rip-up rounds, where the final round makes every rip-up (without the
// check that a final-round rip-up worked out ahead is still valid, seed 730081 differs).
TEST(NetRouter, ThreadsGiveTheSameOutcomes) {
  int failed = 0;
  std::int64_t speculated = 0, redone = 0, rips = 0, unrouted = 0, ahead = 0, ahead_redone = 0;
  auto same = [&](const std::string& at, const router::NetRouter& one, const router::NetRouter& par) {
    const auto &x = one.stats(), &y = par.stats();
    bool ok = x.attempts == y.attempts && x.windows == y.windows && x.whole == y.whole && x.rips == y.rips &&
              x.undone == y.undone && x.rounds == y.rounds && x.first_pass == y.first_pass && one.order() == par.order();
    for (std::size_t i = 0; i < one.outcomes().size(); ++i) {
      const auto &a = one.outcomes()[i], &b = par.outcomes()[i];
      ok = ok && a.routed == b.routed && a.wires == b.wires && a.code == b.code && a.reason == b.reason &&
           a.blockers == b.blockers && a.rips == b.rips && a.shortest == b.shortest;
    }
    if (!ok && failed++ < 5) ADD_FAILURE() << at << ": the outcomes differ from one thread's";
    speculated += y.speculated;
    redone += y.redone;
    ahead += y.rip_ups_ahead;
    ahead_redone += y.rip_ups_redone;
    rips += x.rips;
    for (const auto& o : one.outcomes()) unrouted += !o.routed;
  };
  for (int seed = 1; seed <= sanitized_share(400, 16); ++seed) {
    const RandomLayout L = random_layout(710000 + seed);
    router::NetRouterOptions opt;
    opt.octilinear = seed % 5 == 4;
    const auto fn = opt.octilinear ? router::NetRouter::oct_router(seed % 3 == 0) : router::NetRouter::l1_router(seed % 3 == 0);
    router::NetRouter one(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    one.run(fn);
    opt.threads = 2 + seed % 4;
    opt.cautious = seed % 2 == 0;  // half of them try any net ahead: most such attempts are redone
    router::NetRouter par(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    par.run(fn);
    same("seed " + std::to_string(710000 + seed) + ", " + std::to_string(opt.threads) + " threads", one, par);
  }
  for (int seed = 1; seed <= sanitized_share(30, 6); ++seed) {
    const auto [norm, nets, rules] = local_layout(static_cast<unsigned>(720000 + seed), 40, 120);
    router::NetRouter one(norm.domain, norm.obstacles, nets, rules);
    one.run(router::NetRouter::l1_router(seed % 2 == 0));
    router::NetRouterOptions opt;
    opt.threads = 2 + 2 * (seed % 2);
    opt.cautious = seed % 3 != 0;
    router::NetRouter par(norm.domain, norm.obstacles, nets, rules, opt);
    par.run(router::NetRouter::l1_router(seed % 2 == 0));
    same("local seed " + std::to_string(720000 + seed) + ", " + std::to_string(opt.threads) + " threads", one, par);
  }
  // no rip-up rounds: the final round makes every rip-up (worked out ahead too, and kept more
  // often than in the rounds, so later ones are worked out again)
  std::int64_t final_routed = 0;
  for (int seed = 1; seed <= sanitized_share(200, 10); ++seed) {
    const RandomLayout L = random_layout(730000 + seed);
    router::NetRouterOptions opt;
    opt.max_rounds = 0;
    router::NetRouter one(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    one.run(router::NetRouter::l1_router(seed % 3 == 0));
    opt.threads = 2 + seed % 3;
    router::NetRouter par(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
    par.run(router::NetRouter::l1_router(seed % 3 == 0));
    same("final-round seed " + std::to_string(730000 + seed) + ", " + std::to_string(opt.threads) + " threads", one, par);
    final_routed += static_cast<std::int64_t>(one.stats().final_round_routed);
  }
  std::printf("%lld speculative attempts, %lld of them redone; %lld rip-ups worked out ahead, %lld of them again; "
              "%lld rip-ups, %lld nets unrouted\n",
              static_cast<long long>(speculated), static_cast<long long>(redone), static_cast<long long>(ahead),
              static_cast<long long>(ahead_redone), static_cast<long long>(rips), static_cast<long long>(unrouted));
  std::printf("%lld nets routed by the final round without rip-up rounds\n", static_cast<long long>(final_routed));
  EXPECT_EQ(failed, 0);
  // the rip-up and explaining phases ran (counts that do not depend on timing)
  EXPECT_GT(rips, sanitized_share(50, 10));
  EXPECT_GT(unrouted, sanitized_share(50, 10));
  EXPECT_GT(final_routed, sanitized_share(10, 10));
  // Both ways were taken: attempts and rip-ups made ahead were kept in their turn, and some were
  // worked out again there. How many depends on timing (on an idle machine 3,311 attempts, 1,178
  // redone; 465 rip-ups ahead, 19 again; with a build on the other core 100 and 10; under the
  // sanitizers, with a sixteenth of the layouts, a loaded machine gave 0 rip-ups ahead), so only
  // that each happened at all is asserted, and not under the sanitizers.
  if (!kSanitized) {
    EXPECT_GT(redone, 0);
    EXPECT_GT(speculated - redone, 0);
    EXPECT_GT(ahead - ahead_redone, 0);
    EXPECT_GT(ahead_redone, 0);
  }
}

// NetRouterOptions::reuse: the failed attempts taken again, the undone rip-ups not made again and
// the rip-ups stopped once sure to be undone give the outcome of doing everything afresh, bit for
// bit (every net's wires, code, reason, blockers and rips, and the run's rips and undos), on the
// crowded random layouts (rip-ups in every round) and on local nets (rip-ups apart).
// The two runs made the same decisions and left every net the same: wires, codes, reasons,
// blockers and rips, and the same counts of rips, undone rip-ups, rounds and each phase's routed.
bool same_outcomes(const router::NetRouter& r, const router::NetRouter& s) {
  const auto &x = r.stats(), &y = s.stats();
  bool ok = x.rips == y.rips && x.undone == y.undone && x.rounds == y.rounds && x.first_pass == y.first_pass &&
            x.final_round_routed == y.final_round_routed && x.last_pass_routed == y.last_pass_routed &&
            r.outcomes().size() == s.outcomes().size();
  for (std::size_t i = 0; ok && i < r.outcomes().size(); ++i) {
    const auto &a = r.outcomes()[i], &b = s.outcomes()[i];
    ok = a.routed == b.routed && a.wires == b.wires && a.code == b.code && a.reason == b.reason &&
         a.blockers == b.blockers && a.rips == b.rips;
  }
  return ok;
}

// Crowded nets with a legal routing on a generated layout of about `size` blockage vertices
// (bench/planted_nets.h, as in bench_net_router --planted), w = s = 10.
struct Planted {
  geom::NormalizedObstacles norm;
  std::vector<router::NetPins> nets;
};
Planted planted_layout(std::uint64_t seed, int size, int nets) {
  io::GenOptions go;
  go.kind = io::GenKind::Rects;
  go.size = size;
  go.nets = 0;
  go.seed = seed;
  const io::Layout layout = io::generate_layout(go);
  std::optional<geom::Box> boundary;
  if (layout.boundary) boundary = layout.boundary->box;
  Planted out;
  out.norm = geom::normalize_obstacles(io::blockage_polygons(layout), boundary);
  const std::int64_t side = std::int64_t{out.norm.domain.hi.x} - out.norm.domain.lo.x;
  out.nets = bench::planted_nets(out.norm, nets, 10, 10, side / 40, seed).nets;
  return out;
}

// NetRouterOptions::superset: the last pass's superset of every unrouted net's space (the
// blockages, every wire, the grown blockage edges away from every pin) proves some nets' pins
// apart in their first window that finds no way, instead of in windows up to the whole domain.
// It is sound only if it never separates pins that some window would join: then a net would
// fail with it and route without it. So the outcomes with and without it must be the same, bit
// for bit. Layouts where it matters: a wall across a large domain with one slot; net x's pins at
// the slot's two ends (its wire closes the slot), net y's pins on the two sides of the wall, the
// slot outside y's first window and inside its second (so x's wire, not the wall alone, keeps
// y's pins apart there, and the window limit stops y: NetRouterOptions::search_windows), so one
// of the two is left for the last pass, apart in a component much larger than its first
// windows; random rules, sizes, slot height (room for y's wire between x's pins, or exactly that
// room), islands (rectangles) on both sides, and a third net among them. The superset must prove
// the left net apart in nearly every layout, with fewer whole-domain windows. In every other
// layout the wall has a second slot, far beyond the windows the rounds look in, and no rip-up
// is allowed: y is stopped by the limit in the first pass and the rounds, and only the last pass
// routes it, through the far slot, in windows that grow past the first that finds no way: a
// superset that separated its pins would leave it unrouted (taking every such net as apart fails
// here). (Until 2026-12-06 those layouts had one far slot and no x: the limit stopped y, apart
// in its first two windows; now a net the blockages alone keep apart there grows on, and routes
// in the first pass.) Then dense local nets among rectangles, where it seldom applies, for the
// outcomes.
TEST(NetRouter, LastPassSupersetGivesTheSameOutcomes) {
  int failed = 0;
  std::int64_t apart = 0, last_pass = 0, whole_with = 0, whole_without = 0, layouts = 0, last_routed = 0;
  auto same = [&](const std::string& at, const router::NetRouter& with, const router::NetRouter& without) {
    const bool ok = same_outcomes(with, without) && with.stats().last_pass == without.stats().last_pass &&
                    with.order() == without.order();
    if (!ok && failed++ < 5) ADD_FAILURE() << at << ": the outcomes differ with the superset";
    EXPECT_EQ(without.stats().superset_apart, 0) << at;
    apart += with.stats().superset_apart;
    last_pass += static_cast<std::int64_t>(with.stats().last_pass);
    last_routed += static_cast<std::int64_t>(without.stats().last_pass_routed);
    whole_with += with.stats().whole;
    whole_without += without.stats().whole;
    ++layouts;
  };
  auto both = [&](const std::string& at, const geom::NormalizedObstacles& norm, const std::vector<router::NetPins>& nets,
                  const router::NetRules& rules, router::NetRouterOptions opt, const router::NetRouteFn& fn) {
    router::NetRouter with(norm.domain, norm.obstacles, nets, rules, opt);
    with.run(fn);
    opt.superset = false;
    router::NetRouter without(norm.domain, norm.obstacles, nets, rules, opt);
    without.run(fn);
    same(at, with, without);
  };
  const int walls = static_cast<int>(sanitized_share(300, 10));
  for (int seed = 1; seed <= walls; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(790000 + seed));
    auto uni = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1)); };
    const int w = uni(0, 6), sp = uni(0, 4), a = (w + 1) / 2 + sp, b = std::max(w + sp, 1);
    const bool detour = seed % 2 == 0;  // a far slot, no rip-up: y goes round by it, found by the last pass only
    const int side = detour ? uni(100000, 200000) : uni(20000, 200000), t = uni(10, 300), wx = uni(side / 4, side / 2);
    const int h = 2 * a + 2 * b + 2 + (seed % 4 == 0 ? 0 : uni(0, 40));  // the slot: room for one wire between x's pins
    const int g0 = uni(side / 8, side / 4), g1 = g0 + h;
    const int d = uni(4 * (a + b) + 10, 8 * (a + b) + 400);
    const int m1 = (2 * d + t) / 2 + 4 * (a + b) + 32;  // y's first margin (two point pins)
    const int y0 = g1 + 2 * m1 + uni(0, m1 / 2);        // the slot between y's first window and its second (4 m1)
    std::vector<geom::Box> boxes{{{wx, 0}, {wx + t, g0}}};
    if (detour) {
      const int f0 = uni(side - side / 4, side - side / 8);
      boxes.push_back({{wx, g1}, {wx + t, f0}});
      boxes.push_back({{wx, f0 + h}, {wx + t, side}});
    } else {
      boxes.push_back({{wx, g1}, {wx + t, side}});
    }
    for (int k = 0, n = uni(0, 6); k < n; ++k) {  // islands, away from the wall and the pins
      const int x = uni(0, side - 400), y = uni(0, side - 400), e = uni(20, 390);
      const geom::Box isl{{x, y}, {x + e, y + e}};
      bool clear = isl.hi.x + 2 * (a + b) + 2 < wx - d - 100 || isl.lo.x > wx + t + d + 2 * (a + b) + 100;
      if (clear) boxes.push_back(isl);
    }
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(box_polygons(boxes), geom::Box{{0, 0}, {side, side}});
    const int cx = wx + t / 2;
    std::vector<router::NetPins> nets{
        {"y", {Polygon{{{wx - d, y0}}, {}}, Polygon{{{wx + t + d, y0}}, {}}}},
        {"z", {Polygon{{{wx - d, y0 - 4 * (a + b) - 40}}, {}}, Polygon{{{wx - d - 300, y0 - 4 * (a + b) - 340}}, {}}}}};
    nets.push_back({"x", {Polygon{{{cx, g0 + a}}, {}}, Polygon{{{cx, g1 - a}}, {}}}});
    router::NetRouterOptions opt;
    opt.max_rips = detour ? 0 : uni(1, 3);
    opt.final_round = !detour;
    both("wall seed " + std::to_string(790000 + seed), norm, nets, {w, sp}, opt, router::NetRouter::l1_router(seed % 2 == 0));
    ASSERT_FALSE(::testing::Test::HasFailure()) << "wall seed " << 790000 + seed;
  }
  const std::int64_t wall_apart = apart, wall_whole_with = whole_with, wall_whole_without = whole_without;
  const std::int64_t wall_last_routed = last_routed;
  for (int seed = 1; seed <= sanitized_share(60, 6); ++seed) {
    const auto [norm, nets, rules] = local_layout(static_cast<unsigned>(730000 + seed), 40, 120);
    both("local seed " + std::to_string(730000 + seed), norm, nets, rules, {}, router::NetRouter::l1_router(seed % 2 == 0));
  }
  std::printf("%d wall layouts: %lld nets proven apart by the superset, %lld routed by the last pass, whole-domain "
              "windows %lld with it, %lld without; in all %lld layouts, %lld nets in last passes, %lld proven apart\n",
              walls, static_cast<long long>(wall_apart), static_cast<long long>(wall_last_routed), static_cast<long long>(wall_whole_with),
              static_cast<long long>(wall_whole_without), static_cast<long long>(layouts), static_cast<long long>(last_pass),
              static_cast<long long>(apart));
  EXPECT_EQ(failed, 0);
  const int blocked = walls - walls / 2, detours = walls / 2;
  EXPECT_GE(10 * wall_apart, 9 * blocked);
  EXPECT_GE(10 * wall_last_routed, 9 * detours);
  EXPECT_LT(wall_whole_with, wall_whole_without);
}

// compare(what, nets, obstacles, rules, options, route function) on 100 crowded random layouts
// (L1 and octilinear, Steiner trees, rip limits 1-4; 10 under the sanitizers) of seeds base + 1...
template <class Compare>
void on_random_layouts(int base, Compare compare) {
  for (int seed = 1; seed <= sanitized_share(100, 5); ++seed) {  // seed 9: octilinear Steiner trees
    const RandomLayout L = random_layout(base + seed);
    router::NetRouterOptions opt;
    opt.octilinear = seed % 5 == 4;
    opt.max_rips = 1 + seed % 4;
    const auto fn = opt.octilinear ? router::NetRouter::oct_router(seed % 3 == 0) : router::NetRouter::l1_router(seed % 3 == 0);
    compare("seed " + std::to_string(base + seed), L.nets, L.norm, L.rules, opt, fn);
  }
}

TEST(NetRouter, ReusedWorkGivesTheSameOutcomes) {
  int failed = 0;
  std::int64_t reused = 0, replayed = 0, windows = 0, fresh_windows = 0, rips = 0;
  auto compare = [&](const std::string& at, const std::vector<router::NetPins>& nets, const geom::NormalizedObstacles& norm,
                     const router::NetRules& rules, router::NetRouterOptions opt, const router::NetRouteFn& fn) {
    opt.reuse = true;
    router::NetRouter re(norm.domain, norm.obstacles, nets, rules, opt);
    re.run(fn);
    opt.reuse = false;
    router::NetRouter fresh(norm.domain, norm.obstacles, nets, rules, opt);
    fresh.run(fn);
    const auto &x = re.stats(), &y = fresh.stats();
    const bool ok = same_outcomes(re, fresh) && y.reused == 0 && y.replayed == 0;
    if (!ok && failed++ < 5) ADD_FAILURE() << at << ": reusing work changed the outcome";
    reused += x.reused;
    replayed += x.replayed;
    windows += x.windows;
    fresh_windows += y.windows;
    rips += x.rips;
  };
  on_random_layouts(730000, compare);
  for (int seed = 1; seed <= sanitized_share(5, 5); ++seed) {
    const auto [norm, nets, rules] = local_layout(static_cast<unsigned>(740000 + seed), 60, 150);
    router::NetRouterOptions opt;
    opt.threads = seed % 3 == 0 ? 2 : 1;
    compare("local seed " + std::to_string(740000 + seed), nets, norm, rules, opt, router::NetRouter::l1_router(seed % 2 == 0));
  }
  // Crowded nets with a legal routing (bench/planted_nets.h, as in bench_net_router --planted),
  // where rip-ups go on for several rounds: a failed attempt or an undone rip-up reused without
  // its check of the windows changes the outcome here (seed 750002; and rips 713 against 710 on
  // the benchmark's 3,000 nets). Not under the sanitizers (50 s there; the layouts above run the
  // same code).
  for (int seed = 1; seed <= (kSanitized ? 0 : 2); ++seed) {
    const Planted pl = planted_layout(static_cast<std::uint64_t>(750000 + seed), 3000, 1500);
    compare("planted seed " + std::to_string(750000 + seed), pl.nets, pl.norm, {10, 10}, {}, router::NetRouter::l1_router(false));
  }
  std::printf("%lld attempts taken again, %lld undone rip-ups not made again; %lld windows against %lld afresh; %lld rip-ups\n",
              static_cast<long long>(reused), static_cast<long long>(replayed), static_cast<long long>(windows),
              static_cast<long long>(fresh_windows), static_cast<long long>(rips));
  EXPECT_EQ(failed, 0);
  // every kind of reuse happened
  EXPECT_GT(reused, sanitized_share(100, 20));
  EXPECT_GE(replayed, kSanitized ? 0 : 3);
  EXPECT_LT(windows, fresh_windows);
}

// Windows whose obstacles hold the domain's frame merged (NetSpace::obstacles(..., framed), what
// l1_router and oct_router take) route every net as unframed windows do: the same layouts as the
// reuse test above, with NetRouterOptions::framed saying no to every net for the reference. A
// route function that is not l1_router's or oct_router's takes no frames.
TEST(NetRouter, FramedWindowsGiveTheSameOutcomes) {
  EXPECT_TRUE(router::NetRouter::takes_frames(router::NetRouter::l1_router(false)));
  EXPECT_TRUE(router::NetRouter::takes_frames(router::NetRouter::oct_router()));
  const router::NetRouteFn l1 = router::NetRouter::l1_router(true);
  EXPECT_FALSE(router::NetRouter::takes_frames(
      [&](std::size_t i, const router::NetPins& p, const geom::NormalizedObstacles& o) { return l1(i, p, o); }));
  EXPECT_FALSE(router::NetRouter::takes_frames(router::NetRouter::bend_router(router::BendMetric::Link, 0)));
  int failed = 0, routed = 0;
  auto compare = [&](const std::string& at, const std::vector<router::NetPins>& nets, const geom::NormalizedObstacles& norm,
                     const router::NetRules& rules, router::NetRouterOptions opt, const router::NetRouteFn& fn) {
    router::NetRouter framed(norm.domain, norm.obstacles, nets, rules, opt);
    framed.run(fn);
    opt.framed = [](std::size_t) { return false; };
    router::NetRouter plain(norm.domain, norm.obstacles, nets, rules, opt);
    plain.run(fn);
    if (!same_outcomes(framed, plain) && failed++ < 5) ADD_FAILURE() << at << ": framed windows changed the outcome";
    for (const auto& o : framed.outcomes()) routed += o.routed;
  };
  on_random_layouts(760000, compare);
  for (int seed = 1; seed <= (kSanitized ? 0 : 1); ++seed) {
    const Planted pl = planted_layout(static_cast<std::uint64_t>(770000 + seed), 3000, 1500);
    compare("planted seed " + std::to_string(770000 + seed), pl.nets, pl.norm, {10, 10}, {}, router::NetRouter::l1_router(false));
  }
  std::printf("%d nets routed in framed windows\n", routed);
  EXPECT_EQ(failed, 0);
  EXPECT_GT(routed, kSanitized ? 15 : 1000);  // 1,774 here (the planted layout most); 25 in the sanitizer tree
}

// A stop asked from any thread ends the run with NetRouterStopped.
TEST(NetRouter, ThreadsStop) {
  const RandomLayout L = random_layout(700007);
  std::atomic<int> asked{0};
  router::NetRouterOptions opt;
  opt.threads = 3;
  opt.stop = [&] { return ++asked > 2; };
  router::NetRouter ns(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
  EXPECT_THROW(ns.run(router::NetRouter::l1_router(false)), router::NetRouterStopped);
  EXPECT_GE(asked.load(), 3);
}

// Public maps nobody here drew (Moving AI grid maps, 10 DBU per cell: blocked cells touch and
// pinch everywhere): arena whole and corners of maze-100-1 and 8room_000, 25 local nets of 2-4
// pins at free cell centres 10 apart (within 8 cells of the net's first pin and joined to it among
// the plain blockages), w = s = 2 (a = 3, b = 4: a corridor of one cell takes one wire). Every
// routed net passes the checker, and most are routed (one layer: nets that must cross cannot).
TEST(NetRouter, MovingAiMapsPassTheChecker) {
  TAUT_REQUIRE_SHARED_DATA();
  int routed = 0, nets = 0;
  // under the sanitizers arena alone (the three took 22 s there)
  const std::vector<const char*> names = kSanitized ? std::vector<const char*>{"arena"}
                                                    : std::vector<const char*>{"arena", "maze-100-1", "8room_000"};
  for (const char* name : names) {
    SCOPED_TRACE(name);
    const auto r = io::load_movingai_map(shared_data_dir() + "/movingai/" + name + ".map", 10);
    ASSERT_TRUE(r.layout && r.layout->boundary);
    geom::Box box = r.layout->boundary->box;
    box.hi = {std::min(box.hi.x, box.lo.x + 600), std::min(box.hi.y, box.lo.y + 600)};
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(io::blockage_polygons(*r.layout), box);
    router::L1Router plain(norm.domain, norm.obstacles);
    std::mt19937 rng(77);
    std::vector<Point> used;
    // a free cell centre (near `first`, within 8 cells and joined to it among the plain
    // blockages, when given), 10 from every pin so far
    auto centre = [&](std::optional<Point> first) -> std::optional<Point> {
      for (int t = 0; t < 2000; ++t) {
        Point p{static_cast<geom::Coord>(box.lo.x + 5 + 10 * static_cast<int>(rng() % static_cast<unsigned>((box.hi.x - box.lo.x) / 10))),
                static_cast<geom::Coord>(box.lo.y + 5 + 10 * static_cast<int>(rng() % static_cast<unsigned>((box.hi.y - box.lo.y) / 10)))};
        if (first)
          p = {static_cast<geom::Coord>(first->x + 10 * (static_cast<int>(rng() % 17) - 8)),
               static_cast<geom::Coord>(first->y + 10 * (static_cast<int>(rng() % 17) - 8))};
        bool clash = false;
        for (const Point q : used) clash = clash || (std::abs(p.x - q.x) < 10 && std::abs(p.y - q.y) < 10);
        if (clash || !plain.is_free(p)) continue;
        if (first && plain.shortest(*first, p).status != router::WireStatus::Ok) continue;
        return p;
      }
      return std::nullopt;
    };
    std::vector<router::NetPins> ns;
    for (int i = 0; i < 25; ++i) {
      router::NetPins np;
      np.name = "n" + std::to_string(i);
      for (int k = 0, pins = 2 + static_cast<int>(rng() % 3); k < pins; ++k)
        if (const auto p = centre(np.pins.empty() ? std::nullopt : std::optional<Point>(np.pins[0].outer[0]))) {
          used.push_back(*p);
          np.pins.push_back(Polygon{{*p}, {}});
        }
      if (np.pins.size() >= 2) ns.push_back(std::move(np));
    }
    router::NetRouter nr(norm.domain, norm.obstacles, ns, {2, 2});
    nr.run(router::NetRouter::l1_router(false));
    const std::vector<router::CheckNet> cn = check_nets(ns, nr);
    for (const auto& x : cn) routed += x.routed;
    nets += static_cast<int>(cn.size());
    std::map<std::string, int> codes;
    for (const auto& o : nr.outcomes())
      if (!o.routed) ++codes[o.code];
    std::printf("%s:", name);
    for (const auto& [c, k] : codes) std::printf(" %s %d", c.c_str(), k);
    std::printf("\n");
    const auto problems = router::check_routes(norm, cn, {2, 2}).problems;
    EXPECT_TRUE(problems.empty()) << problems[0].message;
  }
  std::printf("Moving AI maps: %d of %d nets routed\n", routed, nets);
  EXPECT_GT(routed * 2, nets);
}

// Rip-up: the short net "a" goes straight across the plane first and cuts "b"'s pin (10 above
// a's line) off from its other pin far below; b's way alone crosses a, so a is ripped up, b
// routed straight down, and a routed again over the top of b's upper pin.
TEST(NetRouter, RipUpLetsACutOffNetThrough) {
  // the domain leaves no way round a's ends (its wire grown by w + s = 4 reaches x = -4 and 104)
  const geom::Box domain{{-3, -200}, {103, 200}};
  std::vector<router::NetPins> nets(2);
  nets[0] = {"a", {Polygon{{{0, 0}}, {}}, Polygon{{{100, 0}}, {}}}};
  nets[1] = {"b", {Polygon{{{50, 10}}, {}}, Polygon{{{50, -100}}, {}}}};
  router::NetRouter nr(domain, {}, nets, {2, 2});
  nr.run(router::NetRouter::l1_router(false));
  EXPECT_EQ(nr.stats().first_pass, 1u);
  EXPECT_EQ(nr.order(), (std::vector<std::size_t>{0, 1}));
  ASSERT_TRUE(nr.outcomes()[0].routed);
  ASSERT_TRUE(nr.outcomes()[1].routed);
  EXPECT_EQ(nr.outcomes()[0].rips, 1);
  EXPECT_GE(nr.stats().rips, 1);
  const geom::NormalizedObstacles none = geom::normalize_obstacles({}, domain);
  EXPECT_TRUE(router::check_routes(none, check_nets(nets, nr), {2, 2}).problems.empty());
  // b is the straight drop; a climbs over b's upper pin: above y = 10 + w + s
  EXPECT_EQ(nr.outcomes()[1].wires, (std::vector<std::vector<Point>>{{{50, 10}, {50, -100}}}));
  int top = 0;
  for (const auto& w : nr.outcomes()[0].wires)
    for (const Point p : w) top = std::max<int>(top, p.y);
  EXPECT_GE(top, 14);
  // with no rip-up allowed in the rounds and no final round, b stays unrouted, blocked by a's wire
  router::NetRouterOptions no_rips;
  no_rips.max_rips = 0;
  no_rips.final_round = false;
  router::NetRouter stuck(domain, {}, nets, {2, 2}, no_rips);
  stuck.run(router::NetRouter::l1_router(false));
  EXPECT_TRUE(stuck.outcomes()[0].routed);
  EXPECT_FALSE(stuck.outcomes()[1].routed);
  EXPECT_EQ(stuck.outcomes()[1].code, "ROUTE-0012");
  EXPECT_EQ(stuck.outcomes()[1].blockers, (std::vector<std::size_t>{0}));
  EXPECT_NE(stuck.outcomes()[1].reason.find("\"a\""), std::string::npos) << stuck.outcomes()[1].reason;
  EXPECT_NE(stuck.outcomes()[1].reason.find("may not be ripped up (no rip-up rounds: --max-rips 0)"), std::string::npos)
      << stuck.outcomes()[1].reason;
  EXPECT_EQ(stuck.stats().final_round, 0u);
  // the final round rips a up whatever its rips, since that routes both: the same wires as above
  no_rips.final_round = true;
  router::NetRouter freed(domain, {}, nets, {2, 2}, no_rips);
  freed.run(router::NetRouter::l1_router(false));
  EXPECT_EQ(freed.stats().rounds, 2);  // the rounds, two without progress, ripped nothing
  EXPECT_EQ(freed.stats().final_round, 1u);
  EXPECT_EQ(freed.stats().final_round_routed, 1u);
  EXPECT_EQ(freed.stats().rips, 1);
  EXPECT_EQ(freed.stats().undone, 0);
  ASSERT_TRUE(freed.outcomes()[0].routed);
  ASSERT_TRUE(freed.outcomes()[1].routed);
  EXPECT_EQ(freed.outcomes()[0].wires, nr.outcomes()[0].wires);
  EXPECT_EQ(freed.outcomes()[1].wires, nr.outcomes()[1].wires);
  EXPECT_TRUE(router::check_routes(none, check_nets(nets, freed), {2, 2}).problems.empty());
}

// A rip-up that leaves fewer nets routed is undone. In a strip with no way round any wire's ends,
// b (vertical) must cross a1 and a2 (horizontal, routed first: shorter). Ripping both routes b
// and then neither a: one routed instead of two, so the two wires are put back, in every round
// (each rips both once more, up to max_rips); without the undo the second round would start from
// b alone and rip it up again.
TEST(NetRouter, ARipUpThatLosesNetsIsUndone) {
  const geom::Box domain{{-3, -3}, {103, 203}};
  std::vector<router::NetPins> nets(3);
  nets[0] = {"a1", {Polygon{{{0, 50}}, {}}, Polygon{{{100, 50}}, {}}}};
  nets[1] = {"a2", {Polygon{{{0, 150}}, {}}, Polygon{{{100, 150}}, {}}}};
  nets[2] = {"b", {Polygon{{{50, 0}}, {}}, Polygon{{{50, 200}}, {}}}};
  router::NetRouter nr(domain, {}, nets, {2, 2});
  nr.run(router::NetRouter::l1_router(false));
  EXPECT_EQ(nr.order(), (std::vector<std::size_t>{0, 1, 2}));
  ASSERT_TRUE(nr.outcomes()[0].routed);
  ASSERT_TRUE(nr.outcomes()[1].routed);
  EXPECT_FALSE(nr.outcomes()[2].routed);
  EXPECT_EQ(nr.outcomes()[2].code, "ROUTE-0012");
  EXPECT_EQ(nr.outcomes()[2].blockers, (std::vector<std::size_t>{0, 1}));
  EXPECT_GE(nr.stats().undone, 1);
  EXPECT_EQ(nr.stats().undone * 2, nr.stats().rips);  // every rip-up of the run was undone
  // the final round, too: routing b and one a is no gain (two before)
  EXPECT_EQ(nr.stats().final_round, 1u);
  EXPECT_EQ(nr.stats().final_round_routed, 0u);
  EXPECT_NE(nr.outcomes()[2].reason.find("in the final round routed no more nets and was undone"), std::string::npos)
      << nr.outcomes()[2].reason;
  EXPECT_EQ(nr.outcomes()[0].wires, (std::vector<std::vector<Point>>{{{0, 50}, {100, 50}}}));
  const geom::NormalizedObstacles none = geom::normalize_obstacles({}, domain);
  EXPECT_TRUE(router::check_routes(none, check_nets(nets, nr), {2, 2}).problems.empty());
}

// NetRouterOptions::search_windows: a net shut out of its first two windows by another net's wire
// is taken as blocked while the rounds last, and the last pass routes it round its detour. A
// wall of blockage across the layout has a gap, which net b's short wire plugs (b goes first:
// shortest first); a's only way is over the wall's top, 45,000 above its pins, outside its
// second window (margin 4 x 4,036). With no rip-up allowed the rounds cannot help; a must still
// be routed, by the last pass, with the wires the unlimited search gives.
TEST(NetRouter, TheLastPassRoutesADetourBeyondTheWindowLimit) {
  const geom::Box domain{{0, 0}, {10000, 100000}};
  const std::vector<Polygon> wall{{{{4900, 0}, {5100, 0}, {5100, 49000}, {4900, 49000}}, {}},
                                  {{{4900, 51000}, {5100, 51000}, {5100, 95000}, {4900, 95000}}, {}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(wall, domain);
  std::vector<router::NetPins> nets(2);
  nets[0] = {"a", {Polygon{{{1000, 50000}}, {}}, Polygon{{{9000, 50000}}, {}}}};
  nets[1] = {"b", {Polygon{{{5000, 49000}}, {}}, Polygon{{{5000, 51000}}, {}}}};
  auto run = [&](int search_windows, bool final_round = false) {
    router::NetRouterOptions o;
    o.max_rips = 0;
    o.search_windows = search_windows;
    o.final_round = final_round;  // (it would rip b up: see the end)
    auto nr = std::make_unique<router::NetRouter>(norm.domain, norm.obstacles, nets, router::NetRules{0, 0}, o);
    nr->run(router::NetRouter::l1_router(false));
    return nr;
  };
  const auto limited = run(2), unlimited = run(0);
  EXPECT_EQ(limited->order(), (std::vector<std::size_t>{1, 0}));
  for (const auto* nr : {limited.get(), unlimited.get()}) {
    ASSERT_TRUE(nr->outcomes()[0].routed);
    ASSERT_TRUE(nr->outcomes()[1].routed);
    EXPECT_TRUE(router::check_routes(norm, check_nets(nets, *nr), {0, 0}).problems.empty());
  }
  EXPECT_EQ(limited->outcomes()[0].wires, unlimited->outcomes()[0].wires);
  const std::int64_t len = l1_len(limited->outcomes()[0]);
  EXPECT_EQ(len, 8000 + 2 * 45000);  // over the wall's top at y = 95,000
  // limited: a stopped at the limit (first pass and rounds), then routed by the last pass
  EXPECT_EQ(limited->stats().first_pass, 1u);
  EXPECT_GE(limited->stats().capped, 2);
  EXPECT_EQ(limited->stats().last_pass, 1u);
  EXPECT_EQ(limited->stats().last_pass_routed, 1u);
  // unlimited: a follows its detour in the first pass
  EXPECT_EQ(unlimited->stats().first_pass, 2u);
  EXPECT_EQ(unlimited->stats().capped, 0);
  EXPECT_EQ(unlimited->stats().last_pass, 0u);
  // The final round rips b up (whatever its rips): a goes through the gap, and b then round a's
  // end at x = 1,000 (the domain starts at 0), both routed, far shorter; nothing is left for the
  // last pass.
  const auto final = run(2, true);
  EXPECT_EQ(final->stats().final_round, 1u);
  EXPECT_EQ(final->stats().final_round_routed, 1u);
  EXPECT_EQ(final->stats().last_pass, 0u);
  ASSERT_TRUE(final->outcomes()[0].routed);
  ASSERT_TRUE(final->outcomes()[1].routed);
  EXPECT_EQ(final->outcomes()[0].wires, (std::vector<std::vector<Point>>{{{1000, 50000}, {9000, 50000}}}));
  EXPECT_TRUE(router::check_routes(norm, check_nets(nets, *final), {0, 0}).problems.empty());
}

// The window limit stops only a net the other nets' wires keep apart (since 2026-12-06): with
// the gap walled up, the blockages alone keep a's pins apart in its first two windows, no rip-up
// could join them there, and a follows its detour over the wall's top in the first pass, with a
// limit of one window or two, or none (capped, it waited for the last pass, where wires placed since may shut its way). With
// the gap open and b's wire plugging it, a is stopped as above: the pins meet in the second
// window among the blockages alone.
TEST(NetRouter, TheWindowLimitDoesNotStopANetTheBlockagesAloneKeepApart) {
  const geom::Box domain{{0, 0}, {10000, 100000}};
  const std::vector<Polygon> solid{{{{4900, 0}, {5100, 0}, {5100, 95000}, {4900, 95000}}, {}}};
  const std::vector<router::NetPins> nets{{"a", {Polygon{{{1000, 50000}}, {}}, Polygon{{{9000, 50000}}, {}}}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(solid, domain);
  for (const int search_windows : {1, 2, 0}) {
    router::NetRouterOptions o;
    o.max_rips = 0;
    o.final_round = false;
    o.search_windows = search_windows;
    router::NetRouter nr(norm.domain, norm.obstacles, nets, router::NetRules{0, 0}, o);
    nr.run(router::NetRouter::l1_router(false));
    ASSERT_TRUE(nr.outcomes()[0].routed) << search_windows;
    EXPECT_EQ(l1_len(nr.outcomes()[0]), 8000 + 2 * 45000) << search_windows;
    EXPECT_EQ(nr.stats().first_pass, 1u) << search_windows;
    EXPECT_EQ(nr.stats().capped, 0) << search_windows;
    EXPECT_EQ(nr.stats().last_pass, 0u) << search_windows;
    EXPECT_TRUE(router::check_routes(norm, check_nets(nets, nr), {0, 0}).problems.empty());
  }
}

// A wall across the whole domain: a net with a pin on each side can never be routed. The free
// components among the blockages alone, built once per run (NetRouterOptions::superset), stop its
// attempts at their first window that finds no way, in every pass and at every level; before
// 2026-12-06 its windows grew to the whole domain in the first pass, and its way alone did so again
// in the rounds (a generated layout of 2,000 nets with such a wall: 115 s against 58 s without
// it). The outcomes are the same with and without them; "detour" finds no way in its first window
// (a bar between its pins) and is routed in a wider one. Variants: rules w = s = 10 (grown edges),
// a wall of two blockages that touch at a corner (a pinch no wire passes), and a wall with a gap
// 20 wide far from the nets, open among the plain blockages and shut by the clearance of w = s =
// 10: the nets across are then ROUTE-0010, found by explaining them at the Plain level, where
// the components do not apply (a review found them applied there: the nets were ROUTE-0002).
TEST(NetRouter, AWallAcrossTheDomainIsFoundOnceNotByGrowingWindows) {
  const geom::Box domain{{0, 0}, {10000, 100000}};
  const Polygon bar{{{1900, 30000}, {2100, 30000}, {2100, 45000}, {1900, 45000}}, {}};
  const std::vector<Polygon> straight{{{{4900, 0}, {5100, 0}, {5100, 100000}, {4900, 100000}}, {}}, bar};
  const std::vector<Polygon> pinched{{{{4900, 0}, {5100, 0}, {5100, 60000}, {4900, 60000}}, {}},
                                     {{{5100, 60000}, {5300, 60000}, {5300, 100000}, {5100, 100000}}, {}}, bar};
  const std::vector<Polygon> slit{{{{4900, 0}, {5100, 0}, {5100, 98000}, {4900, 98000}}, {}},
                                  {{{4900, 98020}, {5100, 98020}, {5100, 100000}, {4900, 100000}}, {}}, bar};
  const std::vector<router::NetPins> nets{
      {"across", {Polygon{{{1000, 50000}}, {}}, Polygon{{{9000, 50000}}, {}}}},
      {"west", {Polygon{{{1000, 10000}}, {}}, Polygon{{{3000, 20000}}, {}}, Polygon{{{2000, 90000}}, {}}}},
      {"east", {Polygon{{{6000, 10000}}, {}}, Polygon{{{9000, 30000}}, {}}}},
      {"across2", {Polygon{{{4000, 80000}}, {}}, Polygon{{{8000, 20000}}, {}}}},
      {"detour", {Polygon{{{1000, 40000}}, {}}, Polygon{{{3000, 40000}}, {}}}},
  };
  for (const int wall : {0, 1, 2})
    for (const std::int64_t rule : {0, 10}) {
      if (wall == 2 && rule == 0) continue;  // (the slit is open: the nets across are routed through it)
      const std::string at = std::string(wall == 0 ? "straight" : wall == 1 ? "pinched" : "slit") + " wall, w = s = " + std::to_string(rule);
      const geom::NormalizedObstacles norm = geom::normalize_obstacles(wall == 0 ? straight : wall == 1 ? pinched : slit, domain);
      auto run = [&](bool superset) {
        router::NetRouterOptions o;
        o.superset = superset;
        auto nr = std::make_unique<router::NetRouter>(norm.domain, norm.obstacles, nets, router::NetRules{rule, rule}, o);
        nr->run(router::NetRouter::l1_router(false));
        return nr;
      };
      const auto with = run(true), without = run(false);
      for (std::size_t i = 0; i < nets.size(); ++i) {
        const router::NetOutcome &a = with->outcomes()[i], &b = without->outcomes()[i];
        EXPECT_EQ(a.routed, i == 1 || i == 2 || i == 4) << at << ": " << nets[i].name << ": " << a.reason;
        EXPECT_EQ(a.routed, b.routed) << at << ": " << nets[i].name;
        EXPECT_EQ(a.code, b.code) << at << ": " << nets[i].name;
        EXPECT_EQ(a.reason, b.reason) << at << ": " << nets[i].name;
        EXPECT_EQ(a.wires, b.wires) << at << ": " << nets[i].name;
      }
      EXPECT_EQ(with->outcomes()[0].code, wall == 2 ? "ROUTE-0010" : "ROUTE-0002") << at;
      EXPECT_TRUE(router::check_routes(norm, check_nets(nets, *with), {rule, rule}).problems.empty()) << at;
      std::printf("%s: whole-domain windows %lld with, %lld without; apart among the blockages %lld\n", at.c_str(),
                  static_cast<long long>(with->stats().whole), static_cast<long long>(without->stats().whole),
                  static_cast<long long>(with->stats().blockages_apart));
      EXPECT_GT(without->stats().whole, 0) << at;
      // each net across stopped once in the first pass (the grown blockages' components) and, on
      // the straight and pinched walls, once more when explained at the Plain level (the plain
      // blockages' own); the slit is open there, so those two grow and route through it
      EXPECT_GE(with->stats().blockages_apart, wall == 2 ? 2 : 4) << at;
      // (the whole domain is also the window of "west", whose pins span most of it)
      EXPECT_LT(with->stats().whole, without->stats().whole) << at;
    }
}

// The window limit also stops a net whose pins were apart in its first window because of other
// nets' wires and whose way in the second is a detour that window cannot prove shortest (since
// 2026-12-06: before, the window grew on to prove it, which on 10^4 planted nets cost a third of
// the rip-up rounds' time); a net the blockages alone send round such a detour grows its window
// as before (no rip-up could help it). Pins of a at (0, 0) and (1,000, 0); a wall at x = 490..510
// up to y = 100 (a goes over it, 1,202 long, among the blockages alone); net b, shorter, goes
// first, straight up from the wall's top at (500, 100) to (500, 700); a shelf from x = -1,800 to
// b's wire at y = 600..620. Then a's only way goes left round the shelf, over b's end and down:
// 6,002 long (along the top of b's grown wire, y = 701). Its first window (margin 536) holds no way; its second (margin 2,144) holds this
// one, but a way out through its sides is at least 1,000 + 2 x 2,142 = 5,284, so it proves
// nothing. With no rip-up allowed a is taken as blocked in the first pass and the rounds, and the
// last pass routes it, with the wire the unlimited search gives in its first pass. With b's wire
// made a blockage instead (one net), a follows the detour in the first pass, limit or not.
TEST(NetRouter, TheLastPassRoutesADetourItsSecondWindowCannotProve) {
  const geom::Box domain{{-2500, -3000}, {3500, 3000}};
  const Polygon wall{{{490, -3000}, {510, -3000}, {510, 100}, {490, 100}}, {}};
  const Polygon shelf{{{-1800, 600}, {499, 600}, {499, 620}, {-1800, 620}}, {}};
  const router::NetPins a{"a", {Polygon{{{0, 0}}, {}}, Polygon{{{1000, 0}}, {}}}};
  const router::NetPins b{"b", {Polygon{{{500, 100}}, {}}, Polygon{{{500, 700}}, {}}}};
  auto run = [&](const std::vector<Polygon>& blocks, const std::vector<router::NetPins>& nets, int search_windows) {
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(blocks, domain);
    router::NetRouterOptions o;
    o.max_rips = 0;
    o.final_round = false;
    o.search_windows = search_windows;
    auto nr = std::make_unique<router::NetRouter>(norm.domain, norm.obstacles, nets, router::NetRules{0, 0}, o);
    nr->run(router::NetRouter::l1_router(false));
    for (const auto& o2 : nr->outcomes()) EXPECT_TRUE(o2.routed) << o2.reason;
    EXPECT_TRUE(router::check_routes(norm, check_nets(nets, *nr), {0, 0}).problems.empty());
    return nr;
  };
  // b's wire to blame: capped while the limit holds
  const std::vector<router::NetPins> two{a, b};
  const auto limited = run({wall, shelf}, two, 2), unlimited = run({wall, shelf}, two, 0);
  EXPECT_EQ(limited->order(), (std::vector<std::size_t>{1, 0}));
  EXPECT_EQ(limited->outcomes()[0].wires, unlimited->outcomes()[0].wires);
  const std::int64_t len = l1_len(limited->outcomes()[0]);
  EXPECT_EQ(len, 6002);
  EXPECT_EQ(limited->stats().first_pass, 1u);
  EXPECT_GE(limited->stats().capped, 1);
  EXPECT_EQ(limited->stats().last_pass, 1u);
  EXPECT_EQ(limited->stats().last_pass_routed, 1u);
  EXPECT_EQ(unlimited->stats().first_pass, 2u);
  EXPECT_EQ(unlimited->stats().capped, 0);
  // the blockages alone to blame: b's wire a blockage, a alone routed in the first pass
  const Polygon b_wire{{{499, 99}, {501, 99}, {501, 701}, {499, 701}}, {}};
  const auto alone = run({wall, shelf, b_wire}, {a}, 2);
  EXPECT_EQ(l1_len(alone->outcomes()[0]), 6002);
  EXPECT_EQ(alone->stats().first_pass, 1u);
  EXPECT_EQ(alone->stats().capped, 0);
  EXPECT_EQ(alone->stats().last_pass, 0u);
}

// A net whose only way runs at exactly the clearance between two other nets' wires: legal (the
// checker passes it), but the grown wires touch there and merge, closing the gap (a limitation).
// Its reason names both nets (the way alone enters neither, so the wire test alone named none
// and the net kept the full attempt's own reason, walled in: found on planted benchmark nets).
TEST(NetRouter, AGapOfWidthZeroBetweenWiresIsNamed) {
  const geom::Box domain{{0, 0}, {100, 100}};
  // a band 47 < y < 53 between two blockages; w = 0, s = 1: wires keep 1 from blockages and
  // from each other
  const std::vector<Polygon> walls{{{{0, 0}, {100, 0}, {100, 47}, {0, 47}}, {}}, {{{0, 53}, {100, 53}, {100, 100}, {0, 100}}, {}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(walls, domain);
  std::vector<router::NetPins> nets(3);
  nets[0] = {"a", {Polygon{{{20, 49}}, {}}, Polygon{{{80, 49}}, {}}}};
  nets[1] = {"c", {Polygon{{{30, 51}}, {}}, Polygon{{{70, 51}}, {}}}};  // its pins away from a's
  nets[2] = {"b", {Polygon{{{5, 50}}, {}}, Polygon{{{95, 50}}, {}}}};
  const router::NetRules rules{0, 1};
  // the wire along y = 50 is legal among a's and c's straight wires
  const std::vector<std::vector<std::vector<Point>>> ws{{{{20, 49}, {80, 49}}}, {{{30, 51}, {70, 51}}}, {{{5, 50}, {95, 50}}}};
  EXPECT_TRUE(router::check_routes(norm, check_nets(nets, ws), {0, 1}).problems.empty());
  router::NetRouter nr(norm.domain, norm.obstacles, nets, rules);
  nr.run(router::NetRouter::l1_router(false));
  ASSERT_TRUE(nr.outcomes()[0].routed);
  ASSERT_TRUE(nr.outcomes()[1].routed);
  const router::NetOutcome& o = nr.outcomes()[2];
  ASSERT_FALSE(o.routed);
  EXPECT_EQ(o.code, "ROUTE-0012") << o.reason;
  EXPECT_EQ(o.blockers, (std::vector<std::size_t>{0, 1}));
  EXPECT_NE(o.reason.find("gap of width zero"), std::string::npos) << o.reason;
  EXPECT_NE(o.reason.find("\"a\""), std::string::npos) << o.reason;
  EXPECT_NE(o.reason.find("\"c\""), std::string::npos) << o.reason;
}

// A net that cannot be routed says why, at the first level where it fails: walled in by a ring
// of blockage (the router's own reason), shut out by the clearance (a gap too narrow for w/2 + s
// on each side), or cut off by the pins of another net.
TEST(NetRouter, ReasonsForNetsLeftUnrouted) {
  const geom::Box domain{{0, 0}, {100, 100}};
  // two blockages 6 apart: a wire at x = 50 keeps 3 from both. A gap wider than 2a (a =
  // ceil(w/2) + s) takes it; one of exactly 2a does not (the grown blockages touch and merge:
  // a limitation, see net_router.h), nor a narrower one.
  const std::vector<Polygon> walls{{{{0, 40}, {47, 40}, {47, 60}, {0, 60}}, {}}, {{{53, 40}, {100, 40}, {100, 60}, {53, 60}}, {}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(walls, domain);
  std::vector<router::NetPins> nets(1);
  nets[0] = {"x", {Polygon{{{50, 10}}, {}}, Polygon{{{50, 90}}, {}}}};
  for (const auto& [rules, routed] : std::vector<std::pair<router::NetRules, bool>>{{{2, 1}, true}, {{2, 2}, false}, {{3, 2}, false}}) {
    router::NetRouter nr(norm.domain, norm.obstacles, nets, rules);
    nr.run(router::NetRouter::l1_router(false));
    EXPECT_EQ(nr.outcomes()[0].routed, routed) << rules.wire_width << " " << rules.spacing;
    if (!routed) {
      EXPECT_EQ(nr.outcomes()[0].code, "ROUTE-0010");
    }
  }
  {
    // a gap of 4; the short net y sits in it (routed first), its pins block x even alone
    const std::vector<Polygon> narrow{{{{0, 40}, {48, 40}, {48, 60}, {0, 60}}, {}}, {{{52, 40}, {100, 40}, {100, 60}, {52, 60}}, {}}};
    const geom::NormalizedObstacles nn = geom::normalize_obstacles(narrow, domain);
    std::vector<router::NetPins> two = nets;
    two.push_back({"y", {Polygon{{{50, 40}}, {}}, Polygon{{{50, 60}}, {}}}});
    router::NetRouter nr(nn.domain, nn.obstacles, two, {0, 1});
    nr.run(router::NetRouter::l1_router(false));
    EXPECT_TRUE(nr.outcomes()[1].routed);
    const router::NetOutcome& o = nr.outcomes()[0];
    EXPECT_FALSE(o.routed);
    EXPECT_EQ(o.code, "ROUTE-0011") << o.reason;
    EXPECT_EQ(o.blockers, (std::vector<std::size_t>{1}));
  }
  {
    const std::vector<Polygon> ring{{{{30, 30}, {70, 30}, {70, 70}, {30, 70}}, {{{40, 40}, {40, 60}, {60, 60}, {60, 40}}}}};
    const geom::NormalizedObstacles rn = geom::normalize_obstacles(ring, domain);
    std::vector<router::NetPins> in{{"z", {Polygon{{{50, 50}}, {}}, Polygon{{{5, 5}}, {}}}}};
    router::NetRouter nr(rn.domain, rn.obstacles, in, {2, 2});
    nr.run(router::NetRouter::l1_router(false));
    EXPECT_FALSE(nr.outcomes()[0].routed);
    EXPECT_EQ(nr.outcomes()[0].code, "ROUTE-0002");
  }
}

// Pads that meet where the only points keeping the clearance lie inside them, in a pocket the
// clearance's circles bound: w = 0, s = 5; a pad 0,0 10,10 with a 1 x 1 blockage at the middle
// of each side (outside, touching it) and a pad 4,4 6,6 inside it. Every point of the pads'
// edges, their vertices, the grown blockages' vertices and crossings with the pads' edges, and
// where the circles of radius 5 round the blockage corners cross the pads' edges, lies within 5
// of a blockage; 5,5 lies exactly 5 from all four. Before 2026-12-06 those were the only points
// tried, and the net was refused (ROUTE-0010, "its pins meet") without the exact gaps (in the
// scaled plane the multiples of K next to those points happened to reach 5,5); now a pin of at
// most 4,096 lattice points is read whole when they fail, and the net is routed with a wire of
// one point there, which the checker passes.
TEST(NetRouter, PadsMeetingInAPocketTheCirclesBoundAreRouted) {
  const geom::Box domain{{-20, -20}, {30, 30}};
  auto rect = [](geom::Coord x0, geom::Coord y0, geom::Coord x1, geom::Coord y1) {
    return Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
  };
  const std::vector<Polygon> blocks{rect(5, -1, 6, 0), rect(-1, 4, 0, 5), rect(4, 10, 5, 11), rect(10, 5, 11, 6)};
  const std::vector<router::NetPins> nets{{"n", {rect(0, 0, 10, 10), rect(4, 4, 6, 6)}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(blocks, domain);
  const router::NetRules rules{0, 5};
  for (const bool exact : {false, true})
    for (const bool oct : {false, true}) {
      const std::string at = std::string(oct ? "octilinear" : "rectilinear") + (exact ? ", exact gaps" : "");
      router::NetRouterOptions o;
      o.exact_gaps = exact;
      o.octilinear = oct;
      router::NetRouter nr(norm.domain, norm.obstacles, nets, rules, o);
      nr.run(oct ? router::NetRouter::oct_router(false) : router::NetRouter::l1_router(false));
      const router::NetOutcome& out = nr.outcomes()[0];
      EXPECT_TRUE(out.routed) << at << ": " << out.code << " " << out.reason;
      if (!out.routed) continue;
      ASSERT_EQ(out.wires.size(), 1u) << at;  // a wire of one point (written once, or twice as here)
      for (const Point q : out.wires[0]) EXPECT_EQ(q, (Point{5, 5})) << at;
      EXPECT_TRUE(router::check_routes(norm, check_nets(nets, nr), {rules.wire_width, rules.spacing}).problems.empty()) << at;
    }
}

// Pads of one net that touch, overlap or nest (a cluster per net, as flows write a pin's several
// shapes), beside blockages they touch or come within the clearance of, and a pin apart: a net's
// pads are free space for it (cut out of the grown blockages), so its wires could run over or
// along them within the clearance, where the checker measures every wire (three findings of the
// fuzz search of 2026-12-06, route exiting 0 and taut check failing CHECK-0007). Every routed net
// passes the independent checker, under every metric (rectilinear and octilinear, shortest-path
// and Steiner trees, combined and link), with and without exact gaps.
TEST(NetRouter, TouchingPadsBesideBlockagesPassTheChecker) {
  using geom::Box;
  using geom::Coord;
  auto c = [](std::int64_t v) { return static_cast<Coord>(v); };
  auto overlap = [](const Box& a, const Box& b) { return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y; };
  auto rect = [](const Box& b) { return Polygon{{b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}, {}}; };
  int failed = 0;
  std::int64_t nets = 0, routed = 0, meeting = 0, near = 0, stuck = 0, grouped = 0;
  const char* labels[] = {"l1", "l1 steiner", "oct", "oct steiner", "combined", "link"};
  // 1,200 seeds, and the regression seeds of a run of 30,000: wires of one point that found a
  // point keeping the clearance only by the exact Euclidean test against the blockages (the grown
  // blockages are L-infinity neighbourhoods) and the candidates beyond the pins' vertices (5543,
  // 13201), and nets whose pins meet and lie within the clearance everywhere, refused (ROUTE-0010)
  std::vector<int> seeds;
  const int n = std::getenv("TAUT_PAD_SEEDS") ? std::atoi(std::getenv("TAUT_PAD_SEEDS")) : sanitized_share(1200, 10);
  for (int seed = 1; seed <= n; ++seed) seeds.push_back(seed);
  // (324 and 418: a group of pads meeting only through pinches beside a pin apart, routed one pin
  // of each group since 2026-12-06, kept so that the sanitizers' share runs them too)
  for (const int seed : {5543, 13201, 4580, 13330, 25067, 28004, 324, 418})
    if (seed > n) seeds.push_back(seed);
  for (const int seed : seeds) {
    std::mt19937 rng(static_cast<unsigned>(990000 + seed));
    RandomLayout L;
    const Box domain{{0, 0}, {48, 48}};
    L.rules.wire_width = static_cast<std::int64_t>(rng() % 7);
    L.rules.spacing = static_cast<std::int64_t>(rng() % 6);
    const std::int64_t cl = (L.rules.wire_width + 1) / 2 + L.rules.spacing;  // a blockage's clearance, rounded up
    std::vector<Box> blocks;
    for (int t = 0, want = 1 + static_cast<int>(rng() % 4); t < 40 && static_cast<int>(blocks.size()) < want; ++t) {
      const std::int64_t x = rng() % 44, y = rng() % 44;
      const Box b{{c(x), c(y)}, {c(std::min<std::int64_t>(48, x + 1 + rng() % 10)), c(std::min<std::int64_t>(48, y + 1 + rng() % 10))}};
      if (std::none_of(blocks.begin(), blocks.end(), [&](const Box& o) { return overlap(o, b); })) blocks.push_back(b);
    }
    std::vector<Polygon> polys;
    for (const Box& b : blocks) polys.push_back(rect(b));
    L.norm = geom::normalize_obstacles(polys, domain);
    router::L1Router plain(L.norm.domain, L.norm.obstacles);
    std::vector<Box> taken;  // the other nets' pins' boxes, grown by 2 (w + s) + 2
    const std::int64_t apart = 2 * (L.rules.wire_width + L.rules.spacing) + 2;
    auto fits = [&](const Box& b) {
      if (b.lo.x < 0 || b.lo.y < 0 || b.hi.x > 48 || b.hi.y > 48 || b.lo.x >= b.hi.x || b.lo.y >= b.hi.y) return false;
      if (std::any_of(blocks.begin(), blocks.end(), [&](const Box& o) { return overlap(o, b); })) return false;
      return std::none_of(taken.begin(), taken.end(), [&](const Box& o) { return geom::boxes_meet(o, b); });
    };
    std::vector<Box> mine_all;
    for (int i = 0, count = 1 + static_cast<int>(rng() % 2); i < count; ++i) {
      router::NetPins net;
      net.name = "n" + std::to_string(i);
      std::vector<Box> pads;
      // the first pad beside a blockage: on one of its sides, 0 .. cl + 1 away
      for (int t = 0; t < 60 && pads.empty(); ++t) {
        const Box o = blocks[rng() % blocks.size()];
        const std::int64_t gap = rng() % (cl + 2), w = 1 + rng() % 8, h = 1 + rng() % 8;
        const std::int64_t x = o.lo.x - w + static_cast<std::int64_t>(rng() % (o.hi.x - o.lo.x + w + 1));
        const std::int64_t y = o.lo.y - h + static_cast<std::int64_t>(rng() % (o.hi.y - o.lo.y + h + 1));
        Box b;
        switch (rng() % 4) {
          case 0: b = {{c(x), c(o.hi.y + gap)}, {c(x + w), c(o.hi.y + gap + h)}}; break;
          case 1: b = {{c(x), c(o.lo.y - gap - h)}, {c(x + w), c(o.lo.y - gap)}}; break;
          case 2: b = {{c(o.hi.x + gap), c(y)}, {c(o.hi.x + gap + w), c(y + h)}}; break;
          default: b = {{c(o.lo.x - gap - w), c(y)}, {c(o.lo.x - gap), c(y + h)}}; break;
        }
        if (fits(b)) pads.push_back(b);
      }
      if (pads.empty()) continue;
      // more pads, each touching (an edge or a corner), overlapping or inside one before it
      for (int t = 0, want = 1 + static_cast<int>(rng() % 3); t < 60 && static_cast<int>(pads.size()) <= want; ++t) {
        const Box o = pads[rng() % pads.size()];
        const std::int64_t w = 1 + rng() % 8, h = 1 + rng() % 8;
        const std::int64_t x = o.lo.x - w + static_cast<std::int64_t>(rng() % (o.hi.x - o.lo.x + w + 1));
        const std::int64_t y = o.lo.y - h + static_cast<std::int64_t>(rng() % (o.hi.y - o.lo.y + h + 1));
        Box b;
        switch (rng() % 7) {
          case 0: b = {{c(x), o.hi.y}, {c(x + w), c(o.hi.y + h)}}; break;
          case 1: b = {{c(x), c(o.lo.y - h)}, {c(x + w), o.lo.y}}; break;
          case 2: b = {{o.hi.x, c(y)}, {c(o.hi.x + w), c(y + h)}}; break;
          case 3: b = {{c(o.lo.x - w), c(y)}, {o.lo.x, c(y + h)}}; break;
          case 4: b = {o.hi, {c(o.hi.x + w), c(o.hi.y + h)}}; break;  // a corner
          case 5: b = {{c(x + w / 2), c(y + h / 2)}, {c(x + w / 2 + w), c(y + h / 2 + h)}}; break;  // overlapping, maybe
          default: {  // inside
            const std::int64_t x0 = o.lo.x + rng() % (o.hi.x - o.lo.x), y0 = o.lo.y + rng() % (o.hi.y - o.lo.y);
            b = {{c(x0), c(y0)}, {c(x0 + 1 + rng() % (o.hi.x - x0)), c(y0 + 1 + rng() % (o.hi.y - y0))}};
          }
        }
        if (fits(b) && std::find(pads.begin(), pads.end(), b) == pads.end()) pads.push_back(b);
      }
      std::vector<Point> points;
      if (rng() % 3 == 0) {  // a point pin on a pad's corner or side
        const Box o = pads[rng() % pads.size()];
        points.push_back(rng() % 2 ? o.hi : Point{o.lo.x, c(o.lo.y + rng() % (o.hi.y - o.lo.y + 1))});
      }
      // a pin apart: a point or a pad, free, away from the other nets' pins
      for (int t = 0; t < 100; ++t) {
        const Point p{c(rng() % 49), c(rng() % 49)};
        const Box b{p, rng() % 3 == 0 ? Point{c(p.x + 1 + rng() % 5), c(p.y + 1 + rng() % 5)} : p};
        if (b.lo == b.hi ? !(plain.is_free(p) && std::none_of(taken.begin(), taken.end(), [&](const Box& o) { return geom::boxes_meet(o, b); }))
                         : !fits(b))
          continue;
        if (b.lo == b.hi) points.push_back(p);
        else pads.push_back(b);
        break;
      }
      for (const Box& b : pads) net.pins.push_back(rect(b));
      for (const Point p : points)
        if (std::none_of(net.pins.begin(), net.pins.end(), [&](const Polygon& g) { return g.outer.size() == 1 && g.outer[0] == p; }))
          net.pins.push_back(Polygon{{p}, {}});
      if (net.pins.size() < 2) continue;
      for (std::size_t a = 0; a < pads.size(); ++a)
        for (std::size_t b = a + 1; b < pads.size(); ++b) meeting += geom::boxes_meet(pads[a], pads[b]);
      for (const Box& b : pads) {
        taken.push_back(geom::grown_box(b, apart));
        near += std::any_of(blocks.begin(), blocks.end(), [&](const Box& o) { return geom::boxes_meet(geom::grown_box(o, cl), b); });
      }
      for (const Polygon& g : net.pins)
        if (g.outer.size() == 1) taken.push_back(geom::grown_box(Box{g.outer[0], g.outer[0]}, apart));
      L.nets.push_back(std::move(net));
    }
    if (L.nets.empty()) continue;
    const int kind = seed % 6;
    const bool exact = seed % 4 < 2;
    const std::string at = "seed " + std::to_string(990000 + seed) + " " + labels[kind] + (exact ? " exact gaps" : "") + " (w " +
                           std::to_string(L.rules.wire_width) + ", s " + std::to_string(L.rules.spacing) + ")";
    std::unique_ptr<router::NetRouter> nr;
    if (kind < 4) {
      router::NetRouterOptions opt;
      opt.octilinear = kind >= 2;
      opt.exact_gaps = exact;
      nr = std::make_unique<router::NetRouter>(L.norm.domain, L.norm.obstacles, L.nets, L.rules, opt);
      nr->run(opt.octilinear ? router::NetRouter::oct_router(kind % 2 == 1) : router::NetRouter::l1_router(kind % 2 == 1));
    } else {
      BendRun b = bend_run(L, kind == 5 ? 5 : 2);  // link, or C = 7
      b.options.exact_gaps = exact;
      nr = std::make_unique<router::NetRouter>(b.covered.domain, b.covered.obstacles, L.nets, b.rules, b.options);
      nr->run(b.route);
    }
    const router::CheckResult r = router::check_routes(L.norm, check_nets(L.nets, *nr), {L.rules.wire_width, L.rules.spacing});
    for (const auto& p : r.problems)
      if (failed++ < 8) ADD_FAILURE() << at << ": " << p.message;
    nets += static_cast<std::int64_t>(L.nets.size());
    grouped += nr->stats().group_choices;
    for (std::size_t i = 0; i < nr->outcomes().size(); ++i) {
      const router::NetOutcome& o = nr->outcomes()[i];
      routed += o.routed;
      if (!o.routed && o.reason.empty() && failed++ < 8) ADD_FAILURE() << at << ": a net not routed has no reason";
      if (o.routed || o.reason.find("its pins meet") == std::string::npos) continue;
      // refused as pins that meet where no point keeps the blockages' clearance: by brute force,
      // no integer point of its pins is ceil(w/2) + s from every blockage
      ++stuck;
      const std::int64_t need = (L.rules.wire_width + 1) / 2 + L.rules.spacing;
      for (const Polygon& g : L.nets[i].pins) {
        const Box gb = geom::bounding_box(g.outer);
        for (std::int64_t x = gb.lo.x; x <= gb.hi.x; ++x)
          for (std::int64_t y = gb.lo.y; y <= gb.hi.y; ++y) {
            bool keeps = true;
            for (const Box& b : blocks) {
              const std::int64_t dx = std::max<std::int64_t>({b.lo.x - x, 0, x - b.hi.x}), dy = std::max<std::int64_t>({b.lo.y - y, 0, y - b.hi.y});
              keeps = keeps && dx * dx + dy * dy >= need * need;
            }
            if (keeps && failed++ < 8) ADD_FAILURE() << at << ": net " << i << " refused, but " << x << "," << y << " keeps the clearance";
          }
      }
    }
  }
  std::printf("%lld nets: %lld routed (%lld refused: pins that meet within the clearance everywhere); %lld pairs of pads of "
              "a net that meet, %lld pads within a blockage's clearance; %lld attempts routed one pin of each group that meets\n",
              static_cast<long long>(nets), static_cast<long long>(routed), static_cast<long long>(stuck), static_cast<long long>(meeting),
              static_cast<long long>(near), static_cast<long long>(grouped));
  EXPECT_EQ(failed, 0);
  EXPECT_GT(routed, nets / 2);
  EXPECT_GT(meeting, sanitized_share(500, 10));
  EXPECT_GT(near, sanitized_share(1000, 10));
  EXPECT_GE(stuck, 4);  // the four regression seeds
  EXPECT_GT(grouped, 0);  // (the fallback of 2026-12-06 is exercised: groups meeting only through pinches)
}

}  // namespace net_router_test
}  // namespace taut::test
