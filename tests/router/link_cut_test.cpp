// router::balanced_cut and router::CutTree (de Berg's rectilinear polygon cutting theorem,
// seeds/002 section 2) against a brute-force search that shares only geom's types and
// predicates with them: every candidate cut segment is walked in unit steps with exact
// half-unit membership tests (doubled coordinates, geom::locate), its parts are built by walking
// the ring and counted after dropping straight vertices by hand. Checked on every node of the
// cut tree of random polyominoes stretched to share x and y everywhere (collinear edges, long
// straight runs), thin winding walks, combs and spirals:
//   - the cut starts at a reflex vertex, runs through the open interior and ends on the boundary;
//   - the two parts are simple counter-clockwise rectilinear rings without straight vertices,
//     and their areas add up to the polygon's;
//   - both have at most 3n/4 + 2 vertices (Theorem 2, weights 1);
//   - no candidate leaves a smaller larger part (the choice is the best of all extensions);
//   - the tree's leaves are rectangles and its depth is O(log n).
#include "router/link_cut.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <tuple>

#include "geom/predicates.h"
#include "oracle/link_polygon_oracle.h"
#include "support/random_shapes.h"
#include "support/sanitized.h"

namespace taut::test {
namespace link_cut_test {

using geom::Point;
using geom::Ring;
using i64 = std::int64_t;

std::string str(const Ring& r) {
  std::string s;
  for (const Point p : r) s += "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
  return s;
}

// Where the point (X/2, Y/2) lies for the closed polygon: doubled coordinates.
geom::Location locate2(const Ring& r, i64 X, i64 Y) {
  Ring d;
  for (const Point p : r) d.push_back({static_cast<geom::Coord>(2 * p.x), static_cast<geom::Coord>(2 * p.y)});
  return geom::locate({static_cast<geom::Coord>(X), static_cast<geom::Coord>(Y)}, geom::Polygon{d, {}});
}
bool holds2(const Ring& r, i64 X, i64 Y) { return locate2(r, X, Y) != geom::Location::Outside; }
bool inside2(const Ring& r, i64 X, i64 Y) { return locate2(r, X, Y) == geom::Location::Inside; }

// Ring vertices that are not straight, by hand.
std::size_t corners(const Ring& r) {
  std::size_t c = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[(i + r.size() - 1) % r.size()], b = r[i], e = r[(i + 1) % r.size()];
    const bool straight = (a.x == b.x && b.x == e.x) || (a.y == b.y && b.y == e.y);
    c += !straight;
  }
  return c;
}

// Every extension of every reflex vertex, walked in half steps until it first touches the
// boundary; the larger part's corners for each. Returns the least such count (SIZE_MAX: none).
std::size_t best_by_brute_force(const Ring& r) {
  const std::size_t n = r.size();
  std::size_t best = SIZE_MAX;
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = r[(i + n - 1) % n], v = r[i], b = r[(i + 1) % n];
    const i64 cross = (i64{v.x} - a.x) * (i64{b.y} - v.y) - (i64{v.y} - a.y) * (i64{b.x} - v.x);
    if (cross >= 0) continue;  // convex
    const Point din{static_cast<geom::Coord>((v.x > a.x) - (v.x < a.x)), static_cast<geom::Coord>((v.y > a.y) - (v.y < a.y))};
    const Point dout{static_cast<geom::Coord>((b.x > v.x) - (b.x < v.x)), static_cast<geom::Coord>((b.y > v.y) - (b.y < v.y))};
    for (const Point d : {din, Point{static_cast<geom::Coord>(-dout.x), static_cast<geom::Coord>(-dout.y)}}) {
      // half steps from v: the first point on the boundary ends the segment
      i64 k = 1;
      while (inside2(r, 2 * v.x + k * d.x, 2 * v.y + k * d.y)) ++k;
      if (k % 2) return SIZE_MAX - 1;  // a half-integer end: impossible for integer rings
      const Point to{static_cast<geom::Coord>(v.x + k / 2 * d.x), static_cast<geom::Coord>(v.y + k / 2 * d.y)};
      // the parts: walk the ring from v forward to `to` (closing along the cut), and the rest
      std::size_t j = n;
      bool at_vertex = false;
      for (std::size_t e = 0; e < n && j == n; ++e)
        if (r[e] == to) j = e, at_vertex = true;
      for (std::size_t e = 0; e < n && j == n; ++e)
        if (geom::on_segment(to, r[e], r[(e + 1) % n])) j = e;
      if (j == n) return SIZE_MAX - 2;
      Ring left, right;
      for (std::size_t e = i;; e = (e + 1) % n) {
        left.push_back(r[e]);
        if (e == j) break;
      }
      if (!at_vertex) left.push_back(to), right.push_back(to);
      for (std::size_t e = at_vertex ? j : (j + 1) % n;; e = (e + 1) % n) {
        right.push_back(r[e]);
        if (e == i) break;
      }
      best = std::min(best, std::max(corners(left), corners(right)));
    }
  }
  return best;
}

