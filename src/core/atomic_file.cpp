#include "core/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace si {

void write_file_atomically(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
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
    out << content;
    out.flush();
    if (!out) throw_input("error while writing '" + tmp.string() + "'");
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw_input("cannot write '" + target.string() + "'");
  }
}

}  // namespace si
