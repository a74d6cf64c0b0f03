#include "router/staircase.h"

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>

#include "geom/directions.h"
#include "geom/index.h"
#include "geom/predicates.h"

namespace taut::router {

using geom::Box;
using geom::i128;
using geom::i64;
using geom::Point;
using geom::Polygon;
using geom::Segment;
using geom::SegmentIntersection;
using geom::floor_div;

namespace {

// Direction vectors: differences of points inside the domain (|component| < 2^31), so every
// cross or dot product of two of them is below 2^63; computed in __int128 anyway.
struct Dir {
  i64 x = 0, y = 0;
};
i128 cross(Dir a, Dir b) { return i128{a.x} * b.y - i128{a.y} * b.x; }
i128 dot(Dir a, Dir b) { return i128{a.x} * b.x + i128{a.y} * b.y; }
Dir dir(Point from, Point to) { return {i64{to.x} - from.x, i64{to.y} - from.y}; }
Dir neg(Dir d) { return {-d.x, -d.y}; }
bool same_direction(Dir a, Dir b) { return cross(a, b) == 0 && dot(a, b) > 0; }
// 0 for angles in [0, pi), 1 for [pi, 2pi), from +x.
int half(Dir d) { return (d.y < 0 || (d.y == 0 && d.x < 0)) ? 1 : 0; }
bool angle_less(Dir a, Dir b) {
  if (half(a) != half(b)) return half(a) < half(b);
  return cross(a, b) > 0;
}
// Where d lies counter-clockwise from `from`: 0 on it, 1 within (0, pi), 2 at pi, 3 beyond.
int angle_class(Dir from, Dir d) {
  const i128 c = cross(from, d);
  if (c > 0) return 1;
  if (c < 0) return 3;
  return dot(from, d) > 0 ? 0 : 2;
}
// d lies strictly inside the counter-clockwise sector from `from` to `to` (from != to).
bool strictly_inside(Dir from, Dir d, Dir to) {
  const int cd = angle_class(from, d), ct = angle_class(from, to);
  if (cd == 0) return false;
  if (cd != ct) return cd < ct;
  if (cd == 2) return false;  // both opposite to `from`: d == to
  return cross(d, to) > 0;
}

struct PointHash {
  std::size_t operator()(Point p) const {
    std::uint64_t h = (std::uint64_t(std::uint32_t(p.x)) << 32) | std::uint32_t(p.y);
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    return static_cast<std::size_t>(h);
  }
};

// The free wedges at one point: boundary directions sorted counter-clockwise; sector i runs
// from dirs[i] to dirs[i + 1] and carries a wedge id (maximal runs of free sectors) or -1.
struct WedgeMap {
  bool full = false;  // no boundary through the point: one wedge (id 0) of every direction
  std::vector<Dir> dirs;
  std::vector<int> id;
  // The wedge containing direction d (a boundary direction belongs to a free sector beside
  // it), -1 when d points into an obstacle, along a flush stretch, or out of the domain.
  int wedge_of(Dir d) const {
    if (full) return 0;
    const std::size_t k = dirs.size();
    if (k == 0) return -1;
    for (std::size_t i = 0; i < k; ++i)
      if (same_direction(dirs[i], d)) return id[i] >= 0 ? id[i] : id[(i + k - 1) % k];
    if (k == 1) return id[0];
    for (std::size_t i = 0; i < k; ++i)
      if (strictly_inside(dirs[i], d, dirs[(i + 1) % k])) return id[i];
    return -1;  // not reached
  }
  bool any() const { return full || std::any_of(id.begin(), id.end(), [](int w) { return w >= 0; }); }
};

// The builder's state (an anonymous type so the helpers below can name it).
struct Core {
  Box domain;
  geom::ObstacleIndex index;
  StaircaseOptions options;

  Core(const Box& d, std::span<const Polygon> obstacles, StaircaseOptions o)
      : domain(d), index(obstacles), options(o) {}

  bool in_domain(Point p) const {
    return domain.lo.x <= p.x && p.x <= domain.hi.x && domain.lo.y <= p.y && p.y <= domain.hi.y;
  }

  // Same construction as the oracle (tests/oracle/l1_oracle.cpp), on the indexed edges: every
  // indexed edge has its obstacle on the left (outer rings CCW, holes CW).
  WedgeMap wedges(Point p) const { return wedges_from(p, index.edges_in_box({p, p})); }
  // The same from `edges`: every edge whose closed segment contains p (and possibly others).
  WedgeMap wedges_from(Point p, std::span<const std::uint32_t> edges) const {
    WedgeMap w;
    if (!in_domain(p)) return w;  // no wedge at all
    struct Ray {
      Dir d;
      bool ccw_in = false, cw_in = false;
    };
    std::vector<Ray> rays;
    for (const std::uint32_t id : edges) {
      const Segment& e = index.edge(id);
      if (!geom::on_segment(p, e.a, e.b)) continue;
      const bool at_a = p == e.a, at_b = p == e.b;
      if (!at_b) rays.push_back({dir(e.a, e.b), true, false});
      if (!at_a) rays.push_back({dir(e.b, e.a), false, true});
    }
    if (p.x == domain.lo.x || p.x == domain.hi.x) {
      rays.push_back({{0, 1}});
      rays.push_back({{0, -1}});
    }
    if (p.y == domain.lo.y || p.y == domain.hi.y) {
      rays.push_back({{1, 0}});
      rays.push_back({{-1, 0}});
    }
    if (rays.empty()) {
      w.full = true;
      return w;
    }
    std::sort(rays.begin(), rays.end(), [](const Ray& a, const Ray& b) { return angle_less(a.d, b.d); });
    std::vector<Ray> merged;
    for (const Ray& r : rays) {
      if (!merged.empty() && same_direction(merged.back().d, r.d)) {
        merged.back().ccw_in |= r.ccw_in;
        merged.back().cw_in |= r.cw_in;
      } else {
        merged.push_back(r);
      }
    }
    const std::size_t k = merged.size();
    std::vector<bool> free(k);
    for (std::size_t i = 0; i < k; ++i) {
      const Dir a = merged[i].d, b = merged[(i + 1) % k].d;
      const bool in = merged[i].ccw_in || merged[(i + 1) % k].cw_in;
      Dir rep;
      const i128 c = cross(a, b);
      if (k == 1) rep = neg(a);
      else if (c > 0) rep = {a.x + b.x, a.y + b.y};
      else if (c < 0) rep = {-(a.x + b.x), -(a.y + b.y)};
      else rep = {-a.y, a.x};
      const bool outside = (p.x == domain.lo.x && rep.x < 0) || (p.x == domain.hi.x && rep.x > 0) ||
                           (p.y == domain.lo.y && rep.y < 0) || (p.y == domain.hi.y && rep.y > 0);
      free[i] = !in && !outside;
    }
    w.dirs.reserve(k);
    for (const Ray& r : merged) w.dirs.push_back(r.d);
    w.id.assign(k, -1);
    const auto first_blocked = std::find(free.begin(), free.end(), false);
    if (first_blocked == free.end()) {
      w.id.assign(k, 0);
      return w;
    }
    const std::size_t j = static_cast<std::size_t>(first_blocked - free.begin());
    int next_id = -1;
    for (std::size_t step = 1; step <= k; ++step) {
      const std::size_t i = (j + step) % k;
      if (!free[i]) continue;
      if (!free[(i + k - 1) % k]) ++next_id;
      w.id[i] = next_id;
    }
    return w;
  }

