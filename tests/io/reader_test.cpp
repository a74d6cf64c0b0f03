// Tests of the secure layout reader: the bad-input corpus (tests/data/bad/EXPECTED.tsv), every
// field of a full layout, strict numbers and points against an independent reference, line
// numbers, size caps, thread safety and speed.
#include <gtest/gtest.h>

#include "support/corpus.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "geom/validate.h"
#include "io/layout_reader.h"
#include "io/validate_layout.h"
#include "support/run.h"

namespace fs = std::filesystem;

namespace reader_test {
using taut::Diagnostic;
using taut::Severity;
using taut::geom::Point;
using taut::geom::Ring;
using namespace taut::io;

std::string data(const std::string& rel) { return std::string(TAUT_TEST_DATA) + "/" + rel; }

std::string dump(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) s += "  " + taut::format(d) + "\n";
  return s;
}

// read_layout + validate_layout, as `taut check` does it.
std::vector<Diagnostic> check_file(const std::string& path, const ReadOptions& opt = {}) {
  ReadResult r = read_layout(path, opt);
  if (r.layout) {
    auto v = validate_layout(*r.layout);
    r.diagnostics.insert(r.diagnostics.end(), v.begin(), v.end());
  }
  return r.diagnostics;
}

bool code_matches(const std::string& expected, const std::string& actual) {
  if (!expected.empty() && expected.back() == '*')
    return actual.rfind(expected.substr(0, expected.size() - 1), 0) == 0;
  return expected == actual;
}

// geom/validate.cpp may still be a placeholder that finds nothing.
bool polygon_validation_available() {
  return !taut::geom::validate_ring({{0, 0}, {2, 2}, {2, 0}, {0, 3}}).empty();
}

// ---------------------------------------------------------------------------------------------
// The corpus.

TEST(ReaderCorpus, EveryBadFileGivesItsExpectedDiagnostic) {
  const auto rows = taut::test::load_bad_cases();
  for (const auto& r : rows) EXPECT_EQ(r.file.find("<malformed"), std::string::npos) << r.file;
  ASSERT_GE(rows.size(), 60u);
  const bool geom_ready = polygon_validation_available();
  int skipped = 0;
  for (const taut::test::BadCase& row : rows) {
    SCOPED_TRACE("file " + row.file);
    if (row.code.rfind("GEOM-*", 0) == 0 && !geom_ready) {
      ++skipped;
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const auto ds = check_file(data("bad/" + row.file));
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(secs, 1.0) << "slow answer";
    const Severity sev = row.severity == "warning" ? Severity::Warning : Severity::Error;
    if (sev == Severity::Warning) {
      EXPECT_FALSE(taut::has_error(ds)) << dump(ds);
    }
    const auto it = std::find_if(ds.begin(), ds.end(), [&](const Diagnostic& d) { return d.severity == sev; });
    ASSERT_NE(it, ds.end()) << "no " << row.severity << "\n" << dump(ds);
    EXPECT_TRUE(code_matches(row.code, it->code)) << "expected " << row.code << "\n" << dump(ds);
    EXPECT_EQ(it->line, row.line) << dump(ds);
    if (row.object != "-") {
      EXPECT_NE(it->message.find(row.object), std::string::npos) << dump(ds);
    }
    EXPECT_EQ(it->file, data("bad/" + row.file));
    // The diagnostics never leak the content of what an entity pointed at.
    for (const auto& d : ds) EXPECT_EQ(d.message.find("root:"), std::string::npos) << dump(ds);

    if (row.lenient_ok == "yes" || row.lenient_ok == "no") {
      ReadOptions lenient;
      lenient.lenient = true;
      const auto ls = check_file(data("bad/" + row.file), lenient);
      EXPECT_EQ(taut::has_error(ls), row.lenient_ok == "no") << "lenient\n" << dump(ls);
      if (row.lenient_ok == "yes") {
        ASSERT_FALSE(ls.empty());
        EXPECT_EQ(ls[0].severity, Severity::Warning);
        EXPECT_EQ(ls[0].code, row.code);
        EXPECT_EQ(ls[0].line, row.line);
      }
    }
  }
  if (skipped) GTEST_LOG_(INFO) << skipped << " GEOM-* rows skipped: geom/validate.cpp is a placeholder";
}

TEST(ReaderCorpus, EveryFileInTheFolderIsListed) {
  const auto rows = taut::test::load_bad_cases();
  for (const auto& r : rows) EXPECT_EQ(r.file.find("<malformed"), std::string::npos) << r.file;
  for (const auto& e : fs::directory_iterator(data("bad"))) {
    const std::string name = e.path().filename().string();
    if (name == "EXPECTED.tsv" || name == "make_corpus.py") continue;
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](const taut::test::BadCase& r) { return r.file == name; }))
        << name << " is not in EXPECTED.tsv";
  }
}

