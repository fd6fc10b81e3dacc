#include "snell/render/photons/kd_tree.hpp"

#include <algorithm>

namespace snell::render::photons {

namespace {

double component(const math::Vec3& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/// Heap order: the worst neighbour (farthest, then highest index) on top.
bool closer(const Neighbour& a, const Neighbour& b) {
  if (a.distance_squared != b.distance_squared) return a.distance_squared < b.distance_squared;
  return a.index < b.index;
}

}  // namespace

KdTree::KdTree(const std::vector<math::Vec3>& points) {
  nodes_.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) nodes_.push_back(Node{points[i], static_cast<uint32_t>(i), 3});
  build(nodes_, 0, nodes_.size());
}

// The range [lo, hi) becomes a subtree whose root sits at its middle; the left half holds points no
// greater on the root's axis, the right half points no smaller.
void KdTree::build(std::vector<Node>& items, size_t lo, size_t hi) {
  if (hi - lo <= 1) return;
  math::Vec3 low = items[lo].point, high = items[lo].point;
  for (size_t i = lo + 1; i < hi; ++i) {
    low = min(low, items[i].point);
    high = max(high, items[i].point);
  }
  const math::Vec3 extent = high - low;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const size_t mid = lo + (hi - lo) / 2;
  std::nth_element(
      items.begin() + static_cast<std::ptrdiff_t>(lo), items.begin() + static_cast<std::ptrdiff_t>(mid),
      items.begin() + static_cast<std::ptrdiff_t>(hi),
      [axis](const Node& a, const Node& b) { return component(a.point, axis) < component(b.point, axis); });
  items[mid].axis = static_cast<uint8_t>(axis);
  build(items, lo, mid);
  build(items, mid + 1, hi);
}

void KdTree::search(size_t lo, size_t hi, const math::Vec3& centre, size_t k, double& radius_squared,
                    std::vector<Neighbour>& heap) const {
  if (lo >= hi) return;
  const size_t mid = lo + (hi - lo) / 2;
  const Node& node = nodes_[mid];
  const math::Vec3 d = node.point - centre;
  const double d2 = dot(d, d);
  if (d2 <= radius_squared) {
    const Neighbour candidate{node.index, d2};
    if (heap.size() < k) {
      heap.push_back(candidate);
      std::push_heap(heap.begin(), heap.end(), closer);
    } else if (closer(candidate, heap.front())) {
      std::pop_heap(heap.begin(), heap.end(), closer);
      heap.back() = candidate;
      std::push_heap(heap.begin(), heap.end(), closer);
    }
    // With k found, only points nearer than the worst can still enter.
    if (heap.size() == k) radius_squared = std::min(radius_squared, heap.front().distance_squared);
  }
  if (node.axis == 3) return;
  const double offset = component(centre, node.axis) - component(node.point, node.axis);
  const bool left_first = offset <= 0;
  if (left_first)
    search(lo, mid, centre, k, radius_squared, heap);
  else
    search(mid + 1, hi, centre, k, radius_squared, heap);
  // The far side can hold a point at exactly the pruning distance (ties by index), hence <=.
  if (offset * offset <= radius_squared) {
    if (left_first)
      search(mid + 1, hi, centre, k, radius_squared, heap);
    else
      search(lo, mid, centre, k, radius_squared, heap);
  }
}

std::vector<Neighbour> KdTree::nearest(const math::Vec3& centre, size_t k, double max_radius) const {
  std::vector<Neighbour> heap;
  if (k == 0 || nodes_.empty()) return heap;
  heap.reserve(k);
  double radius_squared = max_radius * max_radius;
  search(0, nodes_.size(), centre, k, radius_squared, heap);
  std::sort_heap(heap.begin(), heap.end(), closer);
  return heap;
}

}  // namespace snell::render::photons
