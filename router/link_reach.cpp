#include "router/link_reach.h"

#include <algorithm>
#include <array>
#include <boost/geometry/index/rtree.hpp>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <stdexcept>
#include <utility>

#include "geom/bg.h"
#include "geom/index.h"
#include "geom/predicates.h"

namespace taut::router {

namespace {

using geom::Coord;
using geom::Point;
using geom::Ring;
using i64 = std::int64_t;
namespace bgi = boost::geometry::index;

constexpr int kNone = std::numeric_limits<int>::max();

using link_steps::neg;
using link_steps::ray_of;
using link_steps::unit;
// Rotation by -90 degrees k times: 1 (x, y) -> (y, -x), 2 (-x, -y), 3 (-y, x).
Point rotate(Point p, int k) {
  switch (k & 3) {
    case 1: return {p.y, static_cast<Coord>(-p.x)};
    case 2: return {static_cast<Coord>(-p.x), static_cast<Coord>(-p.y)};
    case 3: return {static_cast<Coord>(-p.y), p.x};
    default: return p;
  }
}
Point transpose(Point p) { return {p.y, p.x}; }

// A ring's vertices looked up by position (sorted; no two vertices of a simple ring coincide).
class RingIndex {
 public:
  explicit RingIndex(const Ring& ring) {
    sorted_.reserve(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) sorted_.push_back({{ring[i].x, ring[i].y}, i});
    std::sort(sorted_.begin(), sorted_.end());
  }
  std::optional<std::size_t> find(Point p) const {
    const std::pair<Coord, Coord> key{p.x, p.y};
    const auto it = std::lower_bound(sorted_.begin(), sorted_.end(), key, [](const auto& a, const auto& k) { return a.first < k; });
    if (it == sorted_.end() || it->first != key) return std::nullopt;
    return it->second;
  }

 private:
  std::vector<std::pair<std::pair<Coord, Coord>, std::size_t>> sorted_;
};

// A counter-clockwise simple rectilinear ring with its vertices looked up by position and its
// edges in a ray-shooting index.
class Shape {
 public:
  explicit Shape(Ring ring) : ring_(std::move(ring)), poly_{ring_, {}}, index_({&poly_, 1}), vertex_(ring_) {}
  std::size_t size() const { return ring_.size(); }
  const Point& at(std::size_t i) const { return ring_[i % ring_.size()]; }
  std::optional<std::size_t> vertex(Point p) const { return vertex_.find(p); }
  bool reflex(std::size_t i) const { return geom::orientation(at(i + size() - 1), at(i), at(i + 1)) < 0; }
  // Whether a path may leave vertex i in direction d (d in the closed interior wedge: along one of
  // its edges, or anywhere at a reflex vertex).
  bool can_leave(std::size_t i, Point d) const {
    const Point a = at(i + size() - 1), v = at(i), c = at(i + 1);
    return d == unit(v, c) || d == unit(v, a) || reflex(i);
  }
  // The first boundary point after p in direction d (p itself and the edges through it ignored).
  std::pair<Point, geom::RayHit> shoot(Point p, Point d) const {
    geom::RayHit h = index_.shoot(p, ray_of(d), {.ignore_edges_at_start = true});
    if (!h.hit()) throw std::logic_error("link_reach: a ray leaves the polygon (not simple, or clockwise)");
    const i64 t = h.t.num / h.t.den;
    return {Point{static_cast<Coord>(p.x + d.x * t), static_cast<Coord>(p.y + d.y * t)}, std::move(h)};
  }
  // How far the closed polygon reaches from boundary point p in direction d, along edges and
  // through reflex vertices: the far end of the maximal closed segment. `outward`: at a start
  // inside an edge, the direction out of the polygon there.
  // Every vertex passed on the way gets the same answer, kept: a line through many vertices
  // (a comb's spine) is walked once, not once per vertex.
  Point reach(Point p, Point d, Point outward) const {
    const int dir = d.x > 0 ? 0 : d.y > 0 ? 1 : d.x < 0 ? 2 : 3;
    if (far_.empty()) far_.assign(4 * size(), kUnknown);
    std::vector<std::size_t> passed;
    Point out = p;
    for (bool first = true;; first = false) {
      if (const auto i = vertex(p)) {
        const Point known = far_[4 * *i + static_cast<std::size_t>(dir)];
        if (known != kUnknown) {
          out = known;
          break;
        }
        passed.push_back(*i);
        if (!can_leave(*i, d)) {
          out = p;
          break;
        }
      } else if (!first || d == outward) {
        out = p;  // stopped inside an edge across the way
        break;
      }
      p = shoot(p, d).first;
    }
    for (const std::size_t i : passed) far_[4 * i + static_cast<std::size_t>(dir)] = out;
    return out;
  }
  std::size_t edge_of(std::uint32_t id) const { return index_.edge_ref(id).vertex; }

