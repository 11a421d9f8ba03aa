#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

// fsync of a file or directory by path; false (errno set) if it cannot be opened or synced.
bool sync_path(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  const int saved = errno;
  ::close(fd);
  errno = saved;
  return ok;
}

void fail(const fs::path& tmp, const std::string& what) {
  const std::string reason = std::strerror(errno);
  std::error_code ec;
  fs::remove(tmp, ec);
  throw_input(what + ": " + reason);
}

}  // namespace

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec)
      throw_input("cannot create directory '" + target.parent_path().string() +
                  "': " + ec.message());
  }
  const fs::path tmp = target.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw_input("cannot write '" + tmp.string() + "': " + std::strerror(errno));
    try {
      write(out);
    } catch (...) {
      out.close();
      fs::remove(tmp, ec);
      throw;
    }
    out.flush();
    if (!out) {
      fs::remove(tmp, ec);
      throw_input("error while writing '" + tmp.string() + "' (disk full?)");
    }
  }
  // The data first, then the name: a crash between them leaves the old file.
  if (!sync_path(tmp, O_RDONLY)) fail(tmp, "cannot sync '" + tmp.string() + "' to disk");
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw_input("cannot write '" + target.string() + "'");
  }
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!sync_path(dir, O_RDONLY | O_DIRECTORY))
    throw_input("cannot sync directory '" + dir.string() + "': " + std::strerror(errno));
}

void write_file_atomically(const std::string& path, const std::string& content) {
  write_file_atomically(path, [&](std::ostream& out) { out << content; });
}

}  // namespace si
