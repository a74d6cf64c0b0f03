// Scaling benchmark of the exact L1 wavefront (router/wavefront.h): the whole distance field
// from one source (every obstacle vertex labelled) on generated layouts of 10^3 .. 10^6
// obstacle vertices, and the brute-force reference (tests/oracle/l1_oracle: visibility graph +
// Dijkstra) on the same layouts while it finishes in reasonable time (up to ~10^4).
//
// Machines here are noisy, so every time is also printed as a ratio to a baseline measured in
// the same run on the same data: `sort` = std::sort of the obstacle vertices by (x, y), an
// n log n unit of this machine's speed. The growth exponent between consecutive sizes is
// log(t2 / t1) / log(n2 / n1) (1.0 is linear; n log^2 n between 10^4 and 10^6 shows as ~1.3).
// The wavefront's distances are compared with the reference wherever the reference ran (at 50
// sampled vertices and targets), so a fast wrong answer cannot pass as a result.
//
//   bench_wavefront [--max N | --sizes N,N,..] [--kind rects|polygons|maze|degenerate] [--ref-max N]
//                   [--reps R]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "oracle/l1_oracle.h"
#include "router/wavefront.h"
#include "bench/bench_util.h"

namespace {

using taut::bench::peak_rss_mib;
using taut::bench::seconds_of;
using taut::geom::Point;

struct Row {
  std::int64_t n = 0;  // obstacle vertices after the union (frame excluded)
  double sort = 0, build = 0, field = 0, ref = -1;
  std::int64_t events = 0, labelled = 0;
  std::size_t bytes = 0, own_bytes = 0;
  double rss = 0;
  int checked = 0;
};

}  // namespace

