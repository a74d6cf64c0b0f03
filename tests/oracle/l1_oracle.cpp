#include "oracle/l1_oracle.h"

#include "geom/fixed_norm.h"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <functional>

#include "geom/predicates.h"

namespace taut::oracle {

using geom::i128;
using geom::i64;
using geom::Location;
using geom::Point;
using geom::Polygon;
using geom::Ring;
using geom::Root2;
using geom::Segment;
using geom::SegmentIntersection;

namespace {

// Beyond every path length (below 2^55: geom/root2.h) and inside the range where Root2 compares
// exactly (|a|, |b| < 2^62).
constexpr Root2 kInf{(i64{1} << 62) - 1, 0};

// Direction vectors are differences of integer points: |component| < 2^32, so cross and dot
// products fit in __int128 with room to spare.
struct Dir {
  i64 x = 0, y = 0;
};
i128 cross(Dir a, Dir b) { return i128{a.x} * b.y - i128{a.y} * b.x; }
i128 dot(Dir a, Dir b) { return i128{a.x} * b.x + i128{a.y} * b.y; }
Dir dir(Point from, Point to) { return {i64{to.x} - from.x, i64{to.y} - from.y}; }
// 0 for angles in [0, pi), 1 for [pi, 2pi), measured from +x.
int half(Dir d) { return (d.y < 0 || (d.y == 0 && d.x < 0)) ? 1 : 0; }
// Strict order of directions by angle from +x, counter-clockwise.
bool angle_less(Dir a, Dir b) {
  if (half(a) != half(b)) return half(a) < half(b);
  return cross(a, b) > 0;
}
bool same_direction(Dir a, Dir b) { return cross(a, b) == 0 && dot(a, b) > 0; }
// Where d lies counter-clockwise from `from`: 0 on it, 1 within (0, pi), 2 at pi, 3 beyond.
int angle_class(Dir from, Dir d) {
  const i128 c = cross(from, d);
  if (c > 0) return 1;
  if (c < 0) return 3;
  return dot(from, d) > 0 ? 0 : 2;
}
// The counter-clockwise angle from `from` to d is at most the one from `from` to `to`.
bool angle_at_most(Dir from, Dir d, Dir to) {
  const int cd = angle_class(from, d), ct = angle_class(from, to);
  if (cd != ct) return cd < ct;
  if (cd == 0 || cd == 2) return true;
  return cross(d, to) >= 0;
}

// Crossing-number location of the point (mx/2, my/2) with respect to a ring, on doubled
// coordinates in __int128 (doubling leaves the range where geom::orient is exact in int64).
Location locate_doubled(i64 mx, i64 my, const Ring& ring) {
  const std::size_t n = ring.size();
  bool inside = false;
  for (std::size_t i = 0; i < n; ++i) {
    const i64 ax = 2 * i64{ring[i].x}, ay = 2 * i64{ring[i].y};
    const i64 bx = 2 * i64{ring[(i + 1) % n].x}, by = 2 * i64{ring[(i + 1) % n].y};
    const i128 o = i128{bx - ax} * (my - ay) - i128{by - ay} * (mx - ax);
    if (o == 0 && std::min(ax, bx) <= mx && mx <= std::max(ax, bx) && std::min(ay, by) <= my &&
        my <= std::max(ay, by))
      return Location::Boundary;
    if ((ay > my) != (by > my)) {
      if (by > ay ? o > 0 : o < 0) inside = !inside;
    }
  }
  return inside ? Location::Inside : Location::Outside;
}
Location locate_doubled(i64 mx, i64 my, const Polygon& poly) {
  const Location outer = locate_doubled(mx, my, poly.outer);
  if (outer != Location::Inside) return outer;
  for (const Ring& h : poly.holes) {
    const Location l = locate_doubled(mx, my, h);
    if (l == Location::Boundary) return Location::Boundary;
    if (l == Location::Inside) return Location::Outside;
  }
  return Location::Inside;
}

std::string str(Point p) { return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")"; }

bool any_contains(std::span<const Wedge> ws, Dir d) {
  return std::any_of(ws.begin(), ws.end(), [&](const Wedge& w) { return w.contains(d.x, d.y); });
}

}  // namespace

bool Wedge::contains(i64 dx, i64 dy) const {
  if (full) return true;
  return angle_at_most({from_x, from_y}, {dx, dy}, {to_x, to_y});
}

Root2 segment_length(Metric metric, Point a, Point b) {
  const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
  switch (metric) {
    case Metric::Octilinear: return geom::octilinear_length(dx, dy);
    case Metric::Farey2: return {geom::kFarey2.length(dx, dy), 0};
    case Metric::Farey3: return {geom::kFarey3.length(dx, dy), 0};
    case Metric::Farey4: return {geom::kFarey4.length(dx, dy), 0};
    case Metric::L1: break;
  }
  return {std::abs(dx) + std::abs(dy), 0};
}

VisibilityGraph::VisibilityGraph(const geom::Box& domain, std::span<const Polygon> obstacles,
                                 Metric metric)
    : domain_(domain), metric_(metric), obstacles_(obstacles.begin(), obstacles.end()) {
  for (const Polygon& poly : obstacles_) {
    auto add_ring = [&](const Ring& r) {
      for (std::size_t i = 0; i < r.size(); ++i) {
        const Point a = r[i], b = r[(i + 1) % r.size()];
        if (a != b) edges_.push_back({a, b});
      }
    };
    add_ring(poly.outer);
    for (const Ring& h : poly.holes) add_ring(h);
  }
  for (const Edge& e : edges_) vertex_wedges_.emplace(e.a, std::vector<Wedge>{});
  for (auto& [p, ws] : vertex_wedges_) {
    ws = wedges_at(p);
    for (const Wedge& w : ws) nodes_.push_back({p, w});
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    for (std::size_t j = i + 1; j < nodes_.size(); ++j) {
      const Node &u = nodes_[i], &v = nodes_[j];
      if (u.p == v.p) continue;  // two wedges of one pinch: never connected
      if (allowed(u.p, std::span<const Wedge>(&u.wedge, 1), v.p,
                  std::span<const Wedge>(&v.wedge, 1)))
        graph_edges_.push_back({i, j, length(u.p, v.p)});
    }
}

bool VisibilityGraph::inside_domain(Point p) const {
  return domain_.lo.x <= p.x && p.x <= domain_.hi.x && domain_.lo.y <= p.y &&
         p.y <= domain_.hi.y;
}

std::vector<Wedge> VisibilityGraph::wedges_at(Point p) const {
  if (!inside_domain(p)) return {};
  for (const Polygon& poly : obstacles_)
    if (geom::locate(p, poly) == Location::Inside) return {};
  // Every boundary direction at p, with what the edge says about the sides next to it: a ring
  // edge a->b has its obstacle on the left, so seen from p the interior is counter-clockwise
  // from b - a (p == a) and clockwise from a - b (p == b).
  struct Ray {
    Dir d;
    bool ccw_in = false, ccw_out = false, cw_in = false, cw_out = false;
  };
  std::vector<Ray> rays;
  for (const Edge& e : edges_) {
    const bool at_a = p == e.a, at_b = p == e.b;
    if (!at_a && !at_b && !geom::on_segment(p, e.a, e.b)) continue;
    if (!at_b) rays.push_back({dir(e.a, e.b), true, false, false, true});
    if (!at_a) rays.push_back({dir(e.b, e.a), false, true, true, false});
  }
  // The domain sides through p are walls too (their sectors are tested below).
  if (p.x == domain_.lo.x || p.x == domain_.hi.x) {
    rays.push_back({{0, 1}});
    rays.push_back({{0, -1}});
  }
  if (p.y == domain_.lo.y || p.y == domain_.hi.y) {
    rays.push_back({{1, 0}});
    rays.push_back({{-1, 0}});
  }
  if (rays.empty()) return {Wedge{.full = true}};
  std::sort(rays.begin(), rays.end(),
            [](const Ray& a, const Ray& b) { return angle_less(a.d, b.d); });
  std::vector<Ray> dirs;  // distinct directions, votes merged
  for (const Ray& r : rays) {
    if (!dirs.empty() && same_direction(dirs.back().d, r.d)) {
      Ray& m = dirs.back();
      m.ccw_in |= r.ccw_in, m.ccw_out |= r.ccw_out, m.cw_in |= r.cw_in, m.cw_out |= r.cw_out;
    } else {
      dirs.push_back(r);
    }
  }
  const std::size_t k = dirs.size();
  // Sector i runs counter-clockwise from dirs[i] to dirs[i + 1]; no boundary enters it near p,
  // so it is wholly free or wholly blocked.
  std::vector<bool> free(k);
  for (std::size_t i = 0; i < k; ++i) {
    const Dir a = dirs[i].d, b = dirs[(i + 1) % k].d;
    const bool in = dirs[i].ccw_in || dirs[(i + 1) % k].cw_in;
    const bool out = dirs[i].ccw_out || dirs[(i + 1) % k].cw_out;
    if (in && out)
      problems_.push_back("sector at " + str(p) + " is both inside and outside an obstacle");
    // A direction strictly inside the sector, to test against the domain.
    Dir rep;
    const i128 c = cross(a, b);
    if (k == 1) rep = {-a.x, -a.y};
    else if (c > 0) rep = {a.x + b.x, a.y + b.y};
    else if (c < 0) rep = {-(a.x + b.x), -(a.y + b.y)};
    else rep = {-a.y, a.x};  // b opposite to a: the left normal of a
    const bool outside = (p.x == domain_.lo.x && rep.x < 0) || (p.x == domain_.hi.x && rep.x > 0) ||
                         (p.y == domain_.lo.y && rep.y < 0) || (p.y == domain_.hi.y && rep.y > 0);
    free[i] = !in && !outside;
  }
  const auto first_blocked = std::find(free.begin(), free.end(), false);
  if (first_blocked == free.end()) return {Wedge{.full = true}};
  // Maximal runs of free sectors, starting after a blocked one so no run wraps the start.
  std::vector<Wedge> out;
  const std::size_t j = static_cast<std::size_t>(first_blocked - free.begin());
  for (std::size_t step = 1; step <= k; ++step) {
    const std::size_t i = (j + step) % k;
    if (!free[i]) continue;
    const std::size_t prev = (i + k - 1) % k;
    if (step == 1 || !free[prev]) out.push_back({dirs[i].d.x, dirs[i].d.y, 0, 0, false});
    out.back().to_x = dirs[(i + 1) % k].d.x;
    out.back().to_y = dirs[(i + 1) % k].d.y;
  }
  return out;
}

bool VisibilityGraph::segment_clear(Point a, Point b) const {
  if (!inside_domain(a) || !inside_domain(b)) return false;  // the box is convex
  std::vector<Point> cuts = {a, b};
  for (const Edge& e : edges_) {
    const SegmentIntersection r = geom::intersect(Segment{a, b}, Segment{e.a, e.b});
    if (r == SegmentIntersection::Proper) return false;
    if (r == SegmentIntersection::None) continue;
    // Touch or overlap: every meeting point that matters is an edge end on ab (a touch at an
    // interior point of the edge is at a or b; an overlap ends at edge ends or at a or b).
    if (geom::on_segment(e.a, a, b)) cuts.push_back(e.a);
    if (geom::on_segment(e.b, a, b)) cuts.push_back(e.b);
  }
  std::sort(cuts.begin(), cuts.end(),
            [&](Point u, Point v) { return geom::dot(a, b, a, u) < geom::dot(a, b, a, v); });
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  // Between two consecutive cuts the open piece meets no vertex and crosses no edge: it lies
  // on one edge or off all of them, so its midpoint decides for all of it. (The wedge tests at
  // the cuts below and at the ends already imply this; it is kept as the plain statement.)
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const i64 mx = i64{cuts[i].x} + cuts[i + 1].x, my = i64{cuts[i].y} + cuts[i + 1].y;
    const bool on_domain_side = mx == 2 * i64{domain_.lo.x} || mx == 2 * i64{domain_.hi.x} ||
                                my == 2 * i64{domain_.lo.y} || my == 2 * i64{domain_.hi.y};
    for (const Polygon& poly : obstacles_) {
      const Location l = locate_doubled(mx, my, poly);
      if (l == Location::Inside) return false;
      // Obstacle edge flush with the domain side: no free space beside it.
      if (l == Location::Boundary && on_domain_side) return false;
    }
  }
  // Passing through a vertex: stay in one wedge.
  for (std::size_t i = 1; i + 1 < cuts.size(); ++i) {
    const Point v = cuts[i];
    const auto it = vertex_wedges_.find(v);
    if (it == vertex_wedges_.end()) {
      problems_.push_back("cut " + str(v) + " is not an obstacle vertex");
      return false;
    }
    const Dir da = dir(v, a), db = dir(v, b);
    const bool ok = std::any_of(it->second.begin(), it->second.end(), [&](const Wedge& w) {
      return w.contains(da.x, da.y) && w.contains(db.x, db.y);
    });
    if (!ok) return false;
  }
  return true;
}

bool VisibilityGraph::allowed(Point a, std::span<const Wedge> wa, Point b,
                              std::span<const Wedge> wb) const {
  if (a == b) return false;
  return any_contains(wa, dir(a, b)) && any_contains(wb, dir(b, a)) && segment_clear(a, b);
}

bool VisibilityGraph::visible(Point a, Point b) const {
  const std::vector<Wedge> wa = wedges_at(a), wb = wedges_at(b);
  return allowed(a, wa, b, wb);
}

std::optional<Root2> VisibilityGraph::check_path(std::span<const Point> path) const {
  std::vector<Point> p;
  for (const Point q : path)
    if (p.empty() || p.back() != q) p.push_back(q);
  if (p.empty() || wedges_at(p.front()).empty()) return std::nullopt;
  Root2 total;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    if (!visible(p[i], p[i + 1])) return std::nullopt;
    total += length(p[i], p[i + 1]);
  }
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Dir da = dir(p[i], p[i - 1]), db = dir(p[i], p[i + 1]);
    const std::vector<Wedge> ws = wedges_at(p[i]);
    if (std::none_of(ws.begin(), ws.end(), [&](const Wedge& w) {
          return w.contains(da.x, da.y) && w.contains(db.x, db.y);
        }))
      return std::nullopt;
  }
  return total;
}

