#include "snell/accel/bvh.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <numeric>

#include "snell/accel/float_slabs.hpp"
#include "snell/accel/four_boxes.hpp"
#include "snell/accel/indexed_objects.hpp"
#include "snell/accel/ray_box.hpp"

namespace snell::accel {

namespace {

using math::Bounds3;

constexpr int kBins = 16;
constexpr size_t kMaxLeafObjects = 8;
// SAH costs relative to one box test: an object test (a transformed quadric, a CSG walk) costs several.
constexpr double kObjectCost = 4.0;
// Below this depth only balanced halving: at most 32 more levels for 2^32 objects, so a traversal stack of
// kStackSize (one entry per level) never overflows.
constexpr int kMaxSahDepth = 64;
constexpr int kMaxBinaryDepth = kMaxSahDepth + 32;
// A walk pops one node and pushes at most kWidth children per level (sorted in place on the stack).
constexpr int kStackSize = (Bvh::kWidth - 1) * kMaxBinaryDepth + Bvh::kWidth;

/// The binary tree the builder makes before it is collapsed to Bvh::Node.
struct BinaryNode {
  Bounds3 box;
  /// Leaf: first object; interior: index of the first child (the second follows it).
  uint32_t offset = 0;
  /// Objects in a leaf; 0 for an interior node.
  uint32_t count = 0;
};

class Builder {
 public:
  Builder(const IndexedObjects& objects, std::vector<BinaryNode>& nodes) : in_(objects), nodes_(nodes) {
    order_.resize(objects.bounded.size());
    std::iota(order_.begin(), order_.end(), 0u);
    centroids_.reserve(order_.size());
    for (const Bounds3& b : objects.boxes) centroids_.push_back(b.center());
  }

  std::vector<const scene::Object*> build() {
    if (!order_.empty()) {
      nodes_.emplace_back();
      build_node(0, 0, order_.size(), 0);
    }
    std::vector<const scene::Object*> leaf_order;
    leaf_order.reserve(order_.size());
    for (uint32_t i : order_) leaf_order.push_back(in_.bounded[i]);
    return leaf_order;
  }

 private:
  struct Split {
    int axis = -1;
    double position = 0;
    double cost = 0;
  };