  // p lies on no edge: is it inside an obstacle? Crossing number along the ray to the east (all
  // of it: an obstacle may reach beyond the domain, as a frame merged with the obstacles on the
  // domain's sides does, NetSpace::obstacles(..., framed)).
  bool inside_obstacle(Point p) const {
    bool inside = false;
    for (const std::uint32_t id : index.edges_in_box({p, {std::numeric_limits<geom::Coord>::max(), p.y}})) {
      const Segment& e = index.edge(id);
      if ((e.a.y > p.y) != (e.b.y > p.y)) {
        const Point lo = e.a.y < e.b.y ? e.a : e.b, hi = e.a.y < e.b.y ? e.b : e.a;
        if (geom::orientation(lo, hi, p) > 0) inside = !inside;
      }
    }
    return inside;
  }

  bool point_free(Point p) const {
    if (!in_domain(p)) return false;
    const WedgeMap w = wedges(p);
    if (w.full) return !inside_obstacle(p);
    return w.any();
  }
};

// Caches of one call (not shared between calls: the builder stays thread-safe).
class Workspace {
 public:
  Workspace(const Core& im, StaircaseStats& st) : im_(im), st_(st) {}

  const WedgeMap& at(Point p) {
    auto it = wedges_.find(p);
    if (it == wedges_.end()) it = wedges_.emplace(p, im_.wedges(p)).first;
    return it->second;
  }

  // The segment pq (p != q, both in the domain) crosses no edge properly, and at every
  // obstacle vertex strictly inside it the directions to p and q lie in one free wedge.
  // Together with "leaves p inside a free wedge" (checked by the caller) this makes the whole
  // segment free: between consecutive vertices it lies on one edge or off all of them.
  bool segment_ok(Point p, Point q) {
    ++st_.pieces;
    const Box box{{std::min(p.x, q.x), std::min(p.y, q.y)}, {std::max(p.x, q.x), std::max(p.y, q.y)}};
    cuts_.clear();
    for (const std::uint32_t id : im_.index.edges_in_box(box)) {
      const Segment& e = im_.index.edge(id);
      const SegmentIntersection r = geom::intersect(Segment{p, q}, e);
      if (r == SegmentIntersection::Proper) return false;
      if (r == SegmentIntersection::None) continue;
      for (const Point v : {e.a, e.b})
        if (v != p && v != q && geom::on_segment(v, p, q)) cuts_.push_back(v);
    }
    for (const Point v : cuts_) {
      const WedgeMap& w = at(v);
      const int wa = w.wedge_of(dir(v, p));
      if (wa < 0 || wa != w.wedge_of(dir(v, q))) return false;
    }
    return true;
  }

  // The wedges at p computed from `edges` (which must hold every edge through p).
  template <class EdgeIds>
  const WedgeMap& at_with(Point p, const EdgeIds& edges) {
    auto it = wedges_.find(p);
    if (it == wedges_.end()) it = wedges_.emplace(p, im_.wedges_from(p, edges)).first;
    return it->second;
  }

  const Core& im() const { return im_; }
  StaircaseStats& stats() { return st_; }

 private:
  const Core& im_;
  StaircaseStats& st_;
  std::unordered_map<Point, WedgeMap, PointHash> wedges_;
  std::vector<Point> cuts_;
};

// One link's solutions: per (first, last) direction the bends, the wedge used at a (first
// direction) and at b (arrival), and the path (a ... b).
struct LinkSolution {
  std::array<Dir, 2> d{};
  int nd = 2;  // 1: straight link (d[0] == d[1])
  std::array<std::array<int, 2>, 2> bends{{{-1, -1}, {-1, -1}}};
  std::array<int, 2> start_wedge{-1, -1};
  std::array<int, 2> end_wedge{-1, -1};  // per last direction
  std::array<std::array<std::vector<Point>, 2>, 2> path;
  bool complete = true;
};

// Local frame of a link: p = a + u d[0] + v d[1], det(d[0], d[1]) = +-1, so (u, v) are
// integers exactly for lattice points; b = (lim[0], lim[1]) with both limits > 0.
// Frame coordinates are scaled by q = |det|: a point p = a + u d[0] + v d[1] has coordinates
// (q u, q v), integers for every lattice point. q is 1 for every cone of the rectilinear and
// octilinear sets (the link searches assume it) and 2 for a cone between the two diagonals of a
// lattice direction set (geom/directions.h), whose staircases from a reach only the frame points
// with both coordinates even.
struct Frame {
  Point a, b;
  std::array<Dir, 2> d;
  i64 det = 1;
  i64 q = 1;  // |det|
  std::array<i64, 2> lim{};
  i64 u_of(Point p) const { return static_cast<i64>(cross(dir(a, p), d[1]) * (det > 0 ? 1 : -1)); }
  i64 v_of(Point p) const { return static_cast<i64>(cross(d[0], dir(a, p)) * (det > 0 ? 1 : -1)); }
  i64 coord(Point p, int k) const { return k == 0 ? u_of(p) : v_of(p); }
  // The point at frame coordinates (u, v), both multiples of q.
  Point at(i64 u, i64 v) const {
    return {static_cast<geom::Coord>(a.x + (u * d[0].x + v * d[1].x) / q),
            static_cast<geom::Coord>(a.y + (u * d[0].y + v * d[1].y) / q)};
  }
  // The point at position pos on the family-k line `line` (k = 0: v = line; k = 1: u = line).
  Point on_line(int k, i64 line, i64 pos) const { return k == 0 ? at(pos, line) : at(line, pos); }
};

struct Key {
  i64 u = 0, v = 0;
  int k = 0;
  friend bool operator==(const Key&, const Key&) = default;
};
struct KeyHash {
  std::size_t operator()(const Key& key) const {
    std::uint64_t h = static_cast<std::uint64_t>(key.u) * 0x9e3779b97f4a7c15ULL;
    h ^= static_cast<std::uint64_t>(key.v) + 0x632be59bd9b4e019ULL + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(key.k) * 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 31;
    return static_cast<std::size_t>(h);
  }
};

// Searches of one link. A line of family k is {a + t d[k] + line * d[1-k]}, 0 <= t <= lim[k];
// its data (every edge meeting it, exact crossing parameters) is computed once, when a search
// first moves along it, and serves the candidates, the piece tests and the wedges.
class LinkSolver {
 public:
  LinkSolver(Workspace& ws, const Frame& f) : ws_(ws), f_(f) {
    // Base candidates: the coordinate of every vertex of an edge meeting R(a, b), plus
    // lim - 1 and lim, per family (see the header for why this is complete).
    const Box r{{std::min(f.a.x, f.b.x), std::min(f.a.y, f.b.y)},
                {std::max(f.a.x, f.b.x), std::max(f.a.y, f.b.y)}};
    for (int k = 0; k < 2; ++k) base_[k] = {f.lim[k] - 1, f.lim[k]};
    for (const std::uint32_t id : ws.im().index.edges_in_box(r)) {
      const Segment& e = ws.im().index.edge(id);
      for (const Point p : {e.a, e.b})
        for (int k = 0; k < 2; ++k) {
          const i64 c = f.coord(p, k);
          if (c >= 0 && c <= f.lim[k]) base_[k].push_back(c);
        }
    }
    for (int k = 0; k < 2; ++k) {
      std::sort(base_[k].begin(), base_[k].end());
      base_[k].erase(std::unique(base_[k].begin(), base_[k].end()), base_[k].end());
    }
  }

