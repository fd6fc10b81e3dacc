#pragma once
// Bounding volume hierarchy over primitives given by their boxes, shared by the scene-level accelerator
// (accel/bvh.hpp) and the mesh shape: binary, built top-down with the surface area heuristic over 16
// centroid bins (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007) and, where
// children would overlap, spatial splits that put a primitive in both (Stich, Friedrich and Dietrich,
// "Spatial splits in bounding volume hierarchies", 2009), collapsed to eight children per node, walked
// nearest child first with a fixed stack. Leaves are ranges of the leaf order, in which a primitive may
// appear more than once; their owner keeps what they hold (objects, packed triangles) and may relabel them.
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "snell/geometry/float_slabs.hpp"
#include "snell/geometry/four_boxes.hpp"
#include "snell/geometry/ray_box.hpp"
#include "snell/math/bounds.hpp"
#include "snell/math/float_lanes.hpp"
#include "snell/math/ray.hpp"

namespace snell::geometry {

/// Asks for the cache lines of [p, p + bytes) ahead of use.
SNELL_LANES_INLINE void prefetch_lines(const void* p, size_t bytes) {
  for (size_t offset = 0; offset < bytes; offset += 64)
    __builtin_prefetch(static_cast<const char*>(p) + offset);
}

class WideBvh {
 public:
  /// kWidth children per node: the binary SAH tree collapsed (each node opens its largest interior
  /// children until it has kWidth; Wald, Benthin and Boulos, "Getting rid of packets", 2008, with the
  /// eight-wide nodes of Ernst and Greiner's multi BVH, 2008), so a walk makes fewer dependent node
  /// fetches: eight measured 10-20% faster than four on incoherent rays (docs/benchmark.md), as a node's
  /// four adjacent cache lines arrive together. Child boxes are float, rounded outward, and tested in single
  /// precision, conservatively (float_slabs.hpp). Unused slots hold FloatBox::nothing(), which no ray enters.
  static constexpr int kWidth = 8;
  struct alignas(64) Node {
    /// Child k's box: rows 0-2 its lo x, y, z, rows 3-5 its hi (so a ray picks its near and far rows once).
    float planes[6][kWidth];
    /// Interior child: its node index, count 0. Leaf child: its label (by default the first primitive
    /// in the leaf order), count > 0. Unused slot: kNoChild, count 0.
    uint32_t child[kWidth];
    uint32_t count[kWidth];
  };
  static constexpr uint32_t kNoChild = UINT32_MAX;

  /// What the tree is built over, and the SAH costs relative to one node visit.
  struct Input {
    /// Each primitive's box (padded by the caller as its tests need).
    std::span<const math::Bounds3> boxes;
    /// Each primitive's kind (0 or 1; empty: all 0). A leaf holds primitives of one kind only.
    std::span<const uint8_t> kinds;
    /// Testing a leaf costs cost[k] per started group of group[k] primitives of kind k (triangles are
    /// tested eight at a time).
    std::array<double, 2> cost{4, 4};
    std::array<uint32_t, 2> group{1, 1};
    /// At most this many primitives per leaf.
    uint32_t max_leaf = 8;
    /// Spatial splits: at most this many references (a primitive in several leaves) per primitive, on
    /// average, over the tree; 1 makes none.
    double reference_budget = 1;
    /// The corners of each primitive of kind 1 (entries of kind 0 unused), so that a spatial split bounds
    /// the parts of the triangle itself on each side; empty: the parts of its box.
    std::span<const std::array<math::Vec3, 3>> triangles;
  };

  WideBvh() = default;
  explicit WideBvh(const Input& input);

  bool empty() const { return order_.empty(); }
  /// Leaf order: position i of the leaves' ranges holds input primitive order()[i].
  const std::vector<uint32_t>& order() const { return order_; }
  size_t node_count() const { return nodes_.size(); }
  size_t bytes() const { return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(uint32_t); }
  math::Bounds3 bounds() const { return bounds_; }

  /// Replaces each leaf's label by relabel(first, count) (first: its range's start in the leaf order).
  template <class Relabel>
  void relabel_leaves(Relabel&& relabel) {
    if (root_count_ > 0) root_index_ = relabel(root_index_, root_count_);
    for (Node& n : nodes_)
      for (int k = 0; k < kWidth; ++k)
        if (n.count[k] > 0) n.child[k] = relabel(n.child[k], n.count[k]);
  }

