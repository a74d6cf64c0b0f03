#include "router/check.h"

#include <algorithm>
#include <boost/geometry/index/rtree.hpp>
#include <boost/multiprecision/cpp_int.hpp>
#include <cmath>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <set>
#include <string>
#include <utility>

#include "geom/bg.h"
#include "geom/predicates.h"

namespace taut::router {
namespace {

namespace bgi = boost::geometry::index;
using geom::Point;
using i64 = std::int64_t;
using i128 = __int128;

std::string text(Point p) { return std::to_string(p.x) + "," + std::to_string(p.y); }

// A direction: an integer vector (differences of coordinates, |component| < 2^31).
struct Dir {
  i64 x = 0, y = 0;
};
Dir dir(Point from, Point to) { return {i64{to.x} - from.x, i64{to.y} - from.y}; }
i128 cross(Dir a, Dir b) { return i128{a.x} * b.y - i128{a.y} * b.x; }
i128 dotp(Dir a, Dir b) { return i128{a.x} * b.x + i128{a.y} * b.y; }
bool same(Dir a, Dir b) { return cross(a, b) == 0 && dotp(a, b) > 0; }
// 0 when the counter-clockwise angle from a to u lies in [0, pi), else 1.
int half(Dir a, Dir u) { return (cross(a, u) > 0 || (cross(a, u) == 0 && dotp(a, u) > 0)) ? 0 : 1; }
// The counter-clockwise angle from a to u is smaller than the one from a to v (angles in [0, 2 pi)).
bool before(Dir a, Dir u, Dir v) {
  if (same(u, v)) return false;
  if (same(a, u)) return true;
  if (same(a, v)) return false;
  const int hu = half(a, u), hv = half(a, v);
  if (hu != hv) return hu < hv;
  return cross(u, v) > 0;
}

// A directed ring edge with the material on its left; `next` is the ring's next edge.
struct Edge {
  Point s, t;
  std::size_t next = 0;
  std::optional<std::size_t> obstacle;  // none for the domain's sides
  bool domain = false;
};

using EdgeBox = std::pair<geom::Box, std::size_t>;
geom::Box box_of(Point a, Point b) {
  return {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
}

geom::Box bounds(std::span<const Point> pts) {
  geom::Box b{pts.front(), pts.front()};
  for (const Point p : pts) b = geom::Box{{std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)}, {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)}};
  return b;
}

// A squared Euclidean distance as an exact fraction num / den (den > 0).
struct Dist2 {
  i128 num = 0, den = 1;
};
using Big = boost::multiprecision::int256_t;
// d^2 >= (twice / 2)^2, i.e. the distance is at least twice / 2: 4 num >= twice^2 den.
bool at_least(Dist2 d, i64 twice) { return Big(d.num) * 4 >= Big(twice) * Big(twice) * Big(d.den); }
double approx(Dist2 d) { return std::sqrt(static_cast<double>(d.num) / static_cast<double>(d.den)); }
// Point p to the closed segment ab.
Dist2 point_segment(Point p, Point a, Point b) {
  const geom::SquaredDistance d = geom::point_segment_distance2(p, a, b);
  return {d.num, d.den};
}
bool smaller(Dist2 x, Dist2 y) { return Big(x.num) * Big(y.den) < Big(y.num) * Big(x.den); }
// The closed segments ab and cd (0 when they meet).
Dist2 segment_segment(Point a, Point b, Point c, Point d) {
  if (geom::intersect({a, b}, {c, d}) != geom::SegmentIntersection::None) return {0, 1};
  Dist2 best = point_segment(a, c, d);
  for (const Dist2 x : {point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)})
    if (smaller(x, best)) best = x;
  return best;
}

