// The L1 shortest-path reference (oracle/l1_oracle.h) against a second, independent reference:
// breadth-first search on the integer grid, with blocked cells rasterized straight from the
// input rectangles (not from normalize_obstacles or the oracle). For axis-parallel obstacles
// with integer vertices an L1-shortest path between integer points can follow grid lines, so
// the two must agree exactly. Plus hand-made cases (pinches, enclosures, slits, collinear
// edges, sloped obstacles) with answers worked out in the comments, and metamorphic checks on
// random sloped layouts.
#include "oracle/l1_oracle.h"
#include "support/random_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <deque>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "oracle/union_oracle.h"
#include "support/reach.h"

namespace l1_oracle_test {

using taut::geom::Box;
using taut::geom::Point;
using taut::geom::Polygon;
using taut::geom::Ring;
using taut::oracle::L1Reference;
using Dist = std::optional<std::int64_t>;
constexpr int kLargeRects = 100;  // about 320 vertices

Ring rect_ring(Box b) { return {b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}; }

// An input blockage: a rectangle, optionally with one rectangular hole.
struct Shape {
  Box outer;
  std::optional<Box> hole;
  Polygon polygon() const {
    Polygon p{rect_ring(outer), {}};
    if (hole) p.holes.push_back(rect_ring(*hole));
    return p;
  }
};

std::string describe(const Box& domain, const std::vector<Shape>& shapes) {
  std::ostringstream os;
  auto box = [&](const Box& b) {
    os << "[" << b.lo.x << "," << b.lo.y << " " << b.hi.x << "," << b.hi.y << "]";
  };
  os << "domain ";
  box(domain);
  for (const Shape& s : shapes) {
    os << " rect ";
    box(s.outer);
    if (s.hole) {
      os << " hole ";
      box(*s.hole);
    }
  }
  return os.str();
}

std::string str(Point p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; }

// ---------------------------------------------------------------------------------------------
// Grid reference. Cell (cx, cy) is the open unit square (cx, cx+1) x (cy, cy+1); it is free iff
// it lies in the domain and no input covers it. Around a lattice point p the four cells NE, NW,
// SW, SE (counter-clockwise) are joined through the unit edge they share (north, west, south,
// east of p) when both are free: the groups are the wedges at p (two diagonal free cells with
// the other two blocked: a pinch). The unit edge east of p is usable iff NE(p) or SE(p) is
// free, and it joins the wedge of that cell at p to the wedge of the same cell at p + (1, 0).
class Grid {
 public:
  Grid(const Box& domain, const std::vector<Shape>& shapes)
      : lo_(domain.lo), w_(domain.hi.x - domain.lo.x), h_(domain.hi.y - domain.lo.y) {
    free_.assign(static_cast<std::size_t>(w_ * h_), true);
    for (int cy = 0; cy < h_; ++cy)
      for (int cx = 0; cx < w_; ++cx) {
        const int x = lo_.x + cx, y = lo_.y + cy;
        auto covers = [&](const Box& b) {
          return b.lo.x <= x && x + 1 <= b.hi.x && b.lo.y <= y && y + 1 <= b.hi.y;
        };
        for (const Shape& s : shapes)
          if (covers(s.outer) && !(s.hole && covers(*s.hole))) free_[cell(cx, cy)] = false;
      }
  }

  // Cell with lower-left corner (x, y) in absolute coordinates is free.
  bool cell_free(int x, int y) const {
    const int cx = x - lo_.x, cy = y - lo_.y;
    if (cx < 0 || cy < 0 || cx >= w_ || cy >= h_) return false;
    return free_[cell(cx, cy)];
  }

