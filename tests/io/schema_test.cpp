// io/schema/layout.xsd says what FORMAT.md says: xmllint accepts every good file and design,
// rejects every bad file except the ones a schema cannot judge (listed below), and agrees with
// an independent reference (and with the reader) on numbers, points and orientations.
#include <gtest/gtest.h>

#include "support/corpus.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "io/layout_reader.h"
#include "support/run.h"

namespace fs = std::filesystem;

namespace schema_test {

const std::string kSchema = std::string(TAUT_SOURCE_DIR) + "/io/schema/layout.xsd";

bool have_xmllint() { return std::system("xmllint --version > /dev/null 2>&1") == 0; }

// Runs xmllint once on many files; true per file when it "validates".
std::map<std::string, bool> xmllint(const std::vector<std::string>& files) {
  std::map<std::string, bool> ok;
  for (const auto& f : files) ok[f] = false;
  std::string cmd = "timeout 120 xmllint --noout --nonet --schema '" + kSchema + "'";
  for (const auto& f : files) cmd += " '" + f + "'";
  cmd += " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    ADD_FAILURE() << "cannot run xmllint";
    return ok;
  }
  std::string out;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  std::size_t pos = 0;
  while (pos < out.size()) {
    std::size_t eol = out.find('\n', pos);
    if (eol == std::string::npos) eol = out.size();
    const std::string line = out.substr(pos, eol - pos);
    const std::string suffix = " validates";
    if (line.size() > suffix.size() && line.compare(line.size() - suffix.size(), suffix.size(), suffix) == 0) {
      const std::string f = line.substr(0, line.size() - suffix.size());
      if (ok.count(f)) ok[f] = true;
    }
    pos = eol + 1;
  }
  return ok;
}

std::vector<std::string> xml_files(const std::string& dir) {
  std::vector<std::string> v;
  if (!fs::exists(dir)) return v;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".xml") v.push_back(e.path().string());
  std::sort(v.begin(), v.end());
  return v;
}

using taut::test::reference_int;

TEST(Schema, GoodFilesAndDesignsValidate) {
  if (!have_xmllint()) GTEST_SKIP() << "xmllint not installed";
  auto files = xml_files(std::string(TAUT_TEST_DATA) + "/good");
  const auto designs = xml_files(std::string(TAUT_SOURCE_DIR) + "/designs");
  files.insert(files.end(), designs.begin(), designs.end());
  ASSERT_GE(files.size(), 3u);
  for (const auto& [f, ok] : xmllint(files)) EXPECT_TRUE(ok) << f;
}

TEST(Schema, BadFilesFailUnlessOnlyTheReaderOrValidationCanTell) {
  if (!have_xmllint()) GTEST_SKIP() << "xmllint not installed";
  // Beyond XML Schema 1.0 (geometry, cross-element rules, at-most-once in any order), or
  // warnings only.
  const std::set<std::string> schema_cannot_tell = {
      "boundary_empty.xml", "boundary_twice.xml",
      "hole_outside_shell.xml", "net_one_pin.xml", "orientations_one_direction.xml", "routes_orientations_one_direction.xml",
      "points_2p30.xml" /* (a point's range: the pattern takes any digits) */,
      "pin_between_touching_blockages.xml", "pin_in_blockage.xml", "pin_neither.xml", "pin_only_x.xml",
      "pin_outside_boundary.xml", "pin_point_and_shape.xml", "polygon_bowtie.xml", "polygon_collinear.xml",
      "polygon_spike.xml", "polygon_two_points.xml", "polygon_zero_area.xml", "rect_empty_x.xml",
      "rect_empty_y.xml", "shape_pin_in_blockage.xml", "shape_pin_outside_boundary.xml",
      "sketch_off_pin.xml", "sketch_three_pins.xml"};
  // Files with a DOCTYPE are left out: they attack the parser (xmllint expands their entities
  // for schema validation, which is exactly the blow-up the reader refuses); reader_test covers them.
  std::vector<std::string> files;
  for (const auto& f : xml_files(std::string(TAUT_TEST_DATA) + "/bad"))
    if (taut::test::read_text(f).find("<!DOCTYPE") == std::string::npos) files.push_back(f);
  ASSERT_GE(files.size(), 50u);
  int rejected = 0;
  for (const auto& [f, ok] : xmllint(files)) {
    const std::string name = fs::path(f).filename().string();
    EXPECT_EQ(ok, schema_cannot_tell.count(name) == 1) << name;
    rejected += !ok;
  }
  EXPECT_GE(rejected, 40);
}