  Split best_split(size_t begin, size_t end, const Bounds3& box) const {
    Bounds3 centroid_box;
    for (size_t i = begin; i < end; ++i) centroid_box.unite(centroids_[order_[i]]);
    Split best;
    best.cost = kObjectCost * static_cast<double>(end - begin);  // cost of a leaf, in units of box area
    const double area = box.surface_area();
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = centroid_box.lo[axis], extent = centroid_box.hi[axis] - lo;
      if (!(extent > 0)) continue;
      std::array<Bounds3, kBins> bin_box;
      std::array<size_t, kBins> bin_count{};
      for (size_t i = begin; i < end; ++i) {
        const uint32_t o = order_[i];
        const int b = std::min(kBins - 1, static_cast<int>(kBins * (centroids_[o][axis] - lo) / extent));
        bin_box[b].unite(in_.boxes[o]);
        ++bin_count[b];
      }
      // Sweep from the right to get the area and count right of each plane, then from the left.
      std::array<double, kBins> right_area{};
      std::array<size_t, kBins> right_count{};
      Bounds3 acc;
      size_t n = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.unite(bin_box[b]);
        n += bin_count[b];
        right_area[b] = acc.surface_area();
        right_count[b] = n;
      }
      acc = Bounds3();
      n = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        acc.unite(bin_box[b]);
        n += bin_count[b];
        if (n == 0 || right_count[b + 1] == 0) continue;
        const double cost = 1 + kObjectCost *
                                    (acc.surface_area() * static_cast<double>(n) +
                                     right_area[b + 1] * static_cast<double>(right_count[b + 1])) /
                                    area;
        if (cost < best.cost) best = {axis, lo + extent * (b + 1) / kBins, cost};
      }
    }
    return best;
  }

  /// Fills the node at `index` (already allocated); an interior node's two children are allocated side by
  /// side, so that testing both touches one or two cache lines.
  void build_node(size_t index, size_t begin, size_t end, int depth) {
    Bounds3 box;
    for (size_t i = begin; i < end; ++i) box.unite(in_.boxes[order_[i]]);
    nodes_[index].box = box;
    const size_t count = end - begin;
    const Split split = count > 1 && depth < kMaxSahDepth ? best_split(begin, end, box) : Split{};
    size_t middle = begin;
    if (split.axis >= 0) {
      middle = static_cast<size_t>(
          std::partition(order_.begin() + begin, order_.begin() + end,
                         [&](uint32_t o) { return centroids_[o][split.axis] < split.position; }) -
          order_.begin());
    }
    const bool split_pays = split.axis >= 0 && middle > begin && middle < end;
    if (!split_pays && count <= kMaxLeafObjects) {
      nodes_[index].offset = static_cast<uint32_t>(begin);
      nodes_[index].count = static_cast<uint32_t>(count);
      return;
    }
    if (!split_pays) {
      // Too many objects for a leaf and no useful plane (equal centroids): halve the list.
      middle = begin + count / 2;
    }
    const size_t children = nodes_.size();
    nodes_[index].offset = static_cast<uint32_t>(children);
    nodes_.emplace_back();
    nodes_.emplace_back();
    build_node(children, begin, middle, depth + 1);
    build_node(children + 1, middle, end, depth + 1);
  }

  const IndexedObjects& in_;
  std::vector<BinaryNode>& nodes_;
  std::vector<uint32_t> order_;
  std::vector<math::Vec3> centroids_;
};

/// Appends the wide node for binary interior node `b` (and, first, its subtrees); returns its index.
uint32_t collapse(const std::vector<BinaryNode>& binary, uint32_t b, std::vector<Bvh::Node>& wide) {
  std::array<uint32_t, Bvh::kWidth> members{binary[b].offset, binary[b].offset + 1};
  int n = 2;
  while (n < Bvh::kWidth) {
    int open = -1;
    double largest = -1;
    for (int k = 0; k < n; ++k) {
      const BinaryNode& m = binary[members[k]];
      if (m.count == 0 && m.box.surface_area() > largest) {
        largest = m.box.surface_area();
        open = k;
      }
    }
    if (open < 0) break;
    const uint32_t opened = members[open];
    members[open] = binary[opened].offset;
    members[n++] = binary[opened].offset + 1;
  }
  const auto index = static_cast<uint32_t>(wide.size());
  wide.emplace_back();
  Bvh::Node node{};
  for (int k = 0; k < Bvh::kWidth; ++k) {
    const FloatBox box = k < n ? FloatBox(binary[members[k]].box) : FloatBox::nothing();
    for (int a = 0; a < 3; ++a) {
      node.lo[a][k] = box.lo[a];
      node.hi[a][k] = box.hi[a];
    }
    node.child[k] = Bvh::kNoChild;
    node.count[k] = 0;
    if (k >= n) continue;
    const BinaryNode& m = binary[members[k]];
    node.child[k] = m.count > 0 ? m.offset : collapse(binary, members[k], wide);
    node.count[k] = m.count;
  }
  wide[index] = node;  // after the recursion, which may have moved `wide`
  return index;
}

}  // namespace

Bvh::Bvh(const scene::Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const IndexedObjects indexed(scene);
  std::vector<BinaryNode> binary;
  objects_ = Builder(indexed, binary).build();
  unbounded_ = indexed.unbounded;
  if (!binary.empty()) {
    root_box_ = FloatBox(binary[0].box);
    root_count_ = binary[0].count;
    root_index_ = root_count_ > 0 ? binary[0].offset : collapse(binary, 0, nodes_);
  }
  nodes_.shrink_to_fit();
  stats_ = structure_stats(scene.objects.size(), unbounded_.size(), nodes_.size(),
                           nodes_.size() * sizeof(Node) + objects_.size() * sizeof(objects_[0]), start);
}

