#include "snell/accel/indexed_objects.hpp"

#include <algorithm>
#include <cmath>

namespace snell::accel {

namespace {

/// Bounds are computed in double from exact shape boxes; 2^-40 of the box's magnitude (thousands of
/// ulps) absorbs their rounding without making boxes measurably larger.
math::Bounds3 padded(const math::Bounds3& b) {
  const double magnitude = std::max(max_component(math::abs(b.lo)), max_component(math::abs(b.hi)));
  const double pad = magnitude * 0x1p-40 + 1e-300;
  return {b.lo - math::Vec3(pad), b.hi + math::Vec3(pad)};
}

}  // namespace

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
      boxes.push_back(padded(b));
      scene_box.unite(boxes.back());
    } else if (!b.is_finite()) {
      unbounded.push_back(o.get());
    }
    // A finite empty box (bounded_by away from the object) can never be hit: the object is dropped.
  }
}

}  // namespace snell::accel
