// `taut tighten` end to end: designs/wind.xml (sketches that wind round blockages, several turns,
// a pinch) and the demo's routed wires, judged by references that share only geom with the
// command (oracle::L1Reference::check_path for free space, oracle::HomotopyWords for the class,
// taut_problem for local tautness); the written lengths, bends and statistics; the SVG; and the
// answers to bad input (exit status 2 and nothing written, file:line and the net's name).
#include <gtest/gtest.h>

#include <sstream>

#include <cmath>

#include "geom/directions.h"
#include "geom/root3_directions.h"
#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "io/layout_reader.h"
#include "io/stats_json.h"
#include "oracle/homotopy.h"
#include "oracle/l1_oracle.h"
#include "oracle/link_oracle.h"
#include "router/tighten.h"
#include "support/layout_reference.h"
#include "support/run.h"
#include "support/sanitized.h"
#include "support/taut_check.h"

namespace taut::test {
namespace tighten_test {

using geom::Point;
using Path = std::vector<Point>;
const std::string kDesigns = std::string(TAUT_SOURCE_DIR) + "/designs/";

using Inputs = std::vector<std::pair<std::string, std::vector<Path>>>;

// The wires of net `net` in a routed file.
std::vector<Path> wires_of(const std::string& file, const std::string& net) {
  io::ReadResult rr = io::read_layout(file);
  std::vector<Path> out;
  if (!rr.layout || !rr.layout->routes) return out;
  for (const io::Route& r : rr.layout->routes->routes)
    if (r.net == net)
      for (const io::Wire& w : r.wires) out.push_back(w.points);
  return out;
}

// The c-oriented wires of `c_file` against the taut (any-angle) wires of `taut_file`: every
// segment in the set, free, in the taut wire's class, of the set's length of the taut wire (twice
// it, exactly: geom/directions.h). A net written as failed is counted (its reason names the set);
// returns how many were.
int expect_c_oriented(const std::string& c_file, const std::string& taut_file, const Inputs& inputs,
                      const geom::LatticeDirections& set) {
  io::ReadResult rr = io::read_layout(c_file);
  EXPECT_TRUE(rr.layout && rr.layout->routes) << c_file;
  if (!rr.layout || !rr.layout->routes) return -1;
  EXPECT_EQ(rr.layout->routes->orientations, set.name());
  std::vector<Point> extra;
  for (const auto& [net, lines] : inputs)
    for (const Path& l : lines) extra.insert(extra.end(), l.begin(), l.end());
  const auto r = reference_for<oracle::L1Reference>(c_file, extra);
  const oracle::HomotopyWords h(r.norm.domain, r.norm.obstacles);
  int failed = 0;
  for (const auto& [net, lines] : inputs) {
    SCOPED_TRACE(net + " " + set.name());
    const std::vector<Path> c = wires_of(c_file, net), t = wires_of(taut_file, net);
    if (c.empty()) {
      ++failed;
      for (const io::Route& x : rr.layout->routes->routes)
        if (x.net == net) {
          EXPECT_EQ(x.status, "failed");
          EXPECT_NE(x.reason.value_or("").find("no " + set.name() + " wire"), std::string::npos);
        }
      continue;
    }
    EXPECT_EQ(c.size(), lines.size());
    EXPECT_EQ(t.size(), lines.size());
    if (c.size() != lines.size() || t.size() != lines.size()) continue;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const Path& w = c[k];
      const bool loop = lines[k].front() == lines[k].back();
      EXPECT_EQ(w.front(), loop ? t[k].front() : lines[k].front());  // a loop: from the taut loop's base
      EXPECT_EQ(w.back(), loop ? t[k].back() : lines[k].back());
      for (std::size_t i = 1; i < w.size(); ++i)
        EXPECT_TRUE(set.along(std::int64_t{w[i].x} - w[i - 1].x, std::int64_t{w[i].y} - w[i - 1].y)) << "segment " << i;
      EXPECT_TRUE(r.ref->check_path(w).has_value()) << "leaves free space";
      if (loop)
        EXPECT_TRUE(same_up_to_rotation(cyclic_word(h.word(w)), cyclic_word(h.word(lines[k])))) << "another class";
      else
        EXPECT_EQ(h.word(w), h.word(lines[k])) << "another homotopy class";
      EXPECT_EQ(set.length2(w), set.length2(t[k]));
      if (set.is_octilinear()) {
        EXPECT_EQ(oct_length(w), oct_length(t[k]));
      }
      if (set.is_rectilinear()) {
        EXPECT_EQ(l1_length(w), l1_length(t[k]));
      }
    }
  }
  return failed;
}

// Every routed wire of `out_file` against the input polyline it came from.
void expect_tightened(const std::string& out_file, const Inputs& inputs) {
  io::ReadResult rr = io::read_layout(out_file);
  ASSERT_TRUE(rr.layout && rr.layout->routes) << out_file;
  std::vector<Point> extra;
  for (const auto& [net, lines] : inputs)
    for (const Path& l : lines) extra.insert(extra.end(), l.begin(), l.end());
  const auto r = reference_for<oracle::L1Reference>(out_file, extra);
  const oracle::HomotopyWords h(r.norm.domain, r.norm.obstacles);
  EXPECT_EQ(rr.layout->routes->metric, "euclidean");
  EXPECT_EQ(rr.layout->routes->orientations, "any");
  for (const auto& [net, lines] : inputs) {
    SCOPED_TRACE(net);
    const io::Route* route = nullptr;
    for (const io::Route& x : rr.layout->routes->routes)
      if (x.net == net) route = &x;
    ASSERT_NE(route, nullptr);
    ASSERT_EQ(route->status, "routed");
    ASSERT_EQ(route->wires.size(), lines.size());
    double total = 0;
    long bends = 0;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const Path& w = route->wires[k].points;
      const Path& in = lines[k];
      if (in.front() == in.back()) {  // a loop: the shortest of its free homotopy class
        EXPECT_EQ(w.front(), w.back());
        EXPECT_TRUE(r.ref->check_path(wrapped(w)).has_value()) << "leaves free space";
        EXPECT_TRUE(same_up_to_rotation(cyclic_word(h.word(w)), cyclic_word(h.word(in)))) << "another class";
        EXPECT_FALSE(cyclic_word(h.word(in)).empty());
        EXPECT_EQ(taut_problem(wrapped(w), r.norm.domain, r.norm.obstacles), "");
      } else {
        EXPECT_EQ(w.front(), in.front());
        EXPECT_EQ(w.back(), in.back());
        EXPECT_TRUE(r.ref->check_path(w).has_value()) << "leaves free space";
        EXPECT_EQ(h.word(w), h.word(in)) << "another homotopy class";
        EXPECT_EQ(taut_problem(w, r.norm.domain, r.norm.obstacles), "");
      }
      EXPECT_LE(router::euclidean_length(w), router::euclidean_length(in) + 1e-6);
      total += router::euclidean_length(w);
      bends += static_cast<long>(w.size()) - 2;
    }
    ASSERT_TRUE(route->length.has_value());
    EXPECT_NEAR(std::stod(*route->length), total, 0.0006);
    EXPECT_EQ(route->bends.value_or(-1), bends);
  }
}

TEST(Tighten, WindingSketches) {
  const std::string dir = temp_dir("tighten_wind");
  const std::string in = kDesigns + "wind.xml";
  const auto run = run_taut({"tighten", in, "-o", dir + "/w.xml", "--svg", dir + "/w.svg", "--stats", dir + "/w.json"});
  ASSERT_EQ(run.status, 0) << run.err;
  io::ReadResult rr = io::read_layout(in);
  ASSERT_TRUE(rr.layout);
  std::vector<std::pair<std::string, std::vector<Path>>> inputs;
  for (const io::Net& n : rr.layout->nets) {
    ASSERT_TRUE(n.sketch) << n.name;
    inputs.push_back({n.name, {n.sketch->points}});
  }
  ASSERT_GE(inputs.size(), 6u);
  expect_tightened(dir + "/w.xml", inputs);
  // the spiral wraps the core's corners twice: (20000,13000) and (26000,13000) appear twice
  io::ReadResult out = io::read_layout(dir + "/w.xml");
  for (const io::Route& r : out.layout->routes->routes)
    if (r.net == "spiral") {
      const Path& w = r.wires[0].points;
      EXPECT_EQ(std::count(w.begin(), w.end(), Point{20000, 13000}), 2);
      EXPECT_EQ(std::count(w.begin(), w.end(), Point{26000, 13000}), 2);
    }
  // statistics: lengths before and after, per net and in total
  const auto j = nlohmann::json::parse(read_text(dir + "/w.json"));
  const auto& t = j["tighten"];
  ASSERT_EQ(t["nets"].size(), inputs.size());
  double before = 0, after = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto& e = t["nets"][i];
    EXPECT_EQ(e["net"], inputs[i].first);
    EXPECT_EQ(e["source"], "sketch");
    EXPECT_NEAR(e["length_before"].get<double>(), router::euclidean_length(inputs[i].second[0]), 0.0006);
    EXPECT_LT(e["length_after"].get<double>(), e["length_before"].get<double>());
    EXPECT_GT(e["sleeve_triangles"].get<long>(), 0);
    before += e["length_before"].get<double>();
    after += e["length_after"].get<double>();
  }
  EXPECT_NEAR(t["length_before"].get<double>(), before, 0.003);
  EXPECT_NEAR(t["length_after"].get<double>(), after, 0.003);
  // rectilinear and octilinear output: the shortest wires of the class in those directions
  for (const std::string o : {"rectilinear", "octilinear"}) {
    const auto c = run_taut({"tighten", in, "-q", "-o", dir + "/" + o + ".xml", "--orientations", o});
    ASSERT_EQ(c.status, 0) << c.err;
    EXPECT_EQ(expect_c_oriented(dir + "/" + o + ".xml", dir + "/w.xml", inputs, *geom::LatticeDirections::parse(o)), 0);
  }
  // every other lattice direction set, named in any order and with opposite directions; a net
  // with no lattice wire of the set's length in its class is failed (exit 1), and `taut check`
  // checks the directions of the others
  int failed = 0, written = 0;
  for (const std::string o : {"c:0,45", "c:180,135", "c:45,90", "c:90,135", "c:225,135", "c:0,45,90", "c:0,90,135",
                              "c:0,45,135", "c:45,90,135"}) {
    const auto set = *geom::LatticeDirections::parse(o);
    const std::string out = dir + "/" + set.name().substr(2) + ".xml";
    const auto c = run_taut({"tighten", in, "-q", "-o", out, "--orientations", o});
    const int f = expect_c_oriented(out, dir + "/w.xml", inputs, set);
    EXPECT_EQ(c.status, f > 0 ? 1 : 0) << o << ": " << c.err;
    failed += f;
    written += static_cast<int>(inputs.size()) - f;
    const auto chk = run_taut({"check", out});  // the clearance is not kept without --clearance
    EXPECT_NE(chk.out.find("lengths and bends ok; " + set.name() + " orientations ok; free space ok; connectivity ok"),
              std::string::npos)
        << chk.out;
  }
  // with the clearance of <rules>, tightened together: `taut check` passes the whole layout
  for (const std::string o : {"c:0,45", "c:45,135"}) {
    const std::string out = dir + "/clear" + o.substr(2) + ".xml";
    const auto c = run_taut({"tighten", in, "-q", "-o", out, "--orientations", o, "--clearance"});
    ASSERT_EQ(c.status, 0) << o << ": " << c.err;
    const auto chk = run_taut({"check", out});
    EXPECT_EQ(chk.status, 0) << o << ": " << chk.err;
    EXPECT_NE(chk.out.find(o + " orientations ok"), std::string::npos) << chk.out;
    EXPECT_EQ(wires_of(out, "spiral").size(), 1u);
  }
  EXPECT_EQ(written, 54);  // every net in every set (the pieces' ends have the parity they need)
  EXPECT_EQ(failed, 0);
  // the picture shows the sketches (dashed) and the tightened wires
  const std::string svg = read_text(dir + "/w.svg");
  EXPECT_NE(svg.find("class=\"sketch\" data-net=\"spiral\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"wire\" data-net=\"spiral\""), std::string::npos);
  // the summary on stderr
  EXPECT_NE(run.err.find("tightened 6 of 6 nets"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("LAYOUT-"), std::string::npos) << run.err;  // the pinless loop net is fine
  // the guard ring is the hexagon's boundary
  const std::vector<Path> ring = wires_of(dir + "/w.xml", "guard");
  ASSERT_EQ(ring.size(), 1u);
  EXPECT_EQ(ring[0].size(), 7u);
}

// A net's one minimum-link wire from the --stats JSON ("p/q" strings), exactly.
std::vector<oracle::QPoint> min_link_wire(const nlohmann::json& net) {
  std::vector<oracle::QPoint> q;
  EXPECT_EQ(net["min_link_wires"].size(), 1u);
  if (net["min_link_wires"].empty()) return q;
  for (const auto& p : net["min_link_wires"][0])
    q.push_back({mpq_class(p[0].get<std::string>()), mpq_class(p[1].get<std::string>())});
  return q;
}

// A minimum-link loop: closed, every link free, freely homotopic to the sketch.
void expect_loop_in_class(const std::vector<oracle::QPoint>& q, const Path& sketch, const geom::Box& domain,
                          const std::vector<geom::Polygon>& obstacles, const oracle::HomotopyWords& h) {
  ASSERT_GE(q.size(), 4u);
  EXPECT_TRUE(q.front().x == q.back().x && q.front().y == q.back().y);
  for (std::size_t k = 0; k + 1 < q.size(); ++k)
    EXPECT_TRUE(oracle::segment_free(q[k], q[k + 1], domain, obstacles)) << "link " << k;
  EXPECT_TRUE(same_up_to_rotation(cyclic_word(h.word(std::span<const oracle::QPoint>(q))), cyclic_word(h.word(sketch))))
      << "another free homotopy class";
}

