#pragma once
// What the own accelerators (bvh, octree, grid) share: the scene's objects split into those with a finite
// culling box and those tested on every ray (planes, objects a transform makes unbounded), and the one
// place where an object is tested against a ray (ray-kind flags, the user's `bounded_by` box, the surface).
#include <chrono>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/object_test_counter.hpp"
#include "snell/accel/query_cost.hpp"

#include "snell/math/bounds.hpp"
#include "snell/scene/scene.hpp"

namespace snell::accel {

/// The box an accelerator culls `object` by: its world bounds, cut down to its `bounded_by` box.
math::Bounds3 culling_bounds(const scene::Object& object);

/// Tests one object: hidden from `kind` means no hit. With a `bounded_by` box only the part of the ray
/// inside the box is tested: a ray missing the box never reaches the object (POV-Ray reference,
/// "Bounded_By"), and a bound smaller than the object (which POV-Ray leaves unspecified) cuts it to the
/// box, the same for every accelerator, so that culling by the box is exact.
/// What every object test does before the object's own: its visibility to the ray's kind, the test
/// counters, and its `bounded_by` box, which narrows the window to its span. False when the object cannot
/// be hit.
inline bool passes_culls(const scene::Object& object, const math::Ray& ray, double& t_min, double& t_max,
                         scene::RayKind kind) {
  if (!object.visible_to(kind)) return false;
  count_object_test(object);
  ObjectTestCounter::count();
  return !object.bounded_by || object.bounded_by->clip(ray, t_min, t_max);
}

inline bool test_object(const scene::Object& object, const math::Ray& ray, double t_min, double t_max,
                        scene::RayKind kind, scene::SurfaceHit& hit) {
  return passes_culls(object, ray, t_min, t_max, kind) && object.intersect(ray, t_min, t_max, hit);
}

/// test_object for an occlusion query: whether the object stops the ray, without building its hit.
inline bool object_blocks(const scene::Object& object, const math::Ray& ray, double t_min, double t_max,
                          scene::RayKind kind) {
  return passes_culls(object, ray, t_min, t_max, kind) && object.blocks(ray, t_min, t_max);
}

/// Tests every object of `objects`, shrinking `t_max` to the nearest hit; true when any was hit.
bool test_all(const std::vector<const scene::Object*>& objects, const math::Ray& ray, double t_min,
              double& t_max, scene::RayKind kind, scene::SurfaceHit& hit);

/// Stats of a structure built since `start`.
AcceleratorStats structure_stats(size_t objects, size_t unbounded, size_t nodes, size_t memory_bytes,
                                 std::chrono::steady_clock::time_point start);

struct IndexedObjects {
  std::vector<const scene::Object*> bounded;
  /// boxes[i] is bounded[i]'s culling box, padded so that rounding never culls a true hit.
  std::vector<math::Bounds3> boxes;
  std::vector<const scene::Object*> unbounded;
  /// Union of `boxes`.
  math::Bounds3 scene_box;

  explicit IndexedObjects(const scene::Scene& scene);
};

}  // namespace snell::accel