 private:
  Ring ring_;
  geom::Polygon poly_;
  geom::ObstacleIndex index_;
  RingIndex vertex_;
  static constexpr Point kUnknown{std::numeric_limits<Coord>::min(), 0};
  mutable std::vector<Point> far_;  // reach() per vertex and direction (E, N, W, S)
};

// The vertical decomposition: a cut from every reflex vertex continuing its vertical edge through
// it, and one up from every point of `extra` (points inside floor edges: edges running +x, the
// polygon above). Returns the open rectangles between the cuts, as closed boxes.
std::vector<geom::Box> vertical_cells(const Shape& s, const std::vector<Point>& extra) {
  const std::size_t n = s.size();
  std::vector<std::vector<Coord>> splits(n);
  for (std::size_t i = 0; i < n; ++i)
    if (s.at(i).y == s.at(i + 1).y) splits[i] = {s.at(i).x, s.at(i + 1).x};
  auto land = [&](Point from, Point d) {
    const auto [q, h] = s.shoot(from, d);
    if (s.vertex(q)) return;
    for (const std::uint32_t id : h.edges) {
      const std::size_t e = s.edge_of(id);
      if (s.at(e).y == s.at(e + 1).y) splits[e].push_back(q.x);
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!s.reflex(i)) continue;
    const Point prev = s.at(i + n - 1), v = s.at(i), next = s.at(i + 1);
    land(v, prev.x == v.x ? unit(prev, v) : neg(unit(v, next)));
  }
  for (const Point p : extra) {
    bool found = false;
    for (std::size_t e = 0; e < n && !found; ++e) {
      const Point a = s.at(e), b = s.at(e + 1);
      if (a.y == p.y && b.y == p.y && a.x < p.x && p.x < b.x) splits[e].push_back(p.x), found = true;
    }
    if (!found) throw std::logic_error("link_reach: an end of the base is not inside a floor edge");
    land(p, {0, 1});
  }
  std::map<std::pair<Coord, Coord>, std::vector<Coord>> ceilings;  // (x1, x2) -> heights
  for (std::size_t e = 0; e < n; ++e) {
    auto& sp = splits[e];
    std::sort(sp.begin(), sp.end());
    sp.erase(std::unique(sp.begin(), sp.end()), sp.end());
    if (s.at(e).y == s.at(e + 1).y && s.at(e + 1).x < s.at(e).x)
      for (std::size_t k = 0; k + 1 < sp.size(); ++k) ceilings[{sp[k], sp[k + 1]}].push_back(s.at(e).y);
  }
  for (auto& [key, ys] : ceilings) std::sort(ys.begin(), ys.end());
  std::vector<geom::Box> cells;
  for (std::size_t e = 0; e < n; ++e) {
    if (!(s.at(e).y == s.at(e + 1).y && s.at(e + 1).x > s.at(e).x)) continue;
    const Coord y = s.at(e).y;
    const auto& sp = splits[e];
    for (std::size_t k = 0; k + 1 < sp.size(); ++k) {
      const auto it = ceilings.find({sp[k], sp[k + 1]});
      const auto top = it == ceilings.end() ? nullptr : &it->second;
      const auto up = top ? std::upper_bound(top->begin(), top->end(), y) : decltype(top->begin()){};
      if (!top || up == top->end()) throw std::logic_error("link_reach: a floor piece has no ceiling piece above it");
      cells.push_back({{sp[k], y}, {sp[k + 1], *up}});
    }
  }
  return cells;
}

enum Kind : std::uint8_t { kVCell, kHCell, kVSeg, kHSeg };
bool vertical(Kind k) { return k == kVCell || k == kVSeg; }

struct Node {
  Kind kind;
  geom::Box box;  // a segment's box is degenerate in one axis
};

// Whether a path can turn from vertical node v to horizontal node h (see the header).
bool adjacent(const Node& v, const Node& h) {
  const geom::Box& a = v.box;
  const geom::Box& b = h.box;
  auto positive = [](Coord lo1, Coord hi1, Coord lo2, Coord hi2) { return std::max(lo1, lo2) < std::min(hi1, hi2); };
  if (v.kind == kVCell && h.kind == kHCell) return positive(a.lo.x, a.hi.x, b.lo.x, b.hi.x) && positive(a.lo.y, a.hi.y, b.lo.y, b.hi.y);
  if (v.kind == kVCell) {  // a horizontal segment at b.lo.y
    return a.lo.y <= b.lo.y && b.lo.y <= a.hi.y && positive(a.lo.x, a.hi.x, b.lo.x, b.hi.x);
  }
  const Coord c = a.lo.x;  // a vertical segment
  if (h.kind == kHCell) return b.lo.x <= c && c <= b.hi.x && positive(a.lo.y, a.hi.y, b.lo.y, b.hi.y);
  return b.lo.x <= c && c <= b.hi.x && a.lo.y <= b.lo.y && b.lo.y <= a.hi.y;
}

// Union of closed intervals known to form one interval; throws when they do not.
ReachInterval merge(std::vector<ReachInterval>& parts) {
  std::sort(parts.begin(), parts.end(), [](const ReachInterval& a, const ReachInterval& b) { return a.lo < b.lo; });
  ReachInterval out = parts.front();
  for (const ReachInterval& p : parts) {
    if (p.lo > out.hi) throw std::logic_error("link_reach: the points of the base a node reaches are not one interval");
    out.hi = std::max(out.hi, p.hi);
  }
  return out;
}

}  // namespace

using Item = std::pair<geom::Box, std::uint32_t>;
using Tree = bgi::rtree<Item, bgi::quadratic<16>>;

struct CutReach::Impl {
  int k = 0;  // the frame: rotate(p, k) puts b's edge along +x with the polygon above it
  Point c0, c1;
  Coord yb = 0, xa = 0, xb = 0;
  std::vector<Node> nodes;
  std::vector<int> level, level2;
  std::vector<ReachInterval> reach;
  Tree vtree, htree;
  std::vector<BaseReach> vertices;
  std::vector<std::uint32_t> start, adj;  // the adjacency, as compressed rows
  std::uint32_t base_line = 0;            // the maximal segment along b

  // The nodes each first link from p (in the frame) runs along: the maximal segment through p
  // when p lies on one, else the cell whose closure holds p (p on no segment lies inside one
  // cell's span that way); std::nullopt outside.
  std::optional<std::pair<std::uint32_t, std::uint32_t>> locate(Point p) const {
    const geom::Box box{p, p};
    auto find = [&](const Tree& tree, Kind segment_kind) -> std::optional<std::uint32_t> {
      std::optional<std::uint32_t> cell;
      for (auto it = tree.qbegin(bgi::intersects(box)); it != tree.qend(); ++it) {
        if (nodes[it->second].kind == segment_kind) return it->second;
        cell = it->second;
      }
      return cell;
    };
    const auto v = find(vtree, kVSeg), h = find(htree, kHSeg);
    if (!v || !h) return std::nullopt;
    return std::pair{*v, *h};
  }
  ReachInterval from_base(ReachInterval r) const {  // the inverse of to_base
    if (r.empty()) return r;
    if (c1.x > c0.x) return ReachInterval{r.lo + c0.x, r.hi + c0.x};
    return ReachInterval{c0.x - r.hi, c0.x - r.lo};
  }
  // A node's link in the polygon's coordinates: its axis there and its fixed coordinate's range.
  CutReach::Run run_of(std::uint32_t x) const {
    const Node& n = nodes[x];
    const bool v = vertical(n.kind);
    const Point a = v ? Point{n.box.lo.x, 0} : Point{0, n.box.lo.y}, b = v ? Point{n.box.hi.x, 0} : Point{0, n.box.hi.y};
    const Point wa = rotate(a, 4 - k), wb = rotate(b, 4 - k);
    const bool world_vertical = v == (k % 2 == 0);
    const i64 lo = world_vertical ? std::min(wa.x, wb.x) : std::min(wa.y, wb.y);
    const i64 hi = world_vertical ? std::max(wa.x, wb.x) : std::max(wa.y, wb.y);
    return {world_vertical, lo, hi};
  }

