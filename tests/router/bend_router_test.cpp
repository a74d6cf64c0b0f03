// router::BendRouter (router/bend_router.h: a modified visibility graph of obstacle vertices,
// tracks and L edges, Dijkstra) against the brute-force reference oracle::BendReference
// (tests/oracle/bend_oracle.h: Dijkstra on the Hanan grid x arriving direction, free space from
// the L1 reference), which shares nothing with the router but geom/predicates.h and the
// normalized input; the reference itself is checked against a lattice search on rasterized
// rectangles in tests/oracle/bend_oracle_test.cpp.
//
// Seeded random instances: small rectilinear layouts on a 0..12 grid (rectangles that overlap,
// share edges, touch at corners = pinches, stick out of the domain or lie flush with its sides;
// frames with a hole and things inside it, C-shaped frames; random rectilinear "histogram"
// polygons; mazes of many small blocks; parallel walls with gaps on a 0..16 grid, where the
// shortest path zigzags and fewer bends cost length), turned by 90 degrees or not, scaled by
// 1..100 (so that the bend costs C in {0, 1, 7, 1000} trade against lengths of every size) and
// moved off the origin, normalized with geom::normalize_obstacles. Each instance gets query pairs
// drawn from random lattice points, points between them, obstacle vertices, pinch vertices,
// points inside obstacle edges and points outside the domain, and each pair is asked in the
// combined metric with C = 0, 1, 7, 1000 and in the link metric. Every answer is checked:
//   - the status: SourceNotFree / TargetNotFree exactly when the reference says the end is not
//     free, Unreachable exactly when the reference finds no path, else Ok;
//   - length and bends equal the reference's optimum exactly (the optimum (length, bends) is
//     unique in either metric: see bend_oracle.h), and cost() is what they give;
//   - the points are integer, start at `from` and end at `to`, every segment horizontal or
//     vertical, and the reference's check_path accepts them as a legal path (free space, no
//     slipping through pinches, no reversal) with exactly the reported length and bends.
// Also: crops of Moving AI maps (cells that touch and pinch everywhere), and rectilinear_cover()
// on random triangles (its normalized union is rectilinear and contains every triangle, and the
// router accepts it and agrees with the reference on it).
//
// Measured: 2,400 instances, ~48,000 queries (~31,000 found, ~420 pairs whose answer depends on
// the metric) in ~3.5 s in the Release tree; a twenty-fourth of them in the sanitizer tree.
//
// A failure prints the seed, the instance as C++ initializers, the query and both answers.
// TAUT_BEND_SEED=N runs only seed N. Seeds that ever failed stay in kRegressionSeeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "io/movingai.h"
#include "oracle/bend_oracle.h"
#include "oracle/union_oracle.h"
#include "router/bend_router.h"
#include "router/l1_router.h"
#include "support/random_shapes.h"
#include "support/run.h"
#include "support/sanitized.h"

namespace taut::test {
namespace bend_router_test {

using geom::Box;
using geom::Point;
using geom::Polygon;
using geom::Ring;
using oracle::BendAnswer;
using oracle::BendReference;
using router::BendMetric;
using router::BendPath;
using router::BendRouter;
using router::WireStatus;
using i64 = std::int64_t;

constexpr std::uint64_t kBaseSeed = 910000;
// Seeds that once failed (replayed first, every run; none yet).
constexpr std::initializer_list<std::uint64_t> kRegressionSeeds = {};

std::string str(Point p) { return "{" + std::to_string(p.x) + ", " + std::to_string(p.y) + "}"; }
std::string str(const std::optional<BendAnswer>& a) {
  if (!a) return "none";
  return "{length " + std::to_string(a->length) + ", bends " + std::to_string(a->bends) + "}";
}
std::string str(WireStatus s) {
  switch (s) {
    case WireStatus::Ok: return "Ok";
    case WireStatus::SourceNotFree: return "SourceNotFree";
    case WireStatus::TargetNotFree: return "TargetNotFree";
    case WireStatus::Unreachable: return "Unreachable";
    case WireStatus::NoIntegerStaircase: return "NoIntegerStaircase";
  }
  return "?";
}
std::string str(const BendPath& p) {
  std::string s = str(p.status);
  if (p.status == WireStatus::Ok) s += " {length " + std::to_string(p.length) + ", bends " + std::to_string(p.bends) + "}";
  s += " points";
  for (const Point q : p.points) s += " " + str(q);
  return s;
}
std::string ring_str(const Ring& r) {
  std::string s = "{";
  for (std::size_t i = 0; i < r.size(); ++i) s += (i ? ", " : "") + str(r[i]);
  return s + "}";
}
// The instance as C++ initializers (the normalized obstacles: what the router was given).
std::string describe(const Box& domain, std::span<const Polygon> obstacles) {
  std::ostringstream os;
  os << "domain {" << str(domain.lo) << ", " << str(domain.hi) << "}, obstacles {";
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    os << (i ? ", " : "") << "{" << ring_str(obstacles[i].outer) << ", {";
    for (std::size_t h = 0; h < obstacles[i].holes.size(); ++h) os << (h ? ", " : "") << ring_str(obstacles[i].holes[h]);
    os << "}}";
  }
  os << "}";
  return os.str();
}

Ring rect_ring(Box b) { return {b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}}; }

// ---------------------------------------------------------------------------------------------
// Checking one query against the reference.

struct Tally {
  i64 instances = 0, queries = 0, ok = 0, not_free = 0, unreachable = 0, pinch_ends = 0, boundary_ends = 0;
  i64 with_bends = 0, metric_matters = 0;  // some C or link changed the answer for a pair
  i64 vertices = 0;
};

const char* metric_name(bool link) { return link ? "link" : "combined"; }

// "" when `got` is the status the reference implies (is some point of each end free? is a path
// found?), else what differs; counts the answers without a path in the tally.
template <class Tally_>
std::string status_check(WireStatus got, bool s_free, bool t_free, bool found, Tally_& tally) {
  const WireStatus expected = !s_free  ? WireStatus::SourceNotFree
                              : !t_free ? WireStatus::TargetNotFree
                              : !found  ? WireStatus::Unreachable
                                        : WireStatus::Ok;
  if (got != expected) return "status " + str(got) + ", expected " + str(expected);
  tally.not_free += expected == WireStatus::SourceNotFree || expected == WireStatus::TargetNotFree;
  tally.unreachable += expected == WireStatus::Unreachable;
  return "";
}

// "" when the router's answer for s -> t agrees with the reference, else what differs.
std::string check_query(const BendReference& ref, const BendRouter& router, Point s, Point t, bool link, i64 C,
                        Tally& tally, std::optional<BendAnswer>* answer = nullptr) {
  const std::optional<BendAnswer> want = ref.best(s, t, link, C);
  if (answer) *answer = want;
  BendPath got;
  try {
    got = router.path(s, t, link ? BendMetric::Link : BendMetric::Combined, C);
  } catch (const std::exception& e) {
    return "query " + str(s) + " -> " + str(t) + " " + metric_name(link) + (link ? "" : " C = " + std::to_string(C)) +
           ": reference " + str(want) + ", router threw: " + e.what();
  }
  std::ostringstream head;
  head << "query " << str(s) << " -> " << str(t) << " " << metric_name(link) << (link ? "" : " C = " + std::to_string(C))
       << ": reference " << str(want) << ", router " << str(got) << "\n  ";
  ++tally.queries;
  if (const std::string r = status_check(got.status, ref.l1().is_free(s), ref.l1().is_free(t), want.has_value(), tally);
      !r.empty())
    return head.str() + r;
  if (!want) return "";
  ++tally.ok;
  tally.with_bends += want->bends > 0;
  if (got.length != want->length || got.bends != want->bends) return head.str() + "the cost differs from the reference's optimum";
  const __int128 cost = link ? __int128{want->bends} : __int128{want->length} + __int128{C} * want->bends;
  if (got.cost(link ? BendMetric::Link : BendMetric::Combined, C) != cost) return head.str() + "cost() is not the metric's";
  if (got.points.empty() || got.points.front() != s || got.points.back() != t) return head.str() + "the points do not run from `from` to `to`";
  if (s == t && got.points.size() != 1) return head.str() + "s == t should give {from}";
  for (std::size_t i = 0; i + 1 < got.points.size(); ++i) {
    const Point a = got.points[i], b = got.points[i + 1];
    if (a.x != b.x && a.y != b.y) return head.str() + "segment " + str(a) + " " + str(b) + " is not axis-parallel";
  }
  const std::optional<BendAnswer> measured = ref.check_path(got.points);
  if (!measured) return head.str() + "the path is not legal (check_path)";
  if (*measured != *want) return head.str() + "the path measures " + str(measured);
  return "";
}

