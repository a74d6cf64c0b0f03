// Bend-aware routing benchmark (issue #6): the modified visibility graph of router/bend_router.h
// against the number of obstacle vertices n (generated rectilinear layouts, seed 42): its size
// (nodes, tracks, straight and L edges), build time, and per-query time for the combined metric
// (C = 1000) and the link metric. Machines here are noisy, so times are also printed as ratios
// to baselines measured in the same run: `sort` (std::sort of the n vertices, an n log n unit)
// and `l1` (one exact L1 query of router::L1Router, Mitchell's wavefront, on the same pairs:
// the query the combined metric generalises). The growth exponent between consecutive sizes is
// log(t2 / t1) / log(n2 / n1). Up to --ref-max vertices (default 1,000) the brute-force
// state-graph reference (tests/oracle/bend_oracle.h: Hanan grid x direction) answers the same
// combined queries in the same run, one after another until --ref-seconds (default 60) are
// spent at that size, and its answers are compared. (At 9,216 vertices, --ref-max 10000, it was
// built in 484 s and took 362 s for its first query on 2026-12-01.) `shape`: the same pairs with each
// end a square pin at that vertex (the largest of side domain/100, /200, ... that overlaps no
// obstacle; a wire may end anywhere on it: the search starts from the square's candidate points),
// combined metric, as a ratio to the point query. `map`: section 4's structure for one fixed
// target (router::BendTargetMap: a Dijkstra run from the target and eight slab trees), its build
// time as a ratio to one graph query, its size in envelope pieces per vertex, and a query from
// every vertex and from as many lattice points (cost only) as a ratio of the graph query's time
// to the map's; and the same map with the target's square pin as the target (its candidate
// points are the Dijkstra run's sources; a query adds its straight shots onto the square), as
// ratios to the point target's. The map's queries are timed three ways, alternating: the default
// search (O(log n): fractional cascading for long intervals), a binary search in every covering
// node (O(log^2 n), the baseline) and cascading every query, as ratios to the default.
//
//   bench_bends [--sizes N,N,...] [--queries Q] [--kind rects|maze] [--ref-max N] [--ref-seconds S]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "oracle/bend_oracle.h"
#include "router/bend_router.h"
#include "router/l1_router.h"

