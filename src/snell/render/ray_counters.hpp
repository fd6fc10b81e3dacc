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

  RayCounters& operator+=(const RayCounters& o) {
    camera += o.camera;
    reflected += o.reflected;
    refracted += o.refracted;
    shadow += o.shadow;
    return *this;
  }
  uint64_t total() const { return camera + reflected + refracted + shadow; }
};

}  // namespace snell::render