// Checks one cut of ring r; "" when right.
std::string check_cut(const Ring& r, const router::CutTree::Node& node, const Ring& left, const Ring& right) {
  const router::PolygonCut& c = *node.cut;
  const std::size_t n = r.size();
  if (c.vertex >= n || r[c.vertex] != c.from) return "the cut does not start at its vertex";
  const Point a = r[(c.vertex + n - 1) % n], b = r[(c.vertex + 1) % n];
  if (geom::orientation(a, c.from, b) >= 0) return "the cut starts at a convex vertex";
  if (c.from.x != c.to.x && c.from.y != c.to.y) return "the cut is not axis-parallel";
  // open interior inside, end on the boundary
  const i64 len = std::abs(i64{c.to.x} - c.from.x) + std::abs(i64{c.to.y} - c.from.y);
  const i64 dx = (c.to.x > c.from.x) - (c.to.x < c.from.x), dy = (c.to.y > c.from.y) - (c.to.y < c.from.y);
  for (i64 k = 1; k < 2 * len; ++k)
    if (!inside2(r, 2 * c.from.x + k * dx, 2 * c.from.y + k * dy)) return "the cut leaves the open interior";
  if (!holds2(r, 2 * c.to.x, 2 * c.to.y) || inside2(r, 2 * c.to.x, 2 * c.to.y)) return "the cut does not end on the boundary";
  for (const Ring* p : {&left, &right}) {
    if (p->size() < 4 || corners(*p) != p->size()) return "a part has straight vertices or too few: " + str(*p);
    for (std::size_t i = 0; i < p->size(); ++i) {
      const Point u = (*p)[i], w = (*p)[(i + 1) % p->size()];
      if (u.x != w.x && u.y != w.y) return "a part has a sloped edge: " + str(*p);
    }
    if (geom::twice_area(*p) <= 0) return "a part is not counter-clockwise: " + str(*p);
  }
  if (geom::twice_area(left) + geom::twice_area(right) != geom::twice_area(r)) return "the parts' areas do not add up";
  const std::size_t big = std::max(left.size(), right.size());
  if (4 * big > 3 * n + 8) return "a part has more than 3n/4 + 2 vertices: " + std::to_string(big) + " of " + std::to_string(n);
  const std::size_t brute = best_by_brute_force(r);
  if (brute != big) return "the brute force's best cut leaves " + std::to_string(brute) + " vertices in the larger part, the cut " + std::to_string(big);
  return "";
}

struct Tally {
  long long polygons = 0, cuts = 0, at_vertex = 0, max_depth_excess = 0;
  int failed = 0;
};

void check_tree(const Ring& ring, const std::string& what, Tally& t) {
  ++t.polygons;
  const router::CutTree tree(ring);
  const auto& nodes = tree.nodes();
  for (const auto& node : nodes) {
    if (!node.cut) {
      if (node.polygon.size() != 4 && t.failed++ < 5) ADD_FAILURE() << what << ": a leaf is no rectangle: " << str(node.polygon);
      continue;
    }
    ++t.cuts;
    const Ring& left = nodes[static_cast<std::size_t>(node.left)].polygon;
    const Ring& right = nodes[static_cast<std::size_t>(node.right)].polygon;
    t.at_vertex += std::find(node.polygon.begin(), node.polygon.end(), node.cut->to) != node.polygon.end();
    const std::string r = check_cut(node.polygon, node, left, right);
    if (!r.empty() && t.failed++ < 5) ADD_FAILURE() << what << ": polygon " << str(node.polygon) << "\n  cut " << node.cut->from.x << "," << node.cut->from.y << " -> " << node.cut->to.x << "," << node.cut->to.y << ": " << r;
  }
  // depth: parts of at most 3n/4 + 2 vertices reach 4 within log_{4/3} n + a few levels
  const double bound = std::log(static_cast<double>(ring.size())) / std::log(4.0 / 3.0) + 4;
  if (tree.depth() > bound && t.failed++ < 5) ADD_FAILURE() << what << ": depth " << tree.depth() << " for " << ring.size() << " vertices";
}

