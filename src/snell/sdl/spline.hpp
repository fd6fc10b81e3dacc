#pragma once
// `spline { ... }` identifiers (POV-Ray 3.7 reference, "Splines"): parameter/value pairs of up to five
// components, evaluated as `MySpline(t)` with linear, quadratic, cubic (Catmull-Rom) or natural
// (natural cubic) interpolation. Outside the parameter range a spline holds its end value.
#include <array>
#include <vector>

namespace snell::sdl {

struct Spline {
  enum class Kind { linear, quadratic, cubic, natural };
  struct Point {
    double t = 0;
    std::array<double, 5> value{};
  };
  Kind kind = Kind::linear;
  /// Sorted by t; a later point with an equal t comes after the earlier one.
  std::vector<Point> points;
  /// Components of the values, 2..5 (float values are stored as <v, v>, as POV-Ray promotes them).
  int size = 2;

  /// Inserts keeping `points` sorted by t.
  void add(double t, const std::array<double, 5>& value);
  /// The value at `t` with interpolation `kind` (the spline's own unless asked otherwise).
  std::array<double, 5> evaluate(double t, Kind kind) const;
  std::array<double, 5> evaluate(double t) const { return evaluate(t, kind); }
};

}  // namespace snell::sdl
