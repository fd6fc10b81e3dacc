#include "snell/geometry/wide_bvh.hpp"

#include <algorithm>
#include <numeric>

namespace snell::geometry {

namespace {

using math::Bounds3;

constexpr int kBins = 16;

/// The binary tree the builder makes before it is collapsed to WideBvh::Node.
struct BinaryNode {
  Bounds3 box;
  /// Leaf: first primitive; interior: index of the first child (the second follows it).
  uint32_t offset = 0;
  /// Primitives in a leaf; 0 for an interior node.
  uint32_t count = 0;
};

/// Primitives of each kind in a range.
using KindCounts = std::array<size_t, 2>;

}  // namespace

class WideBvhBuilder {
 public:
  WideBvhBuilder(const WideBvh::Input& in, WideBvh& tree) : in_(in), tree_(tree) {
    tree_.order_.resize(in.boxes.size());
    std::iota(tree_.order_.begin(), tree_.order_.end(), 0u);
    centroids_.reserve(in.boxes.size());
    for (const Bounds3& b : in.boxes) centroids_.push_back(b.center());
  }

  void build() {
    if (tree_.order_.empty()) return;
    binary_.emplace_back();
    build_node(0, 0, tree_.order_.size(), 0);
    tree_.bounds_ = binary_[0].box;
    tree_.root_box_ = FloatBox(binary_[0].box);
    tree_.root_count_ = binary_[0].count;
    tree_.root_index_ = tree_.root_count_ > 0 ? binary_[0].offset : collapse(0);
    tree_.nodes_.shrink_to_fit();
  }

 private:
  struct Split {
    int axis = -1;
    double position = 0;
    double cost = 0;
  };

  uint8_t kind(uint32_t primitive) const { return in_.kinds.empty() ? 0 : in_.kinds[primitive]; }

  /// SAH cost of testing primitives of these counts in one leaf.
  double leaf_cost(const KindCounts& n) const {
    double c = 0;
    for (int k = 0; k < 2; ++k)
      c += in_.cost[k] * static_cast<double>((n[k] + in_.group[k] - 1) / in_.group[k]);
    return c;
  }

  Split best_split(size_t begin, size_t end, const Bounds3& box, const KindCounts& counts) const {
    const std::vector<uint32_t>& order = tree_.order_;
    Bounds3 centroid_box;
    for (size_t i = begin; i < end; ++i) centroid_box.unite(centroids_[order[i]]);
    Split best;
    best.cost = leaf_cost(counts);  // cost of a leaf, in units of box area
    const double area = box.surface_area();
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = centroid_box.lo[axis], extent = centroid_box.hi[axis] - lo;
      if (!(extent > 0)) continue;
      std::array<Bounds3, kBins> bin_box;
      std::array<KindCounts, kBins> bin_count{};
      for (size_t i = begin; i < end; ++i) {
        const uint32_t o = order[i];
        const int b = std::min(kBins - 1, static_cast<int>(kBins * (centroids_[o][axis] - lo) / extent));
        bin_box[b].unite(in_.boxes[o]);
        ++bin_count[b][kind(o)];
      }
      // Sweep from the right to get the area and counts right of each plane, then from the left.
      std::array<double, kBins> right_area{};
      std::array<KindCounts, kBins> right_count{};
      Bounds3 acc;
      KindCounts n{};
      for (int b = kBins - 1; b > 0; --b) {
        acc.unite(bin_box[b]);
        for (int k = 0; k < 2; ++k) n[k] += bin_count[b][k];
        right_area[b] = acc.surface_area();
        right_count[b] = n;
      }
      acc = Bounds3();
      n = {};
      for (int b = 0; b < kBins - 1; ++b) {
        acc.unite(bin_box[b]);
        for (int k = 0; k < 2; ++k) n[k] += bin_count[b][k];
        const KindCounts& right = right_count[b + 1];
        if (n[0] + n[1] == 0 || right[0] + right[1] == 0) continue;
        const double cost =
            1 + (acc.surface_area() * leaf_cost(n) + right_area[b + 1] * leaf_cost(right)) / area;
        if (cost < best.cost) best = {axis, lo + extent * (b + 1) / kBins, cost};
      }
    }
    return best;
  }

