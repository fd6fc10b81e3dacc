#include "snell/geometry/curve_segment.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {
namespace {

Vec2 operator+(Vec2 p, Vec2 q) {
  return {p.u + q.u, p.v + q.v};
}
Vec2 operator-(Vec2 p, Vec2 q) {
  return {p.u - q.u, p.v - q.v};
}
Vec2 operator*(double s, Vec2 p) {
  return {s * p.u, s * p.v};
}

// Extremes of one coordinate of a piece: its ends and where its derivative 3a s^2 + 2b s + c vanishes.
void coordinate_range(double a, double b, double c, double d, double& lo, double& hi) {
  const auto value = [&](double s) { return ((a * s + b) * s + c) * s + d; };
  lo = std::min(value(0), value(1));
  hi = std::max(value(0), value(1));
  double s0 = 0, s1 = 0;
  if ((a != 0 || b != 0) && solve_quadratic(3 * a, 2 * b, c, s0, s1)) {
    for (const double s : {s0, s1}) {
      if (s > 0 && s < 1) {
        lo = std::min(lo, value(s));
        hi = std::max(hi, value(s));
      }
    }
  }
}

CurveSegment from_coefficients(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  CurveSegment seg{a, b, c, d, {}, {}};
  coordinate_range(a.u, b.u, c.u, d.u, seg.lo.u, seg.hi.u);
  coordinate_range(a.v, b.v, c.v, d.v, seg.lo.v, seg.hi.v);
  return seg;
}

// The piece that starts at points[i] (Bezier, linear) or whose window starts there (quadratic, cubic),
// with the blending matrices of POV-Ray's Compute_Prism / Compute_Lathe.
CurveSegment piece(SplineKind kind, std::span<const Vec2> p, size_t i) {
  switch (kind) {
    case SplineKind::linear:
      return line_segment(p[i], p[i + 1]);
    case SplineKind::quadratic:
      return from_coefficients({}, 0.5 * p[i] - p[i + 1] + 0.5 * p[i + 2], 0.5 * (p[i + 2] - p[i]), p[i + 1]);
    case SplineKind::cubic:
      return from_coefficients(-0.5 * p[i] + 1.5 * p[i + 1] - 1.5 * p[i + 2] + 0.5 * p[i + 3],
                               p[i] - 2.5 * p[i + 1] + 2.0 * p[i + 2] - 0.5 * p[i + 3],
                               0.5 * (p[i + 2] - p[i]), p[i + 1]);
    case SplineKind::bezier:
      return cubic_bezier(p[i], p[i + 1], p[i + 2], p[i + 3]);
  }
  throw std::invalid_argument("unknown spline kind");
}

// Points a piece's window needs beyond its first one.
size_t window(SplineKind kind) {
  switch (kind) {
    case SplineKind::linear:
      return 1;
    case SplineKind::quadratic:
      return 2;
    default:
      return 3;
  }
}

bool same_point(Vec2 p, Vec2 q) {
  constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON for "the outline is closed"
  return std::fabs(p.u - q.u) < kEpsilon && std::fabs(p.v - q.v) < kEpsilon;
}

}  // namespace

Vec2 CurveSegment::at(double s) const {
  return {((a.u * s + b.u) * s + c.u) * s + d.u, ((a.v * s + b.v) * s + c.v) * s + d.v};
}

Vec2 CurveSegment::tangent(double s) const {
  return {(3 * a.u * s + 2 * b.u) * s + c.u, (3 * a.v * s + 2 * b.v) * s + c.v};
}

std::array<double, 4> CurveSegment::against_line(Vec2 n, double k) const {
  return {n.u * d.u + n.v * d.v + k, n.u * c.u + n.v * c.v, n.u * b.u + n.v * b.v, n.u * a.u + n.v * a.v};
}

CurveSegment line_segment(Vec2 p, Vec2 q) {
  return from_coefficients({}, {}, q - p, p);
}

CurveSegment quadratic_bezier(Vec2 p0, Vec2 control, Vec2 p1) {
  // (1-s)^2 p0 + 2 s (1-s) control + s^2 p1, expanded in powers of s.
  return from_coefficients({}, p0 - 2 * control + p1, 2 * (control - p0), p0);
}

CurveSegment cubic_bezier(Vec2 p0, Vec2 c0, Vec2 c1, Vec2 p1) {
  // Bernstein form expanded in powers of s.
  return from_coefficients(p1 - 3 * c1 + 3 * c0 - p0, 3 * c1 - 6 * c0 + 3 * p0, 3 * (c0 - p0), p0);
}

std::vector<CurveSegment> prism_pieces(SplineKind kind, std::span<const Vec2> points) {
  std::vector<CurveSegment> pieces;
  const size_t extra = window(kind);
  // The first on-curve point of the current sub-outline (quadratic and cubic lead with a control point).
  const size_t lead = kind == SplineKind::quadratic || kind == SplineKind::cubic ? 1 : 0;
  if (points.size() <= extra) return pieces;
  Vec2 first = points[lead];
  for (size_t i = 0; i + extra < points.size(); ++i) {
    pieces.push_back(piece(kind, points, i));
    switch (kind) {
      case SplineKind::bezier:
        i += 3;
        break;
      case SplineKind::linear:
        if (same_point(points[i + 1], first)) {
          ++i;
          if (i + 1 < points.size()) first = points[i + 1];
        }
        break;
      case SplineKind::quadratic:
      case SplineKind::cubic:
        if (same_point(points[i + 2], first)) {
          i += kind == SplineKind::quadratic ? 2 : 3;
          if (i + 2 < points.size()) first = points[i + 2];
        }
        break;
    }
  }
  return pieces;
}

bool outline_closed(SplineKind kind, std::span<const Vec2> points, Vec2& first_of_last) {
  if (points.empty()) return false;
  if (kind == SplineKind::bezier) {
    // Each sub-outline is a run of pieces that join end to start and ends at its own first point.
    if (points.size() % 4 != 0) return false;
    size_t loop_start = 0;
    for (size_t i = 4; i < points.size(); i += 4) {
      if (same_point(points[i], points[i - 1])) continue;
      if (!same_point(points[i - 1], points[loop_start])) return false;
      loop_start = i;
    }
    return same_point(points.back(), points[loop_start]);
  }
  const size_t lead = kind == SplineKind::linear ? 0 : 1;
  const size_t skip = window(kind);  // a closing point is followed by this many points of the next
  if (points.size() <= lead) return false;
  first_of_last = points[lead];
  bool closed = false;
  for (size_t i = lead + 1; i < points.size(); ++i) {
    closed = false;
    if (same_point(points[i], first_of_last)) {
      i += skip;
      if (i < points.size()) first_of_last = points[i];
      closed = true;
    }
  }
  return closed;
}

std::vector<CurveSegment> lathe_pieces(SplineKind kind, std::span<const Vec2> points) {
  std::vector<CurveSegment> pieces;
  const size_t extra = window(kind);
  const size_t step = kind == SplineKind::bezier ? 4 : 1;
  for (size_t i = 0; i + extra < points.size(); i += step) pieces.push_back(piece(kind, points, i));
  return pieces;
}

}  // namespace snell::geometry
