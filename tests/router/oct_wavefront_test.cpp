// router::OctWavefront against the brute-force reference oracle::OctilinearReference: exact
// octilinear distances (geom::Root2, a + b*sqrt2), sources, paths, vertex distances and is_free
// on 2,000 seeded random instances, with the same generator, queries and checks as the L1 test
// (tests/support/wavefront_cases.h, WaveMetric::Octilinear), plus hand-worked cases with the
// answers in the comments. The 20,000-instance run is tests/router/oct_wavefront_long_test.cpp
// (make test-long).
//
// The octilinear length of a vector (dx, dy) is d8 = (max - min) + min*sqrt2 of |dx|, |dy|; a
// path's length is the sum over its links (links of any direction: OctWavefront::target_path
// bends at obstacle vertices only; router/staircase.h makes the octilinear wire).
//
// A failing seed prints the instance, both answers and a shrunk instance. To look at one seed:
//   TAUT_OCT_SEED=1234 build/tests/test_router --gtest_filter='OctWavefront.Random*'
// Keep every seed that once failed in kRegressionSeeds below.
#include "router/wavefront.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "geom/root2.h"
#include "oracle/oct_oracle.h"
#include "support/wavefront_cases.h"
#include "support/wavefront_hand.h"

namespace oct_wavefront_test {

using taut::geom::Box;
using taut::geom::Point;
using taut::geom::Polygon;
using taut::geom::Ring;
using taut::geom::Root2;
using taut::oracle::OctilinearReference;
using taut::router::OctWavefront;
using taut::test::WavefrontSweep;
using taut::test::WavefrontTally;
using taut::test::WaveMetric;
using Dist = std::optional<Root2>;
using Stop = OctWavefront::Stop;

// a + b*sqrt2.
constexpr Root2 R(std::int64_t a, std::int64_t b) { return {a, b}; }

// Seeds that failed once, each with a comment saying what was wrong; they run in every build.
// None yet: the list starts empty (the L1 test's table, wavefront_test.cpp, shows the form).
const std::vector<std::uint64_t> kRegressionSeeds = {};

TEST(OctWavefront, RandomInstancesMatchReference) {
  taut::test::run_random_wavefront_test(taut::test::WaveMetric::Octilinear);
}

TEST(OctWavefront, RegressionSeeds) {
  const WavefrontSweep sw =
      taut::test::run_wavefront_seeds(kRegressionSeeds, 50, WaveMetric::Octilinear);
  taut::test::expect_clean_sweep(sw);
  EXPECT_EQ(sw.tally.instances, static_cast<std::int64_t>(kRegressionSeeds.size()));
}

// ---------------------------------------------------------------------------------------------
// Hand-worked cases. Shortest octilinear paths among obstacles are the Euclidean-taut paths of
// some homotopy class (oct_oracle.h), so each answer below is a taut path's links added up by
// d8: (dx, dy) with |dx| >= |dy| costs (|dx| - |dy|) + |dy|*sqrt2.

using taut::test::normalized;
using taut::test::rect;
using taut::test::rect_ring;
using taut::test::Scene;
using taut::test::str;

void expect_run(const Scene& sc, OctWavefront& wf, const std::vector<Point>& sources, const std::vector<Point>& targets,
                const std::vector<Dist>& want, taut::router::WavefrontStop stop = taut::router::WavefrontStop::AllTargets) {
  taut::test::expect_run<OctilinearReference>(sc, wf, sources, targets, want, stop);
}

TEST(OctWavefront, NoObstacles) {
  //  From (0,0): (10,4) is 6 straight + 4 diagonal: 6 + 4*sqrt2; (100,100) one diagonal,
  //  100*sqrt2; (0,100) straight, 100; (37,12): 25 + 12*sqrt2; (101,0) is outside.
  const Scene sc{{{0, 0}, {100, 100}}, {}};
  OctWavefront wf(sc.domain, sc.obstacles);
  expect_run(sc, wf, {{0, 0}}, {{10, 4}, {100, 100}, {0, 100}, {37, 12}, {101, 0}},
             {R(6, 4), R(0, 100), R(100, 0), R(25, 12), std::nullopt}, Stop::Never);
  // A straight link is the only shortest path to (10,4) in the open plane: a bend at a domain
  // corner would cost more (d8 is strictly convex between different cones).
  EXPECT_EQ(wf.target_path(0), (std::vector<Point>{{0, 0}, {10, 4}}));
  EXPECT_TRUE(wf.is_free({0, 0}));
  EXPECT_FALSE(wf.is_free({-1, 0}));
  // No obstacle, no vertex.
  EXPECT_EQ(wf.vertex_distance({10, 4}), std::nullopt);
}

TEST(OctWavefront, RectangleBetweenSourceAndTarget) {
  //  100 +----------------------+      rect R = [40,60] x [20,80] in [0,100]^2
  //      |       +----+         |      s = (20,50), t = (80,50): over R (or under, the same),
  //      |       | R  |         |      s -> (40,80) -> (60,80) -> t:
  //      |   s   |    |   t     |      (20,30) + (20,0) + (20,-30) = 10+20r2 + 20 + 10+20r2
  //      |       +----+         |      = 40 + 40*sqrt2 (L1: 120)
  //    0 +----------------------+
  //  (20,10) -> (80,90): the segment meets R (y = 36.7 at x = 40); below and right of R,
  //  (20,10) -> (60,20) -> (80,90): (40,10) + (20,70) = 30+10r2 + 50+20r2 = 80 + 30*sqrt2, as
  //  over the top, (20,10) -> (40,80) -> (80,90): 50+20r2 + 30+10r2.
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(40, 20, 60, 80)});
  OctWavefront wf(sc.domain, sc.obstacles);
  expect_run(sc, wf, {{20, 50}}, {{80, 50}}, {R(40, 40)});
  expect_run(sc, wf, {{20, 10}}, {{80, 90}}, {R(80, 30)});
  // Targets on R's boundary from (20,50): (40,50) in front, 20; (60,50) behind: over the top
  // corners and down, 10+20r2 + 20 + 30 = 60 + 20*sqrt2; the corner (60,80): the straight link
  // enters R at (40,65), so via (40,80): 10+20r2 + 20 = 30 + 20*sqrt2; (50,50) is inside R.
  expect_run(sc, wf, {{20, 50}}, {{40, 50}, {60, 50}, {60, 80}, {50, 50}, {20, 50}},
             {R(20, 0), R(60, 20), R(30, 20), std::nullopt, R(0, 0)}, Stop::Never);
  EXPECT_FALSE(wf.is_free({50, 50}));
  EXPECT_TRUE(wf.is_free({60, 50}));
  EXPECT_TRUE(wf.is_free({0, 0}));
  EXPECT_FALSE(wf.is_free({-1, 0}));
  // After the full run every corner of R has its distance: the near ones (20,+-30) away,
  // 10 + 20*sqrt2; the far ones 20 more (the straight links to them enter R); (30,30) is no
  // vertex.
  EXPECT_EQ(wf.vertex_distance({40, 20}), R(10, 20));
  EXPECT_EQ(wf.vertex_distance({40, 80}), R(10, 20));
  EXPECT_EQ(wf.vertex_distance({60, 20}), R(30, 20));
  EXPECT_EQ(wf.vertex_distance({60, 80}), R(30, 20));
  EXPECT_EQ(wf.vertex_distance({30, 30}), std::nullopt);
  EXPECT_GE(wf.stats().labelled, 4);
  EXPECT_GE(wf.stats().entities, 4);
}