struct VisibilityGraph::Search {
  bool ok = false;  // s is free
  Point s;
  std::vector<Wedge> s_wedges;
  std::vector<Root2> dist;         // per node, kInf when unreachable
  std::vector<std::size_t> pred;   // per node; nodes_.size() is s
};

VisibilityGraph::Search VisibilityGraph::search_from(Point s) const {
  Search r;
  r.s = s;
  r.s_wedges = wedges_at(s);
  if (r.s_wedges.empty()) return r;
  r.ok = true;
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                      boost::no_property,
                                      boost::property<boost::edge_weight_t, Root2>>;
  const std::size_t n = nodes_.size();
  Graph g(n + 1);
  for (const GraphEdge& e : graph_edges_) boost::add_edge(e.u, e.v, e.w, g);
  for (std::size_t i = 0; i < n; ++i) {
    const Node& u = nodes_[i];
    // (s at a vertex needs no link to that vertex's nodes: s itself may leave into any wedge.)
    if (allowed(s, r.s_wedges, u.p, std::span<const Wedge>(&u.wedge, 1)))
      boost::add_edge(n, i, length(s, u.p), g);
  }
  std::vector<Root2> dist(n + 1);
  std::vector<Graph::vertex_descriptor> pred(n + 1);
  // Root2 as the distance type: exact order (operator<=>), and a sum that stays at kInf
  // (Boost only adds to settled, finite distances, but the guard keeps kInf out of overflow).
  const auto combine = [](Root2 x, Root2 y) { return x == kInf || y == kInf ? kInf : x + y; };
  boost::dijkstra_shortest_paths(g, n,
                                 boost::predecessor_map(pred.data())
                                     .distance_map(dist.data())
                                     .distance_compare(std::less<Root2>())
                                     .distance_combine(combine)
                                     .distance_inf(kInf)
                                     .distance_zero(Root2{}));
  r.dist.assign(dist.begin(), dist.begin() + static_cast<std::ptrdiff_t>(n));
  r.pred.assign(pred.begin(), pred.begin() + static_cast<std::ptrdiff_t>(n));
  return r;
}

