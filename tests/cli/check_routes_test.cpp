// `taut check` on routed files (issue #7's independent checker, router/check.h): a hand-made
// layout with one problem of each kind (a wire through a blockage, one through a point where two
// blockages touch, a pin left unconnected, a stray wire, a short between nets), each named with
// its code, the line of the wire or pin and what it meets; the JSON counts them; exit status 1.
// The same layout with only its legal net routed passes (exit 0).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run.h"

namespace taut {
namespace check_routes_test {

using test::run_taut;

// The 1-based line of the first line of `text` holding `needle`.
int line_of(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  std::string l;
  for (int k = 1; std::getline(in, l); ++k)
    if (l.find(needle) != std::string::npos) return k;
  return -1;
}

const std::string kLayout =
    "<boundary x0=\"0\" y0=\"0\" x1=\"100\" y1=\"100\"/>\n"
    "<blockage id=\"wall\"><rect x0=\"40\" y0=\"0\" x1=\"60\" y1=\"50\"/></blockage>\n"
    "<blockage id=\"sq1\"><rect x0=\"20\" y0=\"70\" x1=\"30\" y1=\"80\"/></blockage>\n"
    "<blockage id=\"sq2\"><rect x0=\"30\" y0=\"80\" x1=\"40\" y1=\"90\"/></blockage>\n"
    "<net name=\"ok\"><pin name=\"a\" x=\"10\" y=\"10\"/><pin name=\"b\" x=\"10\" y=\"90\"/></net>\n"
    "<net name=\"through\"><pin name=\"a\" x=\"30\" y=\"20\"/><pin name=\"b\" x=\"70\" y=\"20\"/></net>\n"
    "<net name=\"pinch\"><pin name=\"a\" x=\"15\" y=\"80\"/><pin name=\"b\" x=\"45\" y=\"80\"/></net>\n"
    "<net name=\"gap\"><pin name=\"a\" x=\"80\" y=\"10\"/><pin name=\"b\" x=\"80\" y=\"40\"/>\n"
    "<pin name=\"far\" x=\"90\" y=\"90\"/></net>\n"
    "<net name=\"cross\"><pin name=\"a\" x=\"5\" y=\"50\"/><pin name=\"b\" x=\"35\" y=\"50\"/></net>\n";

TEST(CheckRoutes, EveryProblemIsNamedWithItsLine) {
  const std::string file = test::layout_file(
      "check_routes_bad",
      kLayout +
          "<routes tool=\"hand\" metric=\"l1\" orientations=\"rectilinear\">\n"
          "<route net=\"ok\" status=\"routed\" length=\"80\" bends=\"0\"><wire points=\"10,10 10,90\"/></route>\n"
          "<route net=\"through\" status=\"routed\" length=\"40\" bends=\"0\">\n<wire points=\"30,20 70,20\"/></route>\n"
          "<route net=\"pinch\" status=\"routed\" length=\"30\" bends=\"0\">\n<wire points=\"15,80 45,80\"/></route>\n"
          "<route net=\"gap\" status=\"routed\" length=\"40\" bends=\"0\">\n<wire points=\"80,10 80,40\"/>\n"
          "<wire points=\"95,60 95,70\"/></route>\n"
          "<route net=\"cross\" status=\"routed\" length=\"30\" bends=\"0\">\n<wire points=\"5,50 35,50\"/></route>\n"
          "</routes>\n");
  const std::string text = test::read_text(file);
  const test::RunResult r = run_taut({"check", file, "--json"});
  ASSERT_EQ(r.status, 1) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& c = j["routes_check"];
  EXPECT_EQ(c["lengths_and_bends"], "ok");
  EXPECT_EQ(c["free_space"], "failed");
  EXPECT_EQ(c["connectivity"], "failed");
  EXPECT_EQ(c["shorts"], "failed");
  EXPECT_EQ(c["problems"]["not_free"], 2);
  EXPECT_EQ(c["problems"]["disconnected_pins"], 1);
  EXPECT_EQ(c["problems"]["stray_wires"], 1);
  EXPECT_EQ(c["problems"]["shorts"], 1);
  EXPECT_EQ(c["wires"], 6);
  EXPECT_EQ(j["errors"], 5);
  auto expect = [&](const std::string& code, const std::string& needle, const std::vector<std::string>& words) {
    const std::string at = file + ":" + std::to_string(line_of(text, needle)) + ": error: [" + code + "]";
    const std::size_t k = r.err.find(at);
    ASSERT_NE(k, std::string::npos) << "no " << at << " in\n" << r.err;
    const std::string msg = r.err.substr(k, r.err.find('\n', k) - k);
    for (const std::string& w : words) EXPECT_NE(msg.find(w), std::string::npos) << msg << " lacks " << w;
  };
  expect("CHECK-0003", "30,20 70,20", {"net \"through\"", "blockage \"wall\""});
  expect("CHECK-0003", "15,80 45,80", {"net \"pinch\"", "30,80", "blockages touch"});
  expect("CHECK-0004", "name=\"far\"", {"net \"gap\"", "pin \"far\""});
  expect("CHECK-0005", "95,60 95,70", {"net \"gap\"", "95,60"});
  // a short is reported once, at the wire of the net listed first, naming the other's line
  expect("CHECK-0006", "10,10 10,90", {"net \"ok\"", "net \"cross\"", "line " + std::to_string(line_of(text, "5,50 35,50")), "a short"});
  // The text form says the same and the exit status is the same.
  const test::RunResult t = run_taut({"check", file});
  EXPECT_EQ(t.status, 1);
  EXPECT_NE(t.out.find("free space failed; connectivity failed; shorts between nets found"), std::string::npos) << t.out;
}

TEST(CheckRoutes, ALegalRoutePasses) {
  const std::string file = test::layout_file(
      "check_routes_good",
      kLayout +
          "<routes tool=\"hand\" metric=\"l1\" orientations=\"rectilinear\">\n"
          "<route net=\"ok\" status=\"routed\" length=\"80\" bends=\"0\"><wire points=\"10,10 10,90\"/></route>\n"
          // along the wall's side and over its top, a pin reached through the middle of a wire
          "<route net=\"through\" status=\"routed\" length=\"100\" bends=\"4\"><wire points=\"30,20 40,20 40,50 "
          "60,50 60,20 70,20\"/></route>\n"
          "<route net=\"gap\" status=\"routed\" length=\"90\" bends=\"1\"><wire points=\"80,10 80,90 90,90\"/></route>\n"
          "<route net=\"pinch\" status=\"failed\" reason=\"hand\"/>\n"
          "<route net=\"cross\" status=\"failed\" reason=\"hand\"/>\n"
          "</routes>\n");
  const test::RunResult r = run_taut({"check", file, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json c = nlohmann::json::parse(r.out)["routes_check"];
  EXPECT_EQ(c["free_space"], "ok");
  EXPECT_EQ(c["connectivity"], "ok");
  EXPECT_EQ(c["shorts"], "ok");
  EXPECT_EQ(c["clearance"], "not required");  // no <rules>
}

// A failed route keeps no wires (FORMAT.md): one that does is CHECK-0009, at the route's line,
// naming the net and its first wire's line, exit status 1, counted in the JSON; here the wire runs
// through the wall, which nothing else checks for a failed route (found by fuzzing hand-edited
// routes, 2026-12-06: taut check passed such a file).
TEST(CheckRoutes, AFailedRouteWithWiresIsRefused) {
  const std::string file = test::layout_file(
      "check_routes_failed_wires",
      kLayout +
          "<routes tool=\"hand\" metric=\"l1\" orientations=\"rectilinear\">\n"
          "<route net=\"ok\" status=\"routed\" length=\"80\" bends=\"0\"><wire points=\"10,10 10,90\"/></route>\n"
          "<route net=\"through\" status=\"failed\" reason=\"hand\">\n<wire points=\"30,20 70,20\"/></route>\n"
          "</routes>\n");
  const std::string text = test::read_text(file);
  const test::RunResult r = run_taut({"check", file, "--json"});
  ASSERT_EQ(r.status, 1) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["routes_check"]["failed_with_wires"], 1);
  EXPECT_EQ(j["routes_check"]["free_space"], "ok");  // (the routed nets' wires)
  EXPECT_EQ(j["errors"], 1);
  const std::string at = file + ":" + std::to_string(line_of(text, "net=\"through\"")) + ": error: [CHECK-0009]";
  const std::size_t k = r.err.find(at);
  ASSERT_NE(k, std::string::npos) << "no " << at << " in\n" << r.err;
  const std::string msg = r.err.substr(k, r.err.find('\n', k) - k);
  EXPECT_NE(msg.find("route \"through\""), std::string::npos) << msg;
  EXPECT_NE(msg.find("line " + std::to_string(line_of(text, "30,20 70,20"))), std::string::npos) << msg;
  const test::RunResult t = run_taut({"check", file});
  EXPECT_EQ(t.status, 1);
  EXPECT_NE(t.out.find("failed routes with wires: 1"), std::string::npos) << t.out;
}

// With <rules wire-width="2" spacing="1">: w/2 + s = 2 from blockages, w + s = 3 between nets.
// The legal route of "through" runs along the wall's side (CHECK-0007, naming the wall); "pinch"
// runs 2 from "ok"'s wire and its pin b (CHECK-0008, naming both); its first steps off its pin
// (15,80), 5 from sq1, and "gap"'s are fine.
TEST(CheckRoutes, ClearanceOfTheRules) {
  const std::string file = test::layout_file(
      "check_routes_rules",
      "<rules wire-width=\"2\" spacing=\"1\"/>\n" + kLayout +
          "<routes tool=\"hand\" metric=\"l1\" orientations=\"rectilinear\">\n"
          "<route net=\"ok\" status=\"routed\" length=\"80\" bends=\"0\"><wire points=\"10,10 10,90\"/></route>\n"
          "<route net=\"through\" status=\"routed\" length=\"100\" bends=\"4\">\n<wire points=\"30,20 40,20 40,50 "
          "60,50 60,20 70,20\"/></route>\n"
          "<route net=\"gap\" status=\"routed\" length=\"90\" bends=\"1\"><wire points=\"80,10 80,90 90,90\"/></route>\n"
          "<route net=\"pinch\" status=\"routed\" length=\"66\" bends=\"3\">\n<wire points=\"15,80 12,80 12,95 45,95 45,80\"/></route>\n"
          "<route net=\"cross\" status=\"failed\" reason=\"hand\"/>\n"
          "</routes>\n");
  const test::RunResult r = run_taut({"check", file, "--json"});
  EXPECT_EQ(r.status, 1) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& c = j["routes_check"];
  EXPECT_EQ(c["clearance"], "failed") << r.err;
  EXPECT_EQ(c["free_space"], "ok") << r.err;
  EXPECT_EQ(c["connectivity"], "ok") << r.err;
  EXPECT_EQ(c["problems"]["blockage_clearance"], 1) << r.err;
  EXPECT_EQ(c["problems"]["net_clearance"], 2) << r.err;
  EXPECT_EQ(j["errors"], 3) << r.err;
  EXPECT_NE(r.err.find("[CHECK-0007] net \"through\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("blockage \"wall\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("comes within 2.0 of a wire of net \"pinch\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[CHECK-0008] net \"pinch\": the segment 12,80 12,95 comes within 2.0 of pin \"b\" of net \"ok\""),
            std::string::npos)
      << r.err;
}

}  // namespace check_routes_test
}  // namespace taut
