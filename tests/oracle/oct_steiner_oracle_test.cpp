// oracle::oct_steiner_minimal_length (Dreyfus-Wagner on the 8-connected integer lattice) against
// simpler exact answers from the octilinear reference (OctilinearReference::distance, a
// visibility graph: another search over other nodes). On axis-parallel rectangles with integer
// corners a shortest octilinear path has an equally long lattice path (the lattice argument of
// oct_oracle_test.cpp), so the lattice distance is the reference's distance and:
//   - two terminals: the minimum is their distance;
//   - three terminals: a tree joining three points is three paths from one branch point (a
//     lattice node), so the minimum is the least sum of the three distances from a free lattice
//     point (no pinches in these layouts: every point has at most one wedge);
//   - k terminals: the union of the shortest paths along a minimum spanning tree of the pairwise
//     distances joins them, so MST >= L; the path in the tree between two terminals is an allowed
//     path, so L >= the largest pairwise distance; walking around the tree (each edge twice) is a
//     closed walk through every terminal of length 2L, whose k pieces between consecutive
//     terminals are each at least a distance; dropping the longest piece leaves a spanning path,
//     so MST <= 2L (k - 1) / k; and a tree for more terminals joins the fewer, so adding a
//     terminal never shortens the minimum.
// Random layouts of rectangles at least 1 apart (some flush with the domain side), terminals at
// lattice points. On sloped obstacles (random triangles) only the lower bound: never below the
// reference's distance (a sliver between lattice points, by hand too). Hand cases with their
// answers worked out (Steiner points, walls, a ring, a pinch with and without a pin on it); the
// limits.
#include "oracle/oct_steiner_oracle.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "oracle/oct_oracle.h"
#include "support/random_shapes.h"
#include "support/sanitized.h"

