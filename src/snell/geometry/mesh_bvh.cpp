#include "snell/geometry/mesh_bvh.hpp"

#include <algorithm>
#include <array>

namespace snell::geometry {
namespace {
constexpr int kBins = 16;
constexpr int kMaxLeafSize = 4;
// The traversal stack holds at most one entry per level plus one, so the depth is capped below its size.
constexpr int kMaxDepth = 100;
}  // namespace

MeshBvh::MeshBvh(std::span<const math::Bounds3> prim_bounds) {
  const int n = static_cast<int>(prim_bounds.size());
  if (n == 0) return;
  prims_.resize(n);
  std::vector<math::Vec3> centroids(n);
  for (int i = 0; i < n; ++i) {
    prims_[i] = i;
    centroids[i] = prim_bounds[i].center();
  }
  nodes_.reserve(2 * static_cast<size_t>(n));
  nodes_.emplace_back();
  build(prim_bounds, centroids, 0, 0, n, 0);
}

void MeshBvh::build(std::span<const math::Bounds3> pb, std::vector<math::Vec3>& centroids, int node,
                    int begin, int end, int depth) {
  math::Bounds3 box, cbox;
  for (int i = begin; i < end; ++i) {
    box.unite(pb[prims_[i]]);
    cbox.unite(centroids[prims_[i]]);
  }
  nodes_[node].box = box;
  const int n = end - begin;
  const auto make_leaf = [&] {
    nodes_[node].offset = begin;
    nodes_[node].count = n;
  };
  if (n <= kMaxLeafSize / 2 || depth >= kMaxDepth) return make_leaf();
  const math::Vec3 ext = cbox.extent();
  const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
  if (!(ext[axis] > 0)) return make_leaf();  // all centroids coincide: no split separates them

  struct Bin {
    math::Bounds3 box;
    int count = 0;
  };
  std::array<Bin, kBins> bins{};
  const double scale = kBins / ext[axis];
  const auto bin_of = [&](int prim) {
    return std::min(kBins - 1, static_cast<int>((centroids[prim][axis] - cbox.lo[axis]) * scale));
  };
  for (int i = begin; i < end; ++i) {
    Bin& b = bins[bin_of(prims_[i])];
    ++b.count;
    b.box.unite(pb[prims_[i]]);
  }
  // Sweep from the right to get the cost of every split plane (SAH with unit costs).
  std::array<double, kBins> right_cost{};
  math::Bounds3 acc;
  int cnt = 0;
  for (int i = kBins - 1; i > 0; --i) {
    acc.unite(bins[i].box);
    cnt += bins[i].count;
    right_cost[i] = cnt * acc.surface_area();
  }
  acc = {};
  cnt = 0;
  double best_cost = math::kInfinity;
  int best_split = -1;
  for (int i = 0; i < kBins - 1; ++i) {
    acc.unite(bins[i].box);
    cnt += bins[i].count;
    const double cost = cnt * acc.surface_area() + right_cost[i + 1];
    if (cnt > 0 && cnt < n && cost < best_cost) {
      best_cost = cost;
      best_split = i;
    }
  }
  const double leaf_cost = n * box.surface_area();
  if (best_split < 0 || (n <= kMaxLeafSize && best_cost >= leaf_cost)) return make_leaf();

  int* first = prims_.data() + begin;
  int* mid = std::partition(first, prims_.data() + end, [&](int p) { return bin_of(p) <= best_split; });
  int split = static_cast<int>(mid - prims_.data());
  if (split == begin || split == end) {  // cannot happen with cnt checks above; keep the build safe anyway
    split = begin + n / 2;
    std::nth_element(first, prims_.data() + split, prims_.data() + end,
                     [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
  }
  const int left = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  nodes_.emplace_back();
  nodes_[node].offset = left;
  nodes_[node].count = 0;
  nodes_[node].axis = axis;
  build(pb, centroids, left, begin, split, depth + 1);
  build(pb, centroids, left + 1, split, end, depth + 1);
}

}  // namespace snell::geometry
