#include "snell/scene/object.hpp"

#include "snell/scene/csg.hpp"

namespace snell::scene {

namespace {

void flip(SurfaceHit& hit) {
  hit.normal = -hit.normal;
  hit.shading_normal = -hit.shading_normal;
}

/// A hit of the still geometry (found with the ray moved back by d^-1) moved to where the object is at the
/// ray's time: t is unchanged because the ray direction is not renormalised. `texture_point` stays where
/// the still geometry was hit.
void move_hit(SurfaceHit& hit, const Ray& ray, const math::Transform& d) {
  hit.point = ray.at(hit.t);
  hit.normal = normalize(d.normal(hit.normal));
  hit.shading_normal = normalize(d.normal(hit.shading_normal));
}

}  // namespace

void Object::bake_placement() {
  if (!shape || csg || motion || transform.is_identity()) return;
  if (auto placed = shape->placed(transform)) {
    shape = std::move(placed);
    transform = math::Transform{};
  }
}

SurfaceHit Object::placed_hit(const Object& object, const math::Transform& transform, bool inverse,
                              const Ray& world_ray, const geometry::LocalHit& local) {
  const Vec3 point = world_ray.at(local.t);
  Vec3 normal = normalize(transform.normal(local.normal));
  if (inverse) normal = -normal;
  Vec3 shading_normal = normal;
  if (length_squared(local.shading_normal) > 0) {
    shading_normal = normalize(transform.normal(local.shading_normal));
    if (inverse) shading_normal = -shading_normal;
  }
  // Every member given at once: a default-constructed hit filled in afterwards was first cleared (a
  // 144-byte `rep stos`, 15% of this function in pigmap.pov's profile).
  return SurfaceHit{local.t, point, normal, shading_normal, local.uv, point, &object, &object, local.part};
}

bool Object::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit,
                       bool outer_inverse) const {
  if (motion) {
    const auto d = motion->at(ray.time);
    if (!d || !intersect_still(d->inverse_ray(ray), t_min, t_max, hit, outer_inverse)) return false;
    move_hit(hit, ray, *d);
    return true;
  }
  return intersect_still(ray, t_min, t_max, hit, outer_inverse);
}

bool Object::blocks(const Ray& ray, double t_min, double t_max) const {
  if (csg && !motion) return csg->crosses(ray, t_min, t_max, flags.inverse);
  if (motion) {
    // Kept per thread: nothing below tests blocks again while it is in use.
    thread_local SurfaceHit scratch;
    return intersect(ray, t_min, t_max, scratch);
  }
  return shape->crosses(transform.inverse_ray(ray), t_min, t_max);
}

void Object::all_hits(const Ray& ray, double t_min, double t_max, std::vector<SurfaceHit>& hits,
                      bool outer_inverse) const {
  if (!motion) return all_hits_still(ray, t_min, t_max, hits, outer_inverse);
  const auto d = motion->at(ray.time);
  if (!d) return;
  const size_t first = hits.size();
  all_hits_still(d->inverse_ray(ray), t_min, t_max, hits, outer_inverse);
  for (size_t i = first; i < hits.size(); ++i) move_hit(hits[i], ray, *d);
}

bool Object::intersect_still(const Ray& ray, double t_min, double t_max, SurfaceHit& hit,
                             bool outer_inverse) const {
  if (csg) {
    if (!csg->intersect(ray, t_min, t_max, hit, outer_inverse != flags.inverse)) return false;
    if (flags.inverse) flip(hit);  // the leaf's own inverse is already in its normal
    hit.solid = this;
    return true;
  }
  geometry::LocalHit local;
  if (!shape->intersect(transform.inverse_ray(ray), t_min, t_max, local)) return false;
  hit = to_world(ray, local);
  return true;
}

void Object::all_hits_still(const Ray& ray, double t_min, double t_max, std::vector<SurfaceHit>& hits,
                            bool outer_inverse) const {
  if (csg) {
    const size_t first = hits.size();
    csg->all_hits(ray, t_min, t_max, hits, outer_inverse != flags.inverse);
    for (size_t i = first; i < hits.size(); ++i) {
      if (flags.inverse) flip(hits[i]);
      hits[i].solid = this;
    }
    return;
  }
  // Reused on this thread (no allocation per ray): a shape's all_hits never reaches another object's.
  thread_local geometry::HitList local;
  local.clear();
  shape->all_hits(transform.inverse_ray(ray), t_min, t_max, local);
  for (const geometry::LocalHit& l : local) hits.push_back(to_world(ray, l));
}

math::Bounds3 Object::world_bounds() const {
  const math::Bounds3 still = csg ? csg->bounds() : transform.bounds(shape->bounds());
  return motion ? motion->swept(still) : still;
}

math::Bounds3 Object::solid_bounds() const {
  if (flags.inverse) return math::Bounds3::infinite();  // everything outside a surface
  return csg ? csg->solid_bounds() : world_bounds();
}

math::Bounds3 Object::solid_bounds_within(const math::Bounds3& box) const {
  const math::Bounds3 whole = solid_bounds().intersection(box);
  if (flags.inverse || motion || csg || whole.empty()) return whole;
  const math::Bounds3 local_box = transform.inverse().bounds(box);
  return transform.bounds(shape->inside_bounds_within(local_box)).intersection(whole);
}

bool Object::inside(const Vec3& world_point, double time) const {
  Vec3 p = world_point;
  if (motion) {
    const auto d = motion->at(time);
    if (!d) return flags.inverse;
    p = d->inverse_point(p);
  }
  const bool in = csg ? csg->inside(p, time) : shape->inside(transform.inverse_point(p));
  return in != flags.inverse;
}

}  // namespace snell::scene
