// `taut voronoi`: the regions it writes (-o CELLS.xml, read back here with libxml2 and exact
// GMP rationals) checked against the brute-force reference (tests/oracle/l1_oracle.h) at a
// lattice of probe points: a probe some site reaches lies in the closure of a nearest site's
// region and in no other region's interior; a probe no site reaches lies in no region's
// interior. Also the JSON summary against the file, the picture, and bad input.
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <nlohmann/json.hpp>
#include <fstream>
#include <sstream>

#include "geom/normalize.h"
#include "geom/predicates.h"
#include "oracle/l1_oracle.h"
#include "support/exact_rings.h"
#include "support/layout_reference.h"
#include "support/run.h"
#include "support/sanitized.h"

namespace taut::test {
namespace voronoi_test {

using geom::Point;

struct Region {
  std::size_t site;
  mpq_class area;
  std::vector<std::vector<std::vector<P2>>> polygons;  // outer ring, then holes
};

mpq_class parse_q(const std::string& s) {
  mpq_class q(s);
  q.canonicalize();
  return q;
}
std::vector<P2> parse_points(const std::string& text) {
  std::vector<P2> out;
  std::istringstream in(text);
  std::string tok;
  while (in >> tok) {
    const auto c = tok.find(',');
    out.push_back({parse_q(tok.substr(0, c)), parse_q(tok.substr(c + 1))});
  }
  return out;
}
std::string prop(xmlNode* n, const char* name) {
  xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(name));
  std::string s = v ? reinterpret_cast<const char*>(v) : "";
  xmlFree(v);
  return s;
}
bool is(xmlNode* n, const char* name) {
  return n->type == XML_ELEMENT_NODE && xmlStrcmp(n->name, reinterpret_cast<const xmlChar*>(name)) == 0;
}

struct Cells {
  std::vector<Point> sites;
  std::vector<Region> regions;
};
Cells read_cells(const std::string& path) {
  Cells c;
  const std::string text = read_text(path);
  xmlDoc* doc = xmlReadMemory(text.data(), static_cast<int>(text.size()), path.c_str(), nullptr, XML_PARSE_NONET);
  EXPECT_NE(doc, nullptr) << path;
  if (!doc) return c;
  xmlNode* root = xmlDocGetRootElement(doc);
  EXPECT_TRUE(is(root, "voronoi"));
  for (xmlNode* n = root->children; n; n = n->next) {
    if (is(n, "site")) {
      if (const std::string pts = prop(n, "points"); !pts.empty()) {  // a shape site: its first vertex
        const P2 first = parse_points(pts).front();
        c.sites.push_back({static_cast<int>(mpz_class(first.x).get_si()), static_cast<int>(mpz_class(first.y).get_si())});
      } else {
        c.sites.push_back({std::stoi(prop(n, "x")), std::stoi(prop(n, "y"))});
      }
    }
    if (!is(n, "region")) continue;
    Region r{std::stoul(prop(n, "site")), parse_q(prop(n, "area")), {}};
    for (xmlNode* p = n->children; p; p = p->next) {
      if (!is(p, "polygon")) continue;
      std::vector<std::vector<P2>> rings{parse_points(prop(p, "points"))};
      for (xmlNode* h = p->children; h; h = h->next)
        if (is(h, "hole")) rings.push_back(parse_points(prop(h, "points")));
      r.polygons.push_back(std::move(rings));
    }
    c.regions.push_back(std::move(r));
  }
  xmlFreeDoc(doc);
  return c;
}

int in_region(const Region& r, const P2& q) {
  int best = -1;
  for (const auto& poly : r.polygons) {
    int w = in_ring(poly[0], q);
    for (std::size_t h = 1; h < poly.size() && w > 0; ++h) {
      const int k = in_ring(poly[h], q);
      if (k == 0) w = 0;
      if (k == 1) w = -1;
    }
    best = std::max(best, w);
  }
  return best;
}

// Checks the file's regions against the reference on a lattice of probes; returns how many
// probes were reached.
// shapes: the shape sites (site index, polygon): sources along their boundary, obstacles too.
int check_cells(const std::string& layout, const std::string& cells_path, const std::vector<Point>& sites,
                int step, const std::vector<std::pair<std::size_t, geom::Polygon>>& shapes = {},
                const std::vector<std::size_t>& left_out = {}) {
  const Cells cells = read_cells(cells_path);
  EXPECT_EQ(cells.sites, sites);
  for (const auto& r : cells.regions) {
    mpq_class a = 0;
    for (const auto& poly : r.polygons) {
      EXPECT_GT(sgn(twice_area(poly[0])), 0) << "outer rings run counter-clockwise";
      a += twice_area(poly[0]);
      for (std::size_t h = 1; h < poly.size(); ++h) {
        EXPECT_LT(sgn(twice_area(poly[h])), 0) << "holes run clockwise";
        a += twice_area(poly[h]);
      }
    }
    EXPECT_EQ(a, 2 * r.area) << "site " << r.site;
  }
  auto lr = reference_for<oracle::L1Reference>(layout, sites);
  if (!lr.ref) return 0;
  if (!shapes.empty()) {  // the shapes are obstacles as well
    std::vector<geom::Polygon> all = lr.norm.obstacles;
    for (const auto& [i, p] : shapes) all.push_back(p);
    lr.norm = geom::normalize_obstacles(all, lr.norm.domain);
    lr.ref = std::make_unique<oracle::L1Reference>(lr.norm.domain, lr.norm.obstacles);
  }
  const geom::Box& D = lr.norm.domain;
  std::vector<Point> probes;
  for (int x = D.lo.x; x <= D.hi.x; x += step)
    for (int y = D.lo.y; y <= D.hi.y; y += step) probes.push_back({x, y});
  std::vector<std::vector<std::optional<std::int64_t>>> dist;  // [site][probe]
  for (Point s : sites) dist.push_back(lr.ref->distances(s, probes));
  for (const std::size_t i : left_out) dist[i].assign(probes.size(), std::nullopt);  // no region: reaches nothing
  // A shape site: the least distance over its corners and the points of its edges level with
  // an obstacle vertex or a probe (the least over a segment is at such a point: the brute-force
  // check over every lattice point is tests/router/segment_source_test.cpp).
  for (const auto& [i, shape] : shapes) {
    std::vector<int> xs, ys;
    for (const auto& p : lr.norm.obstacles)
      for (const Point v : p.outer) xs.push_back(v.x), ys.push_back(v.y);
    for (const Point q : probes) xs.push_back(q.x), ys.push_back(q.y);
    for (auto* v : {&xs, &ys}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    std::vector<Point> cand;
    const auto& r = shape.outer;
    for (std::size_t k = 0; k < r.size(); ++k) {
      const Point a = r[k], b = r[(k + 1) % r.size()];
      cand.push_back(a);
      const int dx = (b.x > a.x) - (b.x < a.x), dy = (b.y > a.y) - (b.y < a.y);
      for (Point c = a; c != b; c = {c.x + dx, c.y + dy})
        if ((dx != 0 && std::binary_search(xs.begin(), xs.end(), c.x)) || (dy != 0 && std::binary_search(ys.begin(), ys.end(), c.y)))
          cand.push_back(c);  // level with one across the edge (a horizontal edge: in x; vertical: in y)
    }
    std::vector<std::optional<std::int64_t>> best(probes.size());
    for (const Point c : cand) {
      const auto d = lr.ref->distances(c, probes);
      for (std::size_t k = 0; k < probes.size(); ++k)
        if (d[k] && (!best[k] || *d[k] < *best[k])) best[k] = d[k];
    }
    for (std::size_t k = 0; k < probes.size(); ++k)  // the shape's own points: distance 0
      if (geom::locate(probes[k], shape) != geom::Location::Outside) best[k] = 0;
    dist[i] = best;
  }
  int reached = 0;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    {
      const int x = probes[i].x, y = probes[i].y;
      std::optional<std::int64_t> best;
      std::vector<std::optional<std::int64_t>> d;
      for (std::size_t s = 0; s < sites.size(); ++s) {
        d.push_back(dist[s][i]);
        if (d.back() && (!best || *d.back() < *best)) best = d.back();
      }
      const P2 qq{x, y};
      bool in_nearest = false;
      for (const auto& r : cells.regions) {
        const int w = in_region(r, qq);
        if (w < 0) continue;
        const bool nearest = best && d[r.site] == best;
        if (w > 0) {
          EXPECT_TRUE(nearest) << "probe " << x << "," << y << " inside the region of site " << r.site;
        }
        in_nearest = in_nearest || nearest;
      }
      if (best) {
        ++reached;
        EXPECT_TRUE(in_nearest) << "probe " << x << "," << y << " is in no nearest site's region";
      }
    }
  }
  return reached;
}

TEST(Voronoi, DemoPinsMatchTheReference) {
  const std::string demo = std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml";
  const std::string dir = temp_dir("voronoi_demo");
  const auto r = run_taut({"voronoi", demo, "-o", dir + "/cells.xml", "--svg", dir + "/cells.svg", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  // Every pin is a site: the two shape pins of net bump too (the pad and the diamond ball).
  EXPECT_EQ(r.err.find("VORONOI-0002"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::vector<Point> sites;
  std::vector<std::pair<std::size_t, geom::Polygon>> shapes;
  for (const auto& s : j["sites"]) {
    if (s.contains("points")) {
      geom::Polygon p;
      for (const auto& v : s["points"]) p.outer.push_back({v[0].get<int>(), v[1].get<int>()});
      shapes.push_back({sites.size(), p});
      sites.push_back(p.outer.front());
    } else {
      sites.push_back({s["point"][0].get<int>(), s["point"][1].get<int>()});
    }
  }
  ASSERT_EQ(sites.size(), 11u);
  ASSERT_EQ(shapes.size(), 2u);
  EXPECT_EQ(j["sites"][0]["net"], "clk");
  EXPECT_EQ(j["sites"][0]["pin"], "drv");
  EXPECT_EQ(j["sites"][9]["pin"], "pad");
  // Probes every 250 DBU (every 500 under the sanitizers: the reference's queries were 12 of
  // that tree's 13 s here).
  const int reached = check_cells(demo, dir + "/cells.xml", sites, kSanitized ? 500 : 250, shapes);
  EXPECT_GT(reached, sanitized_share(3000, 4));
  // The summary agrees with the file.
  const Cells cells = read_cells(dir + "/cells.xml");
  ASSERT_EQ(cells.regions.size(), 11u);
  for (const auto& reg : cells.regions) EXPECT_EQ(parse_q(j["sites"][reg.site]["area_exact"].get<std::string>()), reg.area);
  // The picture: a shaded path per region, under the blockages.
  const std::string svg = read_text(dir + "/cells.svg");
  std::size_t paths = 0;
  for (std::size_t at = svg.find("class=\"region\""); at != std::string::npos; at = svg.find("class=\"region\"", at + 1)) ++paths;
  EXPECT_EQ(paths, 11u);
  EXPECT_LT(svg.find("class=\"region\""), svg.find("class=\"blockage\""));
}

TEST(Voronoi, GivenSitesOnAGeneratedLayout) {
  const std::string dir = temp_dir("voronoi_gen");
  const std::string file = dir + "/rects.xml";
  ASSERT_EQ(run_taut({"gen", "rects", "-o", file, "--size", "40", "--seed", "7"}).status, 0);
  const auto lr = reference_for<oracle::L1Reference>(file);
  ASSERT_TRUE(lr.ref);
  // Sites: free lattice points, two of them on one diagonal (L1 ties over whole quadrants), and
  // from a file.
  std::vector<Point> sites;
  const geom::Box& D = lr.norm.domain;
  for (int k = 1; sites.size() < 6 && k < 40; ++k) {
    const Point p{D.lo.x + (D.hi.x - D.lo.x) * ((k * 7) % 10) / 10, D.lo.y + (D.hi.y - D.lo.y) * ((k * 3) % 10) / 10};
    if (lr.ref->is_free(p) && std::find(sites.begin(), sites.end(), p) == sites.end()) sites.push_back(p);
  }
  ASSERT_GE(sites.size(), 3u);
  std::string text = "# sites\n";
  for (std::size_t i = 2; i < sites.size(); ++i) text += std::to_string(sites[i].x) + "," + std::to_string(sites[i].y) + "\n";
  write_text(dir + "/sites.txt", text);
  const auto r = run_taut({"voronoi", file, "--site", std::to_string(sites[0].x) + "," + std::to_string(sites[0].y), "--site",
                           std::to_string(sites[1].x) + "," + std::to_string(sites[1].y), "--site-file", dir + "/sites.txt",
                           "-o", dir + "/cells.xml", "--svg", dir + "/cells.svg"});
  ASSERT_EQ(r.status, 0) << r.err;
  const int step = std::max(1, (D.hi.x - D.lo.x) / 60);
  EXPECT_GT(check_cells(file, dir + "/cells.xml", sites, step), 1000);
}

// A shape pin that touches a blockage cannot be a site: named with its reason and left out; the
// other shape pin is a site whose region holds it.
TEST(Voronoi, ShapePinTouchingABlockageIsLeftOut) {
  const std::string dir = temp_dir("voronoi_shapes");
  write_text(dir + "/s.xml", R"(<?xml version="1.0"?>
<layout name="s" version="1" dbu-per-micron="1000">
  <boundary x0="0" y0="0" x1="1000" y1="1000"/>
  <blockage id="wall"><rect x0="400" y0="0" x1="600" y1="700"/></blockage>
  <net name="n">
    <pin name="a" x="100" y="100"/>
    <pin name="pad"><rect x0="600" y0="300" x1="700" y1="400"/></pin>
    <pin name="ball"><polygon points="800,500 850,550 800,600 750,550"/></pin>
    <pin name="b" x="900" y="100"/>
    <pin name="pad2"><rect x0="100" y0="800" x1="200" y1="900"/></pin>
    <pin name="c" x="150" y="900"/>
  </net>
</layout>
)");
  const auto r = run_taut({"voronoi", dir + "/s.xml", "--json", "-o", dir + "/cells.xml"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("s.xml:7: warning: [VORONOI-0002] pin \"pad\" of net \"n\" is a shape that cannot be a Voronoi site: it "
                       "touches or overlaps a blockage; it is left out"),
            std::string::npos)
      << r.err;
  // pad2 has point pin c on its edge: left out too, naming c.
  EXPECT_NE(r.err.find("pin \"pad2\" of net \"n\" is a shape that cannot be a Voronoi site: pin \"c\" of net \"n\" lies on or "
                       "in it; it is left out"),
            std::string::npos)
      << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["sites"].size(), 6u);
  EXPECT_EQ(j["sites"][1]["area_exact"], "0");
  EXPECT_EQ(j["sites"][4]["area_exact"], "0");
  // The ball's region holds the ball: its area is at least the ball's (5,000). Point pin b comes
  // after the ball in the file and keeps its own region (the map lists points before shapes).
  EXPECT_GT(j["sites"][2]["area"].get<double>(), 5000.0);
  EXPECT_GT(j["sites"][3]["area"].get<double>(), 0.0);
  const std::vector<Point> sites = {{100, 100}, {600, 300}, {800, 500}, {900, 100}, {100, 800}, {150, 900}};
  const std::vector<std::pair<std::size_t, geom::Polygon>> shapes = {
      {2, geom::Polygon{{{800, 500}, {850, 550}, {800, 600}, {750, 550}}, {}}}};
  EXPECT_GT(check_cells(dir + "/s.xml", dir + "/cells.xml", sites, 25, shapes, {1, 4}), 500);
}

TEST(Voronoi, BadInputIsRefusedAndWritesNothing) {
  const std::string demo = std::string(TAUT_SOURCE_DIR) + "/designs/demo.xml";
  const std::string dir = temp_dir("voronoi_bad");
  // a site inside a blockage: named, exit 2, no file
  auto r = run_taut({"voronoi", demo, "--site", "500,500", "--site", "10000,9000", "-o", dir + "/c.xml", "--svg", dir + "/c.svg"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("[ROUTE-0001] site 1 at 10000,9000 lies inside blockage \"dsp\""), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_FALSE(std::ifstream(dir + "/c.xml").good());
  EXPECT_FALSE(std::ifstream(dir + "/c.svg").good());
  // a bad line of a site file
  write_text(dir + "/bad.txt", "1,1\n2;2\n");
  r = run_taut({"voronoi", demo, "--site-file", dir + "/bad.txt", "-o", dir + "/c.xml"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/bad.txt:2: error: [CLI-0025]"), std::string::npos) << r.err;
  EXPECT_FALSE(std::ifstream(dir + "/c.xml").good());
  // a layout without point pins and no --site
  write_text(dir + "/nopins.xml",
             "<layout name=\"n\" version=\"1\"><boundary x0=\"0\" y0=\"0\" x1=\"100\" y1=\"100\"/></layout>\n");
  r = run_taut({"voronoi", dir + "/nopins.xml"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("[VORONOI-0001]"), std::string::npos) << r.err;
  // two sites at one point: the first has the region, the second is named
  r = run_taut({"voronoi", dir + "/nopins.xml", "--site", "10,10", "--site", "90,90", "--site", "10,10", "--json"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("[VORONOI-0003] site 2 is at the same point as site 0"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["sites"][2]["area_exact"], "0");
  // The two sites split the square along the anti-diagonal x + y = 100; the ties (the two
  // corner triangles beyond it are equally far from both) go by the map's rule, and the areas add up.
  EXPECT_EQ(parse_q(j["sites"][0]["area_exact"].get<std::string>()) + parse_q(j["sites"][1]["area_exact"].get<std::string>()),
            mpq_class(10000));
}

}  // namespace voronoi_test
}  // namespace taut::test
