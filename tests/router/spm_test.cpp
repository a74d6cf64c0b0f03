// router::L1Map (the shortest path map, router/spm.h) against the brute-force reference
// oracle::L1Reference (tests/oracle/l1_oracle.h: visibility graph, Dijkstra), sharing nothing
// with the map but the geometry kernel.
//
// Seeded random instances come from the wavefront tests' generator (support/wavefront_cases.h:
// every `taut gen` kind and five hand-made degenerate families: touching rectangles, pinches,
// diamonds and 45-degree shapes, rings and holes, sloped edges, turned and mirrored, some near
// the coordinate limit). Each instance gets 1-20 sources (repeats allowed: ties) and 100 query
// points (points of interest, obstacle vertices, points on edges, random points, free or not),
// and every query is checked:
//   - is_free agrees with the reference;
//   - the distance is the least reference distance over the sources, exactly; null exactly when
//     no source reaches the query;
//   - the named source is at that distance (ties: any nearest source);
//   - the path runs from that source to the query, every link free and the whole of exactly that
//     length (L1Reference::check_path), bending only at obstacle vertices (or domain corners),
//     and its last link starts at the answer's root (the root sees the query straight).
// Per instance, the trapezoids cover free space exactly: their areas, summed as exact rationals
// (GMP), equal the domain's area minus the obstacles'.
// A failure prints the seed, the instance as C++ initializers and the query. TAUT_SPM_SEED=N runs
// only seed N.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <set>
#include <sstream>

#include "geom/normalize.h"
#include "io/layout_geometry.h"
#include "io/movingai.h"
#include "oracle/l1_oracle.h"
#include "router/spm.h"
#include "router/wavefront.h"
#include "support/run.h"
#include "support/sanitized.h"
#include "support/wavefront_cases.h"