// Good files: no diagnostic at all.
TEST(ReaderGood, GoodFilesAndDesignsReadCleanly) {
  std::vector<std::string> files;
  for (const std::string& dir : {data("good"), std::string(TAUT_SOURCE_DIR) + "/designs"}) {
    if (!fs::exists(dir)) continue;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".xml") files.push_back(e.path().string());
  }
  ASSERT_GE(files.size(), 3u);
  for (const auto& f : files) {
    SCOPED_TRACE(f);
    ReadResult r = read_layout(f);
    ASSERT_TRUE(r.layout.has_value()) << dump(r.diagnostics);
    EXPECT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
    if (f.find("/designs/") == std::string::npos) {
      const auto v = validate_layout(*r.layout);
      EXPECT_TRUE(v.empty()) << dump(v);
    }
  }
}

TEST(ReaderGood, FullLayoutFieldByField) {
  ReadResult r = read_layout(data("good/full.xml"));
  ASSERT_TRUE(r.layout) << dump(r.diagnostics);
  ASSERT_TRUE(r.diagnostics.empty()) << dump(r.diagnostics);
  const Layout& l = *r.layout;
  EXPECT_EQ(l.file, data("good/full.xml"));
  EXPECT_EQ(l.name, "full");
  EXPECT_EQ(l.version, 1);
  EXPECT_EQ(l.dbu_per_micron, 2000);
  EXPECT_EQ(l.line, 3);
  ASSERT_TRUE(l.boundary);
  EXPECT_EQ(l.boundary->box, (Box{{-1000, 0}, {20000, 12000}}));
  EXPECT_EQ(l.boundary->line, 4);
  ASSERT_TRUE(l.rules);
  EXPECT_EQ(l.rules->wire_width, 200);
  EXPECT_EQ(l.rules->spacing, 150);
  EXPECT_EQ(l.rules->bend_cost, 7);
  EXPECT_EQ(l.rules->orientations, "c:0,60,120.5");
  EXPECT_EQ(l.rules->orientation_degrees, (std::vector<double>{0.0, 60.0, 120.5}));
  EXPECT_EQ(l.rules->line, 5);

  ASSERT_EQ(l.blockages.size(), 4u);
  const Blockage& ram = l.blockages[0];
  EXPECT_EQ(ram.id, "ram0");
  EXPECT_EQ(ram.line, 6);
  ASSERT_EQ(ram.shapes.size(), 1u);
  EXPECT_EQ(ram.shapes[0].kind, Shape::Kind::Rect);
  EXPECT_EQ(ram.shapes[0].rect, (Box{{2000, 2000}, {6000, 5000}}));
  EXPECT_EQ(ram.shapes[0].line, 6);
  EXPECT_TRUE(ram.shapes[0].polygon.outer.empty());

  const Blockage& tri = l.blockages[1];
  EXPECT_EQ(tri.id, "tri");
  ASSERT_EQ(tri.shapes.size(), 1u);
  EXPECT_EQ(tri.shapes[0].kind, Shape::Kind::Polygon);
  // The repeated closing vertex is dropped.
  EXPECT_EQ(tri.shapes[0].polygon.outer, (Ring{{9000, 1000}, {13000, 1000}, {11000, 4500}}));
  EXPECT_TRUE(tri.shapes[0].polygon.holes.empty());
  EXPECT_EQ(tri.shapes[0].line, 7);

  const Blockage& ring = l.blockages[2];
  EXPECT_EQ(ring.id, "ring");
  EXPECT_EQ(ring.line, 8);
  ASSERT_EQ(ring.shapes.size(), 1u);
  const Shape& rs = ring.shapes[0];
  EXPECT_EQ(rs.line, 9);
  EXPECT_EQ(rs.polygon.outer, (Ring{{14000, 6000}, {19000, 6000}, {19000, 11000}, {14000, 11000}}));
  ASSERT_EQ(rs.polygon.holes.size(), 2u);
  EXPECT_EQ(rs.polygon.holes[0], (Ring{{15000, 7000}, {15000, 10000}, {16000, 10000}, {16000, 7000}}));
  EXPECT_EQ(rs.polygon.holes[1], (Ring{{17000, 7000}, {17000, 10000}, {18000, 10000}, {18000, 7000}}));
  EXPECT_EQ(rs.hole_lines, (std::vector<int>{10, 12}));

  const Blockage& two = l.blockages[3];
  EXPECT_EQ(two.id, "two");
  ASSERT_EQ(two.shapes.size(), 2u);
  EXPECT_EQ(two.shapes[0].rect, (Box{{-1000, 6000}, {1000, 7000}}));
  EXPECT_EQ(two.shapes[1].rect, (Box{{1000, 6000}, {2000, 8000}}));
  EXPECT_EQ(two.shapes[1].line, 15);

  ASSERT_EQ(l.nets.size(), 2u);
  const Net& clk = l.nets[0];
  EXPECT_EQ(clk.name, "clk");
  EXPECT_EQ(clk.line, 16);
  ASSERT_EQ(clk.pins.size(), 3u);
  EXPECT_EQ(clk.pins[0].name, "drv");
  EXPECT_EQ(clk.pins[0].point, (Point{500, 500}));
  EXPECT_FALSE(clk.pins[0].shape);
  EXPECT_EQ(clk.pins[0].line, 17);
  EXPECT_EQ(clk.pins[1].name, "ff1");
  EXPECT_EQ(clk.pins[1].point, (Point{8000, 9000}));
  EXPECT_EQ(clk.pins[2].name, "ff2");
  EXPECT_EQ(clk.pins[2].point, (Point{2000, 3000}));
  EXPECT_EQ(clk.pins[2].line, 19);
  EXPECT_FALSE(clk.sketch);

  const Net& bump = l.nets[1];
  EXPECT_EQ(bump.name, "bump3");
  ASSERT_EQ(bump.pins.size(), 2u);
  EXPECT_EQ(bump.pins[0].name, "pad");
  EXPECT_FALSE(bump.pins[0].point);
  ASSERT_TRUE(bump.pins[0].shape);
  EXPECT_EQ(bump.pins[0].shape->kind, Shape::Kind::Rect);
  EXPECT_EQ(bump.pins[0].shape->rect, (Box{{100, 11000}, {400, 11800}}));
  EXPECT_EQ(bump.pins[0].shape->line, 22);
  ASSERT_TRUE(bump.pins[1].shape);
  EXPECT_EQ(bump.pins[1].shape->kind, Shape::Kind::Polygon);
  EXPECT_EQ(bump.pins[1].shape->polygon.outer,
            (Ring{{5000, 9000}, {5300, 8700}, {5600, 9000}, {5300, 9300}}));
  ASSERT_TRUE(bump.sketch);
  // Newline and tab between pairs, trailing space; the element starts on line 24.
  EXPECT_EQ(bump.sketch->points, (std::vector<Point>{{250, 11400}, {3000, 11400}, {5000, 9000}}));
  EXPECT_EQ(bump.sketch->line, 24);

  ASSERT_TRUE(l.routes);
  EXPECT_EQ(l.routes->tool, "taut 0.1.0");
  EXPECT_EQ(l.routes->metric, "l1");
  EXPECT_EQ(l.routes->orientations, "rectilinear");
  EXPECT_EQ(l.routes->line, 27);
  ASSERT_EQ(l.routes->routes.size(), 2u);
  const Route& r0 = l.routes->routes[0];
  EXPECT_EQ(r0.net, "clk");
  EXPECT_EQ(r0.status, "routed");
  EXPECT_EQ(r0.length, "23000");
  EXPECT_EQ(r0.bends, 4);
  EXPECT_FALSE(r0.reason);
  ASSERT_EQ(r0.wires.size(), 2u);
  EXPECT_EQ(r0.wires[0].points, (std::vector<Point>{{500, 500}, {500, 9000}, {8000, 9000}}));
  EXPECT_EQ(r0.wires[1].points, (std::vector<Point>{{8000, 9000}, {12000, 9000}, {12000, 11000}}));
  EXPECT_EQ(r0.wires[1].line, 30);
  const Route& r1 = l.routes->routes[1];
  EXPECT_EQ(r1.net, "bump3");
  EXPECT_EQ(r1.status, "failed");
  EXPECT_FALSE(r1.length);
  EXPECT_FALSE(r1.bends);
  EXPECT_EQ(r1.reason, "pin bump is enclosed by blockage ring");
  EXPECT_TRUE(r1.wires.empty());
  EXPECT_EQ(r1.line, 32);
}

