#pragma once
#include <cstdint>

namespace snell::render {

/// Rays traced, by kind, for the statistics (POV-Ray's "Ray->Shape Intersection Tests" summary counts these
/// too). Each render thread owns one; the renderer sums them at the end, so no atomics in the hot path.
struct RayCounters {
  uint64_t camera = 0;
  uint64_t reflected = 0;
  uint64_t refracted = 0;
  uint64_t shadow = 0;
  /// Samples whose colour came out NaN or infinite and were rendered black (finite_sample.hpp).
  uint64_t non_finite_samples = 0;

  RayCounters& operator+=(const RayCounters& o) {
    camera += o.camera;
    reflected += o.reflected;
    refracted += o.refracted;
    shadow += o.shadow;
    non_finite_samples += o.non_finite_samples;
    return *this;
  }
  uint64_t total() const { return camera + reflected + refracted + shadow; }
};

}  // namespace snell::render