  /// Fills the node at `index` (already allocated); an interior node's two children are allocated side by
  /// side, so that testing both touches one or two cache lines.
  void build_node(size_t index, size_t begin, size_t end, int depth) {
    std::vector<uint32_t>& order = tree_.order_;
    Bounds3 box;
    KindCounts counts{};
    for (size_t i = begin; i < end; ++i) {
      box.unite(in_.boxes[order[i]]);
      ++counts[kind(order[i])];
    }
    binary_[index].box = box;
    const size_t count = end - begin;
    const Split split =
        count > 1 && depth < WideBvh::kMaxSahDepth ? best_split(begin, end, box, counts) : Split{};
    size_t middle = begin;
    if (split.axis >= 0) {
      middle = static_cast<size_t>(
          std::partition(order.begin() + begin, order.begin() + end,
                         [&](uint32_t o) { return centroids_[o][split.axis] < split.position; }) -
          order.begin());
    }
    const bool split_pays = split.axis >= 0 && middle > begin && middle < end;
    const bool mixed = counts[0] > 0 && counts[1] > 0;
    if (!split_pays && count <= in_.max_leaf && !mixed) {
      binary_[index].offset = static_cast<uint32_t>(begin);
      binary_[index].count = static_cast<uint32_t>(count);
      return;
    }
    if (!split_pays && count <= in_.max_leaf) {
      // A leaf's worth of both kinds: one leaf of each.
      middle = static_cast<size_t>(std::partition(order.begin() + begin, order.begin() + end,
                                                  [&](uint32_t o) { return kind(o) == 0; }) -
                                   order.begin());
    } else if (!split_pays) {
      // Too many primitives for a leaf and no useful plane (equal centroids): halve the list.
      middle = begin + count / 2;
    }
    const size_t children = binary_.size();
    binary_[index].offset = static_cast<uint32_t>(children);
    binary_.emplace_back();
    binary_.emplace_back();
    build_node(children, begin, middle, depth + 1);
    build_node(children + 1, middle, end, depth + 1);
  }

  /// Appends the wide node for binary interior node `b` (and, first, its subtrees); returns its index.
  uint32_t collapse(uint32_t b) {
    std::vector<WideBvh::Node>& wide = tree_.nodes_;
    std::array<uint32_t, WideBvh::kWidth> members{binary_[b].offset, binary_[b].offset + 1};
    int n = 2;
    while (n < WideBvh::kWidth) {
      int open = -1;
      double largest = -1;
      for (int k = 0; k < n; ++k) {
        const BinaryNode& m = binary_[members[k]];
        if (m.count == 0 && m.box.surface_area() > largest) {
          largest = m.box.surface_area();
          open = k;
        }
      }
      if (open < 0) break;
      const uint32_t opened = members[open];
      members[open] = binary_[opened].offset;
      members[n++] = binary_[opened].offset + 1;
    }
    const auto index = static_cast<uint32_t>(wide.size());
    wide.emplace_back();
    WideBvh::Node node{};
    for (int k = 0; k < WideBvh::kWidth; ++k) {
      const FloatBox box = k < n ? FloatBox(binary_[members[k]].box) : FloatBox::nothing();
      for (int a = 0; a < 3; ++a) {
        node.planes[a][k] = box.lo[a];
        node.planes[3 + a][k] = box.hi[a];
      }
      node.child[k] = WideBvh::kNoChild;
      node.count[k] = 0;
      if (k >= n) continue;
      const BinaryNode& m = binary_[members[k]];
      node.child[k] = m.count > 0 ? m.offset : collapse(members[k]);
      node.count[k] = m.count;
    }
    wide[index] = node;  // after the recursion, which may have moved `wide`
    return index;
  }

  const WideBvh::Input& in_;
  WideBvh& tree_;
  std::vector<BinaryNode> binary_;
  std::vector<math::Vec3> centroids_;
};

WideBvh::WideBvh(const Input& input) {
  WideBvhBuilder(input, *this).build();
}

}  // namespace snell::geometry