// taut tighten designs/wind.xml --min-link in the given orientations, with what the tests judge it
// by: the layout, its normalized blockages (sketch points included in the domain), the homotopy
// reference and the --stats JSON.
struct WindMinLink {
  WindMinLink(const std::string& name, const std::string& orientations)
      : dir(temp_dir(name)),
        run(run_taut({"tighten", kDesigns + "wind.xml", "-o", dir + "/w.xml", "--orientations", orientations, "--svg",
                      dir + "/w.svg", "--stats", dir + "/w.json", "--min-link"})),
        rr(io::read_layout(kDesigns + "wind.xml")),
        norm(normalized_for(kDesigns + "wind.xml", sketch_points(rr))),
        h(norm.domain, norm.obstacles),
        j(run.status == 0 ? nlohmann::json::parse(read_text(dir + "/w.json")) : nlohmann::json()) {}
  static std::vector<Point> sketch_points(const io::ReadResult& r) {
    std::vector<Point> extra;
    for (const io::Net& n : r.layout->nets) extra.insert(extra.end(), n.sketch->points.begin(), n.sketch->points.end());
    return extra;
  }
  std::string dir;
  RunResult run;
  io::ReadResult rr;
  geom::NormalizedObstacles norm;
  oracle::HomotopyWords h;
  nlohmann::json j;
};

// --min-link: each open wire's minimum-link path, exact, in the stats; checked against the
// rational references (free, same class) and against the written (shortest) wire's links.
TEST(Tighten, MinLinkPathsInTheStats) {
  const WindMinLink w("tighten_minlink", "any");
  ASSERT_EQ(w.run.status, 0) << w.run.err;
  const auto& [dir, run, rr, norm, h, j] = w;
  const auto& nets = j["tighten"]["nets"];
  ASSERT_EQ(nets.size(), rr.layout->nets.size());
  int fewer = 0;
  for (std::size_t i = 0; i < nets.size(); ++i) {
    const Path& sketch = rr.layout->nets[i].sketch->points;
    const auto& e = nets[i];
    SCOPED_TRACE(e["net"].get<std::string>());
    const std::vector<oracle::QPoint> q = min_link_wire(e);
    ASSERT_GE(q.size(), 2u);
    EXPECT_EQ(e["min_links"].get<std::size_t>(), q.size() - 1);
    if (sketch.front() == sketch.back()) {
      // the guard ring round the hexagon: a triangle (three links: no fewer can wind round
      // anything)
      EXPECT_EQ(q.size(), 4u);
      expect_loop_in_class(q, sketch, norm.domain, norm.obstacles, h);
      continue;
    }
    EXPECT_TRUE(q.front().x == sketch.front().x && q.front().y == sketch.front().y);
    EXPECT_TRUE(q.back().x == sketch.back().x && q.back().y == sketch.back().y);
    for (std::size_t k = 0; k + 1 < q.size(); ++k)
      EXPECT_TRUE(oracle::segment_free(q[k], q[k + 1], norm.domain, norm.obstacles)) << "link " << k;
    EXPECT_EQ(h.word(std::span<const oracle::QPoint>(q)), h.word(sketch)) << "another homotopy class";
    const long links_after = e["bends_after"].get<long>() + 1;
    EXPECT_LE(static_cast<long>(q.size()) - 1, links_after);
    fewer += static_cast<long>(q.size()) - 1 < links_after;
  }
  EXPECT_GE(fewer, 2);  // the slalom and the spiral save links
  EXPECT_NE(read_text(dir + "/w.svg").find("class=\"min-link\""), std::string::npos);
  EXPECT_NE(run.err.find("minimum links"), std::string::npos) << run.err;
}

// --min-link --orientations octilinear: each open wire's minimum-link octilinear path of its class
// (section 6.3), exact, in the stats and drawn; checked against the rational references (ends, free,
// same class, every link along one of the eight directions), never more links than the written
// (shortest) octilinear wire, and never fewer than the any-angle minimum. The guard ring (a loop)
// gets its octilinear loop (CMinLinker::loop), checked the same way as a closed loop of its class.
TEST(Tighten, OrientedMinLinkPathsInTheStats) {
  const WindMinLink w("tighten_oriented_minlink", "octilinear");
  ASSERT_EQ(w.run.status, 0) << w.run.err;
  const auto& [dir, run, rr, norm, h, j] = w;
  const auto& nets = j["tighten"]["nets"];
  ASSERT_EQ(nets.size(), rr.layout->nets.size());
  int fewer = 0, open = 0;
  std::size_t loop_links = 0;
  for (std::size_t i = 0; i < nets.size(); ++i) {
    const Path& sketch = rr.layout->nets[i].sketch->points;
    const auto& e = nets[i];
    SCOPED_TRACE(e["net"].get<std::string>());
    ASSERT_EQ(e["oriented_min_link_wires"].size(), 1u);
    std::vector<oracle::QPoint> q;
    for (const auto& p : e["oriented_min_link_wires"][0])
      q.push_back({mpq_class(p[0].get<std::string>()), mpq_class(p[1].get<std::string>())});
    ASSERT_GE(q.size(), 2u);
    const std::size_t links = q.size() - 1;
    auto octilinear = [&](std::size_t k) {
      const mpq_class dx = q[k + 1].x - q[k].x, dy = q[k + 1].y - q[k].y;
      return dx == 0 || dy == 0 || dx == dy || dx == -dy;
    };
    if (sketch.front() == sketch.back()) {
      // the guard ring: a closed octilinear loop of its class (since 2026-12-03), its count
      // proven or given as a range, never below the any-angle minimum
      EXPECT_FALSE(e.contains("oriented_min_links_none"));
      expect_loop_in_class(q, sketch, norm.domain, norm.obstacles, h);
      for (std::size_t k = 0; k + 1 < q.size(); ++k) EXPECT_TRUE(octilinear(k)) << "link " << k << " is not octilinear";
      if (e["oriented_min_links"].is_null()) {
        EXPECT_LE(e["oriented_min_links_at_least"].get<std::size_t>(), links);
        EXPECT_EQ(e["oriented_min_links_at_most"].get<std::size_t>(), links);
      } else {
        EXPECT_EQ(e["oriented_min_links"].get<std::size_t>(), links);
      }
      EXPECT_GE(links, e["min_links"].get<std::size_t>());
      loop_links = links;
      continue;
    }
    ++open;
    EXPECT_EQ(e["oriented_min_links"].get<std::size_t>(), links);
    EXPECT_TRUE(q.front().x == sketch.front().x && q.front().y == sketch.front().y);
    EXPECT_TRUE(q.back().x == sketch.back().x && q.back().y == sketch.back().y);
    for (std::size_t k = 0; k + 1 < q.size(); ++k) {
      EXPECT_TRUE(oracle::segment_free(q[k], q[k + 1], norm.domain, norm.obstacles)) << "link " << k;
      EXPECT_TRUE(octilinear(k)) << "link " << k << " is not octilinear";
    }
    EXPECT_EQ(h.word(std::span<const oracle::QPoint>(q)), h.word(sketch)) << "another homotopy class";
    const std::size_t written = e["bends_after"].get<std::size_t>() + 1;
    EXPECT_LE(links, written);
    EXPECT_GE(links, e["min_links"].get<std::size_t>());
    fewer += links < written;
  }
  EXPECT_EQ(open, 5);
  EXPECT_EQ(loop_links, 3u);  // round the hexagon: a triangle of 0, 90 and 135 (or 45) degree links
  EXPECT_GE(fewer, 3);  // the slalom, the spiral, the loop and the squeeze save links (diag does not)
  EXPECT_NE(read_text(dir + "/w.svg").find("class=\"oriented-min-link\""), std::string::npos);
  // the README's picture: make run's command (with --clearance) draws it
  const auto pic = run_taut({"tighten", kDesigns + "wind.xml", "-q", "--clearance", "--min-link", "--orientations",
                             "octilinear", "-o", dir + "/c.xml", "--svg", dir + "/c.svg"});
  ASSERT_EQ(pic.status, 0) << pic.err;
  EXPECT_EQ(read_text(dir + "/c.svg"), read_text(std::string(TAUT_SOURCE_DIR) + "/docs/wind-oct-minlink.svg"))
      << "docs/wind-oct-minlink.svg is not what taut draws now: copy " << dir << "/c.svg";
  EXPECT_NE(run.err.find("(octilinear: "), std::string::npos) << run.err;
}

