// write_file_atomically: writes and overwrites; on failure the old file is intact, a
// diagnostic names the path, and no temporary file is left behind.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"
#include "support/run.h"

namespace taut::io {
namespace atomic_file_test {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(AtomicFile, WritesAndOverwrites) {
  const std::string dir = test::temp_dir("atomic_write");
  const std::string path = dir + "/out.xml";
  ASSERT_FALSE(write_file_atomically(path, "first").has_value());
  EXPECT_EQ(slurp(path), "first");
  ASSERT_FALSE(write_file_atomically(path, "second, longer").has_value());
  EXPECT_EQ(slurp(path), "second, longer");
  ASSERT_FALSE(write_file_atomically(path, "").has_value());
  EXPECT_EQ(slurp(path), "");
  std::string big(5 << 20, '\0');
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 131 % 251);
  ASSERT_FALSE(write_file_atomically(path, big).has_value());
  EXPECT_EQ(slurp(path), big);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.xml"});
  // Ordinary permissions (not mkstemp's 0600), subject to the umask.
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
}

TEST(AtomicFile, RelativePathInCurrentFolder) {
  const std::string dir = test::temp_dir("atomic_relative");
  const fs::path old = fs::current_path();
  fs::current_path(dir);
  const auto d = write_file_atomically("rel.txt", "hello");
  fs::current_path(old);
  ASSERT_FALSE(d.has_value()) << format(*d);
  EXPECT_EQ(slurp(dir + "/rel.txt"), "hello");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"rel.txt"});
}

TEST(AtomicFile, TargetIsAFolder) {
  const std::string dir = test::temp_dir("atomic_folder");
  const std::string target = dir + "/sub";
  fs::create_directory(target);
  test::write_text(target + "/keep.txt", "kept");
  const auto d = write_file_atomically(target, "data");
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->severity, Severity::Error);
  EXPECT_EQ(d->code.substr(0, 5), "IO-01");
  EXPECT_NE(format(*d).find(target), std::string::npos) << format(*d);
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(slurp(target + "/keep.txt"), "kept");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"sub"});
}

TEST(AtomicFile, MissingFolder) {
  const std::string dir = test::temp_dir("atomic_missing");
  const std::string path = dir + "/no/such/folder/out.xml";
  const auto d = write_file_atomically(path, "data");
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->code, "IO-0100");
  EXPECT_NE(d->message.find(dir + "/no/such/folder"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find(std::strerror(ENOENT)), std::string::npos) << d->message;
  EXPECT_EQ(entries(dir), std::vector<std::string>{});
}

TEST(AtomicFile, ReadOnlyFolderKeepsOldFile) {
  const std::string dir = test::temp_dir("atomic_readonly");
  const std::string path = dir + "/out.xml";
  test::write_text(path, "old contents");
  ASSERT_EQ(::chmod(dir.c_str(), 0555), 0);
  // Root (or CAP_DAC_OVERRIDE) writes anyway: detect it instead of assuming.
  const std::string probe = dir + "/probe";
  std::FILE* f = std::fopen(probe.c_str(), "w");
  if (f) {
    std::fclose(f);
    std::remove(probe.c_str());
    ::chmod(dir.c_str(), 0755);
    GTEST_SKIP() << "permissions are not enforced for this user (root?)";
  }
  const auto d = write_file_atomically(path, "new contents");
  ::chmod(dir.c_str(), 0755);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->code, "IO-0100");
  EXPECT_NE(d->message.find(std::strerror(EACCES)), std::string::npos) << d->message;
  EXPECT_EQ(slurp(path), "old contents");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.xml"});
}

}  // namespace atomic_file_test
}  // namespace taut::io
