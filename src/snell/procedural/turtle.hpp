#pragma once
// The 3D turtle of The Algorithmic Beauty of Plants (Prusinkiewicz & Lindenmayer 1990, ch. 1.5): a position
// and an orientation H (heading), L (left), U (up) with H x L = U. It starts at the origin heading +x with L
// = +y and U = +z, so plain 2D L-systems draw in the xy plane and `+` turns counter-clockwise.
//   F(l)  draw a segment forward (length l, default `step`)      f(l)  move forward without drawing
//   +(a) -(a)  turn left / right about U (default angle)         &(a) ^(a)  pitch down / up about L
//   \(a) /(a)  roll left / right about H                          |  turn around (180 degrees about U)
//   [ ]  push / pop the state                                     !(w)  set the width; `!` multiplies it by
//   taper
//   '(c) set the colour index; `'` adds one                       ~  a leaf here
// Other symbols draw nothing. Each `[` multiplies the width by `taper`, so branches are thinner than their
// parent. A segment continued by another one (no `[`, `]` or move in between) narrows to the next one's
// width, giving cones instead of steps.
#include <cstdint>
#include <vector>

#include "snell/math/vec3.hpp"
#include "snell/procedural/lsystem.hpp"

namespace snell::procedural {

using math::Vec3;

struct TurtleSettings {
  double angle_degrees = 90;
  double step = 1;
  /// Diameter of the first segments.
  double width = 0.1;
  double taper = 1;
  /// Symbols interpreted as another turtle command (e.g. L -> + and R -> - for the Koch curve F=FLFRRFLF).
  std::vector<std::pair<char, char>> aliases;
};

/// A drawn segment: from a (radius r0) to b (radius r1), compact enough for millions.
struct TurtleSegment {
  float a[3], b[3];
  float r0, r1;
  std::uint16_t colour;
};

/// The turtle's frame where a `~` placed a leaf.
struct TurtleFrame {
  Vec3 position, heading, left, up;
  double width = 0;
  int colour = 0;
};

struct TurtleResult {
  std::vector<TurtleSegment> segments;
  std::vector<TurtleFrame> leaves;
  /// The state after the last module (tests compare end points).
  TurtleFrame end;
  /// Box of every position the turtle visited.
  Vec3 lo, hi;
};

/// Throws LSystemError for an unmatched `]`.
TurtleResult interpret(const ModuleString& modules, const TurtleSettings& settings);

}  // namespace snell::procedural
