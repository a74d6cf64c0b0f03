// Tests of validate_layout: names, pins against blockages (the union of their shapes) and the
// boundary, sketches, routes, in-memory sanity. Random cases over integer rectangles are checked
// against a brute-force reference on unit cells; polygon cases are drawn by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <random>
#include <tuple>
#include <string>
#include <vector>

#include "geom/validate.h"
#include "io/validate_layout.h"

namespace validate_test {
using taut::Diagnostic;
using taut::Severity;
using taut::geom::Point;
using taut::geom::Ring;
using namespace taut::io;

// A tiny builder so each test reads as a drawing.
struct L {
  Layout l;
  int next_line = 10;
  L& boundary(int x0, int y0, int x1, int y1) {
    l.boundary = Boundary{{{x0, y0}, {x1, y1}}, 2};
    return *this;
  }
  L& rect(const std::string& id, int x0, int y0, int x1, int y1) {
    Blockage b;
    b.id = id;
    b.line = next_line++;
    Shape s;
    s.rect = {{x0, y0}, {x1, y1}};
    s.line = b.line;
    b.shapes.push_back(s);
    l.blockages.push_back(b);
    return *this;
  }
  // Adds a shape to the last blockage.
  L& also_rect(int x0, int y0, int x1, int y1) {
    Shape s;
    s.rect = {{x0, y0}, {x1, y1}};
    s.line = next_line++;
    l.blockages.back().shapes.push_back(s);
    return *this;
  }
  L& poly(const std::string& id, Ring outer, std::vector<Ring> holes = {}) {
    Blockage b;
    b.id = id;
    b.line = next_line++;
    Shape s;
    s.kind = Shape::Kind::Polygon;
    s.polygon.outer = std::move(outer);
    s.polygon.holes = std::move(holes);
    s.line = b.line;
    for (std::size_t k = 0; k < s.polygon.holes.size(); ++k) s.hole_lines.push_back(next_line++);
    b.shapes.push_back(s);
    l.blockages.push_back(b);
    return *this;
  }
  L& net(const std::string& name) {
    Net n;
    n.name = name;
    n.line = next_line++;
    l.nets.push_back(n);
    return *this;
  }
  L& pin(const std::string& name, int x, int y) {
    Pin p;
    p.name = name;
    p.point = Point{x, y};
    p.line = next_line++;
    l.nets.back().pins.push_back(p);
    return *this;
  }
  L& rect_pin(const std::string& name, int x0, int y0, int x1, int y1) {
    Pin p;
    p.name = name;
    Shape s;
    s.rect = {{x0, y0}, {x1, y1}};
    s.line = p.line = next_line++;
    p.shape = s;
    l.nets.back().pins.push_back(p);
    return *this;
  }
  L& poly_pin(const std::string& name, Ring outer) {
    Pin p;
    p.name = name;
    Shape s;
    s.kind = Shape::Kind::Polygon;
    s.polygon.outer = std::move(outer);
    s.line = p.line = next_line++;
    p.shape = s;
    l.nets.back().pins.push_back(p);
    return *this;
  }
  L& sketch(std::vector<Point> pts) {
    l.nets.back().sketch = Sketch{std::move(pts), next_line++};
    return *this;
  }
  L& route(const std::string& net) {
    if (!l.routes) l.routes = Routes{};
    Route r;
    r.net = net;
    r.status = "failed";
    r.line = next_line++;
    l.routes->routes.push_back(r);
    return *this;
  }
};

std::string dump(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) s += "  " + taut::format(d) + "\n";
  return s;
}

std::vector<Diagnostic> with_code(const std::vector<Diagnostic>& ds, const std::string& code) {
  std::vector<Diagnostic> v;
  for (const auto& d : ds)
    if (d.code == code) v.push_back(d);
  return v;
}

// ---------------------------------------------------------------------------------------------
// Point pins against unions of rectangles: random, against unit cells.
//
// Reference: with integer rectangles, each unit cell is either covered or not; an integer point
// is in the interior of the union exactly when its 4 incident cells are all covered.

