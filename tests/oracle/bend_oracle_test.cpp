// The bend-aware reference (oracle/bend_oracle.h: Dijkstra on the Hanan grid x arriving
// direction) against hand-worked cases and against a second, independent search: Dijkstra on the
// unit integer grid x (wedge, arriving direction), with blocked cells rasterized straight from
// the input rectangles (not from normalize_obstacles or the L1 reference), the wedge rule read
// off the four cells around each lattice point as in l1_oracle_test. For axis-parallel obstacles
// with integer vertices and integer query points every Hanan grid point is a lattice point, so
// the lattice search finds the optimum whenever the reference does and can only do better if the
// Hanan grid were not enough: the two must agree exactly, in every metric. Also: the reference's
// grid against the same search on every lattice line (best_on_lattice), its length at C = 0
// against the L1 reference's distance, and check_path on hand-made paths.
#include "oracle/bend_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <optional>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "oracle/l1_oracle.h"
#include "support/sanitized.h"
#include "support/reach.h"
#include "support/random_shapes.h"

namespace bend_oracle_test {

using taut::geom::Box;
using taut::geom::Point;
using taut::geom::Polygon;
using taut::geom::Ring;
using taut::oracle::BendAnswer;
using taut::oracle::BendReference;
using Answer = std::optional<BendAnswer>;

Ring rect_ring(Box b) { return {b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}; }
Polygon rect(int x0, int y0, int x1, int y1) { return {rect_ring({{x0, y0}, {x1, y1}}), {}}; }

std::string str(Point p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; }
std::string str(const Answer& a) {
  if (!a) return "none";
  return "{length " + std::to_string(a->length) + ", bends " + std::to_string(a->bends) + "}";
}

// The reference on the normalized union of `inputs` clipped to `domain`.
struct Scene {
  taut::geom::NormalizedObstacles norm;
  BendReference ref;
  Scene(const Box& domain, const std::vector<Polygon>& inputs)
      : norm(taut::geom::normalize_obstacles(inputs, domain)), ref(norm.domain, norm.obstacles) {}
};

// The metrics every hand case is asked in: combined with these C, and link.
constexpr std::array<std::int64_t, 6> kCs = {0, 1, 7, 21, 22, 1000};

// ---------------------------------------------------------------------------------------------
// Hand-worked cases.

TEST(BendOracle, EmptyPlane) {
  const Scene sc({{0, 0}, {10, 10}}, {});
  for (const std::int64_t C : kCs) {
    EXPECT_EQ(sc.ref.best({1, 1}, {1, 8}, false, C), (BendAnswer{7, 0})) << C;  // straight
    EXPECT_EQ(sc.ref.best({1, 1}, {8, 5}, false, C), (BendAnswer{11, 1})) << C;  // one L
    EXPECT_EQ(sc.ref.best({3, 3}, {3, 3}, false, C), (BendAnswer{0, 0})) << C;
  }
  EXPECT_EQ(sc.ref.best({1, 1}, {1, 8}, true, 0), (BendAnswer{7, 0}));
  EXPECT_EQ(sc.ref.best({1, 1}, {8, 5}, true, 0), (BendAnswer{11, 1}));
  // Along the domain sides (free: no obstacle is flush there), corner to corner.
  EXPECT_EQ(sc.ref.best({0, 0}, {10, 10}, false, 1000), (BendAnswer{20, 1}));
  // Outside the domain: not free.
  EXPECT_EQ(sc.ref.best({-1, 1}, {1, 8}, false, 0), std::nullopt);
  EXPECT_EQ(sc.ref.best({1, 1}, {1, 11}, true, 0), std::nullopt);
}

// A wall x in [6, 14], y in [-30, 30] with a zigzag channel through it: in at y in [4, 6] from
// the left, down the shaft 9 <= x <= 11, out at y in [-6, -4] to the right. As rectangles:
// A = [6,14]x[6,30], B = [6,14]x[-30,-6], C1 = [6,9]x[-6,4], C2 = [11,14]x[-4,6] (A+C2 and B+C1
// merge along y = 6 and y = -6). From s = (0, 0) to t = (20, 0) in the domain [-10,30]x[-40,40]:
//   - through the channel: the path needs a horizontal link at y in [4, 6] (the way in), one at
//     y in [-6, -4] (the way out) and vertical links from y = 0 to the first, between them and
//     back to y = 0: V H V H V, 4 bends; its vertical length is at least 4 + 8 + 4, so 20 + 16 =
//     36, e.g. (0,0) (0,4) (10,4) (10,-4) (20,-4) (20,0), running along C1's top and C2's bottom.
//   - around the wall: up to y = 30 (along A's top edge), across, down: 30 + 20 + 30 = 80 with
//     2 bends; no path has fewer (a 1-bend path is an L, which meets the wall), and a 3-bend one
//     around is no shorter (V H V H with the H at |y| >= 30: 80).
// So C = 0, 1, 7, 21: 36 + 4C < 80 + 2C, answer {36, 4}; C = 22: 124 = 124, the tie goes to
// fewer bends, {80, 2}; C = 1000 and link: {80, 2}. (A 2-bend path is never shorter than a
// 4-bend one here: the link metric prefers the longer path.)
TEST(BendOracle, ChannelOrDetourDependsOnC) {
  const Scene sc({{-10, -40}, {30, 40}},
                 {rect(6, 6, 14, 30), rect(6, -30, 14, -6), rect(6, -6, 9, 4), rect(11, -4, 14, 6)});
  ASSERT_EQ(sc.norm.obstacles.size(), 2u);
  const Point s{0, 0}, t{20, 0};
  for (const std::int64_t C : {0, 1, 7, 21}) EXPECT_EQ(sc.ref.best(s, t, false, C), (BendAnswer{36, 4})) << C;
  for (const std::int64_t C : {22, 23, 1000}) EXPECT_EQ(sc.ref.best(s, t, false, C), (BendAnswer{80, 2})) << C;
  EXPECT_EQ(sc.ref.best(s, t, true, 0), (BendAnswer{80, 2}));
  EXPECT_EQ(sc.ref.best(t, s, true, 0), (BendAnswer{80, 2}));
  EXPECT_EQ(sc.ref.best(t, s, false, 7), (BendAnswer{36, 4}));
  // The paths named above are legal with those costs.
  const std::vector<Point> channel = {{0, 0}, {0, 4}, {10, 4}, {10, -4}, {20, -4}, {20, 0}};
  const std::vector<Point> around = {{0, 0}, {0, 30}, {20, 30}, {20, 0}};
  EXPECT_EQ(sc.ref.check_path(channel), (BendAnswer{36, 4}));
  EXPECT_EQ(sc.ref.check_path(around), (BendAnswer{80, 2}));
  // Straight through the wall, and a 2-bend try at the channel's height: not legal.
  EXPECT_EQ(sc.ref.check_path(std::vector<Point>{{0, 0}, {20, 0}}), std::nullopt);
  EXPECT_EQ(sc.ref.check_path(std::vector<Point>{{0, 0}, {0, 5}, {20, 5}, {20, 0}}), std::nullopt);
}

// Squares [0,10]^2 and [10,20]^2 touching at (10,10) only, domain [-10,30]^2. From (5,15) to
// (15,5): through the pinch is closed. Around either square: (5,15) (5,20) (20,20) (20,5) (15,5)
// or (5,15) (0,15) (0,0) (15,0) (15,5), 40 with 3 bends. No 2-bend path: V H V needs a horizontal
// from x = 5 to 15 clear of both squares, i.e. y = 10 (through the pinch), y = 20 or y = 0, and
// then a vertical through one square; H V H likewise. With the second square moved to
// [11,21]^2 the diagonal gap opens: (5,15) (10,15) (10,5) (15,5), 20 with 2 bends.
TEST(BendOracle, SquaresTouchingAtACornerBlockPassage) {
  const Scene sc({{-10, -10}, {30, 30}}, {rect(0, 0, 10, 10), rect(10, 10, 20, 20)});
  ASSERT_EQ(sc.norm.obstacles.size(), 1u);
  for (const std::int64_t C : kCs) EXPECT_EQ(sc.ref.best({5, 15}, {15, 5}, false, C), (BendAnswer{40, 3})) << C;
  EXPECT_EQ(sc.ref.best({5, 15}, {15, 5}, true, 0), (BendAnswer{40, 3}));
  // Straight through the pinch, either way: not a legal path.
  EXPECT_EQ(sc.ref.check_path(std::vector<Point>{{5, 10}, {15, 10}}), std::nullopt);
  EXPECT_EQ(sc.ref.check_path(std::vector<Point>{{5, 15}, {10, 15}, {10, 5}, {15, 5}}), std::nullopt);
  // Turning at the pinch inside one wedge is fine: (5,10) -> (10,10) -> (10,15) stays in the
  // north-west wedge: 10 with 1 bend.
  EXPECT_EQ(sc.ref.check_path(std::vector<Point>{{5, 10}, {10, 10}, {10, 15}}), (BendAnswer{10, 1}));
  EXPECT_EQ(sc.ref.check_path(std::vector<Point>{{5, 10}, {10, 10}, {10, 5}}), std::nullopt);
  // A query at the pinch starts in either wedge: to (5,15) along the first square's top edge
  // then up (10, 1 bend), to (15,5) along its right edge... down then right (10, 1 bend).
  EXPECT_EQ(sc.ref.best({10, 10}, {5, 15}, false, 1), (BendAnswer{10, 1}));
  EXPECT_EQ(sc.ref.best({10, 10}, {15, 5}, false, 1), (BendAnswer{10, 1}));
  EXPECT_EQ(sc.ref.best({5, 15}, {10, 10}, true, 0), (BendAnswer{10, 1}));
  // From the pinch into the other wedge's side: to (15,15)? inside the second square, not free.
  EXPECT_EQ(sc.ref.best({10, 10}, {15, 15}, false, 1), std::nullopt);

  const Scene gap({{-10, -10}, {30, 30}}, {rect(0, 0, 10, 10), rect(11, 11, 21, 21)});
  ASSERT_EQ(gap.norm.obstacles.size(), 2u);
  for (const std::int64_t C : kCs) EXPECT_EQ(gap.ref.best({5, 15}, {15, 5}, false, C), (BendAnswer{20, 2})) << C;
  EXPECT_EQ(gap.ref.best({5, 15}, {15, 5}, true, 0), (BendAnswer{20, 2}));
}

// The square [10,20]^2 in the domain [0,30]^2; s = (15,20), the middle of its top edge.
//   - to (15,7) below (between the square and a block [10,20]x[0,5] flush on the domain's
//     bottom side): along the top edge to a corner, down its side, back: 5 + 13 + 5 = 23, 2 bends
//     (0 or 1 bend would cross the square);
//   - to (15,25) straight up: 5, 0 bends; to (25,15): along the edge and down past the corner,
//     (15,20) (25,20) (25,15): 15, 1 bend;
//   - from the corner (20,20) to (15,7): down the right side, then left: 13 + 5 = 18, 1 bend.
// A point inside the square, and one on the block's edge flush with the domain side: not free.
// The block's bottom corners are free (one quadrant each): (15,20) to (10,0) along the square's
// and the block's left sides, 5 + 20 = 25, 1 bend; (10,0) to (20,0) over the block, 20, 2 bends.
TEST(BendOracle, QueryOnAnObstacleEdge) {
  const Scene sc({{0, 0}, {30, 30}}, {rect(10, 10, 20, 20), rect(10, 0, 20, 5)});
  for (const std::int64_t C : kCs) {
    EXPECT_EQ(sc.ref.best({15, 20}, {15, 25}, false, C), (BendAnswer{5, 0})) << C;
    EXPECT_EQ(sc.ref.best({15, 20}, {25, 15}, false, C), (BendAnswer{15, 1})) << C;
    EXPECT_EQ(sc.ref.best({20, 20}, {15, 7}, false, C), (BendAnswer{18, 1})) << C;
    EXPECT_EQ(sc.ref.best({15, 20}, {15, 7}, false, C), (BendAnswer{23, 2})) << C;
  }
  EXPECT_EQ(sc.ref.best({15, 20}, {15, 7}, true, 0), (BendAnswer{23, 2}));
  EXPECT_EQ(sc.ref.best({15, 20}, {15, 15}, false, 0), std::nullopt);  // inside
  EXPECT_EQ(sc.ref.best({15, 20}, {15, 0}, false, 0), std::nullopt);   // flush with y = 0
  EXPECT_EQ(sc.ref.best({15, 20}, {10, 0}, false, 0), (BendAnswer{25, 1}));
  EXPECT_EQ(sc.ref.best({10, 0}, {20, 0}, false, 0), (BendAnswer{20, 2}));  // over the block: 5 + 10 + 5
}

// Enclosed: a point in a ring's hole reaches only points in the hole.
TEST(BendOracle, WalledIn) {
  const Polygon ring{rect_ring({{10, 10}, {30, 30}}), {{{15, 15}, {15, 25}, {25, 25}, {25, 15}}}};
  const Scene sc({{0, 0}, {40, 40}}, {ring});
  EXPECT_EQ(sc.ref.best({5, 5}, {20, 20}, false, 1), std::nullopt);
  EXPECT_EQ(sc.ref.best({5, 5}, {20, 20}, true, 0), std::nullopt);
  EXPECT_EQ(sc.ref.best({16, 16}, {24, 24}, false, 1), (BendAnswer{16, 1}));
  EXPECT_EQ(sc.ref.best({15, 15}, {25, 25}, true, 0), (BendAnswer{20, 1}));  // hole corners
}

TEST(BendOracle, CheckPathRules) {
  const Scene sc({{0, 0}, {10, 10}}, {rect(4, 4, 6, 6)});
  using P = std::vector<Point>;
  EXPECT_EQ(sc.ref.check_path(P{{1, 1}}), (BendAnswer{0, 0}));
  EXPECT_EQ(sc.ref.check_path(P{{5, 5}}), std::nullopt);  // inside
  EXPECT_EQ(sc.ref.check_path(P{}), std::nullopt);
  // A point in the middle of a straight run is no bend; repeated points are ignored.
  EXPECT_EQ(sc.ref.check_path(P{{1, 1}, {1, 5}, {1, 5}, {1, 8}, {3, 8}}), (BendAnswer{9, 1}));
  // Along the obstacle's edges, turning at its corners.
  EXPECT_EQ(sc.ref.check_path(P{{4, 2}, {4, 6}, {8, 6}}), (BendAnswer{8, 1}));
  // Sloped: rejected even where free.
  EXPECT_EQ(sc.ref.check_path(P{{1, 1}, {2, 3}}), std::nullopt);
  // Reversal: rejected.
  EXPECT_EQ(sc.ref.check_path(P{{1, 1}, {1, 8}, {1, 3}}), std::nullopt);
  EXPECT_EQ(sc.ref.check_path(P{{1, 1}, {3, 1}, {3, 3}, {3, 1}}), std::nullopt);
  // Through the obstacle.
  EXPECT_EQ(sc.ref.check_path(P{{1, 5}, {8, 5}}), std::nullopt);
  // A U-turn in two bends is fine.
  EXPECT_EQ(sc.ref.check_path(P{{1, 1}, {1, 8}, {2, 8}, {2, 1}}), (BendAnswer{15, 2}));
}

// ---------------------------------------------------------------------------------------------
// Lattice search on rasterized cells (independent of normalize_obstacles and the L1 reference).
// Cell (x, y) is the open unit square (x, x+1) x (y, y+1); free iff inside the domain and in no
// input rectangle. At a lattice point the four cells NE, NW, SW, SE (counter-clockwise) are
// grouped through the unit edges they share when both are free: the groups are the wedges (see
// l1_oracle_test). A unit step east from p is usable iff NE(p) or SE(p) is free; it leaves p in
// that cell's wedge and arrives at p + (1, 0) in the same cell's wedge there. A state is (lattice
// point, wedge, arriving direction); a step may not reverse and costs 1 plus one bend when it
// changes direction.
class CellSearch {
 public:
  CellSearch(const Box& domain, const std::vector<Box>& blocks) : lo_(domain.lo), w_(domain.hi.x - domain.lo.x), h_(domain.hi.y - domain.lo.y) {
    free_.assign(static_cast<std::size_t>(w_ * h_), true);
    for (int cy = 0; cy < h_; ++cy)
      for (int cx = 0; cx < w_; ++cx) {
        const int x = lo_.x + cx, y = lo_.y + cy;
        for (const Box& b : blocks)
          if (b.lo.x <= x && x + 1 <= b.hi.x && b.lo.y <= y && y + 1 <= b.hi.y) free_[cy * w_ + cx] = false;
      }
  }
  bool cell_free(int x, int y) const {
    const int cx = x - lo_.x, cy = y - lo_.y;
    return cx >= 0 && cy >= 0 && cx < w_ && cy < h_ && free_[cy * w_ + cx];
  }
  std::array<int, 4> wedges(Point p) const {  // label per cell NE, NW, SW, SE; -1 blocked
    const std::array<bool, 4> f = {cell_free(p.x, p.y), cell_free(p.x - 1, p.y), cell_free(p.x - 1, p.y - 1),
                                   cell_free(p.x, p.y - 1)};
    return taut::test::cell_wedge_labels(f);
  }
  bool in_domain(Point p) const { return p.x >= lo_.x && p.x <= lo_.x + w_ && p.y >= lo_.y && p.y <= lo_.y + h_; }
  bool is_free(Point p) const {
    if (!in_domain(p)) return false;
    const auto l = wedges(p);
    return std::any_of(l.begin(), l.end(), [](int v) { return v >= 0; });
  }