// Every pair in every metric; returns the first few disagreements.
std::string check_pairs(const BendReference& ref, const BendRouter& router, const std::vector<std::pair<Point, Point>>& pairs,
                        Tally& tally, const std::string& head) {
  std::string out;
  int failures = 0;
  for (const auto& [s, t] : pairs) {
    std::optional<BendAnswer> first;
    bool differs = false;
    int k = 0;
    for (const bool link : {false, true})
      for (const i64 C : link ? std::vector<i64>{0} : std::vector<i64>{0, 1, 7, 1000}) {
        std::optional<BendAnswer> a;
        const std::string r = check_query(ref, router, s, t, link, C, tally, &a);
        if (!r.empty() && failures++ < 3) out += head + "  " + r + "\n";
        if (k++ == 0) first = a;
        else differs |= a != first;
      }
    tally.metric_matters += differs;
    tally.pinch_ends += ref.l1().wedges_at(s).size() >= 2 || ref.l1().wedges_at(t).size() >= 2;
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Random instances.

struct Instance {
  Box domain;
  std::vector<Polygon> obstacles;  // normalized
  std::vector<std::pair<Point, Point>> pairs;
};

Instance make_instance(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uni = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
  std::vector<Polygon> inputs;
  std::vector<Box> rects;  // the rectangles so far (for pinches and edge contacts)
  // A third of the instances are sparse (a few larger shapes), a third dense (many small
  // blocks), a third walls with gaps across the grid: mazes where the shortest path zigzags and
  // fewer bends cost length.
  const int family = uni(0, 2);
  const bool dense = family == 1;
  const int size = family == 2 ? 16 : 12;
  const Box grid{{uni(-1, 0), uni(-1, 0)}, {uni(size - 5, size), uni(size - 5, size)}};
  if (family == 2) {
    // Parallel walls (vertical, or horizontal: the instance is transposed below), each with a
    // gap or two, some spanning the grid, others leaving room around their ends.
    int x = grid.lo.x + uni(1, 3);
    while (x < grid.hi.x - 1) {
      const int from = grid.lo.y + uni(-1, 3), to = grid.hi.y - uni(-1, 3);
      std::vector<int> cuts = {from};
      for (int g = uni(1, 2); g > 0; --g) {
        const int gap = uni(from + 1, to - 2);
        cuts.push_back(gap), cuts.push_back(gap + uni(1, 2));
      }
      cuts.push_back(to);
      std::sort(cuts.begin() + 1, cuts.end() - 1);
      for (std::size_t k = 0; k + 1 < cuts.size(); k += 2)
        if (cuts[k] < cuts[k + 1]) {
          const Box r{{x, cuts[k]}, {x + 1, cuts[k + 1]}};
          rects.push_back(r);
          inputs.push_back({rect_ring(r), {}});
        }
      x += uni(2, 4);
    }
  }
  const int n = family == 2 ? uni(0, 2) : dense ? uni(8, 18) : uni(1, 8);
  for (int i = 0; i < n; ++i) {
    const int kind = uni(0, 9);
    if (dense && kind <= 5) {  // a small block
      Box b;
      b.lo = {uni(grid.lo.x, grid.hi.x - 1), uni(grid.lo.y, grid.hi.y - 1)};
      b.hi = {b.lo.x + uni(1, 2), b.lo.y + uni(1, 2)};
      if (uni(0, 1)) b.hi.x = b.lo.x + 1; else b.hi.y = b.lo.y + 1;
      rects.push_back(b);
      inputs.push_back({rect_ring(b), {}});
    } else if (kind <= 4 || rects.empty()) {  // a random rectangle, sometimes out of the domain
      Box b;
      b.lo = {uni(grid.lo.x - 1, grid.hi.x - 1), uni(grid.lo.y - 1, grid.hi.y - 1)};
      b.hi = {b.lo.x + uni(1, 5), b.lo.y + uni(1, 5)};
      rects.push_back(b);
      inputs.push_back({rect_ring(b), {}});
    } else if (kind <= 6) {  // diagonal to a corner of the last rectangle: a pinch
      const Box o = rects.back();
      const int w = uni(1, 3), h = uni(1, 3);
      Box b;
      switch (uni(0, 3)) {
        case 0: b = {o.hi, {o.hi.x + w, o.hi.y + h}}; break;
        case 1: b = {{o.lo.x - w, o.hi.y}, {o.lo.x, o.hi.y + h}}; break;
        case 2: b = {{o.lo.x - w, o.lo.y - h}, o.lo}; break;
        default: b = {{o.hi.x, o.lo.y - h}, {o.hi.x + w, o.lo.y}}; break;
      }
      rects.push_back(b);
      inputs.push_back({rect_ring(b), {}});
    } else if (kind == 7) {  // beside the last rectangle, sharing part of an edge
      const Box o = rects.back();
      const int w = uni(1, 3), y0 = uni(o.lo.y - 2, o.hi.y - 1), y1 = y0 + uni(1, 4);
      const Box b = uni(0, 1) ? Box{{o.hi.x, y0}, {o.hi.x + w, y1}} : Box{{o.lo.x - w, y0}, {o.lo.x, y1}};
      rects.push_back(b);
      inputs.push_back({rect_ring(b), {}});
    } else if (kind == 8) {  // a frame with a hole, maybe a rectangle inside the hole
      const int x0 = uni(grid.lo.x, grid.hi.x - 5), y0 = uni(grid.lo.y, grid.hi.y - 5);
      const Box o{{x0, y0}, {x0 + uni(5, 7), y0 + uni(5, 7)}};
      const Box h{{o.lo.x + uni(1, 2), o.lo.y + uni(1, 2)}, {o.hi.x - uni(1, 2), o.hi.y - uni(1, 2)}};
      Ring hole = rect_ring(h);
      std::reverse(hole.begin(), hole.end());
      Polygon frame{rect_ring(o), {hole}};
      if (uni(0, 2) == 0) {  // a gap in the frame: a C shape instead
        frame.holes.clear();
        inputs.push_back({rect_ring({o.lo, {o.hi.x, h.lo.y}}), {}});
        inputs.push_back({rect_ring({{o.lo.x, h.hi.y}, o.hi}), {}});
        inputs.push_back({rect_ring({{o.lo.x, h.lo.y}, {h.lo.x, h.hi.y}}), {}});
      } else {
        inputs.push_back(frame);
      }
      rects.push_back(o);
      if (uni(0, 1) && h.hi.x - h.lo.x >= 2 && h.hi.y - h.lo.y >= 2) {
        const Box in{{h.lo.x + uni(0, 1), h.lo.y + uni(0, 1)}, {h.hi.x - 1, h.hi.y - uni(0, 1)}};
        if (in.lo.x < in.hi.x && in.lo.y < in.hi.y) inputs.push_back({rect_ring(in), {}});
      }
    } else {  // a histogram: columns of random heights on a horizontal base (a simple rectilinear ring)
      const int x0 = uni(grid.lo.x - 1, grid.hi.x - 3), y0 = uni(grid.lo.y - 1, grid.hi.y - 3);
      const int cols = uni(2, 5);
      Ring r = {{x0, y0}};
      int x = x0;
      std::vector<std::pair<int, int>> tops;  // (x from, height)
      for (int c = 0; c < cols; ++c) {
        const int w = uni(1, 2), hgt = uni(1, 6);
        tops.push_back({x, hgt});
        x += w;
      }
      r.push_back({x, y0});
      for (int c = cols - 1; c >= 0; --c) {
        const int xe = c + 1 < cols ? tops[c + 1].first : x;
        r.push_back({xe, y0 + tops[c].second});
        r.push_back({tops[c].first, y0 + tops[c].second});
      }
      // Equal neighbouring heights repeat a point: drop it (the collinear vertex left is
      // dropped below, after scaling).
      Ring clean;
      for (const Point p : r)
        if (clean.empty() || clean.back() != p) clean.push_back(p);
      inputs.push_back({clean, {}});
    }
  }
  // Scale and move off the origin.
  static constexpr int kScales[] = {1, 1, 1, 2, 3, 5, 10, 100};
  const int f = kScales[uni(0, 7)];
  const int ox = uni(-50, 50), oy = uni(-50, 50);
  const bool transpose = uni(0, 1);  // x <-> y (reverses the rings: put right below)
  auto tr = [&](Point p) {
    if (transpose) std::swap(p.x, p.y);
    return Point{p.x * f + ox, p.y * f + oy};
  };
  for (Polygon& p : inputs) {
    for (Point& v : p.outer) v = tr(v);
    for (Ring& h : p.holes)
      for (Point& v : h) v = tr(v);
  }
  const Box domain{tr(grid.lo), tr(grid.hi)};
  if (transpose)
    for (Polygon& p : inputs) {
      std::reverse(p.outer.begin(), p.outer.end());
      for (Ring& h : p.holes) std::reverse(h.begin(), h.end());
    }
  // Collinear vertices (a histogram's equal neighbouring heights) out of every outer ring.
  for (Polygon& p : inputs) {
    Ring clean;
    const std::size_t m = p.outer.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Point a = p.outer[(i + m - 1) % m], b = p.outer[i], c = p.outer[(i + 1) % m];
      if (geom::orient(a, b, c) != 0) clean.push_back(b);
    }
    p.outer = clean;
  }
  Instance in;
  const auto norm = geom::normalize_obstacles(inputs, domain);
  in.domain = norm.domain;
  in.obstacles = norm.obstacles;

  // Query candidates.
  std::vector<Point> vertices, edge_points;
  for (const Polygon& p : in.obstacles) {
    auto add = [&](const Ring& r) {
      for (std::size_t i = 0; i < r.size(); ++i) {
        const Point a = r[i], b = r[(i + 1) % r.size()];
        vertices.push_back(a);
        // An integer point strictly inside the edge, when there is one.
        const i64 len = std::abs(i64{b.x} - a.x) + std::abs(i64{b.y} - a.y);
        if (len >= 2) {
          const i64 k = 1 + static_cast<i64>(rng() % static_cast<std::uint64_t>(len - 1));
          edge_points.push_back({static_cast<geom::Coord>(a.x + (b.x > a.x ? k : b.x < a.x ? -k : 0)),
                                 static_cast<geom::Coord>(a.y + (b.y > a.y ? k : b.y < a.y ? -k : 0))});
        }
      }
    };
    add(p.outer);
    for (const Ring& h : p.holes) add(h);
  }
  // Vertices listed twice (a ring touching itself or another: a pinch) or on a domain side.
  std::vector<Point> pinches;
  {
    std::vector<Point> sorted = vertices;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i)
      if ((i + 1 < sorted.size() && sorted[i] == sorted[i + 1]) || sorted[i].x == domain.lo.x || sorted[i].x == domain.hi.x ||
          sorted[i].y == domain.lo.y || sorted[i].y == domain.hi.y)
        pinches.push_back(sorted[i]);
  }
  auto inside = [&](Point p) {
    return std::any_of(in.obstacles.begin(), in.obstacles.end(),
                       [&](const Polygon& o) { return geom::locate(p, o) == geom::Location::Inside; });
  };
  auto pick = [&]() -> Point {
    const int kind = uni(0, 12);
    if (kind == 12 && !pinches.empty()) return pinches[rng() % pinches.size()];
    if (kind <= 2 && !vertices.empty()) return vertices[rng() % vertices.size()];
    if (kind <= 4 && !edge_points.empty()) return edge_points[rng() % edge_points.size()];
    if (kind == 5) return {uni(domain.lo.x - 1, domain.hi.x + 1), uni(domain.lo.y - 1, domain.hi.y + 1)};  // any point
    // A grid point, mostly not inside an obstacle.
    Point p = tr({uni(grid.lo.x, grid.hi.x), uni(grid.lo.y, grid.hi.y)});
    for (int retry = 0; retry < 4 && inside(p); ++retry) p = tr({uni(grid.lo.x, grid.hi.x), uni(grid.lo.y, grid.hi.y)});
    return p;
  };
  const int pairs = uni(3, 5);
  for (int i = 0; i < pairs; ++i) {
    if (family == 2 && uni(0, 1)) {  // across the walls, from the first gap to the last
      in.pairs.push_back({tr({grid.lo.x + uni(0, 1), uni(grid.lo.y, grid.hi.y)}), tr({grid.hi.x - uni(0, 1), uni(grid.lo.y, grid.hi.y)})});
      continue;
    }
    const Point s = pick();
    in.pairs.push_back({s, uni(0, 15) == 0 ? s : pick()});
  }
  return in;
}