  // Fewest bends of a free staircase leaving a along d[first] and arriving at b along
  // d[last]; -1 when there is none with at most `bound` bends (`complete` is cleared when
  // the work budget ran out first).
  //
  // A* over "items": an item is a line entered at a point with g bends, moving along the line
  // as far as it is free ("reach": up to the first edge crossing it, or a vertex it may not
  // pass), so continuing straight is implicit. Lower bound h (consistent): 0 on b's line
  // moving along `last`, 2 on another line of that family, 1 on the other family. Turning
  // off a line at a candidate t in (entry, reach] makes a new item with g + 1; the turns of
  // an item are released lazily by their f = g + 1 + h(new): a line of the other family
  // turns onto b's line (f = g + 1) at once, onto other lines of the last family (f = g + 3)
  // only when that level is reached; a line of the last family turns (f = g + 2) when its own
  // level (g + 2, or g + 0 on b's line) comes. An item entering a line inside the free stretch
  // of an earlier item with no more bends is dropped (everything it reaches, that one does).
  int search(int first, int last, int bound, std::size_t budget, bool& complete,
             std::vector<Point>& path) {
    struct Item {
      Key key;
      int g = 0;
      int parent = -1;
      i64 reach = -1;
      bool dropped = false;
    };
    std::vector<Item> items;
    std::unordered_map<Key, int, KeyHash> best;  // key -> item with the fewest bends
    struct Seen {
      i64 pos, reach;
      int g;
    };
    std::array<std::unordered_map<i64, std::vector<Seen>>, 2> seen;
    // Tasks by 3 * level + h(item), LIFO inside; phase 0 = on arrival, 1 = deferred turns.
    std::vector<std::vector<std::pair<int, int>>> buckets;
    std::size_t cur = 0;
    std::size_t work = 0;
    auto is_final = [&](const Key& s) { return last == 0 ? s.v == f_.lim[1] : s.u == f_.lim[0]; };
    auto h_of = [&](const Key& s) { return s.k != last ? 1 : (is_final(s) ? 0 : 2); };
    auto schedule = [&](int item, int level, int phase) {
      if (level > bound) return;
      const std::size_t b = static_cast<std::size_t>(3 * level + h_of(items[static_cast<std::size_t>(item)].key));
      if (buckets.size() <= b) buckets.resize(b + 1);
      buckets[b].push_back({item, phase});
      cur = std::min(cur, b);
    };
    auto add = [&](const Key& s, int g, int parent) {
      if (s.k != last && (last == 0 ? s.u >= f_.lim[0] : s.v >= f_.lim[1])) return;  // dead end
      if (g + h_of(s) > bound) return;
      auto it = best.find(s);
      if (it != best.end() && items[static_cast<std::size_t>(it->second)].g <= g) return;
      const int id = static_cast<int>(items.size());
      items.push_back({s, g, parent});
      best[s] = id;
      schedule(id, g + h_of(s), 0);
    };
    // Turns of item `id` onto the other family at candidates t in [from, to].
    auto turns = [&](int id, i64 from, i64 to) {
      const Item it = items[static_cast<std::size_t>(id)];
      const int k = it.key.k;
      const i64 line_id = k == 0 ? it.key.v : it.key.u;
      const Line& ln = line(k, line_id);
      for (i64 t = next(k, ln, from - 1); t <= to; t = t < f_.lim[k] ? next(k, ln, t) : to + 1) {
        ++work;
        const Point q = f_.on_line(k, line_id, t);
        const WedgeMap& w = wedge_at(ln, q, t);
        const int win = w.wedge_of(neg(f_.d[k]));
        if (win < 0 || w.wedge_of(f_.d[1 - k]) != win) continue;
        add(k == 0 ? Key{t, it.key.v, 1} : Key{it.key.u, t, 0}, it.g + 1, id);
      }
    };
    const Key start{0, 0, first};
    add(start, 0, -1);
    while (true) {
      while (cur < buckets.size() && buckets[cur].empty()) ++cur;
      if (cur >= buckets.size()) return -1;
      const auto [id, phase] = buckets[cur].back();
      buckets[cur].pop_back();
      if (++work > budget) {
        complete = false;
        ++ws_.stats().budget_hits;
        return -1;
      }
      Item& item = items[static_cast<std::size_t>(id)];
      if (item.dropped || best[item.key] != id) continue;
      const Key key = item.key;
      const int g = item.g, k = key.k;
      const i64 pos = k == 0 ? key.u : key.v, line_id = k == 0 ? key.v : key.u;
      if (phase == 0) {
        ++ws_.stats().states;
        auto& here = seen[k][line_id];
        if (std::any_of(here.begin(), here.end(), [&](const Seen& o) {
              return o.g <= g && o.pos <= pos && pos < o.reach;
            })) {
          item.dropped = true;
          continue;
        }
        item.reach = reach(k, line_id, pos);
        here.push_back({pos, item.reach, g});
        if (item.reach <= pos) continue;
        if (k == last) {
          if (is_final(key)) {
            if (item.reach == f_.lim[k]) {  // b: g is the smallest level still open
              std::vector<Point> rev = {f_.b};
              for (int c = id; c >= 0; c = items[static_cast<std::size_t>(c)].parent)
                rev.push_back(f_.at(items[static_cast<std::size_t>(c)].key.u,
                                    items[static_cast<std::size_t>(c)].key.v));
              path.assign(rev.rbegin(), rev.rend());
              return g;
            }
            schedule(id, g + 2, 1);
          } else {
            turns(id, pos + 1, std::min(item.reach, f_.lim[k] - 1));
          }
        } else {
          if (item.reach == f_.lim[k]) turns(id, f_.lim[k], f_.lim[k]);
          schedule(id, g + 3, 1);
        }
      } else {  // the deferred turns (f = g + 2 off b's line, f = g + 3 onto a last-family line)
        turns(id, pos + 1, std::min(item.reach, f_.lim[k] - 1));
      }
    }
  }

  // Any free staircase (first, last), depth first: from each line the farthest turn is tried
  // first. Returns its bends, or -1 (none, or the budget ran out).
  int greedy(int first, int last, std::size_t budget, std::vector<Point>& path) {
    struct Item {
      Key key;
      int g, parent;
    };
    std::vector<Item> items;
    std::unordered_map<Key, bool, KeyHash> visited;
    std::vector<int> stack;
    auto push = [&](const Key& s, int g, int parent) {
      if (s.k != last && (last == 0 ? s.u >= f_.lim[0] : s.v >= f_.lim[1])) return;
      if (!visited.emplace(s, true).second) return;
      items.push_back({s, g, parent});
      stack.push_back(static_cast<int>(items.size()) - 1);
    };
    push(Key{0, 0, first}, 0, -1);
    std::size_t work = 0;
    std::vector<i64> ts;
    while (!stack.empty()) {
      const int id = stack.back();
      stack.pop_back();
      const Item it = items[static_cast<std::size_t>(id)];
      const int k = it.key.k;
      const i64 pos = k == 0 ? it.key.u : it.key.v, line_id = k == 0 ? it.key.v : it.key.u;
      if (++work > budget) return -1;
      const i64 r = reach(k, line_id, pos);
      if (r <= pos) continue;
      const bool final_line = last == 0 ? it.key.v == f_.lim[1] : it.key.u == f_.lim[0];
      if (k == last && final_line && r == f_.lim[k]) {
        std::vector<Point> rev = {f_.b};
        for (int c = id; c >= 0; c = items[static_cast<std::size_t>(c)].parent)
          rev.push_back(f_.at(items[static_cast<std::size_t>(c)].key.u, items[static_cast<std::size_t>(c)].key.v));
        path.assign(rev.rbegin(), rev.rend());
        return it.g;
      }
      const Line& ln = line(k, line_id);
      const i64 to = k == last ? std::min(r, f_.lim[k] - 1) : r;
      ts.clear();
      for (i64 t = next(k, ln, pos); t <= to; t = t < f_.lim[k] ? next(k, ln, t) : to + 1) {
        ++work;
        const WedgeMap& w = wedge_at(ln, f_.on_line(k, line_id, t), t);
        const int win = w.wedge_of(neg(f_.d[k]));
        if (win >= 0 && w.wedge_of(f_.d[1 - k]) == win) ts.push_back(t);
      }
      for (const i64 t : ts)  // increasing: the farthest turn ends on top of the stack
        push(k == 0 ? Key{t, it.key.v, 1} : Key{it.key.u, t, 0}, it.g + 1, id);
    }
    return -1;
  }

