#include "support/wavefront_cases.h"

#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define TAUT_WAVEFRONT_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TAUT_WAVEFRONT_SANITIZED 1
#endif
#endif
#ifndef TAUT_WAVEFRONT_SANITIZED
#define TAUT_WAVEFRONT_SANITIZED 0
#endif

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "geom/root2.h"
#include "support/sanitized.h"
#include "geom/validate.h"
#include "io/generate.h"
#include "io/layout_geometry.h"
#include "oracle/l1_oracle.h"
#include "oracle/oct_oracle.h"
#include "oracle/union_oracle.h"
#include "router/wavefront.h"

namespace taut::test {
namespace {

using geom::Box;
using geom::Point;
using geom::Polygon;
using geom::Ring;
using geom::Root2;
using Dist = std::optional<std::int64_t>;
using i64 = std::int64_t;
using u64 = std::uint64_t;

// Uniform enough for tests, and the same on every standard library (no std distributions).
class Rand {
 public:
  explicit Rand(u64 seed) : engine_(seed) {}
  u64 next() { return engine_(); }
  i64 range(i64 lo, i64 hi) {  // inclusive
    return lo + static_cast<i64>(engine_() % static_cast<u64>(hi - lo + 1));
  }
  bool chance(int percent) { return static_cast<int>(engine_() % 100) < percent; }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[static_cast<std::size_t>(engine_() % v.size())];
  }

