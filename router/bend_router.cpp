#include "router/bend_router.h"

#include <algorithm>
#include <array>
#include <deque>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/range/iterator_range.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>
#include <functional>
#include <optional>
#include <set>
#include <span>
#include <limits>
#include <map>
#include <string>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "geom/index.h"
#include "geom/predicates.h"
#include "router/pin_shapes.h"

namespace taut::router {

namespace {

using geom::Box;
using geom::Coord;
using geom::i128;
using geom::ceil_div;
using geom::floor_div;
using geom::i64;
using geom::Point;
using geom::Polygon;

// Axis directions, counter-clockwise: E, N, W, S. Quadrant q lies between direction q and
// direction q + 1: NE, NW, SW, SE. Direction k borders quadrants k - 1 and k.
constexpr Point kStep[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
constexpr geom::Direction kRay[4] = {geom::Direction::E, geom::Direction::N, geom::Direction::W,
                                     geom::Direction::S};
int opposite(int k) { return (k + 2) & 3; }
bool horizontal(int k) { return (k & 1) == 0; }

// The axis direction of b - a (a != b, axis-parallel).
int axis_dir(Point a, Point b) {
  if (b.y == a.y) return b.x > a.x ? 0 : 2;
  return b.y > a.y ? 1 : 3;
}

// The L1 distance of two points (int64: coordinates are below 2^30).
i64 dist1(Point a, Point b) { return std::abs(i64{b.x} - a.x) + std::abs(i64{b.y} - a.y); }

std::uint64_t key(Point p) {
  return (std::uint64_t{static_cast<std::uint32_t>(p.x)} << 32) | static_cast<std::uint32_t>(p.y);
}

// Quadrants outside the domain (material for the wedges).
unsigned outside_quadrants(const Box& d, Point p) {
  unsigned m = 0;
  if (p.x >= d.hi.x) m |= 0b1001;  // NE, SE
  if (p.x <= d.lo.x) m |= 0b0110;  // NW, SW
  if (p.y >= d.hi.y) m |= 0b0011;  // NE, NW
  if (p.y <= d.lo.y) m |= 0b1100;  // SW, SE
  return m;
}

// The wedges of a point from its material quadrants: maximal cyclic runs of free quadrants
// (neighbouring free quadrants meet along the axis ray between them). Each wedge as a
// quadrant mask.
std::vector<unsigned> wedges_of(unsigned material) {
  const unsigned free = ~material & 15u;
  std::vector<unsigned> out;
  if (free == 0) return out;
  if (free == 15) return {15u};
  // start at a free quadrant whose clockwise neighbour is material
  int start = 0;
  while (!((free >> start) & 1u) || ((free >> ((start + 3) & 3)) & 1u)) ++start;
  unsigned cur = 0;
  for (int i = 0; i < 4; ++i) {
    const int q = (start + i) & 3;
    if ((free >> q) & 1u) {
      cur |= 1u << q;
    } else if (cur) {
      out.push_back(cur);
      cur = 0;
    }
  }
  if (cur) out.push_back(cur);
  return out;
}

// Direction k leaves a point into wedge w (a quadrant mask) when a quadrant beside it is in w.
bool in_wedge(unsigned w, int k) { return ((w >> k) & 1u) || ((w >> ((k + 3) & 3)) & 1u); }

// The material quadrants around a point from the obstacle edges at it. An edge leaving the
// point along ray k (out) has its material on its left, quadrant k, and free space in quadrant
// k - 1; an edge arriving along ray k (in: the point is its end) the other way round.
struct Sides {
  int state[4] = {-1, -1, -1, -1};  // -1 unknown, 0 free, 1 material
  unsigned rays = 0;                // rays that carry an edge
  void set(int q, int v) {
    if (state[q] >= 0 && state[q] != v) throw std::invalid_argument("BendRouter: obstacle edges disagree about a side");
    state[q] = v;
  }
  void add(int k, bool out) {
    rays |= 1u << k;
    set(k, out ? 1 : 0);
    set((k + 3) & 3, out ? 0 : 1);
  }
  unsigned quadrants() {
    for (int round = 0; round < 4; ++round)
      for (int q = 0; q < 4; ++q) {
        if (state[q] >= 0) continue;
        if (!((rays >> q) & 1u) && state[(q + 3) & 3] >= 0) state[q] = state[(q + 3) & 3];
        else if (!((rays >> ((q + 1) & 3)) & 1u) && state[(q + 1) & 3] >= 0) state[q] = state[(q + 1) & 3];
      }
    unsigned m = 0;
    for (int q = 0; q < 4; ++q) {
      if (state[q] < 0) throw std::invalid_argument("BendRouter: a point with no edge beside it");
      if (state[q] == 1) m |= 1u << q;
    }
    return m;
  }
};

// (length + C * bends, bends) for Combined, (bends, length) for Link: compared
// lexicographically, added componentwise.
struct Cost {
  i128 first = 0;
  i64 second = 0;
  friend bool operator<(const Cost& a, const Cost& b) {
    return a.first != b.first ? a.first < b.first : a.second < b.second;
  }
  friend bool operator==(const Cost&, const Cost&) = default;
};
const Cost kInf{std::numeric_limits<i128>::max(), std::numeric_limits<i64>::max()};
// Costs add componentwise; the infinite cost absorbs.
Cost add_costs(const Cost& a, const Cost& b) {
  if (a == kInf || b == kInf) return kInf;
  return Cost{a.first + b.first, a.second + b.second};
}

// The built graph: graph vertex 2i is node i's h-node, 2i + 1 its v-node; both directions of
// every edge, each with its length and bends (the cost is made per query from the metric).
struct EdgeCost {
  i64 length = 0;
  i64 bends = 0;
};
using Graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, EdgeCost>;

}  // namespace

struct BendRouter::Impl {
  Box domain;
  std::vector<Polygon> obstacles;
  geom::ObstacleIndex index;

  // A node: a point with one of its wedges (graph vertices 2i: h-node, 2i + 1: v-node).
  struct Node {
    Point p;
    unsigned wedge = 0;
  };
  std::vector<Node> nodes;
  std::unordered_map<std::uint64_t, std::vector<std::int32_t>> vertex_nodes;  // obstacle vertex -> nodes

  // A track: from node `from` in direction `dir` to `end` (a free point); `to` >= 0 when it
  // ends on a vertex (that vertex's node whose wedge holds the way back), else -1.
  struct Track {
    std::int32_t from = 0;
    int dir = 0;
    Point start, end;
    std::int32_t to = -1;
  };
  std::vector<Track> tracks;
  // The built tracks of positive length by their fixed coordinate: [0] the vertical ones by x,
  // [1] the horizontal ones by y. A query track meets only those in its own span.
  std::vector<std::int32_t> tracks_across[2];
  // Calls f(track) for every built track of positive length perpendicular to a whose fixed
  // coordinate lies in a's span.
  template <class F>
  void for_each_track_across(const Track& a, F&& f) const {
    const bool h = horizontal(a.dir);
    const std::vector<std::int32_t>& v = tracks_across[h ? 0 : 1];
    const Coord lo = h ? std::min(a.start.x, a.end.x) : std::min(a.start.y, a.end.y);
    const Coord hi = h ? std::max(a.start.x, a.end.x) : std::max(a.start.y, a.end.y);
    auto fixed = [&](std::int32_t i) { const Point p = tracks[static_cast<std::size_t>(i)].start; return h ? p.x : p.y; };
    auto it = std::partition_point(v.begin(), v.end(), [&](std::int32_t i) { return fixed(i) < lo; });
    for (; it != v.end() && fixed(*it) <= hi; ++it) f(tracks[static_cast<std::size_t>(*it)]);
  }

  struct Edge {
    std::int32_t u, v;  // graph vertices
    i64 length;
    int bends;
  };
  std::vector<Edge> edges;
  Graph graph;
  BendGraphStats stats;

  PinShapes pins;

  Impl(const Box& d, std::span<const Polygon> obs)
      : domain(d), obstacles(obs.begin(), obs.end()), index(obs), pins(obs, d) {}

  bool is_vertex(Point p) const { return vertex_nodes.count(key(p)) != 0; }
  // p is in free space (a vertex with a wedge, or another point with free quadrants).
  bool is_free(Point p) const {
    const auto it = vertex_nodes.find(key(p));
    if (it != vertex_nodes.end()) return !it->second.empty();
    return !wedges_of(point_material(p)).empty();
  }

  // The node of vertex p whose wedge holds direction k; -1 when none does.
  std::int32_t vertex_node(Point p, int k) const {
    const auto it = vertex_nodes.find(key(p));
    if (it == vertex_nodes.end()) return -1;
    for (const std::int32_t n : it->second)
      if (in_wedge(nodes[static_cast<std::size_t>(n)].wedge, k)) return n;
    return -1;
  }

  // Material quadrants of a point that is not an obstacle vertex: the domain's outside, the
  // side of every obstacle edge through it, or all four when it lies inside an obstacle.
  unsigned point_material(Point p) const {
    if (p.x < domain.lo.x || p.x > domain.hi.x || p.y < domain.lo.y || p.y > domain.hi.y) return 15u;
    const std::vector<std::uint32_t> through = index.edges_in_box(Box{p, p});
    if (through.empty()) return inside_obstacle(p) ? 15u : outside_quadrants(domain, p);
    Sides sides;
    for (const std::uint32_t id : through) {  // p lies inside each (it is not a vertex)
      const geom::Segment& e = index.edge(id);
      sides.add(axis_dir(p, e.b), true);
      sides.add(axis_dir(p, e.a), false);
    }
    return sides.quadrants() | outside_quadrants(domain, p);
  }