int main(int argc, char** argv) {
  std::int64_t max_n = 1'000'000, ref_max = 5'000;
  int reps = 1;
  std::string kind_name = "rects";
  std::vector<std::int64_t> sizes;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--max") && i + 1 < argc) max_n = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--ref-max") && i + 1 < argc) ref_max = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) kind_name = argv[++i];
    else if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) {
      sizes.clear();
      for (char* tok = std::strtok(argv[++i], ","); tok; tok = std::strtok(nullptr, ",")) sizes.push_back(std::atoll(tok));
    }
    else {
      std::fprintf(stderr, "usage: %s [--max N | --sizes N,N,...] [--kind K] [--ref-max N] [--reps R]\n", argv[0]);
      return 2;
    }
  }
  const auto kind = taut::io::parse_gen_kind(kind_name);
  if (!kind) {
    std::fprintf(stderr, "unknown kind %s\n", kind_name.c_str());
    return 2;
  }
  std::printf("taut wavefront benchmark: kind=%s, one source, whole distance field, one thread, best of %d\n",
              kind_name.c_str(), reps);
  std::printf("%9s %9s | %8s %8s %8s | %7s %8s | %8s %9s %7s %7s | %6s %8s | %8s\n", "vertices", "sort(s)",
              "build(s)", "field(s)", "ref(s)", "field/s", "ref/field", "events", "events/n",
              "B/vert", "own B/v", "rss", "labelled", "checked");
  std::vector<Row> rows;
  bool all_ok = true;
  if (sizes.empty())
    for (std::int64_t n : {1'000, 2'000, 4'000, 10'000, 100'000, 1'000'000})
      if (n <= max_n) sizes.push_back(n);
  for (const std::int64_t target : sizes) {
    Row row;
    const taut::bench::BenchLayout bl = taut::bench::bench_layout(*kind, target);
    const auto& norm = bl.norm;
    const auto& pts = bl.points;
    row.n = static_cast<std::int64_t>(pts.size());
    row.sort = seconds_of([&] { auto v = pts; std::sort(v.begin(), v.end()); }, reps);

    const auto& dom = norm.domain;
    std::optional<taut::router::L1Wavefront> wf;
    const std::size_t heap0 = taut::bench::heap_in_use();
    row.build = seconds_of([&] { wf.reset(); wf.emplace(dom, norm.obstacles); }, reps);
    const Point source = taut::bench::bench_source(dom, [&](Point p) { return wf->is_free(p); });
    const std::vector<Point>& targets = bl.targets;
    row.field = seconds_of([&] { wf->run({&source, 1}, targets, /*stop_early=*/false); }, reps);
    const auto& st = wf->stats();
    row.events = st.events;
    row.labelled = st.labelled;
    row.bytes = taut::bench::heap_in_use() - heap0;  // everything the wavefront holds after the run
    row.own_bytes = wf->memory_bytes();
    if (row.n <= ref_max) {
      std::vector<std::optional<std::int64_t>> ref;
      row.ref = seconds_of([&] {
        taut::oracle::L1Reference oracle(dom, norm.obstacles);
        ref = oracle.distances(source, targets);
      }, 1);
      for (std::size_t i = 0; i < targets.size(); ++i) {
        if (ref[i] != wf->target_distance(i)) {
          all_ok = false;
          std::fprintf(stderr, "MISMATCH at n=%lld target %zu (%lld,%lld): wavefront %lld, reference %lld\n",
                       static_cast<long long>(row.n), i, static_cast<long long>(targets[i].x),
                       static_cast<long long>(targets[i].y),
                       static_cast<long long>(wf->target_distance(i).value_or(-1)),
                       static_cast<long long>(ref[i].value_or(-1)));
        }
        ++row.checked;
      }
    }
    row.rss = peak_rss_mib();
    char refbuf[32] = "-", ratiobuf[32] = "-";
    if (row.ref >= 0) {
      std::snprintf(refbuf, sizeof refbuf, "%.3f", row.ref);
      std::snprintf(ratiobuf, sizeof ratiobuf, "%.0fx", row.ref / (row.build + row.field));
    }
    std::printf("%9lld %9.4f | %8.3f %8.3f %8s | %7.1f %8s | %8lld %9.2f %7.0f %7.0f | %6.0f %8lld | %8d\n",
                static_cast<long long>(row.n), row.sort, row.build, row.field, refbuf,
                (row.build + row.field) / row.sort, ratiobuf, static_cast<long long>(row.events),
                double(row.events) / double(row.n), double(row.bytes) / double(row.n),
                double(row.own_bytes) / double(row.n), row.rss,
                static_cast<long long>(row.labelled), row.checked);
    std::fflush(stdout);
    rows.push_back(row);
  }
  std::printf("\ncolumns: build = index construction, field = run(); ref = reference build + one Dijkstra;\n"
              "field/s = (build + field) / sort; ref/field = ref / (build + field);\n"
              "B/vert = heap bytes the wavefront holds after the run (indexes, entities, queue, caches) / n;\n"
              "own B/v = what L1Wavefront::memory_bytes() accounts for (its own arrays; not the R-tree) / n;\n"
              "rss = peak resident MiB of the whole process so far. The reference is O(n^3)-ish (about 20 min\n"
              "at 10^4), so it runs up to --ref-max (default 5000) and the ratio is read at the largest size.\n");
  std::printf("\ngrowth exponents log(t2/t1)/log(n2/n1) of build + field (sort for comparison):\n");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double ln = std::log(double(rows[i].n) / double(rows[i - 1].n));
    auto ex = [&](double a, double b) { return std::log(b / a) / ln; };
    std::printf("  %lld -> %lld: wavefront %.2f, events %.2f, sort %.2f\n", static_cast<long long>(rows[i - 1].n),
                static_cast<long long>(rows[i].n), ex(rows[i - 1].build + rows[i - 1].field, rows[i].build + rows[i].field),
                ex(double(rows[i - 1].events), double(rows[i].events)), ex(rows[i - 1].sort, rows[i].sort));
  }
  const Row* r4 = nullptr;
  const Row* r6 = nullptr;
  for (const Row& r : rows) {
    if (r.n >= 5'000 && r.n < 50'000) r4 = &r;
    if (r.n >= 500'000) r6 = &r;
  }
  std::printf("\ntargets (issue #3):\n");
  if (r6)
    std::printf("  10^6 vertices in < 10 s: %s (%.2f s at n=%lld)\n", r6->build + r6->field < 10 ? "met" : "MISSED",
                r6->build + r6->field, static_cast<long long>(r6->n));
  if (r4 && r6) {
    const double e = std::log((r6->build + r6->field) / (r4->build + r4->field)) / std::log(double(r6->n) / double(r4->n));
    const double bound = 1.0 + 2.0 * std::log(std::log(double(r6->n)) / std::log(double(r4->n))) /
                                   std::log(double(r6->n) / double(r4->n));
    std::printf("  growth 10^4 -> 10^6 no worse than n log^2 n (exponent %.2f, n log^2 n gives %.2f): %s\n", e, bound,
                e <= bound + 0.05 ? "met" : "MISSED");
  }
  const Row* rref = nullptr;
  for (const Row& r : rows)
    if (r.ref >= 0) rref = &r;
  if (rref)
    std::printf("  >= 100x faster than the reference (at the largest size it ran, n=%lld): %s (%.0fx)\n",
                static_cast<long long>(rref->n), rref->ref / (rref->build + rref->field) >= 100 ? "met" : "MISSED",
                rref->ref / (rref->build + rref->field));
  if (r6)
    std::printf("  < 300 bytes per vertex: %s (%.0f B at n=%lld)\n", double(r6->bytes) / double(r6->n) < 300 ? "met" : "MISSED",
                double(r6->bytes) / double(r6->n), static_cast<long long>(r6->n));
  if (!all_ok) {
    std::printf("\nDISTANCE MISMATCH against the reference (see stderr)\n");
    return 1;
  }
  return 0;
}
