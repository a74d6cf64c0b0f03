// Link diameter benchmark (issue #6; de Berg, seeds/002): router::LinkPolygon::diameter() on
// generated channels (`taut gen channel`, seed 42: teeth cutting into the boundary, so free space
// is one simple rectilinear polygon) against the polygon's vertex count n. Printed per size: the
// polygon (vertices, convex vertices), the router graph's build time, the diameter and its time,
// how many single-source searches the eccentricity bounds needed, and ratios to baselines
// measured in the same run (machines here are noisy): the diameter's time over one link-metric
// path query between the two ends it found (`/query`), and the time of the plain method that
// searches from every convex vertex over the diameter's (`all/`, up to --all-max vertices; its
// answer is compared). Up to --ref-max vertices the exhaustive reference
// (tests/oracle/link_polygon_oracle.h: every pair of Hanan grid points) is timed too (`ref/`)
// and its answer compared. The growth exponent between consecutive sizes is
// log(t2 / t1) / log(n2 / n1).
//
// Also the cut tree of the rectilinear polygon cutting theorem (router/link_cut.h, section 2: the
// divide and conquer under the paper's query structure and exact diameter), its build time as a
// ratio to the router graph's and its depth against log_{4/3} n.
//
// --shape comb measures the worst case instead: a comb whose tooth tips are all 3 links apart,
// where the bounds prune nothing and every tip is searched from.
//
//   bench_diameter [--sizes N,N,...] [--all-max N] [--ref-max N] [--seed S] [--shape channel|comb]
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "io/generate.h"
#include "oracle/link_polygon_oracle.h"
#include "router/bend_router.h"
#include "router/link_cut.h"
#include "router/link_polygon.h"
#include "router/link_reach.h"

