// router::L1Wavefront against the brute-force reference oracle::L1Reference: exact distances,
// sources, paths, vertex distances and is_free on 2,000 seeded random instances from every
// `taut gen` kind and from hand-made degenerate families (tests/support/wavefront_cases.h says
// what they are and what is checked), plus hand-worked cases with the answers in the comments.
// The 20,000-instance run is tests/router/wavefront_long_test.cpp (make test-long).
//
// A failing seed prints the instance, both answers and a shrunk instance. To look at one seed:
//   TAUT_WAVEFRONT_SEED=1234 build/tests/test_router --gtest_filter='Wavefront.Random*'
// Keep every seed that once failed in kRegressionSeeds below.
#include "router/wavefront.h"
#include "router/l1_router.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "oracle/l1_oracle.h"
#include "support/wavefront_cases.h"
#include "support/wavefront_hand.h"
#include "support/sanitized.h"

namespace wavefront_test {

using taut::geom::Box;
using taut::geom::Point;
using taut::geom::Polygon;
using taut::geom::Ring;
using taut::oracle::L1Reference;
using taut::router::L1Wavefront;
using taut::test::WavefrontSweep;
using taut::test::WavefrontTally;
using Dist = std::optional<std::int64_t>;

// Seeds that failed once, each with a comment saying what was wrong; they run in every build.
const std::vector<std::uint64_t> kRegressionSeeds = {
    1003015,  // hit-list clipping dropped the part of a wavelet that alone reached the target
              // (the earlier hitter had slid into the vertex along an edge); clipping now off
    1003651,  // stats check counted repeated vertex queries (pinch at a corner source)
    1008215,  // same, obstacle in the domain corner
    1019004,  // same, ring family
    3053357,  // normalize_obstacles threw: a spike tip whose wedge leaves the domain before it
    3081455,  // holds a lattice point (now rounded outside and clipped back; union_test too)
};

TEST(Wavefront, RandomInstancesMatchReference) {
  taut::test::run_random_wavefront_test(taut::test::WaveMetric::L1);
}

TEST(Wavefront, RegressionSeeds) {
  const WavefrontSweep sw = taut::test::run_wavefront_seeds(kRegressionSeeds, 50);
  taut::test::expect_clean_sweep(sw);
  EXPECT_EQ(sw.tally.instances, static_cast<std::int64_t>(kRegressionSeeds.size()));
}

// ---------------------------------------------------------------------------------------------
// Hand-worked cases.

using taut::test::normalized;
using taut::test::rect;
using taut::test::rect_ring;
using taut::test::Scene;
using taut::test::str;

void expect_run(const Scene& sc, L1Wavefront& wf, const std::vector<Point>& sources, const std::vector<Point>& targets,
                const std::vector<Dist>& want, taut::router::WavefrontStop stop = taut::router::WavefrontStop::AllTargets) {
  taut::test::expect_run<L1Reference>(sc, wf, sources, targets, want, stop);
}

TEST(Wavefront, RectangleBetweenSourceAndTarget) {
  //  100 +----------------------+      rect R = [40,60] x [20,80] in [0,100]^2
  //      |       +----+         |      s = (20,50), t = (80,50): over or under R,
  //      |       | R  |         |      x 60, y 30 + 30: 120
  //      |   s   |    |   t     |      (20,10) -> (80,90) runs below R then up: 60 + 80 = 140
  //      |       +----+         |
  //    0 +----------------------+
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(40, 20, 60, 80)});
  L1Wavefront wf(sc.domain, sc.obstacles);
  expect_run(sc, wf, {{20, 50}}, {{80, 50}}, {120});
  expect_run(sc, wf, {{20, 10}}, {{80, 90}}, {140});
  // Targets on R's boundary: (40,50) in front, 20; (60,50) behind: 40 + 30 + 30 = 100; a
  // corner (60,80): 40 + 30 = 70 (staircase (20,50) (20,80) (60,80)); (50,50) is inside R.
  expect_run(sc, wf, {{20, 50}}, {{40, 50}, {60, 50}, {60, 80}, {50, 50}, {20, 50}},
             {20, 100, 70, std::nullopt, 0}, taut::router::WavefrontStop::Never);
  EXPECT_FALSE(wf.is_free({50, 50}));
  EXPECT_TRUE(wf.is_free({60, 50}));
  EXPECT_TRUE(wf.is_free({0, 0}));
  EXPECT_FALSE(wf.is_free({-1, 0}));
  // After the full run every corner of R has its distance; (30,30) is no vertex.
  EXPECT_EQ(wf.vertex_distance({40, 20}), 50);
  EXPECT_EQ(wf.vertex_distance({40, 80}), 50);
  EXPECT_EQ(wf.vertex_distance({60, 20}), 70);
  EXPECT_EQ(wf.vertex_distance({60, 80}), 70);
  EXPECT_EQ(wf.vertex_distance({30, 30}), std::nullopt);
  EXPECT_GE(wf.stats().labelled, 4);
  EXPECT_GE(wf.stats().entities, 4);
  EXPECT_EQ(taut::router::l1_distance(sc.domain, sc.obstacles, {20, 50}, {80, 50}), 120);
  EXPECT_EQ(taut::router::l1_distance(sc.domain, sc.obstacles, {20, 50}, {50, 50}), std::nullopt);
}

