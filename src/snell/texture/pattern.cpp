#include "snell/texture/pattern.hpp"

#include <cmath>
#include <stdexcept>

namespace snell::texture {

namespace {
// The tolerance POV-Ray's block patterns add before flooring (documented as avoiding "coincident surface"
// noise on planes through integer coordinates).
constexpr double kBlockTolerance = 1e-6;

double frac(double v) {
  return v - std::floor(v);
}
}  // namespace

int CheckerPattern::block(const Vec3& p) const {
  const long long sum = static_cast<long long>(std::floor(p.x + kBlockTolerance)) +
                        static_cast<long long>(std::floor(p.y + kBlockTolerance)) +
                        static_cast<long long>(std::floor(p.z + kBlockTolerance));
  return static_cast<int>(sum & 1);
}

// The hexagons are found on a grid of half-triangle cells (0.5 wide in x, sqrt(3)/2 deep in z) that
// repeats every 6x6 cells: cells in columns 0, 2, 3, 5 lie inside one hexagon, cells in columns 1 and 4
// are split by a hexagon edge along their diagonal. POV-Ray 3.7 "hexagon" (pattern.cpp) folds x by
// |x| and shifts negative z by one period, which we follow so that the tiling matches.
int HexagonPattern::block(const Vec3& p) const {
  constexpr double kCellWidth = 0.5;
  constexpr double kCellDepth = 0.866025404;       // sqrt(3)/2
  constexpr double kPeriodDepth = 6 * kCellDepth;  // 5.196152424
  const double x = std::fabs(p.x);
  const double z = p.z < 0 ? kPeriodDepth - std::fabs(p.z) : p.z;
  double xs = x / kCellWidth, zs = z / kCellDepth;
  xs -= std::floor(xs / 6) * 6;
  zs -= std::floor(zs / 6) * 6;
  const int column = static_cast<int>(std::floor(xs)) % 6;
  const int row = static_cast<int>(std::floor(zs)) % 6;
  // Entry by row for the whole-hexagon columns.
  static constexpr int kOuterColumns[6] = {0, 1, 1, 2, 2, 0};  // columns 0 and 5
  static constexpr int kInnerColumns[6] = {2, 2, 0, 0, 1, 1};  // columns 2 and 3
  // Entry by row for the split columns, below and above the diagonal.
  static constexpr int kBelowDiagonal[6] = {0, 2, 1, 0, 2, 1};
  static constexpr int kAboveDiagonal[6] = {2, 1, 0, 2, 1, 0};
  switch (column) {
    case 0:
    case 5:
      return kOuterColumns[row];
    case 2:
    case 3:
      return kInnerColumns[row];
    default: {
      double xl = xs - column;
      const double zl = zs - row;
      if ((column + row) % 2 == 1) xl = 1 - xl;  // edges of negative slope: mirror the cell
      if (xl == 0) xl = 1e-4;
      return zl / xl < 1 ? kBelowDiagonal[row] : kAboveDiagonal[row];
    }
  }
}

BrickPattern::BrickPattern(const Vec3& size, double mortar) : size_(size), mortar_(mortar) {
  if (!(size.x > 0 && size.y > 0 && size.z > 0))
    throw std::invalid_argument("brick_size components must be positive");
  if (!(mortar >= 0)) throw std::invalid_argument("mortar must not be negative");
}

// POV-Ray 3.7 "brick": horizontal mortar layers every brick height; the vertical joints of alternate
// courses are offset by half a brick in x (end faces) and z (front faces).
int BrickPattern::block(const Vec3& p) const {
  const double fudge = 1e-6 + mortar_;
  const double x = p.x + fudge, y = p.y + fudge, z = p.z + fudge;
  if (frac(y / size_.y) <= mortar_ / size_.y) return 0;
  const bool odd_course = frac(y / size_.y * 0.5) > 0.5;
  const double joint_x = frac(x / size_.x + (odd_course ? 0.5 : 0.0));
  if (joint_x <= mortar_ / size_.x) return 0;
  const double joint_z = frac(z / size_.z + (odd_course ? 0.0 : 0.5));
  if (joint_z <= mortar_ / size_.z) return 0;
  return 1;
}

}  // namespace snell::texture
