#include "snell/accel/brute_force.hpp"

#include <chrono>

#include "snell/accel/indexed_objects.hpp"

namespace snell::accel {

BruteForce::BruteForce(const scene::Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  for (const auto& o : scene.objects) {
    objects_.push_back(o.get());
    const math::Bounds3 b = culling_bounds(*o);
    if (!b.is_finite() || b.empty()) ++stats_.unbounded_objects;
  }
  stats_.objects = objects_.size();
  stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool BruteForce::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                           scene::SurfaceHit& hit) const {
  return test_all(objects_, ray, t_min, t_max, kind, hit);
}

}  // namespace snell::accel