TEST(ReaderGood, DefaultsWhenOptionalPartsAreAbsent) {
  ReadResult r = parse_layout("<layout><rules/></layout>", "mem.xml");
  ASSERT_TRUE(r.layout) << dump(r.diagnostics);
  EXPECT_EQ(r.layout->name, "");
  EXPECT_EQ(r.layout->version, 1);
  EXPECT_EQ(r.layout->dbu_per_micron, 1000);
  EXPECT_FALSE(r.layout->boundary);
  ASSERT_TRUE(r.layout->rules);
  EXPECT_EQ(r.layout->rules->wire_width, 0);
  EXPECT_EQ(r.layout->rules->spacing, 0);
  EXPECT_EQ(r.layout->rules->bend_cost, 0);
  EXPECT_EQ(r.layout->rules->orientations, "rectilinear");
  EXPECT_TRUE(r.layout->rules->orientation_degrees.empty());
  EXPECT_FALSE(r.layout->routes);
  EXPECT_EQ(r.layout->file, "mem.xml");
}

// ---------------------------------------------------------------------------------------------
// Numbers and points against an independent reference: a regex for the syntax and decimal
// string comparison for the range (no from_chars).

// -1: syntax error, 0: out of range, 1: accepted.
using taut::test::reference_int;

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"') o += "&quot;";
    else if (c == '&') o += "&amp;";
    else if (c == '<') o += "&lt;";
    else o += c;
  }
  return o;
}

