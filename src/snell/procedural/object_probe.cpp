#include "snell/procedural/object_probe.hpp"

#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::procedural {

ObjectProbe::ObjectProbe(std::vector<std::shared_ptr<const scene::Object>> objects)
    : objects_(std::move(objects)) {
  for (const auto& object : objects_) bounds_.unite(object->world_bounds());
}

std::optional<ProbeHit> ObjectProbe::nearest(const math::Vec3& origin, const math::Vec3& direction,
                                             double max_distance) const {
  const math::Ray ray{origin, direction, 0};
  std::optional<ProbeHit> found;
  double t_max = max_distance;
  for (const auto& object : objects_) {
    scene::SurfaceHit hit;
    if (object->intersect(ray, 0, t_max, hit)) {
      t_max = hit.t;
      found = ProbeHit{hit.t, hit.point, normalize(hit.normal)};
    }
  }
  return found;
}

std::optional<ProbeHit> ObjectProbe::sample_surface(math::Pcg32& rng, int attempts) const {
  if (objects_.empty() || !bounds_.is_finite() || bounds_.empty()) return std::nullopt;
  const math::Vec3 extent = bounds_.extent();
  const double reach = 2 * length(extent) + 1;
  for (int i = 0; i < attempts; ++i) {
    const math::Vec3 start =
        bounds_.lo + math::Vec3(rng.next_double(), rng.next_double(), rng.next_double()) * extent;
    const math::Vec3 direction = uniform_sphere_direction(rng);
    // Start outside the box so that points on the far side of a convex solid can be reached too.
    if (auto hit = nearest(start - direction * reach, direction, 2 * reach)) return hit;
  }
  return std::nullopt;
}

math::Vec3 uniform_sphere_direction(math::Pcg32& rng) {
  const double z = 1 - 2 * rng.next_double();
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  const double phi = 2 * math::kPi * rng.next_double();
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace snell::procedural
