#include "snell/accel/box_list.hpp"

#include "snell/geometry/mesh.hpp"
#include "snell/geometry/ray_box.hpp"

namespace snell::accel {

bool prefers_box_list(const scene::Scene& scene) {
  size_t bounded = 0;
  for (const auto& o : scene.objects) {
    if (dynamic_cast<const geometry::Mesh*>(o->shape.get())) return false;
    const math::Bounds3 b = culling_bounds(*o);
    if (b.is_finite() && !b.empty() && ++bounded > kBoxListMaxObjects) return false;
  }
  return true;
}

BoxList::BoxList(const scene::Scene& scene) : objects_(scene) {
  const auto start = std::chrono::steady_clock::now();
  stats_ = structure_stats(objects_.bounded.size() + objects_.unbounded.size(), objects_.unbounded.size(), 0,
                           objects_.boxes.size() * sizeof(math::Bounds3), start);
}

bool BoxList::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                        scene::SurfaceHit& hit) const {
  bool found = test_all(objects_.unbounded, ray, t_min, t_max, kind, hit);
  const geometry::RayBox box_ray(ray);
  for (size_t i = 0; i < objects_.bounded.size(); ++i) {
    double entry, exit;
    // The window shrinks with each hit, so boxes beyond the nearest hit so far are skipped.
    if (!box_ray.enter(objects_.boxes[i], t_min, t_max, entry, exit)) continue;
    if (test_object(*objects_.bounded[i], ray, t_min, t_max, kind, hit)) {
      t_max = hit.t;
      found = true;
    }
  }
  return found;
}

const scene::Object* BoxList::occluder(const math::Ray& ray, double t_min, double t_max,
                                       scene::RayKind kind) const {
  for (const scene::Object* o : objects_.unbounded)
    if (object_blocks(*o, ray, t_min, t_max, kind)) return o;
  const geometry::RayBox box_ray(ray);
  for (size_t i = 0; i < objects_.bounded.size(); ++i) {
    double entry, exit;
    if (!box_ray.enter(objects_.boxes[i], t_min, t_max, entry, exit)) continue;
    if (object_blocks(*objects_.bounded[i], ray, t_min, t_max, kind)) return objects_.bounded[i];
  }
  return nullptr;
}

}  // namespace snell::accel
