// router::base_reach and router::links_across (what de Berg's query structure keeps at a node of
// the cut tree, seeds/002 section 3.1) against the brute-force reference alone:
// oracle::LinkPolygonReference::arrival_links, a 0-1 search over the Hanan grid of the node's
// polygon that counts, for every grid point of the cut, the fewest links of a path ending
// perpendicular to it and of one ending along it. For every vertex of both parts of every cut of
// the cut trees of random polyominoes (stretched so that x's and y's are shared everywhere),
// thin winding walks, combs and spirals:
//   - its link distance to the cut (perpendicular arrival) is the reference's least count;
//   - the grid points its two intervals hold are exactly those the reference reaches within that
//     many links and one more;
//   - its along-the-line count is the reference's at every grid point of the cut;
// and for every pair of vertices on the two sides, links_across equals the reference's d(s, t).
#include "router/link_reach.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "geom/predicates.h"
#include "oracle/link_polygon_oracle.h"
#include "router/link_cut.h"
#include "router/link_polygon.h"
#include "support/polygon_frame.h"
#include "support/random_shapes.h"
#include "support/sanitized.h"

namespace taut::test {
namespace link_reach_test {

using geom::Point;
using geom::Ring;

std::string str(Point p) { return std::to_string(p.x) + "," + std::to_string(p.y); }
std::string str(const Ring& r) {
  std::string s;
  for (const Point p : r) s += "(" + str(p) + ")";
  return s;
}

// A random polyomino or, every third seed, a thin winding walk; cleaned, counter-clockwise.
Ring random_polygon(std::mt19937& rng, int seed, int side, int cells, int stretch) {
  Ring ring = seed % 3 == 0 ? random_thin_polygon(rng, stretch).ring : random_rectilinear_polygon(rng, side, cells, stretch, {0, 0});
  ring = router::clean_ring(ring);
  if (geom::twice_area(ring) < 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

struct Tally {
  long long vertices = 0, grid_points = 0, pairs = 0, by_along = 0, plus_one = 0, links_3_up = 0;
  int failed = 0;
};

// Checks every cut of `ring`'s cut tree; `at` names the case in failures.
void check_cuts(const Ring& ring, const std::string& at, Tally& tally) {
  auto fail = [&](const std::string& m) {
    if (tally.failed++ < 8) ADD_FAILURE() << at << ": " << m;
  };
  const router::CutTree tree(ring);
  const auto& nodes = tree.nodes();
  for (const auto& node : nodes) {
    if (!node.cut) continue;
    const oracle::LinkPolygonReference ref(node.polygon);
    const Point e0 = node.cut->from, e1 = node.cut->to;
    const std::string cut = "polygon " + str(node.polygon) + " cut " + str(e0) + " -> " + str(e1);
    struct Side {
      const Ring* part;
      std::vector<router::BaseReach> rec;
    };
    Side sides[2];
    for (int k = 0; k < 2; ++k) {
      const Ring& part = nodes[static_cast<std::size_t>(k == 0 ? node.left : node.right)].polygon;
      sides[k].part = &part;
      try {
        sides[k].rec = router::base_reach(part, e0, e1);
      } catch (const std::exception& ex) {
        fail(cut + ": base_reach threw " + ex.what());
        return;
      }
      for (std::size_t i = 0; i < part.size(); ++i) {
        const Point v = part[i];
        const router::BaseReach& r = sides[k].rec[i];
        const std::string who = cut + ": vertex " + str(v);
        if (geom::on_segment(v, e0, e1)) {
          if (r.links != 0) fail(who + " on the cut has links " + std::to_string(r.links));
          continue;
        }
        ++tally.vertices;
        const auto arr = ref.arrival_links(v, e0, e1);
        int d = -1;
        for (const auto& a : arr)
          if (a.perpendicular >= 0 && (d < 0 || a.perpendicular < d)) d = a.perpendicular;
        if (r.links != d) {
          fail(who + ": links " + std::to_string(r.links) + ", the reference " + std::to_string(d));
          continue;
        }
        tally.links_3_up += d >= 3;
        for (const auto& a : arr) {
          ++tally.grid_points;
          const std::int64_t t = std::abs(std::int64_t{a.x.x} - e0.x) + std::abs(std::int64_t{a.x.y} - e0.y);
          const bool in_d = a.perpendicular >= 0 && a.perpendicular <= d, in_d1 = a.perpendicular >= 0 && a.perpendicular <= d + 1;
          if (in_d != r.at.contains(t) || in_d1 != r.next.contains(t))
            fail(who + ": at " + str(a.x) + " the reference counts " + std::to_string(a.perpendicular) + " (d " +
                 std::to_string(d) + "), the intervals [" + std::to_string(r.at.lo) + "," + std::to_string(r.at.hi) + "] [" +
                 std::to_string(r.next.lo) + "," + std::to_string(r.next.hi) + "] hold t = " + std::to_string(t) + ": " +
                 std::to_string(r.at.contains(t)) + std::to_string(r.next.contains(t)));
          if (a.along != r.along)
            fail(who + ": along the cut to " + str(a.x) + " the reference counts " + std::to_string(a.along) + ", base_reach " +
                 std::to_string(r.along));
        }
      }
    }
    for (std::size_t i = 0; i < sides[0].part->size(); ++i) {
      const Point s = (*sides[0].part)[i];
      if (geom::on_segment(s, e0, e1)) continue;
      for (std::size_t j = 0; j < sides[1].part->size(); ++j) {
        const Point t = (*sides[1].part)[j];
        if (geom::on_segment(t, e0, e1)) continue;
        const router::BaseReach &rs = sides[0].rec[i], &rt = sides[1].rec[j];
        const std::optional<int> want = ref.distance(s, t);
        const int got = router::links_across(rs, rt);
        ++tally.pairs;
        const int lemma = rs.links + rt.links + (rs.at.meets(rt.at) ? -1 : rs.next.meets(rt.at) || rs.at.meets(rt.next) ? 0 : 1);
        tally.by_along += got < lemma;
        tally.plus_one += got == rs.links + rt.links + 1;
        if (!want || got != *want)
          fail(cut + ": d(" + str(s) + " ; " + str(t) + ") = " + std::to_string(want ? *want : -1) + ", links_across " +
               std::to_string(got));
      }
    }
  }
}

TEST(BaseReach, MatchesTheReferenceOnEveryCut) {
  const int count = kSanitized ? 150 : 600;
  Tally tally;
  for (int seed = 1; seed <= count; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(7000 + seed));
    // every tenth polyomino sits against the coordinate limit (corner at 2^30 - 1 - its size)
    const Point origin = seed % 10 == 1 ? Point{geom::kMaxCoord - 64, -geom::kMaxCoord} : Point{0, 0};
    const Ring ring = seed % 3 == 0 ? random_thin_polygon(rng, 1 + seed % 2).ring
                                    : random_rectilinear_polygon(rng, 3 + seed % 5, 6 + seed % 18, 1 + seed % 3, origin);
    if (ring.size() > 40) continue;
    check_cuts(ring, "seed " + std::to_string(seed) + " (" + std::to_string(ring.size()) + " vertices)", tally);
  }
  std::printf("%lld vertices against %lld grid points of their cuts (%lld at 3 links or more); %lld pairs across cuts, "
              "%lld needing +1, %lld joined only along a cut's line\n",
              tally.vertices, tally.grid_points, tally.links_3_up, tally.pairs, tally.plus_one, tally.by_along);
  EXPECT_EQ(tally.failed, 0);
  EXPECT_GE(tally.vertices, kSanitized ? 1000 : 5000);
  EXPECT_GE(tally.links_3_up, kSanitized ? 50 : 200);
  EXPECT_GE(tally.by_along, kSanitized ? 20 : 100);
  EXPECT_GE(tally.plus_one, kSanitized ? 20 : 100);
}

TEST(BaseReach, HandMadeShapes) {
  Tally tally;
  // a comb (teeth 3 links apart) and a staircase
  Ring comb{{0, 0}, {13, 0}, {13, 10}, {12, 10}, {12, 2}, {10, 2}, {10, 10}, {9, 10}, {9, 2}, {7, 2}, {7, 10}, {6, 10}, {6, 2},
            {4, 2}, {4, 10}, {3, 10}, {3, 2}, {1, 2}, {1, 10}, {0, 10}};
  check_cuts(comb, "comb", tally);
  Ring stairs{{0, 0}, {8, 0}, {8, 1}, {7, 1}, {7, 2}, {6, 2}, {6, 3}, {5, 3}, {5, 4}, {4, 4}, {4, 5}, {0, 5}};
  check_cuts(stairs, "staircase", tally);
  EXPECT_EQ(tally.failed, 0);
  EXPECT_GT(tally.pairs, 50);
  // a segment not on an edge is refused
  EXPECT_THROW(router::base_reach(stairs, {1, 1}, {2, 1}), std::invalid_argument);
  EXPECT_THROW(router::base_reach(stairs, {0, 0}, {0, 0}), std::invalid_argument);
}

// The query structure: every pair of vertices against the reference on small polygons, and
// against the graph search of LinkPolygon (the bend router's 0-1 search, another algorithm) on
// larger ones.
TEST(LinkVertexQueries, EveryPairMatches) {
  const int count = kSanitized ? 100 : 400;
  long long pairs = 0, big_pairs = 0;
  int failed = 0, deepest = 0, largest = 0, far = 0;
  for (int seed = 1; seed <= count; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(9000 + seed));
    const bool big = seed % 8 == 0;
    const Ring ring = random_polygon(rng, seed, big ? 14 : 3 + seed % 6, big ? 90 : 6 + seed % 24, 1 + seed % 3);
    const router::LinkVertexQueries q(ring);
    deepest = std::max(deepest, q.tree().depth());
    largest = std::max(largest, static_cast<int>(ring.size()));
    const std::string at = "seed " + std::to_string(seed) + " " + str(ring);
    if (ring.size() <= 40) {
      const oracle::LinkPolygonReference ref(ring);
      for (std::size_t i = 0; i < ring.size(); ++i)
        for (std::size_t j = 0; j < ring.size(); ++j) {
          const int got = q.links(i, j);
          const std::optional<int> want = ref.distance(ring[i], ring[j]);
          ++pairs;
          far += got >= 4;
          if ((!want || got != *want) && failed++ < 8)
            ADD_FAILURE() << at << ": d(" << str(ring[i]) << " ; " << str(ring[j]) << ") = " << (want ? *want : -1) << ", the queries "
                          << got;
        }
    } else {
      const router::LinkPolygon graph(ring);
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const std::vector<int> want = graph.distances(ring[i], ring);
        for (std::size_t j = 0; j < ring.size(); ++j) {
          const int got = q.links(i, j);
          ++big_pairs;
          if (got != want[j] && failed++ < 8)
            ADD_FAILURE() << at << ": d(" << str(ring[i]) << " ; " << str(ring[j]) << ") = " << want[j] << " by the graph, the queries "
                          << got;
        }
      }
    }
  }
  std::printf("%lld pairs against the reference (%d at 4 links or more), %lld against the graph search; up to %d vertices, depth %d\n",
              pairs, far, big_pairs, largest, deepest);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(pairs, kSanitized ? 10000 : 50000);
  EXPECT_GE(big_pairs, kSanitized ? 5000 : 25000);
}

// Generated channels (`taut gen channel`: free space one winding polygon, diameters in the
// hundreds) and a comb (every tooth tip 3 links from every other): from every tenth vertex to
// every vertex, against the graph search.
TEST(LinkVertexQueries, ChannelsAndACombMatchTheGraph) {
  std::vector<std::pair<std::string, Ring>> cases;
  for (const std::int64_t size : {kSanitized ? 200 : 1000, 300}) {
    const Ring channel = channel_ring(size, static_cast<std::uint64_t>(size));
    cases.emplace_back("channel " + std::to_string(size), channel);
  }
  const int teeth = 40;  // spine y in [0, 1], teeth of width 1 up to y = 5
  Ring comb;
  comb.push_back({0, 0});
  comb.push_back({2 * teeth - 1, 0});
  for (int t = teeth - 1; t >= 0; --t) {
    comb.push_back({2 * t + 1, 5});
    comb.push_back({2 * t, 5});
    if (t > 0) {
      comb.push_back({2 * t, 1});
      comb.push_back({2 * t - 1, 1});
    }
  }
  cases.emplace_back("comb", router::clean_ring(comb));
  int failed = 0;
  long long pairs = 0;
  int diameter = 0;
  for (const auto& [name, ring] : cases) {
    const router::LinkVertexQueries q(ring);
    const router::LinkPolygon graph(ring);
    for (std::size_t i = 0; i < ring.size(); i += 10) {
      const std::vector<int> want = graph.distances(ring[i], ring);
      for (std::size_t j = 0; j < ring.size(); ++j) {
        const int got = q.links(i, j);
        ++pairs;
        diameter = std::max(diameter, got);
        if (got != want[j] && failed++ < 8)
          ADD_FAILURE() << name << ": d(" << str(ring[i]) << " ; " << str(ring[j]) << ") = " << want[j] << " by the graph, the queries " << got;
      }
    }
    std::printf("%s: %zu vertices, depth %d, %zu records\n", name.c_str(), ring.size(), q.tree().depth(), q.records());
  }
  std::printf("%lld pairs, the farthest %d links apart\n", pairs, diameter);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(diameter, 30);
}

// Query points for a polygon and its cut tree: vertices, points inside edges, points on the
// tree's cuts (their ends included), points on a vertex's lines, lattice points anywhere in the
// box (some outside). `cut_points`: the cut points drawn from.
std::vector<Point> query_points(std::mt19937& rng, const Ring& ring, const router::CutTree& tree, std::vector<Point>& cut_points) {
  geom::Coord x0 = ring[0].x, x1 = x0, y0 = ring[0].y, y1 = y0;
  for (const Point p : ring) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  auto between = [&](geom::Coord lo, geom::Coord hi) { return static_cast<geom::Coord>(lo + static_cast<geom::Coord>(rng() % static_cast<unsigned>(hi - lo + 1))); };
  cut_points.clear();
  for (const auto& node : tree.nodes())
    if (node.cut) {
      const Point a = node.cut->from, b = node.cut->to;
      cut_points.push_back(b);
      cut_points.push_back({between(std::min(a.x, b.x), std::max(a.x, b.x)), between(std::min(a.y, b.y), std::max(a.y, b.y))});
    }
  std::vector<Point> pts;
  for (int i = 0; i < 18; ++i) {
    const Point v = ring[rng() % ring.size()], w = ring[(rng() % ring.size())];
    switch (rng() % 5) {
      case 0: pts.push_back(v); break;
      case 1: {  // inside an edge
        const std::size_t e = rng() % ring.size();
        const Point a = ring[e], b = ring[(e + 1) % ring.size()];
        pts.push_back({between(std::min(a.x, b.x), std::max(a.x, b.x)), between(std::min(a.y, b.y), std::max(a.y, b.y))});
        break;
      }
      case 2:
        if (!cut_points.empty()) {
          pts.push_back(cut_points[rng() % cut_points.size()]);
          break;
        }
        [[fallthrough]];
      case 3: pts.push_back(rng() % 2 ? Point{v.x, w.y} : Point{v.x, between(y0, y1)}); break;  // on a vertex's line
      default: pts.push_back({between(x0 - 1, x1 + 1), between(y0 - 1, y1 + 1)});
    }
  }
  return pts;
}

// Random polygons with their query structure and query_points(): seeds 1..count, rng seeded with
// seed_base + seed, polygons of random_polygon(rng, seed, 3 + seed % side, 6 + seed % cells,
// 1 + seed % stretch) with at most max_size vertices (larger ones skipped).
struct PolygonSizes {
  int side, cells, stretch;
  std::size_t max_size;
};
template <class F>
void for_each_query_polygon(int count, unsigned seed_base, PolygonSizes z, F&& f) {
  for (int seed = 1; seed <= count; ++seed) {
    std::mt19937 rng(seed_base + static_cast<unsigned>(seed));
    const Ring ring = random_polygon(rng, seed, 3 + seed % z.side, 6 + seed % z.cells, 1 + seed % z.stretch);
    if (ring.size() > z.max_size) continue;
    const router::LinkPointQueries q(ring);
    std::vector<Point> cut_points;
    const std::vector<Point> pts = query_points(rng, ring, q.tree(), cut_points);
    f(seed, ring, q, pts, cut_points);
  }
}

// Any two points (section 3.2) of query_points(), against the reference's distance (nullopt
// outside); both the query (leaf location and lowest common ancestors) and the walk down the tree.
TEST(LinkPointQueries, RandomPointsMatchTheReference) {
  const int count = kSanitized ? 60 : 300;
  long long pairs = 0, outside = 0, on_cuts = 0;
  int failed = 0;
  for_each_query_polygon(count, 13000, {5, 20, 4, 36}, [&](int seed, const Ring& ring, const router::LinkPointQueries& q,
                                                          const std::vector<Point>& pts, const std::vector<Point>& cut_points) {
    const oracle::LinkPolygonReference ref(ring);
    for (const Point a : pts)
      for (const Point b : pts) {
        const std::optional<int> want = ref.distance(a, b), got = q.links(a, b), down = q.links_by_descent(a, b);
        ++pairs;
        outside += !want;
        for (const Point c : cut_points) on_cuts += c == a;
        if ((got != want || down != want) && failed++ < 8)
          ADD_FAILURE() << "seed " << seed << " " << str(ring) << ": d(" << str(a) << " ; " << str(b) << ") = " << (want ? *want : -1)
                        << ", the queries " << (got ? *got : -1) << ", walking down the tree " << (down ? *down : -1);
      }
  });
  std::printf("%lld point pairs (%lld with a point outside, %lld from a point on a cut)\n", pairs, outside, on_cuts);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(pairs, kSanitized ? 10000 : 50000);
  EXPECT_GE(outside, 500);
  EXPECT_GE(on_cuts, 500);
}

// The structure's paths (section 3.3) between points of query_points(): from a to b, every link
// axis-parallel, of positive length, inside the polygon (the reference's distance of its ends is
// 1) and turning at every bend; as many links as the reference's distance; and as long in L1 as
// the L1 reference's distance (a visibility graph with Dijkstra round the polygon as a hole in a
// frame). Nothing for a point outside.
TEST(LinkPointQueries, PathsAreFewestLinksAndL1Shortest) {
  const int count = kSanitized ? 150 : 1500;
  long long pairs = 0, through_cuts = 0, along_cuts = 0;
  int failed = 0;
  for_each_query_polygon(count, 17000, {9, 40, 5, 70}, [&](int seed, const Ring& ring, const router::LinkPointQueries& q,
                                                          const std::vector<Point>& pts, const std::vector<Point>&) {
    const oracle::LinkPolygonReference ref(ring);
    const L1InPolygon l1(ring);
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i % 3; j < pts.size(); j += 3) {
        const Point a = pts[i], b = pts[j];
        const std::optional<int> want = ref.distance(a, b);
        const auto got = q.path(a, b);
        auto fail = [&](const std::string& m) {
          if (failed++ < 8) ADD_FAILURE() << "seed " << seed << " " << str(ring) << ": " << str(a) << " -> " << str(b) << ": " << m;
        };
        ++pairs;
        if (!want) {
          if (got) fail("a path for a point outside");
          continue;
        }
        if (!got) {
          fail("no path");
          continue;
        }
        const std::vector<Point>& p = *got;
        if (p.front() != a || p.back() != b) fail("the path does not join the points");
        std::int64_t length = 0;
        bool legal = true;
        for (std::size_t k = 0; k + 1 < p.size(); ++k) {
          const Point u = p[k], v = p[k + 1];
          legal = legal && u != v && (u.x == v.x || u.y == v.y) && ref.distance(u, v) == std::optional<int>(1);
          legal = legal && (k == 0 || geom::orientation(p[k - 1], u, v) != 0);
          length += std::abs(std::int64_t{v.x} - u.x) + std::abs(std::int64_t{v.y} - u.y);
          for (const auto& node : q.tree().nodes())
            if (node.cut && geom::on_segment(u, node.cut->from, node.cut->to) && geom::on_segment(v, node.cut->from, node.cut->to) && u != v)
              ++along_cuts;
        }
        through_cuts += p.size() > 2;
        const int links = static_cast<int>(p.size()) - 1;
        const std::optional<std::int64_t> l1_want = l1.ref->distance(a, b);
        if (!legal) fail("a link is not free, not axis-parallel, empty or straight on: " + str(Ring(p.begin(), p.end())));
        else if (links != *want) fail(std::to_string(links) + " links, the reference " + std::to_string(*want) + ": " + str(Ring(p.begin(), p.end())));
        else if (!l1_want || length != *l1_want)
          fail("L1 length " + std::to_string(length) + ", the reference " + (l1_want ? std::to_string(*l1_want) : "none") + ": " +
               str(Ring(p.begin(), p.end())));
      }
  });
  std::printf("%lld point pairs (%lld paths with a bend, %lld links along a cut)\n", pairs, through_cuts, along_cuts);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(pairs, kSanitized ? 15000 : 150000);
  EXPECT_GE(along_cuts, 100);
}