  // Whether p, a point of the domain on no obstacle edge, lies inside an obstacle: a ray to the
  // west meets nothing until its first hit, so p is as the side of that hit facing it. At the
  // interior of vertical edges (a horizontal edge along the ray is hit at its east end, a
  // vertex): inside iff one of them has its material (the left of the directed edge) to the east,
  // that is, runs down. At a vertex inside the domain: inside iff the vertex has no free wedge
  // holding direction east (no edge leaves it eastwards, or the ray would have met that edge
  // first). O(log n) by the R-tree; a vertex hit outside the domain (whose wedges count the
  // outside as material) falls back to testing every obstacle.
  bool inside_obstacle(Point p) const {
    const geom::RayHit h = index.shoot(p, geom::Direction::W);
    if (!h.hit()) return false;
    const Point at{static_cast<Coord>(p.x - h.t.num / h.t.den), p.y};  // an integer for axis rays
    bool vertex = false, down = false;
    for (const std::uint32_t id : h.edges) {
      const geom::Segment& e = index.edge(id);
      vertex = vertex || e.a == at || e.b == at;
      down = down || e.a.y > e.b.y;
    }
    if (!vertex) return down;
    if (at.x > domain.lo.x) return vertex_node(at, 0) < 0;
    for (const Polygon& poly : obstacles)
      if (geom::locate(p, poly) == geom::Location::Inside) return true;
    return false;
  }

  // The track from node n at point p in direction k (k in its wedge).
  Track shoot(std::int32_t n, Point p, int k) const {
    Track t;
    t.from = n;
    t.dir = k;
    t.start = p;
    // distance to the domain side
    i64 limit = 0;
    switch (k) {
      case 0: limit = i64{domain.hi.x} - p.x; break;
      case 1: limit = i64{domain.hi.y} - p.y; break;
      case 2: limit = i64{p.x} - domain.lo.x; break;
      default: limit = i64{p.y} - domain.lo.y; break;
    }
    const geom::RayHit h = index.shoot(p, kRay[k], geom::RayOptions{true});
    i64 reach = limit;
    bool hit = false;
    if (h.hit()) {
      // axis rays: integer parameter (den 1, see geom/index.h)
      const i64 at = h.t.num / h.t.den;
      if (at <= limit) reach = at, hit = true;
    }
    t.end = Point{static_cast<Coord>(p.x + kStep[k].x * reach), static_cast<Coord>(p.y + kStep[k].y * reach)};
    if (hit && is_vertex(t.end)) {
      t.to = vertex_node(t.end, opposite(k));
      if (t.to < 0)
        throw std::logic_error("BendRouter: a track from " + std::to_string(p.x) + "," + std::to_string(p.y) +
                               " arrives at vertex " + std::to_string(t.end.x) + "," + std::to_string(t.end.y) +
                               " outside its wedges");
    }
    return t;
  }

  // Appends the edges of a node's own tracks that end on vertices (straight edges).
  void straight_edges(const Track& t, std::vector<Edge>& out) const {
    if (t.to < 0 || t.end == t.start) return;
    const int vv = horizontal(t.dir) ? 0 : 1;
    out.push_back({2 * t.from + vv, 2 * t.to + vv, dist1(t.start, t.end), 0});
  }

  // The L edge of a horizontal and a vertical track when they cross at a corner that is neither
  // end's origin nor a vertex (then the straight edges and a turn there make the same path).
  bool l_edge(const Track& h, const Track& v, Edge& e) const {
    const Coord x = v.start.x, y = h.start.y;
    if (x < std::min(h.start.x, h.end.x) || x > std::max(h.start.x, h.end.x)) return false;
    if (y < std::min(v.start.y, v.end.y) || y > std::max(v.start.y, v.end.y)) return false;
    const Point c{x, y};
    if (c == h.start || c == v.start || is_vertex(c)) return false;
    e = {2 * h.from, 2 * v.from + 1,
         dist1(h.start, c) + dist1(c, v.start), 1};
    return true;
  }

  void build() {
    // nodes: every obstacle vertex with its wedges. Each ring edge at a vertex says which of the
    // two quadrants beside it is material (the left of the directed edge); a quadrant with no
    // edge on either side is what its neighbour across the edgeless ray is. Pairing the in- and
    // out-edges of one ring visit would be wrong where a ring touches itself (a pinch).
    std::unordered_map<std::uint64_t, Sides> material;
    std::vector<Point> order;
    auto ring_material = [&](const geom::Ring& r) {
      const std::size_t m = r.size();
      for (std::size_t i = 0; i < m; ++i) {
        const Point v = r[i], prev = r[(i + m - 1) % m], next = r[(i + 1) % m];
        if (v.x != prev.x && v.y != prev.y) throw std::invalid_argument("BendRouter: an obstacle edge is not axis-parallel");
        if (v == prev || v == next) throw std::invalid_argument("BendRouter: a ring repeats a vertex");
        auto [it, fresh] = material.try_emplace(key(v));
        if (fresh) order.push_back(v);
        it->second.add(axis_dir(v, next), true);
        it->second.add(axis_dir(v, prev), false);
      }
    };
    for (const Polygon& poly : obstacles) {
      ring_material(poly.outer);
      for (const geom::Ring& h : poly.holes) ring_material(h);
    }
    std::sort(order.begin(), order.end());
    for (const Point v : order) {
      const unsigned m = material[key(v)].quadrants() | outside_quadrants(domain, v);
      auto& list = vertex_nodes[key(v)];
      for (const unsigned w : wedges_of(m)) {
        list.push_back(static_cast<std::int32_t>(nodes.size()));
        nodes.push_back({v, w});
      }
    }
    stats.vertices = order.size();
    stats.nodes = nodes.size();

    for (std::int32_t n = 0; n < static_cast<std::int32_t>(nodes.size()); ++n) {
      edges.push_back({2 * n, 2 * n + 1, 0, 1});  // the turn
      for (int k = 0; k < 4; ++k)
        if (in_wedge(nodes[static_cast<std::size_t>(n)].wedge, k)) tracks.push_back(shoot(n, nodes[static_cast<std::size_t>(n)].p, k));
    }
    stats.tracks = tracks.size();
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(tracks.size()); ++i) {
      const Track& t = tracks[static_cast<std::size_t>(i)];
      if (t.end != t.start) tracks_across[horizontal(t.dir) ? 1 : 0].push_back(i);
    }
    for (int h = 0; h < 2; ++h)
      std::stable_sort(tracks_across[h].begin(), tracks_across[h].end(), [&](std::int32_t i, std::int32_t j) {
        const Point p = tracks[static_cast<std::size_t>(i)].start, q = tracks[static_cast<std::size_t>(j)].start;
        return h ? p.y < q.y : p.x < q.x;
      });
    for (const Track& t : tracks)
      if (t.dir == 0 || t.dir == 1) straight_edges(t, edges);  // W and S give the same edges
    stats.straight_edges = edges.size() - nodes.size();

    // L edges: one sweep over x, the horizontal tracks alive in a tree on y
    struct Event {
      Coord x;
      int kind;  // 0 insert horizontal, 1 query vertical, 2 remove horizontal
      std::int32_t track;
    };
    std::vector<Event> ev;
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(tracks.size()); ++i) {
      const Track& t = tracks[static_cast<std::size_t>(i)];
      if (t.end == t.start) continue;
      if (horizontal(t.dir)) {
        ev.push_back({std::min(t.start.x, t.end.x), 0, i});
        ev.push_back({std::max(t.start.x, t.end.x), 2, i});
      } else {
        ev.push_back({t.start.x, 1, i});
      }
    }
    std::sort(ev.begin(), ev.end(), [](const Event& a, const Event& b) {
      return a.x != b.x ? a.x < b.x : a.kind != b.kind ? a.kind < b.kind : a.track < b.track;
    });
    std::multimap<Coord, std::int32_t> alive;
    std::vector<std::multimap<Coord, std::int32_t>::iterator> where(tracks.size());
    const std::size_t before = edges.size();
    for (const Event& e : ev) {
      const Track& t = tracks[static_cast<std::size_t>(e.track)];
      if (e.kind == 0) {
        where[static_cast<std::size_t>(e.track)] = alive.emplace(t.start.y, e.track);
      } else if (e.kind == 2) {
        alive.erase(where[static_cast<std::size_t>(e.track)]);
      } else {
        const Coord lo = std::min(t.start.y, t.end.y), hi = std::max(t.start.y, t.end.y);
        for (auto it = alive.lower_bound(lo); it != alive.end() && it->first <= hi; ++it) {
          Edge edge{};
          if (l_edge(tracks[static_cast<std::size_t>(it->second)], t, edge)) edges.push_back(edge);
        }
      }
    }
    stats.l_edges = edges.size() - before;

    std::vector<std::pair<std::size_t, std::size_t>> arcs;
    std::vector<EdgeCost> costs;
    arcs.reserve(2 * edges.size());
    costs.reserve(2 * edges.size());
    for (const Edge& e : edges) {
      const auto u = static_cast<std::size_t>(e.u), v = static_cast<std::size_t>(e.v);
      arcs.emplace_back(u, v), costs.push_back({e.length, e.bends});
      arcs.emplace_back(v, u), costs.push_back({e.length, e.bends});
    }
    graph = Graph(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(), costs.begin(), 2 * nodes.size());
    edges.clear();
    edges.shrink_to_fit();
  }