TEST(ValidatePins, PointPinsAgainstRandomRectsMatchCellReference) {
  const unsigned base_seed = 12345;
  int interior_cases = 0, boundary_cases = 0;
  for (unsigned it = 0; it < 1500; ++it) {
    const unsigned seed = base_seed + it;
    std::mt19937 rng(seed);
    L b;
    struct R { int x0, y0, x1, y1; std::size_t blockage; };
    std::vector<R> rects;
    const int nb = 1 + static_cast<int>(rng() % 6);
    for (int i = 0; i < nb; ++i) {
      auto coord = [&] { return static_cast<int>(rng() % 9); };
      int x0 = coord(), x1 = coord(), y0 = coord(), y1 = coord();
      if (x0 == x1) ++x1;
      if (y0 == y1) ++y1;
      if (x0 > x1) std::swap(x0, x1);
      if (y0 > y1) std::swap(y0, y1);
      if (i > 0 && rng() % 3 == 0) {
        b.also_rect(x0, y0, x1, y1);  // same blockage, second shape
      } else {
        b.rect("b" + std::to_string(i), x0, y0, x1, y1);
      }
      rects.push_back({x0, y0, x1, y1, b.l.blockages.size() - 1});
    }
    b.net("n");
    std::vector<Point> pins;
    for (int k = 0; k < 12; ++k) {
      pins.push_back({static_cast<int>(rng() % 11) - 1, static_cast<int>(rng() % 11) - 1});
      b.pin("p" + std::to_string(k), pins.back().x, pins.back().y);
    }
    const auto ds = validate_layout(b.l);
    SCOPED_TRACE("seed " + std::to_string(seed) + "\n" + dump(ds));
    for (std::size_t k = 0; k < pins.size(); ++k) {
      const Point p = pins[k];
      auto covered = [&](int cx, int cy) {  // unit cell [cx, cx+1] x [cy, cy+1]
        for (const R& r : rects)
          if (r.x0 <= cx && cx + 1 <= r.x1 && r.y0 <= cy && cy + 1 <= r.y1) return true;
        return false;
      };
      const bool interior = covered(p.x - 1, p.y - 1) && covered(p.x, p.y - 1) && covered(p.x - 1, p.y) &&
                            covered(p.x, p.y);
      const std::string pin_ctx = "pin \"p" + std::to_string(k) + "\" at";
      std::optional<Diagnostic> found;
      for (const auto& d : with_code(ds, "LAYOUT-0004"))
        if (d.message.find(pin_ctx) != std::string::npos) found = d;
      EXPECT_EQ(found.has_value(), interior) << "pin " << k << " at " << p.x << "," << p.y;
      if (!found) continue;
      ++interior_cases;
      EXPECT_EQ(found->line, b.l.nets[0].pins[k].line);
      EXPECT_EQ(found->severity, Severity::Error);
      // Strictly inside one rect: that rect's blockage (first in file order) is named.
      for (const R& r : rects)
        if (r.x0 < p.x && p.x < r.x1 && r.y0 < p.y && p.y < r.y1) {
          EXPECT_NE(found->message.find("blockage \"" + b.l.blockages[r.blockage].id + "\""), std::string::npos);
          break;
        }
      bool strictly = false;
      for (const R& r : rects) strictly |= r.x0 < p.x && p.x < r.x1 && r.y0 < p.y && p.y < r.y1;
      boundary_cases += !strictly;
    }
  }
  // The random cases do reach both kinds of interior point.
  EXPECT_GT(interior_cases, 500);
  EXPECT_GT(boundary_cases, 50);
}

// ---------------------------------------------------------------------------------------------
// Point pins against polygons, drawn.

