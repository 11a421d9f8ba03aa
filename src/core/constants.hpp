// Mathematical constants, spelt once (C++17 has no std::numbers).
#pragma once

namespace si {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace si
