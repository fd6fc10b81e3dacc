#include "snell/scene/object.hpp"

namespace snell::scene {

SurfaceHit Object::to_world(const Ray& world_ray, const geometry::LocalHit& local) const {
  SurfaceHit hit;
  hit.t = local.t;
  hit.point = world_ray.at(local.t);
  hit.normal = normalize(transform.normal(local.normal));
  if (flags.inverse) hit.normal = -hit.normal;
  hit.shading_normal = length_squared(local.shading_normal) > 0
                           ? normalize(transform.normal(local.shading_normal))
                           : hit.normal;
  if (flags.inverse && length_squared(local.shading_normal) > 0) hit.shading_normal = -hit.shading_normal;
  hit.uv = local.uv;
  hit.object = this;
  hit.part = local.part;
  return hit;
}

bool Object::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const {
  geometry::LocalHit local;
  if (!shape->intersect(transform.inverse_ray(ray), t_min, t_max, local)) return false;
  hit = to_world(ray, local);
  return true;
}

math::Bounds3 Object::world_bounds() const { return transform.bounds(shape->bounds()); }

bool Object::inside(const Vec3& world_point) const {
  return shape->inside(transform.inverse_point(world_point)) != flags.inverse;
}

}  // namespace snell::scene