  Answer best(Point s, Point t, bool link, std::int64_t C) const {
    if (!is_free(s) || !is_free(t)) return std::nullopt;
    if (s == t) return BendAnswer{0, 0};
    // Directions E, N, W, S; the two cells beside each unit step, as indices into NE, NW, SW,
    // SE at p, and the same cells seen from the far end q.
    struct Move {
      int dx, dy;
      std::array<int, 2> at_p, at_q;
    };
    static constexpr std::array<Move, 4> kMoves = {{
        {1, 0, {0, 3}, {1, 2}},
        {0, 1, {0, 1}, {3, 2}},
        {-1, 0, {1, 2}, {0, 3}},
        {0, -1, {3, 2}, {0, 1}},
    }};
    using Key = std::pair<__int128, __int128>;
    auto key = [&](std::int64_t len, std::int64_t bends) -> Key {
      if (link) return {bends, len};
      return {__int128{len} + __int128{C} * bends, bends};
    };
    // State: ((point * 4 + wedge) * 5 + direction), direction 4 = start.
    auto id = [&](Point p, int wedge, int d) {
      return ((static_cast<std::size_t>((p.y - lo_.y) * (w_ + 1) + (p.x - lo_.x)) * 4 + wedge) * 5 + d);
    };
    const std::size_t n = static_cast<std::size_t>((w_ + 1) * (h_ + 1)) * 20;
    std::vector<std::optional<std::pair<std::int64_t, std::int64_t>>> dist(n);
    std::vector<bool> done(n);
    using Item = std::tuple<Key, std::size_t, Point, int, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    const auto ls = wedges(s);
    for (int i = 0; i < 4; ++i)
      if (ls[i] == i) {
        dist[id(s, i, 4)] = {{0, 0}};
        queue.push({key(0, 0), id(s, i, 4), s, i, 4});
      }
    while (!queue.empty()) {
      const auto [k, st, p, wedge, din] = queue.top();
      queue.pop();
      if (done[st]) continue;
      done[st] = true;
      const auto [len, bends] = *dist[st];
      if (p == t) return BendAnswer{len, bends};
      const auto lp = wedges(p);
      for (int d = 0; d < 4; ++d) {
        if (din != 4 && d == (din + 2) % 4) continue;
        const Move& m = kMoves[d];
        const Point q{p.x + m.dx, p.y + m.dy};
        if (!in_domain(q)) continue;
        const auto lq = wedges(q);
        for (int c = 0; c < 2; ++c) {
          if (lp[m.at_p[c]] != wedge) continue;  // that side cell is blocked or in another wedge
          const int nb = static_cast<int>(bends) + (din != 4 && d != din);
          const std::size_t ns = id(q, lq[m.at_q[c]], d);
          if (!dist[ns] || key(len + 1, nb) < key(dist[ns]->first, dist[ns]->second)) {
            dist[ns] = {{len + 1, nb}};
            queue.push({key(len + 1, nb), ns, q, lq[m.at_q[c]], d});
          }
        }
      }
    }
    return std::nullopt;
  }

