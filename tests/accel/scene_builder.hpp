#pragma once
// Random test scenes for the accelerator tests: spheres, ellipsoids (spheres placed by scale and rotate
// transforms, standing in for boxes until other shapes land) and a ground plane.
#include <memory>

#include "snell/geometry/plane.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/scene/scene.hpp"

namespace snell::accel::testing {

inline double uniform(math::Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}

inline math::Vec3 uniform_vec(math::Pcg32& rng, double lo, double hi) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}

/// Uniform on the unit sphere (Marsaglia's method by rejection from the cube).
inline math::Vec3 unit_vec(math::Pcg32& rng) {
  for (;;) {
    const math::Vec3 v = uniform_vec(rng, -1, 1);
    const double l2 = length_squared(v);
    if (l2 > 1e-6 && l2 <= 1) return v / std::sqrt(l2);
  }
}

inline std::shared_ptr<scene::Object> make_object(std::shared_ptr<const geometry::Shape> shape,
                                                  const math::Transform& transform = {}) {
  auto o = std::make_shared<scene::Object>();
  o->shape = std::move(shape);
  o->transform = transform;
  return o;
}

struct RandomSceneOptions {
  int spheres = 150;
  int ellipsoids = 80;
  bool plane = true;
  /// Scene lies in [-extent, extent]^3 around `center`.
  double extent = 10;
  math::Vec3 center{0};
  /// Give each object random no_image / no_shadow / no_reflection flags.
  bool random_flags = false;
};

inline scene::Scene random_scene(uint64_t seed, const RandomSceneOptions& opt = {}) {
  math::Pcg32 rng(seed);
  scene::Scene s;
  const double r_max = 0.08 * opt.extent;
  for (int i = 0; i < opt.spheres; ++i) {
    const math::Vec3 c = opt.center + uniform_vec(rng, -opt.extent, opt.extent);
    s.objects.push_back(make_object(std::make_shared<geometry::Sphere>(c, uniform(rng, 0.05, 1) * r_max)));
  }
  for (int i = 0; i < opt.ellipsoids; ++i) {
    const math::Transform t =
        math::Transform::translate(opt.center + uniform_vec(rng, -opt.extent, opt.extent)) *
        math::Transform::rotate_xyz_degrees(uniform_vec(rng, 0, 360)) *
        math::Transform::scale(uniform_vec(rng, 0.1, 1) * r_max);
    s.objects.push_back(make_object(std::make_shared<geometry::Sphere>(math::Vec3(0), 1), t));
  }
  if (opt.plane) {
    s.objects.push_back(
        make_object(std::make_shared<geometry::Plane>(math::Vec3(0, 1, 0), opt.center.y - 0.9 * opt.extent)));
  }
  if (opt.random_flags) {
    for (auto& o : s.objects) {
      auto& obj = const_cast<scene::Object&>(*o);
      obj.flags.no_image = rng.next_double() < 0.3;
      obj.flags.no_shadow = rng.next_double() < 0.3;
      obj.flags.no_reflection = rng.next_double() < 0.3;
    }
  }
  return s;
}

}  // namespace snell::accel::testing
