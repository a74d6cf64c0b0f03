#include "router/tighten.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geom/predicates.h"
#include "router/root3_staircase.h"

namespace taut::router {

using geom::FreeTriangle;
using geom::i64;
using geom::orient;
using geom::Point;

namespace {

// The index of p among t's vertices, or -1.
int corner_of(const FreeTriangle& t, const std::vector<Point>& V, Point p) {
  for (int j = 0; j < 3; ++j)
    if (V[static_cast<std::size_t>(t.v[static_cast<std::size_t>(j)])] == p) return j;
  return -1;
}


// Drops repeated points and straight-through vertices.
std::vector<Point> simplified(const std::vector<Point>& in) {
  std::vector<Point> out;
  for (Point v : in) {
    if (!out.empty() && out.back() == v) continue;
    while (out.size() >= 2 && orient(out[out.size() - 2], out.back(), v) == 0 &&
           geom::dot(out[out.size() - 2], out.back(), out.back(), v) > 0)
      out.pop_back();
    out.push_back(v);
  }
  return out;
}
}  // namespace

// The walk through the triangles: the current triangle and the reduced stack of triangles.
struct Tightener::Walker {
  // Told of every change of the reduced stack (the on-line funnel follows it).
  struct Observer {
    virtual void pushed(std::int32_t from, std::int32_t to) = 0;
    virtual void popped(std::int32_t top, std::int32_t below) = 0;
    virtual ~Observer() = default;
  };
  const Tightener& tg;
  const std::vector<FreeTriangle>& tris;
  const std::vector<Point>& V;
  std::vector<std::int32_t> stack;
  std::size_t crossings = 0;
  std::int32_t cur = -1;
  Observer* observer = nullptr;

  explicit Walker(const Tightener& t)
      : tg(t), tris(t.t_->triangles()), V(t.t_->vertices()) {}

  Point vert(std::int32_t t, int j) const {
    return V[static_cast<std::size_t>(tris[static_cast<std::size_t>(t)].v[static_cast<std::size_t>(j % 3)])];
  }
  const FreeTriangle& tri(std::int32_t t) const { return tris[static_cast<std::size_t>(t)]; }

  void step_to(std::int32_t next) {
    ++crossings;
    if (stack.size() >= 2 && stack[stack.size() - 2] == next) {
      if (observer) observer->popped(stack.back(), next);
      stack.pop_back();
    } else {
      if (observer) observer->pushed(stack.back(), next);
      stack.push_back(next);
    }
    cur = next;
  }

  // Whether the closed corner of triangle t at its vertex j holds the direction from that
  // vertex towards b (b != the vertex). The corner's angle is below 180 degrees.
  bool corner_holds(std::int32_t t, int j, Point b) const {
    const Point v = vert(t, j);
    return orient(v, vert(t, j + 1), b) >= 0 && orient(v, b, vert(t, j + 2)) >= 0;
  }

  static bool in_closed(const FreeTriangle& t, const std::vector<Point>& V, Point b) {
    for (int i = 0; i < 3; ++i)
      if (orient(V[static_cast<std::size_t>(t.v[static_cast<std::size_t>(i)])],
                 V[static_cast<std::size_t>(t.v[static_cast<std::size_t>((i + 1) % 3)])], b) < 0)
        return false;
    return true;
  }

  // Turns around vertex p (a vertex of the current triangle) within its fan of free triangles
  // to the triangle whose corner at p holds the direction towards b, crossing the fan edges on
  // the way. False when no triangle of the fan holds it.
  bool pivot(Point p, Point b) {
    std::vector<std::int32_t> way;
    for (int turn = 0; turn < 2; ++turn) {  // counter-clockwise, then clockwise
      way.clear();
      std::int32_t t = cur;
      for (std::size_t guard = 0; guard <= tris.size(); ++guard) {
        const int j = corner_of(tri(t), V, p);
        if (j < 0) throw std::logic_error("tighten: a fan triangle lost its vertex");
        if (corner_holds(t, j, b)) {
          for (std::int32_t s : way) step_to(s);
          return true;
        }
        // counter-clockwise: across the edge from v[j+2] to v[j]; clockwise: from v[j] to v[j+1]
        const std::int32_t n = tri(t).neighbor[static_cast<std::size_t>(turn == 0 ? (j + 2) % 3 : j)];
        if (n < 0) break;
        way.push_back(n);
        t = n;
      }
    }
    return false;
  }