 private:
  struct Crossing {  // a non-parallel edge meets the line at t = num / den (den > 0)
    i128 num, den;
    std::uint32_t edge;
  };
  struct Parallel {  // an edge lying on the line over [lo, hi]
    i64 lo, hi;
    std::uint32_t edge;
  };
  struct Line {
    std::vector<Crossing> cross;   // sorted by t, 0 <= t <= lim
    std::vector<i64> floors;       // sorted floor(t): the crossing candidates
    std::vector<Parallel> parallel;
    std::vector<Crossing> events;  // crossings and parallel-edge ends, sorted by t
  };

  static bool less_t(const Crossing& a, const Crossing& b) { return a.num * b.den < b.num * a.den; }

  const Line& line(int k, i64 id) {
    auto& cache = lines_[k];
    auto found = cache.find(id);
    if (found != cache.end()) return found->second;
    ++ws_.stats().lines;
    Line out;
    const Dir dk = f_.d[k];
    const Point p0 = f_.on_line(k, id, 0), p1 = f_.on_line(k, id, f_.lim[k]);
    for (const std::uint32_t eid : edges_along(p0, p1)) {
      const Segment& e = ws_.im().index.edge(eid);
      const Dir w = dir(e.a, e.b);
      const Dir r = dir(p0, e.a);
      i128 den = cross(dk, w);
      if (den == 0) {
        if (cross(r, dk) != 0) continue;  // parallel, off the line
        // On the line: t of a point is its coordinate along d[k] (an integer).
        const i64 ta = f_.coord(e.a, k), tb = f_.coord(e.b, k);
        out.parallel.push_back({std::min(ta, tb), std::max(ta, tb), eid});
        continue;
      }
      // p0 + t dk = e.a + s w:  t = cross(r, w) / cross(dk, w),  s = cross(r, dk) / cross(dk, w).
      i128 tn = cross(r, w), sn = cross(r, dk);
      if (den < 0) den = -den, tn = -tn, sn = -sn;
      if (sn < 0 || sn > den) continue;             // the lines meet outside the edge
      if (tn < 0 || tn > i128{f_.lim[k]} * den) continue;  // outside the link's region
      out.cross.push_back({tn, den, eid});
      out.floors.push_back(static_cast<i64>(floor_div(tn, den)));
    }
    std::sort(out.cross.begin(), out.cross.end(), less_t);
    out.events = out.cross;
    for (const Parallel& pe : out.parallel) {
      out.events.push_back({pe.lo, 1, pe.edge});
      out.events.push_back({pe.hi, 1, pe.edge});
    }
    std::sort(out.events.begin(), out.events.end(), less_t);
    std::sort(out.floors.begin(), out.floors.end());
    out.floors.erase(std::unique(out.floors.begin(), out.floors.end()), out.floors.end());
    return cache.emplace(id, std::move(out)).first->second;
  }