namespace taut::oracle {
namespace oct_steiner_oracle_test {

using geom::Box;
using geom::Point;
using geom::Root2;
using test::sanitized_share;
using Len = std::optional<Root2>;

constexpr Box kDomain{{0, 0}, {30, 30}};

// Up to 5 rectangles at least 1 apart in the 30 x 30 domain (some reach its top or right side),
// as normalize_obstacles would give them (counter-clockwise, disjoint).
std::vector<geom::Polygon> random_obstacles(std::mt19937& rng) {
  const int count = static_cast<int>(rng() % 6);
  return test::box_polygons(test::random_boxes_apart(rng, count, 1, 24, 6));
}

Point random_point(std::mt19937& rng) {
  return {static_cast<geom::Coord>(rng() % 31), static_cast<geom::Coord>(rng() % 31)};
}

Point random_free_point(std::mt19937& rng, const OctilinearReference& ref) {
  for (;;) {
    const Point p = random_point(rng);
    if (ref.is_free(p)) return p;
  }
}

Root2 times(Root2 x, std::int64_t c) { return {x.a * c, x.b * c}; }

// The union of the boxes clipped to the domain, as the oracle takes its obstacles.
std::vector<geom::Polygon> normalized(const Box& domain, const std::vector<Box>& boxes) {
  const std::vector<geom::Polygon> in = test::box_polygons(boxes);
  return geom::normalize_obstacles(in, domain).obstacles;
}

TEST(OctSteinerOracle, TwoTerminalsMatchTheDistance) {
  int failed = 0, compared = 0, reached = 0;
  for (int seed = 1; seed <= sanitized_share(400, 4); ++seed) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937 rng(static_cast<unsigned>(seed));
    const std::vector<geom::Polygon> obstacles = random_obstacles(rng);
    const OctilinearReference ref(kDomain, obstacles);
    ASSERT_TRUE(ref.problems().empty());
    // One layout in four: terminals anywhere (inside obstacles too); else free ones.
    const bool anywhere = seed % 4 == 0;
    const Point a = anywhere ? random_point(rng) : random_free_point(rng, ref);
    const Point b = anywhere ? random_point(rng) : random_free_point(rng, ref);
    const Point t[] = {a, b};
    const Len got = oct_steiner_minimal_length(kDomain, obstacles, t);
    const Len want = ref.distance(a, b);
    ++compared;
    reached += want.has_value();
    if (got != want && failed++ < 5)
      ADD_FAILURE() << "(" << a.x << "," << a.y << ") (" << b.x << "," << b.y << "): oracle "
                    << (got ? got->to_double() : -1) << ", distance " << (want ? want->to_double() : -1);
  }
  std::printf("%d pairs, %d connected\n", compared, reached);
  EXPECT_EQ(failed, 0);
}

// Shape terminals: a diamond pad and a point are as far apart as the nearest free lattice point
// of the pad is from the point (the reference's distance, minimised over the pad's lattice
// points, found here by brute force with geom::locate); point pins given as one-vertex polygons
// give what the point overload gives; a pad on no free lattice point has no tree.
TEST(OctSteinerOracle, ShapeTerminalsMatchTheNearestPoint) {
  int failed = 0, compared = 0;
  for (int seed = 1; seed <= sanitized_share(300, 4); ++seed) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937 rng(static_cast<unsigned>(5000 + seed));
    const std::vector<geom::Polygon> obstacles = random_obstacles(rng);
    const OctilinearReference ref(kDomain, obstacles);
    const Point c = random_point(rng), b = random_free_point(rng, ref);
    const geom::Coord r = static_cast<geom::Coord>(1 + rng() % 3);
    const geom::Polygon diamond{{{c.x - r, c.y}, {c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}}, {}};
    Len want;
    for (geom::Coord x = c.x - r; x <= c.x + r; ++x)
      for (geom::Coord y = c.y - r; y <= c.y + r; ++y) {
        const Point p{x, y};
        if (geom::locate(p, diamond) == geom::Location::Outside || !ref.is_free(p)) continue;
        const Len d = ref.distance(p, b);
        if (d && (!want || *d < *want)) want = d;
      }
    const geom::Polygon t[] = {diamond, geom::Polygon{{b}, {}}};
    const Len got = oct_steiner_minimal_length(kDomain, obstacles, std::span<const geom::Polygon>(t));
    ++compared;
    if (got != want && failed++ < 5)
      ADD_FAILURE() << "diamond at (" << c.x << "," << c.y << ") r " << r << ", point (" << b.x << "," << b.y << "): oracle "
                    << (got ? got->to_double() : -1) << ", nearest " << (want ? want->to_double() : -1);
    const Point a = random_free_point(rng, ref), e = random_free_point(rng, ref);
    const Point pts[] = {a, b, e};
    const geom::Polygon as_shapes[] = {geom::Polygon{{a}, {}}, geom::Polygon{{b}, {}}, geom::Polygon{{e}, {}}};
    if (oct_steiner_minimal_length(kDomain, obstacles, pts) !=
            oct_steiner_minimal_length(kDomain, obstacles, std::span<const geom::Polygon>(as_shapes)) &&
        failed++ < 5)
      ADD_FAILURE() << "points as shapes differ";
  }
  std::printf("%d pads\n", compared);
  EXPECT_EQ(failed, 0);
  // a pad inside a blockage (no free lattice point): no tree
  const std::vector<geom::Polygon> wall = normalized(kDomain, {{{10, 10}, {20, 20}}});
  const geom::Polygon t[] = {geom::Polygon{{{14, 14}, {16, 14}, {16, 16}, {14, 16}}, {}}, geom::Polygon{{{2, 2}}, {}}};
  EXPECT_EQ(oct_steiner_minimal_length(kDomain, wall, std::span<const geom::Polygon>(t)), std::nullopt);
}