 private:
  std::mt19937_64 engine_;
};

Point P(i64 x, i64 y) { return {static_cast<geom::Coord>(x), static_cast<geom::Coord>(y)}; }

// ---- text ---------------------------------------------------------------------------------

std::string pt(Point p) { return "{" + std::to_string(p.x) + ", " + std::to_string(p.y) + "}"; }
std::string ring_str(const Ring& r) {
  std::string s = "{";
  for (std::size_t i = 0; i < r.size(); ++i) s += (i ? ", " : "") + pt(r[i]);
  return s + "}";
}
std::string points_str(const std::vector<Point>& v) {
  std::string s = "{";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + pt(v[i]);
  return s + "}";
}
std::string value_str(i64 v) { return std::to_string(v); }
// a + b*sqrt2 as "a+b*sqrt2 (~value)"; "a" when b == 0, "b*sqrt2 (~value)" when a == 0.
std::string value_str(Root2 v) {
  if (v.b == 0) return std::to_string(v.a);
  std::ostringstream os;
  if (v.a != 0)
    os << v.a << (v.b < 0 ? "-" : "+") << (v.b < 0 ? -v.b : v.b);
  else
    os << v.b;
  os << "*sqrt2 (~" << v.to_double() << ")";
  return os.str();
}
template <class T>
std::string dist_str(const std::optional<T>& d) {
  return d ? value_str(*d) : std::string("unreachable");
}
std::string box_str(const Box& b) { return "{" + pt(b.lo) + ", " + pt(b.hi) + "}"; }
std::string polygon_cpp(const Polygon& p) {
  std::string s = "{" + ring_str(p.outer) + ", {";
  for (std::size_t i = 0; i < p.holes.size(); ++i) s += (i ? ", " : "") + ring_str(p.holes[i]);
  return s + "}}";
}

// ---- shapes -------------------------------------------------------------------------------

Ring rect_ring(i64 x0, i64 y0, i64 x1, i64 y1) {
  return {P(x0, y0), P(x1, y0), P(x1, y1), P(x0, y1)};
}
Ring ccw(Ring r) {
  if (geom::twice_area(r) < 0) std::reverse(r.begin(), r.end());
  return r;
}
Ring cw(Ring r) {
  if (geom::twice_area(r) > 0) std::reverse(r.begin(), r.end());
  return r;
}
Polygon rect(i64 x0, i64 y0, i64 x1, i64 y1) { return {rect_ring(x0, y0, x1, y1), {}}; }
Ring diamond_ring(i64 cx, i64 cy, i64 r) {
  return {P(cx + r, cy), P(cx, cy + r), P(cx - r, cy), P(cx, cy - r)};
}
Polygon diamond(i64 cx, i64 cy, i64 r) { return {diamond_ring(cx, cy, r), {}}; }
Ring octagon_ring(i64 x0, i64 y0, i64 x1, i64 y1, i64 c) {
  return {P(x0 + c, y0), P(x1 - c, y0), P(x1, y0 + c), P(x1, y1 - c),
          P(x1 - c, y1), P(x0 + c, y1), P(x0, y1 - c), P(x0, y0 + c)};
}
// 45-degree right triangle with its right angle at one of the four corners of [x,x+a]x[y,y+a].
Polygon tri45(i64 x, i64 y, i64 a, int corner) {
  const Point c[4] = {P(x, y), P(x + a, y), P(x + a, y + a), P(x, y + a)};
  const int k = corner & 3;
  return {ccw({c[k], c[(k + 1) % 4], c[(k + 3) % 4]}), {}};
}

// What a family makes before normalization.
struct Draft {
  Box domain;
  std::vector<Polygon> inputs;
  std::vector<Point> special;  // points of interest
  i64 grid = 10;               // candidate points snap to multiples of this
};

Box hand_domain(Rand& r) {
  const i64 k = r.range(0, 9);
  if (k <= 3) return {P(0, 0), P(100, 100)};
  if (k <= 6) return {P(-10, -10), P(110, 110)};
  return {P(10 * r.range(-2, 0), 10 * r.range(-2, 0)), P(10 * r.range(6, 12), 10 * r.range(6, 12))};
}
i64 g10(Rand& r, i64 lo, i64 hi) { return 10 * r.range(lo, hi); }

// Rectangles on the 10-grid: random, touching an earlier one at a corner or along an edge
// (partly or wholly), flush with the domain side, rings with something in the hole.
void fam_grid_rects(Rand& r, Draft& d, int scale) {
  d.domain = hand_domain(r);
  std::vector<Box> placed;
  const int n = static_cast<int>(r.range(1, 7)) * scale;
  for (int i = 0; i < n; ++i) {
    const i64 kind = r.range(0, 9);
    const i64 w = g10(r, 1, 4), h = g10(r, 1, 4);
    Box b;
    if (placed.empty() || kind <= 2) {
      const i64 x = g10(r, -1, 9), y = g10(r, -1, 9);
      b = {P(x, y), P(x + w, y + h)};
    } else if (kind <= 5) {  // diagonal neighbour: touches at a corner only (a pinch)
      const Box o = r.pick(placed);
      switch (r.range(0, 3)) {
        case 0: b = {o.hi, P(o.hi.x + w, o.hi.y + h)}; break;
        case 1: b = {P(o.lo.x - w, o.hi.y), P(o.lo.x, o.hi.y + h)}; break;
        case 2: b = {P(o.lo.x - w, o.lo.y - h), o.lo}; break;
        default: b = {P(o.hi.x, o.lo.y - h), P(o.hi.x + w, o.lo.y)}; break;
      }
    } else if (kind <= 7) {  // beside an edge, sliding from corner contact to full overlap
      const Box o = r.pick(placed);
      const i64 ow = (o.hi.x - o.lo.x) / 10, oh = (o.hi.y - o.lo.y) / 10;
      const i64 sy = o.lo.y + g10(r, -h / 10, oh), sx = o.lo.x + g10(r, -w / 10, ow);
      switch (r.range(0, 3)) {
        case 0: b = {P(o.hi.x, sy), P(o.hi.x + w, sy + h)}; break;
        case 1: b = {P(o.lo.x - w, sy), P(o.lo.x, sy + h)}; break;
        case 2: b = {P(sx, o.hi.y), P(sx + w, o.hi.y + h)}; break;
        default: b = {P(sx, o.lo.y - h), P(sx + w, o.lo.y)}; break;
      }
    } else if (kind == 8) {  // flush with a domain side
      const Box& D = d.domain;
      const i64 x = g10(r, 0, 8), y = g10(r, 0, 8);
      switch (r.range(0, 3)) {
        case 0: b = {P(D.lo.x, y), P(D.lo.x + w, y + h)}; break;
        case 1: b = {P(D.hi.x - w, y), P(D.hi.x, y + h)}; break;
        case 2: b = {P(x, D.lo.y), P(x + w, D.lo.y + h)}; break;
        default: b = {P(x, D.hi.y - h), P(x + w, D.hi.y)}; break;
      }
    } else {  // a ring, maybe with a rectangle in the hole touching the hole's side
      const i64 x = g10(r, -1, 6), y = g10(r, -1, 6), t = g10(r, 1, 2);
      const i64 W = 2 * t + g10(r, 3, 4), H = 2 * t + g10(r, 3, 4);  // hole >= 30 wide
      b = {P(x, y), P(x + W, y + H)};
      Polygon ring{rect_ring(x, y, x + W, y + H),
                   {cw(rect_ring(x + t, y + t, x + W - t, y + H - t))}};
      d.inputs.push_back(ring);
      placed.push_back(b);
      d.special.push_back(P(x + W / 2, y + H / 2));
      if (r.chance(50)) {
        const i64 hx = x + t, hy = y + t;                         // hole lower-left
        d.inputs.push_back(rect(hx, hy + 10, hx + 10, hy + 20));  // touches the hole's left side
        d.special.push_back(P(hx + 15, hy + 5));
      }
      continue;
    }
    placed.push_back(b);
    d.inputs.push_back(rect(b.lo.x, b.lo.y, b.hi.x, b.hi.y));
  }
}

// Diagonal and sloped edges: diamonds, 45-degree triangles, octagons, sloped triangles and
// parallelograms, tips on earlier vertices and on the domain side, diamond rings.
void fam_grid_diagonal(Rand& r, Draft& d, int scale) {
  d.domain = hand_domain(r);
  const Box D = d.domain;
  const int n = static_cast<int>(r.range(1, 5)) * scale;
  for (int i = 0; i < n; ++i) {
    const i64 x = g10(r, 0, 9), y = g10(r, 0, 9);
    switch (r.range(0, 9)) {
      case 0: d.inputs.push_back(diamond(x, y, g10(r, 1, 3))); break;
      case 1:
        d.inputs.push_back(tri45(x - 10, y - 10, g10(r, 1, 4), static_cast<int>(r.range(0, 3))));
        break;
      case 2: {
        const i64 W = g10(r, 3, 5), H = g10(r, 3, 5);
        d.inputs.push_back({octagon_ring(x - 20, y - 20, x - 20 + W, y - 20 + H, 10), {}});
        break;
      }
      case 3: {  // sloped triangle on the grid
        Ring t{P(x, y), P(x + g10(r, -4, 4), y + g10(r, -4, 4)),
               P(x + g10(r, -4, 4), y + g10(r, -4, 4))};
        if (geom::twice_area(t) != 0) d.inputs.push_back({ccw(t), {}});
        break;
      }
      case 4: {  // parallelogram with slope 2 or 1/2
        if (r.chance(50))
          d.inputs.push_back({{P(x, y), P(x + 20, y), P(x + 30, y + 20), P(x + 10, y + 20)}, {}});
        else
          d.inputs.push_back({{P(x, y), P(x + 20, y + 10), P(x + 20, y + 30), P(x, y + 20)}, {}});
        break;
      }
      case 5: d.inputs.push_back(rect(x, y, x + g10(r, 1, 3), y + g10(r, 1, 3))); break;
      case 6: {  // a diamond whose tip touches a vertex of an earlier shape
        if (d.inputs.empty()) break;
        const Point v = r.pick(r.pick(d.inputs).outer);
        const i64 rr = g10(r, 1, 2);
        switch (r.range(0, 3)) {
          case 0: d.inputs.push_back(diamond(v.x + rr, v.y, rr)); break;
          case 1: d.inputs.push_back(diamond(v.x - rr, v.y, rr)); break;
          case 2: d.inputs.push_back(diamond(v.x, v.y + rr, rr)); break;
          default: d.inputs.push_back(diamond(v.x, v.y - rr, rr)); break;
        }
        break;
      }
      case 7: {  // diamond ring
        const i64 R = g10(r, 3, 4), t = g10(r, 1, 2);
        d.inputs.push_back({diamond_ring(x, y, R), {cw(diamond_ring(x, y, R - t))}});
        d.special.push_back(P(x, y));
        if (r.chance(40)) d.special.push_back(P(x + 5, y));
        break;
      }
      case 8: {  // tip or 45-degree edge on the domain side
        const i64 rr = g10(r, 1, 2);
        switch (r.range(0, 4)) {
          case 4: {  // a triangle touching a domain corner with one vertex: a pinch there
            const Point c0 = r.chance(50) ? D.lo : D.hi;
            const i64 sx = c0 == D.lo ? 1 : -1;
            d.inputs.push_back({ccw({c0, P(c0.x + sx * 2 * rr, c0.y + sx * rr),
                                     P(c0.x + sx * rr, c0.y + sx * 2 * rr)}),
                                {}});
            d.special.push_back(c0);
            break;
          }
          case 0: d.inputs.push_back(diamond(D.lo.x + rr, y, rr)); break;
          case 1: d.inputs.push_back(diamond(x, D.hi.y - rr, rr)); break;
          case 2:
            d.inputs.push_back(tri45(D.hi.x - rr, y, rr, static_cast<int>(r.range(0, 3))));
            break;
          default: d.inputs.push_back(tri45(x, D.lo.y, rr, static_cast<int>(r.range(0, 3)))); break;
        }
        break;
      }
      default: {  // a 45-degree triangle against an earlier rectangle-ish vertex
        if (d.inputs.empty()) break;
        const Point v = r.pick(r.pick(d.inputs).outer);
        d.inputs.push_back(tri45(v.x, v.y, g10(r, 1, 2), static_cast<int>(r.range(0, 3))));
        break;
      }
    }
  }
}

// Rings: points walled in, C-shaped rings with and without a gap, things nested in holes.
void fam_rings(Rand& r, Draft& d, int scale) {
  d.domain = hand_domain(r);
  const int n = static_cast<int>(r.range(1, 2)) * scale;
  for (int i = 0; i < n; ++i) {
    const i64 x = g10(r, 0, 5), y = g10(r, 0, 5);
    switch (r.range(0, 6)) {
      case 5: {  // a hole touching the shell at one point: a pinch between inside and outside
        const i64 W = g10(r, 6, 8), R0 = g10(r, 1, 2);
        const i64 cx = x + 10 * r.range(3, W / 10 - 3);
        d.inputs.push_back({rect_ring(x, y, x + W, y + W), {cw(diamond_ring(cx, y + R0, R0))}});
        d.special.push_back(P(cx, y + R0));
        d.special.push_back(P(cx, y));  // the pinch
        break;
      }
      case 6: {  // two holes touching each other at a point (tips of two diamonds)
        const i64 W = g10(r, 6, 8);
        const i64 cy = y + W / 2 - (W / 2) % 10;
        d.inputs.push_back({rect_ring(x, y, x + W, y + W),
                            {cw(diamond_ring(x + 20, cy, 10)), cw(diamond_ring(x + 40, cy, 10))}});
        d.special.push_back(P(x + 20, cy));
        d.special.push_back(P(x + 40, cy));
        d.special.push_back(P(x + 30, cy));  // the pinch
        break;
      }
      case 0: {  // rect ring with contents
        const i64 t = g10(r, 1, 2), W = 2 * t + g10(r, 3, 4), H = 2 * t + g10(r, 3, 4);
        d.inputs.push_back(
            {rect_ring(x, y, x + W, y + H), {cw(rect_ring(x + t, y + t, x + W - t, y + H - t))}});
        d.special.push_back(P(x + W / 2, y + H / 2));
        d.special.push_back(P(x + t, y + t));  // hole corner
        if (r.chance(50)) {                    // a rect in the hole touching the hole's bottom side
          d.inputs.push_back(rect(x + t + 10, y + t, x + t + 20, y + t + 10));
        } else if (r.chance(50)) {  // a diamond floating in the hole
          d.inputs.push_back(diamond(x + W / 2 - 5, y + H / 2 - 5, 5));
        }
        break;
      }
      case 1: {  // a single pin walled in by a tight ring
        const i64 cx = x + 15, cy = y + 15;
        d.inputs.push_back({rect_ring(cx - 15, cy - 15, cx + 15, cy + 15),
                            {cw(rect_ring(cx - 5, cy - 5, cx + 5, cy + 5))}});
        d.special.push_back(P(cx, cy));
        break;
      }
      case 2: {  // C ring from four walls: gap 0 (closed, walls touch) or 10 (open)
        const i64 W = g10(r, 4, 6), H = g10(r, 4, 6);
        const i64 gap = r.chance(50) ? 0 : 10;
        d.inputs.push_back(rect(x, y, x + W, y + 10));                          // bottom
        d.inputs.push_back(rect(x, y + H - 10, x + W, y + H));                  // top
        d.inputs.push_back(rect(x, y + 10, x + 10, y + H - 10));                // left
        d.inputs.push_back(rect(x + W - 10, y + 10 + gap, x + W, y + H - 10));  // right, gap below
        d.special.push_back(P(x + W / 2, y + H / 2));
        d.special.push_back(P(x + W - 5, y + 10));
        break;
      }
      case 3: {  // ring closed by two L shapes touching at corners only: pinches, no way in
        const i64 W = g10(r, 4, 6), H = g10(r, 4, 6);
        d.inputs.push_back({ccw({P(x, y), P(x + W - 10, y), P(x + W - 10, y + 10),
                                 P(x + 10, y + 10), P(x + 10, y + H - 10), P(x, y + H - 10)}),
                            {}});
        d.inputs.push_back(
            {ccw({P(x + W - 10, y + 10), P(x + W, y + 10), P(x + W, y + H), P(x + 10, y + H),
                  P(x + 10, y + H - 10), P(x + W - 10, y + H - 10)}),
             {}});
        d.special.push_back(P(x + W / 2, y + H / 2));
        break;
      }
      default: {  // diamond ring with a diamond inside the hole touching it at a tip
        const i64 R = g10(r, 3, 4);
        d.inputs.push_back(
            {diamond_ring(x + 40, y + 40, R), {cw(diamond_ring(x + 40, y + 40, R - 10))}});
        const i64 h = R - 10;                                    // hole radius
        d.inputs.push_back(diamond(x + 40 + h - 5, y + 40, 5));  // tip on the hole's right tip
        d.special.push_back(P(x + 40 - 5, y + 40));
        break;
      }
    }
  }
  for (i64 k = r.range(0, 2); k > 0; --k) {
    const i64 x = g10(r, 0, 9), y = g10(r, 0, 9);
    d.inputs.push_back(rect(x, y, x + g10(r, 1, 2), y + g10(r, 1, 2)));
  }
}

// Pinches: checkerboards, walls of rectangles touching at corners from one domain side to the
// other (unreachable halves unless a link is missing), chains of diamonds tip to tip.
void fam_pinches(Rand& r, Draft& d, int scale) {
  d.domain = hand_domain(r);
  const Box D = d.domain;
  for (int rep = 0; rep < scale; ++rep) {
    switch (r.range(0, 3)) {
      case 0: {  // checkerboard patch
        const i64 ox = g10(r, 0, 5), oy = g10(r, 0, 5), c = r.chance(70) ? 10 : 20;
        const i64 k = r.range(2, 4), m = r.range(2, 4);
        for (i64 i = 0; i < k; ++i)
          for (i64 j = 0; j < m; ++j)
            if (r.chance(((i + j) % 2 == 0) ? 80 : 20))
              d.inputs.push_back(rect(ox + i * c, oy + j * c, ox + (i + 1) * c, oy + (j + 1) * c));
        d.special.push_back(P(ox + c, oy + c));
        break;
      }
      case 1: {  // staircase of corner-touching rects from the bottom side to the top side
        i64 x = g10(r, 0, 4), y = D.lo.y;
        const bool missing = r.chance(30);
        const i64 skip = r.range(1, 4);
        for (int i = 0; y < D.hi.y && i < 20; ++i) {
          const i64 s = g10(r, 1, 2);
          if (!(missing && i == skip)) d.inputs.push_back(rect(x, y, x + s, y + s));
          x += s, y += s;
        }
        d.special.push_back(P(D.lo.x, D.hi.y));
        d.special.push_back(P(D.hi.x, D.lo.y));
        break;
      }
      case 2: {  // diamonds tip to tip across the domain
        const i64 y = g10(r, 2, 8), rr = 10;
        for (i64 cx = D.lo.x + rr; cx - rr < D.hi.x; cx += 2 * rr)
          if (!(r.chance(8))) d.inputs.push_back(diamond(cx, y, rr));
        d.special.push_back(P(D.lo.x + 2 * rr, y));
        break;
      }
      default: {  // rects with diamonds and triangles on their corners
        const i64 x = g10(r, 1, 6), y = g10(r, 1, 6), w = g10(r, 1, 3), h = g10(r, 1, 3);
        d.inputs.push_back(rect(x, y, x + w, y + h));
        d.inputs.push_back(diamond(x + w + 10, y + h, 10));  // left tip on the NE corner
        d.inputs.push_back(tri45(x - 20, y - 20, 20, 2));    // right angle on the SW corner
        d.special.push_back(P(x + w, y + h));
        break;
      }
    }
  }
  if (r.chance(50)) {
    const i64 x = g10(r, 0, 9), y = g10(r, 0, 9);
    d.inputs.push_back(rect(x, y, x + g10(r, 1, 2), y + g10(r, 1, 2)));
  }
}

// Arbitrary small integer coordinates: sloped edges crossing at rational points (normalize
// rounds them outward), slivers, unit-wide slits.
void fam_fine(Rand& r, Draft& d, int scale) {
  d.domain = {P(0, 0), P(r.range(6, 20), r.range(6, 20))};
  d.grid = 1;
  const i64 W = d.domain.hi.x, H = d.domain.hi.y;
  const int n = static_cast<int>(r.range(1, 5)) * scale;
  for (int i = 0; i < n; ++i) {
    if (r.chance(50)) {
      const i64 x = r.range(-1, W - 1), y = r.range(-1, H - 1);
      const i64 x1 = x + r.range(1, 5), y1 = y + r.range(1, 5);
      Polygon p = rect(x, y, x1, y1);
      if (x1 - x >= 3 && y1 - y >= 3 && r.chance(25))
        p.holes.push_back(cw(rect_ring(x + 1, y + 1, x1 - 1, y1 - 1)));
      d.inputs.push_back(p);
    } else {
      Ring t;
      for (int k = 0; k < 3; ++k) t.push_back(P(r.range(0, W), r.range(0, H)));
      if (geom::twice_area(t) != 0) d.inputs.push_back({ccw(t), {}});
    }
  }
}

// The `taut gen` kinds at small sizes. Sometimes the domain is cut down to the content (or
// into it), so obstacles lie flush with or are clipped by the domain side.
void fam_gen(Rand& r, Draft& d, io::GenKind kind, int scale) {
  io::GenOptions o;
  o.kind = kind;
  o.nets = 3;
  o.seed = r.next() % 1000000007ULL;
  switch (kind) {
    case io::GenKind::Rects:
      o.size = r.range(3, 40) * scale;
      d.grid = 50;
      break;
    case io::GenKind::Polygons:
      o.size = r.range(3, 40) * scale;
      d.grid = 1;
      break;
    case io::GenKind::Maze:
      o.size = r.range(32, 72) * scale;
      d.grid = 50;
      break;
    case io::GenKind::Degenerate:
    case io::GenKind::Channel:  // no family draws it; here so the switch names every kind
      o.size = r.range(3, 40) * scale;
      d.grid = 50;
      break;
  }
  const io::Layout layout = io::generate_layout(o);
  d.inputs = io::blockage_polygons(layout);
  d.domain = layout.boundary->box;
  if (r.chance(30)) {  // content box (boundary minus the 1000 margin), moved by -200..+100
    const i64 m = 1000;
    Box b{P(d.domain.lo.x + m - 50 * r.range(-2, 4), d.domain.lo.y + m - 50 * r.range(-2, 4)),
          P(d.domain.hi.x - m + 50 * r.range(-2, 4), d.domain.hi.y - m + 50 * r.range(-2, 4))};
    if (b.lo.x < b.hi.x && b.lo.y < b.hi.y) d.domain = b;
  }
  for (const io::Net& net : layout.nets)
    for (const io::Pin& pin : net.pins)
      if (pin.point) d.special.push_back(*pin.point);
}

i64 gcd64(i64 a, i64 b) { return std::gcd(a < 0 ? -a : a, b < 0 ? -b : b); }

std::vector<Point> ring_points(const std::vector<Polygon>& obstacles) {
  std::vector<Point> v;
  for (const Polygon& p : obstacles) {
    v.insert(v.end(), p.outer.begin(), p.outer.end());
    for (const Ring& h : p.holes) v.insert(v.end(), h.begin(), h.end());
  }
  return v;
}

std::vector<Point> make_candidates(Rand& r, const Box& dom, const std::vector<Polygon>& obs,
                                   const std::vector<Point>& special, i64 g) {
  std::vector<Point> out = special;
  auto snap = [](i64 v, i64 step) { return v - (((v % step) + step) % step); };
  // The content's box (obstacles), where most of the action is.
  Box content = dom;
  const std::vector<Point> verts = ring_points(obs);
  if (!verts.empty()) {
    content = {verts[0], verts[0]};
    for (const Point v : verts) {
      content.lo = P(std::min(content.lo.x, v.x), std::min(content.lo.y, v.y));
      content.hi = P(std::max(content.hi.x, v.x), std::max(content.hi.y, v.y));
    }
  }
  auto in = [&](const Box& b, i64 margin, i64 step) {
    auto clamp = [](i64 v) { return std::clamp<i64>(v, -geom::kMaxCoord, geom::kMaxCoord); };
    return P(clamp(snap(r.range(b.lo.x - margin, b.hi.x + margin), step)),
             clamp(snap(r.range(b.lo.y - margin, b.hi.y + margin), step)));
  };
  for (int k = 0; k < 7; ++k) out.push_back(in(r.chance(70) ? content : dom, g, g));
  for (int k = 0; k < 3; ++k) out.push_back(in(content, 0, std::max<i64>(1, g / 2)));
  for (int k = 0; k < 3; ++k) out.push_back(in(r.chance(70) ? content : dom, 0, 1));
  if (!verts.empty())
    for (int k = 0; k < 6; ++k) out.push_back(r.pick(verts));
  // Integer points inside edges.
  std::vector<std::pair<Point, Point>> edges;
  for (const Polygon& p : obs) {
    auto add = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i)
        edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
    };
    add(p.outer);
    for (const Ring& h : p.holes) add(h);
  }
  if (!edges.empty())
    for (int k = 0; k < 6; ++k) {
      const auto [a, b] = r.pick(edges);
      const i64 dx = i64{b.x} - a.x, dy = i64{b.y} - a.y, gg = gcd64(dx, dy);
      if (gg < 2) continue;
      const i64 s = r.range(1, gg - 1);
      out.push_back(P(a.x + s * (dx / gg), a.y + s * (dy / gg)));
    }
  // On the domain sides, and a corner now and then.
  for (int k = 0; k < 3; ++k) {
    const Point p = in(dom, 0, g);
    switch (r.range(0, 3)) {
      case 0: out.push_back(P(dom.lo.x, std::clamp<i64>(p.y, dom.lo.y, dom.hi.y))); break;
      case 1: out.push_back(P(dom.hi.x, std::clamp<i64>(p.y, dom.lo.y, dom.hi.y))); break;
      case 2: out.push_back(P(std::clamp<i64>(p.x, dom.lo.x, dom.hi.x), dom.lo.y)); break;
      default: out.push_back(P(std::clamp<i64>(p.x, dom.lo.x, dom.hi.x), dom.hi.y)); break;
    }
  }
  if (r.chance(30)) out.push_back(r.chance(50) ? dom.lo : dom.hi);
  return out;
}

