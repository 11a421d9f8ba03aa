#include "model/node_set.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_meshes.hpp"

namespace si {
namespace {

TEST(NodeSet, FindsSetsAndNamesTheCallerOnError) {
  Mesh m = testing::square_plate(1, 1);
  EXPECT_EQ(find_node_set(m, "left", "test"), (std::vector<int>{0, 2}));
  m.node_sets["broken"] = {1, 9};
  try {
    find_node_set(m, "broken", "support 3");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().value, "broken");
    EXPECT_NE(std::string(e.what()).find("support 3: node set 'broken' holds node 9"),
              std::string::npos)
        << e.what();
  }
  m.node_sets.clear();
  try {
    find_node_set(m, "edge", "point load 0");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("(available node sets: none)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace si
