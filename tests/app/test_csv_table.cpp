// The CSV reader behind `shellindent fit`: header, comments, quotes, CRLF, and errors that name
// the file, line and column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_test_support.hpp"
#include "core/error.hpp"
#include "io/csv_table.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

fs::path write(const std::string& name, const std::string& text) {
  const fs::path path = testing::fresh_dir("csv_" + name) / "t.csv";
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string error_of(const fs::path& path, const std::string& column = "") {
  try {
    const CsvTable t = read_csv_table(path.string());
    if (!column.empty()) t.numeric_column(column);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    return e.what();
  }
  return "";
}

TEST(CsvTable, ReadsCommentsQuotesAndCrlf) {
  const auto path =
      write("ok", "# comment\r\n\r\nx, \"y, N\" ,name\r\n1,2,\"a \"\"b\"\"\"\r\n3,4e1,c\r\n");
  const CsvTable t = read_csv_table(path.string());
  ASSERT_EQ(t.names.size(), 3u);
  EXPECT_EQ(t.names[1], "y, N");
  EXPECT_EQ(t.rows[0][2], "a \"b\"");
  EXPECT_EQ(t.lines[1], 5);
  EXPECT_EQ(t.numeric_column("y, N")[1], 40.0);
}

TEST(CsvTable, ErrorsNameFileLineAndColumn) {
  EXPECT_TRUE(testing::contains(error_of(write("fields", "a,b\n1,2\n3\n")), "t.csv:3"));
  EXPECT_TRUE(testing::contains(error_of(write("dup", "a,a\n1,2\n")), "appears twice"));
  EXPECT_TRUE(testing::contains(error_of(write("empty", "")), "no header"));
  const std::string nan = error_of(write("text", "a,b\n1,2\n2,x3\n"), "b");
  EXPECT_TRUE(testing::contains(nan, "t.csv:3: b = 'x3': not a number (column 2)")) << nan;
  EXPECT_TRUE(testing::contains(error_of(write("blank", "a,b\n1,\n"), "b"), "empty cell"));
  EXPECT_TRUE(testing::contains(error_of(write("inf", "a,b\n1,1e999\n"), "b"), "finite"));
  const std::string missing = error_of(write("missing", "depth_mm,force_N\n1,2\n"), "force");
  EXPECT_TRUE(testing::contains(missing, "did you mean 'force_N'")) << missing;
  EXPECT_TRUE(testing::contains(missing, "depth_mm, force_N")) << missing;
}

}  // namespace
}  // namespace si
