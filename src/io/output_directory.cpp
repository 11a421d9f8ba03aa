#include "io/output_directory.hpp"

namespace si {

void prepare_output_directory(const std::filesystem::path& dir, const Where& where) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw_input("cannot use this output directory" + (ec ? ": " + ec.message() : std::string()),
                where);
}

}  // namespace si
