// `taut import` on OpenROAD's flip-chip RDL test case (../shared/data/openroad-rdl: 276 bumps,
// 210 pad cells in four orientations, 4 power nets and 135 signal nets on metal10):
//   - the pad pins are where OpenROAD put them: every signal net OpenROAD routed
//     (rdl_route.defok, an independent program's output) has its two free ends inside the net's
//     two imported pin shapes, one in each (the pads in orientations N, W, FS and FW);
//   - the imported layout routes, and the routed file passes `taut check`;
//   - OpenROAD's routing itself, imported with --keep-wiring, passes `taut check`;
//   - a LEF that cannot be read is exit status 2 with nothing written.
// Skips when the data is absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "io/layout_reader.h"
#include "support/run.h"

namespace taut {
namespace import_test {

using test::run_taut;

std::string rdl_dir() {
  const std::string d = std::string(TAUT_SHARED_DATA) + "/openroad-rdl";
  return std::filesystem::is_directory(d) ? d : "";
}

#define REQUIRE_RDL()                                                               \
  do {                                                                              \
    if (rdl_dir().empty()) GTEST_SKIP() << "no openroad-rdl data at " TAUT_SHARED_DATA; \
  } while (0)

std::vector<std::string> import_args(const std::string& out, bool bump_to_pad) {
  const std::string d = rdl_dir();
  std::vector<std::string> a = {"import", d + "/floorplan_flipchip.def", "--lef", d + "/dummy_pads.lef", "--layer", "metal10",
                                "--nets", "VDD DVDD VSS DVSS p_*", "--wire-width", "4", "--spacing", "4", "-o", out};
  if (bump_to_pad) a.push_back("--bump-to-pad");
  return a;
}

bool contains(const io::Shape& s, geom::Point p) {
  EXPECT_EQ(s.kind, io::Shape::Kind::Rect);
  // strictly inside: OpenROAD ends its wires at the pins' centres (a pad drawn mirrored the wrong
  // way would still have the centre on its edge)
  return s.rect.lo.x < p.x && p.x < s.rect.hi.x && s.rect.lo.y < p.y && p.y < s.rect.hi.y;
}

TEST(Import, PadPinsAreWhereOpenRoadRoutedTo) {
  REQUIRE_RDL();
  const std::string dir = test::temp_dir("import_rdl_pins");
  const auto r = run_taut(import_args(dir + "/rdl.xml", false));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto loaded = io::read_layout(dir + "/rdl.xml");
  ASSERT_TRUE(loaded.layout);
  std::map<std::string, const io::Net*> nets;
  for (const io::Net& n : loaded.layout->nets) nets[n.name] = &n;
  EXPECT_EQ(nets.size(), 139u);
  // OpenROAD's wiring of each signal net: its segments' end points, in order
  const std::string defok = test::read_text(rdl_dir() + "/rdl_route.defok");
  const std::string special = defok.substr(defok.find("\nSPECIALNETS"), defok.find("END SPECIALNETS") - defok.find("\nSPECIALNETS"));
  const std::regex item(R"(\n    - (p_\S+) [^;]*;)");
  const std::regex point(R"(\( (\d+) (\d+|\*) \))");
  int checked = 0;
  for (auto it = std::sregex_iterator(special.begin(), special.end(), item); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1];
    const std::string body = (*it)[0];
    std::vector<geom::Point> pts;  // segment ends, in pairs
    for (auto p = std::sregex_iterator(body.begin(), body.end(), point); p != std::sregex_iterator(); ++p) {
      const int x = std::stoi((*p)[1]);
      const int y = (*p)[2] == "*" ? pts.back().y : std::stoi((*p)[2]);
      pts.push_back({x, y});
    }
    ASSERT_TRUE(pts.size() >= 2 && pts.size() % 2 == 0) << name;
    // the free ends: an end no other segment (grown by half the 8000 width) covers; OpenROAD
    // draws each segment out to its corners, so these are where the wire meets its pins
    std::vector<geom::Point> ends;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      bool covered = false;
      for (std::size_t s = 0; s + 1 < pts.size() && !covered; s += 2) {
        if (s == k - k % 2) continue;
        const int x0 = std::min(pts[s].x, pts[s + 1].x) - 4000, x1 = std::max(pts[s].x, pts[s + 1].x) + 4000;
        const int y0 = std::min(pts[s].y, pts[s + 1].y) - 4000, y1 = std::max(pts[s].y, pts[s + 1].y) + 4000;
        covered = x0 <= pts[k].x && pts[k].x <= x1 && y0 <= pts[k].y && pts[k].y <= y1;
      }
      if (!covered) ends.push_back(pts[k]);
    }
    ASSERT_EQ(ends.size(), 2u) << name;
    ASSERT_TRUE(nets.count(name)) << name;
    const io::Net& n = *nets[name];
    ASSERT_EQ(n.pins.size(), 2u) << name;  // the bump (its DEF pin drawn on it: one pin) and the pad
    // one end on each pin
    const bool forward = contains(*n.pins[0].shape, ends[0]) && contains(*n.pins[1].shape, ends[1]);
    const bool backward = contains(*n.pins[1].shape, ends[0]) && contains(*n.pins[0].shape, ends[1]);
    EXPECT_TRUE(forward || backward) << name << " from (" << ends[0].x << ", " << ends[0].y << ") to (" << ends[1].x << ", "
                                     << ends[1].y << ")";
    ++checked;
  }
  EXPECT_EQ(checked, 135);
}

