// Benchmark of the L1 shortest path map (router/spm.h, L1Map): build time and size against the
// number of obstacle vertices n and of sources k, and the time of one distance query, on
// generated layouts. Baselines measured in the same run (machines are noisy; trust ratios):
// std::sort of the n vertices (the build's ratio to it), and the same queries answered the way
// `taut spm` did before the map, one wavefront run per query (router/wavefront.h, stopping at
// the query): the ratio per query, and after how many queries the map has paid for its build.
// Every query timed on the wavefront is compared with the map's answer, so a fast wrong map
// cannot pass.
//
// --strips M,M,..: instead, the adversarial layout for box-based point location: M parallel thin
// strips at 45 degrees, each over the whole height, so the free trapezoids between them are
// long and sloped and every one's bounding box holds most query points. Prints the query time
// with the ratio to the binary-search baseline, and how it grows with M (O(log M) expected).
//
// --orientations octilinear: the octilinear map (OctMap, four weighted decompositions) against
// the octilinear wavefront, the same columns.
//
//   bench_spm [--sizes N,N,..] [--sources K,K,..] [--kind rects|polygons|maze|degenerate]
//             [--queries Q] [--wave-queries W] [--strips M,M,..] [--orientations rectilinear|octilinear]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <optional>
#include <span>
#include <vector>

#include "bench/bench_util.h"
#include "bench/free_points.h"
#include "geom/normalize.h"
#include "router/spm.h"
#include "router/wavefront.h"

