#include "snell/accel/brute_force.hpp"

namespace snell::accel {

BruteForce::BruteForce(const scene::Scene& scene) {
  for (const auto& o : scene.objects) {
    objects_.push_back(o.get());
    if (!o->world_bounds().is_finite()) ++stats_.unbounded_objects;
  }
  stats_.objects = objects_.size();
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