  // One Dijkstra run from s to every sink: per sink its walk (points, each with whether the
  // wire is horizontal there) and its chain of built graph vertices (walk[leads[k] + i] is
  // chains[k][i]).
  struct Search {
    WireStatus status = WireStatus::Ok;
    std::size_t failed = 0;  // the sink (or 0 for the source) when not Ok
    std::vector<std::vector<std::pair<Point, bool>>> walks;
    std::vector<std::vector<std::size_t>> chains;
    std::vector<std::size_t> leads;
    std::vector<BendCost> costs;  // without walks: per sink
    // All: the whole Dijkstra from the source (no sinks): per built graph vertex its cost, its
    // predecessor (itself at a root) and the source's query vertex it was entered from (-1: the
    // source is that vertex); the source's query node and tracks when it is no vertex.
    std::vector<Cost> dist;
    std::vector<std::size_t> pred;
    std::vector<std::int32_t> entered_from;
    std::vector<Node> qnodes;
    std::vector<Track> qtracks;
  };
  // Walks: the walks and chains. Costs: only `costs` (a sink not reached is not an error then).
  // Bends (link metric only): only the bends of `costs` (lengths 0), by a 0-1 breadth-first
  // search instead of Dijkstra.
  // The source and each sink is a set of points, any of which will do (a point pin is one, a
  // shape pin its candidates): the search starts from every free source point at cost 0 and
  // takes the best of a sink's points. A set with no free point is not free.
  // All: see Search.
  enum class Mode { Walks, Costs, Bends, All };
  Search search(std::span<const Point> sources, std::span<const std::vector<Point>> sinks, BendMetric metric,
                i64 bend_cost, Mode mode = Mode::Walks) const;
  Search search(Point s, std::span<const Point> sinks, BendMetric metric, i64 bend_cost,
                Mode mode = Mode::Walks) const {
    std::vector<std::vector<Point>> sets;
    sets.reserve(sinks.size());
    for (const Point t : sinks) sets.push_back({t});
    return search({&s, 1}, sets, metric, bend_cost, mode);
  }
  BendPath path(Point s, Point t, BendMetric metric, i64 bend_cost) const;
  BendTree tree(std::span<const Point> sources, std::span<const std::vector<Point>> sinks, BendMetric metric,
                i64 bend_cost) const;
  // The candidate sets of pins (PinShapes::candidates; a point pin is its point; pins that
  // share a point get it in both sets).
  void pin_sets(const Polygon& source, std::span<const Polygon> sinks, std::vector<Point>& from,
                std::vector<std::vector<Point>>& to) const;
};

namespace {

// A walk of the graph as (point, horizontal there?) pairs, made into the wire's points: an L
// edge gets its corner, repeated and collinear points go.
std::vector<Point> walk_points(const std::vector<std::pair<Point, bool>>& walk) {
  std::vector<Point> pts;
  pts.push_back(walk.front().first);
  for (std::size_t i = 1; i < walk.size(); ++i) {
    const auto [a, ah] = walk[i - 1];
    const auto [b, bh] = walk[i];
    if (a == b) continue;  // a turn
    if (ah != bh) pts.push_back(ah ? Point{b.x, a.y} : Point{a.x, b.y});
    pts.push_back(b);
  }
  std::vector<Point> clean;
  for (const Point p : pts) {
    if (!clean.empty() && clean.back() == p) continue;
    if (clean.size() >= 2) {
      const Point a = clean[clean.size() - 2], b = clean.back();
      if (geom::orientation(a, b, p) == 0 && (i64{b.x} - a.x) * (i64{p.x} - b.x) + (i64{b.y} - a.y) * (i64{p.y} - b.y) > 0) {
        clean.back() = p;
        continue;
      }
    }
    clean.push_back(p);
  }
  return clean;
}

i64 l1_length(const std::vector<Point>& pts) {
  i64 len = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) len += dist1(pts[i - 1], pts[i]);
  return len;
}

}  // namespace

