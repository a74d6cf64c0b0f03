// router::check_routes and router::FreeSpaceChecker (the independent checker of routed layouts,
// issue #7) against the brute-force L1 reference's own free-space rules
// (oracle::VisibilityGraph::check_path: wedges, pinches, walls flush with the domain side;
// tests/oracle/l1_oracle.h), on the degenerate layouts of the wavefront tests (rectangles
// touching at corners and along edges, flush with the domain side, diamonds, rings closed by
// pinches, holes touching their shells, coordinates near 2^30), with random polylines through
// obstacle vertices, pinch points, points on edges and points anywhere. Then connectivity and
// shorts on hand-made nets, each problem found once and named.
#include "router/check.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <set>
#include <string>

#include "oracle/l1_oracle.h"
#include "support/sanitized.h"
#include "support/wavefront_cases.h"

namespace taut::test {
namespace {

using geom::Point;

std::string str(std::span<const Point> ps) {
  std::string s;
  for (const Point p : ps) s += "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
  return s;
}

TEST(FreeSpaceChecker, AgreesWithTheReferenceOnRandomPolylines) {
  int failed = 0;
  long long polylines = 0, legal = 0, through_pinch = 0;
  const int seeds = kSanitized ? 150 : 1500;
  for (int seed = 1; seed <= seeds; ++seed) {
    const WavefrontCase c = make_wavefront_case(static_cast<std::uint64_t>(seed));
    geom::NormalizedObstacles norm;
    norm.domain = c.domain;
    norm.obstacles = c.obstacles;
    const router::FreeSpaceChecker checker(norm);
    const oracle::VisibilityGraph ref(c.domain, c.obstacles, oracle::Metric::L1);
    // Points of interest: obstacle vertices, edge midpoints rounded (often on the edge), the
    // case's candidates, domain corners.
    std::vector<Point> pts = c.candidates;
    for (const auto& poly : c.obstacles) {
      for (const auto* ring : {&poly.outer}) {
        for (std::size_t i = 0; i < ring->size(); ++i) {
          const Point a = (*ring)[i], b = (*ring)[(i + 1) % ring->size()];
          pts.push_back(a);
          pts.push_back({static_cast<geom::Coord>((std::int64_t{a.x} + b.x) / 2), static_cast<geom::Coord>((std::int64_t{a.y} + b.y) / 2)});
        }
      }
      for (const auto& h : poly.holes)
        for (const Point p : h) pts.push_back(p);
    }
    pts.push_back(c.domain.lo);
    pts.push_back(c.domain.hi);
    std::mt19937 rng(static_cast<unsigned>(seed));
    for (int q = 0; q < 60; ++q) {
      std::vector<Point> line;
      const int k = 2 + static_cast<int>(rng() % 3);
      for (int i = 0; i < k; ++i) {
        Point p = pts[rng() % pts.size()];
        // Every other polyline: axis-parallel moves from the previous point to the chosen one's x or y.
        if (q % 2 == 0 && !line.empty()) p = rng() % 2 ? Point{p.x, line.back().y} : Point{line.back().x, p.y};
        if (!line.empty() && line.back() == p) continue;
        line.push_back(p);
      }
      if (line.size() < 2) continue;
      ++polylines;
      const bool want = ref.check_path(line).has_value();
      const router::FreeSpaceChecker::Verdict got = checker.polyline(line);
      legal += want;
      for (std::size_t i = 1; i + 1 < line.size(); ++i) through_pinch += want && ref.wedges_at(line[i]).size() >= 2;
      if (got.free != want && failed++ < 10)
        ADD_FAILURE() << "seed " << seed << " (" << c.family << "): polyline " << str(line) << ": reference "
                      << (want ? "free" : "not free") << ", checker " << (got.free ? "free" : "not free: " + got.why);
    }
    for (const Point p : pts)
      if (checker.point_free(p) != ref.is_free(p) && failed++ < 10)
        ADD_FAILURE() << "seed " << seed << ": point " << p.x << "," << p.y << ": reference " << ref.is_free(p);
  }
  std::printf("%lld polylines on %d layouts, %lld free (%lld passing a pinch in one wedge)\n", polylines, seeds, legal,
              through_pinch);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(legal, polylines / 10);
  EXPECT_GE(polylines - legal, polylines / 10);
}

}  // namespace
}  // namespace taut::test

