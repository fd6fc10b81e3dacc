#pragma once
// Per-ray memory of the objects already tested, for structures that list an object in several cells
// (grid, octree). A small direct-mapped table on the stack: a collision only costs a repeated test, and a
// repeated test can never change the answer (the window only shrinks), so no allocation and no sharing.
#include <array>
#include <cstdint>

namespace snell::accel {

class Mailbox {
 public:
  /// True the first time `id` is seen (since any colliding id); records it.
  bool first_visit(uint32_t id) {
    uint32_t& slot = slots_[id % slots_.size()];
    if (slot == id) return false;
    slot = id;
    return true;
  }

 private:
  std::array<uint32_t, 64> slots_ = filled();
  static constexpr std::array<uint32_t, 64> filled() {
    std::array<uint32_t, 64> a{};
    a.fill(UINT32_MAX);
    return a;
  }
};

}  // namespace snell::accel