std::string check_seed(std::uint64_t seed, Tally& tally) {
  const Instance in = make_instance(seed);
  const std::string head = "seed " + std::to_string(seed) + ": " + describe(in.domain, in.obstacles) + "\n";
  std::optional<BendRouter> router;
  try {
    router.emplace(in.domain, in.obstacles);
  } catch (const std::exception& e) {
    return head + "  building the router threw: " + e.what() + "\n";
  }
  const BendReference ref(in.domain, in.obstacles);
  if (!ref.l1().problems().empty()) return head + "  reference: " + ref.l1().problems().front() + "\n";
  ++tally.instances;
  tally.vertices += static_cast<i64>(router->stats().vertices);
  for (const auto& [s, t] : in.pairs)
    for (const Point p : {s, t})
      if (ref.l1().wedges_at(p).size() == 1 && ref.l1().wedges_at(p).front().full == false) ++tally.boundary_ends;
  return check_pairs(ref, *router, in.pairs, tally, head);
}

std::optional<std::uint64_t> only_seed() {
  if (const char* e = std::getenv("TAUT_BEND_SEED")) return std::strtoull(e, nullptr, 10);
  return std::nullopt;
}

TEST(BendRouter, MatchesReferenceOnRandomLayouts) {
  const auto t0 = std::chrono::steady_clock::now();
  const i64 count = sanitized_share(2400, 12);
  std::vector<std::uint64_t> seeds(std::begin(kRegressionSeeds), std::end(kRegressionSeeds));
  for (i64 i = 0; i < count; ++i) seeds.push_back(kBaseSeed + static_cast<std::uint64_t>(i));
  if (only_seed()) seeds = {*only_seed()};
  Tally tally;
  int failed = 0;
  for (const std::uint64_t seed : seeds) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " (TAUT_BEND_SEED=" + std::to_string(seed) + " replays it)");
    const std::string r = check_seed(seed, tally);
    if (!r.empty() && failed++ < 5) ADD_FAILURE() << r;
  }
  EXPECT_EQ(failed, 0);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%lld instances, %lld queries (%lld Ok, %lld not free, %lld unreachable), %lld pairs at a pinch, %lld ends on a boundary, "
              "%lld Ok with bends, %lld pairs where the metric matters, %lld vertices, %.1f s\n",
              static_cast<long long>(tally.instances), static_cast<long long>(tally.queries), static_cast<long long>(tally.ok),
              static_cast<long long>(tally.not_free), static_cast<long long>(tally.unreachable),
              static_cast<long long>(tally.pinch_ends), static_cast<long long>(tally.boundary_ends),
              static_cast<long long>(tally.with_bends), static_cast<long long>(tally.metric_matters),
              static_cast<long long>(tally.vertices), secs);
  if (only_seed()) return;
  // The sample exercises what it should (thresholds well below the measured counts).
  EXPECT_EQ(tally.instances, static_cast<i64>(seeds.size()));
  EXPECT_GE(tally.ok, sanitized_share(10000, 12));
  EXPECT_GE(tally.not_free, sanitized_share(1000, 12));
  EXPECT_GE(tally.unreachable, sanitized_share(100, 12));
  EXPECT_GE(tally.pinch_ends, sanitized_share(100, 12));
  EXPECT_GE(tally.boundary_ends, sanitized_share(500, 12));
  EXPECT_GE(tally.metric_matters, sanitized_share(100, 12));
}

// At the coordinate limit: the best wire turns at the domain's corner (2^30 - 1, 2^30 - 1), which
// a sentinel point once hid from the L edges (found in review: 2 bends instead of 1).
TEST(BendRouter, CornersAtTheCoordinateLimit) {
  constexpr geom::Coord A = geom::kMaxCoord, B = 715827882, C3 = 357913941;
  for (int mirror = 0; mirror < 4; ++mirror) {
    SCOPED_TRACE("mirror " + std::to_string(mirror));
    const int sx = mirror & 1 ? -1 : 1, sy = mirror & 2 ? -1 : 1;
    auto m = [&](Point p) { return Point{sx * p.x, sy * p.y}; };
    auto rect = [&](Point a, Point b) {
      const Point p = m(a), q = m(b);
      return Polygon{rect_ring({{std::min(p.x, q.x), std::min(p.y, q.y)}, {std::max(p.x, q.x), std::max(p.y, q.y)}}), {}};
    };
    const std::vector<Polygon> in = {rect({-B, -A}, {B, -B}), rect({-C3, 0}, {C3, B})};
    const auto norm = geom::normalize_obstacles(in, Box{{-A, -A}, {A, A}});
    const BendRouter router(norm.domain, norm.obstacles);
    const BendReference ref(norm.domain, norm.obstacles);
    Tally tally;
    for (const bool link : {false, true})
      for (const i64 C : {i64{0}, i64{1}, i64{1} << 31}) {
        if (link && C) continue;
        std::optional<BendAnswer> want;
        EXPECT_EQ(check_query(ref, router, m({-A, A}), m({A, -A}), link, C, tally, &want), "");
        ASSERT_TRUE(want.has_value());
        EXPECT_EQ(want->bends, 1);
      }
  }
}

// ---------------------------------------------------------------------------------------------
// Trees: one source, several sinks (BendRouter::tree).

