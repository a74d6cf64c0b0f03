// Tests of import_def (io/lefdef.h): the eight DEF orientations against positions worked out by
// hand from the DEF reference's definitions, LEF ORIGIN, what becomes a net and what a blockage,
// the bump-to-pad assignment against an exhaustive search over every assignment, each
// diagnostic with its file and line, and seeded mutations of a small design that must be
// answered (a layout or an error), never thrown or crashed on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "io/lefdef.h"
#include "support/small_lef.h"

namespace lefdef_test {
using taut::Diagnostic;
using taut::Severity;
using namespace taut::io;

using taut::test::kLef;

std::string def_with(const std::string& body) {
  return "VERSION 5.8 ;\nDIVIDERCHAR \"/\" ;\nDESIGN top ;\nUNITS DISTANCE MICRONS 1000 ;\n"
         "DIEAREA ( 0 0 ) ( 1000000 1000000 ) ;\n" +
         body + "END DESIGN\n";
}

DefImportResult run(const std::string& def, DefImportOptions o = {}) {
  if (o.layer.empty()) o.layer = "m2";
  return import_def_text({"t.def", def}, {{"t.lef", kLef}}, o);
}

const Blockage* blockage(const Layout& l, const std::string& id) {
  for (const Blockage& b : l.blockages)
    if (b.id == id) return &b;
  return nullptr;
}

const Net* net(const Layout& l, const std::string& name) {
  for (const Net& n : l.nets)
    if (n.name == name) return &n;
  return nullptr;
}

std::string errors(const DefImportResult& r) {
  std::string s;
  for (const Diagnostic& d : r.diagnostics) s += format(d) + "\n";
  return s;
}

TEST(ImportDef, EightOrientationsPlacePinsAsTheDefReferenceDefinesThem) {
  // expected box of pin P (DBU) for a cell placed at (1000, 2000), worked out by hand:
  // N (x, y); S (W-x, H-y); W (H-y, x); E (y, W-x); FN (W-x, y); FS (x, H-y); FW (y, x);
  // FE (H-y, W-x); with W = 30000, H = 10000, P = [1000, 3000] x [2000, 4000]
  const std::vector<std::pair<std::string, Box>> cases = {
      {"N", {{2000, 4000}, {4000, 6000}}},     {"S", {{28000, 8000}, {30000, 10000}}},
      {"W", {{7000, 3000}, {9000, 5000}}},     {"E", {{3000, 29000}, {5000, 31000}}},
      {"FN", {{28000, 4000}, {30000, 6000}}},  {"FS", {{2000, 8000}, {4000, 10000}}},
      {"FW", {{3000, 3000}, {5000, 5000}}},    {"FE", {{7000, 29000}, {9000, 31000}}}};
  for (const auto& [orient, want] : cases) {
    const DefImportResult r = run(def_with("COMPONENTS 1 ;\n - c1 CELL + FIXED ( 1000 2000 ) " + orient + " ;\nEND COMPONENTS\n"));
    ASSERT_TRUE(r.layout) << orient << "\n" << errors(r);
    const Blockage* b = blockage(*r.layout, "c1/P");
    ASSERT_NE(b, nullptr) << orient;
    ASSERT_EQ(b->shapes.size(), 1u);
    EXPECT_EQ(b->shapes[0].kind, Shape::Kind::Rect);
    EXPECT_EQ(b->shapes[0].rect, want) << orient;
  }
}

TEST(ImportDef, OriginShiftsShapesAndPolygonsStayPolygons) {
  const DefImportResult r = run(def_with("COMPONENTS 1 ;\n - b1 BUMP + FIXED ( 100000 200000 ) N ;\nEND COMPONENTS\n"));
  ASSERT_TRUE(r.layout) << errors(r);
  const Blockage* b = blockage(*r.layout, "b1/PAD");
  ASSERT_NE(b, nullptr);
  ASSERT_EQ(b->shapes[0].kind, Shape::Kind::Polygon);
  // the diamond about the origin (22.5, 22.5) um: its centre at the placement + 22500
  const std::vector<Point> want = {{145000, 222500}, {122500, 245000}, {100000, 222500}, {122500, 200000}};
  EXPECT_EQ(b->shapes[0].polygon.outer, want);
}

TEST(ImportDef, NetsTakeTheirTerminalsAndEverythingElseOnTheLayerBlocks) {
  const std::string def = def_with(
      "COMPONENTS 3 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - b CELL + PLACED ( 100000 0 ) N ;\n - u CELL + UNPLACED ;\nEND COMPONENTS\n"
      "PINS 1 ;\n - io + NET s + DIRECTION INPUT + USE SIGNAL\n  + PORT + LAYER m2 ( -500 -500 ) ( 500 500 ) + FIXED ( 50000 90000 ) N ;\nEND PINS\n"
      "BLOCKAGES 2 ;\n - LAYER m2 RECT ( 500000 500000 ) ( 510000 520000 ) ;\n - PLACEMENT RECT ( 0 0 ) ( 10 10 ) ;\nEND BLOCKAGES\n"
      "SPECIALNETS 1 ;\n - OTHER ( * VDD ) + ROUTED m2 2000 + SHAPE STRIPE ( 600000 100000 ) ( 700000 * ) + USE POWER ;\nEND SPECIALNETS\n"
      "NETS 2 ;\n - s ( a P ) ( b P ) ( PIN io ) + USE SIGNAL ;\n - VDD ( a VDD ) + USE POWER ;\nEND NETS\n");
  DefImportOptions o;
  o.nets = {"s", "VDD"};
  o.wire_width = "0.2";
  o.spacing = "0.15";
  const DefImportResult r = run(def, o);
  // (u is unplaced with shapes on the layer: refused)
  ASSERT_FALSE(r.layout);
  ASSERT_EQ(r.diagnostics.size(), 1u) << errors(r);
  EXPECT_EQ(r.diagnostics[0].code, "IO-0122");
  EXPECT_EQ(r.diagnostics[0].line, 9);

  std::string placed = def;
  placed.replace(placed.find(" - u CELL + UNPLACED ;\n"), std::string(" - u CELL + UNPLACED ;\n").size(), "");
  const DefImportResult ok = run(placed, o);
  ASSERT_TRUE(ok.layout) << errors(ok);
  const Layout& l = *ok.layout;
  EXPECT_EQ(l.rules->wire_width, 200);
  EXPECT_EQ(l.rules->spacing, 150);
  EXPECT_EQ(l.boundary->box, (Box{{0, 0}, {1000000, 1000000}}));
  const Net* s = net(l, "s");
  ASSERT_NE(s, nullptr);
  ASSERT_EQ(s->pins.size(), 3u);
  EXPECT_EQ(s->pins[0].name, "a/P");
  EXPECT_EQ(s->pins[1].name, "b/P");
  EXPECT_EQ(s->pins[2].name, "PIN/io");
  EXPECT_EQ(s->pins[2].shape->rect, (Box{{49500, 89500}, {50500, 90500}}));
  // VDD: a/VDD explicitly, b/VDD by the global connection of a power net
  const Net* vdd = net(l, "VDD");
  ASSERT_NE(vdd, nullptr);
  ASSERT_EQ(vdd->pins.size(), 2u);
  EXPECT_EQ(vdd->pins[1].name, "b/VDD");
  // the rest on the layer: obstructions, the layer blockage, the other net's wiring (half the
  // width to each side, none past its ends: no extension values); the placement blockage and m1
  // shapes are not on the layer
  ASSERT_NE(blockage(l, "a/OBS"), nullptr);
  EXPECT_EQ(blockage(l, "a/OBS")->shapes[0].rect, (Box{{10000, 5000}, {12500, 6000}}));
  ASSERT_NE(blockage(l, "b/OBS"), nullptr);
  ASSERT_NE(blockage(l, "BLOCKAGE/1"), nullptr);
  EXPECT_EQ(blockage(l, "BLOCKAGE/2"), nullptr);
  ASSERT_NE(blockage(l, "OTHER/wiring"), nullptr);
  EXPECT_EQ(blockage(l, "OTHER/wiring")->shapes[0].rect, (Box{{600000, 99000}, {700000, 101000}}));
  EXPECT_EQ(l.blockages.size(), 4u);
  EXPECT_EQ(ok.stats.nets, 2u);
  EXPECT_EQ(ok.stats.pins, 5u);
}

// Bumps on a row, pads on another: the written nets join each bump to one pad, and the total L1
// distance between centres is the least over every assignment (exhaustive reference).
TEST(ImportDef, BumpToPadTakesTheAssignmentOfLeastTotalDistance) {
  for (unsigned seed = 1; seed <= 300; ++seed) {
    std::mt19937 rng(seed);
    const int nb = 1 + static_cast<int>(rng() % 5), np = 1 + static_cast<int>(rng() % 5);
    std::string comps, terms;
    std::vector<Point> bump_c, pad_c;  // doubled centres, as the assignment measures
    for (int i = 0; i < nb; ++i) {
      const int x = 100000 * i + static_cast<int>(rng() % 50) * 1000, y = 500000 + static_cast<int>(rng() % 200) * 1000;
      comps += " - b" + std::to_string(i) + " BUMP + FIXED ( " + std::to_string(x) + " " + std::to_string(y) + " ) N ;\n";
      terms += " ( b" + std::to_string(i) + " PAD )";
      bump_c.push_back({2 * x + 45000, 2 * y + 45000});
    }
    for (int j = 0; j < np; ++j) {
      const int x = 60000 * j + static_cast<int>(rng() % 40) * 1000, y = static_cast<int>(rng() % 100) * 1000;
      comps += " - c" + std::to_string(j) + " CELL + FIXED ( " + std::to_string(x) + " " + std::to_string(y) + " ) N ;\n";
      terms += " ( c" + std::to_string(j) + " P )";
      pad_c.push_back({2 * x + 4000, 2 * y + 6000});
    }
    DefImportOptions o;
    o.bump_to_pad = true;
    o.nets = {"n"};
    const DefImportResult r = run(def_with("COMPONENTS " + std::to_string(nb + np) + " ;\n" + comps + "END COMPONENTS\nNETS 1 ;\n - n" +
                                           terms + " ;\nEND NETS\n"),
                                  o);
    ASSERT_TRUE(r.layout) << "seed " << seed << "\n" << errors(r);
    auto dist = [](Point a, Point b) { return std::abs(std::int64_t{a.x} - b.x) + std::abs(std::int64_t{a.y} - b.y); };
    if (nb + np == 2) {  // two pins: the net as it is
      ASSERT_EQ(r.layout->nets.size(), 1u) << "seed " << seed;
      continue;
    }
    // a net per pad used: its bumps, then the pad; no pad in two nets (pins of one net are
    // obstacles for every other: a pad written twice would shut both out)
    std::int64_t got = 0;
    int bumps_seen = 0;
    std::vector<int> uses(np, 0), nets_of(np, 0);
    for (const Net& n : r.layout->nets) {
      ASSERT_GE(n.pins.size(), 2u);
      const std::string& pad = n.pins.back().name;
      ASSERT_EQ(pad[0], 'c') << "seed " << seed;
      const int c = std::stoi(pad.substr(1, pad.find('/') - 1));
      ++nets_of[c];
      for (std::size_t k = 0; k + 1 < n.pins.size(); ++k) {
        ASSERT_EQ(n.pins[k].name[0], 'b') << "seed " << seed;
        const int b = std::stoi(n.pins[k].name.substr(1, n.pins[k].name.find('/') - 1));
        got += dist(bump_c[b], pad_c[c]);
        ++uses[c];
        ++bumps_seen;
      }
    }
    EXPECT_EQ(bumps_seen, nb) << "seed " << seed;
    const int cap = (nb + np - 1) / np;
    for (int c = 0; c < np; ++c) {
      EXPECT_LE(uses[c], cap) << "seed " << seed;
      EXPECT_LE(nets_of[c], 1) << "seed " << seed;
    }
    // exhaustive: every map of bumps to pads using each pad at most cap times
    std::int64_t best = std::numeric_limits<std::int64_t>::max();
    std::vector<int> pick(nb, 0);
    for (;;) {
      std::vector<int> cnt(np, 0);
      bool okc = true;
      std::int64_t c = 0;
      for (int i = 0; i < nb; ++i) {
        okc = okc && ++cnt[pick[i]] <= cap;
        c += dist(bump_c[i], pad_c[pick[i]]);
      }
      if (okc) best = std::min(best, c);
      int k = 0;
      while (k < nb && ++pick[k] == np) pick[k++] = 0;
      if (k == nb) break;
    }
    EXPECT_EQ(got, best) << "seed " << seed;
    // pads joined to no bump are blockages, and said so
    const int unused = static_cast<int>(std::count(uses.begin(), uses.end(), 0));
    int blocked = 0;
    for (const Blockage& b : r.layout->blockages) blocked += b.id.rfind("n/c", 0) == 0;
    EXPECT_EQ(blocked, unused) << "seed " << seed;
    bool warned = false;
    for (const Diagnostic& d : r.diagnostics) warned = warned || d.code == "IO-0128";
    EXPECT_EQ(warned, unused > 0) << "seed " << seed;
  }
}

struct BadCase {
  std::string what, def, code;
  int line;
  std::vector<std::string> nets = {};
  std::string file = "t.def";
};

TEST(ImportDef, BadInputIsAnsweredWithCodeFileAndLine) {
  const std::string comps = "COMPONENTS 1 ;\n - a CELL + FIXED ( 0 0 ) N ;\nEND COMPONENTS\n";  // lines 6-8
  const std::vector<BadCase> cases = {
      {"end of file inside a section", "UNITS DISTANCE MICRONS 1000 ;\nCOMPONENTS 1 ;\n - a CELL", "IO-0121", 3},
      {"no units", "DESIGN x ;\n", "IO-0121", 1},
      {"a bad orientation", def_with("COMPONENTS 1 ;\n - a CELL + FIXED ( 0 0 ) NE ;\nEND COMPONENTS\n"), "IO-0121", 7},
      {"a DIEAREA that is not a rectangle",
       "UNITS DISTANCE MICRONS 1000 ;\nDIEAREA ( 0 0 ) ( 10 0 ) ( 10 10 ) ( 5 20 ) ( 0 10 ) ;\nEND DESIGN\n", "IO-0122", 2},
      {"a coordinate that is not an integer", def_with("COMPONENTS 1 ;\n - a CELL + FIXED ( 0.5 0 ) N ;\nEND COMPONENTS\n"), "IO-0123", 7},
      {"a section read past without its count", def_with("REGIONS ;\nEND REGIONS\n"), "IO-0121", 6},
      {"a coordinate out of range", def_with("COMPONENTS 1 ;\n - a CELL + FIXED ( 2000000000 0 ) N ;\nEND COMPONENTS\n"), "IO-0123", 7},
      {"an undefined macro", def_with("COMPONENTS 1 ;\n - a NOPE + FIXED ( 0 0 ) N ;\nEND COMPONENTS\n"), "IO-0124", 7},
      {"an undefined component in a net", def_with(comps + "NETS 1 ;\n - n ( a P ) ( z P ) ;\nEND NETS\n"), "IO-0124", 10},
      {"an undefined macro pin in a net", def_with(comps + "NETS 1 ;\n - n ( a P ) ( a Q ) ;\nEND NETS\n"), "IO-0124", 10},
      {"an undefined DEF pin in a net", def_with(comps + "NETS 1 ;\n - n ( a P ) ( PIN q ) ;\nEND NETS\n"), "IO-0124", 10},
      {"a --nets pattern matching nothing", def_with(comps + "NETS 1 ;\n - n ( a P ) ;\nEND NETS\n"), "IO-0125", 0, {"x*"}},
      {"a terminal in two nets", def_with(comps + "NETS 2 ;\n - n ( a P ) ;\n - m ( a P ) ;\nEND NETS\n"), "IO-0129", 11},
      {"a DEF cut short", "UNITS DISTANCE MICRONS 1000 ;\nCOMPONENTS 1 ;\n - a CELL + FIXED ( 0 0 ) N ;\nEND COMPONENTS\n", "IO-0121", 4},
      {"a negative wire width", def_with("SPECIALNETS 1 ;\n - w + ROUTED m2 -100 ( 0 0 ) ( 100 0 ) ;\nEND SPECIALNETS\n"), "IO-0123", 7},
      {"a MUSTJOIN net", def_with(comps + "NETS 1 ;\n - MUSTJOIN ( a P ) ;\nEND NETS\n"), "IO-0122", 10},
      {"regular wiring of an unselected net on the layer",
       def_with(comps + "NETS 2 ;\n - n ( a P ) ;\n - m ( a VDD ) + ROUTED m2 ( 0 0 ) ( 100 0 ) ;\nEND NETS\n"), "IO-0122", 11, {"n"}},
      {"a sloped special wire", def_with("SPECIALNETS 1 ;\n - w + ROUTED m2 100 ( 0 0 ) ( 100 100 ) ;\nEND SPECIALNETS\n"), "IO-0122",
       7},
      // names XML cannot carry as written (found by fuzzing, 2026-12-06: two such names became one
      // U+FFFD name in the layout written, which taut check refused)
      {"DEF pins (blockages) named with a Latin-1 byte and a control character",
       def_with("PINS 2 ;\n - p\xe9 + NET x + LAYER m2 ( 0 0 ) ( 100 100 ) + FIXED ( 1000 1000 ) N ;\n"
                " - p\x01 + NET y + LAYER m2 ( 0 0 ) ( 100 100 ) + FIXED ( 5000 1000 ) N ;\nEND PINS\n"),
       "IO-0130", 7},
      // since 2026-12-06: a word that begins no DEF statement (junk before VERSION was skipped
      // to the next ';'), a section head without its count, and UNITS swallowed by a statement
      // missing its ';' (named at UNITS's line; it had none) or not an integer from 1 to 10^6
      {"bytes before VERSION", "\x7f\x45LF\x02 junk ;\n" + def_with(""), "IO-0121", 1},
      {"a word that begins no statement", def_with("COMPONENT 1 ;\n - a CELL + FIXED ( 0 0 ) N ;\nEND COMPONENT\n"), "IO-0121", 6},
      {"a section without its count", def_with("COMPONENTS ;\n - a CELL + FIXED ( 0 0 ) N ;\nEND COMPONENTS\n"), "IO-0121", 6},
      {"UNITS swallowed", "VERSION 5.8 ;\nDESIGN top\nUNITS DISTANCE MICRONS 1000 ;\nEND DESIGN\n", "IO-0121", 3},
      {"UNITS not a whole number", "VERSION 5.8 ;\nDESIGN top ;\n\nUNITS DISTANCE MICRONS 1e3 ;\nEND DESIGN\n", "IO-0123", 4},
      {"a net named with a Latin-1 byte",
       def_with("PINS 2 ;\n - a1 + NET n\xe9 + LAYER m2 ( 0 0 ) ( 100 100 ) + FIXED ( 1000 1000 ) N ;\n"
                " - a2 + NET n\xe9 + LAYER m2 ( 0 0 ) ( 100 100 ) + FIXED ( 5000 1000 ) N ;\nEND PINS\n"
                "NETS 1 ;\n - n\xe9 ( PIN a1 ) ( PIN a2 ) ;\nEND NETS\n"),
       "IO-0130", 11},
  };
  for (const BadCase& c : cases) {
    DefImportOptions o;
    o.nets = c.nets;
    const DefImportResult r = run(c.def, o);
    EXPECT_FALSE(r.layout) << c.what;
    ASSERT_FALSE(r.diagnostics.empty()) << c.what;
    const Diagnostic& d = r.diagnostics.back();
    EXPECT_EQ(d.severity, Severity::Error) << c.what;
    EXPECT_EQ(d.code, c.code) << c.what << ": " << format(d);
    EXPECT_EQ(d.line, c.line) << c.what << ": " << format(d);
    EXPECT_EQ(d.file, c.file) << c.what;
    if (c.what == std::string("bytes before VERSION")) {  // the word escaped
      EXPECT_NE(d.message.find("\"\\x7FELF\\x02\" begins no DEF statement"), std::string::npos) << d.message;
    }
    if (c.code == "IO-0130") {  // the name escaped and the byte
      EXPECT_TRUE(d.message.find("\"PIN/p\\xE9\" has byte 0xE9 at 6") != std::string::npos ||
                  d.message.find("net \"n\\xE9\" has byte 0xE9 at 2") != std::string::npos)
          << d.message;
    }
  }
  // the design's name (the layout's) too, at the DESIGN line
  const DefImportResult design = run("VERSION 5.8 ;\nDIVIDERCHAR \"/\" ;\nDESIGN t\xe9st ;\nUNITS DISTANCE MICRONS 1000 ;\n"
                                     "DIEAREA ( 0 0 ) ( 1000000 1000000 ) ;\nCOMPONENTS 1 ;\n - a CELL + FIXED ( 0 0 ) N ;\nEND COMPONENTS\nEND DESIGN\n");
  ASSERT_FALSE(design.layout);
  EXPECT_EQ(design.diagnostics.back().code, "IO-0130");
  EXPECT_EQ(design.diagnostics.back().line, 3);
  // the LEF's own errors name the LEF
  DefImportOptions m2;
  m2.layer = "m2";
  const std::string lef_text = "MACRO M\n SIZE 1.0005 BY 1 ;\n PIN A\n  PORT\n   LAYER m2 ;\n   RECT 0 0 1 1 ;\n  END\n END A\nEND M\n";
  const DefImportResult lef = import_def_text(
      {"t.def", def_with("COMPONENTS 1 ;\n - a M + FIXED ( 0 0 ) N ;\nEND COMPONENTS\n")}, {{"x.lef", lef_text}}, m2);
  ASSERT_FALSE(lef.layout);
  EXPECT_EQ(lef.diagnostics.back().code, "IO-0123");
  EXPECT_EQ(lef.diagnostics.back().file, "x.lef");
  EXPECT_EQ(lef.diagnostics.back().line, 2);
  // a SIZE of no area (found by fuzzing, 2026-12-06: accepted, and the cell's shapes flipped out
  // of its footprint), at its line in the LEF
  const std::string flat = "MACRO M\n SIZE -10 BY -10 ;\n PIN A\n  PORT\n   LAYER m2 ;\n   RECT 0 0 1 1 ;\n  END\n END A\nEND M\n";
  const DefImportResult sized = import_def_text(
      {"t.def", def_with("COMPONENTS 1 ;\n - a M + FIXED ( 0 0 ) S ;\nEND COMPONENTS\n")}, {{"x.lef", flat}}, m2);
  ASSERT_FALSE(sized.layout);
  EXPECT_EQ(sized.diagnostics.back().code, "IO-0123");
  EXPECT_EQ(sized.diagnostics.back().file, "x.lef");
  EXPECT_EQ(sized.diagnostics.back().line, 2);
  // a MACRO defined again in a second LEF: the later one is used, with a warning naming both places
  const std::string one = "MACRO M\n SIZE 2 BY 2 ;\n PIN A\n  PORT\n   LAYER m2 ;\n   RECT 0 0 1 1 ;\n  END\n END A\nEND M\n";
  const std::string two = "\nMACRO M\n SIZE 2 BY 2 ;\n PIN A\n  PORT\n   LAYER m2 ;\n   RECT 1 1 2 2 ;\n  END\n END A\nEND M\n";
  const DefImportResult again = import_def_text(
      {"t.def", def_with("COMPONENTS 1 ;\n - a M + FIXED ( 0 0 ) N ;\nEND COMPONENTS\n")}, {{"x.lef", one}, {"y.lef", two}}, m2);
  ASSERT_TRUE(again.layout);
  bool warned = false;
  for (const Diagnostic& d : again.diagnostics)
    if (d.code == "IO-0131") {
      warned = true;
      EXPECT_EQ(d.severity, Severity::Warning);
      EXPECT_EQ(d.file, "y.lef");
      EXPECT_EQ(d.line, 2);
      EXPECT_NE(d.message.find("first at x.lef:1"), std::string::npos) << d.message;
    }
  EXPECT_TRUE(warned);
  ASSERT_EQ(again.layout->blockages.size(), 1u);  // the later definition's shape: 1000..2000 DBU
  EXPECT_EQ(again.layout->blockages[0].shapes.at(0).rect.lo, (taut::geom::Point{1000, 1000}));
  // files that cannot be read
  const DefImportResult missing = import_def("/nonexistent/x.def", {}, m2);
  ASSERT_FALSE(missing.layout);
  EXPECT_EQ(missing.diagnostics.back().code, "IO-0120");
  // --wire-width not whole DBU
  DefImportOptions o;
  o.wire_width = "0.0005";
  const DefImportResult w = run(def_with(comps), o);
  ASSERT_FALSE(w.layout);
  EXPECT_EQ(w.diagnostics.back().code, "IO-0123");
}

TEST(ImportDef, WarningsSayWhatIsNotWritten) {
  const std::string def = def_with(
      "COMPONENTS 2 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - b CELL + FIXED ( 0 50000 ) N ;\nEND COMPONENTS\n"
      "SPECIALNETS 1 ;\n - n ( a P ) + ROUTED m2 2000 ( 0 0 ) ( 0 1000 ) ;\nEND SPECIALNETS\n"
      "NETS 2 ;\n - n ( a P ) ( b P ) ;\n - lone ( a VDD ) ;\nEND NETS\n");
  const DefImportResult r = run(def);
  ASSERT_TRUE(r.layout) << errors(r);
  std::vector<std::string> codes;
  for (const Diagnostic& d : r.diagnostics) {
    EXPECT_EQ(d.severity, Severity::Warning);
    codes.push_back(d.code + ":" + std::to_string(d.line));
  }
  // n's wiring is not kept (line 11); lone has one pin shape: a blockage, not a net (line 15)
  EXPECT_EQ(codes, (std::vector<std::string>{"IO-0127:11", "IO-0126:15"}));
  ASSERT_NE(blockage(*r.layout, "lone/a/VDD"), nullptr);
  EXPECT_EQ(r.layout->nets.size(), 1u);
}

// A section whose count differs from the items it holds (a file cut or edited by hand, as
// OpenROAD's flip-chip test DEF: COMPONENTS 1489 with 1,452 items) is named at its head, with
// both numbers, and what it holds is read (since 2026-12-06: before, the count was skipped).
TEST(ImportDef, ASectionCountThatDiffersFromItsItemsIsNamed) {
  const std::string def = def_with(
      "COMPONENTS 3 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - b CELL + FIXED ( 0 50000 ) N ;\nEND COMPONENTS\n"
      "NETS 1 ;\n - n ( a P ) ( b P ) ;\nEND NETS\n"
      "PINS 0 ;\n - q + NET x + LAYER m2 ( 0 0 ) ( 100 100 ) + FIXED ( 1000 1000 ) N ;\nEND PINS\n"
      // sections with nothing on the layer are counted too (since 2026-12-06)
      "REGIONS 1 ;\n - r1 ( -10 0 ) ( 10 10 ) + TYPE FENCE ;\nEND REGIONS\n"
      "GROUPS 1 ;\n - g1 a b\n + REGION r1 ;\nEND GROUPS\n"
      "NONDEFAULTRULES 1 ;\n - wide + HARDSPACING\n + LAYER m2 WIDTH 400 ;\n - wider + LAYER m2 WIDTH 800 ;\nEND NONDEFAULTRULES\n"
      "STYLES 2 ;\n - STYLE 0 ( 30 10 ) ( 10 30 ) ( -10 30 ) ;\n - STYLE 1 ( 0 0 ) ( 5 5 ) ;\nEND STYLES\n"
      "SLOTS 1 ;\n - LAYER m2 RECT ( 0 0 ) ( 10 10 ) ;\nEND SLOTS\n");
  const DefImportResult r = run(def);
  ASSERT_TRUE(r.layout) << errors(r);
  std::vector<std::string> got;
  for (const Diagnostic& d : r.diagnostics)
    if (d.code == "IO-0132") {
      EXPECT_EQ(d.severity, Severity::Warning);
      got.push_back(std::to_string(d.line) + ": " + d.message);
    }
  EXPECT_EQ(got, (std::vector<std::string>{"6: section COMPONENTS declares 3 items and holds 2",
                                           "13: section PINS declares 0 items and holds 1",
                                           "23: section NONDEFAULTRULES declares 1 item and holds 2"}))
      << errors(r);
  ASSERT_NE(net(*r.layout, "n"), nullptr);
  EXPECT_EQ(net(*r.layout, "n")->pins.size(), 2u);
  ASSERT_NE(blockage(*r.layout, "PIN/q"), nullptr);
}

// Regressions from a seeded search over real DEF/LEF files (OpenROAD's test data) and mutations.
TEST(ImportDef, FoundBySearchingRealFiles) {
  // a statement missing its ';' swallows UNITS: refused, not written with 0 DBU per micron
  {
    const DefImportResult r = run("VERSION 5.8 ;\nDESIGN top\nUNITS DISTANCE MICRONS 1000 ;\nCOMPONENTS 1 ;\n - a CELL + FIXED ( 0 0 ) N ;\n"
                                  "END COMPONENTS\nEND DESIGN\n");
    ASSERT_FALSE(r.layout);
    EXPECT_EQ(r.diagnostics.back().code, "IO-0121");
  }
  // COMPONENTMASKSHIFT is a statement; a regular wire's RECT ( dx1 dy1 dx2 dy2 ) off the layer
  {
    const DefImportResult r = run(def_with("COMPONENTMASKSHIFT m1 m2 ;\nCOMPONENTS 2 ;\n - a CELL + FIXED ( 0 0 ) N ;\n"
                                           " - b CELL + FIXED ( 0 50000 ) N ;\nEND COMPONENTS\n"
                                           "NETS 1 ;\n - x ( a VDD ) + ROUTED m1 ( 0 0 ) RECT ( -10 -10 10 10 ) ;\nEND NETS\n"));
    EXPECT_TRUE(r.layout) << errors(r);
  }
  // numbers off the layer need not be whole DBU: an unused via's cut, a macro with nothing on it
  {
    std::string lef = kLef;
    lef.insert(lef.find("END LIBRARY"), "VIA V2 DEFAULT\n LAYER cut ; RECT -0.0005 -0.0005 0.0005 0.0005 ;\nEND V2\n"
                                        "MACRO FAR\n SIZE 0.0005 BY 1 ;\n OBS\n  LAYER m1 ;\n  RECT 0 0 0.0005 1 ;\n END\nEND FAR\n");
    DefImportOptions o;
    o.layer = "m2";
    const DefImportResult r = import_def_text(
        {"t.def", def_with("COMPONENTS 2 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - f FAR + FIXED ( 0 0 ) S ;\nEND COMPONENTS\n")},
        {{"t.lef", lef}}, o);
    EXPECT_TRUE(r.layout) << errors(r);
  }
  // a selected net not written (fewer than two pins) keeps its wiring as a blockage
  {
    const DefImportResult r = run(def_with("COMPONENTS 1 ;\n - a CELL + FIXED ( 0 0 ) N ;\nEND COMPONENTS\n"
                                           "SPECIALNETS 1 ;\n - VSS + ROUTED m2 1000 ( 0 500000 ) ( 1000000 500000 ) + USE GROUND ;\n"
                                           "END SPECIALNETS\n"));
    ASSERT_TRUE(r.layout) << errors(r);
    const Blockage* w = blockage(*r.layout, "VSS/wiring");
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->shapes[0].rect, (Box{{0, 499500}, {1000000, 500500}}));
  }
  // a component defined twice: named, with its line
  {
    const DefImportResult r = run(def_with("COMPONENTS 2 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - a CELL + FIXED ( 0 50000 ) N ;\n"
                                           "END COMPONENTS\n"));
    ASSERT_FALSE(r.layout);
    EXPECT_EQ(r.diagnostics.back().code, "IO-0129");
    EXPECT_EQ(r.diagnostics.back().line, 8);
  }
  // objects carry the DEF line they come from (validation then names it)
  {
    const DefImportResult r = run(def_with("COMPONENTS 1 ;\n - a CELL + FIXED ( 0 0 ) N ;\nEND COMPONENTS\n"));
    ASSERT_TRUE(r.layout);
    ASSERT_NE(blockage(*r.layout, "a/OBS"), nullptr);
    EXPECT_EQ(blockage(*r.layout, "a/OBS")->line, 7);
    EXPECT_EQ(blockage(*r.layout, "a/OBS")->shapes[0].line, 7);
  }
}

