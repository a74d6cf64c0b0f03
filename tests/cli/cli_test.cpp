// The taut command as a flow script sees it: exit codes, stdout/stderr, files written or not.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run.h"

namespace taut::test {
namespace cli_test {

const std::string kDemo = std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml";

TEST(Cli, VersionAndHelp) {
  auto r = run_taut({"--version"});
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("taut 0."), std::string::npos) << r.out;
  r = run_taut({"--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* sub : {"check", "render", "stats", "gen"})
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub;
  for (const char* sub : {"check", "render", "stats", "gen"}) {
    r = run_taut({sub, "--help"});
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_NE(r.out.find("--"), std::string::npos) << sub;
  }
}

TEST(Cli, UsageErrorsExit2) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{}, {"nosuchcommand"}, {"check"}, {"render", kDemo},
        {"check", kDemo, "--bogus"}, {"gen", "nosuchkind", "-o", "/tmp/x.xml"},
        {"gen", "rects", "-o", "/tmp/x.xml", "--size", "12abc"}}) {
    const auto r = run_taut(args);
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    EXPECT_EQ(r.status, 2) << joined << "\n" << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos) << joined;
  }
}

TEST(Cli, MissingFileIsInvalidInput) {
  const auto r = run_taut({"check", "/nonexistent/layout.xml"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent/layout.xml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[IO-"), std::string::npos) << r.err;
}

TEST(Cli, CheckDemo) {
  auto r = run_taut({"check", kDemo});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("ok"), std::string::npos);
  r = run_taut({"check", kDemo, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["valid"].get<bool>());
  EXPECT_EQ(j["errors"].get<int>(), 0);
  EXPECT_GT(j["layout"]["blockages"].get<int>(), 0);
  EXPECT_GT(j["layout"]["nets"].get<int>(), 0);
}

TEST(Cli, RenderWritesSvgAndKeepsOldFileOnBadInput) {
  const std::string dir = temp_dir("render");
  const std::string svg = dir + "/demo.svg";
  auto r = run_taut({"render", kDemo, "-o", svg});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string pic = read_text(svg);
  EXPECT_NE(pic.find("<svg"), std::string::npos);
  EXPECT_NE(pic.find("</svg>"), std::string::npos);

  // A bad input writes nothing and leaves the previous output intact.
  const std::string bad = dir + "/bad.xml";
  write_text(bad, "<layout name=\"x\" version=\"1\"><blockage id=\"a\"><rect x0=\"5\" y0=\"0\" "
                  "x1=\"1\" y1=\"1\"/></blockage></layout>");
  r = run_taut({"render", bad, "-o", svg});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(read_text(svg), pic);
  const std::string fresh = dir + "/fresh.svg";
  r = run_taut({"render", bad, "-o", fresh});
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(file_exists(fresh));
}

TEST(Cli, GenIsReproducibleAndValid) {
  const std::string dir = temp_dir("gen");
  for (const char* kind : {"rects", "polygons", "maze", "degenerate"}) {
    SCOPED_TRACE(kind);
    const std::string a = dir + "/" + kind + "-a.xml", b = dir + "/" + kind + "-b.xml",
                      c = dir + "/" + kind + "-c.xml";
    ASSERT_EQ(run_taut({"gen", kind, "-o", a, "--size", "2000", "--nets", "5", "--seed", "7"}).status, 0);
    ASSERT_EQ(run_taut({"gen", kind, "-o", b, "--size", "2000", "--nets", "5", "--seed", "7"}).status, 0);
    ASSERT_EQ(run_taut({"gen", kind, "-o", c, "--size", "2000", "--nets", "5", "--seed", "8"}).status, 0);
    EXPECT_EQ(read_text(a), read_text(b));
    EXPECT_NE(read_text(a), read_text(c));
    const auto r = run_taut({"check", a, "--json"});
    EXPECT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["layout"]["nets"].get<int>(), 5);
    const int v = j["layout"]["blockage_vertices"].get<int>();
    EXPECT_GE(v, 1800);
    EXPECT_LE(v, 2200);
  }
}

TEST(Cli, StatsJson) {
  const std::string dir = temp_dir("stats");
  const std::string out = dir + "/s.json";
  const auto r = run_taut({"stats", kDemo, "--json", "-o", out});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(nlohmann::json::parse(read_text(out)), j);
  EXPECT_GT(j["nets"].get<int>(), 0);
}

}  // namespace cli_test
}  // namespace taut::test

