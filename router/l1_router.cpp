#include "router/l1_router.h"

#include <algorithm>
#include <stdexcept>
#include <map>
#include <utility>

#include "geom/predicates.h"

namespace taut::router {

using geom::i64;
using geom::Point;

template <class W>
BasicRouter<W>::BasicRouter(const geom::Box& domain, std::span<const geom::Polygon> obstacles)
    : wavefront_(domain, obstacles), staircase_(domain, obstacles), pins_(obstacles, domain) {}

template <class W>
typename BasicRouter<W>::Wire BasicRouter<W>::shortest(geom::Point from, geom::Point to) {
  Wire w;
  if (!wavefront_.is_free(from)) {
    w.status = WireStatus::SourceNotFree;
    return w;
  }
  if (!wavefront_.is_free(to)) {
    w.status = WireStatus::TargetNotFree;
    return w;
  }
  wavefront_.run({&from, 1}, {&to, 1}, W::Stop::AllTargets);
  return finish(0);
}

template <class W>
typename BasicRouter<W>::Wire BasicRouter<W>::finish(std::optional<std::size_t> target) {
  Wire w;
  if (target) w.length = wavefront_.target_distance(*target);
  if (!w.length) {
    w.status = WireStatus::Unreachable;
    return w;
  }
  w.polygonal = wavefront_.target_path(*target);
  auto stairs = kOctilinear ? staircase_.octilinear(w.polygonal, &staircase_stats_)
                            : staircase_.rectilinear(w.polygonal, &staircase_stats_);
  if (!stairs) {
    w.status = WireStatus::NoIntegerStaircase;
    return w;
  }
  w.points = std::move(*stairs);
  w.status = WireStatus::Ok;
  return w;
}

namespace {
// Drops the points the wavefront does not find free.
template <class Wavefront>
void keep_free(std::vector<Point>& v, const Wavefront& wf) {
  v.erase(std::remove_if(v.begin(), v.end(), [&](Point p) { return !wf.is_free(p); }), v.end());
}
}  // namespace

template <class W>
std::optional<std::size_t> BasicRouter<W>::pin_meets_obstacle(const geom::Polygon& pin) const {
  return pins_.meets_obstacle(pin);
}

template <class W>
bool BasicRouter<W>::supports_pin(const geom::Polygon& pin) {
  if (!pin_shape_supported(pin)) return false;
  bool ok = true;
  if (kOctilinear)
    for_each_pin_edge(pin, [&](Point a, Point b) { ok = ok && (a.x == b.x || a.y == b.y); });
  return ok;
}

template <class W>
std::vector<Point> BasicRouter<W>::pin_candidates(const geom::Polygon& pin, const geom::Polygon& other) const {
  return pins_.candidates(pin, other);
}

template <class W>
typename BasicRouter<W>::Wire BasicRouter<W>::shortest(const geom::Polygon& from, const geom::Polygon& to) {
  if (is_point_pin(from) && is_point_pin(to)) return shortest(from.outer[0], to.outer[0]);
  Wire w;
  std::vector<Point> sources = pin_candidates(from, to), targets = pin_candidates(to, from);
  keep_free(sources, wavefront_);
  keep_free(targets, wavefront_);
  if (sources.empty()) {
    w.status = WireStatus::SourceNotFree;
    return w;
  }
  if (targets.empty()) {
    w.status = WireStatus::TargetNotFree;
    return w;
  }
  // Pins that share a point: a wire of one point there.
  if (const auto p = shared_point(sources, from, targets, to, [&](Point q) { return wavefront_.is_free(q); })) {
    w.length = Len{};
    w.polygonal = {*p};
    w.points = {*p};
    w.status = WireStatus::Ok;
    return w;
  }
  wavefront_.run(sources, targets, W::Stop::FirstTarget);
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const auto d = wavefront_.target_distance(i);
    if (d && (!best || *d < *wavefront_.target_distance(*best))) best = i;
  }
  return finish(best);
}