  // Any triangle at vertex p (in any fan) whose corner holds the direction towards b; -1 if none.
  std::int32_t any_corner(Point p, Point b) const {
    const auto it = std::lower_bound(V.begin(), V.end(), p);
    if (it == V.end() || *it != p) return -1;
    const std::size_t vi = static_cast<std::size_t>(it - V.begin());
    for (std::int32_t k = tg.fan_start_[vi]; k < tg.fan_start_[vi + 1]; ++k) {
      const std::int32_t t = tg.fan_[static_cast<std::size_t>(k)];
      const int j = corner_of(tri(t), V, p);
      if (j >= 0 && corner_holds(t, j, b)) return t;
    }
    return -1;
  }

  // Walks every segment of a polyline (repeated points skipped); on failure the segment's index
  // and a point.
  TightenStatus polyline(std::span<const Point> path, std::size_t* segment, Point* where) {
    for (std::size_t i = 1; i < path.size(); ++i) {
      if (path[i] == path[i - 1]) continue;
      Point at{};
      const TightenStatus s = this->segment(path[i - 1], path[i], &at);
      if (s != TightenStatus::Ok) {
        *segment = i - 1;
        *where = at;
        return s;
      }
    }
    return TightenStatus::Ok;
  }

  // Walks the segment from p to b (p in the current triangle). Ok, or why not (with *where).
  TightenStatus segment(Point p, Point b, Point* where) {
    const std::size_t guard_max = 4 * tris.size() + 16;
    for (std::size_t guard = 0; guard < guard_max; ++guard) {
      const FreeTriangle& T = tri(cur);
      if (in_closed(T, V, b)) return TightenStatus::Ok;
      const int jv = corner_of(T, V, p);
      if (jv >= 0 && !corner_holds(cur, jv, b)) {
        if (pivot(p, b)) continue;
        *where = p;
        return any_corner(p, b) >= 0 ? TightenStatus::ThroughPinch : TightenStatus::LeavesFreeSpace;
      }
      int s[3];
      for (int j = 0; j < 3; ++j) s[j] = geom::orientation(p, b, vert(cur, j));
      int ahead = -1;
      for (int j = 0; j < 3; ++j)
        if (s[j] == 0 && vert(cur, j) != p && geom::dot(p, b, p, vert(cur, j)) > 0) ahead = j;
      if (ahead >= 0) {  // the segment runs through a vertex of T (b lies beyond it)
        p = vert(cur, ahead);
        continue;
      }
      int exit = -1;
      for (int i = 0; i < 3; ++i)
        if (s[i] < 0 && s[(i + 1) % 3] > 0) exit = i;
      if (exit < 0) throw std::logic_error("tighten: a segment leaves its triangle through no side");
      const std::int32_t n = T.neighbor[static_cast<std::size_t>(exit)];
      if (n < 0) {
        *where = p;
        return TightenStatus::LeavesFreeSpace;
      }
      step_to(n);
    }
    throw std::logic_error("tighten: the walk along a segment does not end");
  }
};

Tightener::Tightener(const geom::FreeSpaceTriangulation& t) : t_(&t) {
  if (!t.ok()) throw std::invalid_argument("Tightener: the triangulation is not valid");
  geom::VertexFans f = geom::vertex_fans(t);
  fan_start_ = std::move(f.start);
  fan_ = std::move(f.triangles);
}

std::vector<Portal> Tightener::portals_of(const std::vector<std::int32_t>& triangles) const {
  const auto& tris = t_->triangles();
  const auto& V = t_->vertices();
  std::vector<Portal> portals;
  for (std::size_t k = 0; k + 1 < triangles.size(); ++k) {
    const FreeTriangle& a = tris[static_cast<std::size_t>(triangles[k])];
    int edge = -1;
    for (int i = 0; i < 3; ++i)
      if (a.neighbor[static_cast<std::size_t>(i)] == triangles[k + 1]) edge = i;
    if (edge < 0) throw std::logic_error("tighten: consecutive sleeve triangles are not neighbours");
    // seen from triangle k: the edge runs counter-clockwise from its right end to its left end
    portals.push_back(Portal{V[static_cast<std::size_t>(a.v[static_cast<std::size_t>((edge + 1) % 3)])],
                             V[static_cast<std::size_t>(a.v[static_cast<std::size_t>(edge)])]});
  }
  return portals;
}

TightenStatus Tightener::lift(std::span<const Point> path, Sleeve& sleeve, std::size_t* segment,
                              Point* where) const {
  sleeve = Sleeve{};
  std::size_t seg_dummy = 0;
  Point where_dummy{};
  if (!segment) segment = &seg_dummy;
  if (!where) where = &where_dummy;
  *segment = 0;
  if (path.empty()) throw std::invalid_argument("Tightener::lift: an empty path");
  *where = path[0];
  const auto start = t_->locate(path[0]);
  if (!start) return TightenStatus::StartNotFree;
  Walker w(*this);
  w.cur = *start;
  // At a vertex, start in the fan (of possibly several at a pinch) that holds the first segment.
  std::size_t first = 1;
  while (first < path.size() && path[first] == path[0]) ++first;
  if (first < path.size() && corner_of(w.tri(w.cur), w.V, path[0]) >= 0) {
    const std::int32_t t = w.any_corner(path[0], path[first]);
    if (t < 0) {
      *segment = first - 1;
      return TightenStatus::LeavesFreeSpace;
    }
    w.cur = t;
  }
  w.stack.push_back(w.cur);
  if (const TightenStatus s = w.polyline(path, segment, where); s != TightenStatus::Ok) return s;
  sleeve.triangles = std::move(w.stack);
  sleeve.crossings = w.crossings;
  sleeve.portals = portals_of(sleeve.triangles);
  return TightenStatus::Ok;
}

TightenStatus Tightener::band(std::span<const Point> loop, std::vector<std::int32_t>& cycle, std::size_t* segment,
                              Point* where) const {
  cycle.clear();
  std::size_t seg_dummy = 0;
  Point where_dummy{};
  if (!segment) segment = &seg_dummy;
  if (!where) where = &where_dummy;
  *segment = 0;
  if (loop.empty() || loop.front() != loop.back()) throw std::invalid_argument("Tightener::band: the loop is not closed");
  *where = loop[0];
  const Point p = loop[0];
  std::size_t first = 1;
  while (first < loop.size() && loop[first] == p) ++first;
  if (first == loop.size()) return TightenStatus::Ok;  // a single point
  const auto start = t_->locate(p);
  if (!start) return TightenStatus::StartNotFree;
  Walker w(*this);
  w.cur = *start;
  const bool at_vertex = corner_of(w.tri(w.cur), w.V, p) >= 0;
  if (at_vertex) {
    const std::int32_t t = w.any_corner(p, loop[first]);
    if (t < 0) return TightenStatus::LeavesFreeSpace;
    w.cur = t;
  }
  const std::int32_t t0 = w.cur;
  w.stack.push_back(t0);
  if (const TightenStatus s = w.polyline(loop, segment, where); s != TightenStatus::Ok) return s;
  // Close up at p: back into the triangle the loop left p through.
  if (w.cur != t0) {
    if (at_vertex && !w.pivot(p, loop[first])) {
      *segment = loop.size() - 2;
      return w.any_corner(p, loop[first]) >= 0 ? TightenStatus::ThroughPinch : TightenStatus::LeavesFreeSpace;
    }
    if (w.cur != t0) {
      bool adjacent = false;
      for (std::int32_t n : w.tri(w.cur).neighbor) adjacent = adjacent || n == t0;
      if (!adjacent) throw std::logic_error("tighten: a loop does not close up where it started");
      w.step_to(t0);
    }
  }
  // Cyclic reduction (Lemma 5.1): the stack starts and ends with t0.
  const std::vector<std::int32_t>& S = w.stack;
  std::size_t lo = 0, hi = S.size() - 1;
  while (hi - lo >= 2 && S[lo + 1] == S[hi - 1]) {
    ++lo;
    --hi;
  }
  if (hi - lo >= 3) cycle.assign(S.begin() + static_cast<std::ptrdiff_t>(lo), S.begin() + static_cast<std::ptrdiff_t>(hi));
  return TightenStatus::Ok;
}

namespace {

// The same cyclic sequence, up to rotation.
bool same_cycle(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  for (std::size_t r = 0; r < b.size(); ++r) {
    if (b[r] != a[0]) continue;
    bool eq = true;
    for (std::size_t i = 0; i < a.size() && eq; ++i) eq = a[i] == b[(r + i) % b.size()];
    if (eq) return true;
  }
  return false;
}

}  // namespace

Tightener::Loop Tightener::tighten_loop(std::span<const Point> loop) const {
  Loop out;
  std::vector<std::int32_t> cycle;
  out.status = band(loop, cycle, &out.segment, &out.where);
  if (out.status != TightenStatus::Ok) return out;
  if (cycle.empty()) {
    out.contractible = true;
    return out;
  }
  out.band = cycle.size();
  const std::size_t r = cycle.size();
  Sleeve twice;
  for (std::size_t k = 0; k <= 2 * r; ++k) twice.triangles.push_back(cycle[k % r]);
  twice.portals = portals_of(twice.triangles);
  // Candidates: between two visits of one vertex of the twice-around path, from either end of
  // the first portal (a class that winds k times round an obstacle visits its vertices 2k times:
  // every pair is a candidate, the band check keeps those once round the band).
  struct Candidate {
    int path;           // which of the two paths
    std::size_t i, j;   // path[i] == path[j]
    double length;      // only the order of trying: each is certified exactly
  };
  std::vector<std::vector<Point>> paths;
  std::vector<Candidate> candidates;
  for (const Point s : {twice.portals[0].left, twice.portals[0].right}) {
    paths.push_back(funnel(s, s, twice));
    const std::vector<Point>& path = paths.back();
    std::vector<double> prefix(path.size(), 0.0);
    for (std::size_t k = 1; k < path.size(); ++k)
      prefix[k] = prefix[k - 1] + euclidean_length(std::span<const Point>(&path[k - 1], 2));
    // visits of each vertex (a class winding k times round a blockage visits its vertices up
    // to 2k times): every pair is a candidate, the band check keeps those once round the band
    std::vector<std::pair<Point, std::size_t>> visits;
    for (std::size_t k = 0; k < path.size(); ++k) visits.push_back({path[k], k});
    std::sort(visits.begin(), visits.end());
    for (std::size_t x = 0; x < visits.size();) {
      std::size_t y = x;
      while (y < visits.size() && visits[y].first == visits[x].first) ++y;
      for (std::size_t u = x; u < y; ++u)
        for (std::size_t v = u + 1; v < y; ++v) {
          const std::size_t i = visits[u].second, j = visits[v].second;
          if (j >= i + 3)  // a closed loop around something bends at two or more vertices
            candidates.push_back(Candidate{static_cast<int>(paths.size() - 1), i, j, prefix[j] - prefix[i]});
        }
      x = y;
    }
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.length < b.length; });
  for (const Candidate& cand : candidates) {
    const std::vector<Point>& path = paths[static_cast<std::size_t>(cand.path)];
    const std::vector<Point> c(path.begin() + static_cast<std::ptrdiff_t>(cand.i),
                               path.begin() + static_cast<std::ptrdiff_t>(cand.j) + 1);
    std::vector<std::int32_t> cc;
    if (band(c, cc) != TightenStatus::Ok || !same_cycle(cycle, cc)) continue;
    const Tightened t1 = tighten(c);
    if (t1.status != TightenStatus::Ok || t1.points != c) continue;
    std::vector<Point> rot(c.begin() + 1, c.end());
    rot.push_back(c[1]);
    const Tightened t2 = tighten(rot);
    if (t2.status != TightenStatus::Ok || t2.points != rot) continue;
    out.points = c;
    return out;
  }
  throw std::logic_error("tighten: no certified shortest loop among the band's candidates");
}