TEST(OctSteinerOracle, ThreeTerminalsMatchTheBestBranchPoint) {
  std::vector<Point> lattice;
  for (geom::Coord x = 0; x <= 30; ++x)
    for (geom::Coord y = 0; y <= 30; ++y) lattice.push_back({x, y});
  int failed = 0, compared = 0, off_terminal = 0;
  for (int seed = 1; seed <= sanitized_share(150, 5); ++seed) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937 rng(static_cast<unsigned>(1000 + seed));
    const std::vector<geom::Polygon> obstacles = random_obstacles(rng);
    const OctilinearReference ref(kDomain, obstacles);
    std::vector<Point> t;
    for (int i = 0; i < 3; ++i) t.push_back(random_free_point(rng, ref));
    std::vector<std::vector<Len>> d;
    for (const Point p : t) d.push_back(ref.distances(p, lattice));
    Len best;
    Point at{};
    for (std::size_t v = 0; v < lattice.size(); ++v) {
      if (!d[0][v] || !d[1][v] || !d[2][v]) continue;
      const Root2 sum = *d[0][v] + *d[1][v] + *d[2][v];
      if (!best || sum < *best) best = sum, at = lattice[v];
    }
    const Len got = oct_steiner_minimal_length(kDomain, obstacles, t);
    ++compared;
    off_terminal += best && at != t[0] && at != t[1] && at != t[2];
    if (got != best && failed++ < 5)
      ADD_FAILURE() << "oracle " << (got ? got->to_double() : -1) << ", best branch point "
                    << (best ? best->to_double() : -1);
  }
  std::printf("%d triples, %d with the best branch point off the terminals\n", compared, off_terminal);
  EXPECT_EQ(failed, 0);
}

TEST(OctSteinerOracle, BoundsAndMonotone) {
  const auto start = std::chrono::steady_clock::now();
  int failed = 0, calls = 0, strict_steiner = 0;
  auto fail = [&](int seed, std::size_t j, const char* what) {
    if (failed++ < 10) ADD_FAILURE() << "seed " << seed << ", " << j << " terminals: " << what;
  };
  for (int seed = 1; seed <= sanitized_share(250, 5); ++seed) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937 rng(static_cast<unsigned>(5000 + seed));
    const std::vector<geom::Polygon> obstacles = random_obstacles(rng);
    const OctilinearReference ref(kDomain, obstacles);
    std::vector<Point> t;
    for (int i = 0; i < 6; ++i) t.push_back(random_free_point(rng, ref));
    std::vector<std::vector<Len>> dist(6, std::vector<Len>(6));
    for (std::size_t i = 0; i < 6; ++i)
      for (std::size_t j = 0; j < 6; ++j) dist[i][j] = ref.distance(t[i], t[j]);
    Len prev;
    for (std::size_t j = 1; j <= 6; ++j) {
      const Len got = oct_steiner_minimal_length(kDomain, obstacles, std::span<const Point>(t).first(j));
      ++calls;
      bool connected = true;
      for (std::size_t i = 1; i < j; ++i) connected = connected && dist[0][i].has_value();
      if (got.has_value() != connected) {
        fail(seed, j, "reachability differs from the distances");
        break;
      }
      if (j == 1 && got != Root2{}) fail(seed, j, "one terminal is not 0");
      if (j > 1 && prev.has_value() != got.has_value()) fail(seed, j, "connected with fewer, not with more");
      if (prev && got && *got < *prev) fail(seed, j, "a terminal more made it shorter");
      prev = got;
      if (!got) break;
      // the largest pairwise distance, and the MST (Prim) of the pairwise distances
      Root2 farthest{}, mst{};
      std::vector<Len> key(j);
      std::vector<bool> in(j, false);
      key[0] = Root2{};
      for (std::size_t step = 0; step < j; ++step) {
        std::size_t u = j;
        for (std::size_t v = 0; v < j; ++v)
          if (!in[v] && key[v] && (u == j || *key[v] < *key[u])) u = v;
        in[u] = true;
        mst += *key[u];
        for (std::size_t v = 0; v < j; ++v) {
          if (*dist[u][v] > farthest) farthest = *dist[u][v];
          if (!in[v] && (!key[v] || *dist[u][v] < *key[v])) key[v] = dist[u][v];
        }
      }
      if (*got < farthest) fail(seed, j, "shorter than the largest pairwise distance");
      if (*got > mst) fail(seed, j, "longer than the minimum spanning tree");
      if (times(mst, static_cast<std::int64_t>(j)) > times(*got, 2 * static_cast<std::int64_t>(j - 1)))
        fail(seed, j, "below MST * k / (2 (k - 1))");
      strict_steiner += *got < mst;
    }
    // a repeated terminal changes nothing
    std::vector<Point> rep(t.begin(), t.begin() + 4);
    rep.push_back(t[2]);
    rep.push_back(t[0]);
    const Len with_repeats = oct_steiner_minimal_length(kDomain, obstacles, rep);
    const Len without = oct_steiner_minimal_length(kDomain, obstacles, std::span<const Point>(t).first(4));
    calls += 2;
    if (with_repeats != without) fail(seed, 4, "a repeated terminal changed the length");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%d oracle calls (%d trees shorter than the MST) in %.2f s\n", calls, strict_steiner, seconds);
  EXPECT_EQ(failed, 0);
}

