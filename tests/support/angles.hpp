#pragma once
// Degrees in the tests: write 30 * kDeg for 30 degrees in radians.

#include <numbers>

namespace littermap::test {

inline constexpr double kDeg = std::numbers::pi / 180;

}  // namespace littermap::test