TEST(ValidatePins, TwoTrianglesMakeASquare) {
  //  (0,4) +-----+ (4,4)     the diagonal is shared; a pin on it is inside the union,
  //        | \ B |           at a corner of the square or on its border it is not
  //        | A \ |
  //  (0,0) +-----+ (4,0)
  L b;
  b.poly("A", {{0, 0}, {4, 0}, {0, 4}}).poly("B", {{4, 0}, {4, 4}, {0, 4}});
  b.net("n").pin("diag", 2, 2).pin("corner", 4, 0).pin("edge", 2, 0).pin("out", 5, 5);
  const auto ds = validate_layout(b.l);
  const auto hits = with_code(ds, "LAYOUT-0004");
  ASSERT_EQ(hits.size(), 1u) << dump(ds);
  EXPECT_NE(hits[0].message.find("pin \"diag\""), std::string::npos);
  EXPECT_NE(hits[0].message.find("\"A\", \"B\""), std::string::npos);
}

TEST(ValidatePins, PinwheelOfFourTriangles) {
  // Four triangles around (2,2), each with the centre as a vertex: the centre is covered all
  // around. Removing one triangle opens a gap.
  L full, open;
  const std::vector<Ring> tris = {{{0, 0}, {4, 0}, {2, 2}}, {{4, 0}, {4, 4}, {2, 2}},
                                  {{4, 4}, {0, 4}, {2, 2}}, {{0, 4}, {0, 0}, {2, 2}}};
  for (int i = 0; i < 4; ++i) {
    full.poly("t" + std::to_string(i), tris[i]);
    if (i != 2) open.poly("t" + std::to_string(i), tris[i]);
  }
  full.net("n").pin("c", 2, 2).pin("far", 9, 9);
  open.net("n").pin("c", 2, 2).pin("far", 9, 9);
  EXPECT_EQ(with_code(validate_layout(full.l), "LAYOUT-0004").size(), 1u);
  EXPECT_EQ(with_code(validate_layout(open.l), "LAYOUT-0004").size(), 0u);
}

TEST(ValidatePins, ReflexCornersAndClockwiseRings) {
  //  L-shape, clockwise:        pin at the reflex corner (2,2) is on the boundary: fine;
  //  (0,4) +--+ (2,4)           a square [2,4]x[2,4] filling the notch makes it interior.
  //        |  |
  //        |  +-----+ (4,2)
  //        |        |
  //  (0,0) +--------+ (4,0)
  const Ring l_cw = {{0, 0}, {0, 4}, {2, 4}, {2, 2}, {4, 2}, {4, 0}};
  L alone, filled;
  alone.poly("L", l_cw);
  filled.poly("L", l_cw).rect("sq", 2, 2, 4, 4);
  for (L* b : {&alone, &filled}) b->net("n").pin("reflex", 2, 2).pin("inside", 1, 3).pin("edge", 3, 2);
  const auto a = with_code(validate_layout(alone.l), "LAYOUT-0004");
  ASSERT_EQ(a.size(), 1u);
  EXPECT_NE(a[0].message.find("\"inside\""), std::string::npos);
  const auto f = with_code(validate_layout(filled.l), "LAYOUT-0004");
  EXPECT_EQ(f.size(), 3u) << dump(validate_layout(filled.l));
}

TEST(ValidatePins, HolesAreFreeSpaceUnlessFilled) {
  //  ring 0..10 with hole 3..7; a pin inside the hole or on the hole's edge is fine; a rect
  //  blockage exactly filling the hole makes the hole's edge interior to the union.
  const Ring outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Ring hole = {{3, 3}, {3, 7}, {7, 7}, {7, 3}};
  L open, plugged;
  open.poly("ring", outer, {hole});
  plugged.poly("ring", outer, {hole}).rect("plug", 3, 3, 7, 7);
  for (L* b : {&open, &plugged}) b->net("n").pin("in-hole", 5, 5).pin("hole-edge", 3, 5).pin("hole-corner", 7, 7);
  EXPECT_TRUE(with_code(validate_layout(open.l), "LAYOUT-0004").empty()) << dump(validate_layout(open.l));
  const auto p = with_code(validate_layout(plugged.l), "LAYOUT-0004");
  ASSERT_EQ(p.size(), 3u) << dump(validate_layout(plugged.l));
  EXPECT_NE(p[0].message.find("inside blockage \"plug\""), std::string::npos);
  EXPECT_NE(p[1].message.find("\"ring\", \"plug\""), std::string::npos);
}

