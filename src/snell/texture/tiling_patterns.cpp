#include "snell/texture/tiling_patterns.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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

/// Hexagons of side 1 with a corner along x, centred on (1/2, sqrt3/2) + i (3/2, sqrt3/2) + j (0, sqrt3)
/// (where POV-Ray's tiling 2 puts them). The tile is the nearest centre's; its edges face the six
/// neighbours, at the inradius sqrt3/2, along the normals (0, 1) and (+-sqrt3/2, 1/2).
double hexagon_tiles(double x, double z) {
  const double px = x - 0.5, pz = z - kSqrt3 / 2;
  // Lattice coordinates in the basis A = (3/2, sqrt3/2), B = (0, sqrt3).
  const double i = px / 1.5;
  const double j = (pz - i * kSqrt3 / 2) / kSqrt3;
  const double i0 = std::floor(i), j0 = std::floor(j);
  double best = 1e300, dx = 0, dz = 0;
  for (int di = 0; di <= 1; ++di)
    for (int dj = 0; dj <= 1; ++dj) {
      const double ci = i0 + di, cj = j0 + dj;
      const double ex = px - ci * 1.5, ez = pz - ci * kSqrt3 / 2 - cj * kSqrt3;
      const double d2 = ex * ex + ez * ez;
      if (d2 < best) {
        best = d2;
        dx = ex;
        dz = ez;
      }
    }
  const double across =
      std::max({std::fabs(dz), std::fabs(kSqrt3 / 2 * dx + 0.5 * dz), std::fabs(kSqrt3 / 2 * dx - 0.5 * dz)});
  return std::clamp(across / (kSqrt3 / 2), 0.0, 1.0);
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
    default:
      return square_tiles(p.x, p.z);
  }
}

}  // namespace snell::texture
