// Scaling benchmark of the exact OCTILINEAR wavefront (router/wavefront.h, OctWavefront) against
// the L1 wavefront on the same layouts: the whole distance field from one source on generated
// layouts of 10^3 .. 10^6 obstacle vertices. The baseline measured in the same run is the L1
// wavefront itself (and std::sort of the vertices, as in bench_wavefront), so the ratio
// oct / L1 says what the eight frames, the Z[sqrt2] levels and the diagonal rays cost. The
// octilinear brute-force reference (tests/oracle/oct_oracle.h) runs while it finishes (up to
// --ref-max vertices) and 50 distances are compared exactly, so a fast wrong answer cannot pass.
// With --norm N (2, 3 or 4) the fixed-orientation norm of that order (NormWavefront: 16, 32 or 48
// directions, geom/fixed_norm.h) runs instead of the octilinear metric, checked against
// oracle::NormReference.
//
//   bench_oct_wavefront [--sizes N,N,..] [--kind rects|polygons|maze|degenerate] [--ref-max N]
//                       [--reps R] [--norm N]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "geom/normalize.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "oracle/oct_oracle.h"
#include "router/wavefront.h"

namespace {

using taut::bench::seconds_of;
using taut::geom::Point;

struct Row {
  std::int64_t n = 0;
  double sort = 0, l1 = 0, oct = 0, ref = -1;
  std::int64_t l1_events = 0, oct_events = 0;
  double l1_nodes = 0, oct_nodes = 0;  // k-d tree nodes per segment-dragging query
  std::size_t oct_bytes = 0;
  int checked = 0;
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes;
  std::int64_t ref_max = 2000;
  int reps = 1, norm_order = 0;
  std::string kind_name = "rects";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--ref-max") && i + 1 < argc) ref_max = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) kind_name = argv[++i];
    else if (!std::strcmp(argv[i], "--norm") && i + 1 < argc) norm_order = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) {
      for (char* tok = std::strtok(argv[++i], ","); tok; tok = std::strtok(nullptr, ",")) sizes.push_back(std::atoll(tok));
    } else {
      std::fprintf(stderr, "usage: %s [--sizes N,N,...] [--kind K] [--ref-max N] [--reps R] [--norm 2|3|4]\n", argv[0]);
      return 2;
    }
  }
  const auto kind = taut::io::parse_gen_kind(kind_name);
  if (!kind) {
    std::fprintf(stderr, "unknown kind %s\n", kind_name.c_str());
    return 2;
  }
  if (norm_order != 0 && (norm_order < 2 || norm_order > 4)) {
    std::fprintf(stderr, "--norm: 2, 3 or 4\n");
    return 2;
  }
  if (sizes.empty()) sizes = {1'000, 2'000, 10'000, 100'000, 1'000'000};
  // "oct" below is the metric under test: octilinear, or the norm of --norm
  if (norm_order)
    std::printf("taut fixed-orientation norm wavefront benchmark (order %d, %d directions; the oct columns): ",
                norm_order, norm_order == 2 ? 16 : norm_order == 3 ? 32 : 48);
  else
    std::printf("taut octilinear wavefront benchmark: ");
  std::printf("kind=%s, one source, whole distance field, one thread, best of %d\n", kind_name.c_str(), reps);
  std::printf("%9s %8s | %8s %8s %7s | %9s %9s | %7s %8s | %7s %8s | %7s | %6s\n", "vertices", "sort(s)", "l1(s)",
              "oct(s)", "oct/l1", "l1 ev/n", "oct ev/n", "l1 nd/q", "oct nd/q", "ref(s)", "ref/oct", "checked",
              "oct B/v");
  std::vector<Row> rows;
  bool all_ok = true;
  for (const std::int64_t target : sizes) {
    Row row;
    const taut::bench::BenchLayout bl = taut::bench::bench_layout(*kind, target);
    const auto& norm = bl.norm;
    const auto& pts = bl.points;
    row.n = static_cast<std::int64_t>(pts.size());
    row.sort = seconds_of([&] { auto v = pts; std::sort(v.begin(), v.end()); }, reps);
    const auto& dom = norm.domain;
    const std::vector<Point>& targets = bl.targets;
    Point source;
    {
      const taut::router::L1Wavefront l1(dom, norm.obstacles);
      source = taut::bench::bench_source(dom, [&](Point p) { return l1.is_free(p); });
    }
    // Both: construction + the whole field, measured alike.
    std::optional<taut::router::L1Wavefront> l1;
    row.l1 = seconds_of([&] {
      l1.reset();
      l1.emplace(dom, norm.obstacles);
      l1->run({&source, 1}, targets, false);
    }, reps);
    row.l1_events = l1->stats().events;
    row.l1_nodes = double(l1->stats().drag_nodes) / double(std::max<std::int64_t>(1, l1->stats().drag_queries));
    l1.reset();
    // the metric under test: construction, the whole field, stats, heap, and the reference check
    auto measure = [&](auto& oct, auto make, auto make_ref) {
      const std::size_t heap0 = taut::bench::heap_in_use();
      row.oct = seconds_of([&] {
        oct.reset();
        make(oct);
        oct->run({&source, 1}, targets, taut::router::WavefrontStop::Never);
      }, reps);
      row.oct_events = oct->stats().events;
      row.oct_nodes = double(oct->stats().drag_nodes) / double(std::max<std::int64_t>(1, oct->stats().drag_queries));
      row.oct_bytes = taut::bench::heap_in_use() - heap0;
      if (row.n > ref_max) return;
      bool same = true;
      row.ref = seconds_of([&] { same = make_ref(); }, 1);
      row.checked = static_cast<int>(targets.size());
      if (!same) {
        all_ok = false;
        std::fprintf(stderr, "MISMATCH at n=%lld\n", static_cast<long long>(row.n));
      }
    };
    if (norm_order) {
      std::optional<taut::router::NormWavefront> w;
      measure(w, [&](auto& o) { o.emplace(dom, norm.obstacles, norm_order); }, [&] {
        const taut::oracle::NormReference oracle(dom, norm.obstacles, norm_order);
        const auto ref = oracle.distances(source, targets);
        for (std::size_t i = 0; i < targets.size(); ++i)
          if (ref[i] != w->target_distance(i)) return false;
        return true;
      });
    } else {
      std::optional<taut::router::OctWavefront> w;
      measure(w, [&](auto& o) { o.emplace(dom, norm.obstacles); }, [&] {
        const taut::oracle::OctilinearReference oracle(dom, norm.obstacles);
        const auto ref = oracle.distances(source, targets);
        for (std::size_t i = 0; i < targets.size(); ++i)
          if (ref[i] != w->target_distance(i)) return false;
        return true;
      });
    }
    char refbuf[32] = "-", ratiobuf[32] = "-";
    if (row.ref >= 0) {
      std::snprintf(refbuf, sizeof refbuf, "%.3f", row.ref);
      std::snprintf(ratiobuf, sizeof ratiobuf, "%.0fx", row.ref / row.oct);
    }
    std::printf("%9lld %8.4f | %8.3f %8.3f %7.2f | %9.2f %9.2f | %7.1f %8.1f | %7s %8s | %7d | %6.0f\n",
                static_cast<long long>(row.n), row.sort, row.l1, row.oct, row.oct / row.l1,
                double(row.l1_events) / double(row.n), double(row.oct_events) / double(row.n), row.l1_nodes,
                row.oct_nodes, refbuf, ratiobuf, row.checked, double(row.oct_bytes) / double(row.n));
    std::fflush(stdout);
    rows.push_back(row);
  }
  std::printf("\ncolumns: l1, oct = construction + the whole field; oct/l1 = their ratio in this run;\n"
              "ev/n = wavelets popped per vertex; nd/q = k-d tree nodes per segment-dragging query;\n"
              "ref = octilinear reference build + one Dijkstra; oct B/v = heap the octilinear wavefront holds / n.\n");
  std::printf("\ngrowth exponents log(t2/t1)/log(n2/n1):\n");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double ln = std::log(double(rows[i].n) / double(rows[i - 1].n));
    std::printf("  %lld -> %lld: oct %.2f, l1 %.2f, sort %.2f\n", static_cast<long long>(rows[i - 1].n),
                static_cast<long long>(rows[i].n), std::log(rows[i].oct / rows[i - 1].oct) / ln,
                std::log(rows[i].l1 / rows[i - 1].l1) / ln, std::log(rows[i].sort / rows[i - 1].sort) / ln);
  }
  if (!all_ok) {
    std::printf("\nDISTANCE MISMATCH against the reference (see stderr)\n");
    return 1;
  }
  return 0;
}