// --min-link on loops (section 5.2): a ring wound twice round a square has a convex shortest
// loop, and its five links are proven minimal by the winding number; a ring round two squares
// with a third pushed in between them from above has inflection edges (it bends the other way
// under the third), so its count is the minimum, with and without --clearance.
TEST(Tighten, MinLinkLoopsInTheStats) {
  const std::string dir = temp_dir("tighten_minlink_loops");
  const std::string body =
      "  <boundary x0=\"0\" y0=\"0\" x1=\"400\" y1=\"240\"/>\n"
      "  <rules wire-width=\"2\" spacing=\"1\" orientations=\"any\"/>\n"
      "  <blockage id=\"a\"><rect x0=\"40\" y0=\"40\" x1=\"60\" y1=\"60\"/></blockage>\n"
      "  <blockage id=\"b\"><rect x0=\"140\" y0=\"40\" x1=\"160\" y1=\"60\"/></blockage>\n"
      "  <blockage id=\"dent\"><rect x0=\"90\" y0=\"55\" x1=\"110\" y1=\"110\"/></blockage>\n"
      "  <blockage id=\"c\"><rect x0=\"290\" y0=\"110\" x1=\"310\" y1=\"130\"/></blockage>\n"
      "  <net name=\"twice\"><sketch points=\"270,120 300,80 330,120 300,160 270,120 300,80 330,120 300,160 270,120\"/></net>\n"
      "  <net name=\"dented\"><sketch points=\"20,50 30,20 170,20 180,50 150,72 100,46 50,72 20,50\"/></net>\n";
  const std::string file = layout_file("tighten_minlink_loops_in", body);
  const geom::NormalizedObstacles norm = normalized_for(file);
  const oracle::HomotopyWords h(norm.domain, norm.obstacles);
  io::ReadResult in = io::read_layout(file);
  ASSERT_TRUE(in.layout);
  for (const bool clearance : {false, true}) {
    SCOPED_TRACE(clearance ? "--clearance" : "plain");
    std::vector<std::string> args{"tighten", file, "-o", dir + "/t.xml", "--stats", dir + "/t.json", "--min-link"};
    if (clearance) args.push_back("--clearance");
    const auto run = run_taut(args);
    ASSERT_EQ(run.status, 0) << run.err;
    const auto j = nlohmann::json::parse(read_text(dir + "/t.json"));
    const auto& nets = j["tighten"]["nets"];
    ASSERT_EQ(nets.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& e = nets[i];
      SCOPED_TRACE(e["net"].get<std::string>());
      const std::vector<oracle::QPoint> q = min_link_wire(e);
      expect_loop_in_class(q, in.layout->nets[i].sketch->points, norm.domain, norm.obstacles, h);
      ASSERT_GE(q.size(), 4u);
      EXPECT_EQ(e["min_links"].get<std::size_t>(), q.size() - 1);
      EXPECT_FALSE(e.contains("min_links_at_most"));
      if (i == 0) {
        // twice round: five links, proven by the winding number (a closed path of four links
        // winds at most once round a point)
        EXPECT_EQ(q.size(), 6u);
      } else {
        // plain: four links, a long one under both squares and a V under the dent (every link
        // grazes a corner); the blockages grown by the clearance leave no room for it: five
        EXPECT_EQ(q.size(), clearance ? 6u : 5u);
      }
    }
    EXPECT_NE(run.err.find("twice (sketch): length 400.000 -> " + std::string(clearance ? "192" : "160") +
                           ".000, bends 7 -> 7, minimum links 5\n"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find(clearance ? "bends 6 -> 7, minimum links 5" : "bends 6 -> 7, minimum links 4"), std::string::npos)
        << run.err;
  }
  // a ring round two triangles whose shortest loop is convex, where the greedy runs find four
  // links and the winding number only proves three: both bounds, min_links null
  const std::string pair = layout_file("tighten_minlink_pair_in",
                                       "  <boundary x0=\"0\" y0=\"0\" x1=\"120\" y1=\"120\"/>\n"
                                       "  <rules orientations=\"any\"/>\n"
                                       "  <blockage id=\"a\"><polygon points=\"30,80 50,110 30,110\"/></blockage>\n"
                                       "  <blockage id=\"b\"><polygon points=\"50,70 80,100 50,100\"/></blockage>\n"
                                       "  <blockage id=\"c\"><polygon points=\"70,10 80,10 80,30\"/></blockage>\n"
                                       "  <net name=\"pair\"><sketch points=\"45,65 65,5 85,5 85,105 48,103 45,65\"/></net>\n");
  const auto run = run_taut({"tighten", pair, "-o", dir + "/p.xml", "--stats", dir + "/p.json", "--min-link"});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto e = nlohmann::json::parse(read_text(dir + "/p.json"))["tighten"]["nets"][0];
  EXPECT_TRUE(e["min_links"].is_null());
  EXPECT_EQ(e["min_links_at_least"], 3);
  EXPECT_EQ(e["min_links_at_most"], 4);
  EXPECT_EQ(min_link_wire(e).size(), 5u);
  EXPECT_NE(run.err.find("minimum links 3 to 4 (a convex loop's minimum is not proven)"), std::string::npos) << run.err;
}

TEST(Tighten, RoutedWiresOfTheDemo) {
  const std::string dir = temp_dir("tighten_demo");
  const auto routed = run_taut({"route", kDesigns + "demo.xml", "-q", "-o", dir + "/r.xml"});
  ASSERT_EQ(routed.status, 0) << routed.err;
  const auto run = run_taut({"tighten", dir + "/r.xml", "-o", dir + "/t.xml", "--svg", dir + "/t.svg", "--orientations", "any"});
  ASSERT_EQ(run.status, 0) << run.err;
  io::ReadResult rr = io::read_layout(dir + "/r.xml");
  ASSERT_TRUE(rr.layout && rr.layout->routes);
  std::vector<std::pair<std::string, std::vector<Path>>> inputs;
  for (const io::Net& n : rr.layout->nets) {
    if (n.sketch) {
      inputs.push_back({n.name, {n.sketch->points}});  // the sketch wins over the routed wire
      continue;
    }
    for (const io::Route& r : rr.layout->routes->routes)
      if (r.net == n.name) {
        std::vector<Path> lines;
        for (const io::Wire& w : r.wires) lines.push_back(w.points);
        inputs.push_back({n.name, lines});
      }
  }
  expect_tightened(dir + "/t.xml", inputs);
  EXPECT_NE(read_text(dir + "/t.svg").find("class=\"input-wire\""), std::string::npos);
  // the routed layout checks
  test::expect_routes_check_except_clearance(dir + "/t.xml");
  // without --orientations the demo's rules (rectilinear) apply
  const auto rect = run_taut({"tighten", dir + "/r.xml", "-q", "-o", dir + "/rect.xml"});
  ASSERT_EQ(rect.status, 0) << rect.err;
  EXPECT_EQ(expect_c_oriented(dir + "/rect.xml", dir + "/t.xml", inputs, geom::LatticeDirections::rectilinear()), 0);
  test::expect_routes_check_except_clearance(dir + "/rect.xml");  // checks the directions too
  // the rectilinear wires of `route` are L1-shortest already: tightening never lengthens them
  for (const io::Net& n : rr.layout->nets) {
    if (n.sketch) continue;
    std::int64_t before = 0, after = 0;
    for (const Path& w : wires_of(dir + "/r.xml", n.name)) before += l1_length(w);
    for (const Path& w : wires_of(dir + "/rect.xml", n.name)) after += l1_length(w);
    EXPECT_LE(after, before) << n.name;
  }
}

TEST(Tighten, NothingToTightenIsAFailedNet) {
  const std::string dir = temp_dir("tighten_nothing");
  const auto run = run_taut({"tighten", kDesigns + "demo.xml", "-o", dir + "/t.xml", "--orientations", "any"});
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_NE(run.err.find("demo.xml:41: warning: [TIGHTEN-0002] net \"clk\""), std::string::npos) << run.err;
  io::ReadResult rr = io::read_layout(dir + "/t.xml");
  ASSERT_TRUE(rr.layout && rr.layout->routes);
  int failed = 0, routed = 0;
  for (const io::Route& r : rr.layout->routes->routes) {
    failed += r.status == "failed";
    routed += r.status == "routed" && r.net == "bump";
  }
  EXPECT_EQ(failed, 4);
  EXPECT_EQ(routed, 1);
}

// route --tighten: each routed wire pulled taut in its class and written with the fewest links
// (never longer, never more bends than the routed wire: that wire is a staircase of the class),
// and the net with a sketch follows its sketch.
TEST(Tighten, RouteTighten) {
  const std::string dir = temp_dir("tighten_route");
  const std::string demo = kDesigns + "demo.xml";
  for (const std::string o : {"rectilinear", "octilinear"}) {
    SCOPED_TRACE(o);
    const auto plain = run_taut({"route", demo, "--independent", "-q", "--orientations", o, "-o", dir + "/plain.xml"});
    const auto tight = run_taut({"route", demo, "--independent", "--orientations", o, "--tighten", "-o", dir + "/tight.xml"});
    ASSERT_EQ(tight.status, 0) << tight.err;  // octilinear too: bump follows its sketch
    EXPECT_EQ(tight.err.find("ROUTE-0007"), std::string::npos) << tight.err;
    io::ReadResult in = io::read_layout(demo);
    ASSERT_TRUE(in.layout);
    Inputs sketches, routed;
    for (const io::Net& n : in.layout->nets) {
      if (n.sketch)
        sketches.push_back({n.name, {n.sketch->points}});
      else
        routed.push_back({n.name, wires_of(dir + "/plain.xml", n.name)});
    }
    // the tightened sketch, written at any angle, is the reference for the sketch's net
    const auto any = run_taut({"tighten", demo, "-q", "--orientations", "any", "-o", dir + "/any.xml"});
    ASSERT_EQ(any.status, 1) << any.err;  // the other nets have no sketch
    EXPECT_EQ(expect_c_oriented(dir + "/tight.xml", dir + "/any.xml", sketches, *geom::LatticeDirections::parse(o)), 0);
    const auto r = reference_for<oracle::L1Reference>(dir + "/tight.xml");
    const oracle::HomotopyWords h(r.norm.domain, r.norm.obstacles);
    for (const auto& [net, lines] : routed) {
      SCOPED_TRACE(net);
      const std::vector<Path> t = wires_of(dir + "/tight.xml", net);
      ASSERT_EQ(t.size(), lines.size());
      for (std::size_t k = 0; k < lines.size(); ++k) {
        EXPECT_EQ(t[k].front(), lines[k].front());
        EXPECT_EQ(t[k].back(), lines[k].back());
        EXPECT_TRUE(r.ref->check_path(t[k]).has_value());
        EXPECT_EQ(h.word(t[k]), h.word(lines[k]));
        if (o == std::string("octilinear"))
          EXPECT_EQ(oct_length(t[k]), oct_length(lines[k]));  // the routed wire is already shortest
        else
          EXPECT_EQ(l1_length(t[k]), l1_length(lines[k]));
        EXPECT_LE(geom::count_bends(t[k]), geom::count_bends(lines[k]));
      }
    }
    test::expect_routes_check_except_clearance(dir + "/tight.xml");
    // the nets together (not --independent): every net routed, bump by its sketch among the
    // others, and the whole layout passes `taut check` with its clearance (the demo's sketch once
    // ran through sda's pin: ROUTE-0011)
    const auto together = run_taut({"route", demo, "--orientations", o, "--tighten", "-o", dir + "/together.xml"});
    EXPECT_EQ(together.status, 0) << together.err;
    EXPECT_NE(together.err.find("5 of 5 nets routed"), std::string::npos) << together.err;
    const auto chk = run_taut({"check", dir + "/together.xml"});
    EXPECT_EQ(chk.status, 0) << chk.out << chk.err;
  }
}

// Exact clearance: 4 * distance^2 >= D^2 between segment pq and segment ab (D = w + 2s, twice the
// required w/2 + s), in __int128; segments that meet are at distance 0.
bool keeps_clearance(Point p, Point q, Point a, Point b, std::int64_t D) {
  using i128 = __int128;
  if (geom::intersect({p, q}, {a, b}) != geom::SegmentIntersection::None) return D == 0;
  auto far = [D](Point x, Point s0, Point s1) {  // point x against segment s0 s1
    const i128 ux = i128{s1.x} - s0.x, uy = i128{s1.y} - s0.y, vx = i128{x.x} - s0.x, vy = i128{x.y} - s0.y;
    const i128 t = ux * vx + uy * vy, len = ux * ux + uy * uy, dd = i128{D} * D;
    if (t <= 0) return 4 * (vx * vx + vy * vy) >= dd;
    if (t >= len) {
      const i128 wx = i128{x.x} - s1.x, wy = i128{x.y} - s1.y;
      return 4 * (wx * wx + wy * wy) >= dd;
    }
    const i128 c = ux * vy - uy * vx;
    return 4 * c * c >= dd * len;
  };
  return far(p, a, b) && far(q, a, b) && far(a, p, q) && far(b, p, q);
}

// --clearance: wires keep half the wire width plus the spacing from every blockage (checked
// exactly against the blockages as written), in the sketch's class; a sketch that passes closer
// is refused with TIGHTEN-0001; without the flag the rules are named as not kept (TIGHTEN-0006).
TEST(Tighten, ClearanceFromBlockages) {
  const std::string dir = temp_dir("tighten_clearance");
  const std::string body =
      "  <boundary x0=\"0\" y0=\"0\" x1=\"200\" y1=\"140\"/>\n"
      "  <rules wire-width=\"21\" spacing=\"9\" orientations=\"any\"/>\n"
      "  <blockage id=\"sq\"><rect x0=\"40\" y0=\"40\" x1=\"60\" y1=\"60\"/></blockage>\n"
      "  <blockage id=\"tri\"><polygon points=\"135,60 170,60 152,95\"/></blockage>\n"
      "  <net name=\"n\"><pin name=\"p\" x=\"5\" y=\"50\"/><pin name=\"q\" x=\"195\" y=\"4\"/>\n"
      "    <sketch points=\"5,50 5,120 82,120 82,4 195,4\"/></net>\n"
      "  <net name=\"ring\"><sketch points=\"115,35 190,35 190,125 115,125 115,35\"/></net>\n";
  const std::string file = layout_file("tighten_clearance_in", body);
  const std::int64_t D = 21 + 2 * 9;  // twice w/2 + s
  for (const std::string o : {"any", "rectilinear", "octilinear"}) {
    SCOPED_TRACE(o);
    const auto run = run_taut({"tighten", file, "--clearance", "--orientations", o, "-o", dir + "/t.xml"});
    ASSERT_EQ(run.status, 0) << run.err;
    io::ReadResult in = io::read_layout(file);
    ASSERT_TRUE(in.layout);
    const auto r = reference_for<oracle::L1Reference>(file);
    const oracle::HomotopyWords h(r.norm.domain, r.norm.obstacles);
    const std::vector<geom::Polygon> blockages = io::blockage_polygons(*in.layout);
    for (const io::Net& n : in.layout->nets) {
      const std::vector<Path> w = wires_of(dir + "/t.xml", n.name);
      ASSERT_EQ(w.size(), 1u) << n.name;
      const Path& wire = w[0];
      const bool loop = n.sketch->points.front() == n.sketch->points.back();
      if (loop)
        EXPECT_TRUE(same_up_to_rotation(cyclic_word(h.word(wire)), cyclic_word(h.word(n.sketch->points))));
      else
        EXPECT_EQ(h.word(wire), h.word(n.sketch->points)) << n.name;
      EXPECT_TRUE(r.ref->check_path(wire).has_value()) << n.name;
      for (std::size_t i = 1; i < wire.size(); ++i)
        for (const geom::Polygon& b : blockages)
          for (std::size_t k = 0; k < b.outer.size(); ++k)
            EXPECT_TRUE(keeps_clearance(wire[i - 1], wire[i], b.outer[k], b.outer[(k + 1) % b.outer.size()], D))
                << n.name << " segment " << i;
    }
    // and `taut check` (router/check.h, the independent checker) agrees: no clearance problem
    // (from the blockages and between the two nets: they are tightened together), free space and
    // connectivity ok
    const auto chk = run_taut({"check", dir + "/t.xml", "--json"});
    EXPECT_EQ(chk.status, 0) << chk.out << chk.err;
    const nlohmann::json cj = nlohmann::json::parse(chk.out)["routes_check"];
    EXPECT_EQ(cj["problems"]["blockage_clearance"], 0) << chk.err;
    EXPECT_EQ(cj["free_space"], "ok") << chk.err;
    EXPECT_EQ(cj["connectivity"], "ok") << chk.err;
  }
  // without the flag: the wire hugs the square (closer than the rules allow), and it is said
  const auto plain = run_taut({"tighten", file, "-o", dir + "/p.xml"});
  EXPECT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(plain.err.find("[TIGHTEN-0006]"), std::string::npos) << plain.err;
  const Path hug = wires_of(dir + "/p.xml", "n").at(0);
  EXPECT_NE(std::find(hug.begin(), hug.end(), Point{40, 60}), hug.end()) << "the square's corner";
  const auto hug_check = run_taut({"check", dir + "/p.xml", "--json"});
  EXPECT_EQ(hug_check.status, 1);
  EXPECT_GE(nlohmann::json::parse(hug_check.out)["routes_check"]["problems"]["blockage_clearance"].get<int>(), 1) << hug_check.err;
  // a sketch through the clearance zone (20 DBU above the square) is refused, nothing written
  std::string close = body;
  close.replace(close.find("5,50 5,120 82,120"), 17, "5,50 5,70 82,120");
  write_text(dir + "/c.xml", "old");
  const auto refused = run_taut({"tighten", layout_file("tighten_clearance_close", close), "--clearance", "-o", dir + "/c.xml"});
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find("comes within the clearance of a blockage (20 DBU"), std::string::npos) << refused.err;
  EXPECT_EQ(read_text(dir + "/c.xml"), "old");
  // sketches of two nets that cross (or come within w + s) do not say which passes where: refused,
  // each naming the other, nothing written
  std::string crossing = body;
  crossing.replace(crossing.find("115,35 190,35 190,125 115,125 115,35"), 36, "75,35 190,35 190,125 75,125 75,35");
  const auto crossed = run_taut({"tighten", layout_file("tighten_clearance_cross", crossing), "--clearance", "-o", dir + "/c.xml"});
  EXPECT_EQ(crossed.status, 2) << crossed.err;
  EXPECT_NE(crossed.err.find("t.xml:7: error: [TIGHTEN-0001] net \"n\": the sketch's segment 2 (5,120 to 82,120) comes "
                             "within the clearance of net \"ring\"'s sketch (w + s = 30 DBU)"),
            std::string::npos)
      << crossed.err;
  EXPECT_NE(crossed.err.find("t.xml:8: error: [TIGHTEN-0001] net \"ring\": the sketch starts at 75,35, which lies within "
                             "the clearance of net \"n\"'s sketch"),
            std::string::npos)
      << crossed.err;
  EXPECT_EQ(read_text(dir + "/c.xml"), "old");
}

