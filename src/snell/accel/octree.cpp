#include "snell/accel/octree.hpp"

#include <array>
#include <chrono>

#include "snell/accel/indexed_objects.hpp"
#include "snell/accel/mailbox.hpp"
#include "snell/accel/ray_box.hpp"

namespace snell::accel {

namespace {

constexpr size_t kMaxLeafObjects = 8;
constexpr int kMaxDepth = 10;
// Traversal stack: at most seven siblings wait on each level, plus the node being split.
constexpr int kStackSize = 7 * kMaxDepth + 8;
// Listing large objects in many children can grow the tree without bound; past this many entries per
// object every further node becomes a leaf.
constexpr size_t kEntriesPerObject = 16;

math::Bounds3 octant(const math::Bounds3& box, int child) {
  const math::Vec3 mid = box.center();
  math::Bounds3 b;
  for (int a = 0; a < 3; ++a) {
    const bool upper = (child >> a) & 1;
    b.lo[a] = upper ? mid[a] : box.lo[a];
    b.hi[a] = upper ? box.hi[a] : mid[a];
  }
  return b;
}

bool overlaps(const math::Bounds3& a, const math::Bounds3& b) {
  return !a.intersection(b).empty();
}

}  // namespace

class OctreeBuilder {
 public:
  OctreeBuilder(const IndexedObjects& in, Octree& tree)
      : in_(in), tree_(tree), budget_(kEntriesPerObject * in.bounded.size() + 1024) {}

  void build() {
    if (in_.bounded.empty()) return;
    std::vector<uint32_t> all(in_.bounded.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    tree_.nodes_.push_back({in_.scene_box, 0, 0, true});
    build_node(0, all, 0);
  }

 private:
  void build_node(size_t index, const std::vector<uint32_t>& objects, int depth) {
    const math::Bounds3 box = tree_.nodes_[index].box;
    if (objects.size() <= kMaxLeafObjects || depth >= kMaxDepth || tree_.entries_.size() > budget_) {
      Octree::Node& node = tree_.nodes_[index];
      node.first = static_cast<uint32_t>(tree_.entries_.size());
      node.count = static_cast<uint32_t>(objects.size());
      tree_.entries_.insert(tree_.entries_.end(), objects.begin(), objects.end());
      return;
    }
    const auto first = static_cast<uint32_t>(tree_.nodes_.size());
    tree_.nodes_[index].first = first;
    tree_.nodes_[index].leaf = false;
    for (int c = 0; c < 8; ++c) tree_.nodes_.push_back({octant(box, c), 0, 0, true});
    for (int c = 0; c < 8; ++c) {
      const math::Bounds3 child_box = tree_.nodes_[first + c].box;
      std::vector<uint32_t> inside;
      for (uint32_t o : objects)
        if (overlaps(in_.boxes[o], child_box)) inside.push_back(o);
      build_node(first + c, inside, depth + 1);
    }
  }

  const IndexedObjects& in_;
  Octree& tree_;
  size_t budget_;
};

Octree::Octree(const scene::Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const IndexedObjects indexed(scene);
  objects_ = indexed.bounded;
  unbounded_ = indexed.unbounded;
  OctreeBuilder(indexed, *this).build();
  stats_ = structure_stats(scene.objects.size(), unbounded_.size(), nodes_.size(),
                           nodes_.size() * sizeof(Node) + entries_.size() * sizeof(uint32_t) +
                               objects_.size() * sizeof(objects_[0]),
                           start);
}

bool Octree::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                       scene::SurfaceHit& hit) const {
  bool found = test_all(unbounded_, ray, t_min, t_max, kind, hit);
  if (nodes_.empty() || !(t_min < t_max)) return found;
  const RayBox slabs(ray);
  // Numbering children by (number XOR near) gives an order in which a ray never goes back: it can only
  // cross from the near to the far half on each axis.
  const uint32_t near =
      (ray.direction.x < 0 ? 1u : 0u) | (ray.direction.y < 0 ? 2u : 0u) | (ray.direction.z < 0 ? 4u : 0u);
  Mailbox mailbox;
  NodeTally tally;
  std::array<uint32_t, kStackSize> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!slabs.hits(node.box, t_min, t_max)) continue;
    tally.visit();  // nodes the ray enters, as the BVH counts them
    if (!node.leaf) {
      for (int i = 7; i >= 0; --i) stack[top++] = node.first + (static_cast<uint32_t>(i) ^ near);
      continue;
    }
    for (uint32_t k = node.first; k < node.first + node.count; ++k) {
      const uint32_t i = entries_[k];
      if (mailbox.first_visit(i) && test_object(*objects_[i], ray, t_min, t_max, kind, hit)) {
        t_max = hit.t;
        found = true;
      }
    }
  }
  return found;
}

}  // namespace snell::accel