std::vector<Point> Tightener::funnel(Point p, Point q, const Sleeve& sleeve) const {
  const auto& P = sleeve.portals;
  std::size_t b = 0, e = P.size();
  // A portal through an end adds nothing (the end lies in the triangles on both sides of it).
  while (b < e && geom::on_segment(p, P[b].left, P[b].right)) ++b;
  while (e > b && geom::on_segment(q, P[e - 1].left, P[e - 1].right)) --e;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(e - b);
  std::vector<Point> D(static_cast<std::size_t>(2 * n + 6));
  std::vector<Point> out{p};
  std::ptrdiff_t lo = n + 3, hi = lo, a = lo;
  auto at = [&](std::ptrdiff_t i) -> Point& { return D[static_cast<std::size_t>(i)]; };
  at(a) = p;
  // D[lo..a] is the left chain from its tip to the apex, D[a..hi] the right chain from the
  // apex to its tip; the left chain bends counter-clockwise, the right chain clockwise.
  auto add_right = [&](Point w) {
    while (hi > a && orient(at(hi - 1), at(hi), w) >= 0) --hi;
    if (hi == a) {
      while (a > lo) {
        const i64 o = orient(at(a), at(a - 1), w);
        if (o < 0 || (o == 0 && geom::dot(at(a), at(a - 1), at(a - 1), w) <= 0)) break;
        --a;
        out.push_back(at(a));
      }
      hi = a;
    }
    at(++hi) = w;
  };
  auto add_left = [&](Point w) {
    while (lo < a && orient(at(lo + 1), at(lo), w) <= 0) ++lo;
    if (lo == a) {
      while (a < hi) {
        const i64 o = orient(at(a), at(a + 1), w);
        if (o > 0 || (o == 0 && geom::dot(at(a), at(a + 1), at(a + 1), w) <= 0)) break;
        ++a;
        out.push_back(at(a));
      }
      lo = a;
    }
    at(--lo) = w;
  };
  if (b < e) {
    add_left(P[b].left);
    add_right(P[b].right);
    for (std::size_t k = b + 1; k < e; ++k) {
      if (P[k].left == P[k - 1].left)
        add_right(P[k].right);
      else if (P[k].right == P[k - 1].right)
        add_left(P[k].left);
      else
        throw std::logic_error("tighten: consecutive portals share no end");
    }
  }
  add_right(q);
  for (std::ptrdiff_t i = a + 1; i <= hi; ++i) out.push_back(at(i));
  return simplified(out);
}

