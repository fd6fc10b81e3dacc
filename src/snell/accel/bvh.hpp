#pragma once
// Own bounding volume hierarchy: binary, built top-down with the surface area heuristic over 16 centroid
// bins (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007), collapsed to four
// children per node, walked nearest child first with a fixed stack. Unbounded objects are tested apart, as in
// the Embree back end.
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

  /// Four children per node: the binary SAH tree collapsed (each node opens its largest interior
  /// children until it has four; Wald, Benthin and Boulos, "Getting rid of packets", 2008), so a walk
  /// fetches half as many nodes. Child boxes are float, rounded outward, and tested in single
  /// precision, conservatively (float_slabs.hpp); a node fills two cache lines exactly. Unused slots hold
  /// FloatBox::nothing(), which no ray enters.
  struct alignas(64) Node {
    float lo[3][4];
    float hi[3][4];
    /// Interior child: its node index, count 0. Leaf child: first object in `objects_`, count > 0.
    /// Unused slot: kNoChild, count 0.
    uint32_t child[4];
    uint32_t count[4];
  };
  static constexpr uint32_t kNoChild = UINT32_MAX;

 private:
  /// The root: a node (count 0) or, for a scene of few objects, a single leaf.
  uint32_t root_index_ = 0;
  uint32_t root_count_ = 0;
  FloatBox root_box_;
  std::vector<Node> nodes_;
  std::vector<const scene::Object*> objects_;  // in leaf order
  std::vector<const scene::Object*> unbounded_;
  AcceleratorStats stats_;
};

}  // namespace snell::accel
