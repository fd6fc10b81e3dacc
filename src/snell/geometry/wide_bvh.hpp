#pragma once
// Bounding volume hierarchy over primitives given by their boxes, shared by the scene-level accelerator
// (accel/bvh.hpp) and the mesh shape: binary, built top-down with the surface area heuristic over 16
// centroid bins (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007) and, where
// children would overlap, spatial splits that put a primitive in both (Stich, Friedrich and Dietrich,
// "Spatial splits in bounding volume hierarchies", 2009), collapsed to eight children per node by the
// collapse of least summed node area (collapse_plan.hpp), walked nearest child first with a fixed stack.
// Leaves are ranges of the leaf order, in which a primitive may appear more than once; their owner keeps what
// they hold (objects, packed triangles) and may relabel them.
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

/// Asks for the cache lines of [p, p + bytes) ahead of use. Callers pass a constant size; the loop is
/// unrolled on purpose, as GCC's own choice came and went with unrelated changes to the walk around it
/// (a rolled loop cost a random ray through 100k triangles about 200 instructions).
SNELL_LANES_INLINE void prefetch_lines(const void* p, size_t bytes) {
#pragma GCC unroll 8
  for (size_t offset = 0; offset < bytes; offset += 64)
    __builtin_prefetch(static_cast<const char*>(p) + offset);
}

class WideBvh {
 public:
  /// kWidth children per node: the binary SAH tree collapsed (collapse_plan.hpp; wide nodes as in Wald,
  /// Benthin and Boulos, "Getting rid of packets", 2008, with the eight-wide nodes of Ernst and Greiner's
  /// multi BVH, 2008), so a walk makes fewer dependent node fetches: eight measured 10-20% faster than four
  /// on incoherent rays (docs/benchmark.md), as a node's four adjacent cache lines arrive together. Child
  /// boxes are float, rounded outward, and tested in single precision, conservatively (float_slabs.hpp).
  /// Unused slots hold FloatBox::nothing(), which no ray enters.
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
    // Only rays with a finite origin and direction are walked: one with a NaN or infinite component would
    // enter the empty box of an unused child slot (the slab test's NaN rule keeps the window where a
    // distance is NaN), and such a ray meets nothing anyway.
    if (order_.empty() || !(t_min < t_max) || !math::is_finite(ray.origin) || !math::is_finite(ray.direction))
      return 0;
    // A root node's children are tested by the walk itself; only a root leaf needs its box tested here.
    double entry, exit;
    if (root_count_ > 0 && !RayBox(ray).enter(root_box_, t_min, t_max, entry, exit)) return 0;
    // Single precision where the ray and window allow it (half the arithmetic of the double test, L boxes
    // per instruction), else double.
    const FloatSlabs float_slabs(ray);
    return float_slabs.usable() && t_min >= 0
               ? walk_with<L, kOrdered>(float_slabs, t_min, t_max, leaf, prefetch_leaf)
               : walk_with<L, kOrdered>(DoubleSlabs(ray), t_min, t_max, leaf, prefetch_leaf);
  }

 private:
  // Below this depth only balanced halving: at most 32 more levels for 2^32 primitives, so a traversal
  // stack of kStackSize (one entry per level) never overflows.
  static constexpr int kMaxSahDepth = 64;
  static constexpr int kMaxBinaryDepth = kMaxSahDepth + 32;
  // A walk pushes at most kWidth - 1 children per level (sorted in place on the stack).
  static constexpr int kStackSize = (kWidth - 1) * kMaxBinaryDepth + kWidth;
  friend class WideBvhBuilder;

  /// The walk over the wide nodes with the box test of `Slabs` (FloatSlabs or DoubleSlabs). Of the children
  /// hit the nearest (kOrdered) is walked next and the others pushed farthest first; a pending child is
  /// skipped when a hit nearer than its entry has been found meanwhile.
  template <int L, bool kOrdered, class Slabs, class Leaf, class PrefetchLeaf>
  SNELL_LANES_INLINE size_t walk_with(const Slabs& slabs, double t_min, double t_max, Leaf& leaf,
                                      PrefetchLeaf& prefetch_leaf) const {
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
    int top = 0;
    // The subtree walked now, held in registers: the nearest child hit is walked straight after its node,
    // without a round trip through the stack (as Embree's BVHNNodeTraverser1Hit), and a node with one or
    // two children hit needs no sort.
    uint32_t index = root_index_, count = root_count_;
    while (true) {
      ++visited;
      if (count > 0) {
        const double before = t_max;
        if (leaf(index, count, t_max)) break;
        if (t_max != before) {
          box_t_max = Slabs::round_up(t_max);
          lanes.set_t_max(box_t_max);
        }
      } else {
        const Node& node = nodes_[index];
        Real entry[kWidth];
        unsigned mask = static_cast<unsigned>(lanes.test(node.planes, entry));
        if (mask != 0) {
          const auto queue = [&](int k) __attribute__((always_inline)) {
            if (node.count[k] > 0)
              prefetch_leaf(node.child[k]);
            else
              prefetch_lines(&nodes_[node.child[k]], sizeof(Node));
          };
          const int k0 = std::countr_zero(mask);
          mask &= mask - 1;
          queue(k0);
          if (mask == 0) {
            index = node.child[k0];
            count = node.count[k0];
            continue;
          }
          const int k1 = std::countr_zero(mask);
          mask &= mask - 1;
          queue(k1);
          if (mask == 0) {
            // Of equal entries the later child is walked first, as the sort below does.
            const bool second_first = !kOrdered || entry[k1] <= entry[k0];
            const int near = second_first ? k1 : k0, far = second_first ? k0 : k1;
            stack[top++] = {node.child[far], node.count[far], entry[far]};
            index = node.child[near];
            count = node.count[near];
            continue;
          }
          // Three or more: sorted straight onto the stack, farthest first (insertion by decreasing entry),
          // and the nearest taken off again.
          Pending* hits = stack.data() + top;
          hits[0] = {node.child[k0], node.count[k0], entry[k0]};
          int n = 1;
          const auto insert = [&](int k) __attribute__((always_inline)) {
            int j = n++;
            if constexpr (kOrdered)
              for (; j > 0 && hits[j - 1].entry < entry[k]; --j) hits[j] = hits[j - 1];
            hits[j] = {node.child[k], node.count[k], entry[k]};
          };
          insert(k1);
          for (; mask != 0; mask &= mask - 1) {
            const int k = std::countr_zero(mask);
            queue(k);
            insert(k);
          }
          top += n - 1;
          index = hits[n - 1].index;
          count = hits[n - 1].count;
          continue;
        }
      }
      // Next: the nearest pending subtree not entered beyond the nearest hit (box_t_max >= t_max).
      do {
        if (top == 0) return visited;
        --top;
      } while (stack[top].entry > box_t_max);
      index = stack[top].index;
      count = stack[top].count;
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