bool Tightener::free(Point p, Point q) const {
  Sleeve s;
  const std::array<Point, 2> seg{p, q};
  return lift(seg, s) == TightenStatus::Ok;
}

Tightened Tightener::tighten(std::span<const Point> path) const {
  Tightened r;
  Sleeve s;
  r.status = lift(path, s, &r.segment, &r.where);
  r.crossings = s.crossings;
  if (r.status != TightenStatus::Ok) return r;
  r.sleeve = s.triangles.size();
  r.points = funnel(path.front(), path.back(), s);
  return r;
}

// ---- On-line tightening ----------------------------------------------------------------

struct OnlineTightener::Impl : Tightener::Walker::Observer {
  const Tightener& tg;
  Tightener::Walker w;
  Point start, last;
  TightenStatus st = TightenStatus::Ok;
  bool moved = false;  // a segment has been walked (the start triangle is then fixed)

  // The funnel: D[lo..a] the left chain from its tip to the apex, D[a..hi] the right chain;
  // logical indices, stored at index + off in `D`.
  std::vector<Point> D;
  std::ptrdiff_t off = 0, lo = 0, hi = 0, a = 0;
  std::vector<Point> out;  // the path from the start to the apex
  struct Hist {
    std::ptrdiff_t lo, hi, a;
    std::size_t out_size;
    std::ptrdiff_t slot;
    Point old;
  };
  std::vector<Hist> hist;
  std::vector<Portal> portals;     // the sleeve's portals (a stack)
  std::vector<std::uint8_t> ops;   // funnel Adds per portal (0, 1 or 2)
  std::vector<std::pair<bool, std::pair<std::int32_t, std::int32_t>>> log;  // this extend's steps
  bool logging = false;