// ---- checking -----------------------------------------------------------------------------

// What differs between the metrics: the engine under test, its reference, the distance type
// (an L1 distance is an int64, an octilinear one a Root2; both compared exactly), and names in
// the reports. Everything below is written once over M, one of these two.
struct L1Metric {
  using Wavefront = router::L1Wavefront;
  using Reference = oracle::L1Reference;
  using Dist = std::optional<std::int64_t>;
  static constexpr WaveMetric kMetric = WaveMetric::L1;
  static constexpr const char* kWavefront = "L1Wavefront";
  static constexpr const char* kReference = "L1Reference";
  static constexpr const char* kSeedVariable = "TAUT_WAVEFRONT_SEED";
  static constexpr const char* kFamilyNote = "";  // after the family name in a report
  static void run(Wavefront& wf, const std::vector<Point>& sources,
                  const std::vector<Point>& targets, bool stop_early) {
    wf.run(sources, targets, stop_early);
  }
  // The run's last argument as C++ (for reports).
  static std::string stop_cpp(bool stop_early) {
    return std::string("/*stop_early=*/") + (stop_early ? "true" : "false");
  }
};

struct OctMetric {
  using Wavefront = router::OctWavefront;
  using Reference = oracle::OctilinearReference;
  using Dist = std::optional<Root2>;
  static constexpr WaveMetric kMetric = WaveMetric::Octilinear;
  static constexpr const char* kWavefront = "OctWavefront";
  static constexpr const char* kReference = "OctilinearReference";
  static constexpr const char* kSeedVariable = "TAUT_OCT_SEED";
  static constexpr const char* kFamilyNote = ", octilinear metric";
  static void run(Wavefront& wf, const std::vector<Point>& sources,
                  const std::vector<Point>& targets, bool stop_early) {
    wf.run(sources, targets, stop_early ? Wavefront::Stop::AllTargets : Wavefront::Stop::Never);
  }
  static std::string stop_cpp(bool stop_early) {
    return stop_early ? "OctWavefront::Stop::AllTargets" : "OctWavefront::Stop::Never";
  }
};

