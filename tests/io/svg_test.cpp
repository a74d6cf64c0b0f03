// layout_to_svg: the picture is well-formed XML (parsed with libxml2's reader), draws one
// element per blockage, pin, sketch and wire, flips y, and stays valid at 10^4 blockages.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "io/generate.h"
#include "io/layout_reader.h"
#include "io/svg.h"

// The tests' include path does not carry libxml2's folder; the reader API is all opaque
// pointers, so declaring the few functions used here is enough (libxml2 is linked via taut_io).
#if __has_include(<libxml/xmlreader.h>)
#include <libxml/xmlreader.h>
#else
extern "C" {
typedef unsigned char xmlChar;
typedef struct _xmlTextReader* xmlTextReaderPtr;
xmlTextReaderPtr xmlReaderForMemory(const char* buffer, int size, const char* URL,
                                    const char* encoding, int options);
int xmlTextReaderRead(xmlTextReaderPtr reader);
int xmlTextReaderNodeType(xmlTextReaderPtr reader);
int xmlTextReaderDepth(xmlTextReaderPtr reader);
const xmlChar* xmlTextReaderConstLocalName(xmlTextReaderPtr reader);
const xmlChar* xmlTextReaderConstValue(xmlTextReaderPtr reader);
int xmlTextReaderMoveToNextAttribute(xmlTextReaderPtr reader);
int xmlTextReaderMoveToElement(xmlTextReaderPtr reader);
void xmlFreeTextReader(xmlTextReaderPtr reader);
}
#endif

namespace taut::io {
namespace svg_test {

SvgOptions svg_options(int width_px, bool labels) {
  SvgOptions o;
  o.width_px = width_px;
  o.labels = labels;
  return o;
}

struct Element {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::string text;  // text content of a <text> element
};

// Parses the SVG; `ok` is false unless the whole document is well-formed.
struct Parsed {
  bool ok = false;
  std::vector<Element> elements;
  int count_class(const std::string& c) const {
    int n = 0;
    for (const auto& e : elements) {
      auto it = e.attrs.find("class");
      n += it != e.attrs.end() && it->second == c;
    }
    return n;
  }
  int count_name(const std::string& name) const {
    int n = 0;
    for (const auto& e : elements) n += e.name == name;
    return n;
  }
};

Parsed parse_svg(const std::string& svg) {
  Parsed p;
  xmlTextReaderPtr r = xmlReaderForMemory(svg.data(), static_cast<int>(svg.size()), "pic.svg",
                                          nullptr, 0);
  if (!r) return p;
  int status;
  while ((status = xmlTextReaderRead(r)) == 1) {
    const int type = xmlTextReaderNodeType(r);
    if (type == 1) {  // element
      Element e;
      e.name = reinterpret_cast<const char*>(xmlTextReaderConstLocalName(r));
      while (xmlTextReaderMoveToNextAttribute(r) == 1)
        e.attrs[reinterpret_cast<const char*>(xmlTextReaderConstLocalName(r))] =
            reinterpret_cast<const char*>(xmlTextReaderConstValue(r));
      xmlTextReaderMoveToElement(r);
      p.elements.push_back(std::move(e));
    } else if (type == 3 && !p.elements.empty()) {  // text
      p.elements.back().text += reinterpret_cast<const char*>(xmlTextReaderConstValue(r));
    }
  }
  xmlFreeTextReader(r);
  p.ok = status == 0 && !p.elements.empty() && p.elements[0].name == "svg";
  return p;
}

Layout demo() {
  ReadResult r = read_layout(std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml");
  EXPECT_TRUE(r.layout.has_value());
  return r.layout ? *r.layout : Layout{};
}

int count_pins(const Layout& l) {
  int n = 0;
  for (const Net& net : l.nets) n += static_cast<int>(net.pins.size());
  return n;
}

TEST(Svg, DemoHasOneElementPerObject) {
  const Layout l = demo();
  const Parsed p = parse_svg(layout_to_svg(l));
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.count_class("blockage"), static_cast<int>(l.blockages.size()));
  EXPECT_EQ(p.count_class("pin"), count_pins(l));
  EXPECT_EQ(p.count_class("sketch"), 1);
  EXPECT_EQ(p.count_class("wire"), 0);
  EXPECT_EQ(p.count_class("boundary"), 1);
  EXPECT_EQ(p.count_class("legend"), 1);
  // Every blockage id and every net name is written somewhere as a label.
  std::string texts;
  for (const auto& e : p.elements) texts += e.text + "\n";
  for (const Blockage& b : l.blockages) EXPECT_NE(texts.find(b.id + "\n"), std::string::npos) << b.id;
  for (const Net& n : l.nets) EXPECT_NE(texts.find(n.name + " ("), std::string::npos) << n.name;
  // Holes are cut out with the even-odd rule.
  bool evenodd = false;
  for (const auto& e : p.elements)
    if (e.name == "path" && e.attrs.count("fill-rule")) evenodd |= e.attrs.at("fill-rule") == "evenodd";
  EXPECT_TRUE(evenodd);
}

// The world group maps (x, y) to (a x + e, d y + f) with d < 0: y points up, and every pin
// lands inside the picture.
TEST(Svg, FlipsYAndFits) {
  const Layout l = demo();
  const Parsed p = parse_svg(layout_to_svg(l, svg_options(800, true)));
  ASSERT_TRUE(p.ok);
  const double w = std::stod(p.elements[0].attrs.at("width"));
  const double h = std::stod(p.elements[0].attrs.at("height"));
  EXPECT_NEAR(std::max(w, h), 800, 200);  // the drawing's longest side is 800, plus legend
  double a = 0, b = 0, c = 0, d = 0, e = 0, f = 0;
  bool found = false;
  for (const auto& el : p.elements)
    if (el.name == "g" && el.attrs.count("transform")) {
      std::istringstream in(el.attrs.at("transform").substr(7));  // after "matrix("
      in >> a >> b >> c >> d >> e >> f;
      found = true;
      break;
    }
  ASSERT_TRUE(found);
  EXPECT_GT(a, 0);
  EXPECT_LT(d, 0);
  EXPECT_EQ(b, 0);
  EXPECT_EQ(c, 0);
  for (const auto& el : p.elements)
    if (el.name == "circle") {
      const double x = a * std::stod(el.attrs.at("cx")) + e;
      const double y = d * std::stod(el.attrs.at("cy")) + f;
      EXPECT_GE(x, 0);
      EXPECT_LE(x, w);
      EXPECT_GE(y, 0);
      EXPECT_LE(y, h);
    }
  // The boundary's corners map inside the picture with y flipped.
  const Box bb = l.boundary->box;
  EXPECT_LT(d * bb.hi.y + f, d * bb.lo.y + f);
  EXPECT_GE(a * bb.lo.x + e, 0);
  EXPECT_LE(a * bb.hi.x + e, w);
}

TEST(Svg, RoutesAndHostileNames) {
  Layout l = demo();
  l.nets[0].name = "a&b<c>\"d'e";
  Routes rs;
  rs.tool = "test";
  Route r1{l.nets[0].name, "routed", "1", 0, {}, {}, 0};
  r1.wires.push_back({{{500, 500}, {500, 13000}}, 0});
  r1.wires.push_back({{{500, 13000}, {13000, 13000}, {13000, 12500}}, 0});
  Route r2{"en", "routed", "10000", 0, {}, {{{{1000, 6000}, {11000, 6000}}, 0}}, 0};
  Route r3{"bump", "failed", {}, {}, std::string("no way <round> & out"), {}, 0};
  rs.routes = {r1, r2, r3};
  l.routes = rs;
  const Parsed p = parse_svg(layout_to_svg(l));
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.count_class("wire"), 3);
  int hostile = 0;
  for (const auto& e : p.elements) hostile += e.text.find("a&b<c>\"d'e") != std::string::npos;
  EXPECT_GE(hostile, 1);
}

TEST(Svg, TenThousandBlockagesStayValidWithoutLabels) {
  GenOptions o;
  o.kind = GenKind::Rects;
  o.size = 40000;  // 10^4 rects
  o.nets = 200;
  const Layout l = generate_layout(o);
  ASSERT_EQ(l.blockages.size(), 10000u);
  const Parsed p = parse_svg(layout_to_svg(l));
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.count_class("blockage"), 10000);
  EXPECT_EQ(p.count_class("pin"), 400);
  EXPECT_LT(p.count_name("text"), 40);  // legend only: no per-blockage or per-pin labels
}

