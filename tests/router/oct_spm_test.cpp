// router::OctMap (the octilinear shortest path map, router/spm.h) against the brute-force
// reference oracle::OctilinearReference (tests/oracle/oct_oracle.h: visibility graph with
// octilinear edge lengths, Dijkstra), sharing nothing with the map but the geometry kernel.
//
// The seeded instances and per-query checks are spm_test's (support/spm_check.h: every `taut
// gen` kind and the hand-made degenerate families, some near the coordinate limit; 1-20
// sources, 100 queries; distance a + b*sqrt2 exact, source, path of exactly that octilinear
// length from that source bending at obstacle vertices, last link from the root), plus: the
// map without its grid answers the same; a domain too wide for the frames' integer range
// (OctMap::fits) is refused with std::domain_error. TAUT_OCT_SPM_SEED=N runs only seed N.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "geom/normalize.h"
#include "io/layout_geometry.h"
#include "io/movingai.h"
#include "oracle/oct_oracle.h"
#include "router/spm.h"
#include "router/wavefront.h"
#include "support/run.h"
#include "support/sanitized.h"
#include "support/spm_check.h"
#include "support/wavefront_cases.h"

namespace taut::test {
namespace oct_spm_test {

using geom::Point;
using geom::Root2;
using i64 = std::int64_t;

struct Tally : SpmTally {
  i64 refused = 0;
};

std::string check_seed(std::uint64_t seed, Tally& tally) {
  std::optional<oracle::OctilinearReference> ref;
  const auto in = make_spm_instance(seed, 29, tally, ref);
  if (!in) return "";
  const WavefrontCase& c = in->c;
  const geom::Box& D = c.domain;
  const i64 width_plus_height = i64{D.hi.x} - D.lo.x + i64{D.hi.y} - D.lo.y;
  if (!router::OctMap::fits(D)) {
    // Refused only when the frames' coordinates (sums of two centred ones) could leave the range.
    if (width_plus_height < (i64{1} << 31) - 8) return in->head + "  fits() refuses a domain that fits\n";
    try {
      router::OctMap refused(D, c.obstacles, in->sources);
      return in->head + "  a domain fits() refuses was accepted\n";
    } catch (const std::domain_error&) {
    }
    ++tally.refused;
    return "";
  }
  std::optional<router::OctMap> map;
  try {
    map.emplace(D, c.obstacles, in->sources);
  } catch (const std::exception& e) {
    return in->head + "  building the map threw: " + e.what() + "\n";
  }
  if (std::string r = compare_spm_grid(*in, *map, router::OctMap(D, c.obstacles, in->sources, router::OctMap::Options{.grid = false}));
      !r.empty())
    return r;
  ++tally.instances;
  tally.multi_source += in->sources.size() > 1;
  return check_spm_queries(*in, *map, *ref, tally);
}

void run_seeds(const std::vector<std::uint64_t>& seeds, Tally& tally) {
  run_spm_seeds(seeds, [&](std::uint64_t seed) { return check_seed(seed, tally); }, "TAUT_OCT_SPM_SEED");
}

TEST(OctMap, MatchesTheReferenceOnRandomLayouts) {
  if (const char* s = std::getenv("TAUT_OCT_SPM_SEED")) {
    Tally t;
    run_seeds({std::strtoull(s, nullptr, 10)}, t);
    return;
  }
  const auto share = [](std::int64_t n) { return sanitized_share(n, 4); };
  Tally t;
  run_seeds(spm_seed_list(), t);
  std::cout << "instances " << t.instances << " (skipped " << t.skipped << ", refused as too wide " << t.refused
            << ", multi-source " << t.multi_source << "), queries " << t.queries << ": reachable " << t.reachable
            << " (with a diagonal part " << t.diagonal << ", ties " << t.ties << "), unreachable " << t.unreachable
            << ", not free " << t.not_free << "; paths checked " << t.paths << "\n";
  EXPECT_GE(t.instances, share(900));
  EXPECT_GE(t.multi_source, share(700));
  EXPECT_GE(t.reachable, share(50000));
  EXPECT_GE(t.diagonal, share(20000));
  EXPECT_GE(t.unreachable, share(400));
  EXPECT_GE(t.not_free, share(4000));
  EXPECT_GE(t.ties, share(50));
}

// Moving AI grid maps (blockages that touch and pinch everywhere): the map against one
// octilinear wavefront run on 2,000 points per map, a quarter on grid lines, 1-8 sources (two
// of the five maps under the sanitizers). The
// map takes its vertex distances from the wavefront, so this checks the four decompositions
// and their weighted staircases; on arena (122 vertices) the reference judges too.
TEST(OctMap, MovingAiMapsMatchTheWavefront) {
  TAUT_REQUIRE_SHARED_DATA();
  int maps = 0;
  // Under the sanitizers the two small maps only (the 512 x 512 ones take most of the time).
  const std::vector<const char*> names = kSanitized ? std::vector<const char*>{"arena", "maze-100-1"}
                                                    : std::vector<const char*>{"8room_000", "arena", "den520d", "maze-100-1", "random512-10-0"};
  for (const char* name : names) {
    SCOPED_TRACE(name);
    const GridMapCase g = check_map_on_grid_map<router::OctMap, router::OctWavefront>(name, 13, 2000);
    EXPECT_EQ(g.mismatches, 0);
    EXPECT_GT(g.reached, 200);
    if (std::string(name) == "arena") {
      EXPECT_EQ((grid_map_reference_mismatches<router::OctMap, oracle::OctilinearReference>(g)), 0) << "against the reference on arena";
    }
    ++maps;
  }
  EXPECT_EQ(maps, static_cast<int>(names.size()));
}

// Worked by hand. A wall x in [40, 60], y in [0, 80] of the 100 x 100 domain, sources (10, 10)
// and (90, 50).
TEST(OctMap, TwoSourcesAroundAWall) {
  const geom::Box dom{{0, 0}, {100, 100}};
  const std::vector<geom::Polygon> obs = {{{{40, 0}, {60, 0}, {60, 80}, {40, 80}}, {}}};
  const std::vector<Point> src = {{10, 10}, {90, 50}};
  const router::OctMap map(dom, obs, src);
  // (30, 20): 20 across and 10 up from source 0: 10 straight + 10 diagonal.
  ASSERT_TRUE(map.locate({30, 20}));
  EXPECT_EQ(map.locate({30, 20})->distance, (Root2{10, 10}));
  EXPECT_EQ(map.locate({30, 20})->source, 0u);
  // (70, 0): from source 1, 20 left and 50 down: 30 straight + 20 diagonal.
  EXPECT_EQ(map.locate({70, 0})->distance, (Root2{30, 20}));
  EXPECT_EQ(map.path({70, 0}), (std::vector<Point>{{90, 50}, {70, 0}}));
  // (50, 90) above the wall: from source 1, 40 left and 40 up: 40 diagonal.
  EXPECT_EQ(map.locate({50, 90})->distance, (Root2{0, 40}));
  EXPECT_EQ(map.locate({50, 90})->source, 1u);
  // (20, 0), behind nothing: from source 0, 10 and 10: 10 diagonal.
  EXPECT_EQ(map.locate({20, 0})->distance, (Root2{0, 10}));
  // (50, 85) just above the wall from source 0: over the corner (40, 80): 30 across and 70 up
  // to it (40 straight + 30 diagonal), then 10 across and 5 up (5 + 5 diagonal): 45 + 35.
  // Source 1: 40 left, 35 up: 5 straight + 35 diagonal, nearer.
  EXPECT_EQ(map.locate({50, 85})->distance, (Root2{5, 35}));
  // (30, 0) and (70, 90): source 0 is 20 and 10 from (30, 0) (10 + 10 diagonal); (70, 90) is 20
  // and 40 from source 1 (20 + 20 diagonal).
  EXPECT_EQ(map.locate({30, 0})->distance, (Root2{10, 10}));
  EXPECT_EQ(map.locate({70, 90})->distance, (Root2{20, 20}));
  EXPECT_FALSE(map.is_free({50, 40}));
  EXPECT_FALSE(map.locate({50, 40}));
  EXPECT_TRUE(map.is_free({40, 40}));
}

// Source behind a wall: the path must bend at the wall's corner, and the straight last link
// is diagonal. Wall x in [40, 60], y in [0, 80]; source (50, 90) above it, query (30, 0) below
// left: to the corner (40, 80) 10 and 10 (10 diagonal), then 10 and 80 (70 + 10 diagonal).
TEST(OctMap, PathBendsAtACorner) {
  const geom::Box dom{{0, 0}, {100, 100}};
  const std::vector<geom::Polygon> obs = {{{{40, 0}, {60, 0}, {60, 80}, {40, 80}}, {}}};
  const std::vector<Point> src = {{50, 90}};
  const router::OctMap map(dom, obs, src);
  const auto a = map.locate({30, 0});
  ASSERT_TRUE(a);
  EXPECT_EQ(a->distance, (Root2{70, 20}));
  EXPECT_EQ(a->root, (Point{40, 80}));
  EXPECT_EQ(map.path({30, 0}), (std::vector<Point>{{50, 90}, {40, 80}, {30, 0}}));
}

// The frames' coordinates are sums of two centred ones: a domain whose width plus height passes
// about 2^31 is refused (std::domain_error), one just inside is accepted.
TEST(OctMap, RefusesDomainsTooWideForTheFrames) {
  const geom::Coord m = geom::kMaxCoord;
  EXPECT_FALSE(router::OctMap::fits({{-m, -m}, {m, m}}));
  EXPECT_THROW(router::OctMap({{-m, -m}, {m, m}}, {}, std::vector<Point>{{0, 0}}), std::domain_error);
  const geom::Box ok{{-m, -m}, {m, 0}};  // width 2^31 - 2, height 2^30 - 1: too wide
  EXPECT_FALSE(router::OctMap::fits(ok));
  const geom::Box fits{{-(1 << 29), -(1 << 29)}, {(1 << 29) - 4, (1 << 29) - 4}};  // half-sums below 2^30
  EXPECT_TRUE(router::OctMap::fits(fits));
  const router::OctMap map(fits, {}, std::vector<Point>{{-(1 << 29), -(1 << 29)}});
  const auto a = map.locate({(1 << 29) - 4, 0});
  ASSERT_TRUE(a);
  // dx = 2^30 - 4, dy = 2^29: 2^29 - 4 straight and 2^29 diagonal.
  EXPECT_EQ(a->distance, (Root2{(1 << 29) - 4, 1 << 29}));
}

}  // namespace oct_spm_test
}  // namespace taut::test
