// router::BasicRouter::tree (one source pin, several sink pins, a shortest-path tree) and
// router::without_overlaps against brute force, for L1Router and OctRouter.
//
// Trees: the layouts and query candidates of tests/support/wavefront_cases.h (one in four a larger
// layout); pins are candidates or small shapes there (pin_test.cpp's idea), sinks sometimes equal
// to the source or another sink, on a shortest path of another sink, not free or walled off. The
// reference (oracle::L1Reference / OctilinearReference) gives each sink's least distance over
// every pair of free integer points of the two closed pins, hence the status and failed sink. An
// Ok tree's wires are checked on their own: rectilinear (L1) or octilinear, allowed in free space
// (the reference's path check), no two segments overlapping along a positive length, total length
// between the largest distance and the sum; and a Dijkstra along the wires from the source pin
// reaches every sink at exactly its distance (connected, and a shortest-path tree). Its graph
// splits the segments at every wire vertex, integer crossing and pin point on them, with one node
// per wedge at a pinch: a path may not pass there from one wedge to another, which per-wire path
// checks cannot see once without_overlaps has cut the staircases into pieces.
//
// without_overlaps: random axis/45-degree polylines on a 0..12 grid against a unit-step brute
// force (a step is kept iff no earlier segment covered it), and hand cases.
//
// TAUT_TREE_SEED=N runs only seed N of each tree test, printing the instance and every answer.
#include "router/l1_router.h"
#include "router/oct_router.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numeric>
#include <optional>
#include <queue>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "geom/predicates.h"
#include "geom/root2.h"
#include "oracle/l1_oracle.h"
#include "oracle/oct_oracle.h"
#include "support/sanitized.h"
#include "support/wavefront_cases.h"

namespace tree_test {

using taut::geom::Box;
using taut::geom::Point;
using taut::geom::Polygon;
using taut::geom::Root2;
using taut::oracle::L1Reference;
using taut::oracle::Metric;
using taut::oracle::OctilinearReference;
using taut::router::L1Router;
using taut::router::OctRouter;
using taut::router::WireStatus;
using i64 = std::int64_t;
using Wires = std::vector<std::vector<Point>>;
using Seg = std::pair<Point, Point>;

// Hand-written range mapping (no std distributions: a seed means the same instance everywhere).
struct Rand {
  std::mt19937_64 e;
  explicit Rand(std::uint64_t seed) : e(seed) {}
  int range(int lo, int hi) { return lo + static_cast<int>(e() % static_cast<std::uint64_t>(hi - lo + 1)); }
  bool chance(int percent) { return static_cast<int>(e() % 100) < percent; }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[static_cast<std::size_t>(e() % v.size())]; }
};

Root2 r2(i64 v) { return {v, 0}; }
Root2 r2(Root2 v) { return v; }

std::string str(Point p) { return "{" + std::to_string(p.x) + ", " + std::to_string(p.y) + "}"; }
std::string str(const std::vector<Point>& ps) {
  std::string s;
  for (const Point p : ps) s += (s.empty() ? "{" : ", ") + str(p);
  return s + "}";
}
std::string str(const Polygon& p) {
  std::string s = "Polygon{" + str(p.outer) + ", {";
  for (std::size_t i = 0; i < p.holes.size(); ++i) s += (i ? ", " : "") + str(p.holes[i]);
  return s + "}}";
}
std::string str(const std::optional<Root2>& v) {
  std::ostringstream os;
  v ? os << *v : os << "none";
  return os.str();
}

bool in_pin(Point p, const Polygon& pin) {
  return pin.outer.size() == 1 ? p == pin.outer[0] : taut::geom::locate(p, pin) != taut::geom::Location::Outside;
}

std::vector<Point> integer_points(const Polygon& pin) {
  Box b{pin.outer[0], pin.outer[0]};
  for (const Point v : pin.outer)
    b = {{std::min(b.lo.x, v.x), std::min(b.lo.y, v.y)}, {std::max(b.hi.x, v.x), std::max(b.hi.y, v.y)}};
  std::vector<Point> out;
  for (int x = b.lo.x; x <= b.hi.x; ++x)
    for (int y = b.lo.y; y <= b.hi.y; ++y)
      if (in_pin({x, y}, pin)) out.push_back({x, y});
  return out;
}

