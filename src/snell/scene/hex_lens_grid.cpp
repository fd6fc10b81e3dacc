#include "snell/scene/hex_lens_grid.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "snell/math/constants.hpp"

namespace snell::scene {

namespace {

/// A lattice point as (ring, step along the ring) of a hexagonal lattice: ring r has 6r points, corners at
/// steps 0, r, 2r, ... The position is computed from the six corner directions.
math::Vec2 lattice_point(int ring, int step, double spacing) {
  if (ring == 0) return {0, 0};
  const int side = step / ring, along = step % ring;
  // Corners of ring r lie at r*spacing in the directions 0, 60, ..., 300 degrees (a corner on the u axis,
  // as POV-Ray's grids have).
  const double a0 = side * math::kPi / 3, a1 = (side + 1) * math::kPi / 3;
  const double t = static_cast<double>(along) / ring;
  const double r = ring * spacing;
  return {r * ((1 - t) * std::cos(a0) + t * std::cos(a1)), r * ((1 - t) * std::sin(a0) + t * std::sin(a1))};
}

/// The grid's points in batch order: the centre and the outer corners first (a coarse hexagon), then
/// the corners of the inner rings, then the rest of the outer rings' points.
/// POV-Ray's lattice spacing for a grid of `rings` rings: 1 / ((rings + 1) sqrt(3)), i.e. 0.288675,
/// 0.192450 and 0.144338 for its 7, 19 and 37 point grids.
double lattice_spacing(int rings) {
  return 1 / ((rings + 1) * std::sqrt(3.0));
}

std::vector<math::Vec2> ordered_grid(int rings) {
  const double spacing = lattice_spacing(rings);
  std::vector<math::Vec2> points{lattice_point(0, 0, spacing)};
  for (int ring = rings; ring >= 1; --ring)
    for (int side = 0; side < 6; ++side) points.push_back(lattice_point(ring, side * ring, spacing));
  for (int ring = rings; ring >= 2; --ring)
    for (int along = 1; along < ring; ++along)
      for (int side = 0; side < 6; ++side)
        points.push_back(lattice_point(ring, side * ring + along, spacing));
  return points;
}

}  // namespace

std::optional<math::Vec2> hex_lens_sample(int index, int blur_samples, double jitter_u, double jitter_v) {
  static const std::array<std::vector<math::Vec2>, 3> grids{ordered_grid(1), ordered_grid(2),
                                                            ordered_grid(3)};
  const int rings = blur_samples == 7 ? 1 : blur_samples == 19 ? 2 : blur_samples == 37 ? 3 : 0;
  if (rings == 0 || index < 0 || index >= blur_samples) return std::nullopt;
  const std::vector<math::Vec2>& grid = grids[static_cast<size_t>(rings - 1)];
  // Jitter within the lattice cell: at most half the spacing each way (POV-Ray's HexJitter).
  const double half_spacing = 0.5 * lattice_spacing(rings);
  const math::Vec2 p = grid[static_cast<size_t>(index)];
  return math::Vec2{p.u + (2 * jitter_u - 1) * half_spacing, p.v + (2 * jitter_v - 1) * half_spacing};
}

}  // namespace snell::scene