  // Wedge label (0..3) of each of the four cells NE, NW, SW, SE at p; -1 for a blocked cell.
  std::array<int, 4> wedges(Point p) const {
    const std::array<bool, 4> f = {cell_free(p.x, p.y), cell_free(p.x - 1, p.y),
                                   cell_free(p.x - 1, p.y - 1), cell_free(p.x, p.y - 1)};
    return taut::test::cell_wedge_labels(f);
  }
  int wedge_count(Point p) const {
    const auto l = wedges(p);
    int n = 0;
    for (int i = 0; i < 4; ++i) n += l[i] == i;
    return n;
  }
  bool in_domain(Point p) const {
    return p.x >= lo_.x && p.x <= lo_.x + w_ && p.y >= lo_.y && p.y <= lo_.y + h_;
  }

  // BFS distances from s to every state (lattice point, wedge label); -1 unreachable.
  std::vector<int> bfs(Point s) const {
    std::vector<int> dist(static_cast<std::size_t>((w_ + 1) * (h_ + 1) * 4), -1);
    std::deque<std::size_t> queue;
    if (in_domain(s)) {
      const auto l = wedges(s);
      for (int i = 0; i < 4; ++i)
        if (l[i] == i) {
          dist[state(s, i)] = 0;
          queue.push_back(state(s, i));
        }
    }
    // Unit moves: direction, the two cells beside the edge as indices into p's NE,NW,SW,SE,
    // and the same two cells as seen from the other end q.
    struct Move {
      int dx, dy;
      std::array<int, 2> at_p, at_q;
    };
    static constexpr std::array<Move, 4> kMoves = {{
        {1, 0, {0, 3}, {1, 2}},    // east: NE, SE of p are NW, SW of q
        {-1, 0, {1, 2}, {0, 3}},   // west
        {0, 1, {0, 1}, {3, 2}},    // north: NE, NW of p are SE, SW of q
        {0, -1, {3, 2}, {0, 1}},   // south
    }};
    while (!queue.empty()) {
      const std::size_t st = queue.front();
      queue.pop_front();
      const Point p = point_of(st);
      const int wedge = static_cast<int>(st % 4);
      const auto lp = wedges(p);
      for (const Move& m : kMoves) {
        const Point q{p.x + m.dx, p.y + m.dy};
        if (!in_domain(q)) continue;
        const auto lq = wedges(q);
        for (int k = 0; k < 2; ++k) {
          if (lp[m.at_p[k]] != wedge) continue;  // that side cell is not in our wedge (or blocked)
          const std::size_t next = state(q, lq[m.at_q[k]]);
          if (dist[next] < 0) {
            dist[next] = dist[st] + 1;
            queue.push_back(next);
          }
        }
      }
    }
    return dist;
  }
  Dist distance_to(const std::vector<int>& dist, Point t) const {
    if (!in_domain(t)) return std::nullopt;
    const auto l = wedges(t);
    int best = -1;
    for (int i = 0; i < 4; ++i)
      if (l[i] == i && dist[state(t, i)] >= 0 && (best < 0 || dist[state(t, i)] < best))
        best = dist[state(t, i)];
    if (best < 0) return std::nullopt;
    return best;
  }