// The same for segments with rational ends, given scaled by a common denominator into
// arbitrary-precision integers (the pin-access cut, see check_clearance).
using Huge = boost::multiprecision::cpp_int;
int sign(const Huge& v) { return (v > 0) - (v < 0); }
struct HugePoint {
  Huge x, y;
};
struct HugeDist2 {
  Huge num, den;
};
Huge h_cross(const HugePoint& o, const HugePoint& a, const HugePoint& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }
HugeDist2 h_point_segment(const HugePoint& p, const HugePoint& a, const HugePoint& b) {
  const Huge abx = b.x - a.x, aby = b.y - a.y, apx = p.x - a.x, apy = p.y - a.y;
  const Huge len2 = abx * abx + aby * aby, t = apx * abx + apy * aby;
  if (len2 == 0 || t <= 0) return {apx * apx + apy * apy, 1};
  if (t >= len2) {
    const Huge bpx = p.x - b.x, bpy = p.y - b.y;
    return {bpx * bpx + bpy * bpy, 1};
  }
  const Huge c = abx * apy - aby * apx;
  return {c * c, len2};
}
bool h_within(const HugePoint& p, const HugePoint& a, const HugePoint& b) {  // p in ab's box
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}
HugeDist2 h_segment_segment(const HugePoint& a, const HugePoint& b, const HugePoint& c, const HugePoint& d) {
  const int o1 = sign(h_cross(a, b, c)), o2 = sign(h_cross(a, b, d)), o3 = sign(h_cross(c, d, a)), o4 = sign(h_cross(c, d, b));
  const bool meet = (o1 * o2 < 0 && o3 * o4 < 0) || (o1 == 0 && h_within(c, a, b)) || (o2 == 0 && h_within(d, a, b)) ||
                    (o3 == 0 && h_within(a, c, d)) || (o4 == 0 && h_within(b, c, d));
  if (meet) return {0, 1};
  HugeDist2 best = h_point_segment(a, c, d);
  for (const HugeDist2& x : {h_point_segment(b, c, d), h_point_segment(c, a, b), h_point_segment(d, a, b)})
    if (x.num * best.den < best.num * x.den) best = x;
  return best;
}

}  // namespace

struct FreeSpaceChecker::Impl {
  geom::Box domain;
  std::vector<geom::Polygon> obstacles_copy;  // its own copy: the checker may outlive the caller's
  const std::vector<geom::Polygon>* obstacles = nullptr;
  std::vector<Edge> edges;
  bgi::rtree<EdgeBox, bgi::rstar<16>> edge_tree;
  bgi::rtree<EdgeBox, bgi::rstar<16>> obstacle_tree;  // obstacles' bounding boxes