// Regressions from a review: pins turned about their origin, ORIGIN with a turned cell, vias in
// wiring (the layer they lead to, their orientation, arrays, `+ VIA`), DENSITY, and a wildcard
// that must not take a terminal another net names.
TEST(ImportDef, FoundByReview) {
  std::string lef = kLef;
  lef.insert(lef.find("END LIBRARY"),
             "MACRO OFF\n SIZE 10 BY 5 ;\n ORIGIN 1 2 ;\n PIN A\n  PORT\n   LAYER m2 ;\n   RECT ( -1 -2 ) ( 0 -1 ) ;\n  END\n END A\n"
             " DENSITY\n  LAYER m2 ;\n  RECT 0 0 10 5 50 ;\n END\nEND OFF\n"
             "NONDEFAULTRULE NDR\n HARDSPACING ;\n LAYER m2\n  WIDTH 1 ;\n END m2\n VIA NV DEFAULT\n  LAYER m1 ; RECT -1 -1 1 1 ;\n"
             "  LAYER m2 ; RECT -3 -1 3 1 ;\n END NV\nEND NDR\n");
  DefImportOptions o;
  o.layer = "m2";
  auto go = [&](const std::string& body, DefImportOptions opt) { return import_def_text({"t.def", def_with(body)}, {{"t.lef", lef}}, opt); };
  {
    const DefImportResult r = go(
        "COMPONENTS 1 ;\n - f OFF + FIXED ( 0 0 ) E ;\nEND COMPONENTS\n"
        "PINS 2 ;\n - pe + NET x + PORT + LAYER m2 ( 0 0 ) ( 3000 1000 ) + FIXED ( 100000 100000 ) E ;\n"
        " - pw + NET x + PORT + LAYER m2 ( 0 0 ) ( 3000 1000 ) + FIXED ( 100000 100000 ) FW ;\nEND PINS\n",
        o);
    ASSERT_TRUE(r.layout) << errors(r);
    // E: (y, W - x) with W = 10000, the pin [0, 1000]^2 after ORIGIN
    EXPECT_EQ(blockage(*r.layout, "f/A")->shapes[0].rect, (Box{{0, 9000}, {1000, 10000}}));
    // about the pin's origin: E (y, -x), FW (y, x)
    EXPECT_EQ(blockage(*r.layout, "PIN/pe")->shapes[0].rect, (Box{{100000, 97000}, {101000, 100000}}));
    EXPECT_EQ(blockage(*r.layout, "PIN/pw")->shapes[0].rect, (Box{{100000, 100000}, {101000, 103000}}));
  }
  {
    const DefImportResult r = go(
        "SPECIALNETS 5 ;\n"
        " - nv + ROUTED m1 2000 ( 800000 800000 ) NV ;\n"  // a via of a NONDEFAULTRULE
        " - up + ROUTED m1 2000 ( 500000 500000 ) V12 ( 500000 600000 ) ;\n"          // m1, then m2 after the via
        " - down + ROUTED m2 2000 ( 0 0 ) ( 0 100000 ) V12 E ( 100000 100000 ) ;\n"   // m2, then m1
        " - arr + ROUTED m1 2000 ( 700000 700000 ) V12 DO 2 BY 1 STEP 10000 0 ;\n"
        " - pv + VIA V12 ( 300000 300000 ) ( 400000 * ) ;\nEND SPECIALNETS\n",
        o);
    ASSERT_TRUE(r.layout) << errors(r);
    const Blockage* up = blockage(*r.layout, "up/wiring");
    ASSERT_NE(up, nullptr);
    ASSERT_EQ(up->shapes.size(), 2u);  // the via's m2 pad, then the m2 segment
    EXPECT_EQ(up->shapes[0].rect, (Box{{498000, 499000}, {502000, 501000}}));
    EXPECT_EQ(up->shapes[1].rect, (Box{{499000, 500000}, {501000, 600000}}));
    const Blockage* down = blockage(*r.layout, "down/wiring");
    ASSERT_NE(down, nullptr);
    ASSERT_EQ(down->shapes.size(), 2u);  // the m2 segment, the via's pad turned E; the m1 segment is not on m2
    EXPECT_EQ(down->shapes[1].rect, (Box{{-1000, 98000}, {1000, 102000}}));
    ASSERT_NE(blockage(*r.layout, "arr/wiring"), nullptr);
    EXPECT_EQ(blockage(*r.layout, "arr/wiring")->shapes.size(), 2u);
    ASSERT_NE(blockage(*r.layout, "nv/wiring"), nullptr);
    EXPECT_EQ(blockage(*r.layout, "nv/wiring")->shapes[0].rect, (Box{{797000, 799000}, {803000, 801000}}));
    ASSERT_NE(blockage(*r.layout, "pv/wiring"), nullptr);
    EXPECT_EQ(blockage(*r.layout, "pv/wiring")->shapes[1].rect, (Box{{398000, 299000}, {402000, 301000}}));
  }
  {  // a wildcard does not take a terminal another net names, whichever nets are selected
    const std::string body =
        "COMPONENTS 3 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - b CELL + FIXED ( 0 50000 ) N ;\n - c CELL + FIXED ( 0 100000 ) N ;\n"
        "END COMPONENTS\nSPECIALNETS 1 ;\n - n1 ( * P ) ;\nEND SPECIALNETS\nNETS 1 ;\n - n2 ( a P ) ( b P ) ;\nEND NETS\n";
    DefImportOptions one = o;
    one.nets = {"n1"};
    const DefImportResult r1 = go(body, one);
    ASSERT_TRUE(r1.layout) << errors(r1);
    EXPECT_EQ(net(*r1.layout, "n1"), nullptr);  // only c/P: one pin, not a net
    EXPECT_NE(blockage(*r1.layout, "a/P"), nullptr);
    DefImportOptions both = o;
    both.nets = {"n1", "n2"};
    const DefImportResult r2 = go(body, both);
    ASSERT_TRUE(r2.layout) << errors(r2);
    ASSERT_NE(net(*r2.layout, "n2"), nullptr);
    EXPECT_EQ(net(*r2.layout, "n2")->pins.size(), 2u);
  }
}