// The best way to reach t: the node it is reached through (nodes_.size() = straight from s)
// and the length; kInf when unreachable.
struct VisibilityGraph::Arrival {
  std::size_t via = 0;
  Root2 total = kInf;
};

VisibilityGraph::Arrival VisibilityGraph::arrive(const Search& sr, Point t,
                                                 std::span<const Wedge> wt) const {
  const std::size_t n = nodes_.size();
  Arrival best;
  if (allowed(sr.s, sr.s_wedges, t, wt)) best = {n, length(sr.s, t)};
  for (std::size_t i = 0; i < n; ++i) {
    if (sr.dist[i] == kInf || sr.dist[i] >= best.total) continue;
    const Node& u = nodes_[i];
    const Root2 len = sr.dist[i] + length(u.p, t);
    if (len < best.total && allowed(u.p, std::span<const Wedge>(&u.wedge, 1), t, wt))
      best = {i, len};
  }
  return best;
}

std::vector<std::optional<Root2>> VisibilityGraph::distances(
    Point s, std::span<const Point> targets) const {
  std::vector<std::optional<Root2>> out(targets.size());
  const Search sr = search_from(s);
  if (!sr.ok) return out;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const Point t = targets[k];
    if (t == s) {
      out[k] = Root2{};
      continue;
    }
    const std::vector<Wedge> wt = wedges_at(t);
    if (wt.empty()) continue;
    const Arrival best = arrive(sr, t, wt);
    if (best.total != kInf) out[k] = best.total;
  }
  return out;
}

