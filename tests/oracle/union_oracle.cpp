#include "oracle/union_oracle.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace taut::oracle {

using geom::i128;
using geom::i64;
using geom::Location;
using geom::Ring;
using geom::Segment;
using geom::SegmentIntersection;

namespace {

bool in_box(Point p, const Box& b) {
  return b.lo.x <= p.x && p.x <= b.hi.x && b.lo.y <= p.y && p.y <= b.hi.y;
}

std::string str(Point p) {
  return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
}

// Squared distance from p to segment ab is <= r2 (exact: cross^2 <= r2 * |ab|^2 in i128).
bool seg_within(Point p, Point a, Point b, i64 r2) {
  auto d2 = [](Point u, Point v) {
    const i64 dx = i64{u.x} - v.x, dy = i64{u.y} - v.y;
    return i128{dx} * dx + i128{dy} * dy;
  };
  if (d2(p, a) <= r2 || d2(p, b) <= r2) return true;
  const i64 t = geom::dot(a, b, a, p), len2 = geom::dot(a, b, a, b);
  if (t <= 0 || t >= len2) return false;
  const i128 c = geom::orient(a, b, p);
  return c * c <= i128{r2} * len2;
}

i128 cross(Point d1, Point d2) { return i128{d1.x} * d2.y - i128{d1.y} * d2.x; }
// Angle from s to d counter-clockwise in (0, 2pi]: class 0 (0,pi), 1 pi, 2 (pi,2pi), 3 2pi.
int angle_class(Point s, Point d) {
  const i128 c = cross(s, d);
  if (c > 0) return 0;
  if (c < 0) return 2;
  return i128{s.x} * d.x + i128{s.y} * d.y < 0 ? 1 : 3;
}
bool angle_less(Point s, Point a, Point b) {
  const int ca = angle_class(s, a), cb = angle_class(s, b);
  if (ca != cb) return ca < cb;
  if (ca == 1 || ca == 3) return false;
  return cross(a, b) > 0;
}
bool strictly_inside(Point d, Point s, Point e) {
  return angle_class(s, d) != 3 && angle_less(s, d, e);
}

}  // namespace

bool in_inputs(Point p, std::span<const Polygon> inputs, const Box& domain) {
  if (!in_box(p, domain)) return false;
  for (const Polygon& q : inputs)
    if (geom::locate(p, q) != Location::Outside) return true;
  return false;
}

bool in_obstacles(Point p, std::span<const Polygon> obstacles) {
  return obstacle_at(p, obstacles) >= 0;
}

int obstacle_at(Point p, std::span<const Polygon> obstacles) {
  for (std::size_t i = 0; i < obstacles.size(); ++i)
    if (geom::locate(p, obstacles[i]) != Location::Outside) return static_cast<int>(i);
  return -1;
}

bool within(Point p, const Polygon& polygon, i64 r2) {
  if (geom::locate(p, polygon) != Location::Outside) return true;
  auto ring_within = [&](const Ring& r) {
    for (std::size_t i = 0; i < r.size(); ++i)
      if (seg_within(p, r[i], r[(i + 1) % r.size()], r2)) return true;
    return false;
  };
  if (ring_within(polygon.outer)) return true;
  for (const Ring& h : polygon.holes)
    if (ring_within(h)) return true;
  return false;
}

Polygon scaled(const Polygon& polygon, geom::Coord f) {
  Polygon out = polygon;
  auto sc = [&](Ring& r) {
    for (Point& p : r) p = {p.x * f, p.y * f};
  };
  sc(out.outer);
  for (Ring& h : out.holes) sc(h);
  return out;
}

i128 twice_area(std::span<const Polygon> obstacles) {
  i128 a = 0;
  for (const Polygon& p : obstacles) {
    a += geom::twice_area(p.outer);
    for (const Ring& h : p.holes) a += geom::twice_area(h);
  }
  return a;
}