  // Ids of the edges meeting the closed segment p0 p1 (a superset is fine: line() filters).
  // Axis-parallel lines query their own thin box; diagonal ones a chain of small boxes.
  std::vector<std::uint32_t> edges_along(Point p0, Point p1) {
    const geom::ObstacleIndex& index = ws_.im().index;
    if (p0.x == p1.x || p0.y == p1.y)
      return index.edges_in_box({{std::min(p0.x, p1.x), std::min(p0.y, p1.y)},
                                 {std::max(p0.x, p1.x), std::max(p0.y, p1.y)}});
    const i64 len = std::abs(i64{p1.x} - p0.x);  // |dx| == |dy| on a diagonal
    const i64 chunk = std::max<i64>(16, len / 32);
    const i64 sx = p1.x > p0.x ? 1 : -1, sy = p1.y > p0.y ? 1 : -1;
    std::vector<std::uint32_t> ids;
    for (i64 t = 0; t < len; t += chunk) {
      const i64 t1 = std::min(len, t + chunk);
      const Point q0{static_cast<geom::Coord>(p0.x + sx * t), static_cast<geom::Coord>(p0.y + sy * t)};
      const Point q1{static_cast<geom::Coord>(p0.x + sx * t1), static_cast<geom::Coord>(p0.y + sy * t1)};
      const auto part = index.edges_in_box({{std::min(q0.x, q1.x), std::min(q0.y, q1.y)},
                                            {std::max(q0.x, q1.x), std::max(q0.y, q1.y)}});
      ids.insert(ids.end(), part.begin(), part.end());
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
  }

  // The next candidate after pos on a family-k line (pos < lim[k]; lim[k] is a candidate).
  i64 next(int k, const Line& ln, i64 pos) const {
    const std::vector<i64>& b = base_[k];
    i64 best = *std::upper_bound(b.begin(), b.end(), pos);
    const auto it = std::upper_bound(ln.floors.begin(), ln.floors.end(), pos);
    if (it != ln.floors.end()) best = std::min(best, *it);
    return best;
  }

  // The farthest position a move along the family-k line `id` entered at pos can reach:
  // stops at floor(t) before an edge crossing the line at a non-integer t, at an integer
  // point on an edge where the line may not pass (transversal edge, vertex, pinch), or at
  // lim[k]. Arrival at the returned position is allowed (its piece is free).
  i64 reach(int k, i64 id, i64 pos) {
    const Line& ln = line(k, id);
    const i64 lim = f_.lim[k];
    auto it = std::upper_bound(ln.events.begin(), ln.events.end(), pos,
                               [](i64 c, const Crossing& x) { return i128{c} * x.den < x.num; });
    while (it != ln.events.end()) {
      if (it->num > i128{lim} * it->den) break;
      if (it->num % it->den != 0) return static_cast<i64>(floor_div(it->num, it->den));
      const i64 t = static_cast<i64>(it->num / it->den);
      const WedgeMap& w = wedge_at(ln, f_.on_line(k, id, t), t);
      const int win = w.wedge_of(neg(f_.d[k]));
      if (win < 0) return pos;  // cannot happen (the piece before t is free); stay safe
      if (t == lim || w.wedge_of(f_.d[k]) != win) return t;
      while (it != ln.events.end() && it->num == i128{t} * it->den) ++it;
    }
    return lim;
  }

  // The wedges at q (position pos on line ln): every edge through q crosses the line at q or
  // lies on it.
  const WedgeMap& wedge_at(const Line& ln, Point q, i64 pos) {
    scratch_.clear();
    const auto lo = std::lower_bound(ln.cross.begin(), ln.cross.end(), pos,
                                     [](const Crossing& x, i64 c) { return x.num < i128{c} * x.den; });
    for (auto it = lo; it != ln.cross.end() && it->num == i128{pos} * it->den; ++it)
      scratch_.push_back(it->edge);
    for (const Parallel& pe : ln.parallel)
      if (pe.lo <= pos && pos <= pe.hi) scratch_.push_back(pe.edge);
    // Most candidates lie on no edge and off the domain sides: one full wedge, no cache entry.
    const Box& dom = ws_.im().domain;
    if (scratch_.empty() && dom.lo.x < q.x && q.x < dom.hi.x && dom.lo.y < q.y && q.y < dom.hi.y)
      return full_;
    return ws_.at_with(q, scratch_);
  }

  Workspace& ws_;
  const Frame& f_;
  std::array<std::vector<i64>, 2> base_;
  std::array<std::unordered_map<i64, Line>, 2> lines_;
  std::vector<std::uint32_t> scratch_;
  const WedgeMap full_ = [] {
    WedgeMap w;
    w.full = true;
    return w;
  }();
};

i64 sgn(i64 v) { return (v > 0) - (v < 0); }

// The unit steps of a link a -> b: the two directions of its cone (d[0] == d[1] when the link
// itself lies along one of the style's directions: `straight`).
struct LinkDirs {
  std::array<Dir, 2> d;
  bool straight = false;
};
LinkDirs link_dirs(Point a, Point b, const geom::LatticeDirections& set) {
  const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
  const i64 sx = sgn(dx), sy = sgn(dy), ax = std::abs(dx), ay = std::abs(dy);
  LinkDirs r;
  r.straight = set.along(dx, dy);
  if (r.straight) r.d = {Dir{sx, sy}, Dir{sx, sy}};
  else if (set.is_rectilinear()) r.d = {Dir{sx, 0}, Dir{0, sy}};
  else if (set.is_octilinear() && ax > ay) r.d = {Dir{sx, 0}, Dir{sx, sy}};
  else if (set.is_octilinear()) r.d = {Dir{0, sy}, Dir{sx, sy}};
  else {
    const auto [d1, d2] = set.cone_steps(set.cone(dx, dy));
    r.d = {Dir{d1.x, d1.y}, Dir{d2.x, d2.y}};
  }
  return r;
}
LinkDirs link_dirs(Point a, Point b, StaircaseStyle style) { return link_dirs(a, b, lattice_set(style)); }

// The frame of a non-straight link, with the wedges its two directions leave a and reach b in.
Frame link_frame(Workspace& ws, Point a, Point b, const std::array<Dir, 2>& d, LinkSolution& s) {
  Frame fr;
  fr.a = a;
  fr.b = b;
  fr.d = d;
  fr.det = static_cast<i64>(cross(d[0], d[1]));  // +-1, or +-2 between two diagonals
  fr.q = fr.det < 0 ? -fr.det : fr.det;
  fr.lim = {fr.u_of(b), fr.v_of(b)};
  for (int k = 0; k < 2; ++k) {
    s.start_wedge[k] = ws.at(a).wedge_of(d[k]);
    s.end_wedge[k] = ws.at(b).wedge_of(neg(d[k]));
  }
  return fr;
}

// Solve one link (a != b). Joints: which ends of the link are joints with a neighbouring
// link (bit 0: at a, bit 1: at b); ignored when exact (every (first, last) pair to its
// optimum, for link_table). Otherwise a pair is only searched below the best pair found so
// far that uses the same wedges at the joints plus the number of joints: swapping that best
// pair in changes each joint by at most one bend, so no DP over the links needs more.
// A link along one of the set's directions: the segment itself, when it is free.
LinkSolution solve_straight(Workspace& ws, Point a, Point b, const geom::LatticeDirections& set) {
  LinkSolution s;
  const auto [d, straight] = link_dirs(a, b, set);
  s.d = d;
  s.nd = 1;
  const int w0 = ws.at(a).wedge_of(d[0]);
  if (w0 < 0 || !ws.segment_ok(a, b)) return s;
  const int w1 = ws.at(b).wedge_of(neg(d[0]));
  if (w1 < 0) return s;
  s.start_wedge = {w0, w0};
  s.end_wedge = {w1, w1};
  for (int f = 0; f < 2; ++f)
    for (int l = 0; l < 2; ++l) {
      s.bends[f][l] = 0;
      s.path[f][l] = {a, b};
    }
  return s;
}

LinkSolution solve_link(Workspace& ws, Point a, Point b, StaircaseStyle style, bool exact,
                        int joints) {
  const auto [d, straight] = link_dirs(a, b, style);
  if (straight)
    return solve_straight(ws, a, b, lattice_set(style));
  LinkSolution s;
  s.d = d;
  ++ws.stats().links;
  const Frame fr = link_frame(ws, a, b, d, s);
  LinkSolver solver(ws, fr);
  constexpr int kNoBound = std::numeric_limits<int>::max() / 4;
  // The turning pairs first (an L is their best case), so the others get a bound early.
  for (const auto& [f, l] : {std::pair{0, 1}, std::pair{1, 0}, std::pair{0, 0}, std::pair{1, 1}}) {
    if (s.start_wedge[f] < 0 || s.end_wedge[l] < 0) continue;
    int bound = kNoBound;
    const int slack = (joints & 1) + ((joints >> 1) & 1) - 1;
    if (!exact)
      for (int f2 = 0; f2 < 2; ++f2)
        for (int l2 = 0; l2 < 2; ++l2)
          if (s.bends[f2][l2] >= 0 &&
              (!(joints & 1) || s.start_wedge[f2] == s.start_wedge[f]) &&
              (!(joints & 2) || s.end_wedge[l2] == s.end_wedge[l]))
            bound = std::min(bound, s.bends[f2][l2] + slack);
    if (bound < 0) continue;
    bool complete = true;
    s.bends[f][l] = solver.search(f, l, bound, ws.im().options.max_work_per_search, complete,
                                  s.path[f][l]);
    s.complete = s.complete && complete;
  }
  // The budget ran out before any pair was found: a depth-first search that goes as far as
  // it can before turning finds some free staircase (not necessarily with the fewest bends).
  if (!s.complete && std::none_of(&s.bends[0][0], &s.bends[0][0] + 4, [](int b) { return b >= 0; })) {
    for (int f = 0; f < 2; ++f)
      for (int l = 0; l < 2; ++l) {
        if (s.start_wedge[f] < 0 || s.end_wedge[l] < 0) continue;
        s.bends[f][l] = solver.greedy(f, l, 4 * ws.im().options.max_work_per_search, s.path[f][l]);
        if (s.bends[f][l] >= 0) ++ws.stats().greedy_links;
      }
  }
  return s;
}

// ---- One piece of a taut path, in its class (c-oriented output, router/tighten.h) ----
//
// alpha runs from a to b with every segment strictly inside the cone of the frame's two
// directions, so in frame coordinates (u along d[0], v along d[1]; a = (0,0), b = (U,V)) it is
// a strictly increasing function v = alpha(u). A staircase from a to b of the same length is
// monotone in u and v inside the box [0,U] x [0,V], and it is in alpha's class exactly when
// every obstacle point of the box lies on the same side of it as of alpha (the region between
// two monotone paths with equal ends holds no obstacle point iff they are homotopic; an obstacle
// cannot cross either path). For an obstacle point s above alpha that means: the staircase does
// not enter the open quadrant {u < s.u, v > s.v}; below: not {u > s.u, v < s.v}. So the
// staircases of the class are the monotone lattice paths of F = box minus those open quadrants,
// where "above" and "below" are taken over the obstacle edges clipped to the box (an interior
// point's quadrant lies in the quadrant of the edge point its down-right (up-left) ray meets
// first; that point is in the box and on the same side). Every monotone path in F is free: an
// obstacle's interior lies in such quadrants, a point on an edge is touched only from its free
// side, and a pinch between two obstacles of one side is passed only on their common free side.
//
// F is a staircase polygon: a run along u never enters an "above" quadrant and a run along v
// never a "below" one, so each run goes as far as the other side allows, and the greedy that
// alternates maximal runs (capped at b, floored to the lattice) reaches b with the fewest links
// for its first direction (each of its turns dominates the same turn of any other staircase).
// Its last direction is then fixed by parity; the other last direction would cost a link more,
// which a joint saves at most once, so the DP over pieces loses nothing without it.
struct ClipWall {
  std::array<i64, 2> p{}, q{};   // frame coordinates of the edge's ends ([0] = u, [1] = v)
  i128 n0 = 0, d0 = 1, n1 = 1, d1 = 1;  // the part inside the box: t in [n0/d0, n1/d1]
  int side = 0;                  // +1: above alpha, -1: below
};

// a/b < c/d for d's > 0
bool frac_less(i128 a, i128 b, i128 c, i128 d) { return a * d < c * b; }
i128 floor_frac(i128 c, i128 d) { return c >= 0 ? c / d : -((-c + d - 1) / d); }  // d > 0

// The walls are gathered lazily: a run along u from pos can only be stopped by points below
// alpha with v > pos.v, and those with u below the answer B lie in [pos.u, B] x [pos.v, alpha(B)]
// (below alpha, and alpha increases); a run along v symmetrically. So each run queries the
// R-tree for boxes of growing length until the answer falls inside, and each edge is clipped and
// classified once per piece. The work follows the staircase, not the piece's whole box.
class PieceSolver {
 public:
  PieceSolver(Workspace& ws, const Frame& fr, std::span<const Point> alpha)
      : index_(ws.im().index), fr_(fr), first_slab_(std::max<i64>(1, ws.im().options.first_slab)),
        domain_(ws.im().domain) {
    for (const Point p : alpha) {
      a_[0].push_back(fr.u_of(p));
      a_[1].push_back(fr.v_of(p));
    }
    lim_ = fr.lim;
    // The domain's sides as walls, the outside on their left (clockwise round the domain): the
    // box [0, U] x [0, V] of a cone across an axis (c:0,45's between NE and W, say) reaches
    // out of the box of a and b, and the staircase must not leave the domain there.
    const Box& D = ws.im().domain;
    const std::array<Point, 4> c{Point{D.lo.x, D.lo.y}, Point{D.lo.x, D.hi.y}, Point{D.hi.x, D.hi.y},
                                 Point{D.hi.x, D.lo.y}};
    for (std::size_t i = 0; i < 4; ++i) {
      ClipWall w;
      w.p = {fr.u_of(c[i]), fr.v_of(c[i])};
      w.q = {fr.u_of(c[(i + 1) % 4]), fr.v_of(c[(i + 1) % 4])};
      if (clip(w)) {
        w.side = side_of(w);
        domain_walls_.push_back(w);
      }
    }
  }

