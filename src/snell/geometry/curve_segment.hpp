#pragma once
// Pieces of 2D splines in POV-Ray's cubic form p(s) = ((a s + b) s + c) s + d, s in [0, 1], as prism,
// lathe and text outlines use them. The point lists follow POV-Ray 3.7's rules (reference, "Prism" and
// "Lathe"): a quadratic piece between P[i+1] and P[i+2] takes P[i] as its control point, a cubic
// (Catmull-Rom) piece also P[i+3], a Bezier piece is four points P[i..i+3].
#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "snell/math/vec3.hpp"

namespace snell::geometry {

using math::Vec2;

enum class SplineKind { linear, quadratic, cubic, bezier };

struct CurveSegment {
  Vec2 a, b, c, d;
  /// Bounding rectangle of the piece over s in [0, 1].
  Vec2 lo, hi;

  Vec2 at(double s) const;
  Vec2 tangent(double s) const;
  /// Coefficients (ascending) of n.u * u(s) + n.v * v(s) + k, the signed distance-like value of the
  /// piece against the line n . q + k = 0.
  std::array<double, 4> against_line(Vec2 n, double k) const;
  /// Whether the line n . q + k = 0 can cross the bounding rectangle.
  bool line_may_cross(Vec2 n, double k) const;
};

/// Whether the line n . q + k = 0 can cross the rectangle [lo, hi]: some corner on or below it, some on or
/// above it.
inline bool line_may_cross_rectangle(Vec2 lo, Vec2 hi, Vec2 n, double k) {
  const double v0 = n.u * lo.u + n.v * lo.v + k, v1 = n.u * hi.u + n.v * lo.v + k;
  const double v2 = n.u * lo.u + n.v * hi.v + k, v3 = n.u * hi.u + n.v * hi.v + k;
  return std::min({v0, v1, v2, v3}) <= 0 && std::max({v0, v1, v2, v3}) >= 0;
}

inline bool CurveSegment::line_may_cross(Vec2 n, double k) const {
  return line_may_cross_rectangle(lo, hi, n, k);
}

/// A straight piece from p to q.
CurveSegment line_segment(Vec2 p, Vec2 q);
/// A quadratic Bezier piece (TrueType outlines).
CurveSegment quadratic_bezier(Vec2 p0, Vec2 control, Vec2 p1);
/// A cubic Bezier piece.
CurveSegment cubic_bezier(Vec2 p0, Vec2 c0, Vec2 c1, Vec2 p1);

/// The pieces of a prism outline: sub-outlines close when a point repeats the sub-outline's first
/// on-curve point, and the next sub-outline starts after it (POV-Ray's Compute_Prism rules).
std::vector<CurveSegment> prism_pieces(SplineKind kind, std::span<const Vec2> points);
/// Whether every sub-outline of a prism's points closes (POV-Ray's Parse_Prism check). For linear
/// splines `first_of_last` receives the first point of the last sub-outline, which closes it.
bool outline_closed(SplineKind kind, std::span<const Vec2> points, Vec2& first_of_last);
/// The pieces of an open lathe profile: n-1 linear, n-2 quadratic, n-3 cubic or n/4 Bezier pieces.
std::vector<CurveSegment> lathe_pieces(SplineKind kind, std::span<const Vec2> points);

}  // namespace snell::geometry
