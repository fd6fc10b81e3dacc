#pragma once
// Which nodes of a binary BVH become the nodes of a wide one. A wide node of width w stands for a binary
// interior node and takes as its children up to w binary nodes below it (leaves, or interior nodes that
// become wide nodes in turn); the binary nodes in between dissolve. Of all such collapses this picks the
// one of least summed surface area over its wide nodes, by dynamic programming over the binary tree
// (Ylitie, Karras and Laine, "Efficient incoherent ray traversal on GPUs through compressed wide BVHs",
// HPG 2017, section 3.1; here the binary leaves stay leaves, so their share of the SAH cost is the same in
// every collapse and left out). The greedy alternative, opening the largest child until a node is full,
// fills the nodes near the root and leaves those above the leaves with three or four children: over
// 100,000 small triangles 4,638 nodes of 4.0 children on average, against 2,534 of 6.5 here
// (docs/benchmark.md, session 28).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace snell::geometry {

class CollapsePlan {
 public:
  static constexpr int kMaxWidth = 8;

  /// A binary node as the plan sees it: its box's surface area and, for an interior node, the index of its
  /// first child (the second follows it). Children come after their parent in the list.
  struct Binary {
    double area = 0;
    bool leaf = true;
    uint32_t first_child = 0;
  };

  /// Plans the collapse of `tree` (node 0 the root) to nodes of `width` children (2 .. kMaxWidth). The plan
  /// keeps a view of `tree`, which must outlive it: members() reads it.
  CollapsePlan(std::span<const Binary> tree, int width);

  /// Puts in `members` the binary nodes that become the children of interior node b's wide node, in the
  /// binary tree's order; returns how many (2 .. width).
  int members(uint32_t b, std::array<uint32_t, kMaxWidth>& members) const;

  /// The summed surface area of the wide nodes of interior node b's subtree, b's own included.
  double cost(uint32_t b) const { return plans_[b].cost[1]; }

 private:
  /// For i child slots: the least summed area of the wide nodes that represent the subtree in at most i
  /// slots of the node above; how the two children share i slots (split[i] for the first); and whether
  /// i - 1 slots do as well (bit i of `fewer`). One slot: the node becomes a wide node itself. Single
  /// precision, 48 bytes a binary node (the plan lives beside the binary tree while it is collapsed: about
  /// 2 of these a block of 8 triangles): a near tie it decides either way costs no more than its rounding.
  struct Node {
    std::array<float, kMaxWidth + 1> cost{};
    std::array<uint8_t, kMaxWidth + 1> split{};
    uint16_t fewer = 0;
  };

  void gather(uint32_t b, int slots, std::array<uint32_t, kMaxWidth>& members, int& n) const;

  std::span<const Binary> tree_;
  int width_;
  std::vector<Node> plans_;
};

}  // namespace snell::geometry
