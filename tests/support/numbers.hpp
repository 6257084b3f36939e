// Angles for the tests' closed forms: π, and one degree in radians (π/180).
#pragma once

#include <numbers>

namespace rollspin::test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDeg = kPi / 180.0;

}  // namespace rollspin::test
