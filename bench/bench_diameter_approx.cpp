// Approximate link diameter benchmark (issue #6; de Berg, seeds/002 section 4.2):
// router::approximate_link_diameter (MAXDIST: one sweep builds the horizontal decomposition, one
// pass over its tree) on generated channels (`taut gen channel`, seed 42) and on combs, against
// the polygon's vertex count n. Printed per size, with ratios to baselines measured in the same
// run (machines here are noisy): the estimate's time over sorting the ring's n y-coordinates
// once (`/sort`: the sweep sorts the edges, so this is its constant factor), and up to --exact-max
// vertices the exact divide and conquer (LinkVertexQueries: its build plus its diameter,
// `exact/`) with both answers; peak memory of the process after the estimate alone (measured
// before any exact run). The growth exponent between consecutive sizes is
// log(t2 / t1) / log(n2 / n1).
//
//   bench_diameter_approx [--sizes N,N,...] [--exact-max N] [--shape channel|comb]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "router/link_approx.h"
#include "router/link_polygon.h"
#include "router/link_reach.h"

namespace {

using taut::bench::seconds_of;

struct Row {
  std::size_t n = 0, cells = 0, pieces = 0;
  int estimate = 0, exact = -1;
  double approx = 0, sort = 0, exact_time = -1, rss_before = 0, rss = 0;
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes = {1000, 10000, 100000, 1000000};
  std::int64_t exact_max = 100000;
  std::string shape = "channel";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) {
      sizes.clear();
      for (char* tok = std::strtok(argv[++i], ","); tok; tok = std::strtok(nullptr, ",")) sizes.push_back(std::atoll(tok));
    } else if (!std::strcmp(argv[i], "--exact-max") && i + 1 < argc) {
      exact_max = std::atoll(argv[++i]);
    } else if (!std::strcmp(argv[i], "--shape") && i + 1 < argc) {
      shape = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--sizes N,N,...] [--exact-max N] [--shape channel|comb]\n", argv[0]);
      return 2;
    }
  }
  if (shape != "channel" && shape != "comb") {
    std::fprintf(stderr, "unknown shape %s\n", shape.c_str());
    return 2;
  }
  std::printf("taut approximate link diameter benchmark (de Berg's MAXDIST, within 3): %s, one thread\n",
              shape == "comb" ? "combs" : "generated channels (seed 42)");
  std::printf("%9s %9s %7s | %9s %8s %8s | %9s %9s %8s | %8s\n", "n", "cells", "pieces", "approx(s)", "/sort", "estimate", "exact(s)",
              "exact/", "diameter", "peak rss (MiB)");
  std::vector<Row> rows;
  for (const std::int64_t size : sizes) {
    taut::geom::Ring ring;
    if (shape == "comb") {
      ring = taut::router::clean_ring(taut::bench::comb(size));
    } else {
      taut::io::GenOptions go;
      go.kind = taut::io::GenKind::Channel;
      go.size = size;
      go.nets = 0;
      go.seed = 42;
      const taut::io::Layout layout = taut::io::generate_layout(go);
      const auto f = taut::router::free_space_polygon(layout.boundary->box, taut::io::blockage_polygons(layout));
      if (f.status != taut::router::FreeSpacePolygon::Status::Ok) {
        std::fprintf(stderr, "size %lld: free space is not a simple polygon\n", static_cast<long long>(size));
        return 1;
      }
      ring = f.ring;
    }
    Row row;
    row.n = ring.size();
    taut::router::LinkDiameterEstimate e;
    row.rss_before = taut::bench::peak_rss_mib();
    row.approx = seconds_of([&] { e = taut::router::approximate_link_diameter(ring); }, 3);
    row.rss = taut::bench::peak_rss_mib();
    row.estimate = e.estimate;
    row.cells = e.cells;
    row.pieces = e.pieces;
    row.sort = seconds_of(
        [&] {
          std::vector<std::int64_t> ys;
          ys.reserve(ring.size());
          for (const auto p : ring) ys.push_back(p.y);
          std::sort(ys.begin(), ys.end());
          taut::bench::keep(ys.front());
        },
        3);
    if (static_cast<std::int64_t>(row.n) <= exact_max) {
      row.exact_time = seconds_of([&] { row.exact = taut::router::LinkVertexQueries(ring).diameter().links; }, 1);
    }
    std::printf("%9zu %9zu %7.2f | %9.4f %8.1f %8d | ", row.n, row.cells, static_cast<double>(row.pieces) / static_cast<double>(row.cells), row.approx, row.approx / row.sort, row.estimate);
    if (row.exact >= 0)
      std::printf("%9.3f %9.0f %8d%s", row.exact_time, row.exact_time / row.approx, row.exact,
                  std::abs(row.exact - row.estimate) > 3 ? " MORE THAN 3 OFF" : "");
    else
      std::printf("%9s %9s %8s", "-", "-", "-");
    std::printf(" | %6.0f -> %.0f\n", row.rss_before, row.rss);
    if (row.exact >= 0 && std::abs(row.exact - row.estimate) > 3) return 1;
    rows.push_back(row);
  }
  std::printf("(pieces: M computed per cell, on average (the tooth's term asks each side for its whole chord too); /sort: "
              "the estimate's time over sorting n integers; exact/: LinkVertexQueries' build and diameter over the "
              "estimate's time; peak rss: the process's, before and after the estimate, after generating and normalizing the layout and "
              "the smaller sizes' exact runs)\n");
  std::printf("\ngrowth exponents between consecutive sizes (1.0 = linear):\n%9s -> %9s | %8s %8s\n", "n1", "n2", "approx",
              "exact");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const Row &a = rows[i - 1], &b = rows[i];
    const double dn = std::log(static_cast<double>(b.n) / static_cast<double>(a.n));
    std::printf("%9zu -> %9zu | %8.2f ", a.n, b.n, std::log(b.approx / a.approx) / dn);
    if (a.exact >= 0 && b.exact >= 0) std::printf("%8.2f\n", std::log(b.exact_time / a.exact_time) / dn);
    else std::printf("%8s\n", "-");
  }
  return 0;
}