  Impl(const Tightener& t, Point s) : tg(t), w(t), start(s), last(s) {
    D.assign(64, Point{});
    off = 32;
    at(0) = s;
    out.push_back(s);
    const auto t0 = tg.t_->locate(s);
    if (!t0) {
      st = TightenStatus::StartNotFree;
      return;
    }
    w.cur = *t0;
    w.stack.push_back(w.cur);
    w.observer = this;
  }

  Point& at(std::ptrdiff_t i) { return D[static_cast<std::size_t>(i + off)]; }
  const Point& at(std::ptrdiff_t i) const { return D[static_cast<std::size_t>(i + off)]; }
  void room() {  // one free slot beyond each end
    if (lo - 1 + off >= 0 && hi + 1 + off < static_cast<std::ptrdiff_t>(D.size())) return;
    const std::size_t n = D.size();
    std::vector<Point> bigger(2 * n);
    const std::ptrdiff_t shift = static_cast<std::ptrdiff_t>(n / 2);
    for (std::size_t i = 0; i < n; ++i) bigger[i + static_cast<std::size_t>(shift)] = D[i];
    D.swap(bigger);
    off += shift;
  }
  void remember(std::ptrdiff_t slot) { hist.push_back(Hist{lo, hi, a, out.size(), slot, at(slot)}); }
  void undo_one() {
    const Hist& h = hist.back();
    at(h.slot) = h.old;
    lo = h.lo;
    hi = h.hi;
    a = h.a;
    out.resize(h.out_size);
    hist.pop_back();
  }