  explicit Impl(const geom::NormalizedObstacles& norm)
      : domain(norm.domain), obstacles_copy(norm.obstacles), obstacles(&obstacles_copy) {
    auto add_ring = [&](const geom::Ring& ring, std::optional<std::size_t> obstacle, bool is_domain) {
      const std::size_t first = edges.size(), n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        Edge e;
        e.s = ring[i];
        e.t = ring[(i + 1) % n];
        e.next = first + (i + 1) % n;
        e.obstacle = obstacle;
        e.domain = is_domain;
        edges.push_back(e);
      }
    };
    for (std::size_t k = 0; k < norm.obstacles.size(); ++k) {
      const geom::Polygon& poly = norm.obstacles[k];
      add_ring(poly.outer, k, false);
      for (const geom::Ring& h : poly.holes) add_ring(h, k, false);
    }
    // The domain as a clockwise ring: the material (outside) on the left of every side.
    const geom::Box& d = domain;
    add_ring({{d.lo.x, d.lo.y}, {d.lo.x, d.hi.y}, {d.hi.x, d.hi.y}, {d.hi.x, d.lo.y}}, std::nullopt, true);
    std::vector<EdgeBox> boxes;
    boxes.reserve(edges.size());
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (edges[i].s != edges[i].t) boxes.emplace_back(box_of(edges[i].s, edges[i].t), i);
    edge_tree = decltype(edge_tree)(boxes.begin(), boxes.end());
    std::vector<EdgeBox> obs;
    for (std::size_t k = 0; k < norm.obstacles.size(); ++k) obs.emplace_back(bounds(norm.obstacles[k].outer), k);
    obstacle_tree = decltype(obstacle_tree)(obs.begin(), obs.end());
  }

  std::vector<std::size_t> edges_near(const geom::Box& b) const {
    std::vector<EdgeBox> hits;
    edge_tree.query(bgi::intersects(b), std::back_inserter(hits));
    std::vector<std::size_t> out;
    out.reserve(hits.size());
    for (const auto& h : hits) out.push_back(h.second);
    return out;
  }

  bool in_domain(Point p) const { return p.x >= domain.lo.x && p.x <= domain.hi.x && p.y >= domain.lo.y && p.y <= domain.hi.y; }

  // The free sectors around p: sorted boundary directions, and per sector (from dirs[i] to
  // dirs[i + 1], cyclically) whether it is free. `on_ring` false: p touches no ring (then
  // `inside` tells whether it lies in an obstacle, the obstacle in `hit`).
  struct Around {
    bool on_ring = false, inside = false;
    std::optional<std::size_t> hit;
    std::vector<Dir> dirs;
    std::vector<char> free;
    // u (and v) in the closure of one free sector
    bool in_one(Dir u, Dir v) const {
      if (!on_ring) return !inside;
      const std::size_t k = dirs.size();
      for (std::size_t i = 0; i < k; ++i) {
        if (!free[i]) continue;
        const Dir a = dirs[i], b = dirs[(i + 1) % k];
        auto holds = [&](Dir w) { return same(w, a) || same(w, b) || (k == 1 ? true : before(a, w, b)); };
        if (holds(u) && holds(v)) return true;
      }
      return false;
    }
  };
  Around around(Point p) const {
    Around r;
    // The ring edges at p, as directions from p: an edge leaving p has the material just
    // counter-clockwise of it (on its left); an edge arriving at p has it just clockwise of the
    // direction back along it, which is the same sector seen from its other end, so the
    // leaving edges alone decide. (Pairing each ring visit's two edges fails where a ring
    // touches itself at p.)
    struct Ray {
      Dir d;
      bool out = false;
    };
    std::vector<Ray> rays;
    auto add = [&](Dir d, bool out) {
      for (Ray& x : rays)
        if (same(x.d, d)) {
          x.out = x.out || out;
          return;
        }
      rays.push_back({d, out});
    };
    for (const std::size_t i : edges_near({p, p})) {
      const Edge& e = edges[i];
      if (!geom::on_segment(p, e.s, e.t)) continue;
      r.on_ring = true;
      if (!r.hit) r.hit = e.obstacle;
      if (p != e.t) add(dir(p, e.t), true);
      if (p != e.s) add(dir(p, e.s), false);
    }
    if (!r.on_ring) {
      std::vector<EdgeBox> hits;
      obstacle_tree.query(bgi::intersects(geom::Box{p, p}), std::back_inserter(hits));
      for (const auto& h : hits)
        if (geom::locate(p, (*obstacles)[h.second]) == geom::Location::Inside) {
          r.inside = true;
          r.hit = h.second;
        }
      if (!in_domain(p)) r.inside = true;
      return r;
    }
    const Dir base = rays.front().d;
    std::sort(rays.begin(), rays.end(), [&](const Ray& u, const Ray& v) { return before(base, u.d, v.d); });
    const std::size_t k = rays.size();
    r.dirs.resize(k);
    r.free.resize(k);
    for (std::size_t i = 0; i < k; ++i) {
      r.dirs[i] = rays[i].d;
      r.free[i] = !rays[i].out;
    }
    return r;
  }

  // Segment ab (a != b): free, with its ends only required to leave into some wedge.
  Verdict segment(Point a, Point b) const {
    Verdict v;
    auto fail = [&](Point at, std::optional<std::size_t> obstacle, std::string why) {
      v.free = false;
      v.at = at;
      v.obstacle = obstacle;
      v.why = std::move(why);
      return v;
    };
    if (!in_domain(a)) return fail(a, std::nullopt, "the point " + text(a) + " lies outside the routing area");
    if (!in_domain(b)) return fail(b, std::nullopt, "the point " + text(b) + " lies outside the routing area");
    std::vector<Point> contacts;
    for (const std::size_t i : edges_near(box_of(a, b))) {
      const Edge& e = edges[i];
      switch (geom::intersect({a, b}, {e.s, e.t})) {
        case geom::SegmentIntersection::None:
          continue;
        case geom::SegmentIntersection::Proper:
          return fail(a, e.obstacle,
                      e.domain ? "the segment " + text(a) + " " + text(b) + " crosses the side of the routing area"
                               : "the segment " + text(a) + " " + text(b) + " crosses a blockage edge (" + text(e.s) + " " +
                                     text(e.t) + ")");
        case geom::SegmentIntersection::Overlap:
          [[fallthrough]];
        case geom::SegmentIntersection::Touch:
          for (const Point p : {e.s, e.t})
            if (geom::on_segment(p, a, b)) contacts.push_back(p);
          for (const Point p : {a, b})
            if (geom::on_segment(p, e.s, e.t)) contacts.push_back(p);
          break;
      }
    }
    if (contacts.empty()) {
      const Around r = around(a);
      if (r.inside) return fail(a, r.hit, "the point " + text(a) + " lies inside a blockage");
      return v;
    }
    std::sort(contacts.begin(), contacts.end());
    contacts.erase(std::unique(contacts.begin(), contacts.end()), contacts.end());
    for (const Point q : contacts) {
      const Around r = around(q);
      const Dir to_a = dir(q, a), to_b = dir(q, b);
      const bool ok = q == a ? r.in_one(to_b, to_b) : q == b ? r.in_one(to_a, to_a) : r.in_one(to_a, to_b);
      if (!ok)
        return fail(q, r.hit,
                    q == a || q == b ? "the segment " + text(a) + " " + text(b) + " leaves " + text(q) + " into a blockage"
                                     : "the segment " + text(a) + " " + text(b) + " passes through " + text(q) +
                                           " into a blockage, or through a point where blockages touch");
    }
    return v;
  }
};

