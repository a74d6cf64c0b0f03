#include "router/pin_shapes.h"

#include <stdexcept>
#include <algorithm>

#include "geom/predicates.h"

namespace taut::router {

using geom::ceil_div;
using geom::floor_div;
using geom::i64;
using geom::Point;

namespace {
geom::Box ring_box(const geom::Ring& r) {
  geom::Box b{r[0], r[0]};
  for (const Point v : r) {
    b.lo = {std::min(b.lo.x, v.x), std::min(b.lo.y, v.y)};
    b.hi = {std::max(b.hi.x, v.x), std::max(b.hi.y, v.y)};
  }
  return b;
}

// Where the point (x2 / 2, y2 / 2) lies with respect to a ring: exact in __int128 (the doubled
// coordinates of a midpoint exceed the int64 predicates' range). Crossing number with the
// half-open rule; on an edge is Boundary.
geom::Location locate_half(i64 x2, i64 y2, std::span<const Point> ring) {
  bool in = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    const i64 ax = 2 * i64{a.x}, ay = 2 * i64{a.y}, bx = 2 * i64{b.x}, by = 2 * i64{b.y};
    const geom::i128 o = geom::i128{bx - ax} * (y2 - ay) - geom::i128{by - ay} * (x2 - ax);
    if (o == 0 && std::min(ax, bx) <= x2 && x2 <= std::max(ax, bx) && std::min(ay, by) <= y2 &&
        y2 <= std::max(ay, by))
      return geom::Location::Boundary;
    if ((ay > y2) != (by > y2)) {  // the edge straddles the horizontal line through the point
      const bool crosses_right = by > ay ? o > 0 : o < 0;  // point left of the upward edge
      if (crosses_right) in = !in;
    }
  }
  return in ? geom::Location::Inside : geom::Location::Outside;
}
geom::Location locate_half(i64 x2, i64 y2, const geom::Polygon& poly) {
  const geom::Location outer = locate_half(x2, y2, poly.outer);
  if (outer != geom::Location::Inside) return outer;
  for (const geom::Ring& h : poly.holes) {
    const geom::Location l = locate_half(x2, y2, h);
    if (l == geom::Location::Boundary) return l;
    if (l == geom::Location::Inside) return geom::Location::Outside;
  }
  return geom::Location::Inside;
}

// Do the interiors of polygons p and q meet (a common area, not only touching)? Both with
// outer rings counter-clockwise and holes clockwise (interior on the left of every edge).
// Exact. They do iff two edges cross properly, or two edges overlap collinearly in the same
// direction (the interiors lie on the same side: this alone catches p == q), or a vertex of one
// lies strictly inside the other, or an edge of one, cut at the other's vertices on it, has a
// piece whose midpoint lies strictly inside the other: otherwise no point of either boundary is
// interior to the other, and two connected interiors that meet would then coincide.
bool interiors_meet(const geom::Polygon& p, const geom::Polygon& q) {
  std::vector<geom::Segment> ep, eq;
  for_each_pin_edge(p, [&](Point a, Point b) { ep.push_back({a, b}); });
  for_each_pin_edge(q, [&](Point a, Point b) { eq.push_back({a, b}); });
  for (const geom::Segment& e : ep)
    for (const geom::Segment& f : eq) {
      const geom::SegmentIntersection r = geom::intersect(e, f);
      if (r == geom::SegmentIntersection::Proper) return true;
      if (r == geom::SegmentIntersection::Overlap && geom::dot(e.a, e.b, f.a, f.b) > 0) return true;
    }
  auto vertex_inside = [](const geom::Polygon& a, const geom::Polygon& b) {
    bool hit = false;
    auto test = [&](const geom::Ring& r) {
      for (const Point v : r) hit = hit || geom::locate(v, b) == geom::Location::Inside;
    };
    test(a.outer);
    for (const geom::Ring& h : a.holes) test(h);
    return hit;
  };
  if (vertex_inside(p, q) || vertex_inside(q, p)) return true;
  auto piece_inside = [](const std::vector<geom::Segment>& edges, const geom::Polygon& other) {
    std::vector<Point> cuts;
    for (const geom::Segment& e : edges) {
      cuts = {e.a, e.b};
      for_each_pin_edge(other, [&](Point v, Point) {
        if (geom::on_segment(v, e.a, e.b)) cuts.push_back(v);
      });
      std::sort(cuts.begin(), cuts.end());  // collinear points: (x, y) order is along the edge
      cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
      for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
        if (locate_half(i64{cuts[i].x} + cuts[i + 1].x, i64{cuts[i].y} + cuts[i + 1].y, other) ==
            geom::Location::Inside)
          return true;
    }
    return false;
  };
  return piece_inside(ep, q) || piece_inside(eq, p);
}
}  // namespace

bool is_point_pin(const geom::Polygon& pin) { return pin.outer.size() == 1 && pin.holes.empty(); }