  ReachInterval to_base(ReachInterval r) const {  // x in the frame -> distance from b0 along b
    if (r.empty()) return r;
    if (c1.x > c0.x) return ReachInterval{r.lo - c0.x, r.hi - c0.x};
    return ReachInterval{c0.x - r.hi, c0.x - r.lo};
  }
  // The record of a point p (in the frame) whose first links run along nodes v and h.
  BaseReach record(Point p, std::uint32_t v, std::uint32_t h) const {
    BaseReach r;
    if (p.y == yb && xa <= p.x && p.x <= xb) {
      r.links = 0, r.along = 0;
      r.at = r.next = to_base({p.x, p.x});
      return r;
    }
    // a point inside a cell standing on b reaches only its own foot with one link
    auto reach_of = [&](std::uint32_t x) {
      return nodes[x].kind == kVCell && level[x] == 1 ? ReachInterval{p.x, p.x} : reach[x];
    };
    const std::uint32_t best = level[v] <= level[h] ? v : h, other = best == v ? h : v;
    if (level[best] != kNone) {
      r.links = level[best];
      r.at = reach_of(best);
      r.next = r.at;
      if (level[other] == r.links + 1) {
        std::vector<ReachInterval> parts{r.at, reach_of(other)};
        r.next = merge(parts);
      }
      r.at = to_base(r.at), r.next = to_base(r.next);
    }
    const int a = std::min(level2[v], level2[h]);
    if (a != kNone) r.along = a + 1;
    // a path that arrives along b's line may turn there in place: it reaches all of b
    const ReachInterval all = to_base({xa, xb});
    if (r.along >= 0 && (r.links < 0 || r.along + 1 <= r.links)) r.links = r.along + 1, r.at = all;
    if (r.along >= 0 && r.along <= r.links) r.next = all;
    return r;
  }
};

CutReach::~CutReach() = default;
CutReach::CutReach(CutReach&&) noexcept = default;
CutReach& CutReach::operator=(CutReach&&) noexcept = default;
const std::vector<BaseReach>& CutReach::vertices() const { return impl_->vertices; }

std::optional<BaseReach> CutReach::at(Point q) const {
  const Impl& m = *impl_;
  const Point p = rotate(q, m.k);
  const auto vh = m.locate(p);
  if (!vh) return std::nullopt;
  return m.record(p, vh->first, vh->second);
}

std::optional<CutReach::Ways> CutReach::ways(Point q) const {
  const Impl& m = *impl_;
  const Point p = rotate(q, m.k);
  if (p.y == m.yb && m.xa <= p.x && p.x <= m.xb) return std::nullopt;
  const auto vh = m.locate(p);
  if (!vh) return std::nullopt;
  const auto [v, h] = *vh;
  Ways w;
  const std::uint32_t best = m.level[v] <= m.level[h] ? v : h, other = best == v ? h : v;
  auto way = [&](std::uint32_t x) {
    if (m.level[x] == kNone) return Way{};
    // a point inside a cell standing on b reaches only its own foot with one link
    const ReachInterval r = m.nodes[x].kind == kVCell && m.level[x] == 1 ? ReachInterval{p.x, p.x} : m.reach[x];
    return Way{m.level[x], m.to_base(r)};
  };
  w.first = way(best), w.second = way(other);
  const int a = std::min(m.level2[v], m.level2[h]);
  if (a != kNone) w.along = {a + 1, m.to_base({m.xa, m.xb})};
  return w;
}

std::vector<CutReach::Run> CutReach::runs(Point q, int way, ReachInterval& within) const {
  const Impl& m = *impl_;
  const Point p = rotate(q, m.k);
  const auto vh = m.locate(p);
  if (!vh) throw std::invalid_argument("CutReach::runs: the point is outside the part");
  const auto [v, h] = *vh;
  // the way's levels: the first search's (to land on b), or the second's (to reach b's line)
  const bool along = way == 2;
  const std::vector<int>& level = along ? m.level2 : m.level;
  const std::uint32_t best = level[v] <= level[h] ? v : h, n0 = way == 1 ? (best == v ? h : v) : best;
  if (level[n0] == kNone) throw std::invalid_argument("CutReach::runs: no such way");
  // positions of b in the frame (x on b's line) the path may still land on
  ReachInterval r = m.from_base(within);
  auto narrow = [](ReachInterval a, ReachInterval b) { return ReachInterval{std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; };
  if (!along && m.nodes[n0].kind == kVCell && m.level[n0] == 1) r = narrow(r, {p.x, p.x});
  // The current optimal sets of the two coordinate chains (see LinkPointQueries::path), in the
  // frame: of the nodes one level down (all of which give the fewest links), the one nearest to
  // its chain's set is taken. Taking any other fails the tests' L1 check.
  ReachInterval sx{p.x, p.x}, sy{p.y, p.y};
  auto step = [](ReachInterval& s, i64 lo, i64 hi) {
    if (std::max(s.lo, lo) <= std::min(s.hi, hi)) s = {std::max(s.lo, lo), std::min(s.hi, hi)};
    else s = lo > s.hi ? ReachInterval{lo, lo} : ReachInterval{hi, hi};
  };
  auto range = [&](std::uint32_t x) {
    const geom::Box& b = m.nodes[x].box;
    return vertical(m.nodes[x].kind) ? std::pair<i64, i64>{b.lo.x, b.hi.x} : std::pair<i64, i64>{b.lo.y, b.hi.y};
  };
  std::vector<Run> out;
  for (std::uint32_t n = n0;;) {
    if (r.empty()) throw std::logic_error("link_reach: a way's nodes reach none of the positions asked for");
    out.push_back(m.run_of(n));
    const auto [lo, hi] = range(n);
    step(vertical(m.nodes[n].kind) ? sx : sy, lo, hi);
    if (along && n == m.base_line) return out;  // the last link, along b's line
    if (!along && m.level[n] == 1) {            // a vertical node on b: the landing, narrowed to r
      const ReachInterval landing = narrow(r, {lo, hi});
      if (landing.empty()) throw std::logic_error("link_reach: a node on the base does not reach the positions asked for");
      const Point wa = rotate({static_cast<Coord>(landing.lo), 0}, 4 - m.k), wb = rotate({static_cast<Coord>(landing.hi), 0}, 4 - m.k);
      Run& last = out.back();
      last.lo = last.vertical ? std::min(wa.x, wb.x) : std::min(wa.y, wb.y);
      last.hi = last.vertical ? std::max(wa.x, wb.x) : std::max(wa.y, wb.y);
      within = m.to_base(landing);
      return out;
    }
    std::optional<std::uint32_t> pick;
    i64 pick_gap = 0;
    const ReachInterval& s = vertical(m.nodes[n].kind) ? sy : sx;  // the next node's chain
    for (std::uint32_t i = m.start[n]; i < m.start[n + 1]; ++i) {
      const std::uint32_t y = m.adj[i];
      if (level[y] != level[n] - 1 || (!along && !m.reach[y].meets(r))) continue;
      const auto [ylo, yhi] = range(y);
      const i64 gap = ylo > s.hi ? ylo - s.hi : s.lo > yhi ? s.lo - yhi : 0;
      if (!pick || gap < pick_gap) pick = y, pick_gap = gap;
    }
    if (!pick) throw std::logic_error("link_reach: a node has no neighbour one level down on its way");
    if (!along) r = narrow(r, m.reach[*pick]);
    n = *pick;
  }
}

std::vector<BaseReach> base_reach(const Ring& polygon, Point b0, Point b1) { return CutReach(polygon, b0, b1).vertices(); }

CutReach::CutReach(const Ring& polygon, Point b0, Point b1) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const std::size_t n = polygon.size();
  // the frame: b's edge runs +x (the polygon above it)
  int k = -1;
  for (std::size_t i = 0; i < n && k < 0; ++i) {
    const Point a = polygon[i], b = polygon[(i + 1) % n];
    if (b0 == b1 || !geom::on_segment(b0, a, b) || !geom::on_segment(b1, a, b)) continue;
    const Point u = unit(a, b);
    k = u.x > 0 ? 0 : u.y > 0 ? 1 : u.x < 0 ? 2 : 3;
  }
  m.k = k;
  if (k < 0) throw std::invalid_argument("base_reach: the base is not a segment of positive length on an edge");
  Ring ring;
  ring.reserve(n);
  for (const Point p : polygon) ring.push_back(rotate(p, k));
  const Shape shape(ring);
  const Point c0 = rotate(b0, k), c1 = rotate(b1, k);
  const Coord yb = c0.y, xa = std::min(c0.x, c1.x), xb = std::max(c0.x, c1.x);
  m.c0 = c0, m.c1 = c1, m.yb = yb, m.xa = xa, m.xb = xb;
  std::vector<Point> extra;
  for (const Point p : {c0, c1})
    if (!shape.vertex(p)) extra.push_back(p);

  // nodes: the cells of both decompositions, then the maximal segments through the vertices and
  // the base's ends
  std::vector<Node>& nodes = m.nodes;
  for (const geom::Box& b : vertical_cells(shape, extra)) nodes.push_back({kVCell, b});
  {
    Ring t;
    t.reserve(n);
    for (std::size_t i = n; i-- > 0;) t.push_back(transpose(ring[i]));
    for (const geom::Box& b : vertical_cells(Shape(std::move(t)), {}))
      nodes.push_back({kHCell, {transpose(b.lo), transpose(b.hi)}});
  }
  std::map<std::tuple<int, Coord, Coord>, std::uint32_t> segment_ids;
  auto segment = [&](Kind kind, Point lo, Point hi) {
    const auto key = kind == kVSeg ? std::tuple{int{kind}, lo.x, lo.y} : std::tuple{int{kind}, lo.y, lo.x};
    const auto [it, fresh] = segment_ids.emplace(key, static_cast<std::uint32_t>(nodes.size()));
    if (fresh) nodes.push_back({kind, {lo, hi}});
    return it->second;
  };
  struct Through {
    std::uint32_t v, h;
  };
  auto through = [&](Point p) {
    const Point down{0, -1};
    const Point out = shape.vertex(p) ? Point{0, 0} : down;  // the base's ends inside its edge
    const Through t{segment(kVSeg, shape.reach(p, down, out), shape.reach(p, {0, 1}, out)),
                    segment(kHSeg, shape.reach(p, {-1, 0}, out), shape.reach(p, {1, 0}, out))};
    return t;
  };
  std::vector<Through> at_vertex;
  at_vertex.reserve(n);
  for (const Point p : ring) at_vertex.push_back(through(p));
  const std::uint32_t base_line = m.base_line = through(c0).h;
  through(c1);  // (its vertical segment: a point on the cut up from c1 lies on it)

  std::vector<Item> vitems, hitems;
  for (std::uint32_t i = 0; i < nodes.size(); ++i) (vertical(nodes[i].kind) ? vitems : hitems).push_back({nodes[i].box, i});
  m.vtree = Tree(vitems), m.htree = Tree(hitems);
  const Tree& htree = m.htree;
  // the adjacency, found once (from the vertical nodes' side) for both searches, as compressed rows
  std::vector<std::uint32_t>& start = m.start;
  std::vector<std::uint32_t>& adj = m.adj;
  start.assign(nodes.size() + 1, 0);
  {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    std::vector<Item> found;
    for (const Item& v : vitems) {
      found.clear();
      htree.query(bgi::intersects(v.first), std::back_inserter(found));
      for (const Item& h : found)
        if (adjacent(nodes[v.second], nodes[h.second])) pairs.push_back({v.second, h.second});
    }
    for (const auto& [v, h] : pairs) ++start[v + 1], ++start[h + 1];
    for (std::size_t i = 0; i < nodes.size(); ++i) start[i + 1] += start[i];
    adj.resize(start.back());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const auto& [v, h] : pairs) adj[fill[v]++] = h, adj[fill[h]++] = v;
  }
  auto neighbours = [&](std::uint32_t x, auto&& visit) {
    for (std::uint32_t i = start[x]; i < start[x + 1]; ++i) visit(adj[i]);
  };