template <class W>
typename BasicRouter<W>::Steiner BasicRouter<W>::steiner(std::span<const Point> pins, std::size_t starts) {
  // Grown from each of the first `starts` pins in turn; the shortest kept (the first on ties).
  Steiner best;
  const std::size_t tries = std::max<std::size_t>(1, std::min(starts, pins.size()));
  for (std::size_t s0 = 0; s0 < tries; ++s0) {
    std::vector<Point> rotated(pins.begin() + static_cast<std::ptrdiff_t>(s0), pins.end());
    rotated.insert(rotated.end(), pins.begin(), pins.begin() + static_cast<std::ptrdiff_t>(s0));
    Steiner t = steiner_from_first(rotated);
    auto back = [&](std::size_t i) { return (i + s0) % pins.size(); };
    if (t.failed) t.failed = back(*t.failed);
    for (std::size_t& i : t.order) i = back(i);
    if (t.status == WireStatus::SourceNotFree || t.status == WireStatus::TargetNotFree || t.status == WireStatus::Unreachable)
      return t;  // a pin not free or walled in: the same from every start
    // NoIntegerStaircase depends on the paths taken: another start may do without it
    if (best.status != WireStatus::Ok && (t.status == WireStatus::Ok || s0 == 0)) best = std::move(t);
    else if (t.status == WireStatus::Ok && t.length < best.length) best = std::move(t);
  }
  return best;
}

template <class W>
typename BasicRouter<W>::Steiner BasicRouter<W>::steiner_from_first(std::span<const Point> pins) {
  Steiner t;
  if constexpr (kOctilinear) {
    throw std::logic_error("BasicRouter::steiner: rectilinear (L1) wires only");
  } else {
    if (pins.empty()) {
      t.status = WireStatus::Ok;
      return t;
    }
    for (std::size_t i = 0; i < pins.size(); ++i)
      if (!wavefront_.is_free(pins[i])) {
        t.status = i == 0 ? WireStatus::SourceNotFree : WireStatus::TargetNotFree;
        t.failed = i;
        return t;
      }
    std::vector<Point> points{pins[0]};
    std::vector<geom::Segment> segments;
    std::vector<std::size_t> left;
    for (std::size_t i = 1; i < pins.size(); ++i) left.push_back(i);
    t.order.push_back(0);
    std::vector<std::vector<Point>> wires;
    while (!left.empty()) {
      std::vector<Point> targets;
      for (const std::size_t i : left) targets.push_back(pins[i]);
      wavefront_.run(points, segments, targets, WavefrontStop::FirstTarget);
      std::optional<std::size_t> best;
      for (std::size_t j = 0; j < targets.size(); ++j) {
        const auto d = wavefront_.target_distance(j);
        if (d && (!best || *d < *wavefront_.target_distance(*best))) best = j;
      }
      if (!best) {
        t.status = WireStatus::Unreachable;
        t.failed = left.front();
        return t;
      }
      Wire w = finish(best);
      if (w.status != WireStatus::Ok) {
        t.status = w.status;
        t.failed = left[*best];
        return t;
      }
      for (std::size_t i = 1; i < w.points.size(); ++i) segments.push_back({w.points[i - 1], w.points[i]});
      if (w.points.size() >= 2) wires.push_back(std::move(w.points));
      points.push_back(pins[left[*best]]);
      t.order.push_back(left[*best]);
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(*best));
    }
    t.wires = without_overlaps(wires);
    if (t.wires.empty()) t.wires.push_back({pins[0]});  // every pin at one point
    for (const auto& w : t.wires)
      for (std::size_t i = 1; i < w.size(); ++i)
        t.length += std::abs(std::int64_t{w[i].x} - w[i - 1].x) + std::abs(std::int64_t{w[i].y} - w[i - 1].y);
    t.status = WireStatus::Ok;
    return t;
  }
}