BendRouter::Impl::Search BendRouter::Impl::search(std::span<const Point> sources,
                                                  std::span<const std::vector<Point>> sinks, BendMetric metric,
                                                  i64 bend_cost, Mode mode) const {
  Search out;
  // The query points (group 0: the source's, group k + 1: sink k's): an obstacle vertex uses its
  // nodes; another free point gets a node of its own (its one wedge) with its tracks.
  std::vector<Point> q(sources.begin(), sources.end());
  std::vector<std::size_t> group(q.size(), 0);
  for (std::size_t k = 0; k < sinks.size(); ++k)
    for (const Point t : sinks[k]) q.push_back(t), group.push_back(k + 1);
  const std::int32_t base = static_cast<std::int32_t>(nodes.size());
  const std::int32_t built = 2 * base;  // graph vertices of the built graph
  std::vector<Node> qnodes;
  std::vector<std::vector<std::int32_t>> ends(q.size());  // nodes of each query point
  for (std::size_t i = 0; i < q.size(); ++i) {
    const auto it = vertex_nodes.find(key(q[i]));
    if (it != vertex_nodes.end()) {
      ends[i] = it->second;
    } else {
      const auto same = std::find_if(qnodes.begin(), qnodes.end(), [&](const Node& n) { return n.p == q[i]; });
      if (same != qnodes.end()) {
        ends[i] = {base + static_cast<std::int32_t>(same - qnodes.begin())};
      } else {
        const std::vector<unsigned> w = wedges_of(point_material(q[i]));
        if (!w.empty()) {
          ends[i].push_back(base + static_cast<std::int32_t>(qnodes.size()));
          qnodes.push_back({q[i], w.front()});
        }
      }
    }
  }
  {
    std::vector<char> has_free(sinks.size() + 1, 0);
    for (std::size_t i = 0; i < q.size(); ++i)
      if (!ends[i].empty()) has_free[group[i]] = 1;
    for (std::size_t g = 0; g <= sinks.size(); ++g)
      if (!has_free[g]) {
        out.status = g == 0 ? WireStatus::SourceNotFree : WireStatus::TargetNotFree;
        out.failed = g == 0 ? 0 : g - 1;
        return out;
      }
  }
  // the query nodes that hold a source point
  std::vector<char> source_qnode(qnodes.size(), 0);
  for (std::size_t i = 0; i < q.size(); ++i)
    if (group[i] == 0)
      for (const std::int32_t n : ends[i])
        if (n >= base) source_qnode[static_cast<std::size_t>(n - base)] = 1;
  auto is_source_qnode = [&](std::int32_t n) { return n >= base && source_qnode[static_cast<std::size_t>(n - base)]; };
  auto weight = [&](i64 length, i64 bends) {
    return metric == BendMetric::Link ? Cost{bends, length} : Cost{i128{length} + i128{bend_cost} * bends, bends};
  };
  auto node_of = [&](std::int32_t gv) -> const Node& {
    return gv < built ? nodes[static_cast<std::size_t>(gv / 2)] : qnodes[static_cast<std::size_t>(gv / 2 - base)];
  };

  // the query nodes' tracks and edges: straight to the vertex a track ends on, L with the built
  // tracks, and straight or L between two query nodes
  std::vector<Track> qtracks;
  for (std::size_t j = 0; j < qnodes.size(); ++j)
    for (int k = 0; k < 4; ++k)
      if (in_wedge(qnodes[j].wedge, k)) qtracks.push_back(shoot(base + static_cast<std::int32_t>(j), qnodes[j].p, k));
  std::vector<Edge> qedges;
  for (std::size_t i = 0; i < qtracks.size(); ++i) {
    const Track& a = qtracks[i];
    straight_edges(a, qedges);
    if (a.end == a.start) continue;
    for_each_track_across(a, [&](const Track& b) {
      Edge e{};
      if (horizontal(a.dir) ? l_edge(a, b, e) : l_edge(b, a, e)) qedges.push_back(e);
    });
    for (std::size_t j = 0; j < qtracks.size(); ++j) {
      const Track& b = qtracks[j];
      if (b.from == a.from) continue;
      if (b.dir == opposite(a.dir)) {
        // b's point on a's track: a straight edge (each pair once: from the smaller node)
        const Point p = b.start;
        const bool on = a.from < b.from && std::min(a.start.x, a.end.x) <= p.x && p.x <= std::max(a.start.x, a.end.x) &&
                        std::min(a.start.y, a.end.y) <= p.y && p.y <= std::max(a.start.y, a.end.y);
        const int vv = horizontal(a.dir) ? 0 : 1;
        if (on) qedges.push_back({2 * a.from + vv, 2 * b.from + vv, dist1(a.start, p), 0});
      } else if (horizontal(a.dir) && !horizontal(b.dir) && b.end != b.start) {
        Edge e{};
        if (l_edge(a, b, e)) qedges.push_back(e);
      }
    }
  }

  // Dijkstra on the built graph only: a query node that is a start enters it through its edges
  // (each neighbour starts at that edge's cost), a sink that is not a vertex is reached through
  // its edges (each neighbour offers its distance plus the edge), and an edge between the source
  // and a sink is an offer of its own.
  struct Entry {
    std::int32_t gv;     // a vertex of the built graph
    std::int32_t query;  // the query graph vertex it is joined to (-1: it is the point itself)
    Cost w;
  };
  std::vector<Entry> starts;
  std::vector<std::vector<Entry>> finishes(sinks.size());
  struct Offer {
    Cost cost = kInf;
    std::optional<std::size_t> finish;     // index into finishes[k]
    std::int32_t direct_from = -1, direct_to = -1;  // an edge between the source and the sink
    std::optional<Point> shared;           // a free point of the source and the sink
  };
  std::vector<Offer> offers(sinks.size());
  std::unordered_set<std::uint64_t> free_sources;
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (ends[i].empty()) continue;  // not free
    if (group[i] == 0) free_sources.insert(key(q[i]));
    for (const std::int32_t n : ends[i])
      if (n < base)
        for (const std::int32_t gv : {2 * n, 2 * n + 1}) {
          if (group[i] == 0) starts.push_back({gv, -1, Cost{}});
          else finishes[group[i] - 1].push_back({gv, -1, Cost{}});
        }
  }
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (group[i] == 0 || ends[i].empty() || !free_sources.count(key(q[i]))) continue;
    Offer& o = offers[group[i] - 1];
    if (!o.shared) o = Offer{Cost{}, std::nullopt, -1, -1, q[i]};  // a sink at the source
  }
  // the query points at each query node (0: the source), so an edge finds its ends in O(1)
  std::unordered_map<std::int32_t, std::vector<std::size_t>> at_node;
  for (std::size_t i = 0; i < q.size(); ++i)
    for (const std::int32_t n : ends[i])
      if (n >= base) at_node[n].push_back(i);
  for (const Edge& e : qedges) {
    const Cost w = weight(e.length, e.bends);
    for (const auto& [a, b] : {std::pair{e.u, e.v}, std::pair{e.v, e.u}}) {
      if (a < built) continue;
      const auto it = at_node.find(a / 2);
      if (it == at_node.end()) continue;
      if (is_source_qnode(a / 2)) {  // a source's node: an entry (a sink there is at the source)
        if (b < built) starts.push_back({b, a, w});
        continue;
      }
      for (const std::size_t i : it->second) {
        const std::size_t k = group[i] - 1;
        if (b < built) {
          finishes[k].push_back({b, a, w});
        } else if (is_source_qnode(b / 2) && w < offers[k].cost) {
          offers[k] = Offer{w, std::nullopt, b, a, std::nullopt};
        }
      }
    }
  }

  if (mode == Mode::Bends) {
    // 0-1 breadth-first search on bends (every edge has 0 or 1; the entries too, pushed in
    // order: 0 at the front, 1 at the back, so the deque stays sorted)
    constexpr i64 kNone = std::numeric_limits<i64>::max();
    const std::size_t nv = static_cast<std::size_t>(built);
    std::vector<i64> db(nv, kNone);
    std::vector<char> done(nv, 0);
    std::deque<std::size_t> dq;
    for (const Entry& e : starts) {
      const auto v = static_cast<std::size_t>(e.gv);
      const auto b = static_cast<i64>(e.w.first);
      if (b >= db[v]) continue;
      db[v] = b;
      if (b == 0) dq.push_front(v);
      else dq.push_back(v);
    }
    while (!dq.empty()) {
      const std::size_t u = dq.front();
      dq.pop_front();
      if (done[u]) continue;
      done[u] = 1;
      for (const auto e : boost::make_iterator_range(boost::out_edges(u, graph))) {
        const std::size_t v = boost::target(e, graph);
        const i64 b = graph[e].bends;
        if (db[u] + b >= db[v]) continue;
        db[v] = db[u] + b;
        if (b == 0) dq.push_front(v);
        else dq.push_back(v);
      }
    }
    for (std::size_t k = 0; k < sinks.size(); ++k) {
      i64 best = offers[k].cost == kInf ? kNone : static_cast<i64>(offers[k].cost.first);
      for (const Entry& f : finishes[k])
        if (db[static_cast<std::size_t>(f.gv)] != kNone)
          best = std::min(best, db[static_cast<std::size_t>(f.gv)] + static_cast<i64>(f.w.first));
      BendCost c;
      c.reached = best != kNone;
      c.bends = c.reached ? best : 0;
      out.costs.push_back(c);
    }
    return out;
  }

  const std::size_t nv = static_cast<std::size_t>(built);
  std::vector<Cost> dist(nv, kInf);
  std::vector<std::size_t> pred(nv);
  for (std::size_t v = 0; v < nv; ++v) pred[v] = v;
  std::vector<std::size_t> roots;  // the graph vertices Dijkstra starts from
  std::vector<std::int32_t> entered_from(nv, -1);  // the source's query vertex; -1: a source vertex
  for (const Entry& e : starts) {
    const auto v = static_cast<std::size_t>(e.gv);
    if (e.w < dist[v]) {
      if (dist[v] == kInf) roots.push_back(v);
      dist[v] = e.w;
      entered_from[v] = e.query;
    }
  }
  std::unordered_map<std::size_t, std::vector<std::pair<std::size_t, std::size_t>>> finish_at;  // -> (sink, entry)
  for (std::size_t k = 0; k < sinks.size(); ++k)
    for (std::size_t i = 0; i < finishes[k].size(); ++i)
      finish_at[static_cast<std::size_t>(finishes[k][i].gv)].emplace_back(k, i);
  // The offers made so far (a multiset, so the largest is at hand with many sinks) and how many
  // sinks have none yet.
  std::multiset<Cost> offered;
  std::size_t unoffered = 0;
  for (const Offer& o : offers) {
    if (o.cost == kInf) ++unoffered;
    else offered.insert(o.cost);
  }
  struct Stop {};
  struct Visitor : boost::default_dijkstra_visitor {
    const std::vector<Cost>* dist;
    const std::vector<std::vector<Entry>>* finishes;
    const std::unordered_map<std::size_t, std::vector<std::pair<std::size_t, std::size_t>>>* finish_at;
    std::vector<Offer>* offers;
    std::multiset<Cost>* offered;
    std::size_t* unoffered;
    bool all = false;  // settle every vertex
    void examine_vertex(std::size_t u, const Graph&) const {
      if (all) return;
      const Cost& d = (*dist)[u];
      // every sink's best offer is at most what is left: done
      if (*unoffered == 0 && !(d < *offered->rbegin())) throw Stop{};
      const auto it = finish_at->find(u);
      if (it == finish_at->end()) return;
      for (const auto& [k, i] : it->second) {
        const Cost c = add_costs(d, (*finishes)[k][i].w);
        Offer& o = (*offers)[k];
        if (!(c < o.cost)) continue;
        if (o.cost == kInf) --*unoffered;
        else offered->erase(offered->find(o.cost));
        offered->insert(c);
        o = Offer{c, i, -1, -1, std::nullopt};
      }
    }
  };
  Visitor vis;
  vis.dist = &dist;
  vis.finishes = &finishes;
  vis.finish_at = &finish_at;
  vis.offers = &offers;
  vis.offered = &offered;
  vis.unoffered = &unoffered;
  vis.all = mode == Mode::All;
  const auto index = boost::get(boost::vertex_index, graph);
  const auto wmap = boost::make_function_property_map<Graph::edge_descriptor, Cost>(
      [&](const Graph::edge_descriptor& e) {
        const EdgeCost& c = graph[e];
        return weight(c.length, c.bends);
      });
  std::vector<boost::default_color_type> color(nv, boost::white_color);
  try {
    if (!roots.empty())
      boost::dijkstra_shortest_paths_no_init(
          graph, roots.begin(), roots.end(), boost::make_iterator_property_map(pred.begin(), index),
          boost::make_iterator_property_map(dist.begin(), index), wmap, index, std::less<Cost>(), add_costs, Cost{}, vis,
          boost::make_iterator_property_map(color.begin(), index));
  } catch (const Stop&) {
  }

  if (mode == Mode::All) {
    out.dist = std::move(dist);
    out.pred = std::move(pred);
    out.entered_from = std::move(entered_from);
    out.qnodes = std::move(qnodes);
    out.qtracks = std::move(qtracks);
    return out;
  }
  if (mode == Mode::Costs) {
    for (const Offer& o : offers) {
      BendCost c;
      if (o.cost != kInf) {
        c.reached = true;
        if (metric == BendMetric::Link) {
          c.bends = static_cast<i64>(o.cost.first);
          c.length = o.cost.second;
        } else {
          c.bends = o.cost.second;
          c.length = static_cast<i64>(o.cost.first - i128{bend_cost} * o.cost.second);
        }
      }
      out.costs.push_back(c);
    }
    return out;
  }

  // each sink's walk: the source's query vertex (if any), the built vertices from the root of
  // the predecessor tree to the finish, the sink's query vertex (if any)
  out.walks.resize(sinks.size());
  out.chains.resize(sinks.size());
  out.leads.assign(sinks.size(), 0);
  for (std::size_t k = 0; k < sinks.size(); ++k) {
    const Offer& o = offers[k];
    if (o.cost == kInf) {
      out.status = WireStatus::Unreachable;
      out.failed = k;
      return out;
    }
    auto& walk = out.walks[k];
    auto add_gv = [&](std::int32_t gv) { walk.emplace_back(node_of(gv).p, gv % 2 == 0); };
    if (o.shared) {
      walk.emplace_back(*o.shared, true);
    } else if (!o.finish) {
      add_gv(o.direct_from);
      add_gv(o.direct_to);
    } else {
      const Entry& fin = finishes[k][*o.finish];
      std::vector<std::size_t> back;
      for (std::size_t v = static_cast<std::size_t>(fin.gv);; v = pred[v]) {
        back.push_back(v);
        if (pred[v] == v) break;
        if (back.size() > nv) throw std::logic_error("BendRouter: predecessor cycle");
      }
      std::reverse(back.begin(), back.end());
      const std::int32_t from = entered_from[back.front()];
      if (from >= 0) add_gv(from);
      out.leads[k] = from >= 0 ? 1 : 0;
      for (const std::size_t v : back) add_gv(static_cast<std::int32_t>(v));
      if (fin.query >= 0) add_gv(fin.query);
      out.chains[k] = std::move(back);
    }
    // the wire must cost what Dijkstra says
    const std::vector<Point> pts = walk_points(walk);
    if (!(weight(l1_length(pts), geom::count_bends(pts)) == o.cost))
      throw std::logic_error("BendRouter: a wire's cost differs from the graph's distance");
  }
  out.status = WireStatus::Ok;
  return out;
}

