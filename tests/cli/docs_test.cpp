// The README is part of the contract: every diagnostic code used in the sources is listed
// there, and the quick start names the two commands.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>

#include "support/run.h"

namespace taut::test {
namespace docs_test {
namespace fs = std::filesystem;

std::set<std::string> codes_in_sources() {
  const std::regex code(R"(\b(IO|GEOM|LAYOUT|CLI|CHECK|ROUTE|VORONOI)-[0-9]{4}\b)");
  std::set<std::string> codes;
  for (const char* dir : {"geom", "io", "router", "tools"}) {
    for (const auto& e : fs::recursive_directory_iterator(fs::path(TAUT_SOURCE_DIR) / dir)) {
      const auto ext = e.path().extension();
      if (ext != ".cpp" && ext != ".h") continue;
      const std::string text = read_text(e.path().string());
      for (auto it = std::sregex_iterator(text.begin(), text.end(), code);
           it != std::sregex_iterator(); ++it)
        codes.insert(it->str());
    }
  }
  return codes;
}

TEST(Docs, EveryDiagnosticCodeIsInTheReadme) {
  const std::string readme = read_text(std::string(TAUT_SOURCE_DIR) + "/README.md");
  const auto codes = codes_in_sources();
  EXPECT_GT(codes.size(), 10u);
  for (const auto& c : codes) EXPECT_NE(readme.find("`" + c + "`"), std::string::npos) << c;
}

TEST(Docs, QuickStart) {
  const std::string readme = read_text(std::string(TAUT_SOURCE_DIR) + "/README.md");
  EXPECT_NE(readme.find("make run"), std::string::npos);
  EXPECT_NE(readme.find("make test"), std::string::npos);
}

}  // namespace docs_test
}  // namespace taut::test