// A fixed-orientation norm (geom/fixed_norm.h): NormWavefront against NormReference, lengths
// int64 (scaled by geom::kNormScale).
template <int N>
struct NormTestMetric {
  struct Wavefront : router::NormWavefront {
    Wavefront(const Box& domain, std::span<const Polygon> obstacles)
        : router::NormWavefront(domain, obstacles, N) {}
  };
  struct Reference : oracle::NormReference {
    Reference(const Box& domain, std::span<const Polygon> obstacles)
        : oracle::NormReference(domain, obstacles, N) {}
  };
  using Dist = std::optional<std::int64_t>;
  static constexpr WaveMetric kMetric =
      N == 2 ? WaveMetric::Farey2 : N == 3 ? WaveMetric::Farey3 : WaveMetric::Farey4;
  static constexpr const char* kWavefront = "NormWavefront";
  static constexpr const char* kReference = "NormReference";
  static constexpr const char* kSeedVariable = "TAUT_NORM_SEED";
  static constexpr const char* kFamilyNote =
      N == 2 ? ", Farey norm 2" : N == 3 ? ", Farey norm 3" : ", Farey norm 4";
  static void run(Wavefront& wf, const std::vector<Point>& sources,
                  const std::vector<Point>& targets, bool stop_early) {
    wf.run(sources, targets, stop_early ? Wavefront::Stop::AllTargets : Wavefront::Stop::Never);
  }
  static std::string stop_cpp(bool stop_early) {
    return stop_early ? "NormWavefront::Stop::AllTargets" : "NormWavefront::Stop::Never";
  }
};

struct Scene {
  Box domain;
  std::vector<Polygon> obstacles;
  std::set<Point> vertices;    // distinct obstacle vertices
  std::int64_t wedge_sum = 0;  // sum over vertices of the reference's wedge count
  bool is_vertex(Point p) const { return vertices.count(p) != 0; }
  bool is_domain_corner(Point p) const {
    return (p.x == domain.lo.x || p.x == domain.hi.x) && (p.y == domain.lo.y || p.y == domain.hi.y);
  }
};

template <class Reference>
Scene make_scene(const Box& domain, std::vector<Polygon> obstacles, const Reference& ref) {
  Scene sc;
  sc.domain = domain;
  sc.obstacles = std::move(obstacles);
  for (const Point v : ring_points(sc.obstacles)) sc.vertices.insert(v);
  for (const Point v : sc.vertices) sc.wedge_sum += static_cast<i64>(ref.wedges_at(v).size());
  return sc;
}

std::string scene_cpp(const Scene& sc) {
  std::ostringstream os;
  os << "  const Box domain" << box_str(sc.domain) << ";\n";
  os << "  const std::vector<Polygon> obstacles{  // " << sc.obstacles.size() << " obstacles, "
     << sc.vertices.size() << " distinct vertices\n";
  for (const Polygon& p : sc.obstacles) os << "      " << polygon_cpp(p) << ",\n";
  os << "  };\n";
  return os.str();
}

struct Query {
  std::vector<Point> sources, targets;
  bool stop_early = true;
  std::vector<Point> vertex_points;  // vertex_distance comparisons after the run
  std::vector<Point> free_points;    // is_free comparisons
  bool run = true;                   // false: is_free comparisons only
};

template <class M>
std::string query_cpp(const Query& q) {
  std::ostringstream os;
  if (!q.free_points.empty()) os << "  is_free points " << points_str(q.free_points) << "\n";
  if (q.run) {
    os << "  const std::vector<Point> sources" << points_str(q.sources) << ";\n";
    os << "  const std::vector<Point> targets" << points_str(q.targets) << ";\n";
    os << "  wf.run(sources, targets, " << M::stop_cpp(q.stop_early) << ");\n";
    if (!q.vertex_points.empty())
      os << "  vertex_distance at " << points_str(q.vertex_points) << "\n";
  }
  return os.str();
}

template <class Reference>
std::string wedges_str(const Reference& ref, Point p) {
  const auto ws = ref.wedges_at(p);
  if (ws.empty()) return "no wedge";
  if (ws.size() == 1 && ws[0].full) return "open";
  std::string s = std::to_string(ws.size()) + " wedge(s):";
  for (const auto& w : ws)
    s += " (" + std::to_string(w.from_x) + "," + std::to_string(w.from_y) + ")->(" +
         std::to_string(w.to_x) + "," + std::to_string(w.to_y) + ")";
  return s;
}

