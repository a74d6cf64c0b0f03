// router::L1Map with SHAPE sources (pins: polygons with horizontal, vertical and 45-degree edges,
// sources along their whole boundary; router/spm.h) against the brute-force reference
// (tests/oracle/l1_oracle.h) on the obstacles plus the shapes: the distance from a shape is the
// least reference distance over every lattice point of its boundary (the least is at one: an
// end of an edge or a projection of an integer point, router/wavefront.h).
//
// Instances: support/wavefront_cases.h (every `taut gen` kind and the hand-made degenerate
// families), each with up to 4 small shapes (400 instances; 25 under the sanitizers) (rectangles, diamonds, 45-degree triangles and
// L-shapes) put at random candidate points where L1Map::shape_problem accepts them (off every
// blockage and each other), 0-2 point sources and 60 queries. Checks per query: is_free, the
// distance (exactly; null exactly when nothing reaches the query), the named source at that
// distance, the path from that source (a point source, or a point on that shape's boundary) to
// the query, free and of exactly that length, its last link starting at the answer's root; and
// the same answers without the grid. TAUT_SHAPE_SOURCE_SEED=N runs only seed N.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "oracle/l1_oracle.h"
#include "router/spm.h"
#include "support/sanitized.h"
#include "support/spm_check.h"
#include "support/wavefront_cases.h"