// --clearance in gaps of exactly the clearance (since 2026-12-05): a gap between two blockages of
// exactly twice w/2 + s, and two nets' sketches exactly w + s apart, are legal (taut check passes
// them), so they are tightened (in the net router's scaled plane, --stats tighten.together.scale
// above 1), not refused; one DBU narrower they are refused (TIGHTEN-0001, nothing written).
TEST(Tighten, ClearanceTakesGapsOfExactlyTheClearance) {
  const std::string dir = temp_dir("tighten_exact_gaps");
  // w 100, s 100: 150 from blockages, 200 between nets
  auto body = [](int gap_right, int b_x) {
    return "  <boundary x0=\"0\" y0=\"0\" x1=\"4000\" y1=\"4000\"/>\n"
           "  <rules wire-width=\"100\" spacing=\"100\" orientations=\"rectilinear\"/>\n"
           "  <blockage id=\"l\"><rect x0=\"0\" y0=\"1000\" x1=\"1000\" y1=\"3000\"/></blockage>\n"
           "  <blockage id=\"r\"><rect x0=\"" + std::to_string(gap_right) + "\" y0=\"1000\" x1=\"2500\" y1=\"3000\"/></blockage>\n"
           "  <net name=\"a\"><pin name=\"s\" x=\"1150\" y=\"400\"/><pin name=\"t\" x=\"1400\" y=\"3800\"/>\n"
           "    <sketch points=\"1150,400 1150,3500 1400,3800\"/></net>\n"
           "  <net name=\"b\"><pin name=\"s\" x=\"" + std::to_string(b_x) + "\" y=\"300\"/><pin name=\"t\" x=\"3900\" y=\"300\"/>\n"
           "    <sketch points=\"" + std::to_string(b_x) + ",300 " + std::to_string(b_x) + ",700 3900,700 3900,300\"/></net>\n";
  };
  // b's sketch runs up x = 1350, exactly 200 right of a's (and its pin exactly 200 from a's pin);
  // pulled taut, a runs up x = 1150 through the gap, b along y = 300
  const std::string exact = layout_file("tighten_exact_gaps_in", body(1300, 1350));
  const auto run = run_taut({"tighten", exact, "--clearance", "-o", dir + "/t.xml", "--stats", dir + "/t.json"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_GT(nlohmann::json::parse(read_text(dir + "/t.json"))["tighten"]["together"]["scale"].get<int>(), 1);
  EXPECT_EQ(wires_of(dir + "/t.xml", "a"), (std::vector<Path>{{{1150, 400}, {1150, 3800}, {1400, 3800}}}));
  EXPECT_EQ(wires_of(dir + "/t.xml", "b"), (std::vector<Path>{{{1350, 300}, {3900, 300}}}));
  const auto chk = run_taut({"check", dir + "/t.xml"});
  EXPECT_EQ(chk.status, 0) << chk.err;
  // b's sketch truly too near blockage r (100 below it): b is refused, and only b (a, in the
  // exact gap, is legal: the layout's units, where the whole is then tightened, would refuse it too)
  std::string near = body(1300, 1350);
  near.replace(near.find(",700 3900,700"), 13, ",900 3900,900");
  write_text(dir + "/c.xml", "old");
  const auto one = run_taut({"tighten", layout_file("tighten_exact_gaps_near", near), "--clearance", "-o", dir + "/c.xml"});
  EXPECT_EQ(one.status, 2) << one.err;
  EXPECT_NE(one.err.find("[TIGHTEN-0001] net \"b\""), std::string::npos) << one.err;
  EXPECT_EQ(one.err.find("net \"a\""), std::string::npos) << one.err;
  EXPECT_EQ(read_text(dir + "/c.xml"), "old");
  // a net whose pins share a point (a pad and a point pin on it) is routed by a wire of one
  // point: it keeps it, and the gap's wire is still tightened in the scaled plane (the empty
  // piece list it left once refused the scaled result, and wrote the net with no wire), by
  // tighten --clearance and by route --tighten
  const std::string touching = layout_file(
      "tighten_exact_gaps_touching",
      "  <boundary x0=\"0\" y0=\"0\" x1=\"4000\" y1=\"4000\"/>\n"
      "  <rules wire-width=\"100\" spacing=\"100\"/>\n"
      "  <blockage id=\"l\"><rect x0=\"0\" y0=\"1000\" x1=\"1000\" y1=\"3000\"/></blockage>\n"
      "  <blockage id=\"r\"><rect x0=\"1300\" y0=\"1000\" x1=\"2500\" y1=\"3000\"/></blockage>\n"
      "  <net name=\"a\"><pin name=\"s\" x=\"1150\" y=\"400\"/><pin name=\"t\" x=\"1400\" y=\"3800\"/></net>\n"
      "  <net name=\"c\"><pin name=\"p\"><rect x0=\"3000\" y0=\"3000\" x1=\"3400\" y1=\"3400\"/></pin>"
      "<pin name=\"q\" x=\"3200\" y=\"3200\"/></net>\n");
  ASSERT_EQ(run_taut({"route", touching, "-q", "-o", dir + "/tr.xml"}).status, 0);
  EXPECT_EQ(wires_of(dir + "/tr.xml", "c"), (std::vector<Path>{{{3200, 3200}, {3200, 3200}}}));
  const auto tt = run_taut({"tighten", dir + "/tr.xml", "-q", "--clearance", "-o", dir + "/tt.xml", "--stats", dir + "/tt.json"});
  ASSERT_EQ(tt.status, 0) << tt.err;
  EXPECT_GT(nlohmann::json::parse(read_text(dir + "/tt.json"))["tighten"]["together"]["scale"].get<int>(), 1);
  EXPECT_EQ(wires_of(dir + "/tt.xml", "c"), (std::vector<Path>{{{3200, 3200}, {3200, 3200}}}));
  EXPECT_EQ(run_taut({"check", dir + "/tt.xml", "-q"}).status, 0);
  ASSERT_EQ(run_taut({"route", touching, "-q", "--tighten", "-o", dir + "/rt.xml", "--stats", dir + "/rt.json"}).status, 0);
  EXPECT_GT(nlohmann::json::parse(read_text(dir + "/rt.json"))["tighten"]["scale"].get<int>(), 1);
  EXPECT_EQ(wires_of(dir + "/rt.xml", "c"), (std::vector<Path>{{{3200, 3200}, {3200, 3200}}}));
  // one DBU narrower: the gap, then the nets
  for (const auto& [name, b] : {std::pair{std::string("gap"), body(1299, 1350)}, std::pair{std::string("nets"), body(1300, 1349)}}) {
    SCOPED_TRACE(name);
    write_text(dir + "/c.xml", "old");
    const auto refused = run_taut({"tighten", layout_file("tighten_exact_gaps_" + name, b), "--clearance", "-o", dir + "/c.xml"});
    EXPECT_EQ(refused.status, 2) << refused.err;
    EXPECT_NE(refused.err.find("[TIGHTEN-0001]"), std::string::npos) << refused.err;
    EXPECT_EQ(read_text(dir + "/c.xml"), "old");
  }
}

// Routed trees stay joined (since 2026-12-05): `taut tighten`, with and without --clearance, on
// the routed wires of generated layouts with nets of up to six pins cuts the wires at their
// joints before it tightens them, so every net still joins its pins (`taut check`'s
// connectivity), and with --clearance the whole check passes. Taken as sketches (each line
// tightened whole), a branch that ended on another wire's segment was left behind: seeds 26, 32
// and 35 failed the check so, with and without the flag. Then octilinear layouts with sloped
// blockages, tightened with --clearance in the scaled plane.
TEST(Tighten, RoutedTreesStayJoined) {
  const std::string dir = temp_dir("tighten_trees");
  // (under the sanitizers, where each taut run costs seconds, one layout of each kind)
  for (const int seed : kSanitized ? std::vector<int>{26} : std::vector<int>{26, 32, 35, 11, 16}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::string in = dir + "/l" + std::to_string(seed) + ".xml", routed = dir + "/r" + std::to_string(seed) + ".xml";
    ASSERT_EQ(run_taut({"gen", seed % 2 ? "rects" : "maze", "-o", in, "--size", "600", "--nets", "12", "--pins", "2-6",
                        "--width", "10", "--spacing", "10", "--seed", std::to_string(seed)})
                  .status,
              0);
    ASSERT_EQ(run_taut({"route", in, "-q", "-o", routed}).status, 0);
    for (const bool clearance : {false, true}) {
      SCOPED_TRACE(clearance ? "--clearance" : "plain");
      std::vector<std::string> args{"tighten", routed, "-q", "-o", dir + "/t.xml", "--stats", dir + "/t.json"};
      if (clearance) args.push_back("--clearance");
      if (seed == 26) args.push_back("--min-link");
      const auto t = run_taut(args);
      ASSERT_EQ(t.status, 0) << t.err;
      const auto chk = run_taut({"check", dir + "/t.xml", "--json"});
      const nlohmann::json cj = nlohmann::json::parse(chk.out)["routes_check"];
      EXPECT_EQ(cj["connectivity"], "ok") << chk.err;
      EXPECT_EQ(cj["free_space"], "ok") << chk.err;
      if (clearance) {
        EXPECT_EQ(chk.status, 0) << chk.err;
      }
      // the statistics are of the wires written: their length, and one minimum-link path per wire
      io::ReadResult out = io::read_layout(dir + "/t.xml");
      ASSERT_TRUE(out.layout && out.layout->routes);
      const auto j = nlohmann::json::parse(read_text(dir + "/t.json"))["tighten"]["nets"];
      ASSERT_EQ(j.size(), out.layout->routes->routes.size());
      for (std::size_t i = 0; i < j.size(); ++i) {
        const io::Route& r = out.layout->routes->routes[i];
        std::vector<Path> wires;
        for (const io::Wire& w : r.wires) wires.push_back(w.points);
        EXPECT_EQ(j[i]["length_after"].get<double>(), std::stod(io::format_total_length(wires))) << r.net;
        if (seed == 26) {
          EXPECT_EQ(j[i]["min_link_wires"].size(), wires.size()) << r.net;
        }
      }
    }
  }
  // sloped blockages (octilinear): the scaled plane is used there too (not exact, so only a
  // result the check passes is taken); seed 21's file failed the check before (a tree's branch)
  int scaled = 0;
  for (const int seed : kSanitized ? std::vector<int>{21, 15} : std::vector<int>{21, 9, 15}) {
    SCOPED_TRACE("polygons seed " + std::to_string(seed));
    const std::string in = dir + "/p" + std::to_string(seed) + ".xml", routed = dir + "/pr" + std::to_string(seed) + ".xml";
    ASSERT_EQ(run_taut({"gen", "polygons", "-o", in, "--size", "800", "--nets", "20", "--pins", "2-4", "--width", "10",
                        "--spacing", "10", "--seed", std::to_string(seed)})
                  .status,
              0);
    ASSERT_EQ(run_taut({"route", in, "-q", "--orientations", "octilinear", "-o", routed}).status, 0);
    const auto t = run_taut({"tighten", routed, "--clearance", "--orientations", "octilinear", "-o", dir + "/t.xml",
                             "--stats", dir + "/t.json"});
    ASSERT_EQ(t.status, 0) << t.err;
    // seed 15: a routed wire at exactly the clearance of a sloped blockage where the union rounds
    // a crossing; both planes refuse it, but it passes taut check's Euclidean measure, so it is
    // written as it is (TIGHTEN-0013, since 2026-12-05; TIGHTEN-0001, exit 2, before)
    EXPECT_EQ(t.err.find("TIGHTEN-0013") != std::string::npos, seed == 15) << t.err;
    EXPECT_EQ(t.err.find("TIGHTEN-0001"), std::string::npos) << t.err;
    scaled += nlohmann::json::parse(read_text(dir + "/t.json"))["tighten"]["together"]["scale"].get<int>() > 1;
    const auto chk = run_taut({"check", dir + "/t.xml"});
    EXPECT_EQ(chk.status, 0) << chk.err;
  }
  EXPECT_EQ(scaled, kSanitized ? 1 : 2);
}

// Together with the clearance (a review's cases): wind.xml's spiral, whose sketch and taut wire run
// along themselves (twice round the core), stays one wire from pin to pin in its class, and every
// net passes taut check, in all three orientations and through route --tighten (the guard ring is
// routed by the net router as its tightened loop); the first round does not depend on the order of
// the nets (B's wire is the same with B first); rules too large for the coordinates are refused.
TEST(Tighten, TogetherReviewCases) {
  const std::string dir = temp_dir("tighten_together_review");
  const std::string wind = kDesigns + "wind.xml";
  io::ReadResult in = io::read_layout(wind);
  ASSERT_TRUE(in.layout);
  const geom::NormalizedObstacles norm = normalized_for(wind);
  const oracle::HomotopyWords h(norm.domain, norm.obstacles);
  const io::Net* spiral = nullptr;
  for (const io::Net& n : in.layout->nets)
    if (n.name == "spiral") spiral = &n;
  ASSERT_NE(spiral, nullptr);
  for (const std::string o : {"any", "rectilinear", "octilinear"}) {
    SCOPED_TRACE(o);
    const auto t = run_taut({"tighten", wind, "--clearance", "--orientations", o, "-q", "-o", dir + "/t.xml"});
    ASSERT_EQ(t.status, 0) << t.err;
    EXPECT_EQ(run_taut({"check", dir + "/t.xml", "-q"}).status, 0);
    const std::vector<Path> w = wires_of(dir + "/t.xml", "spiral");
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].front(), spiral->sketch->points.front());
    EXPECT_EQ(w[0].back(), spiral->sketch->points.back());
    EXPECT_EQ(h.word(w[0]), h.word(spiral->sketch->points));
  }
  const auto routed = run_taut({"route", wind, "--tighten", "--orientations", "octilinear", "-o", dir + "/r.xml"});
  EXPECT_EQ(routed.status, 0) << routed.err;
  EXPECT_EQ(run_taut({"check", dir + "/r.xml", "-q"}).status, 0);
  const std::vector<Path> rs = wires_of(dir + "/r.xml", "spiral");
  ASSERT_EQ(rs.size(), 1u);
  EXPECT_EQ(h.word(rs[0]), h.word(spiral->sketch->points));
  // order
  const std::string a = "  <net name=\"A\"><pin name=\"p\" x=\"100\" y=\"500\"/><pin name=\"q\" x=\"900\" y=\"500\"/>\n"
                        "    <sketch points=\"100,500 100,900 900,900 900,500\"/></net>\n";
  const std::string b = "  <net name=\"B\"><pin name=\"p\" x=\"500\" y=\"950\"/><pin name=\"q\" x=\"500\" y=\"50\"/>\n"
                        "    <sketch points=\"500,950 50,950 50,50 500,50\"/></net>\n";
  const std::string head = "  <boundary x0=\"0\" y0=\"0\" x1=\"1000\" y1=\"1000\"/>\n"
                           "  <rules wire-width=\"10\" spacing=\"10\" orientations=\"any\"/>\n"
                           "  <blockage id=\"b\"><rect x0=\"600\" y0=\"200\" x1=\"700\" y1=\"300\"/></blockage>\n";
  ASSERT_EQ(run_taut({"tighten", layout_file("tighten_order_ab", head + a + b), "--clearance", "-q", "-o", dir + "/ab.xml"}).status, 0);
  ASSERT_EQ(run_taut({"tighten", layout_file("tighten_order_ba", head + b + a), "--clearance", "-q", "-o", dir + "/ba.xml"}).status, 0);
  EXPECT_EQ(wires_of(dir + "/ab.xml", "B"), wires_of(dir + "/ba.xml", "B"));
  EXPECT_EQ(wires_of(dir + "/ab.xml", "B"), (std::vector<Path>{{{500, 950}, {80, 520}, {80, 480}, {500, 50}}}));
  // rules whose w + s passes the coordinate limit
  const std::string huge = "  <rules wire-width=\"1000000000\" spacing=\"500000000\" orientations=\"any\"/>\n" + a;
  write_text(dir + "/h.xml", "old");
  const auto refused = run_taut({"tighten", layout_file("tighten_huge_rules", huge), "--clearance", "-o", dir + "/h.xml"});
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find("[TIGHTEN-0007]"), std::string::npos) << refused.err;
  EXPECT_EQ(read_text(dir + "/h.xml"), "old");
}

