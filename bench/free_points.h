// Random free points of a benchmark layout, for sources, sites and queries: uniform in the
// domain, kept when a source-less shortest path map (router/spm.h) says they are free (a point
// location each, O(log n) on these layouts). Apart from bench_util.h so only the benches that
// use the map compile its header.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <random>
#include <span>
#include <vector>

#include "bench/bench_util.h"

#include "router/spm.h"

namespace taut::bench {

inline std::vector<geom::Point> random_free_points(const geom::Box& dom, std::span<const geom::Polygon> obstacles,
                                                   std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto coord = [&](geom::Coord lo, geom::Coord hi) {
    return static_cast<geom::Coord>(lo + static_cast<std::int64_t>(rng() % (static_cast<std::uint64_t>(std::int64_t{hi} - lo) + 1)));
  };
  std::vector<geom::Point> out;
  const router::L1Map probe(dom, obstacles, {});
  while (out.size() < count) {
    const geom::Point p{coord(dom.lo.x, dom.hi.x), coord(dom.lo.y, dom.hi.y)};
    if (probe.is_free(p)) out.push_back(p);
  }
  return out;
}

// `nets` nets of `k` pins drawn from `pool` (rng seeded with `seed`): "local" nets have their
// pins in a square of a tenth of the domain's side around their first (what placed cells give),
// global ones anywhere (bench_net_tree, bench_steiner).
inline std::vector<std::vector<geom::Point>> random_nets(std::span<const geom::Point> pool, const geom::Box& dom, std::size_t nets,
                                                         std::size_t k, bool local, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::vector<geom::Point>> pins(nets);
  const std::int64_t side = (std::int64_t{dom.hi.x} - dom.lo.x) / 10;
  for (auto& net : pins) {
    const geom::Point c = pool[rng() % pool.size()];
    net.push_back(c);
    for (std::size_t tries = 0; net.size() < k && tries < 2000000; ++tries) {
      const geom::Point p = pool[rng() % pool.size()];
      if (!local || (std::abs(std::int64_t{p.x} - c.x) <= side / 2 && std::abs(std::int64_t{p.y} - c.y) <= side / 2))
        net.push_back(p);
    }
  }
  return pins;
}

// The total L1 length of polylines.
inline std::int64_t total_length(const std::vector<std::vector<geom::Point>>& wires) {
  std::int64_t s = 0;
  for (const auto& w : wires)
    for (std::size_t i = 1; i < w.size(); ++i)
      s += std::abs(std::int64_t{w[i].x} - w[i - 1].x) + std::abs(std::int64_t{w[i].y} - w[i - 1].y);
  return s;
}

// A point pin as the routers take pins: a polygon whose outer ring is the one point.
inline geom::Polygon point_pin(geom::Point p) {
  geom::Polygon g;
  g.outer = {p};
  return g;
}

// The options of bench_net_tree and bench_steiner: [--sizes N,..] [--pins K,..] [--nets M]
// [--kind K]. std::nullopt (after printing the usage) for anything else or an unknown kind.
struct NetBenchArgs {
  std::vector<std::int64_t> sizes, pins;
  int nets = 10;
  std::string kind_name = "rects";
  io::GenKind kind = io::GenKind::Rects;
};
inline std::optional<NetBenchArgs> parse_net_bench_args(int argc, char** argv, NetBenchArgs a) {
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) a.sizes = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--pins") && i + 1 < argc) a.pins = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--nets") && i + 1 < argc) a.nets = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) a.kind_name = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--sizes N,..] [--pins K,..] [--nets M] [--kind K]\n", argv[0]);
      return std::nullopt;
    }
  }
  const auto kind = io::parse_gen_kind(a.kind_name);
  if (!kind) {
    std::fprintf(stderr, "unknown kind %s\n", a.kind_name.c_str());
    return std::nullopt;
  }
  a.kind = *kind;
  return a;
}

}  // namespace taut::bench
