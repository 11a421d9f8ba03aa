// The fuzz corpus (tests/fuzz/corpus/) replayed by the ordinary test suite: every file, and
// every input a fuzzer once found to crash (kept there once fixed), must end in a result or an
// input error, without the sanitizers of scripts/fuzz.sh too.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "io/case_file.hpp"
#include "section/layup_notation.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int replay(const std::string& target, void (*one)(const std::string&)) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SHELLINDENT_SOURCE_DIR) / "tests" /
                                                  "fuzz" / "corpus" / target)) {
    const std::string text = read_all(entry.path());
    try {
      one(text);
    } catch (const Error&) {
    }
    ++count;
  }
  return count;
}

TEST(FuzzCorpus, CaseFileReaderEndsInACaseOrAnInputError) {
  EXPECT_GE(replay("case_file", [](const std::string& t) { parse_case_file(t, "corpus.yaml"); }),
            15);
}

TEST(FuzzCorpus, LayupParserRoundTripsItsCompactForm) {
  const int n = replay("layup", [](const std::string& t) {
    const std::vector<double> a = parse_layup(t);  // an input error ends the replay of `t`
    const std::string compact = format_layup(a);
    try {
      EXPECT_EQ(parse_layup(compact), a) << t << " -> " << compact;
    } catch (const Error& e) {
      ADD_FAILURE() << t << " -> " << compact << " refused: " << e.what();
    }
  });
  EXPECT_GE(n, 16);
}

}  // namespace
}  // namespace si