TEST(ReaderNumbers, RandomStringsAgreeWithReference) {
  const unsigned base_seed = 20240611;
  const std::string alphabet = "0123456789-+ .eExXnaif,\t";
  for (unsigned i = 0; i < 3000; ++i) {
    const unsigned seed = base_seed + i;
    std::mt19937 rng(seed);
    std::string s;
    const int len = std::uniform_int_distribution<int>(0, 12)(rng);
    const bool digits_only = rng() % 2;
    for (int k = 0; k < len; ++k)
      s += digits_only && !(k == 0 && rng() % 3 == 0)
               ? static_cast<char>('0' + rng() % 10)
               : alphabet[rng() % alphabet.size()];
    if (s.find('\t') != std::string::npos) continue;  // XML normalizes a tab in an attribute
    const std::string doc = "<layout><boundary x0=\"" + xml_escape(s) +
                            "\" y0=\"-5\" x1=\"1073741823\" y1=\"5\"/></layout>";
    ReadResult r = parse_layout(doc, "n.xml");
    const int ref = reference_int(s);
    SCOPED_TRACE("seed " + std::to_string(seed) + " value \"" + s + "\"\n" + dump(r.diagnostics));
    if (ref == 1) {
      std::int64_t v = std::stoll(s);
      if (v >= 1073741823) {  // x0 >= x1: an empty boundary
        ASSERT_FALSE(r.layout);
        EXPECT_EQ(r.diagnostics.at(0).code, "GEOM-0010");
        continue;
      }
      ASSERT_TRUE(r.layout);
      EXPECT_EQ(r.layout->boundary->box.lo.x, v);
    } else {
      ASSERT_FALSE(r.layout);
      ASSERT_EQ(r.diagnostics.size(), 1u);
      EXPECT_EQ(r.diagnostics[0].code, ref == 0 ? "IO-0013" : "IO-0012");
      EXPECT_NE(r.diagnostics[0].message.find("attribute x0"), std::string::npos);
      EXPECT_EQ(r.diagnostics[0].line, 1);
    }
  }
}

