#include "support/corpus.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

namespace taut::test {

std::vector<BadCase> load_bad_cases() {
  std::vector<BadCase> rows;
  std::ifstream in(std::string(TAUT_TEST_DATA) + "/bad/EXPECTED.tsv");
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {  // column names
      header = false;
      continue;
    }
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, '\t')) f.push_back(cell);
    if (f.size() != 6) {
      rows.push_back({"<malformed EXPECTED.tsv row: " + line + ">", "", 0, "", "", "error"});
      continue;
    }
    rows.push_back({f[0], f[1], std::stoi(f[2]), f[3], f[4], f[5]});
  }
  return rows;
}

int reference_int(const std::string& s) {
  static const std::regex re("-?[0-9]+");
  if (!std::regex_match(s, re)) return -1;
  std::string digits = s[0] == '-' ? s.substr(1) : s;
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
  const std::string max = "1073741823";
  if (digits.size() != max.size()) return digits.size() < max.size() ? 1 : 0;
  return digits <= max ? 1 : 0;
}

}  // namespace taut::test
