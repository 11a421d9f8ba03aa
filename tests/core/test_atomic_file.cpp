#include "core/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

// A fresh per-test directory (ctest runs tests in parallel).
fs::path test_dir() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / ("si_atomic_" + std::string(info->name()));
  fs::remove_all(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFile, WritesTheContentCreatingDirectoriesAndLeavesNoTemporary) {
  const fs::path dir = test_dir();
  const fs::path file = dir / "a" / "b" / "out.txt";
  write_file_atomically(file.string(), std::string("x\0y\n", 4));
  EXPECT_EQ(read(file), std::string("x\0y\n", 4));
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  fs::remove_all(dir);
}

TEST(AtomicFile, ReplacesAnExistingFileWhole) {
  const fs::path dir = test_dir();
  const fs::path file = dir / "out.txt";
  write_file_atomically(file.string(), std::string(100000, 'a'));
  write_file_atomically(file.string(), "short");
  EXPECT_EQ(read(file), "short");
  fs::remove_all(dir);
}

TEST(AtomicFile, StreamWriterGivesTheSameBytesAsTheString) {
  const fs::path dir = test_dir();
  write_file_atomically((dir / "s.txt").string(), [](std::ostream& os) {
    os.precision(17);
    os << 0.1 << '\n';
  });
  std::ostringstream expected;
  expected.precision(17);
  expected << 0.1 << '\n';
  EXPECT_EQ(read(dir / "s.txt"), expected.str());
  fs::remove_all(dir);
}

// A parent that is a file: an input error naming the directory, nothing written.
TEST(AtomicFile, UnwritableDirectoryIsAnInputErrorNamingIt) {
  const fs::path dir = test_dir();
  write_file_atomically((dir / "blocker").string(), "file, not a directory");
  try {
    write_file_atomically((dir / "blocker" / "out.txt").string(), "data");
    ADD_FAILURE() << "writing below a file succeeded";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_NE(std::string(e.what()).find("blocker"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(dir / "blocker"), "file, not a directory");
  fs::remove_all(dir);
}

// A writer that throws half-way leaves the old file and no temporary.
TEST(AtomicFile, FailedWriterKeepsTheOldFile) {
  const fs::path dir = test_dir();
  const fs::path file = dir / "out.txt";
  write_file_atomically(file.string(), "old");
  EXPECT_THROW(write_file_atomically(file.string(),
                                     [](std::ostream& os) {
                                       os << "half";
                                       throw std::runtime_error("writer failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read(file), "old");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace si