// Whether the axis-parallel segment ab lies on the union of the wires' segments.
bool on_metal(Point a, Point b, const std::vector<std::vector<Point>>& wires) {
  if (a == b) {
    for (const auto& w : wires)
      for (std::size_t i = 0; i + 1 < w.size(); ++i)
        if (geom::on_segment(a, w[i], w[i + 1])) return true;
    return std::any_of(wires.begin(), wires.end(), [&](const auto& w) { return w.size() == 1 && w[0] == a; });
  }
  const bool horiz = a.y == b.y;
  const i64 lo = horiz ? std::min(a.x, b.x) : std::min(a.y, b.y), hi = horiz ? std::max(a.x, b.x) : std::max(a.y, b.y);
  std::vector<std::pair<i64, i64>> spans;  // the wires' stretches on ab's line
  for (const auto& w : wires)
    for (std::size_t i = 0; i + 1 < w.size(); ++i) {
      const Point p = w[i], q = w[i + 1];
      if (horiz && p.y == a.y && q.y == a.y) spans.emplace_back(std::min(p.x, q.x), std::max(p.x, q.x));
      if (!horiz && p.x == a.x && q.x == a.x) spans.emplace_back(std::min(p.y, q.y), std::max(p.y, q.y));
    }
  std::sort(spans.begin(), spans.end());
  i64 reach = lo;
  for (const auto& [x0, x1] : spans) {
    if (x0 > reach) break;
    reach = std::max(reach, x1);
  }
  return reach >= hi;
}

// "" when the tree of `source` to `sinks` agrees with the reference, else what differs.
std::string check_tree(const BendReference& ref, const BendRouter& router, Point source, const std::vector<Point>& sinks,
                       bool link, i64 C, i64& trees_ok) {
  std::ostringstream head;
  head << "tree from " << str(source) << " to";
  for (const Point p : sinks) head << " " << str(p);
  head << " " << metric_name(link) << (link ? "" : " C = " + std::to_string(C)) << ": ";
  router::BendTree t;
  try {
    t = router.tree(source, sinks, link ? BendMetric::Link : BendMetric::Combined, C);
  } catch (const std::exception& e) {
    return head.str() + "router threw: " + e.what();
  }
  // the expected status: the source, then the first sink not free, then the first unreachable
  WireStatus expected = WireStatus::Ok;
  std::size_t failed = 0;
  std::vector<std::optional<BendAnswer>> want;
  if (!ref.l1().is_free(source)) expected = WireStatus::SourceNotFree;
  for (std::size_t k = 0; k < sinks.size() && expected == WireStatus::Ok; ++k)
    if (!ref.l1().is_free(sinks[k])) expected = WireStatus::TargetNotFree, failed = k;
  for (std::size_t k = 0; k < sinks.size(); ++k) want.push_back(ref.best(source, sinks[k], link, C));
  for (std::size_t k = 0; k < sinks.size() && expected == WireStatus::Ok; ++k)
    if (!want[k]) expected = WireStatus::Unreachable, failed = k;
  // costs() and fewest_bends() (link): the same optimum per sink from one search without paths; a
  // sink walled in is not reached rather than an error
  {
    const WireStatus free_status = expected == WireStatus::Unreachable ? WireStatus::Ok : expected;
    WireStatus cs = WireStatus::Ok;
    std::size_t cf = 0;
    const std::vector<router::BendCost> c =
        router.costs(source, sinks, link ? BendMetric::Link : BendMetric::Combined, C, &cs, &cf);
    if (cs != free_status) return head.str() + "costs(): status " + str(cs) + ", expected " + str(free_status);
    if (cs == WireStatus::TargetNotFree && cf != failed) return head.str() + "costs(): wrong failed sink";
    for (std::size_t k = 0; cs == WireStatus::Ok && k < sinks.size(); ++k) {
      if (c[k].reached != want[k].has_value()) return head.str() + "costs(): sink " + std::to_string(k) + " reached?";
      if (want[k] && (c[k].length != want[k]->length || c[k].bends != want[k]->bends))
        return head.str() + "costs(): sink " + std::to_string(k) + " costs (" + std::to_string(c[k].length) + ", " +
               std::to_string(c[k].bends) + "), the optimum is " + str(want[k]);
    }
    if (link) {
      const std::vector<i64> fb = router.fewest_bends(source, sinks, &cs, &cf);
      if (cs != free_status) return head.str() + "fewest_bends(): status " + str(cs);
      for (std::size_t k = 0; cs == WireStatus::Ok && k < sinks.size(); ++k)
        if (fb[k] != (want[k] ? want[k]->bends : -1))
          return head.str() + "fewest_bends(): sink " + std::to_string(k) + " gets " + std::to_string(fb[k]);
    }
  }
  if (t.status != expected) return head.str() + "status " + str(t.status) + ", expected " + str(expected);
  if (expected != WireStatus::Ok) {
    if (expected != WireStatus::SourceNotFree && t.failed != failed)
      return head.str() + "failed sink " + std::to_string(t.failed) + ", expected " + std::to_string(failed);
    return "";
  }
  if (t.paths.size() != sinks.size() || t.wires.empty()) return head.str() + "wrong number of paths or no wire";
  for (std::size_t i = 0; i < t.wires.size(); ++i) {
    const auto& w = t.wires[i];
    if (!ref.check_path(w)) return head.str() + "wire " + std::to_string(i) + " is not legal";
    // the first wire starts at the source, every other on the wires before it
    const std::vector<std::vector<Point>> before(t.wires.begin(), t.wires.begin() + static_cast<std::ptrdiff_t>(i));
    if (i == 0 ? w.front() != source : !on_metal(w.front(), w.front(), before))
      return head.str() + "wire " + std::to_string(i) + " starts at " + str(w.front()) + ", off the tree";
  }
  for (std::size_t k = 0; k < sinks.size(); ++k) {
    const auto& p = t.paths[k];
    if (p.empty() || p.front() != source || p.back() != sinks[k]) return head.str() + "path " + std::to_string(k) + " has wrong ends";
    const auto m = ref.check_path(p);
    if (!m) return head.str() + "path " + std::to_string(k) + " is not legal";
    if (*m != *want[k]) return head.str() + "path " + std::to_string(k) + " measures " + str(m) + ", the optimum is " + str(want[k]);
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
      if (!on_metal(p[i], p[i + 1], t.wires)) return head.str() + "path " + std::to_string(k) + " leaves the wires at " + str(p[i]);
    if (p.size() == 1 && !on_metal(p[0], p[0], t.wires)) return head.str() + "sink " + std::to_string(k) + " is not on the wires";
  }
  ++trees_ok;
  return "";
}

TEST(BendRouter, TreesMatchTheReference) {
  const i64 count = sanitized_share(600, 12);
  i64 trees = 0, trees_ok = 0, shared = 0;
  int failed = 0;
  for (i64 i = 0; i < count; ++i) {
    const std::uint64_t seed = kBaseSeed + 50000 + static_cast<std::uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Instance in = make_instance(seed);
    const BendRouter router(in.domain, in.obstacles);
    const BendReference ref(in.domain, in.obstacles);
    if (in.pairs.size() < 2) continue;
    std::mt19937_64 rng(seed);
    for (int round = 0; round < 3; ++round) {
      const Point source = in.pairs[rng() % in.pairs.size()].first;
      std::vector<Point> sinks;
      const std::size_t n = 2 + rng() % 4;
      for (std::size_t k = 0; k < n; ++k) {
        const auto& pr = in.pairs[rng() % in.pairs.size()];
        sinks.push_back(rng() % 2 ? pr.first : pr.second);
      }
      const bool link = rng() % 3 == 0;
      const i64 C = link ? 0 : std::vector<i64>{0, 1, 7, 1000}[rng() % 4];
      ++trees;
      const i64 before = trees_ok;
      const std::string r = check_tree(ref, router, source, sinks, link, C, trees_ok);
      if (!r.empty() && failed++ < 5) ADD_FAILURE() << "seed " << seed << ": " << describe(in.domain, in.obstacles) << "\n  " << r;
      if (trees_ok > before) {
        const auto t = router.tree(source, sinks, link ? BendMetric::Link : BendMetric::Combined, C);
        shared += t.wires.size() < sinks.size();
      }
    }
  }
  std::printf("%lld trees, %lld of them joined every sink, %lld with fewer wires than sinks\n", static_cast<long long>(trees),
              static_cast<long long>(trees_ok), static_cast<long long>(shared));
  EXPECT_EQ(failed, 0);
  EXPECT_GE(trees_ok, sanitized_share(300, 12));
}

// ---------------------------------------------------------------------------------------------
// BendTargetMap (section 4: many queries to one fixed target by slab trees): on the random
// instances, a target from the instance's pairs and every query point of the instance plus
// every lattice point of a coarse grid over the domain (inside obstacles, on edges, at pinches,
// outside the domain), in the combined metric with C in {0, 1, 7, 1000} and in the link metric:
// the status and the cost equal the reference's, and path() gives a legal path from q to the
// target with exactly that cost.

