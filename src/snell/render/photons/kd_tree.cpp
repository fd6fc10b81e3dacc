#include "snell/render/photons/kd_tree.hpp"

#include <algorithm>

namespace snell::render::photons {

namespace {

double component(const math::Vec3& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/// Nearer first; equal distances by index. A function object, not a function pointer, so that
/// nth_element and sort inline it (as a pointer it was an eighth of a photon scene's time).
struct Closer {
  bool operator()(const Neighbour& a, const Neighbour& b) const {
    if (a.distance_squared != b.distance_squared) return a.distance_squared < b.distance_squared;
    return a.index < b.index;
  }
};

/// Keeps the k nearest of `found` (k <= its size) and returns the distance of the farthest of them.
[[gnu::noinline]] double keep_nearest(std::vector<Neighbour>& found, size_t k) {
  std::nth_element(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(k - 1), found.end(), Closer{});
  found.resize(k);
  return found[k - 1].distance_squared;
}

/// Ranges this small are not split: a linear scan of a few contiguous points costs less than descending.
constexpr size_t kLeafSize = 8;

}  // namespace

KdTree::KdTree(const std::vector<math::Vec3>& points) {
  nodes_.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) nodes_.push_back(Node{points[i], static_cast<uint32_t>(i), 3});
  build(nodes_, 0, nodes_.size());
}

// The range [lo, hi) becomes a subtree whose root sits at its middle; the left half holds points no
// greater on the root's axis, the right half points no smaller. Ranges of kLeafSize or fewer stay as
// they are: search scans them whole.
void KdTree::build(std::vector<Node>& items, size_t lo, size_t hi) {
  if (hi - lo <= kLeafSize) return;
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

// Candidates within the radius go to `found` unsorted; when it holds twice k, the k nearest are kept and
// the radius shrinks to the farthest of them (select-and-shrink: amortised constant work per candidate,
// where a heap of k paid log k). Points at exactly the shrunk radius stay: ties are settled by index at
// the end, so the answer is the k smallest (distance, index) whatever order the tree visits them in.
// A far side is pruned by the squared distance from the centre to its cell, kept incrementally over the
// axes (`gap`: the centre's distance to the cell along each axis, `cell_distance` the sum of their squares;
// Arya and Mount, "Algorithms for fast vector quantization", 1993), not by the last splitting plane alone:
// fewer cells are entered. The test keeps a relative margin of 1e-12 over the rounding of that sum, so a
// cell is dropped only where none of its points could pass the distance test in `consider`.
void KdTree::search(size_t lo, size_t hi, const math::Vec3& centre, size_t k, double& radius_squared,
                    std::vector<Neighbour>& found, math::Vec3& gap, double cell_distance) const {
  auto consider = [&](const Node& node) {
    const math::Vec3 d = node.point - centre;
    const double d2 = dot(d, d);
    if (d2 > radius_squared) return;
    found.push_back(Neighbour{node.index, d2});
    if (found.size() == k) {
      // The first k found bound the search at once: nothing farther than the farthest of them can enter.
      radius_squared = std::max_element(found.begin(), found.end(), Closer{})->distance_squared;
    } else if (found.size() >= 2 * k) {
      radius_squared = keep_nearest(found, k);
    }
  };
  if (hi - lo <= kLeafSize) {
    for (size_t i = lo; i < hi; ++i) consider(nodes_[i]);
    return;
  }
  const size_t mid = lo + (hi - lo) / 2;
  const Node& node = nodes_[mid];
  const double offset = component(centre, node.axis) - component(node.point, node.axis);
  const bool left_first = offset <= 0;
  // The near side first, and the splitting point after it: the first k found are then near ones, and
  // bound the rest of the search tightly.
  if (left_first)
    search(lo, mid, centre, k, radius_squared, found, gap, cell_distance);
  else
    search(mid + 1, hi, centre, k, radius_squared, found, gap, cell_distance);
  consider(node);
  // The far side's cell lies beyond the plane: at least |offset| away along this axis. It can hold a point
  // at exactly the pruning distance (ties by index), hence <=.
  double& along = gap[node.axis];
  const double before = along;
  const double far_distance = cell_distance - before * before + offset * offset;
  if (far_distance <= radius_squared * (1 + 1e-12)) {
    along = offset;
    if (left_first)
      search(mid + 1, hi, centre, k, radius_squared, found, gap, far_distance);
    else
      search(lo, mid, centre, k, radius_squared, found, gap, far_distance);
    along = before;
  }
}

double KdTree::nearest_in_any_order(const math::Vec3& centre, size_t k, double max_radius,
                                    std::vector<Neighbour>& found) const {
  found.clear();
  if (k == 0 || nodes_.empty()) return 0;
  double radius_squared = max_radius * max_radius;
  math::Vec3 gap{0, 0, 0};
  search(0, nodes_.size(), centre, k, radius_squared, found, gap, 0);
  if (found.size() > k) return keep_nearest(found, k);
  double farthest = 0;
  for (const Neighbour& n : found) farthest = std::max(farthest, n.distance_squared);
  return farthest;
}

void KdTree::nearest(const math::Vec3& centre, size_t k, double max_radius,
                     std::vector<Neighbour>& found) const {
  nearest_in_any_order(centre, k, max_radius, found);
  std::sort(found.begin(), found.end(), Closer{});
}

std::vector<Neighbour> KdTree::nearest(const math::Vec3& centre, size_t k, double max_radius) const {
  std::vector<Neighbour> found;
  nearest(centre, k, max_radius, found);
  return found;
}

}  // namespace snell::render::photons
