#pragma once
// The float built-ins of POV-Ray's function language (POV-Ray 3.7 reference, "Float Functions"; log is
// base 10, ln natural, int truncates). Kept here, not in the parser, so that the register code can
// recognise the ones it evaluates at several points at once (lane kernels, lane_math.hpp).
#include <cstdint>
#include <span>

namespace snell::function {

struct Builtin {
  const char* name;
  double (*unary)(double);           // one argument, or null
  double (*binary)(double, double);  // two arguments, or null
};

/// abs, acos, ... tan, tanh, atan2, pow, mod, div (min, max and select are parsed apart).
std::span<const Builtin> builtins();

/// min and max of two values, as the parser chains them for min(a, b, c...).
double builtin_min(double a, double b);
double builtin_max(double a, double b);

/// Which built-ins the register code evaluates as whole vectors of lanes.
enum class LaneKernel : std::uint8_t { none, abs, sqr, sqrt, sin, cos, atan2, min, max };

/// The kernel of a built-in's entry point; none for any other function.
LaneKernel lane_kernel(double (*unary)(double));
LaneKernel lane_kernel(double (*binary)(double, double));

}  // namespace snell::function
