// Helpers shared by the benchmark programs: best-of-R timing, peak RSS, heap bytes in use.
#pragma once
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "geom/normalize.h"
#include "io/generate.h"
#include "io/layout_geometry.h"

namespace taut::bench {

using Clock = std::chrono::steady_clock;

// Best wall time of `reps` runs of f, in seconds.
inline double seconds_of(const std::function<void()>& f, int reps) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

// Keeps a value the timed code computed from being optimized away (like benchmark::DoNotOptimize:
// the compiler must assume the value is read).
template <class T>
inline void keep(const T& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}

// Peak resident set of the process so far, MiB.
inline double peak_rss_mib() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return static_cast<double>(ru.ru_maxrss) / 1024.0;
}

// Bytes the process holds from malloc right now (glibc: small chunks + mmapped chunks), so the
// difference across a construction is everything that object (and its containers) holds.
inline std::size_t heap_in_use() {
  const struct mallinfo2 mi = mallinfo2();
  return mi.uordblks + mi.hblkhd;
}

// A generated layout (seed 42, no nets) of about `size` blockage vertices, normalized, with
// every obstacle vertex (`points`, the n of the tables) and 50 of them spread over the layout as
// targets (they let the reference be compared).
struct BenchLayout {
  geom::NormalizedObstacles norm;
  std::vector<geom::Point> points, targets;
};
inline BenchLayout bench_layout(io::GenKind kind, std::int64_t size) {
  io::GenOptions go;
  go.kind = kind;
  go.size = size;
  go.nets = 0;
  go.seed = 42;
  const io::Layout layout = io::generate_layout(go);
  std::optional<geom::Box> boundary;
  if (layout.boundary) boundary = layout.boundary->box;
  BenchLayout b;
  b.norm = geom::normalize_obstacles(io::blockage_polygons(layout), boundary);
  for (const auto& o : b.norm.obstacles) {
    b.points.insert(b.points.end(), o.outer.begin(), o.outer.end());
    for (const auto& h : o.holes) b.points.insert(b.points.end(), h.begin(), h.end());
  }
  for (int i = 0; i < 50 && !b.points.empty(); ++i) b.targets.push_back(b.points[(b.points.size() * i) / 50]);
  return b;
}

// The source: the first free point of a fixed sequence starting at the domain's lower-left
// corner (deterministic), so the wave has to cross the whole layout. is_free: a wavefront's.
template <class IsFree>
geom::Point bench_source(const geom::Box& dom, IsFree is_free) {
  geom::Point source{dom.lo.x, dom.lo.y};
  for (std::int64_t k = 0; k < 1'000'000 && !is_free(source); ++k)
    source = geom::Point{static_cast<geom::Coord>(dom.lo.x + (k * 7919) % (std::int64_t{dom.hi.x} - dom.lo.x + 1)),
                         static_cast<geom::Coord>(dom.lo.y + (k * 104729) % (std::int64_t{dom.hi.y} - dom.lo.y + 1))};
  return source;
}

// The baseline the scaling benchmarks divide by: std::sort of the points, best of 3.
inline double sort_seconds(const std::vector<geom::Point>& points) {
  return seconds_of(
      [&] {
        std::vector<geom::Point> v = points;
        std::sort(v.begin(), v.end());
      },
      3);
}

// "1000,10000" -> {1000, 10000} (a --sizes style option; modifies s).
inline std::vector<std::int64_t> parse_list(char* s) {
  std::vector<std::int64_t> v;
  for (char* tok = std::strtok(s, ","); tok; tok = std::strtok(nullptr, ",")) v.push_back(std::atoll(tok));
  return v;
}

// A comb of t teeth standing on a spine (4t + 4 vertices before cleaning): every tooth tip is 3
// links from every other, so the eccentricity bounds prune nothing and the diameter searches
// from every tip: the worst case of the method (bench_diameter, bench_diameter_approx).
inline geom::Ring comb(std::int64_t size) {
  const geom::Coord t = static_cast<geom::Coord>(std::max<std::int64_t>(1, (size - 4) / 4)), u = 100;
  const geom::Coord X = (4 * t + 2) * u, S = 3 * u, H = 40 * u;
  geom::Ring r = {{0, 0}, {X, 0}, {X, S}};
  for (geom::Coord i = t - 1; i >= 0; --i) {
    const geom::Coord a = (2 + 4 * i) * u;
    r.insert(r.end(), {{a + 2 * u, S}, {a + 2 * u, S + H}, {a, S + H}, {a, S}});
  }
  r.push_back({0, S});
  return r;
}

}  // namespace taut::bench
