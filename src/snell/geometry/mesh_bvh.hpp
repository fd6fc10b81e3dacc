#pragma once
// Bounding volume hierarchy over a mesh's triangles (or any primitives given by their boxes), built with
// binned SAH (Wald 2007, "On fast Construction of SAH-based Bounding Volume Hierarchies") and traversed
// near child first. It is private to Mesh; the scene-level accelerator lives in accel/.
#include <span>
#include <vector>

#include "snell/math/bounds.hpp"
#include "snell/math/ray.hpp"

namespace snell::geometry {

class MeshBvh {
 public:
  explicit MeshBvh(std::span<const math::Bounds3> prim_bounds);

  math::Bounds3 bounds() const { return nodes_.empty() ? math::Bounds3() : nodes_[0].box; }
  int node_count() const { return static_cast<int>(nodes_.size()); }

  /// Calls visit(prim, t_max) for every primitive whose leaf box the ray enters within (t_min, t_max);
  /// `visit` may lower t_max (closest-hit search) and later boxes are culled against it.
  template <class Visit>
  void traverse(const math::Ray& ray, double t_min, double& t_max, Visit&& visit) const;

 private:
  struct Node {
    math::Bounds3 box;
    int offset = 0;  // leaf: first index into prims_; inner: index of the left child (right = left + 1)
    int count = 0;   // > 0 for a leaf
    int axis = 0;
  };
  void build(std::span<const math::Bounds3> prim_bounds, std::vector<math::Vec3>& centroids, int node,
             int begin, int end, int depth);

  std::vector<Node> nodes_;
  std::vector<int> prims_;
};

namespace detail {
// Slab test against [t0, t1]; NaNs from 0 * inf (origin on a slab of a parallel ray) leave t0/t1 alone.
inline bool hits_box(const math::Bounds3& b, const math::Vec3& o, const math::Vec3& inv, double t0,
                     double t1) {
  for (int a = 0; a < 3; ++a) {
    double tn = (b.lo[a] - o[a]) * inv[a];
    double tf = (b.hi[a] - o[a]) * inv[a];
    if (tn > tf) std::swap(tn, tf);
    if (tn > t0) t0 = tn;
    if (tf < t1) t1 = tf;
    if (t0 > t1) return false;
  }
  return true;
}
}  // namespace detail

template <class Visit>
void MeshBvh::traverse(const math::Ray& ray, double t_min, double& t_max, Visit&& visit) const {
  if (nodes_.empty()) return;
  const math::Vec3 inv{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!detail::hits_box(node.box, ray.origin, inv, t_min, t_max)) continue;
    if (node.count > 0) {
      for (int i = 0; i < node.count; ++i) visit(prims_[node.offset + i], t_max);
    } else if (top + 2 <= 128) {
      // Push the far child first so the near one is visited first.
      const bool neg = ray.direction[node.axis] < 0;
      stack[top++] = node.offset + (neg ? 0 : 1);
      stack[top++] = node.offset + (neg ? 1 : 0);
    }
  }
}

}  // namespace snell::geometry