TEST(CutTree, RandomPolyominoesAgainstTheBruteForce) {
  const int count = static_cast<int>(sanitized_share(1500, 10));
  Tally t;
  for (int seed = 1; seed <= count; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    const int side = 3 + seed % 10, cells = 4 + seed % 90, stretch = 1 + seed % 4;
    const Ring ring = random_rectilinear_polygon(rng, side, cells, stretch, {static_cast<geom::Coord>(seed % 7) - 3, -5});
    check_tree(ring, "seed " + std::to_string(seed), t);
  }
  for (int seed = 1; seed <= count / 3; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(100000 + seed));
    check_tree(random_thin_polygon(rng, 1 + seed % 3).ring, "thin seed " + std::to_string(seed), t);
  }
  std::printf("%lld polygons, %lld cuts (%lld ending at a vertex)\n", t.polygons, t.cuts, t.at_vertex);
  EXPECT_EQ(t.failed, 0);
  EXPECT_GE(t.cuts, sanitized_share(8000, 10));
  EXPECT_GE(t.at_vertex, sanitized_share(2000, 10));
}

// Shapes with many reflex vertices in a row: combs, square spirals of width-1 corridors and
// staircases.
TEST(CutTree, CombsSpiralsAndStaircases) {
  Tally t;
  for (int teeth = 1; teeth <= 40; ++teeth) {
    // a bar with teeth of three heights standing on it
    std::vector<geom::Box> boxes = {{{0, 0}, {static_cast<geom::Coord>(4 * teeth - 2), 1}}};
    for (int k = 0; k < teeth; ++k)
      boxes.push_back({{static_cast<geom::Coord>(4 * k), 1}, {static_cast<geom::Coord>(4 * k + 2), static_cast<geom::Coord>(6 + k % 3)}});
    check_tree(union_ring(boxes), "comb of " + std::to_string(teeth), t);
  }
  for (int turns = 1; turns <= 12; ++turns) {
    // a square spiral corridor of width 1: walk the centre line and take its boundary
    std::vector<geom::Box> cells;
    int x = 0, y = 0, dx = 1, dy = 0;
    for (int leg = 1; leg <= 2 * turns; ++leg) {
      for (int s = 0; s < 2 * leg; ++s) {
        cells.push_back({{static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)}, {static_cast<geom::Coord>(x + 1), static_cast<geom::Coord>(y + 1)}});
        x += dx, y += dy;
      }
      std::swap(dx, dy);
      dx = -dx;
    }
    check_tree(union_ring(cells), "spiral of " + std::to_string(turns), t);
  }
  for (int steps = 1; steps <= 30; ++steps) {
    Ring r = {{0, 0}};
    for (int k = 0; k < steps; ++k) {
      r.push_back({static_cast<geom::Coord>(2 * k + 2), static_cast<geom::Coord>(2 * k)});
      r.push_back({static_cast<geom::Coord>(2 * k + 2), static_cast<geom::Coord>(2 * k + 2)});
    }
    r.push_back({0, static_cast<geom::Coord>(2 * steps)});
    check_tree(r, "staircase of " + std::to_string(steps), t);
  }
  std::printf("%lld polygons, %lld cuts\n", t.polygons, t.cuts);
  EXPECT_EQ(t.failed, 0);
}