TEST(ReaderNumbers, Boundaries) {
  for (const std::string v : {"1073741823", "-1073741823", "0", "-0", "0000000000001073741823"}) {
    ReadResult r = parse_layout("<layout><net name=\"n\"><pin name=\"p\" x=\"" + v + "\" y=\"0\"/></net></layout>", "b.xml");
    ASSERT_TRUE(r.layout) << v << dump(r.diagnostics);
    EXPECT_EQ(r.layout->nets[0].pins[0].point->x, std::stoll(v));
  }
  for (const std::string v : {"1073741824", "-1073741824", "2147483647", "-2147483648", "9223372036854775808"}) {
    ReadResult r = parse_layout("<layout><net name=\"n\"><pin name=\"p\" x=\"" + v + "\" y=\"0\"/></net></layout>", "b.xml");
    ASSERT_FALSE(r.layout) << v;
    EXPECT_EQ(r.diagnostics.at(0).code, "IO-0013") << v;
  }
}

TEST(ReaderPoints, RandomListsAgreeWithReference) {
  const unsigned base_seed = 777;
  for (unsigned i = 0; i < 1500; ++i) {
    const unsigned seed = base_seed + i;
    std::mt19937 rng(seed);
    // Build a list from tokens; the reference decides validity from the token structure.
    const int n = std::uniform_int_distribution<int>(0, 5)(rng);
    std::string s;
    std::vector<Point> pts;
    bool valid = n > 0;
    if (rng() % 4 == 0) s += " ";
    for (int k = 0; k < n; ++k) {
      if (k > 0) {
        switch (rng() % 8) {
          case 0: s += ";"; valid = false; break;
          case 1: s += ""; valid = false; break;
          case 2: s += "  "; break;
          case 3: s += " , "; valid = false; break;
          default: s += " "; break;
        }
      }
      const int x = static_cast<int>(rng() % 2001) - 1000, y = static_cast<int>(rng() % 2001) - 1000;
      std::string xs = std::to_string(x), ys = std::to_string(y);
      switch (rng() % 10) {
        case 0: xs += ".5"; valid = false; break;
        case 1: ys = "+" + ys; valid = false; break;
        case 2: xs = ""; valid = false; break;
        default: break;
      }
      const char* sep = rng() % 12 == 0 ? ", " : ",";
      if (sep[1]) valid = false;
      s += xs + sep + ys;
      pts.push_back({x, y});
    }
    if (rng() % 4 == 0) s += " ";
    const std::string doc = "<layout><net name=\"n\"><pin name=\"a\" x=\"0\" y=\"0\"/><sketch points=\"" + s +
                            "\"/></net></layout>";
    ReadResult r = parse_layout(doc, "p.xml");
    SCOPED_TRACE("seed " + std::to_string(seed) + " points \"" + s + "\"\n" + dump(r.diagnostics));
    if (valid && pts.size() < 2) {
      ASSERT_FALSE(r.layout);
      EXPECT_EQ(r.diagnostics.at(0).code, "IO-0021");
    } else if (valid) {
      ASSERT_TRUE(r.layout);
      EXPECT_EQ(r.layout->nets[0].sketch->points, pts);
    } else {
      ASSERT_FALSE(r.layout);
      EXPECT_EQ(r.diagnostics.at(0).code, n == 0 ? "IO-0014" : "IO-0014");
    }
  }
}

TEST(ReaderPoints, ClosingVertexDroppedOnlyWhenEqualToFirst) {
  ReadResult r = parse_layout(
      "<layout><blockage id=\"a\"><polygon points=\"0,0 4,0 0,4 0,0\"/>"
      "<polygon points=\"0,0 4,0 0,4 0,1\"/></blockage></layout>",
      "c.xml");
  ASSERT_TRUE(r.layout) << dump(r.diagnostics);
  EXPECT_EQ(r.layout->blockages[0].shapes[0].polygon.outer.size(), 3u);
  EXPECT_EQ(r.layout->blockages[0].shapes[1].polygon.outer.size(), 4u);
}

// ---------------------------------------------------------------------------------------------
// Structure, lines and limits.