// Two sloped triangles leave the free segment (0,0)-(3,1) with no lattice staircase (the
// corridor is 2/3 wide): rectilinear output fails for that net, `any` writes the segment.
TEST(Tighten, NoLatticeStaircaseInTheClassIsAFailedNet) {
  const std::string dir = temp_dir("tighten_pinch");
  const std::string file = layout_file("tighten_staircase",
                                       "  <boundary x0=\"-3\" y0=\"-3\" x1=\"6\" y1=\"4\"/>\n"
                                       "  <blockage id=\"a\"><polygon points=\"-1,0 2,1 -1,1\"/></blockage>\n"
                                       "  <blockage id=\"b\"><polygon points=\"1,0 4,0 4,1\"/></blockage>\n"
                                       "  <net name=\"n\"><pin name=\"p\" x=\"0\" y=\"0\"/><pin name=\"q\" x=\"3\" y=\"1\"/>\n"
                                       "    <sketch points=\"0,0 3,1\"/></net>\n");
  auto run = run_taut({"tighten", file, "-o", dir + "/t.xml", "--orientations", "rectilinear"});
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_NE(run.err.find("[TIGHTEN-0004] net \"n\""), std::string::npos) << run.err;
  io::ReadResult rr = io::read_layout(dir + "/t.xml");
  ASSERT_TRUE(rr.layout && rr.layout->routes);
  EXPECT_EQ(rr.layout->routes->routes.at(0).status, "failed");
  run = run_taut({"tighten", file, "-o", dir + "/t.xml", "--orientations", "any"});
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(wires_of(dir + "/t.xml", "n"), (std::vector<Path>{{{0, 0}, {3, 1}}}));
  // routed wires: the first has no staircase, the second crosses blockage b; the second's error
  // is still found (exit 2, nothing written)
  const std::string routed = layout_file(
      "tighten_staircase_routed",
      "  <boundary x0=\"-3\" y0=\"-3\" x1=\"6\" y1=\"4\"/>\n"
      "  <blockage id=\"a\"><polygon points=\"-1,0 2,1 -1,1\"/></blockage>\n"
      "  <blockage id=\"b\"><polygon points=\"1,0 4,0 4,1\"/></blockage>\n"
      "  <net name=\"n\"><pin name=\"p\" x=\"0\" y=\"0\"/><pin name=\"q\" x=\"3\" y=\"1\"/></net>\n"
      "  <routes><route net=\"n\" status=\"routed\" length=\"8.162\" bends=\"0\">\n"
      "    <wire points=\"0,0 3,1\"/><wire points=\"3,-2 3,3\"/></route></routes>\n");
  write_text(dir + "/r.xml", "old");
  run = run_taut({"tighten", routed, "-o", dir + "/r.xml", "--orientations", "rectilinear"});
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_NE(run.err.find("[TIGHTEN-0001] net \"n\": the wire's segment 1 (3,-2 to 3,3)"), std::string::npos) << run.err;
  EXPECT_EQ(read_text(dir + "/r.xml"), "old");
}

// A routed wire far outside the boundary (a hand-edited file): refused with TIGHTEN-0001 at its
// line, exit 2, nothing written, with --clearance too, with and without <rules>. With
// --clearance the tightener's window round the wire, clipped to the boundary, was empty and
// reached the triangulation: exit 3, an internal error (found by fuzzing, 2026-12-06); a wire
// outside by less than the window's margin was refused as it should be.
TEST(Tighten, AWireFarOutsideTheBoundaryIsRefused) {
  const std::string dir = temp_dir("tighten_wire_outside_out");
  for (const std::string rules : {"", "  <rules wire-width=\"4\" spacing=\"2\"/>\n"})
    for (const std::string y : {"1050", "1500", "900000"}) {
      const std::string file = layout_file(
          "tighten_wire_outside",
          "  <boundary x0=\"0\" y0=\"0\" x1=\"1000\" y1=\"1000\"/>\n" + rules +
              "  <net name=\"a\"><pin name=\"l\" x=\"100\" y=\"500\"/><pin name=\"r\" x=\"900\" y=\"500\"/></net>\n"
              "  <routes><route net=\"a\" status=\"routed\" length=\"800\" bends=\"0\">\n"
              "    <wire points=\"100," + y + " 900," + y + "\"/></route></routes>\n");
      const int line = rules.empty() ? 5 : 6;
      for (const bool clearance : {false, true}) {
        if (!clearance && !rules.empty()) continue;  // (TIGHTEN-0006: the rules need --clearance)
        write_text(dir + "/t.xml", "old");
        std::vector<std::string> cmd{"tighten", file, "-o", dir + "/t.xml"};
        if (clearance) cmd.push_back("--clearance");
        const auto run = run_taut(cmd);
        const std::string what = "y " + y + (clearance ? " --clearance" : "") + (rules.empty() ? "" : " with rules");
        EXPECT_EQ(run.status, 2) << what << run.err;
        EXPECT_NE(run.err.find(":" + std::to_string(line) + ": error: [TIGHTEN-0001] net \"a\": the wire starts at 100," + y +
                               ", which lies outside the boundary"),
                  std::string::npos)
            << what << run.err;
        EXPECT_EQ(read_text(dir + "/t.xml"), "old") << what;
      }
    }
}

// c:45,135 steps keep the parity of x + y: a net whose pins differ in it has no wire in those
// directions (TIGHTEN-0004, failed, exit 1, with the reason), while c:0,45,90 writes it; the same
// layout with the set in <rules> is tightened in it (no TIGHTEN-0003).
TEST(Tighten, DiagonalSetKeepsParity) {
  const std::string dir = temp_dir("tighten_parity");
  const std::string body =
      "  <boundary x0=\"0\" y0=\"0\" x1=\"100\" y1=\"100\"/>\n"
      "  <blockage id=\"a\"><rect x0=\"40\" y0=\"40\" x1=\"60\" y1=\"60\"/></blockage>\n"
      "  <net name=\"even\"><pin name=\"p\" x=\"10\" y=\"50\"/><pin name=\"q\" x=\"90\" y=\"50\"/>\n"
      "    <sketch points=\"10,50 50,90 90,50\"/></net>\n"
      "  <net name=\"odd\"><pin name=\"p\" x=\"10\" y=\"20\"/><pin name=\"q\" x=\"91\" y=\"20\"/>\n"
      "    <sketch points=\"10,20 91,20\"/></net>\n";
  const std::string file = layout_file("tighten_parity_in", body);
  const auto run = run_taut({"tighten", file, "-o", dir + "/t.xml", "--orientations", "c:45,135"});
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_NE(run.err.find("[TIGHTEN-0004] net \"odd\": no c:45,135 wire with integer vertices"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("differ in the parity of x + y"), std::string::npos) << run.err;
  EXPECT_TRUE(wires_of(dir + "/t.xml", "odd").empty());
  const std::vector<Path> even = wires_of(dir + "/t.xml", "even");
  ASSERT_EQ(even.size(), 1u);
  // round the top of the square at 45 degrees: up from (10,50) to the corner's diagonal, across, down
  const geom::LatticeDirections diag = *geom::LatticeDirections::parse("c:45,135");
  for (std::size_t i = 1; i < even[0].size(); ++i)
    EXPECT_TRUE(diag.along(std::int64_t{even[0][i].x} - even[0][i - 1].x, std::int64_t{even[0][i].y} - even[0][i - 1].y));
  EXPECT_EQ(diag.length2(even[0]), diag.length2(Path{{10, 50}, {40, 60}, {60, 60}, {90, 50}}));
  const auto mixed = run_taut({"tighten", file, "-o", dir + "/m.xml", "--orientations", "c:0,45,90"});
  EXPECT_EQ(mixed.status, 0) << mixed.err;
  EXPECT_EQ(wires_of(dir + "/m.xml", "odd"), (std::vector<Path>{{{10, 20}, {91, 20}}}));
  // both diagonals and the horizontal: the parity binds only between the diagonals (review)
  const auto three = run_taut({"tighten", file, "-o", dir + "/3.xml", "--orientations", "c:0,45,135"});
  EXPECT_EQ(three.status, 0) << three.err;
  EXPECT_EQ(wires_of(dir + "/3.xml", "odd"), (std::vector<Path>{{{10, 20}, {91, 20}}}));
  // from <rules>
  const std::string rules = layout_file("tighten_parity_rules", "  <rules orientations=\"c:135,45\"/>\n" + body);
  const auto r = run_taut({"tighten", rules, "-o", dir + "/r.xml"});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.find("TIGHTEN-0003"), std::string::npos) << r.err;
  EXPECT_EQ(wires_of(dir + "/r.xml", "even"), even);
  io::ReadResult rr = io::read_layout(dir + "/r.xml");
  ASSERT_TRUE(rr.layout && rr.layout->routes);
  EXPECT_EQ(rr.layout->routes->orientations, "c:45,135");
}

TEST(Tighten, ContractibleLoopIsAFailedNet) {
  const std::string dir = temp_dir("tighten_contractible");
  const std::string file = layout_file("tighten_contractible_in",
                                       "  <rules orientations=\"any\"/>\n"
                                       "  <blockage id=\"a\"><rect x0=\"40\" y0=\"40\" x1=\"60\" y1=\"60\"/></blockage>\n"
                                       "  <net name=\"ring\"><sketch points=\"10,10 30,10 30,30 10,10\"/></net>\n"
                                       "  <net name=\"guard\"><sketch points=\"10,50 50,10 90,50 50,90 10,50\"/></net>\n");
  const auto run = run_taut({"tighten", file, "-o", dir + "/t.xml"});
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_NE(run.err.find("warning: [TIGHTEN-0005] net \"ring\""), std::string::npos) << run.err;
  // the square's boundary, counter-clockwise, from whichever corner
  auto ring = [](const std::vector<Path>& w) {
    if (w.size() != 1 || w[0].size() < 2 || w[0].front() != w[0].back()) return Path{};
    Path p(w[0].begin(), w[0].end() - 1);
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    return p;
  };
  const Path square{{40, 40}, {60, 40}, {60, 60}, {40, 60}};
  EXPECT_EQ(ring(wires_of(dir + "/t.xml", "guard")), square);
  // route --tighten gives the guard ring its loop too
  const auto routed = run_taut({"route", file, "--orientations", "rectilinear", "--tighten", "-o", dir + "/r.xml"});
  EXPECT_EQ(routed.status, 1) << routed.err;  // "ring" is contractible
  EXPECT_EQ(ring(wires_of(dir + "/r.xml", "guard")), square);
  EXPECT_EQ(routed.err.find("ROUTE-0006"), std::string::npos) << routed.err;  // the loop net is not "unrouted"
  // --min-link: the failed net has no count (null, not 0), the guard ring its triangle
  EXPECT_EQ(run_taut({"tighten", file, "-o", dir + "/m.xml", "--min-link", "--stats", dir + "/m.json"}).status, 1);
  const auto nets = nlohmann::json::parse(read_text(dir + "/m.json"))["tighten"]["nets"];
  ASSERT_EQ(nets.size(), 2u);
  EXPECT_TRUE(nets[0]["min_links"].is_null()) << nets[0];
  EXPECT_TRUE(nets[0]["min_link_wires"].empty()) << nets[0];
  EXPECT_EQ(nets[1]["min_links"], 3) << nets[1];
}