 private:
  Point lo_;
  int w_, h_;
  std::vector<bool> free_;
};

// Random axis-parallel layouts on a small grid: rectangles that overlap, share edges, touch at
// corners (pinches), stick out of the domain (clipped) or lie flush with its sides. With `walls`,
// first parallel walls one unit thick with a gap or two each (zigzag channels: the shortest path
// is often not the one with the fewest bends).
std::vector<Box> random_blocks(std::mt19937& rng, const Box& domain, bool walls) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<Box> out;
  if (walls) {
    const bool vertical = uni(0, 1);
    const int lo = vertical ? domain.lo.x : domain.lo.y, hi = vertical ? domain.hi.x : domain.hi.y;
    const int lo2 = vertical ? domain.lo.y : domain.lo.x, hi2 = vertical ? domain.hi.y : domain.hi.x;
    for (int at = lo + uni(1, 3); at < hi - 1; at += uni(2, 4)) {
      const int from = lo2 + uni(-1, 3), to = hi2 - uni(-1, 3);
      std::vector<int> cuts = {from};
      for (int g = uni(1, 2); g > 0; --g) {
        const int gap = uni(from + 1, std::max(from + 1, to - 2));
        cuts.push_back(gap), cuts.push_back(gap + uni(1, 2));
      }
      cuts.push_back(to);
      std::sort(cuts.begin() + 1, cuts.end() - 1);
      for (std::size_t k = 0; k + 1 < cuts.size(); k += 2)
        if (cuts[k] < cuts[k + 1])
          out.push_back(vertical ? Box{{at, cuts[k]}, {at + 1, cuts[k + 1]}} : Box{{cuts[k], at}, {cuts[k + 1], at + 1}});
    }
  }
  const int n = walls ? uni(0, 2) : uni(1, 8);
  for (int i = 0; i < n; ++i) {
    Box b;
    if (!out.empty() && uni(0, 2) == 0) {  // diagonal to a corner of the previous one: a pinch
      const Box o = out.back();
      const int w = uni(1, 3), h = uni(1, 3);
      b = taut::test::corner_box(o, w, h, uni(0, 3));
    } else {
      b.lo = {uni(domain.lo.x - 1, domain.hi.x - 1), uni(domain.lo.y - 1, domain.hi.y - 1)};
      b.hi = {b.lo.x + uni(1, 5), b.lo.y + uni(1, 5)};
    }
    out.push_back(b);
  }
  return out;
}