TEST(OctWavefront, TwoSquaresTouchingAtACornerBlockTheDiagonal) {
  //      +-------------------+     A = [20,50]^2, B = [50,80]^2 touch at the pinch (50,50)
  //      |        +---+      |     s = (40,60) (NW of the pinch), t = (60,40) (SE of it)
  //      |   s    | B |      |     the diagonal through the pinch would be 20*sqrt2; a wire may
  //      |    +---*---+      |     not pass there, so around A: s -> (20,50) -> (20,20) ->
  //      |    | A |   t      |     (50,20) -> t: 10+10r2 + 30 + 30 + 10+10r2 = 80 + 20*sqrt2,
  //      |    +---+          |     or around B, (50,80) (80,80) (80,50): the same
  //      +-------------------+
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(20, 20, 50, 50), rect(50, 50, 80, 80)});
  ASSERT_EQ(sc.obstacles.size(), 1u);  // merged: they touch
  OctWavefront wf(sc.domain, sc.obstacles);
  EXPECT_TRUE(wf.is_free({50, 50}));
  expect_run(sc, wf, {{40, 60}}, {{60, 40}}, {R(80, 20)});
  // A query point at the pinch may use either wedge: 10*sqrt2 to each side; from it, both sides.
  expect_run(sc, wf, {{40, 60}}, {{50, 50}}, {R(0, 10)});
  expect_run(sc, wf, {{50, 50}}, {{60, 40}, {40, 60}, {50, 50}}, {R(0, 10), R(0, 10), R(0, 0)});
  // From A's top edge to its right edge: the pinch may not be passed; around A's three other
  // corners 20 + 30 + 30 + 20 = 100 (around B: (40,50) (50,80) (80,80) (80,50) (50,40),
  // 20+10r2 + 30 + 30 + 20+10r2 = 100 + 20*sqrt2).
  expect_run(sc, wf, {{40, 50}}, {{50, 40}}, {R(100, 0)});
  expect_run(sc, wf, {{40, 60}}, {{60, 40}}, {R(80, 20)}, Stop::Never);
  // The pinch: 10*sqrt2 (the nearer wedge); A's top-left corner (20,50): (-20,-10), 10 + 10*sqrt2.
  EXPECT_EQ(wf.vertex_distance({50, 50}), R(0, 10));
  EXPECT_EQ(wf.vertex_distance({20, 50}), R(10, 10));
}