// --keep-wiring: a net's special wiring as wires on their centrelines; a segment drawn out by half
// its width past a corner (OpenROAD's way: the boxes meet flush) is taken back to the corner,
// so the wires meet end to end; an extension value lengthens the blockage of another net's wire.
TEST(ImportDef, KeptWiringMeetsAtItsCorners) {
  const std::string def = def_with(
      "COMPONENTS 2 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - b CELL + FIXED ( 200000 100000 ) N ;\nEND COMPONENTS\n"
      "SPECIALNETS 2 ;\n"
      // a/P centre (2000, 3000) to b/P centre (202000, 103000): right, up, right; width 1000
      " - s ( a P ) ( b P ) + ROUTED m2 1000 ( 2000 3000 ) ( 100500 3000 ) NEW m2 1000 ( 100000 2500 ) ( 100000 103500 )\n"
      "   NEW m2 1000 ( 99500 103000 ) ( 202000 103000 ) ;\n"
      " - o + ROUTED m2 1000 ( 500000 500000 300 ) ( 600000 500000 ) ;\n"
      "END SPECIALNETS\n");
  DefImportOptions o;
  o.nets = {"s"};
  o.keep_wiring = true;
  const DefImportResult r = run(def, o);
  ASSERT_TRUE(r.layout) << errors(r);
  ASSERT_TRUE(r.layout->routes);
  ASSERT_EQ(r.layout->routes->routes.size(), 1u);
  const Route& rt = r.layout->routes->routes[0];
  EXPECT_EQ(rt.status, "routed");
  ASSERT_EQ(rt.wires.size(), 3u);
  EXPECT_EQ(rt.wires[0].points, (std::vector<Point>{{2000, 3000}, {100000, 3000}}));
  EXPECT_EQ(rt.wires[1].points, (std::vector<Point>{{100000, 3000}, {100000, 103000}}));
  EXPECT_EQ(rt.wires[2].points, (std::vector<Point>{{100000, 103000}, {202000, 103000}}));
  EXPECT_EQ(rt.length, "300000");
  const Blockage* w = blockage(*r.layout, "o/wiring");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->shapes[0].rect, (Box{{499700, 499500}, {600000, 500500}}));
  // without the flag: no routes, and the wiring not kept is said
  o.keep_wiring = false;
  const DefImportResult plain = run(def, o);
  ASSERT_TRUE(plain.layout);
  EXPECT_FALSE(plain.layout->routes);
  ASSERT_FALSE(plain.diagnostics.empty());
  EXPECT_EQ(plain.diagnostics[0].code, "IO-0127");
  // a kept net whose wiring on the layer has no metal (a segment of one point, another of width
  // 0) is written failed, and its reason says what the DEF has there and where (since
  // 2026-12-06: before, "no special wiring")
  const std::string empty = def_with(
      "COMPONENTS 2 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - b CELL + FIXED ( 200000 100000 ) N ;\nEND COMPONENTS\n"
      "SPECIALNETS 1 ;\n - s ( a P ) ( b P ) + ROUTED m2 1000 ( 2000 3000 ) ( 2000 3000 )\n"
      "   NEW m2 0 ( 2000 3000 ) ( 9000 3000 ) ;\nEND SPECIALNETS\n");
  o.keep_wiring = true;
  const DefImportResult e = run(empty, o);
  ASSERT_TRUE(e.layout) << errors(e);
  ASSERT_TRUE(e.layout->routes);
  ASSERT_EQ(e.layout->routes->routes.size(), 1u);
  EXPECT_EQ(e.layout->routes->routes[0].status, "failed");
  EXPECT_EQ(e.layout->routes->routes[0].reason, "its special wiring on layer m2 in the DEF has no segment of both length and width (line 11)");
  // a path of one point on the layer too
  const DefImportResult one = run(def_with("COMPONENTS 2 ;\n - a CELL + FIXED ( 0 0 ) N ;\n - b CELL + FIXED ( 200000 100000 ) N ;\n"
                                           "END COMPONENTS\nSPECIALNETS 1 ;\n - s ( a P ) ( b P )\n + ROUTED m2 1000 ( 2000 3000 ) ;\n"
                                           "END SPECIALNETS\n"),
                                  o);
  ASSERT_TRUE(one.layout) << errors(one);
  ASSERT_TRUE(one.layout->routes);
  EXPECT_EQ(one.layout->routes->routes[0].reason, "its special wiring on layer m2 in the DEF has no segment of both length and width (line 12)");
}