namespace taut::test {
namespace {

using geom::Point;
using i64 = std::int64_t;

std::string pt(Point p) { return "{" + std::to_string(p.x) + ", " + std::to_string(p.y) + "}"; }
std::string instance_cpp(const WavefrontCase& c, const std::vector<Point>& sources) {
  std::ostringstream os;
  os << "  domain {" << pt(c.domain.lo) << ", " << pt(c.domain.hi) << "}\n  obstacles {";
  for (const auto& p : c.obstacles) {
    os << "{{";
    for (std::size_t i = 0; i < p.outer.size(); ++i) os << (i ? ", " : "") << pt(p.outer[i]);
    os << "}, {";
    for (std::size_t h = 0; h < p.holes.size(); ++h) {
      os << (h ? ", {" : "{");
      for (std::size_t i = 0; i < p.holes[h].size(); ++i) os << (i ? ", " : "") << pt(p.holes[h][i]);
      os << "}";
    }
    os << "}}, ";
  }
  os << "}\n  sources {";
  for (Point s : sources) os << pt(s) << ", ";
  os << "}\n";
  return os.str();
}

mpz_class Z(i64 v) { return mpz_class(static_cast<long>(v)); }

// Twice the signed area of a ring (positive counter-clockwise), by the shoelace formula in GMP
// integers: independent of geom's own area code.
mpz_class twice_signed_area(const geom::Ring& r) {
  mpz_class a = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point p = r[i], q = r[(i + 1) % r.size()];
    a += Z(p.x) * Z(q.y) - Z(q.x) * Z(p.y);
  }
  return a;
}

// y of segment s at x, exactly (s not vertical).
mpq_class y_at(const geom::Segment& s, i64 x) {
  mpq_class r(Z(s.a.y) * (Z(s.b.x) - Z(s.a.x)) + (Z(s.b.y) - Z(s.a.y)) * (Z(x) - Z(s.a.x)), Z(s.b.x) - Z(s.a.x));
  r.canonicalize();
  return r;
}

struct Tally {
  i64 instances = 0, queries = 0, reachable = 0, unreachable = 0, not_free = 0, paths = 0,
      multi_source = 0, ties = 0, trapezoids = 0, skipped = 0, blocked_sources = 0, location_nodes = 0,
      edges = 0;
};

std::string check_seed(std::uint64_t seed, Tally& tally) {
  WavefrontCase c;
  try {
    c = make_wavefront_case(seed);
  } catch (const std::exception& e) {
    ++tally.skipped;  // the generator's own failure (counted by the wavefront tests)
    return "";
  }
  const oracle::L1Reference ref(c.domain, c.obstacles);
  if (!ref.problems().empty()) {
    ++tally.skipped;
    return "";
  }
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 17);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  std::vector<Point> free_pts;
  for (Point p : c.candidates)
    if (ref.is_free(p)) free_pts.push_back(p);
  if (free_pts.empty()) {
    ++tally.skipped;
    return "";
  }
  const std::size_t ns = 1 + pick(std::min<std::size_t>(20, free_pts.size() + 3));
  std::vector<Point> sources;
  for (std::size_t i = 0; i < ns; ++i) sources.push_back(free_pts[pick(free_pts.size())]);
  // One instance in four also gets a source that may not be free (ignored by the map; the
  // indices of the others must not move).
  if (pick(4) == 0) {
    const Point extra = c.candidates[pick(c.candidates.size())];
    sources.insert(sources.begin() + static_cast<std::ptrdiff_t>(pick(sources.size() + 1)), extra);
    tally.blocked_sources += !ref.is_free(extra);
  }
  // Queries: candidates (vertices, points on edges, points of interest), then random points.
  std::vector<Point> queries;
  for (std::size_t i = 0; i < c.candidates.size() && queries.size() < 60; ++i)
    queries.push_back(c.candidates[pick(c.candidates.size())]);
  const geom::Box& D = c.domain;
  while (queries.size() < 100) {
    const i64 x = D.lo.x + static_cast<i64>(rng() % static_cast<std::uint64_t>(i64{D.hi.x} - D.lo.x + 1));
    const i64 y = D.lo.y + static_cast<i64>(rng() % static_cast<std::uint64_t>(i64{D.hi.y} - D.lo.y + 1));
    queries.push_back({static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)});
  }
  std::set<Point> vertices;
  for (const auto& p : c.obstacles) {
    vertices.insert(p.outer.begin(), p.outer.end());
    for (const auto& h : p.holes) vertices.insert(h.begin(), h.end());
  }
  for (Point corner : {D.lo, D.hi, Point{D.lo.x, D.hi.y}, Point{D.hi.x, D.lo.y}}) vertices.insert(corner);

  const std::string head = "seed " + std::to_string(seed) + " (family " + c.family + ")\n" + instance_cpp(c, sources);
  std::optional<router::L1Map> map;
  try {
    map.emplace(c.domain, c.obstacles, sources);
  } catch (const std::exception& e) {
    return head + "  building the map threw: " + e.what() + "\n";
  }
  // The same map answering by the persistent search alone (no grid): every query the same.
  {
    const router::L1Map plain(c.domain, c.obstacles, sources, router::L1Map::Options{.grid = false});
    for (const Point q : queries) {
      const auto a = map->locate(q), b = plain.locate(q);
      if (a.has_value() != b.has_value() || (a && (a->distance != b->distance || a->source != b->source ||
                                                   a->root != b->root || a->root_id != b->root_id)))
        return head + "  at " + std::to_string(q.x) + "," + std::to_string(q.y) +
               ": the grid and the persistent search answer differently\n";
    }
  }
  ++tally.instances;
  tally.multi_source += sources.size() > 1;
  tally.location_nodes += map->stats().location_nodes;
  tally.edges += map->stats().vertices;  // ring edges number about the ring vertices

  // The trapezoids tile free space: exact areas.
  {
    mpq_class sum = 0;
    const auto traps = map->trapezoids();
    for (const auto& t : traps) {
      if (t.left.x == t.right.x) continue;
      const mpq_class h0 = y_at(t.top, t.left.x) - y_at(t.bottom, t.left.x);
      const mpq_class h1 = y_at(t.top, t.right.x) - y_at(t.bottom, t.right.x);
      if (h0 < 0 || h1 < 0) return head + "  a trapezoid with negative height\n";
      sum += mpq_class(i64{t.right.x} - t.left.x) * (h0 + h1) / 2;
    }
    mpz_class twice_free = (Z(D.hi.x) - Z(D.lo.x)) * (Z(D.hi.y) - Z(D.lo.y)) * 2;
    for (const auto& p : c.obstacles) {  // outer rings counter-clockwise, holes clockwise
      twice_free -= twice_signed_area(p.outer);
      for (const auto& h : p.holes) twice_free -= twice_signed_area(h);
    }
    const mpq_class free_area = mpq_class(twice_free) / 2;
    if (sum != free_area)
      return head + "  trapezoid areas sum to " + sum.get_str() + ", free area is " + free_area.get_str() + "\n";
    tally.trapezoids += static_cast<i64>(traps.size());
  }

  std::vector<std::vector<std::optional<i64>>> ref_d;  // [source][query]
  for (Point s : sources) ref_d.push_back(ref.distances(s, queries));
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Point q = queries[i];
    const std::string where = head + "  query " + pt(q) + ": ";
    ++tally.queries;
    const bool rf = ref.is_free(q);
    if (map->is_free(q) != rf) return where + "is_free " + std::to_string(!rf) + ", reference " + std::to_string(rf) + "\n";
    std::optional<i64> best;
    int at_best = 0;
    for (std::size_t s = 0; s < sources.size(); ++s)
      if (const auto d = ref_d[s][i]) {
        if (!best || *d < *best) {
          best = d;
          at_best = 0;
        }
        if (*d == *best) ++at_best;
      }
    const auto a = map->locate(q);
    if (!rf) {
      ++tally.not_free;
      if (a) return where + "not free, but the map answers " + std::to_string(a->distance) + "\n";
      continue;
    }
    if (!best) {
      ++tally.unreachable;
      if (a) return where + "unreachable, but the map answers " + std::to_string(a->distance) + "\n";
      if (!map->path(q).empty()) return where + "unreachable, but the map gives a path\n";
      continue;
    }
    if (!a) return where + "the map finds no source, reference distance " + std::to_string(*best) + "\n";
    if (a->distance != *best)
      return where + "distance " + std::to_string(a->distance) + ", reference " + std::to_string(*best) + "\n";
    ++tally.reachable;
    tally.ties += at_best > 1;
    if (a->source >= sources.size() || ref_d[a->source][i] != best)
      return where + "source " + std::to_string(a->source) + " is not at the least distance\n";
    const std::vector<Point> path = map->path(q);
    if (path.empty() || path.front() != sources[a->source] || path.back() != q)
      return where + "the path does not run from the named source to the query\n";
    const Point root = path.size() >= 2 ? path[path.size() - 2] : path.front();
    if (root != a->root && a->root != q) return where + "the path's last link does not start at the root " + pt(a->root) + "\n";
    for (std::size_t k = 1; k + 1 < path.size(); ++k)
      if (!vertices.count(path[k])) return where + "the path bends at " + pt(path[k]) + ", not an obstacle vertex\n";
    const auto len = ref.check_path(path);
    if (!len || *len != *best)
      return where + "the path is " + (len ? "of length " + std::to_string(*len) : std::string("not free")) + "\n";
    ++tally.paths;
  }
  return "";
}

