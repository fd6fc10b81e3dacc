#pragma once
// A binary tree of rectangles over an outline's curve pieces, so that a ray asks only the pieces near its
// path: a text object's outline has hundreds (benchmark.pov's two lines of text about 600), and testing
// every one for every ray that reaches the text was 7% of that scene's time. Built once with median
// splits; a query visits the nodes whose rectangle meets a segment's bounding rectangle and its line.
#include <cstdint>
#include <span>
#include <vector>

#include "snell/geometry/curve_segment.hpp"

namespace snell::geometry {

class PieceTree {
 public:
  PieceTree() = default;
  explicit PieceTree(std::span<const CurveSegment> pieces);

  /// Calls f(piece index) for every piece whose rectangle may meet the part of the line n . q + k = 0
  /// within the rectangle [lo, hi] (either may be infinite): a superset of the pieces that line part
  /// crosses. Indices come in no particular order.
  template <class F>
  void for_each_near(Vec2 lo, Vec2 hi, Vec2 n, double k, F&& f) const {
    if (nodes_.empty()) return;
    uint32_t stack[kMaxDepth + 1];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (node.hi.u < lo.u || node.lo.u > hi.u || node.hi.v < lo.v || node.lo.v > hi.v) continue;
      if (!line_may_cross_rectangle(node.lo, node.hi, n, k)) continue;
      if (node.count > 0) {
        for (uint32_t i = node.first; i < node.first + node.count; ++i) f(order_[i]);
        continue;
      }
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
    }
  }

 private:
  /// Interior node: count 0, children first and first + 1. Leaf: order_[first .. first + count).
  struct Node {
    Vec2 lo, hi;
    uint32_t first = 0, count = 0;
  };
  /// Median splits halve the pieces at each level, so 2^40 pieces would be needed to go deeper; the walk
  /// holds one pending sibling per level.
  static constexpr int kMaxDepth = 40;

  void build(uint32_t node, uint32_t begin, uint32_t end, std::span<const CurveSegment> pieces);

  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;
};

}  // namespace snell::geometry