  // The greedy staircase leaving a along d[first]: its points (frame), or empty when it gets stuck.
  // More than `cap` points: StaircaseTooFine (StaircaseOptions::snap_scale).
  std::vector<std::array<i64, 2>> greedy(int first, std::size_t cap) {
    std::vector<std::array<i64, 2>> pts{{0, 0}};
    std::array<i64, 2> pos{0, 0};
    for (int k = first;; k = 1 - k) {
      const i64 r = reach(k, pos);
      if (r <= pos[k]) return {};  // stuck (or a first run of length 0)
      pos[k] = r;
      pts.push_back(pos);
      if (pts.size() > cap)
        throw StaircaseTooFine("a staircase of more than " + std::to_string(cap) + " points, too fine to snap back");
      if (pos[0] == lim_[0] && pos[1] == lim_[1]) return pts;
    }
  }

 private:
  // Clip the frame segment to the box; false when nothing of it is inside.
  bool clip(ClipWall& w) const {
    for (int k = 0; k < 2; ++k) {
      const i64 dq = w.q[k] - w.p[k];
      if (dq == 0) {
        if (w.p[k] < 0 || w.p[k] > lim_[k]) return false;
        continue;
      }
      // t where the coordinate is 0 and lim: (0 - p)/dq, (lim - p)/dq
      i128 na = -i128{w.p[k]}, nb = i128{lim_[k]} - w.p[k], d = dq;
      if (d < 0) {
        na = -na;
        nb = -nb;
        d = -d;
      }
      if (na > nb) std::swap(na, nb);
      if (frac_less(w.n0, w.d0, na, d)) {
        w.n0 = na;
        w.d0 = d;
      }
      if (frac_less(nb, d, w.n1, w.d1)) {
        w.n1 = nb;
        w.d1 = d;
      }
    }
    return !frac_less(w.n1, w.d1, w.n0, w.d0);
  }

  // Coordinate k at parameter n/d, as a fraction over d.
  static i128 at(const ClipWall& w, int k, i128 n, i128 d) { return i128{w.p[k]} * d + n * (w.q[k] - w.p[k]); }

  // Sign of (point - alpha) in v at the point's u: the point is (X/D, Y/D), 0 <= X/D <= U.
  int side_of_point(i128 X, i128 Y, i128 D) const {
    // the segment of alpha over u: the last vertex with au <= u (not the very last one)
    std::size_t lo = 0, hi = a_[0].size() - 1;  // invariant: au[lo] <= u, answer in [lo, hi)
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if (i128{a_[0][mid]} * D <= X) lo = mid;
      else hi = mid;
    }
    const i128 du = a_[0][lo + 1] - a_[0][lo], dv = a_[1][lo + 1] - a_[1][lo];
    const i128 s = (Y - i128{a_[1][lo]} * D) * du - (X - i128{a_[0][lo]} * D) * dv;
    return (s > 0) - (s < 0);
  }

  // +1: the wall lies above alpha (larger v), -1: below. Walls do not cross alpha (it is free),
  // so the sign of any point off alpha decides; alpha's vertices are the only places where the
  // difference bends, so the clipped ends and the vertices between them are enough. A wall
  // along alpha: the side of its obstacle (on the left of the edge; the frame keeps orientation
  // when det = +1).
  int side_of(const ClipWall& w) const {
    for (const auto& [n, d] : {std::pair{w.n0, w.d0}, std::pair{w.n1, w.d1}}) {
      const int s = side_of_point(at(w, 0, n, d), at(w, 1, n, d), d);
      if (s != 0) return s;
    }
    const i64 du = w.q[0] - w.p[0], dv = w.q[1] - w.p[1];
    if (du != 0) {
      // alpha's vertices strictly between the clipped ends' u
      const i128 ua = at(w, 0, w.n0, w.d0), ub = at(w, 0, w.n1, w.d1);
      const bool a_first = frac_less(ua, w.d0, ub, w.d1);
      const i128 lo_n = a_first ? ua : ub, lo_d = a_first ? w.d0 : w.d1;
      const i128 hi_n = a_first ? ub : ua, hi_d = a_first ? w.d1 : w.d0;
      // au is strictly increasing: the vertices with lo < au < hi form one run
      auto j = static_cast<std::size_t>(
          std::partition_point(a_[0].begin(), a_[0].end(), [&](i64 u) { return i128{u} * lo_d <= lo_n; }) - a_[0].begin());
      for (; j < a_[0].size() && i128{a_[0][j]} * hi_d < hi_n; ++j) {
        // the wall's v at u = au[j] against av[j]
        const i128 s = ((i128{w.p[1]} - a_[1][j]) * du + (i128{a_[0][j]} - w.p[0]) * dv) * (du > 0 ? 1 : -1);
        if (s != 0) return s > 0 ? 1 : -1;
      }
    }
    const bool left_in_frame = fr_.det > 0;
    const bool with_alpha = du > 0 || (du == 0 && dv > 0);
    return left_in_frame == with_alpha ? 1 : -1;
  }

  // The wall of edge `id`, clipped to the box and classified (nullptr: it misses the box).
  const ClipWall* wall(std::uint32_t id) {
    const auto [it, fresh] = cache_.try_emplace(id, -1);
    if (fresh) {
      const Segment& e = index_.edge(id);
      ClipWall w;
      w.p = {fr_.u_of(e.a), fr_.v_of(e.a)};
      w.q = {fr_.u_of(e.b), fr_.v_of(e.b)};
      if (clip(w)) {
        w.side = side_of(w);
        it->second = static_cast<int>(walls_.size());
        walls_.push_back(w);
      }
    }
    return it->second < 0 ? nullptr : &walls_[static_cast<std::size_t>(it->second)];
  }

  // Alpha's coordinate 1-k where its coordinate k is c (0 <= c <= lim[k]), rounded up.
  i64 alpha_ceil(int k, i64 c) const {
    const std::vector<i64>& ak = a_[k];
    const std::vector<i64>& ao = a_[1 - k];
    if (c >= ak.back()) return ao.back();
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(ak.begin(), ak.end(), c) - ak.begin()) - 1;
    const i128 num = i128{ao[i]} * (ak[i + 1] - ak[i]) + i128{c - ak[i]} * (ao[i + 1] - ao[i]);
    return static_cast<i64>(-floor_frac(-num, ak[i + 1] - ak[i]));
  }