// One query of a BendTargetMap against the reference's answer `want` (nullopt: none): its
// status, cost, and a legal path of that cost from q that ends where `ends_ok` says. "" when
// they agree; *path (when answered) receives the path.
std::string check_map_query(const router::BendTargetMap& map, const BendReference& ref, Point q, bool target_free,
                            const std::optional<BendAnswer>& want, const std::function<bool(Point)>& ends_ok,
                            const std::string& at, BendPath* path) {
  WireStatus st = WireStatus::Ok;
  const router::BendCost got = map.cost(q, &st);
  const WireStatus expected = !target_free ? WireStatus::TargetNotFree
                              : !ref.l1().is_free(q) ? WireStatus::SourceNotFree
                              : !want ? WireStatus::Unreachable
                                      : WireStatus::Ok;
  std::ostringstream head;
  head << at << " from " << str(q) << ": reference " << str(want) << ", map status " << str(st) << " length "
       << got.length << " bends " << got.bends << "\n  ";
  if (st != expected) return head.str() + "status differs";
  if (!want) return "";
  if (got.length != want->length || got.bends != want->bends) return head.str() + "cost differs";
  *path = map.path(q);
  const std::optional<BendAnswer> m = ref.check_path(path->points);
  if (path->points.empty() || path->points.front() != q || !ends_ok(path->points.back()) || !m || *m != *want)
    return head.str() + "path " + str(*path) + " measures " + str(m);
  return "";
}

TEST(BendRouter, TargetMapMatchesTheReference) {
  const i64 count = sanitized_share(250, 10);
  i64 queries = 0, ok = 0, corners = 0, pieces = 0;
  int failed = 0;
  for (i64 i = 0; i < count; ++i) {
    const std::uint64_t seed = kBaseSeed + 90000 + static_cast<std::uint64_t>(i);
    const Instance in = make_instance(seed);
    const BendRouter router(in.domain, in.obstacles);
    const BendReference ref(in.domain, in.obstacles);
    std::mt19937_64 rng(seed);
    const Point target = in.pairs[rng() % in.pairs.size()].second;
    std::vector<Point> qs;
    for (const auto& [s, t] : in.pairs) qs.push_back(s), qs.push_back(t);
    const i64 w = i64{in.domain.hi.x} - in.domain.lo.x, h = i64{in.domain.hi.y} - in.domain.lo.y;
    for (int gy = -1; gy <= 6; ++gy)
      for (int gx = -1; gx <= 6; ++gx)
        qs.push_back({static_cast<geom::Coord>(in.domain.lo.x + w * gx / 5), static_cast<geom::Coord>(in.domain.lo.y + h * gy / 5)});
    for (const bool link : {false, true})
      for (const i64 C : link ? std::vector<i64>{0} : std::vector<i64>{0, 1, 7, 1000}) {
        const BendMetric metric = link ? BendMetric::Link : BendMetric::Combined;
        router::BendTargetMap map(router, target, metric, C);
        pieces += static_cast<i64>(map.pieces());
        const bool target_free = ref.l1().is_free(target);
        // every query is checked below with the default search (Bounded: these small trees are
        // searched node by node); cascading every query (the walk down from the lowest common
        // ancestor) and the binary search per node answer the same
        using Search = router::BendTargetMap::SlabSearch;
        std::vector<router::BendCost> bounded;
        for (const Point q : qs) bounded.push_back(map.cost(q));
        for (const Search m : {Search::Cascading, Search::PerNode}) {
          map.set_slab_search(m);
          for (std::size_t k = 0; k < qs.size(); ++k)
            if (const router::BendCost c = map.cost(qs[k]);
                c.reached != bounded[k].reached || c.length != bounded[k].length || c.bends != bounded[k].bends) {
              if (failed++ < 5)
                ADD_FAILURE() << "seed " << seed << ": from " << str(qs[k]) << (m == Search::Cascading ? " cascading " : " per node ")
                              << c.length << "/" << c.bends << ", bounded " << bounded[k].length << "/" << bounded[k].bends;
            }
        }
        map.set_slab_search(Search::Bounded);
        if ((map.status() == WireStatus::Ok) != target_free) {
          if (failed++ < 5) ADD_FAILURE() << "seed " << seed << ": target " << str(target) << " status " << str(map.status());
          continue;
        }
        const std::string at = "seed " + std::to_string(seed) + ": " + describe(in.domain, in.obstacles) + "\n  target " +
                               str(target) + " " + metric_name(link) + (link ? "" : " C = " + std::to_string(C));
        for (const Point q : qs) {
          ++queries;
          const std::optional<BendAnswer> want = target_free ? ref.best(q, target, link, C) : std::nullopt;
          BendPath p;
          const std::string r = check_map_query(map, ref, q, target_free, want, [&](Point e) { return e == target; }, at, &p);
          if (!r.empty()) {
            if (failed++ < 5) ADD_FAILURE() << r;
            continue;
          }
          if (!want) continue;
          ++ok;
          corners += p.bends > 0;
        }
      }
  }
  std::printf("%lld instances, %lld target-map queries (%lld answered), %lld with bends, %lld envelope pieces\n",
              static_cast<long long>(count), static_cast<long long>(queries), static_cast<long long>(ok),
              static_cast<long long>(corners), static_cast<long long>(pieces));
  EXPECT_EQ(failed, 0);
  EXPECT_GE(ok, sanitized_share(25000, 10));
  EXPECT_GE(corners, sanitized_share(20000, 10));
}

// ---------------------------------------------------------------------------------------------
// Shape pins (BendRouter::path and tree on geom::Polygon pins): a wire may start and end anywhere
// on a pin. The reference searches from EVERY integer point of the closed source shape to every
// integer point of the sink's, on the full integer lattice (BendReference::
// best_between_on_lattice), so it knows nothing of the router's candidate points
// (router/pin_shapes.h): equal costs check that the candidates hold an optimal end. Layouts:
// the random instances above that are not scaled (a lattice of at most 18 x 18), pins drawn
// there: points, rectangles, L shapes, rectangles with a hole, diamonds and right triangles with
// 45-degree edges, small and large, many touching blockages, some touching or overlapping each
// other or lying partly outside the domain; shapes that overlap a blockage are dropped
// (pin_meets_obstacle; such pins are refused by route, ROUTE-0005) and counted.

// The integer points of a closed pin (point or shape) inside the box.
std::vector<Point> pin_lattice(const Polygon& pin, const Box& box) {
  if (pin.outer.size() == 1 && pin.holes.empty()) return {pin.outer[0]};
  std::vector<Point> out;
  for (geom::Coord x = box.lo.x - 1; x <= box.hi.x + 1; ++x)
    for (geom::Coord y = box.lo.y - 1; y <= box.hi.y + 1; ++y)
      if (geom::locate({x, y}, pin) != geom::Location::Outside) out.push_back({x, y});
  return out;
}

std::string pin_str(const Polygon& p) {
  std::string s = "{" + ring_str(p.outer);
  for (const Ring& h : p.holes) s += ", hole " + ring_str(h);
  return s + "}";
}

// A random pin near the lattice `grid` (rectangles, L, a rectangle with a hole, a diamond, a
// 45-degree triangle, a long strip along a diagonal, or a point), often placed against an
// obstacle vertex.
Polygon random_pin(std::mt19937_64& rng, const Box& grid, std::span<const Polygon> obstacles) {
  auto uni = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1)); };
  Point o{uni(grid.lo.x, grid.hi.x), uni(grid.lo.y, grid.hi.y)};
  if (!obstacles.empty() && uni(0, 2) == 0) {  // at an obstacle vertex
    const Ring& r = obstacles[rng() % obstacles.size()].outer;
    o = r[rng() % r.size()];
  }
  const int w = uni(1, 4), h = uni(1, 4);
  const int sx = uni(0, 1) ? 1 : -1, sy = uni(0, 1) ? 1 : -1;  // which way from o
  auto at = [&](int dx, int dy) { return Point{o.x + sx * dx, o.y + sy * dy}; };
  Polygon p;
  switch (uni(0, 8)) {
    case 0: p.outer = {o}; break;
    case 7: {  // a long strip along a diagonal, short edges vertical (often reaching out of the domain)
      const int len = uni(3, 12), wd = uni(1, 3), s = sx * sy;
      p.outer = {{o.x - len, o.y - s * len}, {o.x + len, o.y + s * len}, {o.x + len, o.y + s * len + wd}, {o.x - len, o.y - s * len + wd}};
      break;
    }
    case 8: {  // the same with horizontal short edges
      const int len = uni(3, 12), wd = uni(1, 3), s = sx * sy;
      p.outer = {{o.x - len, o.y - s * len}, {o.x - len + wd, o.y - s * len}, {o.x + len + wd, o.y + s * len}, {o.x + len, o.y + s * len}};
      break;
    }
    case 1: p.outer = {at(0, 0), at(w, 0), at(w, h), at(0, h)}; break;
    case 2: {  // an L
      const int w2 = uni(1, 4), h2 = uni(1, 4);
      p.outer = {at(0, 0), at(w + w2, 0), at(w + w2, h), at(w, h), at(w, h + h2), at(0, h + h2)};
      break;
    }
    case 3: {  // a rectangle with a hole
      const int W = uni(3, 6), H = uni(3, 6);
      p.outer = {at(0, 0), at(W, 0), at(W, H), at(0, H)};
      p.holes = {{at(1, 1), at(W - 1, 1), at(W - 1, H - 1), at(1, H - 1)}};
      break;
    }
    case 4: {  // a diamond around o
      const int r = uni(1, 3);
      p.outer = {{o.x + r, o.y}, {o.x, o.y + r}, {o.x - r, o.y}, {o.x, o.y - r}};
      break;
    }
    case 5: p.outer = {at(0, 0), at(w, 0), at(0, w)}; break;  // a right triangle, 45-degree hypotenuse
    default: {  // a hexagon with two 45-degree edges
      const int c = uni(1, std::min(w, h));
      p.outer = {at(c, 0), at(w + c, 0), at(w + c, h), at(w, h + c), at(0, h + c), at(0, c)};
      break;
    }
  }
  return p;
}