TEST(ReaderStructure, CommentsAndWhitespaceAreFineTextIsNot) {
  EXPECT_TRUE(parse_layout("<!-- c --><layout> <!-- x -->\n\t<?pi x?><boundary x0='0' y0='0' x1='1' "
                           "y1='1'><!-- y --></boundary></layout>",
                           "c.xml")
                  .layout);
  ReadResult r = parse_layout("<layout>\n\n x</layout>", "t.xml");
  ASSERT_FALSE(r.layout);
  EXPECT_EQ(r.diagnostics.at(0).code, "IO-0011");
  EXPECT_EQ(r.diagnostics.at(0).line, 3);
  r = parse_layout("<layout><![CDATA[x]]></layout>", "t.xml");
  EXPECT_EQ(r.diagnostics.at(0).code, "IO-0011");
}

TEST(ReaderStructure, NamespacedThingsAreUnknown) {
  ReadResult r = parse_layout("<layout xmlns:q='urn:q'><q:boundary/></layout>", "n.xml");
  EXPECT_EQ(r.diagnostics.at(0).code, "IO-0008");
  r = parse_layout("<layout xmlns:q='urn:q' q:name='x'/>", "n.xml");
  EXPECT_EQ(r.diagnostics.at(0).code, "IO-0009");
  r = parse_layout("<layout xmlns='urn:q'/>", "n.xml");
  EXPECT_EQ(r.diagnostics.at(0).code, "IO-0007");
}

TEST(ReaderStructure, LenientSkipsUnknownSubtrees) {
  ReadOptions opt;
  opt.lenient = true;
  ReadResult r = parse_layout(
      "<layout><blockage id='a' color='red'><group><rect x0='0' y0='0' x1='1' y1='1'/></group>"
      "<rect x0='5' y0='5' x1='6' y1='6'/></blockage></layout>",
      "l.xml", opt);
  ASSERT_TRUE(r.layout) << dump(r.diagnostics);
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.layout->blockages[0].shapes.size(), 1u);
  EXPECT_EQ(r.layout->blockages[0].shapes[0].rect.lo, (Point{5, 5}));
}

TEST(ReaderStructure, LineNumbersBeyond65535) {
  std::string doc = "<layout>";
  doc.append(70000, '\n');
  doc += "<blockage id='far'>\n<rect x0='0' y0='0'\n x1='1.5' y1='1'/></blockage></layout>";
  ReadResult r = parse_layout(doc, "far.xml");
  ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].line, 70002);  // the line the <rect> tag starts on
  EXPECT_NE(r.diagnostics[0].message.find("blockage \"far\" rect: attribute x1: \"1.5\""), std::string::npos);
  r = parse_layout(doc.substr(0, doc.size() - 20), "far.xml");  // cut off
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].code, "IO-0005");
  EXPECT_GE(r.diagnostics[0].line, 70003);
}

TEST(ReaderLimits, SizeCapAndMissingFile) {
  ReadOptions small;
  small.max_bytes = 100;
  const auto r = read_layout(data("good/full.xml"), small);
  ASSERT_FALSE(r.layout);
  EXPECT_EQ(r.diagnostics.at(0).code, "IO-0002");
  EXPECT_EQ(parse_layout(std::string(101, ' '), "x", small).diagnostics.at(0).code, "IO-0002");
  const auto m = read_layout(data("bad/no_such_file.xml"));
  EXPECT_EQ(m.diagnostics.at(0).code, "IO-0001");
  const auto d = read_layout(data("bad"));  // a folder
  EXPECT_EQ(d.diagnostics.at(0).code, "IO-0001");
}