TEST(Wavefront, TwoSquaresTouchingAtACornerBlockTheDiagonal) {
  //      +-------------------+     A = [20,50]^2, B = [50,80]^2 touch at the pinch (50,50)
  //      |        +---+      |     s = (40,60) (NW of the pinch), t = (60,40) (SE of it)
  //      |   s    | B |      |     straight through the pinch would be 40; a wire may not pass
  //      |    +---*---+      |     there, so around A (x 40->20->60, y 60->20->40) or around B
  //      |    | A |   t      |     (x 40->80->60, y 60->80->40): 120 either way
  //      |    +---+          |
  //      +-------------------+
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(20, 20, 50, 50), rect(50, 50, 80, 80)});
  ASSERT_EQ(sc.obstacles.size(), 1u);  // merged: they touch
  L1Wavefront wf(sc.domain, sc.obstacles);
  EXPECT_TRUE(wf.is_free({50, 50}));
  expect_run(sc, wf, {{40, 60}}, {{60, 40}}, {120});
  // A query point at the pinch may use either wedge: 20 to each side; from it, both sides.
  expect_run(sc, wf, {{40, 60}}, {{50, 50}}, {20});
  expect_run(sc, wf, {{50, 50}}, {{60, 40}, {40, 60}, {50, 50}}, {20, 20, 0});
  // From A's top edge to its right edge: the pinch may not be passed; around A's three other
  // corners 20 + 30 + 30 + 20 (around B: 140).
  expect_run(sc, wf, {{40, 50}}, {{50, 40}}, {20 + 30 + 30 + 20});
  expect_run(sc, wf, {{40, 60}}, {{60, 40}}, {120}, taut::router::WavefrontStop::Never);
  EXPECT_EQ(wf.vertex_distance({50, 50}), 20);
  EXPECT_EQ(wf.vertex_distance({20, 50}), 30);
}

