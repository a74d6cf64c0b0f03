// Test support: run the taut executable and capture what it says.
#pragma once

#include <string>
#include <vector>

namespace taut::test {

struct RunResult {
  int status = -1;       // exit status, or 128 + signal when killed by a signal
  std::string out;       // stdout
  std::string err;       // stderr
  double seconds = 0.0;  // wall time (reported, never asserted against a tight bound)
};

// Runs TAUT_EXE with args (no shell), stdin from /dev/null, killed after timeout_s seconds.
RunResult run_taut(const std::vector<std::string>& args, double timeout_s = 30.0);

// A fresh empty folder under the test's temporary directory.
std::string temp_dir(const std::string& name);
std::string read_text(const std::string& path);
void write_text(const std::string& path, const std::string& text);
bool file_exists(const std::string& path);

}  // namespace taut::test