// A two-pin net's sketch that misses a pin (found by a seeded mutation of designs/wind.xml:
// net "diag"'s pin "bottom" moved from 38000,9000 to 2000,9000, the sketch still ending at the
// old place). Before 2026-12-05 `tighten` wrote the tightened sketch as the net's routed wire and
// `route --tighten` followed it: both files failed taut check (CHECK-0004, the pins not joined).
// Now `tighten` writes the net as failed (TIGHTEN-0012, exit 1) and `route --tighten` routes it
// without the sketch (ROUTE-0020, not ROUTE-0007); both files pass the check. A net with such a
// sketch and routed wires gets its routed wires tightened instead. A sketch on a net
// of three pins is ignored, as LAYOUT-0009 says (it was tightened and written as routed too).
TEST(Tighten, SketchOffItsPinsIsNotTaken) {
  const std::string dir = temp_dir("tighten_off_pins");
  std::string text = read_text(kDesigns + "wind.xml");
  const std::string pin = "<pin name=\"bottom\" x=\"38000\" y=\"9000\"/>";
  const std::size_t at = text.find(pin);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, pin.size(), "<pin name=\"bottom\" x=\"2000\" y=\"9000\"/>");
  const std::string file = dir + "/in.xml";
  write_text(file, text);
  // the line of diag's <sketch>
  const std::size_t sk = text.find("<sketch", text.find("<net name=\"diag\""));
  ASSERT_NE(sk, std::string::npos);
  const std::string line = std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(sk), '\n'));
  const auto t = run_taut({"tighten", file, "--clearance", "-o", dir + "/t.xml"});
  EXPECT_EQ(t.status, 1) << t.err;
  EXPECT_NE(t.err.find(file + ":" + line + ": warning: [TIGHTEN-0012] net \"diag\": its <sketch> ends at (38000,9000), not on the "
                       "second pin \"bottom\""),
            std::string::npos)
      << t.err;
  io::ReadResult rt = io::read_layout(dir + "/t.xml");
  ASSERT_TRUE(rt.layout && rt.layout->routes);
  int failed = 0, routed = 0;
  for (const io::Route& r : rt.layout->routes->routes) {
    failed += r.status == "failed" && r.net == "diag" && r.wires.empty();
    routed += r.status == "routed";
  }
  EXPECT_EQ(failed, 1);
  EXPECT_EQ(routed, 5);
  const auto ct = run_taut({"check", dir + "/t.xml", "-q"});
  EXPECT_EQ(ct.status, 0) << ct.err;
  const auto r = run_taut({"route", file, "--tighten", "--orientations", "rectilinear", "-o", dir + "/r.xml"});
  EXPECT_LE(r.status, 1) << r.err;
  EXPECT_NE(r.err.find(file + ":" + line + ": warning: [ROUTE-0020] net \"diag\""), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("ROUTE-0007"), std::string::npos) << r.err;
  const auto cr = run_taut({"check", dir + "/r.xml", "-q"});
  EXPECT_EQ(cr.status, 0) << cr.err;
  // a routed net whose sketch misses its pin: its routed wires are tightened instead (before
  // 2026-12-05 the net was failed and its wires dropped)
  {
    const std::string routed = layout_file(
        "tighten_off_pins_routed",
        "  <blockage id=\"a\"><rect x0=\"40\" y0=\"40\" x1=\"60\" y1=\"60\"/></blockage>\n"
        "  <net name=\"t\"><pin name=\"p\" x=\"10\" y=\"10\"/><pin name=\"q\" x=\"90\" y=\"90\"/>"
        "<sketch points=\"10,10 10,80 80,80\"/></net>\n"
        "  <routes><route net=\"t\" status=\"routed\" length=\"160\" bends=\"3\">"
        "<wire points=\"10,10 10,70 30,70 30,90 90,90\"/></route></routes>\n");
    const auto rt = run_taut({"tighten", routed, "-o", dir + "/rt.xml"});
    EXPECT_EQ(rt.status, 0) << rt.err;
    EXPECT_NE(rt.err.find("warning: [TIGHTEN-0012] net \"t\": its <sketch> ends at (80,80), not on the second pin \"q\": "
                          "tightened, it would join nothing; its routed wires are tightened instead"),
              std::string::npos)
        << rt.err;
    io::ReadResult rr = io::read_layout(dir + "/rt.xml");
    ASSERT_TRUE(rr.layout && rr.layout->routes && rr.layout->routes->routes.size() == 1u) << rt.err;
    const io::Route& x = rr.layout->routes->routes[0];
    EXPECT_EQ(x.status, "routed");
    EXPECT_EQ(x.bends, std::optional<std::int64_t>(1));  // from 3: pulled taut (as long: an L1 staircase)
    EXPECT_EQ(wires_of(dir + "/rt.xml", "t"), (std::vector<Path>{{{10, 10}, {10, 90}, {90, 90}}}));
    EXPECT_EQ(run_taut({"check", dir + "/rt.xml", "-q"}).status, 0);
  }
  // the sketch drawn from the second pin to the first joins them too: taken (LAYOUT-0008 warns of the order)
  {
    std::string rev = read_text(kDesigns + "wind.xml");
    const std::size_t s0 = rev.find("points=\"", rev.find("<sketch", rev.find("<net name=\"diag\""))) + 8;
    const std::size_t s1 = rev.find('"', s0);
    std::vector<std::string> pts;
    std::stringstream ss(rev.substr(s0, s1 - s0));
    for (std::string p; ss >> p;) pts.insert(pts.begin(), p);
    std::string joined_pts;
    for (const auto& p : pts) joined_pts += (joined_pts.empty() ? "" : " ") + p;
    rev.replace(s0, s1 - s0, joined_pts);
    write_text(dir + "/rev.xml", rev);
    const auto tr = run_taut({"tighten", dir + "/rev.xml", "--clearance", "-o", dir + "/rev.t.xml"});
    EXPECT_EQ(tr.status, 0) << tr.err;
    EXPECT_EQ(tr.err.find("TIGHTEN-0012"), std::string::npos) << tr.err;
    // one warning for the reversed sketch, not one for each end
    const std::size_t w = tr.err.find("[LAYOUT-0008] net \"diag\" sketch: runs from the second pin");
    EXPECT_NE(w, std::string::npos) << tr.err;
    EXPECT_EQ(tr.err.find("LAYOUT-0008", tr.err.find('\n', w)), std::string::npos) << tr.err;
    EXPECT_EQ(run_taut({"check", dir + "/rev.t.xml", "-q"}).status, 0);
  }
  // three pins and a sketch, no routed wire: nothing to tighten
  const std::string three = layout_file("tighten_off_pins_three",
                                        "  <blockage id=\"a\"><rect x0=\"40\" y0=\"40\" x1=\"60\" y1=\"60\"/></blockage>\n"
                                        "  <net name=\"t\"><pin name=\"p\" x=\"10\" y=\"10\"/><pin name=\"q\" x=\"90\" y=\"90\"/>"
                                        "<pin name=\"r\" x=\"90\" y=\"10\"/><sketch points=\"10,10 10,90 90,90\"/></net>\n");
  const auto t3 = run_taut({"tighten", three, "-o", dir + "/t3.xml"});
  EXPECT_EQ(t3.status, 1) << t3.err;
  EXPECT_NE(t3.err.find("warning: [TIGHTEN-0002] net \"t\": nothing to tighten: the net has no routed wire, and its <sketch> is ignored"),
            std::string::npos)
      << t3.err;
}

// Routed wires in directions the output lacks, by default: `tighten` without --orientations on
// a file routed octilinear over rules that say rectilinear (FORMAT.md's default) writes
// rectilinear staircases, and since 2026-12-05 says so (TIGHTEN-0014, naming the nets and the
// option that keeps their directions); with --orientations octilinear it is silent.
TEST(Tighten, DefaultOrientationsOffTheRoutedWiresAreSaid) {
  const std::string dir = temp_dir("tighten_default_orient");
  ASSERT_EQ(run_taut({"gen", "channel", "-o", dir + "/g.xml", "--size", "100", "--nets", "6", "--seed", "6", "--width", "4",
                      "--spacing", "4"})
                .status,
            0);
  ASSERT_LE(run_taut({"route", dir + "/g.xml", "--orientations", "octilinear", "-q", "-o", dir + "/r.xml"}).status, 1);
  const auto t = run_taut({"tighten", dir + "/r.xml", "-o", dir + "/t.xml"});
  EXPECT_LE(t.status, 1) << t.err;
  EXPECT_NE(t.err.find("warning: [TIGHTEN-0014] 4 nets' routed wires (net \"n0\" and others) run in directions outside "
                       "rectilinear, the output's (from <rules orientations>, rectilinear by default): they are written as "
                       "rectilinear staircases, "
                       "which may be longer; --orientations octilinear keeps their directions"),
            std::string::npos)
      << t.err;
  const auto o = run_taut({"tighten", dir + "/r.xml", "--orientations", "octilinear", "-o", dir + "/o.xml"});
  EXPECT_LE(o.status, 1) << o.err;
  EXPECT_EQ(o.err.find("TIGHTEN-0014"), std::string::npos) << o.err;
}

// Staircases too fine to snap back (found by a seeded search, 2026-12-05): `tighten --clearance`
// tightens first in the net router's scaled plane (K up to 8192), where a gap of exactly the
// clearance is 2 units wide. A sketch up such a vertical gap, to c:45,135 (no vertical), was
// staircased there in zigzags of 2 units: about K x 1,000 links, then unioned into the space;
// the run took minutes and over 20 GB. Such a staircase is now not built (router::
// StaircaseTooFine): the piece is left untightened there, so the layout's units decide, where
// the gap is closed: net "a" is TIGHTEN-0011 (its sketch keeps exactly the clearance), "n" (ends
// of different parity of x + y) TIGHTEN-0004, both written as failed, exit 1. With rectilinear
// output "a" is tightened up the gap.
TEST(Tighten, StaircasesTooFineForTheScaledPlaneAreNotBuilt) {
  const std::string dir = temp_dir("tighten_too_fine");
  const std::string file = layout_file(
      "tighten_too_fine_in",
      "  <boundary x0=\"0\" y0=\"0\" x1=\"4000\" y1=\"4000\"/>\n"
      "  <rules wire-width=\"100\" spacing=\"100\" orientations=\"rectilinear\"/>\n"
      "  <blockage id=\"l\"><rect x0=\"0\" y0=\"1000\" x1=\"1000\" y1=\"3000\"/></blockage>\n"
      "  <blockage id=\"r\"><rect x0=\"1300\" y0=\"1000\" x1=\"2500\" y1=\"3000\"/></blockage>\n"
      "  <net name=\"a\"><pin name=\"s\" x=\"1150\" y=\"400\"/><pin name=\"t\" x=\"1400\" y=\"3800\"/>\n"
      "    <sketch points=\"1150,400 1150,3500 1400,3800\"/></net>\n"
      "  <net name=\"n\"><pin name=\"p\" x=\"3000\" y=\"3500\"/><pin name=\"q\" x=\"3001\" y=\"3500\"/>\n"
      "    <sketch points=\"3000,3500 3001,3500\"/></net>\n");
  const auto t = run_taut({"tighten", file, "--clearance", "--orientations", "c:45,135", "-o", dir + "/t.xml"});
  EXPECT_EQ(t.status, 1) << t.err;
  EXPECT_NE(t.err.find("warning: [TIGHTEN-0011] net \"a\": its sketch could not be tightened"), std::string::npos) << t.err;
  EXPECT_NE(t.err.find("warning: [TIGHTEN-0004] net \"n\""), std::string::npos) << t.err;
  io::ReadResult rr = io::read_layout(dir + "/t.xml");
  ASSERT_TRUE(rr.layout && rr.layout->routes) << t.err;
  for (const io::Route& r : rr.layout->routes->routes) EXPECT_EQ(r.status, "failed") << r.net;
  EXPECT_EQ(run_taut({"check", dir + "/t.xml", "-q"}).status, 0);
  const auto rect = run_taut({"tighten", file, "--clearance", "--orientations", "rectilinear", "-o", dir + "/r.xml"});
  EXPECT_EQ(rect.status, 0) << rect.err;
  EXPECT_EQ(wires_of(dir + "/r.xml", "a"), (std::vector<Path>{{{1150, 400}, {1150, 3800}, {1400, 3800}}}));
}