// An entity pointing at a real file with a marker: the marker must never show up, whatever
// the entity type (general, parameter, external subset).
TEST(ReaderSecurity, NothingIsEverLoaded) {
  const std::string dir = taut::test::temp_dir("xxe");
  const std::string secret = dir + "/secret.txt";
  taut::test::write_text(secret, "MARKER-7d1f");
  const std::string dtd = dir + "/x.dtd";
  taut::test::write_text(dtd, "<!ENTITY leak 'MARKER-7d1f'>");
  const std::vector<std::string> docs = {
      "<!DOCTYPE layout [<!ENTITY x SYSTEM 'file://" + secret + "'>]><layout name='&x;'/>",
      "<!DOCTYPE layout [<!ENTITY % p SYSTEM 'file://" + dtd + "'> %p;]><layout name='&leak;'/>",
      "<!DOCTYPE layout SYSTEM 'file://" + dtd + "'><layout name='&leak;'/>",
      "<layout xmlns:xi='http://www.w3.org/2001/XInclude'><xi:include href='file://" + secret +
          "' parse='text'/></layout>",
  };
  for (const auto& doc : docs) {
    for (bool lenient : {false, true}) {
      ReadOptions opt;
      opt.lenient = lenient;
      ReadResult r = parse_layout(doc, "x.xml", opt);
      SCOPED_TRACE(doc + "\n" + dump(r.diagnostics));
      if (r.layout) {
        EXPECT_EQ(r.layout->name.find("MARKER"), std::string::npos);
      }
      EXPECT_TRUE(lenient || !r.layout);
      for (const auto& d : r.diagnostics) EXPECT_EQ(d.message.find("MARKER"), std::string::npos);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Concurrency and speed.

TEST(ReaderThreads, ConcurrentParsesGiveTheSameDiagnostics) {
  const auto rows = taut::test::load_bad_cases();
  for (const auto& r : rows) EXPECT_EQ(r.file.find("<malformed"), std::string::npos) << r.file;
  std::vector<std::string> files;
  for (const auto& r : rows) files.push_back(data("bad/" + r.file));
  files.push_back(data("good/full.xml"));
  std::vector<std::vector<std::string>> sequential(files.size());
  for (std::size_t i = 0; i < files.size(); ++i)
    for (const auto& d : read_layout(files[i]).diagnostics) sequential[i].push_back(taut::format(d));
  std::vector<std::vector<std::vector<std::string>>> got(4, std::vector<std::vector<std::string>>(files.size()));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t k = 0; k < files.size(); ++k) {
        const std::size_t i = (k + static_cast<std::size_t>(t) * 7) % files.size();
        for (const auto& d : read_layout(files[i]).diagnostics) got[t][i].push_back(taut::format(d));
      }
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t)
    for (std::size_t i = 0; i < files.size(); ++i) EXPECT_EQ(got[t][i], sequential[i]) << files[i];
}

TEST(ReaderSpeed, ManyRects) {
#ifdef NDEBUG
  const int n = 250000;  // 10^6 vertices
#else
  const int n = 50000;
#endif
  std::string doc = "<?xml version=\"1.0\"?>\n<layout name=\"big\">\n";
  doc.reserve(static_cast<std::size_t>(n) * 90);
  for (int i = 0; i < n; ++i) {
    const int x = (i % 500) * 40, y = (i / 500) * 40;
    doc += "  <blockage id=\"b" + std::to_string(i) + "\"><rect x0=\"" + std::to_string(x) + "\" y0=\"" +
           std::to_string(y) + "\" x1=\"" + std::to_string(x + 20) + "\" y1=\"" + std::to_string(y + 20) +
           "\"/></blockage>\n";
  }
  doc += "</layout>\n";
  const auto t0 = std::chrono::steady_clock::now();
  ReadResult r = parse_layout(doc, "big.xml");
  const double read_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(r.layout) << dump(r.diagnostics);
  ASSERT_EQ(r.layout->blockages.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(r.layout->blockages[n - 1].shapes[0].line, n + 2);
  const auto t1 = std::chrono::steady_clock::now();
  const auto v = validate_layout(*r.layout);
  const double val_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  EXPECT_TRUE(v.empty());
  std::printf("[ speed    ] %d rects (%zu bytes): read %.3f s, validate %.3f s\n", n, doc.size(), read_s, val_s);
}

TEST(Orientations, CSetsThatNameRectilinearOrOctilinear) {
  using taut::io::canonical_orientations;
  EXPECT_EQ(canonical_orientations("c:0,90"), "rectilinear");
  EXPECT_EQ(canonical_orientations("c:270,180,90.0"), "rectilinear");
  EXPECT_EQ(canonical_orientations("c:0,45,90,135"), "octilinear");
  EXPECT_EQ(canonical_orientations("c:225,315,0,90,90"), "octilinear");
  // anything else is left as written
  for (const char* other : {"c:0,60,120", "c:0,45,90", "c:0,90,45.5", "c:0", "c:", "c:0,,90", "c:-90,0", "c:0,9e1",
                            "rectilinear", "octilinear", "any", "bogus"})
    EXPECT_EQ(canonical_orientations(other), other);
}

}  // namespace reader_test
