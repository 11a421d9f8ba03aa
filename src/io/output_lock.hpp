// One run per output directory. Two runs writing into one directory raced on the same temporary
// names ("cannot rename path_0000.vtu.tmp") or silently mixed their files; the second one is now
// refused. The lock is an flock(2) on DIR/.shellindent.lock, held while the run lives and
// released by the kernel if the process dies (a killed run never leaves a stale lock); the file
// is removed when the lock is released.
//
// Taking the lock is also the check that the directory can be written: it runs before any
// solve, so an unwritable directory is an input error at once, not an I/O error at the end.
#pragma once

#include <filesystem>

#include "core/error.hpp"

namespace si {

// The lock file's name inside the output directory.
constexpr const char* kOutputLockName = ".shellindent.lock";

class OutputLock {
 public:
  // Locks `dir` (which must exist). Throws an input error at `where` (the case's output.dir or
  // the command line's --out) if the directory cannot be written or another shellindent
  // process holds it. Then removes the temporary files ("<name>.tmp") a killed run of ours may
  // have left: nobody else can be writing them.
  OutputLock(const std::filesystem::path& dir, const Where& where);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  std::filesystem::path file_;
  int fd_ = -1;
};

}  // namespace si