FreeSpaceChecker::FreeSpaceChecker(const geom::NormalizedObstacles& obstacles) : impl_(std::make_unique<Impl>(obstacles)) {}
FreeSpaceChecker::~FreeSpaceChecker() = default;
FreeSpaceChecker::FreeSpaceChecker(FreeSpaceChecker&&) noexcept = default;
FreeSpaceChecker& FreeSpaceChecker::operator=(FreeSpaceChecker&&) noexcept = default;

bool FreeSpaceChecker::point_free(Point p) const {
  if (!impl_->in_domain(p)) return false;
  const Impl::Around r = impl_->around(p);
  if (!r.on_ring) return !r.inside;
  return std::any_of(r.free.begin(), r.free.end(), [](char f) { return f != 0; });
}

std::vector<std::pair<geom::Segment, std::size_t>> FreeSpaceChecker::obstacle_edges_near(const geom::Box& box) const {
  std::vector<std::pair<geom::Segment, std::size_t>> out;
  for (const std::size_t i : impl_->edges_near(box)) {
    const Edge& e = impl_->edges[i];
    if (e.obstacle) out.push_back({{e.s, e.t}, *e.obstacle});
  }
  return out;
}

FreeSpaceChecker::Verdict FreeSpaceChecker::polyline(std::span<const Point> points) const {
  Verdict v;
  // Distinct consecutive points only (a repeated point adds nothing).
  std::vector<Point> p;
  for (const Point q : points)
    if (p.empty() || p.back() != q) p.push_back(q);
  if (p.empty()) return v;
  if (p.size() == 1) {
    if (!point_free(p[0])) {
      v.free = false;
      v.at = p[0];
      v.why = "the point " + text(p[0]) + " is not in free space";
    }
    return v;
  }
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    v = impl_->segment(p[i], p[i + 1]);
    if (!v.free) return v;
  }
  // (a closed polyline, last point = first, also passes through its first point: that is checked
  // as a bend between its last segment and its first; since 2026-12-05, before which a closed
  // wire through a point where blockages touch passed when that point was its first)
  const bool closed = p.size() >= 3 && p.front() == p.back();
  for (std::size_t i = closed ? 0 : 1; i + 1 < p.size(); ++i) {
    const Impl::Around r = impl_->around(p[i]);
    if (!r.on_ring) continue;
    const Point before = i == 0 ? p[p.size() - 2] : p[i - 1];
    if (!r.in_one(dir(p[i], before), dir(p[i], p[i + 1]))) {
      v.free = false;
      v.at = p[i];
      v.obstacle = r.hit;
      v.why = "the wire bends at " + text(p[i]) + " from one side of a blockage to another (through a point where "
              "blockages touch, or across a blockage's corner)";
      return v;
    }
  }
  return v;
}

namespace {

struct UnionFind {
  std::vector<std::size_t> up;
  explicit UnionFind(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), std::size_t{0}); }
  std::size_t find(std::size_t x) {
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
  }
  void join(std::size_t a, std::size_t b) { up[find(a)] = find(b); }
};

// Does the closed segment ab meet the closed polygon?
bool meets_shape(Point a, Point b, const geom::Polygon& shape) {
  if (geom::locate(a, shape) != geom::Location::Outside || geom::locate(b, shape) != geom::Location::Outside) return true;
  auto ring_hit = [&](const geom::Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i)
      if (geom::intersect({a, b}, {r[i], r[(i + 1) % r.size()]}) != geom::SegmentIntersection::None) return true;
    return false;
  };
  if (ring_hit(shape.outer)) return true;
  return std::any_of(shape.holes.begin(), shape.holes.end(), ring_hit);
}

// Do two closed polygons meet? An edge of one (outer ring or hole) meets the other, or the
// other lies wholly inside it.
bool shapes_meet(const geom::Polygon& a, const geom::Polygon& b) {
  auto ring_meets = [&](const geom::Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i)
      if (meets_shape(r[i], r[(i + 1) % r.size()], b)) return true;
    return false;
  };
  if (ring_meets(a.outer) || std::any_of(a.holes.begin(), a.holes.end(), ring_meets)) return true;
  return !b.outer.empty() && geom::locate(b.outer[0], a) != geom::Location::Outside;
}

geom::Box pin_box(const CheckPin& pin) {
  if (pin.point) return {*pin.point, *pin.point};
  return bounds(pin.shape->outer);
}

bool segment_meets_pin(Point a, Point b, const CheckPin& pin) {
  if (pin.point) return geom::on_segment(*pin.point, a, b);
  return pin.shape && meets_shape(a, b, *pin.shape);
}

