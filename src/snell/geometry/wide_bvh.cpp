#include "snell/geometry/wide_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "snell/geometry/collapse_plan.hpp"

namespace snell::geometry {

static_assert(CollapsePlan::kMaxWidth >= WideBvh::kWidth, "a plan for nodes as wide as the tree's");

namespace {

using math::Bounds3;
using math::Vec3;

/// Centroid bins for object splits, and equal-width bins of the node's box for spatial splits.
constexpr int kObjectBins = 16;
constexpr int kSpatialBins = 16;
/// Spatial splits are tried only where the object split's children overlap by more than this fraction of
/// the root's surface area (Stich, Friedrich and Dietrich's alpha, "Spatial splits in bounding volume
/// hierarchies", HPG 2009): elsewhere they rarely pay, and testing them is most of the build's work.
constexpr double kOverlapShare = 1e-5;
/// Spatial splits only at nodes of more than this many full leaves: the budget then goes to the cuts near
/// the root, which spare the most box tests (docs/benchmark.md: long triangles, 32 rather than 4 leaves,
/// 22.7 rather than 32.3 visits a random ray).
constexpr size_t kSpatialMinimumLeaves = 32;

/// The binary tree the builder makes before it is collapsed to WideBvh::Node.
struct BinaryNode {
  Bounds3 box;
  /// Leaf: first position in the leaf order; interior: index of the first child (the second follows it).
  uint32_t offset = 0;
  /// Primitives in a leaf; 0 for an interior node.
  uint32_t count = 0;
};

/// A primitive, or the part of it a spatial split left on one side: its box may be smaller than the
/// primitive's.
struct Reference {
  Bounds3 box;
  uint32_t primitive;
};
using References = std::vector<Reference>;

/// Primitives of each kind in a range.
using KindCounts = std::array<size_t, 2>;

}  // namespace

class WideBvhBuilder {
 public:
  WideBvhBuilder(const WideBvh::Input& in, WideBvh& tree)
      : in_(in),
        tree_(tree),
        reference_limit_(
            static_cast<size_t>(static_cast<double>(in.boxes.size()) * std::max(1.0, in.reference_budget))) {}

  void build() {
    if (in_.boxes.empty()) return;
    References all;
    all.reserve(in_.boxes.size());
    for (size_t i = 0; i < in_.boxes.size(); ++i) all.push_back({in_.boxes[i], static_cast<uint32_t>(i)});
    references_ = all.size();
    for (const Reference& r : all) root_box_.unite(r.box);
    tree_.order_.reserve(std::min(reference_limit_, 2 * all.size()));
    binary_.emplace_back();
    build_node(0, std::move(all), 0);
    tree_.bounds_ = binary_[0].box;
    tree_.root_box_ = FloatBox(binary_[0].box);
    tree_.root_count_ = binary_[0].count;
    if (tree_.root_count_ == 0) {
      std::vector<CollapsePlan::Binary> shape;
      shape.reserve(binary_.size());
      for (const BinaryNode& b : binary_) shape.push_back({b.box.surface_area(), b.count > 0, b.offset});
      const CollapsePlan plan(shape, WideBvh::kWidth);
      tree_.root_index_ = collapse(0, plan);
    } else {
      tree_.root_index_ = binary_[0].offset;
    }
    tree_.nodes_.shrink_to_fit();
    tree_.order_.shrink_to_fit();
  }

 private:
  /// A plane and what it costs. An object split sorts references by their centroids (each goes wholly to
  /// one side); a spatial split cuts the references it crosses in two.
  struct Split {
    int axis = -1;
    double position = 0;
    double cost = 0;
    bool spatial = false;
    Bounds3 left, right;
    KindCounts left_count{}, right_count{};
  };

  uint8_t kind(uint32_t primitive) const { return in_.kinds.empty() ? 0 : in_.kinds[primitive]; }

  /// SAH cost of testing primitives of these counts in one leaf.
  double leaf_cost(const KindCounts& n) const {
    double c = 0;
    for (int k = 0; k < 2; ++k)
      c += in_.cost[k] * static_cast<double>((n[k] + in_.group[k] - 1) / in_.group[k]);
    return c;
  }