// Sloped obstacles (random triangles, normalized: they cross, touch and pinch): a wire of the
// lattice is an allowed path, so two terminals are never closer than the reference's distance
// (which may be less: an infimum over octilinear paths with any bends) and never joined when the
// reference finds no path. Here the reference's visible() matters (a sliver may cross a unit
// segment between two free lattice points without covering either).
TEST(OctSteinerOracle, SlopedObstaclesNeverBelowTheDistance) {
  const Box d{{0, 0}, {20, 20}};
  int failed = 0, compared = 0, longer = 0;
  for (int seed = 1; seed <= sanitized_share(200, 4); ++seed) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    std::mt19937 rng(static_cast<unsigned>(9000 + seed));
    const std::vector<geom::Polygon> in = test::random_triangles(rng, d, 4);
    const std::vector<geom::Polygon> obstacles = geom::normalize_obstacles(in, d).obstacles;
    const OctilinearReference ref(d, obstacles);
    for (int i = 0; i < 4; ++i) {
      Point t[2];
      for (Point& p : t)
        do p = {static_cast<geom::Coord>(rng() % 21), static_cast<geom::Coord>(rng() % 21)};
        while (!ref.is_free(p));
      const Len got = oct_steiner_minimal_length(d, obstacles, t);
      const Len dist = ref.distance(t[0], t[1]);
      ++compared;
      if (got && (!dist || *got < *dist) && failed++ < 5)
        ADD_FAILURE() << "(" << t[0].x << "," << t[0].y << ") (" << t[1].x << "," << t[1].y << "): oracle "
                      << got->to_double() << ", distance " << (dist ? dist->to_double() : -1);
      longer += dist && (!got || *got > *dist);
    }
  }
  std::printf("%d pairs, %d longer on the lattice than the distance (or not joined)\n", compared, longer);
  EXPECT_EQ(failed, 0);
}

// A sliver: the triangle (1,1), (6,3), (8,4) (area 1/2, no lattice point but its corners) crosses
// the unit segment (3,2)-(4,2) at x in [10/3, 7/2] while both ends are free (the sliver passes
// below (3,2) and above (4,2)). So the two are not joined by that segment (length 1) but round the
// tip (1,1): (3,2) -> (2,2) -> (1,1) -> (2,1) -> (3,1) -> (4,2), 3 + 2*sqrt2, which is the
// reference's distance (d8(2,1) + d8(3,1) through the tip), a lower bound for every lattice path.
TEST(OctSteinerOracle, SliverBetweenLatticePoints) {
  const Box d{{0, 0}, {10, 10}};
  const std::vector<geom::Polygon> in{{{{1, 1}, {8, 4}, {6, 3}}, {}}};
  const std::vector<geom::Polygon> obstacles = geom::normalize_obstacles(in, d).obstacles;
  const OctilinearReference ref(d, obstacles);
  ASSERT_TRUE(ref.is_free({3, 2}));
  ASSERT_TRUE(ref.is_free({4, 2}));
  ASSERT_FALSE(ref.visible({3, 2}, {4, 2}));
  const Point path[] = {{3, 2}, {2, 2}, {1, 1}, {2, 1}, {3, 1}, {4, 2}};
  ASSERT_EQ(ref.check_octilinear_path(path), (Root2{3, 2}));
  ASSERT_EQ(ref.distance({3, 2}, {4, 2}), (Root2{3, 2}));
  const Point t[] = {{3, 2}, {4, 2}};
  EXPECT_EQ(oct_steiner_minimal_length(d, obstacles, t), (Root2{3, 2}));
}