// A point pin, or (shape) a small rectangle, diamond, 45-degree triangle or L-shape at c.
Polygon random_pin(Rand& r, Point c, bool shape) {
  if (!shape) return Polygon{{c}, {}};
  const int k = r.range(1, 3), h = r.range(1, 3), sx = r.chance(50) ? k : -k, sy = r.chance(50) ? k : -k;
  switch (r.range(1, 4)) {
    case 1: return Polygon{{c, {c.x + k, c.y}, {c.x + k, c.y + h}, {c.x, c.y + h}}, {}};
    case 2: return Polygon{{{c.x - k, c.y}, {c.x, c.y - k}, {c.x + k, c.y}, {c.x, c.y + k}}, {}};
    case 3: return Polygon{{c, {c.x + sx, c.y}, {c.x, c.y + sy}}, {}};
    default:
      return Polygon{{c, {c.x + 2, c.y}, {c.x + 2, c.y + 1}, {c.x + 1, c.y + 1}, {c.x + 1, c.y + 2}, {c.x, c.y + 2}}, {}};
  }
}

bool octilinear(Point a, Point b) {
  const i64 dx = std::abs(i64{b.x} - a.x), dy = std::abs(i64{b.y} - a.y);
  return dx == 0 || dy == 0 || dx == dy;
}

// Segments ab and cd lie on one line and share a positive length (exact).
bool overlap(Seg s, Seg t) {
  using taut::geom::dot;
  const auto [a, b] = s;
  const auto [c, d] = t;
  if (a == b || c == d || taut::geom::orient(a, b, c) != 0 || taut::geom::orient(a, b, d) != 0) return false;
  const i64 u = dot(a, b, a, c), v = dot(a, b, a, d);
  return std::min(dot(a, b, a, b), std::max(u, v)) > std::max<i64>(0, std::min(u, v));
}

// Every pair of overlapping segments, as text.
std::string overlaps(const std::vector<Seg>& segs) {
  std::string out;
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j)
      if (overlap(segs[i], segs[j]))
        out += "segments " + str(segs[i].first) + "-" + str(segs[i].second) + " and " + str(segs[j].first) + "-" +
               str(segs[j].second) + " overlap\n";
  return out;
}

// The crossing of segments ab and cd when they are not parallel and meet at an integer point.
std::optional<Point> integer_crossing(Seg s, Seg t) {
  const auto [a, b] = s;
  const auto [c, d] = t;
  const i64 rx = i64{b.x} - a.x, ry = i64{b.y} - a.y, sx = i64{d.x} - c.x, sy = i64{d.y} - c.y;
  const i64 qx = i64{c.x} - a.x, qy = i64{c.y} - a.y;
  i64 den = rx * sy - ry * sx, tn = qx * sy - qy * sx, un = qx * ry - qy * rx;
  if (den < 0) den = -den, tn = -tn, un = -un;
  if (den == 0 || tn < 0 || tn > den || un < 0 || un > den || (rx * tn) % den || (ry * tn) % den) return std::nullopt;
  return Point{static_cast<int>(a.x + rx * tn / den), static_cast<int>(a.y + ry * tn / den)};
}

