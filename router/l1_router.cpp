#include "router/l1_router.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <map>
#include <set>
#include <utility>

#include "geom/predicates.h"

namespace taut::router {

using geom::i64;
using geom::Point;

template <class W>
BasicRouter<W>::BasicRouter(const geom::Box& domain, std::span<const geom::Polygon> obstacles)
    : wavefront_(domain, obstacles), staircase_(domain, obstacles), pins_(obstacles, domain, kOctilinear) {}

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
// The length of segment ab: L1 (Len std::int64_t) or octilinear d8 (geom::Root2).
template <class Len>
Len segment_length(Point a, Point b) {
  const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
  if constexpr (std::is_same_v<Len, geom::Root2>) return geom::octilinear_length(dx, dy);
  else return std::abs(dx) + std::abs(dy);
}
// The total length of the wires.
template <class Len>
Len wires_length(const std::vector<std::vector<Point>>& wires) {
  Len l{};
  for (const auto& w : wires)
    for (std::size_t i = 1; i < w.size(); ++i) l += segment_length<Len>(w[i - 1], w[i]);
  return l;
}
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
typename BasicRouter<W>::Steiner BasicRouter<W>::steiner(std::span<const Point> pins, std::size_t starts,
                                                         bool improve_tree) {
  // Grown from each of the first `starts` pins in turn; the shortest kept (the first on ties).
  // The improvement pass then runs on the shortest few of them (kImproved; measured in
  // tests/router/steiner_test.cpp: improving all eight finds little more and costs far more).
  std::vector<Steiner> ok;  // in start order
  Steiner first_failure;
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
    if (t.status == WireStatus::Ok) ok.push_back(std::move(t));
    else if (s0 == 0) first_failure = std::move(t);
  }
  if (ok.empty()) return first_failure;
  std::stable_sort(ok.begin(), ok.end(), [](const Steiner& a, const Steiner& b) { return a.length < b.length; });
  if (improve_tree)
    for (std::size_t i = 0; i < ok.size() && i < kImproved; ++i)
      if (ok[i].length > Len{}) ok[i].improved = improve(pins, ok[i]);
  std::size_t best = 0;
  for (std::size_t i = 1; i < ok.size(); ++i)
    if (ok[i].length < ok[best].length) best = i;
  return std::move(ok[best]);
}

namespace {

// A tree's metal as a graph: every segment (axis-parallel; octilinear: or diagonal) split at
// every segment end, pin and crossing lying on it; a piece two wires share is one edge. A
// diagonal crossing a diagonal halfway between lattice points is no node (the graph then only
// understates how the metal is joined: a path it takes for needed may be re-joined, never one
// that is needed dropped).
struct MetalGraph {
  std::vector<Point> nodes;                                       // ascending
  std::vector<std::pair<std::size_t, std::size_t>> edges;         // node indices
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> adj;  // (neighbour, edge)
  std::vector<char> key;                                          // a pin, or degree other than 2
  std::size_t at(Point p) const {
    return static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), p) - nodes.begin());
  }
};

// nullopt when a segment is neither horizontal nor vertical (not a rectilinear tree), or with
// `octilinear` not diagonal either.
std::optional<MetalGraph> metal_graph(const std::vector<std::vector<Point>>& wires, std::span<const Point> pins,
                                      bool octilinear = false) {
  std::vector<geom::Segment> segs;
  for (const auto& w : wires)
    for (std::size_t i = 1; i < w.size(); ++i) {
      if (w[i] == w[i - 1]) continue;
      const i64 dx = i64{w[i].x} - w[i - 1].x, dy = i64{w[i].y} - w[i - 1].y;
      if (dx != 0 && dy != 0 && (!octilinear || (dx != dy && dx != -dy))) return std::nullopt;
      segs.push_back({std::min(w[i - 1], w[i]), std::max(w[i - 1], w[i])});
    }
  MetalGraph g;
  for (const geom::Segment& s : segs) g.nodes.insert(g.nodes.end(), {s.a, s.b});
  g.nodes.insert(g.nodes.end(), pins.begin(), pins.end());
  if (octilinear) {  // proper crossings at lattice points (ends on a segment are nodes already)
    for (std::size_t i = 0; i < segs.size(); ++i)
      for (std::size_t j = i + 1; j < segs.size(); ++j)
        if (geom::intersect(segs[i], segs[j]) == geom::SegmentIntersection::Proper) {
          const geom::RationalPoint r = geom::line_intersection(segs[i], segs[j]);
          if (r.is_integer())
            g.nodes.push_back({static_cast<geom::Coord>(r.x_num / r.den), static_cast<geom::Coord>(r.y_num / r.den)});
        }
  } else {
    for (const geom::Segment& h : segs)  // crossings of a horizontal and a vertical segment
      if (h.a.y == h.b.y)
        for (const geom::Segment& v : segs)
          if (v.a.x == v.b.x && h.a.x <= v.a.x && v.a.x <= h.b.x && v.a.y <= h.a.y && h.a.y <= v.b.y)
            g.nodes.push_back({v.a.x, h.a.y});
  }
  std::sort(g.nodes.begin(), g.nodes.end());
  g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
  std::vector<std::pair<std::size_t, std::size_t>> pieces;
  for (const geom::Segment& s : segs) {
    // the nodes on s, in order along it (both sorted the same way: s.a < s.b)
    std::vector<std::size_t> on;
    const bool horizontal = s.a.y == s.b.y;
    for (std::size_t i = g.at(s.a); i < g.nodes.size() && g.nodes[i] <= s.b; ++i) {
      const Point p = g.nodes[i];
      if (octilinear ? geom::orient(s.a, s.b, p) == 0 : horizontal ? p.y == s.a.y : p.x == s.a.x) on.push_back(i);
    }
    for (std::size_t k = 1; k < on.size(); ++k) pieces.push_back({on[k - 1], on[k]});
  }
  std::sort(pieces.begin(), pieces.end());
  pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
  g.edges = std::move(pieces);
  g.adj.assign(g.nodes.size(), {});
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    g.adj[g.edges[e].first].push_back({g.edges[e].second, e});
    g.adj[g.edges[e].second].push_back({g.edges[e].first, e});
  }
  g.key.assign(g.nodes.size(), 0);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) g.key[i] = g.adj[i].size() != 2;
  for (const Point p : pins) g.key[g.at(p)] = 1;
  return g;
}