namespace {

using taut::bench::seconds_of;
using taut::geom::Point;

struct Row {
  std::size_t n = 0, convex = 0, searches = 0;
  int links = 0;
  double build = 0, diameter = 0, query = 0, all = -1, ref = -1, cuts = 0;
  // de Berg's structure (router/link_reach.h): its build, its diameter, one vertex-pair query
  double qbuild = 0, qdiameter = 0, qlinks = 0, hybrid = 0, pbuild = 0, plinks = 0, pdescent = 0, pgraph = 0, ppath = 0, pgraph_path = 0, plinks_per_path = 0;
  bool hybrid_cut_tree = false;
  std::size_t records = 0;
  bool q_agree = true;
  int depth = 0;
  std::size_t tree_nodes = 0;
  bool all_agree = true, ref_agree = true;
  std::size_t edges = 0;
};

// The plain method: one search from every convex vertex to the convex vertices after it (on the
// same built graph as the diameter, so neither time includes the build).
int all_pairs(const taut::router::LinkPolygon& poly) {
  const std::vector<Point> convex = poly.convex_corners();
  int best = 0;
  for (std::size_t i = 0; i + 1 < convex.size(); ++i) {
    const std::span<const Point> rest(convex.data() + i + 1, convex.size() - i - 1);
    for (const int d : poly.distances(convex[i], rest)) best = std::max(best, d);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes = {100, 1000, 10000, 100000};
  std::int64_t all_max = 300, ref_max = 60;
  std::uint64_t seed = 42;
  std::string shape = "channel";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = taut::bench::parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--all-max") && i + 1 < argc) all_max = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--ref-max") && i + 1 < argc) ref_max = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (!std::strcmp(argv[i], "--shape") && i + 1 < argc) shape = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--sizes N,N,...] [--all-max N] [--ref-max N] [--seed S] [--shape channel|comb]\n", argv[0]);
      return 2;
    }
  }
  if (shape != "channel" && shape != "comb") {
    std::fprintf(stderr, "unknown shape %s\n", shape.c_str());
    return 2;
  }
  if (shape == "channel")
    std::printf("taut link diameter benchmark: generated channels (seed %llu), one thread\n",
                static_cast<unsigned long long>(seed));
  else
    std::printf("taut link diameter benchmark: combs (every tooth tip 3 links from every other), one thread\n");
  std::printf("%8s %7s %10s | %8s %9s %9s %8s | %8s %9s %9s\n", "n", "convex", "graph-edg", "build(s)", "diam(s)",
              "diameter", "searches", "/query", "all/", "ref/");
  std::vector<Row> rows;
  for (const std::int64_t size : sizes) {
    taut::router::FreeSpacePolygon f;
    if (shape == "comb") {
      f.status = taut::router::FreeSpacePolygon::Status::Ok;
      f.ring = taut::bench::comb(size);
    } else {
      taut::io::GenOptions go;
      go.kind = taut::io::GenKind::Channel;
      go.size = size;
      go.nets = 0;
      go.seed = seed;
      const taut::io::Layout layout = taut::io::generate_layout(go);
      f = taut::router::free_space_polygon(layout.boundary->box, taut::io::blockage_polygons(layout));
    }
    if (f.status != taut::router::FreeSpacePolygon::Status::Ok) {
      std::fprintf(stderr, "size %lld: free space is not a simple polygon\n", static_cast<long long>(size));
      return 1;
    }
    Row row;
    row.n = f.ring.size();
    std::unique_ptr<taut::router::LinkPolygon> poly;
    row.build = seconds_of([&] { poly = std::make_unique<taut::router::LinkPolygon>(f.ring); }, 1);
    const auto& st = poly->graph_stats();
    row.edges = st.straight_edges + st.l_edges;
    taut::router::LinkDiameter d;
    row.diameter = seconds_of([&] { d = poly->diameter(SIZE_MAX); }, 1);  // the bounds alone
    row.links = d.links;
    row.convex = d.convex_vertices;
    row.searches = d.searches;
    row.query = seconds_of([&] { (void)poly->path(d.from, d.to); }, 3);
    // the rectilinear cutting theorem's tree (router/link_cut.h), on the polygon's cleaned ring
    std::unique_ptr<taut::router::CutTree> tree;
    row.cuts = seconds_of([&] { tree = std::make_unique<taut::router::CutTree>(poly->ring()); }, 1);
    row.depth = tree->depth();
    row.tree_nodes = tree->nodes().size();
    std::unique_ptr<taut::router::LinkVertexQueries> vq;
    row.qbuild = seconds_of([&] { vq = std::make_unique<taut::router::LinkVertexQueries>(poly->ring()); }, 1);
    taut::router::LinkVertexQueries::Diameter qd;
    row.qdiameter = seconds_of([&] { qd = vq->diameter(); }, 1);
    row.q_agree = qd.links == d.links;
    row.records = vq->records();
    {  // section 3.2: any two points (lattice points of the box, inside), against the graph's distance
      std::unique_ptr<taut::router::LinkPointQueries> pq;
      row.pbuild = seconds_of([&] { pq = std::make_unique<taut::router::LinkPointQueries>(poly->ring()); }, 1);
      const auto& r = poly->ring();
      taut::geom::Coord x0 = r[0].x, x1 = x0, y0 = r[0].y, y1 = y0;
      for (const Point p : r) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
      std::vector<Point> pts;
      for (std::uint64_t i = 1; pts.size() < 2000; ++i) {
        const Point p{static_cast<taut::geom::Coord>(x0 + static_cast<taut::geom::Coord>(i * 7919 % static_cast<std::uint64_t>(x1 - x0 + 1))),
                      static_cast<taut::geom::Coord>(y0 + static_cast<taut::geom::Coord>(i * 104729 % static_cast<std::uint64_t>(y1 - y0 + 1)))};
        if (poly->contains(p)) pts.push_back(p);
      }
      long long sink = 0;
      row.plinks = seconds_of([&] {
                     for (std::size_t i = 0; i + 1 < pts.size(); i += 2) sink += *pq->links(pts[i], pts[i + 1]);
                   }, 1) / static_cast<double>(pts.size() / 2);
      row.pdescent = seconds_of([&] {
                       for (std::size_t i = 0; i + 1 < pts.size(); i += 2) sink -= *pq->links_by_descent(pts[i], pts[i + 1]);
                     }, 1) / static_cast<double>(pts.size() / 2);
      row.pgraph = seconds_of([&] {
                     for (std::size_t i = 0; i + 1 < pts.size(); i += 20) sink -= *poly->distance(pts[i], pts[i + 1]);
                   }, 1) / static_cast<double>(pts.size() / 20);
      // section 3.3: the paths, against the graph's path query (links and L1 length equal)
      long long path_links = 0;
      row.ppath = seconds_of([&] {
                    for (std::size_t i = 0; i + 1 < pts.size(); i += 2) path_links += static_cast<long long>(pq->path(pts[i], pts[i + 1])->size()) - 1;
                  }, 1) / static_cast<double>(pts.size() / 2);
      row.plinks_per_path = static_cast<double>(path_links) / static_cast<double>(pts.size() / 2);
      row.pgraph_path = seconds_of([&] {
                          for (std::size_t i = 0; i + 1 < pts.size(); i += 20) sink += poly->path(pts[i], pts[i + 1])->links;
                        }, 1) / static_cast<double>(pts.size() / 20);
      for (std::size_t i = 0; i + 1 < pts.size(); i += 20) {
        const auto g = poly->path(pts[i], pts[i + 1]);
        const auto p = pq->path(pts[i], pts[i + 1]);
        std::int64_t length = 0;
        for (std::size_t k = 0; k + 1 < p->size(); ++k)
          length += std::abs(std::int64_t{(*p)[k + 1].x} - (*p)[k].x) + std::abs(std::int64_t{(*p)[k + 1].y} - (*p)[k].y);
        row.q_agree = row.q_agree && static_cast<int>(p->size()) - 1 == g->links && length == g->length;
      }
      for (std::size_t i = 0; i + 1 < pts.size(); i += 20) row.q_agree = row.q_agree && pq->links(pts[i], pts[i + 1]) == poly->distance(pts[i], pts[i + 1]);
      for (std::size_t i = 0; i + 1 < pts.size(); i += 2) row.q_agree = row.q_agree && pq->links(pts[i], pts[i + 1]) == pq->links_by_descent(pts[i], pts[i + 1]);
      taut::bench::keep(sink);
    }
    {
      taut::router::LinkDiameter h;
      row.hybrid = seconds_of([&] { h = poly->diameter(); }, 1);
      row.hybrid_cut_tree = h.cut_tree;
      row.q_agree = row.q_agree && h.links == d.links;
    }
    {
      const std::size_t m = poly->ring().size();
      long long sink = 0;
      const int reps = 100000;
      row.qlinks = seconds_of([&] {
                     for (int r = 0; r < reps; ++r) sink += vq->links(static_cast<std::size_t>(r) * 7919 % m, static_cast<std::size_t>(r) * 104729 % m);
                   }, 1) / reps;
      taut::bench::keep(sink);
    }
    if (static_cast<std::int64_t>(row.n) <= all_max) {
      int all = 0;
      row.all = seconds_of([&] { all = all_pairs(*poly); }, 1);
      row.all_agree = all == d.links;
    }
    if (static_cast<std::int64_t>(row.n) <= ref_max) {
      int ref = 0;
      row.ref = seconds_of([&] { ref = taut::oracle::LinkPolygonReference(f.ring).diameter().links; }, 1);
      row.ref_agree = ref == d.links;
    }
    std::printf("%8zu %7zu %10zu | %8.3f %9.4f %9d %8zu | %8.1f ", row.n, row.convex, row.edges, row.build,
                row.diameter, row.links, row.searches, row.diameter / row.query);
    if (row.all >= 0) std::printf("%9.1f%s ", row.all / row.diameter, row.all_agree ? "" : "!");
    else std::printf("%9s ", "-");
    if (row.ref >= 0) std::printf("%9.1f%s", row.ref / row.diameter, row.ref_agree ? "" : "!");
    else std::printf("%9s", "-");
    std::printf("\n");
    std::printf("%8s cut tree (section 2): %.3f s (%.2f x the graph's build), %zu nodes, depth %d (log_4/3 n = %.1f)\n", "",
                row.cuts, row.cuts / row.build, row.tree_nodes, row.depth, std::log(static_cast<double>(row.n)) / std::log(4.0 / 3.0));
    std::printf("%8s de Berg's structure (sections 3.1, 4.1): build %.3f s (%.2f x the graph's), %zu records (%.1f per vertex); "
                "diameter %.4f s%s (bounds / this: %.1f; with the builds: %.2f); a vertex pair %.2f us (graph query / this: %.0f); "
                "taut diameter's default (the bounds, the cut tree after 32 searches): %.4f s by the %s\n",
                "", row.qbuild, row.qbuild / row.build, row.records, static_cast<double>(row.records) / static_cast<double>(row.n),
                row.qdiameter, row.q_agree ? "" : " MISMATCH", row.diameter / row.qdiameter,
                (row.build + row.diameter) / (row.qbuild + row.qdiameter), row.qlinks * 1e6, row.query / row.qlinks, row.hybrid,
                row.hybrid_cut_tree ? "cut tree" : "bounds");
    std::printf("%8s any two points (section 3.2): build %.3f s (%.2f x the graph's); a query %.2f us (graph distance query / this: %.0f; "
                "walking down the tree / this: %.1f); a path (section 3.3, %.1f links) %.2f us (graph path query / this: %.0f)\n",
                "", row.pbuild, row.pbuild / row.build, row.plinks * 1e6, row.pgraph / row.plinks, row.pdescent / row.plinks,
                row.plinks_per_path, row.ppath * 1e6, row.pgraph_path / row.ppath);
    std::fflush(stdout);
    if (!row.all_agree || !row.ref_agree || !row.q_agree) {
      std::fprintf(stderr, "MISMATCH at n = %zu\n", row.n);
      return 1;
    }
    rows.push_back(row);
  }
  std::printf("(/query: the diameter's time over one link path query between its ends; all/: the plain method's "
              "time (a search from every convex vertex) over the diameter's; ref/: the exhaustive reference's time over "
              "the diameter's; all answers equal)\n");
  std::printf("\ngrowth exponents between consecutive sizes (1.0 = linear):\n");
  std::printf("%8s -> %8s | %8s %8s %8s %8s %8s %8s %8s\n", "n1", "n2", "edges", "build", "diameter", "searches", "cut-tree",
              "q-build", "q-diam");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const Row& a = rows[i - 1];
    const Row& b = rows[i];
    const double dn = std::log(static_cast<double>(b.n) / static_cast<double>(a.n));
    std::printf("%8zu -> %8zu | %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f\n", a.n, b.n,
                std::log(static_cast<double>(b.edges) / static_cast<double>(a.edges)) / dn,
                std::log(b.build / a.build) / dn, std::log(b.diameter / a.diameter) / dn,
                std::log(static_cast<double>(b.searches) / static_cast<double>(a.searches)) / dn, std::log(b.cuts / a.cuts) / dn,
                std::log(b.qbuild / a.qbuild) / dn, std::log(b.qdiameter / a.qdiameter) / dn);
  }
  return 0;
}