template <class W>
typename BasicRouter<W>::Tree BasicRouter<W>::tree(const geom::Polygon& source,
                                                   std::span<const geom::Polygon> sinks) {
  Tree t;
  t.distance.assign(sinks.size(), std::nullopt);
  // The source's candidates see every sink's vertices (pin_candidates() projects "other"'s
  // vertices, which is all it reads of it).
  geom::Polygon all_sinks;
  for (const geom::Polygon& s : sinks) {
    all_sinks.outer.insert(all_sinks.outer.end(), s.outer.begin(), s.outer.end());
    for (const geom::Ring& h : s.holes) all_sinks.outer.insert(all_sinks.outer.end(), h.begin(), h.end());
  }
  std::vector<Point> sources = pin_candidates(source, all_sinks);
  keep_free(sources, wavefront_);
  if (sources.empty()) {
    t.status = WireStatus::SourceNotFree;
    return t;
  }
  std::vector<Point> targets;
  std::vector<std::size_t> owner;  // targets[j] is a candidate of sinks[owner[j]]
  std::optional<Point> touch_point;
  for (std::size_t i = 0; i < sinks.size(); ++i) {
    std::vector<Point> c = pin_candidates(sinks[i], source);
    keep_free(c, wavefront_);
    if (c.empty()) {
      t.status = WireStatus::TargetNotFree;
      t.failed = i;
      return t;
    }
    if (const auto touch = shared_point(c, sinks[i], sources, source, [&](Point q) { return wavefront_.is_free(q); })) {
      t.distance[i] = Len{};
      if (!touch_point) touch_point = touch;
      continue;
    }
    for (const Point p : c) {
      targets.push_back(p);
      owner.push_back(i);
    }
  }
  std::vector<std::optional<std::size_t>> best(sinks.size());  // each sink's nearest candidate
  if (!targets.empty()) {
    wavefront_.run(sources, targets, W::Stop::AllTargets);
    for (std::size_t j = 0; j < targets.size(); ++j) {
      const auto d = wavefront_.target_distance(j);
      auto& b = best[owner[j]];
      if (d && (!b || *d < *wavefront_.target_distance(*b))) b = j;
    }
    for (std::size_t i = 0; i < sinks.size(); ++i)
      if (best[i]) t.distance[i] = wavefront_.target_distance(*best[i]);
    for (std::size_t i = 0; i < sinks.size(); ++i)
      if (!t.distance[i]) {
        t.status = WireStatus::Unreachable;
        t.failed = i;
        return t;
      }
  }
  // The paths as a trie: node = (parent node, point). Paths of one run that pass through the
  // same vertex wedge share the run's prefix; comparing whole prefixes (not points) keeps two
  // paths through one point in different wedges apart.
  struct Node {
    Point p;
    std::size_t parent;
    std::size_t first_sink;  // the first sink whose path passes here
    std::vector<std::size_t> children;
  };
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<Node> nodes;
  std::map<std::pair<std::size_t, Point>, std::size_t> index;
  std::vector<std::size_t> roots;
  for (std::size_t i = 0; i < sinks.size(); ++i) {
    if (!best[i]) continue;
    const std::vector<Point> path = wavefront_.target_path(*best[i]);
    std::size_t at = kNone;
    for (const Point p : path) {
      auto [it, fresh] = index.try_emplace({at, p}, nodes.size());
      if (fresh) {
        nodes.push_back({p, at, i, {}});
        if (at == kNone)
          roots.push_back(it->second);
        else
          nodes[at].children.push_back(it->second);
      }
      at = it->second;
    }
  }
  // Chains: from a root or a branch point along single children to a leaf or the next branch,
  // each one staircase. At a branch point v the polygonal paths pass through v inside one free
  // wedge, but a chain's staircase, searched on its own, may reach v around the other side of
  // an obstacle that touches v (a pinch) and its continuation leave on this side: a joint that
  // passes through the pinch. Each joint is checked (StaircaseBuilder::turn_ok); a chain whose
  // joint fails is staircased again with its whole path from the root, whose joints the
  // builder keeps inside one wedge (the duplicated part is merged below where it coincides).
  auto staircase = [&](const std::vector<Point>& poly) {
    return kOctilinear ? staircase_.octilinear(poly, &staircase_stats_) : staircase_.rectilinear(poly, &staircase_stats_);
  };
  std::vector<std::vector<Point>> stairs;
  std::vector<std::optional<Point>> arrive(nodes.size());  // branch point: the written point before it
  std::vector<std::size_t> starts = roots;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const std::size_t u = starts[k];
    if (nodes[u].children.empty() && nodes[u].parent == kNone) {
      stairs.push_back({nodes[u].p});  // a path of one point: a sink at a source candidate
      continue;
    }
    for (const std::size_t first : nodes[u].children) {
      std::vector<Point> chain = {nodes[u].p};
      std::size_t v = first;
      chain.push_back(nodes[v].p);
      while (nodes[v].children.size() == 1) {
        v = nodes[v].children[0];
        chain.push_back(nodes[v].p);
      }
      auto s = staircase(chain);
      if (s && arrive[u] && !staircase_.turn_ok(*arrive[u], nodes[u].p, (*s)[1])) {
        std::vector<Point> whole;
        for (std::size_t w = u; w != kNone; w = nodes[w].parent) whole.push_back(nodes[w].p);
        std::reverse(whole.begin(), whole.end());
        whole.insert(whole.end(), chain.begin() + 1, chain.end());
        s = staircase(whole);
        ++staircase_stats_.rejoined;
      }
      if (!s) {
        t.status = WireStatus::NoIntegerStaircase;
        t.failed = nodes[v].first_sink;
        return t;
      }
      if (nodes[v].children.size() > 1) {
        arrive[v] = (*s)[s->size() - 2];
        starts.push_back(v);
      }
      stairs.push_back(std::move(*s));
    }
  }
  t.wires = without_overlaps(stairs);
  if (t.wires.empty()) {  // every sink touches the source, or sits at a source candidate
    const Point p = touch_point ? *touch_point : stairs.empty() ? sources[0] : stairs[0][0];
    t.wires.push_back({p});
  }
  t.status = WireStatus::Ok;
  return t;
}

