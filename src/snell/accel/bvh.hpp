#pragma once
// Own bounding volume hierarchy: binary, built top-down with the surface area heuristic over 16 centroid
// bins (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007), collapsed to eight
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

  /// kWidth children per node: the binary SAH tree collapsed (each node opens its largest interior
  /// children until it has kWidth; Wald, Benthin and Boulos, "Getting rid of packets", 2008, with the
  /// eight-wide nodes of Ernst and Greiner's multi BVH, 2008), so a walk makes fewer dependent node
  /// fetches: eight measured 10-20% faster than four on incoherent rays (docs/benchmark.md), as a node's
  /// four adjacent cache lines arrive together. Child boxes are float, rounded outward, and tested in single
  /// precision, conservatively (float_slabs.hpp). Unused slots hold FloatBox::nothing(), which no ray enters.
  static constexpr int kWidth = 8;
  struct alignas(64) Node {
    float lo[3][kWidth];
    float hi[3][kWidth];
    /// Interior child: its node index, count 0. Leaf child: first object in `objects_`, count > 0.
    /// Unused slot: kNoChild, count 0.
    uint32_t child[kWidth];
    uint32_t count[kWidth];
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
