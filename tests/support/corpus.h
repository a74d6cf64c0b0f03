// Test support shared by the reader, schema and CLI tests: the bad-input corpus manifest
// (tests/data/bad/EXPECTED.tsv) and an independent reference for FORMAT.md numbers.
#pragma once

#include <string>
#include <vector>

namespace taut::test {

// One row of EXPECTED.tsv (its header comment says what each column means).
struct BadCase {
  std::string file, code;
  int line = 0;
  std::string object, lenient_ok, severity;
};

// The rows of EXPECTED.tsv; a malformed row is returned with file "<malformed EXPECTED.tsv
// row: ...>" so the test that reads it fails on it.
std::vector<BadCase> load_bad_cases();

// FORMAT.md integers by a regex and decimal string comparison (no from_chars):
// -1 syntax error, 0 out of range (|v| > 2^30 - 1), 1 accepted.
int reference_int(const std::string& s);

}  // namespace taut::test