namespace {

using taut::bench::seconds_of;
using taut::geom::Point;

struct Row {
  std::int64_t n = 0;
  double sort = 0, build = 0, combined = 0, link = 0, l1 = 0, ref = -1, shape = 0, map_build = 0, map_query = 0;
  double map_pieces = 0, map_mib = 0, pin_map_build = 0, pin_map_query = 0, map_query_per_node = 0, map_query_cascading = 0;
  double map_entries = 0;
  int map_agree = 0, map_checked = 0;
  int ref_agree = 0, ref_done = 0;
  double ref_build = 0;
  taut::router::BendGraphStats stats;
  std::size_t edges = 0;
  int found = 0, l1_found = 0, queries = 0;
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes = {100, 1000, 10000, 100000};
  int queries = 20;
  std::string kind_name = "rects";
  std::int64_t ref_max = 1000;
  double ref_seconds = 60;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = taut::bench::parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--queries") && i + 1 < argc) queries = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) kind_name = argv[++i];
    else if (!std::strcmp(argv[i], "--ref-max") && i + 1 < argc) ref_max = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--ref-seconds") && i + 1 < argc) ref_seconds = std::atof(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--sizes N,N,...] [--queries Q] [--kind rects|maze] [--ref-max N] [--ref-seconds S]\n", argv[0]);
      return 2;
    }
  }
  const auto kind = taut::io::parse_gen_kind(kind_name);
  if (!kind) {
    std::fprintf(stderr, "unknown kind %s\n", kind_name.c_str());
    return 2;
  }
  std::printf("taut bend benchmark: kind=%s, %d queries per size (pairs of spread obstacle vertices), one thread\n",
              kind_name.c_str(), queries);
  std::printf("%8s %8s %9s %10s %10s | %9s %9s | %10s %10s %10s | %8s %8s %8s | %10s | %9s %9s %9s %9s %9s\n", "n", "nodes", "tracks",
              "straight", "L-edges", "build(s)", "/sort", "comb(ms)", "link(ms)", "l1(ms)", "comb/l1",
              "link/l1", "found (l1)", "shape/comb", "map(s)", "/comb", "pieces/n", "query(us)", "comb/query");
  std::vector<Row> rows;
  for (const std::int64_t size : sizes) {
    const taut::bench::BenchLayout b = taut::bench::bench_layout(*kind, size);
    Row row;
    row.n = static_cast<std::int64_t>(b.points.size());
    row.sort = taut::bench::sort_seconds(b.points);
    std::unique_ptr<taut::router::BendRouter> router;
    row.build = seconds_of([&] { router = std::make_unique<taut::router::BendRouter>(b.norm.domain, b.norm.obstacles); }, 1);
    row.stats = router->stats();
    // query pairs: spread vertices, the first half against the second half
    std::vector<std::pair<Point, Point>> pairs;
    const std::size_t m = b.targets.size();
    for (int q = 0; q < queries && m >= 2; ++q)
      pairs.emplace_back(b.targets[static_cast<std::size_t>(q) % (m / 2)], b.targets[m / 2 + static_cast<std::size_t>(q) % (m - m / 2)]);
    row.queries = static_cast<int>(pairs.size());
    int found = 0;
    row.combined = seconds_of([&] {
                     found = 0;
                     for (const auto& [s, t] : pairs)
                       found += router->path(s, t, taut::router::BendMetric::Combined, 1000).status ==
                                taut::router::WireStatus::Ok;
                   }, 1) / std::max<std::size_t>(1, pairs.size());
    row.found = found;
    row.link = seconds_of([&] {
                 for (const auto& [s, t] : pairs) (void)router->path(s, t, taut::router::BendMetric::Link, 0);
               }, 1) / std::max<std::size_t>(1, pairs.size());
    // square pins at the pairs' ends
    auto square_at = [&](Point p) {
      const taut::geom::Box& d = b.norm.domain;
      for (std::int64_t side = std::max<std::int64_t>(1, (std::int64_t{d.hi.x} - d.lo.x) / 100); side >= 1; side /= 2)
        for (const auto& [sx, sy] : {std::pair{1, 1}, std::pair{-1, 1}, std::pair{-1, -1}, std::pair{1, -1}}) {
          const auto q = [&](std::int64_t dx, std::int64_t dy) {
            return Point{static_cast<taut::geom::Coord>(p.x + sx * dx), static_cast<taut::geom::Coord>(p.y + sy * dy)};
          };
          taut::geom::Polygon sq{{q(0, 0), q(side, 0), q(side, side), q(0, side)}, {}};
          if (!router->pin_meets_obstacle(sq)) return sq;
        }
      return taut::geom::Polygon{{p}, {}};
    };
    std::vector<std::pair<taut::geom::Polygon, taut::geom::Polygon>> pins;
    for (const auto& [s, t] : pairs) pins.emplace_back(square_at(s), square_at(t));
    row.shape = seconds_of([&] {
                  for (const auto& [s, t] : pins) (void)router->path(s, t, taut::router::BendMetric::Combined, 1000);
                }, 1) / std::max<std::size_t>(1, pins.size());
    // section 4: the map of the first pair's target, queried from every vertex and lattice points
    {
      const Point target = pairs.empty() ? b.points.front() : pairs.front().second;
      std::unique_ptr<taut::router::BendTargetMap> map;
      const std::size_t heap0 = taut::bench::heap_in_use();
      row.map_build = seconds_of([&] { map = std::make_unique<taut::router::BendTargetMap>(*router, target, taut::router::BendMetric::Combined, 1000); }, 1);
      row.map_mib = static_cast<double>(taut::bench::heap_in_use() - heap0) / (1024.0 * 1024.0);
      row.map_pieces = static_cast<double>(map->pieces()) / static_cast<double>(std::max<std::int64_t>(1, row.n));
      std::vector<Point> qs(b.points.begin(), b.points.end());
      const taut::geom::Box& d = b.norm.domain;
      std::uint64_t s = 7;
      for (std::size_t i = 0; i < b.points.size(); ++i) {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        const auto fx = static_cast<std::int64_t>((s >> 33) % static_cast<std::uint64_t>(std::int64_t{d.hi.x} - d.lo.x + 1));
        const auto fy = static_cast<std::int64_t>((s >> 13) % static_cast<std::uint64_t>(std::int64_t{d.hi.y} - d.lo.y + 1));
        qs.push_back({static_cast<taut::geom::Coord>(d.lo.x + fx), static_cast<taut::geom::Coord>(d.lo.y + fy)});
      }
      std::int64_t sink = 0;
      row.map_entries = static_cast<double>(map->catalog_entries()) / static_cast<double>(std::max<std::int64_t>(1, row.n));
      // the default search (Bounded, O(log n)) against the baseline, a binary search in every
      // covering node (O(log^2 n)), and cascading every query; the three alternate five times and
      // the best of each is kept
      using Search = taut::router::BendTargetMap::SlabSearch;
      row.map_query = row.map_query_per_node = row.map_query_cascading = 1e30;
      auto time_queries = [&](Search m) {
        map->set_slab_search(m);
        return seconds_of([&] {
                 for (const Point q : qs) sink += map->cost(q).length;
               }, 1) / static_cast<double>(qs.size());
      };
      for (int rep = 0; rep < 5; ++rep) {
        row.map_query_per_node = std::min(row.map_query_per_node, time_queries(Search::PerNode));
        row.map_query_cascading = std::min(row.map_query_cascading, time_queries(Search::Cascading));
        row.map_query = std::min(row.map_query, time_queries(Search::Bounded));
      }
      // the graph query answers the same (on a sample)
      for (std::size_t i = 0; i < qs.size(); i += std::max<std::size_t>(1, qs.size() / 20)) {
        const auto want = router->path(qs[i], target, taut::router::BendMetric::Combined, 1000);
        taut::router::WireStatus st{};
        const auto got = map->cost(qs[i], &st);
        ++row.map_checked;
        row.map_agree += st == want.status && (st != taut::router::WireStatus::Ok || (got.length == want.length && got.bends == want.bends));
      }
      // the same with the target's square pin as the target (its candidates are the sources)
      const taut::geom::Polygon pin = square_at(target);
      std::unique_ptr<taut::router::BendTargetMap> pin_map;
      row.pin_map_build = seconds_of([&] { pin_map = std::make_unique<taut::router::BendTargetMap>(*router, pin, taut::router::BendMetric::Combined, 1000); }, 1);
      row.pin_map_query = seconds_of([&] {
                            for (const Point q : qs) sink += pin_map->cost(q).length;
                          }, 1) / static_cast<double>(qs.size());
      taut::bench::keep(sink);
    }
    taut::router::L1Router l1(b.norm.domain, b.norm.obstacles);
    row.l1 = seconds_of([&] {
               row.l1_found = 0;
               for (const auto& [s, t] : pairs) row.l1_found += l1.shortest(s, t).status == taut::router::WireStatus::Ok;
             }, 1) / std::max<std::size_t>(1, pairs.size());
    if (row.n <= ref_max) {
      // query by query until the budget is spent (the reference's Hanan grid has about n^2 / 4
      // nodes); its time per query against the graph query's
      const auto t0 = std::chrono::steady_clock::now();
      const taut::oracle::BendReference ref(b.norm.domain, b.norm.obstacles);
      row.ref_build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      row.ref_agree = 0;
      double spent = 0;
      for (const auto& [s, t] : pairs) {
        if (spent > ref_seconds) break;
        std::optional<taut::oracle::BendAnswer> want;
        const double one = seconds_of([&] { want = ref.best(s, t, false, 1000); }, 1);
        spent += one;
        ++row.ref_done;
        const auto got = router->path(s, t, taut::router::BendMetric::Combined, 1000);
        row.ref_agree += want ? got.status == taut::router::WireStatus::Ok && got.length == want->length &&
                                    got.bends == want->bends
                              : got.status != taut::router::WireStatus::Ok;
      }
      row.ref = spent / std::max(1, row.ref_done);
    }
    const auto& st = row.stats;
    std::printf("%8lld %8zu %9zu %10zu %10zu | %9.3f %9.1f | %10.2f %10.2f %10.2f | %8.2f %8.2f %5d/%d (%d) | %10.2f | %9.3f %9.1f %9.1f %9.2f %9.0f\n",
                static_cast<long long>(row.n), st.nodes, st.tracks, st.straight_edges, st.l_edges, row.build,
                row.build / row.sort, row.combined * 1e3, row.link * 1e3, row.l1 * 1e3, row.combined / row.l1,
                row.link / row.l1, row.found, row.queries, row.l1_found, row.shape / row.combined, row.map_build,
                row.map_build / row.combined, row.map_pieces, row.map_query * 1e6, row.combined / row.map_query);
    std::printf("%8s map answers equal to the graph query's on %d of %d sampled points; %.1f MiB in all, %.0f catalog entries per vertex\n", "",
                row.map_agree, row.map_checked, row.map_mib, row.map_entries);
    std::printf("%8s map query: bounded (default) %.2f us, binary search per node %.2f us (%.2f x bounded), cascading always %.2f us (%.2f x bounded)\n", "",
                row.map_query * 1e6, row.map_query_per_node * 1e6, row.map_query_per_node / row.map_query,
                row.map_query_cascading * 1e6, row.map_query_cascading / row.map_query);
    std::printf("%8s map to the target's square pin: build %.3f s (%.2f x the point's), query %.2f us (%.2f x the point's)\n", "",
                row.pin_map_build, row.pin_map_build / row.map_build, row.pin_map_query * 1e6, row.pin_map_query / row.map_query);
    if (row.ref >= 0)
      std::printf("%8s reference: built in %.2f s, %.2f ms per query (%.0f x combined), %d of %d queries run, %d answers equal\n", "",
                  row.ref_build, row.ref * 1e3, row.ref / row.combined, row.ref_done, row.queries, row.ref_agree);
    else
      std::printf("%8s reference: not run (n > --ref-max %lld)\n", "", static_cast<long long>(ref_max));
    std::fflush(stdout);
    rows.push_back(row);
  }
  std::printf("\ngrowth exponents between consecutive sizes (1.0 = linear):\n");
  std::printf("%8s -> %8s | %8s %8s %8s %8s %8s %8s\n", "n1", "n2", "edges", "build", "combined", "l1", "map", "map-q");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const Row& a = rows[i - 1];
    const Row& b = rows[i];
    const double dn = std::log(static_cast<double>(b.n) / static_cast<double>(a.n));
    const double ea = static_cast<double>(a.stats.straight_edges + a.stats.l_edges + a.stats.nodes);
    const double eb = static_cast<double>(b.stats.straight_edges + b.stats.l_edges + b.stats.nodes);
    std::printf("%8lld -> %8lld | %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f\n", static_cast<long long>(a.n), static_cast<long long>(b.n),
                std::log(eb / ea) / dn, std::log(b.build / a.build) / dn, std::log(b.combined / a.combined) / dn,
                std::log(b.l1 / a.l1) / dn, std::log(b.map_build / a.map_build) / dn, std::log(b.map_query / a.map_query) / dn);
  }
  return 0;
}