  // How far a run along d[k] from pos may go because of wall w (floored; lim when w does not
  // stop it): the least coordinate k over w's points whose other coordinate exceeds pos's.
  i64 wall_reach(const ClipWall& w, int k, const std::array<i64, 2>& pos) const {
    const int o = 1 - k;
    const i128 c0 = at(w, o, w.n0, w.d0), c1 = at(w, o, w.n1, w.d1);
    const bool in0 = c0 > i128{pos[o]} * w.d0, in1 = c1 > i128{pos[o]} * w.d1;
    if (!in0 && !in1) return lim_[k];
    // the closure of {t in [t0, t1] : coordinate o > pos[o]}: its ends
    i128 sn0 = w.n0, sd0 = w.d0, sn1 = w.n1, sd1 = w.d1;
    if (!in0 || !in1) {
      const i128 dq = w.q[o] - w.p[o];  // nonzero: the ends differ in o
      i128 n = i128{pos[o]} - w.p[o], d = dq;
      if (d < 0) {
        n = -n;
        d = -d;
      }
      if (!in0) {
        sn0 = n;
        sd0 = d;
      } else {
        sn1 = n;
        sd1 = d;
      }
    }
    i128 f = std::min(floor_frac(at(w, k, sn0, sd0), sd0), floor_frac(at(w, k, sn1, sd1), sd1));
    f = floor_frac(f, fr_.q) * fr_.q;  // down to the staircase's lattice (q = 1 but between diagonals)
    return f < lim_[k] ? static_cast<i64>(f) : lim_[k];
  }

  // The farthest coordinate k a run along d[k] from pos reaches (floored, capped at lim): a run
  // along u is stopped by walls below alpha that rise above pos.v, one along v by walls above
  // alpha that reach right of pos.u.
  i64 reach(int k, const std::array<i64, 2>& pos) {
    const int o = 1 - k, want = k == 0 ? -1 : 1;
    i64 best = lim_[k];
    for (const ClipWall& w : domain_walls_)
      if (w.side == want) best = std::min(best, wall_reach(w, k, pos));
    // slabs [from, B] of doubling width: a wall point that stops the run before B lies in one of
    // the slabs so far, each only as tall as alpha allows at its right side
    i64 from = pos[k];
    for (i64 step = first_slab_;; step = std::min(step, lim_[k]) * 2) {
      const i64 B = pos[k] + std::min(step, lim_[k] - pos[k]);
      std::array<i64, 2> lo{}, hi{};
      lo[k] = from;
      hi[k] = B;
      from = B;
      lo[o] = pos[o];
      hi[o] = std::max(pos[o], std::min(lim_[o], alpha_ceil(k, B)));
      index_.edges_in_box(frame_box(lo, hi), ids_);
      for (const std::uint32_t id : ids_)
        if (const ClipWall* w = wall(id); w && w->side == want) best = std::min(best, wall_reach(*w, k, pos));
      if (best <= B || B == lim_[k]) return best;
    }
  }

  // The box of the frame parallelogram [lo, hi], its corners rounded outward (they are not
  // lattice points when q = 2).
  Box frame_box(const std::array<i64, 2>& lo, const std::array<i64, 2>& hi) const {
    i64 x0 = std::numeric_limits<i64>::max(), y0 = x0, x1 = std::numeric_limits<i64>::min(), y1 = x1;
    for (const i64 u : {lo[0], hi[0]})
      for (const i64 v : {lo[1], hi[1]}) {
        const i64 X = i64{fr_.a.x} * fr_.q + u * fr_.d[0].x + v * fr_.d[1].x;
        const i64 Y = i64{fr_.a.y} * fr_.q + u * fr_.d[0].y + v * fr_.d[1].y;
        x0 = std::min(x0, static_cast<i64>(floor_div(X, fr_.q)));
        y0 = std::min(y0, static_cast<i64>(floor_div(Y, fr_.q)));
        x1 = std::max(x1, static_cast<i64>(geom::ceil_div(X, fr_.q)));
        y1 = std::max(y1, static_cast<i64>(geom::ceil_div(Y, fr_.q)));
      }
    // Within the domain (every indexed edge is): a wide cone's parallelogram reaches out of it,
    // by up to the piece's size, past the int32 coordinate range near the coordinate limit. An
    // empty part becomes a point on the domain's side (edges it returns are real walls: harmless).
    auto into = [](i64& a, i64& b, i64 lo, i64 hi) {
      a = std::clamp(a, lo, hi);
      b = std::clamp(b, lo, hi);
      if (b < a) b = a;
    };
    into(x0, x1, domain_.lo.x, domain_.hi.x);
    into(y0, y1, domain_.lo.y, domain_.hi.y);
    return Box{{static_cast<geom::Coord>(x0), static_cast<geom::Coord>(y0)},
               {static_cast<geom::Coord>(x1), static_cast<geom::Coord>(y1)}};
  }

  const geom::ObstacleIndex& index_;
  const Frame& fr_;
  i64 first_slab_;
  Box domain_;
  std::array<std::vector<i64>, 2> a_;  // alpha's vertices: u and v (both strictly increasing)
  std::array<i64, 2> lim_{};
  std::vector<ClipWall> walls_;
  std::vector<ClipWall> domain_walls_;
  std::unordered_map<std::uint32_t, int> cache_;  // edge id -> index in walls_, -1: misses the box
  std::vector<std::uint32_t> ids_;
};

// One piece (alpha from a to b, every segment strictly inside one cone of the style) in its class.
LinkSolution solve_piece(Workspace& ws, std::span<const Point> alpha, const geom::LatticeDirections& set) {
  const Point a = alpha.front(), b = alpha.back();
  LinkSolution s;
  s.d = link_dirs(a, b, set).d;  // not straight: the caller checked
  ++ws.stats().links;
  const Frame fr = link_frame(ws, a, b, s.d, s);
  if (fr.lim[0] % fr.q != 0 || fr.lim[1] % fr.q != 0) return s;  // b is off a's lattice: no staircase
  PieceSolver solver(ws, fr, alpha);
  std::size_t cap = std::numeric_limits<std::size_t>::max();
  if (const i64 k = ws.im().options.snap_scale; k > 1) {  // StaircaseTooFine
    i128 l1 = 0;
    for (std::size_t i = 1; i < alpha.size(); ++i)
      l1 += std::abs(i64{alpha[i].x} - alpha[i - 1].x) + std::abs(i64{alpha[i].y} - alpha[i - 1].y);
    cap = static_cast<std::size_t>(16 + 4 * static_cast<i128>(alpha.size()) + 4 * l1 / k);
  }
  for (int f = 0; f < 2; ++f) {
    if (s.start_wedge[f] < 0) continue;
    const std::vector<std::array<i64, 2>> g = solver.greedy(f, cap);
    if (g.empty()) continue;
    const int links = static_cast<int>(g.size()) - 1;
    const int l = (links % 2 == 1) ? f : 1 - f;
    if (s.end_wedge[l] < 0) continue;
    s.bends[f][l] = links - 1;
    for (const auto& p : g) s.path[f][l].push_back(fr.at(p[0], p[1]));
  }
  return s;
}

// Drop repeated points and points where the direction does not change.
std::vector<Point> simplify(const std::vector<Point>& in) {
  std::vector<Point> out;
  for (const Point p : in) {
    if (!out.empty() && out.back() == p) continue;
    if (out.size() >= 2 && same_direction(dir(out[out.size() - 2], out.back()), dir(out.back(), p)))
      out.back() = p;
    else
      out.push_back(p);
  }
  return out;
}

// The links' staircases joined: a DP over the links, state = (first, last) option of the current
// link; joints cost one bend when the arrival and departure directions differ and need one wedge
// at the joint. Then a defensive re-check of the whole polyline.
std::optional<std::vector<Point>> join_links(Workspace& ws, const std::vector<LinkSolution>& sol) {
  const std::size_t m = sol.size();
  constexpr int kInf = std::numeric_limits<int>::max() / 4;
  struct Cell {
    int cost = kInf;
    int prev = -1;  // option index f * 2 + l of the previous link
  };
  std::vector<std::array<Cell, 4>> dp(m);
  for (std::size_t i = 0; i < m; ++i) {
    const LinkSolution& s = sol[i];
    for (int f = 0; f < 2; ++f)
      for (int l = 0; l < 2; ++l) {
        if (s.bends[f][l] < 0) continue;
        Cell& c = dp[i][f * 2 + l];
        if (i == 0) {
          c.cost = s.bends[f][l];
          continue;
        }
        const LinkSolution& p = sol[i - 1];
        for (int pf = 0; pf < 2; ++pf)
          for (int pl = 0; pl < 2; ++pl) {
            const Cell& pc = dp[i - 1][pf * 2 + pl];
            if (pc.cost >= kInf) continue;
            if (p.end_wedge[pl] != s.start_wedge[f]) continue;  // both >= 0 here
            const int joint = same_direction(p.d[pl], s.d[f]) ? 0 : 1;
            const int total = pc.cost + joint + s.bends[f][l];
            if (total < c.cost) c = {total, pf * 2 + pl};
          }
      }
  }
  int best = -1;
  for (int o = 0; o < 4; ++o)
    if (dp[m - 1][o].cost < kInf && (best < 0 || dp[m - 1][o].cost < dp[m - 1][best].cost)) best = o;
  if (best < 0) return std::nullopt;
  std::vector<int> choice(m);
  for (std::size_t i = m; i-- > 0;) {
    choice[i] = best;
    best = dp[i][best].prev;
  }
  std::vector<Point> out;
  for (std::size_t i = 0; i < m; ++i) {
    const std::vector<Point>& p = sol[i].path[choice[i] / 2][choice[i] % 2];
    out.insert(out.end(), p.begin(), p.end());
  }
  out = simplify(out);

  // Defensive re-check of the final polyline with the general segment test (long segments,
  // joints merged): a failure here would be a bug, reported as "no path" rather than a wrong one.
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    const Dir fwd = dir(out[i], out[i + 1]);
    const WedgeMap& w = ws.at(out[i]);
    const int wf = w.wedge_of(fwd);
    if (wf < 0) return std::nullopt;
    if (i > 0 && w.wedge_of(dir(out[i], out[i - 1])) != wf) return std::nullopt;
    if (!ws.segment_ok(out[i], out[i + 1])) return std::nullopt;
    if (ws.at(out[i + 1]).wedge_of(neg(fwd)) < 0) return std::nullopt;
  }
  return out;
}

}  // namespace

