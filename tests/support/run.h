// Test support: run the taut executable and capture what it says.
#pragma once

#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geom/types.h"

namespace taut::test {

struct RunResult {
  int status = -1;       // exit status, or 128 + signal when killed by a signal
  std::string out;       // stdout
  std::string err;       // stderr
  double seconds = 0.0;  // wall time (reported, never asserted against a tight bound)
};

// Runs TAUT_EXE with args (no shell), stdin from /dev/null, killed after timeout_s seconds.
RunResult run_taut(const std::vector<std::string>& args, double timeout_s = 30.0);
// The same, sending signal `sig` once after `after_s` seconds (if it still runs).
RunResult run_taut_signalled(const std::vector<std::string>& args, double after_s, int sig, double timeout_s = 60.0);

// A fresh empty folder under the test's temporary directory.
std::string temp_dir(const std::string& name);
std::string read_text(const std::string& path);
void write_text(const std::string& path, const std::string& text);
bool file_exists(const std::string& path);
// A layout file t.xml in a fresh folder: <layout name="t" version="1"> + body + </layout>.
std::string layout_file(const std::string& folder, const std::string& body);
// The points of a JSON array of [x, y] pairs (the "points" of `taut path --json`).
std::vector<geom::Point> points_of(const nlohmann::json& pts);

// `taut check FILE --json` on a routed file: every part every router promises passes (the
// lengths and bends as written, the orientations, free space, connectivity). Shorts and the
// clearance of <rules> are allowed to fail, as `route --independent`, the bend metrics and
// tightening keep neither: the exit status is 0, or 1 with every error one of those. Records a
// test failure otherwise.
void expect_routes_check_except_clearance(const std::string& file);
// `taut check --json` on a routed file passes outright (status 0) with its wires in the
// orientations (checked, not skipped), in free space and connected.
void expect_routes_check_ok(const std::string& file);

// The public benchmark data folder (../shared/data beside the checkout, or -DTAUT_SHARED_DATA=),
// or "" when it is absent. Tests that need it skip with a message when it is absent, except
// under CI (environment variable CI set), where its absence is a failure.
std::string shared_data_dir();

#define TAUT_REQUIRE_SHARED_DATA()                                                          \
  do {                                                                                      \
    if (::taut::test::shared_data_dir().empty()) {                                          \
      if (std::getenv("CI")) FAIL() << "shared data not found at " TAUT_SHARED_DATA;        \
      GTEST_SKIP() << "shared data not found at " TAUT_SHARED_DATA " (set -DTAUT_SHARED_DATA)"; \
    }                                                                                       \
  } while (0)

}  // namespace taut::test