void run_seeds(const std::vector<std::uint64_t>& seeds, Tally& tally) {
  int reported = 0;
  std::vector<std::uint64_t> failed;
  for (std::uint64_t seed : seeds) {
    const std::string r = check_seed(seed, tally);
    if (r.empty()) continue;
    failed.push_back(seed);
    if (reported++ < 3) ADD_FAILURE() << r;
  }
  if (!failed.empty()) {
    std::string list;
    for (auto s : failed) list += std::to_string(s) + " ";
    ADD_FAILURE() << failed.size() << " failing seeds: " << list << "(TAUT_SPM_SEED=N reruns one)";
  }
}

std::optional<std::uint64_t> seed_from_env() {
  if (const char* s = std::getenv("TAUT_SPM_SEED")) return std::strtoull(s, nullptr, 10);
  return std::nullopt;
}

// Seeds that once failed, kept: 6 (and 2, 167, 186): the wedge of a vertex's wall parts was
// picked from its edges before they were sorted, so a vertex lost its own ray below or above
// it (a rectangle flush with the domain side, the source above it, queries below).
TEST(L1Map, RegressionSeeds) {
  Tally t;
  run_seeds({6, 2, 167, 186}, t);
  EXPECT_EQ(t.instances, 4);
}

TEST(L1Map, MatchesTheReferenceOnRandomLayouts) {
  if (const auto s = seed_from_env()) {
    Tally t;
    run_seeds({*s}, t);
    return;
  }
  // Under the sanitizers a quarter of the seeds (support/sanitized.h); the thresholds scale with them.
  const auto share = [](std::int64_t n) { return sanitized_share(n, 4); };
  std::vector<std::uint64_t> seeds;
  for (std::int64_t s = 1; s <= share(1000); ++s) seeds.push_back(static_cast<std::uint64_t>(s));
  for (std::int64_t s = 0; s < share(100); ++s) seeds.push_back(kLargeSeedBase + static_cast<std::uint64_t>(s));
  Tally t;
  run_seeds(seeds, t);
  std::cout << "instances " << t.instances << " (skipped " << t.skipped << ", multi-source " << t.multi_source
            << "), queries " << t.queries << ": reachable " << t.reachable << " (ties " << t.ties << "), unreachable "
            << t.unreachable << ", not free " << t.not_free << "; paths checked " << t.paths << "; trapezoids "
            << t.trapezoids << "; sources not free " << t.blocked_sources << "; point-location nodes "
            << t.location_nodes << " for " << t.edges << " decomposition points\n";
  // The generator must exercise what the test claims.
  EXPECT_GE(t.instances, share(1000));
  EXPECT_GE(t.multi_source, share(800));
  EXPECT_GE(t.reachable, share(60000));
  EXPECT_GE(t.unreachable, share(500));
  EXPECT_GE(t.not_free, share(5000));
  EXPECT_GE(t.ties, share(100));
  EXPECT_GE(t.blocked_sources, share(20));
  // Node copying keeps every version of the sweep's edge set in O(1) nodes per update in
  // expectation (about 3 per edge measured); path copying would take O(log n) per update.
  EXPECT_LE(t.location_nodes, 6 * t.edges);
}

