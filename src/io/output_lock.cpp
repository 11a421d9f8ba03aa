#include "io/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace si {
namespace {

// Temporary files of our atomic writes: "<result>.tmp" for the results we write (path.csv,
// path_0010.vtu, checkpoint.json, static.json, sweep.csv, ...). Only these are removed: a user's
// own "notes.tmp" in the directory is left alone.
bool is_our_temporary(const std::string& name) {
  const std::string suffix = ".tmp";
  if (name.size() <= suffix.size() || name.compare(name.size() - 4, 4, suffix) != 0) return false;
  for (const char* prefix : {"path", "events", "checkpoint", "static", "sweep", "case.yaml"})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

void remove_stale_temporaries(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && is_our_temporary(entry.path().filename().string()))
      std::filesystem::remove(entry.path(), ec);
}

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& dir, const Where& where)
    : file_(dir / kOutputLockName) {
  // The file may be unlinked by the holder between our open() and flock(): then we hold a lock
  // on a file nobody else will see, so check that the path still names the locked file.
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw_input(std::string("cannot write in the output directory: ") + std::strerror(errno),
                  where);
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK)
        throw_input(
            "another shellindent run is writing into this output directory; wait for it to "
            "end or choose another directory",
            where);
      throw_input(std::string("cannot lock the output directory: ") + std::strerror(error), where);
    }
    struct stat held {};
    struct stat named {};
    if (::fstat(fd_, &held) == 0 && ::stat(file_.c_str(), &named) == 0 &&
        held.st_dev == named.st_dev && held.st_ino == named.st_ino) {
      remove_stale_temporaries(dir);
      return;
    }
    ::close(fd_);
    fd_ = -1;
  }
  throw_input("cannot lock the output directory (its lock file keeps changing)", where);
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());  // before unlocking: a waiting run then sees a fresh file
  ::close(fd_);
}

}  // namespace si