BendPath BendRouter::Impl::path(Point s, Point t, BendMetric metric, i64 bend_cost) const {
  BendPath out;
  const Point sinks[1] = {t};
  const Search r = search(s, sinks, metric, bend_cost);
  out.status = r.status;
  if (r.status != WireStatus::Ok) return out;
  out.points = walk_points(r.walks[0]);
  out.bends = geom::count_bends(out.points);
  out.length = l1_length(out.points);
  return out;
}

BendTree BendRouter::Impl::tree(std::span<const Point> sources, std::span<const std::vector<Point>> sinks,
                                BendMetric metric, i64 bend_cost) const {
  BendTree out;
  const Search r = search(sources, sinks, metric, bend_cost);
  out.status = r.status;
  out.failed = r.failed;
  if (r.status != WireStatus::Ok) return out;
  // The chains of built vertices form the predecessor tree: each sink's wire starts at the last
  // vertex of its chain that an earlier sink's chain passed (its walk from there on), else at
  // the source; a first stretch that runs along an earlier wire from there is cut off.
  std::unordered_set<std::size_t> seen;
  std::vector<std::pair<Point, Point>> metal;  // segments written so far
  for (std::size_t k = 0; k < sinks.size(); ++k) {
    const auto& walk = r.walks[k];
    out.paths.push_back(walk_points(walk));
    const auto& chain = r.chains[k];
    std::size_t start = 0;  // index into walk
    for (std::size_t i = chain.size(); i-- > 0;)
      if (seen.count(chain[i])) {
        start = r.leads[k] + i;
        break;
      }
    seen.insert(chain.begin(), chain.end());
    std::vector<Point> w = walk_points({walk.begin() + static_cast<std::ptrdiff_t>(start), walk.end()});
    while (w.size() >= 2) {
      const Point p = w[0], n = w[1];
      const i64 len = dist1(p, n);
      const int dx = (n.x > p.x) - (n.x < p.x), dy = (n.y > p.y) - (n.y < p.y);
      i64 along = 0;  // how far an earlier segment runs from p towards n
      for (const auto& [a, b] : metal)
        for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
          const int ex = (to.x > from.x) - (to.x < from.x), ey = (to.y > from.y) - (to.y < from.y);
          if (ex != dx || ey != dy) continue;
          // p on the segment, the segment going on past p in the same direction
          const bool on = dx != 0 ? from.y == p.y && std::min(from.x, to.x) <= p.x && p.x < std::max(from.x, to.x)
                                  : from.x == p.x && std::min(from.y, to.y) <= p.y && p.y < std::max(from.y, to.y);
          if (on) along = std::max(along, dist1(p, to));
        }
      if (along == 0) break;
      if (along >= len) {
        w.erase(w.begin());
        continue;
      }
      w[0] = Point{static_cast<Coord>(p.x + dx * along), static_cast<Coord>(p.y + dy * along)};
      break;
    }
    if (w.size() == 1) continue;  // the sink lies on earlier metal or on the source pin
    for (std::size_t i = 1; i < w.size(); ++i) metal.emplace_back(w[i - 1], w[i]);
    out.wires.push_back(std::move(w));
  }
  if (out.wires.empty() && !out.paths.empty()) out.wires.push_back(out.paths[0]);  // all at the source
  return out;
}

void BendRouter::Impl::pin_sets(const Polygon& source, std::span<const Polygon> sinks, std::vector<Point>& from,
                                std::vector<std::vector<Point>>& to) const {
  // the source's candidates see every sink's vertices
  Polygon all_sinks;
  for (const Polygon& s : sinks) {
    all_sinks.outer.insert(all_sinks.outer.end(), s.outer.begin(), s.outer.end());
    for (const geom::Ring& h : s.holes) all_sinks.outer.insert(all_sinks.outer.end(), h.begin(), h.end());
  }
  // free candidates only, so that a shared point is a free one
  auto free_only = [&](std::vector<Point> v) {
    v.erase(std::remove_if(v.begin(), v.end(), [&](Point p) { return !is_free(p); }), v.end());
    return v;
  };
  from = free_only(pins.candidates(source, all_sinks));
  to.clear();
  for (const Polygon& s : sinks) {
    to.push_back(free_only(pins.candidates(s, source)));
    // pins that meet: their shared point in both sets (search() offers it at no cost)
    if (const auto p = shared_point(from, source, to.back(), s, [&](Point q) { return is_free(q); })) {
      if (!std::binary_search(from.begin(), from.end(), *p)) from.insert(std::upper_bound(from.begin(), from.end(), *p), *p);
      to.back().push_back(*p);
    }
  }
}

BendRouter::BendRouter(const Box& domain, std::span<const Polygon> obstacles)
    : impl_(std::make_unique<Impl>(domain, obstacles)) {
  impl_->build();
}
BendRouter::~BendRouter() = default;
BendRouter::BendRouter(BendRouter&&) noexcept = default;
BendRouter& BendRouter::operator=(BendRouter&&) noexcept = default;

BendPath BendRouter::path(Point from, Point to, BendMetric metric, std::int64_t bend_cost) const {
  if (metric == BendMetric::Combined && (bend_cost < 0 || bend_cost > (i64{1} << 31)))
    throw std::invalid_argument("BendRouter: the bend cost must lie in [0, 2^31]");
  return impl_->path(from, to, metric, bend_cost);
}

BendTree BendRouter::tree(Point source, std::span<const Point> sinks, BendMetric metric, std::int64_t bend_cost) const {
  if (metric == BendMetric::Combined && (bend_cost < 0 || bend_cost > (i64{1} << 31)))
    throw std::invalid_argument("BendRouter: the bend cost must lie in [0, 2^31]");
  std::vector<std::vector<Point>> sets;
  sets.reserve(sinks.size());
  for (const Point t : sinks) sets.push_back({t});
  return impl_->tree({&source, 1}, sets, metric, bend_cost);
}

BendTree BendRouter::tree(const Polygon& source, std::span<const Polygon> sinks, BendMetric metric,
                          std::int64_t bend_cost) const {
  if (metric == BendMetric::Combined && (bend_cost < 0 || bend_cost > (i64{1} << 31)))
    throw std::invalid_argument("BendRouter: the bend cost must lie in [0, 2^31]");
  auto check = [](const Polygon& pin) {
    if (!pin_shape_supported(pin))
      throw std::invalid_argument("BendRouter: a pin edge is not horizontal, vertical or at 45 degrees");
  };
  check(source);
  for (const Polygon& s : sinks) check(s);
  std::vector<Point> from;
  std::vector<std::vector<Point>> to;
  impl_->pin_sets(source, sinks, from, to);
  return impl_->tree(from, to, metric, bend_cost);
}

BendPath BendRouter::path(const Polygon& from, const Polygon& to, BendMetric metric, std::int64_t bend_cost) const {
  BendPath out;
  const BendTree t = tree(from, {&to, 1}, metric, bend_cost);
  out.status = t.status;
  if (t.status != WireStatus::Ok) return out;
  out.points = t.paths[0];
  out.bends = geom::count_bends(out.points);
  out.length = l1_length(out.points);
  return out;
}

std::optional<std::size_t> BendRouter::pin_meets_obstacle(const Polygon& pin) const {
  return impl_->pins.meets_obstacle(pin);
}

std::vector<BendCost> BendRouter::costs(Point source, std::span<const Point> sinks, BendMetric metric,
                                        std::int64_t bend_cost, WireStatus* status, std::size_t* failed) const {
  if (metric == BendMetric::Combined && (bend_cost < 0 || bend_cost > (i64{1} << 31)))
    throw std::invalid_argument("BendRouter: the bend cost must lie in [0, 2^31]");
  Impl::Search r = impl_->search(source, sinks, metric, bend_cost, Impl::Mode::Costs);
  if (status) *status = r.status;
  if (failed) *failed = r.failed;
  return std::move(r.costs);
}

std::vector<std::int64_t> BendRouter::fewest_bends(Point source, std::span<const Point> sinks, WireStatus* status,
                                                   std::size_t* failed) const {
  Impl::Search r = impl_->search(source, sinks, BendMetric::Link, 0, Impl::Mode::Bends);
  if (status) *status = r.status;
  if (failed) *failed = r.failed;
  std::vector<std::int64_t> out;
  for (const BendCost& c : r.costs) out.push_back(c.reached ? c.bends : -1);
  return out;
}