// Every comparison of one query; "" when all agree. Implausible WavefrontStats go to `soft`
// (they do not hide wrong answers).
template <class M>
std::string check_query(const Scene& sc, const typename M::Reference& ref,
                        typename M::Wavefront& wf, const Query& q, WavefrontTally* tally,
                        std::ostream* log, std::string* soft) {
  using Dist = typename M::Dist;
  std::ostringstream bad, stats_bad;
  for (const Point p : q.free_points) {
    const bool want = ref.is_free(p), got = wf.is_free(p);
    if (tally) {
      ++tally->free_checks;
      tally->not_free += !want;
    }
    if (log)
      *log << "  is_free " << pt(p) << ": reference " << want << ", wavefront " << got << "\n";
    if (want != got)
      bad << "is_free" << pt(p) << ": reference " << want << " (" << wedges_str(ref, p)
          << "), wavefront " << got << "\n";
  }
  if (!bad.str().empty() || !q.run) return bad.str();

  // The reference: each source against every target and vertex point; the best over sources.
  std::vector<Point> all = q.targets;
  all.insert(all.end(), q.vertex_points.begin(), q.vertex_points.end());
  std::map<Point, std::vector<Dist>> memo;
  std::vector<const std::vector<Dist>*> per_source;
  const auto t0 = std::chrono::steady_clock::now();
  for (const Point s : q.sources) {
    auto it = memo.find(s);
    if (it == memo.end()) it = memo.emplace(s, ref.distances(s, all)).first;
    per_source.push_back(&it->second);
  }
  const auto t1 = std::chrono::steady_clock::now();
  std::vector<Dist> best(all.size());
  std::vector<std::size_t> best_source(all.size(), 0);
  for (std::size_t k = 0; k < all.size(); ++k)
    for (std::size_t j = 0; j < q.sources.size(); ++j) {
      const Dist v = (*per_source[j])[k];
      if (v && (!best[k] || *v < *best[k])) best[k] = v, best_source[k] = j;
    }

  M::run(wf, q.sources, q.targets, q.stop_early);
  const auto t2 = std::chrono::steady_clock::now();
  if (tally) {
    tally->reference_seconds += std::chrono::duration<double>(t1 - t0).count();
    tally->wavefront_seconds += std::chrono::duration<double>(t2 - t1).count();
  }
  bool any_free_source = false;
  for (const Point s : q.sources) any_free_source |= ref.is_free(s);
  if (tally) {
    ++tally->runs;
    tally->multi_source_runs += q.sources.size() > 1;
    for (const Point s : q.sources) {
      const auto ws = ref.wedges_at(s);
      if (ws.size() >= 2)
        ++tally->pinch_sources;
      else if (ws.size() == 1 && !ws[0].full)
        ++tally->boundary_sources;
    }
  }
  bool split = false;
  for (std::size_t k = 0; k < q.targets.size(); ++k) {
    const Point t = q.targets[k];
    const Dist got = wf.target_distance(k);
    const std::optional<std::size_t> src = wf.target_source(k);
    const std::vector<Point> path = wf.target_path(k);
    if (log)
      *log << "  target #" << k << " " << pt(t) << " (" << wedges_str(ref, t) << "): reference "
           << dist_str(best[k]) << ", wavefront " << dist_str(got) << " from source "
           << (src ? std::to_string(*src) : "-") << " path " << points_str(path) << "\n";
    if (tally) {
      ++tally->comparisons;
      const auto ws = ref.wedges_at(t);
      if (!ws.empty()) {
        if (best[k])
          ++tally->reachable;
        else
          ++tally->unreachable;
        if (ws.size() >= 2)
          ++tally->pinch_points;
        else if (!ws[0].full)
          ++tally->boundary_points;
        split |= !best[k];
      }
      for (const Point s : q.sources) tally->source_is_target += s == t && ws.size() > 0;
    }
    auto fail = [&](const std::string& what) {
      bad << "target #" << k << " " << pt(t) << " (" << wedges_str(ref, t) << "): " << what
          << "\n    reference: distance " << dist_str(best[k]);
      if (best[k]) {
        const auto rp = ref.path(q.sources[best_source[k]], t);
        bad << " from source " << best_source[k] << " " << pt(q.sources[best_source[k]])
            << ", a shortest path " << (rp ? points_str(*rp) : std::string("(none?)"));
      }
      bad << "\n    wavefront: distance " << dist_str(got) << " from source "
          << (src ? std::to_string(*src) : std::string("-")) << ", path " << points_str(path)
          << "\n";
    };
    if (got != best[k]) {
      fail("distance differs");
      continue;
    }
    if (!best[k]) {
      if (src)
        fail("unreachable, but target_source is set");
      else if (!path.empty())
        fail("unreachable, but the path is not empty");
      continue;
    }
    if (!src || *src >= q.sources.size()) {
      fail("no valid target_source");
      continue;
    }
    if ((*per_source[*src])[k] != best[k]) {
      fail("target_source " + std::to_string(*src) +
           " does not achieve the distance (from it: " + dist_str((*per_source[*src])[k]) + ")");
      continue;
    }
    if (path.empty()) {
      fail("empty path for a reachable target");
      continue;
    }
    if (tally) {
      ++tally->paths;
      tally->bends += static_cast<i64>(path.size()) - 2 > 0 ? static_cast<i64>(path.size()) - 2 : 0;
    }
    if (path.front() != q.sources[*src]) {
      fail("the path does not start at its source " + pt(q.sources[*src]));
      continue;
    }
    if (path.back() != t) {
      fail("the path does not end at the target");
      continue;
    }
    bool ok = true;
    for (std::size_t i = 0; i + 1 < path.size() && ok; ++i)
      if (path[i] == path[i + 1]) {
        fail("the path repeats the point " + pt(path[i]));
        ok = false;
      }
    for (std::size_t i = 1; i + 1 < path.size() && ok; ++i) {
      if (sc.is_vertex(path[i])) continue;
      if (sc.is_domain_corner(path[i])) {  // a corner of the frame: harmless, counted
        if (tally) ++tally->domain_corner_bends;
        continue;
      }
      fail("the path bends at " + pt(path[i]) + ", which is not an obstacle vertex");
      ok = false;
    }
    if (!ok) continue;
    const Dist checked = ref.check_path(path);
    if (checked != best[k])
      fail(std::string(M::kReference) + "::check_path gives " +
           (checked ? value_str(*checked)
                    : std::string("nullopt (a segment or bend is not allowed)")));
  }
  if (tally && split && any_free_source) ++tally->split_runs;

  // vertex_distance: exact after a full run; after an early stop a reported value is never
  // below the true distance.
  std::set<Point> reached_vertices;
  for (std::size_t i = 0; i < q.vertex_points.size(); ++i) {
    const Point v = q.vertex_points[i];
    const std::size_t k = q.targets.size() + i;
    const Dist got = wf.vertex_distance(v);
    if (log)
      *log << "  vertex " << pt(v) << " (" << wedges_str(ref, v) << "): reference "
           << dist_str(best[k]) << ", wavefront " << dist_str(got) << "\n";
    if (tally) ++tally->vertex_checks;
    const std::string head = "vertex_distance" + pt(v) + " (" + wedges_str(ref, v) +
                             ", stop_early " + (q.stop_early ? "true" : "false") + "): ";
    if (sc.is_vertex(v)) {
      if (best[k]) reached_vertices.insert(v);
      if (!q.stop_early && got != best[k])
        bad << head << "reference " << dist_str(best[k]) << ", wavefront " << dist_str(got) << "\n";
      if (q.stop_early && got && (!best[k] || *got < *best[k]))
        bad << head << "wavefront " << dist_str(got) << " is below the reference "
            << dist_str(best[k]) << "\n";
    } else if (!sc.is_domain_corner(v) && got) {
      bad << head << "not an obstacle vertex, but the wavefront gives " << value_str(*got) << "\n";
    }
  }

  const router::WavefrontStats& st = wf.stats();
  auto stats_str = [&] {
    std::ostringstream os;
    os << "vertices " << st.vertices << " entities " << st.entities << " events " << st.events
       << " wavelets " << st.wavelets << " labelled " << st.labelled
       << " drag_queries " << st.drag_queries << " ray_queries " << st.ray_queries;
    return os.str();
  };
  if (log) *log << "  stats: " << stats_str() << "\n";
  if (st.vertices < 0 || st.entities < 0 || st.events < 0 || st.wavelets < 0 || st.labelled < 0 ||
      st.drag_queries < 0 || st.ray_queries < 0)
    stats_bad << "stats: a negative counter: " << stats_str() << "\n";
  if (st.labelled > st.entities) stats_bad << "stats: labelled > entities: " << stats_str() << "\n";
  if (st.entities < sc.wedge_sum)
    stats_bad << "stats: entities below the " << sc.wedge_sum
              << " (vertex, wedge) pairs of the obstacle vertices: " << stats_str() << "\n";
  if (!q.stop_early && any_free_source && !sc.obstacles.empty() && st.events == 0)
    stats_bad << "stats: no event in a full run among obstacles: " << stats_str() << "\n";
  if (!q.stop_early && st.labelled < static_cast<i64>(reached_vertices.size()))
    stats_bad << "stats: labelled below the " << reached_vertices.size()
              << " reachable vertices checked: " << stats_str() << "\n";
  if (soft && !stats_bad.str().empty()) *soft += stats_bad.str();
  return bad.str();
}