// Least length along the wires from the source pin to each sink pin (nullopt: not connected).
// Nodes: wire vertices, integer crossings of segments and the pins' integer points on segments
// (where a wire passes through a pin: integer, as a wire segment and a pin edge are never both
// diagonal), one node per wedge at a pinch; edges: the pieces of the segments between nodes; the
// source pin joins every node in it; a sink touching the source (`touch`) is at 0.
struct Metal {
  std::vector<std::optional<Root2>> dist;
  int branch_points = 0, pinch_points = 0;  // nodes where >= 3 pieces meet; points at a pinch
};
template <class Reference>
Metal metal_distances(const Reference& ref, Metric metric, const Wires& wires, const Polygon& source,
                      const std::vector<Polygon>& sinks, const std::vector<bool>& touch) {
  Metal m;
  std::vector<Seg> segs;
  std::set<Point> pts;
  for (const auto& w : wires) {
    pts.insert(w.begin(), w.end());
    for (std::size_t i = 0; i + 1 < w.size(); ++i)
      if (w[i] != w[i + 1]) segs.push_back({w[i], w[i + 1]});
  }
  std::vector<Point> pin_points = integer_points(source);
  for (const Polygon& s : sinks)
    for (const Point p : integer_points(s)) pin_points.push_back(p);
  for (const Point p : pin_points)
    for (const auto& [a, b] : segs)
      if (taut::geom::on_segment(p, a, b)) pts.insert(p);
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j)
      if (const auto p = integer_crossing(segs[i], segs[j])) pts.insert(*p);
  std::map<Point, std::size_t> base;
  std::map<Point, std::vector<taut::oracle::Wedge>> pinch;
  std::vector<Point> at;
  for (const Point p : pts) {
    base[p] = at.size();
    auto ws = ref.wedges_at(p);
    at.insert(at.end(), ws.size() >= 2 ? ws.size() : 1, p);
    if (ws.size() >= 2) pinch[p] = std::move(ws), ++m.pinch_points;
  }
  auto node = [&](Point p, Point toward) {  // the copy of p whose wedge holds the direction
    const std::size_t b = base.at(p);
    if (const auto it = pinch.find(p); it != pinch.end())
      for (std::size_t j = 0; j < it->second.size(); ++j)
        if (it->second[j].contains(i64{toward.x} - p.x, i64{toward.y} - p.y)) return b + j;
    return b;
  };
  const std::size_t hub = at.size();
  std::vector<std::vector<std::pair<std::size_t, Root2>>> adj(hub + 1);
  for (const auto& [a, b] : segs) {
    std::vector<Point> on;
    for (const Point p : pts)
      if (taut::geom::on_segment(p, a, b)) on.push_back(p);
    std::sort(on.begin(), on.end(),
              [&](Point p, Point q) { return taut::geom::dot(a, b, a, p) < taut::geom::dot(a, b, a, q); });
    for (std::size_t i = 0; i + 1 < on.size(); ++i) {
      const std::size_t u = node(on[i], on[i + 1]), v = node(on[i + 1], on[i]);
      const Root2 len = taut::oracle::segment_length(metric, on[i], on[i + 1]);
      adj[u].push_back({v, len});
      adj[v].push_back({u, len});
    }
  }
  for (std::size_t u = 0; u < hub; ++u) {
    m.branch_points += adj[u].size() >= 3;
    if (in_pin(at[u], source)) adj[hub].push_back({u, Root2{}});
  }
  std::vector<std::optional<Root2>> dist(hub + 1);
  using Item = std::pair<Root2, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
  q.push({*(dist[hub] = Root2{}), hub});
  while (!q.empty()) {
    const auto [d, u] = q.top();
    q.pop();
    if (d != *dist[u]) continue;
    for (const auto& [v, w] : adj[u])
      if (!dist[v] || d + w < *dist[v]) q.push({*(dist[v] = d + w), v});
  }
  m.dist.resize(sinks.size());
  for (std::size_t i = 0; i < sinks.size(); ++i) {
    if (touch[i]) m.dist[i] = Root2{};
    for (std::size_t u = 0; u < hub; ++u)
      if (dist[u] && in_pin(at[u], sinks[i]) && (!m.dist[i] || *dist[u] < *m.dist[i])) m.dist[i] = dist[u];
  }
  return m;
}

struct Tally {
  std::map<std::string, i64> n;  // what the nets exercised, by name
  i64 failures = 0;
  std::vector<std::uint64_t> failed_seeds;
};