TEST(OctWavefront, RingWithTheTargetInTheHole) {
  //  ring [20,80]^2 with hole [40,60]^2
  const Scene sc =
      normalized({{0, 0}, {100, 100}},
                 {{rect_ring(20, 20, 80, 80), {{{40, 40}, {40, 60}, {60, 60}, {60, 40}}}}});
  OctWavefront wf(sc.domain, sc.obstacles);
  EXPECT_FALSE(wf.is_free({30, 30}));  // in the ring
  EXPECT_TRUE(wf.is_free({40, 50}));   // on the hole's side
  EXPECT_TRUE(wf.is_free({50, 50}));
  // From outside: the hole is unreachable; (10,10) -> (80,20) -> (90,90) passes below and right
  // of the ring: (70,10) + (10,70) = 60+10r2 + 60+10r2 = 120 + 20*sqrt2 (or via (20,80)).
  expect_run(sc, wf, {{10, 10}}, {{50, 50}, {90, 90}, {60, 60}, {30, 30}},
             {std::nullopt, R(120, 20), std::nullopt, std::nullopt});
  // From inside the hole: everything outside is unreachable; (45,55) is (-5,5) away, 5*sqrt2;
  // the hole's corner (60,60) one diagonal, 10*sqrt2.
  expect_run(sc, wf, {{50, 50}}, {{45, 55}, {60, 60}, {90, 90}, {50, 50}},
             {R(0, 5), R(0, 10), std::nullopt, R(0, 0)}, Stop::Never);
  EXPECT_EQ(wf.vertex_distance({40, 40}), R(0, 10));
  EXPECT_EQ(wf.vertex_distance({20, 20}), std::nullopt);  // outer corner: not reached
  // Both at once: each target from the source on its side; (80,20) is (70,10) from (10,10).
  expect_run(sc, wf, {{10, 10}, {50, 50}}, {{90, 90}, {45, 45}, {80, 20}},
             {R(120, 20), R(0, 5), R(60, 10)});
  EXPECT_EQ(wf.target_source(0), 0u);
  EXPECT_EQ(wf.target_source(1), 1u);
  EXPECT_EQ(wf.target_source(2), 0u);
}