  // Is the edge between D[j-1] and D[j] made redundant by a new right vertex w (walked from the
  // right tip towards the left tip)? The predicate of the off-line funnel's pops.
  bool bad_right(std::ptrdiff_t j, Point v) const {
    if (j > a) return orient(at(j - 1), at(j), v) >= 0;
    const i64 o = orient(at(j), at(j - 1), v);
    return o > 0 || (o == 0 && geom::dot(at(j), at(j - 1), at(j - 1), v) > 0);
  }
  // The same for a new left vertex and the edge between D[j] and D[j+1].
  bool bad_left(std::ptrdiff_t j, Point v) const {
    if (j < a) return orient(at(j + 1), at(j), v) <= 0;
    const i64 o = orient(at(j), at(j + 1), v);
    return o < 0 || (o == 0 && geom::dot(at(j), at(j + 1), at(j + 1), v) > 0);
  }
  void add_right(Point v) {
    room();
    // Split: the last index t (from the right tip down) whose edge is not made redundant; the
    // redundant edges form a run at the right end.
    std::ptrdiff_t l = lo, r = hi;  // answer in [lo, hi]: edges (t, hi] are bad
    while (l < r) {
      const std::ptrdiff_t m = l + (r - l + 1) / 2;
      if (bad_right(m, v)) r = m - 1;
      else l = m;
    }
    const std::ptrdiff_t t = l;
    remember(t + 1);
    if (t < a) {
      for (std::ptrdiff_t j = a - 1; j >= t; --j) out.push_back(at(j));
      a = t;
    }
    hi = t;
    at(++hi) = v;
  }
  void add_left(Point v) {
    room();
    std::ptrdiff_t l = lo, r = hi;  // answer in [lo, hi]: edges [lo, t) are bad
    while (l < r) {
      const std::ptrdiff_t m = l + (r - l) / 2;
      if (bad_left(m, v)) l = m + 1;
      else r = m;
    }
    const std::ptrdiff_t t = l;
    remember(t - 1);
    if (t > a) {
      for (std::ptrdiff_t j = a + 1; j <= t; ++j) out.push_back(at(j));
      a = t;
    }
    lo = t;
    at(--lo) = v;
  }