// One net against the reference; "" when everything agrees, else what differs.
template <class Router, class Reference>
std::string check_tree(const Reference& ref, Router& router, const Polygon& source, const std::vector<Polygon>& sinks,
                       Tally& t, bool verbose) {
  constexpr Metric metric = Router::kOctilinear ? Metric::Octilinear : Metric::L1;
  const std::size_t k = sinks.size();
  auto free_points = [&](const Polygon& p) {
    std::vector<Point> out;
    for (const Point q : integer_points(p))
      if (ref.is_free(q)) out.push_back(q);
    return out;
  };
  // The reference, statuses in the router's order: the source, the sinks' freedom, then reach.
  const std::vector<Point> src = free_points(source);
  std::vector<Point> targets;
  std::vector<std::size_t> owner;
  WireStatus want = src.empty() ? WireStatus::SourceNotFree : WireStatus::Ok;
  std::optional<std::size_t> want_failed;
  for (std::size_t i = 0; i < k; ++i) {
    const std::vector<Point> f = free_points(sinks[i]);
    if (f.empty() && want == WireStatus::Ok) want = WireStatus::TargetNotFree, want_failed = i;
    for (const Point p : f) targets.push_back(p), owner.push_back(i);
  }
  std::vector<std::optional<Root2>> best(k);
  for (const Point p : src) {
    const auto ds = ref.distances(p, targets);
    for (std::size_t j = 0; j < ds.size(); ++j)
      if (ds[j] && (!best[owner[j]] || r2(*ds[j]) < *best[owner[j]])) best[owner[j]] = r2(*ds[j]);
  }
  for (std::size_t i = 0; i < k && want == WireStatus::Ok; ++i)
    if (!best[i]) want = WireStatus::Unreachable, want_failed = i;

  const auto tr = router.tree(source, sinks);
  auto given = [&](std::size_t i) {  // the router's distance to sink i, as Root2
    return i < tr.distance.size() && tr.distance[i] ? std::optional(r2(*tr.distance[i])) : std::nullopt;
  };
  if (verbose) {
    std::printf("  source %s\n", str(source).c_str());
    for (std::size_t i = 0; i < k; ++i)
      std::printf("  sink %zu %s: reference %s, router %s\n", i, str(sinks[i]).c_str(), str(best[i]).c_str(),
                  str(given(i)).c_str());
    std::printf("  status %s (reference %s), failed %s\n", taut::router::to_string(tr.status),
                taut::router::to_string(want), tr.failed ? std::to_string(*tr.failed).c_str() : "-");
    for (const auto& w : tr.wires) std::printf("  wire %s\n", str(w).c_str());
  }
  ++t.n["trees"];
  ++t.n[taut::router::to_string(want)];
  t.n["sinks"] += static_cast<i64>(k);
  t.n["shape sources"] += source.outer.size() > 1;
  for (const Polygon& s : sinks) t.n["shape sinks"] += s.outer.size() > 1;
  std::ostringstream bad;
  if (tr.status == WireStatus::NoIntegerStaircase && want == WireStatus::Ok) {
    ++t.n["no integer staircase"];  // legitimate with sloped blockages; counted, not failed
    if (!tr.failed || *tr.failed >= k) bad << "NoIntegerStaircase without a valid failed sink\n";
  } else if (tr.status != want) {
    bad << "status " << taut::router::to_string(tr.status) << ", reference " << taut::router::to_string(want)
        << (want_failed ? " for sink " + std::to_string(*want_failed) : "") << "\n";
  } else if (tr.failed != want_failed) {
    bad << "failed sink " << (tr.failed ? std::to_string(*tr.failed) : "none") << ", reference "
        << (want_failed ? std::to_string(*want_failed) : "none") << "\n";
  }
  // Every distance given is exact; an Ok tree gives them all.
  if ((tr.status == WireStatus::Ok || !tr.distance.empty()) && tr.distance.size() != k)
    bad << tr.distance.size() << " distances for " << k << " sinks\n";
  for (std::size_t i = 0; i < k && tr.distance.size() == k; ++i)
    if (given(i) ? given(i) != best[i] : tr.status == WireStatus::Ok)
      bad << "sink " << i << " distance " << str(given(i)) << ", reference " << str(best[i]) << "\n";
  if (tr.status != WireStatus::Ok || want != WireStatus::Ok || !bad.str().empty()) return bad.str();

  // The wires on their own.
  std::vector<bool> touch(k);
  for (std::size_t i = 0; i < k; ++i) t.n["touching sinks"] += touch[i] = best[i] == Root2{};
  if (std::all_of(touch.begin(), touch.end(), [](bool b) { return b; }) &&
      (tr.wires.size() != 1 || tr.wires[0].size() != 1 || !in_pin(tr.wires[0][0], source)))
    bad << "every sink touches the source: expected one wire of one point of the source\n";
  if (tr.wires.empty()) bad << "no wires\n";
  std::vector<Seg> segs;
  Root2 total, sum, most;
  for (std::size_t w = 0; w < tr.wires.size(); ++w) {
    const auto& wire = tr.wires[w];
    for (std::size_t i = 0; i + 1 < wire.size(); ++i) {
      const Point a = wire[i], b = wire[i + 1];
      if (Router::kOctilinear ? !octilinear(a, b) : a.x != b.x && a.y != b.y)
        bad << "wire " << w << " segment " << str(a) << "-" << str(b) << " has a wrong direction\n";
      total += taut::oracle::segment_length(metric, a, b);
      if (a != b) segs.push_back({a, b});
    }
    bool allowed = false;
    if constexpr (Router::kOctilinear)
      allowed = ref.check_octilinear_path(wire).has_value();
    else
      allowed = ref.check_path(wire).has_value();
    if (!allowed) bad << "wire " << w << " " << str(wire) << " is not allowed in free space\n";
  }
  bad << overlaps(segs);
  for (const auto& b : best) sum += *b, most = std::max(most, *b);
  if (total > sum || total < most) bad << "total length " << total << " outside [" << most << ", " << sum << "]\n";
  const Metal metal = metal_distances(ref, metric, tr.wires, source, sinks, touch);
  for (std::size_t i = 0; i < k; ++i)
    if (metal.dist[i] != best[i])
      bad << "sink " << i << " along the wires " << str(metal.dist[i]) << ", distance " << str(best[i]) << "\n";
  t.n["branched trees"] += metal.branch_points > 0;
  t.n["trees through a pinch"] += metal.pinch_points > 0;
  t.n["sharing trees"] += total < sum;
  return bad.str();
}

