#pragma once
// A circular arc turned around the y axis: the curved walls of POV-Ray's `ovus` and `lemon`. In the
// (rho, y) half-plane (rho = distance from the axis) the arc is part of the circle of centre
// (center_rho, center_y) and radius `radius`, limited to y_lo <= y <= y_hi. Its surface is one sheet of a
// torus of major radius |center_rho| (a spindle torus when the circle crosses the axis), so a ray meets it
// at roots of the torus quartic that lie on the arc's own sheet.
#include <array>

#include "snell/geometry/shape.hpp"

namespace snell::geometry {

/// Coefficients (ascending) in u of (|p|^2 + R^2 - r^2)^2 - 4 R^2 (p_x^2 + p_z^2) for p = o + u dn with
/// |dn| = 1: zero on the torus of major radius R around the y axis and minor radius r (both sheets,
/// rho - R and rho + R, when the tube crosses the axis).
std::array<double, 5> torus_quartic(const Vec3& o, const Vec3& dn, double major, double minor);

struct ArcOfRevolution {
  double center_rho = 0;  // negative: the circle's centre lies across the axis (lemon, ovus)
  double center_y = 0;
  double radius = 1;
  double y_lo = 0, y_hi = 1;

  /// Crossings with t in (t_min, t_max), unordered, at most 4; writes t and the outward normal.
  int crossings(const Ray& ray, double t_min, double t_max, double* ts, Vec3* normals) const;
  /// Whether p lies inside the circle turned around the axis, within the arc's height band.
  bool encloses(const Vec3& p) const;
  /// Outward normal at a point of the surface.
  Vec3 normal_at(const Vec3& p) const;
};

}  // namespace snell::geometry
