// Benchmark of the L1 geodesic Voronoi diagram (router/voronoi.h, l1_voronoi): the time to turn
// a built shortest path map into exact polygons, against the number of obstacle vertices n and
// of sites k, on generated layouts. Baselines in the same run (machines are noisy; trust
// ratios): the map's own build (the diagram's ratio to it) and std::sort of the n vertices.
// Also the diagram's size: regions, rings, ring vertices, and the map pieces it merged.
//
// --shapes: the sites are 6 x 6 squares (pins; shape sources, router/spm.h) at the same random
// free points, those that keep off the blockages and each other; the baseline column is then the
// point-site map of the squares' lower-left corners, built in the same run.
//
//   bench_voronoi [--sizes N,N,..] [--sites K,K,..] [--kind rects|polygons|maze|degenerate] [--shapes]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "bench/free_points.h"
#include "router/spm.h"
#include "router/voronoi.h"

namespace {

using taut::bench::parse_list;
using taut::bench::seconds_of;
using taut::geom::Point;

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::int64_t> sizes = {1000, 10000, 100000}, site_counts = {10, 1000};
  std::string kind_name = "rects";
  bool shapes = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) sizes = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--sites") && i + 1 < argc) site_counts = parse_list(argv[++i]);
    else if (!std::strcmp(argv[i], "--kind") && i + 1 < argc) kind_name = argv[++i];
    else if (!std::strcmp(argv[i], "--shapes")) shapes = true;
    else {
      std::fprintf(stderr, "usage: %s [--sizes N,..] [--sites K,..] [--kind K] [--shapes]\n", argv[0]);
      return 2;
    }
  }
  const auto kind = taut::io::parse_gen_kind(kind_name);
  if (!kind) {
    std::fprintf(stderr, "unknown kind %s\n", kind_name.c_str());
    return 2;
  }
  std::printf("L1 geodesic Voronoi diagram, kind %s, %s sites; times are best of 1\n", kind_name.c_str(),
              shapes ? "6 x 6 square (shape)" : "point");
  std::printf("%9s %6s | %8s %9s %8s %8s | %8s %8s %8s %9s%s\n", "vertices", "sites", "map s", "voronoi s", "/map",
              "/sort", "pieces", "regions", "rings", "ring verts", shapes ? " | point map s  shape/point" : "");
  struct Sample {
    double logn, logt;
  };
  std::vector<Sample> growth;
  for (const std::int64_t size : sizes) {
    const auto lay = taut::bench::bench_layout(*kind, size);
    const auto n = static_cast<std::int64_t>(lay.points.size());
    const double sort_s = taut::bench::sort_seconds(lay.points);
    const auto& dom = lay.norm.domain;
    const std::vector<Point> free_pts = taut::bench::random_free_points(
        dom, lay.norm.obstacles, static_cast<std::size_t>(*std::max_element(site_counts.begin(), site_counts.end())), 7);
    for (const std::int64_t k : site_counts) {
      std::vector<Point> sites(free_pts.begin(), free_pts.begin() + k);
      std::vector<taut::geom::Polygon> squares;
      double point_build = 0;
      if (shapes) {
        std::vector<taut::geom::Polygon> wanted;
        for (const Point p : sites) wanted.push_back({{p, {p.x + 6, p.y}, {p.x + 6, p.y + 6}, {p.x, p.y + 6}}, {}});
        const auto why = taut::router::L1Map::shape_problems(dom, lay.norm.obstacles, wanted);
        sites.clear();
        for (std::size_t i = 0; i < wanted.size(); ++i)
          if (!why[i]) {
            squares.push_back(wanted[i]);
            sites.push_back(wanted[i].outer[0]);
          }
        std::optional<taut::router::L1Map> point_map;
        point_build = seconds_of([&] { point_map.emplace(dom, lay.norm.obstacles, sites); }, 1);
      }
      std::optional<taut::router::L1Map> map;
      const double build = seconds_of(
          [&] {
            if (shapes)
              map.emplace(dom, lay.norm.obstacles, std::vector<Point>{}, squares);
            else
              map.emplace(dom, lay.norm.obstacles, sites);
          },
          1);
      std::vector<taut::router::VoronoiRegion> regions;
      std::size_t pieces = 0;
      const double vor = seconds_of(
          [&] {
            if (shapes) {
              pieces = map->pieces(taut::router::L1Map::Detail::BySource).size();
              regions = taut::router::l1_voronoi(*map);  // (the pieces again, and the shapes)
              return;
            }
            const auto by_site = map->pieces(taut::router::L1Map::Detail::BySource);
            pieces = by_site.size();
            regions = taut::router::l1_voronoi(by_site);
          },
          1);
      std::size_t rings = 0, verts = 0;
      for (const auto& r : regions)
        for (const auto& p : r.polygons) {
          rings += 1 + p.holes.size();
          verts += p.outer.size();
          for (const auto& h : p.holes) verts += h.size();
        }
      std::printf("%9lld %6zu | %8.3f %9.3f %8.2f %8.0f | %8zu %8zu %8zu %9zu", static_cast<long long>(n),
                  sites.size(), build, vor, vor / build, vor / sort_s, pieces, regions.size(), rings, verts);
      if (shapes) std::printf(" | %12.3f %11.2f", point_build, build / point_build);
      std::printf("\n");
      std::fflush(stdout);
      if (k == site_counts.front()) growth.push_back({std::log(static_cast<double>(n)), std::log(vor)});
    }
  }
  if (growth.size() >= 2) {
    const auto& a = growth[growth.size() - 2];
    const auto& b = growth.back();
    std::printf("diagram time grows as n^%.2f between the two largest sizes (%lld sites: the first count)\n",
                (b.logt - a.logt) / (b.logn - a.logn), static_cast<long long>(site_counts.front()));
  }
  std::printf("columns: /map = diagram time / the map's build; /sort = diagram time / std::sort of the n vertices;\n"
              "pieces = the map's convex pieces by site that the diagram merges; rings and ring vertices of all regions\n");
  return 0;
}