// The chains between key nodes: node and edge sequences, and their lengths (Len: std::int64_t,
// L1; geom::Root2, octilinear).
template <class Len>
struct KeyPath {
  std::vector<std::size_t> nodes, edges;
  Len length{};
};
template <class Len>
std::vector<KeyPath<Len>> key_paths(const MetalGraph& g) {
  std::vector<KeyPath<Len>> out;
  std::vector<char> used(g.edges.size(), 0);
  auto len = [&](std::size_t e) { return segment_length<Len>(g.nodes[g.edges[e].first], g.nodes[g.edges[e].second]); };
  auto walk = [&](std::size_t u, std::size_t e0, std::size_t v0) {
    KeyPath<Len> p;
    p.nodes = {u};
    std::size_t e = e0, v = v0;
    while (true) {
      used[e] = 1;
      p.edges.push_back(e);
      p.length += len(e);
      p.nodes.push_back(v);
      if (g.key[v]) break;
      const auto& a = g.adj[v];  // degree 2: the other edge
      const auto next = a[0].second == e ? a[1] : a[0];
      if (used[next.second]) break;  // a ring of degree-2 nodes (cannot happen with a pin on it)
      e = next.second;
      v = next.first;
    }
    out.push_back(std::move(p));
  };
  for (std::size_t u = 0; u < g.nodes.size(); ++u)
    if (g.key[u])
      for (const auto& [v, e] : g.adj[u])
        if (!used[e]) walk(u, e, v);
  return out;
}

// The polyline of a path's nodes without the points where it goes straight on.
template <class Len>
std::vector<Point> path_points(const MetalGraph& g, const KeyPath<Len>& p) {
  std::vector<Point> out;
  for (const std::size_t n : p.nodes) {
    const Point q = g.nodes[n];
    if (out.size() >= 2) {
      const Point a = out[out.size() - 2], b = out.back();
      // (collinear is straight on: consecutive pieces of a path do not overlap)
      if ((a.x == b.x && b.x == q.x) || (a.y == b.y && b.y == q.y) || geom::orient(a, b, q) == 0) {
        out.back() = q;
        continue;
      }
    }
    out.push_back(q);
  }
  return out;
}

}  // namespace

