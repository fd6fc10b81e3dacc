#pragma once
// A static 3-d tree over points for photon gathering (Jensen 2001, "Realistic Image Synthesis Using Photon
// Mapping", ch. 6; Bentley 1975): built once by median splits along the widest axis, then queried from any
// number of threads for the k nearest points within a radius.
#include <cstdint>
#include <vector>

#include "snell/math/vec3.hpp"

namespace snell::render::photons {

struct Neighbour {
  /// Index of the point in the vector the tree was built from.
  uint32_t index;
  double distance_squared;
};

class KdTree {
 public:
  explicit KdTree(const std::vector<math::Vec3>& points);

  /// Up to `k` points within `max_radius` of `centre`, nearest first; equal distances are ordered by
  /// index, so the answer does not depend on the tree's layout.
  std::vector<Neighbour> nearest(const math::Vec3& centre, size_t k, double max_radius) const;
  /// The same into `found` (cleared first), whose capacity the caller keeps from query to query.
  void nearest(const math::Vec3& centre, size_t k, double max_radius, std::vector<Neighbour>& found) const;
  /// The same points in an order fixed by the tree (the same for the same points), not sorted: the sort
  /// was a third of a photon gather's cost, and a gather sums them whatever their order. Returns the
  /// largest squared distance among them (0 when there are none).
  double nearest_in_any_order(const math::Vec3& centre, size_t k, double max_radius,
                              std::vector<Neighbour>& found) const;

  size_t size() const { return nodes_.size(); }

 private:
  struct Node {
    math::Vec3 point;
    uint32_t index;
    /// Axis the node splits its range on (0, 1, 2); 3 where the range is a leaf, scanned whole.
    uint8_t axis;
  };
  void build(std::vector<Node>& items, size_t lo, size_t hi);
  void search(size_t lo, size_t hi, const math::Vec3& centre, size_t k, double& radius_squared,
              std::vector<Neighbour>& found, math::Vec3& gap, double cell_distance) const;

  std::vector<Node> nodes_;
};

}  // namespace snell::render::photons
