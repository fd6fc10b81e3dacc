#include "snell/accel/bvh.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <numeric>

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
constexpr int kStackSize = 128;

class Builder {
 public:
  Builder(const IndexedObjects& objects, std::vector<Bvh::Node>& nodes) : in_(objects), nodes_(nodes) {
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
    nodes_[index].box = FloatBox(box);
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
  std::vector<Bvh::Node>& nodes_;
  std::vector<uint32_t> order_;
  std::vector<math::Vec3> centroids_;
};

}  // namespace

Bvh::Bvh(const scene::Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const IndexedObjects indexed(scene);
  objects_ = Builder(indexed, nodes_).build();
  unbounded_ = indexed.unbounded;
  nodes_.shrink_to_fit();
  stats_ = structure_stats(scene.objects.size(), unbounded_.size(), nodes_.size(),
                           nodes_.size() * sizeof(Node) + objects_.size() * sizeof(objects_[0]), start);
}

bool Bvh::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                    scene::SurfaceHit& hit) const {
  bool found = test_all(unbounded_, ray, t_min, t_max, kind, hit);
  if (nodes_.empty() || !(t_min < t_max)) return found;
  const RayBox slabs(ray);
  double root_entry, root_exit;
  if (!slabs.enter(nodes_[0].box, t_min, t_max, root_entry, root_exit)) return found;
  // Children are tested from their parent, the nearer walked first and the other kept with its entry t,
  // so that it is skipped when a hit nearer than that entry has been found meanwhile.
  struct Pending {
    uint32_t node;
    double entry;
  };
  std::array<Pending, kStackSize> stack;
  int top = 0;
  uint32_t current = 0;
  for (;;) {
    const Node& node = nodes_[current];
    if (node.count > 0) {
      for (uint32_t i = node.offset; i < node.offset + node.count; ++i) {
        if (test_object(*objects_[i], ray, t_min, t_max, kind, hit)) {
          t_max = hit.t;
          found = true;
        }
      }
    } else {
      uint32_t near = node.offset, far = node.offset + 1;
      double near_entry, far_entry, exit;
      bool near_hit = slabs.enter(nodes_[near].box, t_min, t_max, near_entry, exit);
      bool far_hit = slabs.enter(nodes_[far].box, t_min, t_max, far_entry, exit);
      if (near_hit && far_hit) {
        if (far_entry < near_entry) {
          std::swap(near, far);
          std::swap(near_entry, far_entry);
        }
        stack[top++] = {far, far_entry};
        current = near;
        continue;
      }
      if (near_hit || far_hit) {
        current = near_hit ? near : far;
        continue;
      }
    }
    for (;;) {
      if (top == 0) return found;
      const Pending p = stack[--top];
      if (p.entry <= t_max) {
        current = p.node;
        break;
      }
    }
  }
  return found;
}

}  // namespace snell::accel