const BendGraphStats& BendRouter::stats() const { return impl_->stats; }

// ---------------------------------------------------------------------------------------------
// BendTargetMap (section 4)

namespace {

// One slab tree: items (a vertex's track crossing the query axis) sorted by u (the coordinate
// along the query interval), a segment tree over them whose every node stands for the lower
// envelope of its items' keys along v: piecewise constant, from each breakpoint on (up to the
// next) the best item, or -1.
//
// Fractional cascading (Chazelle and Guibas), so a query costs O(log n): node n's catalog holds
// its envelope's breakpoints and every kSample-th entry of each child's catalog, each entry with
// the envelope's item there and, per child, the index of the child's last entry at or before
// it. Between two consecutive entries of a node each child has fewer than kSample entries, so a
// child's position follows from its parent's in at most kSample steps. A query binary-searches v
// once, in the catalog of the lowest node whose leaves hold its whole interval (the lowest
// common ancestor of its end leaves), then walks down the two paths to those leaves, taking the
// item of every node that the interval covers whole. A query's interval is a track from the
// query point to the first obstacle, usually short, and then a binary search in each covering
// node is faster than the walk (which touches twice the nodes): so an interval under a node of
// at most kDirectSpan leaves is searched that way, a constant's work, and only longer ones
// cascade. Measured (bench_bends, README's Performance): this takes 1.00-1.19 times the time of a
// binary search in every covering node (O(log^2 n), query with direct_span unbounded: the benchmark's baseline),
// cascading every query 1.12-1.45 times. A catalog holds at most kSample / (kSample - 1) times
// its envelope's breakpoints (about 1.02 times on the benchmark's layouts: samples often repeat
// a breakpoint); the envelopes are not kept.
struct SlabTree {
  struct Item {
    Coord u;
    Coord vlo, vhi;  // the closed range of v the item covers
    Cost key;
    std::int32_t gv;  // the built graph vertex the step arrives at
  };
  struct Piece {
    Coord v0;
    std::int32_t item;  // -1: none
  };
  struct Entry {
    Coord v;
    std::int32_t item;     // the envelope's item at v (-1: none)
    std::int32_t down[2];  // per child: its catalog's last entry with v' <= v (-1: none)
  };
  static constexpr std::size_t kSample = 4;
  // Intervals whose lowest common ancestor spans at most this many leaves are searched node by
  // node (at most 2 log2(kDirectSpan) nodes, each a binary search over O(kDirectSpan) entries: a
  // constant), longer ones by cascading.
  static constexpr std::size_t kDirectSpan = 4096;
  std::vector<Item> items;     // sorted by u
  std::size_t leaves = 0;      // a power of two; node 1 is the root, leaf i is node leaves + i
  std::vector<Entry> entries;  // every node's catalog, node n's the len[n] entries from at[n]
  std::vector<std::uint32_t> at, len;
  std::size_t breakpoints = 0;  // of all envelopes

  bool better(std::int32_t a, std::int32_t b) const {
    if (a < 0) return false;
    if (b < 0) return true;
    const Item& x = items[static_cast<std::size_t>(a)];
    const Item& y = items[static_cast<std::size_t>(b)];
    if (x.key < y.key) return true;
    if (y.key < x.key) return false;
    return x.gv < y.gv;  // ties: the same answer every time
  }
  // The envelope of two envelopes.
  std::vector<Piece> merge(std::span<const Piece> a, std::span<const Piece> b) const {
    std::vector<Piece> out;
    std::size_t i = 0, j = 0;
    std::int32_t ca = -1, cb = -1;  // current items of a and b
    while (i < a.size() || j < b.size()) {
      Coord v;
      if (j >= b.size() || (i < a.size() && a[i].v0 <= b[j].v0)) v = a[i].v0;
      else v = b[j].v0;
      while (i < a.size() && a[i].v0 == v) ca = a[i++].item;
      while (j < b.size() && b[j].v0 == v) cb = b[j++].item;
      const std::int32_t best = better(cb, ca) ? cb : ca;
      if (out.empty() ? best >= 0 : out.back().item != best) {
        if (!out.empty() && out.back().v0 == v) out.back().item = best;
        else out.push_back({v, best});
      }
    }
    return out;
  }
  void build(std::vector<Item> all) {
    std::sort(all.begin(), all.end(), [](const Item& a, const Item& b) { return a.u < b.u; });
    items = std::move(all);
    leaves = 1;
    while (leaves < items.size()) leaves *= 2;
    // Children before parents, each catalog appended to `entries` as it is made; a node's
    // envelope is freed once its parent's is made (only the catalogs are kept).
    std::vector<std::vector<Piece>> env(2 * leaves);
    for (std::size_t i = 0; i < items.size(); ++i) {
      const Item& it = items[i];
      env[leaves + i] = {{it.vlo, static_cast<std::int32_t>(i)}, {static_cast<Coord>(it.vhi + 1), -1}};  // |v| < 2^30
    }
    breakpoints = 0;
    entries.clear();
    at.assign(2 * leaves, 0);
    len.assign(2 * leaves, 0);
    std::vector<Coord> vs;
    std::vector<Entry> out;
    for (std::size_t n = 2 * leaves; n-- > 1;) {
      const bool leaf = n >= leaves;
      if (!leaf) env[n] = merge(env[2 * n], env[2 * n + 1]);
      breakpoints += env[n].size();
      // the catalog's values: the breakpoints and the children's samples, sorted, distinct
      vs.clear();
      for (const Piece& pc : env[n]) vs.push_back(pc.v0);
      if (!leaf)
        for (const std::size_t c : {2 * n, 2 * n + 1})
          for (std::size_t k = kSample - 1; k < len[c]; k += kSample) vs.push_back(entries[at[c] + k].v);
      std::sort(vs.begin(), vs.end());
      vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
      out.clear();
      std::size_t e = 0, d[2] = {0, 0};
      std::int32_t item = -1;
      for (const Coord v : vs) {
        while (e < env[n].size() && env[n][e].v0 <= v) item = env[n][e++].item;
        Entry en{v, item, {-1, -1}};
        if (!leaf)
          for (std::size_t k = 0; k < 2; ++k) {
            const std::size_t c = 2 * n + k;
            while (d[k] < len[c] && entries[at[c] + d[k]].v <= v) ++d[k];
            en.down[k] = static_cast<std::int32_t>(d[k]) - 1;
          }
        out.push_back(en);
      }
      if (entries.size() + out.size() > std::numeric_limits<std::int32_t>::max())
        throw std::length_error("BendTargetMap: a slab tree past 2^31 catalog entries");
      at[n] = static_cast<std::uint32_t>(entries.size());
      len[n] = static_cast<std::uint32_t>(out.size());
      entries.insert(entries.end(), out.begin(), out.end());
      if (!leaf) {
        std::vector<Piece>().swap(env[2 * n]);
        std::vector<Piece>().swap(env[2 * n + 1]);
      }
    }
    entries.shrink_to_fit();
  }
  // The leaves [lo, hi) of the items with u in [ulo, uhi].
  std::pair<std::size_t, std::size_t> leaf_range(Coord ulo, Coord uhi) const {
    const auto lo = static_cast<std::size_t>(std::lower_bound(items.begin(), items.end(), ulo, [](const Item& a, Coord x) { return a.u < x; }) - items.begin());
    const auto hi = static_cast<std::size_t>(std::upper_bound(items.begin(), items.end(), uhi, [](Coord x, const Item& a) { return x < a.u; }) - items.begin());
    return {lo, hi};
  }
  // Node n's catalog's last entry with v' <= v (-1: none), by binary search.
  std::int32_t position(std::size_t n, Coord v) const {
    const Entry* b = entries.data() + at[n];
    const Entry* e = b + len[n];
    return static_cast<std::int32_t>(std::upper_bound(b, e, v, [](Coord x, const Entry& en) { return x < en.v; }) - b) - 1;
  }
  // The best item with u in [ulo, uhi] whose range holds v; -1: none. O(log n): cascading from
  // the lowest common ancestor when it spans more than direct_span leaves, else a binary search
  // in each covering node (O(log^2 direct_span), a constant; with direct_span >= leaves always
  // that, O(log^2 n): the benchmark's baseline).
  std::int32_t query(Coord ulo, Coord uhi, Coord v, std::size_t direct_span) const {
    if (ulo > uhi || items.empty()) return -1;
    const auto [lo, hi] = leaf_range(ulo, uhi);
    if (lo >= hi) return -1;
    // the lowest common ancestor of the end leaves, and the leaves it spans
    std::size_t a = leaves + lo, b = leaves + hi - 1, span = 1;
    while (a != b) a >>= 1, b >>= 1, span <<= 1;
    if (span <= direct_span) return search_nodes(lo, hi, v);
    const std::size_t nlo = a * span - leaves;
    std::int32_t best = -1;
    descend(a, nlo, nlo + span, position(a, v), lo, hi, v, best);
    return best;
  }
  // A binary search in every node that covers the leaves [lo, hi).
  std::int32_t search_nodes(std::size_t lo, std::size_t hi, Coord v) const {
    std::int32_t best = -1;
    auto look = [&](std::size_t n) {
      const std::int32_t p = position(n, v);
      if (p >= 0 && better(entries[at[n] + static_cast<std::size_t>(p)].item, best))
        best = entries[at[n] + static_cast<std::size_t>(p)].item;
    };
    for (lo += leaves, hi += leaves; lo < hi; lo >>= 1, hi >>= 1) {
      if (lo & 1) look(lo++);
      if (hi & 1) look(--hi);
    }
    return best;
  }
  // Node n spans leaves [nlo, nhi); p: its catalog's last entry with v' <= v (-1: none).
  void descend(std::size_t n, std::size_t nlo, std::size_t nhi, std::int32_t p, std::size_t lo, std::size_t hi,
               Coord v, std::int32_t& best) const {
    // [nlo, nhi) meets [lo, hi): the caller skips the children outside it
    const Entry* cat = entries.data() + at[n];
    if (lo <= nlo && nhi <= hi) {
      if (p >= 0 && better(cat[p].item, best)) best = cat[p].item;
      return;
    }
    const std::size_t mid = (nlo + nhi) / 2;
    for (std::size_t k = 0; k < 2; ++k) {
      const std::size_t c = 2 * n + k;
      if (hi <= (k == 0 ? nlo : mid) || (k == 0 ? mid : nhi) <= lo) continue;
      const Entry* cc = entries.data() + at[c];
      const auto size = static_cast<std::int32_t>(len[c]);
      std::int32_t q = p >= 0 ? cat[p].down[k] : -1;
      for (std::size_t steps = 0; q + 1 < size && cc[q + 1].v <= v; ++q)
        if (++steps >= kSample) throw std::logic_error("BendTargetMap: a slab tree's catalog pointer is off");
      descend(c, k == 0 ? nlo : mid, k == 0 ? mid : nhi, q, lo, hi, v, best);
    }
  }
  std::size_t pieces() const { return breakpoints; }
  std::size_t catalog_entries() const { return entries.size(); }
};

}  // namespace