// Moving AI grid maps (blockages that touch and pinch everywhere): the map against the
// wavefront on 3,000 points per map, a quarter of them on grid lines, with 1-8 sources. The
// wavefront is checked against the reference in wavefront_test, but the map takes its vertex
// distances from it, so this comparison checks the decomposition and the staircases, not those
// distances; on the small map (arena, 122 vertices) the independent reference judges too.
TEST(L1Map, MovingAiMapsMatchTheWavefront) {
  TAUT_REQUIRE_SHARED_DATA();
  int maps = 0;
  for (const char* name : {"8room_000", "arena", "brc202d", "den520d", "lak303d", "maze-100-1", "random512-10-0"}) {
    SCOPED_TRACE(name);
    const auto r = io::load_movingai_map(shared_data_dir() + "/movingai/" + name + ".map", 10);
    ASSERT_TRUE(r.layout && r.layout->boundary);
    const auto norm = geom::normalize_obstacles(io::blockage_polygons(*r.layout), r.layout->boundary->box);
    const geom::Box& dom = norm.domain;
    std::mt19937_64 rng(11);
    std::vector<Point> queries, sources;
    const router::L1Map probe(dom, norm.obstacles, {});
    while (queries.size() < 3000) {
      Point p{static_cast<geom::Coord>(dom.lo.x + static_cast<i64>(rng() % static_cast<std::uint64_t>(dom.hi.x - dom.lo.x + 1))),
              static_cast<geom::Coord>(dom.lo.y + static_cast<i64>(rng() % static_cast<std::uint64_t>(dom.hi.y - dom.lo.y + 1)))};
      if (rng() % 4 == 0) p.x -= p.x % 10;
      if (rng() % 4 == 0) p.y -= p.y % 10;
      queries.push_back(p);
    }
    const std::size_t k = 1 + rng() % 8;
    for (const Point q : queries)
      if (sources.size() < k && probe.is_free(q) && rng() % 50 == 0) sources.push_back(q);
    const router::L1Map map(dom, norm.obstacles, sources);
    router::L1Wavefront wf(dom, norm.obstacles);
    wf.run(sources, queries, router::WavefrontStop::AllTargets);
    int reached = 0, mismatches = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const bool free = wf.is_free(queries[i]);
      const auto d = wf.target_distance(i);
      const auto a = map.locate(queries[i]);
      if (map.is_free(queries[i]) != free || d.has_value() != a.has_value() || (d && *d != a->distance)) {
        if (mismatches++ < 3)
          ADD_FAILURE() << "query " << pt(queries[i]) << ": wavefront " << (d ? std::to_string(*d) : "none")
                        << ", map " << (a ? std::to_string(a->distance) : "none");
        continue;
      }
      reached += d.has_value();
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(reached, 300);
    if (std::string(name) == "arena") {
      const oracle::L1Reference ref(dom, norm.obstacles);
      std::vector<std::optional<i64>> best(queries.size());
      for (const Point s : sources) {
        const auto d = ref.distances(s, queries);
        for (std::size_t i = 0; i < queries.size(); ++i)
          if (d[i] && (!best[i] || *d[i] < *best[i])) best[i] = d[i];
      }
      int ref_mismatches = 0;
      for (std::size_t i = 0; i < queries.size(); ++i) {
        const auto a = map.locate(queries[i]);
        if (a.has_value() != best[i].has_value() || (a && a->distance != *best[i])) ++ref_mismatches;
      }
      EXPECT_EQ(ref_mismatches, 0) << "against the reference on arena";
    }
    ++maps;
  }
  EXPECT_EQ(maps, 7);
}

