#include "snell/accel/octree.hpp"

#include <array>
#include <bit>
#include <chrono>

#include "snell/accel/indexed_objects.hpp"
#include "snell/accel/mailbox.hpp"
#include "snell/accel/nearest_hit.hpp"
#include "snell/geometry/ray_box.hpp"

namespace snell::accel {

namespace {

constexpr size_t kMaxLeafObjects = 8;
constexpr int kMaxDepth = 10;
// Traversal stack: at most seven siblings wait on each level, plus the node being split.
constexpr int kStackSize = 7 * kMaxDepth + 8;
// Listing large objects in many children can grow the tree without bound; past this many entries per
// object every further node becomes a leaf.
constexpr size_t kEntriesPerObject = 16;
// The cost of walking one node (its box test and the push of its children), in object tests, for the
// decision to split.
constexpr double kNodeCost = 1.0;

/// The axes a node is halved along: those at least half as long as its longest side. Halving a thin side
/// (a flat layer of objects) would cut every object in two and list it in both halves without separating
/// anything, so such a node has four or two children instead of eight (an adaptive octree, as in the
/// "adaptive hierarchical" space subdivision of Kaplan, 1985, where cells follow the scene's shape).
uint8_t split_axes(const math::Bounds3& box) {
  const math::Vec3 size = box.hi - box.lo;
  const double longest = max_component(size);
  uint8_t axes = 0;
  for (int a = 0; a < 3; ++a)
    if (size[a] >= 0.5 * longest) axes |= static_cast<uint8_t>(1u << a);
  return axes;
}

/// Child `child` of a node halved along `axes`: bit j of `child` selects the upper half along the j-th
/// split axis.
math::Bounds3 octant(const math::Bounds3& box, uint8_t axes, uint32_t child) {
  const math::Vec3 mid = box.center();
  math::Bounds3 b = box;
  int j = 0;
  for (int a = 0; a < 3; ++a) {
    if (!((axes >> a) & 1)) continue;
    const bool upper = (child >> j++) & 1;
    b.lo[a] = upper ? mid[a] : box.lo[a];
    b.hi[a] = upper ? box.hi[a] : mid[a];
  }
  return b;
}

int child_count(uint8_t axes) {
  return 1 << std::popcount(axes);
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
    tree_.nodes_.push_back({in_.scene_box, 0, 0, true, 0});
    build_node(0, all, 0);
  }

 private:
  void build_node(size_t index, const std::vector<uint32_t>& objects, int depth) {
    const math::Bounds3 box = tree_.nodes_[index].box;
    const uint8_t axes = split_axes(box);
    const int children = child_count(axes);
    std::array<std::vector<uint32_t>, 8> inside;
    bool split = objects.size() > kMaxLeafObjects && depth < kMaxDepth && tree_.entries_.size() <= budget_;
    if (split) {
      // Split only where it pays by the surface area heuristic: a ray that enters the node enters a child
      // with the odds of their areas, and objects larger than a child are listed in several. Past that
      // point (a soup of triangles larger than the cells) splitting multiplies the entries and never
      // separates the objects, and a depth-first build used to spend the whole entry budget there,
      // leaving the rest of the tree as leaves of thousands.
      double expected_tests = kNodeCost;
      for (int c = 0; c < children; ++c) {
        const math::Bounds3 child_box = octant(box, axes, static_cast<uint32_t>(c));
        for (uint32_t o : objects)
          if (overlaps(in_.boxes[o], child_box)) inside[c].push_back(o);
        expected_tests +=
            child_box.surface_area() / box.surface_area() * static_cast<double>(inside[c].size());
      }
      split = expected_tests < static_cast<double>(objects.size());
    }
    if (!split) {
      Octree::Node& node = tree_.nodes_[index];
      node.first = static_cast<uint32_t>(tree_.entries_.size());
      node.count = static_cast<uint32_t>(objects.size());
      tree_.entries_.insert(tree_.entries_.end(), objects.begin(), objects.end());
      return;
    }
    const auto first = static_cast<uint32_t>(tree_.nodes_.size());
    tree_.nodes_[index].first = first;
    tree_.nodes_[index].leaf = false;
    tree_.nodes_[index].axes = axes;
    for (int c = 0; c < children; ++c)
      tree_.nodes_.push_back({octant(box, axes, static_cast<uint32_t>(c)), 0, 0, true, 0});
    for (int c = 0; c < children; ++c) {
      const std::vector<uint32_t> mine = std::move(inside[c]);
      build_node(first + c, mine, depth + 1);
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
  triangles_ = plain_triangles(objects_);
  unbounded_ = indexed.unbounded;
  OctreeBuilder(indexed, *this).build();
  stats_ = structure_stats(scene.objects.size(), unbounded_.size(), nodes_.size(),
                           nodes_.size() * sizeof(Node) + entries_.size() * sizeof(uint32_t) +
                               objects_.size() * (sizeof(objects_[0]) + sizeof(PlainTriangle)),
                           start);
}

bool Octree::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                       scene::SurfaceHit& hit) const {
  NearestHit nearest(ray, t_min, t_max, kind, hit);
  for (const scene::Object* o : unbounded_) nearest.test_general(*o);
  if (nodes_.empty() || !(t_min < t_max)) return nearest.finish();
  const geometry::RayBox slabs(ray);
  // Numbering children by (number XOR near) gives an order in which a ray never goes back: it can only
  // cross from the near to the far half on each axis. `near` depends on which axes a node splits.
  std::array<uint32_t, 8> near_for_axes;
  for (uint32_t axes = 0; axes < 8; ++axes) {
    uint32_t near = 0;
    int j = 0;
    for (int a = 0; a < 3; ++a) {
      if (!((axes >> a) & 1)) continue;
      if (ray.direction[a] < 0) near |= 1u << j;
      ++j;
    }
    near_for_axes[axes] = near;
  }
  Mailbox mailbox;
  NodeTally tally;
  std::array<uint32_t, kStackSize> stack;
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!slabs.hits(node.box, t_min, nearest.t_max())) continue;
    tally.visit();  // nodes the ray enters, as the BVH counts them
    if (!node.leaf) {
      const uint32_t near = near_for_axes[node.axes];
      for (int i = child_count(node.axes) - 1; i >= 0; --i)
        stack[top++] = node.first + (static_cast<uint32_t>(i) ^ near);
      continue;
    }
    for (uint32_t k = node.first; k < node.first + node.count; ++k) {
      const uint32_t i = entries_[k];
      if (mailbox.first_visit(i)) nearest.test(*objects_[i], triangles_[i]);
    }
  }
  return nearest.finish();
}

}  // namespace snell::accel