// Pairs a first version got wrong, found by a larger run of the test above: a way along the cut's
// line took the first node one level down (here the line y = 4, 8 longer than y = 8), not the one
// nearest to its coordinate chain.
TEST(LinkPointQueries, PathsFoundTooLongOnce) {
  struct Case {
    Ring ring;
    Point a, b;
    std::int64_t length;
  };
  const Case cases[] = {
      {{{0, 4}, {3, 4}, {3, 0}, {12, 0}, {12, 4}, {10, 4}, {10, 13}, {12, 13}, {12, 26}, {10, 26}, {10, 29}, {0, 29}, {0, 26}, {6, 26}, {6, 22},
        {10, 22}, {10, 16}, {6, 16}, {6, 8}, {4, 8}, {4, 18}, {0, 18}},
       {10, 16}, {4, 18}, 24},
      {{{0, 0}, {10, 0}, {10, 2}, {12, 2}, {12, 5}, {10, 5}, {10, 8}, {7, 8}, {7, 5}, {6, 5}, {6, 11}, {10, 11}, {10, 13}, {7, 13}, {7, 16}, {10, 16},
        {10, 17}, {13, 17}, {13, 20}, {7, 20}, {7, 21}, {6, 21}, {6, 23}, {5, 23}, {5, 21}, {3, 21}, {3, 20}, {0, 20}},
       {10, 8}, {6, 13}, 15},
      {{{0, 0}, {10, 0}, {10, 2}, {12, 2}, {12, 5}, {10, 5}, {10, 8}, {7, 8}, {7, 5}, {6, 5}, {6, 11}, {10, 11}, {10, 13}, {7, 13}, {7, 16}, {10, 16},
        {10, 17}, {13, 17}, {13, 20}, {7, 20}, {7, 21}, {6, 21}, {6, 23}, {5, 23}, {5, 21}, {3, 21}, {3, 20}, {0, 20}},
       {7, 6}, {6, 13}, 10},
  };
  for (const Case& c : cases) {
    const router::LinkPointQueries q(c.ring);
    const oracle::LinkPolygonReference ref(c.ring);
    for (const auto& [a, b] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
      const auto p = q.path(a, b);
      ASSERT_TRUE(p.has_value());
      std::int64_t length = 0;
      for (std::size_t k = 0; k + 1 < p->size(); ++k) length += std::abs(std::int64_t{(*p)[k + 1].x} - (*p)[k].x) + std::abs(std::int64_t{(*p)[k + 1].y} - (*p)[k].y);
      EXPECT_EQ(length, c.length) << str(a) << " -> " << str(b) << ": " << str(Ring(p->begin(), p->end()));
      EXPECT_EQ(static_cast<int>(p->size()) - 1, ref.distance(a, b));
      EXPECT_EQ(L1InPolygon(c.ring).ref->distance(a, b), std::optional<std::int64_t>(c.length));
    }
  }
}