TEST(ValidatePins, RepeatedAndCollinearVerticesDoNotConfuse) {
  // The same square written with a repeated vertex and a collinear vertex on the pin.
  L b;
  b.poly("sq", {{0, 0}, {2, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}).rect("below", 0, -4, 4, 0);
  b.net("n").pin("on-collinear", 2, 0).pin("on-repeat", 4, 0);
  const auto hits = with_code(validate_layout(b.l), "LAYOUT-0004");
  ASSERT_EQ(hits.size(), 1u);  // (2,0) is inside the union; (4,0) is a corner of both
  EXPECT_NE(hits[0].message.find("\"on-collinear\""), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Shape pins.

TEST(ValidatePins, RectPinsInsideRectsMatchReference) {
  const unsigned base_seed = 555;
  for (unsigned it = 0; it < 600; ++it) {
    const unsigned seed = base_seed + it;
    std::mt19937 rng(seed);
    L b;
    struct R { int x0, y0, x1, y1; };
    std::vector<R> blocks;
    auto rnd_rect = [&]() {
      int x0 = static_cast<int>(rng() % 9), x1 = static_cast<int>(rng() % 9);
      int y0 = static_cast<int>(rng() % 9), y1 = static_cast<int>(rng() % 9);
      if (x0 == x1) ++x1;
      if (y0 == y1) ++y1;
      return R{std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1)};
    };
    b.boundary(0, 0, 6, 6);
    for (int i = 0; i < 3; ++i) {
      blocks.push_back(rnd_rect());
      b.rect("b" + std::to_string(i), blocks.back().x0, blocks.back().y0, blocks.back().x1, blocks.back().y1);
    }
    b.net("n");
    std::vector<R> pins;
    for (int k = 0; k < 6; ++k) {
      pins.push_back(rnd_rect());
      b.rect_pin("p" + std::to_string(k), pins.back().x0, pins.back().y0, pins.back().x1, pins.back().y1);
    }
    const auto ds = validate_layout(b.l);
    SCOPED_TRACE("seed " + std::to_string(seed) + "\n" + dump(ds));
    for (std::size_t k = 0; k < pins.size(); ++k) {
      const R& s = pins[k];
      bool inside = false;
      for (const R& r : blocks) inside |= r.x0 < s.x0 && s.x1 < r.x1 && r.y0 < s.y0 && s.y1 < r.y1;
      const bool outside = s.x0 > 6 || s.y0 > 6;  // closed boxes [0,6]^2 and s are disjoint
      const std::string ctx = "pin \"p" + std::to_string(k) + "\":";
      bool got_inside = false, got_outside = false;
      for (const auto& d : with_code(ds, "LAYOUT-0005")) got_inside |= d.message.find(ctx) != std::string::npos;
      for (const auto& d : with_code(ds, "LAYOUT-0006")) got_outside |= d.message.find(ctx) != std::string::npos;
      EXPECT_EQ(got_inside, inside) << "pin " << k;
      EXPECT_EQ(got_outside, outside) << "pin " << k;
    }
  }
}

TEST(ValidatePins, ShapePinsAndPolygonBlockages) {
  //  ring 0..10 with hole 3..7: a pin in the solid part is inside; one in the hole, one around
  //  the hole, one touching the outer edge from inside are not.
  L b;
  b.boundary(-20, -20, 20, 20);
  b.poly("ring", {{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{3, 3}, {3, 7}, {7, 7}, {7, 3}}});
  b.net("n")
      .rect_pin("solid", 1, 1, 2, 2)
      .rect_pin("in-hole", 4, 4, 5, 5)
      .rect_pin("around-hole", 2, 2, 8, 8)
      .rect_pin("touching", 0, 1, 2, 2)
      .poly_pin("tri-solid", {{1, 8}, {2, 8}, {1, 9}});
  const auto ds = validate_layout(b.l);
  const auto hits = with_code(ds, "LAYOUT-0005");
  ASSERT_EQ(hits.size(), 2u) << dump(ds);
  EXPECT_NE(hits[0].message.find("\"solid\""), std::string::npos);
  EXPECT_NE(hits[1].message.find("\"tri-solid\""), std::string::npos);
}

TEST(ValidatePins, TriangleNearTheBoundaryCorner) {
  // The triangle's box overlaps the boundary [0,10]^2 but the triangle itself stays outside;
  // the second triangle touches the corner (10,10) exactly: it meets the closed boundary.
  L b;
  b.boundary(0, 0, 10, 10);
  b.net("n").poly_pin("out", {{9, 12}, {12, 9}, {14, 14}}).poly_pin("touch", {{10, 10}, {14, 11}, {11, 14}});
  const auto hits = with_code(validate_layout(b.l), "LAYOUT-0006");
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NE(hits[0].message.find("\"out\""), std::string::npos);
}

TEST(ValidatePins, PointPinsOnBoundaryEdgesAreFine) {
  L b;
  b.boundary(-5, -5, 5, 5);
  b.net("n").pin("sw", -5, -5).pin("e", 5, 0).pin("n", 0, 5).pin("out-x", 6, 0).pin("out-y", 0, -6);
  const auto hits = with_code(validate_layout(b.l), "LAYOUT-0006");
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NE(hits[0].message.find("\"out-x\" at (6,0)"), std::string::npos);
  EXPECT_NE(hits[1].message.find("\"out-y\" at (0,-6)"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Names, nets, sketches, routes.

TEST(ValidateNames, DuplicatesNameTheFirstLine) {
  L b;
  b.rect("a", 0, 0, 1, 1).rect("a", 2, 2, 3, 3).rect("c", 4, 4, 5, 5);
  b.net("n").pin("p", 10, 10).pin("p", 11, 11).net("n").pin("x", 12, 12).pin("y", 13, 13);
  const auto ds = validate_layout(b.l);
  const auto blk = with_code(ds, "LAYOUT-0001");
  ASSERT_EQ(blk.size(), 1u);
  EXPECT_EQ(blk[0].line, b.l.blockages[1].line);
  EXPECT_NE(blk[0].message.find("line " + std::to_string(b.l.blockages[0].line)), std::string::npos);
  const auto net = with_code(ds, "LAYOUT-0002");
  ASSERT_EQ(net.size(), 1u);
  EXPECT_EQ(net[0].line, b.l.nets[1].line);
  const auto pin = with_code(ds, "LAYOUT-0003");
  ASSERT_EQ(pin.size(), 1u);
  EXPECT_EQ(pin[0].line, b.l.nets[0].pins[1].line);
  EXPECT_EQ(ds.size(), 3u) << dump(ds);
}

TEST(ValidateNets, FewerThanTwoPinsIsAWarning) {
  L b;
  b.net("none").net("one").pin("p", 0, 0).net("two").pin("a", 1, 1).pin("b", 2, 2);
  const auto ds = validate_layout(b.l);
  const auto w = with_code(ds, "LAYOUT-0007");
  ASSERT_EQ(w.size(), 2u) << dump(ds);
  for (const auto& d : w) EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_FALSE(taut::has_error(ds));
}

TEST(ValidateNets, SketchEndpoints) {
  L b;
  b.net("ok").pin("a", 0, 0).rect_pin("b", 10, 10, 20, 20).sketch({{0, 0}, {5, 0}, {10, 15}});
  b.net("bad-start").pin("a", 0, 0).pin("b", 9, 9).sketch({{1, 0}, {9, 9}});
  b.net("reversed").pin("a", 0, 0).pin("b", 9, 9).sketch({{9, 9}, {0, 0}});
  b.net("poly-end").pin("a", 0, 0).poly_pin("b", {{10, 0}, {14, 0}, {12, 3}}).sketch({{0, 0}, {13, 1}});
  b.net("three").pin("a", 0, 0).pin("b", 9, 9).pin("c", 5, 5).sketch({{0, 0}, {9, 9}});
  const auto ds = validate_layout(b.l);
  EXPECT_FALSE(taut::has_error(ds)) << dump(ds);
  const auto ends = with_code(ds, "LAYOUT-0008");
  // one warning for the reversed sketch, which says so (it joins the pins: tighten follows it)
  ASSERT_EQ(ends.size(), 2u) << dump(ds);
  EXPECT_NE(ends[0].message.find("net \"bad-start\" sketch: starts at (1,0)"), std::string::npos);
  EXPECT_NE(ends[1].message.find("net \"reversed\" sketch: runs from the second pin \"b\" to the first \"a\" (reversed)"),
            std::string::npos) << ends[1].message;
  EXPECT_EQ(ends[1].line, b.l.nets[2].sketch->line);
  const auto three = with_code(ds, "LAYOUT-0009");
  ASSERT_EQ(three.size(), 1u);
  EXPECT_EQ(three[0].line, b.l.nets[4].sketch->line);
}

// A closed sketch is a loop (a guard ring): no pins needed, none checked; one that stays at one
// point is not a loop.
TEST(ValidateNets, LoopSketchesNeedNoPins) {
  L b;
  b.net("ring").sketch({{0, 0}, {10, 0}, {10, 10}, {0, 0}});
  b.net("ring3").pin("a", 50, 50).pin("b", 60, 60).pin("c", 70, 70).sketch({{0, 0}, {10, 0}, {10, 10}, {0, 0}});
  b.net("dot").sketch({{5, 5}, {5, 5}, {5, 5}});
  const auto ds = validate_layout(b.l);
  EXPECT_FALSE(taut::has_error(ds)) << dump(ds);
  const auto few = with_code(ds, "LAYOUT-0007");
  ASSERT_EQ(few.size(), 1u) << dump(ds);
  EXPECT_NE(few[0].message.find("net \"dot\""), std::string::npos);
  EXPECT_TRUE(with_code(ds, "LAYOUT-0008").empty()) << dump(ds);
  ASSERT_EQ(with_code(ds, "LAYOUT-0009").size(), 1u) << dump(ds);  // "dot": a sketch, not a loop
}

TEST(ValidateRoutes, UnknownNetAndTwice) {
  L b;
  b.net("a").pin("p", 0, 0).pin("q", 1, 1);
  b.route("a").route("zz").route("a");
  const auto ds = validate_layout(b.l);
  ASSERT_EQ(with_code(ds, "LAYOUT-0010").size(), 1u);
  EXPECT_EQ(with_code(ds, "LAYOUT-0010")[0].line, b.l.routes->routes[1].line);
  ASSERT_EQ(with_code(ds, "LAYOUT-0011").size(), 1u);
  EXPECT_EQ(with_code(ds, "LAYOUT-0011")[0].line, b.l.routes->routes[2].line);
}

// ---------------------------------------------------------------------------------------------
// In-memory layouts (generators, tests) get the checks the reader would have made.

TEST(ValidateMemory, SanityOfHandBuiltLayouts) {
  L b;
  b.boundary(0, 0, 0, 5);
  b.rect("empty", 3, 3, 3, 4).rect("far", 0, 0, 1 << 30, 1);
  b.l.blockages.push_back(Blockage{"none", {}, 99});
  b.net("").pin("", 1, 1);
  Pin both;
  both.name = "both";
  both.point = Point{1, 1};
  both.shape = Shape{};
  b.l.nets.back().pins.push_back(both);
  b.l.rules = Rules{};
  b.l.rules->spacing = -1;
  b.l.rules->orientations = "c:0,180,360";
  b.l.rules->orientation_degrees = {0, 180, 360};
  const auto ds = validate_layout(b.l);
  EXPECT_EQ(with_code(ds, "GEOM-0010").size(), 2u) << dump(ds);  // boundary and rect
  EXPECT_EQ(with_code(ds, "LAYOUT-0013").size(), 1u);
  EXPECT_EQ(with_code(ds, "LAYOUT-0012").size(), 1u);
  EXPECT_EQ(with_code(ds, "LAYOUT-0017").size(), 2u);
  EXPECT_EQ(with_code(ds, "LAYOUT-0015").size(), 1u);
  EXPECT_EQ(with_code(ds, "LAYOUT-0016").size(), 1u);
  EXPECT_EQ(with_code(ds, "LAYOUT-0014").size(), 1u);
  for (const auto& d : ds) EXPECT_TRUE(d.code.rfind("GEOM-", 0) == 0 || d.code.rfind("LAYOUT-", 0) == 0);
}

TEST(ValidateMemory, OrientationSets) {
  for (const auto& [text, degs, ok] : std::vector<std::tuple<std::string, std::vector<double>, bool>>{
           {"rectilinear", {}, true}, {"any", {}, true}, {"c:0,90", {0, 90}, true},
           {"c:0,60,120", {0, 60, 120}, true}, {"c:90,270", {90, 270}, false}, {"c:45", {45}, false},
           {"hex", {}, false}}) {
    L b;
    b.l.rules = Rules{};
    b.l.rules->orientations = text;
    b.l.rules->orientation_degrees = degs;
    EXPECT_EQ(validate_layout(b.l).empty(), ok) << text;
  }
}

// Polygon problems come from geom::validate_polygon and point at the <polygon> or <hole> line.
TEST(ValidateGeometry, PolygonProblemsPointAtTheirLine) {
  if (taut::geom::validate_ring({{0, 0}, {2, 2}, {2, 0}, {0, 3}}).empty())
    GTEST_SKIP() << "geom/validate.cpp is still a placeholder";
  L b;
  b.poly("bow", {{0, 0}, {2, 2}, {2, 0}, {0, 3}});
  b.poly("far-hole", {{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{20, 20}, {20, 22}, {22, 22}, {22, 20}}});
  const auto ds = validate_layout(b.l);
  ASSERT_GE(ds.size(), 2u) << dump(ds);
  bool bow = false, hole = false;
  for (const auto& d : ds) {
    EXPECT_EQ(d.code.rfind("GEOM-", 0), 0u);
    if (d.message.find("blockage \"bow\" polygon") != std::string::npos) bow = d.line == b.l.blockages[0].line;
    if (d.message.find("blockage \"far-hole\" polygon: hole 0") != std::string::npos)
      hole = d.line == b.l.blockages[1].shapes[0].hole_lines[0];
  }
  EXPECT_TRUE(bow) << dump(ds);
  EXPECT_TRUE(hole) << dump(ds);
}

// ---------------------------------------------------------------------------------------------

TEST(ValidateSpeed, ManyBlockagesAndPins) {
#ifdef NDEBUG
  const int nb = 100000, np = 10000;
#else
  const int nb = 20000, np = 2000;
#endif
  L b;
  b.boundary(0, 0, 1000000, 1000000);
  for (int i = 0; i < nb; ++i) {
    const int x = (i % 300) * 3000, y = (i / 300) * 3000;
    b.rect("b" + std::to_string(i), x, y, x + 2000, y + 2000);
  }
  for (int k = 0; k < np / 2; ++k) {
    const int x = (k % 300) * 3000 + 2500, y = (k / 300) * 3000 + 2500;
    b.net("n" + std::to_string(k)).pin("a", x, y).pin("b", x - 500, y - 500);  // a free, b on a corner
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto ds = validate_layout(b.l);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(ds.empty()) << dump(std::vector<Diagnostic>(ds.begin(), ds.begin() + std::min<std::size_t>(ds.size(), 5)));
  std::printf("[ speed    ] validate %d blockages, %d pins: %.3f s\n", nb, np, s);
}

}  // namespace validate_test