  // search 1: from the base, arriving perpendicular to it
  std::vector<int>& level = m.level;
  std::vector<ReachInterval>& reach = m.reach;
  level.assign(nodes.size(), kNone);
  reach.assign(nodes.size(), {});
  std::vector<std::uint32_t> frontier;
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    const geom::Box& b = nodes[i].box;
    if (nodes[i].kind == kVCell && b.lo.y == yb && b.lo.x < xb && b.hi.x > xa) {
      if (b.lo.x < xa || b.hi.x > xb) throw std::logic_error("link_reach: a cell straddles an end of the base");
      level[i] = 1, reach[i] = {b.lo.x, b.hi.x};
    } else if (nodes[i].kind == kVSeg && b.lo.y <= yb && yb <= b.hi.y && xa <= b.lo.x && b.lo.x <= xb) {
      level[i] = 1, reach[i] = {b.lo.x, b.lo.x};
    }
    if (level[i] == 1) frontier.push_back(i);
  }
  std::vector<std::vector<ReachInterval>> pending(nodes.size());  // contributions to the next level
  std::vector<std::uint32_t> next_frontier;
  for (int d = 1; !frontier.empty(); ++d) {
    for (const std::uint32_t x : frontier)
      neighbours(x, [&](std::uint32_t y) {
        if (level[y] != kNone && level[y] != d + 1) return;
        level[y] = d + 1;
        if (pending[y].empty()) next_frontier.push_back(y);
        pending[y].push_back(reach[x]);
      });
    frontier.clear();
    for (const std::uint32_t y : next_frontier) reach[y] = merge(pending[y]), std::vector<ReachInterval>().swap(pending[y]);
    frontier.swap(next_frontier);
    next_frontier.clear();
  }

  // search 2: from the base's line, arriving perpendicular to it (then one link along it)
  std::vector<int>& level2 = m.level2;
  level2.assign(nodes.size(), kNone);
  level2[base_line] = 0;
  frontier = {base_line};
  for (int d = 0; !frontier.empty(); ++d) {
    std::vector<std::uint32_t> next;
    for (const std::uint32_t x : frontier)
      neighbours(x, [&](std::uint32_t y) {
        if (level2[y] != kNone) return;
        level2[y] = d + 1;
        next.push_back(y);
      });
    frontier = std::move(next);
  }

  m.vertices.resize(n);
  for (std::size_t i = 0; i < n; ++i) m.vertices[i] = m.record(ring[i], at_vertex[i].v, at_vertex[i].h);
}