template class BasicRouter<L1Wavefront>;
template class BasicRouter<OctWavefront>;

std::vector<std::vector<Point>> without_overlaps(std::span<const std::vector<Point>> wires) {
  // A segment's line: its class (0 horizontal, 1 vertical, 2 and 3 the diagonals dx = dy and
  // dx = -dy) and the coordinate that is constant along it (y, x, y - x, y + x); t is the
  // coordinate along it (x, except y on verticals).
  auto point_at = [](int cls, i64 inv, i64 t) {
    switch (cls) {
      case 0: return Point{static_cast<geom::Coord>(t), static_cast<geom::Coord>(inv)};
      case 1: return Point{static_cast<geom::Coord>(inv), static_cast<geom::Coord>(t)};
      case 2: return Point{static_cast<geom::Coord>(t), static_cast<geom::Coord>(inv + t)};
      default: return Point{static_cast<geom::Coord>(t), static_cast<geom::Coord>(inv - t)};
    }
  };
  std::map<std::pair<int, i64>, std::map<i64, i64>> covered;  // line -> disjoint [lo, hi]
  std::vector<std::vector<Point>> out;
  std::vector<Point> cur;
  auto flush = [&] {
    if (cur.size() >= 2) out.push_back(std::move(cur));
    cur.clear();
  };
  auto extend = [&](Point a, Point b) {
    if (cur.empty() || cur.back() != a) {
      flush();
      cur = {a};
    }
    cur.push_back(b);
  };
  for (const std::vector<Point>& w : wires) {
    for (std::size_t k = 0; k + 1 < w.size(); ++k) {
      const Point a = w[k], b = w[k + 1];
      const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
      if (dx == 0 && dy == 0) continue;
      int cls;
      i64 inv, t0, t1;
      if (dy == 0) cls = 0, inv = a.y, t0 = a.x, t1 = b.x;
      else if (dx == 0) cls = 1, inv = a.x, t0 = a.y, t1 = b.y;
      else if (dx == dy) cls = 2, inv = i64{a.y} - a.x, t0 = a.x, t1 = b.x;
      else if (dx == -dy) cls = 3, inv = i64{a.y} + a.x, t0 = a.x, t1 = b.x;
      else {
        extend(a, b);  // another slope: kept as it is
        continue;
      }
      const i64 lo = std::min(t0, t1), hi = std::max(t0, t1);
      std::map<i64, i64>& cov = covered[{cls, inv}];
      std::vector<std::pair<i64, i64>> pieces;  // the uncovered parts of [lo, hi], ascending
      i64 start = lo;
      auto it = cov.upper_bound(lo);
      if (it != cov.begin() && std::prev(it)->second > lo) --it;
      for (; it != cov.end() && it->first < hi; ++it) {
        if (it->first > start) pieces.push_back({start, it->first});
        start = std::max(start, it->second);
      }
      if (start < hi) pieces.push_back({start, hi});
      if (t0 <= t1) {
        for (const auto& [p, q] : pieces) extend(point_at(cls, inv, p), point_at(cls, inv, q));
      } else {
        for (auto r = pieces.rbegin(); r != pieces.rend(); ++r)
          extend(point_at(cls, inv, r->second), point_at(cls, inv, r->first));
      }
      // Cover [lo, hi], merging the intervals it meets or touches.
      i64 nlo = lo, nhi = hi;
      auto m = cov.upper_bound(lo);
      if (m != cov.begin() && std::prev(m)->second >= lo) --m;
      while (m != cov.end() && m->first <= hi) {
        nlo = std::min(nlo, m->first);
        nhi = std::max(nhi, m->second);
        m = cov.erase(m);
      }
      cov.emplace(nlo, nhi);
    }
    flush();
  }
  return out;
}

const char* to_string(WireStatus status) {
  switch (status) {
    case WireStatus::Ok: return "ok";
    case WireStatus::SourceNotFree: return "source not free";
    case WireStatus::TargetNotFree: return "target not free";
    case WireStatus::Unreachable: return "unreachable";
    case WireStatus::NoIntegerStaircase: return "no integer staircase";
  }
  return "?";
}

}  // namespace taut::router