// What the query structure and the exact diameter will build on these cuts (de Berg section 3,
// Lemma 2), checked on the brute-force reference alone (oracle::LinkPolygonReference::
// arrival_links: for a point a and every grid point x of a node's cut e, the least links from a
// arriving at x perpendicular to e, and along it). For vertices s and t on the two sides of e:
//  - exact by the separator: d(s, t) is the least, over points x of e and the two ways of
//    arriving, of the two counts, less one when both arrive the same way (the link through x is
//    counted twice);
//  - e(s, d) (the points reached perpendicularly within d links) is an interval of e, for
//    d = d_s and d_s + 1, with d_s the least perpendicular count;
//  - the paper's Lemma 2, d(s, t) = d_s + d_t + (-1 / 0 / +1 by how e(s, .) and e(t, .) meet),
//    holds unless a best path runs along e: a cut extends an edge of its vertex, so a path can
//    reach e's end along that edge, which the lemma's perpendicular arrivals do not count. The
//    test counts those pairs (the query structure must add the arrivals along e at its two ends).
TEST(CutTree, LemmaTwoOnTheCuts) {
  const int count = 400;  // about a second under the sanitizers: all of it runs there too
  long long pairs = 0, minus = 0, zero = 0, plus = 0, along = 0;
  int failed = 0;
  auto fail = [&](const std::string& m) {
    if (failed++ < 5) ADD_FAILURE() << m;
  };
  for (int seed = 1; seed <= count; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(5000 + seed));
    const Ring ring = seed % 3 == 0 ? random_thin_polygon(rng, 1 + seed % 2).ring
                                    : random_rectilinear_polygon(rng, 3 + seed % 4, 6 + seed % 14, 1 + seed % 3, {0, 0});
    if (ring.size() > 28) continue;
    const router::CutTree tree(ring);
    const auto& nodes = tree.nodes();
    for (const auto& node : nodes) {
      if (!node.cut || node.depth > 1) continue;
      const oracle::LinkPolygonReference ref(node.polygon);
      const Point e0 = node.cut->from, e1 = node.cut->to;
      const std::string at = "seed " + std::to_string(seed) + ": polygon " + str(node.polygon) + " cut " + std::to_string(e0.x) + "," +
                             std::to_string(e0.y) + " -> " + std::to_string(e1.x) + "," + std::to_string(e1.y);
      struct Side {
        Point v;
        int d = -1;  // least perpendicular count
        std::vector<oracle::LinkPolygonReference::Arrival> arr;
      };
      auto sides_of = [&](const Ring& part) {
        std::vector<Side> out;
        for (const Point v : part) {
          if (geom::on_segment(v, e0, e1)) continue;
          Side sd{v, -1, ref.arrival_links(v, e0, e1)};
          for (const auto& a : sd.arr)
            if (a.perpendicular >= 0 && (sd.d < 0 || a.perpendicular < sd.d)) sd.d = a.perpendicular;
          out.push_back(std::move(sd));
        }
        return out;
      };
      const std::vector<Side> L = sides_of(nodes[static_cast<std::size_t>(node.left)].polygon);
      const std::vector<Side> R = sides_of(nodes[static_cast<std::size_t>(node.right)].polygon);
      // the points with a perpendicular count <= d: [first, last] and whether contiguous
      auto interval = [](const Side& sd, int d) {
        int first = -1, last = -1, n = 0;
        for (int i = 0; i < static_cast<int>(sd.arr.size()); ++i) {
          const int l = sd.arr[static_cast<std::size_t>(i)].perpendicular;
          if (l >= 0 && l <= d) {
            if (first < 0) first = i;
            last = i, ++n;
          }
        }
        return std::tuple{first, last, first < 0 || n == last - first + 1};
      };
      for (const std::vector<Side>* side : {&L, &R})
        for (const Side& sd : *side) {
          if (sd.d < 0) {
            fail(at + ": no perpendicular arrival from " + std::to_string(sd.v.x) + "," + std::to_string(sd.v.y));
            continue;
          }
          for (const int d : {sd.d, sd.d + 1})
            if (!std::get<2>(interval(sd, d)))
              fail(at + ": e(v, " + std::to_string(d) + ") of v = " + std::to_string(sd.v.x) + "," + std::to_string(sd.v.y) + " is not an interval");
        }
      auto meet = [&](const Side& a, int da, const Side& b, int db) {
        const auto [a0, a1, aok] = interval(a, da);
        const auto [b0, b1, bok] = interval(b, db);
        return a0 >= 0 && b0 >= 0 && std::max(a0, b0) <= std::min(a1, b1);
      };
      for (const Side& s : L)
        for (const Side& t : R) {
          if (s.d < 0 || t.d < 0) continue;
          const std::optional<int> want = ref.distance(s.v, t.v);
          ++pairs;
          const std::string pair = at + ": d(" + std::to_string(s.v.x) + "," + std::to_string(s.v.y) + " ; " + std::to_string(t.v.x) +
                                   "," + std::to_string(t.v.y) + ") = " + std::to_string(want ? *want : -1);
          // the separator formula, over every point of e and both ways of arriving
          int best = -1;
          for (std::size_t i = 0; i < s.arr.size() && i < t.arr.size(); ++i) {
            const int sa[2] = {s.arr[i].perpendicular, s.arr[i].along}, ta[2] = {t.arr[i].perpendicular, t.arr[i].along};
            for (int os = 0; os < 2; ++os)
              for (int ot = 0; ot < 2; ++ot)
                if (sa[os] >= 0 && ta[ot] >= 0 && (best < 0 || sa[os] + ta[ot] - (os == ot ? 1 : 0) < best))
                  best = sa[os] + ta[ot] - (os == ot ? 1 : 0);
          }
          if (!want || best != *want) {
            fail(pair + ", the separator formula gives " + std::to_string(best));
            continue;
          }
          int delta = 1;
          if (meet(s, s.d, t, t.d)) delta = -1;
          else if (meet(s, s.d + 1, t, t.d) || meet(s, s.d, t, t.d + 1)) delta = 0;
          (delta < 0 ? minus : delta == 0 ? zero : plus) += 1;
          if (*want == s.d + t.d + delta) continue;
          // outside the lemma only when one of them reaches an end of e along e's line within its
          // perpendicular distance (from the boundary edge the cut extends)
          auto along_at_end = [&](const Side& sd) {
            const auto& f = sd.arr.front();
            const auto& b = sd.arr.back();
            return (f.along >= 0 && f.along <= sd.d) || (b.along >= 0 && b.along <= sd.d);
          };
          if (along_at_end(s) || along_at_end(t)) ++along;
          else fail(pair + ", Lemma 2 gives " + std::to_string(s.d) + " + " + std::to_string(t.d) + " + " + std::to_string(delta));
        }
    }
  }
  std::printf("%lld pairs across cuts: Lemma 2 with delta -1 %lld, 0 %lld, +1 %lld; %lld only by a path along the cut\n",
              pairs, minus, zero, plus, along);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(pairs, 10000);
  EXPECT_GE(std::min({minus, zero}), 1000);
  EXPECT_GE(plus, 50);
}

