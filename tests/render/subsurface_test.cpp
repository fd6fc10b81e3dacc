// Subsurface scattering by the dipole: a large flat slab of Jensen et al. 2001's measured materials, lit
// at normal incidence by a distant white light, reflects on average the total diffuse reflectance Rd of
// ../shared/reference-values.md section 2 (within 5%).
#include "snell/render/subsurface.hpp"

#include <gtest/gtest.h>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

/// Mean of a 16x12 render of the plane y = 0 with finish `f` (pigment 1), lit and seen from straight above.
Color lit_plane_average(const material::Finish& f, double ior = 1, int single_samples = 50) {
  scene::Scene s;
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0.0), test::texture({Color(1)}, f), ior));
  s.lights.push_back(test::point_light({0, 1e7, 0}));
  s.settings.subsurface_samples = 64;
  s.settings.subsurface_single_samples = single_samples;
  s.camera.location = {0, 5, 0};
  s.camera.direction = {0, -1, 0};
  s.camera.up = {0, 0, 1};
  s.camera.right = {4.0 / 3, 0, 0};
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 16;
  o.height = 12;
  o.threads = 2;
  const RenderResult r = Renderer(s, *accel, o).render();
  Color sum;
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      const auto c = r.image.at(x, y);
      sum += Color(c.r, c.g, c.b);
    }
  return sum / double(o.width * o.height);
}

Color slab_average(const char* material_name) {
  material::Finish f;
  f.ambient = Color(0);
  f.subsurface = true;
  f.subsurface_material = material::measured_material(material_name);
  return lit_plane_average(f);
}

void expect_within_5_percent(const Color& got, const Color& want, const char* name) {
  EXPECT_NEAR(got.r, want.r, 0.05 * want.r) << name;
  EXPECT_NEAR(got.g, want.g, 0.05 * want.g) << name;
  EXPECT_NEAR(got.b, want.b, 0.05 * want.b) << name;
}

TEST(Subsurface, LitSlabReflectsTotalDiffuseReflectance) {
  expect_within_5_percent(slab_average("marble"), {0.830191, 0.790960, 0.752610}, "marble");
  expect_within_5_percent(slab_average("skimmilk"), {0.814946, 0.812984, 0.682295}, "skimmilk");
  expect_within_5_percent(slab_average("skin1"), {0.435956, 0.227331, 0.130999}, "skin1");
}

// POV-Ray's estimate for a `translucency` finish (render/subsurface_povray.hpp): a plane with pigment 1,
// diffuse 0.5 and ior 1.5. Half of the probes from below the surface find nothing and POV-Ray averages over
// those that hit, so the diffuse part is 2 Ft(0)^2 Rd = 2 * 0.96^2 * 0.5 = 0.9216; the single-scattering
// part, with s' drawn from sigma_t's exponential and both paths attenuated, averages
// alpha' Ft(0)^2 / (4 (1 + G)(2 + G)) with G = 1 and alpha' = 0.950991: 0.0365. Together 0.958.
TEST(Subsurface, TranslucentPlaneMatchesPovRaysEstimate) {
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 0.5;
  f.subsurface = true;
  f.subsurface_translucency = Color(1);
  const Color got = lit_plane_average(f, 1.5, 16);
  EXPECT_NEAR(got.g, 0.9581, 0.04);
  EXPECT_NEAR(got.r, got.b, 0.03);  // grey in, grey out
}

TEST(Subsurface, TranslucencyMappingKeepsPigmentAsReflectance) {
  material::Finish f;
  f.diffuse = 0.5;
  f.subsurface = true;
  f.subsurface_translucency = Color(1, 2, 3);
  const material::Dipole d = finish_dipole(f, Color(0.8, 0.6, 0.4), 1.5);
  EXPECT_NEAR(d.total_reflectance().r, 0.4, 1e-6);
  EXPECT_NEAR(d.total_reflectance().b, 0.2, 1e-6);
  EXPECT_NEAR(d.sigma_s_prime.b, 1.0 / 3, 1e-12);
}

}  // namespace
}  // namespace snell::render
