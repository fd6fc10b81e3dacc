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

BoxList::BoxList(const scene::Scene& scene)
    : BoxList(std::chrono::steady_clock::now(), IndexedObjects(scene)) {}

BoxList::BoxList(std::chrono::steady_clock::time_point start, IndexedObjects indexed)
    : bounded_(std::move(indexed.bounded)), unbounded_(std::move(indexed.unbounded)), lanes_(indexed.boxes) {
  stats_ = structure_stats(bounded_.size() + unbounded_.size(), unbounded_.size(), 0, lanes_.bytes(), start);
}

bool BoxList::intersect(const math::Ray& ray, double t_min, double t_max, scene::RayKind kind,
                        scene::SurfaceHit& hit) const {
  bool found = test_all(unbounded_, ray, t_min, t_max, kind, hit);
  // Boxes in the objects' order: the window shrinks with each hit, so later boxes beyond the nearest hit
  // so far are skipped. (Testing the entered boxes nearest first cost more than it saved: +2% to +3%
  // instructions on POV-Ray scenes of 3 to 76 objects.)
  lanes_.for_each_entered(geometry::RayBox(ray), t_min, t_max, [&](size_t i) {
    if (test_object(*bounded_[i], ray, t_min, t_max, kind, hit)) {
      t_max = hit.t;
      found = true;
    }
    return false;
  });
  return found;
}

const scene::Object* BoxList::occluder(const math::Ray& ray, double t_min, double t_max,
                                       scene::RayKind kind) const {
  for (const scene::Object* o : unbounded_)
    if (object_blocks(*o, ray, t_min, t_max, kind)) return o;
  const scene::Object* blocker = nullptr;
  lanes_.for_each_entered(geometry::RayBox(ray), t_min, t_max, [&](size_t i) {
    if (object_blocks(*bounded_[i], ray, t_min, t_max, kind)) blocker = bounded_[i];
    return blocker != nullptr;
  });
  return blocker;
}

}  // namespace snell::accel
