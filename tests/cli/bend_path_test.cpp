// `taut path --metric combined|link` (issue #6) end to end: the JSON and text output, the cost
// it states, the rules' bend cost as the default, the trade between length and bends on the demo
// (exact at the tie), sloped blockages routed around their rectilinear cover with a warning
// naming the blockage and its line, and the refusals. Every answer is checked against
// oracle::BendReference (a Hanan-grid state-graph Dijkstra, independent of router::BendRouter)
// on the same rectilinear cover, and every wire with the reference's path check.
#include <gtest/gtest.h>

#include <map>
#include <tuple>
#include <nlohmann/json.hpp>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "io/layout_reader.h"
#include "oracle/bend_oracle.h"
#include "router/bend_router.h"
#include "support/run.h"
#include "support/sanitized.h"

namespace taut {
namespace bend_path_test {

using geom::Point;
using test::run_taut;

const std::string kDemo = std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml";

std::string pt(Point p) { return std::to_string(p.x) + "," + std::to_string(p.y); }

std::vector<Point> points_of(const nlohmann::json& a) {
  std::vector<Point> v;
  for (const auto& p : a) v.push_back({p[0].get<geom::Coord>(), p[1].get<geom::Coord>()});
  return v;
}

// The reference on the layout's blockages as `path` sees them: the rectilinear cover, normalized
// in the routing domain of the layout and the two ends.
struct Ref {
  geom::NormalizedObstacles norm;
  std::unique_ptr<oracle::BendReference> ref;
};
Ref reference_for(const std::string& file, std::vector<Point> ends) {
  const io::ReadResult rr = io::read_layout(file);
  EXPECT_TRUE(rr.layout.has_value());
  Ref r;
  r.norm = geom::normalize_obstacles(router::rectilinear_cover(io::blockage_polygons(*rr.layout)),
                                     io::routing_domain(*rr.layout, ends));
  r.ref = std::make_unique<oracle::BendReference>(r.norm.domain, r.norm.obstacles);
  return r;
}

// Runs `taut path --json` and checks its answer against the reference.
nlohmann::json check_path(const std::string& file, Point a, Point b, const std::vector<std::string>& metric,
                          bool link, std::int64_t c) {
  std::vector<std::string> args = {"path", file, "--from", pt(a), "--to", pt(b), "--json", "-q"};
  args.insert(args.end(), metric.begin(), metric.end());
  const auto run = run_taut(args);
  EXPECT_EQ(run.status, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  // one reference per layout and domain (the demo has a boundary: one for all its pairs)
  static std::map<std::string, Ref> cache;
  const io::ReadResult rr = io::read_layout(file);
  const geom::Box dom = io::routing_domain(*rr.layout, std::vector<Point>{a, b});
  const std::string key = file + "@" + pt(dom.lo) + ":" + pt(dom.hi);
  if (!cache.count(key)) cache.emplace(key, reference_for(file, {a, b}));
  const Ref& r = cache.at(key);
  const auto want = r.ref->best(a, b, link, c);
  EXPECT_TRUE(want.has_value());
  if (!want || run.status != 0) return j;
  EXPECT_EQ(j["metric"], link ? "link" : "combined");
  EXPECT_EQ(j["length"].get<std::int64_t>(), want->length);
  EXPECT_EQ(j["bends"].get<std::int64_t>(), want->bends);
  EXPECT_EQ(j["cost"].get<std::int64_t>(), link ? want->bends : want->length + c * want->bends);
  if (!link) {
    EXPECT_EQ(j["bend_cost"].get<std::int64_t>(), c);
  }
  const std::vector<Point> w = points_of(j["points"]);
  EXPECT_EQ(w.front(), a);
  EXPECT_EQ(w.back(), b);
  const auto got = r.ref->check_path(w);
  EXPECT_TRUE(got.has_value()) << "the wire leaves free space";
  if (got) {
    EXPECT_EQ(got->length, want->length);
    EXPECT_EQ(got->bends, want->bends);
  }
  return j;
}

TEST(BendPath, DemoTradesLengthForBendsExactlyAtTheTie) {
  // From the demo's lower-left corner into the pocket beside the L-shaped blockage: the shortest
  // wire (15500) needs 3 bends, the best 2-bend wire is 4000 longer. So C = 3999 keeps 3 bends,
  // C = 4000 ties (27500 either way; the tie goes to fewer bends) and takes 2.
  const Point a{500, 500}, b{5500, 8000};
  const auto l1 = check_path(kDemo, a, b, {"--metric", "combined", "--bend-cost", "0"}, false, 0);
  EXPECT_EQ(l1["length"], 15500);
  EXPECT_EQ(l1["bends"], 3);
  const auto below = check_path(kDemo, a, b, {"--metric", "combined", "--bend-cost", "3999"}, false, 3999);
  EXPECT_EQ(below["bends"], 3);
  const auto tie = check_path(kDemo, a, b, {"--metric", "combined", "--bend-cost", "4000"}, false, 4000);
  EXPECT_EQ(tie["bends"], 2);
  EXPECT_EQ(tie["cost"], 27500);
  const auto link = check_path(kDemo, a, b, {"--metric", "link"}, true, 0);
  EXPECT_EQ(link["bends"], 2);
  EXPECT_EQ(link["length"], 19500);
  EXPECT_EQ(link.count("bend_cost"), 0u);
  // the L1 metric on the same pair: the same length as combined with C = 0
  const auto r = run_taut({"path", kDemo, "--from", pt(a), "--to", pt(b), "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["length"], 15500);
}

TEST(BendPath, DemoPairsAgainstTheReference) {
  const std::vector<std::pair<Point, Point>> pairs = {
      {{500, 500}, {10000, 10000}}, {{1000, 6000}, {11000, 6000}}, {{9500, 3000}, {14500, 3000}},
      {{1000, 13000}, {21000, 5000}}, {{8000, 4000}, {12000, 4600}},  // from the pinch of ram1 and io
      {{0, 0}, {24000, 14000}},       {{500, 3500}, {10500, 10500}}};
  for (const auto& [a, b] : pairs) {
    SCOPED_TRACE(pt(a) + " -> " + pt(b));
    // every C in the Release tree; two under the sanitizers (each run of taut is ~10x slower there)
    const std::vector<std::int64_t> costs = test::kSanitized ? std::vector<std::int64_t>{0, 1000}
                                                            : std::vector<std::int64_t>{0, 1, 7, 1000, 1000000};
    for (const std::int64_t c : costs) {
      SCOPED_TRACE("C = " + std::to_string(c));
      check_path(kDemo, a, b, {"--metric", "combined", "--bend-cost", std::to_string(c)}, false, c);
    }
    check_path(kDemo, a, b, {"--metric", "link"}, true, 0);
  }
}

// --from-file: many sources to one target (router::BendTargetMap): each record in the file's
// order, equal to the reference's optimum and legal; a source inside a blockage gets its reason
// (ROUTE-0001) and the exit status 1; usage errors exit 2 with nothing on stdout.
TEST(BendPath, ManySourcesToOneTarget) {
  const std::string dir = test::temp_dir("bend_from_file");
  const std::string pts = dir + "/from.txt";
  const std::vector<Point> from = {{500, 500}, {1000, 6000}, {9500, 3000}, {24000, 14000}, {10000, 10000}, {8000, 4000}};
  std::string text = "# sources\n";
  for (const Point p : from) text += pt(p) + "\n\n";
  test::write_text(pts, text);
  const Point to{10500, 10500};
  const Ref ref = reference_for(kDemo, {});
  for (const bool link : {false, true}) {
    SCOPED_TRACE(link ? "link" : "combined");
    std::vector<std::string> args = {"path", kDemo, "--from-file", pts, "--to", pt(to), "--json", "-q"};
    if (link) args.insert(args.end(), {"--metric", "link"});
    else args.insert(args.end(), {"--metric", "combined", "--bend-cost", "700"});
    const auto r = run_taut(args);
    EXPECT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["to"], nlohmann::json::array({to.x, to.y}));
    ASSERT_EQ(j["paths"].size(), from.size());
    for (std::size_t i = 0; i < from.size(); ++i) {
      const auto& rec = j["paths"][i];
      EXPECT_EQ(rec["from"], nlohmann::json::array({from[i].x, from[i].y}));
      const auto want = ref.ref->best(from[i], to, link, 700);
      ASSERT_TRUE(want.has_value());
      EXPECT_EQ(rec["length"].get<std::int64_t>(), want->length) << pt(from[i]);
      EXPECT_EQ(rec["bends"].get<std::int64_t>(), want->bends) << pt(from[i]);
      EXPECT_EQ(rec["cost"].get<std::int64_t>(), link ? want->bends : want->length + 700 * want->bends);
      const std::vector<Point> w = points_of(rec["points"]);
      ASSERT_FALSE(w.empty());
      EXPECT_EQ(w.front(), from[i]);
      EXPECT_EQ(w.back(), to);
      const auto got = ref.ref->check_path(w);
      ASSERT_TRUE(got.has_value()) << "the wire leaves free space";
      EXPECT_EQ(*got, *want);
    }
  }
  // a source inside a blockage: its record has a reason, the others are answered, exit status 1
  test::write_text(pts, "500,500\n5000,3000\n");
  const auto bad = run_taut({"path", kDemo, "--from-file", pts, "--to", pt(to), "--metric", "link", "--json"});
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("ROUTE-0001"), std::string::npos) << bad.err;
  const auto jb = nlohmann::json::parse(bad.out);
  ASSERT_EQ(jb["paths"].size(), 2u);
  EXPECT_TRUE(jb["paths"][0]["cost"].is_number());
  EXPECT_TRUE(jb["paths"][1]["cost"].is_null());
  EXPECT_NE(jb["paths"][1]["reason"].get<std::string>().find("inside blockage"), std::string::npos) << bad.out;
  // usage: both or neither of --from and --from-file, the l1 metric, a bad line
  test::write_text(dir + "/bad.txt", "1,2\n3;4\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"path", kDemo, "--from", "1,1", "--from-file", pts, "--to", "5,5", "--metric", "link"}, "CLI-0022"},
      {{"path", kDemo, "--to", "5,5", "--metric", "link"}, "CLI-0022"},
      {{"path", kDemo, "--from-file", pts, "--to", "5,5"}, "CLI-0020"},
      {{"path", kDemo, "--from-file", dir + "/bad.txt", "--to", "5,5", "--metric", "link"}, dir + "/bad.txt:2: error: [CLI-0025]"},
  };
  for (const auto& [args, code] : cases) {
    const auto r = run_taut(args);
    EXPECT_EQ(r.status, 2) << code;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find(code), std::string::npos) << r.err;
  }
}

// --to-pin NET PIN: wires end anywhere on a pin of the layout. A small layout (so the
// reference can search from every integer point of the pin: best_between_on_lattice) with a
// diamond, an L-shaped pin, a point pin and a square partly under a blockage (since 2026-12-06
// reached as its part outside it, the free lattice points of the pin; before, ROUTE-0005); every
// record of --from-file (BendTargetMap on the shape) and every --from wire (l1 too: combined
// with C = 0 gives the L1 length) against it; then the refusals: no such net or pin (CLI-0028,
// exit 2, nothing on stdout), --to with --to-pin (CLI-0022).
TEST(BendPath, ToAPinOfTheLayout) {
  const std::string dir = test::temp_dir("bend_to_pin");
  const std::string file = dir + "/pins.xml";
  test::write_text(file, R"(<?xml version="1.0" encoding="UTF-8"?>
<layout name="pins" version="1" dbu-per-micron="1000">
  <boundary x0="0" y0="0" x1="30" y1="24"/>
  <blockage id="a"><rect x0="4" y0="4" x1="12" y1="8"/></blockage>
  <blockage id="b"><polygon points="16,2 26,2 26,12 22,12 22,6 16,6"/></blockage>
  <blockage id="c"><rect x0="8" y0="12" x1="14" y1="20"/></blockage>
  <net name="n">
    <pin name="bump"><polygon points="18,14 21,17 18,20 15,17"/></pin>
    <pin name="ell"><polygon points="24,16 28,16 28,22 26,22 26,18 24,18"/></pin>
    <pin name="dot" x="2" y="22"/>
    <pin name="under"><rect x0="10" y0="6" x1="14" y1="10"/></pin>
  </net>
</layout>
)");
  const io::ReadResult rr = io::read_layout(file);
  ASSERT_TRUE(rr.layout.has_value());
  const geom::NormalizedObstacles norm = geom::normalize_obstacles(io::blockage_polygons(*rr.layout), io::routing_domain(*rr.layout, {}));
  const oracle::BendReference ref(norm.domain, norm.obstacles);
  auto lattice = [&](const geom::Polygon& pin) {
    std::vector<Point> out;
    for (geom::Coord x = norm.domain.lo.x; x <= norm.domain.hi.x; ++x)
      for (geom::Coord y = norm.domain.lo.y; y <= norm.domain.hi.y; ++y)
        if (geom::locate({x, y}, pin) != geom::Location::Outside && ref.l1().is_free({x, y})) out.push_back({x, y});
    return out;
  };
  const std::map<std::string, geom::Polygon> pins = {
      {"bump", geom::Polygon{{{18, 14}, {21, 17}, {18, 20}, {15, 17}}, {}}},
      {"ell", geom::Polygon{{{24, 16}, {28, 16}, {28, 22}, {26, 22}, {26, 18}, {24, 18}}, {}}},
      {"dot", geom::Polygon{{{2, 22}}, {}}},
      {"under", geom::Polygon{{{10, 6}, {14, 6}, {14, 10}, {10, 10}}, {}}}};
  std::vector<Point> from;
  for (geom::Coord y = 0; y <= 24; y += 3)
    for (geom::Coord x = 1; x <= 30; x += 4) from.push_back({x, y});
  std::string text;
  for (const Point p : from) text += pt(p) + "\n";
  const std::string pts = dir + "/from.txt";
  test::write_text(pts, text);
  int answered = 0, inside = 0;
  for (const auto& [name, pin] : pins) {
    const std::vector<Point> T = name == "dot" ? std::vector<Point>{pin.outer[0]} : lattice(pin);
    for (const bool link : {false, true}) {
      if (test::kSanitized && link != (name == "ell")) continue;  // one metric per pin there
      SCOPED_TRACE(name + (link ? " link" : " combined"));
      const std::int64_t c = link ? 0 : 3;
      std::vector<std::string> args = {"path", file, "--from-file", pts, "--to-pin", "n", name, "--json", "-q"};
      if (link) args.insert(args.end(), {"--metric", "link"});
      else args.insert(args.end(), {"--metric", "combined", "--bend-cost", "3"});
      const auto r = run_taut(args);
      EXPECT_EQ(r.status, 1) << r.err;  // some sources lie inside blockages
      const auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j["to_pin"], nlohmann::json({{"net", "n"}, {"pin", name}}));
      ASSERT_EQ(j["paths"].size(), from.size());
      for (std::size_t i = 0; i < from.size(); ++i) {
        const auto& rec = j["paths"][i];
        const Point q[1] = {from[i]};
        const auto want = ref.best_between_on_lattice(q, T, link, c);
        if (!want) {
          EXPECT_TRUE(rec["cost"].is_null()) << pt(from[i]);
          EXPECT_FALSE(ref.l1().is_free(from[i]) && rec["reason"].get<std::string>().find("inside") != std::string::npos);
          ++inside;
          continue;
        }
        ASSERT_TRUE(rec["cost"].is_number()) << pt(from[i]) << " " << rec.dump();
        ++answered;
        EXPECT_EQ(rec["length"].get<std::int64_t>(), want->length) << pt(from[i]);
        EXPECT_EQ(rec["bends"].get<std::int64_t>(), want->bends) << pt(from[i]);
        const std::vector<Point> w = points_of(rec["points"]);
        ASSERT_FALSE(w.empty());
        EXPECT_EQ(w.front(), from[i]);
        EXPECT_NE(std::find(T.begin(), T.end(), w.back()), T.end()) << "the wire ends off the pin: " << pt(w.back());
        const auto got = ref.check_path(w);
        ASSERT_TRUE(got.has_value()) << "the wire leaves free space";
        EXPECT_EQ(*got, *want);
      }
    }
    // one source, every metric; l1 against the reference's length with C = 0 (one source under
    // the sanitizers, where every run of taut costs a second)
    const std::vector<Point> singles = test::kSanitized ? std::vector<Point>{{29, 1}} : std::vector<Point>{{1, 1}, {29, 1}, {15, 22}};
    for (const Point a : singles) {
      const Point q[1] = {a};
      for (const std::vector<std::string>& metric : std::vector<std::vector<std::string>>{
               {"--metric", "l1"}, {"--metric", "combined", "--bend-cost", "3"}, {"--metric", "link"}}) {
        const bool link = metric[1] == "link";
        const auto want = ref.best_between_on_lattice(q, T, link, metric[1] == "combined" ? 3 : 0);
        ASSERT_TRUE(want.has_value());
        std::vector<std::string> args = {"path", file, "--from", pt(a), "--to-pin", "n", name, "--json", "-q"};
        args.insert(args.end(), metric.begin(), metric.end());
        const auto r = run_taut(args);
        ASSERT_EQ(r.status, 0) << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j["length"].get<std::int64_t>(), want->length) << pt(a) << " to " << name << " " << metric[1];
        if (metric[1] != "l1") {
          EXPECT_EQ(j["bends"].get<std::int64_t>(), want->bends) << pt(a) << " to " << name << " " << metric[1];
        }
        const std::vector<Point> w = points_of(j["points"]);
        EXPECT_NE(std::find(T.begin(), T.end(), w.back()), T.end());
        EXPECT_TRUE(ref.check_path(w).has_value());
      }
    }
  }
  EXPECT_GE(answered, test::sanitized_share(300, 2));
  EXPECT_GE(inside, test::sanitized_share(20, 2));
  // usage errors: exit 2, nothing on stdout
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"path", file, "--from", "1,1", "--to-pin", "m", "bump"}, "CLI-0028] --to-pin: " + file + " has no net \"m\""},
      {{"path", file, "--from", "1,1", "--to-pin", "n", "pad", "--metric", "link"}, "CLI-0028] --to-pin: net \"n\" (" + file + ":7) has no pin \"pad\"; its pins: \"bump\", \"ell\", \"dot\", \"under\""},
      {{"path", file, "--from", "1,1", "--to", "2,2", "--to-pin", "n", "bump"}, "CLI-0022"},
      {{"path", file, "--from", "1,1"}, "CLI-0001] --to X,Y or --to-pin NET PIN is required"},
  };
  for (const auto& [args, code] : cases) {
    const auto r = run_taut(args);
    EXPECT_EQ(r.status, 2) << code;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find(code), std::string::npos) << r.err;
  }
}

