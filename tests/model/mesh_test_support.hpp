// Helpers shared by the mesh tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "model/mesh.hpp"

namespace si::testing {

// Expects f to throw an input si::Error whose message contains every one of `parts`.
inline void expect_input_error(const std::function<void()>& f,
                               const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no error thrown; expected one mentioning '" << parts.front() << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput) << e.what();
    for (const auto& part : parts) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "message: " << e.what() << "\nexpected to contain: " << part;
    }
  }
}

inline double longest_edge(const Mesh& mesh, int e) {
  const auto x = element_corners(mesh, e);
  double longest = 0;
  for (int k = 0; k < 4; ++k) longest = std::max(longest, (x[(k + 1) % 4] - x[k]).norm());
  return longest;
}

inline Vector3d centroid(const Mesh& mesh, int e) {
  const auto x = element_corners(mesh, e);
  return (x[0] + x[1] + x[2] + x[3]) / 4;
}

// Observed order of convergence of a discretisation error when the element size halves.
inline double observed_order(double coarse_error, double fine_error) {
  return std::log2(std::abs(coarse_error / fine_error));
}

// Every node whose position satisfies `on` is in set `name`, and no other.
inline void expect_set_is(const Mesh& mesh, const std::string& name,
                          const std::function<bool(const Vector3d&)>& on) {
  ASSERT_EQ(mesh.node_sets.count(name), 1u) << "missing node set " << name;
  EXPECT_EQ(mesh.node_sets.at(name), nodes_where(mesh, on)) << "node set " << name;
  EXPECT_FALSE(mesh.node_sets.at(name).empty()) << "node set " << name;
}

}  // namespace si::testing