TEST(Wavefront, RingWithTheTargetInTheHole) {
  //  ring [20,80]^2 with hole [40,60]^2
  const Scene sc =
      normalized({{0, 0}, {100, 100}},
                 {{rect_ring(20, 20, 80, 80), {{{40, 40}, {40, 60}, {60, 60}, {60, 40}}}}});
  L1Wavefront wf(sc.domain, sc.obstacles);
  EXPECT_FALSE(wf.is_free({30, 30}));  // in the ring
  EXPECT_TRUE(wf.is_free({40, 50}));   // on the hole's side
  EXPECT_TRUE(wf.is_free({50, 50}));
  // From outside: the hole is unreachable; around the ring 80 + 80 = 160 (a staircase).
  expect_run(sc, wf, {{10, 10}}, {{50, 50}, {90, 90}, {60, 60}, {30, 30}},
             {std::nullopt, 160, std::nullopt, std::nullopt});
  // From inside the hole: everything outside is unreachable.
  expect_run(sc, wf, {{50, 50}}, {{45, 55}, {60, 60}, {90, 90}, {50, 50}},
             {10, 20, std::nullopt, 0},
             taut::router::WavefrontStop::Never);
  EXPECT_EQ(wf.vertex_distance({40, 40}), 20);
  EXPECT_EQ(wf.vertex_distance({20, 20}), std::nullopt);  // outer corner: not reached
  // Both at once: each target from the source on its side.
  expect_run(sc, wf, {{10, 10}, {50, 50}}, {{90, 90}, {45, 45}, {80, 20}}, {160, 10, 80});
}

TEST(Wavefront, SeveralSources) {
  // R = [40,60] x [20,80]; sources (20,50) and (80,10).
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(40, 20, 60, 80)});
  L1Wavefront wf(sc.domain, sc.obstacles);
  // (80,50): 40 from the second; (20,60): 10 from the first; (60,50): 20 + 40 = 60 from the
  // second (100 from the first); (50,50) inside R.
  expect_run(sc, wf, {{20, 50}, {80, 10}}, {{80, 50}, {20, 60}, {60, 50}, {50, 50}},
             {40, 10, 60, std::nullopt});
  EXPECT_EQ(wf.target_source(0), 1u);
  EXPECT_EQ(wf.target_source(1), 0u);
  EXPECT_EQ(wf.target_source(2), 1u);
  // A source that is not free is ignored; no source at all reaches nothing.
  expect_run(sc, wf, {{50, 50}, {20, 50}}, {{80, 50}}, {120});
  EXPECT_EQ(wf.target_source(0), 1u);
  expect_run(sc, wf, {{50, 50}}, {{80, 50}, {50, 50}}, {std::nullopt, std::nullopt});
  expect_run(sc, wf, {}, {{80, 50}}, {std::nullopt});
  // Source equal to a target: distance 0, path {s}.
  expect_run(sc, wf, {{10, 10}}, {{10, 10}}, {0});
  EXPECT_EQ(wf.target_path(0), (std::vector<Point>{{10, 10}}));
}

TEST(Wavefront, DiamondTouchingTheDomainSide) {
  //  Diamond (50,0) (70,20) (50,40) (30,20): its tip touches the bottom side at (50,0), a pinch
  //  against the wall. (20,0) -> (80,0): crossing x = 50 needs y >= 40: 60 + 40 + 40 = 140.
  //  (40,10) on the lower left edge: straight, 30. (60,10) on the lower right edge: over the
  //  apex and around the right corner (70,20): x 20 -> 70 -> 60, y 0 -> 40 -> 10: 130.
  const Scene sc =
      normalized({{0, 0}, {100, 100}}, {{{{50, 0}, {70, 20}, {50, 40}, {30, 20}}, {}}});
  L1Wavefront wf(sc.domain, sc.obstacles);
  EXPECT_TRUE(wf.is_free({50, 0}));
  expect_run(sc, wf, {{20, 0}}, {{80, 0}, {50, 0}, {40, 10}, {60, 10}}, {140, 30, 30, 130},
             taut::router::WavefrontStop::Never);
  // The tip as a source reaches both sides.
  expect_run(sc, wf, {{50, 0}}, {{20, 0}, {80, 0}}, {30, 30});
}

