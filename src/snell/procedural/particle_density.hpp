#pragma once
// The density of a cloud of particles as a pigment, for `media { density { } }`: each particle adds its
// colour times the smooth kernel (1 - (d/R)^2)^2 within its radius R (the kernel of POV-Ray's blob
// components), so the medium glows or darkens where particles gather. A uniform grid of cells as large as
// the biggest particle keeps a lookup to the particles of 27 cells.
#include <unordered_map>
#include <vector>

#include "snell/material/pigment.hpp"
#include "snell/math/color.hpp"

namespace snell::procedural {

struct DensityBlob {
  math::Vec3 center;
  double radius = 0;
  math::Color color;
};

class ParticleDensity final : public material::Pigment {
 public:
  explicit ParticleDensity(std::vector<DensityBlob> blobs);
  material::Rgbft at(const material::PatternPoint& point) const override;
  /// The summed colour at a world point.
  math::Color density(const math::Vec3& p) const;

 private:
  using CellKey = long long;
  CellKey key(long long x, long long y, long long z) const;
  std::vector<DensityBlob> blobs_;
  double cell_ = 1;
  std::unordered_map<CellKey, std::vector<int>> cells_;
};

}  // namespace snell::procedural