std::vector<std::string> check_obstacles(std::span<const Polygon> obstacles, const Box& domain) {
  std::vector<std::string> errors;
  auto err = [&](const std::string& s) {
    if (errors.size() < 20) errors.push_back(s);
  };
  struct Edge {
    Point a, b;
    int obstacle, ring, index, size;
  };
  std::vector<Edge> edges;
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    const Polygon& poly = obstacles[o];
    for (int r = -1; r < static_cast<int>(poly.holes.size()); ++r) {
      const Ring& ring = r < 0 ? poly.outer : poly.holes[r];
      const std::string name = "obstacle " + std::to_string(o) + " ring " + std::to_string(r);
      if (ring.size() < 3) {
        err(name + ": fewer than 3 vertices");
        continue;
      }
      const i128 a = geom::twice_area(ring);
      if (r < 0 ? a <= 0 : a >= 0) err(name + ": wrong orientation");
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point p = ring[i], q = ring[(i + 1) % ring.size()];
        if (!in_box(p, domain)) err(name + ": vertex outside the domain " + str(p));
        if (p == q) err(name + ": repeated vertex " + str(p));
        edges.push_back({p, q, static_cast<int>(o), r, static_cast<int>(i), static_cast<int>(ring.size())});
      }
      if (r >= 0)
        for (Point p : ring)
          if (geom::locate(p, std::span<const Point>(poly.outer)) == Location::Outside)
            err(name + ": hole vertex outside the shell " + str(p));
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& e, const Edge& f) {
    return std::min(e.a.x, e.b.x) < std::min(f.a.x, f.b.x);
  });
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    const int exmax = std::max(e.a.x, e.b.x);
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge& f = edges[j];
      if (std::min(f.a.x, f.b.x) > exmax) break;
      if (std::max(e.a.y, e.b.y) < std::min(f.a.y, f.b.y) ||
          std::max(f.a.y, f.b.y) < std::min(e.a.y, e.b.y))
        continue;
      const SegmentIntersection r = geom::intersect({e.a, e.b}, {f.a, f.b});
      if (r == SegmentIntersection::None) continue;
      const std::string where = str(e.a) + "-" + str(e.b) + " and " + str(f.a) + "-" + str(f.b);
      if (e.obstacle != f.obstacle) {
        err("distinct obstacles meet: " + where);
        continue;
      }
      if (r == SegmentIntersection::Proper) err("edges cross: " + where);
      if (r == SegmentIntersection::Overlap) err("edges overlap: " + where);
      if (r == SegmentIntersection::Touch) {
        const bool shared = e.a == f.a || e.a == f.b || e.b == f.a || e.b == f.b;
        if (!shared) err("edge touches the middle of another: " + where);
      }
    }
  }
  // Passes of the boundary through one vertex must not cross: both rays of one pass lie on the
  // same side of the two rays of any other pass (equal rays are overlapping edges, found above).
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    const Polygon& poly = obstacles[o];
    std::map<Point, std::vector<std::pair<Point, Point>>> passes;  // vertex -> (out, in reversed)
    for (int r = -1; r < static_cast<int>(poly.holes.size()); ++r) {
      const Ring& ring = r < 0 ? poly.outer : poly.holes[r];
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Point p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
        passes[v].push_back({{q.x - v.x, q.y - v.y}, {p.x - v.x, p.y - v.y}});
      }
    }
    for (const auto& [v, list] : passes) {
      if (list.size() < 2) continue;
      for (std::size_t a = 0; a < list.size(); ++a)
        for (std::size_t b = 0; b < list.size(); ++b)
          if (a != b && strictly_inside(list[b].first, list[a].first, list[a].second) !=
                            strictly_inside(list[b].second, list[a].first, list[a].second))
            err("obstacle " + std::to_string(o) + " crosses itself at vertex " + str(v));
    }
  }
  // No obstacle inside another (their edges do not meet, so one vertex decides).
  for (std::size_t a = 0; a < obstacles.size(); ++a)
    for (std::size_t b = 0; b < obstacles.size(); ++b) {
      if (a == b || obstacles[a].outer.empty()) continue;
      if (geom::locate(obstacles[a].outer[0], obstacles[b]) != Location::Outside)
        err("obstacle " + std::to_string(a) + " lies in obstacle " + std::to_string(b));
    }
  return errors;
}

}  // namespace taut::oracle
