#pragma once
// Embree 3 as the ray-query structure: every bounded object is one primitive of an Embree user geometry,
// intersected by our own double-precision code; Embree only builds and traverses the BVH in float.
// Embree's header stays in the .cpp (it is large and slows every build that would include it).
#include <memory>
#include <vector>

#include "snell/accel/accelerator.hpp"

namespace snell::accel {

class EmbreeAccelerator final : public Accelerator {
 public:
  /// The scene must outlive the accelerator. Throws std::runtime_error with Embree's message on failure.
  explicit EmbreeAccelerator(const scene::Scene& scene);
  ~EmbreeAccelerator() override;
  EmbreeAccelerator(const EmbreeAccelerator&) = delete;
  EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

  /// Safe to call from many threads at once (Embree allows concurrent traversal of a committed scene).
  bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                 scene::SurfaceHit& hit) const override;
  std::string_view name() const override { return "embree"; }
  AcceleratorStats stats() const override { return stats_; }

 private:
  struct Embree;
  std::unique_ptr<Embree> embree_;
  /// Objects in Embree, indexed by primitive id.
  std::vector<const scene::Object*> bounded_;
  /// Objects whose world bounds are not finite (planes...): tested directly on every ray.
  std::vector<const scene::Object*> unbounded_;
  AcceleratorStats stats_;
};

}  // namespace snell::accel
