// `taut path` and `taut route` with --orientations octilinear (or <rules orientations=
// "octilinear">): every wire they return is checked against the brute-force octilinear
// reference (tests/oracle/oct_oracle.h): it starts and ends at the pins, every segment is
// horizontal, vertical or at 45 degrees, its vertices are integers, it stays in free space, and
// its length is exactly the shortest octilinear distance a + b*sqrt2 (JSON "length_exact").
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "geom/normalize.h"
#include "io/layout_geometry.h"
#include "io/layout_reader.h"
#include "oracle/oct_oracle.h"
#include "support/layout_reference.h"
#include "support/run.h"
#include "support/sanitized.h"

namespace taut::test {
namespace oct_route_test {

using geom::Point;
using geom::Root2;
const std::string kDemo = std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml";

using Reference = LayoutReference<oracle::OctilinearReference>;
Reference reference_for(const std::string& file, std::vector<Point> extra = {}) {
  return test::reference_for<oracle::OctilinearReference>(file, extra);
}

// A wire as the contract promises it; returns its exact octilinear length.
std::optional<Root2> expect_oct_wire(const oracle::OctilinearReference& ref, const std::vector<Point>& w, Point a,
                                     Point b) {
  EXPECT_GE(w.size(), 2u);
  if (w.empty()) return std::nullopt;
  EXPECT_EQ(w.front(), a);
  EXPECT_EQ(w.back(), b);
  for (std::size_t i = 1; i < w.size(); ++i)
    EXPECT_TRUE(oracle::is_octilinear(w[i - 1], w[i])) << "segment " << i << " is not at 0/45/90/135 degrees";
  const auto len = ref.check_octilinear_path(w);
  EXPECT_TRUE(len.has_value()) << "the wire leaves free space or is not octilinear";
  return len;
}

Root2 exact_of(const nlohmann::json& j) { return {j[0].get<std::int64_t>(), j[1].get<std::int64_t>()}; }

TEST(OctPath, DemoJsonIsShortestOctilinearAndFree) {
  const Point a{500, 500}, b{18000, 11500};
  const auto r = run_taut({"path", kDemo, "--from", "500,500", "--to", "18000,11500", "--orientations", "octilinear",
                           "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["metric"], "l1");
  EXPECT_EQ(j["orientations"], "octilinear");
  const Reference ref = reference_for(kDemo, {a, b});
  const auto want = ref.ref->distance(a, b);
  ASSERT_TRUE(want.has_value());
  EXPECT_GT(want->b, 0);  // the demo's shortest octilinear wire does use diagonals
  const Root2 exact = exact_of(j["length_exact"]);
  EXPECT_EQ(exact, *want);
  // cost and length: a + b*sqrt2 as the nearest double, written with enough digits to read back
  // exactly (CLI.md asks for at least 9)
  EXPECT_EQ(j["cost"].get<double>(), want->to_double());
  EXPECT_EQ(j["cost"], j["length"]);
  const auto pts = points_of(j["points"]);
  EXPECT_EQ(expect_oct_wire(*ref.ref, pts, a, b), *want);
  long bends = 0;
  for (std::size_t i = 2; i < pts.size(); ++i) {
    const std::int64_t ux = pts[i - 1].x - pts[i - 2].x, uy = pts[i - 1].y - pts[i - 2].y;
    const std::int64_t vx = pts[i].x - pts[i - 1].x, vy = pts[i].y - pts[i - 1].y;
    if (ux * vy - uy * vx != 0 || ux * vx + uy * vy < 0) ++bends;
  }
  EXPECT_EQ(j["bends"].get<long>(), bends);
  // and it is shorter than the rectilinear wire between the same points
  const auto rl = run_taut({"path", kDemo, "--from", "500,500", "--to", "18000,11500", "--json"});
  ASSERT_EQ(rl.status, 0);
  EXPECT_LT(want->to_double(), nlohmann::json::parse(rl.out)["cost"].get<double>());
  // The text form names the exact length.
  const auto t = run_taut({"path", kDemo, "--from", "500,500", "--to", "18000,11500", "--orientations", "octilinear"});
  ASSERT_EQ(t.status, 0);
  EXPECT_NE(t.out.find("(" + std::to_string(want->a) + "+" + std::to_string(want->b) + "*sqrt2) (octilinear)"),
            std::string::npos)
      << t.out;
}

TEST(OctPath, RulesChooseOctilinearAndTheOptionOverrides) {
  const std::string file = layout_file("oct_rules", R"(  <rules orientations="octilinear"/>
  <blockage id="b"><rect x0="10" y0="-5" x1="20" y1="5"/></blockage>
)");
  const auto r = run_taut({"path", file, "--from", "0,0", "--to", "30,0", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["orientations"], "octilinear");
  // over the block's top corner (10,5): (10,5) is 5 diagonal + 5 straight, then 10 along the
  // top, then the same down to (30,0): 20 + 10*sqrt2 (rectilinear: 5 + 30 + 5 = 40)
  EXPECT_EQ(exact_of(j["length_exact"]), (Root2{20, 10}));
  const auto rl = run_taut({"path", file, "--from", "0,0", "--to", "30,0", "--orientations", "rectilinear", "--json"});
  ASSERT_EQ(rl.status, 0) << rl.err;
  const auto jl = nlohmann::json::parse(rl.out);
  EXPECT_FALSE(jl.contains("orientations"));
  EXPECT_EQ(jl["cost"].get<std::int64_t>(), 40);
}

// A c: set whose directions are those of rectilinear or octilinear (modulo 180 degrees, in any
// order, repeated) is that set, from the command line and from <rules>; any other is refused.
TEST(OctPath, CSetsThatNameTheTwoSets) {
  const std::string body = R"(  <blockage id="b"><rect x0="10" y0="-5" x1="20" y1="5"/></blockage>
)";
  const std::string plain = layout_file("cset_plain", body);
  auto json_of = [](const std::vector<std::string>& args) {
    const auto r = run_taut(args);
    EXPECT_EQ(r.status, 0) << r.err;
    return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
  };
  const std::vector<std::string> q = {"--from", "0,0", "--to", "30,0", "--json"};
  auto with = [&](std::vector<std::string> head, const std::vector<std::string>& tail) {
    head.insert(head.end(), tail.begin(), tail.end());
    return head;
  };
  const auto oct = json_of(with({"path", plain, "--orientations", "octilinear"}, q));
  const auto rect = json_of(with({"path", plain, "--orientations", "rectilinear"}, q));
  ASSERT_EQ(exact_of(oct["length_exact"]), (Root2{20, 10}));
  ASSERT_EQ(rect["cost"].get<std::int64_t>(), 40);
  for (const std::string set : {"c:0,45,90,135", "c:135,90,45,0", "c:0,45,90,135,180,225", "c:0.0,45.00,90,135"})
    EXPECT_EQ(json_of(with({"path", plain, "--orientations", set}, q)), oct) << set;
  for (const std::string set : {"c:0,90", "c:90,0", "c:0,90,180,270", "c:270,180"})
    EXPECT_EQ(json_of(with({"path", plain, "--orientations", set}, q)), rect) << set;
  const std::string rules = layout_file("cset_rules", "  <rules orientations=\"c:90,0,45,135\"/>\n" + body);
  EXPECT_EQ(json_of(with({"path", rules}, q)), oct);
  // a route written with such rules says which set it used
  const std::string dir = temp_dir("cset_route");
  const std::string net = R"(  <net name="n"><pin name="a" x="0" y="0"/><pin name="b" x="30" y="0"/></net>
)";
  const auto r = run_taut({"route", layout_file("cset_route", "  <rules orientations=\"c:0,90,180\"/>\n" + body + net),
                           "-o", dir + "/r.xml", "-q"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(read_text(dir + "/r.xml").find("orientations=\"rectilinear\""), std::string::npos);
  const auto bad = run_taut(with({"path", plain, "--orientations", "c:0,60,120"}, q));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("[CLI-0021]"), std::string::npos) << bad.err;
}

TEST(OctPath, UnreachableAndBlockedEndsExit1WithNullCost) {
  const std::string file = layout_file("oct_unreach", R"(  <boundary x0="0" y0="0" x1="100" y1="100"/>
  <blockage id="ring"><polygon points="40,40 60,40 60,60 40,60"><hole points="45,45 55,45 55,55 45,55"/></polygon></blockage>
)");
  auto r = run_taut({"path", file, "--from", "10,10", "--to", "50,50", "--orientations", "octilinear", "--json"});
  EXPECT_EQ(r.status, 1);
  auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["cost"].is_null());
  EXPECT_NE(r.err.find("ROUTE-0002"), std::string::npos) << r.err;
  r = run_taut({"path", file, "--from", "10,10", "--to", "42,42", "--orientations", "octilinear", "--json"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("ROUTE-0001"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ring"), std::string::npos) << r.err;
}

// Every two-pin net of generated layouts, routed octilinear, against the reference.
TEST(OctRoute, GeneratedLayoutsMatchTheReference) {
  const std::string dir = temp_dir("oct_route_gen");
  int routed = 0, unreachable = 0, no_staircase = 0, diagonal = 0;
  for (const char* kind : {"rects", "polygons", "maze", "degenerate"}) {
    for (int seed = 1; seed <= (kSanitized ? 1 : 3); ++seed) {  // each taut run costs seconds under ASan
      SCOPED_TRACE(std::string(kind) + " seed " + std::to_string(seed));
      const std::string in = dir + "/" + kind + std::to_string(seed) + ".xml";
      const std::string out = dir + "/" + kind + std::to_string(seed) + ".routed.xml";
      ASSERT_EQ(run_taut({"gen", kind, "-o", in, "--size", "300", "--nets", "8", "--seed", std::to_string(seed)}).status, 0);
      const auto r = run_taut({"route", in, "--independent", "-o", out, "-q", "--orientations", "octilinear"});
      ASSERT_TRUE(r.status == 0 || r.status == 1) << r.err;
      io::ReadResult rr = io::read_layout(out);
      ASSERT_TRUE(rr.layout && rr.layout->routes);
      EXPECT_EQ(rr.layout->routes->orientations, "octilinear");
      test::expect_routes_check_except_clearance(out);
      const Reference ref = reference_for(in);
      ASSERT_EQ(rr.layout->routes->routes.size(), rr.layout->nets.size());
      bool any_failed = false;
      for (std::size_t i = 0; i < rr.layout->nets.size(); ++i) {
        const io::Net& net = rr.layout->nets[i];
        const io::Route& route = rr.layout->routes->routes[i];
        ASSERT_EQ(net.pins.size(), 2u);
        const Point a = *net.pins[0].point, b = *net.pins[1].point;
        const auto want = ref.ref->distance(a, b);
        if (route.status == "routed") {
          ++routed;
          ASSERT_EQ(route.wires.size(), 1u);
          EXPECT_EQ(expect_oct_wire(*ref.ref, route.wires[0].points, a, b), want) << net.name;
          if (want && want->b > 0) ++diagonal;
          continue;
        }
        any_failed = true;
        const std::string reason = route.reason.value_or("");
        if (reason.find("integer vertices") != std::string::npos) {
          ++no_staircase;
          ASSERT_TRUE(want.has_value()) << net.name << ": " << reason;
          EXPECT_NE(reason.find(std::to_string(want->a) + "+" + std::to_string(want->b) + "*sqrt2"), std::string::npos)
              << reason;
        } else {
          ++unreachable;
          EXPECT_FALSE(want.has_value()) << net.name << ": " << reason;
        }
      }
      EXPECT_EQ(r.status, any_failed ? 1 : 0);
    }
  }
  std::printf("generated nets: %d routed (%d with diagonals), %d unreachable, %d without an integer staircase\n",
              routed, diagonal, unreachable, no_staircase);
  EXPECT_GT(routed, sanitized_share(60, 3));
  EXPECT_GT(diagonal, sanitized_share(30, 3));
}

// The demo with octilinear wires: every net routed, bump's to the diamond pin "ball" (45-degree
// shape edges, taken since 2026-12-03; before, ROUTE-0005 named it), its wire ending on the
// diamond's boundary; the file passes the whole taut check (the clearance included).
TEST(OctRoute, DemoRoutesEveryNetWithTheDiamondPin) {
  const std::string dir = temp_dir("oct_route_demo");
  const auto r = run_taut({"route", kDemo, "-o", dir + "/r.xml", "--orientations", "octilinear", "--svg",
                           dir + "/r.svg"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("ROUTE-0005"), std::string::npos) << r.err;
  io::ReadResult rr = io::read_layout(dir + "/r.xml");
  ASSERT_TRUE(rr.layout && rr.layout->routes);
  EXPECT_EQ(rr.layout->routes->orientations, "octilinear");
  int routed = 0;
  for (const io::Route& route : rr.layout->routes->routes) {
    routed += route.status == "routed";
    if (route.net != "bump") continue;
    ASSERT_EQ(route.wires.size(), 1u);
    ASSERT_FALSE(route.wires[0].points.empty());
    const auto end = route.wires[0].points.back(), start = route.wires[0].points.front();
    // the ball: the diamond |x - 22500| + |y - 2500| <= 500 (designs/demo.xml)
    auto on_ball = [](auto p) { return std::abs(p.x - 22500) + std::abs(p.y - 2500) == 500; };
    EXPECT_TRUE(on_ball(end) || on_ball(start)) << end.x << "," << end.y;
  }
  EXPECT_EQ(routed, 5);
  EXPECT_EQ(run_taut({"check", dir + "/r.xml", "-q"}).status, 0);
  EXPECT_TRUE(file_exists(dir + "/r.svg"));
}

// Shape pins with horizontal and vertical edges: the wire may end anywhere on them.
TEST(OctRoute, RectangularShapePins) {
  const std::string file = layout_file("oct_route_shapes", R"(  <boundary x0="0" y0="0" x1="100" y1="60"/>
  <blockage id="wall"><rect x0="40" y0="0" x1="44" y1="40"/></blockage>
  <net name="pads">
    <pin name="a"><rect x0="10" y0="50" x1="30" y1="55"/></pin>
    <pin name="b"><rect x0="60" y0="5" x1="70" y1="10"/></pin>
  </net>
  <net name="pad_to_point">
    <pin name="c"><rect x0="10" y0="5" x1="20" y1="10"/></pin>
    <pin name="d" x="35" y="30"/>
  </net>
)");
  const std::string dir = temp_dir("oct_route_shapes_out");
  const auto r = run_taut({"route", file, "-o", dir + "/r.xml", "--orientations", "octilinear"});
  EXPECT_EQ(r.status, 0) << r.err;
  io::ReadResult rr = io::read_layout(dir + "/r.xml");
  ASSERT_TRUE(rr.layout && rr.layout->routes);
  const Reference ref = reference_for(file);
  // pads: from a's corner (30,50) round the wall's top corner (44,40)... the reference's least
  // length over every pair of integer points of the two pads
  auto best = [&](const geom::Box& p, const geom::Box& q) {
    std::optional<Root2> b;
    for (int x = p.lo.x; x <= p.hi.x; ++x)
      for (int y = p.lo.y; y <= p.hi.y; ++y) {
        std::vector<Point> ts;
        for (int u = q.lo.x; u <= q.hi.x; ++u)
          for (int v = q.lo.y; v <= q.hi.y; ++v) ts.push_back({u, v});
        for (const auto& d : ref.ref->distances({x, y}, ts))
          if (d && (!b || *d < *b)) b = d;
      }
    return b;
  };
  const auto want_pads = best({{10, 50}, {30, 55}}, {{60, 5}, {70, 10}});
  const auto want_pt = best({{10, 5}, {20, 10}}, {{35, 30}, {35, 30}});
  ASSERT_EQ(rr.layout->routes->routes.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const io::Route& route = rr.layout->routes->routes[static_cast<std::size_t>(i)];
    ASSERT_EQ(route.status, "routed") << route.reason.value_or("");
    ASSERT_EQ(route.wires.size(), 1u);
    const auto& w = route.wires[0].points;
    const auto len = ref.ref->check_octilinear_path(w);
    EXPECT_EQ(len, i == 0 ? want_pads : want_pt) << route.net;
  }
  // the point pin's wire: from (20,10), the pad corner nearest (35,30): 5 + 15 sqrt2
  EXPECT_EQ(want_pt, (Root2{5, 15}));
}

}  // namespace oct_route_test
}  // namespace taut::test
