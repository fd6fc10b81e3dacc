#include "snell/geometry/collapse_plan.hpp"

#include <cmath>

namespace snell::geometry {

CollapsePlan::CollapsePlan(std::span<const Binary> tree, int width)
    : tree_(tree), width_(width), plans_(tree.size()) {
  // Children follow their parent: a pass from the back meets them first. A leaf costs nothing in any
  // number of slots (its cost[] stays zero).
  for (size_t i = tree.size(); i-- > 0;) {
    const Binary& b = tree[i];
    if (b.leaf) continue;
    const Node& first = plans_[b.first_child];
    const Node& second = plans_[b.first_child + 1];
    Node& plan = plans_[i];
    std::array<float, kMaxWidth + 1> shared{};
    for (int slots = 2; slots <= width; ++slots) {
      // A valid share even where no sum compares (NaN or infinite areas of degenerate boxes).
      shared[slots] = INFINITY;
      plan.split[slots] = 1;
      for (int k = 1; k < slots; ++k) {
        const float c = first.cost[k] + second.cost[slots - k];
        if (c < shared[slots]) {
          shared[slots] = c;
          plan.split[slots] = static_cast<uint8_t>(k);
        }
      }
    }
    plan.cost[1] = static_cast<float>(b.area) + shared[width];
    for (int slots = 2; slots <= width; ++slots) {
      const bool fewer = !(shared[slots] < plan.cost[slots - 1]);
      plan.fewer |= static_cast<uint16_t>(fewer << slots);
      plan.cost[slots] = fewer ? plan.cost[slots - 1] : shared[slots];
    }
  }
}

int CollapsePlan::members(uint32_t b, std::array<uint32_t, kMaxWidth>& members) const {
  const uint8_t k = plans_[b].split[width_];
  int n = 0;
  gather(tree_[b].first_child, k, members, n);
  gather(tree_[b].first_child + 1, width_ - k, members, n);
  return n;
}

void CollapsePlan::gather(uint32_t b, int slots, std::array<uint32_t, kMaxWidth>& members, int& n) const {
  const Node& plan = plans_[b];
  while (!tree_[b].leaf && slots > 1 && (plan.fewer >> slots & 1u) != 0) --slots;
  if (tree_[b].leaf || slots == 1) {
    members[n++] = b;
    return;
  }
  gather(tree_[b].first_child, plan.split[slots], members, n);
  gather(tree_[b].first_child + 1, slots - plan.split[slots], members, n);
}

}  // namespace snell::geometry