std::string describe(const Box& domain, const std::vector<Box>& blocks) {
  std::ostringstream os;
  auto box = [&](const Box& b) { os << "{{" << b.lo.x << "," << b.lo.y << "},{" << b.hi.x << "," << b.hi.y << "}}"; };
  os << "domain ";
  box(domain);
  os << " blocks";
  for (const Box& b : blocks) {
    os << " ";
    box(b);
  }
  return os.str();
}

TEST(BendOracle, MatchesCellLatticeSearchOnRandomLayouts) {
  int compared = 0, found = 0, pinch_queries = 0, metric_matters = 0;
  // A sample in the sanitizer tree (memory errors; ~10x the run time).
  const int layouts = static_cast<int>(taut::test::sanitized_share(400, 8));
  for (unsigned seed = 6000; seed < 6000 + static_cast<unsigned>(layouts); ++seed) {
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const bool walls = seed % 2 == 1;
    const Box domain{{uni(-1, 0), uni(-1, 0)}, {uni(8, 14), uni(8, 14)}};
    const std::vector<Box> blocks = random_blocks(rng, domain, walls);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + describe(domain, blocks));
    std::vector<Polygon> inputs;
    for (const Box& b : blocks) inputs.push_back({rect_ring(b), {}});
    const Scene sc(domain, inputs);
    const CellSearch cells(domain, blocks);
    std::vector<Point> vertices;
    for (const Polygon& p : sc.norm.obstacles) {
      for (const Point v : p.outer) vertices.push_back(v);
      for (const Ring& h : p.holes) vertices.insert(vertices.end(), h.begin(), h.end());
    }
    auto pick = [&]() -> Point {
      if (!vertices.empty() && uni(0, 2) == 0) return vertices[rng() % vertices.size()];
      return {uni(domain.lo.x, domain.hi.x), uni(domain.lo.y, domain.hi.y)};
    };
    for (int q = 0; q < 6; ++q) {
      const Point s = pick(), t = pick();
      ASSERT_EQ(sc.ref.l1().is_free(t), cells.is_free(t)) << str(t);
      pinch_queries += sc.ref.l1().wedges_at(t).size() >= 2;
      const Answer by_link = sc.ref.best(s, t, true, 0);
      ASSERT_EQ(by_link, cells.best(s, t, true, 0)) << "link " << str(s) << " -> " << str(t);
      for (const std::int64_t C : {0, 1, 3, 1000}) {
        const Answer a = sc.ref.best(s, t, false, C);
        ASSERT_EQ(str(a), str(cells.best(s, t, false, C))) << "C " << C << " " << str(s) << " -> " << str(t);
        if (C == 0) {  // the shortest length is the L1 distance
          const auto d = sc.ref.l1().distance(s, t);
          ASSERT_EQ(a.has_value(), d.has_value());
          if (a) {
            ASSERT_EQ(a->length, *d);
          }
        }
        if (C == 0 && a && by_link && *a != *by_link) ++metric_matters;
        ++compared;
        found += a.has_value();
      }
      if (q < 2) {  // the Hanan grid is enough: every lattice line as well changes nothing
        ASSERT_EQ(str(sc.ref.best(s, t, false, 1)), str(sc.ref.best_on_lattice(s, t, false, 1)));
        ASSERT_EQ(str(sc.ref.best(s, t, true, 0)), str(sc.ref.best_on_lattice(s, t, true, 0)));
      }
    }
  }
  // The sample exercises what it should.
  EXPECT_EQ(compared, layouts * 6 * 4);
  EXPECT_GT(found, compared / 3);
  EXPECT_LT(found, compared);
  EXPECT_GT(pinch_queries, taut::test::sanitized_share(20, 10));
  // The shortest path is not the one with the fewest bends.
  EXPECT_GT(metric_matters, taut::test::sanitized_share(10, 10));
  std::printf("compared %d, found %d, at pinches %d, shortest and fewest bends differ %d\n", compared, found,
              pinch_queries, metric_matters);
}

}  // namespace bend_oracle_test