 private:
  std::size_t cell(int cx, int cy) const { return static_cast<std::size_t>(cy * w_ + cx); }
  std::size_t state(Point p, int wedge) const {
    return static_cast<std::size_t>(((p.y - lo_.y) * (w_ + 1) + (p.x - lo_.x)) * 4 + wedge);
  }
  Point point_of(std::size_t st) const {
    const int i = static_cast<int>(st / 4);
    return {lo_.x + i % (w_ + 1), lo_.y + i / (w_ + 1)};
  }
  Point lo_;
  int w_, h_;
  std::vector<bool> free_;
};

// ---------------------------------------------------------------------------------------------

struct Scene {
  Box domain;
  std::vector<Polygon> obstacles;
};

Scene normalized(const Box& domain, const std::vector<Polygon>& inputs) {
  const auto r = taut::geom::normalize_obstacles(inputs, domain);
  return {r.domain, r.obstacles};
}
Scene normalized(const Box& domain, const std::vector<Shape>& shapes) {
  std::vector<Polygon> in;
  for (const Shape& s : shapes) in.push_back(s.polygon());
  return normalized(domain, in);
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

// Random axis-parallel layouts on a coarse grid: overlapping, edge-touching and corner-touching
// (pinching) rectangles, frames with holes and rectangles inside the holes, some sticking out of
// the domain (clipped).
std::vector<Shape> random_shapes(std::mt19937& rng, const Box& domain) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const int step = uni(1, 3);
  auto snap = [&](int v) { return v - ((v % step) + step) % step; };
  std::vector<Shape> shapes;
  const int n = uni(1, 7);
  for (int i = 0; i < n; ++i) {
    Box b;
    const bool in_hole = !shapes.empty() && shapes.back().hole && uni(0, 1) == 0;
    if (in_hole) {
      const Box h = *shapes.back().hole;
      if (h.hi.x - h.lo.x < 2 || h.hi.y - h.lo.y < 2) continue;
      b.lo = {uni(h.lo.x, h.hi.x - 1), uni(h.lo.y, h.hi.y - 1)};
      b.hi = {uni(b.lo.x + 1, h.hi.x), uni(b.lo.y + 1, h.hi.y)};
    } else if (!shapes.empty() && uni(0, 3) == 0) {
      // Diagonal to a corner of the previous rectangle: a pinch (unless something fills it).
      const Box o = shapes.back().outer;
      const int w = step * uni(1, 3), h = step * uni(1, 3);
      b = taut::test::corner_box(o, w, h, uni(0, 3));
    } else {
      b.lo = {snap(uni(domain.lo.x - 2, domain.hi.x - 1)),
              snap(uni(domain.lo.y - 2, domain.hi.y - 1))};
      b.hi = {b.lo.x + step * uni(1, 4), b.lo.y + step * uni(1, 4)};
    }
    Shape s{b, std::nullopt};
    if (!in_hole && uni(0, 4) == 0 && b.hi.x - b.lo.x >= 3 && b.hi.y - b.lo.y >= 3) {
      Box h;
      h.lo = {uni(b.lo.x + 1, b.hi.x - 2), uni(b.lo.y + 1, b.hi.y - 2)};
      h.hi = {uni(h.lo.x + 1, b.hi.x - 1), uni(h.lo.y + 1, b.hi.y - 1)};
      s.hole = h;
    }
    shapes.push_back(s);
  }
  return shapes;
}

TEST(L1Oracle, MatchesGridBfsOnRandomRectilinearLayouts) {
  const unsigned base = 7100;
  int compared = 0, reachable = 0, pinch_queries = 0, layouts_with_pinch = 0, paths = 0;
  for (unsigned it = 0; it < 1500; ++it) {
    const unsigned seed = base + it;
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const Box domain{{uni(-3, 0), uni(-3, 0)}, {uni(5, 11), uni(5, 11)}};
    const std::vector<Shape> shapes = random_shapes(rng, domain);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + describe(domain, shapes));
    const Scene scene = normalized(domain, shapes);
    ASSERT_EQ(join(taut::oracle::check_obstacles(scene.obstacles, scene.domain)), "");
    const L1Reference ref(scene.domain, scene.obstacles);
    ASSERT_EQ(join(ref.problems()), "");
    const Grid grid(domain, shapes);

    // Query candidates: obstacle vertices, pinch points, random lattice points (free, on
    // boundaries, inside obstacles, walled in).
    std::vector<Point> vertices, pinches;
    for (const Polygon& p : scene.obstacles) {
      for (const Point v : p.outer) vertices.push_back(v);
      for (const Ring& h : p.holes)
        for (const Point v : h) vertices.push_back(v);
    }
    for (int y = domain.lo.y; y <= domain.hi.y; ++y)
      for (int x = domain.lo.x; x <= domain.hi.x; ++x)
        if (grid.wedge_count({x, y}) >= 2) pinches.push_back({x, y});
    layouts_with_pinch += !pinches.empty();
    auto pick = [&]() -> Point {
      const int kind = uni(0, 5);
      if (kind == 0 && !vertices.empty()) return vertices[rng() % vertices.size()];
      if (kind == 1 && !pinches.empty()) return pinches[rng() % pinches.size()];
      return {uni(domain.lo.x, domain.hi.x), uni(domain.lo.y, domain.hi.y)};
    };
    for (int q = 0; q < 3; ++q) {
      const Point s = pick();
      std::vector<Point> targets;
      for (int k = 0; k < 12; ++k) targets.push_back(pick());
      const std::vector<int> bfs = grid.bfs(s);
      const std::vector<Dist> got = ref.distances(s, targets);
      ASSERT_EQ(ref.is_free(s), grid.wedge_count(s) > 0) << "s " << str(s);
      for (std::size_t k = 0; k < targets.size(); ++k) {
        const Point t = targets[k];
        const Dist want = grid.distance_to(bfs, t);
        ASSERT_EQ(got[k], want) << "s " << str(s) << " t " << str(t);
        ASSERT_EQ(static_cast<int>(ref.wedges_at(t).size()), grid.wedge_count(t)) << str(t);
        ++compared;
        reachable += want.has_value();
        pinch_queries += grid.wedge_count(t) >= 2;
      }
      // A shortest path: from s to t, its length is the distance, and every segment is a
      // shortest connection on the grid too (else the oracle took a forbidden shortcut).
      const Point t = targets[0];
      const auto path = ref.path(s, t);
      ASSERT_EQ(path.has_value(), got[0].has_value()) << "s " << str(s) << " t " << str(t);
      if (!path) continue;
      ++paths;
      ASSERT_EQ(path->front(), s);
      ASSERT_EQ(path->back(), t);
      std::int64_t len = 0;
      for (std::size_t i = 0; i + 1 < path->size(); ++i) {
        const Point a = (*path)[i], b = (*path)[i + 1];
        const std::int64_t l = std::abs(a.x - b.x) + std::abs(a.y - b.y);
        len += l;
        ASSERT_EQ(grid.distance_to(grid.bfs(a), b), l) << "segment " << str(a) << str(b);
      }
      ASSERT_EQ(len, *got[0]);
      ASSERT_EQ(ref.check_path(*path), got[0]);
    }
  }
  // The generator must exercise what it is meant to.
  EXPECT_GT(compared, 50000);
  EXPECT_GT(reachable, compared / 3);
  EXPECT_LT(reachable, compared - compared / 20);
  EXPECT_GT(layouts_with_pinch, 100);
  EXPECT_GT(pinch_queries, 500);
  EXPECT_GT(paths, 2000);
  std::printf("compared %d (reachable %d, at pinches %d), layouts with a pinch %d, paths %d\n",
              compared, reachable, pinch_queries, layouts_with_pinch, paths);
}