template <class W>
std::size_t BasicRouter<W>::improve(std::span<const Point> pins, Steiner& t, std::span<const geom::Polygon> pads) {
  std::size_t changes = 0;
  // Paths (by their points) already tried without a gain: not tried again after changes
  // elsewhere. A change elsewhere can open a gain for them, so this trades a little length for
  // far fewer runs (measured in tests/router/steiner_test.cpp and bench_steiner).
  std::set<std::vector<Point>> tried;
  const std::vector<geom::Coord>& xs = pins_.vertex_xs();
  const std::vector<geom::Coord>& ys = pins_.vertex_ys();
  std::vector<Point> sorted_pins(pins.begin(), pins.end());
  std::sort(sorted_pins.begin(), sorted_pins.end());
  while (true) {
    bool changed = false;
    std::optional<MetalGraph> graph = metal_graph(t.wires, pins, kOctilinear);
    if (!graph) return changes;  // not rectilinear (octilinear): left as it is
    // A node where blockages touch (a wire passes through the point, each time in one of its free
    // wedges: a way round a pinch that comes back to it): the graph joins its edges there, whatever
    // their wedges, so a path through it could cross from one wedge to another (dropping the way
    // round, seed 3070 of a search over `taut gen` layouts, 2026-12-05, where `route --tree steiner`
    // then failed taut check with CHECK-0003). Such a tree is left as it is.
    for (const Point n : graph->nodes)
      if (wavefront_.vertex_wedges(n).size() > 1) return changes;
    // Pads (shape pins) are metal: the nodes lying on one are key (a path ends where it meets
    // a pad) and joined through it.
    std::vector<std::vector<std::size_t>> members(pads.size()), pad_of(graph->nodes.size());
    for (std::size_t k = 0; k < pads.size(); ++k)
      for (std::size_t n = 0; n < graph->nodes.size(); ++n)
        if (in_pin(graph->nodes[n], pads[k])) {
          members[k].push_back(n);
          pad_of[n].push_back(k);
          graph->key[n] = 1;
        }
    const MetalGraph& g = *graph;
    const std::vector<KeyPath<Len>> paths = key_paths<Len>(g);
    std::vector<std::size_t> longest_first(paths.size());
    for (std::size_t i = 0; i < paths.size(); ++i) longest_first[i] = i;
    std::stable_sort(longest_first.begin(), longest_first.end(),
                     [&](std::size_t a, std::size_t b) { return paths[a].length > paths[b].length; });
    for (const std::size_t pi : longest_first) {
      const KeyPath<Len>& p = paths[pi];
      std::vector<Point> shape;
      for (const std::size_t n : p.nodes) shape.push_back(g.nodes[n]);
      if (shape.back() < shape.front()) std::reverse(shape.begin(), shape.end());
      if (!tried.insert(shape).second) continue;
      // the tree without p's edges and inner nodes: the part holding p's first end
      std::vector<char> gone(g.edges.size(), 0), side;
      for (const std::size_t e : p.edges) gone[e] = 1;
      auto part_of = [&](std::size_t from) {
        side.assign(g.nodes.size(), 0);
        std::vector<std::size_t> stack{from};
        side[from] = 1;
        while (!stack.empty()) {
          const std::size_t u = stack.back();
          stack.pop_back();
          for (const auto& [v, e] : g.adj[u])
            if (!gone[e] && !side[v]) {
              side[v] = 1;
              stack.push_back(v);
            }
          for (const std::size_t k : pad_of[u])
            for (const std::size_t v : members[k])
              if (!side[v]) {
                side[v] = 1;
                stack.push_back(v);
              }
        }
      };
      part_of(p.nodes.front());
      // the run leaves from the part with less metal (fewer segment sources to expand)
      if (!side[p.nodes.back()]) {
        std::int64_t here = 0, there = 0;
        for (std::size_t e = 0; e < g.edges.size(); ++e) {
          if (gone[e]) continue;
          const Point a = g.nodes[g.edges[e].first], b = g.nodes[g.edges[e].second];
          (side[g.edges[e].first] ? here : there) += std::abs(std::int64_t{a.x} - b.x) + std::abs(std::int64_t{a.y} - b.y);
        }
        if (here > there) part_of(p.nodes.back());
      }
      auto rest = [&] {  // every edge but p's, as two-point wires
        std::vector<std::vector<Point>> r;
        for (std::size_t e = 0; e < g.edges.size(); ++e)
          if (!gone[e]) r.push_back({g.nodes[g.edges[e].first], g.nodes[g.edges[e].second]});
        return r;
      };
      if (side[p.nodes.back()] && side[p.nodes.front()]) {  // still joined without it: dropped
        t.wires = rest();
        changed = true;
        break;
      }
      // sources: the first part's metal; targets: the other part's nodes and the projections
      // onto its segments of the obstacle vertices, domain corners and the first part's nodes.
      // The other part is the one holding p's other end: metal in neither part (a pin on a pad
      // that meets the tree's pads only through another pad: pads that meet are joined by their
      // own metal, not by the graph) is not reached through p, and a way to it would drop p's
      // join (found by fuzzing, 2026-12-06: a pin apart left unconnected).
      std::vector<char> other;
      {
        std::vector<char> first_side = side;
        part_of(first_side[p.nodes.front()] ? p.nodes.back() : p.nodes.front());
        other = std::move(side);
        side = std::move(first_side);
      }
      std::vector<char> inner(g.nodes.size(), 0);
      for (std::size_t k = 1; k + 1 < p.nodes.size(); ++k) inner[p.nodes[k]] = 1;
      std::vector<Point> points, targets;
      std::vector<geom::Segment> segments;
      std::vector<geom::Coord> axs, ays;
      for (std::size_t n = 0; n < g.nodes.size(); ++n) {
        if (side[n]) {
          axs.push_back(g.nodes[n].x);
          ays.push_back(g.nodes[n].y);
          if (g.key[n]) points.push_back(g.nodes[n]);
        } else if (!inner[n] && other[n]) {
          targets.push_back(g.nodes[n]);
        }
      }
      std::sort(axs.begin(), axs.end());
      std::sort(ays.begin(), ays.end());
      // octilinear: the projections along the four orientations (ProjectionLines, wavefront.h)
      std::optional<ProjectionLines> first_lines;
      if constexpr (kOctilinear) {
        first_lines.emplace(true, lattice_);
        for (std::size_t n = 0; n < g.nodes.size(); ++n)
          if (side[n]) first_lines->add(g.nodes[n]);
        first_lines->done();
        if (!obstacle_lines_) {
          obstacle_lines_.emplace(true, lattice_);
          for (const geom::Polygon& o : wavefront_.frame_obstacles()) {
            for (const Point v : o.outer) obstacle_lines_->add(v);
            for (const geom::Ring& h : o.holes)
              for (const Point v : h) obstacle_lines_->add(v);
          }
          obstacle_lines_->done();
        }
      }
      for (std::size_t e = 0; e < g.edges.size(); ++e) {
        if (gone[e]) continue;
        const Point a = g.nodes[g.edges[e].first], b = g.nodes[g.edges[e].second];  // a < b
        if (side[g.edges[e].first]) {
          segments.push_back({a, b});
          continue;
        }
        if (!other[g.edges[e].first]) continue;
        if constexpr (kOctilinear) {
          obstacle_lines_->inside(a, b, targets);
          first_lines->inside(a, b, targets);
          continue;
        }
        const bool horizontal = a.y == b.y;
        for (const std::vector<geom::Coord>* v : {&(horizontal ? xs : ys), static_cast<const std::vector<geom::Coord>*>(&(horizontal ? axs : ays))}) {
          const geom::Coord lo = horizontal ? a.x : a.y, hi = horizontal ? b.x : b.y;
          for (auto it = std::upper_bound(v->begin(), v->end(), lo); it != v->end() && *it < hi; ++it)
            targets.push_back(horizontal ? Point{*it, a.y} : Point{a.x, *it});
        }
      }
      // the pads: the first part's are sources along their edges; the other part's targets at
      // their candidate points against the first part's nodes
      if (!pads.empty()) {
        geom::Polygon first;
        for (std::size_t n = 0; n < g.nodes.size(); ++n)
          if (side[n]) first.outer.push_back(g.nodes[n]);
        for (std::size_t k = 0; k < pads.size(); ++k) {
          if (members[k].empty()) continue;
          if (side[members[k][0]]) {
            for_each_pin_edge(pads[k], [&](Point a, Point b) { segments.push_back({a, b}); });
          } else if (other[members[k][0]]) {
            const std::vector<Point> c = pin_candidates(pads[k], first);
            targets.insert(targets.end(), c.begin(), c.end());
          }
        }
      }
      std::sort(targets.begin(), targets.end());
      targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
      keep_free(targets, wavefront_);
      if (targets.empty()) continue;
      run_from(points, segments, targets, WavefrontStop::FirstTarget);
      std::optional<std::size_t> best;
      for (std::size_t j = 0; j < targets.size(); ++j) {
        const auto d = wavefront_.target_distance(j);
        if (d && (!best || *d < *wavefront_.target_distance(*best))) best = j;
      }
      if (!best || *wavefront_.target_distance(*best) >= p.length) continue;
      Wire w = finish(best);
      if (w.status != WireStatus::Ok) continue;
      t.wires = rest();
      if (w.points.size() >= 2) t.wires.push_back(std::move(w.points));
      changed = true;
      break;
    }
    if (changed) {
      ++changes;
      continue;
    }
    {
    // No single path gains: move a Steiner point. A key node u of degree three or more (or a
    // pin of degree two or more), with the key paths at it taken out, leaves one part per path
    // (and the pin, a part of its own); the point s (in free space) with the least sum of the
    // parts' distances to it, joined to each part by a shortest path, replaces those paths when
    // that sum is strictly smaller than theirs. Candidates for s: the grid of
    // the x and y of u, the paths' far ends and the tree's nodes within their box, and of the
    // obstacle vertices there while the grid stays small (an optimal Steiner point of three
    // points among rectangles lies on the extended Hanan grid of the points and the obstacles'
    // corners; the parts are more than points, so this is a heuristic with the exact distances).
    for (std::size_t u = 0; u < g.nodes.size() && !changed; ++u) {
      const bool is_pin = std::binary_search(sorted_pins.begin(), sorted_pins.end(), g.nodes[u]);
      if (!g.key[u] || g.adj[u].size() < (is_pin ? 2u : 3u)) continue;
      if (!pad_of[u].empty()) continue;  // a join on a pad stays (the pad is metal there)
      std::vector<std::size_t> at_u;
      for (std::size_t pi = 0; pi < paths.size(); ++pi)
        if (paths[pi].nodes.front() == u || paths[pi].nodes.back() == u) at_u.push_back(pi);
      if (at_u.size() != g.adj[u].size()) continue;  // (a path from u back to u: not in a tree)
      std::vector<Point> memo_key{g.nodes[u]};
      std::vector<char> gone(g.edges.size(), 0);
      std::vector<std::size_t> far;
      Len old_length{};
      for (const std::size_t pi : at_u) {
        const KeyPath<Len>& kp = paths[pi];
        for (const std::size_t e : kp.edges) gone[e] = 1;
        far.push_back(kp.nodes.front() == u ? kp.nodes.back() : kp.nodes.front());
        old_length += kp.length;
        for (const std::size_t n : kp.nodes) memo_key.push_back(g.nodes[n]);
      }
      if (!tried.insert(memo_key).second) continue;
      // the parts: flood fills from the far ends over the edges left
      std::vector<int> part(g.nodes.size(), -1);
      bool tree = true;
      for (std::size_t k = 0; k < far.size() && tree; ++k) {
        if (part[far[k]] >= 0) tree = false;  // two far ends joined without u: not a tree
        std::vector<std::size_t> stack{far[k]};
        part[far[k]] = static_cast<int>(k);
        while (!stack.empty()) {
          const std::size_t a = stack.back();
          stack.pop_back();
          for (const auto& [b, e] : g.adj[a])
            if (!gone[e] && part[b] < 0) {
              part[b] = static_cast<int>(k);
              stack.push_back(b);
            }
          for (const std::size_t pk : pad_of[a])  // joined through a pad
            for (const std::size_t b : members[pk])
              if (part[b] < 0) {
                part[b] = static_cast<int>(k);
                stack.push_back(b);
              }
        }
      }
      if (!tree) continue;
      // the candidate grid
      geom::Coord x0 = g.nodes[u].x, x1 = x0, y0 = g.nodes[u].y, y1 = y0;
      for (const std::size_t f : far) {
        x0 = std::min(x0, g.nodes[f].x), x1 = std::max(x1, g.nodes[f].x);
        y0 = std::min(y0, g.nodes[f].y), y1 = std::max(y1, g.nodes[f].y);
      }
      std::vector<geom::Coord> gx, gy;
      std::vector<std::int64_t> gsum, gdiff;  // octilinear: the diagonals x + y and x - y
      for (const Point q : g.nodes) {
        if (x0 <= q.x && q.x <= x1) gx.push_back(q.x);
        if (y0 <= q.y && q.y <= y1) gy.push_back(q.y);
        if constexpr (kOctilinear)
          if (x0 <= q.x && q.x <= x1 && y0 <= q.y && q.y <= y1) {
            gsum.push_back(std::int64_t{q.x} + q.y);
            gdiff.push_back(std::int64_t{q.x} - q.y);
          }
      }
      auto add_obstacles = [](std::vector<geom::Coord>& v, const std::vector<geom::Coord>& all, geom::Coord lo,
                              geom::Coord hi) {
        const auto a = std::lower_bound(all.begin(), all.end(), lo), b = std::upper_bound(all.begin(), all.end(), hi);
        if (b - a <= static_cast<std::ptrdiff_t>(kMoveGridSide)) v.insert(v.end(), a, b);
      };
      add_obstacles(gx, xs, x0, x1);
      add_obstacles(gy, ys, y0, y1);
      for (auto* v : {&gx, &gy}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
      }
      for (auto* v : {&gsum, &gdiff}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
      }
      if (gx.size() * gy.size() > kMoveGridPoints) continue;
      std::vector<Point> grid;
      for (const geom::Coord x : gx)
        for (const geom::Coord y : gy) grid.push_back({x, y});
      if constexpr (kOctilinear) {
        // Octilinear: also where a diagonal of a node meets another node's line, horizontal,
        // vertical or the other diagonal (at integer points only), within the box: the lines
        // of the octilinear Hanan grid of the nodes (the obstacle vertices add axis lines only).
        const std::size_t diagonal_points = (gsum.size() + gdiff.size()) * (gx.size() + gy.size()) + gsum.size() * gdiff.size() * (lattice_ > 1 ? 4 : 1);
        if (grid.size() + diagonal_points <= kMoveGridPoints) {
          auto add = [&](std::int64_t x, std::int64_t y) {
            if (x0 <= x && x <= x1 && y0 <= y && y <= y1) grid.push_back({static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)});
          };
          for (const std::int64_t c : gsum) {
            for (const geom::Coord x : gx) add(x, c - x);
            for (const geom::Coord y : gy) add(c - y, y);
            for (const std::int64_t d : gdiff)
              if (lattice_ > 1) {  // the multiples of lattice_ in x next to the crossing, on both diagonals
                for (const i64 x : geom::lattice_neighbours(c + d, lattice_)) {
                  add(x, c - x);
                  add(x, x - d);
                }
              } else if ((c + d) % 2 == 0) {
                add((c + d) / 2, (c - d) / 2);
              }
          }
          for (const std::int64_t d : gdiff) {
            for (const geom::Coord x : gx) add(x, x - d);
            for (const geom::Coord y : gy) add(y + d, y);
          }
          std::sort(grid.begin(), grid.end());
          grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
        }
      }
      keep_free(grid, wavefront_);
      // not where blockages touch: the parts' paths would meet there from different free wedges,
      // and the tree would pass through the pinch (FORMAT.md forbids it)
      grid.erase(std::remove_if(grid.begin(), grid.end(), [&](Point q) { return wavefront_.vertex_wedges(q).size() > 1; }),
                 grid.end());
      if (grid.empty()) continue;
      // each part's metal: its key nodes and its edges
      std::vector<std::vector<Point>> part_points(far.size());
      std::vector<std::vector<geom::Segment>> part_segments(far.size());
      for (std::size_t n = 0; n < g.nodes.size(); ++n)
        if (part[n] >= 0 && (g.key[n] || g.adj[n].empty())) part_points[static_cast<std::size_t>(part[n])].push_back(g.nodes[n]);
      for (std::size_t k = 0; k < far.size(); ++k)
        if (part_points[k].empty()) part_points[k].push_back(g.nodes[far[k]]);
      if (is_pin) {  // the pin stays, a part of its own
        part_points.push_back({g.nodes[u]});
        part_segments.emplace_back();
      }
      for (std::size_t e = 0; e < g.edges.size(); ++e)
        if (!gone[e] && part[g.edges[e].first] >= 0)
          part_segments[static_cast<std::size_t>(part[g.edges[e].first])].push_back(
              {g.nodes[g.edges[e].first], g.nodes[g.edges[e].second]});
      // a part's pads are its metal too: sources along their edges
      for (std::size_t pk = 0; pk < pads.size(); ++pk)
        if (!members[pk].empty() && part[members[pk][0]] >= 0)
          for_each_pin_edge(pads[pk], [&](Point a, Point b) {
            part_segments[static_cast<std::size_t>(part[members[pk][0]])].push_back({a, b});
          });
      // A lower bound of each part's distance: the distance (L1, or octilinear) to the box of
      // each of its points and segments, blockages ignored (exact for a point and an axis
      // segment; the length grows with |dx| and |dy|, which a box only shortens). Candidates
      // whose bound, with the exact distances of the parts run so far, reaches the old length
      // are dropped before each run (most moves end here without a run at all).
      auto bound_to_part = [&](Point q, std::size_t k) {
        auto gap = [](geom::Coord v, geom::Coord lo, geom::Coord hi) {
          return v < lo ? std::int64_t{lo} - v : v > hi ? std::int64_t{v} - hi : std::int64_t{0};
        };
        std::optional<Len> d;
        auto take = [&](std::int64_t dx, std::int64_t dy) {
          Len l;
          if constexpr (kOctilinear) l = geom::octilinear_length(dx, dy);
          else l = dx + dy;
          if (!d || l < *d) d = l;
        };
        for (const Point a : part_points[k]) take(gap(q.x, a.x, a.x), gap(q.y, a.y, a.y));
        for (const geom::Segment& sg : part_segments[k])
          take(gap(q.x, std::min(sg.a.x, sg.b.x), std::max(sg.a.x, sg.b.x)),
               gap(q.y, std::min(sg.a.y, sg.b.y), std::max(sg.a.y, sg.b.y)));
        return *d;  // (every part has a point)
      };
      const std::size_t parts = part_points.size();
      std::vector<Len> bound(grid.size() * parts);  // [j * parts + k]
      std::vector<Len> sum(grid.size(), Len{});  // exact so far plus the bounds of the rest
      for (std::size_t j = 0; j < grid.size(); ++j)
        for (std::size_t k = 0; k < parts; ++k) {
          bound[j * parts + k] = bound_to_part(grid[j], k);
          sum[j] += bound[j * parts + k];
        }
      std::vector<std::size_t> alive;
      for (std::size_t j = 0; j < grid.size(); ++j)
        if (sum[j] < old_length) alive.push_back(j);
      for (std::size_t k = 0; k < parts && !alive.empty(); ++k) {
        std::vector<Point> targets;
        for (const std::size_t j : alive) targets.push_back(grid[j]);
        run_from(part_points[k], part_segments[k], targets, WavefrontStop::AllTargets);
        std::vector<std::size_t> still;
        for (std::size_t i = 0; i < alive.size(); ++i) {
          const auto d = wavefront_.target_distance(i);
          if (!d) continue;
          const std::size_t j = alive[i];
          sum[j] += *d - bound[j * parts + k];
          if (sum[j] < old_length) still.push_back(j);
        }
        alive = std::move(still);
      }
      std::optional<std::size_t> best;
      for (const std::size_t j : alive)
        if (!best || sum[j] < sum[*best]) best = j;
      if (!best) continue;
      std::vector<std::vector<Point>> joins;
      bool ok = true;
      for (std::size_t k = 0; k < part_points.size() && ok; ++k) {
        run_from(part_points[k], part_segments[k], std::vector<Point>{grid[*best]}, WavefrontStop::FirstTarget);
        Wire w = finish(std::size_t{0});
        ok = w.status == WireStatus::Ok;
        if (ok && w.points.size() >= 2) joins.push_back(std::move(w.points));
      }
      if (!ok) continue;
      std::vector<std::vector<Point>> wires;
      for (std::size_t e = 0; e < g.edges.size(); ++e)
        if (!gone[e]) wires.push_back({g.nodes[g.edges[e].first], g.nodes[g.edges[e].second]});
      for (auto& w : joins) wires.push_back(std::move(w));
      t.wires = std::move(wires);
      changed = true;
    }
    if (changed) {
      ++changes;
      continue;
    }
    // nothing improves: written as the key paths, one wire each
    std::vector<std::vector<Point>> wires;
    for (const KeyPath<Len>& p : paths) wires.push_back(path_points(g, p));
    if (!wires.empty()) t.wires = std::move(wires);
    break;
    }
  }
  t.length = wires_length<Len>(t.wires);
  return changes;
}