TEST(CutTree, RectangleIsALeafAndBadInputIsRefused) {
  const router::CutTree tree(Ring{{0, 0}, {5, 0}, {5, 3}, {0, 3}});
  ASSERT_EQ(tree.nodes().size(), 1u);
  EXPECT_FALSE(tree.nodes()[0].cut.has_value());
  EXPECT_EQ(tree.depth(), 0);
  EXPECT_THROW(router::balanced_cut(Ring{{0, 0}, {1, 0}, {0, 1}}), std::invalid_argument);
  // a straight vertex (the review's case: it used to reach the internal count check)
  EXPECT_THROW(router::balanced_cut(Ring{{0, 0}, {5, 0}, {9, 0}, {9, 9}, {6, 9}, {6, 3}, {3, 3}, {3, 9}, {0, 9}}),
               std::invalid_argument);
  EXPECT_THROW(router::balanced_cut(Ring{{0, 0}, {4, 0}, {4, 4}, {2, 6}, {0, 4}}), std::invalid_argument);  // sloped
  // an L: one reflex vertex, two extensions; both leave a rectangle and a rectangle
  const auto cut = router::balanced_cut(Ring{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}});
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->from, (Point{2, 2}));
  EXPECT_EQ(cut->left.size(), 4u);
  EXPECT_EQ(cut->right.size(), 4u);
}

}  // namespace link_cut_test
}  // namespace taut::test
