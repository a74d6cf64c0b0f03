// Helpers shared by the benchmark programs: best-of-R timing, peak RSS, heap bytes in use.
#pragma once
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>

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

}  // namespace taut::bench
