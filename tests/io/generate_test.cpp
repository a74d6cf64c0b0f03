// generate_layout: reproducible bytes, vertex count within 10% of `size`, every polygon simple
// (own O(n^2) exact check), every pin outside every blockage interior (own brute-force point
// location), everything inside the boundary, and validate_layout() finds no error.
#include <gtest/gtest.h>

#include <chrono>
#include <set>

#include "io/generate.h"
#include "io/layout_writer.h"
#include "io/validate_layout.h"

namespace taut::io {
namespace generate_test {

using i128 = __int128;
using Ring = std::vector<Point>;

i128 cross(Point o, Point a, Point b) {
  return (i128{a.x} - o.x) * (i128{b.y} - o.y) - (i128{a.y} - o.y) * (i128{b.x} - o.x);
}
int sgn(i128 v) { return (v > 0) - (v < 0); }
bool on_closed_segment(Point p, Point a, Point b) {
  return cross(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}
bool segments_meet(Point a, Point b, Point c, Point d) {
  const int d1 = sgn(cross(a, b, c)), d2 = sgn(cross(a, b, d));
  const int d3 = sgn(cross(c, d, a)), d4 = sgn(cross(c, d, b));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return on_closed_segment(c, a, b) || on_closed_segment(d, a, b) || on_closed_segment(a, c, d) ||
         on_closed_segment(b, c, d);
}

// Simple ring: no zero-length edges after dropping repeats, non-adjacent edges disjoint,
// adjacent edges meet only at their shared vertex (no spike), non-zero area.
std::string ring_problem(const Ring& ring) {
  Ring r;
  for (Point p : ring)
    if (r.empty() || r.back() != p) r.push_back(p);
  while (r.size() > 1 && r.front() == r.back()) r.pop_back();
  const std::size_t n = r.size();
  if (n < 3) return "fewer than 3 distinct vertices";
  i128 area = 0;
  for (std::size_t i = 0; i < n; ++i) area += cross(Point{0, 0}, r[i], r[(i + 1) % n]);
  if (area == 0) return "zero area";
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = r[i], b = r[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Point c = r[j], d = r[(j + 1) % n];
      const bool next = j == i + 1, prev = (j + 1) % n == i;
      if (next || prev) {
        // Adjacent: the far endpoint of one must not lie on the other (spike / overlap).
        const Point far_i = next ? a : b;  // endpoint of edge i not shared with edge j
        const Point far_j = next ? d : c;  // endpoint of edge j not shared with edge i
        if (on_closed_segment(far_j, a, b) || on_closed_segment(far_i, c, d))
          return "spike at edge " + std::to_string(i);
        continue;
      }
      if (segments_meet(a, b, c, d))
        return "edges " + std::to_string(i) + " and " + std::to_string(j) + " meet";
    }
  }
  return {};
}

// -1 outside, 0 boundary, 1 inside; crossing number with exact integer tests.
int where(Point p, const Ring& r) {
  bool in = false;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const Point a = r[i], b = r[(i + 1) % n];
    if (on_closed_segment(p, a, b)) return 0;
    if ((a.y > p.y) != (b.y > p.y)) {
      const i128 c = cross(a, b, p);
      if ((b.y > a.y) == (c > 0)) in = !in;
    }
  }
  return in ? 1 : -1;
}
bool interior(Point p, const Shape& s) {
  if (s.kind == Shape::Kind::Rect)
    return s.rect.lo.x < p.x && p.x < s.rect.hi.x && s.rect.lo.y < p.y && p.y < s.rect.hi.y;
  if (where(p, s.polygon.outer) != 1) return false;
  for (const Ring& h : s.polygon.holes)
    if (where(p, h) != -1) return false;
  return true;
}

std::string polygon_problem(const geom::Polygon& poly) {
  if (auto e = ring_problem(poly.outer); !e.empty()) return "outer: " + e;
  for (std::size_t h = 0; h < poly.holes.size(); ++h) {
    const Ring& hole = poly.holes[h];
    if (auto e = ring_problem(hole); !e.empty()) return "hole: " + e;
    for (Point p : hole)
      if (where(p, poly.outer) != 1) return "hole vertex not strictly inside the outer ring";
    for (std::size_t i = 0; i < hole.size(); ++i)
      for (std::size_t j = 0; j < poly.outer.size(); ++j)
        if (segments_meet(hole[i], hole[(i + 1) % hole.size()], poly.outer[j],
                          poly.outer[(j + 1) % poly.outer.size()]))
          return "hole edge meets outer edge";
  }
  return {};
}

std::int64_t vertex_count(const Layout& l) {
  std::int64_t v = 0;
  for (const Blockage& b : l.blockages)
    for (const Shape& s : b.shapes) {
      if (s.kind == Shape::Kind::Rect) {
        v += 4;
        continue;
      }
      v += static_cast<std::int64_t>(s.polygon.outer.size());
      for (const Ring& h : s.polygon.holes) v += static_cast<std::int64_t>(h.size());
    }
  return v;
}

GenOptions options(GenKind kind, std::int64_t size, int nets, std::uint64_t seed) {
  GenOptions o;
  o.kind = kind;
  o.size = size;
  o.nets = nets;
  o.seed = seed;
  return o;
}

const std::vector<GenKind> kKinds = {GenKind::Rects, GenKind::Polygons, GenKind::Maze,
                                     GenKind::Degenerate, GenKind::Channel};

TEST(Generate, KindNames) {
  for (const std::string& name : gen_kind_names()) {
    ASSERT_TRUE(parse_gen_kind(name).has_value()) << name;
    EXPECT_EQ(gen_kind_name(*parse_gen_kind(name)), name);
  }
  EXPECT_EQ(gen_kind_names().size(), 5u);
  EXPECT_FALSE(parse_gen_kind("Rects").has_value());
  EXPECT_FALSE(parse_gen_kind("").has_value());
}

TEST(Generate, SameSeedSameBytesOtherSeedOtherBytes) {
  for (GenKind kind : kKinds) {
    SCOPED_TRACE(gen_kind_name(kind));
    const std::string a = layout_to_xml(generate_layout(options(kind, 2000, 8, 7)));
    const std::string b = layout_to_xml(generate_layout(options(kind, 2000, 8, 7)));
    const std::string c = layout_to_xml(generate_layout(options(kind, 2000, 8, 8)));
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
  }
}

TEST(Generate, SizeWithinTenPercent) {
  for (GenKind kind : kKinds)
    for (std::int64_t size : {200, 1000, 5000, 30000})
      for (std::uint64_t seed : {1u, 2u}) {
        SCOPED_TRACE(gen_kind_name(kind) + " size " + std::to_string(size) + " seed " +
                     std::to_string(seed));
        const std::int64_t v = vertex_count(generate_layout(options(kind, size, 0, seed)));
        EXPECT_GE(v * 10, size * 9) << v;
        EXPECT_LE(v * 10, size * 11) << v;
      }
}

// Pins free and distinct, polygons simple, everything in the boundary; validate_layout agrees.
TEST(Generate, ValidLayouts) {
  const std::uint64_t base = 1000;
  for (GenKind kind : kKinds)
    for (std::uint64_t k = 0; k < 6; ++k) {
      const std::uint64_t seed = base + k;
      const std::int64_t size = k < 3 ? 150 : 1200;
      SCOPED_TRACE(gen_kind_name(kind) + " size " + std::to_string(size) + " seed " +
                   std::to_string(seed));
      const Layout l = generate_layout(options(kind, size, 25, seed));
      ASSERT_TRUE(l.boundary.has_value());
      const Box bb = l.boundary->box;
      auto in_box = [&](Point p) {
        return bb.lo.x <= p.x && p.x <= bb.hi.x && bb.lo.y <= p.y && p.y <= bb.hi.y;
      };
      std::set<std::string> ids;
      for (const Blockage& b : l.blockages) {
        EXPECT_TRUE(ids.insert(b.id).second) << "duplicate id " << b.id;
        for (const Shape& s : b.shapes) {
          if (s.kind == Shape::Kind::Rect) {
            EXPECT_LT(s.rect.lo.x, s.rect.hi.x);
            EXPECT_LT(s.rect.lo.y, s.rect.hi.y);
            EXPECT_TRUE(in_box(s.rect.lo) && in_box(s.rect.hi)) << b.id;
          } else {
            EXPECT_EQ(polygon_problem(s.polygon), "") << b.id;
            for (Point p : s.polygon.outer) EXPECT_TRUE(in_box(p)) << b.id;
          }
        }
      }
      ASSERT_EQ(l.nets.size(), 25u);
      std::set<Point> pins;
      for (const Net& n : l.nets) {
        ASSERT_EQ(n.pins.size(), 2u);
        for (const Pin& p : n.pins) {
          ASSERT_TRUE(p.point.has_value());
          EXPECT_TRUE(pins.insert(*p.point).second) << "two pins at the same point";
          EXPECT_TRUE(in_box(*p.point));
          for (const Blockage& b : l.blockages)
            for (const Shape& s : b.shapes)
              EXPECT_FALSE(interior(*p.point, s))
                  << n.name << "." << p.name << " (" << p.point->x << "," << p.point->y
                  << ") inside " << b.id;
        }
      }
      const auto diags = validate_layout(l);
      std::string text;
      for (const auto& d : diags) text += format(d) + "\n";
      EXPECT_FALSE(has_error(diags)) << text;
    }
}

// Nets of 2..20 pins with rules: pin counts in range (both ends drawn), every pin after a net's
// first within a tenth of the layout's side of it, pins of different nets 2(w + s) + 2 apart,
// <rules> written, the layout valid, the same options the same bytes.
TEST(Generate, MultiPinNetsWithRules) {
  for (GenKind kind : {GenKind::Rects, GenKind::Maze, GenKind::Degenerate})
    for (std::uint64_t seed : {3u, 4u}) {
      SCOPED_TRACE(gen_kind_name(kind) + " seed " + std::to_string(seed));
      GenOptions o = options(kind, 3000, 40, seed);
      o.min_pins = 2;
      o.max_pins = 20;
      o.wire_width = 6;
      o.spacing = 4;
      const Layout l = generate_layout(o);
      EXPECT_EQ(layout_to_xml(l), layout_to_xml(generate_layout(o)));
      ASSERT_TRUE(l.rules.has_value());
      EXPECT_EQ(l.rules->wire_width, 6);
      EXPECT_EQ(l.rules->spacing, 4);
      ASSERT_EQ(l.nets.size(), 40u);
      const Box bb = l.boundary->box;
      const std::int64_t reach = std::max<std::int64_t>((std::int64_t{bb.hi.x} - bb.lo.x) / 20, 100);
      std::set<std::size_t> counts;
      for (std::size_t i = 0; i < l.nets.size(); ++i) {
        const Net& n = l.nets[i];
        EXPECT_GE(n.pins.size(), 2u);
        EXPECT_LE(n.pins.size(), 20u);
        counts.insert(n.pins.size());
        for (const Pin& p : n.pins) {
          if (kind != GenKind::Degenerate) {  // degenerate pins sit on a coarse grid anywhere
            EXPECT_LE(std::abs(p.point->x - n.pins[0].point->x), reach) << n.name;
            EXPECT_LE(std::abs(p.point->y - n.pins[0].point->y), reach) << n.name;
          }
          for (std::size_t j = 0; j < i; ++j)
            for (const Pin& q : l.nets[j].pins)
              EXPECT_FALSE(std::abs(p.point->x - q.point->x) < 22 && std::abs(p.point->y - q.point->y) < 22)
                  << n.name << " and " << l.nets[j].name;
        }
      }
      EXPECT_GT(counts.size(), 8u);  // the counts spread over the range
      EXPECT_FALSE(has_error(validate_layout(l)));
    }
  // the default, two pins, keeps its names and bytes whatever the new options' defaults
  EXPECT_EQ(generate_layout(options(GenKind::Rects, 500, 3, 9)).nets[0].pins[1].name, "b");
}

// Maze walls: rects that never overlap, touch along edges, and leave a connected corridor.
TEST(Generate, MazeWallsTouchWithoutOverlap) {
  const Layout l = generate_layout(options(GenKind::Maze, 800, 0, 3));
  std::vector<Box> r;
  for (const Blockage& b : l.blockages) {
    ASSERT_EQ(b.shapes.size(), 1u);
    ASSERT_EQ(b.shapes[0].kind, Shape::Kind::Rect);
    r.push_back(b.shapes[0].rect);
  }
  int touching_edges = 0;
  for (std::size_t i = 0; i < r.size(); ++i)
    for (std::size_t j = i + 1; j < r.size(); ++j) {
      const int ox = std::min(r[i].hi.x, r[j].hi.x) - std::max(r[i].lo.x, r[j].lo.x);
      const int oy = std::min(r[i].hi.y, r[j].hi.y) - std::max(r[i].lo.y, r[j].lo.y);
      EXPECT_FALSE(ox > 0 && oy > 0) << "walls " << i << " and " << j << " overlap";
      if ((ox == 0 && oy > 0) || (oy == 0 && ox > 0)) ++touching_edges;
    }
  EXPECT_GT(touching_edges, static_cast<int>(r.size()) / 2);
}

// Degenerate layouts really are degenerate: shared coordinates and touching shapes.
TEST(Generate, DegenerateHasTouchingShapes) {
  const Layout l = generate_layout(options(GenKind::Degenerate, 2000, 0, 5));
  std::vector<Box> boxes;
  for (const Blockage& b : l.blockages)
    for (const Shape& s : b.shapes) {
      if (s.kind == Shape::Kind::Rect) {
        boxes.push_back(s.rect);
      } else {
        Box bb{s.polygon.outer[0], s.polygon.outer[0]};
        for (Point p : s.polygon.outer) {
          bb.lo = {std::min(bb.lo.x, p.x), std::min(bb.lo.y, p.y)};
          bb.hi = {std::max(bb.hi.x, p.x), std::max(bb.hi.y, p.y)};
        }
        boxes.push_back(bb);
      }
    }
  int corner_touch = 0, edge_touch = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const int ox = std::min(boxes[i].hi.x, boxes[j].hi.x) - std::max(boxes[i].lo.x, boxes[j].lo.x);
      const int oy = std::min(boxes[i].hi.y, boxes[j].hi.y) - std::max(boxes[i].lo.y, boxes[j].lo.y);
      corner_touch += ox == 0 && oy == 0;
      edge_touch += (ox == 0 && oy > 0) || (oy == 0 && ox > 0);
    }
  EXPECT_GT(corner_touch, 0);
  EXPECT_GT(edge_touch, 0);
}

TEST(Generate, ZeroNetsAndTinySizes) {
  for (GenKind kind : kKinds)
    for (std::int64_t size : {0, 1, 3, 4}) {
      SCOPED_TRACE(gen_kind_name(kind) + " size " + std::to_string(size));
      const Layout l = generate_layout(options(kind, size, 3, 1));
      EXPECT_FALSE(l.blockages.empty());
      EXPECT_EQ(l.nets.size(), 3u);
      EXPECT_FALSE(has_error(validate_layout(l)));
    }
}

// A million vertices: reported, not asserted (machines differ); the budget is < 1 s in Release.
TEST(Generate, MillionVerticesTiming) {
#ifdef NDEBUG
  const std::int64_t size = 1000000;
#else
  const std::int64_t size = 100000;
#endif
  for (GenKind kind : kKinds) {
    const auto t0 = std::chrono::steady_clock::now();
    const Layout l = generate_layout(options(kind, size, 100, 1));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::int64_t v = vertex_count(l);
    std::cout << gen_kind_name(kind) << ": " << v << " vertices in " << s << " s\n";
    EXPECT_GE(v * 10, size * 9);
    EXPECT_LE(v * 10, size * 11);
  }
}

}  // namespace generate_test
}  // namespace taut::io
