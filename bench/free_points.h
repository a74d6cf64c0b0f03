// Random free points of a benchmark layout, for sources, sites and queries: uniform in the
// domain, kept when a source-less shortest path map (router/spm.h) says they are free (a point
// location each, O(log n) on these layouts). Apart from bench_util.h so only the benches that
// use the map compile its header.
#pragma once

#include <cstdint>
#include <random>
#include <span>
#include <vector>

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

}  // namespace taut::bench
