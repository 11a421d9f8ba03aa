// docs/results.md's column table and studies/result_columns.py are generated from the column
// table (analysis/path_columns.hpp): these tests fail when either differs from it. To
// regenerate both after changing the table: scripts/update_schema.sh (it runs these tests with
// SHELLINDENT_WRITE_SCHEMA=1, which writes the files instead of comparing).
#include "io/column_tables.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "analysis/path_columns.hpp"
#include "core/error.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

std::string source_file(const std::string& relative) {
  return std::string(SHELLINDENT_SOURCE_DIR) + "/" + relative;
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool writing() {
  const char* v = std::getenv("SHELLINDENT_WRITE_SCHEMA");
  return v != nullptr && std::string(v) == "1";
}

// `text` with the block between the markers replaced by `block`; empty if a marker is missing.
std::string with_block(const std::string& text, const std::string& block) {
  const std::size_t begin = text.find(kColumnsBegin), end = text.find(kColumnsEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin) return "";
  const std::size_t from = begin + std::string(kColumnsBegin).size() + 1;  // after its newline
  return text.substr(0, from) + block + text.substr(end);
}

TEST(ColumnTables, ResultsDocHasTheTable) {
  const std::string path = source_file("docs/results.md");
  const std::string text = read(path);
  const std::string expected = with_block(text, path_columns_markdown());
  ASSERT_FALSE(expected.empty()) << path << " lacks the markers " << kColumnsBegin;
  if (writing() && text != expected) std::ofstream(path) << expected;
  EXPECT_EQ(writing() ? expected : text, expected)
      << path << " differs from the column table: run scripts/update_schema.sh";
}

TEST(ColumnTables, StudiesModuleHasTheTable) {
  const std::string path = source_file("studies/result_columns.py");
  const std::string expected = path_columns_python();
  if (writing() && read(path) != expected) std::ofstream(path) << expected;
  EXPECT_EQ(read(path), expected) << path << " differs from the column table: run "
                                  << "scripts/update_schema.sh";
}

// The comparison sees a change: a doc with one row altered no longer matches.
TEST(ColumnTables, AnAlteredRowIsADifference) {
  const std::string doc =
      std::string("# x\n") + kColumnsBegin + "\n" + path_columns_markdown() + kColumnsEnd + "\n";
  EXPECT_EQ(with_block(doc, path_columns_markdown()), doc);
  std::string altered = doc;
  altered.replace(altered.find("strain energy"), 6, "stress");
  EXPECT_NE(with_block(altered, path_columns_markdown()), altered);
  EXPECT_EQ(with_block("no markers", path_columns_markdown()), "");
}

TEST(PathColumns, NamesAreUniqueAndEveryColumnIsComputedAndRestored) {
  std::set<std::string> names;
  for (const ColumnSpec& c : path_columns()) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_NE(std::string(c.unit), "") << c.name;
    EXPECT_FALSE(c.description.empty()) << c.name;
    EXPECT_TRUE((c.of_state == nullptr) != (c.of_point == nullptr)) << c.name;
    EXPECT_NE(c.restore, nullptr) << c.name;
    if (c.monitor) {
      EXPECT_NE(c.of_state, nullptr) << c.name << ": a monitor needs the state only";
    }
  }
  EXPECT_EQ(std::string(column_name(PathColumn::kForce)), "force_N");
  EXPECT_EQ(path_columns().back().id, PathColumn::kBranch);
}

// A run has the columns of every run, plus the failure index of each criterion it monitors (in
// table order, whatever the case's order), plus the stability columns (stable, lowest eigenvalue,
// branch) with path.stability, plus the force's error estimate with mesh.error_estimate:
// companion; a run without any of them has exactly the others.
TEST(PathColumns, OptionalColumnsOnlyInRunsThatAskForThem) {
  const std::vector<PathColumn>& base = base_columns();
  EXPECT_EQ(base.back(), PathColumn::kApexMidDeflection);
  EXPECT_EQ(base.size() + 8, path_columns().size());
  const std::vector<PathColumn> run =
      run_columns({Criterion::kQuadraticDelamination, Criterion::kHashin});
  ASSERT_EQ(run.size(), base.size() + 2);
  EXPECT_EQ(run[base.size()], PathColumn::kHashinIndex);
  EXPECT_EQ(run[base.size() + 1], PathColumn::kDelaminationIndex);
  EXPECT_EQ(failure_column(Criterion::kTsaiWu), PathColumn::kTsaiWuIndex);
  EXPECT_EQ(path_monitors(run).size(), path_monitors().size() + 2);
  const std::vector<PathColumn> stable = run_columns({Criterion::kHashin}, true);
  ASSERT_EQ(stable.size(), base.size() + 4);
  EXPECT_EQ(stable[base.size() + 1], PathColumn::kStable);
  EXPECT_EQ(stable[base.size() + 2], PathColumn::kLowestEigenvalue);
  EXPECT_EQ(stable.back(), PathColumn::kBranch);
  EXPECT_EQ(path_column(PathColumn::kStable).group, ColumnGroup::kStability);
  EXPECT_EQ(path_column(PathColumn::kBranch).group, ColumnGroup::kStability);
  EXPECT_EQ(path_monitors(stable).size(), path_monitors().size() + 1);  // not monitors
  const std::vector<PathColumn> companion = run_columns({}, false, true);
  ASSERT_EQ(companion.size(), base.size() + 1);
  EXPECT_EQ(companion.back(), PathColumn::kForceError);                // after every run's columns
  EXPECT_EQ(path_monitors(companion).size(), path_monitors().size());  // not a monitor
}

// The checkpoint's point values restore every column (distinct values, so a swap shows).
TEST(PathColumns, PointValuesRoundTrip) {
  std::vector<double> v;
  std::vector<PathColumn> all;
  for (const ColumnSpec& c : path_columns()) all.push_back(c.id);
  for (std::size_t i = 0; i < all.size(); ++i) v.push_back(1.5 + static_cast<double>(i));
  v[static_cast<std::size_t>(PathColumn::kContactNodes)] = 7;
  v[static_cast<std::size_t>(PathColumn::kIterations)] = 3;
  v[static_cast<std::size_t>(PathColumn::kStable)] = 1;
  v[static_cast<std::size_t>(PathColumn::kBranch)] = 1;  // an integer, like the flag
  EXPECT_EQ(path_point_values(path_point_from_values(v, all), all), v);
  // Without the optional columns the values stop before them.
  v.resize(base_columns().size());
  EXPECT_EQ(path_point_values(path_point_from_values(v)), v);
  EXPECT_THROW(path_point_from_values(std::vector<double>(3, 0.0)), Error);
}

// The monitors are the table's monitor columns, in its order: the force, the apex deflection,
// the contact radius and the apex curvatures.
TEST(PathColumns, MonitorsAreTheMonitorColumns) {
  const std::vector<StateMonitor> m = path_monitors();
  ASSERT_EQ(m.size(), 6u);
  EXPECT_EQ(m[0].name, "force_N");
  EXPECT_EQ(m[5].name, "k22_per_mm");
  IndentationState s;
  s.force = 2;
  s.apex_curvature = Vector3d(3, 4, 5);
  const Eigen::VectorXd values = monitor_values(s);
  EXPECT_EQ(values[0], 2);
  EXPECT_EQ(values[5], 5);
  EXPECT_EQ(m[3].value(s), 3);
}

}  // namespace
}  // namespace si
