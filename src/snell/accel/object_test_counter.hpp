#pragma once
// The count of object tests (ray against one object's surface) made by any accelerator, for `--stats`
// (tests per ray) and for the tests that compare structures by their work per ray.
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace snell::accel {

/// One thread's count, alone in its cache line.
struct alignas(64) ObjectTestSlot {
  std::atomic<uint64_t> tests{0};
};

/// Object tests made by every accelerator, counted only while `enabled` (for --stats and the tests that
/// compare structures by work per ray): off, a render pays one predictable branch per test. Each thread
/// counts in its own cache line: one counter shared by the render threads cost --stats renders a fifth of
/// their time in cache-line traffic.
struct ObjectTestCounter {
  static inline std::atomic<bool> enabled{false};

  static void count(uint64_t tests = 1) {
    if (enabled.load(std::memory_order_relaxed)) slot().fetch_add(tests, std::memory_order_relaxed);
  }
  /// Tests counted since the last reset, over all threads.
  static uint64_t total() {
    uint64_t sum = 0;
    for (const ObjectTestSlot& s : slots_) sum += s.tests.load(std::memory_order_relaxed);
    return sum;
  }
  static void reset() {
    for (ObjectTestSlot& s : slots_) s.tests.store(0, std::memory_order_relaxed);
  }

 private:
  static constexpr size_t kSlots = 64;
  static inline ObjectTestSlot slots_[kSlots];
  static inline std::atomic<size_t> next_slot_{0};

  /// This thread's slot (threads beyond kSlots share, still correctly, as the counters are atomic).
  static std::atomic<uint64_t>& slot() {
    thread_local const size_t mine = next_slot_.fetch_add(1, std::memory_order_relaxed) % kSlots;
    return slots_[mine].tests;
  }
};

}  // namespace snell::accel
