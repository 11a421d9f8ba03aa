// libFuzzer target: the lay-up parser (section/layup_notation.hpp) on arbitrary bytes. Every
// input must end in a ply list or an si::Error; a ply list must survive the round trip through
// its compact form, parse_layup(format_layup(a)) == a (issue 13 item 4: "[0_1000]2" printed as
// "[0_2000]", which the parser refused). Build and run: scripts/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "section/layup_notation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<double> angles;
  try {
    angles = si::parse_layup(text);
  } catch (const si::Error&) {
    return 0;
  }
  const std::string compact = si::format_layup(angles);
  try {
    if (si::parse_layup(compact) == angles) return 0;
  } catch (const si::Error& e) {
    std::fprintf(stderr, "compact form refused: %s\n", e.what());
  }
  std::fprintf(stderr, "round trip broken: '%s' -> '%s'\n", text.c_str(), compact.c_str());
  std::abort();
}