// Hand-worked degenerate cases (each answer worked out in the comment, and the reference agrees).
struct HandCase {
  const char* name;
  geom::Box domain;
  std::vector<geom::Polygon> obstacles;
  std::vector<Point> sources;
  Point query;
  std::optional<i64> distance;
};

TEST(L1Map, HandWorkedDegenerateCases) {
  const std::vector<HandCase> cases = {
      // Two squares touching at (10,10) only: a pinch. From (5,15) to (15,5) the straight
      // staircase through (10,10) is closed; around either square: 20 + 20 = 40.
      {"pinch", {{-10, -10}, {30, 30}}, {{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}}, {{{10, 10}, {20, 10}, {20, 20}, {10, 20}}, {}}},
       {{5, 15}}, {15, 5}, 40},
      // A source at the pinch starts in either free wedge: 5 + 5 = 10 to both sides.
      {"source at the pinch, one side", {{-10, -10}, {30, 30}},
       {{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}}, {{{10, 10}, {20, 10}, {20, 20}, {10, 20}}, {}}}, {{10, 10}}, {5, 15}, 10},
      {"source at the pinch, other side", {{-10, -10}, {30, 30}},
       {{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}}, {{{10, 10}, {20, 10}, {20, 20}, {10, 20}}, {}}}, {{10, 10}}, {15, 5}, 10},
      // Three rectangles whose left edges lie on x = 10 (vertices stacked on one vertical): from
      // (0,12) to (25,7) through the gap 5 <= y <= 10, monotone: 25 + 5 = 30.
      {"stacked vertices", {{0, 0}, {30, 30}},
       {{{{10, 0}, {20, 0}, {20, 5}, {10, 5}}, {}}, {{{10, 10}, {20, 10}, {20, 15}, {10, 15}}, {}},
        {{{10, 20}, {20, 20}, {20, 25}, {10, 25}}, {}}},
       {{0, 12}}, {25, 7}, 30},
      // A source in the middle of a top edge: to the point below the square, around a corner:
      // 5 + 10 + 5 + 10 = 30.
      {"source inside an edge", {{0, 0}, {30, 30}}, {{{{10, 10}, {20, 10}, {20, 20}, {10, 20}}, {}}}, {{15, 20}}, {15, 0}, 30},
      // A rectangle flush with the domain's right side (merged into the frame): the source
      // above, the query below, around its left end: left to x = 10 (15), down 20, right 15: 50.
      {"flush with the domain side", {{0, 0}, {30, 30}}, {{{{10, 10}, {30, 10}, {30, 20}, {10, 20}}, {}}}, {{25, 25}}, {25, 5}, 50},
      // A sloped wall, the parallelogram (8,2) (10,2) (12,18) (10,18), between the source
      // (0,10) and the query (20,10): around either end, 20 across plus 8 down and 8 up: 36.
      {"sloped wall", {{0, 0}, {20, 20}}, {{{{8, 2}, {10, 2}, {12, 18}, {10, 18}}, {}}}, {{0, 10}}, {20, 10}, 36},
      // A walled-in query (inside a ring's hole) and a query inside a blockage.
      {"walled in", {{0, 0}, {40, 40}},
       {{{{10, 10}, {30, 10}, {30, 30}, {10, 30}}, {{{15, 15}, {15, 25}, {25, 25}, {25, 15}}}}}, {{5, 5}}, {20, 20}, std::nullopt},
      {"inside a blockage", {{0, 0}, {40, 40}}, {{{{10, 10}, {30, 10}, {30, 30}, {10, 30}}, {}}}, {{5, 5}}, {20, 12}, std::nullopt},
  };
  for (const HandCase& c : cases) {
    SCOPED_TRACE(c.name);
    // (touching squares become one obstacle with a pinch, as in every real run)
    const geom::NormalizedObstacles norm = geom::normalize_obstacles(c.obstacles, c.domain);
    const router::L1Map map(norm.domain, norm.obstacles, c.sources);
    const auto a = map.locate(c.query);
    ASSERT_EQ(a.has_value(), c.distance.has_value());
    const oracle::L1Reference ref(norm.domain, norm.obstacles);
    EXPECT_EQ(ref.distance(c.sources[0], c.query), c.distance) << "the hand-worked answer is wrong";
    if (!a) continue;
    EXPECT_EQ(a->distance, *c.distance);
    const auto path = map.path(c.query);
    ASSERT_GE(path.size(), 1u);
    EXPECT_EQ(path.front(), c.sources[a->source]);
    EXPECT_EQ(ref.check_path(path), c.distance);
  }
}

