#pragma once
// Ray queries against a handful of scene objects, for generators that must see geometry: boids avoiding
// obstacles and particle emitters on an object's surface. The objects are the same scene::Objects the
// renderer intersects, so a boid sees exactly what the camera sees.
#include <memory>
#include <optional>
#include <vector>

#include "snell/math/bounds.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/scene/object.hpp"

namespace snell::procedural {

struct ProbeHit {
  double distance = 0;
  math::Vec3 point;
  /// Unit normal, outward from the solid.
  math::Vec3 normal;
};

class ObjectProbe {
 public:
  ObjectProbe() = default;
  explicit ObjectProbe(std::vector<std::shared_ptr<const scene::Object>> objects);

  bool empty() const { return objects_.empty(); }
  /// The nearest surface along `direction` (unit) from `origin` closer than `max_distance`.
  std::optional<ProbeHit> nearest(const math::Vec3& origin, const math::Vec3& direction,
                                  double max_distance) const;
  /// A point on the objects' surface: a ray from a random point of their (finite) bounds in a random
  /// direction, its first hit. This favours surface facing the middle of the box over exact area
  /// weighting, which suits emitters; nullopt after `attempts` misses.
  std::optional<ProbeHit> sample_surface(math::Pcg32& rng, int attempts = 64) const;
  const math::Bounds3& bounds() const { return bounds_; }

 private:
  std::vector<std::shared_ptr<const scene::Object>> objects_;
  math::Bounds3 bounds_;
};

/// A uniformly distributed unit vector (Archimedes' hat-box theorem: z uniform in [-1, 1]).
math::Vec3 uniform_sphere_direction(math::Pcg32& rng);

}  // namespace snell::procedural