// Octilinear routes tightened by `taut tighten --clearance` (found by a seeded search over
// `taut gen` layouts routed and tightened, 2026-12-05):
// - into rectilinear (the default without <rules orientations>, or --orientations rectilinear):
//   a diagonal wire the tightener did not shorten was written as it was, under
//   <routes orientations="rectilinear"> (CHECK-0002; channel seed 6, polygons seed 8). A wire
//   outside the output's directions is now always replaced by its tightened form;
// - in octilinear: wires the octilinear router ran diagonally past sloped blockage edges keep the
//   clearance as taut check measures it (Euclidean) but not by the tightener's squares, and were
//   refused with TIGHTEN-0001 (exit 2, nothing written: degenerate seed 11); they are now written
//   as they are (TIGHTEN-0013) and the others tightened round them.
// Every file written passes taut check.
TEST(Tighten, OctilinearRoutesTightened) {
  const std::string dir = temp_dir("tighten_oct_routes");
  struct Case {
    std::vector<std::string> gen;
    std::string to;  // --orientations of tighten
    bool as_given;   // a TIGHTEN-0013 expected
  };
  const std::vector<Case> cases = {
      {{"channel", "--size", "100", "--nets", "3", "--pins", "2", "--width", "0", "--spacing", "10", "--seed", "6"}, "", false},
      {{"polygons", "--size", "40", "--nets", "3", "--pins", "3-6", "--width", "3", "--spacing", "10", "--seed", "8"},
       "rectilinear", false},
      {{"degenerate", "--size", "300", "--nets", "15", "--pins", "2", "--width", "10", "--spacing", "10", "--seed", "11"},
       "", true},
  };
  int k = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.gen[0] + " seed " + c.gen.back());
    const std::string in = dir + "/g" + std::to_string(k) + ".xml", routed = dir + "/r" + std::to_string(k) + ".xml",
                      out = dir + "/t" + std::to_string(k) + ".xml";
    ++k;
    std::vector<std::string> gen{"gen"};
    gen.insert(gen.end(), c.gen.begin(), c.gen.end());
    gen.insert(gen.end(), {"-o", in});
    ASSERT_EQ(run_taut(gen).status, 0);
    const auto r = run_taut({"route", in, "-q", "--orientations", "octilinear", "-o", routed});
    ASSERT_LE(r.status, 1) << r.err;
    // the routed input has diagonal segments, and how many nets it routes
    auto routed_nets = [](const std::string& file, bool* diagonal) {
      io::ReadResult rr = io::read_layout(file);
      int n = 0;
      if (!rr.layout || !rr.layout->routes) return -1;
      for (const io::Route& x : rr.layout->routes->routes) {
        n += x.status == "routed";
        for (const io::Wire& w : x.wires)
          for (std::size_t j = 0; j + 1 < w.points.size() && diagonal; ++j)
            *diagonal = *diagonal || (w.points[j].x != w.points[j + 1].x && w.points[j].y != w.points[j + 1].y);
      }
      return n;
    };
    bool diagonal = false;
    const int routed_in = routed_nets(routed, &diagonal);
    ASSERT_TRUE(diagonal);
    std::vector<std::string> args{"tighten", routed, "--clearance", "-o", out};
    if (!c.to.empty()) args.insert(args.end(), {"--orientations", c.to});
    const auto t = run_taut(args);
    ASSERT_LE(t.status, 1) << t.err;
    EXPECT_EQ(t.err.find("TIGHTEN-0013") != std::string::npos, c.as_given) << t.err;
    EXPECT_EQ(t.err.find("TIGHTEN-0010"), std::string::npos) << t.err;  // every other net tightened into rectilinear
    int failed_as_given = 0;
    for (std::size_t at = t.err.find("TIGHTEN-0013"); at != std::string::npos; at = t.err.find("TIGHTEN-0013", at + 1))
      ++failed_as_given;
    EXPECT_EQ(routed_nets(out, nullptr), routed_in - failed_as_given) << t.err;
    const auto chk = run_taut({"check", out, "-q"});
    EXPECT_EQ(chk.status, 0) << chk.err;
  }
}

// A guard ring with a pin (README's "Loops": the loop belongs to no pin, and the pins are not
// joined to it) beside a net with two pins, with rules: route --tighten writes the ring round both
// blockages, and taut check accepts it (since 2026-12-05: it reported CHECK-0005, a wire touching
// none of the net's pins, so route's check of the exact gaps failed too, and the run went again
// with the gaps closed, ROUTE-0019). The ring's loop keeps the gaps open (exact_gaps.scale > 1).
TEST(Tighten, GuardRingWithAPinPassesTheCheck) {
  const std::string dir = temp_dir("tighten_ring_pin");
  const std::string file = layout_file("tighten_ring_pin_in",
                                       "  <boundary x0=\"0\" y0=\"0\" x1=\"2000\" y1=\"2000\"/>\n"
                                       "  <rules wire-width=\"20\" spacing=\"20\"/>\n"
                                       "  <blockage id=\"core\"><rect x0=\"800\" y0=\"800\" x1=\"1200\" y1=\"1200\"/></blockage>\n"
                                       "  <blockage id=\"side\"><rect x0=\"1240\" y0=\"900\" x1=\"1400\" y1=\"1100\"/></blockage>\n"
                                       "  <net name=\"ring\"><pin name=\"a\" x=\"500\" y=\"500\"/>"
                                       "<sketch points=\"500,500 1500,500 1500,1500 500,1500 500,500\"/></net>\n"
                                       "  <net name=\"x\"><pin name=\"a\" x=\"100\" y=\"100\"/><pin name=\"b\" x=\"1900\" y=\"1900\"/></net>\n");
  const auto routed = run_taut({"route", file, "--tighten", "-o", dir + "/r.xml", "--stats", dir + "/r.json"});
  EXPECT_EQ(routed.status, 0) << routed.err;
  EXPECT_EQ(routed.err.find("ROUTE-0019"), std::string::npos) << routed.err;
  EXPECT_GT(nlohmann::json::parse(read_text(dir + "/r.json"))["net_router"]["exact_gaps"]["scale"].get<int>(), 1);
  // round both blockages, at the clearance 10 + 20 = 30 from them (the gap between them, 40, is
  // too narrow for the ring to pass)
  const std::vector<Path> ring = wires_of(dir + "/r.xml", "ring");
  ASSERT_EQ(ring.size(), 1u);
  const Path& w = ring[0];
  ASSERT_GE(w.size(), 5u);
  EXPECT_EQ(w.front(), w.back());
  const auto [lx, hx] = std::minmax_element(w.begin(), w.end(), [](Point a, Point b) { return a.x < b.x; });
  const auto [ly, hy] = std::minmax_element(w.begin(), w.end(), [](Point a, Point b) { return a.y < b.y; });
  EXPECT_EQ(lx->x, 770);
  EXPECT_EQ(hx->x, 1430);
  EXPECT_EQ(ly->y, 770);
  EXPECT_EQ(hy->y, 1230);
  const auto check = run_taut({"check", dir + "/r.xml", "-q"});
  EXPECT_EQ(check.status, 0) << check.out << check.err;
  // the exemption is for closed wires only: the loop net given two pins and, by hand, an open wire
  // that stops short of its second pin is still CHECK-0004, and an open wire touching no pin
  // CHECK-0005
  std::string text = read_text(dir + "/r.xml");
  const std::size_t at = text.find("<wire", text.find("<route net=\"ring\""));
  ASSERT_NE(at, std::string::npos);
  const std::size_t end = text.find("/>", at) + 2;
  std::string pinned = text;
  pinned.replace(at, end - at, "<wire points=\"500,500 500,600\"/>");
  pinned.replace(pinned.find("<pin name=\"a\" x=\"500\" y=\"500\"/>"), 0, "<pin name=\"b\" x=\"500\" y=\"700\"/>");
  write_text(dir + "/short.xml", pinned);
  const auto shorted = run_taut({"check", dir + "/short.xml", "-q"});
  EXPECT_EQ(shorted.status, 1) << shorted.out << shorted.err;
  EXPECT_NE(shorted.err.find("CHECK-0004"), std::string::npos) << shorted.err;
  std::string stray = text;
  stray.replace(at, end - at, "<wire points=\"300,300 300,400\"/>");
  write_text(dir + "/stray.xml", stray);
  const auto strayed = run_taut({"check", dir + "/stray.xml", "-q"});
  EXPECT_EQ(strayed.status, 1) << strayed.out << strayed.err;
  EXPECT_NE(strayed.err.find("CHECK-0005"), std::string::npos) << strayed.err;
}

// The wind design's sketches (a slalom, a spiral wound twice round a block, a loop round a
// triangle, a guard ring round a hexagon, a pinch) tightened into every kind of set at multiples
// of 30 degrees: every net is written, taut check finds every segment within the rounding of the
// set's directions, in free space, joined (its own computation: geom::Root3Directions::fits is
// also recomputed here).
TEST(Tighten, SetsAtMultiplesOf30DegreesOnTheWindDesign) {
  const std::string dir = temp_dir("tighten_thirty");
  // with --clearance (since 2026-12-07) every net together, the clearance of wind.xml's <rules>
  // kept (the whole check passes: clearance from blockages and between nets, no shorts)
  for (const bool clearance : {false, true})
  for (const std::string set : {"c:0,60,120", "c:30,90,150", "c:0,30,60,90,120,150", "c:0,60", "c:0,90,150"}) {
    SCOPED_TRACE(set + (clearance ? " --clearance" : ""));
    const std::string out = dir + "/w.xml";
    std::vector<std::string> cmd{"tighten", kDesigns + "wind.xml", "-o", out, "--orientations", set, "--stats", dir + "/s.json"};
    if (clearance) cmd.push_back("--clearance");
    const auto run = run_taut(cmd);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(read_text(out).find("orientations=\"" + set + "\""), std::string::npos);
    const auto checked = run_taut({"check", out, "--json"});
    const auto j = nlohmann::json::parse(checked.out);
    EXPECT_EQ(j["routes_check"]["orientations"], "ok") << checked.err;
    EXPECT_EQ(j["routes_check"]["free_space"], "ok") << checked.err;
    EXPECT_EQ(j["routes_check"]["connectivity"], "ok") << checked.err;
    if (clearance) {
      EXPECT_EQ(checked.status, 0) << checked.out;
      EXPECT_EQ(j["routes_check"]["clearance"], "ok") << checked.out;
      EXPECT_EQ(j["routes_check"]["shorts"], "ok") << checked.out;
      EXPECT_TRUE(nlohmann::json::parse(read_text(dir + "/s.json"))["tighten"].contains("together"));
    }
    const auto fits = geom::Root3Directions::parse(set);
    const auto layout = io::read_layout(out);
    ASSERT_TRUE(layout.layout && layout.layout->routes);
    int routed = 0;
    for (const io::Route& r : layout.layout->routes->routes) {
      EXPECT_EQ(r.status, "routed") << r.net << ": " << r.reason.value_or("");
      routed += r.status == "routed";
      for (const io::Wire& w : r.wires)
        for (std::size_t i = 1; i < w.points.size(); ++i)
          EXPECT_TRUE(fits->fits(std::int64_t{w.points[i].x} - w.points[i - 1].x, std::int64_t{w.points[i].y} - w.points[i - 1].y))
              << r.net << " segment " << i;
    }
    EXPECT_EQ(routed, 6);
    EXPECT_EQ(nlohmann::json::parse(read_text(dir + "/s.json"))["tighten"]["nets"].size(), 6u);
  }
}