// One larger layout (a few hundred vertices), also against the grid: the size the wavefront
// tests will use. Counts kept small for the sanitizer build.
TEST(L1Oracle, LargerLayoutMatchesGridBfs) {
  const unsigned seed = 7001;
  std::mt19937 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const Box domain{{0, 0}, {120, 120}};
  std::vector<Shape> shapes;
  for (int i = 0; i < kLargeRects; ++i) {
    const Point lo{2 * uni(0, 57), 2 * uni(0, 57)};
    shapes.push_back({{lo, {lo.x + 2 * uni(1, 5), lo.y + 2 * uni(1, 5)}}, std::nullopt});
  }
  SCOPED_TRACE("seed " + std::to_string(seed) + ": " + describe(domain, shapes));
  const Scene scene = normalized(domain, shapes);
  const L1Reference ref(scene.domain, scene.obstacles);
  ASSERT_EQ(join(ref.problems()), "");
  const Grid grid(domain, shapes);
  std::vector<Point> targets;
  for (int k = 0; k < 200; ++k) targets.push_back({uni(0, 120), uni(0, 120)});
  int reachable = 0;
  for (int q = 0; q < 4; ++q) {
    const Point s = targets[static_cast<std::size_t>(q)];
    const std::vector<int> bfs = grid.bfs(s);
    const std::vector<Dist> got = ref.distances(s, targets);
    for (std::size_t k = 0; k < targets.size(); ++k) {
      ASSERT_EQ(got[k], grid.distance_to(bfs, targets[k])) << str(s) << " " << str(targets[k]);
      reachable += got[k].has_value();
    }
  }
  EXPECT_GT(reachable, 300);
  std::printf("%zu nodes, %zu visibility edges\n", ref.node_count(), ref.edge_count());
}

