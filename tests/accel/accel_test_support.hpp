#pragma once
// Random scenes and the hit comparison shared by the accelerator tests.
#include <gtest/gtest.h>

#include <memory>

#include "snell/accel/accelerator.hpp"
#include "snell/geometry/plane.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/pcg32.hpp"

namespace snell::accel_test {

using math::Transform;
using math::Vec3;
using scene::RayKind;

inline double uniform(math::Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}
inline Vec3 uniform_vec(math::Pcg32& rng, double lo, double hi) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}

inline std::shared_ptr<scene::Object> make_object(std::shared_ptr<const geometry::Shape> shape,
                                                  Transform t = {}) {
  auto o = std::make_shared<scene::Object>();
  o->shape = std::move(shape);
  o->transform = t;
  return o;
}

/// Spheres, box-like ellipsoids (unit spheres scaled, rotated, moved by the object transform) and two
/// planes; about a fifth of the objects carry each of no_shadow / no_image / no_reflection.
inline scene::Scene random_scene(uint64_t seed, int count, double extent = 10) {
  math::Pcg32 rng(seed);
  scene::Scene s;
  for (int i = 0; i < count; ++i) {
    std::shared_ptr<scene::Object> o;
    if (i % 2 == 0) {
      o = make_object(std::make_shared<geometry::Sphere>(uniform_vec(rng, -extent, extent),
                                                         uniform(rng, 0.02, 0.15) * extent));
    } else {
      const Transform t = Transform::translate(uniform_vec(rng, -extent, extent)) *
                          Transform::rotate_xyz_degrees(uniform_vec(rng, 0, 360)) *
                          Transform::scale(uniform_vec(rng, 0.01, 0.2) * extent);
      o = make_object(std::make_shared<geometry::Sphere>(Vec3(0), 1.0), t);
    }
    o->flags.no_shadow = rng.next_double() < 0.2;
    o->flags.no_image = rng.next_double() < 0.2;
    o->flags.no_reflection = rng.next_double() < 0.2;
    s.objects.push_back(o);
  }
  s.objects.push_back(make_object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -1.2 * extent)));
  auto tilted =
      make_object(std::make_shared<geometry::Plane>(Vec3(0, 0, 1), 0),
                  Transform::translate({0, 0, 1.3 * extent}) * Transform::rotate_xyz_degrees({20, 0, 0}));
  tilted->flags.no_reflection = true;
  s.objects.push_back(tilted);
  return s;
}

inline void expect_same_hit(const accel::Accelerator& a, const accel::Accelerator& b, const math::Ray& ray,
                            double t_min, double t_max, RayKind kind) {
  scene::SurfaceHit ha, hb;
  const bool fa = a.intersect(ray, t_min, t_max, kind, ha);
  const bool fb = b.intersect(ray, t_min, t_max, kind, hb);
  ASSERT_EQ(fa, fb) << "origin " << ray.origin.x << ' ' << ray.origin.y << ' ' << ray.origin.z;
  if (!fa) return;
  EXPECT_EQ(ha.object, hb.object);
  EXPECT_DOUBLE_EQ(ha.t, hb.t);
  EXPECT_GT(ha.t, t_min);
  EXPECT_LT(ha.t, t_max);
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(ha.point[k], hb.point[k]);
}

inline constexpr RayKind kKinds[] = {RayKind::camera, RayKind::reflection, RayKind::refraction,
                                     RayKind::shadow};

/// expect_same_hit for `rays` random rays from [-reach, reach]^3 (directions deliberately not unit length)
/// and each ray kind in turn, over [1e-6, inf) or, with `windows`, also random windows; returns how many
/// hit something.
inline int compare_random_rays(const accel::Accelerator& tested, const accel::Accelerator& brute,
                               math::Pcg32& rng, int rays, double reach, bool windows = false) {
  int hits = 0;
  for (int i = 0; i < rays; ++i) {
    const math::Ray ray{uniform_vec(rng, -reach, reach), uniform_vec(rng, -1, 1) * uniform(rng, 0.3, 3), 0};
    const RayKind kind = kKinds[i % 4];
    const double t_min = !windows || i % 3 ? 1e-6 : uniform(rng, 0, 10);
    const double t_max = !windows || i % 5 ? math::kInfinity : t_min + uniform(rng, 0, 10);
    expect_same_hit(tested, brute, ray, t_min, t_max, kind);
    scene::SurfaceHit h;
    hits += brute.intersect(ray, t_min, t_max, kind, h);
  }
  return hits;
}

/// Whether a.occluder agrees with brute force's nearest hit over (1e-6, t_max) and names an object the ray
/// really hits.
inline bool occluder_agrees(const accel::Accelerator& a, const accel::Accelerator& brute,
                            const math::Ray& ray, double t_max, RayKind kind, bool& blocked) {
  scene::SurfaceHit nearest, own;
  blocked = brute.intersect(ray, 1e-6, t_max, kind, nearest);
  const scene::Object* o = a.occluder(ray, 1e-6, t_max, kind);
  return blocked == (o != nullptr) && (!o || (o->visible_to(kind) && o->intersect(ray, 1e-6, t_max, own)));
}

}  // namespace snell::accel_test