const geom::LatticeDirections& lattice_set(StaircaseStyle style) {
  static const geom::LatticeDirections rect = geom::LatticeDirections::rectilinear();
  static const geom::LatticeDirections oct = geom::LatticeDirections::octilinear();
  return style == StaircaseStyle::Rectilinear ? rect : oct;
}

struct StaircaseBuilder::Impl : Core {
  using Core::Core;
};

StaircaseBuilder::StaircaseBuilder(const Box& domain, std::span<const Polygon> obstacles,
                                   StaircaseOptions options)
    : impl_(std::make_unique<Impl>(domain, obstacles, options)) {}
StaircaseBuilder::~StaircaseBuilder() = default;
StaircaseBuilder::StaircaseBuilder(StaircaseBuilder&&) noexcept = default;
StaircaseBuilder& StaircaseBuilder::operator=(StaircaseBuilder&&) noexcept = default;

bool StaircaseBuilder::is_free(Point p) const { return impl_->point_free(p); }

bool StaircaseBuilder::turn_ok(Point a, Point v, Point b) const {
  if (a == v || b == v || !impl_->in_domain(v)) return false;
  const WedgeMap w = impl_->wedges(v);
  const int wa = w.wedge_of(dir(v, a));
  return wa >= 0 && wa == w.wedge_of(dir(v, b));
}

LinkTable StaircaseBuilder::link_table(Point a, Point b, StaircaseStyle style) const {
  LinkTable t;
  StaircaseStats st;
  Workspace ws(*impl_, st);
  if (a == b || !impl_->point_free(a)) return t;
  const LinkSolution s = solve_link(ws, a, b, style, true, 3);
  for (int k = 0; k < 2; ++k)
    t.dirs[k] = {static_cast<geom::Coord>(s.d[k].x), static_cast<geom::Coord>(s.d[k].y)};
  t.bends = s.bends;
  t.complete = s.complete;
  return t;
}

std::optional<std::vector<Point>> StaircaseBuilder::rectilinear(std::span<const Point> path,
                                                                StaircaseStats* stats) const {
  return staircase(path, StaircaseStyle::Rectilinear, stats);
}
std::optional<std::vector<Point>> StaircaseBuilder::octilinear(std::span<const Point> path,
                                                               StaircaseStats* stats) const {
  return staircase(path, StaircaseStyle::Octilinear, stats);
}

std::optional<std::vector<Point>> StaircaseBuilder::staircase(std::span<const Point> path,
                                                              StaircaseStyle style,
                                                              StaircaseStats* stats) const {
  StaircaseStats local;
  StaircaseStats& st = stats ? *stats : local;
  std::vector<Point> pts;
  for (const Point p : path)
    if (pts.empty() || pts.back() != p) pts.push_back(p);
  if (pts.empty()) return std::nullopt;
  for (const Point p : pts)
    if (!impl_->in_domain(p)) return std::nullopt;
  if (!impl_->point_free(pts.front())) return std::nullopt;
  if (pts.size() == 1) return pts;
  Workspace ws(*impl_, st);
  const std::size_t m = pts.size() - 1;
  std::vector<LinkSolution> sol;
  sol.reserve(m);
  for (std::size_t i = 0; i < m; ++i) {
    const int joints = (i > 0 ? 1 : 0) | (i + 1 < m ? 2 : 0);
    sol.push_back(solve_link(ws, pts[i], pts[i + 1], style, false, joints));
  }

  return join_links(ws, sol);
}

std::optional<std::vector<Point>> StaircaseBuilder::staircase_in_class(std::span<const Point> taut,
                                                                       std::span<const std::size_t> cuts,
                                                                       StaircaseStyle style,
                                                                       StaircaseStats* stats) const {
  return staircase_in_class(taut, cuts, lattice_set(style), stats);
}

std::optional<std::vector<Point>> StaircaseBuilder::staircase_in_class(std::span<const Point> taut,
                                                                       std::span<const std::size_t> cuts,
                                                                       const geom::LatticeDirections& set,
                                                                       StaircaseStats* stats) const {
  StaircaseStats local;
  StaircaseStats& st = stats ? *stats : local;
  if (taut.empty() || cuts.size() < 2 || cuts.front() != 0 || cuts.back() != taut.size() - 1)
    return std::nullopt;
  for (const Point p : taut)
    if (!impl_->in_domain(p)) return std::nullopt;
  if (!impl_->point_free(taut.front())) return std::nullopt;
  Workspace ws(*impl_, st);
  std::vector<LinkSolution> sol;
  sol.reserve(cuts.size() - 1);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const std::size_t i0 = cuts[k], i1 = cuts[k + 1];
    if (i1 <= i0) return std::nullopt;
    const Point a = taut[i0], b = taut[i1];
    if (link_dirs(a, b, set).straight) {
      if (i1 != i0 + 1) return std::nullopt;  // a piece along a basis direction is one segment
      sol.push_back(solve_straight(ws, a, b, set));
    } else {
      sol.push_back(solve_piece(ws, taut.subspan(i0, i1 - i0 + 1), set));
    }
  }
  return join_links(ws, sol);
}

}  // namespace taut::router
