#include "geom/predicates.h"

#include <algorithm>

namespace taut::geom {

bool on_segment(Point p, Point a, Point b) {
  if (orient(a, b, p) != 0) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

SquaredDistance point_segment_distance2(Point p, Point a, Point b) {
  const i128 ux = i128{b.x} - a.x, uy = i128{b.y} - a.y, vx = i128{p.x} - a.x, vy = i128{p.y} - a.y;
  const i128 t = ux * vx + uy * vy, l = ux * ux + uy * uy;
  if (l == 0 || t <= 0) return {vx * vx + vy * vy, 1};
  if (t >= l) {
    const i128 wx = i128{p.x} - b.x, wy = i128{p.y} - b.y;
    return {wx * wx + wy * wy, 1};
  }
  const i128 c = ux * vy - uy * vx;  // |c| < 2^63
  return {c * c, l};
}

SegmentIntersection intersect(Segment s, Segment t) {
  const int d1 = orientation(s.a, s.b, t.a);
  const int d2 = orientation(s.a, s.b, t.b);
  const int d3 = orientation(t.a, t.b, s.a);
  const int d4 = orientation(t.a, t.b, s.b);
  if (d1 == 0 && d2 == 0 && d3 == 0 && d4 == 0) {
    // All four points on one line, or at least one segment is a single point. Two single
    // points are not necessarily on one line (every orient is 0 trivially): compare them.
    const bool s_point = s.a == s.b, t_point = t.a == t.b;
    if (s_point && t_point)
      return s.a == t.a ? SegmentIntersection::Touch : SegmentIntersection::None;
    // Otherwise the points are collinear on a non-degenerate line, and projecting on one
    // axis the line is not perpendicular to is injective: x unless the line is vertical.
    const bool vertical = (s_point ? t.a.x == t.b.x : s.a.x == s.b.x);
    auto key = [vertical](Point p) { return vertical ? p.y : p.x; };
    const Coord s0 = std::min(key(s.a), key(s.b)), s1 = std::max(key(s.a), key(s.b));
    const Coord t0 = std::min(key(t.a), key(t.b)), t1 = std::max(key(t.a), key(t.b));
    const Coord lo = std::max(s0, t0), hi = std::min(s1, t1);
    if (lo > hi) return SegmentIntersection::None;
    if (lo == hi) return SegmentIntersection::Touch;
    return SegmentIntersection::Overlap;
  }
  if (d1 * d2 > 0 || d3 * d4 > 0) return SegmentIntersection::None;
  if (d1 == 0 || d2 == 0 || d3 == 0 || d4 == 0) {
    // One endpoint lies on the other segment's line; check it really lies on the segment.
    if ((d1 == 0 && on_segment(t.a, s.a, s.b)) || (d2 == 0 && on_segment(t.b, s.a, s.b)) ||
        (d3 == 0 && on_segment(s.a, t.a, t.b)) || (d4 == 0 && on_segment(s.b, t.a, t.b)))
      return SegmentIntersection::Touch;
    return SegmentIntersection::None;
  }
  return SegmentIntersection::Proper;
}

RationalPoint line_intersection(Segment s, Segment t) {
  // p = s.a + (s.b - s.a) * u,  u = cross(t.a - s.a, t.b - t.a) / cross(s.b - s.a, t.b - t.a)
  const i128 rx = i128{s.b.x} - s.a.x, ry = i128{s.b.y} - s.a.y;
  const i128 qx = i128{t.b.x} - t.a.x, qy = i128{t.b.y} - t.a.y;
  const i128 wx = i128{t.a.x} - s.a.x, wy = i128{t.a.y} - s.a.y;
  i128 den = rx * qy - ry * qx;          // < 2^63
  i128 num = wx * qy - wy * qx;          // < 2^63
  if (den < 0) { den = -den; num = -num; }
  RationalPoint r;
  r.den = den;
  r.x_num = i128{s.a.x} * den + rx * num;  // < 2^30*2^63 + 2^31*2^63 < 2^95
  r.y_num = i128{s.a.y} * den + ry * num;
  return r;
}

i128 twice_area(std::span<const Point> ring) {
  i128 sum = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point p = ring[i], q = ring[(i + 1) % n];
    sum += i128{p.x} * q.y - i128{q.x} * p.y;
  }
  return sum;
}

Location locate(Point p, std::span<const Point> ring) {
  // Crossing number with the half-open rule on y; exact because every test is an orient sign.
  const std::size_t n = ring.size();
  bool inside = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    if (on_segment(p, a, b)) return Location::Boundary;
    if ((a.y > p.y) != (b.y > p.y)) {
      // Edge straddles the horizontal line through p; is the crossing right of p?
      const int o = orientation(a, b, p);
      if ((b.y > a.y) ? (o > 0) : (o < 0)) inside = !inside;
    }
  }
  return inside ? Location::Inside : Location::Outside;
}

Location locate(Point p, const Polygon& poly) {
  const Location outer = locate(p, std::span<const Point>(poly.outer));
  if (outer != Location::Inside) return outer;
  // Boundary wins over Outside so the answer does not depend on the order of the holes (it
  // only matters for invalid polygons whose holes overlap).
  Location result = Location::Inside;
  for (const Ring& h : poly.holes) {
    const Location l = locate(p, std::span<const Point>(h));
    if (l == Location::Boundary) return Location::Boundary;
    if (l == Location::Inside) result = Location::Outside;
  }
  return result;
}

std::int64_t count_bends(std::span<const Point> polyline) {
  std::int64_t bends = 0;
  bool have_prev = false;
  i64 px = 0, py = 0;
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    const i64 dx = i64{polyline[i].x} - polyline[i - 1].x;
    const i64 dy = i64{polyline[i].y} - polyline[i - 1].y;
    if (dx == 0 && dy == 0) continue;  // zero-length segment: no direction
    if (have_prev) {
      const i64 cross = px * dy - py * dx;  // |.| < 2^63 (see the top of predicates.h)
      const i64 dotp = px * dx + py * dy;
      if (cross != 0 || dotp < 0) ++bends;  // turn, or 180-degree reversal
    }
    px = dx;
    py = dy;
    have_prev = true;
  }
  return bends;
}

}  // namespace taut::geom
