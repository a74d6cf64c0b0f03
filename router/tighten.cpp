#include "router/tighten.h"

#include <cmath>
#include <stdexcept>

#include "geom/predicates.h"

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

}  // namespace

// The walk through the triangles: the current triangle and the reduced stack of triangles.
struct Tightener::Walker {
  const Tightener& tg;
  const std::vector<FreeTriangle>& tris;
  const std::vector<Point>& V;
  std::vector<std::int32_t> stack;
  std::size_t crossings = 0;
  std::int32_t cur = -1;

  explicit Walker(const Tightener& t)
      : tg(t), tris(t.t_->triangles()), V(t.t_->vertices()) {}

  Point vert(std::int32_t t, int j) const {
    return V[static_cast<std::size_t>(tris[static_cast<std::size_t>(t)].v[static_cast<std::size_t>(j % 3)])];
  }
  const FreeTriangle& tri(std::int32_t t) const { return tris[static_cast<std::size_t>(t)]; }

  void step_to(std::int32_t next) {
    ++crossings;
    if (stack.size() >= 2 && stack[stack.size() - 2] == next)
      stack.pop_back();
    else
      stack.push_back(next);
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
  const auto& tris = t.triangles();
  fan_start_.assign(t.vertices().size() + 1, 0);
  for (const FreeTriangle& tr : tris)
    for (std::int32_t v : tr.v) ++fan_start_[static_cast<std::size_t>(v) + 1];
  for (std::size_t i = 1; i < fan_start_.size(); ++i) fan_start_[i] += fan_start_[i - 1];
  fan_.assign(static_cast<std::size_t>(fan_start_.back()), 0);
  std::vector<std::int32_t> fill(fan_start_.begin(), fan_start_.end() - 1);
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (std::int32_t v : tris[i].v) fan_[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = static_cast<std::int32_t>(i);
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
    if (t < 0) return TightenStatus::LeavesFreeSpace;
    w.cur = t;
  }
  w.stack.push_back(w.cur);
  std::size_t seg = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    if (path[i] == path[i - 1]) continue;
    Point at{};
    const TightenStatus s = w.segment(path[i - 1], path[i], &at);
    if (s != TightenStatus::Ok) {
      *segment = i - 1;
      *where = at;
      return s;
    }
    ++seg;
  }
  sleeve.triangles = std::move(w.stack);
  sleeve.crossings = w.crossings;
  const auto& tris = t_->triangles();
  const auto& V = t_->vertices();
  for (std::size_t k = 0; k + 1 < sleeve.triangles.size(); ++k) {
    const FreeTriangle& a = tris[static_cast<std::size_t>(sleeve.triangles[k])];
    int edge = -1;
    for (int i = 0; i < 3; ++i)
      if (a.neighbor[static_cast<std::size_t>(i)] == sleeve.triangles[k + 1]) edge = i;
    if (edge < 0) throw std::logic_error("tighten: sleeve triangles are not neighbours");
    sleeve.portals.push_back(Portal{V[static_cast<std::size_t>(a.v[static_cast<std::size_t>((edge + 1) % 3)])],
                                    V[static_cast<std::size_t>(a.v[static_cast<std::size_t>(edge)])]});
  }
  return TightenStatus::Ok;
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
  // Drop repeated points and straight-through vertices.
  std::vector<Point> clean;
  for (Point v : out) {
    if (!clean.empty() && clean.back() == v) continue;
    while (clean.size() >= 2 && orient(clean[clean.size() - 2], clean.back(), v) == 0 &&
           geom::dot(clean[clean.size() - 2], clean.back(), clean.back(), v) > 0)
      clean.pop_back();
    clean.push_back(v);
  }
  return clean;
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
