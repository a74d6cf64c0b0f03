// Shape pins with an edge at another angle than 0, 45 or 90 degrees, and shape pins partly under a
// blockage (since 2026-12-06; before, every router refused them with ROUTE-0005): `taut route`
// and `taut path --to-pin` reach such a pin as its staircase, the union of the unit lattice's
// cells that lie in it and meet no blockage's interior (router::pad_staircase), since a wire's
// vertices are integers. Checked against references sharing only geom with the router:
//   - alone (--independent, rectilinear and octilinear): on random layouts (blockages touching and
//     overlapping, random pins: triangles, turned rectangles, star-shaped polygons, some with
//     holes; in half the layouts a triangle lies partly over some pins), the cells in each pin
//     outside the blockages are found by brute force (tests/support/pin_cells.h), and the
//     wire must end on a corner of one of the staircase's cells and be exactly as long as the
//     shortest wire from the net's point pin to any such corner (oracle::L1Reference,
//     oracle::OctilinearReference over every corner); a pin with no cell is ROUTE-0005;
//   - together with rules (rectilinear, octilinear, --metric combined): the written layout passes
//     `taut check` (its wires end in the pins, keep the clearance);
//   - by hand: a pin touching a blockage with a clearance, and `path --to-pin`; a pad another
//     net's wire comes within the clearance of, reached from its clear part.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "geom/normalize.h"
#include "geom/validate.h"
#include "io/layout_reader.h"
#include "oracle/l1_oracle.h"
#include "oracle/oct_oracle.h"
#include "support/layout_reference.h"
#include "support/pin_cells.h"
#include "support/run.h"
#include "support/sanitized.h"

