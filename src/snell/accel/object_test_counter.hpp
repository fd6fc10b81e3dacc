#pragma once
// The count of object tests (ray against one object's surface) made by any accelerator, for `--stats`
// (tests per ray) and for the tests that compare structures by their work per ray.
#include <atomic>
#include <cstdint>

namespace snell::accel {

/// Object tests made by every accelerator, counted only while `enabled` (for --stats and the tests that
/// compare structures by work per ray): off, a render pays one predictable branch per test.
struct ObjectTestCounter {
  static inline std::atomic<bool> enabled{false};
  static inline std::atomic<uint64_t> tests{0};
  static void count() {
    if (enabled.load(std::memory_order_relaxed)) tests.fetch_add(1, std::memory_order_relaxed);
  }
};

}  // namespace snell::accel
