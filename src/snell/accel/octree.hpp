#pragma once
// Octree over the objects' boxes: each node splits its box at the centre into eight (into four or two
// along a thin side, so flat scenes still separate); an object is listed in every child its box overlaps
// (tested once per ray, Mailbox). Children are walked near to far.
#include <cstdint>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/nearest_hit.hpp"

namespace snell::accel {

class Octree final : public Accelerator {
 public:
  explicit Octree(const scene::Scene& scene);
  bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                 scene::SurfaceHit& hit) const override;
  std::string_view name() const override { return "octree"; }
  AcceleratorStats stats() const override { return stats_; }

  struct Node {
    math::Bounds3 box;
    /// Interior: index of the first of 2^(axes split) consecutive children (bit j of a child's number set
    /// for the upper half along the j-th split axis). Leaf: first entry in `entries_`.
    uint32_t first = 0;
    uint32_t count = 0;
    bool leaf = true;
    /// Interior: bit a set when the node is halved along axis a.
    uint8_t axes = 0;
  };

 private:
  friend class OctreeBuilder;
  std::vector<Node> nodes_;
  /// Leaf lists: indices into objects_.
  std::vector<uint32_t> entries_;
  std::vector<const scene::Object*> objects_;
  /// plain_triangle of each of objects_.
  std::vector<PlainTriangle> triangles_;
  std::vector<const scene::Object*> unbounded_;
  AcceleratorStats stats_;
};

}  // namespace snell::accel