namespace taut::test {
namespace shape_source_test {

using geom::Point;
using i64 = std::int64_t;

std::vector<Point> boundary_lattice(const geom::Polygon& p) {
  std::vector<Point> out;
  const auto& r = p.outer;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point a = r[i], b = r[(i + 1) % r.size()];
    const int dx = (b.x > a.x) - (b.x < a.x), dy = (b.y > a.y) - (b.y < a.y);
    for (Point c = a; c != b; c = {c.x + dx, c.y + dy}) out.push_back(c);
  }
  return out;
}
bool on_boundary(Point q, const geom::Polygon& p) { return geom::locate(q, p) == geom::Location::Boundary; }

// A small shape at p, size s: one of four kinds.
geom::Polygon shape_at(Point p, int s, int kind) {
  switch (kind) {
    case 0: return {{p, {p.x + s, p.y}, {p.x + s, p.y + s + 1}, {p.x, p.y + s + 1}}, {}};          // rectangle
    case 1: return {{{p.x, p.y - s}, {p.x + s, p.y}, {p.x, p.y + s}, {p.x - s, p.y}}, {}};          // diamond
    case 2: return {{p, {p.x + 2 * s, p.y}, {p.x + s, p.y + s}}, {}};                              // 45-degree triangle
    default: return {{p, {p.x + 2 * s, p.y}, {p.x + 2 * s, p.y + s}, {p.x + s, p.y + s}, {p.x + s, p.y + 2 * s}, {p.x, p.y + 2 * s}}, {}};  // L
  }
}

struct Tally {
  i64 instances = 0, skipped = 0, shapes = 0, queries = 0, reached = 0, from_shape = 0, foot = 0, pieces_checked = 0;
};

std::string check_seed(std::uint64_t seed, Tally& tally) {
  WavefrontCase c;
  try {
    c = make_wavefront_case(seed);
  } catch (const std::exception&) {
    ++tally.skipped;
    return "";
  }
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 53);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  const geom::Box& D = c.domain;
  const i64 span = std::min<i64>(i64{D.hi.x} - D.lo.x, i64{D.hi.y} - D.lo.y);
  std::vector<geom::Polygon> shapes;
  for (int attempt = 0; attempt < 12 && shapes.size() < 4; ++attempt) {
    const Point p = c.candidates[pick(c.candidates.size())];
    const int s = static_cast<int>(1 + pick(static_cast<std::size_t>(std::clamp<i64>(span / 20, 1, 6))));
    std::vector<geom::Polygon> more = shapes;
    more.push_back(shape_at(p, s, static_cast<int>(pick(4))));
    if (pick(3) == 0) std::reverse(more.back().outer.begin(), more.back().outer.end());  // clockwise: cleaned
    if (router::L1Map::shape_problem(D, c.obstacles, more).empty()) shapes = std::move(more);
  }
  if (shapes.empty()) {
    ++tally.skipped;
    return "";
  }
  std::vector<geom::Polygon> all = c.obstacles;
  all.insert(all.end(), shapes.begin(), shapes.end());
  const auto norm = geom::normalize_obstacles(all, D);
  const oracle::L1Reference ref(D, norm.obstacles);
  if (!ref.problems().empty()) {
    ++tally.skipped;
    return "";
  }
  std::vector<Point> free_pts;
  for (Point p : c.candidates)
    if (ref.is_free(p)) free_pts.push_back(p);
  std::vector<Point> points;
  for (std::size_t k = free_pts.empty() ? 0 : pick(3); k > 0; --k) points.push_back(free_pts[pick(free_pts.size())]);
  std::vector<Point> queries;
  while (queries.size() < 60) {
    if (queries.size() < 30) {
      queries.push_back(c.candidates[pick(c.candidates.size())]);
    } else if (queries.size() < 40) {  // near a shape
      const auto& r = shapes[pick(shapes.size())].outer;
      const Point v = r[pick(r.size())];
      queries.push_back({v.x + static_cast<int>(pick(7)) - 3, v.y + static_cast<int>(pick(7)) - 3});
    } else {
      const i64 x = D.lo.x + static_cast<i64>(rng() % static_cast<std::uint64_t>(i64{D.hi.x} - D.lo.x + 1));
      const i64 y = D.lo.y + static_cast<i64>(rng() % static_cast<std::uint64_t>(i64{D.hi.y} - D.lo.y + 1));
      queries.push_back({static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)});
    }
  }
  std::string head = "seed " + std::to_string(seed) + " (family " + c.family + ")\n  shapes";
  for (const auto& sh : shapes) {
    head += " {";
    for (const Point v : sh.outer) head += spm_pt(v);
    head += "}";
  }
  head += "\n  point sources";
  for (const Point p : points) head += " " + spm_pt(p);
  head += "\n";

  std::vector<std::vector<std::optional<i64>>> per_source;  // [source][query]
  for (const Point p : points) per_source.push_back(least_distances(ref, {p}, queries));
  for (const auto& sh : shapes) per_source.push_back(least_distances(ref, boundary_lattice(sh), queries));

  std::optional<router::L1Map> map;
  try {
    map.emplace(D, c.obstacles, points, shapes);
  } catch (const std::exception& e) {
    return head + "  building the map threw: " + e.what() + "\n";
  }
  const router::L1Map plain(D, c.obstacles, points, shapes, router::L1Map::Options{.grid = false});
  ++tally.instances;
  tally.shapes += static_cast<i64>(shapes.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Point q = queries[i];
    const std::string where = head + "  query " + spm_pt(q) + ": ";
    ++tally.queries;
    if (map->is_free(q) != ref.is_free(q)) return where + "is_free differs from the reference\n";
    std::optional<i64> best;
    for (const auto& d : per_source)
      if (d[i] && (!best || *d[i] < *best)) best = d[i];
    const auto a = map->locate(q), b = plain.locate(q);
    if (a.has_value() != b.has_value() || (a && (a->distance != b->distance || a->source != b->source || a->root != b->root)))
      return where + "the grid and the persistent search answer differently\n";
    const std::optional<i64> got = a ? std::optional<i64>(a->distance) : std::nullopt;
    if (got != best)
      return where + "distance " + (got ? std::to_string(*got) : "none") + ", reference " + (best ? std::to_string(*best) : "none") + "\n";
    if (!best) continue;
    ++tally.reached;
    if (a->source >= per_source.size() || per_source[a->source][i] != best) return where + "the named source is not at the least distance\n";
    const auto path = map->path(q);
    if (path.empty() || path.back() != q) return where + "the path does not end at the query\n";
    if (a->source < points.size()) {
      if (path.front() != points[a->source]) return where + "the path does not start at its point source\n";
    } else {
      if (!on_boundary(path.front(), shapes[a->source - points.size()]))
        return where + "the path starts at " + spm_pt(path.front()) + ", off its shape's boundary\n";
      ++tally.from_shape;
    }
    tally.foot += a->root_id == router::L1Map::kFootRoot;
    const Point root = path.size() >= 2 ? path[path.size() - 2] : path.front();
    if (root != a->root && a->root != q) return where + "the path's last link does not start at the root " + spm_pt(a->root) + "\n";
    const auto len = ref.check_path(path);
    if (!len || *len != *best) return where + "the path is " + (len ? "of length " + std::to_string(*len) : std::string("not free")) + "\n";
  }
  // The cells (one instance in four): the pieces by root and by source cover the same area, the
  // free space exactly when all of it is reached (the domain's area minus the blockages' and the
  // shapes'), and at every
  // query strictly inside a piece the piece's formula gives the reference distance and its source is a
  // nearest one.
  if (pick(4) == 0) {
    router::Rational free_area = router::Rational(i64{D.hi.x} - D.lo.x) * (i64{D.hi.y} - D.lo.y);
    for (const auto& p : norm.obstacles) {
      free_area -= router::Rational(static_cast<long long>(geom::twice_area(p.outer))) / 2;
      for (const auto& h : p.holes) free_area -= router::Rational(static_cast<long long>(geom::twice_area(h))) / 2;
    }
    router::Rational root_total = 0;
    for (const auto detail : {router::L1Map::Detail::ByRoot, router::L1Map::Detail::BySource}) {
      const auto pieces = map->pieces(detail);
      router::Rational sum = 0;
      for (const auto& pc : pieces) sum += router::twice_signed_area(pc.ring) / 2;
      // Walled-in free space is in no piece; the map reaches everything the reference does.
      // Free space is all reached when every obstacle vertex is (the map's reach is checked
      // against the reference at the queries) and none is a pinch (a walled-in pocket could
      // hide behind a reached wedge of the same point); otherwise the pieces cover less.
      bool all_reached = true;
      for (const auto& p : norm.obstacles)
        for (const Point v : p.outer) all_reached = all_reached && map->locate(v) && ref.wedges_at(v).size() == 1;
      for (const auto& p : norm.obstacles)
        for (const auto& h : p.holes)
          for (const Point v : h) all_reached = all_reached && map->locate(v) && ref.wedges_at(v).size() == 1;
      if (detail == router::L1Map::Detail::ByRoot) root_total = sum;
      else if (sum != root_total) return head + "  the pieces by root and by source cover different areas\n";
      if (sum > free_area || (all_reached && sum != free_area))
        return head + "  pieces (" + (detail == router::L1Map::Detail::ByRoot ? "by root" : "by source") + ") cover " +
               sum.str() + ", the free area is " + free_area.str() + "\n";
      for (std::size_t i = 0; i < queries.size(); ++i) {
        const Point q = queries[i];
        std::optional<i64> best;
        for (const auto& d : per_source)
          if (d[i] && (!best || *d[i] < *best)) best = d[i];
        if (!best) continue;
        for (const auto& pc : pieces) {
          bool inside = true;
          for (std::size_t k = 0; k < pc.ring.size() && inside; ++k) {
            const router::RPoint &a = pc.ring[k], &b = pc.ring[(k + 1) % pc.ring.size()];
            inside = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) > 0;  // strictly: at a pinch a
                                                                                   // side's own distance differs
          }
          if (!inside) continue;
          auto piece_text = [&] {
            std::string r = " (piece";
            for (const auto& v : pc.ring) r += " " + v.x.str() + "," + v.y.str();
            r += "; root " + spm_pt(pc.root) + " at " + std::to_string(pc.root_distance);
            if (pc.root_segment) r += ", straight from " + spm_pt(pc.root_segment->a) + "-" + spm_pt(pc.root_segment->b);
            return r + ")";
          };
          if (pc.source >= per_source.size() || per_source[pc.source][i] != best)
            return head + "  query " + spm_pt(q) + " lies in a piece of source " + std::to_string(pc.source) + ", not a nearest" +
                   piece_text() + "\n";
          // the cells and locate() settle ties alike (voronoi.h: a point goes where locate sends it)
          if (const auto a = map->locate(q); !a || a->source != pc.source)
            return head + "  query " + spm_pt(q) + " lies in a piece of source " + std::to_string(pc.source) +
                   ", locate() names another" + piece_text() + "\n";
          if (detail != router::L1Map::Detail::ByRoot) continue;
          i64 formula;
          if (pc.root_segment) {
            const Point a = pc.root_segment->a, b = pc.root_segment->b;
            if (a.x == b.x) {
              formula = std::abs(i64{q.x} - a.x);
            } else {
              const i64 sl = (i64{b.y} - a.y) / (i64{b.x} - a.x);
              formula = std::abs(i64{q.y} - a.y - sl * (i64{q.x} - a.x));
            }
          } else {
            formula = pc.root_distance + std::abs(i64{q.x} - pc.root.x) + std::abs(i64{q.y} - pc.root.y);
          }
          if (formula != *best)
            return head + "  query " + spm_pt(q) + ": its piece says " + std::to_string(formula) + ", reference " +
                   std::to_string(*best) + piece_text() + "\n";
        }
      }
    }
    ++tally.pieces_checked;
  }
  return "";
}

