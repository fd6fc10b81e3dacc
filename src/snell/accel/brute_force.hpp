#pragma once
#include <vector>

#include "snell/accel/accelerator.hpp"

namespace snell::accel {

/// Tests every object: the reference that other accelerators are checked against.
class BruteForce final : public Accelerator {
 public:
  explicit BruteForce(const scene::Scene& scene);
  bool intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                 scene::SurfaceHit& hit) const override;
  std::string_view name() const override { return "none"; }
  AcceleratorStats stats() const override { return stats_; }

 private:
  std::vector<const scene::Object*> objects_;
  AcceleratorStats stats_;
};

}  // namespace snell::accel
