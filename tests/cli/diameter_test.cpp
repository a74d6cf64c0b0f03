// `taut diameter` (issue #6, de Berg's rectilinear link diameter) end to end: the JSON and text
// output on designs/diameter.xml and on layouts written two ways (blockages cutting into the
// boundary, or one frame blockage whose hole is the free polygon), each checked against
// oracle::LinkPolygonReference (an exhaustive Hanan-grid search, independent of the router); the
// wire it prints is checked to lie in free space, to have that many links and to be L1-shortest;
// and every refusal (DIAM-0001 ... DIAM-0005) names the file and line, exits 2 and writes nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "geom/predicates.h"
#include "io/layout_geometry.h"
#include "io/layout_reader.h"
#include "oracle/l1_oracle.h"
#include "oracle/link_polygon_oracle.h"
#include "router/link_polygon.h"
#include "support/polygon_frame.h"
#include "support/run.h"

namespace taut {
namespace diameter_test {

using geom::Point;
using test::run_taut;

const std::string kDesign = std::string(TAUT_SOURCE_DIR) + "/designs/diameter.xml";

std::string pt(Point p) { return std::to_string(p.x) + "," + std::to_string(p.y); }

// The free polygon of a layout file, as the reference sees it: the boundary minus the blockages,
// computed here by the product (free_space_polygon has its own test against generated rings).
geom::Ring free_ring(const std::string& file) {
  const io::ReadResult rr = io::read_layout(file);
  EXPECT_TRUE(rr.layout.has_value());
  const router::FreeSpacePolygon f =
      router::free_space_polygon(rr.layout->boundary->box, io::blockage_polygons(*rr.layout));
  EXPECT_EQ(f.status, router::FreeSpacePolygon::Status::Ok);
  return f.ring;
}

// The printed wire: in the polygon (every vertex and every segment's midpoint, doubled), with
// `links` segments, from `from` to `to`, of L1 length `length`, which is the L1 distance.
void expect_legal_wire(const geom::Ring& ring, const nlohmann::json& j) {
  const oracle::LinkPolygonReference ref(ring);
  const std::vector<Point> pts = test::points_of(j["points"]);
  ASSERT_GE(pts.size(), 2u);
  EXPECT_EQ(pts.front(), (Point{j["from"][0].get<geom::Coord>(), j["from"][1].get<geom::Coord>()}));
  EXPECT_EQ(pts.back(), (Point{j["to"][0].get<geom::Coord>(), j["to"][1].get<geom::Coord>()}));
  EXPECT_EQ(static_cast<int>(pts.size()) - 1, j["diameter"].get<int>());
  EXPECT_EQ(j["bends"].get<int>(), j["diameter"].get<int>() - 1);
  std::int64_t len = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Point a = pts[i], b = pts[i + 1];
    EXPECT_TRUE(a.x == b.x || a.y == b.y) << pt(a) << " " << pt(b);
    if (i > 0) {
      EXPECT_NE(geom::orientation(pts[i - 1], a, b), 0) << "collinear links at " << pt(a);
    }
    len += std::abs(std::int64_t{b.x} - a.x) + std::abs(std::int64_t{b.y} - a.y);
    // every point of the segment: its ends and the points between grid lines (a segment between
    // two points of a rectilinear polygon leaves it only through a vertex line)
    EXPECT_TRUE(ref.contains(a));
    EXPECT_EQ(ref.distance(a, b), std::optional<int>(a == b ? 0 : 1)) << pt(a) << " " << pt(b);
  }
  EXPECT_EQ(len, j["length"].get<std::int64_t>());
  // L1-shortest: the L1 reference inside the polygon
  const test::L1InPolygon l1(ring);
  EXPECT_EQ(l1.ref->distance(pts.front(), pts.back()), std::optional<std::int64_t>(len));
}

TEST(Diameter, DesignMatchesTheExhaustiveReference) {
  const test::RunResult r = run_taut({"diameter", kDesign, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const geom::Ring ring = free_ring(kDesign);
  const oracle::LinkPolygonReference ref(ring);
  EXPECT_EQ(j["diameter"].get<int>(), ref.diameter().links);
  EXPECT_EQ(j["diameter"].get<int>(), 8);  // designs/diameter.xml, as the README says
  EXPECT_EQ(j["metric"], "link");
  EXPECT_EQ(j["vertices"].get<std::size_t>(), ring.size());
  const Point from{j["from"][0].get<geom::Coord>(), j["from"][1].get<geom::Coord>()};
  const Point to{j["to"][0].get<geom::Coord>(), j["to"][1].get<geom::Coord>()};
  EXPECT_EQ(ref.distance(from, to), std::optional<int>(j["diameter"].get<int>()));
  expect_legal_wire(ring, j);

  const std::string dir = test::temp_dir("diameter_svg");
  const test::RunResult t = run_taut({"diameter", kDesign, "--svg", dir + "/d.svg"});
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("link diameter 8 (7 bends), from " + pt(from) + " to " + pt(to)), std::string::npos) << t.out;
  EXPECT_NE(test::read_text(dir + "/d.svg").find("class=\"diameter\""), std::string::npos);
  // the README's picture is what the command draws now
  EXPECT_EQ(test::read_text(dir + "/d.svg"), test::read_text(std::string(TAUT_SOURCE_DIR) + "/docs/diameter.svg"))
      << "docs/diameter.svg is not what taut draws now: copy " << dir << "/d.svg";
}

// The same free polygon written as blockages that cut into the boundary and as one frame
// blockage with the polygon as its hole: the same answer, equal to the reference.
TEST(Diameter, TwoWaysToWriteTheSamePolygon) {
  // an L-shaped corridor with a notch: free = [0,10]x[0,2] + [0,2]x[0,10] minus nothing, plus a
  // bay at the top right; the boundary is [0,12]x[0,12]
  const std::string rects = test::layout_file("diameter_rects",
      "<boundary x0=\"0\" y0=\"0\" x1=\"12\" y1=\"12\"/>"
      "<blockage id=\"a\"><rect x0=\"2\" y0=\"2\" x1=\"12\" y1=\"9\"/></blockage>"
      "<blockage id=\"b\"><rect x0=\"10\" y0=\"0\" x1=\"12\" y1=\"2\"/></blockage>"
      "<blockage id=\"c\"><rect x0=\"2\" y0=\"10\" x1=\"9\" y1=\"12\"/></blockage>");
  const std::string frame = test::layout_file("diameter_frame",
      "<boundary x0=\"-5\" y0=\"-5\" x1=\"20\" y1=\"20\"/>"
      "<blockage id=\"frame\"><polygon points=\"-5,-5 20,-5 20,20 -5,20\">"
      "<hole points=\"0,0 10,0 10,2 2,2 2,9 12,9 12,12 9,12 9,10 2,10 2,12 0,12\"/></polygon></blockage>");
  int links = -1;
  for (const std::string& f : {rects, frame}) {
    const test::RunResult r = run_taut({"diameter", f, "--json"});
    ASSERT_EQ(r.status, 0) << f << "\n" << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const geom::Ring ring = free_ring(f);
    EXPECT_EQ(j["diameter"].get<int>(), oracle::LinkPolygonReference(ring).diameter().links) << f;
    expect_legal_wire(ring, j);
    if (links >= 0) {
      EXPECT_EQ(j["diameter"].get<int>(), links);
    }
    links = j["diameter"].get<int>();
  }
  EXPECT_GE(links, 3);
}

// A comb of 40 teeth whose tips are all 3 links apart: the eccentricity bounds prune nothing, so
// after 32 searches the command switches to de Berg's divide and conquer on the cut tree
// ("method": "cut-tree"); the answer is the reference's. designs/diameter.xml stays with the
// bounds ("method": "bounds", a few searches).
TEST(Diameter, ACombSwitchesToTheCutTree) {
  std::string body = "<boundary x0=\"0\" y0=\"0\" x1=\"79\" y1=\"5\"/>";
  for (int t = 0; t + 1 < 40; ++t)  // the gaps between teeth [2t, 2t + 1] x [1, 5]
    body += "<blockage id=\"gap" + std::to_string(t) + "\"><rect x0=\"" + std::to_string(2 * t + 1) + "\" y0=\"1\" x1=\"" +
            std::to_string(2 * t + 2) + "\" y1=\"5\"/></blockage>";
  const std::string f = test::layout_file("diameter_comb", body);
  const test::RunResult r = run_taut({"diameter", f, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const geom::Ring ring = free_ring(f);
  EXPECT_EQ(j["diameter"].get<int>(), 3);
  EXPECT_EQ(j["diameter"].get<int>(), oracle::LinkPolygonReference(ring).diameter().links);
  EXPECT_EQ(j["method"], "cut-tree");
  EXPECT_EQ(j["searches"].get<int>(), 32);
  EXPECT_EQ(j["convex_vertices"].get<int>(), 82);  // two per tooth, two at the bottom
  expect_legal_wire(ring, j);
  const test::RunResult d = run_taut({"diameter", kDesign, "--json"});
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_EQ(nlohmann::json::parse(d.out)["method"], "bounds");
  // --method forces either: the same diameter both ways, on both layouts
  for (const std::string& file : {f, kDesign}) {
    int links[2] = {-1, -1};
    for (int m = 0; m < 2; ++m) {
      const test::RunResult x = run_taut({"diameter", file, "--json", "--method", m == 0 ? "bounds" : "cut-tree"});
      ASSERT_EQ(x.status, 0) << x.err;
      const nlohmann::json jx = nlohmann::json::parse(x.out);
      EXPECT_EQ(jx["method"], m == 0 ? "bounds" : "cut-tree") << file;
      links[m] = jx["diameter"].get<int>();
      expect_legal_wire(free_ring(file), jx);
    }
    EXPECT_EQ(links[0], links[1]) << file;
  }
  const test::RunResult bad = run_taut({"diameter", kDesign, "--method", "fast"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("CLI-0029"), std::string::npos) << bad.err;
  EXPECT_TRUE(bad.out.empty());
}

// --method approx: de Berg's estimate within 3 (section 4.2), without a wire: its bounds hold the
// exact diameter (the reference's) on the design, the comb and a winding walk; the picture is
// written; the text says it is an estimate.
TEST(Diameter, ApproxGivesBoundsThatHoldTheDiameter) {
  std::string comb = "<boundary x0=\"0\" y0=\"0\" x1=\"79\" y1=\"5\"/>";
  for (int t = 0; t + 1 < 40; ++t)
    comb += "<blockage id=\"gap" + std::to_string(t) + "\"><rect x0=\"" + std::to_string(2 * t + 1) + "\" y0=\"1\" x1=\"" +
            std::to_string(2 * t + 2) + "\" y1=\"5\"/></blockage>";
  const std::string dir = test::temp_dir("diameter_approx");
  for (const std::string& file : {kDesign, test::layout_file("diameter_approx_comb", comb)}) {
    const geom::Ring ring = free_ring(file);
    const int want = oracle::LinkPolygonReference(ring).diameter().links;
    const std::string svg = dir + "/approx.svg";
    std::remove(svg.c_str());
    const test::RunResult r = run_taut({"diameter", file, "--json", "--method", "approx", "--svg", svg});
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "approx");
    EXPECT_FALSE(j.contains("diameter")) << "an estimate is not the diameter";
    const int est = j["estimate"].get<int>(), lo = j["bounds"][0].get<int>(), hi = j["bounds"][1].get<int>();
    EXPECT_LE(std::abs(est - want), 3) << file;
    EXPECT_LE(lo, want) << file;
    EXPECT_GE(hi, want) << file;
    EXPECT_EQ(j["vertices"].get<std::size_t>(), ring.size());
    EXPECT_GT(j["cells"].get<int>(), 1);
    EXPECT_TRUE(std::filesystem::exists(svg));
    const test::RunResult t = run_taut({"diameter", file, "--method", "approx"});
    ASSERT_EQ(t.status, 0) << t.err;
    EXPECT_NE(t.out.find("estimate " + std::to_string(est) + ", within 3"), std::string::npos) << t.out;
  }
}

// Sloped blockage edges that free space never sees: outside the boundary, or under another
// blockage. The diameter is computed.
TEST(Diameter, SlopedEdgesFreeSpaceDoesNotSee) {
  const std::string f = test::layout_file("diameter_sloped_away",
      "<boundary x0=\"0\" y0=\"0\" x1=\"10\" y1=\"10\"/>"
      "<blockage id=\"far\"><polygon points=\"100,100 110,100 100,110\"/></blockage>"
      "<blockage id=\"cut\"><polygon points=\"4,4 12,4 20,12 20,20 4,20\"/></blockage>"
      "<blockage id=\"under\"><polygon points=\"0,0 3,0 0,3\"/></blockage>"
      "<blockage id=\"over\"><rect x0=\"0\" y0=\"0\" x1=\"3\" y1=\"3\"/></blockage>");
  const test::RunResult r = run_taut({"diameter", f, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const geom::Ring ring = free_ring(f);
  EXPECT_EQ(j["diameter"].get<int>(), oracle::LinkPolygonReference(ring).diameter().links);
  expect_legal_wire(ring, j);
}

TEST(Diameter, RefusalsNameTheFileAndLine) {
  const std::string dir = test::temp_dir("diameter_refusals");
  struct Case {
    std::string name, body, code, line, words;
  };
  const std::vector<Case> cases = {
      {"noboundary", "\n<blockage id=\"a\"><rect x0=\"0\" y0=\"0\" x1=\"5\" y1=\"5\"/></blockage>", "DIAM-0001",
       ":1:", "no <boundary>"},
      {"sloped", "<boundary x0=\"0\" y0=\"0\" x1=\"10\" y1=\"10\"/>\n<blockage id=\"tri\">\n<polygon points=\"0,0 4,0 0,4\"/></blockage>",
       "DIAM-0002", ":4:", "blockage \"tri\""},
      // the sloped edge is a hole's, on its own line
      {"slopedhole", "<boundary x0=\"0\" y0=\"0\" x1=\"20\" y1=\"20\"/>\n<blockage id=\"frame\"><polygon points=\"0,0 20,0 20,20 0,20\">\n"
                     "<hole points=\"2,2 18,2 18,18 10,18 2,10\"/></polygon></blockage>",
       "DIAM-0002", ":4:", "blockage \"frame\" gives free space an edge"},
      // one shape of a blockage is an island, its other shape reaches the boundary
      {"shapeisland", "<boundary x0=\"0\" y0=\"0\" x1=\"10\" y1=\"10\"/>\n<blockage id=\"m\"><rect x0=\"0\" y0=\"0\" x1=\"2\" y1=\"2\"/>\n"
                      "<rect x0=\"5\" y0=\"5\" x1=\"6\" y1=\"6\"/></blockage>",
       "DIAM-0003", ":4:", "a shape of blockage \"m\""},
      {"island", "<boundary x0=\"0\" y0=\"0\" x1=\"10\" y1=\"10\"/>\n<blockage id=\"isle\"><rect x0=\"3\" y0=\"3\" x1=\"5\" y1=\"5\"/></blockage>",
       "DIAM-0003", ":3:", "blockage \"isle\""},
      {"pieces", "\n<boundary x0=\"0\" y0=\"0\" x1=\"10\" y1=\"10\"/><blockage id=\"wall\"><rect x0=\"4\" y0=\"0\" x1=\"5\" y1=\"10\"/></blockage>",
       "DIAM-0004", ":3:", "2 pieces"},
      // two blockages from opposite sides meet at one corner: free space pinches there
      {"pinch", "\n<boundary x0=\"0\" y0=\"0\" x1=\"10\" y1=\"10\"/><blockage id=\"lo\"><rect x0=\"0\" y0=\"0\" x1=\"5\" y1=\"5\"/></blockage>"
                "<blockage id=\"hi\"><rect x0=\"5\" y0=\"5\" x1=\"10\" y1=\"10\"/></blockage>",
       "DIAM-0004", ":3:", "2 pieces"},
      // one piece that goes round a blockage touching another at a corner: it touches itself there
      {"selftouch", "\n<boundary x0=\"0\" y0=\"0\" x1=\"30\" y1=\"30\"/><blockage id=\"b\"><rect x0=\"20\" y0=\"0\" x1=\"30\" y1=\"10\"/></blockage>"
                    "<blockage id=\"a\"><rect x0=\"10\" y0=\"10\" x1=\"20\" y1=\"20\"/></blockage>",
       "DIAM-0004", ":3:", "touches itself at 20,10"},
      {"full", "\n<boundary x0=\"0\" y0=\"0\" x1=\"10\" y1=\"10\"/><blockage id=\"all\"><rect x0=\"0\" y0=\"0\" x1=\"10\" y1=\"10\"/></blockage>",
       "DIAM-0005", ":3:", "no free space"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string f = test::layout_file("diameter_" + c.name, c.body);
    const std::string svg = dir + "/" + c.name + ".svg";
    const test::RunResult r = run_taut({"diameter", f, "--json", "--svg", svg});
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(test::file_exists(svg));
    EXPECT_NE(r.err.find(f + c.line + " error: [" + c.code + "]"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("error:"), r.err.rfind("error:")) << "one error";
    EXPECT_NE(r.err.find(c.words), std::string::npos) << r.err;
  }
}

}  // namespace diameter_test
}  // namespace taut
