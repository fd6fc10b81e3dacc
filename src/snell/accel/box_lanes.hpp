#pragma once
// Boxes in structure-of-arrays form, tested against one ray a few at a time: the slab test of
// geometry::RayBox::enter, operation for operation in double on vectors of boxes, so that a box passes
// exactly when RayBox::enter would let it (math/simd.hpp: no fused multiply-add, same bits on SSE2 and AVX2).
#include <cstdint>
#include <vector>

#include "snell/geometry/ray_box.hpp"
#include "snell/math/bounds.hpp"

namespace snell::accel {

class BoxLanes {
 public:
  /// Boxes tested per call of `entered`.
  static constexpr int kChunk = 4;

  explicit BoxLanes(const std::vector<math::Bounds3>& boxes);

  /// Number of chunks of kChunk boxes (the last padded with boxes no ray enters).
  size_t chunks() const { return lo_[0].size() / kChunk; }
  /// Bit k set where box chunk * kChunk + k is entered within [t0, t1] by the ray of `ray_box`.
  std::uint32_t entered(const geometry::RayBox& ray_box, size_t chunk, double t0, double t1) const;

 private:
  std::vector<double> lo_[3], hi_[3];
};

}  // namespace snell::accel
