#include "snell/math/float_lanes.hpp"

#include "snell/math/cpu.hpp"

namespace snell::math::lanes {

namespace {

std::atomic<bool> g_wide{has_avx2()};

}  // namespace

bool wide_lanes() {
  return g_wide.load(std::memory_order_relaxed);
}

bool use_portable_lanes(bool portable) {
  g_wide.store(!portable && has_avx2(), std::memory_order_relaxed);
  return has_avx2();
}

}  // namespace snell::math::lanes