// Three nets on the layout of `seed` (layouts of at most 160 x 160, not scaled up).
template <class Router, class Reference>
void run_seed(std::uint64_t seed, Tally& t, bool verbose) {
  const taut::test::WavefrontCase wc = taut::test::make_wavefront_case(seed);
  const Box& d = wc.domain;
  if (wc.huge || wc.candidates.empty() || i64{d.hi.x} - d.lo.x > 160 || i64{d.hi.y} - d.lo.y > 160) return;
  const Reference ref(wc.domain, wc.obstacles);
  Router router(wc.domain, wc.obstacles);
  ++t.n["seeds"];
  if (verbose) {
    std::printf("seed %llu family %s domain {%s, %s}\n", static_cast<unsigned long long>(seed), wc.family.c_str(),
                str(d.lo).c_str(), str(d.hi).c_str());
    for (const Polygon& o : wc.obstacles) std::printf("  obstacle %s\n", str(o).c_str());
  }
  std::vector<Point> free_c;
  for (const Point c : wc.candidates)
    if (ref.is_free(c)) free_c.push_back(c);
  std::vector<Point> pinches;  // obstacle vertices where parts of obstacles touch
  for (const Polygon& o : wc.obstacles)
    for (std::size_t i = 0; i <= o.holes.size(); ++i)
      for (const Point v : i ? o.holes[i - 1] : o.outer)
        if (ref.wedges_at(v).size() >= 2) pinches.push_back(v);
  Rand r(seed * 0x9E3779B97F4A7C15ULL + 12345);
  auto make_pin = [&](Point c, bool shape) {  // a shape the router takes, else the point
    for (int attempt = 0; shape && attempt < 6; ++attempt) {
      const Polygon p = random_pin(r, c, true);
      if (std::all_of(p.outer.begin(), p.outer.end(),
                      [&](Point v) { return v.x >= d.lo.x && v.x <= d.hi.x && v.y >= d.lo.y && v.y <= d.hi.y; }) &&
          taut::router::pin_shape_supported(p) && !router.pin_meets_obstacle(p))
        return p;
    }
    return Polygon{{c}, {}};
  };
  auto draw = [&](int any_percent) {  // a free candidate, or any_percent of the time any candidate
    return free_c.empty() || r.chance(any_percent) ? r.pick(wc.candidates) : r.pick(free_c);
  };
  auto a_free_point = [&](const Polygon& p) -> std::optional<Point> {
    for (const Point q : integer_points(p))
      if (ref.is_free(q)) return q;
    return std::nullopt;
  };
  for (int q = 0; q < 3; ++q) {
    const Polygon source = make_pin(draw(4), r.chance(15));
    std::vector<Point> near;  // free candidates reachable from the source (most sinks are)
    if (const auto s = a_free_point(source)) {
      const auto ds = ref.distances(*s, free_c);
      for (std::size_t i = 0; i < ds.size(); ++i)
        if (ds[i]) near.push_back(free_c[i]);
    }
    std::vector<Polygon> sinks;
    for (const int k = r.range(2, 8); static_cast<int>(sinks.size()) < k;) {
      const int kind = r.range(0, 99);
      if (kind < 10) {
        sinks.push_back(kind < 5 || sinks.empty() ? source : r.pick(sinks)), ++t.n["repeated sinks"];
      } else if (kind < 20 && !pinches.empty()) {  // near a pinch: paths may branch there
        const Point v = r.pick(pinches), p{v.x + r.range(-8, 8), v.y + r.range(-8, 8)};
        if (ref.is_free(p)) sinks.push_back(Polygon{{p}, {}}), ++t.n["sinks near a pinch"];
      } else if (kind < 40 && !sinks.empty()) {  // a lattice point on a shortest path to another sink
        const auto s = a_free_point(source), e = a_free_point(r.pick(sinks));
        const auto path = s && e ? ref.path(*s, *e) : std::nullopt;
        std::vector<Point> on;
        for (std::size_t i = 0; path && i + 1 < path->size(); ++i) {
          const Point a = (*path)[i], b = (*path)[i + 1];
          const int dx = b.x - a.x, dy = b.y - a.y, g = std::gcd(dx, dy);
          for (int j = 0; g > 0 && j <= g; ++j) on.push_back({a.x + dx / g * j, a.y + dy / g * j});
        }
        if (!on.empty()) sinks.push_back(make_pin(r.pick(on), r.chance(10))), ++t.n["sinks on a path"];
      } else {
        sinks.push_back(make_pin(near.empty() || r.chance(12) ? draw(25) : r.pick(near), r.chance(15)));
      }
    }
    if (verbose) std::printf(" net %d\n", q);
    const std::string bad = check_tree<Router, Reference>(ref, router, source, sinks, t, verbose);
    if (bad.empty()) continue;
    if (t.failed_seeds.empty() || t.failed_seeds.back() != seed) t.failed_seeds.push_back(seed);
    if (++t.failures > 5) continue;
    std::string net = "source " + str(source) + "\nsinks:\n";
    for (const Polygon& s : sinks) net += "  " + str(s) + "\n";
    ADD_FAILURE() << "seed " << seed << " (family " << wc.family << ", net " << q
                  << "; rerun with TAUT_TREE_SEED=" << seed << ")\n" << net << bad;
  }
}

