#pragma once
// Boxes in structure-of-arrays form, tested against one ray a few at a time: the slab test of
// geometry::RayBox::enter, operation for operation in double on vectors of boxes, so that a box passes
// exactly when RayBox::enter would let it (math/simd.hpp: no fused multiply-add, same bits on SSE2 and AVX2).
#include <bit>
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
  /// Bytes the boxes take.
  size_t bytes() const { return 6 * lo_[0].size() * sizeof(double); }
  /// Bit k set where box chunk * kChunk + k is entered within [t0, t1] by the ray of `ray_box`.
  std::uint32_t entered(const geometry::RayBox& ray_box, size_t chunk, double t0, double t1) const;

  /// Calls visit(i) for each box i entered within [t0, t1], in index order, until it returns true (then
  /// true). Each chunk is tested with the `t1` of that moment, so a caller that lowers it as it finds hits
  /// skips the boxes beyond them.
  template <typename Visit>
  bool for_each_entered(const geometry::RayBox& ray_box, double t0, const double& t1, Visit&& visit) const {
    for (size_t chunk = 0; chunk < chunks(); ++chunk)
      for (std::uint32_t bits = entered(ray_box, chunk, t0, t1); bits; bits &= bits - 1)
        if (visit(chunk * kChunk + static_cast<size_t>(std::countr_zero(bits)))) return true;
    return false;
  }

 private:
  std::vector<double> lo_[3], hi_[3];
};

}  // namespace snell::accel