struct WireSegment {
  std::size_t net, wire;
  Point a, b;
};

}  // namespace

namespace {

using SegmentTree = bgi::rtree<EdgeBox, bgi::rstar<16>>;

geom::Box grown(const geom::Box& b, i64 r) {
  auto clamp = [](i64 v) { return static_cast<geom::Coord>(std::clamp<i64>(v, INT32_MIN, INT32_MAX)); };
  return {{clamp(i64{b.lo.x} - r), clamp(i64{b.lo.y} - r)}, {clamp(i64{b.hi.x} + r), clamp(i64{b.hi.y} + r)}};
}

std::string distance_text(Dist2 d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f", approx(d));
  return buf;
}
std::string half_text(i64 twice) { return std::to_string(twice / 2) + (twice % 2 ? ".5" : ""); }

// A non-negative fraction num / den (den > 0).
struct Frac {
  i64 num, den;
};
bool frac_less(const Frac& x, const Frac& y) { return i128(x.num) * y.den < i128(y.num) * x.den; }
// The closed interval of t in [0, 1] where a + t (b - a) lies in the closed box z, if any.
std::optional<std::pair<Frac, Frac>> box_interval(Point a, Point b, const geom::Box& z) {
  Frac lo{0, 1}, hi{1, 1};
  const i64 lo_c[2] = {z.lo.x, z.lo.y}, hi_c[2] = {z.hi.x, z.hi.y};
  const i64 pa[2] = {a.x, a.y}, pb[2] = {b.x, b.y};
  for (int k = 0; k < 2; ++k) {
    const i64 d = pb[k] - pa[k];
    if (d == 0) {
      if (pa[k] < lo_c[k] || pa[k] > hi_c[k]) return std::nullopt;
      continue;
    }
    // t where the coordinate reaches the box's two sides, ordered
    Frac t0{lo_c[k] - pa[k], d}, t1{hi_c[k] - pa[k], d};
    if (d < 0) t0 = {pa[k] - lo_c[k], -d}, t1 = {pa[k] - hi_c[k], -d}, std::swap(t0, t1);
    if (frac_less(lo, t0)) lo = t0;
    if (frac_less(t1, hi)) hi = t1;
  }
  if (frac_less(hi, lo)) return std::nullopt;
  return std::pair{lo, hi};
}

// The clearance of <rules> from blockages (see check.h): w/2 + s, but for the parts of a wire in
// the access zones of its own net's pins. Wires not in free space are reported as such and not measured.
void check_blockage_clearance(const FreeSpaceChecker& free, std::span<const CheckNet> nets, const CheckRules& rules,
                              const std::vector<std::size_t>& wire_id, const std::vector<char>& not_free,
                              CheckResult& result) {
  const i64 tb = rules.wire_width + 2 * rules.spacing;  // twice w/2 + s
  const i64 acc = (rules.wire_width + 1) / 2 + rules.spacing;  // the pin access radius
  for (std::size_t n = 0; n < nets.size(); ++n) {
    const CheckNet& net = nets[n];
    if (!net.routed) continue;
    // The access zones: the closed squares of half-side acc around the net's point pins.
    std::vector<geom::Box> zones;
    for (const CheckPin& pin : net.pins)
      if (pin.point)
        zones.push_back({{static_cast<geom::Coord>(pin.point->x - acc), static_cast<geom::Coord>(pin.point->y - acc)},
                         {static_cast<geom::Coord>(pin.point->x + acc), static_cast<geom::Coord>(pin.point->y + acc)}});
    for (std::size_t wi = 0; wi < net.wires.size(); ++wi) {
      const CheckWire& wire = net.wires[wi];
      if (not_free[wire_id[n] + wi]) continue;  // in a blockage: reported as not free, not measured
      std::vector<Point> p;
      for (const Point q : wire.points)
        if (p.empty() || p.back() != q) p.push_back(q);
      // A wire of one point (pins that meet, or a point written alone) is measured as the
      // segment from that point to itself.
      if (p.size() == 1) p.push_back(p.front());
      std::set<std::size_t> reported;  // obstacles named for this wire
      for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        const Point a = p[i], b = p[i + 1];
        // Pin access: the parts of ab in an access zone are exempt. Each zone holds one closed
        // interval of t (a + t (b - a), t in [0, 1]) with rational ends; the parts held to the
        // clearance are the closures of what the intervals leave, each measured exactly.
        std::vector<std::pair<Frac, Frac>> cover;
        for (const geom::Box& z : zones)
          if (auto iv = box_interval(a, b, z)) cover.push_back(*iv);
        std::sort(cover.begin(), cover.end(), [](const auto& x, const auto& y) { return frac_less(x.first, y.first); });
        std::vector<std::pair<Frac, Frac>> held;
        Frac at{0, 1};
        for (const auto& [lo, hi] : cover) {
          if (frac_less(at, lo)) held.push_back({at, lo});
          if (frac_less(at, hi)) at = hi;
        }
        if (frac_less(at, Frac{1, 1})) held.push_back({at, Frac{1, 1}});
        for (const auto& [t0, t1] : held) {
          const bool cut = !(t0.num == 0 && t1.num == t1.den);
          const Huge D = Huge(t0.den) * t1.den;
          auto scaled = [&](const Huge& j) {  // a + (j / D)(b - a), times D
            return HugePoint{Huge(a.x) * D + Huge(i64{b.x} - a.x) * j, Huge(a.y) * D + Huge(i64{b.y} - a.y) * j};
          };
          const HugePoint s0 = cut ? scaled(Huge(t0.num) * t1.den) : HugePoint{},
                          s1 = cut ? scaled(Huge(t1.num) * t0.den) : HugePoint{};
          for (const auto& [e, obstacle] : free.obstacle_edges_near(grown(box_of(a, b), tb / 2 + 1))) {
            if (reported.count(obstacle)) continue;
            Dist2 d;
            if (!cut) {
              d = segment_segment(a, b, e.a, e.b);
              if (at_least(d, tb)) continue;
            } else {
              const HugeDist2 h = h_segment_segment(s0, s1, HugePoint{Huge(e.a.x) * D, Huge(e.a.y) * D},
                                                    HugePoint{Huge(e.b.x) * D, Huge(e.b.y) * D});
              if (h.num * 4 >= Huge(tb) * tb * h.den * D * D) continue;
              // for the message only: the squared distance num / (den D^2), to 6 decimals
              const double dd = static_cast<double>(D);
              const double approx_d2 = static_cast<double>(h.num) / static_cast<double>(h.den) / dd / dd;
              d = {static_cast<i128>(approx_d2 * 1e6), 1000000};
            }
          reported.insert(obstacle);
          CheckProblem pr;
          pr.kind = CheckProblem::Kind::BlockageClearance;
          pr.net = n;
          pr.wire = wi;
          pr.line = wire.line;
          pr.at = a;
          pr.obstacle = obstacle;
          pr.message = "net \"" + net.name + "\": the segment " + text(a) + " " + text(b) + " comes within " +
                       distance_text(d) + " of a blockage edge (" + text(e.a) + " " + text(e.b) + "), closer than w/2 + s = " +
                       half_text(tb);
          result.problems.push_back(std::move(pr));
          }
        }
      }
    }
  }
}