// One file per value: the schema's number pattern (with its range) against the reference, and
// the reader against both.
TEST(Schema, NumbersAgreeWithReferenceAndReader) {
  if (!have_xmllint()) GTEST_SKIP() << "xmllint not installed";
  const unsigned seed = 4242;
  std::mt19937 rng(seed);
  std::vector<std::string> values = {"0", "-0", "007", "1073741823", "-1073741823", "1073741824", "1073741830",
                                     "1073740999", "1073741799", "1073741819", "1069999999", "999999999",
                                     "01073741823", "2147483648", "+5", " 12", "12 ", "1e3", "0x10", "", "-",
                                     "1.5", "nan", "inf", "12abc"};
  const std::string max = "1073741823";
  for (int i = 0; i < 300; ++i) {
    // Near the limit: the limit's first k digits, then random digits (exercises every branch).
    const int k = static_cast<int>(rng() % 10);
    std::string s = max.substr(0, static_cast<std::size_t>(k));
    while (s.size() < 10) s += static_cast<char>('0' + rng() % 10);
    if (rng() % 3 == 0) s = "-" + s;
    if (rng() % 5 == 0) s = s.substr(0, 1 + rng() % s.size());
    values.push_back(s);
  }
  const std::string dir = taut::test::temp_dir("schema_numbers");
  std::vector<std::string> files;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string f = dir + "/v" + std::to_string(i) + ".xml";
    taut::test::write_text(f, "<layout><net name=\"n\"><pin name=\"p\" x=\"" + values[i] +
                                  "\" y=\"0\"/></net></layout>\n");
    files.push_back(f);
  }
  const auto ok = xmllint(files);
  for (std::size_t i = 0; i < values.size(); ++i) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " value \"" + values[i] + "\"");
    const bool ref = reference_int(values[i]) == 1;
    EXPECT_EQ(ok.at(files[i]), ref);
    EXPECT_EQ(taut::io::read_layout(files[i]).layout.has_value(), ref);
  }
}

// Points lists and orientations: the schema and the reader accept the same strings.
TEST(Schema, PointsAndOrientationsAgreeWithReader) {
  if (!have_xmllint()) GTEST_SKIP() << "xmllint not installed";
  const unsigned seed = 99;
  std::mt19937 rng(seed);
  const std::vector<std::string> orient_tokens = {"0", "45", "90", "359", "360", "359.5", "0.25", "1e2", "-45",
                                                  "", "007", "1.", ".5", "400", "180"};
  const std::vector<std::string> point_tokens = {"1,2", "-3,4", "5,-6", "1,2,3", "1;2", "1.5,2", " ", "  ",
                                                 "\t", "1 ,2", "+1,2", "1073741823,0"};
  std::vector<std::pair<std::string, std::string>> docs;  // what, document
  for (const std::string o : {"rectilinear", "octilinear", "any", "c:0,90", "Rectilinear", "c:", "c:0,", "any "})
    docs.push_back({"orientations " + o, "<layout><rules orientations=\"" + o + "\"/></layout>"});
  for (int i = 0; i < 60; ++i) {
    std::string o = "c:";
    const int n = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < n; ++k) o += (k ? "," : "") + orient_tokens[rng() % orient_tokens.size()];
    docs.push_back({"orientations " + o, "<layout><rules orientations=\"" + o + "\"/></layout>"});
  }
  for (int i = 0; i < 80; ++i) {
    std::string pts;
    const int n = 2 + static_cast<int>(rng() % 3);
    for (int k = 0; k < n; ++k) {
      const std::string& t = point_tokens[rng() % point_tokens.size()];
      pts += t;
      if (k + 1 < n && rng() % 4) pts += " ";
    }
    docs.push_back({"points " + pts, "<layout><net name=\"n\"><pin name=\"a\" x=\"1\" y=\"2\"/><pin name=\"b\" "
                                     "x=\"3\" y=\"4\"/><sketch points=\"" + pts + "\"/></net></layout>"});
  }
  const std::string dir = taut::test::temp_dir("schema_strings");
  std::vector<std::string> files;
  for (std::size_t i = 0; i < docs.size(); ++i) {
    files.push_back(dir + "/d" + std::to_string(i) + ".xml");
    taut::test::write_text(files.back(), docs[i].second);
  }
  const auto ok = xmllint(files);
  for (std::size_t i = 0; i < docs.size(); ++i) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " " + docs[i].first);
    const auto r = taut::io::read_layout(files[i]);
    EXPECT_EQ(ok.at(files[i]), r.layout.has_value()) << (r.diagnostics.empty() ? "" : taut::format(r.diagnostics[0]));
  }
}

}  // namespace schema_test