  Portal portal(std::int32_t from, std::int32_t to) const {
    const FreeTriangle& t = w.tri(from);
    for (int i = 0; i < 3; ++i)
      if (t.neighbor[static_cast<std::size_t>(i)] == to)
        return Portal{w.vert(from, i + 1), w.vert(from, i)};
    throw std::logic_error("tighten: on-line step between triangles that are not neighbours");
  }
  void add_portal(const Portal& pt) {
    std::uint8_t n = 0;
    if (lo == a && a == hi) {  // the funnel is empty: a portal through the start adds nothing
      if (!geom::on_segment(start, pt.left, pt.right)) {
        add_left(pt.left);
        add_right(pt.right);
        n = 2;
      }
    } else if (pt.left == portals.back().left) {
      add_right(pt.right);
      n = 1;
    } else if (pt.right == portals.back().right) {
      add_left(pt.left);
      n = 1;
    } else {
      throw std::logic_error("tighten: consecutive portals share no end");
    }
    portals.push_back(pt);
    ops.push_back(n);
  }
  void remove_portal() {
    for (std::uint8_t k = 0; k < ops.back(); ++k) undo_one();
    ops.pop_back();
    portals.pop_back();
  }
  void pushed(std::int32_t from, std::int32_t to) override {
    add_portal(portal(from, to));
    if (logging) log.push_back({true, {from, to}});
  }
  void popped(std::int32_t top, std::int32_t below) override {
    remove_portal();
    if (logging) log.push_back({false, {below, top}});
  }

  TightenStatus extend(Point q, Point* where) {
    if (st != TightenStatus::Ok) return st;
    if (q == last) return TightenStatus::Ok;
    if (!moved && corner_of(w.tri(w.cur), w.V, start) >= 0) {
      // at a vertex, start in the fan (of possibly several at a pinch) that holds the first segment
      const std::int32_t t = w.any_corner(start, q);
      if (t < 0) {
        if (where) *where = start;
        return TightenStatus::LeavesFreeSpace;
      }
      w.cur = t;
      w.stack.assign(1, t);
    }
    const std::int32_t cur0 = w.cur;
    log.clear();
    logging = true;
    Point at_fail{};
    TightenStatus s = TightenStatus::Ok;
    bool threw = false;
    try {
      s = w.segment(last, q, &at_fail);
    } catch (...) {  // a broken triangulation: undo, then let it through
      threw = true;
      s = TightenStatus::LeavesFreeSpace;
    }
    logging = false;
    if (s != TightenStatus::Ok) {
      // undo this segment's steps, last first (the observer is detached meanwhile)
      w.observer = nullptr;
      for (std::size_t k = log.size(); k-- > 0;) {
        const auto& [push, tri] = log[k];
        if (push) {
          remove_portal();
          w.stack.pop_back();
        } else {
          w.stack.push_back(tri.second);
          add_portal(portal(tri.first, tri.second));
        }
      }
      w.observer = this;
      w.cur = cur0;
      if (threw) throw std::logic_error("tighten: the on-line walk failed (the step was undone)");
      if (where) *where = at_fail;
      return s;
    }
    moved = true;
    last = q;
    return TightenStatus::Ok;
  }
};

