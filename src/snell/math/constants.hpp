#pragma once
#include <limits>

namespace snell::math {
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kInvPi = 1.0 / kPi;
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr double kDegreesToRadians = kPi / 180.0;

constexpr double radians(double degrees) { return degrees * kDegreesToRadians; }
}  // namespace snell::math