namespace taut::test {
namespace sloped_pin_test {

using geom::Point;
using geom::Polygon;

// A random pin with an edge at another angle than 0, 45 or 90 degrees in [ox, ox + 14] x [oy, oy
// + 14] (random_sloped_pin: a triangle, a turned rectangle or a star-shaped polygon, one in four
// with a triangular hole).
Polygon random_sloped_pin_at(std::mt19937& rng, int ox, int oy) {
  Polygon pin = random_sloped_pin(rng, 4);
  for (Point& p : pin.outer) p = {p.x + ox, p.y + oy};
  for (geom::Ring& h : pin.holes)
    for (Point& p : h) p = {p.x + ox, p.y + oy};
  return pin;
}

std::string points_text(const geom::Ring& r) {
  std::string s;
  for (const Point p : r) s += (s.empty() ? "" : " ") + std::to_string(p.x) + "," + std::to_string(p.y);
  return s;
}

struct Net {
  std::string name;
  Polygon pin;       // the sloped pin, in a slot of 16 x 16 on the left
  Point point;       // the point pin, on the right
  bool pin_first = true;
  std::vector<Polygon> under;  // blockages that may meet the pin's interior
};

// A layout of 120 x 100: sloped pins in twelve slots at x 2..34, blockages (rectangles that may
// touch and overlap, and a sloped triangle) in x 40..72, point pins on a grid at x 80..116.
// With `overlap`, a triangle among the pins lies partly over some of them (never wholly over
// one: that is LAYOUT-0005).
std::string random_layout(std::mt19937& rng, std::vector<Net>& nets, const std::string& rules, bool overlap = false) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::string body = "<layout version=\"1\">\n  <boundary x0=\"0\" y0=\"0\" x1=\"120\" y1=\"100\"/>\n" + rules;
  const int rects = uni(2, 6);
  for (int k = 0; k < rects; ++k) {
    const int x0 = uni(40, 66), y0 = uni(0, 90), w = uni(2, 6) * (uni(0, 1) ? 1 : 2), h = uni(4, 30);
    body += "  <blockage id=\"b" + std::to_string(k) + "\"><rect x0=\"" + std::to_string(x0) + "\" y0=\"" + std::to_string(y0) +
            "\" x1=\"" + std::to_string(std::min(x0 + w, 72)) + "\" y1=\"" + std::to_string(std::min(y0 + h, 100)) + "\"/></blockage>\n";
  }
  const int tx = uni(40, 60), ty = uni(10, 80);
  body += "  <blockage id=\"tri\"><polygon points=\"" + std::to_string(tx) + "," + std::to_string(ty) + " " + std::to_string(tx + 12) +
          "," + std::to_string(ty + 3) + " " + std::to_string(tx + 2) + "," + std::to_string(ty + 9) + "\"/></blockage>\n";
  std::vector<int> slots(12), spots(40);
  std::iota(slots.begin(), slots.end(), 0);
  std::iota(spots.begin(), spots.end(), 0);
  std::shuffle(slots.begin(), slots.end(), rng);
  std::shuffle(spots.begin(), spots.end(), rng);
  nets.clear();
  for (int i = 0; i < 6; ++i) {
    Net n;
    n.name = "n" + std::to_string(i);
    n.pin = random_sloped_pin_at(rng, 2 + 16 * (slots[i] % 2), 2 + 16 * (slots[i] / 2));
    n.point = {80 + 9 * (spots[i] % 5), 4 + 9 * (spots[i] / 5)};
    n.pin_first = uni(0, 1) == 1;
    std::string shape = "<polygon points=\"" + points_text(n.pin.outer) + "\">";
    for (const geom::Ring& h : n.pin.holes) shape += "<hole points=\"" + points_text(h) + "\"/>";
    shape += "</polygon>";
    const std::string a = "    <pin name=\"s\">" + shape + "</pin>\n";
    const std::string b = "    <pin name=\"p\" x=\"" + std::to_string(n.point.x) + "\" y=\"" + std::to_string(n.point.y) + "\"/>\n";
    body += "  <net name=\"" + n.name + "\">\n" + (n.pin_first ? a + b : b + a) + "  </net>\n";
    nets.push_back(std::move(n));
  }
  while (overlap) {
    const Polygon t{{{uni(0, 36), uni(0, 100)}, {uni(0, 36), uni(0, 100)}, {uni(0, 36), uni(0, 100)}}, {}};
    if (!geom::validate_polygon(t).empty()) continue;
    bool ok = true;  // every pin keeps a lattice point outside it
    for (const Net& n : nets) {
      bool out = false;
      for (int x = 0; x <= 36 && !out; ++x)
        for (int y = 0; y <= 100 && !out; ++y)
          out = geom::locate(Point{x, y}, n.pin) != geom::Location::Outside && geom::locate(Point{x, y}, t) == geom::Location::Outside;
      ok = ok && out;
    }
    if (!ok) continue;
    for (Net& n : nets) n.under.push_back(t);  // (a cut that misses the pin takes no cell of it)
    body += "  <blockage id=\"over\"><polygon points=\"" + points_text(t.outer) + "\"/></blockage>\n";
    break;
  }
  return body + "</layout>\n";
}

// The lattice points the staircase of `pin` holds: the corners of its cells (brute force).
std::vector<Point> staircase_points(const Polygon& pin, const std::vector<Polygon>& under = {}) {
  const auto [cells, whole] = expected_staircase_cells(cells_in_pin(pin, 1, 0, 0, 120, 100, under), 1);
  std::set<std::pair<int, int>> pts;
  for (const auto& [x, y] : cells)
    for (const int dx : {0, 1})
      for (const int dy : {0, 1}) pts.insert({x + dx, y + dy});
  std::vector<Point> out;
  for (const auto& [x, y] : pts) out.push_back({x, y});
  return out;
}

std::map<std::string, io::Route> routes_of(const std::string& file) {
  std::map<std::string, io::Route> out;
  io::ReadResult rr = io::read_layout(file);
  EXPECT_TRUE(rr.layout && rr.layout->routes) << file;
  if (rr.layout && rr.layout->routes)
    for (io::Route& r : rr.layout->routes->routes) out[r.net] = std::move(r);
  return out;
}

TEST(SlopedPins, AloneAsShortAsTheReferenceToTheStaircase) {
  const std::string dir = temp_dir("sloped_alone");
  std::mt19937 rng(9061);
  int routed = 0, no_cell = 0, dearer = 0, oct_routed = 0, oct_shorter = 0, holed = 0, under = 0;
  std::int64_t extra = 0;
  const int layouts = sanitized_share(30, 3);
  for (int L = 0; L < layouts; ++L) {
    std::vector<Net> nets;
    const std::string file = dir + "/l" + std::to_string(L) + ".xml";
    write_text(file, random_layout(rng, nets, "", L % 2 == 1));
    SCOPED_TRACE(file);
    const auto ref = reference_for<oracle::L1Reference>(file);
    const auto oref = reference_for<oracle::OctilinearReference>(file);
    ASSERT_TRUE(ref.ref && oref.ref);
    for (const bool oct : {false, true}) {
      const std::string out = dir + "/l" + std::to_string(L) + (oct ? ".oct" : "") + ".routed.xml";
      std::vector<std::string> cmd{"route", file, "--independent", "-q", "-o", out};
      if (oct) cmd.insert(cmd.end(), {"--orientations", "octilinear"});
      const auto r = run_taut(cmd);
      ASSERT_TRUE(r.status == 0 || r.status == 1) << r.err;
      std::map<std::string, io::Route> routes = routes_of(out);
      for (const Net& n : nets) {
        SCOPED_TRACE(n.name + " " + points_text(n.pin.outer) + (oct ? " octilinear" : ""));
        ASSERT_TRUE(routes.count(n.name));
        const io::Route& route = routes[n.name];
        const std::vector<Point> ends = staircase_points(n.pin, n.under);
        under += !oct && !n.under.empty() && staircase_points(n.pin) != ends;
        holed += !oct && !n.pin.holes.empty();
        if (ends.empty()) {
          EXPECT_EQ(route.status, "failed");
          EXPECT_NE(route.reason.value_or("").find("no cell of the unit lattice lies in"), std::string::npos)
              << route.reason.value_or("");
          no_cell += !oct;
          continue;
        }
        // the route against the reference's shortest wire from the point pin to any of `ends`
        // (L1 or octilinear lengths; `measure` checks the wire's segments and gives its length):
        // the wire from its end on the staircase to the point pin, nullopt when not routed
        auto against = [&](const auto& reference, auto measure) -> std::optional<std::vector<Point>> {
          const auto d = reference.distances(n.point, ends);
          std::optional<std::decay_t<decltype(*d[0])>> best;
          for (const auto& v : d)
            if (v && (!best || *v < *best)) best = v;
          if (!best) {
            EXPECT_EQ(route.status, "failed");
            return std::nullopt;
          }
          if (route.status != "routed" || route.wires.size() != 1) {
            ADD_FAILURE() << route.status << " " << route.reason.value_or("") << ", " << route.wires.size() << " wires";
            return std::nullopt;
          }
          std::vector<Point> w = route.wires[0].points;
          if (!n.pin_first) std::reverse(w.begin(), w.end());
          EXPECT_EQ(w.back(), n.point);
          EXPECT_NE(std::find(ends.begin(), ends.end(), w.front()), ends.end()) << w.front().x << "," << w.front().y;
          const auto len = measure(w);
          EXPECT_TRUE(len && *len == *best);
          return w;
        };
        if (!oct) {
          const auto w = against(*ref.ref, [&](const std::vector<Point>& p) { return ref.ref->check_path(p); });
          if (!w) continue;
          ++routed;
          // the price of the staircase: the nearest lattice point of the pin itself
          std::vector<Point> pin_points;
          for (int x = 0; x <= 120; ++x)
            for (int y = 0; y <= 100; ++y)
              if (geom::locate(Point{x, y}, n.pin) != geom::Location::Outside) pin_points.push_back({x, y});
          const std::int64_t len = *ref.ref->check_path(*w);
          std::int64_t nearest = len;
          for (const auto& v : ref.ref->distances(n.point, pin_points))
            if (v) nearest = std::min(nearest, *v);
          dearer += nearest < len;
          extra += len - nearest;
        } else {
          const auto w = against(*oref.ref, [&](const std::vector<Point>& p) { return oref.ref->check_octilinear_path(p); });
          if (!w) continue;
          ++oct_routed;
          bool diagonal = false;
          for (std::size_t i = 1; i < w->size(); ++i) diagonal = diagonal || ((*w)[i].x != (*w)[i - 1].x && (*w)[i].y != (*w)[i - 1].y);
          oct_shorter += diagonal;
        }
      }
    }
  }
  std::printf("%d layouts: %d nets routed alone to their pins' staircases (%d octilinear, %d of them with a diagonal), "
              "%d pins without a cell (ROUTE-0005), %d with a hole, %d partly under a blockage; %d wires longer than one to "
              "the pin's nearest lattice point, by %lld in all\n",
              layouts, routed, oct_routed, oct_shorter, no_cell, holed, under, dearer, static_cast<long long>(extra));
  EXPECT_GT(routed, layouts * 6 / 2);
  EXPECT_EQ(oct_routed, routed);
  EXPECT_GT(under, 0);
  if (!kSanitized) {
    EXPECT_GT(no_cell, 0);
  }
}

TEST(SlopedPins, TogetherWithRulesPassTheChecker) {
  const std::string dir = temp_dir("sloped_together");
  std::mt19937 rng(9062);
  std::map<std::string, int> routed;
  int nets_total = 0;
  const int layouts = sanitized_share(12, 2);
  for (int L = 0; L < layouts; ++L) {
    std::vector<Net> nets;
    const std::string file = dir + "/l" + std::to_string(L) + ".xml";
    write_text(file, random_layout(rng, nets, "  <rules wire-width=\"2\" spacing=\"1\"/>\n", L % 2 == 1));
    SCOPED_TRACE(file);
    nets_total += static_cast<int>(nets.size());
    for (const auto& [what, extra] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"rectilinear", {}},
             {"octilinear", {"--orientations", "octilinear"}},
             {"combined", {"--metric", "combined", "--bend-cost", "8"}},
             {"tighten", {"--tighten"}}}) {
      const std::string out = dir + "/l" + std::to_string(L) + "." + what + ".xml";
      std::vector<std::string> cmd{"route", file, "-q", "-o", out};
      cmd.insert(cmd.end(), extra.begin(), extra.end());
      const auto r = run_taut(cmd);
      ASSERT_TRUE(r.status == 0 || r.status == 1) << what << ": " << r.err;
      const auto c = run_taut({"check", out, "-q"});
      EXPECT_EQ(c.status, 0) << what << ": " << c.err;
      for (const auto& [name, route] : routes_of(out)) {
        routed[what] += route.status == "routed";
        if (route.status != "routed") {
          EXPECT_FALSE(route.reason.value_or("").empty()) << name;
        }
      }
    }
  }
  std::printf("%d layouts, %d nets with a sloped pin together (w = 2, s = 1): routed %d rectilinear, %d octilinear, %d "
              "combined, %d tightened; every file passes taut check\n",
              layouts, nets_total, routed["rectilinear"], routed["octilinear"], routed["combined"], routed["tighten"]);
  for (const auto& [what, k] : routed) EXPECT_GT(k, nets_total / 2) << what;
}