// Between nets, with one R-tree query per wire segment and one per pin: shorts (a shared point,
// whatever the rules; once per pair of wires, and per wire and pin) and, with rules, the
// clearance (w + s from wires and point pins, w/2 + s from shape pins; judged on the pairs of
// segments that do not touch, once per pair of wires or wire and pin).
void check_between_nets(std::span<const CheckNet> nets, const std::vector<WireSegment>& segments, const SegmentTree& tree,
                        const CheckRules& rules, const std::vector<std::size_t>& wire_id, CheckResult& result) {
  const bool clearance = rules.wire_width > 0 || rules.spacing > 0;
  const i64 tb = rules.wire_width + 2 * rules.spacing;    // twice w/2 + s
  const i64 tn = 2 * (rules.wire_width + rules.spacing);  // twice w + s
  const i64 reach = clearance ? tn / 2 + 1 : 0;
  auto add = [&](CheckProblem::Kind kind, const WireSegment& s, std::size_t other_net, std::string what) {
    CheckProblem pr;
    pr.kind = kind;
    pr.net = s.net;
    pr.wire = s.wire;
    pr.other_net = other_net;
    pr.line = nets[s.net].wires[s.wire].line;
    pr.at = s.a;
    pr.message = "net \"" + nets[s.net].name + "\": the segment " + text(s.a) + " " + text(s.b) + " " + std::move(what);
    result.problems.push_back(std::move(pr));
  };
  std::set<std::pair<std::size_t, std::size_t>> shorted, close;  // (wire id, other's wire or pin id)
  std::vector<EdgeBox> hits;
  for (const WireSegment& s : segments) {
    hits.clear();
    tree.query(bgi::intersects(grown(box_of(s.a, s.b), reach)), std::back_inserter(hits));
    for (const auto& h : hits) {
      const WireSegment& o = segments[h.second];
      if (o.net <= s.net) continue;  // each pair of nets once, from the lower
      const std::pair<std::size_t, std::size_t> key{wire_id[s.net] + s.wire, wire_id[o.net] + o.wire};
      const std::string other = "a wire of net \"" + nets[o.net].name + "\" (" + text(o.a) + " " + text(o.b) + ", line " +
                                std::to_string(nets[o.net].wires[o.wire].line) + ")";
      if (geom::intersect({s.a, s.b}, {o.a, o.b}) != geom::SegmentIntersection::None) {
        if (shorted.insert(key).second) add(CheckProblem::Kind::Short, s, o.net, "touches " + other + ": a short");
        continue;
      }
      if (!clearance || close.count(key)) continue;
      const Dist2 d = segment_segment(s.a, s.b, o.a, o.b);
      if (at_least(d, tn)) continue;
      close.insert(key);
      add(CheckProblem::Kind::NetClearance, s, o.net,
          "comes within " + distance_text(d) + " of " + other + ", closer than w + s = " + half_text(tn));
    }
  }
  std::size_t pin_id = wire_id.back();  // pins numbered after every wire, in the same keys
  for (std::size_t n = 0; n < nets.size(); ++n)
    for (const CheckPin& pin : nets[n].pins) {
      ++pin_id;
      hits.clear();
      tree.query(bgi::intersects(grown(pin_box(pin), reach)), std::back_inserter(hits));
      const std::string other = "pin \"" + pin.name + "\" of net \"" + nets[n].name + "\" (line " + std::to_string(pin.line) + ")";
      for (const auto& h : hits) {
        const WireSegment& s = segments[h.second];
        if (s.net == n) continue;
        const std::pair<std::size_t, std::size_t> key{wire_id[s.net] + s.wire, pin_id};
        if (segment_meets_pin(s.a, s.b, pin)) {
          if (shorted.insert(key).second) add(CheckProblem::Kind::Short, s, n, "touches " + other + ": a short");
          continue;
        }
        if (!clearance || close.count(key)) continue;
        Dist2 d;
        if (pin.point) {
          d = point_segment(*pin.point, s.a, s.b);
        } else {
          bool first = true;
          auto ring = [&](const geom::Ring& r) {
            for (std::size_t i = 0; i < r.size(); ++i) {
              const Dist2 x = segment_segment(s.a, s.b, r[i], r[(i + 1) % r.size()]);
              if (first || smaller(x, d)) d = x;
              first = false;
            }
          };
          ring(pin.shape->outer);
          for (const auto& hole : pin.shape->holes) ring(hole);
        }
        const i64 need = pin.point ? tn : tb;
        if (at_least(d, need)) continue;
        close.insert(key);
        add(CheckProblem::Kind::NetClearance, s, n,
            "comes within " + distance_text(d) + " of " + other + ", closer than " + (pin.point ? "w + s = " : "w/2 + s = ") +
                half_text(need));
      }
    }
}

}  // namespace