TEST(OctWavefront, SeveralSources) {
  // R = [40,60] x [20,80]; sources (20,50) and (80,10).
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(40, 20, 60, 80)});
  OctWavefront wf(sc.domain, sc.obstacles);
  // (80,50): 40 straight up from the second (40 + 40*sqrt2 from the first); (20,60): 10 from
  // the first; (60,50): (-20,40) from the second, 20 + 20*sqrt2 (60 + 20*sqrt2 from the first);
  // (50,50) inside R.
  expect_run(sc, wf, {{20, 50}, {80, 10}}, {{80, 50}, {20, 60}, {60, 50}, {50, 50}},
             {R(40, 0), R(10, 0), R(20, 20), std::nullopt});
  EXPECT_EQ(wf.target_source(0), 1u);
  EXPECT_EQ(wf.target_source(1), 0u);
  EXPECT_EQ(wf.target_source(2), 1u);
  // A source that is not free is ignored; no source at all reaches nothing.
  expect_run(sc, wf, {{50, 50}, {20, 50}}, {{80, 50}}, {R(40, 40)});
  EXPECT_EQ(wf.target_source(0), 1u);
  expect_run(sc, wf, {{50, 50}}, {{80, 50}, {50, 50}}, {std::nullopt, std::nullopt});
  expect_run(sc, wf, {}, {{80, 50}}, {std::nullopt});
  // Source equal to a target: distance 0, path {s}.
  expect_run(sc, wf, {{10, 10}}, {{10, 10}}, {R(0, 0)});
  EXPECT_EQ(wf.target_path(0), (std::vector<Point>{{10, 10}}));
}

TEST(OctWavefront, StopAtTheFirstTarget) {
  // R = [40,60] x [20,80], source (20,50): (20,60) is 10 away, (80,50) 40 + 40*sqrt2. With
  // Stop::FirstTarget the nearest target is reached with its exact distance; the other may be
  // reached too, never nearer than it is.
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(40, 20, 60, 80)});
  OctWavefront wf(sc.domain, sc.obstacles);
  const std::vector<Point> sources{{20, 50}}, targets{{80, 50}, {20, 60}};
  wf.run(sources, targets, Stop::FirstTarget);
  EXPECT_EQ(wf.target_distance(1), R(10, 0));
  EXPECT_EQ(wf.target_path(1), (std::vector<Point>{{20, 50}, {20, 60}}));
  if (const Dist d = wf.target_distance(0)) {
    EXPECT_EQ(*d, R(40, 40));
  }
}

TEST(OctWavefront, DiamondTouchingTheDomainSide) {
  //  Diamond (50,0) (70,20) (50,40) (30,20): its tip touches the bottom side at (50,0), a pinch
  //  against the wall. (20,0) -> (80,0) must pass over the apex, hugging the diamond:
  //  (20,0) (30,20) (50,40) (70,20) (80,0): (10,20) + (20,20) + (20,-20) + (10,-20)
  //  = 10+10r2 + 20r2 + 20r2 + 10+10r2 = 20 + 60*sqrt2. (40,10) on the lower left edge:
  //  straight, (20,10): 10 + 10*sqrt2. (60,10) on the lower right edge: over the apex and
  //  around the right corner (70,20), then (-10,-10) down the edge: 10 + 60*sqrt2.
  const Scene sc =
      normalized({{0, 0}, {100, 100}}, {{{{50, 0}, {70, 20}, {50, 40}, {30, 20}}, {}}});
  OctWavefront wf(sc.domain, sc.obstacles);
  EXPECT_TRUE(wf.is_free({50, 0}));
  expect_run(sc, wf, {{20, 0}}, {{80, 0}, {50, 0}, {40, 10}, {60, 10}},
             {R(20, 60), R(30, 0), R(10, 10), R(10, 60)}, Stop::Never);
  // The apex: (10,20) + (20,20) = 10 + 30*sqrt2.
  EXPECT_EQ(wf.vertex_distance({50, 40}), R(10, 30));
  // The tip as a source reaches both sides along the wall.
  expect_run(sc, wf, {{50, 0}}, {{20, 0}, {80, 0}}, {R(30, 0), R(30, 0)});
}