std::optional<Root2> VisibilityGraph::distance(Point s, Point t) const {
  return distances(s, std::span<const Point>(&t, 1))[0];
}

std::optional<std::vector<Point>> VisibilityGraph::path(Point s, Point t) const {
  const Search sr = search_from(s);
  if (!sr.ok) return std::nullopt;
  if (s == t) return std::vector<Point>{s};
  const std::vector<Wedge> wt = wedges_at(t);
  if (wt.empty()) return std::nullopt;
  const std::size_t n = nodes_.size();
  const Arrival best = arrive(sr, t, wt);
  if (best.total == kInf) return std::nullopt;
  std::vector<Point> rev = {t};
  for (std::size_t v = best.via; v != n; v = sr.pred[v]) rev.push_back(nodes_[v].p);
  rev.push_back(s);
  std::vector<Point> out;
  for (auto it = rev.rbegin(); it != rev.rend(); ++it)
    if (out.empty() || out.back() != *it) out.push_back(*it);
  return out;
}

// L1: every length is a Root2 with b == 0 (segment_length), so sums keep b == 0.
namespace {
std::optional<i64> as_l1(const std::optional<Root2>& d) {
  if (!d) return std::nullopt;
  return d->a;
}
}  // namespace

std::vector<std::optional<i64>> L1Reference::distances(Point s,
                                                       std::span<const Point> targets) const {
  const std::vector<std::optional<Root2>> d = VisibilityGraph::distances(s, targets);
  std::vector<std::optional<i64>> out(d.size());
  std::transform(d.begin(), d.end(), out.begin(), as_l1);
  return out;
}

std::optional<i64> L1Reference::distance(Point s, Point t) const {
  return as_l1(VisibilityGraph::distance(s, t));
}

std::optional<i64> L1Reference::check_path(std::span<const Point> path) const {
  return as_l1(VisibilityGraph::check_path(path));
}

}  // namespace taut::oracle
