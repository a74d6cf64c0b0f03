// layout_to_xml and same_document: every element survives a write/read round trip, names are
// escaped, attributes come in FORMAT.md's order, and same_document notices every field.
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "io/generate.h"
#include "io/layout.h"
#include "io/layout_reader.h"
#include "io/layout_writer.h"

namespace taut::io {
namespace writer_test {

Layout read_back(const std::string& xml) {
  ReadResult r = parse_layout(xml, "written.xml");
  std::string why;
  for (const auto& d : r.diagnostics) why += format(d) + "\n";
  EXPECT_TRUE(r.layout.has_value()) << why << "\n--- written:\n" << xml;
  return r.layout ? *r.layout : Layout{};
}

Shape rect(int x0, int y0, int x1, int y1) {
  Shape s;
  s.rect = {{x0, y0}, {x1, y1}};
  return s;
}
Shape poly(geom::Ring outer, std::vector<geom::Ring> holes = {}) {
  Shape s;
  s.kind = Shape::Kind::Polygon;
  s.polygon = {std::move(outer), std::move(holes)};
  return s;
}

// Every element and optional attribute of FORMAT.md, with names that need escaping and
// coordinates at the limits.
Layout everything() {
  const int M = geom::kMaxCoord;
  Layout l;
  l.name = "all & <every> \"thing\" 'here'";
  l.dbu_per_micron = 2000;
  l.boundary = Boundary{{{-M, -M}, {M, M}}, 0};
  Rules r;
  r.wire_width = 200;
  r.spacing = 150;
  r.bend_cost = 7;
  r.orientations = "octilinear";
  l.rules = r;
  l.blockages.push_back({"a&b", {rect(-M, -M, -M + 10, -M + 10)}, 0});
  l.blockages.push_back({"tri", {poly({{0, 0}, {10, 0}, {5, 7}})}, 0});
  l.blockages.push_back(
      {"ring\"1\"", {poly({{0, 0}, {100, 0}, {100, 100}, {0, 100}},
                          {{{10, 10}, {10, 20}, {20, 20}, {20, 10}},
                           {{50, 50}, {50, 60}, {60, 60}}}),
                     rect(200, 200, 300, 300)},
       0});
  Net clk;
  clk.name = "clk<0>";
  clk.pins.push_back({"drv", Point{M, -M}, std::nullopt, 0});
  clk.pins.push_back({"ff'1", Point{-5, 7}, std::nullopt, 0});
  clk.pins.push_back({"ff2", Point{0, 0}, std::nullopt, 0});
  l.nets.push_back(clk);
  Net bump;
  bump.name = "bump";
  bump.pins.push_back({"pad", std::nullopt, rect(1, 2, 3, 4), 0});
  bump.pins.push_back({"ball", std::nullopt,
                       poly({{0, 0}, {9, 0}, {9, 9}, {0, 9}}, {{{1, 1}, {1, 2}, {2, 2}}}), 0});
  bump.sketch = Sketch{{{2, 3}, {5, 5}, {4, 4}}, 0};
  l.nets.push_back(bump);
  Net lonely;
  lonely.name = "tab\there\nnewline";
  lonely.pins.push_back({"only", Point{1, 1}, std::nullopt, 0});
  l.nets.push_back(lonely);
  Routes rs;
  rs.tool = "taut 0.1.0";
  rs.metric = "l1";
  rs.orientations = "rectilinear";
  Route ok;
  ok.net = "clk<0>";
  ok.status = "routed";
  ok.length = "23000.125";
  ok.bends = 4;
  ok.wires.push_back({{{500, 500}, {500, 9000}, {8000, 9000}}, 0});
  ok.wires.push_back({{{8000, 9000}, {12000, 9000}}, 0});
  rs.routes.push_back(ok);
  Route bad;
  bad.net = "bump";
  bad.status = "failed";
  bad.reason = "pin ball is enclosed by blockage \"ring\" & more";
  rs.routes.push_back(bad);
  l.routes = rs;
  return l;
}

TEST(Writer, EveryElementRoundTrips) {
  const Layout l = everything();
  const std::string xml = layout_to_xml(l);
  const Layout back = read_back(xml);
  EXPECT_TRUE(same_document(l, back)) << xml;
  // Writing what was read gives the same bytes.
  EXPECT_EQ(layout_to_xml(back), xml);
}

TEST(Writer, EscapesNames) {
  const std::string xml = layout_to_xml(everything());
  EXPECT_NE(xml.find("name=\"all &amp; &lt;every&gt; &quot;thing&quot; &apos;here&apos;\""),
            std::string::npos);
  EXPECT_NE(xml.find("id=\"a&amp;b\""), std::string::npos);
  EXPECT_NE(xml.find("name=\"tab&#9;here&#10;newline\""), std::string::npos);
  EXPECT_EQ(xml.find("\t"), std::string::npos);
}

TEST(Writer, AttributeOrderAndIndentation) {
  const std::string xml = layout_to_xml(everything());
  const std::string m = std::to_string(geom::kMaxCoord);
  for (const std::string& s : {
           std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<layout name="),
           std::string("\" version=\"1\" dbu-per-micron=\"2000\">\n"),
           "  <boundary x0=\"-" + m + "\" y0=\"-" + m + "\" x1=\"" + m + "\" y1=\"" + m + "\"/>\n",
           std::string("  <rules wire-width=\"200\" spacing=\"150\" bend-cost=\"7\" "
                       "orientations=\"octilinear\"/>\n"),
           std::string("  <blockage id=\"tri\"><polygon points=\"0,0 10,0 5,7\"/></blockage>\n"),
           std::string("      <hole points=\"10,10 10,20 20,20 20,10\"/>\n"),
           std::string("    <pin name=\"ff2\" x=\"0\" y=\"0\"/>\n"),
           std::string("    <pin name=\"pad\"><rect x0=\"1\" y0=\"2\" x1=\"3\" y1=\"4\"/></pin>\n"),
           std::string("    <sketch points=\"2,3 5,5 4,4\"/>\n"),
           std::string("  <routes tool=\"taut 0.1.0\" metric=\"l1\" orientations=\"rectilinear\">\n"),
           std::string("    <route net=\"clk&lt;0&gt;\" status=\"routed\" length=\"23000.125\" "
                       "bends=\"4\">\n"),
           std::string("      <wire points=\"500,500 500,9000 8000,9000\"/>\n"),
           std::string("    <route net=\"bump\" status=\"failed\" reason=\""),
       })
    EXPECT_NE(xml.find(s), std::string::npos) << "missing: " << s << "\nin:\n" << xml;
  // 2-space indentation: every line's leading spaces are even, and nesting depth matches.
  std::istringstream in(xml);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto lead = line.find_first_not_of(' ');
    EXPECT_EQ(lead % 2, 0u) << line;
  }
}

TEST(Writer, MinimalLayouts) {
  Layout l;
  l.name = "empty";
  const std::string xml = layout_to_xml(l);
  EXPECT_EQ(xml.find("<boundary"), std::string::npos);
  EXPECT_EQ(xml.find("<rules"), std::string::npos);
  EXPECT_EQ(xml.find("<routes"), std::string::npos);
  EXPECT_TRUE(same_document(l, read_back(xml)));
  // Empty <routes> (a router that had nothing to do) stays present.
  l.routes = Routes{"taut", "", "", {}, 0, std::nullopt};
  EXPECT_TRUE(same_document(l, read_back(layout_to_xml(l))));
}

TEST(Writer, DemoDesignRoundTrips) {
  ReadResult r = read_layout(std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml");
  ASSERT_TRUE(r.layout.has_value());
  const std::string xml = layout_to_xml(*r.layout);
  EXPECT_TRUE(same_document(*r.layout, read_back(xml)));
}

TEST(Writer, GeneratedLayoutsRoundTrip) {
  for (const std::string& kind : gen_kind_names())
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(kind + " seed " + std::to_string(seed));
      GenOptions o;
      o.kind = *parse_gen_kind(kind);
      o.size = 300;
      o.nets = 5;
      o.seed = seed;
      const Layout l = generate_layout(o);
      EXPECT_TRUE(same_document(l, read_back(layout_to_xml(l))));
    }
}

// Random routes with random names from a hostile alphabet.
TEST(Writer, RandomRoutesRoundTrip) {
  const std::uint64_t base = 20240601;
  for (std::uint64_t k = 0; k < 40; ++k) {
    const std::uint64_t seed = base + k;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    auto coord = [&] { return static_cast<int>(rng() % 2001) - 1000; };
    auto name = [&] {
      const std::vector<std::string> alphabet = {"a", "b", "&", "<", ">", "\"", "'", " ",
                                                 "_", "-", ".", "\xC3\xA9", "\xE2\x82\xAC",
                                                 "\xF0\x9F\x98\x80", "&amp;", "]]>"};
      std::string s = "n";
      for (int i = rng() % 6; i > 0; --i) s += alphabet[rng() % alphabet.size()];
      return s;
    };
    Layout l;
    l.name = name();
    Routes rs;
    rs.tool = name();
    for (int n = 0; n < 4; ++n) {
      Net net;
      net.name = name() + std::to_string(n);
      net.pins.push_back({"a", Point{coord(), coord()}, std::nullopt, 0});
      net.pins.push_back({"b", Point{coord(), coord()}, std::nullopt, 0});
      l.nets.push_back(net);
      Route r;
      r.net = net.name;
      r.status = rng() % 2 ? "routed" : "failed";
      if (r.status == "routed") {
        r.length = std::to_string(rng() % 100000);
        r.bends = static_cast<std::int64_t>(rng() % 9);
        for (int w = 1 + rng() % 3; w > 0; --w) {
          Wire wire;
          for (int p = 2 + rng() % 4; p > 0; --p) wire.points.push_back({coord(), coord()});
          r.wires.push_back(wire);
        }
      } else {
        r.reason = name();
      }
      rs.routes.push_back(r);
    }
    l.routes = rs;
    EXPECT_TRUE(same_document(l, read_back(layout_to_xml(l))));
  }
}

// Bytes no XML document can hold (possible only in a layout built in memory) still give a
// well-formed file; they are replaced, so the document is not the same.
TEST(Writer, UnrepresentableBytesStayWellFormed) {
  for (const std::string& bad : {std::string("\x01"), std::string("\xC3"), std::string("\xFF"),
                                std::string("\xED\xA0\x80"), std::string("\xC0\xAF"),
                                std::string("\xEF\xBF\xBF"), std::string("a\0b", 3)}) {
    Layout l;
    l.name = "x" + bad + "y";
    const std::string xml = layout_to_xml(l);
    ReadResult r = parse_layout(xml, "w.xml");
    ASSERT_TRUE(r.layout.has_value()) << xml;
    // Each bad byte is replaced by U+FFFD; the good ones around stay.
    const std::string& got = r.layout->name;
    EXPECT_EQ(got.front(), 'x');
    EXPECT_EQ(got.back(), 'y');
    EXPECT_NE(got.find("\xEF\xBF\xBD"), std::string::npos);
    EXPECT_FALSE(same_document(l, *r.layout));
  }
}

TEST(SameDocument, IgnoresFileAndLinesOnly) {
  const Layout a = everything();
  Layout b = a;
  b.file = "elsewhere.xml";
  b.line = 99;
  b.boundary->line = 3;
  b.rules->line = 4;
  b.blockages[2].line = 5;
  b.blockages[2].shapes[0].line = 6;
  b.blockages[2].shapes[0].hole_lines = {7, 8};
  b.nets[1].pins[1].shape->line = 9;
  b.nets[1].pins[1].line = 10;
  b.nets[1].sketch->line = 11;
  b.nets[1].line = 12;
  b.routes->line = 13;
  b.routes->routes[0].line = 14;
  b.routes->routes[0].wires[1].line = 15;
  EXPECT_TRUE(same_document(a, b));

  // Each mutation of content is noticed.
  std::vector<std::function<void(Layout&)>> mutations = {
      [](Layout& l) { l.name += "x"; },
      [](Layout& l) { l.version = 2; },
      [](Layout& l) { l.dbu_per_micron = 1000; },
      [](Layout& l) { l.boundary.reset(); },
      [](Layout& l) { l.boundary->box.hi.x -= 1; },
      [](Layout& l) { l.rules.reset(); },
      [](Layout& l) { l.rules->spacing += 1; },
      [](Layout& l) { l.rules->orientations = "any"; },
      [](Layout& l) { l.blockages.pop_back(); },
      [](Layout& l) { l.blockages[0].id = "z"; },
      [](Layout& l) { l.blockages[2].shapes[0].polygon.holes[1][0].x += 1; },
      [](Layout& l) { l.blockages[2].shapes[1].rect.lo.y += 1; },
      [](Layout& l) { l.blockages[2].shapes[1].kind = Shape::Kind::Polygon; },
      [](Layout& l) { l.nets[0].pins[1].point->y += 1; },
      [](Layout& l) { l.nets[0].pins[1].name = "q"; },
      [](Layout& l) { l.nets[1].sketch.reset(); },
      [](Layout& l) { l.nets[1].sketch->points.pop_back(); },
      [](Layout& l) { l.nets[1].pins[0].shape->rect.hi.x += 1; },
      [](Layout& l) { l.nets.pop_back(); },
      [](Layout& l) { l.routes.reset(); },
      [](Layout& l) { l.routes->tool = "other"; },
      [](Layout& l) { l.routes->routes[0].length = "1"; },
      [](Layout& l) { l.routes->routes[0].bends.reset(); },
      [](Layout& l) { l.routes->routes[1].reason.reset(); },
      [](Layout& l) { l.routes->routes[0].wires[0].points[0].x += 1; },
  };
  for (std::size_t i = 0; i < mutations.size(); ++i) {
    Layout c = a;
    mutations[i](c);
    EXPECT_FALSE(same_document(a, c)) << "mutation " << i;
    EXPECT_FALSE(same_document(c, a)) << "mutation " << i;
  }
}

}  // namespace writer_test
}  // namespace taut::io
