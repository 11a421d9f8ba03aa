// Helpers shared by the continuation tests that inspect a Branch.
#pragma once

#include <vector>

#include "continuation/branch.hpp"

namespace si::cont::test {

inline std::vector<Event> events_of(const Branch& branch, EventType type) {
  std::vector<Event> out;
  for (const auto& e : branch.events)
    if (e.type == type) out.push_back(e);
  return out;
}

}  // namespace si::cont::test
