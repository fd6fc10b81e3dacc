#pragma once
// A ray prepared for shapes of revolution around the y axis (lathe, sor): unit direction and origin moved
// to the ray's closest approach to the shape's origin, so that polynomial coefficients stay of the shape's
// size however far the ray starts. A point of the ray is o + u dn with u = f + t |d|; its squared distance
// from the axis is a u^2 + b u + c.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "snell/math/ray.hpp"

namespace snell::geometry {

struct AxialRay {
  math::Vec3 o, dn;
  double f = 0, length = 0;
  double a = 0, b = 0, c = 0;
  double inv_dy = 0;  // 1 / dn.y: the band tests below run per piece, a division each cost more than the rest
  // Where the squared distance from the axis is least, and that least value, once per ray (for a > 0; a ray
  // along the axis keeps c all the way).
  double closest_u = 0, least_rho2 = 0;

  /// False for a degenerate (zero or non-finite) direction.
  bool prepare(const math::Ray& ray) {
    length = math::length(ray.direction);
    if (!(length > 0) || !std::isfinite(length)) return false;
    dn = ray.direction / length;
    f = dot(ray.origin, dn);
    o = ray.origin - f * dn;
    a = dn.x * dn.x + dn.z * dn.z;
    b = 2 * (o.x * dn.x + o.z * dn.z);
    c = o.x * o.x + o.z * o.z;
    inv_dy = 1 / dn.y;  // infinite for a horizontal ray, which the shapes handle apart
    if (a > 0) {
      closest_u = -b / (2 * a);
      least_rho2 = c - b * b / (4 * a);
    }
    return true;
  }
  /// Whether the ray never comes within `radius` of the axis.
  bool misses_cylinder(double radius) const { return a > 0 && least_rho2 > radius * radius * (1 + 1e-9); }
  double t_of(double u) const { return (u - f) / length; }
  double u_of(double t) const { return f + t * length; }

  /// The t interval in which a non-horizontal ray is between heights y_lo and y_hi (a little wider, so
  /// that a root at the band's edge is never outside it).
  std::pair<double, double> band_span(double y_lo, double y_hi) const {
    const double slack = 1e-7 * (1 + std::fabs(y_lo) + std::fabs(y_hi));
    double u0 = (y_lo - slack - o.y) * inv_dy, u1 = (y_hi + slack - o.y) * inv_dy;
    if (u0 > u1) std::swap(u0, u1);
    return {t_of(u0), t_of(u1)};
  }

  /// The heights [y_lo, y_hi] a non-horizontal ray passes while it is within `reach` of the axis and
  /// between u_lo and u_hi (empty, y_lo > y_hi, where it never is). A piece whose height band lies outside
  /// them is out of reach (AxialReach::skips): a loop over a shape's pieces skips it without its band
  /// tests, which cost more than the rest of a shadow ray's test of a sor (sor1.pov: 9 pieces, ~50
  /// instructions each).
  std::pair<double, double> heights_within(double reach, double u_lo, double u_hi) const {
    constexpr double kNone = std::numeric_limits<double>::infinity();
    if (a > 0) {
      const double room = reach * reach - least_rho2;
      if (!(room >= 0)) return {kNone, -kNone};
      const double half = std::sqrt(room / a);
      u_lo = std::max(u_lo, closest_u - half);
      u_hi = std::min(u_hi, closest_u + half);
    }
    if (!(u_lo <= u_hi)) return {kNone, -kNone};
    const double y0 = o.y + u_lo * dn.y, y1 = o.y + u_hi * dn.y;
    return {std::min(y0, y1), std::max(y0, y1)};
  }

  /// Whether a non-horizontal ray stays out of the ring r_min <= r <= r_max while it crosses the height
  /// band [y_lo, y_hi]: its squared distance from the axis, convex in u, is then above r_max^2 or below
  /// r_min^2 there. Lets shapes skip a piece's polynomial (as POV-Ray's per-segment bounding cylinders).
  bool misses_band(double y_lo, double y_hi, double r_min, double r_max) const {
    const double slack = 1e-9 * (1 + std::fabs(y_lo) + std::fabs(y_hi));
    double u0 = (y_lo - slack - o.y) * inv_dy, u1 = (y_hi + slack - o.y) * inv_dy;
    if (u0 > u1) std::swap(u0, u1);
    const auto rho2 = [&](double u) { return (a * u + b) * u + c; };
    const double vertex = a > 0 ? std::clamp(closest_u, u0, u1) : u0;
    const double lowest = std::min({rho2(vertex), rho2(u0), rho2(u1)}),
                 highest = std::max(rho2(u0), rho2(u1));
    return lowest > r_max * r_max * (1 + 1e-9) + slack || highest < r_min * r_min * (1 - 1e-9) - slack;
  }
};

/// How far a shape of revolution reaches, for AxialRay::heights_within: a millionth beyond its radius, and
/// a pad on its pieces' height bands. misses_band widens a band by 1e-9 (1 + |y0| + |y1|) and the ring by
/// a relative 1e-9: a thousand times that covers both and the rounding of the reach's own heights, so
/// every piece skipped is one the band tests would have skipped.
struct AxialReach {
  double pad = 0, reach = 0;
  AxialReach() = default;
  /// `radius` bounds every piece's; `height` the largest |y| of the pieces.
  AxialReach(double radius, double height) : pad(1e-6 * (1 + 2 * height)), reach(radius * (1 + 1e-6) + pad) {}
  /// Whether the piece spanning heights [y0, y1] lies outside `heights` (heights_within's answer).
  bool skips(const std::pair<double, double>& heights, double y0, double y1) const {
    return y1 + pad < heights.first || y0 - pad > heights.second;
  }
};

}  // namespace snell::geometry