struct PinTally {
  i64 layouts = 0, queries = 0, ok = 0, not_free = 0, unreachable = 0, shared = 0, from_inside_edge = 0;
  i64 dropped = 0, trees = 0, trees_ok = 0;
};

// The router's wire from pin a to pin b against the reference; "" when they agree.
std::string check_pin_query(const BendReference& ref, const BendRouter& router, const Box& domain, const Polygon& a,
                            const Polygon& b, bool link, i64 C, PinTally& tally) {
  const std::vector<Point> A = pin_lattice(a, domain), B = pin_lattice(b, domain);
  const std::optional<BendAnswer> want = ref.best_between_on_lattice(A, B, link, C);
  std::ostringstream head;
  head << "pins " << pin_str(a) << " -> " << pin_str(b) << " " << metric_name(link)
       << (link ? "" : " C = " + std::to_string(C)) << ": reference " << str(want) << ", ";
  BendPath got;
  try {
    got = router.path(a, b, link ? BendMetric::Link : BendMetric::Combined, C);
  } catch (const std::exception& e) {
    return head.str() + "router threw: " + e.what();
  }
  head << "router " << str(got) << "\n  ";
  ++tally.queries;
  auto any_free = [&](const std::vector<Point>& v) {
    return std::any_of(v.begin(), v.end(), [&](Point p) { return ref.l1().is_free(p); });
  };
  if (const std::string r = status_check(got.status, any_free(A), any_free(B), want.has_value(), tally); !r.empty())
    return head.str() + r;
  if (!want) return "";
  ++tally.ok;
  tally.shared += want->length == 0;
  if (got.length != want->length || got.bends != want->bends) return head.str() + "the cost differs from the reference's optimum";
  auto on_pin = [](Point p, const Polygon& pin) {  // a point pin is one vertex
    return pin.outer.size() == 1 ? p == pin.outer[0] : geom::locate(p, pin) != geom::Location::Outside;
  };
  if (got.points.empty() || !on_pin(got.points.front(), a) || !on_pin(got.points.back(), b))
    return head.str() + "the wire does not run from pin to pin";
  const std::optional<BendAnswer> measured = ref.check_path(got.points);
  if (!measured) return head.str() + "the path is not legal (check_path)";
  if (*measured != *want) return head.str() + "the path measures " + str(measured);
  // a start that is no vertex of the shape: the candidates at work
  if (a.outer.size() > 1 && std::find(a.outer.begin(), a.outer.end(), got.points.front()) == a.outer.end()) ++tally.from_inside_edge;
  return "";
}

// A tree from a source pin to sink pins: every sink's path is optimal, legal and on the wires,
// and every wire starts on the source pin or on an earlier wire.
std::string check_pin_tree(const BendReference& ref, const BendRouter& router, const Box& domain, const Polygon& source,
                           const std::vector<Polygon>& sinks, bool link, i64 C, PinTally& tally) {
  std::ostringstream head;
  head << "tree from " << pin_str(source) << " to";
  for (const Polygon& p : sinks) head << " " << pin_str(p);
  head << " " << metric_name(link) << (link ? "" : " C = " + std::to_string(C)) << ": ";
  ++tally.trees;
  router::BendTree t;
  try {
    t = router.tree(source, sinks, link ? BendMetric::Link : BendMetric::Combined, C);
  } catch (const std::exception& e) {
    return head.str() + "router threw: " + e.what();
  }
  const std::vector<Point> S = pin_lattice(source, domain);
  std::vector<std::optional<BendAnswer>> want;
  for (const Polygon& p : sinks) want.push_back(ref.best_between_on_lattice(S, pin_lattice(p, domain), link, C));
  const bool all = std::all_of(want.begin(), want.end(), [](const auto& w) { return w.has_value(); });
  if ((t.status == WireStatus::Ok) != all) return head.str() + "status " + str(t.status) + ", reference reaches all: " + (all ? "yes" : "no");
  if (!all) return "";
  auto in_shape = [](Point p, const Polygon& g) { return geom::locate(p, g) != geom::Location::Outside; };
  for (std::size_t k = 0; k < sinks.size(); ++k) {
    const auto& p = t.paths[k];
    if (p.empty() || !in_shape(p.front(), source) || !in_shape(p.back(), sinks[k]))
      return head.str() + "path " + std::to_string(k) + " does not run from the source pin to its sink";
    const auto m = ref.check_path(p);
    if (!m) return head.str() + "path " + std::to_string(k) + " is not legal";
    if (*m != *want[k]) return head.str() + "path " + std::to_string(k) + " measures " + str(m) + ", the optimum is " + str(want[k]);
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
      if (!on_metal(p[i], p[i + 1], t.wires)) return head.str() + "path " + std::to_string(k) + " leaves the wires at " + str(p[i]);
  }
  for (std::size_t i = 0; i < t.wires.size(); ++i) {
    const auto& w = t.wires[i];
    if (!ref.check_path(w)) return head.str() + "wire " + std::to_string(i) + " is not legal";
    const std::vector<std::vector<Point>> before(t.wires.begin(), t.wires.begin() + static_cast<std::ptrdiff_t>(i));
    if (!in_shape(w.front(), source) && !on_metal(w.front(), w.front(), before))
      return head.str() + "wire " + std::to_string(i) + " starts at " + str(w.front()) + ", off the tree";
  }
  ++tally.trees_ok;
  return "";
}

// Cases the review found (2026-11-24): two strips along crossing diagonals share integer points
// although their candidates do not (the crossings are half-integer points); and a one-link wire
// between strips reaching out of the domain, whose slide stops where one end leaves the domain
// (the other end is that crossing's projection). Each against the lattice reference, and the
// L1 router on the first.
TEST(BendRouter, ShapePinRegressions) {
  struct Case {
    Box domain;
    Polygon a, b;
    bool link;
    i64 C;
  };
  const std::vector<Case> cases = {
      {{{0, 0}, {5, 5}}, {{{0, 0}, {4, 4}, {4, 5}, {0, 1}}, {}}, {{{4, 0}, {5, 0}, {1, 4}, {0, 4}}, {}}, false, 1},
      {{{0, 0}, {5, 5}}, {{{0, 0}, {4, 4}, {4, 5}, {0, 1}}, {}}, {{{4, 0}, {5, 0}, {1, 4}, {0, 4}}, {}}, true, 0},
      {{{0, 0}, {3, 3}}, {{{-5, -2}, {-3, -2}, {3, 4}, {1, 4}}, {}}, {{{0, -1}, {2, -1}, {6, 3}, {4, 3}}, {}}, false, 1},
      {{{-1, -1}, {12, 10}}, {{{2, 10}, {0, 10}, {-9, 1}, {-7, 1}}, {}}, {{{9, 6}, {11, 6}, {16, 11}, {14, 11}}, {}}, true, 0},
  };
  PinTally tally;
  for (const Case& k : cases) {
    const BendRouter router(k.domain, {});
    const BendReference ref(k.domain, {});
    const std::string r = check_pin_query(ref, router, k.domain, k.a, k.b, k.link, k.C, tally);
    EXPECT_TRUE(r.empty()) << r;
  }
  // the L1 router joins the crossing strips at a shared point
  router::L1Router l1(cases[0].domain, {});
  const router::L1Wire w = l1.shortest(cases[0].a, cases[0].b);
  ASSERT_EQ(w.status, WireStatus::Ok);
  EXPECT_EQ(w.length.value_or(-1), 0);
}

