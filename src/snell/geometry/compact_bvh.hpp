#pragma once
// A small-footprint bounding volume hierarchy for shapes made of very many primitives (an L-system's
// branches): float boxes (32-byte nodes), up to 4 primitives per leaf and a median split on the longest
// axis of the centroids, which builds in O(n log n) with no extra memory per primitive. The caller reorders
// its primitives by `order()` so leaves refer to contiguous ranges and no index array is kept. (The mesh's
// SAH tree, triangle_tree.hpp, traces faster but needs several times the memory per primitive.)
#include <cstdint>
#include <span>
#include <vector>

#include "snell/math/bounds.hpp"
#include "snell/math/ray.hpp"

namespace snell::geometry {

class CompactBvh {
 public:
  /// Builds over the boxes; afterwards primitive i of the tree is input primitive order()[i].
  explicit CompactBvh(std::span<const math::Bounds3> boxes);

  const std::vector<std::uint32_t>& order() const { return order_; }
  /// Frees the permutation once the caller has applied it.
  void drop_order() { order_ = {}; }
  math::Bounds3 bounds() const;
  std::size_t bytes() const {
    return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(std::uint32_t);
  }

  /// Calls visit(prim, t_max) for the primitives of every leaf the ray enters within (t_min, t_max), near
  /// leaves first; `visit` may lower t_max.
  template <class Visit>
  void traverse(const math::Ray& ray, double t_min, double& t_max, Visit&& visit) const;

 private:
  struct Node {
    float lo[3], hi[3];
    /// Leaf: first primitive; inner: index of the second child (the first follows the node).
    std::uint32_t offset;
    /// Primitives in a leaf, 0 for an inner node.
    std::uint32_t count;
  };
  static_assert(sizeof(Node) == 32);

  std::uint32_t build(std::span<const math::Bounds3> boxes, std::uint32_t begin, std::uint32_t end);
  /// Entry distance of the ray into the node's box within [t0, t1], or a negative value when it misses.
  static double enter(const Node& n, const math::Vec3& o, const math::Vec3& inv, double t0, double t1);

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;
};

inline double CompactBvh::enter(const Node& n, const math::Vec3& o, const math::Vec3& inv, double t0,
                                double t1) {
  for (int a = 0; a < 3; ++a) {
    double tn = (n.lo[a] - o[a]) * inv[a];
    double tf = (n.hi[a] - o[a]) * inv[a];
    if (tn > tf) std::swap(tn, tf);
    if (tn > t0) t0 = tn;  // NaN (0 * inf) leaves the interval alone
    if (tf < t1) t1 = tf;
    if (t0 > t1) return -1;
  }
  return t0;
}

template <class Visit>
void CompactBvh::traverse(const math::Ray& ray, double t_min, double& t_max, Visit&& visit) const {
  if (nodes_.empty()) return;
  const math::Vec3 inv{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
  std::uint32_t stack[64];
  int top = 0;
  if (enter(nodes_[0], ray.origin, inv, t_min, t_max) < 0) return;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.count > 0) {
      for (std::uint32_t i = 0; i < node.count; ++i) visit(static_cast<int>(node.offset + i), t_max);
      continue;
    }
    const std::uint32_t a = static_cast<std::uint32_t>(&node - nodes_.data()) + 1, b = node.offset;
    const double ta = enter(nodes_[a], ray.origin, inv, t_min, t_max);
    const double tb = enter(nodes_[b], ray.origin, inv, t_min, t_max);
    // Push the farther child first so the nearer is visited first (the depth stays below 64: see build).
    if (ta >= 0 && tb >= 0) {
      stack[top++] = ta <= tb ? b : a;
      stack[top++] = ta <= tb ? a : b;
    } else if (ta >= 0) {
      stack[top++] = a;
    } else if (tb >= 0) {
      stack[top++] = b;
    }
  }
}

}  // namespace snell::geometry