TEST(Import, TheRdlLayoutRoutesAndChecks) {
  REQUIRE_RDL();
  const std::string dir = test::temp_dir("import_rdl_route");
  const auto r = run_taut(import_args(dir + "/rdl.xml", true));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto route = run_taut(
      {"route", dir + "/rdl.xml", "-o", dir + "/routed.xml", "--stats", dir + "/s.json", "--svg", dir + "/rdl.svg", "-q"}, 600);
  ASSERT_TRUE(route.status == 0 || route.status == 1) << route.err;
  EXPECT_EQ(test::read_text(dir + "/rdl.svg"), test::read_text(std::string(TAUT_SOURCE_DIR) + "/docs/rdl.svg"))
      << "docs/rdl.svg is not what taut draws now: copy " << dir << "/rdl.svg";
  const auto j = nlohmann::json::parse(test::read_text(dir + "/s.json"));
  // 135 signal nets and 102 power bumps, each its own net (--bump-to-pad)
  EXPECT_EQ(j["nets"], 237);
  // every one routed since 2026-12-06 (BUMP_9_12's pad, which another net's wire comes within the
  // clearance of, is reached from the part it leaves clear; before, 236)
  EXPECT_EQ(j["totals"]["routed"], 237);
  const auto check = run_taut({"check", dir + "/routed.xml"}, 600);
  EXPECT_EQ(check.status, 0) << check.out << check.err;
}

// OpenROAD's own routing of the signal nets, kept as <routes>, passes taut's independent check:
// free space (its power wiring and the other pins as blockages), connectivity, clearance (4 um
// at exactly the spacing in places), lengths as written.
TEST(Import, OpenRoadsRoutingPassesTheCheck) {
  REQUIRE_RDL();
  const std::string dir = test::temp_dir("import_rdl_keep");
  const std::string d = rdl_dir();
  const auto r = run_taut({"import", d + "/rdl_route.defok", "--lef", d + "/dummy_pads.lef", "--layer", "metal10", "--nets", "p_*",
                           "--wire-width", "4", "--spacing", "4", "--keep-wiring", "-q", "-o", dir + "/or.xml"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto check = run_taut({"check", dir + "/or.xml", "--json"}, 600);
  EXPECT_EQ(check.status, 0) << check.out << check.err;
  const auto stats = run_taut({"stats", dir + "/or.xml", "--json"});
  ASSERT_EQ(stats.status, 0) << stats.err;
  const auto j = nlohmann::json::parse(stats.out);
  EXPECT_EQ(j["totals"]["routed"], 135);
  // with --bump-to-pad: refused
  const auto both = run_taut({"import", d + "/rdl_route.defok", "--lef", d + "/dummy_pads.lef", "--layer", "metal10",
                              "--keep-wiring", "--bump-to-pad", "-o", dir + "/both.xml"});
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("[CLI-0032]"), std::string::npos) << both.err;
  EXPECT_FALSE(test::file_exists(dir + "/both.xml"));
}

TEST(Import, AMissingLefWritesNothing) {
  REQUIRE_RDL();
  const std::string dir = test::temp_dir("import_rdl_missing");
  auto a = import_args(dir + "/rdl.xml", false);
  a[3] = dir + "/none.lef";
  const auto r = run_taut(a);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("[IO-0120]"), std::string::npos) << r.err;
  EXPECT_FALSE(test::file_exists(dir + "/rdl.xml"));
  // a pattern that matches no net
  a = import_args(dir + "/rdl.xml", false);
  a[7] = "p_* q_*";
  const auto q = run_taut(a);
  EXPECT_EQ(q.status, 2);
  EXPECT_NE(q.err.find("[IO-0125]"), std::string::npos) << q.err;
  EXPECT_FALSE(test::file_exists(dir + "/rdl.xml"));
}

}  // namespace import_test
}  // namespace taut
