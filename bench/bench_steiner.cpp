// Steiner trees for multi-pin nets (issue #7; router::L1Router::steiner, the default of `taut
// route` for nets of three or more point pins) against the shortest-path tree from the first pin
// (BasicRouter::tree, `--tree spt`) on the same router in the same run: time per net and its
// ratio to the tree's, and total wire length as a ratio to the tree's; also grown from the first
// pin only (starts = 1) to show what the eight starts buy, and without the improvement pass (its
// time as a ratio, and its length) to show what the pass costs and buys. Nets: "local" pins in a square of a
// tenth of the layout's side around a random free point, "global" pins anywhere. Every tree is
// built on the same router; a net where either fails is counted and left out of the ratios.
// A second table does the same for OCTILINEAR wires (OctRouter::steiner against OctRouter::tree,
// lengths measured in d8; its improvement pass included).
//
//   bench_steiner [--sizes N,N,..] [--pins K,K,..] [--nets M] [--kind K]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/free_points.h"
#include "router/l1_router.h"
#include "router/oct_router.h"

namespace {

using taut::bench::total_length;
using taut::bench::seconds_of;
using taut::geom::Point;
using taut::bench::point_pin;
using taut::geom::Polygon;

}  // namespace

int main(int argc, char** argv) {
  // 10^5: minutes per row
  taut::bench::NetBenchArgs defaults;
  defaults.sizes = {1000, 10000};
  defaults.pins = {3, 8, 20};
  const auto args = taut::bench::parse_net_bench_args(argc, argv, defaults);
  if (!args) return 2;
  const auto& [sizes, pin_counts, nets, kind_name, kind] = *args;
  // The nets' shortest-path trees from their first pins on `router`, timed: each tree's length by
  // `measure` (-1: failed) and the seconds.
  auto spt_trees = [](auto& router, const std::vector<std::vector<Point>>& pins, auto measure) {
    std::vector<double> len(pins.size(), -1);
    const double s = seconds_of(
        [&] {
          for (std::size_t n = 0; n < pins.size(); ++n) {
            std::vector<Polygon> sinks;
            for (std::size_t j = 1; j < pins[n].size(); ++j) sinks.push_back(point_pin(pins[n][j]));
            const auto t = router.tree(point_pin(pins[n][0]), sinks);
            if (t.status == taut::router::WireStatus::Ok) len[n] = measure(t.wires);
          }
        },
        1);
    return std::pair{std::move(len), s};
  };
  std::printf("Steiner trees vs shortest-path trees, kind %s, %d nets per row, one thread\n", kind_name.c_str(), nets);
  std::printf("%9s %6s %5s | %9s %9s %8s | %8s %8s | %8s %8s | %s\n", "vertices", "nets", "pins", "spt ms", "steiner ms",
              "/spt", "len/spt", "1 start", "/nopass", "nopass", "failed");
  for (const std::int64_t size : sizes) {
    const auto lay = taut::bench::bench_layout(kind, size);
    const auto& dom = lay.norm.domain;
    taut::router::L1Router router(dom, lay.norm.obstacles);
    const std::vector<Point> pool = taut::bench::random_free_points(dom, lay.norm.obstacles, 200000, 11);
    for (const bool local : {true, false}) {
      for (const std::int64_t k : pin_counts) {
        const std::vector<std::vector<Point>> pins = taut::bench::random_nets(
            pool, dom, static_cast<std::size_t>(nets), static_cast<std::size_t>(k), local,
            static_cast<std::uint64_t>(size * 131 + k * 7 + local));
        const auto [spt_len, spt_s] =
            spt_trees(router, pins, [](const auto& w) { return static_cast<double>(total_length(w)); });
        std::vector<std::int64_t> st_len(pins.size(), -1), one_len(pins.size(), -1);
        const double st_s = seconds_of(
            [&] {
              for (std::size_t n = 0; n < pins.size(); ++n) {
                const auto t = router.steiner(pins[n]);
                if (t.status == taut::router::WireStatus::Ok) st_len[n] = t.length;
              }
            },
            1);
        std::vector<std::int64_t> plain_len(pins.size(), -1);  // without the improvement pass
        const double plain_s = seconds_of(
            [&] {
              for (std::size_t n = 0; n < pins.size(); ++n) {
                const auto t = router.steiner(pins[n], 8, false);
                if (t.status == taut::router::WireStatus::Ok) plain_len[n] = t.length;
              }
            },
            1);
        for (std::size_t n = 0; n < pins.size(); ++n) {
          const auto t = router.steiner(pins[n], 1);
          if (t.status == taut::router::WireStatus::Ok) one_len[n] = t.length;
        }
        double spt_sum = 0, st_sum = 0, one_sum = 0, plain_sum = 0;
        int failed = 0;
        for (std::size_t n = 0; n < pins.size(); ++n) {
          if (spt_len[n] < 0 || st_len[n] < 0 || one_len[n] < 0 || plain_len[n] < 0) {
            ++failed;
            continue;
          }
          spt_sum += spt_len[n];
          st_sum += static_cast<double>(st_len[n]);
          one_sum += static_cast<double>(one_len[n]);
          plain_sum += static_cast<double>(plain_len[n]);
        }
        const double per = 1000.0 / static_cast<double>(nets);
        std::printf("%9zu %6s %5lld | %9.2f %9.2f %8.1f | %8.3f %8.3f | %8.1f %8.3f | %d\n", lay.points.size(),
                    local ? "local" : "global", static_cast<long long>(k), spt_s * per, st_s * per, st_s / spt_s,
                    st_sum / spt_sum, one_sum / spt_sum, st_s / plain_s, plain_sum / spt_sum, failed);
        std::fflush(stdout);
      }
    }
  }
  std::printf("(len/spt: the Steiner trees' total length over the shortest-path trees'; 1 start: the same grown from the "
              "first pin only; /nopass: time over the same search without the improvement pass, nopass: its length over "
              "the shortest-path trees')\n");

  // Octilinear: the same nets on OctRouter, lengths in d8.
  auto d8_length = [](const std::vector<std::vector<Point>>& wires) {
    taut::geom::Root2 l{};
    for (const auto& w : wires)
      for (std::size_t i = 1; i < w.size(); ++i)
        l += taut::geom::octilinear_length(std::int64_t{w[i].x} - w[i - 1].x, std::int64_t{w[i].y} - w[i - 1].y);
    return l.to_double();
  };
  std::printf("\nOctilinear Steiner trees vs octilinear shortest-path trees, kind %s, %d nets per row, one thread\n",
              kind_name.c_str(), nets);
  std::printf("%9s %6s %5s | %9s %9s %8s | %8s | %s\n", "vertices", "nets", "pins", "spt ms", "steiner ms", "/spt", "len/spt",
              "failed");
  for (const std::int64_t size : sizes) {
    const auto lay = taut::bench::bench_layout(kind, size);
    const auto& dom = lay.norm.domain;
    taut::router::OctRouter router(dom, lay.norm.obstacles);
    const std::vector<Point> pool = taut::bench::random_free_points(dom, lay.norm.obstacles, 200000, 11);
    for (const bool local : {true, false}) {
      for (const std::int64_t k : pin_counts) {
        const std::vector<std::vector<Point>> pins = taut::bench::random_nets(
            pool, dom, static_cast<std::size_t>(nets), static_cast<std::size_t>(k), local,
            static_cast<std::uint64_t>(size * 131 + k * 7 + local));
        const auto [spt_len, spt_s] = spt_trees(router, pins, d8_length);
        std::vector<double> st_len(pins.size(), -1);
        const double st_s = seconds_of(
            [&] {
              for (std::size_t n = 0; n < pins.size(); ++n) {
                const auto t = router.steiner(pins[n]);
                if (t.status == taut::router::WireStatus::Ok) st_len[n] = t.length.to_double();
              }
            },
            1);
        double spt_sum = 0, st_sum = 0;
        int failed = 0;
        for (std::size_t n = 0; n < pins.size(); ++n) {
          if (spt_len[n] < 0 || st_len[n] < 0) {
            ++failed;
            continue;
          }
          spt_sum += spt_len[n];
          st_sum += st_len[n];
        }
        const double per = 1000.0 / static_cast<double>(nets);
        std::printf("%9zu %6s %5lld | %9.2f %9.2f %8.1f | %8.3f | %d\n", lay.points.size(), local ? "local" : "global",
                    static_cast<long long>(k), spt_s * per, st_s * per, st_s / spt_s, st_sum / spt_sum, failed);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