int links_across(const BaseReach& s, const BaseReach& t) {
  int best = s.links + t.links + 1;
  if (s.at.meets(t.at)) best = s.links + t.links - 1;
  else if (s.next.meets(t.at) || s.at.meets(t.next)) best = s.links + t.links;
  return std::min({best, s.links + t.along, s.along + t.links, s.along + t.along - 1});
}

namespace {
// A point's position on a cut (p on it): its distance from the cut's first end.
i64 cut_position(const PolygonCut& c, Point p) { return std::abs(i64{p.x} - c.from.x) + std::abs(i64{p.y} - c.from.y); }
// d(a, b) for two points of one rectangle.
int rectangle_links(Point a, Point b) { return a == b ? 0 : a.x == b.x || a.y == b.y ? 1 : 2; }
}  // namespace

int links_to_cut_point(const BaseReach& t, std::int64_t position) {
  // arrive there perpendicular, or perpendicular elsewhere and then along the cut, or along the
  // cut's line
  return std::min(t.at.contains(position) ? t.links : t.links + 1, t.along);
}

struct LinkPointQueries::Leaves {
  Tree tree;  // (closed leaf rectangle, node index)
};

LinkPointQueries::~LinkPointQueries() = default;
LinkPointQueries::LinkPointQueries(LinkPointQueries&&) noexcept = default;
LinkPointQueries& LinkPointQueries::operator=(LinkPointQueries&&) noexcept = default;

LinkPointQueries::LinkPointQueries(const Ring& polygon) : tree_(polygon), leaves_(std::make_unique<Leaves>()) {
  const auto& nodes = tree_.nodes();
  parts_.resize(nodes.size());
  std::vector<Item> leaves;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const auto& node = nodes[k];
    if (!node.cut) {
      const auto [lo, hi] = std::minmax_element(node.polygon.begin(), node.polygon.end(),
                                                [](Point p, Point q) { return std::pair{p.x, p.y} < std::pair{q.x, q.y}; });
      leaves.push_back({geom::Box{*lo, *hi}, static_cast<std::uint32_t>(k)});
      continue;
    }
    for (int side = 0; side < 2; ++side)
      parts_[k][static_cast<std::size_t>(side)].emplace(nodes[static_cast<std::size_t>(side == 0 ? node.left : node.right)].polygon,
                                                        node.cut->from, node.cut->to);
  }
  leaves_->tree = Tree(leaves);
}

std::int32_t LinkPointQueries::common_ancestor(std::int32_t a, std::int32_t b) const {
  const auto& nodes = tree_.nodes();
  auto at = [&](std::int32_t k) -> const CutTree::Node& { return nodes[static_cast<std::size_t>(k)]; };
  while (at(a).depth > at(b).depth) a = at(a).parent;
  while (at(b).depth > at(a).depth) b = at(b).parent;
  while (a != b) a = at(a).parent, b = at(b).parent;
  return a;
}

std::optional<std::int32_t> LinkPointQueries::stop_node(Point p) const {
  std::optional<std::int32_t> stop;
  for (auto it = leaves_->tree.qbegin(bgi::intersects(geom::Box{p, p})); it != leaves_->tree.qend(); ++it) {
    const auto leaf = static_cast<std::int32_t>(it->second);
    stop = stop ? common_ancestor(*stop, leaf) : leaf;
  }
  return stop;
}

std::optional<int> LinkPointQueries::links(Point a, Point b) const {
  const auto sa = stop_node(a), sb = stop_node(b);
  if (!sa || !sb) return std::nullopt;
  const auto& nodes = tree_.nodes();
  const std::int32_t k = common_ancestor(*sa, *sb);
  const auto& node = nodes[static_cast<std::size_t>(k)];
  if (!node.cut) return rectangle_links(a, b);
  const PolygonCut& c = *node.cut;
  const bool on_a = geom::on_segment(a, c.from, c.to), on_b = geom::on_segment(b, c.from, c.to);
  if (on_a && on_b) return a == b ? 0 : 1;
  // a point off the cut stops below k, in one part: its record there
  auto record = [&](Point p, std::int32_t stop) {
    while (nodes[static_cast<std::size_t>(stop)].parent != k) stop = nodes[static_cast<std::size_t>(stop)].parent;
    const int side = stop == node.left ? 0 : 1;
    const auto r = parts_[static_cast<std::size_t>(k)][static_cast<std::size_t>(side)]->at(p);
    if (!r) throw std::logic_error("LinkPointQueries: a point in a leaf has no record in its part");
    return std::pair{side, *r};
  };
  if (on_a) return links_to_cut_point(record(b, *sb).second, cut_position(c, a));
  if (on_b) return links_to_cut_point(record(a, *sa).second, cut_position(c, b));
  const auto ra = record(a, *sa), rb = record(b, *sb);
  if (ra.first == rb.first) throw std::logic_error("LinkPointQueries: two points part at a node on the same side");
  return links_across(ra.second, rb.second);
}

