// Every file in tests/data/bad/ through the real command, as a user meets it: the documented
// exit status, a message naming file:line, the code and the object, no output file written,
// no sanitizer report (the ASan/UBSan tree runs this same test), and an answer in well under a
// second (the time is printed; a 10 s guard only catches hangs such as an entity blow-up).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/corpus.h"
#include "support/run.h"

namespace taut::test {
namespace bad_input_test {

using Row = BadCase;

std::vector<Row> load_rows() { return load_bad_cases(); }

std::string first_line_with(const std::string& text, const std::string& what) {
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line))
    if (line.find(what) != std::string::npos) return line;
  return {};
}

void expect_no_sanitizer_report(const RunResult& r) {
  for (const char* s : {"AddressSanitizer", "LeakSanitizer", "runtime error:", "UndefinedBehavior"})
    EXPECT_EQ(r.err.find(s), std::string::npos) << r.err;
}

class BadInput : public ::testing::TestWithParam<Row> {};

TEST_P(BadInput, AnsweredAsDocumented) {
  const Row& row = GetParam();
  ASSERT_EQ(row.file.find("<malformed"), std::string::npos) << row.file;
  const std::string path = std::string(TAUT_TEST_DATA) + "/bad/" + row.file;
  ASSERT_TRUE(file_exists(path)) << path;
  const bool is_error = row.severity == "error";

  const RunResult r = run_taut({"check", path}, 10.0);
  std::cout << "[ timing   ] " << row.file << ": " << r.seconds << " s\n";
  EXPECT_LT(r.seconds, 10.0) << "hang guard";
  EXPECT_EQ(r.status, is_error ? 2 : 0) << r.err;
  expect_no_sanitizer_report(r);

  const std::string first = first_line_with(r.err, is_error ? ": error: " : ": warning: ");
  ASSERT_FALSE(first.empty()) << r.err;
  const std::string where = row.line > 0 ? path + ":" + std::to_string(row.line) + ":" : path + ":";
  EXPECT_EQ(first.rfind(where, 0), 0u) << "expected to start with " << where << "\n" << first;
  if (row.code == "GEOM-*") {
    EXPECT_NE(first.find("[GEOM-"), std::string::npos) << first;
  } else {
    EXPECT_NE(first.find("[" + row.code + "]"), std::string::npos) << first;
  }
  if (row.object != "-") {
    EXPECT_NE(first.find(row.object), std::string::npos) << first;
  }

  // No output file for invalid input; the output is written when the input is only warned about.
  const std::string dir = temp_dir("bad-" + std::to_string(std::hash<std::string>{}(row.file)));
  const std::string svg = dir + "/out.svg";
  const RunResult rr = run_taut({"render", path, "-o", svg}, 10.0);
  EXPECT_EQ(rr.status, is_error ? 2 : 0) << rr.err;
  EXPECT_EQ(file_exists(svg), !is_error);
  expect_no_sanitizer_report(rr);

  if (row.lenient_ok == "yes" || row.lenient_ok == "no") {
    const RunResult rl = run_taut({"check", "--lenient", path}, 10.0);
    EXPECT_EQ(rl.status, row.lenient_ok == "yes" ? 0 : 2) << rl.err;
    if (row.lenient_ok == "yes") {
      EXPECT_NE(first_line_with(rl.err, ": warning: [" + row.code + "]"), "") << rl.err;
    }
    expect_no_sanitizer_report(rl);
  }
}

std::string row_name(const ::testing::TestParamInfo<Row>& info) {
  std::string n;
  for (char c : info.param.file) n += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(load_rows()), row_name);

}  // namespace bad_input_test
}  // namespace taut::test