struct BendTargetMap::Impl {
  using Node = BendRouter::Impl::Node;
  using Track = BendRouter::Impl::Track;
  using Edge = BendRouter::Impl::Edge;
  const BendRouter::Impl* r = nullptr;
  Point target;                  // a point target (or the shape's first vertex)
  std::optional<Polygon> shape;  // a shape target: its candidates are the search's sources
  BendMetric metric = BendMetric::Combined;
  i64 bend_cost = 0;
  WireStatus status = WireStatus::Ok;
  BendRouter::Impl::Search settled;  // Mode::All from the target
  std::int32_t base = 0;             // the first query node's index (the target's, if any)
  // slab trees by kind: first link direction a, second b (a perpendicular to b): index 2a + (b
  // is a + 1 (mod 4) ? 0 : 1)
  SlabTree slabs[8];
  using SlabSearch = BendTargetMap::SlabSearch;
  SlabSearch search = SlabSearch::Bounded;

  Cost weight(i64 length, i64 bends) const {
    return metric == BendMetric::Link ? Cost{bends, length} : Cost{i128{length} + i128{bend_cost} * bends, bends};
  }
  // The cost with `shift` added to its length component.
  Cost shifted(Cost c, i64 shift) const {
    if (metric == BendMetric::Link) c.second += shift;
    else c.first += shift;
    return c;
  }
  static int kind(int a, int b) { return 2 * a + (b == ((a + 1) & 3) ? 0 : 1); }
  const Node& node_of(std::int32_t gv) const {
    return gv < 2 * base ? r->nodes[static_cast<std::size_t>(gv / 2)]
                         : settled.qnodes[static_cast<std::size_t>(gv / 2 - base)];
  }

  // The best first step from q: its cost and the walk to the target.
  struct Best {
    Cost cost = kInf;
    std::vector<std::pair<Point, bool>> walk;  // the first points, before the chain
    std::int32_t gv = -1;                      // the built graph vertex the chain starts at, or -1
  };
  WireStatus best(Point q, Best& out) const;
  void build(std::span<const Point> sources);
  bool at_target(Point q) const { return shape ? in_pin(q, *shape) : q == target; }
  // The first point of the target on the closed segment from a to b (a not on it), or nullopt.
  std::optional<Point> first_on_target(Point a, Point b) const;

  // Where a corner may lie on track t (along its axis): after its start, and before the vertex
  // it ends on, if any. Empty when the track holds no such point.
  std::optional<std::pair<Coord, Coord>> corner_range(const Track& t) const {
    const bool h = horizontal(t.dir);
    const Coord step = h ? kStep[t.dir].x : kStep[t.dir].y;
    const Coord from = (h ? t.start.x : t.start.y) + step;
    const Coord to = (h ? t.end.x : t.end.y) - (r->is_vertex(t.end) ? step : 0);
    if ((i64{to} - from) * step < 0) return std::nullopt;
    return std::pair{std::min(from, to), std::max(from, to)};
  }
};

WireStatus BendTargetMap::Impl::best(Point q, Best& b) const {
  // a free point of the target costs 0, even when no candidate of a shape target is free (a
  // shape under blockages with a free spot inside), as BendRouter::path gives it
  if (status != WireStatus::Ok && !(shape && at_target(q) && r->is_free(q))) return status;
  const std::vector<Cost>& dist = settled.dist;
  auto consider = [&](Cost c, std::vector<std::pair<Point, bool>> walk, std::int32_t gv) {
    if (c == kInf || !(c < b.cost)) return;
    b.cost = c;
    b.walk = std::move(walk);
    b.gv = gv;
  };
  if (at_target(q)) {
    if (shape && !r->is_free(q)) return WireStatus::SourceNotFree;
    consider(Cost{}, {{q, true}}, -1);
    return WireStatus::Ok;
  }
  const auto vit = r->vertex_nodes.find(key(q));
  if (vit != r->vertex_nodes.end()) {  // a vertex: its own nodes' costs
    if (vit->second.empty()) return WireStatus::SourceNotFree;
    for (const std::int32_t n : vit->second)
      for (const std::int32_t gv : {2 * n, 2 * n + 1}) consider(dist[static_cast<std::size_t>(gv)], {}, gv);
    return b.cost == kInf ? WireStatus::Unreachable : WireStatus::Ok;
  }
  const std::vector<unsigned> w = wedges_of(r->point_material(q));
  if (w.empty()) return WireStatus::SourceNotFree;
  const std::int32_t qn = -1;  // q's node id in its tracks (unused as a graph vertex)
  std::vector<Track> tracks;
  for (int k = 0; k < 4; ++k)
    if (in_wedge(w.front(), k)) tracks.push_back(r->shoot(qn, q, k));
  for (const Track& t : tracks) {
    if (t.end == t.start) continue;
    const bool h = horizontal(t.dir);
    const i64 len = dist1(t.start, t.end);
    // straight to the vertex the track ends on
    if (t.to >= 0) {
      const std::int32_t gv = 2 * t.to + (h ? 0 : 1);
      consider(add_costs(dist[static_cast<std::size_t>(gv)], weight(len, 0)), {{q, h}}, gv);
    }
    // an L: the corners on the track, after q and before a vertex it ends on
    const int a = t.dir;
    const auto range = corner_range(t);
    if (!range) continue;
    for (const int bdir : {(a + 1) & 3, (a + 3) & 3}) {
      const SlabTree& s = slabs[kind(a, bdir)];
      const Coord v = h ? q.y : q.x;
      const std::size_t direct = search == SlabSearch::PerNode     ? std::numeric_limits<std::size_t>::max()
                                 : search == SlabSearch::Cascading ? 0
                                                                   : SlabTree::kDirectSpan;
      const std::int32_t i = s.query(range->first, range->second, v, direct);
      if (i < 0) continue;
      const SlabTree::Item& it = s.items[static_cast<std::size_t>(i)];
      // cost: key + C - (kStep[a] + kStep[b]) . q in the length
      const Point sv{kStep[a].x + kStep[bdir].x, kStep[a].y + kStep[bdir].y};
      const i64 sq = i64{sv.x} * q.x + i64{sv.y} * q.y;
      consider(add_costs(shifted(it.key, -sq), weight(0, 1)), {{q, h}}, it.gv);
    }
  }
  // straight to the target itself (an L to a source that is no vertex is in the slab trees)
  for (const Track& t : tracks) {
    if (t.end == t.start) continue;
    if (const auto x = first_on_target(t.start, t.end))
      consider(weight(dist1(q, *x), 0), {{q, horizontal(t.dir)}, {*x, horizontal(t.dir)}}, -1);
  }
  return b.cost == kInf ? WireStatus::Unreachable : WireStatus::Ok;
}