TEST(OctWavefront, TriangleInTheWay) {
  //  Triangle (-30,0) (30,0) (0,40); s = (0,-20), t = (0,60): around (-30,0) and the apex:
  //  (-30,20) + (30,40) + (0,20) = 10+20r2 + 10+30r2 + 20 = 40 + 50*sqrt2; to the apex itself
  //  20 + 50*sqrt2. (10,20) is inside.
  //  From the base (free side below) to the apex: (-10,0) -> (-30,0) -> (0,40):
  //  20 + 10+30r2 = 30 + 30*sqrt2; to (30,0) along the base, 40.
  const Scene sc = normalized({{-100, -100}, {100, 100}}, {{{{-30, 0}, {30, 0}, {0, 40}}, {}}});
  OctWavefront wf(sc.domain, sc.obstacles);
  expect_run(sc, wf, {{0, -20}}, {{0, 60}, {0, 40}, {10, 20}},
             {R(40, 50), R(20, 50), std::nullopt});
  expect_run(sc, wf, {{-10, 0}}, {{0, 40}, {30, 0}}, {R(30, 30), R(40, 0)});
  // (15,20) on the sloped edge (slope -4/3, not octilinear) from (30,40) outside: a straight
  // link, (-15,-20): 5 + 15*sqrt2.
  expect_run(sc, wf, {{30, 40}}, {{15, 20}}, {R(5, 15)});
}

TEST(OctWavefront, SlitInAWallAcrossTheDomain) {
  //  Walls [0,45] x [40,60] and [55,100] x [40,60], flush with both sides: a slit 10 wide.
  //  (0,0) -> (0,100) (domain corners): through the slit along its left side,
  //  (0,0) (45,40) (45,60) (0,100): 5+40r2 + 20 + 5+40r2 = 30 + 80*sqrt2.
  //  (0,0) -> (100,100): across the slit, (0,0) (45,40) (55,60) (100,100):
  //  5+40r2 + 10+10r2 + 5+40r2 = 20 + 90*sqrt2. (50,50) in the slit: the diagonal from (0,0)
  //  enters the left wall at (40,40), so via its corner (45,40): 5+40r2 + (5,10) 5+5r2
  //  = 10 + 45*sqrt2. (0,50) lies where a wall is flush with the domain side: not free.
  const Scene open = normalized({{0, 0}, {100, 100}}, {rect(0, 40, 45, 60), rect(55, 40, 100, 60)});
  OctWavefront wf(open.domain, open.obstacles);
  EXPECT_FALSE(wf.is_free({0, 50}));
  EXPECT_TRUE(wf.is_free({0, 40}));
  EXPECT_TRUE(wf.is_free({50, 50}));
  expect_run(open, wf, {{0, 0}}, {{0, 100}, {100, 100}, {50, 50}, {0, 50}},
             {R(30, 80), R(20, 90), R(10, 45), std::nullopt});
  // Closed by a pinch only: [0,50] x [40,50] and [50,100] x [50,60] touch at (50,50), whose
  // free wedges face NW and SE. (50,50) from (0,0): the diagonal enters the left wall at
  // (40,40), so via its corner (50,40) and up its side: 10+40r2 + 10 = 20 + 40*sqrt2; (60,40)
  // below the right wall: straight, 20 + 40*sqrt2; above the walls nothing is reachable.
  const Scene pinched =
      normalized({{0, 0}, {100, 100}}, {rect(0, 40, 50, 50), rect(50, 50, 100, 60)});
  OctWavefront wf2(pinched.domain, pinched.obstacles);
  expect_run(pinched, wf2, {{0, 0}}, {{0, 100}, {50, 50}, {100, 100}, {60, 40}},
             {std::nullopt, R(20, 40), std::nullopt, R(20, 40)});
}