TEST(BendRouter, ShapePinsMatchTheReference) {
  const i64 layouts = sanitized_share(500, 10);
  PinTally tally;
  int failed = 0;
  for (std::uint64_t seed = kBaseSeed + 70000; tally.layouts < layouts; ++seed) {
    const Instance in = make_instance(seed);
    if (in.domain.hi.x - in.domain.lo.x > 18 || in.domain.hi.y - in.domain.lo.y > 18) continue;  // scaled
    ++tally.layouts;
    SCOPED_TRACE("seed " + std::to_string(seed));
    const BendRouter router(in.domain, in.obstacles);
    const BendReference ref(in.domain, in.obstacles);
    std::mt19937_64 rng(seed);
    std::vector<Polygon> pins;
    while (pins.size() < 5) {
      Polygon p = random_pin(rng, in.domain, in.obstacles);
      if (router.pin_meets_obstacle(p)) {
        ++tally.dropped;
        continue;
      }
      pins.push_back(std::move(p));
    }
    for (int q = 0; q < 4; ++q) {
      const Polygon& a = pins[rng() % pins.size()];
      const Polygon& b = pins[rng() % pins.size()];
      for (const bool link : {false, true})
        for (const i64 C : link ? std::vector<i64>{0} : std::vector<i64>{0, 1, 7, 1000}) {
          const std::string r = check_pin_query(ref, router, in.domain, a, b, link, C, tally);
          if (!r.empty() && failed++ < 5)
            ADD_FAILURE() << "seed " << seed << ": " << describe(in.domain, in.obstacles) << "\n  " << r;
        }
    }
    const bool link = rng() % 3 == 0;
    const i64 C = link ? 0 : std::vector<i64>{0, 1, 7, 1000}[rng() % 4];
    const std::vector<Polygon> sinks(pins.begin() + 1, pins.begin() + 2 + static_cast<std::ptrdiff_t>(rng() % 3));
    const std::string r = check_pin_tree(ref, router, in.domain, pins[0], sinks, link, C, tally);
    if (!r.empty() && failed++ < 5) ADD_FAILURE() << "seed " << seed << ": " << describe(in.domain, in.obstacles) << "\n  " << r;
  }
  std::printf("%lld layouts, %lld pin queries (%lld Ok, %lld of them pins that meet, %lld starting inside a shape's edge; "
              "%lld not free, %lld unreachable), %lld shapes dropped (under a blockage), %lld trees (%lld joined)\n",
              static_cast<long long>(tally.layouts), static_cast<long long>(tally.queries), static_cast<long long>(tally.ok),
              static_cast<long long>(tally.shared), static_cast<long long>(tally.from_inside_edge),
              static_cast<long long>(tally.not_free), static_cast<long long>(tally.unreachable),
              static_cast<long long>(tally.dropped), static_cast<long long>(tally.trees), static_cast<long long>(tally.trees_ok));
  EXPECT_EQ(failed, 0);
  EXPECT_GE(tally.ok, sanitized_share(5000, 10));
  EXPECT_GE(tally.from_inside_edge, sanitized_share(500, 10));
  EXPECT_GE(tally.shared, sanitized_share(100, 10));
  EXPECT_GE(tally.trees_ok, sanitized_share(200, 10));
}

// BendTargetMap with a pin as the target: a shape (or a point) from random_pin, queries from
// points of the lattice around the layout, the obstacle vertices and points on and beside the
// target's edges; each against the reference's search from the query point to EVERY integer
// point of the target (best_between_on_lattice), which knows nothing of the candidates or of
// the straight shots the map adds per query.
TEST(BendRouter, TargetMapOnShapePinsMatchesTheReference) {
  const i64 layouts = sanitized_share(300, 10);
  i64 done = 0, queries = 0, ok = 0, on_shape = 0, straight = 0, corners = 0;
  int failed = 0;
  for (std::uint64_t seed = kBaseSeed + 95000; done < layouts; ++seed) {
    const Instance in = make_instance(seed);
    if (in.domain.hi.x - in.domain.lo.x > 18 || in.domain.hi.y - in.domain.lo.y > 18) continue;  // scaled
    const BendRouter router(in.domain, in.obstacles);
    std::mt19937_64 rng(seed);
    Polygon target = random_pin(rng, in.domain, in.obstacles);
    if (router.pin_meets_obstacle(target)) continue;
    ++done;
    const BendReference ref(in.domain, in.obstacles);
    const std::vector<Point> T = pin_lattice(target, in.domain);
    auto is_point = [](const Polygon& pin) { return pin.outer.size() == 1 && pin.holes.empty(); };
    const bool target_free = std::any_of(T.begin(), T.end(), [&](Point p) { return ref.l1().is_free(p); });
    std::vector<Point> qs;
    for (int k = 0; k < 16; ++k)
      qs.push_back({in.domain.lo.x - 1 + static_cast<geom::Coord>(rng() % static_cast<std::uint64_t>(in.domain.hi.x - in.domain.lo.x + 3)),
                    in.domain.lo.y - 1 + static_cast<geom::Coord>(rng() % static_cast<std::uint64_t>(in.domain.hi.y - in.domain.lo.y + 3))});
    for (int k = 0; k < 8 && !in.obstacles.empty(); ++k) {
      const Ring& r = in.obstacles[rng() % in.obstacles.size()].outer;
      qs.push_back(r[rng() % r.size()]);
    }
    for (int k = 0; k < 6; ++k) {  // on the target or one step beside it
      const Point t = T[rng() % T.size()];
      qs.push_back({t.x + static_cast<geom::Coord>(rng() % 3) - 1, t.y + static_cast<geom::Coord>(rng() % 3) - 1});
    }
    for (const bool link : {false, true})
      for (const i64 C : link ? std::vector<i64>{0} : std::vector<i64>{0, 1, 7, 1000}) {
        const BendMetric metric = link ? BendMetric::Link : BendMetric::Combined;
        const router::BendTargetMap map(router, target, metric, C);
        std::ostringstream at;
        at << "seed " << seed << ": " << describe(in.domain, in.obstacles) << "\n  target " << pin_str(target) << " "
           << metric_name(link) << (link ? "" : " C = " + std::to_string(C));
        if ((map.status() == WireStatus::Ok) != target_free) {
          if (failed++ < 5) ADD_FAILURE() << at.str() << ": map status " << str(map.status());
          continue;
        }
        auto on_target = [&](Point e) {
          return is_point(target) ? e == target.outer[0] : geom::locate(e, target) != geom::Location::Outside;
        };
        for (const Point q : qs) {
          ++queries;
          const Point qq[1] = {q};
          const std::optional<BendAnswer> want = target_free ? ref.best_between_on_lattice(qq, T, link, C) : std::nullopt;
          BendPath p;
          const std::string r = check_map_query(map, ref, q, target_free, want, on_target, at.str(), &p);
          if (!r.empty()) {
            if (failed++ < 5) ADD_FAILURE() << r;
            continue;
          }
          if (!want) continue;
          ++ok;
          on_shape += want->length == 0;
          straight += want->length > 0 && p.bends == 0;
          corners += p.bends > 0;
        }
      }
  }
  std::printf("%lld layouts, %lld queries to a pin (%lld answered: %lld on it, %lld straight, %lld with bends)\n",
              static_cast<long long>(done), static_cast<long long>(queries), static_cast<long long>(ok),
              static_cast<long long>(on_shape), static_cast<long long>(straight), static_cast<long long>(corners));
  EXPECT_EQ(failed, 0);
  EXPECT_GE(ok, sanitized_share(10000, 10));
  EXPECT_GE(straight, sanitized_share(1000, 10));
  EXPECT_GE(corners, sanitized_share(3000, 10));
}

// The review's case: a shape target lying over a blockage whose only free spot is a hole in it,
// so no candidate of the shape is free (the map is TargetNotFree) while a query point in the hole
// lies on the target and is free: it costs 0, as BendRouter::path gives it.
TEST(BendRouter, TargetMapOnAShapeWithoutAFreeCandidate) {
  const Box domain{{0, 0}, {10, 10}};
  const std::vector<Polygon> blockages = {Polygon{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}}};
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(blockages, domain);
  const BendRouter router(norm.domain, norm.obstacles);
  const Polygon pin{{{-1, -1}, {11, -1}, {11, 11}, {-1, 11}}, {}};
  for (const bool link : {false, true}) {
    const BendMetric metric = link ? BendMetric::Link : BendMetric::Combined;
    const router::BendTargetMap map(router, pin, metric, 7);
    EXPECT_EQ(map.status(), WireStatus::TargetNotFree);
    for (const Point q : {Point{5, 5}, Point{4, 5}, Point{6, 6}}) {
      WireStatus st{};
      const router::BendCost c = map.cost(q, &st);
      EXPECT_EQ(st, WireStatus::Ok) << str(q);
      EXPECT_EQ(c.length, 0);
      EXPECT_EQ(c.bends, 0);
      const BendPath want = router.path(Polygon{{q}, {}}, pin, metric, 7);
      EXPECT_EQ(want.status, WireStatus::Ok);
      EXPECT_EQ(map.path(q).points, std::vector<Point>{q});
    }
    WireStatus st{};
    (void)map.cost({2, 2}, &st);  // inside the blockage
    EXPECT_EQ(st, WireStatus::TargetNotFree);
  }
}

// ---------------------------------------------------------------------------------------------
// Crops of Moving AI maps: blocked cells (10 DBU each) that touch along edges and at corners
// everywhere, clipped to a window of the map.

