#include "snell/texture/tiling_patterns.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "snell/math/constants.hpp"

namespace snell::texture {

namespace {

constexpr double kSqrt3 = 1.7320508075688772;

double frac(double v) {
  return v - std::floor(v);
}

/// Squares of side 1 with their edges on integer coordinates; inradius 1/2.
double square_tiles(double x, double z) {
  return std::max(std::fabs(2 * frac(x) - 1), std::fabs(2 * frac(z) - 1));
}

/// Triangles of side 1: in the lattice basis a = (1, 0), b = (1/2, sqrt3/2) a point's fractional
/// coordinates (u, v) lie in the upward triangle when u + v < 1, else in the downward one. The
/// barycentric coordinates times the height are the distances to the three edges, and the inradius is a
/// third of the height, so the ramp is 1 - 3 * (smallest barycentric coordinate).
double triangle_tiles(double x, double z) {
  const double v = 2 * z / kSqrt3;
  const double u = x - v / 2;
  const double fu = frac(u), fv = frac(v);
  if (fu + fv < 1) {
    const double nearest = std::min({1 - fu - fv, fu, fv});
    return 0.5 * std::clamp(1 - 3 * nearest, 0.0, 1.0);
  }
  const double nearest = std::min({fu + fv - 1, 1 - fu, 1 - fv});
  return 0.5 + 0.5 * std::clamp(1 - 3 * nearest, 0.0, 1.0);
}

/// Lozenges (60 degree rhombi of side 1): the cells of the triangle lattice a = (1, 0), b = (1/2, sqrt3/2).
/// Parallel edges lie sqrt3/2 apart and the inradius is sqrt3/4, so in the lattice coordinates the ramp is
/// the square's.
double lozenge_tiles(double x, double z) {
  const double v = 2 * z / kSqrt3;
  return square_tiles(x - v / 2, v);
}

/// The offset of (x, z) from the centre of its hexagon: hexagons of side 1 with a corner along x, centred on
/// (1/2, sqrt3/2) + i (3/2, sqrt3/2) + j (0, sqrt3) (where POV-Ray's tilings 2 and 5 put them). The nearest
/// centre is one of the corners of the lattice cell (basis A = (3/2, sqrt3/2), B = (0, sqrt3)) holding it.
math::Vec2 hexagon_offset(double x, double z) {
  const double px = x - 0.5, pz = z - kSqrt3 / 2;
  const double i = px / 1.5;
  const double j = (pz - i * kSqrt3 / 2) / kSqrt3;
  const double i0 = std::floor(i), j0 = std::floor(j);
  double best = 1e300;
  math::Vec2 offset{0, 0};
  for (int di = 0; di <= 1; ++di)
    for (int dj = 0; dj <= 1; ++dj) {
      const double ci = i0 + di, cj = j0 + dj;
      const double ex = px - ci * 1.5, ez = pz - ci * kSqrt3 / 2 - cj * kSqrt3;
      const double d2 = ex * ex + ez * ez;
      if (d2 < best) {
        best = d2;
        offset = {ex, ez};
      }
    }
  return offset;
}

/// Hexagons: the edges face the six neighbours, at the inradius sqrt3/2, along the normals (0, 1) and
/// (+-sqrt3/2, 1/2).
double hexagon_tiles(double x, double z) {
  const math::Vec2 d = hexagon_offset(x, z);
  const double across = std::max(
      {std::fabs(d.v), std::fabs(kSqrt3 / 2 * d.u + 0.5 * d.v), std::fabs(kSqrt3 / 2 * d.u - 0.5 * d.v)});
  return std::clamp(across / (kSqrt3 / 2), 0.0, 1.0);
}

/// Rhombi in three orientations ("tumbling blocks"): each hexagon of tiling 2 cut from its centre to its
/// corners at 0, 120 and 240 degrees. The rhombus in the sector from corner angle a to a + 120 degrees has
/// sides along e(a) and e(a + 120); in those coordinates (s, t) its ramp is the square's, as for the
/// lozenges. The kinds run against the angle: 2 for the sector starting at 0 degrees, then 1, then 0
/// (matched to POV-Ray's tiling 5 renders).
double rhombus_tiles(double x, double z) {
  const math::Vec2 d = hexagon_offset(x, z);
  constexpr double kThird = 2 * math::kPi / 3;
  const int sector = static_cast<int>(std::floor(std::atan2(d.v, d.u) / kThird) + 3) % 3;
  const double a0 = sector * kThird, a1 = a0 + kThird;
  const double e0u = std::cos(a0), e0v = std::sin(a0), e1u = std::cos(a1), e1v = std::sin(a1);
  const double det = e0u * e1v - e0v * e1u;
  const double s = (d.u * e1v - d.v * e1u) / det, t = (e0u * d.v - e0v * d.u) / det;
  const double ramp = std::clamp(std::max(std::fabs(2 * s - 1), std::fabs(2 * t - 1)), 0.0, 1.0);
  return (2 - sector + ramp) / 3;
}

}  // namespace

TilingPattern::TilingPattern(int tiling) : tiling_(tiling) {
  if (!supported(tiling))
    throw std::invalid_argument("tiling " + std::to_string(tiling) + " is not supported yet");
}

double TilingPattern::value(const Vec3& p) const {
  switch (tiling_) {
    case 2:
      return hexagon_tiles(p.x, p.z);
    case 3:
      return triangle_tiles(p.x, p.z);
    case 4:
      return lozenge_tiles(p.x, p.z);
    case 5:
      return rhombus_tiles(p.x, p.z);
    default:
      return square_tiles(p.x, p.z);
  }
}

}  // namespace snell::texture