CheckResult check_routes(const geom::NormalizedObstacles& obstacles, std::span<const CheckNet> nets, const CheckRules& rules) {
  CheckResult result;
  const FreeSpaceChecker free(obstacles);
  std::vector<WireSegment> segments;
  for (std::size_t n = 0; n < nets.size(); ++n) {
    const CheckNet& net = nets[n];
    if (!net.routed) continue;
    for (std::size_t w = 0; w < net.wires.size(); ++w) {
      const CheckWire& wire = net.wires[w];
      ++result.wires;
      const FreeSpaceChecker::Verdict v = free.polyline(wire.points);
      if (!v.free) {
        CheckProblem p;
        p.kind = CheckProblem::Kind::NotFree;
        p.net = n;
        p.wire = w;
        p.line = wire.line;
        p.at = v.at;
        p.obstacle = v.obstacle;
        p.message = "net \"" + net.name + "\": " + v.why;
        result.problems.push_back(std::move(p));
      }
      for (std::size_t i = 0; i + 1 < wire.points.size(); ++i)
        segments.push_back({n, w, wire.points[i], wire.points[i + 1]});
      if (wire.points.size() == 1) segments.push_back({n, w, wire.points[0], wire.points[0]});
    }
  }
  result.segments = segments.size();
  std::vector<EdgeBox> boxes;
  boxes.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) boxes.emplace_back(box_of(segments[i].a, segments[i].b), i);
  const SegmentTree tree(boxes.begin(), boxes.end());
  std::vector<EdgeBox> hits;

  // Connectivity per net: items 0..W-1 the wires, W.. the pins.
  std::vector<std::size_t> first(nets.size() + 1, 0);
  {
    std::size_t k = 0;
    for (std::size_t n = 0; n < nets.size(); ++n) {
      first[n] = k;
      while (k < segments.size() && segments[k].net == n) ++k;
    }
    first[nets.size()] = k;
  }
  for (std::size_t n = 0; n < nets.size(); ++n) {
    const CheckNet& net = nets[n];
    if (!net.routed) continue;
    auto closed = [](const CheckWire& w) { return w.points.size() >= 2 && w.points.front() == w.points.back(); };
    if (net.loop && std::all_of(net.wires.begin(), net.wires.end(), closed)) continue;
    const std::size_t wires = net.wires.size(), items = wires + net.pins.size();
    UnionFind uf(items);
    for (std::size_t i = first[n]; i < first[n + 1]; ++i) {
      const WireSegment& s = segments[i];
      hits.clear();
      tree.query(bgi::intersects(box_of(s.a, s.b)), std::back_inserter(hits));
      for (const auto& h : hits) {
        const WireSegment& o = segments[h.second];
        if (o.net != n || o.wire == s.wire) continue;
        if (geom::intersect({s.a, s.b}, {o.a, o.b}) != geom::SegmentIntersection::None) uf.join(s.wire, o.wire);
      }
      for (std::size_t p = 0; p < net.pins.size(); ++p)
        if (segment_meets_pin(s.a, s.b, net.pins[p])) uf.join(s.wire, wires + p);
    }
    // Pins that coincide (or overlap) connect without a wire: a shape pin is metal, so two shapes
    // of the net that meet (a common point, closed) are joined by their own metal, as the router
    // takes them in a tree (before 2026-12-06 two shapes connected only through a wire, and a
    // tree the router joined through their overlap failed here; found by fuzzing).
    for (std::size_t p = 0; p < net.pins.size(); ++p)
      for (std::size_t q = p + 1; q < net.pins.size(); ++q) {
        const CheckPin &a = net.pins[p], &b = net.pins[q];
        const bool meet = a.point && b.point   ? *a.point == *b.point
                          : a.point && b.shape ? geom::locate(*a.point, *b.shape) != geom::Location::Outside
                          : b.point && a.shape ? geom::locate(*b.point, *a.shape) != geom::Location::Outside
                          : a.shape && b.shape ? shapes_meet(*a.shape, *b.shape)
                                               : false;
        if (meet) uf.join(wires + p, wires + q);
      }
    if (net.pins.empty()) continue;
    const std::size_t root = uf.find(wires);  // the first pin's group
    std::vector<std::string> apart;
    for (std::size_t p = 1; p < net.pins.size(); ++p)
      if (uf.find(wires + p) != root) {
        CheckProblem pr;
        pr.kind = CheckProblem::Kind::Disconnected;
        pr.net = n;
        pr.line = net.pins[p].line;
        pr.at = net.pins[p].point ? *net.pins[p].point : net.pins[p].shape->outer.front();
        pr.message = "net \"" + net.name + "\": pin \"" + net.pins[p].name + "\" is not connected to pin \"" +
                     net.pins[0].name + "\" by the net's wires";
        result.problems.push_back(std::move(pr));
      }
    for (std::size_t w = 0; w < wires; ++w)
      if (uf.find(w) != root && !net.wires[w].points.empty() && !(net.loop && closed(net.wires[w]))) {
        // Stray only when its group holds no pin at all (a group with pins was named above).
        bool has_pin = false;
        for (std::size_t p = 0; p < net.pins.size(); ++p) has_pin = has_pin || uf.find(wires + p) == uf.find(w);
        if (has_pin) continue;
        CheckProblem pr;
        pr.kind = CheckProblem::Kind::StrayWire;
        pr.net = n;
        pr.wire = w;
        pr.line = net.wires[w].line;
        pr.at = net.wires[w].points.front();
        pr.message = "net \"" + net.name + "\": the wire from " + text(net.wires[w].points.front()) +
                     " touches none of the net's pins and no wire joined to them";
        result.problems.push_back(std::move(pr));
      }
  }

  std::vector<std::size_t> wire_id(nets.size() + 1, 0);  // nets' wires numbered in one sequence
  for (std::size_t n = 0; n < nets.size(); ++n) wire_id[n + 1] = wire_id[n] + nets[n].wires.size();
  check_between_nets(nets, segments, tree, rules, wire_id, result);
  if (rules.wire_width > 0 || rules.spacing > 0) {
    std::vector<char> not_free(wire_id.back(), 0);
    for (const CheckProblem& p : result.problems)
      if (p.kind == CheckProblem::Kind::NotFree) not_free[wire_id[p.net] + *p.wire] = 1;
    check_blockage_clearance(free, nets, rules, wire_id, not_free, result);
  }
  std::stable_sort(result.problems.begin(), result.problems.end(),
                   [](const CheckProblem& a, const CheckProblem& b) { return a.line < b.line; });
  return result;
}

}  // namespace taut::router