template <class M>
std::string guarded_check(const Scene& sc, const typename M::Reference& ref,
                          typename M::Wavefront& wf, const Query& q, WavefrontTally* tally,
                          std::ostream* log, std::string* soft) {
  try {
    return check_query<M>(sc, ref, wf, q, tally, log, soft);
  } catch (const std::exception& e) {
    return std::string("exception from ") + M::kWavefront + ": " + e.what() + "\n";
  }
}

// The failure of q on a fresh pair of engines over `obstacles`; "" when everything agrees.
// soft: implausible stats count as a failure too.
template <class M>
std::string failure_on(const Box& domain, const std::vector<Polygon>& obstacles, const Query& q,
                       bool soft, Scene* scene_out = nullptr) {
  const typename M::Reference ref(domain, obstacles);
  Scene sc = make_scene(domain, obstacles, ref);
  std::string f;
  try {
    typename M::Wavefront wf(sc.domain, sc.obstacles);
    std::string stats_bad;
    f = guarded_check<M>(sc, ref, wf, q, nullptr, nullptr, &stats_bad);
    if (soft) f += stats_bad;
  } catch (const std::exception& e) {
    f = std::string("exception from the ") + M::kWavefront + " constructor: " + e.what() + "\n";
  }
  if (scene_out) *scene_out = std::move(sc);
  return f;
}

// Drops query points, sources, targets, obstacles and holes while the query still fails.
template <class M>
std::string shrink(const Scene& original, const Query& original_q, bool soft) {
  std::vector<Polygon> obs = original.obstacles;
  Query q = original_q;
  std::string failure = failure_on<M>(original.domain, obs, q, soft);
  if (failure.empty())
    return std::string(
               "  (the failure does not reproduce on fresh engines: it depends on "
               "earlier runs on the same ") +
           M::kWavefront + " object)\n";
  int budget = 800, attempts = 0;
  auto attempt = [&](const std::vector<Polygon>& o, const Query& qq) {
    if (budget-- <= 0) return false;
    ++attempts;
    const std::string f = failure_on<M>(original.domain, o, qq, soft);
    if (f.empty()) return false;
    obs = o, q = qq, failure = f;
    return true;
  };
  auto reduce = [&](std::vector<Point> Query::*m) {
    for (std::size_t i = 0; (q.*m).size() > 1 && i < (q.*m).size(); ++i) {
      Query t = q;
      t.*m = {(q.*m)[i]};
      if (attempt(obs, t)) break;
    }
    for (std::size_t i = 0; i < (q.*m).size();) {
      Query t = q;
      (t.*m).erase((t.*m).begin() + static_cast<std::ptrdiff_t>(i));
      if (!attempt(obs, t)) ++i;
    }
  };
  auto reduce_query = [&] {
    reduce(&Query::free_points);
    reduce(&Query::vertex_points);
    reduce(&Query::targets);
    reduce(&Query::sources);
  };
  reduce_query();
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < obs.size();) {
      std::vector<Polygon> o = obs;
      o.erase(o.begin() + static_cast<std::ptrdiff_t>(i));
      if (attempt(o, q))
        changed = true;
      else
        ++i;
    }
    // A hole can go when nothing else lies in it.
    for (std::size_t i = 0; i < obs.size(); ++i)
      for (std::size_t h = 0; h < obs[i].holes.size();) {
        bool empty = true;
        for (std::size_t j = 0; j < obs.size() && empty; ++j)
          if (j != i)
            for (const Point v : obs[j].outer)
              if (geom::locate(v, obs[i].holes[h]) != geom::Location::Outside) empty = false;
        std::vector<Polygon> o = obs;
        o[i].holes.erase(o[i].holes.begin() + static_cast<std::ptrdiff_t>(h));
        if (empty && attempt(o, q))
          changed = true;
        else
          ++h;
      }
  }
  reduce_query();
  Scene sc;
  failure = failure_on<M>(original.domain, obs, q, soft, &sc);
  std::ostringstream os;
  os << "  shrunk (" << attempts << " attempts) to:\n"
     << scene_cpp(sc) << "  " << M::kWavefront << " wf(domain, obstacles);\n"
     << query_cpp<M>(q) << "  failure:\n"
     << failure;
  return os.str();
}

template <class M>
std::string instance_report(const WavefrontCase& c, const Scene& sc, const Query& q,
                            const std::string& failure, bool do_shrink, bool soft = false) {
  std::ostringstream os;
  os << "seed " << c.seed << " (family " << c.family << M::kFamilyNote
     << "): wavefront and reference disagree\n"
     << failure << "  instance:\n"
     << scene_cpp(sc) << "  query:\n"
     << query_cpp<M>(q);
  if (do_shrink) os << shrink<M>(sc, q, soft);
  os << "  rerun alone: " << M::kSeedVariable << "=" << c.seed << "\n";
  return os.str();
}

// ---- crash reporting ----------------------------------------------------------------------

char g_crash_message[200];
volatile std::size_t g_crash_length = 0;

void write_crash_message() {
  if (g_crash_length > 0) {
    const ssize_t ignored = ::write(2, g_crash_message, g_crash_length);
    (void)ignored;
  }
}

extern "C" void on_crash_signal(int sig) {
  write_crash_message();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void install_crash_handler() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL}) std::signal(sig, on_crash_signal);
  // AddressSanitizer and UBSan (-fno-sanitize-recover) end the process without a signal (and
  // without calling a death callback for UBSan), so say how to find the seed.
  if (TAUT_WAVEFRONT_SANITIZED && !std::getenv("TAUT_WAVEFRONT_TRACE"))
    std::fprintf(stderr,
                 "(sanitizer build: if a sanitizer report ends this run, rerun with "
                 "TAUT_WAVEFRONT_TRACE=1 to see the seed it died on)\n");
}

void set_crash_seed(std::optional<u64> seed, WaveMetric metric = WaveMetric::L1) {
  if (!seed) {
    g_crash_length = 0;
    return;
  }
  const bool oct = metric == WaveMetric::Octilinear, l1 = metric == WaveMetric::L1;
  const int n = std::snprintf(g_crash_message, sizeof g_crash_message,
                              "\n*** crashed while checking %swavefront seed %llu (rerun alone: "
                              "%s=%llu)\n",
                              oct ? "octilinear " : l1 ? "" : "norm ", static_cast<unsigned long long>(*seed),
                              oct ? OctMetric::kSeedVariable
                              : l1 ? L1Metric::kSeedVariable
                                   : NormTestMetric<2>::kSeedVariable,
                              static_cast<unsigned long long>(*seed));
  g_crash_length = n > 0 ? static_cast<std::size_t>(n) : 0;
}

}  // namespace

// ---- public -------------------------------------------------------------------------------

void WavefrontTally::add(const WavefrontTally& o) {
  instances += o.instances;
  obstacle_vertices += o.obstacle_vertices;
  max_vertices = std::max(max_vertices, o.max_vertices);
  free_checks += o.free_checks;
  not_free += o.not_free;
  runs += o.runs;
  multi_source_runs += o.multi_source_runs;
  comparisons += o.comparisons;
  reachable += o.reachable;
  unreachable += o.unreachable;
  paths += o.paths;
  bends += o.bends;
  vertex_checks += o.vertex_checks;
  pinch_points += o.pinch_points;
  boundary_points += o.boundary_points;
  source_is_target += o.source_is_target;
  split_runs += o.split_runs;
  domain_corner_bends += o.domain_corner_bends;
  pinch_sources += o.pinch_sources;
  boundary_sources += o.boundary_sources;
  transformed += o.transformed;
  invalid_inputs += o.invalid_inputs;
  generator_errors += o.generator_errors;
  huge += o.huge;
  stats_issue_seeds += o.stats_issue_seeds;
  if (first_stats_issue.empty()) first_stats_issue = o.first_stats_issue;
  reference_seconds += o.reference_seconds;
  wavefront_seconds += o.wavefront_seconds;
  for (const auto& [k, v] : o.families) families[k] += v;
}

