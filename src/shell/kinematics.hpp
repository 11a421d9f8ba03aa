#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/linalg.hpp"

namespace si {

enum class Kinematics { kLinear, kNonlinear };

}  // namespace si
