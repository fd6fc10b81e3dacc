#include "snell/texture/cellular_patterns.hpp"

#include <algorithm>
#include <cmath>

#include "snell/texture/povray_noise.hpp"

namespace snell::texture {

namespace {

/// POV-Ray's EPSILON: cells rounds coordinates within it of an integer up, crackle down (pattern.cpp).
constexpr double kFaceTolerance = 1e-10;

int cell_of(double x) {
  return static_cast<int>(std::floor(x + kFaceTolerance));
}

double minkowski(const Vec3& d, double metric) {
  if (metric == 2) return dot(d, d);  // squared; the root is taken once at the end
  if (metric == 1) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
  return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
         std::pow(std::fabs(d.z), metric);
}

double minkowski_root(double sum, double metric) {
  if (metric == 2) return std::sqrt(sum);
  if (metric == 1) return sum;
  return std::pow(sum, 1 / metric);
}

}  // namespace

double CellsPattern::value(const Vec3& p) const {
  return std::min(
      povray_pattern_random(static_cast<size_t>(povray_hash3d(cell_of(p.x), cell_of(p.y), cell_of(p.z)))),
      1.0);
}

double CracklePattern::value(const Vec3& p) const {
  const double metric = params_.metric;
  auto cell = [](double x) { return static_cast<int>(std::floor(x - kFaceTolerance)); };
  const int cx = cell(p.x), cy = cell(p.y), cz = cell(p.z);
  // With one point per cube, the three nearest points lie in the 3x3x3 block around p or in the cubes
  // glued onto its faces (two cubes away along one axis only): 27 + 6*9 = 81 candidates, visited in
  // POV-Ray's order (which decides ties).
  double nearest[3] = {INFINITY, INFINITY, INFINITY};
  Vec3 nearest_point{0, 0, 0};
  for (int dx = -2; dx <= 2; ++dx) {
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dz = -2; dz <= 2; ++dz) {
        if ((std::abs(dx) == 2) + (std::abs(dy) == 2) + (std::abs(dz) == 2) > 1) continue;
        const Vec3 q = povray_point_in_cube(cx + dx, cy + dy, cz + dz);
        const double d = minkowski(q - p, metric);
        if (d < nearest[0]) {
          nearest[2] = nearest[1];
          nearest[1] = nearest[0];
          nearest[0] = d;
          nearest_point = q;
        } else if (d < nearest[1]) {
          nearest[2] = nearest[1];
          nearest[1] = d;
        } else if (d < nearest[2]) {
          nearest[2] = d;
        }
      }
    }
  }
  if (params_.solid) {
    // One smooth-noise value per cell, taken at the cell's point (as POV-Ray does).
    return povray_noise(nearest_point, params_.noise.get());
  }
  const double offset_term = params_.offset == 0 ? 0 : minkowski(Vec3{params_.offset, 0, 0}, metric);
  double sum = 0;
  const double weights[3] = {params_.form.x, params_.form.y, params_.form.z};
  for (int i = 0; i < 3; ++i)
    if (weights[i] != 0) sum += weights[i] * minkowski_root(nearest[i] + offset_term, metric);
  return std::clamp(sum, 0.0, 1.0);
}

}  // namespace snell::texture