// ---------------------------------------------------------------------------------------------
// Hand-made cases.

TEST(L1Oracle, SquaresTouchingAtACorner) {
  //   y
  //   4 .   .   +---+        B = [2,4]x[2,4]
  //     s(1,3)  | B |
  //   2 .   +---*---+        * (2,2): pinch, two wedges (NW and SE)
  //     | A |   t(3,1)
  //   0 +---+   .   .        A = [0,2]x[0,2]
  //     0   2   4
  // Straight through the pinch would be 4. Around A: x 1 -> <=0 -> 3 (4), y 3 -> <=0 -> 1 (4).
  const Box domain{{-2, -2}, {6, 6}};
  const Scene sc = normalized(domain, std::vector<Shape>{
      {{{0, 0}, {2, 2}}, {}},
      {{{2, 2}, {4, 4}}, {}}});
  ASSERT_EQ(sc.obstacles.size(), 1u);  // merged: they touch
  const L1Reference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.problems().size(), 0u);
  EXPECT_EQ(ref.wedges_at({2, 2}).size(), 2u);
  EXPECT_EQ(ref.distance({1, 3}, {3, 1}), 8);
  EXPECT_FALSE(ref.visible({1, 3}, {3, 1}));
  EXPECT_FALSE(ref.visible({0, 4}, {4, 0}));  // the anti-diagonal through the pinch
  // A query at the pinch may use either wedge.
  EXPECT_EQ(ref.distance({1, 3}, {2, 2}), 2);
  EXPECT_EQ(ref.distance({2, 2}, {3, 1}), 2);
  EXPECT_EQ(ref.distance({2, 2}, {2, 2}), 0);
  // Along the edges of A: (0,2) -> (2,2) -> (2,0) would switch wedges at the pinch.
  EXPECT_EQ(ref.distance({1, 2}, {2, 1}), 1 + 2 + 2 + 1);  // around A's far corners: 6
  const auto p = ref.path({1, 3}, {3, 1});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(ref.check_path(*p), 8);
  EXPECT_EQ(ref.check_path(std::vector<Point>{{1, 3}, {2, 2}, {3, 1}}), std::nullopt);
}

TEST(L1Oracle, PointEnclosedByARing) {
  //  +-----------+   frame [0,10]^2 with hole [3,7]^2; s = (5,5) in the hole
  //  |  +-----+  |
  //  |  |  s  |  |
  //  |  +-----+  |
  //  +-----------+
  const Box domain{{-5, -5}, {15, 15}};
  const Scene sc = normalized(domain, std::vector<Shape>{
      {{{0, 0}, {10, 10}}, Box{{3, 3}, {7, 7}}}});
  const L1Reference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.distance({5, 5}, {12, 5}), std::nullopt);
  EXPECT_EQ(ref.distance({5, 5}, {1, 1}), std::nullopt);  // inside the obstacle: not free
  EXPECT_FALSE(ref.is_free({1, 1}));
  EXPECT_EQ(ref.distance({5, 5}, {4, 4}), 2);
  EXPECT_EQ(ref.distance({5, 5}, {3, 5}), 2);   // on the hole's edge
  EXPECT_EQ(ref.distance({5, 5}, {7, 7}), 4);   // at the hole's corner
  EXPECT_EQ(ref.distance({3, 3}, {7, 7}), 8);
  EXPECT_EQ(ref.distance({0, 0}, {10, 10}), 20);  // outer corners: around the frame
  EXPECT_EQ(ref.distance({-5, -5}, {15, 15}), 40);
  EXPECT_EQ(ref.distance({0, 5}, {10, 5}), 20);  // left edge to right edge, around
}