namespace {

using taut::bench::parse_list;
using taut::bench::seconds_of;
using taut::geom::Point;

// M parallelograms at 45 degrees, 2 wide, 8 apart, over a height of 8 M: each spans the height.
int run_strips(const std::vector<std::int64_t>& counts, int nqueries) {
  std::printf("adversarial layout: M parallel strips at 45 degrees (every trapezoid's box holds most points)\n");
  std::printf("%7s %9s | %8s %10s | %8s %8s\n", "strips", "vertices", "build s", "trapezoids", "query us", "/bsearch");
  int failures = 0;
  for (const std::int64_t m : counts) {
    const taut::geom::Coord h = static_cast<taut::geom::Coord>(8 * m);
    std::vector<taut::geom::Polygon> shapes;
    std::vector<Point> pts;
    for (std::int64_t i = 0; i < m; ++i) {
      const auto x = static_cast<taut::geom::Coord>(8 * i - h);
      taut::geom::Polygon p;
      p.outer = {{x, 0}, {x + 2, 0}, {x + 2 + h, h}, {x + h, h}};
      pts.insert(pts.end(), p.outer.begin(), p.outer.end());
      shapes.push_back(std::move(p));
    }
    const taut::geom::Box dom{{static_cast<taut::geom::Coord>(-h - 8), -8}, {static_cast<taut::geom::Coord>(h + 8), h + 8}};
    const auto norm = taut::geom::normalize_obstacles(shapes, dom);
    const Point src{static_cast<taut::geom::Coord>(-h - 4), -4};
    std::optional<taut::router::L1Map> map;
    const double build = seconds_of([&] { map.emplace(norm.domain, norm.obstacles, std::span<const Point>(&src, 1)); }, 1);
    const std::vector<Point> queries = taut::bench::random_free_points(norm.domain, norm.obstacles, static_cast<std::size_t>(nqueries), 5);
    volatile std::int64_t sink = 0;
    int reached = 0;
    for (const Point& q : queries) reached += map->locate(q).has_value();
    if (reached != nqueries) ++failures;  // every free point here is reachable from the corner
    const double qs = seconds_of(
        [&] {
          for (const Point& q : queries)
            if (const auto a = map->locate(q)) sink = sink + a->distance;
        },
        3);
    std::sort(pts.begin(), pts.end());
    const double bs = seconds_of(
        [&] {
          for (const Point& q : queries) sink = sink + (std::upper_bound(pts.begin(), pts.end(), q) - pts.begin());
        },
        3);
    std::printf("%7lld %9zu | %8.3f %10lld | %8.2f %8.1f\n", static_cast<long long>(m), pts.size(), build,
                static_cast<long long>(map->stats().trapezoids), qs / nqueries * 1e6, qs / bs);
    std::fflush(stdout);
  }
  if (failures) std::printf("UNREACHED free points in %d strip layouts\n", failures);
  return failures ? 1 : 0;
}

std::int64_t num(std::int64_t d) { return d; }
std::int64_t num(const taut::geom::Root2& d) { return d.a + d.b; }

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes = {1000, 10000, 100000, 1000000}, source_counts = {1, 100, 10000};
  std::string kind_name = "rects";
  int nqueries = 100000, wave_queries = 0;  // 0: 20, or 5 from 10^5 vertices on
  std::vector<std::int64_t> strips;
  bool oct = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--sources") && i + 1 < argc) source_counts = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) kind_name = argv[++i];
    else if (!std::strcmp(argv[i], "--queries") && i + 1 < argc) nqueries = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--wave-queries") && i + 1 < argc) wave_queries = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--strips") && i + 1 < argc) strips = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--orientations") && i + 1 < argc) {
      const std::string o = argv[++i];
      if (o != "rectilinear" && o != "octilinear") {
        std::fprintf(stderr, "--orientations: rectilinear or octilinear\n");
        return 2;
      }
      oct = o == "octilinear";
    } else {
      std::fprintf(stderr, "usage: %s [--sizes N,..] [--sources K,..] [--kind K] [--queries Q] [--wave-queries W] [--strips M,..] [--orientations O]\n",
                   argv[0]);
      return 2;
    }
  }
  if (!strips.empty()) return run_strips(strips, std::min(nqueries, 20000));
  const auto kind = taut::io::parse_gen_kind(kind_name);
  if (!kind) {
    std::fprintf(stderr, "unknown kind %s\n", kind_name.c_str());
    return 2;
  }
  std::printf("%s shortest path map, kind %s; times are best of 1, sort = std::sort of the n vertices in the same run\n",
              oct ? "octilinear" : "L1", kind_name.c_str());
  std::printf("%9s %6s | %8s %7s %7s | %9s %8s %8s %7s %7s | %8s %9s %9s %8s %s\n", "vertices", "srcs", "build s",
              "/sort", "/wave", "trapezoids", "rays/trap", "B/vertex", "query us", "/bsearch", "wave s", "wave/query",
              "break-even", "checked", "");
  struct Point2 {
    double logn, logt;
  };
  std::vector<Point2> growth;
  int failures = 0;
  auto measure = [&]<class Map, class Wave>(std::int64_t size) {
    const auto lay = taut::bench::bench_layout(*kind, size);
    const auto n = static_cast<std::int64_t>(lay.points.size());
    const double sort_s = taut::bench::sort_seconds(lay.points);
    const auto& dom = lay.norm.domain;
    const std::vector<Point> free_pts =
        taut::bench::random_free_points(dom, lay.norm.obstacles, static_cast<std::size_t>(nqueries) + 10000, 7);
    for (const std::int64_t k : source_counts) {
      std::vector<Point> sources(free_pts.end() - k, free_pts.end());
      std::vector<Point> queries(free_pts.begin(), free_pts.begin() + nqueries);
      std::optional<Map> map;
      const std::size_t heap0 = taut::bench::heap_in_use();
      const double build = seconds_of([&] { map.emplace(dom, lay.norm.obstacles, sources); }, 1);
      const std::size_t bytes = taut::bench::heap_in_use() - heap0;
      // Query time: every query once (best of 3 passes).
      volatile std::int64_t sink = 0;  // keeps the queries from being optimised away
      const double qs = seconds_of(
          [&] {
            for (const Point& q : queries)
              if (const auto a = map->locate(q)) sink = sink + num(a->distance);
          },
          3);
      // Baseline for the query time, in the same run: one binary search per query in the sorted
      // vertices (a 1-D lookup with the same kind of cache misses), best of 3 passes.
      std::vector<Point> sorted = lay.points;
      std::sort(sorted.begin(), sorted.end());
      const double bs = seconds_of(
          [&] {
            for (const Point& q : queries) sink = sink + (std::upper_bound(sorted.begin(), sorted.end(), q) - sorted.begin());
          },
          3);
      // One wavefront per query (the pre-map way), on the first few queries; answers compared.
      Wave wf(dom, lay.norm.obstacles);
      const int w = std::min<int>(wave_queries > 0 ? wave_queries : (n >= 100000 ? 5 : 20), nqueries);
      int checked = 0;
      const double wave = seconds_of(
          [&] {
            for (int i = 0; i < w; ++i) {
              wf.run(sources, {&queries[i], 1}, taut::router::WavefrontStop::AllTargets);
              const auto d = wf.target_distance(0);
              const auto a = map->locate(queries[i]);
              if (d.has_value() != a.has_value() || (d && *d != a->distance)) ++failures;
              else ++checked;
            }
          },
          1);
      const double per_query = qs / nqueries, wave_per = wave / w;
      const double wave_build = seconds_of(
          [&] { wf.run(sources, {}, taut::router::WavefrontStop::Never); }, 1);
      std::printf("%9lld %6lld | %8.3f %7.0f %7.2f | %9lld %8.2f %8.0f %7.2f %7.1f | %8.4f %9.0f %9.1f %5d/%d\n",
                  static_cast<long long>(n), static_cast<long long>(k), build, build / sort_s, build / wave_build,
                  static_cast<long long>(map->stats().trapezoids),
                  static_cast<double>(map->stats().rays) / std::max<std::int64_t>(1, map->stats().trapezoids),
                  static_cast<double>(bytes) / n, per_query * 1e6, qs / bs, wave_per, wave_per / per_query,
                  build / std::max(1e-12, wave_per - per_query), checked, w);
      std::fflush(stdout);
      if (k == source_counts.front()) growth.push_back({std::log(static_cast<double>(n)), std::log(build)});
    }
  };
  for (const std::int64_t size : sizes) {
    if (oct)
      measure.operator()<taut::router::OctMap, taut::router::OctWavefront>(size);
    else
      measure.operator()<taut::router::L1Map, taut::router::L1Wavefront>(size);
  }
  if (growth.size() >= 2) {
    const auto& a = growth[growth.size() - 2];
    const auto& b = growth.back();
    std::printf("build time grows as n^%.2f between the two largest sizes (%zu sources: the first count)\n",
                (b.logt - a.logt) / (b.logn - a.logn), static_cast<std::size_t>(source_counts.front()));
  }
  std::printf("columns: /sort = build / std::sort of the vertices; /wave = build / one full wavefront run (the\n"
              "map's own first step); wave s = one wavefront run per query, stopping at it; wave/query = that\n"
              "over the map's query time; break-even = queries after which the map has paid for its build;\n"
              "/bsearch = query time over one std::upper_bound in the n sorted vertices per query (same run)\n");
  if (failures) std::printf("MISMATCHES: %d queries differ between the map and the wavefront\n", failures);
  return failures ? 1 : 0;
}
