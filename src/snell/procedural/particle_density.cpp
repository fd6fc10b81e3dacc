#include "snell/procedural/particle_density.hpp"

#include <algorithm>
#include <cmath>

namespace snell::procedural {

ParticleDensity::ParticleDensity(std::vector<DensityBlob> blobs) : blobs_(std::move(blobs)) {
  double largest = 0;
  for (const DensityBlob& b : blobs_) largest = std::max(largest, b.radius);
  cell_ = largest > 0 ? largest : 1;
  for (size_t i = 0; i < blobs_.size(); ++i) {
    const math::Vec3& c = blobs_[i].center;
    cells_[key(std::llround(std::floor(c.x / cell_)), std::llround(std::floor(c.y / cell_)),
               std::llround(std::floor(c.z / cell_)))]
        .push_back(static_cast<int>(i));
  }
}

ParticleDensity::CellKey ParticleDensity::key(long long x, long long y, long long z) const {
  // 21 bits per axis; particles beyond +/- a million cells share cells, which costs time, not correctness.
  const auto wrap = [](long long v) { return static_cast<unsigned long long>(v) & 0x1fffffULL; };
  return static_cast<CellKey>((wrap(x) << 42) | (wrap(y) << 21) | wrap(z));
}

math::Color ParticleDensity::density(const math::Vec3& p) const {
  math::Color sum(0);
  if (blobs_.empty() || !math::is_finite(p)) return sum;
  const long long cx = std::llround(std::floor(p.x / cell_)), cy = std::llround(std::floor(p.y / cell_)),
                  cz = std::llround(std::floor(p.z / cell_));
  for (long long dx = -1; dx <= 1; ++dx)
    for (long long dy = -1; dy <= 1; ++dy)
      for (long long dz = -1; dz <= 1; ++dz) {
        const auto found = cells_.find(key(cx + dx, cy + dy, cz + dz));
        if (found == cells_.end()) continue;
        for (const int i : found->second) {
          const DensityBlob& b = blobs_[static_cast<size_t>(i)];
          const double q = length_squared(p - b.center) / (b.radius * b.radius);
          if (q < 1) sum += b.color * ((1 - q) * (1 - q));
        }
      }
  return sum;
}

material::Rgbft ParticleDensity::at(const material::PatternPoint& point) const {
  return {density(point.p), 0, 0};
}

}  // namespace snell::procedural