template <class W>
typename BasicRouter<W>::Steiner BasicRouter<W>::steiner_from_first(std::span<const Point> pins) {
  // Point pins are one-vertex shapes: the shape version joins them as point sources and aims at
  // the points themselves, so it is the same search.
  std::vector<geom::Polygon> shapes;
  shapes.reserve(pins.size());
  for (const Point p : pins) shapes.push_back(geom::Polygon{{p}, {}});
  return steiner_from_first(std::span<const geom::Polygon>(shapes));
}

template <class W>
typename BasicRouter<W>::Steiner BasicRouter<W>::steiner(std::span<const geom::Polygon> pins, std::size_t starts,
                                                         bool improve_tree) {
  bool points = true;
  for (const geom::Polygon& p : pins) points = points && is_point_pin(p);
  if (points) {
    std::vector<Point> pts;
    for (const geom::Polygon& p : pins) pts.push_back(p.outer[0]);
    return steiner(pts, starts, improve_tree);
  }
  // As the point version: from each of the first `starts` pins, the shortest kept (the first on
  // ties); a pin not free or walled in is the same from every start.
  std::vector<Steiner> ok;  // in start order
  Steiner first_failure;
  const std::size_t tries = std::max<std::size_t>(1, std::min(starts, pins.size()));
  for (std::size_t s0 = 0; s0 < tries; ++s0) {
    std::vector<geom::Polygon> rotated(pins.begin() + static_cast<std::ptrdiff_t>(s0), pins.end());
    rotated.insert(rotated.end(), pins.begin(), pins.begin() + static_cast<std::ptrdiff_t>(s0));
    Steiner t = steiner_from_first(std::span<const geom::Polygon>(rotated));
    auto back = [&](std::size_t i) { return (i + s0) % pins.size(); };
    if (t.failed) t.failed = back(*t.failed);
    for (std::size_t& i : t.order) i = back(i);
    if (t.status == WireStatus::SourceNotFree || t.status == WireStatus::TargetNotFree || t.status == WireStatus::Unreachable)
      return t;
    if (t.status == WireStatus::Ok) ok.push_back(std::move(t));
    else if (s0 == 0) first_failure = std::move(t);
  }
  if (ok.empty()) return first_failure;
  // The improvement pass's path re-embedding (the pads metal, see improve()) on the shortest few.
  std::stable_sort(ok.begin(), ok.end(), [](const Steiner& a, const Steiner& b) { return a.length < b.length; });
  if (improve_tree) {
    std::vector<Point> points;
    std::vector<geom::Polygon> pads;
    for (const geom::Polygon& p : pins) {
      if (is_point_pin(p)) points.push_back(p.outer[0]);
      else pads.push_back(p);
    }
    for (std::size_t i = 0; i < ok.size() && i < kImproved; ++i)
      if (ok[i].length > Len{}) ok[i].improved = improve(points, ok[i], pads);
  }
  std::size_t best = 0;
  for (std::size_t i = 1; i < ok.size(); ++i)
    if (ok[i].length < ok[best].length) best = i;
  return std::move(ok[best]);
}

