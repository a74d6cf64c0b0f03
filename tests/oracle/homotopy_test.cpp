// oracle::HomotopyWords (tests/oracle/homotopy.h): hand-worked words around one square, paths
// that touch the obstacle along an edge and through its top vertex, loops; and on the wavefront
// tests' seeded layouts (every `taut gen` kind, degenerate families), invariance under
// homotopy moves: replacing a segment a-b by a-c-b where the triangle abc holds no obstacle
// point, and inserting a there-and-back excursion, never changes the reduced word, while a
// loop around one obstacle changes it. Obstacles whose ring passes through its top vertex
// twice (lobes pinched there: the constructor once threw on them, or cut inside the obstacle),
// by hand and in seeded random layouts whose rings are also reversed, rotated, and given
// repeated and collinear vertices: a loop around each obstacle crosses its cut once, and free
// triangles give the empty word.
#include "oracle/homotopy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <random>

#include "geom/predicates.h"
#include "oracle/l1_oracle.h"
#include "support/reach.h"
#include "support/sanitized.h"
#include "support/wavefront_cases.h"
#include "support/wavefront_hand.h"

namespace taut::test {
namespace homotopy_test {

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

// The signed number of times a word crosses the cut of obstacle k (its letter k + 1).
int crossings_of(const std::vector<int>& w, std::size_t k) {
  int n = 0;
  for (int l : w) n += l == static_cast<int>(k + 1) ? 1 : l == -static_cast<int>(k + 1) ? -1 : 0;
  return n;
}

// One obstacle inside the box lo-hi, at mid height y: a loop around it crosses its cut once
// (-1 counter-clockwise, +1 clockwise), and paths over and under it from one side to the other
// differ.
void expect_one_obstacle_loop(const oracle::HomotopyWords& h, Point lo, Point hi, geom::Coord y) {
  const Path around{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}, lo};
  EXPECT_EQ(h.word(around), std::vector<int>{-1});
  EXPECT_EQ(h.word(Path(around.rbegin(), around.rend())), std::vector<int>{1});
  const Path over{{lo.x, y}, {lo.x, hi.y}, hi, {hi.x, y}}, under{{lo.x, y}, lo, {hi.x, lo.y}, {hi.x, y}};
  EXPECT_NE(h.word(over), h.word(under));
}

TEST(HomotopyWords, TopVertexWhereTwoLobesTouch) {
  // Two triangles touching at their common top vertex (1,1) are one obstacle whose ring passes
  // through (1,1) twice. The old constructor took the ring neighbours of the first visit,
  // (1,0) and (2,0), as the sides of the interior: they bound the free wedge between the lobes,
  // and the edge it picked missed the cut line (std::logic_error).
  const Scene sc = normalized({{-2, -2}, {5, 4}}, {geom::Polygon{{{0, 0}, {1, 0}, {1, 1}}, {}},
                                                   geom::Polygon{{{1, 1}, {2, 0}, {3, 0}}, {}}});
  ASSERT_EQ(sc.obstacles.size(), 1u);
  ASSERT_EQ(sc.obstacles[0].outer, (geom::Ring{{0, 0}, {1, 0}, {1, 1}, {2, 0}, {3, 0}, {1, 1}}));
  const oracle::HomotopyWords h(sc.domain, sc.obstacles);
  ASSERT_EQ(h.cut_count(), 1u);
  expect_one_obstacle_loop(h, {-1, -1}, {4, 3}, 1);
  EXPECT_TRUE(h.word(Path{{0, 2}, {3, 2}, {2, 3}, {0, 2}}).empty());  // over the cut and back, above (1,1)
  EXPECT_TRUE(h.word(Path{{4, 1}, {3, 1}, {4, -1}, {4, 1}}).empty());   // right of the lobes
}

TEST(HomotopyWords, TopVertexWhereTwoLobesTouchMirrored) {
  // The mirror image. Here the old constructor did not throw but was wrong: the first visit of
  // (2,2) has neighbours (4,0) and (6,0), so it started the cut at x = 2 + e on the left lobe's
  // edge (2,2)-(4,0), and the cut ended at once on the right lobe's edge (2,2)-(6,0) across the
  // notch between the lobes: it never reached the outside, and a loop around the obstacle had
  // the empty word.
  const Scene sc = normalized({{-2, -2}, {9, 5}}, {geom::Polygon{{{0, 0}, {4, 0}, {2, 2}}, {}},
                                                   geom::Polygon{{{2, 2}, {6, 0}, {8, 0}}, {}}});
  ASSERT_EQ(sc.obstacles.size(), 1u);
  ASSERT_EQ(sc.obstacles[0].outer, (geom::Ring{{0, 0}, {4, 0}, {2, 2}, {6, 0}, {8, 0}, {2, 2}}));
  const oracle::HomotopyWords h(sc.domain, sc.obstacles);
  expect_one_obstacle_loop(h, {-1, -1}, {9, 4}, 1);
}

// Seeded layouts of the kind above: a 3 x 3 grid of 24 x 24 cells, most holding an obstacle
// made of 2 or 3 lobes (triangles, sometimes quadrilaterals) that touch only at their common
// top vertex v (each lobe lies in its own angular sector below v, sectors from 12 directions
// including straight down and horizontally left), normalized into one pinched ring. Each ring
// is then reversed (1 in 2), rotated, and given a repeated and a collinear vertex (1 in 3 each):
// the oracle must not rely on normalization's orientation or cleaning. Checks: no throw; the
// loop round each cell crosses that obstacle's cut exactly once (letter -(k + 1) net for
// counter-clockwise, so its word is nontrivial); random triangles in a cell that meet no lobe
// (half of them with corners near v, in the notches between lobes) have the empty word.
TEST(HomotopyWords, RandomObstaclesPinchedAtTheirTopVertex) {
  const int S = 24, G = 3;
  static constexpr Point dirs[] = {{-1, 0}, {-3, -1}, {-2, -1}, {-1, -1}, {-1, -2}, {-1, -3},
                                   {0, -1}, {1, -3},  {1, -2},  {1, -1},  {2, -1},  {3, -1}};  // by angle
  const std::uint64_t layouts = static_cast<std::uint64_t>(sanitized_share(3000, 10));
  i64 obstacles = 0, reversed = 0, repeated = 0, collinear = 0, triangles = 0;
  for (std::uint64_t seed = 1; seed <= layouts; ++seed) {
    std::mt19937_64 rng(seed);
    auto r = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
    struct Cell {
      int x0, y0;
      Point v;
      std::vector<geom::Ring> lobes;
    };
    std::vector<Cell> cells;
    std::vector<geom::Polygon> inputs;
    for (int i = 0; i < G; ++i)
      for (int j = 0; j < G; ++j) {
        if (r(0, 3) == 0) continue;
        Cell c{i * S, j * S, {i * S + r(8, 16), j * S + r(16, 20)}, {}};
        const int L = r(2, 3);
        std::vector<int> idx(std::size(dirs));
        std::iota(idx.begin(), idx.end(), 0);
        std::shuffle(idx.begin(), idx.end(), rng);
        idx.resize(static_cast<std::size_t>(2 * L));
        std::sort(idx.begin(), idx.end());
        auto reach = [&](Point d) {  // x within v.x -+ 6, y down to v.y - 14: inside the cell
          const int t = std::min(d.x ? 6 / std::abs(d.x) : 99, d.y ? 14 / std::abs(d.y) : 99);
          const int k = r(1, t);
          return Point{c.v.x + k * d.x, c.v.y + k * d.y};
        };
        for (int l = 0; l < L; ++l) {
          const Point a = reach(dirs[idx[2 * l]]), b = reach(dirs[idx[2 * l + 1]]);
          const Point m{a.x + b.x - c.v.x, a.y + b.y - c.v.y};
          const bool quad = r(0, 2) == 0 && m.x >= c.x0 + 2 && m.x <= c.x0 + S - 2 && m.y >= c.y0 + 2;
          geom::Ring lobe = quad ? geom::Ring{c.v, a, m, b} : geom::Ring{c.v, a, b};
          if (geom::twice_area(lobe) < 0) std::reverse(lobe.begin(), lobe.end());
          c.lobes.push_back(lobe);
          inputs.push_back({lobe, {}});
        }
        cells.push_back(c);
      }
    if (cells.empty()) continue;
    const std::string where = "seed " + std::to_string(seed);
    Scene sc = normalized({{0, 0}, {G * S, G * S}}, inputs);
    ASSERT_EQ(sc.obstacles.size(), cells.size()) << where;
    // which obstacle each cell holds; then unnormalize the rings
    std::vector<std::size_t> of(cells.size());
    for (std::size_t ci = 0; ci < cells.size(); ++ci) {
      const auto it = std::find_if(sc.obstacles.begin(), sc.obstacles.end(), [&](const geom::Polygon& p) {
        return std::count(p.outer.begin(), p.outer.end(), cells[ci].v) >= 2;  // pinched there
      });
      ASSERT_NE(it, sc.obstacles.end()) << where;
      of[ci] = static_cast<std::size_t>(it - sc.obstacles.begin());
    }
    for (geom::Polygon& p : sc.obstacles) {
      geom::Ring& ring = p.outer;
      if (r(0, 1)) std::reverse(ring.begin(), ring.end()), ++reversed;
      std::rotate(ring.begin(), ring.begin() + r(0, static_cast<int>(ring.size()) - 1), ring.end());
      if (r(0, 2) == 0) {
        const auto i = static_cast<std::ptrdiff_t>(r(0, static_cast<int>(ring.size()) - 1));
        ring.insert(ring.begin() + i, ring[static_cast<std::size_t>(i)]);
        ++repeated;
      }
      if (r(0, 2) == 0) {  // the midpoint of an edge with even steps
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Point a = ring[i], b = ring[(i + 1) % ring.size()];
          if (a != b && (a.x - b.x) % 2 == 0 && (a.y - b.y) % 2 == 0) {
            ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(i) + 1, Point{(a.x + b.x) / 2, (a.y + b.y) / 2});
            ++collinear;
            break;
          }
        }
      }
    }
    std::unique_ptr<oracle::HomotopyWords> hp;
    try {
      hp = std::make_unique<oracle::HomotopyWords>(sc.domain, sc.obstacles);
    } catch (const std::exception& e) {
      FAIL() << where << ": " << e.what();
    }
    const oracle::HomotopyWords& h = *hp;
    ASSERT_EQ(h.cut_count(), sc.obstacles.size()) << where;
    for (std::size_t ci = 0; ci < cells.size(); ++ci) {
      const Cell& c = cells[ci];
      ++obstacles;
      const Path around{{c.x0 + 1, c.y0 + 1}, {c.x0 + S - 1, c.y0 + 1}, {c.x0 + S - 1, c.y0 + S - 1},
                        {c.x0 + 1, c.y0 + S - 1}, {c.x0 + 1, c.y0 + 1}};
      const std::vector<int> w = h.word(around);
      ASSERT_FALSE(w.empty()) << where << " cell " << ci;
      ASSERT_EQ(crossings_of(w, of[ci]), -1) << where << " cell " << ci;
      ASSERT_EQ(crossings_of(h.word(Path(around.rbegin(), around.rend())), of[ci]), 1) << where << " cell " << ci;
      // free triangles: no lobe vertex in the closed triangle, no side meeting a lobe edge, and
      // a corner outside every lobe
      auto inside = [](Point a, Point b, Point c2, Point p) {
        const int s1 = geom::orientation(a, b, p), s2 = geom::orientation(b, c2, p), s3 = geom::orientation(c2, a, p);
        return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
      };
      for (int t = 0; t < 30; ++t) {
        auto pick = [&] {
          if (t % 2) return Point{std::clamp(c.v.x + r(-3, 3), c.x0 + 1, c.x0 + S - 1), c.v.y + r(-3, 3)};
          return Point{c.x0 + r(1, S - 1), c.y0 + r(1, S - 1)};
        };
        const Point a = pick(), b = pick(), d = pick();
        if (geom::orientation(a, b, d) == 0) continue;
        bool free = true;
        for (const geom::Ring& lobe : c.lobes) {
          free = free && geom::locate(a, lobe) == geom::Location::Outside;
          for (std::size_t i = 0; free && i < lobe.size(); ++i) {
            const geom::Segment e{lobe[i], lobe[(i + 1) % lobe.size()]};
            free = !inside(a, b, d, e.a) && geom::intersect({a, b}, e) == geom::SegmentIntersection::None &&
                   geom::intersect({b, d}, e) == geom::SegmentIntersection::None &&
                   geom::intersect({d, a}, e) == geom::SegmentIntersection::None;
          }
        }
        if (!free) continue;
        ++triangles;
        ASSERT_TRUE(h.word(Path{a, b, d, a}).empty()) << where << " cell " << ci << " triangle " << str(Path{a, b, d, a});
      }
    }
  }
  std::printf("%lld obstacles (rings: %lld reversed, %lld with a repeated, %lld with a collinear vertex), %lld free triangles\n",
              static_cast<long long>(obstacles), static_cast<long long>(reversed), static_cast<long long>(repeated),
              static_cast<long long>(collinear), static_cast<long long>(triangles));
  EXPECT_GE(obstacles, sanitized_share(15000, 10));
  EXPECT_GE(triangles, sanitized_share(100000, 10));
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

}  // namespace homotopy_test
}  // namespace taut::test