// The regression seeds and `trees` nets (an eighth under the sanitizers), or only seed
// TAUT_TREE_SEED verbosely; then floors on what the generator exercised (about half of what it
// does), scaled likewise.
template <class Router, class Reference>
void run_trees(i64 trees, const char* name, const std::vector<std::pair<std::string, i64>>& floors,
               const std::vector<std::uint64_t>& regression = {}) {
  Tally t;
  if (const char* s = std::getenv("TAUT_TREE_SEED"))
    return run_seed<Router, Reference>(std::strtoull(s, nullptr, 10), t, true);
  const auto t0 = std::chrono::steady_clock::now();
  for (const std::uint64_t seed : regression) run_seed<Router, Reference>(seed, t, false);
  for (std::uint64_t i = 1; t.n["trees"] < taut::test::sanitized_share(trees, 4) && i < 20000; ++i)
    run_seed<Router, Reference>(i % 4 == 0 ? taut::test::kLargeSeedBase + i : i, t, false);
  std::printf("%s (%.2f s):", name, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  for (const auto& [what, count] : t.n) std::printf(" %s %lld,", what.c_str(), static_cast<long long>(count));
  std::string seeds;
  for (const auto s : t.failed_seeds) seeds += " " + std::to_string(s);
  std::printf("\n");
  EXPECT_EQ(t.failures, 0) << "failing seeds:" << seeds;
  for (const auto& [what, floor] : floors) EXPECT_GE(t.n[what], taut::test::sanitized_share(floor, 4)) << what;
}

TEST(Tree, L1TreesMatchReference) {
  run_trees<L1Router, L1Reference>(
      6000, "L1",
      {{"trees", 6000}, {"ok", 2600}, {"unreachable", 300}, {"target not free", 50}, {"source not free", 15},
       {"shape sinks", 1500}, {"shape sources", 300}, {"touching sinks", 2000}, {"sinks on a path", 1900},
       {"repeated sinks", 1400}, {"branched trees", 1600}, {"sharing trees", 2200}, {"trees through a pinch", 600},
       {"sinks near a pinch", 450}},
      {12281});  // a branch point at a pinch (Tree.BranchPointAtPinch)
}

TEST(Tree, OctilinearTreesMatchReference) {
  run_trees<OctRouter, OctilinearReference>(
      2000, "octilinear",
      {{"trees", 2000}, {"ok", 850}, {"unreachable", 100}, {"target not free", 15}, {"source not free", 5},
       {"shape sinks", 350}, {"shape sources", 70}, {"touching sinks", 650}, {"sinks on a path", 650},
       {"repeated sinks", 450}, {"branched trees", 500}, {"sharing trees", 700}, {"trees through a pinch", 150},
       {"sinks near a pinch", 150}});
}

// Branch points at a pinch (found by the random test): two sinks' shortest paths share the
// prefix to an obstacle vertex where two parts of one obstacle touch and go on inside the wedge
// they arrived in; so must the wires.
TEST(Tree, BranchPointAtPinch) {
  struct Case {
    Polygon obstacle;
    Point source;
    std::vector<Point> sinks;
  };
  const std::vector<Case> cases = {
      // Three triangles in a row touching at (20, 60) and (40, 80): (40, 73) is reached around
      // the top one's right side, (0, 50) on past it.
      {Polygon{{{0, 60}, {20, 60}, {40, 60}, {40, 80}, {50, 90}, {40, 90}, {40, 80}, {20, 60}, {0, 80}}, {}},
       {40, 90},
       {{0, 50}, {40, 73}}},
      // A triangle hanging at (70, 60) from a larger body; the source is in the pocket between.
      {Polygon{{{40, 20}, {60, 30}, {60, 40}, {70, 60}, {70, 50}, {90, 50}, {70, 60}, {50, 60}, {40, 40}}, {}},
       {70, 59},
       {{53, 86}, {60, 100}}},
  };
  const Box dom{{0, 0}, {100, 100}};
  for (const Case& c : cases) {
    const std::vector<Polygon> obs{c.obstacle};
    std::vector<Polygon> sinks;
    for (const Point p : c.sinks) sinks.push_back(Polygon{{p}, {}});
    Tally t;
    const L1Reference l1_ref(dom, obs);
    L1Router l1(dom, obs);
    EXPECT_EQ((check_tree<L1Router, L1Reference>(l1_ref, l1, Polygon{{c.source}, {}}, sinks, t, false)), "")
        << "L1, source " << str(c.source);
    const OctilinearReference oct_ref(dom, obs);
    OctRouter oct(dom, obs);
    EXPECT_EQ((check_tree<OctRouter, OctilinearReference>(oct_ref, oct, Polygon{{c.source}, {}}, sinks, t, false)), "")
        << "octilinear, source " << str(c.source);
    EXPECT_EQ(t.n["ok"], 2);
  }
}

// ---- without_overlaps -------------------------------------------------------------------

using Step = Seg;  // a directed unit step (axis or diagonal)

std::vector<Step> steps(Point a, Point b) {
  const int dx = b.x - a.x, dy = b.y - a.y, n = std::max(std::abs(dx), std::abs(dy));
  std::vector<Step> out;
  for (int i = 0; i < n; ++i)
    out.push_back({{a.x + dx / n * i, a.y + dy / n * i}, {a.x + dx / n * (i + 1), a.y + dy / n * (i + 1)}});
  return out;
}
Step undirected(Step s) { return s.first < s.second ? s : Step{s.second, s.first}; }
Root2 length(Point a, Point b) { return taut::geom::octilinear_length(i64{b.x} - a.x, i64{b.y} - a.y); }

// "" when `out` is what without_overlaps(in) must be, else what is wrong: the union kept, no
// overlap, every step in the direction of its first cover, each piece's steps kept steps of one
// input wire in its order (a piece may go on where a lost there-and-back ends where it began).
std::string check_without_overlaps(const Wires& in, const Wires& out) {
  std::map<Step, Step> first;                                 // undirected step -> first direction
  std::map<Step, std::pair<std::size_t, std::size_t>> where;  // kept step -> (wire, index in it)
  for (std::size_t w = 0; w < in.size(); ++w)
    for (std::size_t i = 0, n = 0; i + 1 < in[w].size(); ++i)
      for (const Step& s : steps(in[w][i], in[w][i + 1]))
        if (first.emplace(undirected(s), s).second) where[s] = {w, n++};
  std::ostringstream bad;
  std::map<Step, int> seen;
  std::vector<Seg> segs;
  Root2 total, union_length;
  for (const auto& [u, s] : first) union_length += length(s.first, s.second);
  for (const auto& piece : out) {
    if (std::all_of(piece.begin(), piece.end(), [&](Point p) { return p == piece[0]; }))
      bad << "piece " << str(piece) << " has fewer than 2 distinct points\n";
    std::optional<std::pair<std::size_t, std::size_t>> prev;
    for (std::size_t i = 0; i + 1 < piece.size(); ++i) {
      if (!octilinear(piece[i], piece[i + 1])) {
        bad << "piece " << str(piece) << " has a segment at another angle\n";
        continue;
      }
      if (piece[i] != piece[i + 1]) segs.push_back({piece[i], piece[i + 1]});
      total += length(piece[i], piece[i + 1]);
      for (const Step& s : steps(piece[i], piece[i + 1])) {
        ++seen[undirected(s)];
        const auto it = where.find(s);
        if (it == where.end())
          bad << "piece " << str(piece) << ": step " << str(s.first) << "->" << str(s.second)
              << (first.count(undirected(s)) ? " runs against the input's direction\n" : " is not in the input\n");
        else if (prev && (it->second.first != prev->first || it->second.second <= prev->second))
          bad << "piece " << str(piece) << " is not a part of one input wire at " << str(s.first) << "\n";
        prev = it == where.end() ? std::nullopt : std::optional(it->second);
      }
    }
  }
  for (const auto& [u, s] : first)
    if (!seen.count(u)) bad << "step " << str(s.first) << "->" << str(s.second) << " of the input is lost\n";
  for (const auto& [u, n] : seen)
    if (n > 1) bad << "step " << str(u.first) << "-" << str(u.second) << " covered " << n << " times\n";
  bad << overlaps(segs);
  if (total != union_length) bad << "output length " << total << ", union " << union_length << "\n";
  return bad.str();
}

// Polylines on the 0..12 grid, often starting at an earlier wire's vertex, with spikes (a
// segment back along the previous one), straight continuations and one-point wires.
Wires random_wires(Rand& r) {
  Wires ws(static_cast<std::size_t>(r.range(1, 5)));
  const int dirs[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}};
  for (std::size_t w = 0; w < ws.size(); ++w) {
    Point p{r.range(0, 12), r.range(0, 12)};
    if (w > 0 && r.chance(50)) p = r.pick(ws[static_cast<std::size_t>(r.range(0, static_cast<int>(w) - 1))]);
    ws[w] = {p};
    for (int s = 0, last = -1, segments = r.chance(5) ? 0 : r.range(1, 6); s < segments; ++s)
      for (int attempt = 0; attempt < 10; ++attempt) {
        const int dir = last >= 0 && r.chance(20) ? last ^ 1 : r.chance(40) ? r.range(0, 3) : r.range(0, 7);
        const int dx = dirs[dir][0], dy = dirs[dir][1];
        const int room = std::min(dx > 0 ? 12 - p.x : dx < 0 ? p.x : 12, dy > 0 ? 12 - p.y : dy < 0 ? p.y : 12);
        if (room == 0) continue;
        const int len = r.range(1, std::min(room, 6));
        ws[w].push_back(p = {p.x + dx * len, p.y + dy * len});
        last = dir;
        break;
      }
  }
  return ws;
}