std::optional<Point> BendTargetMap::Impl::first_on_target(Point a, Point b) const {
  if (!shape) {
    const bool on = std::min(a.x, b.x) <= target.x && target.x <= std::max(a.x, b.x) &&
                    std::min(a.y, b.y) <= target.y && target.y <= std::max(a.y, b.y);
    return on ? std::optional<Point>(target) : std::nullopt;
  }
  // a horizontal or vertical segment from a point outside the shape: its first point on the
  // closed shape is on an edge (a crossing, or the nearer end of a collinear overlap); edges are
  // at 0, 45 or 90 degrees, so every such point is an integer point
  std::optional<Point> best;
  auto offer = [&](Point p) {
    if (!best || dist1(a, p) < dist1(a, *best)) best = p;
  };
  const bool h = a.y == b.y;
  const Coord lo = h ? std::min(a.x, b.x) : std::min(a.y, b.y), hi = h ? std::max(a.x, b.x) : std::max(a.y, b.y);
  const Coord fixed = h ? a.y : a.x;
  for_each_pin_edge(*shape, [&](Point e0, Point e1) {
    // the edge in (along, across) coordinates of the segment
    const i64 s0 = h ? e0.x : e0.y, c0 = h ? e0.y : e0.x, s1 = h ? e1.x : e1.y, c1 = h ? e1.y : e1.x;
    auto at = [&](i64 along) { return h ? Point{static_cast<Coord>(along), fixed} : Point{fixed, static_cast<Coord>(along)}; };
    if (c0 == fixed && c1 == fixed) {  // collinear: the overlap's nearer end
      const i64 olo = std::max<i64>(lo, std::min(s0, s1)), ohi = std::min<i64>(hi, std::max(s0, s1));
      if (olo <= ohi) offer(at(olo)), offer(at(ohi));
      return;
    }
    if ((c0 - fixed) * (c1 - fixed) > 0 || c0 == c1) return;
    const i64 along = s0 + (fixed - c0) * (s1 - s0) / (c1 - c0);  // exact: |ds| is 0 or |dc|
    if (lo <= along && along <= hi) offer(at(along));
  });
  return best;
}

void BendTargetMap::Impl::build(std::span<const Point> sources) {
  base = static_cast<std::int32_t>(r->nodes.size());
  settled = r->search(sources, {}, metric, bend_cost, BendRouter::Impl::Mode::All);
  if (settled.status != WireStatus::Ok) {
    status = WireStatus::TargetNotFree;
    return;
  }
  // the slab trees: every track of positive length is a candidate second link, arriving at its
  // start in the direction opposite to it: the built tracks (their start a vertex, at its cost)
  // and the tracks of the sources that are no vertex (at cost 0)
  std::vector<SlabTree::Item> items[8];
  auto add = [&](const Track& t, Cost d, std::int32_t gv) {
    const auto range = corner_range(t);  // the corner runs along the track
    if (!range) return;
    const int bdir = opposite(t.dir);  // the second link's direction
    const Point p = t.start;
    for (const int a : {(bdir + 1) & 3, (bdir + 3) & 3}) {  // the first link's direction
      const Point sv{kStep[a].x + kStep[bdir].x, kStep[a].y + kStep[bdir].y};
      const i64 sp = i64{sv.x} * p.x + i64{sv.y} * p.y;
      // the query runs along a's axis (u) at the corner's other coordinate (v: along the track)
      items[kind(a, bdir)].push_back({horizontal(a) ? p.x : p.y, range->first, range->second, shifted(d, sp), gv});
    }
  };
  for (const Track& t : r->tracks) {
    if (t.end == t.start) continue;
    const std::int32_t gv = 2 * t.from + (horizontal(opposite(t.dir)) ? 0 : 1);
    const Cost d = settled.dist[static_cast<std::size_t>(gv)];
    if (d != kInf) add(t, d, gv);
  }
  for (const Track& t : settled.qtracks)
    if (t.end != t.start) add(t, Cost{}, 2 * t.from + (horizontal(opposite(t.dir)) ? 0 : 1));
  for (int k = 0; k < 8; ++k) slabs[k].build(std::move(items[k]));
}

BendTargetMap::BendTargetMap(const BendRouter& router, Point target, BendMetric metric, std::int64_t bend_cost)
    : BendTargetMap(router, Polygon{{target}, {}}, metric, bend_cost) {}

BendTargetMap::BendTargetMap(const BendRouter& router, const Polygon& target, BendMetric metric, std::int64_t bend_cost)
    : impl_(std::make_unique<Impl>()) {
  if (metric == BendMetric::Combined && (bend_cost < 0 || bend_cost > (i64{1} << 31)))
    throw std::invalid_argument("BendTargetMap: the bend cost must lie in [0, 2^31]");
  if (target.outer.empty()) throw std::invalid_argument("BendTargetMap: an empty target");
  if (!is_point_pin(target) && !pin_shape_supported(target))
    throw std::invalid_argument("BendTargetMap: a target shape's edges must be horizontal, vertical or at 45 degrees");
  Impl& m = *impl_;
  m.r = router.impl_.get();
  m.target = target.outer.front();
  m.metric = metric;
  m.bend_cost = metric == BendMetric::Link ? 0 : bend_cost;
  if (is_point_pin(target)) {
    m.build({&m.target, 1});
    return;
  }
  m.shape = target;
  // the shape's candidates (PinShapes: with q's own projections, which first_on_target covers:
  // a wire ending at one of them is straight) that are free
  std::vector<Point> sources = m.r->pins.candidates(target, Polygon{});
  sources.erase(std::remove_if(sources.begin(), sources.end(), [&](Point p) { return !m.r->is_free(p); }), sources.end());
  m.build(sources);
}

BendTargetMap::~BendTargetMap() = default;
BendTargetMap::BendTargetMap(BendTargetMap&&) noexcept = default;
BendTargetMap& BendTargetMap::operator=(BendTargetMap&&) noexcept = default;

WireStatus BendTargetMap::status() const { return impl_->status; }

BendCost BendTargetMap::cost(Point q, WireStatus* status) const {
  Impl::Best b;
  const WireStatus s = impl_->best(q, b);
  if (status) *status = s;
  BendCost c;
  if (s != WireStatus::Ok) return c;
  c.reached = true;
  if (impl_->metric == BendMetric::Link) {
    c.bends = static_cast<i64>(b.cost.first);
    c.length = b.cost.second;
  } else {
    c.bends = b.cost.second;
    c.length = static_cast<i64>(b.cost.first - i128{impl_->bend_cost} * b.cost.second);
  }
  return c;
}

BendPath BendTargetMap::path(Point q) const {
  const Impl& m = *impl_;
  Impl::Best b;
  BendPath out;
  out.status = m.best(q, b);
  if (out.status != WireStatus::Ok) return out;
  std::vector<std::pair<Point, bool>> walk = b.walk;
  if (b.gv >= 2 * m.base) {  // an L to a source that is no vertex
    walk.emplace_back(m.node_of(b.gv).p, b.gv % 2 == 0);
  } else if (b.gv >= 0) {
    // the chain of the Dijkstra run from the target: predecessors lead back to it
    std::size_t v = static_cast<std::size_t>(b.gv);
    for (std::size_t guard = 0;; ++guard) {
      if (guard > m.settled.pred.size()) throw std::logic_error("BendTargetMap: predecessor cycle");
      walk.emplace_back(m.node_of(static_cast<std::int32_t>(v)).p, v % 2 == 0);
      if (m.settled.pred[v] == v) break;
      v = m.settled.pred[v];
    }
    const std::int32_t from = m.settled.entered_from[v];
    if (from >= 0) walk.emplace_back(m.node_of(from).p, from % 2 == 0);
  }
  out.points = walk_points(walk);
  out.bends = geom::count_bends(out.points);
  out.length = l1_length(out.points);
  if (!(m.weight(out.length, out.bends) == b.cost))
    throw std::logic_error("BendTargetMap: a wire's cost differs from the structure's");
  return out;
}

std::size_t BendTargetMap::catalog_entries() const {
  std::size_t s = 0;
  for (const SlabTree& t : impl_->slabs) s += t.catalog_entries();
  return s;
}

void BendTargetMap::set_slab_search(SlabSearch s) { impl_->search = s; }

std::size_t BendTargetMap::pieces() const {
  std::size_t s = 0;
  for (const SlabTree& t : impl_->slabs) s += t.pieces();
  return s;
}

std::vector<Polygon> rectilinear_cover(std::span<const Polygon> polygons, std::vector<std::size_t>* covered, int pieces) {
  if (pieces < 1 || pieces > kMaxCoverPieces)
    throw std::invalid_argument("rectilinear_cover: pieces must lie in [1, " + std::to_string(kMaxCoverPieces) + "]");
  // floor and ceiling of n / d (d > 0)
  std::vector<Polygon> out;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const Polygon& p = polygons[i];
    out.push_back(p);
    bool sloped = false;
    auto boxes = [&](const geom::Ring& r) {
      for (std::size_t j = 0; j < r.size(); ++j) {
        const Point a = r[j], b = r[(j + 1) % r.size()];
        if (a.x == b.x || a.y == b.y) continue;
        sloped = true;
        const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
        // k pieces, each no narrower than one unit in both directions' larger extent
        const i64 k = std::min<i64>(pieces, std::max(std::abs(dx), std::abs(dy)));
        for (i64 m = 0; m < k; ++m) {
          // the piece from a + (b - a) m / k to a + (b - a) (m + 1) / k, its box rounded outwards
          const i64 x0 = a.x + floor_div(std::min(dx * m, dx * (m + 1)), k), x1 = a.x + ceil_div(std::max(dx * m, dx * (m + 1)), k);
          const i64 y0 = a.y + floor_div(std::min(dy * m, dy * (m + 1)), k), y1 = a.y + ceil_div(std::max(dy * m, dy * (m + 1)), k);
          const auto X0 = static_cast<Coord>(x0), X1 = static_cast<Coord>(x1);
          const auto Y0 = static_cast<Coord>(y0), Y1 = static_cast<Coord>(y1);
          out.push_back(Polygon{{{X0, Y0}, {X1, Y0}, {X1, Y1}, {X0, Y1}}, {}});
        }
      }
    };
    boxes(p.outer);
    for (const geom::Ring& h : p.holes) boxes(h);
    if (sloped && covered) covered->push_back(i);
  }
  return out;
}

}  // namespace taut::router
