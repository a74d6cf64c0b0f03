// Benchmark of multi-pin nets in `taut route`: BasicRouter::tree (router/l1_router.h), one
// wavefront run from the net's first pin to all its other pins, stopping when the last is
// reached, then the staircases) against the alternative of building the L1 shortest path map of
// the first pin (router/spm.h, L1Map: a wavefront run to the end of free space, then the
// decomposition) and answering each sink by point location. The map's time counts only its
// build and the queries (no staircases), so the ratio map / tree understates the map's cost.
// Baseline in the same run: std::sort of the n vertices. Every sink's distance from the tree is
// compared with the map's, so a fast wrong answer cannot pass.
//
// Nets: "local" nets have their pins in a square of a tenth of the layout's side around a
// random free point (what placed cells give); "global" nets anywhere.
//
//   bench_net_tree [--sizes N,N,..] [--pins K,K,..] [--nets M] [--kind K]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/free_points.h"
#include "router/l1_router.h"
#include "router/spm.h"

namespace {

using taut::bench::seconds_of;
using taut::geom::Point;
using taut::bench::point_pin;
using taut::geom::Polygon;

}  // namespace

int main(int argc, char** argv) {
  taut::bench::NetBenchArgs defaults;
  defaults.sizes = {1000, 10000, 100000};
  defaults.pins = {3, 8, 32};
  const auto args = taut::bench::parse_net_bench_args(argc, argv, defaults);
  if (!args) return 2;
  const auto& [sizes, pin_counts, nets, kind_name, kind] = *args;
  std::printf("multi-pin nets: shortest-path tree (one wavefront run to the sinks) vs the source's L1Map, kind %s, %d nets per row\n",
              kind_name.c_str(), nets);
  std::printf("%9s %6s %5s | %10s %7s | %10s %7s | %8s %s\n", "vertices", "nets", "pins", "tree ms/net", "/sort",
              "map ms/net", "/sort", "map/tree", "checked");
  int failures = 0;
  for (const std::int64_t size : sizes) {
    const auto lay = taut::bench::bench_layout(kind, size);
    const double sort_s = taut::bench::sort_seconds(lay.points);
    const auto& dom = lay.norm.domain;
    taut::router::L1Router router(dom, lay.norm.obstacles);
    const std::vector<Point> pool = taut::bench::random_free_points(dom, lay.norm.obstacles, 200000, 11);
    for (const bool local : {true, false}) {
      for (const std::int64_t k : pin_counts) {
        const std::vector<std::vector<Point>> pins = taut::bench::random_nets(
            pool, dom, static_cast<std::size_t>(nets), static_cast<std::size_t>(k), local,
            static_cast<std::uint64_t>(size * 131 + k * 7 + local));
        std::vector<std::vector<std::optional<std::int64_t>>> tree_d(pins.size()), map_d(pins.size());
        const double tree_s = seconds_of(
            [&] {
              for (std::size_t n = 0; n < pins.size(); ++n) {
                std::vector<Polygon> sinks;
                for (std::size_t j = 1; j < pins[n].size(); ++j) sinks.push_back(point_pin(pins[n][j]));
                const auto t = router.tree(point_pin(pins[n][0]), sinks);
                tree_d[n] = t.distance;
              }
            },
            1);
        const double map_s = seconds_of(
            [&] {
              for (std::size_t n = 0; n < pins.size(); ++n) {
                const Point src = pins[n][0];
                taut::router::L1Map map(dom, lay.norm.obstacles, {&src, 1});
                map_d[n].clear();
                for (std::size_t j = 1; j < pins[n].size(); ++j) {
                  const auto a = map.locate(pins[n][j]);
                  map_d[n].push_back(a ? std::optional(a->distance) : std::nullopt);
                  if (a) (void)map.path(pins[n][j], *a);
                }
              }
            },
            1);
        int checked = 0;
        for (std::size_t n = 0; n < pins.size(); ++n)
          for (std::size_t j = 0; j < map_d[n].size(); ++j) {
            ++checked;
            if (j >= tree_d[n].size() || tree_d[n][j] != map_d[n][j]) ++failures;
          }
        const double per = 1000.0 / static_cast<double>(nets);
        std::printf("%9zu %6s %5lld | %10.2f %7.1f | %10.2f %7.1f | %8.1f %d\n", lay.points.size(),
                    local ? "local" : "global", static_cast<long long>(k), tree_s * per, tree_s / nets / sort_s,
                    map_s * per, map_s / nets / sort_s, map_s / tree_s, checked);
        std::fflush(stdout);
      }
    }
  }
  if (failures) std::printf("MISMATCHES between tree and map distances: %d\n", failures);
  return failures ? 1 : 0;
}
