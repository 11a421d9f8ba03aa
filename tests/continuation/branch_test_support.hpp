// Helpers shared by the continuation tests that inspect a Branch.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "continuation/branch.hpp"
#include "continuation/settings.hpp"

namespace si::cont::test {

inline std::vector<Event> events_of(const Branch& branch, EventType type) {
  std::vector<Event> out;
  for (const auto& e : branch.events)
    if (e.type == type) out.push_back(e);
  return out;
}

// The library hands checkpoints to the caller's writer (shellindent's is core/atomic_file.hpp);
// a plain one is enough for a test.
inline FileWriter plain_file_writer() {
  return [](const std::string& path, const std::string& content) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << content;
  };
}

}  // namespace si::cont::test