TEST(ShapeSources, MatchTheReferenceOnRandomLayouts) {
  Tally t;
  // 25 seeds under the sanitizers (100 took 11 s there)
  if (!run_seed_range("TAUT_SHAPE_SOURCE_SEED", 400, [&](std::uint64_t seed) { return check_seed(seed, t); }, 8)) return;
  std::cout << "instances " << t.instances << " (skipped " << t.skipped << "), shapes " << t.shapes << ", queries "
            << t.queries << ": reached " << t.reached << ", from a shape " << t.from_shape << " (straight out of a side "
            << t.foot << "); cells checked on " << t.pieces_checked << " instances\n";
  EXPECT_GE(t.instances, sanitized_share(330, 8));
  EXPECT_GE(t.shapes, sanitized_share(900, 8));
  EXPECT_GE(t.from_shape, sanitized_share(12000, 8));
  EXPECT_GE(t.foot, sanitized_share(900, 8));
  EXPECT_GE(t.pieces_checked, sanitized_share(60, 8));
}

// Shapes that touch a blockage, each other or the domain side are refused, by name.
TEST(ShapeSources, RefusesShapesThatTouch) {
  const geom::Box dom{{0, 0}, {100, 100}};
  const std::vector<geom::Polygon> obs = {{{{40, 40}, {60, 40}, {60, 60}, {40, 60}}, {}}};
  auto problem = [&](std::vector<geom::Polygon> shapes) { return router::L1Map::shape_problem(dom, obs, shapes); };
  EXPECT_EQ(problem({{{{10, 10}, {20, 10}, {20, 20}, {10, 20}}, {}}}), "");
  EXPECT_EQ(problem({{{{30, 40}, {40, 40}, {40, 50}, {30, 50}}, {}}}), "shape source 0: it touches or overlaps a blockage");
  EXPECT_NE(problem({{{{45, 45}, {50, 45}, {50, 50}, {45, 50}}, {}}}).find("touches or overlaps a blockage"), std::string::npos);
  EXPECT_NE(problem({{{{10, 10}, {20, 10}, {20, 20}, {10, 20}}, {}}, {{{20, 20}, {30, 20}, {30, 30}, {20, 30}}, {}}})
                .find("shape source 1: it touches or overlaps shape source 0"),
            std::string::npos);
  EXPECT_NE(problem({{{{0, 10}, {20, 10}, {20, 20}, {0, 20}}, {}}}).find("inside the domain"), std::string::npos);
  EXPECT_NE(problem({{{{10, 10}, {20, 10}, {22, 15}, {10, 20}}, {}}}).find("45 degrees"), std::string::npos);
  EXPECT_THROW(router::L1Map(dom, obs, {}, std::vector<geom::Polygon>{{{{30, 40}, {40, 40}, {40, 50}, {30, 50}}, {}}}),
               std::invalid_argument);
  // Greedy, per shape: the second of two touching shapes is refused, the first taken; a point
  // source on a shape refuses it.
  const std::vector<geom::Polygon> two = {{{{10, 10}, {20, 10}, {20, 20}, {10, 20}}, {}}, {{{20, 20}, {30, 20}, {30, 30}, {20, 30}}, {}},
                                          {{{70, 70}, {80, 70}, {80, 80}, {70, 80}}, {}}};
  const std::vector<Point> pts = {{75, 80}};
  const auto why = router::L1Map::shape_problems(dom, obs, two, pts);
  ASSERT_EQ(why.size(), 3u);
  EXPECT_FALSE(why[0]);
  EXPECT_EQ(why[1].text(), "it touches or overlaps shape source 0");
  EXPECT_EQ(why[2].text(), "point source 0 lies on or in it");
}

