// Seeded mutations of the files in designs/, through the real commands, as a user's edits or a
// flow's bugs would make them: numbers moved onto other numbers of the file or next to them (pins
// on blockage edges and corners, blockages that touch, sketches off their pins, shared x and y),
// and lines deleted, doubled or cut short. Whatever the file, each command answers with a
// documented exit status (0, 1 or 2; never 3 or a signal), says nothing of a sanitizer (the
// ASan/UBSan tree runs this test too), writes nothing when it refuses the input (2), and when it
// writes a routed file (0 or 1), `taut check` passes it: every net written as routed joins its
// pins, stays in free space and keeps the clearance of <rules>. A failure prints the seed and the
// mutated file; keep each such file as a regression test. A first version of this search found
// the sketch that misses its pin (tighten_test.cpp: Tighten.SketchOffItsPinsIsNotTaken); with
// the binary before that fix, seeds 970044 and 970172 here fail (CHECK-0004: `tighten
// --clearance` and `route --tighten` wrote a net as routed whose wire missed a pin).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "support/run.h"
#include "support/sanitized.h"

namespace taut::test {
namespace mutation_test {

// The numbers of an XML text that stand alone in an attribute value: a run of digits (with a
// leading minus) between a quote, comma or space on each side.
std::vector<std::pair<std::size_t, std::size_t>> numbers(const std::string& t) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  auto apart = [&](std::size_t i) { return t[i] == '"' || t[i] == ',' || std::isspace(static_cast<unsigned char>(t[i])); };
  for (std::size_t i = 1; i < t.size(); ++i) {
    std::size_t j = i;
    if (t[j] == '-') ++j;
    if (j >= t.size() || !std::isdigit(static_cast<unsigned char>(t[j])) || !apart(i - 1)) continue;
    while (j < t.size() && std::isdigit(static_cast<unsigned char>(t[j]))) ++j;
    if (j < t.size() && apart(j)) out.push_back({i, j});
    i = j;
  }
  return out;
}

std::vector<std::string> lines_of(const std::string& t) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at <= t.size()) {
    const std::size_t nl = t.find('\n', at);
    out.push_back(t.substr(at, nl == std::string::npos ? std::string::npos : nl - at));
    if (nl == std::string::npos) break;
    at = nl + 1;
  }
  return out;
}

std::string joined(const std::vector<std::string>& ls) {
  std::string s;
  for (std::size_t i = 0; i < ls.size(); ++i) s += (i ? "\n" : "") + ls[i];
  return s;
}

std::string mutated(std::string t, std::mt19937& rng) {
  const int kind = static_cast<int>(rng() % 8);
  if (kind < 6) {  // a number: onto another of the file's numbers, next to one, or moved a little
    const auto nums = numbers(t);
    if (nums.empty()) return t;
    // half the time a number of a pin or sketch (fewer than the blockages' in most files)
    std::vector<std::pair<std::size_t, std::size_t>> pins;
    for (const auto& n : nums) {
      const std::size_t line = t.rfind('\n', n.first);
      const std::string head = t.substr(line == std::string::npos ? 0 : line, n.first - (line == std::string::npos ? 0 : line));
      if (head.find("<pin") != std::string::npos || head.find("<sketch") != std::string::npos) pins.push_back(n);
    }
    const auto [a, b] = !pins.empty() && rng() % 2 ? pins[rng() % pins.size()] : nums[rng() % nums.size()];
    const auto [c, d] = nums[rng() % nums.size()];
    long long v = std::stoll(t.substr(c, d - c));
    if (kind < 2) v = std::stoll(t.substr(a, b - a)) + std::vector<long long>{-100, -10, -2, -1, 1, 2, 10, 100}[rng() % 8];
    else if (kind < 4) v += static_cast<long long>(rng() % 3) - 1;
    return t.substr(0, a) + std::to_string(v) + t.substr(b);
  }
  std::vector<std::string> ls = lines_of(t);
  if (ls.size() < 2) return t;
  const std::size_t i = rng() % ls.size();
  if (kind == 6) {  // a line deleted or doubled
    if (rng() % 2) ls.erase(ls.begin() + static_cast<long>(i));
    else ls.insert(ls.begin() + static_cast<long>(i), ls[i]);
    return joined(ls);
  }
  return t.substr(0, rng() % t.size());  // cut short
}