// A c: set in <rules> is the default output: one at multiples of 30 degrees is written in it
// (since 2026-12-07, and, later that day, with --clearance and --min-link; before, at any angle
// with TIGHTEN-0003), and since the twenty-first session (the same day) one at other angles, each
// direction at its integer step (geom::Root3Directions::parse_any); a direction no step realizes
// still gets TIGHTEN-0003.
TEST(Tighten, CSetInTheRulesIsTheOutputsDirections) {
  const std::string dir = temp_dir("tighten_cset");
  const std::string body = "  <rules orientations=\"c:0,60,120\"/>\n"
                           "  <blockage id=\"a\"><rect x0=\"40\" y0=\"40\" x1=\"60\" y1=\"60\"/></blockage>\n"
                           "  <net name=\"n\"><pin name=\"p\" x=\"10\" y=\"50\"/><pin name=\"q\" x=\"90\" y=\"50\"/>\n"
                           "    <sketch points=\"10,50 50,90 90,50\"/></net>\n";
  const std::string file = layout_file("tighten_cset_in", body);
  const auto run = run_taut({"tighten", file, "-o", dir + "/t.xml"});
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err.find("TIGHTEN-0003"), std::string::npos) << run.err;
  EXPECT_NE(read_text(dir + "/t.xml").find("orientations=\"c:0,60,120\""), std::string::npos);
  expect_routes_check_ok(dir + "/t.xml");
  // other angles: in the set, every segment at its steps within the rounding (taut check), the
  // minimum-link path's bends rational (integer steps)
  std::string ten = body;
  ten.replace(ten.find("c:0,60,120"), 10, "c:0,10,100");
  const auto t10 = run_taut({"tighten", layout_file("tighten_cset_ten", ten), "-o", dir + "/t10.xml", "--min-link",
                             "--stats", dir + "/t10.json"});
  EXPECT_EQ(t10.status, 0) << t10.err;
  EXPECT_EQ(t10.err.find("TIGHTEN-0003"), std::string::npos) << t10.err;
  EXPECT_NE(t10.err.find("c:0,10,100: 10 degrees as the step ("), std::string::npos) << t10.err;
  EXPECT_NE(read_text(dir + "/t10.xml").find("orientations=\"c:0,10,100\""), std::string::npos);
  {
    expect_routes_check_ok(dir + "/t10.xml");
    const auto w10 = wires_of(dir + "/t10.xml", "n");
    ASSERT_EQ(w10.size(), 1u);
    EXPECT_GT(w10[0].size(), 4u);  // not the taut wire: 10,50 40,60 is at 18.4 degrees, a staircase of 10 and 100
    const auto j = nlohmann::json::parse(read_text(dir + "/t10.json"))["tighten"];
    EXPECT_EQ(j["orientation_steps"].size(), 2u) << j.dump();  // 10 and 100 degrees
    ASSERT_TRUE(j["nets"][0].contains("oriented_min_link_wires")) << j.dump();
    for (const auto& pt : j["nets"][0]["oriented_min_link_wires"][0])
      for (const auto& c : pt) EXPECT_EQ(c.get<std::string>().find("sqrt3"), std::string::npos) << j.dump();
  }
  // a direction no integer step of at most 2^24 realizes within 2^-36 radians: at any angle, said
  std::string near = body;
  near.replace(near.find("c:0,60,120"), 10, "c:0,45.000001");
  const auto tn = run_taut({"tighten", layout_file("tighten_cset_near", near), "-o", dir + "/tn.xml"});
  EXPECT_EQ(tn.status, 0) << tn.err;
  EXPECT_NE(tn.err.find("warning: [TIGHTEN-0003]"), std::string::npos) << tn.err;
  EXPECT_NE(tn.err.find("no integer step of at most 2^24 lies within 2^-36 radians of a direction"), std::string::npos)
      << tn.err;
  EXPECT_EQ(wires_of(dir + "/tn.xml", "n"), (std::vector<Path>{{{10, 50}, {40, 60}, {60, 60}, {90, 50}}}));
  // with --clearance: in the set too (no clearance in these rules: the same wire)
  const auto tc = run_taut({"tighten", file, "-o", dir + "/tc.xml", "--clearance"});
  EXPECT_EQ(tc.status, 0) << tc.err;
  EXPECT_EQ(tc.err.find("TIGHTEN-0003"), std::string::npos) << tc.err;
  EXPECT_EQ(wires_of(dir + "/tc.xml", "n"), wires_of(dir + "/t.xml", "n"));
  // with --min-link: in the set too, and (since 2026-12-07, the same day; before, TIGHTEN-0015
  // and null) its minimum-link path in the set, exact in Q(sqrt3)
  const auto tm = run_taut({"tighten", file, "-o", dir + "/tm.xml", "--min-link", "--stats", dir + "/tm.json"});
  EXPECT_EQ(tm.status, 0) << tm.err;
  EXPECT_EQ(tm.err.find("TIGHTEN-0003"), std::string::npos) << tm.err;
  EXPECT_EQ(tm.err.find("TIGHTEN-0015"), std::string::npos) << tm.err;
  EXPECT_NE(tm.err.find("minimum links 2 (c:0,60,120: 2)"), std::string::npos) << tm.err;
  EXPECT_EQ(wires_of(dir + "/tm.xml", "n"), wires_of(dir + "/t.xml", "n"));
  {
    const auto j = nlohmann::json::parse(read_text(dir + "/tm.json"))["tighten"]["nets"][0];
    EXPECT_EQ(j["min_links"], 2) << j.dump();  // at any angle: to (50, 190/3) above the square, then down
    // in the set: up at 60 degrees from (10, 50) and down at 120 degrees into (90, 50); the two
    // lines meet at x = 50, 40 sqrt3 above the pins, clear of the square's top corners (at
    // x = 40 the first is 30 sqrt3 > 10 above them)
    EXPECT_EQ(j["oriented_min_links"], 2) << j.dump();
    EXPECT_FALSE(j.contains("oriented_min_links_none")) << j.dump();
    EXPECT_EQ(j["oriented_min_link_wires"],
              nlohmann::json::parse(R"([[["10", "50"], ["50", "50+40*sqrt3"], ["90", "50"]]])"))
        << j.dump();
  }
  // c:0,90 is another name of the rectilinear directions: the same as --orientations rectilinear
  std::string rect_rules = read_text(file);
  rect_rules.replace(rect_rules.find("c:0,60,120"), 10, "c:90,0");
  const std::string rfile = layout_file("tighten_cset_rect", "");
  write_text(rfile, rect_rules);
  const auto r1 = run_taut({"tighten", rfile, "-o", dir + "/r1.xml"});
  ASSERT_EQ(r1.status, 0) << r1.err;
  EXPECT_EQ(r1.err.find("TIGHTEN-0003"), std::string::npos) << r1.err;
  const auto r2 = run_taut({"tighten", file, "-o", dir + "/r2.xml", "--orientations", "c:0,90,180"});
  ASSERT_EQ(r2.status, 0) << r2.err;
  const auto r3 = run_taut({"tighten", file, "-o", dir + "/r3.xml", "--orientations", "rectilinear"});
  ASSERT_EQ(r3.status, 0) << r3.err;
  EXPECT_EQ(wires_of(dir + "/r1.xml", "n"), wires_of(dir + "/r3.xml", "n"));
  EXPECT_EQ(wires_of(dir + "/r2.xml", "n"), wires_of(dir + "/r3.xml", "n"));
  EXPECT_EQ(wires_of(dir + "/r3.xml", "n"), (std::vector<Path>{{{10, 50}, {10, 60}, {90, 60}, {90, 50}}}));
}

TEST(Tighten, BadInputExit2AndWritesNothing) {
  const std::string dir = temp_dir("tighten_bad");
  const std::string body =
      "  <boundary x0=\"0\" y0=\"0\" x1=\"100\" y1=\"100\"/>\n"
      "  <rules orientations=\"any\"/>\n"
      "  <blockage id=\"a\"><rect x0=\"40\" y0=\"40\" x1=\"60\" y1=\"60\"/></blockage>\n"
      "  <blockage id=\"b\"><rect x0=\"60\" y0=\"60\" x1=\"80\" y1=\"80\"/></blockage>\n"
      "  <net name=\"n\">\n"
      "    <pin name=\"p\" x=\"10\" y=\"50\"/>\n"
      "    <pin name=\"q\" x=\"90\" y=\"50\"/>\n"
      "    <sketch points=\"10,50 90,50\"/>\n"
      "  </net>\n";
  const std::string file = layout_file("tighten_bad_in", body);
  write_text(dir + "/t.xml", "old");
  auto run = run_taut({"tighten", file, "-o", dir + "/t.xml"});
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_NE(run.err.find("t.xml:9: error: [TIGHTEN-0001] net \"n\": the sketch's segment 1 (10,50 to 90,50) leaves free space"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(read_text(dir + "/t.xml"), "old");
  // through the point where a and b touch
  std::string pinch = body;
  pinch.replace(pinch.find("10,50 90,50"), 11, "10,50 10,90 60,60 90,10 90,50");
  run = run_taut({"tighten", layout_file("tighten_bad_pinch", pinch), "-o", dir + "/t.xml"});
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_NE(run.err.find("passes through a point where blockages touch at or after 60,60"), std::string::npos) << run.err;
  // c: sets with a direction no integer step of at most 2^24 realizes within 2^-36 radians (since
  // the twenty-first session, 2026-12-07; before, any direction at neither a multiple of 45 nor of
  // 30 degrees, such as c:0,10) are not available
  for (const auto& extra : std::vector<std::vector<std::string>>{
           {"--orientations", "c:0,0.000001"}, {"--orientations", "c:0,45.000001,60", "--min-link"},
           {"--orientations", "c:0,89.999999", "--clearance", "--min-link"}}) {
    std::vector<std::string> cmd{"tighten", file, "-o", dir + "/t.xml"};
    cmd.insert(cmd.end(), extra.begin(), extra.end());
    run = run_taut(cmd);
    EXPECT_EQ(run.status, 2) << run.err;
    EXPECT_NE(run.err.find("[CLI-0027]"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("such as 0.000001 or 45.000001, does not"), std::string::npos) << run.err;
    EXPECT_EQ(read_text(dir + "/t.xml"), "old");
  }
  // the message says which direction, or what else (Root3Directions::parse_any's reason)
  run = run_taut({"tighten", file, "-o", dir + "/t.xml", "--orientations", "c:0,0.000001"});
  EXPECT_NE(run.err.find("c:0,0.000001: no integer step of at most 2^24 lies within 2^-36 radians of 0.000001 degrees"),
            std::string::npos)
      << run.err;
  run = run_taut({"tighten", file, "-o", dir + "/t.xml", "--orientations", "c:1,2,3,4,5,6,7,8,9"});
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_NE(run.err.find("9 directions at multiples of neither 30 nor 45 degrees (at most 8)"), std::string::npos) << run.err;
  run = run_taut({"tighten", file, "-o", dir + "/t.xml", "--orientations", "c:10,10.00000000000001"});
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_NE(run.err.find("10 and 10.00000000000001 degrees are too close to tell apart"), std::string::npos) << run.err;
  EXPECT_EQ(read_text(dir + "/t.xml"), "old");
}

// A layout with nothing drawn (no blockage, no pin): nothing to tighten, not an internal error
// (the routing domain was an empty box, which the triangulation refuses: exit 3; found by
// fuzzing, 2026-12-06).
TEST(Tighten, NothingDrawnIsNotAnInternalError) {
  const std::string dir = temp_dir("tighten_nothing");
  const std::vector<std::pair<std::string, int>> files = {
      {"<layout/>\n", 0},
      {"<layout version=\"1\"><rules wire-width=\"2\" spacing=\"1\" orientations=\"any\"/></layout>\n", 0},
      // a sketch on a net without pins that is not a loop: ignored (LAYOUT-0009), nothing to tighten
      {"<layout version=\"1\"><net name=\"a\"><sketch points=\"0,0 0,1\"/></net></layout>\n", 1}};
  for (const auto& [text, want] : files) {
    write_text(dir + "/in.xml", text);
    for (const std::vector<std::string>& extra : std::vector<std::vector<std::string>>{
             {}, {"--clearance"}, {"--min-link"}, {"--clearance", "--orientations", "octilinear"}}) {
      std::vector<std::string> cmd{"tighten", dir + "/in.xml", "-o", dir + "/out.xml"};
      cmd.insert(cmd.end(), extra.begin(), extra.end());
      std::remove((dir + "/out.xml").c_str());
      const auto r = run_taut(cmd);
      EXPECT_EQ(r.status, want) << text << r.err;
      EXPECT_EQ(r.err.find("internal error"), std::string::npos) << text << r.err;
      EXPECT_TRUE(file_exists(dir + "/out.xml")) << text;
    }
    // (route routes orientations="any" octilinear and tightens the wires, since 2026-12-06)
    for (const std::vector<std::string>& other : std::vector<std::vector<std::string>>{
             {"route", dir + "/in.xml", "-q", "-o", dir + "/r.xml"}, {"check", dir + "/in.xml", "-q"}, {"stats", dir + "/in.xml"}}) {
      const auto r = run_taut(other);
      EXPECT_TRUE(r.status >= 0 && r.status <= 2) << other[0] << " " << text << r.err;
      EXPECT_EQ(r.err.find("internal error"), std::string::npos) << other[0] << " " << text << r.err;
    }
  }
}

// Sets whose cones do not bracket a link's box (c:0,45: NE and W round north; c:45,135: NE and
// SE round east): in the unbounded plane (no <boundary>) the staircase with the fewest links
// leaves the box of the link's ends, (0,0) (1000,1000) (0,1000) in c:0,45. The domain and the
// tightening windows must hold it: before 2026-12-06 their walls, 64 DBU from the ends, made a
// zigzag of a bend per 128 DBU (millions on a wire 10^9 long; found by fuzzing).
TEST(Tighten, WideConesLeaveTheBoxOfTheEnds) {
  const std::string dir = temp_dir("tighten_wide_cones");
  struct Case {
    std::int64_t x1, y1;
    std::string set;
    std::vector<Path> want;  // the one staircase with one bend (the other order crosses nothing either)
  };
  const std::vector<Case> cases = {
      {0, 1000, "c:0,45", {{{0, 0}, {1000, 1000}, {0, 1000}}}},
      {1000, 0, "c:45,135", {}},
      {0, 1000, "c:0,135", {}},
      {1000, 0, "c:90,135", {}},
      {1000000000, 0, "c:45,135", {}},
      {0, 1000000000, "c:0,45", {}},
  };
  for (const Case& c : cases)
    for (const bool clearance : {false, true}) {
      const std::string pts = "0,0 " + std::to_string(c.x1) + "," + std::to_string(c.y1);
      write_text(dir + "/in.xml", "<layout version=\"1\"><net name=\"a\"><pin name=\"p\" x=\"0\" y=\"0\"/><pin name=\"q\" x=\"" +
                                      std::to_string(c.x1) + "\" y=\"" + std::to_string(c.y1) + "\"/><sketch points=\"" + pts +
                                      "\"/></net></layout>\n");
      std::vector<std::string> cmd{"tighten", dir + "/in.xml", "-o", dir + "/out.xml", "--orientations", c.set};
      if (clearance) cmd.push_back("--clearance");
      const auto r = run_taut(cmd);
      ASSERT_EQ(r.status, 0) << c.set << " " << pts << r.err;
      const std::vector<Path> w = wires_of(dir + "/out.xml", "a");
      ASSERT_EQ(w.size(), 1u) << c.set << " " << pts;
      EXPECT_EQ(w[0].size(), 3u) << c.set << " " << pts << " clearance " << clearance << ": " << r.err;  // one bend
      if (!c.want.empty() && !clearance) {
        EXPECT_EQ(w, c.want);
      }
      EXPECT_EQ(run_taut({"check", dir + "/out.xml", "-q"}).status, 0) << c.set << " " << pts;
    }
}

}  // namespace tighten_test
}  // namespace taut::test
