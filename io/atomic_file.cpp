// write_file_atomically: mkstemp in the destination's folder, write, fsync, rename.
//
// The temporary file lives in the same folder as the destination because rename(2) is only
// atomic within one file system. The folder is fsync'ed after the rename so the new name is
// durable too (best effort: some file systems refuse fsync on folders).
#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace taut::io {
namespace {

// Diagnostic codes (listed in the README):
//   IO-0100 cannot create the temporary file next to the destination
//   IO-0101 cannot write (or fsync/close) the temporary file
//   IO-0102 cannot rename the temporary file over the destination
//   IO-0103 the destination is a folder
Diagnostic io_error(const char* code, const std::string& path, const std::string& what,
                    int err) {
  Diagnostic d;
  d.severity = Severity::Error;
  d.code = code;
  d.file = path;
  d.message = what + ": " + std::strerror(err);
  return d;
}

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

}  // namespace

std::optional<Diagnostic> write_file_atomically(const std::string& path, std::string_view bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    Diagnostic d = io_error("IO-0103", path, "cannot write '" + path + "'", EISDIR);
    return d;
  }
  const std::string folder = folder_of(path);
  const auto slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  std::string tmpl = (folder == "/" ? std::string("/") : folder + "/") + "." + base + ".tmp.XXXXXX";
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');

  const int fd = ::mkstemp(name.data());
  if (fd < 0) {
    return io_error("IO-0100", path,
                    "cannot create a temporary file in '" + folder + "' to write '" + path + "'",
                    errno);
  }
  const std::string tmp(name.data());
  auto fail = [&](const char* code, const std::string& what, int err) {
    ::unlink(tmp.c_str());
    return io_error(code, path, what, err);
  };

  // mkstemp creates the file 0600; give it the usual permissions (subject to the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);

  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      return fail("IO-0101", "cannot write '" + path + "'", err);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    return fail("IO-0101", "cannot write '" + path + "' (fsync)", err);
  }
  if (::close(fd) != 0) return fail("IO-0101", "cannot write '" + path + "' (close)", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0)
    return fail("IO-0102", "cannot rename the temporary file to '" + path + "'", errno);

  const int dfd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (dfd >= 0) {
    ::fsync(dfd);  // best effort: the data is already in place under its name
    ::close(dfd);
  }
  return std::nullopt;
}

}  // namespace taut::io
