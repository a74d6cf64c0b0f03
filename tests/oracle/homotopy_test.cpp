// oracle::HomotopyWords (tests/oracle/homotopy.h): hand-worked words around one square, paths
// that touch the obstacle along an edge and through its top vertex, loops; and on the wavefront
// tests' seeded layouts (every `taut gen` kind, degenerate families), invariance under
// homotopy moves: replacing a segment a-b by a-c-b where the triangle abc holds no obstacle
// point, and inserting a there-and-back excursion, never changes the reduced word, while a
// loop around one obstacle changes it.
#include "oracle/homotopy.h"

#include <gtest/gtest.h>

#include <random>

#include "oracle/l1_oracle.h"
#include "support/reach.h"
#include "support/sanitized.h"
#include "support/wavefront_cases.h"
#include "support/wavefront_hand.h"

namespace taut::test {
namespace {

using geom::Point;
using Path = std::vector<Point>;
using i64 = std::int64_t;

TEST(HomotopyWords, AroundOneSquare) {
  const Scene sc = normalized({{0, 0}, {100, 100}}, {rect(40, 40, 60, 60)});
  const oracle::HomotopyWords h(sc.domain, sc.obstacles);
  ASSERT_EQ(h.cut_count(), 1u);
  const Path over{{20, 50}, {50, 80}, {80, 50}}, under{{20, 50}, {50, 20}, {80, 50}};
  EXPECT_EQ(h.word(over), std::vector<int>{1});
  EXPECT_TRUE(h.word(under).empty());
  // along the top edge, bending at the top-left corner and at the top vertex (60,60)
  EXPECT_EQ(h.word(Path{{20, 50}, {40, 60}, {60, 60}, {80, 50}}), h.word(over));
  // through the top vertex from the lower right back up to the upper right: no crossing
  EXPECT_TRUE(h.word(Path{{80, 40}, {60, 60}, {80, 80}}).empty());
  // down the right side from above the top vertex: crosses once, like over the top
  EXPECT_EQ(h.word(Path{{20, 50}, {20, 70}, {60, 60}, {60, 40}, {80, 50}}), h.word(over));
  // a loop around the square, either way, and one not around it
  EXPECT_EQ(h.word(Path{{20, 50}, {50, 80}, {80, 50}, {50, 20}, {20, 50}}), std::vector<int>{1});
  EXPECT_EQ(h.word(Path{{20, 50}, {50, 20}, {80, 50}, {50, 80}, {20, 50}}), std::vector<int>{-1});
  EXPECT_TRUE(h.word(Path{{20, 50}, {30, 90}, {20, 50}}).empty());
  // twice around
  EXPECT_EQ(h.word(Path{{20, 50}, {50, 80}, {80, 50}, {50, 20}, {20, 50}, {50, 80}, {80, 50}, {50, 20}, {20, 50}}),
            (std::vector<int>{1, 1}));
}

TEST(HomotopyWords, TopVertexWithTheObstacleToItsLeft) {
  // a triangle whose top vertex has the interior to its left only: (60,60) with edges to
  // (60,20) (straight down) and (20,20): the cut runs at x = 60 - e
  const Scene sc = normalized({{0, 0}, {100, 100}}, {geom::Polygon{{{20, 20}, {60, 20}, {60, 60}}, {}}});
  const oracle::HomotopyWords h(sc.domain, sc.obstacles);
  const Path over{{10, 50}, {40, 90}, {90, 40}}, under{{10, 50}, {40, 10}, {90, 40}};
  EXPECT_NE(h.word(over), h.word(under));
  EXPECT_EQ(h.word(Path{{10, 50}, {60, 60}, {90, 40}}), h.word(over));  // through the top vertex
  EXPECT_EQ(h.word(Path{{10, 50}, {20, 20}, {60, 20}, {90, 40}}), h.word(under));  // along the bottom
}

// A homotopy move keeps the word when the triangle a, c, b is free: its sides are allowed
// segments, none of a, b, c is an obstacle vertex, and no obstacle vertex lies in the closed
// triangle (an obstacle meeting it would then have to cross a side).
bool free_triangle(const oracle::L1Reference& ref, const std::vector<Point>& vertices, Point a, Point b, Point c) {
  if (!ref.visible(a, c) || !ref.visible(c, b)) return false;
  for (Point v : vertices)
    if (v == a || v == b || v == c) return false;
  auto cr = [](Point o, Point p, Point q) {
    return (i64{p.x} - o.x) * (i64{q.y} - o.y) - (i64{p.y} - o.y) * (i64{q.x} - o.x);
  };
  const i64 o = cr(a, b, c);
  if (o == 0) return true;
  for (Point v : vertices) {
    const i64 s1 = cr(a, b, v), s2 = cr(b, c, v), s3 = cr(c, a, v);
    if ((o > 0 && s1 >= 0 && s2 >= 0 && s3 >= 0) || (o < 0 && s1 <= 0 && s2 <= 0 && s3 <= 0)) return false;
  }
  return true;
}

TEST(HomotopyWords, HomotopyMovesKeepTheWord) {
  i64 instances = 0, moves = 0, loops = 0, nonempty = 0;
  for (std::uint64_t seed = 1; seed <= static_cast<std::uint64_t>(sanitized_share(600, 4)); ++seed) {
    WavefrontCase c;
    try {
      c = make_wavefront_case(seed);
    } catch (const std::exception&) {
      continue;
    }
    const oracle::L1Reference ref(c.domain, c.obstacles);
    if (!ref.problems().empty() || c.obstacles.empty()) continue;
    std::vector<Point> free_pts;
    for (Point p : c.candidates)
      if (ref.is_free(p)) free_pts.push_back(p);
    const std::vector<Point> vertices = obstacle_vertices(c.obstacles);
    for (Point v : vertices)
      if (ref.is_free(v) && ref.wedges_at(v).size() == 1) free_pts.push_back(v);
    if (free_pts.size() < 3) continue;
    const oracle::HomotopyWords h(c.domain, c.obstacles);
    std::mt19937_64 rng(seed);
    auto pick = [&] { return free_pts[rng() % free_pts.size()]; };
    // a random free path: a walk through visible points
    Path path{pick()};
    for (int tries = 0; tries < 200 && path.size() < 8; ++tries) {
      const Point q = pick();
      if (q != path.back() && ref.visible(path.back(), q)) path.push_back(q);
    }
    if (path.size() < 3) continue;
    ++instances;
    const std::vector<int> w = h.word(path);
    nonempty += !w.empty();
    // moves: insert a free corner c into a segment, or a there-and-back excursion
    Path moved = path;
    for (int m = 0; m < 60; ++m) {
      const std::size_t i = rng() % (moved.size() - 1);
      const Point cpt = pick();
      if (cpt == moved[i] || cpt == moved[i + 1]) continue;
      if (m % 3 == 0) {
        if (!ref.visible(moved[i], cpt)) continue;
        moved.insert(moved.begin() + static_cast<std::ptrdiff_t>(i) + 1, {cpt, moved[i]});
      } else {
        if (!free_triangle(ref, vertices, moved[i], moved[i + 1], cpt)) continue;
        moved.insert(moved.begin() + static_cast<std::ptrdiff_t>(i) + 1, cpt);
      }
      ++moves;
      ASSERT_EQ(h.word(moved), w) << "seed " << seed << " (" << c.family << ") move " << m;
    }
    // a loop around obstacle k: appended at the end, it changes the word unless the loop is
    // trivial (a walk that only goes there and back): go out to a free point and back by
    // different visible routes and count only loops with a nonempty word of their own
    const Point s = path.back();
    for (int tries = 0; tries < 400; ++tries) {
      const Point p1 = pick(), p2 = pick();
      if (!ref.visible(s, p1) || !ref.visible(p1, p2) || !ref.visible(p2, s)) continue;
      const Path loop{s, p1, p2, s};
      if (h.word(loop).empty()) continue;
      Path longer = path;
      longer.insert(longer.end(), loop.begin() + 1, loop.end());
      ASSERT_NE(h.word(longer), w) << "seed " << seed << ": a loop with a word of its own changed nothing";
      ++loops;
      break;
    }
  }
  std::printf("%lld instances (%lld paths with a nonempty word), %lld moves, %lld loops\n",
              static_cast<long long>(instances), static_cast<long long>(nonempty), static_cast<long long>(moves),
              static_cast<long long>(loops));
  EXPECT_GE(instances, sanitized_share(400, 4));
  EXPECT_GE(moves, sanitized_share(5000, 4));
  EXPECT_GE(nonempty, sanitized_share(100, 4));
  EXPECT_GE(loops, sanitized_share(50, 4));
}

}  // namespace
}  // namespace taut::test