// The same on channels of 500 and 2,000 vertices (too large for the references), against the
// graph search of router::LinkPolygon: as many links as its distance, as long as its path (which
// its own tests check against the L1 reference), every link free by its distance of 1.
TEST(LinkPointQueries, PathsOnChannelsMatchTheGraphSearch) {
  long long pairs = 0, links_total = 0;
  int failed = 0;
  for (const std::int64_t size : {500, 2000}) {
    const Ring channel = channel_ring(size, static_cast<std::uint64_t>(size + 3));
    const router::LinkPolygon graph(channel);
    const router::LinkPointQueries q(graph.ring());
    const Ring& ring = graph.ring();
    geom::Coord x0 = ring[0].x, x1 = x0, y0 = ring[0].y, y1 = y0;
    for (const Point p : ring) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    std::mt19937 rng(static_cast<unsigned>(size));
    std::vector<Point> pts;
    while (pts.size() < (kSanitized ? 40u : 200u)) {
      const Point p = rng() % 3 == 0 ? ring[rng() % ring.size()]
                                     : Point{static_cast<geom::Coord>(x0 + static_cast<geom::Coord>(rng() % static_cast<unsigned>(x1 - x0 + 1))),
                                             static_cast<geom::Coord>(y0 + static_cast<geom::Coord>(rng() % static_cast<unsigned>(y1 - y0 + 1)))};
      if (graph.contains(p)) pts.push_back(p);
    }
    for (std::size_t i = 0; i + 1 < pts.size(); i += 2) {
      const Point a = pts[i], b = pts[i + 1];
      const auto want = graph.path(a, b);
      const auto got = q.path(a, b);
      ++pairs;
      std::string why;
      if (!want || !got) why = "no path";
      else {
        const std::vector<Point>& p = *got;
        std::int64_t length = 0;
        for (std::size_t k = 0; k + 1 < p.size(); ++k) {
          const Point u = p[k], v = p[k + 1];
          if (u == v || (u.x != v.x && u.y != v.y) || graph.distance(u, v) != std::optional<int>(1) || (k > 0 && geom::orientation(p[k - 1], u, v) == 0))
            why = "link " + str(u) + " - " + str(v) + " is not a free straight link";
          length += std::abs(std::int64_t{v.x} - u.x) + std::abs(std::int64_t{v.y} - u.y);
        }
        const int links = static_cast<int>(p.size()) - 1;
        links_total += links;
        if (p.front() != a || p.back() != b) why = "the path does not join the points";
        else if (links != want->links) why = std::to_string(links) + " links, the graph's " + std::to_string(want->links);
        else if (length != want->length) why = "L1 length " + std::to_string(length) + ", the graph's " + std::to_string(want->length);
      }
      if (!why.empty() && failed++ < 8) ADD_FAILURE() << "channel " << size << ": " << str(a) << " -> " << str(b) << ": " << why;
    }
  }
  std::printf("%lld pairs, %lld links in all\n", pairs, links_total);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(links_total, pairs * 10);
}