namespace taut::test {
namespace {

// Connectivity and shorts against a brute force on the unit lattice: rectilinear wires with
// integer vertices meet only at lattice points, so two wires touch iff they share a lattice
// point of their own, a point pin is reached iff it is one of a wire's lattice points, a
// rectangle pin iff a wire has a lattice point in it. Random nets on a 10 x 10 grid (no
// obstacles): which pins are cut off from the first, which wires touch no pin's group, which
// pairs of wires of different nets short, and which wires touch another net's pin.
TEST(CheckRoutes, ConnectivityAndShortsMatchALatticeBruteForce) {
  int failed = 0;
  long long disconnected = 0, stray = 0, shorts = 0, connected_nets = 0;
  for (int seed = 1; seed <= (kSanitized ? 300 : 3000); ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    auto coord = [&] { return static_cast<geom::Coord>(rng() % 10); };
    std::vector<router::CheckNet> nets(1 + rng() % 3);
    int line = 1;
    for (std::size_t n = 0; n < nets.size(); ++n) {
      nets[n].name = "n" + std::to_string(n);
      nets[n].routed = true;
      const int pins = 2 + static_cast<int>(rng() % 3);
      for (int p = 0; p < pins; ++p) {
        router::CheckPin pin;
        pin.name = "p" + std::to_string(p);
        pin.line = line++;
        if (rng() % 4 == 0) {
          const geom::Coord x = coord(), y = coord();
          const geom::Coord w = static_cast<geom::Coord>(1 + rng() % 2), h = static_cast<geom::Coord>(1 + rng() % 2);
          pin.shape = geom::Polygon{{{x, y}, {static_cast<geom::Coord>(x + w), y}, {static_cast<geom::Coord>(x + w), static_cast<geom::Coord>(y + h)}, {x, static_cast<geom::Coord>(y + h)}}, {}};
        } else {
          pin.point = Point{coord(), coord()};
        }
        nets[n].pins.push_back(pin);
      }
      const int wires = static_cast<int>(rng() % 5);
      for (int w = 0; w < wires; ++w) {
        router::CheckWire wire;
        wire.line = line++;
        Point p{coord(), coord()};
        if (rng() % 2 && !nets[n].pins.empty() && nets[n].pins[rng() % nets[n].pins.size()].point)
          p = *nets[n].pins[rng() % nets[n].pins.size()].point;
        wire.points.push_back(p);
        const int legs = 1 + static_cast<int>(rng() % 3);
        for (int k = 0; k < legs; ++k) {
          p = k % 2 == 0 ? Point{coord(), p.y} : Point{p.x, coord()};
          wire.points.push_back(p);
        }
        nets[n].wires.push_back(wire);
      }
    }
    // The lattice points of each wire, and the pins' cells.
    auto wire_points = [](const router::CheckWire& w) {
      std::set<std::pair<int, int>> s;
      for (std::size_t i = 0; i + 1 < w.points.size(); ++i) {
        const Point a = w.points[i], b = w.points[i + 1];
        for (int x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x)
          for (int y = std::min(a.y, b.y); y <= std::max(a.y, b.y); ++y) s.insert({x, y});
      }
      if (w.points.size() == 1) s.insert({w.points[0].x, w.points[0].y});
      return s;
    };
    auto pin_points = [](const router::CheckPin& p) {
      std::set<std::pair<int, int>> s;
      if (p.point) {
        s.insert({p.point->x, p.point->y});
      } else {
        const auto& r = p.shape->outer;
        for (int x = r[0].x; x <= r[2].x; ++x)
          for (int y = r[0].y; y <= r[2].y; ++y) s.insert({x, y});
      }
      return s;
    };
    auto meet = [](const std::set<std::pair<int, int>>& a, const std::set<std::pair<int, int>>& b) {
      for (const auto& p : a)
        if (b.count(p)) return true;
      return false;
    };
    std::multiset<std::string> want, got;
    for (std::size_t n = 0; n < nets.size(); ++n) {
      const auto& net = nets[n];
      const std::size_t W = net.wires.size(), N = W + net.pins.size();
      std::vector<std::set<std::pair<int, int>>> pts(N);
      for (std::size_t i = 0; i < W; ++i) pts[i] = wire_points(net.wires[i]);
      for (std::size_t i = 0; i < net.pins.size(); ++i) pts[W + i] = pin_points(net.pins[i]);
      // Groups by flood fill; two pins meet directly only when a point pin lies on the other
      // (two shapes need a wire between them, as in the product).
      std::vector<int> group(N, -1);
      for (std::size_t s = 0; s < N; ++s) {
        if (group[s] >= 0) continue;
        std::vector<std::size_t> stack{s};
        group[s] = static_cast<int>(s);
        while (!stack.empty()) {
          const std::size_t u = stack.back();
          stack.pop_back();
          for (std::size_t v = 0; v < N; ++v) {
            if (group[v] >= 0) continue;
            const bool pins = u >= W && v >= W;
            if (pins && net.pins[u - W].shape && net.pins[v - W].shape) continue;
            if (meet(pts[u], pts[v])) {
              group[v] = static_cast<int>(s);
              stack.push_back(v);
            }
          }
        }
      }
      bool all = true;
      for (std::size_t p = 1; p < net.pins.size(); ++p)
        if (group[W + p] != group[W]) {
          want.insert("disconnected " + net.name + " " + net.pins[p].name);
          all = false;
        }
      connected_nets += all;
      for (std::size_t w = 0; w < W; ++w) {
        bool has_pin = false;
        for (std::size_t p = 0; p < net.pins.size(); ++p) has_pin = has_pin || group[W + p] == group[w];
        if (!has_pin) want.insert("stray " + net.name + " " + std::to_string(net.wires[w].line));
      }
    }
    for (std::size_t n = 0; n < nets.size(); ++n)
      for (std::size_t m = 0; m < nets.size(); ++m) {
        if (m == n) continue;
        for (const auto& w : nets[n].wires) {
          const auto wp = wire_points(w);
          if (m > n)
            for (const auto& o : nets[m].wires)
              if (meet(wp, wire_points(o)))
                want.insert("short " + std::to_string(w.line) + " wire " + std::to_string(o.line));
          for (const auto& p : nets[m].pins)
            if (meet(wp, pin_points(p))) want.insert("short " + std::to_string(w.line) + " pin " + std::to_string(p.line));
        }
      }
    geom::NormalizedObstacles norm;
    norm.domain = {{-1, -1}, {12, 12}};
    const router::CheckResult r = router::check_routes(norm, nets);
    for (const auto& p : r.problems) {
      const auto& net = nets[p.net];
      switch (p.kind) {
        case router::CheckProblem::Kind::Disconnected: {
          std::string pin;
          for (const auto& q : net.pins)
            if (q.line == p.line) pin = q.name;
          got.insert("disconnected " + net.name + " " + pin);
          ++disconnected;
          break;
        }
        case router::CheckProblem::Kind::StrayWire:
          got.insert("stray " + net.name + " " + std::to_string(p.line));
          ++stray;
          break;
        case router::CheckProblem::Kind::Short: {
          // Which: the message names "line L" of the other's wire or pin.
          const auto& other = nets[*p.other_net];
          const std::size_t at = p.message.rfind("line ");
          const int other_line = std::stoi(p.message.substr(at + 5));
          bool pin = false;
          for (const auto& q : other.pins) pin = pin || q.line == other_line;
          got.insert("short " + std::to_string(p.line) + (pin ? " pin " : " wire ") + std::to_string(other_line));
          ++shorts;
          break;
        }
        case router::CheckProblem::Kind::NotFree:
          got.insert("not free " + net.name);
          break;
      }
    }
    if (want != got && failed++ < 8) {
      std::string w, g;
      for (const auto& s : want) w += "  " + s + "\n";
      for (const auto& s : got) g += "  " + s + "\n";
      ADD_FAILURE() << "seed " << seed << ": brute force\n" << w << "checker\n" << g;
    }
  }
  std::printf("%lld disconnected pins, %lld stray wires, %lld shorts, %lld nets connected\n", disconnected, stray, shorts,
              connected_nets);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(disconnected, 100);
  EXPECT_GE(stray, 100);
  EXPECT_GE(shorts, 100);
  EXPECT_GE(connected_nets, 100);
}

}  // namespace
}  // namespace taut::test