std::string WavefrontTally::summary() const {
  std::ostringstream os;
  os << instances << " instances (" << obstacle_vertices << " obstacle vertices, at most "
     << max_vertices << "), " << runs << " runs (" << multi_source_runs << " multi-source, "
     << split_runs << " with a free unreachable target), " << comparisons << " target distances ("
     << reachable << " reachable, " << unreachable << " unreachable, " << pinch_points
     << " at pinches, " << boundary_points << " on walls, " << source_is_target
     << " equal to a source), " << paths << " paths (" << bends << " bends), " << vertex_checks
     << " vertex distances, " << free_checks << " is_free (" << not_free << " not free); "
     << pinch_sources << " sources at pinches, " << boundary_sources << " on walls; " << transformed
     << " instances turned or mirrored, " << huge << " with huge coordinates; " << invalid_inputs
     << " invalid generated polygons dropped, " << generator_errors << " generator errors; "
     << domain_corner_bends << " path bends at a domain corner; " << stats_issue_seeds
     << " seeds with implausible stats; time in runs: reference " << reference_seconds
     << " s, wavefront " << wavefront_seconds << " s; families:";
  for (const auto& [k, v] : families) os << " " << k << " " << v;
  return os.str();
}

WavefrontCase make_wavefront_case(std::uint64_t seed) {
  Rand r(seed);
  const int scale = seed >= kLargeSeedBase ? 3 : 1;
  Draft d;
  WavefrontCase c;
  c.seed = seed;
  switch (seed % 9) {
    case 0:
      c.family = "gen-rects";
      fam_gen(r, d, io::GenKind::Rects, scale);
      break;
    case 1:
      c.family = "gen-polygons";
      fam_gen(r, d, io::GenKind::Polygons, scale);
      break;
    case 2:
      c.family = "gen-maze";
      fam_gen(r, d, io::GenKind::Maze, scale);
      break;
    case 3:
      c.family = "gen-degenerate";
      fam_gen(r, d, io::GenKind::Degenerate, scale);
      break;
    case 4:
      c.family = "grid-rects";
      fam_grid_rects(r, d, scale);
      break;
    case 5:
      c.family = "grid-diagonal";
      fam_grid_diagonal(r, d, scale);
      break;
    case 6:
      c.family = "rings";
      fam_rings(r, d, scale);
      break;
    case 7:
      c.family = "pinches";
      fam_pinches(r, d, scale);
      break;
    default:
      c.family = "fine";
      fam_fine(r, d, scale);
      break;
  }
  // One of the eight symmetries of the square (the families have preferred directions; the
  // wavefront has four diagonal directions to get right), and now and then coordinates scaled
  // up towards the limit 2^30 - 1 and moved off the origin.
  auto map_all = [&](auto&& f) {
    for (Polygon& p : d.inputs) {
      for (Point& v : p.outer) v = f(v);
      for (Ring& h : p.holes)
        for (Point& v : h) v = f(v);
    }
    for (Point& v : d.special) v = f(v);
    const Point a = f(d.domain.lo), b = f(d.domain.hi);
    d.domain = {P(std::min(a.x, b.x), std::min(a.y, b.y)),
                P(std::max(a.x, b.x), std::max(a.y, b.y))};
  };
  const int sym = static_cast<int>(r.range(0, 7));
  if (sym != 0) {
    map_all([&](Point p) {
      i64 x = p.x, y = p.y;
      if (sym & 1) x = -x;
      if (sym & 2) y = -y;
      if (sym & 4) std::swap(x, y);
      return P(x, y);
    });
    c.transformed = true;
  }
  if (r.chance(10)) {
    i64 m = 1;
    map_all([&](Point p) {
      m = std::max<i64>({m, std::abs(i64{p.x}), std::abs(i64{p.y})});
      return p;
    });
    const i64 f = std::max<i64>(1, geom::kMaxCoord / (2 * m));
    const i64 room = geom::kMaxCoord - f * m;  // |coordinate| <= f * m before the shift
    const i64 tx = r.chance(50) ? room : r.range(-room, room), ty = r.range(-room, room);
    map_all([&](Point p) { return P(f * p.x + tx, f * p.y + ty); });
    d.grid *= f;
    c.huge = true;
  }
  // Every family makes valid polygons; this only guards the contract of normalize_obstacles.
  std::vector<Polygon> valid;
  for (const Polygon& p : d.inputs) {
    if (geom::validate_polygon(p).empty())
      valid.push_back(p);
    else
      ++c.invalid_inputs;
  }
  geom::NormalizedObstacles n;
  try {
    n = geom::normalize_obstacles(valid, d.domain);
  } catch (const std::exception& e) {
    std::ostringstream os;
    os << "normalize_obstacles threw \"" << e.what() << "\" on the generated input (not a "
       << "wavefront bug):\n  const Box domain" << box_str(d.domain) << ";\n"
       << "  const std::vector<Polygon> inputs{\n";
    for (const Polygon& p : valid) os << "      " << polygon_cpp(p) << ",\n";
    os << "  };\n";
    throw std::runtime_error(os.str());
  }
  c.domain = n.domain;
  c.obstacles = n.obstacles;
  c.candidates = make_candidates(r, c.domain, c.obstacles, d.special, d.grid);
  c.special = d.special.size();
  return c;
}

namespace {

template <class M>
std::string check_seed(std::uint64_t seed, WavefrontTally& tally, bool verbose,
                       bool shrink_failures) {
  using Reference = typename M::Reference;
  using Wavefront = typename M::Wavefront;
  WavefrontCase c;
  try {
    c = make_wavefront_case(seed);
  } catch (const std::exception& e) {
    ++tally.generator_errors;
    return "seed " + std::to_string(seed) + ": " + e.what();
  }
  std::ostream* log = verbose ? &std::cout : nullptr;
  const std::vector<std::string> problems = oracle::check_obstacles(c.obstacles, c.domain);
  if (!problems.empty())
    return "seed " + std::to_string(seed) + " (family " + c.family +
           "): normalize_obstacles broke its invariants (not a wavefront bug): " + problems[0] +
           "\n";
  const Reference ref(c.domain, c.obstacles);
  if (!ref.problems().empty())
    return "seed " + std::to_string(seed) + " (family " + c.family +
           "): the reference found the input inconsistent (not a wavefront bug): " +
           ref.problems()[0] + "\n";
  const Scene sc = make_scene(c.domain, c.obstacles, ref);
  ++tally.instances;
  tally.transformed += c.transformed;
  tally.invalid_inputs += c.invalid_inputs;
  tally.huge += c.huge;
  ++tally.families[c.family];
  tally.obstacle_vertices += static_cast<i64>(sc.vertices.size());
  tally.max_vertices = std::max<i64>(tally.max_vertices, static_cast<i64>(sc.vertices.size()));
  if (log) {
    *log << "seed " << seed << " family " << c.family << M::kFamilyNote
         << (c.transformed ? " (turned/mirrored)" : "") << (c.huge ? " (huge coordinates)" : "")
         << "\n"
         << scene_cpp(sc);
    *log << "  candidates " << points_str(c.candidates) << " (first " << c.special << " special)\n";
    log->flush();
  }

  std::optional<Wavefront> wf;
  try {
    wf.emplace(sc.domain, sc.obstacles);
  } catch (const std::exception& e) {
    Query none;
    none.run = false;
    return instance_report<M>(
        c, sc, none,
        std::string("exception from the ") + M::kWavefront + " constructor: " + e.what() + "\n",
        false);
  }
  Rand r(seed ^ 0x5deece66dULL);
  bool stats_noted = false;
  auto check = [&](const Query& q) -> std::string {
    if (log) *log << "query:\n" << query_cpp<M>(q);
    std::string stats_bad;
    const std::string f = guarded_check<M>(sc, ref, *wf, q, &tally, log, &stats_bad);
    if (log) log->flush();
    if (!stats_bad.empty() && !stats_noted) {
      stats_noted = true;
      ++tally.stats_issue_seeds;
      if (tally.first_stats_issue.empty() || log)
        tally.first_stats_issue = instance_report<M>(c, sc, q, stats_bad, shrink_failures, true);
    }
    return f.empty() ? f : instance_report<M>(c, sc, q, f, shrink_failures);
  };

  // is_free on every candidate, free or not.
  Query q0;
  q0.run = false;
  q0.free_points = c.candidates;
  if (c.domain.lo.x > -geom::kMaxCoord)  // just outside the domain
    q0.free_points.push_back(P(c.domain.lo.x - 1, c.domain.lo.y));
  if (c.domain.hi.y < geom::kMaxCoord)
    q0.free_points.push_back(P(c.domain.hi.x, c.domain.hi.y + 1));
  if (auto f = check(q0); !f.empty()) return f;
  std::vector<Point> free_pts, blocked, special_free;
  for (std::size_t i = 0; i < c.candidates.size(); ++i) {
    const Point p = c.candidates[i];
    if (ref.is_free(p)) {
      free_pts.push_back(p);
      if (i < c.special) special_free.push_back(p);
    } else {
      blocked.push_back(p);
    }
  }
  if (free_pts.empty()) return "";
  const std::vector<Point> all_vertices(sc.vertices.begin(), sc.vertices.end());
  auto pick_source = [&] {
    return !special_free.empty() && r.chance(35) ? r.pick(special_free) : r.pick(free_pts);
  };
  auto add_targets = [&](Query& q, int lo, int hi) {
    for (i64 k = r.range(lo, hi); k > 0; --k) q.targets.push_back(r.pick(free_pts));
    if (!blocked.empty() && r.chance(50)) q.targets.push_back(r.pick(blocked));
    if (r.chance(25)) q.targets.push_back(r.pick(q.sources));
    for (std::size_t i = q.targets.size(); i > 1; --i)
      std::swap(q.targets[i - 1], q.targets[static_cast<std::size_t>(r.next() % i)]);
  };

  // A: one source, many targets; a full run checks every vertex distance.
  Query a;
  a.sources = {pick_source()};
  add_targets(a, 5, 10);
  a.stop_early = r.chance(50);
  if (!a.stop_early || r.chance(30)) a.vertex_points = all_vertices;
  if (auto f = check(a); !f.empty()) return f;

  // The object survives being moved (and keeps answering).
  {
    Wavefront moved(std::move(*wf));
    *wf = std::move(moved);
  }

  // B: two to four sources (sometimes one not free, sometimes a duplicate).
  Query b;
  for (i64 k = r.range(2, 4); k > 0; --k) b.sources.push_back(pick_source());
  if (!blocked.empty() && r.chance(15)) b.sources.push_back(r.pick(blocked));
  if (r.chance(10)) b.sources.push_back(b.sources[0]);
  add_targets(b, 3, 7);
  b.stop_early = r.chance(60);
  if (!b.stop_early)
    for (int k = 0; k < 8 && !all_vertices.empty(); ++k)
      b.vertex_points.push_back(r.pick(all_vertices));
  if (auto f = check(b); !f.empty()) return f;

  // C (now and then): nothing can start (no free source) or nothing is asked.
  if (r.chance(15)) {
    Query q;
    if (!blocked.empty() && r.chance(60)) q.sources = {r.pick(blocked)};
    q.targets = {r.pick(free_pts), r.pick(free_pts)};
    q.stop_early = r.chance(50);
    if (auto f = check(q); !f.empty()) return f;
  }
  if (r.chance(10)) {
    Query q;
    q.sources = {pick_source()};
    q.stop_early = false;
    q.vertex_points = all_vertices;
    if (auto f = check(q); !f.empty()) return f;
  }

  // The convenience function (L1 only: there is no octilinear one).
  if constexpr (M::kMetric == WaveMetric::L1) {
    const Point s = pick_source(), t = r.pick(free_pts);
    const Dist want = ref.distance(s, t);
    Dist got;
    std::string err;
    try {
      got = router::l1_distance(sc.domain, sc.obstacles, s, t);
    } catch (const std::exception& e) {
      err = e.what();
    }
    if (log)
      *log << "l1_distance" << pt(s) << pt(t) << ": reference " << dist_str(want) << ", wavefront "
           << dist_str(got) << "\n";
    if (got != want || !err.empty()) {
      Query q;
      q.sources = {s};
      q.targets = {t};
      return instance_report<M>(c, sc, q,
                                "router::l1_distance" + pt(s) + pt(t) + ": reference " +
                                    dist_str(want) + ", l1_distance " + dist_str(got) +
                                    (err.empty() ? "" : " exception " + err) + "\n",
                                shrink_failures);
    }
  }
  (void)wf->memory_bytes();
  return "";
}

}  // namespace

