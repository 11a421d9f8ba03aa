// libFuzzer target: the case-file reader (io/case_file.hpp) on arbitrary bytes. Every input must
// end in a case or in an si::Error (the CLI's exit 2): any other exception (a yaml-cpp
// conversion, std::bad_alloc...), a crash, a leak or a hang is a defect. Seeded with the
// studies' case files (tests/fuzz/corpus/case_file/). Build and run: scripts/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "io/case_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const si::CaseFile c = si::parse_case_file(text, "fuzz.yaml");
    (void)c;
  } catch (const si::Error&) {
  }
  return 0;
}