TEST(WithoutOverlaps, HandCases) {
  const std::vector<std::pair<Wires, Wires>> cases = {  // input, output
      // Two wires leaving a common point along the same line.
      {{{{0, 0}, {5, 0}}, {{0, 0}, {8, 0}}}, {{{0, 0}, {5, 0}}, {{5, 0}, {8, 0}}}},
      // Wires fully covered by an earlier one (one along a diagonal, against its direction).
      {{{{0, 0}, {10, 0}, {10, 10}, {6, 6}}, {{2, 0}, {7, 0}}, {{9, 9}, {7, 7}}}, {{{0, 0}, {10, 0}, {10, 10}, {6, 6}}}},
      // A U-turn spike inside one wire: back down the same vertical, then on.
      {{{{0, 0}, {5, 0}, {5, 5}, {5, 2}, {9, 2}}}, {{{0, 0}, {5, 0}, {5, 5}}, {{5, 2}, {9, 2}}}},
      // A later wire along the middle of an earlier one, against its direction, is split.
      {{{{2, 3}, {2, 9}}, {{0, 8}, {2, 8}, {2, 4}, {6, 4}}}, {{{2, 3}, {2, 9}}, {{0, 8}, {2, 8}}, {{2, 4}, {6, 4}}}},
      // A one-point wire is dropped; crossing wires are kept whole.
      {{{{3, 3}}, {{0, 0}, {6, 6}}, {{0, 6}, {6, 0}}}, {{{0, 0}, {6, 6}}, {{0, 6}, {6, 0}}}},
  };
  for (const auto& [in, out] : cases) {
    const Wires got = taut::router::without_overlaps(in);
    std::string text;
    for (const auto& w : in) text += str(w) + " ";
    EXPECT_EQ(check_without_overlaps(in, got), "") << text;
    EXPECT_EQ(got, out) << text;
  }
}