TEST(L1Oracle, SlitOneDbuWide) {
  //  y=4 ##########.##########     A = [-5,4]x[2,4], B = [5,15]x[2,4]: slit x in [4,5]
  //  y=2 ##########.##########     flush with both domain sides
  //        s=(0,0) below, t=(0,6) above: 4 + 6 + 4 = 14
  const Box domain{{-5, -5}, {15, 10}};
  const Scene sc = normalized(domain, std::vector<Shape>{
      {{{-5, 2}, {4, 4}}, {}},
      {{{5, 2}, {15, 4}}, {}}});
  const L1Reference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.distance({0, 0}, {0, 6}), 14);
  EXPECT_EQ(ref.distance({4, 0}, {5, 6}), 7);
  EXPECT_EQ(ref.distance({4, 3}, {5, 3}), 1);  // across the slit, both on boundaries
  EXPECT_TRUE(ref.visible({4, 0}, {5, 6}));     // diagonal through the slit
  EXPECT_FALSE(ref.visible({3, 0}, {5, 6}));
  // On the domain side where A is flush: no free space beside it.
  EXPECT_FALSE(ref.is_free({-5, 3}));
  EXPECT_TRUE(ref.is_free({-5, 2}));  // A's corner on the side: free below
  // Close the slit: B touches A along x = 4 (merged), nothing crosses.
  const Scene closed = normalized(domain, std::vector<Shape>{
      {{{-5, 2}, {4, 4}}, {}},
      {{{4, 2}, {15, 4}}, {}}});
  const L1Reference ref2(closed.domain, closed.obstacles);
  EXPECT_EQ(ref2.distance({0, 0}, {0, 6}), std::nullopt);
  EXPECT_EQ(ref2.distance({4, 2}, {4, 4}), std::nullopt);  // (4,2) below, (4,4) above
}

TEST(L1Oracle, CollinearEdges) {
  //  ..+--+.+--+.+--+..     three squares on y = 0: [0,2], [3,5], [6,8] (height 2)
  //  ..|  |.|  |.|  |..     paths along y = 0 and y = 2 run on the edges
  //  --+--+-+--+-+--+--
  const Box domain{{-2, -2}, {10, 6}};
  const Scene sc = normalized(domain, std::vector<Shape>{
      {{{0, 0}, {2, 2}}, {}},
      {{{3, 0}, {5, 2}}, {}},
      {{{6, 0}, {8, 2}}, {}}});
  const L1Reference ref(sc.domain, sc.obstacles);
  EXPECT_TRUE(ref.visible({-1, 0}, {9, 0}));
  EXPECT_TRUE(ref.visible({-1, 2}, {9, 2}));
  EXPECT_EQ(ref.distance({-1, 0}, {9, 0}), 10);
  EXPECT_EQ(ref.distance({1, 0}, {7, 0}), 6);
  EXPECT_EQ(ref.distance({1, 2}, {7, 2}), 6);
  EXPECT_EQ(ref.distance({1, 2}, {7, 0}), 8);  // down through a gap: 6 + 2
  EXPECT_FALSE(ref.visible({1, 1}, {4, 1}));   // (1,1) is inside A: not free
  EXPECT_EQ(ref.distance({2, 1}, {3, 1}), 1);  // across the 1-wide gap
  EXPECT_EQ(ref.distance({-2, -2}, {10, -2}), 12);  // along the domain side
}

