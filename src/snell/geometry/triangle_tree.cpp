#include "snell/geometry/triangle_tree.hpp"

namespace snell::geometry {

namespace {

// SAH cost of a leaf's block of up to eight triangles, filtered at once, relative to one node visit.
constexpr double kBlockCost = 2.0;
/// Spatial splits may put each triangle in two leaves on average (docs/benchmark.md: long triangles).
constexpr double kReferenceBudget = 2;

}  // namespace

TriangleTree::TriangleTree(std::span<const math::Vec3> vertices, std::span<const std::array<int, 3>> faces) {
  std::vector<math::Bounds3> boxes(faces.size());
  std::vector<std::array<math::Vec3, 3>> corners(faces.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) corners[f][k] = vertices[faces[f][k]];
    boxes[f] = padded(math::Bounds3(corners[f][0], corners[f][1]).unite(corners[f][2]));
  }
  const std::vector<uint8_t> all_triangles(faces.size(), 1);
  WideBvh::Input input;
  input.boxes = boxes;
  input.kinds = all_triangles;
  input.triangles = corners;
  input.reference_budget = kReferenceBudget;
  input.cost = {kBlockCost, kBlockCost};
  input.group = {TriangleBlock::kSize, TriangleBlock::kSize};
  input.max_leaf = TriangleBlock::kSize;
  bvh_ = WideBvh(input);
  bvh_.relabel_leaves([&](uint32_t first, uint32_t count) {
    TriangleBlock& block = blocks_.emplace_back();
    block.first = first;
    for (uint32_t i = first; i < first + count; ++i) {
      const uint32_t f = bvh_.order()[i];
      block.add(vertices[faces[f][0]], vertices[faces[f][1]], vertices[faces[f][2]]);
    }
    // The owner's double test runs on these very vertices: a clear hit of the filter may stand for it.
    block.decisive = static_cast<uint8_t>((1u << block.count) - 1);
    return static_cast<uint32_t>(blocks_.size() - 1);
  });
  blocks_.shrink_to_fit();
  for (const TriangleBlock& block : blocks_) scales_.include(block);
}

}  // namespace snell::geometry
