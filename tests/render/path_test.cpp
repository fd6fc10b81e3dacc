// The path integrator against closed forms: inside a closed sphere whose wall emits Le and reflects
// diffusely with albedo a, every direction sees L = Le / (1 - a) (the white-furnace test).
#include "snell/render/path.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

RenderResult render_path(const scene::Scene& s, int width, int height, int threads) {
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.threads = threads;
  o.integrator = "path";
  return Renderer(s, *accel, o).render();
}

double mean_green(const RenderResult& r) {
  double sum = 0;
  for (int y = 0; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x) sum += r.image.at(x, y).g;
  return sum / (r.image.width * r.image.height);
}

TEST(PathIntegrator, WhiteFurnaceSphereConvergesToClosedForm) {
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 0.8;
  f.emission = Color(0.5);
  s.objects.push_back(
      test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 1.0), test::texture({Color(1)}, f)));
  // L = 0.5 / (1 - 0.8) = 2.5; Russian roulette makes single paths noisy, the mean converges.
  EXPECT_NEAR(mean_green(render_path(s, 40, 30, 2)), 2.5, 0.05 * 2.5);
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

TEST(PathIntegrator, EmissiveSphereLightsAPlaneAsTheClosedFormWithLittleNoise) {
  // A sphere of radius R and radiance L whose centre is d above a diffuse plane gives the point below it
  // the irradiance pi L (R/d)^2, so the plane's radiance there is albedo * L * (R/d)^2. Found by BSDF
  // sampling alone, one cosine sample in 1/(R/d)^2 = 16 would hit the sphere (relative deviation ~4);
  // sampling the sphere's cone with MIS makes the estimate nearly noise-free.
  scene::Scene s;
  material::Finish glow;
  glow.ambient = Color(0);
  glow.diffuse = 0;
  glow.emission = Color(1);
  s.objects.push_back(
      test::object(std::make_shared<geometry::Sphere>(Vec3(0, 2, 0), 0.5), test::texture({Color(1)}, glow)));
  material::Finish matte;
  matte.ambient = Color(0);
  matte.diffuse = 0.7;
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0.0), test::texture({Color(1)}, matte)));
  // Looking at the origin from the side with a narrow field: every pixel sees the plane within 0.03 of it.
  s.camera.location = {3, 1, 0};
  s.camera.direction = normalize(Vec3(-3, -1, 0)) * 100;
  s.camera.up = normalize(Vec3(-1, 3, 0));
  s.camera.right = {0, 0, 4.0 / 3};
  const RenderResult r = render_path(s, 40, 30, 2);
  const double mean = mean_green(r);
  double squares = 0;
  for (int y = 0; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x) squares += std::pow(r.image.at(x, y).g - mean, 2);
  const double deviation = std::sqrt(squares / (r.image.width * r.image.height));
  const double expected = 0.7 * 0.5 * 0.5 / (2.0 * 2.0);
  EXPECT_NEAR(mean, expected, 0.02 * expected);
  EXPECT_LT(deviation, 0.2 * expected);
}

}  // namespace
}  // namespace snell::render
