#pragma once
// POV-Ray 3.7's tiling block patterns `square`, `triangular` and `cubic` (POV-Ray 3.7 reference,
// "Square", "Triangular", "Cubic"): each picks one of 4 or 6 entries so that no two neighbours match.
#include <memory>
#include <string>

#include "snell/texture/pattern.hpp"

namespace snell::texture {

/// `square`: unit squares in the x-z plane in four entries, 0 at the origin's square, 1 the next one
/// along +z, 3 along +x and 2 diagonally (POV-Ray's numbering); constant along y.
class SquarePattern final : public BlockPattern {
 public:
  int block(const Vec3& p) const override;
  int block_count() const override { return 4; }
};

/// `triangular`: equilateral triangles of side 1 in the x-z plane, rows of height sqrt(3)/2 along z,
/// in six entries so that the six triangles around each corner all differ; constant along y.
class TriangularPattern final : public BlockPattern {
 public:
  int block(const Vec3& p) const override;
  int block_count() const override { return 6; }
};

/// `cubic`: the six pyramids from the origin through the faces of a cube: +x, +y, +z, -x, -y, -z.
class CubicPattern final : public BlockPattern {
 public:
  int block(const Vec3& p) const override;
  int block_count() const override { return 6; }
};

/// The pattern for `square`, `triangular` or `cubic`; null for any other name.
std::shared_ptr<const BlockPattern> make_polygon_block_pattern(const std::string& name);

}  // namespace snell::texture