// Worked by hand: a pad x in [10, 20], y in [10, 14]; a wall x in [30, 32], y in [0, 30].
// (15, 30): straight up from the pad's top: 16. (25, 12): straight right from its side: 5.
// (40, 12): behind the wall: from the pad's corner (20, 14) right 12 and up 16 to (32, 30)...
// no: up to the wall's top corner (30, 30) is 10 + 16 = 26 from (20, 14), then (32, 30) and
// down to (40, 12): 2 + 8 + 18 = 28: 54; from the pad's top edge straight up to (30 - ., 30)
// is no shorter. Below: the wall reaches y = 0 (the domain side): no way under.
TEST(ShapeSources, PadBesideAWall) {
  const geom::Box dom{{0, 0}, {50, 40}};
  const std::vector<geom::Polygon> obs = {{{{30, 0}, {32, 0}, {32, 30}, {30, 30}}, {}}};
  const std::vector<geom::Polygon> pad = {{{{10, 10}, {20, 10}, {20, 14}, {10, 14}}, {}}};
  const auto norm = geom::normalize_obstacles(obs, dom);
  const router::L1Map map(norm.domain, norm.obstacles, {}, pad);
  ASSERT_TRUE(map.locate({15, 30}));
  EXPECT_EQ(map.locate({15, 30})->distance, 16);
  EXPECT_EQ(map.path({15, 30}), (std::vector<Point>{{15, 14}, {15, 30}}));
  EXPECT_EQ(map.locate({25, 12})->distance, 5);
  EXPECT_EQ(map.path({25, 12}), (std::vector<Point>{{20, 12}, {25, 12}}));
  EXPECT_EQ(map.locate({40, 12})->distance, 54);
  EXPECT_EQ(map.locate({5, 5})->distance, 10);  // from the corner (10, 10)
  EXPECT_FALSE(map.is_free({15, 12}));          // inside the pad
  EXPECT_EQ(map.locate({20, 12})->distance, 0);  // on its side
}

}  // namespace shape_source_test
}  // namespace taut::test