OnlineTightener::OnlineTightener(const Tightener& t, Point start) : impl_(std::make_unique<Impl>(t, start)) {}
OnlineTightener::~OnlineTightener() = default;
TightenStatus OnlineTightener::status() const { return impl_->st; }
TightenStatus OnlineTightener::extend(Point q, Point* where) { return impl_->extend(q, where); }
Point OnlineTightener::end() const { return impl_->last; }
std::size_t OnlineTightener::sleeve() const { return impl_->w.stack.size(); }

std::vector<Point> OnlineTightener::path() const {
  Impl& m = *impl_;  // path() changes the funnel and restores it exactly
  const Point q = m.last;
  // portals through the current point add nothing (as in Tightener::funnel): taken off, then put back
  std::vector<Portal> trailing;
  while (!m.portals.empty() && m.ops.back() != 0 && geom::on_segment(q, m.portals.back().left, m.portals.back().right)) {
    trailing.push_back(m.portals.back());
    m.remove_portal();
  }
  m.add_right(q);
  std::vector<Point> out = m.out;
  for (std::ptrdiff_t i = m.a + 1; i <= m.hi; ++i) out.push_back(m.at(i));
  m.undo_one();
  for (std::size_t k = trailing.size(); k-- > 0;) m.add_portal(trailing[k]);
  return simplified(out);
}

COriented c_oriented(const Tightener& tight, const StaircaseBuilder& sb, std::span<const Point> taut,
                     StaircaseStyle style) {
  return c_oriented(tight, sb, taut, lattice_set(style));
}

COriented c_oriented(const Tightener& tight, const StaircaseBuilder& sb, std::span<const Point> taut,
                     const geom::LatticeDirections& set) {
  COriented r;
  if (taut.size() <= 1) {
    r.points.assign(taut.begin(), taut.end());
    return r;
  }
  const std::vector<std::size_t> cut_at = tangent_cuts(taut, set);  // indices of the cuts in taut
  // Each piece is built in its class (StaircaseBuilder::staircase_in_class); tightening the
  // result back to `taut` checks that (a class's shortest path is unique), so a bug there shows
  // as a missing wire, never as a wire in another class.
  std::optional<std::vector<Point>> s = sb.staircase_in_class(taut, cut_at, set);
  if (!s) return r;
  const Tightened back = tight.tighten(*s);
  if (back.status != TightenStatus::Ok || !std::equal(back.points.begin(), back.points.end(), taut.begin(), taut.end()))
    return r;
  r.points = std::move(*s);
  return r;
}

Root3Wire c_oriented(const Tightener& tight, const Root3StaircaseBuilder& sb, std::span<const Point> taut,
                     const geom::Root3Directions& set) {
  Root3Wire w = sb.staircase(taut, set, [&](Point p, Point q) { return tight.free(p, q); });
  if (!w.ok()) return w;
  const Tightened back = tight.tighten(w.points);
  if (back.status != TightenStatus::Ok || !std::equal(back.points.begin(), back.points.end(), taut.begin(), taut.end()))
    w.why = "rounded to integer vertices, its wire in " + set.name() +
            (back.status != TightenStatus::Ok ? " leaves free space" : " changes its class");
  return w;
}

double euclidean_length(std::span<const Point> path) {
  double len = 0;
  for (std::size_t i = 1; i < path.size(); ++i)
    len += std::hypot(static_cast<double>(i64{path[i].x} - path[i - 1].x),
                      static_cast<double>(i64{path[i].y} - path[i - 1].y));
  return len;
}

std::string tighten_status_text(TightenStatus s) {
  switch (s) {
    case TightenStatus::Ok: return "ok";
    case TightenStatus::StartNotFree: return "starts outside free space";
    case TightenStatus::LeavesFreeSpace: return "leaves free space (enters a blockage or leaves the boundary)";
    case TightenStatus::ThroughPinch: return "passes through a point where blockages touch";
  }
  return "?";
}

}  // namespace taut::router