TEST(Mutation, DesignsAreAnsweredAndRoutedFilesPassTheCheck) {
  std::vector<std::string> designs;
  for (const auto& e : std::filesystem::directory_iterator(std::string(TAUT_SOURCE_DIR) + "/designs"))
    if (e.path().extension() == ".xml") designs.push_back(e.path().string());
  std::sort(designs.begin(), designs.end());
  ASSERT_GE(designs.size(), 5u);
  const std::string dir = temp_dir("mutation");
  const std::string out = dir + "/out.xml";
  // the commands whose written files must pass the whole check
  const std::vector<std::vector<std::string>> commands = {
      {"route", "-q"},
      {"route", "-q", "--tighten", "--orientations", "rectilinear"},
      {"tighten", "-q", "--clearance"},
      {"route", "-q", "--metric", "combined", "--bend-cost", "100"},
      {"route", "-q", "--orientations", "octilinear", "--tree", "steiner"},
  };
  std::map<int, int> statuses;
  int failed = 0, checked = 0;
  const int count = kSanitized ? 20 : 200;
  for (int seed = 1; seed <= count && failed < 5; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(970000 + seed));
    std::string text = read_text(designs[rng() % designs.size()]);
    for (int k = 0, n = 1 + static_cast<int>(rng() % 4); k < n; ++k) text = mutated(text, rng);
    const std::string file = dir + "/m" + std::to_string(seed) + ".xml";
    write_text(file, text);
    auto fail = [&](const std::string& what, const std::vector<std::string>& args, const RunResult& r) {
      std::string cmd;
      for (const auto& a : args) cmd += " " + a;
      ADD_FAILURE() << "seed " << 970000 + seed << ": taut" << cmd << ": " << what << "\n" << r.err << "\nthe file:\n" << text;
      ++failed;
    };
    auto sane = [&](const std::vector<std::string>& args, const RunResult& r) {
      if (r.status < 0 || r.status > 2) fail("exit status " + std::to_string(r.status), args, r);
      for (const char* s : {"AddressSanitizer", "LeakSanitizer", "runtime error:", "UndefinedBehavior"})
        if (r.err.find(s) != std::string::npos) fail(std::string("sanitizer: ") + s, args, r);
    };
    const std::vector<std::string> check_args{"check", file, "-q"};
    const RunResult c = run_taut(check_args);
    sane(check_args, c);
    ++statuses[c.status];
    // two commands of the five on each file
    for (int k = 0; k < 2; ++k) {
      std::vector<std::string> args = commands[rng() % commands.size()];
      args.insert(args.begin() + 1, file);
      args.insert(args.end(), {"-o", out});
      std::filesystem::remove(out);
      const RunResult r = run_taut(args);
      sane(args, r);
      ++statuses[r.status];
      if (r.status == 2 && file_exists(out)) fail("wrote its output on exit status 2", args, r);
      if ((r.status == 0 || r.status == 1) && !file_exists(out)) fail("wrote nothing on exit status " + std::to_string(r.status), args, r);
      if ((r.status == 0 || r.status == 1) && file_exists(out)) {
        const RunResult k2 = run_taut({"check", out, "-q"});
        ++checked;
        if (k2.status != 0) fail("its output fails taut check (exit " + std::to_string(k2.status) + ")", args, k2);
      }
    }
  }
  std::printf("%d mutated files: exit 0 %d times, 1 %d, 2 %d; %d written files checked\n", count, statuses[0], statuses[1],
              statuses[2], checked);
  EXPECT_EQ(failed, 0);
  EXPECT_GE(checked, count / 3);  // enough mutants route at all
  EXPECT_GE(statuses[2], count / 5);  // and enough are refused
}

}  // namespace mutation_test
}  // namespace taut::test
