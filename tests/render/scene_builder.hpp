#pragma once
// Small scenes built in C++ for the render tests.
#include <memory>

#include "snell/geometry/plane.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/scene/scene.hpp"

namespace snell::test {

inline std::shared_ptr<material::Texture> texture(const material::Rgbft& color,
                                                  const material::Finish& finish = {}) {
  auto t = std::make_shared<material::Texture>();
  t->pigment = std::make_shared<material::SolidPigment>(color);
  t->finish = finish;
  return t;
}

inline std::shared_ptr<scene::Object> object(std::shared_ptr<const geometry::Shape> shape,
                                             std::shared_ptr<const material::Texture> tex, double ior = 1) {
  auto o = std::make_shared<scene::Object>();
  o->shape = std::move(shape);
  o->texture = std::move(tex);
  if (ior != 1) {
    auto interior = std::make_shared<material::Interior>();
    interior->ior = ior;
    o->interior = interior;
  }
  return o;
}

inline scene::Light point_light(const math::Vec3& p, const math::Color& c = math::Color(1)) {
  scene::Light l;
  l.position = p;
  l.color = c;
  return l;
}

/// A unit sphere of colour (1, 0.5, 0.25) with POV-Ray's default finish (ambient 0.1, diffuse 0.6), seen
/// head-on from (0, 0, -5) and lit from (0, 5, -6): its centre pixel is ambient + 0.6 N.L = 0.1 + 0.6 /
/// sqrt 2.
inline scene::Scene lit_sphere_scene() {
  scene::Scene s;
  s.objects.push_back(object(std::make_shared<geometry::Sphere>(math::Vec3(0, 0, 0), 1.0),
                             texture({math::Color(1, 0.5, 0.25)}, material::Finish{})));
  s.lights.push_back(point_light({0, 5, -6}));
  s.camera.location = {0, 0, -5};
  s.camera.direction = {0, 0, 1};
  s.camera.right = {1, 0, 0};
  return s;
}

/// A reflective sphere, a glassy one and a floor: reflection, refraction and shadows in a few pixels.
inline scene::Scene two_spheres() {
  scene::Scene s;
  material::Finish shiny;
  shiny.phong = 0.8;
  shiny.reflection_min = shiny.reflection_max = math::Color(0.3);
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(math::Vec3(-0.6, 0, 0), 0.7),
                                   test::texture({math::Color(0.9, 0.2, 0.1)}, shiny)));
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(math::Vec3(0.7, 0.2, 0.5), 0.6),
                                   test::texture({math::Color(0.2, 0.9, 0.4), 0.6, 0.1}), 1.4));
  s.objects.push_back(test::object(std::make_shared<geometry::Plane>(math::Vec3(0, 1, 0), -0.7),
                                   test::texture({math::Color(0.8)})));
  s.lights.push_back(test::point_light({3, 5, -4}));
  s.background.rgb = math::Color(0.1, 0.2, 0.4);
  s.camera.location = {0, 0.5, -4};
  s.camera.right = {4.0 / 3, 0, 0};
  return s;
}

}  // namespace snell::test