std::string check_wavefront_seed(std::uint64_t seed, WavefrontTally& tally, bool verbose,
                                 bool shrink_failures, WaveMetric metric) {
  switch (metric) {
    case WaveMetric::Octilinear: return check_seed<OctMetric>(seed, tally, verbose, shrink_failures);
    case WaveMetric::Farey2: return check_seed<NormTestMetric<2>>(seed, tally, verbose, shrink_failures);
    case WaveMetric::Farey3: return check_seed<NormTestMetric<3>>(seed, tally, verbose, shrink_failures);
    case WaveMetric::Farey4: return check_seed<NormTestMetric<4>>(seed, tally, verbose, shrink_failures);
    case WaveMetric::L1: break;
  }
  return check_seed<L1Metric>(seed, tally, verbose, shrink_failures);
}

WavefrontSweep run_wavefront_seeds(const std::vector<std::uint64_t>& seeds, std::size_t max_reports,
                                   WaveMetric metric) {
  install_crash_handler();
  const bool trace = std::getenv("TAUT_WAVEFRONT_TRACE") != nullptr;
  WavefrontSweep out;
  const auto start = std::chrono::steady_clock::now();
  for (const u64 seed : seeds) {
    set_crash_seed(seed, metric);
    if (trace)
      std::fprintf(stderr, "%swavefront seed %llu\n",
                   metric == WaveMetric::Octilinear ? "octilinear " : "",
                   static_cast<unsigned long long>(seed));
    const std::string f =
        check_wavefront_seed(seed, out.tally, false, out.reports.size() < max_reports, metric);
    if (!f.empty()) {
      out.failed_seeds.push_back(seed);
      if (out.reports.size() < max_reports) out.reports.push_back(f);
    }
  }
  set_crash_seed(std::nullopt);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

WavefrontSweep run_wavefront_sweep(std::uint64_t first, std::int64_t count, std::size_t max_reports,
                                   WaveMetric metric) {
  std::vector<u64> seeds;
  for (i64 i = 0; i < count; ++i) seeds.push_back(first + static_cast<u64>(i));
  return run_wavefront_seeds(seeds, max_reports, metric);
}

std::optional<std::uint64_t> wavefront_seed_from_env(WaveMetric metric) {
  const char* s = std::getenv(metric == WaveMetric::Octilinear ? OctMetric::kSeedVariable
                              : metric == WaveMetric::L1       ? L1Metric::kSeedVariable
                                                               : NormTestMetric<2>::kSeedVariable);
  if (!s || !*s) return std::nullopt;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(s, &end, 10);
  if (end == s || *end != '\0') return std::nullopt;
  return v;
}

void expect_clean_sweep(const WavefrontSweep& sw) {
  for (const std::string& r : sw.reports) ADD_FAILURE() << r;
  if (!sw.failed_seeds.empty()) {
    std::string list;
    for (std::size_t i = 0; i < sw.failed_seeds.size() && i < 200; ++i)
      list += " " + std::to_string(sw.failed_seeds[i]);
    ADD_FAILURE() << sw.failed_seeds.size() << " failing seed(s):" << list;
  }
  EXPECT_EQ(sw.tally.invalid_inputs, 0) << "the generator made invalid polygons";
  EXPECT_EQ(sw.tally.stats_issue_seeds, 0) << "implausible WavefrontStats, first:\n"
                                           << sw.tally.first_stats_issue;
}

void run_random_wavefront_test(WaveMetric metric) {
  if (const auto seed = wavefront_seed_from_env(metric)) {
    WavefrontTally tally;
    EXPECT_EQ(check_wavefront_seed(*seed, tally, /*verbose=*/true, /*shrink_failures=*/true, metric), "");
    std::printf("%s\n", tally.summary().c_str());
    return;
  }
  // Under the sanitizers an eighth of the seeds (support/sanitized.h); the thresholds scale with them.
  const auto share = [](std::int64_t n) { return sanitized_share(n, 4); };
  const WavefrontSweep sw = run_wavefront_sweep(1, share(2000), 3, metric);
  std::printf("%s\n%.2f s\n", sw.tally.summary().c_str(), sw.seconds);
  expect_clean_sweep(sw);
  // The generator exercises what it is meant to (the counts that depend on the wavefront's
  // answers, paths and bends, only count agreeing targets; the others are the reference's).
  const WavefrontTally& t = sw.tally;
  EXPECT_EQ(t.instances, share(2000));
  for (const char* f : {"gen-rects", "gen-polygons", "gen-maze", "gen-degenerate", "grid-rects",
                        "grid-diagonal", "rings", "pinches", "fine"}) {
    EXPECT_GE(t.families.count(f) ? t.families.at(f) : 0, share(200)) << f;
  }
  EXPECT_GE(t.comparisons, share(20000));
  EXPECT_GE(t.multi_source_runs, share(1500));
  EXPECT_GE(t.unreachable, share(500));
  EXPECT_GE(t.split_runs, share(200));
  EXPECT_GE(t.pinch_points, share(300));
  EXPECT_GE(t.boundary_points, share(3000));
  EXPECT_GE(t.source_is_target, share(300));
  EXPECT_GE(t.vertex_checks, share(20000));
  EXPECT_GE(t.not_free, share(5000));
  EXPECT_GE(t.bends, share(5000));
}

}  // namespace taut::test