bool in_pin(Point p, const geom::Polygon& pin) {
  return is_point_pin(pin) ? p == pin.outer[0] : geom::locate(p, pin) != geom::Location::Outside;
}

std::optional<Point> shared_point(std::span<const Point> a_cands, const geom::Polygon& a,
                                  std::span<const Point> b_cands, const geom::Polygon& b,
                                  const std::function<bool(Point)>& usable) {
  for (const Point p : a_cands)
    if (in_pin(p, b) && usable(p)) return p;
  for (const Point p : b_cands)
    if (in_pin(p, a) && usable(p)) return p;
  if (is_point_pin(a) || is_point_pin(b)) return std::nullopt;
  // where an edge of a meets an edge of b: p + d t (d a unit step, 0 <= t <= its length), the
  // crossing's parameters over D = cross(d1, d2) in {+-1, +-2}
  std::optional<Point> found;
  auto unit = [](Point p, Point q, Point& d, i64& len) {
    const i64 dx = i64{q.x} - p.x, dy = i64{q.y} - p.y;
    d = {static_cast<geom::Coord>((dx > 0) - (dx < 0)), static_cast<geom::Coord>((dy > 0) - (dy < 0))};
    len = std::max(std::abs(dx), std::abs(dy));
  };
  for_each_pin_edge(a, [&](Point p1, Point q1) {
    if (found) return;
    Point d1;
    i64 l1 = 0;
    unit(p1, q1, d1, l1);
    for_each_pin_edge(b, [&](Point p2, Point q2) {
      if (found) return;
      Point d2;
      i64 l2 = 0;
      unit(p2, q2, d2, l2);
      i64 D = i64{d1.x} * d2.y - i64{d1.y} * d2.x;
      if (D == 0) return;  // parallel: a shared stretch ends at a vertex, tried above
      const i64 wx = i64{p2.x} - p1.x, wy = i64{p2.y} - p1.y;
      i64 n1 = wx * d2.y - wy * d2.x, n2 = wx * d1.y - wy * d1.x;  // t1 = n1 / D, t2 = n2 / D
      if (D < 0) D = -D, n1 = -n1, n2 = -n2;
      if (n1 < 0 || n1 > l1 * D || n2 < 0 || n2 > l2 * D) return;
      const i64 X = i64{p1.x} * D + d1.x * n1, Y = i64{p1.y} * D + d1.y * n1;  // the crossing times D
      for (const i64 x : {floor_div(X, D), ceil_div(X, D)})
        for (const i64 y : {floor_div(Y, D), ceil_div(Y, D)}) {
          const Point p{static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)};
          if (!found && in_pin(p, a) && in_pin(p, b) && usable(p)) found = p;
        }
    });
  });
  return found;
}

bool pin_shape_supported(const geom::Polygon& pin) {
  if (is_point_pin(pin)) return true;
  if (pin.outer.size() < 3) return false;
  for (const geom::Ring& h : pin.holes)
    if (h.size() < 3) return false;
  bool ok = true;
  for_each_pin_edge(pin, [&](Point a, Point b) {
    const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
    if (dx == 0 && dy == 0) ok = false;
    if (dx != 0 && dy != 0 && dx != dy && dx != -dy) ok = false;
  });
  return ok;
}

PinShapes::PinShapes(std::span<const geom::Polygon> obstacles, std::optional<geom::Box> domain, bool octilinear)
    : octilinear_(octilinear), domain_(domain), obstacles_(obstacles.begin(), obstacles.end()) {
  auto add_point = [&](Point v) {
    xs_.push_back(v.x);
    ys_.push_back(v.y);
    if (octilinear_) {
      sums_.push_back(i64{v.x} + v.y);
      diffs_.push_back(i64{v.x} - v.y);
    }
  };
  auto add = [&](const geom::Ring& r) {
    for (const Point v : r) add_point(v);
  };
  for (const geom::Polygon& p : obstacles_) {
    add(p.outer);
    for (const geom::Ring& h : p.holes) add(h);
    boxes_.push_back(ring_box(p.outer));
  }
  if (domain_)
    for (const geom::Coord x : {domain_->lo.x, domain_->hi.x})
      for (const geom::Coord y : {domain_->lo.y, domain_->hi.y}) add_point({x, y});
  auto distinct = [](auto& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  };
  distinct(xs_);
  distinct(ys_);
  distinct(sums_);
  distinct(diffs_);
}

namespace {
geom::Polygon counter_clockwise(const geom::Polygon& pin) {  // interior on the left of every edge
  geom::Polygon p = pin;
  if (geom::twice_area(p.outer) < 0) std::reverse(p.outer.begin(), p.outer.end());
  for (geom::Ring& h : p.holes)
    if (geom::twice_area(h) > 0) std::reverse(h.begin(), h.end());
  return p;
}
}  // namespace

bool shape_meets_obstacle(const geom::Polygon& pin, const geom::Polygon& obstacle) {
  return !is_point_pin(pin) && interiors_meet(counter_clockwise(pin), obstacle);
}

