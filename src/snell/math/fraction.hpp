#pragma once
// The fractional part of a double, as std::fmod(x, 1.0) gives it (same sign as x), without fmod's cost:
// glibc's fmod runs an exact long-division loop (~90 instructions for the values sample sequences and
// patterns pass), while x - trunc(x) is exact too (the difference keeps only bits x already has), so the
// two agree bit for bit for every finite x, and both are NaN for infinities and NaN.
#include <cmath>

namespace snell::math {

inline double fraction(double x) {
  return x - std::trunc(x);
}

}  // namespace snell::math
