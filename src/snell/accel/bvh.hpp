#pragma once
// Own bounding volume hierarchy: binary, built top-down with the surface area heuristic over 16 centroid
// bins (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007), walked
// nearer child first with a fixed stack. Unbounded objects are tested apart, as in the Embree back end.
#include <cstdint>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/ray_box.hpp"

namespace snell::accel {

class Bvh final : public Accelerator {
 public:
  explicit Bvh(const scene::Scene& scene);
  bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                 scene::SurfaceHit& hit) const override;
  std::string_view name() const override { return "bvh"; }
  AcceleratorStats stats() const override { return stats_; }

  struct Node {
    FloatBox box;
    /// Leaf: first object in `objects_`; interior: index of the first child (the second follows it).
    uint32_t offset = 0;
    /// Objects in a leaf; 0 for an interior node.
    uint32_t count = 0;
  };

 private:
  std::vector<Node> nodes_;
  std::vector<const scene::Object*> objects_;  // in leaf order
  std::vector<const scene::Object*> unbounded_;
  AcceleratorStats stats_;
};

}  // namespace snell::accel