  /// SAH cost of a node (one visit) over two leaves of these boxes and counts, in units of `area`.
  double split_cost(const Bounds3& left, const KindCounts& nl, const Bounds3& right, const KindCounts& nr,
                    double area) const {
    return 1 + (left.surface_area() * leaf_cost(nl) + right.surface_area() * leaf_cost(nr)) / area;
  }

  /// The part of reference r's box where the primitive meets the slab lo <= x[axis] <= hi: for a triangle
  /// the box of the triangle clipped to the slab (its corners inside and where its edges cross the planes,
  /// padded for the rounding of those crossings), for anything else the slab's part of the box. Empty
  /// when they do not meet.
  Bounds3 clipped(const Reference& r, int axis, double lo, double hi) const {
    Bounds3 piece = r.box;
    if (!in_.triangles.empty() && kind(r.primitive) == 1) {
      const std::array<Vec3, 3>& corner = in_.triangles[r.primitive];
      Bounds3 part;
      for (int e = 0; e < 3; ++e) {
        const Vec3& p = corner[e];
        const Vec3& q = corner[(e + 1) % 3];
        if (p[axis] >= lo && p[axis] <= hi) part.unite(p);
        for (const double plane : {lo, hi}) {
          if ((p[axis] < plane) == (q[axis] < plane)) continue;
          Vec3 crossing = p + (q - p) * ((plane - p[axis]) / (q[axis] - p[axis]));
          crossing[axis] = plane;
          part.unite(crossing);
        }
      }
      piece = part.empty() ? part : piece.intersection(padded(part));
    }
    piece.lo[axis] = std::max(piece.lo[axis], lo);
    piece.hi[axis] = std::min(piece.hi[axis], hi);
    return piece;
  }

  /// The cheapest centroid plane over kObjectBins bins on each axis, or a leaf's cost if none is cheaper.
  Split object_split(const References& refs, const Bounds3& box, const KindCounts& counts) const {
    Bounds3 centroid_box;
    for (const Reference& r : refs) centroid_box.unite(r.box.center());
    Split best;
    best.cost = leaf_cost(counts);
    const double area = box.surface_area();
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = centroid_box.lo[axis], extent = centroid_box.hi[axis] - lo;
      if (!(extent > 0)) continue;
      std::array<Bounds3, kObjectBins> bin_box;
      std::array<KindCounts, kObjectBins> bin_count{};
      for (const Reference& r : refs) {
        const int b =
            std::min(kObjectBins - 1, static_cast<int>(kObjectBins * (r.box.center()[axis] - lo) / extent));
        bin_box[b].unite(r.box);
        ++bin_count[b][kind(r.primitive)];
      }
      sweep(
          bin_box, bin_count, bin_count, area, [&](int b) { return lo + extent * (b + 1) / kObjectBins; },
          axis, false, best);
    }
    return best;
  }

  /// The cheapest of kSpatialBins - 1 equally spaced planes across the node's box on its longest axis, if
  /// cheaper than `best`: a reference crossing a plane counts on both sides, with the part of it there.
  /// (Planes on the other axes too: about twice the build time for 1.5% fewer visits, docs/benchmark.md.)
  void spatial_split(const References& refs, const Bounds3& box, Split& best) const {
    const double area = box.surface_area();
    const Vec3 size = box.extent();
    const int axis = size.x > size.y ? (size.x > size.z ? 0 : 2) : (size.y > size.z ? 1 : 2);
    const double lo = box.lo[axis], extent = box.hi[axis] - lo;
    if (!(extent > 0) || !std::isfinite(extent)) return;
    const auto plane = [&](int b) {
      return b + 1 == kSpatialBins ? box.hi[axis] : lo + extent * (b + 1) / kSpatialBins;
    };
    const auto bin_of = [&](double x) {
      return std::clamp(static_cast<int>(kSpatialBins * (x - lo) / extent), 0, kSpatialBins - 1);
    };
    std::array<Bounds3, kSpatialBins> bin_box;
    std::array<KindCounts, kSpatialBins> entering{}, leaving{};
    for (const Reference& r : refs) {
      const int first = bin_of(r.box.lo[axis]), last = bin_of(r.box.hi[axis]);
      ++entering[first][kind(r.primitive)];
      ++leaving[last][kind(r.primitive)];
      if (first == last) {
        bin_box[first].unite(r.box);
        continue;
      }
      for (int b = first; b <= last; ++b)
        bin_box[b].unite(clipped(r, axis, b == 0 ? lo : plane(b - 1), plane(b)));
    }
    sweep(bin_box, entering, leaving, area, plane, axis, true, best);
  }