TEST(L1Oracle, TriangleInTheWay) {
  //        t (0,6)
  //          /\      triangle (-3,0) (3,0) (0,4)
  //         /  \     s -> (-3,0) -> t: (3+2) + (3+6) = 14; lower bound: y travels 8, and
  //        /____\    at y = 0 the triangle spans x in [-3,3], so x travels >= 3 + 3.
  //        s (0,-2)
  const Box domain{{-10, -10}, {10, 10}};
  const Scene sc = normalized(domain, std::vector<Polygon>{{{{-3, 0}, {3, 0}, {0, 4}}, {}}});
  const L1Reference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.distance({0, -2}, {0, 6}), 14);
  EXPECT_TRUE(ref.visible({-3, 0}, {0, 6}));
  EXPECT_TRUE(ref.visible({-3, 0}, {0, 4}));   // along the edge
  EXPECT_FALSE(ref.visible({-3, 0}, {1, 4}));  // cuts the corner at (0,4)
  EXPECT_EQ(ref.distance({-3, 0}, {3, 0}), 6);
  EXPECT_EQ(ref.distance({-1, 0}, {1, 2}), std::nullopt);  // (1,2) is inside
  // From the base (free side: below) to the apex: around (-3,0): 2 + (3 + 4) = 9.
  EXPECT_EQ(ref.distance({-1, 0}, {0, 4}), 9);
}

TEST(L1Oracle, DiamondTouchingTheDomainSide) {
  //  Diamond (5,0) (7,2) (5,4) (3,2) in [0,10]^2: its tip touches the bottom side at (5,0),
  //  a pinch against the domain wall. s = (2,0), t = (8,0): crossing x = 5 needs y >= 4, so
  //  y travels >= 8 and x 6: 14.
  const Box domain{{0, 0}, {10, 10}};
  const Scene sc = normalized(domain, std::vector<Polygon>{{{{5, 0}, {7, 2}, {5, 4}, {3, 2}}, {}}});
  const L1Reference ref(sc.domain, sc.obstacles);
  EXPECT_EQ(ref.wedges_at({5, 0}).size(), 2u);
  EXPECT_FALSE(ref.visible({2, 0}, {8, 0}));
  EXPECT_EQ(ref.distance({2, 0}, {8, 0}), 14);
  EXPECT_EQ(ref.distance({5, 0}, {8, 0}), 3);
  EXPECT_EQ(ref.distance({2, 0}, {5, 0}), 3);
}

// ---------------------------------------------------------------------------------------------
// Sloped obstacles: no second reference, so metamorphic checks. Symmetry, the L1 lower bound,
// equality with it when the segment is allowed, the triangle inequality (not through a
// pinch), paths that check, and scaling the scene by 2 and turning it by 90 degrees doubles
// every distance.

TEST(L1Oracle, MetamorphicOnRandomSlopedLayouts) {
  const unsigned base = 9100;
  int checked = 0, unreachable = 0;
  for (unsigned it = 0; it < 300; ++it) {
    const unsigned seed = base + it;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const Box domain{{0, 0}, {uni(6, 16), uni(6, 16)}};
    const std::vector<Polygon> in = taut::test::random_triangles(rng, domain, 5);
    const auto nr = taut::geom::normalize_obstacles(in, domain);
    if (nr.stats.rounded != 0) continue;  // keep scaling exact: integer crossings only
    const L1Reference ref(nr.domain, nr.obstacles);
    ASSERT_EQ(join(ref.problems()), "");
    // The same scene scaled by 2 and turned a quarter counter-clockwise (keeps ring
    // orientation, and L1 lengths up to the factor 2).
    auto turn = [](Point p) { return Point{-2 * p.y, 2 * p.x}; };
    std::vector<Polygon> turned;
    for (const Polygon& p : nr.obstacles) {
      Polygon q;
      for (const Point v : p.outer) q.outer.push_back(turn(v));
      for (const Ring& h : p.holes) {
        q.holes.emplace_back();
        for (const Point v : h) q.holes.back().push_back(turn(v));
      }
      turned.push_back(q);
    }
    const Box domain2{{-2 * domain.hi.y, 2 * domain.lo.x}, {-2 * domain.lo.y, 2 * domain.hi.x}};
    const L1Reference ref2(domain2, turned);
    std::vector<Point> pts;
    for (int k = 0; k < 6; ++k) pts.push_back({uni(0, domain.hi.x), uni(0, domain.hi.y)});
    for (const Polygon& p : nr.obstacles)
      pts.push_back(p.outer[rng() % p.outer.size()]);
    std::vector<std::vector<Dist>> d;
    for (const Point s : pts) d.push_back(ref.distances(s, pts));
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Point s = pts[i];
      std::vector<Point> pts2;
      for (const Point p : pts) pts2.push_back(turn(p));
      const std::vector<Dist> d2 = ref2.distances(pts2[i], pts2);
      for (std::size_t j = 0; j < pts.size(); ++j) {
        const Point t = pts[j];
        SCOPED_TRACE("s " + str(s) + " t " + str(t));
        ASSERT_EQ(d[i][j], d[j][i]);
        ASSERT_EQ(d2[j].has_value(), d[i][j].has_value());
        if (d[i][j]) {
          ASSERT_EQ(*d2[j], 2 * *d[i][j]);
        }
        if (!d[i][j]) {
          ++unreachable;
          continue;
        }
        ++checked;
        const std::int64_t l1 = std::abs(s.x - t.x) + std::abs(s.y - t.y);
        ASSERT_GE(*d[i][j], l1);
        if (ref.visible(s, t)) {
          ASSERT_EQ(*d[i][j], l1);
        }
        for (std::size_t k = 0; k < pts.size(); ++k)
          // Not through a pinch: a query point there may switch wedges, a path may not.
          if (d[i][k] && d[k][j] && ref.wedges_at(pts[k]).size() == 1) {
            ASSERT_LE(*d[i][j], *d[i][k] + *d[k][j])
                << "via " << str(pts[k]) << " wedges " << ref.wedges_at(pts[k]).size();
          }
        const auto p = ref.path(s, t);
        ASSERT_TRUE(p.has_value());
        ASSERT_EQ(ref.check_path(*p), d[i][j]);
      }
    }
  }
  EXPECT_GT(checked, 3000);
  EXPECT_GT(unreachable, 100);
  std::printf("checked %d pairs, %d unreachable\n", checked, unreachable);
}