TEST(BendPath, TextOutputRulesBendCostAndTheSlopedBlockageWarning) {
  const std::string dir = test::temp_dir("bend_path");
  const std::string file = dir + "/rules.xml";
  test::write_text(file,
                   "<layout name=\"r\" version=\"1\">\n"
                   "  <boundary x0=\"0\" y0=\"0\" x1=\"100\" y1=\"100\"/>\n"
                   "  <rules bend-cost=\"25\"/>\n"
                   "  <blockage id=\"wall\"><rect x0=\"40\" y0=\"0\" x1=\"60\" y1=\"80\"/></blockage>\n"
                   "  <blockage id=\"tri\"><polygon points=\"70,10 90,10 90,30\"/></blockage>\n"
                   "</layout>\n");
  // the rules' bend cost is the default; the triangle is routed around its cover, with a warning
  const auto r = run_taut({"path", file, "--from", "10,10", "--to", "95,5", "--metric", "combined"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(file + ":5: warning: [ROUTE-0008] blockage \"tri\" has sloped edges"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.out.rfind("cost ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("(combined, bend cost 25)"), std::string::npos) << r.out;
  const auto j = check_path(file, {10, 10}, {95, 5}, {"--metric", "combined"}, false, 25);
  // -q silences the warning
  const auto quiet = run_taut({"path", file, "--from", "10,10", "--to", "95,5", "--metric", "combined", "-q"});
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
  // --bend-cost overrides the rules
  check_path(file, {10, 10}, {95, 5}, {"--metric", "combined", "--bend-cost", "0"}, false, 0);
  // the l1 metric warns that it does not weigh the rules' bend cost
  const auto l1 = run_taut({"path", file, "--from", "10,10", "--to", "95,5"});
  EXPECT_EQ(l1.status, 0);
  EXPECT_NE(l1.err.find("CLI-0024"), std::string::npos) << l1.err;
  // a point inside the triangle's cover but outside the triangle is not free for this metric: with
  // one box per sloped edge (--cover-pieces 1) the whole square under the hypotenuse is covered;
  // with the default 16 pieces only boxes of 2 x 2 along it, so (72, 28) is free and (71, 11), on
  // the hypotenuse, is not
  check_path(file, {10, 10}, {72, 28}, {"--metric", "link"}, true, 0);
  const auto on_edge = run_taut({"path", file, "--from", "10,10", "--to", "71,11", "--metric", "link", "--json"});
  EXPECT_EQ(on_edge.status, 1);
  EXPECT_NE(on_edge.err.find("cover of sloped blockage \"tri\""), std::string::npos) << on_edge.err;
  const auto in_cover =
      run_taut({"path", file, "--from", "10,10", "--to", "72,28", "--metric", "link", "--json", "--cover-pieces", "1"});
  EXPECT_EQ(in_cover.status, 1);
  EXPECT_NE(in_cover.err.find("ROUTE-0001"), std::string::npos) << in_cover.err;
  EXPECT_NE(in_cover.err.find("cover of sloped blockage \"tri\""), std::string::npos) << in_cover.err;
  const auto jc = nlohmann::json::parse(in_cover.out);
  EXPECT_TRUE(jc["cost"].is_null());
  // octilinear orientations from the rules: refused with the rules' file:line
  const std::string oct = dir + "/oct.xml";
  test::write_text(oct,
                   "<layout name=\"o\" version=\"1\">\n"
                   "  <rules orientations=\"octilinear\"/>\n"
                   "</layout>\n");
  const auto ro = run_taut({"path", oct, "--from", "0,0", "--to", "5,5", "--metric", "link"});
  EXPECT_EQ(ro.status, 2);
  EXPECT_NE(ro.err.find(oct + ":2: error: [CLI-0021]"), std::string::npos) << ro.err;
  EXPECT_EQ(run_taut({"path", oct, "--from", "0,0", "--to", "5,5", "--metric", "link", "--orientations", "rectilinear"}).status, 0);
  // the largest bend cost is written and read back
  const auto big = run_taut({"route", file, "-q", "--metric", "combined", "--bend-cost", "1073741823", "-o", dir + "/big.xml"});
  EXPECT_EQ(big.status, 0) << big.err;
  EXPECT_EQ(run_taut({"check", dir + "/big.xml"}).status, 0);
  // walled in: exit 1, cost null
  const std::string walled = dir + "/walled.xml";
  test::write_text(walled,
                   "<layout name=\"w\" version=\"1\">\n"
                   "  <boundary x0=\"0\" y0=\"0\" x1=\"100\" y1=\"100\"/>\n"
                   "  <blockage id=\"wall\"><rect x0=\"40\" y0=\"0\" x1=\"60\" y1=\"100\"/></blockage>\n"
                   "</layout>\n");
  const auto u = run_taut({"path", walled, "--from", "10,10", "--to", "90,90", "--metric", "link", "--json"});
  EXPECT_EQ(u.status, 1);
  EXPECT_NE(u.err.find("ROUTE-0002"), std::string::npos) << u.err;
  EXPECT_TRUE(nlohmann::json::parse(u.out)["cost"].is_null());
}

// The README's two pictures are what `taut route` draws now, and the routed files say what they
// were routed with and pass `taut check`.
TEST(BendRoute, BendsDesignPicturesAndRoutes) {
  const std::string dir = test::temp_dir("bend_route");
  const std::string design = std::string(TAUT_SOURCE_DIR) + "/designs/bends.xml";
  struct Case {
    std::string c;
    std::int64_t length, bends;
  };
  for (const Case& k : {Case{"0", 20000, 7}, Case{"5000", 23000, 4}}) {
    SCOPED_TRACE("C = " + k.c);
    const std::string xml = dir + "/b" + k.c + ".xml", svg = dir + "/b" + k.c + ".svg";
    const auto r = run_taut({"route", design, "-q", "--metric", "combined", "--bend-cost", k.c, "-o", xml, "--svg", svg});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(test::read_text(svg), test::read_text(std::string(TAUT_SOURCE_DIR) + "/docs/bends-c" + k.c + ".svg"))
        << "docs/bends-c" << k.c << ".svg is not what taut draws now: copy " << svg;
    const io::ReadResult rr = io::read_layout(xml);
    ASSERT_TRUE(rr.layout && rr.layout->routes);
    EXPECT_EQ(rr.layout->routes->metric, "combined");
    EXPECT_EQ(rr.layout->routes->bend_cost.value_or(-1), std::stoll(k.c));
    ASSERT_EQ(rr.layout->routes->routes.size(), 1u);
    const io::Route& route = rr.layout->routes->routes[0];
    EXPECT_EQ(route.bends.value_or(-1), k.bends);
    ASSERT_EQ(route.wires.size(), 1u);
    // the same wire as `path` gives, checked against the reference
    const std::vector<Point>& w = route.wires[0].points;
    const Ref ref = reference_for(design, {w.front(), w.back()});
    const auto want = ref.ref->best(w.front(), w.back(), false, std::stoll(k.c));
    ASSERT_TRUE(want.has_value());
    EXPECT_EQ(want->length, k.length);
    EXPECT_EQ(want->bends, k.bends);
    const auto got = ref.ref->check_path(w);
    ASSERT_TRUE(got.has_value());
    EXPECT_EQ(got->length, k.length);
    EXPECT_EQ(got->bends, k.bends);
    test::expect_routes_check_except_clearance(xml);
  }
  // the rules' bend cost when no --bend-cost is given: bends.xml with bend-cost="5000" in its
  // <rules> routes the 4-bend wire of C = 5000, and --bend-cost 0 still overrides it
  {
    std::string text = test::read_text(design);
    const std::string from = "<rules bend-cost=\"0\"";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "<rules bend-cost=\"5000\"");
    const std::string rules = dir + "/rules5000.xml";
    test::write_text(rules, text);
    for (const auto& [extra, c, bends] : {std::tuple{std::vector<std::string>{}, 5000, 4},
                                          std::tuple{std::vector<std::string>{"--bend-cost", "0"}, 0, 7}}) {
      std::vector<std::string> args{"route", rules, "-q", "--metric", "combined", "-o", dir + "/rules.routed.xml"};
      args.insert(args.end(), extra.begin(), extra.end());
      const auto r = run_taut(args);
      ASSERT_EQ(r.status, 0) << r.err;
      const io::ReadResult rr = io::read_layout(dir + "/rules.routed.xml");
      ASSERT_TRUE(rr.layout && rr.layout->routes);
      EXPECT_EQ(rr.layout->routes->bend_cost.value_or(-1), c);
      ASSERT_EQ(rr.layout->routes->routes.size(), 1u);
      EXPECT_EQ(rr.layout->routes->routes[0].bends.value_or(-1), bends);
    }
  }
  // link: no bend-cost attribute; route --tighten does not combine with it
  const auto l = run_taut({"route", design, "-q", "--metric", "link", "-o", dir + "/link.xml"});
  ASSERT_EQ(l.status, 0) << l.err;
  const io::ReadResult rl = io::read_layout(dir + "/link.xml");
  ASSERT_TRUE(rl.layout && rl.layout->routes);
  EXPECT_EQ(rl.layout->routes->metric, "link");
  EXPECT_FALSE(rl.layout->routes->bend_cost.has_value());
  EXPECT_EQ(rl.layout->routes->routes[0].bends.value_or(-1), 4);
  const auto t = run_taut({"route", design, "--metric", "link", "--tighten", "-o", dir + "/t.xml"});
  EXPECT_EQ(t.status, 2);
  EXPECT_NE(t.err.find("CLI-0020"), std::string::npos) << t.err;
  EXPECT_FALSE(test::file_exists(dir + "/t.xml"));
  // the demo, together (the default): every net routed, and the whole check passes, the clearance
  // of the demo's <rules> included (the bend-aware wires among the others' grown wires and pins);
  // both metrics
  for (const std::vector<std::string>& m : {std::vector<std::string>{"--metric", "combined", "--bend-cost", "1000"},
                                           std::vector<std::string>{"--metric", "link"}}) {
    std::vector<std::string> args{"route", kDemo, "-o", dir + "/together.xml", "--stats", dir + "/together.json"};
    args.insert(args.end(), m.begin(), m.end());
    const auto r = run_taut(args);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("not routed"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("ROUTE-0015"), std::string::npos) << r.err;
    const auto c = run_taut({"check", dir + "/together.xml"});
    EXPECT_EQ(c.status, 0) << c.out << c.err;
    EXPECT_NE(c.out.find("clearance ok"), std::string::npos) << c.out;
    const nlohmann::json j = nlohmann::json::parse(test::read_text(dir + "/together.json"));
    EXPECT_TRUE(j.contains("net_router")) << j.dump();
    // two threads write the same file byte for byte
    args[3] = dir + "/together2.xml";
    args.insert(args.end(), {"--threads", "2"});
    const auto r2 = run_taut(args);
    EXPECT_EQ(r2.status, 0) << r2.err;
    EXPECT_EQ(r2.err.find("ROUTE-0017"), std::string::npos) << r2.err;
    EXPECT_EQ(test::read_text(dir + "/together2.xml"), test::read_text(dir + "/together.xml"));
  }
  // the demo with --independent: each net alone among the blockages, so each wire is the best
  // there (clk's three pins as a tree from drv; bump between two shape pins, a rectangle and a
  // diamond)
  const auto d = run_taut({"route", kDemo, "--metric", "combined", "--bend-cost", "1000", "--independent", "-o", dir + "/demo.xml"});
  EXPECT_EQ(d.status, 0) << d.err;
  EXPECT_EQ(d.err.find("not routed"), std::string::npos) << d.err;
  const io::ReadResult rd = io::read_layout(dir + "/demo.xml");
  ASSERT_TRUE(rd.layout && rd.layout->routes);
  const Ref ref = reference_for(kDemo, {});
  for (const io::Route& route : rd.layout->routes->routes) {
    SCOPED_TRACE(route.net);
    EXPECT_EQ(route.status, "routed");
    if (route.net == "bump") {
      // one wire from the pad to the diamond, legal, no costlier than the best wire between any
      // corner of one and any corner of the other, and optimal between its own ends
      ASSERT_EQ(route.wires.size(), 1u);
      const std::vector<Point>& w = route.wires[0].points;
      const io::Net& net = *std::find_if(rd.layout->nets.begin(), rd.layout->nets.end(), [](const io::Net& n) { return n.name == "bump"; });
      const geom::Polygon pad = io::shape_polygon(*net.pins[0].shape), bump = io::shape_polygon(*net.pins[1].shape);
      EXPECT_NE(geom::locate(w.front(), pad), geom::Location::Outside) << pt(w.front());
      EXPECT_NE(geom::locate(w.back(), bump), geom::Location::Outside) << pt(w.back());
      const auto got = ref.ref->check_path(w);
      ASSERT_TRUE(got.has_value());
      const std::int64_t cost = got->length + 1000 * got->bends;
      const auto best = ref.ref->best(w.front(), w.back(), false, 1000);
      ASSERT_TRUE(best.has_value());
      EXPECT_EQ(best->length + 1000 * best->bends, cost);
      for (const Point a : pad.outer)
        for (const Point b : bump.outer)
          if (const auto c = ref.ref->best(a, b, false, 1000)) {
            EXPECT_LE(cost, c->length + 1000 * c->bends) << pt(a) << " " << pt(b);
          }
      EXPECT_EQ(route.bends.value_or(-1), got->bends);
    }
    if (route.net != "clk") continue;
    // every sink's best path runs along clk's wires: each wire legal, the tree starts at drv
    ASSERT_FALSE(route.wires.empty());
    EXPECT_EQ(route.wires[0].points.front(), (Point{500, 500}));
    for (const io::Wire& w : route.wires) EXPECT_TRUE(ref.ref->check_path(w.points).has_value());
    const auto sinks = std::vector<Point>{{10000, 10000}, {13000, 12500}};
    for (const Point sink : sinks) {
      bool on = false;
      for (const io::Wire& w : route.wires)
        for (std::size_t i = 0; i + 1 < w.points.size(); ++i) on = on || geom::on_segment(sink, w.points[i], w.points[i + 1]);
      EXPECT_TRUE(on) << "no wire reaches " << pt(sink);
    }
  }
  EXPECT_NE(d.err.find("[ROUTE-0008] blockage \"tri\""), std::string::npos) << d.err;
  // shape pins these metrics refuse, named with the blockage (exit 1, the net written as failed):
  // one under the rectilinear cover of a sloped blockage with no lattice cell outside it, one with
  // an edge at another angle than 0, 45 or 90 degrees too thin for a cell of the lattice; a shape
  // on a blockage's edge is routed, and since 2026-12-06 (before, ROUTE-0005) so are a pin partly
  // under a blockage (from its part outside it) and a pin at such an angle that holds cells (its
  // staircase)
  const std::string bad = dir + "/pins.xml";
  test::write_text(bad, R"(<layout name="pins">
  <boundary x0="0" y0="0" x1="100" y1="100"/>
  <blockage id="wall"><rect x0="40" y0="0" x1="50" y1="60"/></blockage>
  <blockage id="ramp"><polygon points="60,70 90,70 90,90"/></blockage>
  <net name="under"><pin name="a" x="10" y="10"/><pin name="b"><rect x0="45" y0="58" x1="55" y1="62"/></pin></net>
  <net name="cover"><pin name="a" x="10" y="10"/><pin name="b"><rect x0="75" y0="81" x1="76" y1="82"/></pin></net>
  <net name="slope"><pin name="a" x="10" y="10"/><pin name="b"><polygon points="20,20 30,20 30,25"/></pin></net>
  <net name="sliver"><pin name="a" x="10" y="10"/><pin name="b"><polygon points="20,40 30,40 30,41"/></pin></net>
  <net name="touch"><pin name="a" x="10" y="10"/><pin name="b"><rect x0="50" y0="20" x1="60" y1="30"/></pin></net>
</layout>
)");
  // (--independent: the four nets share the pin at 10,10, which no two nets routed together can)
  const auto p = run_taut({"route", bad, "--metric", "link", "--independent", "-o", dir + "/pins.routed.xml"});
  EXPECT_EQ(p.status, 1) << p.err;
  EXPECT_EQ(p.err.find("net \"under\" not routed"), std::string::npos) << p.err;
  EXPECT_NE(p.err.find("[ROUTE-0005] net \"cover\" not routed: pin \"b\" lies partly under the rectilinear cover of sloped "
                       "blockage \"ramp\" (" + bad + ":4)"),
            std::string::npos) << p.err;
  EXPECT_NE(p.err.find("[ROUTE-0005] net \"sliver\" not routed: pin \"b\" has an edge at an angle other than 0, 45 or 90 "
                       "degrees, and no cell of the unit lattice lies inside it"),
            std::string::npos) << p.err;
  EXPECT_EQ(p.err.find("net \"slope\" not routed"), std::string::npos) << p.err;
  EXPECT_EQ(p.err.find("net \"touch\" not routed"), std::string::npos) << p.err;
  const io::ReadResult rp = io::read_layout(dir + "/pins.routed.xml");
  ASSERT_TRUE(rp.layout && rp.layout->routes);
  for (const io::Route& route : rp.layout->routes->routes) {
    EXPECT_EQ(route.status, route.net == "touch" || route.net == "slope" || route.net == "under" ? "routed" : "failed")
        << route.net;
    if (route.net == "under") {
      // the pad (45..55 x 58..62) less the wall (up to x 50, y 60): one bend, along the wall's top
      // to (45, 60), a corner of the part outside the wall
      ASSERT_EQ(route.wires.size(), 1u);
      EXPECT_EQ(route.bends.value_or(-1), 1);
      EXPECT_EQ(route.wires[0].points, (std::vector<Point>{{10, 10}, {10, 60}, {45, 60}}));
    }
    if (route.net == "slope") {
      // one bend to the triangle's staircase, whose columns start at x = 22 (the top edge, y = 20 +
      // (x - 20) / 2, reaches 21 at both sides of a column from there): the wire ends on it, in the pin
      ASSERT_EQ(route.wires.size(), 1u);
      EXPECT_EQ(route.bends.value_or(-1), 1);
      const Point end = route.wires[0].points.back();
      EXPECT_EQ(route.wires[0].points.front(), (Point{10, 10}));
      EXPECT_TRUE(end.x >= 22 && end.x <= 30 && end.y >= 20 && 2 * (end.y - 20) <= end.x - 20) << pt(end);
    }
    if (route.net == "touch") {
      // from (10, 10) over the wall (top at y = 60) and down the wall's right side to the
      // rectangle's corner (50, 30): two bends, then the shortest such wire (length 120)
      ASSERT_EQ(route.wires.size(), 1u);
      EXPECT_EQ(route.bends.value_or(-1), 2);
      EXPECT_EQ(route.wires[0].points, (std::vector<Point>{{10, 10}, {10, 60}, {50, 60}, {50, 30}}));
    }
  }
  test::expect_routes_check_except_clearance(dir + "/demo.xml");
}

}  // namespace bend_path_test
}  // namespace taut
