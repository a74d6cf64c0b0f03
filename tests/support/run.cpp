#include "support/run.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace taut::test {
namespace fs = std::filesystem;

RunResult run_taut(const std::vector<std::string>& args, double timeout_s) { return run_taut_signalled(args, -1, 0, timeout_s); }

RunResult run_taut_signalled(const std::vector<std::string>& args, double after_s, int sig, double timeout_s) {
  const fs::path dir = fs::temp_directory_path() /
                       ("taut-run-" + std::to_string(::getpid()) + "-" +
                        std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
  fs::create_directories(dir);
  const std::string out_path = (dir / "out").string(), err_path = (dir / "err").string();

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> argv_s{TAUT_EXE};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);

  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, TAUT_EXE, &fa, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot spawn " TAUT_EXE);
  posix_spawn_file_actions_destroy(&fa);

  int wstatus = 0;
  bool signalled = false;
  for (;;) {
    const pid_t r = ::waitpid(pid, &wstatus, WNOHANG);
    if (r == pid) break;
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (sig != 0 && after_s >= 0 && !signalled && el > after_s) {
      ::kill(pid, sig);
      signalled = true;
    }
    if (el > timeout_s) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &wstatus, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  RunResult res;
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
  res.out = read_text(out_path);
  res.err = read_text(err_path);
  fs::remove_all(dir);
  return res;
}

std::string temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("taut-test-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string layout_file(const std::string& folder, const std::string& body) {
  const std::string file = temp_dir(folder) + "/t.xml";
  write_text(file, "<layout name=\"t\" version=\"1\">\n" + body + "</layout>\n");
  return file;
}

std::vector<geom::Point> points_of(const nlohmann::json& pts) {
  std::vector<geom::Point> out;
  for (const auto& p : pts) out.push_back({p[0].get<int>(), p[1].get<int>()});
  return out;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

bool file_exists(const std::string& path) { return fs::exists(path); }

std::string shared_data_dir() {
  return fs::is_directory(fs::path(TAUT_SHARED_DATA) / "movingai") ? std::string(TAUT_SHARED_DATA) : "";
}

void expect_routes_check_ok(const std::string& file) {
  const RunResult r = run_taut({"check", file, "--json"});
  EXPECT_EQ(r.status, 0) << file << ": " << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("routes_check")) << file;
  const nlohmann::json& c = j["routes_check"];
  EXPECT_EQ(c["orientations"], "ok") << file;
  EXPECT_EQ(c["free_space"], "ok") << file;
  EXPECT_EQ(c["connectivity"], "ok") << file;
}

void expect_routes_check_except_clearance(const std::string& file) {
  const RunResult r = run_taut({"check", file, "--json"});
  ASSERT_TRUE(r.status == 0 || r.status == 1) << file << ": " << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("routes_check")) << file;
  const nlohmann::json& c = j["routes_check"];
  EXPECT_EQ(c["lengths_and_bends"], "ok") << file << ": " << r.err;
  EXPECT_NE(c["orientations"], "failed") << file << ": " << r.err;
  EXPECT_EQ(c["free_space"], "ok") << file << ": " << r.err;
  EXPECT_EQ(c["connectivity"], "ok") << file << ": " << r.err;
  const int allowed = c["problems"]["shorts"].get<int>() + c["problems"]["blockage_clearance"].get<int>() +
                      c["problems"]["net_clearance"].get<int>();
  EXPECT_EQ(j["errors"].get<int>(), allowed) << file << ": " << r.err;
  EXPECT_EQ(r.status, allowed == 0 ? 0 : 1) << file;
}

}  // namespace taut::test
