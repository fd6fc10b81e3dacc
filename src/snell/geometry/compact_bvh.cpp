#include "snell/geometry/compact_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace snell::geometry {

namespace {
constexpr std::uint32_t kLeafSize = 4;
}

CompactBvh::CompactBvh(std::span<const math::Bounds3> boxes) {
  order_.resize(boxes.size());
  std::iota(order_.begin(), order_.end(), 0u);
  if (boxes.empty()) return;
  nodes_.reserve(2 * boxes.size() / kLeafSize + 1);
  build(boxes, 0, static_cast<std::uint32_t>(boxes.size()));
  nodes_.shrink_to_fit();
}

math::Bounds3 CompactBvh::bounds() const {
  if (nodes_.empty()) return {};
  const Node& n = nodes_[0];
  return {math::Vec3(n.lo[0], n.lo[1], n.lo[2]), math::Vec3(n.hi[0], n.hi[1], n.hi[2])};
}

// Median splits halve the range each level, so the depth is log2(n / 4) + 1: under 64 for any n that fits
// in 32 bits, which bounds traverse()'s stack.
std::uint32_t CompactBvh::build(std::span<const math::Bounds3> boxes, std::uint32_t begin,
                                std::uint32_t end) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  math::Bounds3 box, centre_box;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.unite(boxes[order_[i]]);
    centre_box.unite(boxes[order_[i]].center());
  }
  Node node{};
  for (int a = 0; a < 3; ++a) {
    // Round outward so the float box still contains the double one.
    node.lo[a] = std::nextafter(static_cast<float>(box.lo[a]), -std::numeric_limits<float>::infinity());
    node.hi[a] = std::nextafter(static_cast<float>(box.hi[a]), std::numeric_limits<float>::infinity());
  }
  const math::Vec3 extent = centre_box.extent();
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  if (end - begin <= kLeafSize || !(extent[axis] > 0)) {
    node.offset = begin;
    node.count = end - begin;
    nodes_[index] = node;
    return index;
  }
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t p, std::uint32_t q) {
                     // Twice the centroid: no centroid array is kept (memory for millions of primitives).
                     return boxes[p].lo[axis] + boxes[p].hi[axis] < boxes[q].lo[axis] + boxes[q].hi[axis];
                   });
  build(boxes, begin, mid);
  node.offset = build(boxes, mid, end);
  node.count = 0;
  nodes_[index] = node;
  return index;
}

}  // namespace snell::geometry
