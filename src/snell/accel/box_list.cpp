#include "snell/accel/box_list.hpp"

#include <bit>

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

BoxList::BoxList(const scene::Scene& scene) : objects_(scene), lanes_(objects_.boxes) {
  const auto start = std::chrono::steady_clock::now();
  stats_ = structure_stats(objects_.bounded.size() + objects_.unbounded.size(), objects_.unbounded.size(), 0,
                           objects_.boxes.size() * sizeof(math::Bounds3), start);
}

bool BoxList::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                        scene::SurfaceHit& hit) const {
  bool found = test_all(objects_.unbounded, ray, t_min, t_max, kind, hit);
  const geometry::RayBox box_ray(ray);
  // Boxes in the objects' order: the window shrinks with each hit, so later boxes beyond the nearest hit
  // so far are skipped. (Testing the entered boxes nearest first cost more than it saved: +2% to +3%
  // instructions on POV-Ray scenes of 3 to 76 objects.)
  for (size_t chunk = 0; chunk < lanes_.chunks(); ++chunk)
    for (std::uint32_t entered = lanes_.entered(box_ray, chunk, t_min, t_max); entered;
         entered &= entered - 1) {
      const size_t i = chunk * BoxLanes::kChunk + static_cast<size_t>(std::countr_zero(entered));
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
  for (size_t chunk = 0; chunk < lanes_.chunks(); ++chunk)
    for (std::uint32_t entered = lanes_.entered(box_ray, chunk, t_min, t_max); entered;
         entered &= entered - 1) {
      const size_t i = chunk * BoxLanes::kChunk + static_cast<size_t>(std::countr_zero(entered));
      if (object_blocks(*objects_.bounded[i], ray, t_min, t_max, kind)) return objects_.bounded[i];
    }
  return nullptr;
}

}  // namespace snell::accel