namespace taut::test {
namespace cli_test {

// A routed layout whose written length/bends agree with its wires passes; one that lies fails
// with exit status 1 and a CHECK-0001 naming the route.
TEST(Cli, CheckRoutesLengthsAndBends) {
  const std::string dir = temp_dir("routes");
  auto layout = [](const std::string& length, const std::string& bends) {
    return "<layout name=\"r\" version=\"1\">\n"
           "  <net name=\"a\"><pin name=\"p\" x=\"0\" y=\"0\"/><pin name=\"q\" x=\"30\" y=\"40\"/></net>\n"
           "  <net name=\"b\"><pin name=\"p\" x=\"0\" y=\"100\"/><pin name=\"q\" x=\"30\" y=\"140\"/></net>\n"
           "  <routes tool=\"test\">\n"
           "    <route net=\"a\" status=\"routed\" length=\"70\" bends=\"1\"><wire points=\"0,0 30,0 30,40\"/></route>\n"
           "    <route net=\"b\" status=\"routed\" length=\"" + length + "\" bends=\"" + bends +
           "\"><wire points=\"0,100 30,140\"/></route>\n"
           "  </routes>\n</layout>\n";
  };
  write_text(dir + "/good.xml", layout("50.000", "0"));
  auto r = run_taut({"check", dir + "/good.xml"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("lengths and bends ok"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("free space ok; connectivity ok; shorts between nets none; clearance not required"), std::string::npos)
      << r.out;

  write_text(dir + "/bad.xml", layout("49.000", "2"));
  r = run_taut({"check", dir + "/bad.xml"});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find(dir + "/bad.xml:6: error: [CHECK-0001] route \"b\": length"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("route \"b\": bends is written as 2 but the wires give 0"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("route \"a\""), std::string::npos) << r.err;
}

// With <routes orientations="rectilinear"> (or "octilinear") every wire segment must run in
// those directions: the first offending segment of a route is named (CHECK-0002, exit 1).
TEST(Cli, CheckRoutesOrientations) {
  const std::string dir = temp_dir("routes_orientations");
  auto layout = [](const std::string& orientations) {
    return "<layout name=\"r\" version=\"1\">\n"
           "  <net name=\"a\"><pin name=\"p\" x=\"0\" y=\"0\"/><pin name=\"q\" x=\"30\" y=\"40\"/></net>\n"
           "  <routes tool=\"test\" orientations=\"" + orientations + "\">\n"
           "    <route net=\"a\" status=\"routed\" length=\"52.426\" bends=\"1\"><wire points=\"0,0 30,30 30,40\"/></route>\n"
           "  </routes>\n</layout>\n";
  };
  write_text(dir + "/oct.xml", layout("octilinear"));
  auto r = run_taut({"check", dir + "/oct.xml"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("octilinear orientations ok"), std::string::npos) << r.out;
  write_text(dir + "/rect.xml", layout("rectilinear"));
  r = run_taut({"check", dir + "/rect.xml"});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find(dir + "/rect.xml:4: error: [CHECK-0002] route \"a\": the wire segment 0,0 30,30 is not "
                                          "horizontal or vertical"),
            std::string::npos)
      << r.err;
  r = run_taut({"check", dir + "/rect.xml", "--json"});
  EXPECT_EQ(r.status, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["routes_check"]["orientations"], "failed");
  write_text(dir + "/any.xml", layout("any"));
  r = run_taut({"check", dir + "/any.xml", "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["routes_check"]["orientations"], "not checked");
}

// With a set at multiples of 30 degrees (since 2026-12-07) integer vertices cannot follow 60
// degrees exactly: a segment passes when moving each end by at most half a unit in x and y puts
// it on a direction of the set (geom::Root3Directions::fits), and the first that does not is
// named (CHECK-0002). 0,0 -> 10,17 -> 30,17 is 60 then 0 degrees after rounding (10 sqrt3 =
// 17.32); 0,0 -> 10,22 is not (11 sqrt3 = 19.05 < 21); c:0,90,45 is a lattice set, checked
// exactly. A set at other angles (since the twenty-first session, the same day) is checked
// against its steps (geom::Root3Directions::parse_any): 0,0 -> 57,10 -> 87,10 is 10 then 0
// degrees in c:0,10,100 (57 tan 10 = 10.05); 10,22 is not; the steps are named. A set with a
// direction no step realizes (c:0,0.000001) is not checked.
TEST(Cli, CheckRoutesInASetAtMultiplesOf30Degrees) {
  const std::string dir = temp_dir("routes_orientations30");
  // (the second pin at 30,17, or at `q`)
  auto layout = [](const std::string& orientations, const std::string& points, const std::string& length,
                   const std::string& q = "x=\"30\" y=\"17\"") {
    return "<layout name=\"r\" version=\"1\">\n"
           "  <net name=\"a\"><pin name=\"p\" x=\"0\" y=\"0\"/><pin name=\"q\" " + q + "/></net>\n"
           "  <routes tool=\"test\" orientations=\"" + orientations + "\">\n"
           "    <route net=\"a\" status=\"routed\" length=\"" + length + "\" bends=\"1\"><wire points=\"" + points +
           "\"/></route>\n  </routes>\n</layout>\n";
  };
  write_text(dir + "/hex.xml", layout("c:0,60,120", "0,0 10,17 30,17", "39.723"));
  auto r = run_taut({"check", dir + "/hex.xml"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("c:0,60,120 orientations ok"), std::string::npos) << r.out;
  write_text(dir + "/off.xml", layout("c:120,0,60", "0,0 10,22 30,17", "44.782"));
  r = run_taut({"check", dir + "/off.xml", "--json"});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find(dir + "/off.xml:4: error: [CHECK-0002] route \"a\": the wire segment 0,0 10,22 is not at 0, "
                             "60 or 120 degrees within the rounding of its ends"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("10,22 30,17"), std::string::npos) << r.err;  // the first offending segment only
  EXPECT_EQ(nlohmann::json::parse(r.out)["routes_check"]["orientations"], "failed");
  write_text(dir + "/lattice.xml", layout("c:0,90,45", "0,0 10,17 30,17", "39.723"));
  r = run_taut({"check", dir + "/lattice.xml"});
  EXPECT_EQ(r.status, 1) << r.err;  // 10,17 is not at 45 degrees, exactly
  EXPECT_NE(r.err.find("the wire segment 0,0 10,17 is not at 0, 45 or 90 degrees (<routes"), std::string::npos) << r.err;
  auto layout10 = [&](const std::string& orientations, const std::string& points, const std::string& length) {
    return layout(orientations, points, length, "x=\"87\" y=\"10\"");
  };
  write_text(dir + "/ten.xml", layout10("c:0,10,100", "0,0 57,10 87,10", "87.871"));
  r = run_taut({"check", dir + "/ten.xml", "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["routes_check"]["orientations"], "ok");
  write_text(dir + "/ten_off.xml", layout10("c:0,10,100", "0,0 10,22 87,10", "102.096"));
  r = run_taut({"check", dir + "/ten_off.xml"});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("[CHECK-0002] route \"a\": the wire segment 0,0 10,22 is not at 0, 10 or 100 degrees within the "
                       "rounding of its ends (half a unit in x and in y each), 10 degrees as the step ("),
            std::string::npos)
      << r.err;
  write_text(dir + "/tiny.xml", layout10("c:0,0.000001", "0,0 57,10 87,10", "87.871"));
  r = run_taut({"check", dir + "/tiny.xml", "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["routes_check"]["orientations"], "not checked");
}

}  // namespace cli_test
}  // namespace taut::test
