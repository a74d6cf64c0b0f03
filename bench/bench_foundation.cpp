// Scaling benchmark of the foundation pipeline: generate -> write XML -> read -> validate ->
// normalize (union) -> triangulate, for generated layouts of 10^4 .. 10^6 blockage vertices.
//
// Machines here are noisy, so every time is also printed as a ratio to a baseline measured in
// the same run on the same data: `sort` = std::sort of the layout's vertices by (x, y), an
// n log n unit of this machine's speed. The growth exponent between consecutive sizes is
// log(t2 / t1) / log(n2 / n1) (1.0 is linear; n log n shows as slightly above 1).
//
//   bench_foundation [--max N] [--kind rects|polygons|maze|degenerate] [--reps R]
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
#include "geom/triangulation.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "io/layout_reader.h"
#include "io/layout_writer.h"
#include "io/validate_layout.h"
#include "bench/bench_util.h"

namespace {

using taut::bench::peak_rss_mib;
using taut::bench::seconds_of;

struct Row {
  std::int64_t n = 0;
  double sort = 0, read = 0, validate = 0, normalize = 0, triangulate = 0;
  std::size_t obstacles = 0, triangles = 0;
  double rss = 0;
  double total() const { return read + validate + normalize + triangulate; }
};

}  // namespace

int main(int argc, char** argv) {
  std::int64_t max_n = 1'000'000;
  int reps = 1;
  std::string kind_name = "rects";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--max") && i + 1 < argc) max_n = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) kind_name = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--max N] [--kind K] [--reps R]\n", argv[0]);
      return 2;
    }
  }
  const auto kind = taut::io::parse_gen_kind(kind_name);
  if (!kind) {
    std::fprintf(stderr, "unknown kind %s\n", kind_name.c_str());
    return 2;
  }
  std::printf("taut foundation benchmark: kind=%s, one thread, best of %d\n", kind_name.c_str(), reps);
  std::printf("%9s %9s | %8s %8s %8s %8s %8s | %6s %6s %6s %6s | %9s %10s %8s\n", "vertices",
              "sort(s)", "read(s)", "valid(s)", "union(s)", "tri(s)", "total(s)", "read/s",
              "val/s", "uni/s", "tri/s", "obstacles", "triangles", "rss(MiB)");
  std::vector<Row> rows;
  for (std::int64_t n = 10'000; n <= max_n; n *= 10) {
    Row row;
    taut::io::GenOptions go;
    go.kind = *kind;
    go.size = n;
    go.nets = 0;
    go.seed = 42;
    const taut::io::Layout generated = taut::io::generate_layout(go);
    const std::string xml = taut::io::layout_to_xml(generated);
    row.n = static_cast<std::int64_t>(taut::io::blockage_vertex_count(generated));

    std::vector<taut::geom::Point> pts;
    for (const auto& p : taut::io::blockage_polygons(generated)) pts.insert(pts.end(), p.outer.begin(), p.outer.end());
    row.sort = seconds_of([&] { auto v = pts; std::sort(v.begin(), v.end()); }, reps);

    taut::io::ReadResult rr;
    row.read = seconds_of([&] { rr = taut::io::parse_layout(xml, "generated.xml"); }, reps);
    if (!rr.layout) {
      std::fprintf(stderr, "generated layout did not read back\n");
      return 1;
    }
    row.validate = seconds_of([&] { (void)taut::io::validate_layout(*rr.layout); }, reps);
    const auto polys = taut::io::blockage_polygons(*rr.layout);
    std::optional<taut::geom::Box> boundary;
    if (rr.layout->boundary) boundary = rr.layout->boundary->box;
    taut::geom::NormalizedObstacles norm;
    row.normalize = seconds_of([&] { norm = taut::geom::normalize_obstacles(polys, boundary); }, reps);
    row.obstacles = norm.obstacles.size();
    taut::geom::FreeSpaceTriangulation tri;
    row.triangulate = seconds_of([&] { tri = taut::geom::triangulate_free_space(norm.domain, norm.obstacles); }, reps);
    if (!tri.ok()) {
      std::fprintf(stderr, "triangulation failed at n=%lld\n", static_cast<long long>(row.n));
      return 1;
    }
    row.triangles = tri.triangles().size();
    row.rss = peak_rss_mib();
    std::printf("%9lld %9.4f | %8.3f %8.3f %8.3f %8.3f %8.3f | %6.1f %6.1f %6.1f %6.1f | %9zu %10zu %8.0f\n",
                static_cast<long long>(row.n), row.sort, row.read, row.validate, row.normalize,
                row.triangulate, row.total(), row.read / row.sort, row.validate / row.sort,
                row.normalize / row.sort, row.triangulate / row.sort, row.obstacles, row.triangles,
                row.rss);
    std::fflush(stdout);
    rows.push_back(row);
  }
  std::printf("\ngrowth exponents log(t2/t1)/log(n2/n1):\n");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double ln = std::log(double(rows[i].n) / double(rows[i - 1].n));
    auto ex = [&](double a, double b) { return std::log(b / a) / ln; };
    std::printf("  %lld -> %lld: read %.2f, validate %.2f, union %.2f, triangulate %.2f, total %.2f (sort %.2f)\n",
                static_cast<long long>(rows[i - 1].n), static_cast<long long>(rows[i].n),
                ex(rows[i - 1].read, rows[i].read), ex(rows[i - 1].validate, rows[i].validate),
                ex(rows[i - 1].normalize, rows[i].normalize),
                ex(rows[i - 1].triangulate, rows[i].triangulate), ex(rows[i - 1].total(), rows[i].total()),
                ex(rows[i - 1].sort, rows[i].sort));
  }
  if (!rows.empty() && rows.back().n >= 900'000)
    std::printf("\ntarget: 10^6 vertices read + normalized + triangulated in < 20 s: %s (%.2f s)\n",
                rows.back().read + rows.back().normalize + rows.back().triangulate < 20 ? "met" : "MISSED",
                rows.back().read + rows.back().normalize + rows.back().triangulate);
  return 0;
}