template <class W>
typename BasicRouter<W>::Steiner BasicRouter<W>::steiner_from_first(std::span<const geom::Polygon> pins) {
  Steiner t;
  {
    if (pins.empty()) {
      t.status = WireStatus::Ok;
      return t;
    }
    // every pin has a free point (a shape: a free candidate against the others' vertices)
    geom::Polygon all;
    for (const geom::Polygon& p : pins) all.outer.insert(all.outer.end(), p.outer.begin(), p.outer.end());
    for (std::size_t i = 0; i < pins.size(); ++i) {
      std::vector<Point> c = is_point_pin(pins[i]) ? std::vector<Point>{pins[i].outer[0]} : pin_candidates(pins[i], all);
      keep_free(c, wavefront_);
      if (c.empty()) {
        t.status = i == 0 ? WireStatus::SourceNotFree : WireStatus::TargetNotFree;
        t.failed = i;
        return t;
      }
    }
    // The tree so far: points (point pins) and segments (wires, and the joined shapes' edges);
    // `metal` every point of it (what the shapes' candidates are projected from).
    std::vector<Point> points;
    std::vector<geom::Segment> segments;
    geom::Polygon metal;
    auto join = [&](const geom::Polygon& pin) {
      if (is_point_pin(pin)) {
        points.push_back(pin.outer[0]);
      } else {
        for_each_pin_edge(pin, [&](Point a, Point b) { segments.push_back({a, b}); });
        for (const geom::Ring& h : pin.holes) metal.outer.insert(metal.outer.end(), h.begin(), h.end());
      }
      metal.outer.insert(metal.outer.end(), pin.outer.begin(), pin.outer.end());
    };
    join(pins[0]);
    t.order.push_back(0);
    std::vector<std::size_t> left;
    for (std::size_t i = 1; i < pins.size(); ++i) left.push_back(i);
    std::vector<std::vector<Point>> wires;
    while (!left.empty()) {
      std::vector<Point> targets;
      std::vector<std::size_t> owner;  // targets[j] is a point of pins[left[owner[j]]]
      for (std::size_t k = 0; k < left.size(); ++k) {
        const geom::Polygon& pin = pins[left[k]];
        std::vector<Point> c = is_point_pin(pin) ? std::vector<Point>{pin.outer[0]} : pin_candidates(pin, metal);
        keep_free(c, wavefront_);
        for (const Point p : c) {
          targets.push_back(p);
          owner.push_back(k);
        }
      }
      run_from(points, segments, targets, WavefrontStop::FirstTarget);
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
      const std::size_t k = owner[*best];
      Wire w = finish(best);
      if (w.status != WireStatus::Ok) {
        t.status = w.status;
        t.failed = left[k];
        return t;
      }
      for (std::size_t i = 1; i < w.points.size(); ++i) segments.push_back({w.points[i - 1], w.points[i]});
      metal.outer.insert(metal.outer.end(), w.points.begin(), w.points.end());
      if (w.points.size() >= 2) wires.push_back(std::move(w.points));
      join(pins[left[k]]);
      t.order.push_back(left[k]);
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
    }
    t.wires = without_overlaps(wires);
    if (t.wires.empty()) {  // every pin touches the first: one free point of it
      std::vector<Point> c = is_point_pin(pins[0]) ? std::vector<Point>{pins[0].outer[0]} : pin_candidates(pins[0], all);
      keep_free(c, wavefront_);
      t.wires.push_back({c.front()});
    }
    t.length = wires_length<Len>(t.wires);
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

template <class W>
void BasicRouter<W>::set_lattice(std::int64_t k) {
  if (k < 1) throw std::invalid_argument("the lattice must be at least 1");
  if (k != lattice_) obstacle_lines_.reset();
  lattice_ = k;
  pins_.set_lattice(k);
}

template <class W>
void BasicRouter<W>::run_from(std::span<const Point> points, std::span<const geom::Segment> segments,
                              std::span<const Point> targets, WavefrontStop stop) {
  if constexpr (kOctilinear) wavefront_.run(points, segments, targets, stop, lattice_);
  else wavefront_.run(points, segments, targets, stop);
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
