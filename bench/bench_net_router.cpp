// The net router (issue #7; router::NetRouter, `taut route`'s default): m local nets of 2-5 point
// pins with width and spacing, routed together (grown blockages, the other nets' grown wires and
// pins, rip-up), against the same nets routed each alone on one router (`--independent`, the
// baseline, in the same run): completion, total length as a ratio to the independent wires' (a
// lower bound for what each net gets: routing among others only lengthens it), rip-ups, time and
// its ratio to the baseline, and how time grows with m (exponent between rows).
//
//   bench_net_router [--sizes N,..] [--nets M,..]    (--sizes: blockage vertices)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/free_points.h"
#include "router/l1_router.h"
#include "router/net_router.h"

namespace {

using taut::bench::total_length;
using taut::geom::Point;
using taut::geom::Polygon;

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes = {1000}, net_counts = {10, 30, 100};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = taut::bench::parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--nets") && i + 1 < argc) net_counts = taut::bench::parse_list(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--sizes N,..] [--nets M,..]\n", argv[0]);
      return 2;
    }
  }
  std::printf("net router vs each net alone (baseline), rects layouts, local nets of 2-5 point pins, w = s = 10\n");
  std::printf("%9s %6s | %8s %8s %7s | %9s %9s %8s %6s | %s\n", "vertices", "nets", "routed", "1st pass", "rips", "alone s",
              "together s", "/alone", "growth", "len/alone");
  for (const std::int64_t size : sizes) {
    const auto lay = taut::bench::bench_layout(taut::io::GenKind::Rects, size);
    const auto& dom = lay.norm.domain;
    const std::vector<Point> pool = taut::bench::random_free_points(dom, lay.norm.obstacles, 20000, 17);
    double last_t = 0, last_m = 0;
    for (const std::int64_t m : net_counts) {
      std::vector<taut::router::NetPins> nets;
      for (std::size_t k = 2; k <= 5; ++k) {
        const auto pins = taut::bench::random_nets(pool, dom, static_cast<std::size_t>(m) / 4 + (k - 2 < static_cast<std::size_t>(m) % 4),
                                                   k, true, static_cast<std::uint64_t>(size * 31 + m * 7 + k));
        for (const auto& p : pins) {
          taut::router::NetPins np;
          np.name = "n" + std::to_string(nets.size());
          for (const Point q : p) np.pins.push_back(taut::bench::point_pin(q));
          nets.push_back(std::move(np));
        }
      }
      // baseline: each net alone on one router (what --independent does)
      std::vector<std::int64_t> alone_len(nets.size(), -1);
      std::size_t alone_ok = 0;
      const double alone_s = taut::bench::seconds_of([&] {
        taut::router::L1Router r(dom, lay.norm.obstacles);
        for (std::size_t i = 0; i < nets.size(); ++i) {
          const auto& pins = nets[i].pins;
          if (pins.size() == 2) {
            const auto w = r.shortest(pins[0], pins[1]);
            if (w.status == taut::router::WireStatus::Ok) alone_len[i] = total_length({w.points});
          } else {
            const auto t = r.tree(pins[0], std::span<const Polygon>(pins).subspan(1));
            if (t.status == taut::router::WireStatus::Ok) alone_len[i] = total_length(t.wires);
          }
          alone_ok += alone_len[i] >= 0;
        }
      }, 1);
      taut::router::NetRouter nr(dom, lay.norm.obstacles, nets, {10, 10});
      const double together_s = taut::bench::seconds_of([&] { nr.run(taut::router::NetRouter::l1_router(false)); }, 1);
      std::size_t routed = 0;
      std::int64_t len = 0, len_alone_same = 0;
      for (std::size_t i = 0; i < nets.size(); ++i) {
        routed += nr.outcomes()[i].routed;
        if (nr.outcomes()[i].routed && alone_len[i] >= 0) {
          len += total_length(nr.outcomes()[i].wires);
          len_alone_same += alone_len[i];
        }
      }
      const double growth = last_t > 0 ? std::log(together_s / last_t) / std::log(static_cast<double>(nets.size()) / last_m) : 0;
      std::printf("%9lld %6zu | %8zu %8zu %7lld | %9.3f %9.3f %8.1f %6.2f | %.3f  (alone: %zu routed)\n",
                  static_cast<long long>(lay.points.size()), nets.size(), routed, nr.stats().first_pass,
                  static_cast<long long>(nr.stats().rips), alone_s, together_s, together_s / alone_s, growth,
                  len_alone_same > 0 ? static_cast<double>(len) / static_cast<double>(len_alone_same) : 0.0, alone_ok);
      std::printf("%18s nets tried %lld times in %lld windows (%lld whole): building spaces %.3f s, paths %.3f s\n", "",
                  static_cast<long long>(nr.stats().attempts), static_cast<long long>(nr.stats().windows),
                  static_cast<long long>(nr.stats().whole), nr.stats().space_seconds, nr.stats().route_seconds);
      std::fflush(stdout);
      last_t = together_s, last_m = static_cast<double>(nets.size());
    }
  }
  return 0;
}