// Lower bounds for the hand cases. d8(dx, dy) (the octilinear length, a norm) is at least
// w . (dx, dy) for every w with w . u <= 1 for the eight unit moves u = (+-1, 0), (0, +-1),
// (+-1, +-1)/sqrt2 (the norm's unit ball is their convex hull). A tree joining three terminals
// t_i is three paths from one branch point v, so L >= sum_i d8(v - t_i) >= sum_i w_i . (v - t_i),
// which for w_1 + w_2 + w_3 = 0 is -sum_i w_i . t_i whatever v is.
TEST(OctSteinerOracle, HandCases) {
  const Box d{{0, 0}, {10, 10}};
  auto len = [&](std::vector<Point> t, const std::vector<geom::Polygon>& obstacles = {}) {
    return oct_steiner_minimal_length(d, obstacles, t);
  };
  // (0,0), (4,0), (2,2), no obstacles: 4*sqrt2 (two diagonals meeting at (2,2)); shorter than the
  // rectilinear star at (2,0) (6) and the star at the Steiner point (2,1) (3 + 2*sqrt2 ~ 5.83).
  // Lower bound: w = (1, sqrt2 - 1), (-1, sqrt2 - 1), (0, 2 - 2*sqrt2) (each at most 1 on every
  // unit move: 1, 1, sqrt2 - 1, ... and |2 - 2*sqrt2| ~ 0.83), summing to 0:
  // -sum w_i . t_i = 0 + 4 - 2 (2 - 2*sqrt2) = 4*sqrt2.
  EXPECT_EQ(len({{0, 0}, {4, 0}, {2, 2}}), (Root2{0, 4}));
  // (0,0), (4,0), (2,3): 1 + 4*sqrt2 with the Steiner point (2,2) that is no terminal (diagonals
  // to (0,0) and (4,0), one unit up); the star at the terminal (2,3) is 2 + 4*sqrt2, at (2,1)
  // 4 + 2*sqrt2 ~ 6.83 > 6.66. Lower bound: w = (sqrt2 - 1/2, 1/2), (1/2 - sqrt2, 1/2), (0, -1)
  // (the first is 1 on (1,1)/sqrt2, sqrt2 - 1/2 ~ 0.91 on (1,0), less on the others), summing to
  // 0: -sum w_i . t_i = 0 - 4 (1/2 - sqrt2) + 3 = 1 + 4*sqrt2.
  EXPECT_EQ(len({{0, 0}, {4, 0}, {2, 3}}), (Root2{1, 4}));
  // Collinear terminals: the span (the tree holds the path between the ends, at least their
  // distance; the segment is that long).
  EXPECT_EQ(len({{1, 5}, {9, 5}, {4, 5}}), (Root2{8, 0}));
  EXPECT_EQ(len({{7, 7}, {0, 0}, {3, 3}}), (Root2{0, 7}));
  // The unit square's corners: 3 (three sides). Every tree of the class has at least 3 unit
  // lattice edges; the X of the two diagonals (2*sqrt2) joins at (1/2, 1/2), not an integer point.
  EXPECT_EQ(len({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), (Root2{3, 0}));
  // None, one, repeated terminals.
  EXPECT_EQ(len({}), Root2{});
  EXPECT_EQ(len({{3, 3}}), Root2{});
  EXPECT_EQ(len({{3, 3}, {3, 3}}), Root2{});
  EXPECT_EQ(len({{2, 2}, {2, 2}, {5, 5}}), (Root2{0, 3}));
  // Outside the domain.
  EXPECT_EQ(len({{0, 0}, {11, 0}}), std::nullopt);
  EXPECT_EQ(len({{-1, 5}}), std::nullopt);

  // A terminal inside an obstacle: none; on its boundary (a corner): free.
  const auto square = normalized(d, {{{3, 3}, {6, 6}}});
  EXPECT_EQ(len({{0, 0}, {4, 5}}, square), std::nullopt);
  EXPECT_EQ(len({{4, 4}}, square), std::nullopt);
  EXPECT_EQ(len({{0, 0}, {3, 3}}, square), (Root2{0, 3}));
  // A wall from the domain's bottom side up to y = 8, x in [4, 6]: (2,2) to (8,2) over it. A
  // path crosses x = 4 at some y1 >= 8 and x = 6 at some y2 >= 8: at least d8(2, y1 - 2) +
  // d8(2, y2 - y1) + d8(2, y2 - 2) >= (4 + 2*sqrt2) + 2 + (4 + 2*sqrt2) (d8 = max + (sqrt2 - 1)
  // min), attained through the wall's top corners (4,8) and (6,8): 10 + 4*sqrt2.
  const auto wall = normalized(d, {{{4, 0}, {6, 8}}});
  EXPECT_EQ(len({{2, 2}, {8, 2}}, wall), (Root2{10, 4}));

  // A ring (outer [2,8]^2, hole (4,6)^2): a terminal in the hole is walled in.
  const auto ring = normalized(d, {{{2, 2}, {8, 4}}, {{2, 6}, {8, 8}}, {{2, 4}, {4, 6}}, {{6, 4}, {8, 6}}});
  ASSERT_EQ(ring.size(), 1u);
  ASSERT_EQ(ring[0].holes.size(), 1u);
  EXPECT_EQ(len({{5, 5}, {0, 0}}, ring), std::nullopt);
  EXPECT_EQ(len({{5, 5}}, ring), Root2{});
  EXPECT_EQ(len({{4, 4}, {6, 6}}, ring), (Root2{0, 2}));  // the hole's diagonal
  // (4,4), (6,6), (5,4) in the hole: 2 + sqrt2 ((4,4) -> (5,4) -> (6,5) -> (6,6)). Lower bound
  // (obstacles only lengthen trees): w = (1, sqrt2 - 1), (1 - sqrt2, -1), (sqrt2 - 2, 2 - sqrt2)
  // (the second is 1 on (0,-1) and on (-1,-1)/sqrt2, the third 2*sqrt2 - 2 ~ 0.83 on
  // (-1,1)/sqrt2), summing to 0: -sum w_i . t_i = -4*sqrt2 + 6*sqrt2 - (sqrt2 - 2) = 2 + sqrt2.
  EXPECT_EQ(len({{4, 4}, {6, 6}, {5, 4}}, ring), (Root2{2, 1}));
}

// Two squares touching at a corner (a pinch at (2,2)) filling the domain [0,4]^2 but for the
// other two quadrants: (1,3) and (3,1) lie in regions that meet only at the pinch, and no wire
// may pass through it. A terminal AT the pinch is metal: the wires from both wedges end there.
TEST(OctSteinerOracle, Pinch) {
  const Box d{{0, 0}, {4, 4}};
  const auto pinched = normalized(d, {{{0, 0}, {2, 2}}, {{2, 2}, {4, 4}}});
  const OctilinearReference ref(d, pinched);
  ASSERT_EQ(ref.wedges_at({2, 2}).size(), 2u);
  ASSERT_EQ(ref.distance({1, 3}, {3, 1}), std::nullopt);
  ASSERT_EQ(ref.distance({1, 3}, {2, 2}), (Root2{0, 1}));
  const Point across[] = {{1, 3}, {3, 1}};
  EXPECT_EQ(oct_steiner_minimal_length(d, pinched, across), std::nullopt);
  const Point at_pinch[] = {{1, 3}, {3, 1}, {2, 2}};
  EXPECT_EQ(oct_steiner_minimal_length(d, pinched, at_pinch), (Root2{0, 2}));
  const Point one_side[] = {{1, 3}, {2, 2}, {0, 4}};
  // (2,2) -> (1,3) -> (0,4) along the diagonal: 2*sqrt2
  EXPECT_EQ(oct_steiner_minimal_length(d, pinched, one_side), (Root2{0, 2}));
}

TEST(OctSteinerOracle, Limits) {
  std::vector<Point> nine;
  for (geom::Coord i = 0; i < 9; ++i) nine.push_back({i, 0});
  const Box d{{0, 0}, {10, 10}};
  EXPECT_THROW(oct_steiner_minimal_length(d, {}, nine), std::invalid_argument);
  nine.back() = nine.front();  // 8 distinct: the span
  EXPECT_EQ(oct_steiner_minimal_length(d, {}, nine), (Root2{7, 0}));
  const Point two[] = {{0, 0}, {79, 79}};
  EXPECT_EQ(oct_steiner_minimal_length({{0, 0}, {79, 79}}, {}, two), (Root2{0, 79}));
  EXPECT_THROW(oct_steiner_minimal_length({{0, 0}, {80, 79}}, {}, two), std::invalid_argument);
}

}  // namespace oct_steiner_oracle_test
}  // namespace taut::oracle