// Parallel strips at 45 degrees over the whole height: long sloped trapezoids whose bounding
// boxes hold most of the domain (the case that made box-based point location scan O(n) of
// them). Every answer against the reference, at points on the strips' edges, on the walls
// through their corners, and between; and the point-location structure stays O(n).
TEST(L1Map, ParallelSlopedStrips) {
  const int m = 30, h = 8 * m;
  std::vector<geom::Polygon> strips;
  for (int i = 0; i < m; ++i) {
    const int x = 8 * i - h;
    strips.push_back({{{x, 0}, {x + 2, 0}, {x + 2 + h, h}, {x + h, h}}, {}});
  }
  const geom::Box dom{{-h - 8, -8}, {h + 8, h + 8}};
  const auto norm = geom::normalize_obstacles(strips, dom);
  const std::vector<Point> src = {{-h - 4, -4}, {h + 4, h + 4}};
  const router::L1Map map(norm.domain, norm.obstacles, src);
  const router::L1Map plain(norm.domain, norm.obstacles, src, router::L1Map::Options{.grid = false});
  const oracle::L1Reference ref(norm.domain, norm.obstacles);
  std::vector<Point> queries;
  std::mt19937_64 rng(5);
  for (int k = 0; k < 600; ++k) {
    const int i = static_cast<int>(rng() % m), y = static_cast<int>(rng() % (h + 1));
    const int x = 8 * i - h + y;  // on strip i's left edge
    queries.push_back({x, y});
    queries.push_back({x + 2 + static_cast<int>(rng() % 7), y});  // on its right edge, or beyond
    queries.push_back({x - 1, y});
    queries.push_back({8 * i - h + static_cast<int>(rng() % 3), static_cast<int>(rng() % (h + 9)) - 8});  // a corner's wall
  }
  int checked = 0;
  std::vector<std::vector<std::optional<std::int64_t>>> d;
  for (const Point s : src) d.push_back(ref.distances(s, queries));
  for (std::size_t q = 0; q < queries.size(); ++q) {
    std::optional<std::int64_t> want;
    for (const auto& ds : d)
      if (ds[q] && (!want || *ds[q] < *want)) want = ds[q];
    for (const router::L1Map* m : {&map, &plain}) {
      const auto a = m->locate(queries[q]);
      ASSERT_EQ(a.has_value(), want.has_value()) << queries[q].x << "," << queries[q].y;
      if (a) {
        EXPECT_EQ(a->distance, *want) << queries[q].x << "," << queries[q].y;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 3000);
  EXPECT_LE(map.stats().location_nodes, 6 * map.stats().vertices);
}

// A hand-made case: two sources on either side of a wall with a gap; the Voronoi boundary and
// the distances are worked out by hand.
TEST(L1Map, TwoSourcesAroundAWall) {
  // Wall x in [40, 60], y in [0, 80] of the 100 x 100 domain: the gap is above y = 80.
  const geom::Box dom{{0, 0}, {100, 100}};
  const std::vector<geom::Polygon> obs = {{{{40, 0}, {60, 0}, {60, 80}, {40, 80}}, {}}};
  const std::vector<Point> src = {{10, 10}, {90, 50}};
  router::L1Map map(dom, obs, src);
  // (20, 10): 10 from source 0.
  ASSERT_TRUE(map.locate({20, 10}));
  EXPECT_EQ(map.locate({20, 10})->distance, 10);
  EXPECT_EQ(map.locate({20, 10})->source, 0u);
  // (30, 10) is 20 from source 0; source 1 goes over the wall: 30 + 30 to (60, 80), 20 across,
  // 10 + 70 down to it: 160.
  EXPECT_EQ(map.locate({30, 10})->source, 0u);
  // (70, 0): source 1 is 20 + 50 = 70 away; source 0 must go over the wall: 30 (to x=40) + 70
  // (up to 80) + 20 (across) + 10 + 80 (down) = 210.
  EXPECT_EQ(map.locate({70, 0})->distance, 70);
  EXPECT_EQ(map.locate({70, 0})->source, 1u);
  // (50, 90) above the wall: source 0 is 40 + 80 = 120, source 1 is 40 + 40 = 80.
  EXPECT_EQ(map.locate({50, 90})->distance, 80);
  // (0, 100): source 0 is 10 + 90 = 100 straight; source 1: 90 + 50 = 140.
  EXPECT_EQ(map.locate({0, 100})->distance, 100);
  // Inside the wall: not free; on its side: free.
  EXPECT_FALSE(map.is_free({50, 40}));
  EXPECT_FALSE(map.locate({50, 40}));
  EXPECT_TRUE(map.is_free({40, 40}));
  EXPECT_EQ(map.locate({40, 40})->distance, 60);  // 30 + 30 from source 0
  // The path to (70, 0) is straight from source 1.
  EXPECT_EQ(map.path({70, 0}), (std::vector<Point>{{90, 50}, {70, 0}}));
}

}  // namespace
}  // namespace taut::test
