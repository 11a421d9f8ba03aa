#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/linalg.hpp"

namespace si {

struct Mesh {
  std::vector<Vector3d> nodes;               // reference mid-surface coordinates (mm)
  std::vector<Vector3d> directors;           // unit reference normal per node
  std::vector<std::array<int, 4>> elements;  // node indices, counter-clockwise about the directors
  std::map<std::string, std::vector<int>>
      node_sets;  // sorted unique node indices, e.g. "edge", "apex"
  int num_nodes() const;
  int num_elements() const;
};

}  // namespace si