// Seeded mutations of a small design (tokens deleted, duplicated, swapped, the text cut short):
// every one is answered with a layout or an error diagnostic, never an exception.
TEST(ImportDef, MutatedInputIsAnsweredNeverThrown) {
  const std::string base = def_with(
      "COMPONENTS 2 ;\n - a CELL + FIXED ( 0 0 ) FS ;\n - b BUMP + FIXED ( 100000 100000 ) W ;\nEND COMPONENTS\n"
      "PINS 1 ;\n - io + NET s + PORT + LAYER m2 ( -500 -500 ) ( 500 500 ) + FIXED ( 50000 90000 ) N ;\nEND PINS\n"
      "SPECIALNETS 1 ;\n - W ( * VDD ) + ROUTED m2 2000 + SHAPE STRIPE ( 600000 100000 ) ( 700000 * ) V12 NEW m2 2000 ( 0 0 ) ( 0 10 ) ;\n"
      "END SPECIALNETS\nNETS 1 ;\n - s ( a P ) ( b PAD ) ( PIN io ) + USE SIGNAL ;\nEND NETS\n");
  ASSERT_TRUE(run(base).layout) << errors(run(base));
  std::vector<std::string> toks;
  for (std::size_t i = 0; i < base.size();) {
    std::size_t j = base.find_first_of(" \n", i);
    if (j == std::string::npos) j = base.size();
    toks.push_back(base.substr(i, j - i + (j < base.size() ? 1 : 0)));
    i = j + 1;
  }
  int layouts = 0, refused = 0;
  for (unsigned seed = 1; seed <= 2000; ++seed) {
    std::mt19937 rng(seed);
    std::vector<std::string> t = toks;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits && !t.empty(); ++e) {
      const std::size_t k = rng() % t.size();
      switch (rng() % 5) {
        case 0: t.erase(t.begin() + static_cast<long>(k)); break;
        case 1: t.insert(t.begin() + static_cast<long>(k), t[rng() % t.size()]); break;
        case 2: std::swap(t[k], t[rng() % t.size()]); break;
        case 3: t.resize(k); break;
        default: t[k] = std::to_string(static_cast<int>(rng() % 4000000) - 2000000) + " "; break;
      }
    }
    const std::string text = std::accumulate(t.begin(), t.end(), std::string());
    DefImportResult r;
    ASSERT_NO_THROW(r = run(text)) << "seed " << seed;
    if (r.layout) {
      ++layouts;
    } else {
      ++refused;
      ASSERT_FALSE(r.diagnostics.empty()) << "seed " << seed;
      EXPECT_EQ(r.diagnostics.back().severity, Severity::Error) << "seed " << seed;
    }
  }
  EXPECT_GT(layouts, 50);
  EXPECT_GT(refused, 500);
}

}  // namespace lefdef_test