namespace {

using Run = CutReach::Run;

// Values v_i in the closed intervals iv[i] minimising |from - v_0| + sum |v_i - v_{i+1}| +
// |v_last - to|. Forward, the least cost of the prefix is c + dist(v, S_i) on iv[i] for an
// interval S_i (the optimal set: S_i = S_{i-1} meet iv[i], or iv[i]'s nearer end when they do
// not meet); backward, v_i = the point of S_i nearest v_{i+1}.
std::vector<i64> least_variation(i64 from, const std::vector<std::pair<i64, i64>>& iv, i64 to) {
  std::vector<std::pair<i64, i64>> best(iv.size());
  i64 lo = from, hi = from;
  for (std::size_t i = 0; i < iv.size(); ++i) {
    const auto [a, b] = iv[i];
    if (std::max(lo, a) <= std::min(hi, b)) lo = std::max(lo, a), hi = std::min(hi, b);
    else lo = hi = a > hi ? a : b;
    best[i] = {lo, hi};
  }
  std::vector<i64> v(iv.size());
  i64 next = to;
  for (std::size_t i = iv.size(); i-- > 0;) v[i] = next = std::clamp(next, best[i].first, best[i].second);
  return v;
}

// The path through the runs from a to b with the least L1 length (see LinkPointQueries::path).
std::vector<Point> realise(Point a, std::vector<Run> runs, Point b) {
  if (runs.empty()) throw std::logic_error("link_reach: a path without links");
  auto pin = [](Run& r, Point p) {
    const i64 c = r.vertical ? p.x : p.y;
    if (c < r.lo || c > r.hi) throw std::logic_error("link_reach: an end of a path is off its first or last link");
    r.lo = r.hi = c;
  };
  pin(runs.front(), a);
  pin(runs.back(), b);
  std::vector<std::pair<i64, i64>> xs, ys;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].lo > runs[i].hi) throw std::logic_error("link_reach: a link with no room");
    if (i > 0 && runs[i].vertical == runs[i - 1].vertical) throw std::logic_error("link_reach: two links of a path on one axis");
    (runs[i].vertical ? xs : ys).push_back({runs[i].lo, runs[i].hi});
  }
  const std::vector<i64> x = least_variation(a.x, xs, b.x), y = least_variation(a.y, ys, b.y);
  std::vector<Point> pts{a};
  std::size_t ix = 0, iy = 0;
  for (std::size_t i = 0; i + 1 < runs.size(); ++i) {  // the bend between runs i and i + 1
    const i64 bx = runs[i].vertical ? x[ix++] : x[ix], by = runs[i].vertical ? y[iy] : y[iy++];
    pts.push_back({static_cast<Coord>(bx), static_cast<Coord>(by)});
  }
  pts.push_back(b);
  // links of length zero and straight bends go
  std::vector<Point> out;
  for (const Point p : pts) {
    if (!out.empty() && out.back() == p) continue;
    if (out.size() >= 2 && geom::orientation(out[out.size() - 2], out.back(), p) == 0) out.back() = p;
    else out.push_back(p);
  }
  return out;
}

// The fewest links over the ways of two records meeting on a cut, and the pair of ways (0 first,
// 1 second, 2 along) that gives it: two perpendicular ways land on one point (their last links
// are one) or on two joined along the cut; an along way meets a perpendicular one where it lands;
// two along ways share their last link.
struct Glue {
  int links = std::numeric_limits<int>::max(), wa = -1, wb = -1;
};
Glue best_glue(const CutReach::Ways& a, const CutReach::Ways& b) {
  const CutReach::Way* wa[3] = {&a.first, &a.second, &a.along};
  const CutReach::Way* wb[3] = {&b.first, &b.second, &b.along};
  Glue g;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (wa[i]->links < 0 || wb[j]->links < 0) continue;
      int links = wa[i]->links + wb[j]->links;
      if (i == 2 && j == 2) links -= 1;
      else if (i < 2 && j < 2) links += wa[i]->at.meets(wb[j]->at) ? -1 : 1;
      if (links < g.links) g = {links, i, j};
    }
  return g;
}

}  // namespace

std::optional<std::vector<Point>> LinkPointQueries::path(Point a, Point b) const {
  const auto sa = stop_node(a), sb = stop_node(b);
  if (!sa || !sb) return std::nullopt;
  if (a == b) return std::vector<Point>{a};
  const auto& nodes = tree_.nodes();
  const std::int32_t k = common_ancestor(*sa, *sb);
  const auto& node = nodes[static_cast<std::size_t>(k)];
  if (!node.cut) {  // a rectangle: any L
    if (a.x == b.x || a.y == b.y) return std::vector<Point>{a, b};
    return std::vector<Point>{a, Point{b.x, a.y}, b};
  }
  const PolygonCut& c = *node.cut;
  const bool on_a = geom::on_segment(a, c.from, c.to), on_b = geom::on_segment(b, c.from, c.to);
  if (on_a && on_b) return std::vector<Point>{a, b};
  auto part = [&](std::int32_t stop) -> const CutReach& {
    while (nodes[static_cast<std::size_t>(stop)].parent != k) stop = nodes[static_cast<std::size_t>(stop)].parent;
    return *parts_[static_cast<std::size_t>(k)][stop == node.left ? 0 : 1];
  };
  const bool vertical_cut = c.from.x == c.to.x;
  const Run along_cut{vertical_cut, vertical_cut ? c.from.x : c.from.y, vertical_cut ? c.from.x : c.from.y};
  auto reversed = [](std::vector<Run> r) {
    std::reverse(r.begin(), r.end());
    return r;
  };
  if (on_a || on_b) {  // from the point off the cut to the one on it, then turned round if needed
    const Point q = on_a ? b : a, on = on_a ? a : b;
    const CutReach& reach = part(on_a ? *sb : *sa);
    const auto w = reach.ways(q);
    if (!w) throw std::logic_error("LinkPointQueries: a point in a leaf has no ways in its part");
    const i64 pos = cut_position(c, on);
    const ReachInterval here{pos, pos};
    // land on the point, or elsewhere and then along the cut, or come along the cut's line
    int links = std::numeric_limits<int>::max(), way = -1;
    bool then_along = false;
    const CutReach::Way* ws[3] = {&w->first, &w->second, &w->along};
    for (int i = 0; i < 3; ++i) {
      if (ws[i]->links < 0) continue;
      const bool lands = i == 2 || ws[i]->at.contains(pos);
      const int l = ws[i]->links + (lands ? 0 : 1);
      if (l < links) links = l, way = i, then_along = !lands;
    }
    ReachInterval within = then_along || way == 2 ? ws[way]->at : here;
    std::vector<Run> runs = reach.runs(q, way, within);
    if (then_along) runs.push_back(along_cut);
    std::vector<Point> p = realise(q, std::move(runs), on);
    if (on_a) std::reverse(p.begin(), p.end());
    return p;
  }
  const CutReach &ra = part(*sa), &rb = part(*sb);
  const auto wa = ra.ways(a), wb = rb.ways(b);
  if (!wa || !wb) throw std::logic_error("LinkPointQueries: a point in a leaf has no ways in its part");
  const Glue g = best_glue(*wa, *wb);
  const CutReach::Way* was[3] = {&wa->first, &wa->second, &wa->along};
  const CutReach::Way* wbs[3] = {&wb->first, &wb->second, &wb->along};
  std::vector<Run> runs;
  if (g.wa < 2 && g.wb < 2 && was[g.wa]->at.meets(wbs[g.wb]->at)) {  // one landing: the last links are one
    const ReachInterval& x = was[g.wa]->at;
    const ReachInterval& y = wbs[g.wb]->at;
    ReachInterval within{std::max(x.lo, y.lo), std::min(x.hi, y.hi)};
    runs = ra.runs(a, g.wa, within);
    std::vector<Run> rest = reversed(rb.runs(b, g.wb, within));
    Run& joint = runs.back();
    joint.lo = std::max(joint.lo, rest.front().lo), joint.hi = std::min(joint.hi, rest.front().hi);
    runs.insert(runs.end(), rest.begin() + 1, rest.end());
  } else {
    ReachInterval wi = was[g.wa]->at, wj = wbs[g.wb]->at;
    runs = ra.runs(a, g.wa, wi);
    std::vector<Run> rest = reversed(rb.runs(b, g.wb, wj));
    if (g.wa == 2 && g.wb == 2) {  // both along the cut's line: one link
      runs.insert(runs.end(), rest.begin() + 1, rest.end());
    } else {
      if (g.wa < 2 && g.wb < 2) runs.push_back(along_cut);  // two landings, joined along the cut
      runs.insert(runs.end(), rest.begin(), rest.end());
    }
  }
  std::vector<Point> p = realise(a, std::move(runs), b);
  return p;
}

