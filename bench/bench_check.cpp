// The independent checker's cost (issue #7; router/check.h): router::check_routes on generated
// layouts (`taut gen rects`, seed 42) with M two-pin nets, local as placed nets are: each net's
// second pin is moved to within a few cells of its first (a cell: the layout's side over
// sqrt(M)), and given a three-segment wire from pin to pin (a vertical, a horizontal and a
// vertical run: not routed, so it crosses blockages and neighbouring nets, and every check has
// work to do), with <rules> w = 20, s = 20. (Nets spanning the layout cross each other
// Theta(M^2) times, and any checker reports that many problems.) Printed per
// size: blockage vertices, nets, wire segments, problems found, the check's time and its ratio
// to the blockage union's (geom::normalize_obstacles, which every command runs first) measured
// in the same run, and the growth exponent log(t2 / t1) / log(n2 / n1) over the wire segments.
//
//   bench_check [--sizes V:M,V:M,...]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_util.h"
#include "geom/normalize.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "router/check.h"

int main(int argc, char** argv) {
  std::vector<std::pair<std::int64_t, int>> sizes = {{1000, 100}, {10000, 1000}, {100000, 10000}};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc) {
      sizes.clear();
      for (char* tok = std::strtok(argv[++i], ","); tok; tok = std::strtok(nullptr, ",")) {
        long long v = 0;
        int m = 0;
        if (std::sscanf(tok, "%lld:%d", &v, &m) == 2) sizes.emplace_back(v, m);
      }
    } else {
      std::fprintf(stderr, "usage: %s [--sizes V:M,V:M,...]\n", argv[0]);
      return 2;
    }
  }
  std::printf("taut checker benchmark: generated rects layouts (seed 42), unrouted three-segment wires, w = s = 20, one thread\n");
  std::printf("%9s %7s %9s %9s | %9s %9s %9s\n", "vertices", "nets", "segments", "problems", "check(s)", "union(s)", "/union");
  struct Row {
    double segments, check;
  };
  std::vector<Row> rows;
  for (const auto& [size, nets] : sizes) {
    taut::io::GenOptions go;
    go.kind = taut::io::GenKind::Rects;
    go.size = size;
    go.nets = nets;
    go.seed = 42;
    const taut::io::Layout layout = taut::io::generate_layout(go);
    const auto polys = taut::io::blockage_polygons(layout);
    const std::optional<taut::geom::Box> boundary =
        layout.boundary ? std::optional<taut::geom::Box>(layout.boundary->box) : std::nullopt;
    taut::geom::NormalizedObstacles norm;
    const double union_s = taut::bench::seconds_of([&] { norm = taut::geom::normalize_obstacles(polys, boundary); }, 1);
    const taut::geom::Box box = norm.domain;
    const std::int64_t cell =
        std::max<std::int64_t>(1, (std::int64_t{box.hi.x} - box.lo.x) / std::max<std::int64_t>(1, static_cast<std::int64_t>(std::sqrt(nets))));
    std::vector<taut::router::CheckNet> cn;
    std::size_t segments = 0;
    for (const taut::io::Net& n : layout.nets) {
      taut::router::CheckNet c;
      c.name = n.name;
      c.routed = true;
      for (const taut::io::Pin& p : n.pins) c.pins.push_back({p.name, p.point, std::nullopt, p.line});
      if (c.pins.size() >= 2 && c.pins[0].point && c.pins[1].point) {
        const taut::geom::Point a = *c.pins[0].point, far = *c.pins[1].point;
        // the second pin pulled to within 2 cells of the first, the same way
        auto pull = [&](taut::geom::Coord from, taut::geom::Coord to, taut::geom::Coord lo, taut::geom::Coord hi) {
          const std::int64_t d = std::int64_t{to} - from, m = 2 * cell;
          const std::int64_t v = from + (d % (m + 1));
          return static_cast<taut::geom::Coord>(std::clamp<std::int64_t>(v, lo, hi));
        };
        const taut::geom::Point b{pull(a.x, far.x, box.lo.x, box.hi.x), pull(a.y, far.y, box.lo.y, box.hi.y)};
        c.pins[1].point = b;
        const taut::geom::Coord ym = static_cast<taut::geom::Coord>((std::int64_t{a.y} + b.y) / 2);
        c.wires.push_back({{a, {a.x, ym}, {b.x, ym}, b}, 0});
        segments += 3;
      }
      cn.push_back(std::move(c));
    }
    taut::router::CheckRules rules;
    rules.wire_width = 20;
    rules.spacing = 20;
    taut::router::CheckResult r;
    const double check_s = taut::bench::seconds_of([&] { r = taut::router::check_routes(norm, cn, rules); }, 1);
    std::printf("%9lld %7d %9zu %9zu | %9.3f %9.3f %9.2f\n", static_cast<long long>(size), nets, segments, r.problems.size(), check_s,
                union_s, check_s / union_s);
    rows.push_back({static_cast<double>(segments), check_s});
  }
  std::printf("\ngrowth exponents of the check over the wire segments (1.0 = linear):\n");
  for (std::size_t i = 1; i < rows.size(); ++i)
    std::printf("  %.0f -> %.0f segments: %.2f\n", rows[i - 1].segments, rows[i].segments,
                std::log(rows[i].check / rows[i - 1].check) / std::log(rows[i].segments / rows[i - 1].segments));
  return 0;
}