// Coordinates near the limit (2^30 - 1): the triangle and diamond cases scaled by 2^27, in a
// domain spanning the whole coordinate range; every distance scales exactly.
TEST(L1Oracle, HugeCoordinates) {
  const int k = 1 << 27;
  auto big = [&](Point p) { return Point{p.x * k, p.y * k}; };
  const Box domain{{-taut::geom::kMaxCoord, -taut::geom::kMaxCoord},
                   {taut::geom::kMaxCoord, taut::geom::kMaxCoord}};
  {
    const std::vector<Polygon> tri{{{big({-3, 0}), big({3, 0}), big({0, 4})}, {}}};
    const L1Reference ref(domain, tri);
    EXPECT_EQ(ref.distance(big({0, -2}), big({0, 6})), std::int64_t{14} * k);
    EXPECT_EQ(ref.distance(big({-1, 0}), big({0, 4})), std::int64_t{9} * k);
    // The diagonal between far corners passes (0,0) on the base and enters the triangle:
    // blocked; a staircase around the triangle still has the L1 length 4 (2^30 - 1).
    EXPECT_FALSE(ref.visible(domain.lo, domain.hi));
    EXPECT_EQ(ref.distance(domain.lo, domain.hi), 4 * std::int64_t{taut::geom::kMaxCoord});
    EXPECT_TRUE(ref.visible({domain.lo.x, domain.hi.y}, {domain.hi.x, domain.hi.y}));
  }
  {
    // The diamond touching the bottom side of a domain whose bottom is at -(2^30 - 1).
    const int b = -taut::geom::kMaxCoord;
    const Box d2{{0, b}, {10 * k, b + 7 * k}};
    auto at = [&](int x, int y) { return Point{x * k, b + y * k}; };
    const std::vector<Polygon> dia{{{at(5, 0), at(7, 2), at(5, 4), at(3, 2)}, {}}};
    const L1Reference ref(d2, dia);
    EXPECT_EQ(ref.wedges_at(at(5, 0)).size(), 2u);
    EXPECT_EQ(ref.distance(at(2, 0), at(8, 0)), std::int64_t{14} * k);
  }
}

}  // namespace l1_oracle_test
