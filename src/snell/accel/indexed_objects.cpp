#include "snell/accel/indexed_objects.hpp"

#include "snell/geometry/ray_box.hpp"

namespace snell::accel {

math::Bounds3 culling_bounds(const scene::Object& object) {
  const math::Bounds3 world = object.world_bounds();
  return object.bounded_by ? world.intersection(*object.bounded_by) : world;
}

bool test_all(const std::vector<const scene::Object*>& objects, const math::Ray& ray, double t_min,
              double& t_max, scene::RayKind kind, scene::SurfaceHit& hit) {
  bool found = false;
  for (const scene::Object* o : objects) {
    if (test_object(*o, ray, t_min, t_max, kind, hit)) {
      t_max = hit.t;
      found = true;
    }
  }
  return found;
}

AcceleratorStats structure_stats(size_t objects, size_t unbounded, size_t nodes, size_t memory_bytes,
                                 std::chrono::steady_clock::time_point start) {
  AcceleratorStats s;
  s.objects = objects;
  s.unbounded_objects = unbounded;
  s.nodes = nodes;
  s.memory_bytes = memory_bytes;
  s.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

IndexedObjects::IndexedObjects(const scene::Scene& scene) {
  for (const auto& o : scene.objects) {
    const math::Bounds3 b = culling_bounds(*o);
    if (b.is_finite() && !b.empty()) {
      bounded.push_back(o.get());
      boxes.push_back(geometry::padded(b));
      scene_box.unite(boxes.back());
    } else if (!b.is_finite()) {
      unbounded.push_back(o.get());
    }
    // A finite empty box (bounded_by away from the object) can never be hit: the object is dropped.
  }
}

}  // namespace snell::accel