std::optional<int> LinkPointQueries::links_by_descent(Point a, Point b) const {
  const auto& nodes = tree_.nodes();
  for (std::size_t k = 0;;) {
    const auto& node = nodes[k];
    if (!node.cut) {  // a rectangle (checked for containment only at the root: below, the parts did)
      if (k == 0) {
        const auto [lo, hi] = std::minmax_element(node.polygon.begin(), node.polygon.end(),
                                                  [](Point p, Point q) { return std::pair{p.x, p.y} < std::pair{q.x, q.y}; });
        for (const Point p : {a, b})
          if (p.x < lo->x || p.x > hi->x || p.y < lo->y || p.y > hi->y) return std::nullopt;
      }
      return rectangle_links(a, b);
    }
    const PolygonCut& c = *node.cut;
    const bool on_a = geom::on_segment(a, c.from, c.to), on_b = geom::on_segment(b, c.from, c.to);
    if (on_a && on_b) return a == b ? 0 : 1;
    auto locate = [&](Point p) -> std::optional<std::pair<int, BaseReach>> {
      for (int side = 0; side < 2; ++side)
        if (auto r = parts_[k][static_cast<std::size_t>(side)]->at(p)) return std::pair{side, *r};
      return std::nullopt;
    };
    const auto ra = on_a ? std::nullopt : locate(a);
    const auto rb = on_b ? std::nullopt : locate(b);
    if ((!on_a && !ra) || (!on_b && !rb)) return std::nullopt;
    if (on_a) return links_to_cut_point(rb->second, cut_position(c, a));
    if (on_b) return links_to_cut_point(ra->second, cut_position(c, b));
    if (ra->first != rb->first) return links_across(ra->second, rb->second);
    k = static_cast<std::size_t>(ra->first == 0 ? node.left : node.right);
  }
}

LinkVertexQueries::LinkVertexQueries(const Ring& polygon) : tree_(polygon) {
  const auto& nodes = tree_.nodes();
  for (auto& r : reach_) r.resize(nodes.size());
  std::vector<RingIndex> index;
  index.reserve(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const auto& node = nodes[k];
    index.emplace_back(node.polygon);
    if (!node.cut) continue;
    for (int side = 0; side < 2; ++side) {
      const auto child = static_cast<std::size_t>(side == 0 ? node.left : node.right);
      reach_[side][k] = base_reach(nodes[child].polygon, node.cut->from, node.cut->to);
    }
  }
  way_.resize(polygon.size());
  for (std::size_t v = 0; v < polygon.size(); ++v) {
    const Point p = polygon[v];
    for (std::int32_t k = 0;;) {
      const auto& node = nodes[static_cast<std::size_t>(k)];
      if (!node.cut) {
        way_[v].push_back({k, -2, 0});
        break;
      }
      const PolygonCut& c = *node.cut;
      if (geom::on_segment(p, c.from, c.to)) {
        way_[v].push_back({k, -1, cut_position(c, p)});
        break;
      }
      const std::int32_t child[2] = {node.left, node.right};
      int side = -1;
      for (int s = 0; s < 2 && side < 0; ++s)
        if (const auto i = index[static_cast<std::size_t>(child[s])].find(p)) {
          side = s;
          way_[v].push_back({k, static_cast<std::int8_t>(s), static_cast<std::int64_t>(*i)});
        }
      if (side < 0) throw std::logic_error("LinkVertexQueries: a vertex off the cut is in neither part");
      k = child[side];
    }
  }
}

std::size_t LinkVertexQueries::records() const {
  std::size_t n = 0;
  for (const auto& side : reach_)
    for (const auto& r : side) n += r.size();
  return n;
}

int LinkVertexQueries::links(std::size_t i, std::size_t j) const {
  const auto& a = way_.at(i);
  const auto& b = way_.at(j);
  const Ring& ring = tree_.nodes()[0].polygon;
  if (i == j) return 0;
  const Point p = ring[i], q = ring[j];
  for (std::size_t k = 0;; ++k) {
    const Step& s = a[k];
    const Step& t = b[k];
    if (s.side == -2) return rectangle_links(p, q);
    if (s.side == -1 && t.side == -1) return 1;                  // both on the cut
    if (s.side == -1 || t.side == -1) {
      // one on the cut at position pos, the other's record: arrive there perpendicular, or
      // perpendicular elsewhere and along the cut, or along the cut's line
      const Step& off = s.side == -1 ? t : s;
      const std::int64_t pos = s.side == -1 ? s.index : t.index;
      return links_to_cut_point(reach_[off.side][static_cast<std::size_t>(off.node)][static_cast<std::size_t>(off.index)], pos);
    }
    if (s.side != t.side)
      return links_across(reach_[s.side][static_cast<std::size_t>(s.node)][static_cast<std::size_t>(s.index)],
                          reach_[t.side][static_cast<std::size_t>(t.node)][static_cast<std::size_t>(t.index)]);
  }
}

