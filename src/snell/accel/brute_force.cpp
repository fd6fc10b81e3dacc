#include "snell/accel/brute_force.hpp"

#include <chrono>

namespace snell::accel {

BruteForce::BruteForce(const scene::Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  for (const auto& o : scene.objects) {
    objects_.push_back(o.get());
    const math::Bounds3 b = o->world_bounds();
    if (!b.is_finite() || b.empty()) ++stats_.unbounded_objects;
  }
  stats_.objects = objects_.size();
  stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool BruteForce::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                           scene::SurfaceHit& hit) const {
  bool found = false;
  for (const scene::Object* o : objects_) {
    if (!o->visible_to(kind)) continue;
    if (o->intersect(ray, t_min, t_max, hit)) {
      t_max = hit.t;
      found = true;
    }
  }
  return found;
}

}  // namespace snell::accel