// The divide-and-conquer diameter: the reference's diameter over convex vertices on small
// polygons, LinkPolygon's (eccentricity bounds over graph searches) on channels and combs; the
// pair it names is that far apart.
TEST(LinkVertexQueries, DiameterMatches) {
  int failed = 0, checked = 0, largest = 0;
  auto check = [&](const Ring& ring, int want, const std::string& at) {
    const router::LinkVertexQueries q(ring);
    const auto d = q.diameter();
    ++checked;
    largest = std::max(largest, d.links);
    const std::size_t n = ring.size();
    auto convex = [&](std::size_t i) { return geom::orientation(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) > 0; };
    if ((d.links != want || !convex(d.from) || !convex(d.to) || q.links(d.from, d.to) != want) && failed++ < 8)
      ADD_FAILURE() << at << ": diameter " << want << ", the cut tree's " << d.links << " between " << str(ring[d.from]) << " and "
                    << str(ring[d.to]) << " (" << q.links(d.from, d.to) << " apart)";
  };
  for (int seed = 1; seed <= (kSanitized ? 150 : 600); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(11000 + seed));
    const Ring ring = random_polygon(rng, seed, 3 + seed % 6, 6 + seed % 30, 1 + seed % 3);
    if (ring.size() > 44) continue;
    check(ring, oracle::LinkPolygonReference(ring).convex_vertex_diameter(), "seed " + std::to_string(seed) + " " + str(ring));
  }
  for (const std::int64_t size : {200, 500, 1000, 2000}) {
    const Ring channel = channel_ring(size, static_cast<std::uint64_t>(size + 7));
    check(channel, router::LinkPolygon(channel).diameter(SIZE_MAX).links, "channel " + std::to_string(size));
  }
  std::printf("%d polygons, diameters up to %d\n", checked, largest);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(largest, 100);
}

}  // namespace link_reach_test
}  // namespace taut::test