TEST(OctWavefront, StatsArePlausible) {
  // A handful of rectangles; a full run reaches every vertex.
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(10, 10, 30, 20), rect(40, 30, 50, 90),
                                                     rect(60, 10, 90, 40), rect(30, 20, 40, 30)});
  OctWavefront wf(sc.domain, sc.obstacles);
  wf.run(std::vector<Point>{{5, 5}}, {}, Stop::Never);
  // Two pinches: (30,20) and (40,30), two wedges each.
  const OctilinearReference ref(sc.domain, sc.obstacles);
  std::set<Point> vertices;
  for (const Polygon& p : sc.obstacles) vertices.insert(p.outer.begin(), p.outer.end());
  std::int64_t wedges = 0;
  for (const Point v : vertices) wedges += static_cast<std::int64_t>(ref.wedges_at(v).size());
  EXPECT_EQ(wedges, static_cast<std::int64_t>(vertices.size()) + 2);
  const auto& st = wf.stats();
  EXPECT_GE(st.vertices, static_cast<std::int64_t>(vertices.size()));  // + the frame's corners
  EXPECT_GE(st.entities, wedges);
  EXPECT_GT(st.events, 0);
  EXPECT_GT(st.wavelets, 0);
  EXPECT_GE(st.labelled, wedges);  // everything is reachable from (5,5)
  EXPECT_LE(st.labelled, st.entities);
  EXPECT_GT(st.drag_queries + st.ray_queries, 0);
  EXPECT_GT(wf.memory_bytes(), 0u);
  for (const Polygon& p : sc.obstacles)
    for (const Point v : p.outer) {
      EXPECT_TRUE(wf.vertex_distance(v).has_value());
      EXPECT_EQ(wf.vertex_distance(v), ref.distance({5, 5}, v));
    }
}

// A diagonal track ray from a query point (not an obstacle vertex) is shot on the R-tree in
// growing windows: square boxes around the ray's segment, the first 16 DBU long here. The long
// edge (15,0)-(39,48) meets the first box but crosses the NE ray from (0,0) only at (30,30),
// beyond the window; the diamond around (20,20) crosses it at (19.5,19.5) and misses the box.
// Found in review: the ray stopped at the far edge, the source's wavelet ran through the
// diamond, and the run threw ("no free wedge of (20,21) holds the wave"). The 20 small squares
// far away only make the index's typical edge gap, and so the first window, small.
TEST(OctWavefront, DiagonalRayFromAQueryPointPastALongEdgeInItsWindow) {
  std::vector<Polygon> in = {{{{15, 0}, {39, 48}, {41, 49}}, {}},
                             {{{20, 19}, {21, 20}, {20, 21}, {19, 20}}, {}}};
  for (int i = 0; i < 20; ++i) {
    const int x = 45 + (i % 5) * 3, y = 2 + (i / 5) * 3;
    in.push_back(rect(x, y, x + 1, y + 1));
  }
  const Scene sc = normalized({{-2, -2}, {60, 60}}, in);
  const OctilinearReference ref(sc.domain, sc.obstacles);
  OctWavefront wf(sc.domain, sc.obstacles);
  const Point s{0, 0};
  std::vector<Point> targets;  // every free lattice point around and behind the diamond
  for (int x = 18; x <= 35; ++x)
    for (int y = 18; y <= 35; ++y)
      if (ref.is_free({x, y})) targets.push_back({x, y});
  ASSERT_NO_THROW(wf.run({&s, 1}, targets, Stop::AllTargets));
  EXPECT_GT(wf.stats().ray_queries, 0);
  for (std::size_t t = 0; t < targets.size(); ++t)
    EXPECT_EQ(wf.target_distance(t), ref.distance(s, targets[t])) << str({targets[t]});
  // Straight behind the diamond, (24,24) is reached round a corner: (0,0)-(19,20)-(20,21)-(24,24)
  // is (1 + 19 sqrt2) + sqrt2 + (1 + 3 sqrt2).
  EXPECT_EQ(wf.target_distance(static_cast<std::size_t>(
                std::find(targets.begin(), targets.end(), Point{24, 24}) - targets.begin())),
            R(2, 23));
}

}  // namespace oct_wavefront_test