TEST(Wavefront, WallAcrossTheDomain) {
  //  Walls [0,45] x [40,60] and [55,100] x [40,60], flush with both sides: a slit 10 wide.
  //  (0,0) -> (0,100) (domain corners): x 0 -> 45 -> 0, y 100: 190.
  const Scene open = normalized({{0, 0}, {100, 100}}, {rect(0, 40, 45, 60), rect(55, 40, 100, 60)});
  L1Wavefront wf(open.domain, open.obstacles);
  EXPECT_FALSE(wf.is_free({0, 50}));  // on the domain side where the wall lies flush
  EXPECT_TRUE(wf.is_free({0, 40}));   // the wall's corner on the side: free below
  EXPECT_TRUE(wf.is_free({50, 50}));  // in the slit
  expect_run(open, wf, {{0, 0}}, {{0, 100}, {100, 100}, {50, 50}, {0, 50}},
             {190, 200, 100, std::nullopt});
  // Closed: the walls touch along x = 50.
  const Scene closed =
      normalized({{0, 0}, {100, 100}}, {rect(0, 40, 50, 60), rect(50, 40, 100, 60)});
  L1Wavefront wf2(closed.domain, closed.obstacles);
  expect_run(closed, wf2, {{0, 0}}, {{0, 100}, {100, 40}, {100, 60}},
             {std::nullopt, 140, std::nullopt},
             taut::router::WavefrontStop::Never);
  // Closed by a pinch only: [0,50] x [40,50] and [50,100] x [50,60] touch at (50,50).
  const Scene pinched =
      normalized({{0, 0}, {100, 100}}, {rect(0, 40, 50, 50), rect(50, 50, 100, 60)});
  L1Wavefront wf3(pinched.domain, pinched.obstacles);
  expect_run(pinched, wf3, {{0, 0}}, {{0, 100}, {50, 50}, {100, 100}, {60, 40}},
             {std::nullopt, 100, std::nullopt, 100});
}

TEST(Wavefront, TriangleInTheWay) {
  //  Triangle (-30,0) (30,0) (0,40); s = (0,-20), t = (0,60): y travels 80, x must reach
  //  |x| >= 30 at y = 0: 60 more: 140; to the apex (0,40) around (-30,0): 60 + 60 = 120.
  //  From the base (free side below) to the apex: (-10,0) -> (-30,0) -> (0,40): 20 + 70 = 90.
  const Scene sc = normalized({{-100, -100}, {100, 100}}, {{{{-30, 0}, {30, 0}, {0, 40}}, {}}});
  L1Wavefront wf(sc.domain, sc.obstacles);
  expect_run(sc, wf, {{0, -20}}, {{0, 60}, {0, 40}, {10, 20}}, {140, 120, std::nullopt});
  expect_run(sc, wf, {{-10, 0}}, {{0, 40}, {30, 0}}, {90, 40});
  // (15,20) on the sloped edge from (30,40) outside: a straight segment, 15 + 20.
  expect_run(sc, wf, {{30, 40}}, {{15, 20}}, {35});
}

TEST(Wavefront, NoObstacles) {
  const Scene sc{{{0, 0}, {100, 100}}, {}};
  L1Wavefront wf(sc.domain, sc.obstacles);
  expect_run(sc, wf, {{0, 0}}, {{100, 100}, {0, 100}, {37, 12}, {101, 0}},
             {200, 100, 49, std::nullopt},
             taut::router::WavefrontStop::Never);
  // The segment is free: no bend is needed (a bend at a domain corner is still a shortest path).
  for (const Point p : wf.target_path(0))
    EXPECT_TRUE(
        (p == Point{0, 0} || p == Point{100, 100} || p == Point{0, 100} || p == Point{100, 0}));
}

TEST(Wavefront, StatsArePlausible) {
  // A handful of rectangles; a full run reaches every vertex.
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(10, 10, 30, 20), rect(40, 30, 50, 90),
                                                     rect(60, 10, 90, 40), rect(30, 20, 40, 30)});
  L1Wavefront wf(sc.domain, sc.obstacles);
  wf.run(std::vector<Point>{{5, 5}}, {}, /*stop_early=*/false);
  // Two pinches: (30,20) and (40,30), two wedges each.
  const L1Reference ref(sc.domain, sc.obstacles);
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
    for (const Point v : p.outer) EXPECT_TRUE(wf.vertex_distance(v).has_value());
}

