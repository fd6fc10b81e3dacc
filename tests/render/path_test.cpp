// The path integrator against closed forms: inside a closed sphere whose wall emits Le and reflects
// diffusely with albedo a, every direction sees L = Le / (1 - a) (the white-furnace test).
#include "snell/render/path.hpp"

#include <gtest/gtest.h>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

TEST(PathIntegrator, WhiteFurnaceSphereConvergesToClosedForm) {
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 0.8;
  f.emission = Color(0.5);
  s.objects.push_back(
      test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 1.0), test::texture({Color(1)}, f)));
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 40;
  o.height = 30;
  o.threads = 2;
  o.integrator = "path";
  const RenderResult r = Renderer(s, *accel, o).render();
  double sum = 0;
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) sum += r.image.at(x, y).g;
  // L = 0.5 / (1 - 0.8) = 2.5; Russian roulette makes single paths noisy, the mean converges.
  EXPECT_NEAR(sum / (o.width * o.height), 2.5, 0.05 * 2.5);
}

TEST(PathIntegrator, LambertPlaneUnderPointLightMatchesWhitted) {
  // One diffuse bounce of direct light: albedo * light * cos, POV-Ray's units (no ambient, black sky).
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 0.7;
  s.objects.push_back(test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0.0),
                                   test::texture({Color(1, 0.5, 0.25)}, f)));
  s.lights.push_back(test::point_light({0, 1e7, 0}));
  s.camera.location = {0, 5, 0};
  s.camera.direction = {0, -1, 0};
  s.camera.up = {0, 0, 1};
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 4;
  o.height = 3;
  o.threads = 1;
  o.integrator = "path";
  const RenderResult r = Renderer(s, *accel, o).render();
  // The diffuse bounce leaves to a black sky, so only the direct term remains: 0.7 * colour * 1.
  EXPECT_NEAR(r.image.at(1, 1).r, 0.7, 1e-3);
  EXPECT_NEAR(r.image.at(1, 1).b, 0.7 * 0.25, 1e-3);
}

}  // namespace
}  // namespace snell::render