// By hand: a turned square pad sitting on a blockage's edge, with a clearance of 3 (w = 2, s = 2):
// its staircase is cut out of the grown blockage as a pad is, so the wire reaches it and keeps the
// clearance up to its end; `path --to-pin` reaches the same staircase; a sliver with no cell, and
// a square under a ramp's slope with no cell outside it, are ROUTE-0005 from both.
TEST(SlopedPins, APadOnABlockageAndPathToPin) {
  const std::string file = layout_file("sloped_hand", R"(  <boundary x0="0" y0="0" x1="100" y1="60"/>
  <rules wire-width="2" spacing="2"/>
  <blockage id="wall"><rect x0="40" y0="0" x1="60" y1="30"/></blockage>
  <net name="pad">
    <pin name="sq"><polygon points="44,30 54,32 52,42 42,40"/></pin>
    <pin name="p" x="90" y="50"/>
  </net>
  <net name="sliver">
    <pin name="thin"><polygon points="10,10 30,14 30,15"/></pin>
    <pin name="p" x="10" y="50"/>
  </net>
  <blockage id="ramp"><polygon points="60,40 90,40 90,55"/></blockage>
  <net name="covered">
    <pin name="sq"><rect x0="70" y0="45" x1="71" y1="46"/></pin>
    <pin name="p" x="20" y="55"/>
  </net>
)");
  const std::string out = temp_dir("sloped_hand_out") + "/r.xml";
  const auto r = run_taut({"route", file, "-o", out});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("[ROUTE-0005] net \"sliver\" not routed: pin \"thin\" has an edge at an angle other than 0, 45 or 90 "
                       "degrees, and no cell of the unit lattice lies inside it"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("[ROUTE-0005] net \"covered\" not routed: pin \"sq\" lies partly under a blockage"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("no cell of the unit lattice lies in its part outside them"), std::string::npos) << r.err;
  const auto c = run_taut({"check", out, "-q"});
  EXPECT_EQ(c.status, 0) << c.err;
  std::map<std::string, io::Route> routes = routes_of(out);
  ASSERT_EQ(routes["pad"].status, "routed") << routes["pad"].reason.value_or("");
  const std::vector<Point> ends = staircase_points(Polygon{{{44, 30}, {54, 32}, {52, 42}, {42, 40}}, {}});
  const Point end = routes["pad"].wires.at(0).points.front();
  EXPECT_NE(std::find(ends.begin(), ends.end(), end), ends.end()) << end.x << "," << end.y;
  // path --to-pin (no clearance): the shortest wire from 90,50 to the staircase, against the reference
  const auto p = run_taut({"path", file, "--from", "90,50", "--to-pin", "pad", "sq", "--json"});
  EXPECT_EQ(p.status, 0) << p.err;
  const auto ref = reference_for<oracle::L1Reference>(file);
  std::optional<std::int64_t> best;
  for (const auto& v : ref.ref->distances(Point{90, 50}, ends))
    if (v && (!best || *v < *best)) best = v;
  ASSERT_TRUE(best.has_value());
  EXPECT_NE(p.out.find("\"cost\":" + std::to_string(*best) + ","), std::string::npos) << p.out;
  const auto q = run_taut({"path", file, "--from", "10,50", "--to-pin", "sliver", "thin"});
  EXPECT_EQ(q.status, 1) << q.err;
  EXPECT_NE(q.err.find("ROUTE-0005"), std::string::npos) << q.err;
  EXPECT_NE(q.err.find("no cell of the unit lattice lies inside it"), std::string::npos) << q.err;
  for (const char* metric : {"l1", "link"}) {
    const auto u = run_taut({"path", file, "--from", "20,55", "--to-pin", "covered", "sq", "--metric", metric});
    EXPECT_EQ(u.status, 1) << u.err;
    EXPECT_NE(u.err.find("[ROUTE-0005] pin \"sq\" of net \"covered\""), std::string::npos) << u.err;
    EXPECT_NE(u.err.find("lies partly under"), std::string::npos) << u.err;
    EXPECT_NE(u.err.find("no cell of the unit lattice lies in its part outside them"), std::string::npos) << u.err;
  }
}

// A pad that another net's wire comes within the clearance of (w = 2, s = 2: net a's wire at y =
// 33 keeps 3 = w/2 + s from the pad's top side, and grown by w + s = 4 it covers the pad's top
// unit): since 2026-12-06 net b is reached from the part of its pad that wire leaves clear, in the
// first pass, with no rip-up, rectilinear, octilinear and under --metric combined; before, its
// attempt was refused there (ROUTE-0005 inside the net router), and it took a rip-up of a (the
// same refusal kept the RDL's BUMP_9_12 unrouted). The checker passes, and b's wire is not
// claimed shortest (NetAttempt::claims) while a's is; nor is c's, whose pad lies partly under a
// blockage (NetSpace::reached_otherwise).
TEST(SlopedPins, APadAnotherNetsWireComesNearIsReachedFromItsClearPart) {
  const std::string file = layout_file("pad_clear_part", R"(  <boundary x0="0" y0="0" x1="100" y1="60"/>
  <rules wire-width="2" spacing="2"/>
  <net name="a">
    <pin name="l" x="40" y="33"/>
    <pin name="r" x="70" y="33"/>
  </net>
  <net name="b">
    <pin name="pad"><rect x0="50" y0="20" x1="60" y1="30"/></pin>
    <pin name="p" x="5" y="5"/>
  </net>
  <blockage id="wall"><rect x0="80" y0="0" x1="90" y1="10"/></blockage>
  <net name="c">
    <pin name="pad"><rect x0="85" y0="5" x1="95" y1="14"/></pin>
    <pin name="p" x="95" y="50"/>
  </net>
)");
  const std::string dir = temp_dir("pad_clear_part_out");
  for (const std::vector<std::string>& how : std::vector<std::vector<std::string>>{
           {"--orientations", "rectilinear"}, {"--orientations", "octilinear"}, {"--metric", "combined", "--bend-cost", "5"}}) {
    SCOPED_TRACE(how[1]);
    std::vector<std::string> cmd{"route", file, "-o", dir + "/r.xml", "--stats", dir + "/s.json", "-q"};
    cmd.insert(cmd.end(), how.begin(), how.end());
    const auto r = run_taut(cmd);
    EXPECT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(read_text(dir + "/s.json"));
    EXPECT_EQ(j["net_router"]["rip_ups"], 0);
    EXPECT_EQ(j["net_router"]["first_pass_routed"], 3);
    const auto c = run_taut({"check", dir + "/r.xml", "-q"});
    EXPECT_EQ(c.status, 0) << c.err;
    // no claim of the shortest for b, whose pad was cut (a's straight wire is claimed)
    EXPECT_EQ(j["routes"]["b"]["shortest"], false);
    EXPECT_EQ(j["routes"]["a"]["shortest"], true);
    // c's pad, partly under the wall, reached as its part outside it (NetSpace::reach): routed, no claim
    EXPECT_EQ(j["routes"]["c"]["status"], "routed");
    EXPECT_EQ(j["routes"]["c"]["shortest"], false);
    std::map<std::string, io::Route> routes = routes_of(dir + "/r.xml");
    ASSERT_EQ(routes["b"].status, "routed");
    const Point end = routes["b"].wires.at(0).points.front();
    EXPECT_TRUE(end.x >= 50 && end.x <= 60 && end.y >= 20 && end.y <= 29) << end.x << "," << end.y;
  }
}

}  // namespace sloped_pin_test
}  // namespace taut::test