std::optional<std::size_t> PinShapes::meets_obstacle(const geom::Polygon& pin) const {
  if (is_point_pin(pin)) return std::nullopt;
  const geom::Polygon p = counter_clockwise(pin);
  const geom::Box b = ring_box(p.outer);
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const geom::Box& o = boxes_[i];
    if (o.hi.x < b.lo.x || o.lo.x > b.hi.x || o.hi.y < b.lo.y || o.lo.y > b.hi.y) continue;
    if (interiors_meet(p, obstacles_[i])) return i;
  }
  return std::nullopt;
}

void PinShapes::set_lattice(std::int64_t k) {
  if (k < 1) throw std::invalid_argument("the lattice must be at least 1");
  lattice_ = k;
}

std::vector<Point> PinShapes::candidates(const geom::Polygon& pin, const geom::Polygon& other) const {
  std::vector<Point> out(pin.outer.begin(), pin.outer.end());
  for (const geom::Ring& h : pin.holes) out.insert(out.end(), h.begin(), h.end());
  if (is_point_pin(pin)) return out;
  std::vector<Point> others(other.outer.begin(), other.outer.end());
  for (const geom::Ring& h : other.holes) others.insert(others.end(), h.begin(), h.end());
  if (domain_ && !is_point_pin(other))  // where the other pin's edges cross the domain's sides
    for_each_pin_edge(other, [&](Point a, Point b) {
      const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
      for (const i64 x : {i64{domain_->lo.x}, i64{domain_->hi.x}})
        if (dx != 0 && std::min(a.x, b.x) < x && x < std::max(a.x, b.x))
          others.push_back({static_cast<geom::Coord>(x), static_cast<geom::Coord>(a.y + (x - a.x) * dy / dx)});
      for (const i64 y : {i64{domain_->lo.y}, i64{domain_->hi.y}})
        if (dy != 0 && std::min(a.y, b.y) < y && y < std::max(a.y, b.y))
          others.push_back({static_cast<geom::Coord>(a.x + (y - a.y) * dx / dy), static_cast<geom::Coord>(y)});
    });
  for_each_pin_edge(pin, [&](Point a, Point b) {
    const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y;
    // The edge's point at row y (not horizontal) or column x (not vertical): exact, |dx| = |dy|
    // on a 45-degree edge.
    auto at_y = [&](i64 y) {
      return Point{static_cast<geom::Coord>(a.x + (dx == 0 ? 0 : (y - a.y) * dx / dy)), static_cast<geom::Coord>(y)};
    };
    auto at_x = [&](i64 x) {
      return Point{static_cast<geom::Coord>(x), static_cast<geom::Coord>(a.y + (dy == 0 ? 0 : (x - a.x) * dy / dx))};
    };
    const i64 ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
    const i64 xlo = std::min(a.x, b.x), xhi = std::max(a.x, b.x);
    if (dy != 0) {  // horizontal projections: one per row of obstacle vertices in the edge's range
      for (auto it = std::lower_bound(ys_.begin(), ys_.end(), ylo); it != ys_.end() && *it <= yhi; ++it)
        out.push_back(at_y(*it));
      for (const Point o : others)
        if (o.y >= ylo && o.y <= yhi) out.push_back(at_y(o.y));
    }
    if (dx != 0) {  // vertical projections: one per column
      for (auto it = std::lower_bound(xs_.begin(), xs_.end(), xlo); it != xs_.end() && *it <= xhi; ++it)
        out.push_back(at_x(*it));
      for (const Point o : others)
        if (o.x >= xlo && o.x <= xhi) out.push_back(at_x(o.x));
    }
    if (octilinear_ && dx != 0 && dy != 0) {
      // Projections along the other diagonal: on an edge along (1, 1) (x - y = k), the point
      // with x + y = c is at x = (c + k) / 2; on one along (1, -1) (x + y = c), the point with
      // x - y = d is at x = (c + d) / 2. Half-integers give both integer neighbours.
      const bool rising = (dx > 0) == (dy > 0);
      const i64 line = rising ? i64{a.x} - a.y : i64{a.x} + a.y;
      auto project = [&](i64 other_line) {  // x + y (rising edge) or x - y (falling edge)
        const i64 twice = other_line + line;
        for (const i64 x : geom::lattice_neighbours(twice, lattice_))
          if (x >= xlo && x <= xhi) out.push_back(at_x(x));
      };
      // the other lines whose projection lies in [xlo, xhi]: 2 xlo - line <= other <= 2 xhi - line
      const std::vector<i64>& lines = rising ? sums_ : diffs_;
      for (auto it = std::lower_bound(lines.begin(), lines.end(), 2 * xlo - line); it != lines.end() && *it <= 2 * xhi - line; ++it)
        project(*it);
      for (const Point o : others) {
        const i64 other_line = rising ? i64{o.x} + o.y : i64{o.x} - o.y;
        if (other_line >= 2 * xlo - line && other_line <= 2 * xhi - line) project(other_line);
      }
    }
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace taut::router