TEST(WithoutOverlaps, RandomPolylinesMatchUnitSteps) {
  const i64 n = taut::test::sanitized_share(6000, 4);
  i64 overlapping = 0, split = 0, dropped = 0, failures = 0;
  for (i64 seed = 1; seed <= n; ++seed) {
    Rand r(static_cast<std::uint64_t>(seed) * 1000003ULL);
    const Wires in = random_wires(r), out = taut::router::without_overlaps(in);
    const std::string bad = check_without_overlaps(in, out);
    std::size_t in_wires = 0;
    Root2 in_length, out_length;
    for (const Wires* ws : {&in, &out})
      for (const auto& w : *ws) {
        in_wires += ws == &in && w.size() > 1;
        for (std::size_t i = 0; i + 1 < w.size(); ++i) (ws == &in ? in_length : out_length) += length(w[i], w[i + 1]);
      }
    overlapping += out_length < in_length;
    split += out.size() > in_wires;
    dropped += out.size() < in_wires;
    if (bad.empty() || ++failures > 5) continue;
    std::string s;
    for (const Wires* ws : {&in, &out}) {
      s += ws == &in ? "input:\n" : "output:\n";
      for (const auto& w : *ws) s += "  " + str(w) + "\n";
    }
    ADD_FAILURE() << "seed " << seed << ", " << s << bad;
  }
  std::printf("%lld random sets: %lld with overlaps, %lld with more pieces than wires, %lld with fewer\n",
              static_cast<long long>(n), static_cast<long long>(overlapping), static_cast<long long>(split),
              static_cast<long long>(dropped));
  EXPECT_EQ(failures, 0);
  EXPECT_GE(overlapping, n / 4);
  EXPECT_GE(split, n / 10);
  EXPECT_GE(dropped, n / 100);
}

}  // namespace tree_test