TEST(BendRouter, MovingAiCropsMatchTheReference) {
  TAUT_REQUIRE_SHARED_DATA();
  Tally tally;
  int failed = 0, crops = 0;
  std::mt19937_64 rng(77);
  for (const char* name : {"8room_000", "arena", "den520d", "maze-100-1", "random512-10-0"}) {
    const auto r = io::load_movingai_map(shared_data_dir() + "/movingai/" + name + ".map", 10);
    ASSERT_TRUE(r.layout && r.layout->boundary) << name << " did not load";
    const std::vector<Polygon> all = io::blockage_polygons(*r.layout);
    const Box map = r.layout->boundary->box;
    for (int k = 0; k < sanitized_share(3, 3); ++k) {
      // A window of 24 x 24 cells with some blockage in it.
      const int cells = 24;
      const int cw = (map.hi.x - map.lo.x) / 10 - cells, ch = (map.hi.y - map.lo.y) / 10 - cells;
      std::optional<geom::NormalizedObstacles> norm;
      for (int attempt = 0; attempt < 50; ++attempt) {
        const int cx = static_cast<int>(rng() % static_cast<std::uint64_t>(cw + 1));
        const int cy = static_cast<int>(rng() % static_cast<std::uint64_t>(ch + 1));
        const Box win{{map.lo.x + 10 * cx, map.lo.y + 10 * cy}, {map.lo.x + 10 * (cx + cells), map.lo.y + 10 * (cy + cells)}};
        std::vector<Polygon> in;
        for (const Polygon& p : all) {
          i64 x0 = p.outer[0].x, x1 = x0, y0 = p.outer[0].y, y1 = y0;
          for (const Point v : p.outer) x0 = std::min<i64>(x0, v.x), x1 = std::max<i64>(x1, v.x), y0 = std::min<i64>(y0, v.y), y1 = std::max<i64>(y1, v.y);
          if (x1 >= win.lo.x && x0 <= win.hi.x && y1 >= win.lo.y && y0 <= win.hi.y) in.push_back(p);
        }
        norm = geom::normalize_obstacles(in, win);
        std::size_t verts = 0;
        for (const Polygon& p : norm->obstacles) verts += p.outer.size();
        if (verts >= 12) break;
      }
      const BendReference ref(norm->domain, norm->obstacles);
      const BendRouter router(norm->domain, norm->obstacles);
      const Box& d = norm->domain;
      std::vector<std::pair<Point, Point>> pairs;
      std::vector<Point> vertices;
      for (const Polygon& p : norm->obstacles) {
        vertices.insert(vertices.end(), p.outer.begin(), p.outer.end());
        for (const Ring& h : p.holes) vertices.insert(vertices.end(), h.begin(), h.end());
      }
      std::sort(vertices.begin(), vertices.end());
      std::vector<Point> pinches;  // listed twice: a ring touches itself or another there
      for (std::size_t i = 0; i + 1 < vertices.size(); ++i)
        if (vertices[i] == vertices[i + 1]) pinches.push_back(vertices[i]);
      auto pick = [&]() -> Point {
        if (!pinches.empty() && rng() % 6 == 0) return pinches[rng() % pinches.size()];
        if (!vertices.empty() && rng() % 4 == 0) return vertices[rng() % vertices.size()];
        Point p{d.lo.x + static_cast<geom::Coord>(rng() % static_cast<std::uint64_t>(d.hi.x - d.lo.x + 1)),
                d.lo.y + static_cast<geom::Coord>(rng() % static_cast<std::uint64_t>(d.hi.y - d.lo.y + 1))};
        if (rng() % 2 == 0) p.x -= (p.x - d.lo.x) % 10;  // on cell lines: edges, corners, pinches
        if (rng() % 2 == 0) p.y -= (p.y - d.lo.y) % 10;
        return p;
      };
      for (int q = 0; q < sanitized_share(60, 3); ++q) pairs.push_back({pick(), pick()});
      const std::string head = std::string(name) + " crop " + describe(d, norm->obstacles) + "\n";
      const std::string r2 = check_pairs(ref, router, pairs, tally, head);
      if (!r2.empty() && failed++ < 3) ADD_FAILURE() << r2;
      ++crops;
    }
  }
  EXPECT_EQ(failed, 0);
  std::printf("%d crops, %lld queries (%lld Ok, %lld not free, %lld unreachable), %lld pairs at a pinch, %lld where the metric matters\n",
              crops, static_cast<long long>(tally.queries), static_cast<long long>(tally.ok), static_cast<long long>(tally.not_free),
              static_cast<long long>(tally.unreachable), static_cast<long long>(tally.pinch_ends),
              static_cast<long long>(tally.metric_matters));
  EXPECT_GE(tally.ok, tally.queries / 4);
  EXPECT_GE(tally.pinch_ends, sanitized_share(20, 5));
  EXPECT_GE(tally.with_bends, tally.ok / 2);
}

// ---------------------------------------------------------------------------------------------
// rectilinear_cover on random triangles, with 1, 2, 3 and 16 pieces per sloped edge: the
// normalized union of the cover has only horizontal and vertical edges and contains every
// triangle (every lattice point in or on a triangle, and every unit cell centre inside one, is in
// the closed union: checked on coordinates doubled so the centres are lattice points, with the
// union reference of oracle/union_oracle.h); it lies inside the one-box-per-edge cover (pieces =
// 1) and is often smaller; every triangle is reported as covered; and the router, built on the
// cover, agrees with the reference.

TEST(BendRouter, RectilinearCoverContainsTheTriangles) {
  Tally tally;
  int failed = 0;
  i64 points_checked = 0, finer = 0;
  const int count = static_cast<int>(sanitized_share(300, 6));
  for (int it = 0; it < count; ++it) {
    const unsigned seed = 5200 + static_cast<unsigned>(it);
    SCOPED_TRACE("triangles seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    const Box domain{{0, 0}, {12, 12}};
    const std::vector<Polygon> tris = random_triangles(rng, domain, 4);
    std::vector<Polygon> coarse;  // pieces = 1, doubled
    i64 coarse_points = 0;
    for (const int pieces : {1, 2, 3, 16}) {
      SCOPED_TRACE("pieces " + std::to_string(pieces));
      std::vector<std::size_t> covered;
      const std::vector<Polygon> cover = router::rectilinear_cover(tris, &covered, pieces);
      std::vector<std::size_t> all(tris.size());
      for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
      ASSERT_EQ(covered, all);  // every triangle has a sloped edge
      const auto norm = geom::normalize_obstacles(cover, domain);
      for (const Polygon& p : norm.obstacles) {
        auto straight = [](const Ring& r) {
          for (std::size_t i = 0; i < r.size(); ++i)
            if (r[i].x != r[(i + 1) % r.size()].x && r[i].y != r[(i + 1) % r.size()].y) return false;
          return true;
        };
        ASSERT_TRUE(straight(p.outer)) << "a sloped outer edge in " << describe(norm.domain, norm.obstacles);
        for (const Ring& h : p.holes) ASSERT_TRUE(straight(h)) << "a sloped hole edge in " << describe(norm.domain, norm.obstacles);
      }
      std::vector<Polygon> doubled;
      for (const Polygon& p : norm.obstacles) doubled.push_back(oracle::scaled(p, 2));
      for (const Polygon& t : tris) {
        const Polygon t2 = oracle::scaled(t, 2);
        for (int y = 0; y <= 24; ++y)
          for (int x = 0; x <= 24; ++x) {
            const geom::Location l = geom::locate(Point{x, y}, t2);
            // Lattice points (even, even) in or on the triangle; other points strictly inside.
            const bool must = (x % 2 == 0 && y % 2 == 0) ? l != geom::Location::Outside : l == geom::Location::Inside;
            if (!must) continue;
            ++points_checked;
            ASSERT_TRUE(oracle::in_obstacles({x, y}, doubled)) << "(" << x << "/2, " << y << "/2) of a triangle is not covered";
          }
      }
      // inside the coarse cover, and how much of the half-lattice it covers
      i64 points = 0;
      for (int y = -2; y <= 26; ++y)
        for (int x = -2; x <= 26; ++x) {
          if (!oracle::in_obstacles({x, y}, doubled)) continue;
          ++points;
          if (pieces > 1) {
            ASSERT_TRUE(oracle::in_obstacles({x, y}, coarse)) << "(" << x << "/2, " << y << "/2) is outside the coarse cover";
          }
        }
      if (pieces == 1) coarse = doubled, coarse_points = points;
      if (pieces == 16) finer += points < coarse_points;
      if (pieces != std::vector<int>{1, 2, 3, 16}[static_cast<std::size_t>(it) % 4]) continue;
      // The router takes the cover, and agrees with the reference on it.
      const BendReference ref(norm.domain, norm.obstacles);
      const BendRouter router(norm.domain, norm.obstacles);
      std::vector<std::pair<Point, Point>> pairs;
      auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
      for (int q = 0; q < 3; ++q) pairs.push_back({{uni(0, 12), uni(0, 12)}, {uni(0, 12), uni(0, 12)}});
      const std::string r = check_pairs(ref, router, pairs, tally, "seed " + std::to_string(seed) + ": " + describe(norm.domain, norm.obstacles) + "\n");
      if (!r.empty() && failed++ < 3) ADD_FAILURE() << r;
    }
  }
  std::printf("%d layouts of triangles, %lld points checked, the 16-piece cover smaller than the one-box cover in %lld\n",
              count, static_cast<long long>(points_checked), static_cast<long long>(finer));
  EXPECT_EQ(failed, 0);
  EXPECT_GT(points_checked, count * 80);
  EXPECT_GT(finer, count / 2);
  EXPECT_GT(tally.ok, count);
}

}  // namespace bend_router_test
}  // namespace taut::test
