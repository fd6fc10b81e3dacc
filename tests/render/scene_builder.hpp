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

}  // namespace snell::test
