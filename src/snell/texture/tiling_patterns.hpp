#pragma once
// `tiling N` (POV-Ray 3.7 reference, "Tiling"; behaviour of POV-Ray's pattern.cpp TilingPattern, by
// J. Grimbert): the x-z plane covered by tiles, constant along y. A tiling with k kinds of tile gives
// kind i the values [i/k, (i+1)/k]: i/k at the point deepest inside the tile, rising linearly to
// (i+1)/k on its outline (the "bevel" a colour_map turns into caulk). For a regular polygon the ramp is
// 1 - (distance to the nearest edge) / (inradius).
// snell has tilings 1 to 5 so far: 1 squares (side 1, edges on integer x and z), 2 hexagons (side 1, one
// corner along x), 3 triangles (side 1, one edge along x; upward triangles are kind 0, downward kind 1),
// 4 lozenges (60 degree rhombi, one kind), 5 rhombi in three orientations (three kinds).
#include "snell/texture/pattern.hpp"

namespace snell::texture {

class TilingPattern final : public ValuePattern {
 public:
  /// Throws std::invalid_argument for a tiling snell does not have (see supported()).
  explicit TilingPattern(int tiling);
  double value(const Vec3& p) const override;
  /// Whether tiling number `n` is implemented (POV-Ray has 1 to 27).
  static bool supported(int n) { return n >= 1 && n <= 5; }

 private:
  int tiling_;
};

}  // namespace snell::texture