TEST(Svg, GeneratedPolygonsAndDegenerate) {
  for (GenKind kind : {GenKind::Polygons, GenKind::Maze, GenKind::Degenerate}) {
    GenOptions o;
    o.kind = kind;
    o.size = 2000;
    const Layout l = generate_layout(o);
    const Parsed p = parse_svg(layout_to_svg(l));
    ASSERT_TRUE(p.ok) << gen_kind_name(kind);
    EXPECT_EQ(p.count_class("blockage"), static_cast<int>(l.blockages.size()));
    EXPECT_EQ(p.count_class("pin"), count_pins(l));
  }
}

TEST(Svg, EmptyAndUnboundedLayouts) {
  Layout empty;
  EXPECT_TRUE(parse_svg(layout_to_svg(empty)).ok);
  Layout one;
  one.nets.push_back({"n", {{"p", Point{5, 5}, {}, 0}}, {}, 0});
  const Parsed p = parse_svg(layout_to_svg(one, svg_options(100, false)));
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.count_class("pin"), 1);
  EXPECT_EQ(p.count_class("boundary"), 0);
}

TEST(Svg, LabelsCanBeTurnedOff) {
  const Layout l = demo();
  const Parsed with = parse_svg(layout_to_svg(l, svg_options(1200, true)));
  const Parsed without = parse_svg(layout_to_svg(l, svg_options(1200, false)));
  ASSERT_TRUE(with.ok && without.ok);
  EXPECT_GT(with.count_name("text"), without.count_name("text") + static_cast<int>(l.blockages.size()) - 1);
}

}  // namespace svg_test
}  // namespace taut::io