// Obstacles that hold the domain's frame already merged (the union of the obstacles and
// geom::domain_frame(), clipped to the frame's box: what NetSpace::obstacles(..., framed) gives the
// net router's wavefronts) answer every question as the obstacles alone do: is_free, distances
// from one and from two sources, and L1Router's wires (whose staircase builder then meets an
// obstacle reaching beyond the domain). On the random instances of the reference test (pinches,
// touching obstacles, obstacles flush with the sides, huge coordinates).
TEST(Wavefront, FramedObstaclesAnswerAsUnframed) {
  std::int64_t instances = 0, compared = 0, reached = 0, wires = 0, failed = 0;
  for (std::uint64_t seed = 1; seed <= static_cast<std::uint64_t>(taut::test::sanitized_share(400, 10)); ++seed) {
    const taut::test::WavefrontCase c = taut::test::make_wavefront_case(seed);
    const Box& d = c.domain;
    std::vector<Polygon> with = c.obstacles;
    with.push_back(taut::geom::domain_frame(d));
    const Box g{{d.lo.x - 1, d.lo.y - 1}, {d.hi.x + 1, d.hi.y + 1}};
    const taut::geom::NormalizedObstacles framed = taut::geom::normalize_obstacles(with, g);
    int frames = 0;
    for (const Polygon& p : framed.obstacles) frames += p.outer == taut::geom::domain_frame(d).outer;
    ASSERT_EQ(frames, 1) << "seed " << seed;
    ++instances;
    L1Wavefront a(d, c.obstacles), b(d, framed.obstacles);
    taut::router::OctWavefront oa(d, c.obstacles), ob(d, framed.obstacles);
    std::vector<Point> sources;
    for (const Point p : c.candidates) {
      if (a.is_free(p) != b.is_free(p) || oa.is_free(p) != ob.is_free(p)) {
        if (failed++ < 5) ADD_FAILURE() << "seed " << seed << ": is_free" << str(std::vector<Point>{p}) << " differs";
      }
      if (a.is_free(p) && sources.size() < 2) sources.push_back(p);
    }
    for (std::size_t k = 1; k <= sources.size(); ++k) {
      const std::span<const Point> src(sources.data(), k);
      a.run(src, c.candidates, taut::router::WavefrontStop::Never);
      b.run(src, c.candidates, taut::router::WavefrontStop::Never);
      oa.run(src, c.candidates, taut::router::WavefrontStop::Never);
      ob.run(src, c.candidates, taut::router::WavefrontStop::Never);
      for (std::size_t i = 0; i < c.candidates.size(); ++i) {
        ++compared;
        reached += a.target_distance(i).has_value();
        if (a.target_distance(i) != b.target_distance(i) || oa.target_distance(i) != ob.target_distance(i)) {
          if (failed++ < 5) ADD_FAILURE() << "seed " << seed << ": the distance to" << str(std::vector<Point>{c.candidates[i]}) << " differs";
        }
      }
    }
    if (sources.empty()) continue;
    taut::router::L1Router ra(d, c.obstacles), rb(d, framed.obstacles);
    for (std::size_t i = 0; i < c.candidates.size() && i < 6; ++i) {
      const auto wa = ra.shortest(sources[0], c.candidates[i]), wb = rb.shortest(sources[0], c.candidates[i]);
      wires += wa.status == taut::router::WireStatus::Ok;
      if (wa.status != wb.status || wa.length != wb.length) {
        if (failed++ < 5) ADD_FAILURE() << "seed " << seed << ": the wire to" << str(std::vector<Point>{c.candidates[i]}) << " differs";
      }
    }
  }
  std::printf("%lld instances, %lld distances compared (%lld reached), %lld wires\n", static_cast<long long>(instances),
              static_cast<long long>(compared), static_cast<long long>(reached), static_cast<long long>(wires));
  EXPECT_EQ(failed, 0);
  EXPECT_GT(reached, taut::test::sanitized_share(4000, 10));
  EXPECT_GT(wires, taut::test::sanitized_share(1000, 10));
}

}  // namespace wavefront_test