namespace {

/// The root of the walk: a node (count 0) or a single leaf, and where the ray enters its box.
struct Subtree {
  uint32_t index;
  uint32_t count;
  double entry;
};

/// The nearest-hit walk over the wide nodes, with the box test of `Slabs` (FloatSlabs or
/// DoubleSlabs). Children hit are pushed farthest first, so the nearest is walked next; a pending child is
/// skipped when a hit nearer than its entry has been found meanwhile.
template <class Slabs>
bool walk(const Slabs& slabs, const std::vector<Bvh::Node>& nodes,
          const std::vector<const scene::Object*>& objects, const Subtree& root, const math::Ray& ray,
          double t_min, double t_max, scene::RayKind kind, scene::SurfaceHit& hit) {
  using Real = typename Slabs::Real;
  /// A subtree waiting to be walked: a node (count 0) or a leaf's objects (count > 0), entered at `entry`.
  /// No default member initialisers: the stack of these must cost nothing to create.
  struct Pending {
    uint32_t index;
    uint32_t count;
    Real entry;
  };
  bool found = false;
  const Real box_t_min = Slabs::round_down(t_min);
  Real box_t_max = Slabs::round_up(t_max);
  NodeTally tally;
  std::array<Pending, kStackSize> stack;
  stack[0] = {root.index, root.count, Slabs::round_down(root.entry)};
  int top = 1;
  while (top > 0) {
    const Pending p = stack[--top];
    if (p.entry > t_max) continue;
    tally.visit();
    if (p.count > 0) {
      for (uint32_t i = p.index; i < p.index + p.count; ++i) {
        if (test_object(*objects[i], ray, t_min, t_max, kind, hit)) {
          t_max = hit.t;
          box_t_max = Slabs::round_up(t_max);
          found = true;
        }
      }
      continue;
    }
    const Bvh::Node& node = nodes[p.index];
    Real entry[Bvh::kWidth];
    int mask = slabs.test(node.lo, node.hi, box_t_min, box_t_max, entry);
    // The children hit are sorted straight onto the stack, farthest first (insertion by decreasing entry).
    Pending* hits = stack.data() + top;
    int n = 0;
    for (; mask != 0; mask &= mask - 1) {
      const int k = std::countr_zero(static_cast<unsigned>(mask));
      if (node.child[k] == Bvh::kNoChild) continue;
      int j = n++;
      for (; j > 0 && hits[j - 1].entry < entry[k]; --j) hits[j] = hits[j - 1];
      hits[j] = {node.child[k], node.count[k], entry[k]};
    }
    top += n;
  }
  return found;
}

}  // namespace

bool Bvh::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                    scene::SurfaceHit& hit) const {
  bool found = test_all(unbounded_, ray, t_min, t_max, kind, hit);
  if (objects_.empty() || !(t_min < t_max)) return found;
  // A root node's children are tested by the walk itself; only a root leaf needs its box tested here.
  double entry = t_min, exit;
  if (root_count_ > 0 && !RayBox(ray).enter(root_box_, t_min, t_max, entry, exit)) return found;
  // Single precision where the ray allows it (half the arithmetic of the double test, four boxes per
  // instruction), else double.
  const FloatSlabs float_slabs(ray);
  const Subtree root{root_index_, root_count_, entry};
  const bool walked_hit = float_slabs.usable()
                              ? walk(float_slabs, nodes_, objects_, root, ray, t_min, t_max, kind, hit)
                              : walk(DoubleSlabs(ray), nodes_, objects_, root, ray, t_min, t_max, kind, hit);
  return walked_hit || found;
}

}  // namespace snell::accel