  /// Evaluates the planes between bins: left of plane b lie the references entering bins 0 .. b, right
  /// of it those leaving bins b + 1 ... Keeps the cheapest in `best`.
  template <size_t N, class Plane>
  void sweep(const std::array<Bounds3, N>& bin_box, const std::array<KindCounts, N>& entering,
             const std::array<KindCounts, N>& leaving, double area, const Plane& plane, int axis,
             bool spatial, Split& best) const {
    std::array<Bounds3, N> right_box;
    std::array<KindCounts, N> right_count{};
    Bounds3 acc;
    KindCounts n{};
    for (size_t b = N - 1; b > 0; --b) {
      acc.unite(bin_box[b]);
      for (int k = 0; k < 2; ++k) n[k] += leaving[b][k];
      right_box[b] = acc;
      right_count[b] = n;
    }
    acc = Bounds3();
    n = {};
    for (size_t b = 0; b + 1 < N; ++b) {
      acc.unite(bin_box[b]);
      for (int k = 0; k < 2; ++k) n[k] += entering[b][k];
      const KindCounts& right = right_count[b + 1];
      if (n[0] + n[1] == 0 || right[0] + right[1] == 0) continue;
      const double cost = split_cost(acc, n, right_box[b + 1], right, area);
      if (cost < best.cost)
        best = {axis, plane(static_cast<int>(b)), cost, spatial, acc, right_box[b + 1], n, right};
    }
  }

  /// Sends each reference to the side of the plane its centroid lies on.
  static void divide_by_centroid(References& refs, const Split& s, References& left, References& right) {
    for (const Reference& r : refs) (r.box.center()[s.axis] < s.position ? left : right).push_back(r);
  }

  /// Sends each reference to the side of the plane it lies on; one crossing it is cut in two, or, where
  /// that is cheaper by the SAH, sent whole to one side ("reference unsplitting", Stich et al.).
  void divide_spatially(References& refs, const Split& s, References& left, References& right) {
    Bounds3 left_box = s.left, right_box = s.right;
    KindCounts nl = s.left_count, nr = s.right_count;
    for (const Reference& r : refs) {
      if (r.box.hi[s.axis] <= s.position) {
        left.push_back(r);
        continue;
      }
      if (r.box.lo[s.axis] >= s.position) {
        right.push_back(r);
        continue;
      }
      const uint8_t k = kind(r.primitive);
      // The sweep saw a reference that ends on the plane on one side only: that one is always cut.
      if (nl[k] > 0 && nr[k] > 0) {
        // Costs up to the common factor (the children's leaf costs per area, counts as the sweep had them).
        KindCounts nl_less = nl, nr_less = nr;
        --nl_less[k];
        --nr_less[k];
        const double cut = left_box.surface_area() * leaf_cost(nl) + right_box.surface_area() * leaf_cost(nr);
        const double whole_left = Bounds3(left_box).unite(r.box).surface_area() * leaf_cost(nl) +
                                  right_box.surface_area() * leaf_cost(nr_less);
        const double whole_right = left_box.surface_area() * leaf_cost(nl_less) +
                                   Bounds3(right_box).unite(r.box).surface_area() * leaf_cost(nr);
        if (whole_left < cut && whole_left <= whole_right) {
          left.push_back(r);
          left_box.unite(r.box);
          nr = nr_less;
          continue;
        }
        if (whole_right < cut) {
          right.push_back(r);
          right_box.unite(r.box);
          nl = nl_less;
          continue;
        }
      }
      const Bounds3 l = clipped(r, s.axis, -math::kInfinity, s.position);
      const Bounds3 h = clipped(r, s.axis, s.position, math::kInfinity);
      if (!l.empty()) left.push_back({l, r.primitive});
      if (!h.empty()) right.push_back({h, r.primitive});
    }
  }