namespace {

// Whether some p of `ps` and q of `qs` have p.x < q.x and p.y < q.y; the pair's tags, if so.
struct Tagged {
  std::int64_t x, y;
  std::size_t tag;
};
std::optional<std::pair<std::size_t, std::size_t>> dominated(std::vector<Tagged>& ps, std::vector<Tagged>& qs) {
  auto by_x = [](const Tagged& a, const Tagged& b) { return a.x < b.x; };
  std::sort(ps.begin(), ps.end(), by_x);
  std::sort(qs.begin(), qs.end(), by_x);
  std::size_t k = 0;
  const Tagged* low = nullptr;  // the lowest p seen with p.x < q.x
  for (const Tagged& q : qs) {
    for (; k < ps.size() && ps[k].x < q.x; ++k)
      if (!low || ps[k].y < low->y) low = &ps[k];
    if (low && low->y < q.y) return std::pair{low->tag, q.tag};
  }
  return std::nullopt;
}

}  // namespace

LinkVertexQueries::Diameter LinkVertexQueries::diameter() const {
  const auto& nodes = tree_.nodes();
  const Ring& ring = nodes[0].polygon;
  const std::size_t n = ring.size();
  Diameter best;
  // members[node][side]: (vertex, record index) of the convex vertices that pass the node there
  std::vector<std::array<std::vector<std::pair<std::size_t, std::size_t>>, 2>> members(nodes.size());
  std::vector<std::vector<std::size_t>> leaf(nodes.size());
  for (std::size_t v = 0; v < n; ++v) {
    if (geom::orientation(ring[(v + n - 1) % n], ring[v], ring[(v + 1) % n]) <= 0) continue;  // convex only
    for (const Step& s : way_[v]) {
      if (s.side >= 0) members[static_cast<std::size_t>(s.node)][static_cast<std::size_t>(s.side)].push_back({v, static_cast<std::size_t>(s.index)});
      else if (s.side == -2) leaf[static_cast<std::size_t>(s.node)].push_back(v);
    }
  }
  auto offer = [&](int links, std::size_t a, std::size_t b) {
    if (links > best.links) best = {links, std::min(a, b), std::max(a, b)};
  };
  for (const auto& l : leaf)  // two corners of one rectangle
    for (std::size_t i = 0; i < l.size(); ++i)
      for (std::size_t j = i + 1; j < l.size(); ++j) offer(rectangle_links(ring[l[i]], ring[l[j]]), l[i], l[j]);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const auto& side = members[k];
    if (side[0].empty() || side[1].empty()) continue;
    // groups by (d, kind), kind = min(along, d + 1) - d in {-1, 0, 1}: larger alongs change nothing
    std::map<std::pair<int, int>, std::vector<std::size_t>> groups[2];  // (d, along) -> indices into side[s]
    int top[2] = {0, 0};
    for (int s = 0; s < 2; ++s)
      for (const auto& [v, i] : side[s]) top[s] = std::max(top[s], reach_[s][k][i].links);
    for (int s = 0; s < 2; ++s)
      for (std::size_t m = 0; m < side[s].size(); ++m) {
        const BaseReach& r = reach_[s][k][side[s][m].second];
        if (r.links < top[s] - 3) continue;  // the top pair is at least top0 + top1 - 3 apart
        groups[s][{r.links, std::min(r.along, r.links + 1)}].push_back(m);
      }
    const auto rec = [&](int s, std::size_t m) -> const BaseReach& { return reach_[s][k][side[s][m].second]; };
    for (const auto& [gk, g] : groups[0])
      for (const auto& [hk, h] : groups[1]) {
        const auto [gd, galong] = gk;
        const auto [hd, halong] = hk;
        const int sum = gd + hd;
        const int along = std::min({gd + halong, galong + hd, galong + halong - 1});
        if (std::min(sum + 1, along) <= best.links) continue;
        // Lemma 2's +1: next_v misses at_w and at_v misses next_w, one wholly before the other
        std::optional<std::pair<std::size_t, std::size_t>> w;
        {
          std::vector<Tagged> ps, qs;
          for (const std::size_t m : g) ps.push_back({rec(0, m).next.hi, rec(0, m).at.hi, m});
          for (const std::size_t m : h) qs.push_back({rec(1, m).at.lo, rec(1, m).next.lo, m});
          w = dominated(ps, qs);
        }
        if (!w) {
          std::vector<Tagged> ps, qs;
          for (const std::size_t m : h) ps.push_back({rec(1, m).at.hi, rec(1, m).next.hi, m});
          for (const std::size_t m : g) qs.push_back({rec(0, m).next.lo, rec(0, m).at.lo, m});
          if (const auto x = dominated(ps, qs)) w = std::pair{x->second, x->first};
        }
        int delta = 1;
        if (!w) {  // 0 when two at intervals miss each other
          delta = 0;
          auto lowest_hi = [&](int s, const std::vector<std::size_t>& ms) {
            return *std::min_element(ms.begin(), ms.end(), [&](std::size_t a, std::size_t b) { return rec(s, a).at.hi < rec(s, b).at.hi; });
          };
          auto highest_lo = [&](int s, const std::vector<std::size_t>& ms) {
            return *std::max_element(ms.begin(), ms.end(), [&](std::size_t a, std::size_t b) { return rec(s, a).at.lo < rec(s, b).at.lo; });
          };
          const std::size_t a0 = lowest_hi(0, g), b0 = highest_lo(1, h), a1 = highest_lo(0, g), b1 = lowest_hi(1, h);
          if (rec(0, a0).at.hi < rec(1, b0).at.lo) w = std::pair{a0, b0};
          else if (rec(1, b1).at.hi < rec(0, a1).at.lo) w = std::pair{a1, b1};
          else delta = -1, w = std::pair{g.front(), h.front()};
        }
        offer(std::min(sum + delta, along), side[0][w->first].first, side[1][w->second].first);
      }
  }
  return best;
}

}  // namespace taut::router
