// router::L1Router between shape pins (and a shape pin and a point pin) against brute force:
// the smallest L1Reference distance over every pair of free integer points of the two closed
// pin shapes. Integer points suffice for the reference because every candidate of
// L1Router::pin_candidates() is an integer point for edges at 0, 45 and 90 degrees, and the
// wire must have integer vertices anyway; the brute force does not use the candidates, so it
// checks the claim that they contain an optimal end. Layouts are the coarse-grid families of
// tests/support/wavefront_cases.h (degenerate: shared x and y, touching blockages, diagonals);
// the shapes are small rectangles, diamonds, 45-degree triangles and L-shapes anchored at the
// layouts' query candidates, so they touch blockages, sit on their corners and edges, and
// straddle pinches. Shapes whose interior meets a blockage are refused by the router
// (pin_meets_obstacle); they are checked against a quarter-lattice probe and skipped.
#include "router/l1_router.h"
#include "router/oct_router.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "geom/predicates.h"
#include "oracle/l1_oracle.h"
#include "oracle/oct_oracle.h"
#include "support/sanitized.h"
#include "support/wavefront_cases.h"

namespace pin_test {

using taut::geom::Box;
using taut::geom::Location;
using taut::geom::Point;
using taut::geom::Polygon;
using taut::oracle::L1Reference;
using taut::oracle::OctilinearReference;
using taut::router::L1Router;
using taut::router::OctRouter;
using taut::router::WireStatus;

bool in_pin(Point p, const Polygon& pin) {
  if (pin.outer.size() == 1) return p == pin.outer[0];
  return taut::geom::locate(p, pin) != Location::Outside;
}

std::vector<Point> integer_points(const Polygon& pin) {
  if (pin.outer.size() == 1) return {pin.outer[0]};
  Box b{pin.outer[0], pin.outer[0]};
  for (const Point v : pin.outer) {
    b.lo = {std::min(b.lo.x, v.x), std::min(b.lo.y, v.y)};
    b.hi = {std::max(b.hi.x, v.x), std::max(b.hi.y, v.y)};
  }
  std::vector<Point> out;
  for (int x = b.lo.x; x <= b.hi.x; ++x)
    for (int y = b.lo.y; y <= b.hi.y; ++y)
      if (in_pin({x, y}, pin)) out.push_back({x, y});
  return out;
}

// A small random pin anchored at c: a point, rectangle, diamond, 45-degree triangle or L-shape.
Polygon random_pin(std::mt19937_64& rng, Point c) {
  auto uni = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
  const int sx = uni(0, 1) ? 1 : -1, sy = uni(0, 1) ? 1 : -1;
  Polygon p;
  switch (uni(0, 4)) {
    case 0: p.outer = {c}; break;
    case 1: {
      const int w = uni(1, 4), h = uni(1, 4);
      p.outer = {c, {c.x + w, c.y}, {c.x + w, c.y + h}, {c.x, c.y + h}};
      break;
    }
    case 2: {
      const int r = uni(1, 3);
      p.outer = {{c.x - r, c.y}, {c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}};
      break;
    }
    case 3: {
      const int k = uni(1, 4);
      p.outer = {c, {c.x + sx * k, c.y}, {c.x, c.y + sy * k}};
      break;
    }
    default: {
      const int k = uni(1, 2);
      p.outer = {c, {c.x + 2 * k, c.y}, {c.x + 2 * k, c.y + k}, {c.x + k, c.y + k}, {c.x + k, c.y + 2 * k},
                 {c.x, c.y + 2 * k}};
      break;
    }
  }
  return p;
}

// One-sided check of pin_meets_obstacle(): a quarter-lattice point strictly inside both the pin
// and an obstacle means their interiors meet.
bool probe_meets(const Polygon& pin, const std::vector<Polygon>& obstacles) {
  if (pin.outer.size() == 1) return false;
  std::vector<Polygon> pin4{pin}, obs4 = obstacles;
  auto scale = [](Polygon& p) {
    for (Point& v : p.outer) v = {4 * v.x, 4 * v.y};
    for (auto& h : p.holes)
      for (Point& v : h) v = {4 * v.x, 4 * v.y};
  };
  scale(pin4[0]);
  for (Polygon& o : obs4) scale(o);
  for (const Point q : integer_points(pin4[0])) {
    if (taut::geom::locate(q, pin4[0]) != Location::Inside) continue;
    for (const Polygon& o : obs4)
      if (taut::geom::locate(q, o) == Location::Inside) return true;
  }
  return false;
}

// Router L1Router with L1Reference (rectilinear wires), or OctRouter with OctilinearReference
// (octilinear wires), over `want` pairs of pins.
struct Counts {
  int compared = 0, routed = 0, refused = 0, unreachable = 0, touching = 0, shapes = 0, unsupported = 0, diagonal = 0;
};
bool has_diagonal_edge(const Polygon& pin) {
  bool d = false;
  taut::router::for_each_pin_edge(pin, [&](Point a, Point b) { d = d || (a.x != b.x && a.y != b.y); });
  return d;
}
template <class Router, class Reference>
Counts shape_pins_match_brute_force(int want = 600) {
  int compared = 0, routed = 0, refused = 0, unreachable = 0, touching = 0, shapes = 0, unsupported = 0, diagonal = 0;
  constexpr bool oct = Router::kOctilinear;
  for (std::uint64_t seed = 1; compared < want && seed < 20000; ++seed) {
    const taut::test::WavefrontCase wc = taut::test::make_wavefront_case(seed);
    if (wc.huge || wc.candidates.empty()) continue;
    const Box& d = wc.domain;
    if (std::int64_t{d.hi.x} - d.lo.x > 160 || std::int64_t{d.hi.y} - d.lo.y > 160) continue;
    SCOPED_TRACE("seed " + std::to_string(seed) + " family " + wc.family);
    std::mt19937_64 rng(seed * 7919);
    const Reference ref(wc.domain, wc.obstacles);
    Router router(wc.domain, wc.obstacles);
    for (int q = 0; q < 3; ++q) {
      const Polygon a = random_pin(rng, wc.candidates[rng() % wc.candidates.size()]);
      const Polygon b = random_pin(rng, wc.candidates[rng() % wc.candidates.size()]);
      bool inside_domain = true;
      for (const Polygon* p : {&a, &b})
        for (const Point v : p->outer)
          inside_domain = inside_domain && v.x >= d.lo.x && v.x <= d.hi.x && v.y >= d.lo.y && v.y <= d.hi.y;
      if (!inside_domain) continue;
      // both routers take every shape random_pin draws (edges at 0, 45 and 90 degrees)
      if (!taut::router::pin_shape_supported(a) || !taut::router::pin_shape_supported(b)) {
        ++unsupported;
        continue;
      }
      bool refuse = false;
      for (const Polygon* p : {&a, &b}) {
        const bool meets = router.pin_meets_obstacle(*p).has_value();
        if (probe_meets(*p, wc.obstacles)) {
          EXPECT_TRUE(meets) << "a quarter-lattice point lies in both";
        }
        refuse = refuse || meets;
      }
      if (refuse) {
        ++refused;
        continue;
      }
      shapes += (a.outer.size() > 1) + (b.outer.size() > 1);
      // Brute force over free integer points.
      std::vector<Point> pa, pb;
      for (const Point p : integer_points(a))
        if (ref.is_free(p)) pa.push_back(p);
      for (const Point p : integer_points(b))
        if (ref.is_free(p)) pb.push_back(p);
      std::optional<typename Router::Len> best;
      for (const Point p : pa)
        for (const auto& dist : ref.distances(p, pb))
          if (dist && (!best || *dist < *best)) best = dist;
      const auto w = router.shortest(a, b);
      ++compared;
      diagonal += has_diagonal_edge(a) || has_diagonal_edge(b);
      std::string what = "pins a.outer[0]=(" + std::to_string(a.outer[0].x) + "," + std::to_string(a.outer[0].y) +
                         ") size " + std::to_string(a.outer.size()) + ", b.outer[0]=(" +
                         std::to_string(b.outer[0].x) + "," + std::to_string(b.outer[0].y) + ") size " +
                         std::to_string(b.outer.size());
      if (pa.empty()) {
        EXPECT_EQ(w.status, WireStatus::SourceNotFree) << what;
        continue;
      }
      if (pb.empty()) {
        EXPECT_EQ(w.status, WireStatus::TargetNotFree) << what;
        continue;
      }
      if (!best) {
        EXPECT_EQ(w.status, WireStatus::Unreachable) << what;
        ++unreachable;
        continue;
      }
      if (!w.length.has_value()) {
        ADD_FAILURE() << what << " status " << taut::router::to_string(w.status);
        continue;
      }
      EXPECT_EQ(*w.length, *best) << what;
      if (w.status != WireStatus::Ok) continue;  // NoIntegerStaircase: the length is still exact
      ++routed;
      touching += *best == typename Router::Len{};
      if (w.points.empty()) {
        ADD_FAILURE() << what << ": no points";
        continue;
      }
      EXPECT_TRUE(in_pin(w.points.front(), a)) << what;
      EXPECT_TRUE(in_pin(w.points.back(), b)) << what;
      for (std::size_t i = 0; i + 1 < w.points.size(); ++i) {
        if constexpr (oct)
          EXPECT_TRUE(taut::oracle::is_octilinear(w.points[i], w.points[i + 1])) << what;
        else
          EXPECT_TRUE(w.points[i].x == w.points[i + 1].x || w.points[i].y == w.points[i + 1].y) << what;
      }
      if (w.points.size() > 1) {
        if constexpr (oct)
          EXPECT_EQ(ref.check_octilinear_path(w.points), best) << what;
        else
          EXPECT_EQ(ref.check_path(w.points), best) << what;
      }
    }
  }
  std::printf("compared %d (routed %d, unreachable %d, touching pins %d, shapes %d, pairs with a 45-degree edge %d), "
              "refused %d, %d with a shape the router does not take\n",
              compared, routed, unreachable, touching, shapes, diagonal, refused, unsupported);
  return {compared, routed, refused, unreachable, touching, shapes, unsupported, diagonal};
}

TEST(Pins, ShapePinsMatchBruteForce) {
  const Counts c = shape_pins_match_brute_force<L1Router, L1Reference>();
  EXPECT_GE(c.compared, 600);
  EXPECT_GE(c.routed, 300);
  EXPECT_GE(c.refused, 20);
  EXPECT_GE(c.touching, 5);
  EXPECT_EQ(c.unsupported, 0);
}

// The same for octilinear wires over 2,000 pairs (250 in the sanitizer tree): every wire is checked octilinear, free, from
// pin to pin, of the least octilinear length over every pair of free integer points of the two
// shapes. Diamonds and 45-degree triangles included (since 2026-12-03: their candidates add the
// projections along the other diagonal, both integer neighbours of a half-integer one; without
// those projections this test fails).
TEST(Pins, OctilinearShapePinsMatchBruteForce) {
  const int n = static_cast<int>(taut::test::sanitized_share(2000, 4));
  const Counts c = shape_pins_match_brute_force<OctRouter, OctilinearReference>(n);
  EXPECT_GE(c.compared, n);
  EXPECT_GE(c.routed, n / 2);
  EXPECT_GE(c.refused, 10);
  EXPECT_GE(c.touching, 5);
  EXPECT_GE(c.shapes, n / 2);
  EXPECT_GE(c.diagonal, n / 4);
  EXPECT_EQ(c.unsupported, 0);
}

// Hand cases with the answers worked out.
TEST(Pins, HandCases) {
  const Box dom{{0, 0}, {40, 20}};
  // A wall x in [10, 12], y in [0, 15]; a pad left of it, a diamond right of it.
  const std::vector<Polygon> obs = {Polygon{{{10, 0}, {12, 0}, {12, 15}, {10, 15}}, {}}};
  L1Router router(dom, obs);
  const L1Reference ref(dom, obs);
  // Pad [2, 6] x [2, 4] and point (30, 2): over the wall's top (y = 15) from the pad's corner
  // (6, 4), the pad point furthest right and up: 24 across, 11 up and 13 down = 48.
  const Polygon pad{{{2, 2}, {6, 2}, {6, 4}, {2, 4}}, {}};
  const Polygon pt{{{30, 2}}, {}};
  auto w = router.shortest(pad, pt);
  ASSERT_EQ(w.status, WireStatus::Ok);
  EXPECT_EQ(*w.length, 48);
  EXPECT_EQ(ref.distance({6, 4}, {30, 2}), 48);
  // A diamond centred (30, 10) with radius 3 instead of the point: to its left vertex (27, 10)
  // 21 across, 11 up and 5 down = 37 (its top vertex (30, 13) gives 24 + 11 + 2, the same).
  const Polygon diamond{{{27, 10}, {30, 7}, {33, 10}, {30, 13}}, {}};
  w = router.shortest(pad, diamond);
  ASSERT_EQ(w.status, WireStatus::Ok);
  EXPECT_EQ(*w.length, 37);
  // The start is a projection, not a vertex: a wide pad [14, 30] x [17, 19] above the point
  // (20, 5): straight down from (20, 17), 12.
  const Polygon wide{{{14, 17}, {30, 17}, {30, 19}, {14, 19}}, {}};
  const Polygon p2{{{20, 5}}, {}};
  w = router.shortest(wide, p2);
  ASSERT_EQ(w.status, WireStatus::Ok);
  EXPECT_EQ(*w.length, 12);
  EXPECT_EQ(w.points.front(), (Point{20, 17}));
  // Touching pins: a wire of one point.
  const Polygon touch{{{6, 4}, {8, 4}, {8, 8}, {6, 8}}, {}};
  w = router.shortest(pad, touch);
  ASSERT_EQ(w.status, WireStatus::Ok);
  EXPECT_EQ(*w.length, 0);
  EXPECT_EQ(w.points.size(), 1u);
  // Crossing bars with no vertex of one inside the other: they share [16, 18] x [6, 8].
  const Polygon bar_h{{{14, 6}, {20, 6}, {20, 8}, {14, 8}}, {}}, bar_v{{{16, 3}, {18, 3}, {18, 11}, {16, 11}}, {}};
  w = router.shortest(bar_h, bar_v);
  ASSERT_EQ(w.status, WireStatus::Ok);
  EXPECT_EQ(*w.length, 0);
  // Overlap with the wall is refused; touching it is not.
  EXPECT_TRUE(router.pin_meets_obstacle(Polygon{{{8, 2}, {11, 2}, {11, 4}, {8, 4}}, {}}).has_value());
  EXPECT_FALSE(router.pin_meets_obstacle(Polygon{{{8, 2}, {10, 2}, {10, 4}, {8, 4}}, {}}).has_value());
  // The wall itself as a pin (same area, edges in the same direction), and a triangle with an
  // edge from the wall's corner (10, 15) to a point of its right side (12, 13), through the
  // wall's interior: no vertex strictly inside, no proper crossing, only the midpoint (11, 14).
  EXPECT_TRUE(router.pin_meets_obstacle(obs[0]).has_value());
  EXPECT_TRUE(router.pin_meets_obstacle(Polygon{{{10, 15}, {12, 13}, {12, 17}}, {}}).has_value());
  EXPECT_FALSE(router.pin_meets_obstacle(Polygon{{{10, 15}, {12, 17}, {8, 17}}, {}}).has_value());
  // Edges at other angles are not supported.
  EXPECT_FALSE(taut::router::pin_shape_supported(Polygon{{{0, 0}, {2, 1}, {0, 3}}, {}}));
  EXPECT_TRUE(taut::router::pin_shape_supported(diamond));
}

}  // namespace pin_test