  /// Fills the node at `index` (already allocated) over `refs`; an interior node's two children are
  /// allocated side by side, so that testing both touches one or two cache lines.
  void build_node(size_t index, References refs, int depth) {
    Bounds3 box;
    KindCounts counts{};
    for (const Reference& r : refs) {
      box.unite(r.box);
      ++counts[kind(r.primitive)];
    }
    binary_[index].box = box;
    const size_t count = refs.size();
    References left, right;
    if (count > 1 && depth < WideBvh::kMaxSahDepth) {
      Split split = object_split(refs, box, counts);
      const double overlap = split.left.intersection(split.right).surface_area();
      if (references_ < reference_limit_ && count > kSpatialMinimumLeaves * in_.max_leaf &&
          (split.axis < 0 || overlap > kOverlapShare * root_box_.surface_area()))
        spatial_split(refs, box, split);
      if (split.spatial)
        divide_spatially(refs, split, left, right);
      else if (split.axis >= 0)
        divide_by_centroid(refs, split, left, right);
      if (left.empty() || right.empty()) {
        left.clear();
        right.clear();
      }
    }
    const bool mixed = counts[0] > 0 && counts[1] > 0;
    if (left.empty() && count <= in_.max_leaf && !mixed) {
      make_leaf(index, refs);
      return;
    }
    if (left.empty() && count <= in_.max_leaf) {
      // A leaf's worth of both kinds: one leaf of each.
      for (const Reference& r : refs) (kind(r.primitive) == 0 ? left : right).push_back(r);
    } else if (left.empty()) {
      // Too many primitives for a leaf and no useful plane (equal centroids, or past the SAH depth):
      // halve the list.
      left.assign(refs.begin(), refs.begin() + static_cast<std::ptrdiff_t>(count / 2));
      right.assign(refs.begin() + static_cast<std::ptrdiff_t>(count / 2), refs.end());
    }
    references_ += left.size() + right.size() - count;
    refs = References();  // free before the recursion
    const size_t children = binary_.size();
    binary_[index].offset = static_cast<uint32_t>(children);
    binary_.emplace_back();
    binary_.emplace_back();
    build_node(children, std::move(left), depth + 1);
    build_node(children + 1, std::move(right), depth + 1);
  }

  void make_leaf(size_t index, const References& refs) {
    binary_[index].offset = static_cast<uint32_t>(tree_.order_.size());
    binary_[index].count = static_cast<uint32_t>(refs.size());
    for (const Reference& r : refs) tree_.order_.push_back(r.primitive);
  }

  /// Appends the wide node for binary interior node `b` (and, first, its subtrees), its children as
  /// `plan` has them; returns its index.
  uint32_t collapse(uint32_t b, const CollapsePlan& plan) {
    std::vector<WideBvh::Node>& wide = tree_.nodes_;
    std::array<uint32_t, CollapsePlan::kMaxWidth> members{};
    const int n = plan.members(b, members);
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
      node.child[k] = m.count > 0 ? m.offset : collapse(members[k], plan);
      node.count[k] = m.count;
    }
    wide[index] = node;  // after the recursion, which may have moved `wide`
    return index;
  }

  const WideBvh::Input& in_;
  WideBvh& tree_;
  std::vector<BinaryNode> binary_;
  Bounds3 root_box_;
  /// References made so far, and the most allowed (Input::reference_budget).
  size_t references_ = 0;
  size_t reference_limit_;
};

WideBvh::WideBvh(const Input& input) {
  WideBvhBuilder(input, *this).build();
}

}  // namespace snell::geometry