  /// Calls leaf(label, count, t_max) for the leaves whose box the ray may enter within [t_min, t_max],
  /// nearest box first; `leaf` may lower t_max (later boxes are culled against it), and returning true
  /// ends the walk. With kOrdered false the children are walked in no particular order (occlusion
  /// queries, which take any hit: the sort of each node's children only costs there, and shadow rays
  /// through 100k triangles ran 1.36x faster without it). L box tests per instruction (math/float_lanes.hpp).
  /// prefetch_leaf(label) is called for each leaf as it is queued, and the tree prefetches queued nodes
  /// likewise: a walk over a tree larger than the caches waits mostly on memory, and a queued child's lines
  /// then arrive while its siblings are tested (random rays through 100k triangles: about 1.3x the rays per
  /// second). Returns the nodes visited.
  template <int L, bool kOrdered = true, class Leaf, class PrefetchLeaf>
  SNELL_LANES_INLINE size_t walk(const math::Ray& ray, double t_min, double t_max, Leaf& leaf,
                                 PrefetchLeaf& prefetch_leaf) const {
    if (order_.empty() || !(t_min < t_max)) return 0;
    // A root node's children are tested by the walk itself; only a root leaf needs its box tested here.
    double entry = t_min, exit;
    if (root_count_ > 0 && !RayBox(ray).enter(root_box_, t_min, t_max, entry, exit)) return 0;
    // Single precision where the ray and window allow it (half the arithmetic of the double test, L boxes
    // per instruction), else double.
    const FloatSlabs float_slabs(ray);
    return float_slabs.usable() && t_min >= 0
               ? walk_with<L, kOrdered>(float_slabs, entry, t_min, t_max, leaf, prefetch_leaf)
               : walk_with<L, kOrdered>(DoubleSlabs(ray), entry, t_min, t_max, leaf, prefetch_leaf);
  }

 private:
  // Below this depth only balanced halving: at most 32 more levels for 2^32 primitives, so a traversal
  // stack of kStackSize (one entry per level) never overflows.
  static constexpr int kMaxSahDepth = 64;
  static constexpr int kMaxBinaryDepth = kMaxSahDepth + 32;
  // A walk pops one node and pushes at most kWidth children per level (sorted in place on the stack).
  static constexpr int kStackSize = (kWidth - 1) * kMaxBinaryDepth + kWidth;
  friend class WideBvhBuilder;

  /// The walk over the wide nodes with the box test of `Slabs` (FloatSlabs or DoubleSlabs). Children hit
  /// are pushed farthest first (kOrdered), so the nearest is walked next; a pending child is skipped when a
  /// hit nearer than its entry has been found meanwhile.
  template <int L, bool kOrdered, class Slabs, class Leaf, class PrefetchLeaf>
  SNELL_LANES_INLINE size_t walk_with(const Slabs& slabs, double root_entry, double t_min, double t_max,
                                      Leaf& leaf, PrefetchLeaf& prefetch_leaf) const {
    using Real = typename Slabs::Real;
    /// A subtree waiting to be walked: a node (count 0) or a leaf (count > 0), entered at `entry`. No
    /// default member initialisers: the stack of these must cost nothing to create. 16 bytes, so that an
    /// entry's address is one shift of its index.
    struct alignas(16) Pending {
      uint32_t index;
      uint32_t count;
      Real entry;
    };
    Real box_t_max = Slabs::round_up(t_max);
    typename Slabs::template Lanes<L> lanes(slabs, Slabs::round_down(t_min), box_t_max);
    size_t visited = 0;
    std::array<Pending, kStackSize> stack;
    stack[0] = {root_index_, root_count_, Slabs::round_down(root_entry)};
    int top = 1;
    while (top > 0) {
      const Pending p = stack[--top];
      // box_t_max >= t_max: a child entered beyond it is entered beyond the nearest hit.
      if (p.entry > box_t_max) continue;
      ++visited;
      if (p.count > 0) {
        const double before = t_max;
        if (leaf(p.index, p.count, t_max)) break;
        if (t_max != before) {
          box_t_max = Slabs::round_up(t_max);
          lanes.set_t_max(box_t_max);
        }
        continue;
      }
      const Node& node = nodes_[p.index];
      Real entry[kWidth];
      int mask = lanes.test(node.planes, entry);
      // The children hit are sorted straight onto the stack, farthest first (insertion by decreasing
      // entry).
      Pending* hits = stack.data() + top;
      int n = 0;
      for (; mask != 0; mask &= mask - 1) {
        const int k = std::countr_zero(static_cast<unsigned>(mask));
        if (node.child[k] == kNoChild) continue;
        int j = n++;
        if constexpr (kOrdered)
          for (; j > 0 && hits[j - 1].entry < entry[k]; --j) hits[j] = hits[j - 1];
        hits[j] = {node.child[k], node.count[k], entry[k]};
        if (node.count[k] > 0)
          prefetch_leaf(node.child[k]);
        else
          prefetch_lines(&nodes_[node.child[k]], sizeof(Node));
      }
      top += n;
    }
    return visited;
  }

  /// The root: a node (count 0) or, for few primitives, a single leaf.
  uint32_t root_index_ = 0;
  uint32_t root_count_ = 0;
  FloatBox root_box_;
  math::Bounds3 bounds_;
  std::vector<Node> nodes_;
  std::vector<uint32_t> order_;
};

}  // namespace snell::geometry
