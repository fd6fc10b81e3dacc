// Glossy reflection and rough transmission (render/glossy.hpp): blur 0 gives the mirror and Snell
// directions of ../shared/reference-values.md section 3 exactly; a white furnace (uniform surroundings)
// never returns more light than arrives; blurred rays spread evenly about the plane of incidence.
#include "snell/render/glossy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.hpp"
#include "snell/geometry/box.hpp"
#include "snell/math/constants.hpp"
#include "snell/render/microfacet.hpp"
#include "snell/render/optics.hpp"
#include "snell/render/renderer.hpp"
#include "snell/render/whitted.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

const double kHalf = std::sqrt(0.5);

RoughSurface surface(const Vec3& incident, double alpha) {
  return {incident, Vec3(0, 1, 0), Vec3(0, 1, 0), alpha};
}

TEST(GlossyTest, ZeroBlurIsTheMirrorDirectionExactly) {
  const Vec3 i(kHalf, -kHalf, 0);
  const RoughSample r = sample_glossy_reflection(surface(i, 0), 0.3, 0.7);
  EXPECT_EQ(r.direction, math::reflect(i, Vec3(0, 1, 0)));
  EXPECT_NEAR(r.direction.x, kHalf, 1e-15);
  EXPECT_NEAR(r.direction.y, kHalf, 1e-15);
  EXPECT_EQ(r.weight, 1.0);
}

TEST(GlossyTest, ZeroBlurIsTheSnellDirectionExactly) {
  // reference-values.md section 3: i = (sqrt 1/2, -sqrt 1/2, 0), eta = 1/1.5 -> (0.4714045208,
  // -0.8819171037).
  const RoughSample t = sample_rough_transmission(surface(Vec3(kHalf, -kHalf, 0), 0), 1 / 1.5, 0.5, 0.5);
  EXPECT_FALSE(t.reflected);
  EXPECT_NEAR(t.direction.x, 0.4714045208, 1e-9);
  EXPECT_NEAR(t.direction.y, -0.8819171037, 1e-9);
  EXPECT_EQ(t.weight, 1.0);
  // i = (0.5, -sqrt 3/2, 0), eta = 1.5 -> (0.75, -0.6614378278).
  const RoughSample out =
      sample_rough_transmission(surface(Vec3(0.5, -std::sqrt(0.75), 0), 0), 1.5, 0.5, 0.5);
  EXPECT_NEAR(out.direction.x, 0.75, 1e-9);
  EXPECT_NEAR(out.direction.y, -0.6614378278, 1e-9);
  // 45 degrees from glass (critical angle 41.81): total internal reflection, weight 1.
  const RoughSample tir = sample_rough_transmission(surface(Vec3(kHalf, -kHalf, 0), 0), 1.5, 0.5, 0.5);
  EXPECT_TRUE(tir.reflected);
  EXPECT_NEAR(tir.direction.y, kHalf, 1e-15);
}

TEST(GlossyTest, WhiteFurnaceReflectsNoMoreThanArrives) {
  // Uniform white surroundings: the estimate is the directional albedo of the GGX mirror, <= 1, near 1 for
  // a nearly smooth surface and falling with roughness (light lost to masking, single scattering).
  const auto white = [](const Vec3&) { return Color(1); };
  for (double view_deg : {0.0, 45.0, 80.0}) {
    const double th = math::radians(view_deg);
    const Vec3 i(std::sin(th), -std::cos(th), 0);
    double previous = 1;
    for (double alpha : {0.02, 0.2, 0.5, 1.0}) {
      math::Pcg32 rng(7);
      const double albedo = glossy_reflection(surface(i, alpha), 20000, rng, white).r;
      EXPECT_LE(albedo, 1.0) << "alpha " << alpha << " view " << view_deg;
      EXPECT_LE(albedo, previous + 1e-3) << "alpha " << alpha << " view " << view_deg;
      if (alpha <= 0.02) {
        EXPECT_GT(albedo, 0.98) << "view " << view_deg;
      }
      previous = albedo;
    }
  }
}

TEST(GlossyTest, FurnaceEstimateMatchesTheBrdfIntegral) {
  // The estimator's mean is the integral of the GGX BRDF times cos over the hemisphere, with F = 1:
  // D(h) G2(v, l) / (4 v.z) (Walter et al. 2007, eq. 20), here by quadrature over l.
  const auto white = [](const Vec3&) { return Color(1); };
  const Vec3 v(std::sin(math::radians(45)), 0, std::cos(math::radians(45)));
  for (double alpha : {0.2, 0.5, 1.0}) {
    const int n_cos = 1000, n_phi = 128;
    const double dc = 1.0 / n_cos, dp = 2 * math::kPi / n_phi;
    double integral = 0;
    for (int i = 0; i < n_cos; ++i)
      for (int j = 0; j < n_phi; ++j) {
        const double c = (i + 0.5) * dc, phi = (j + 0.5) * dp, s = std::sqrt(1 - c * c);
        const Vec3 l(s * std::cos(phi), s * std::sin(phi), c);
        integral += ggx_distribution(normalize(v + l), alpha) * ggx_masking_shadowing(v, l, alpha) /
                    (4 * v.z) * dc * dp;
      }
    // The same view in the world frame the glossy code uses (normal +y, incident towards the surface).
    math::Pcg32 rng(5);
    const double estimate = glossy_reflection(surface(Vec3(-v.x, -v.z, 0), alpha), 40000, rng, white).r;
    EXPECT_NEAR(estimate, integral, 0.01) << "alpha " << alpha;
  }
}

TEST(GlossyTest, RoughTransmissionFurnaceStaysBelowOne) {
  const auto white = [](const Vec3&) { return Color(1); };
  for (double eta : {1 / 1.5, 1.5}) {
    for (double alpha : {0.05, 0.3, 0.8}) {
      math::Pcg32 rng(3);
      const RoughTransmission t =
          rough_transmission(surface(normalize(Vec3(0.3, -1, 0)), alpha), eta, 20000, rng, white, white);
      EXPECT_LE(t.refracted.r + t.reflected.r, 1.0) << "eta " << eta << " alpha " << alpha;
      EXPECT_GT(t.refracted.r + t.reflected.r, 0.5) << "eta " << eta << " alpha " << alpha;
    }
  }
}

TEST(GlossyTest, RoughRefractionScattersAroundTheSnellDirection) {
  // The mean refracted direction of a slightly rough surface stays near Snell's; the spread grows with blur.
  const Vec3 i(kHalf, -kHalf, 0);
  const Vec3 snell = normalize(*refract(i, Vec3(0, 1, 0), 1 / 1.5));
  double spread_small = 0, spread_large = 0;
  for (double alpha : {0.05, 0.4}) {
    math::Pcg32 rng(11);
    Vec3 mean(0, 0, 0);
    double spread = 0;
    const int n = 4000;
    for (int k = 0; k < n; ++k) {
      const RoughSample t =
          sample_rough_transmission(surface(i, alpha), 1 / 1.5, rng.next_double(), rng.next_double());
      ASSERT_FALSE(t.reflected);
      mean += t.direction / n;
      spread += (1 - dot(t.direction, snell)) / n;
    }
    if (alpha < 0.1) {
      EXPECT_GT(dot(normalize(mean), snell), 0.999);
      spread_small = spread;
    } else {
      spread_large = spread;
    }
  }
  EXPECT_GT(spread_large, 10 * spread_small);
}

TEST(GlossyTest, RoughSurfaceStillReflectsTotallyPastTheCriticalAngle) {
  // From glass (eta 1.5) at 60 degrees, past the 41.81 degree critical angle, a microfacet refracts only
  // when tilted by more than 18 degrees towards the ray: for GGX, P(tan theta_m > t) = alpha^2 / (alpha^2 +
  // t^2), 2.3% at alpha 0.05 (fewer still among visible normals). At 30 degrees, 11.8 degrees of tilt: 5.4%.
  const Vec3 steep(std::sin(math::radians(60)), -std::cos(math::radians(60)), 0);
  const Vec3 gentle(0.5, -std::sqrt(0.75), 0);
  math::Pcg32 rng(17);
  const int n = 4000;
  int reflected_steep = 0, reflected_gentle = 0;
  for (int k = 0; k < n; ++k) {
    const RoughSample t =
        sample_rough_transmission(surface(steep, 0.05), 1.5, rng.next_double(), rng.next_double());
    if (t.reflected) {
      ++reflected_steep;
      if (t.weight > 0) {
        EXPECT_GT(t.direction.y, 0);
      }
    } else if (t.weight > 0) {
      EXPECT_LT(t.direction.y, 0);
    }
    if (sample_rough_transmission(surface(gentle, 0.05), 1.5, rng.next_double(), rng.next_double()).reflected)
      ++reflected_gentle;
  }
  EXPECT_GT(reflected_steep, 0.977 * n);
  EXPECT_LT(reflected_gentle, 0.054 * n);
  EXPECT_GT(reflected_gentle, 0);
}

TEST(GlossyTest, SampleCountIsFullOnlyWhereCameraRaysHit) {
  EXPECT_EQ(rough_sample_count(0, 1), 8);
  EXPECT_EQ(rough_sample_count(32, 1), 32);
  EXPECT_EQ(rough_sample_count(32, 2), 1);
}

/// A glossy floor (y = 0, reflection 1, no diffuse) under a bright wall that covers only x > 0: the camera
/// ray in the plane x = 0 has its mirror ray on the wall's edge, so a blurred reflection sees the wall with
/// half of its rays (the visible normals are symmetric about the plane of incidence).
scene::Scene floor_under_half_wall(double blur) {
  scene::Scene s;
  material::Finish floor;
  floor.ambient = Color(0);
  floor.diffuse = 0;
  floor.reflection_min = floor.reflection_max = Color(1);
  floor.reflection_blur = blur;
  floor.reflection_samples = 1024;
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0), test::texture({Color(1)}, floor)));
  material::Finish glow;
  glow.ambient = Color(0);
  glow.diffuse = 0;
  glow.emission = Color(1);
  s.objects.push_back(test::object(std::make_shared<geometry::Box>(Vec3(0, -1, 10), Vec3(1000, 1000, 11)),
                                   test::texture({Color(1)}, glow)));
  s.camera.location = {0, 5, -5};
  return s;
}

TEST(GlossyTest, BlurredMirrorSeesHalfOfAWallWhoseEdgeItsMirrorRayGrazes) {
  const Vec3 eye(0, 5, -5);  // 45 degrees onto the floor at the origin; the mirror ray reaches the wall
  const Vec3 to_floor = normalize(Vec3(0, 0, 0) - eye);
  {
    const scene::Scene s = floor_under_half_wall(0.1);
    const auto accel = accel::make_accelerator("none", s);
    WhittedIntegrator w(s, *accel);
    TraceContext ctx;
    ctx.rng = math::Pcg32(99);
    const Color c = w.trace_camera_ray({eye, to_floor}, ctx);
    // Half the rays, times the mean masking-shadowing weight (the GGX albedo, 0.98 at 45 degrees and this
    // blur; FurnaceEstimateMatchesTheBrdfIntegral); 1024 rays leave a binomial noise of 0.016.
    EXPECT_NEAR(c.r, 0.49, 0.035);
    EXPECT_GE(ctx.counters.reflected, 1000u);
  }
  {
    // The mirror: all or nothing just either side of the edge.
    const scene::Scene s = floor_under_half_wall(0);
    const auto accel = accel::make_accelerator("none", s);
    WhittedIntegrator w(s, *accel);
    TraceContext ctx;
    EXPECT_NEAR(w.trace_camera_ray({eye, normalize(Vec3(0.01, 0, 0) - eye)}, ctx).r, 1.0, 1e-12);
    EXPECT_EQ(w.trace_camera_ray({eye, normalize(Vec3(-0.01, 0, 0) - eye)}, ctx).r, 0.0);
  }
}

/// A glossy sphere, a frosted glass sphere and a floor (blur 0: test::two_spheres' mirror and glass).
RenderResult render_rough_spheres(int threads, bool blur) {
  scene::Scene s;
  material::Finish glossy;
  glossy.reflection_min = glossy.reflection_max = Color(0.6);
  glossy.reflection_blur = blur ? 0.2 : 0;
  material::Finish frosted;
  frosted.transmission_blur = blur ? 0.2 : 0;
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(-0.6, 0, 0), 0.7),
                                   test::texture({Color(0.9, 0.2, 0.1)}, glossy)));
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0.7, 0.2, 0.5), 0.6),
                                   test::texture({Color(0.2, 0.9, 0.4), 0.6, 0.1}, frosted), 1.4));
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -0.7), test::texture({Color(0.8)})));
  s.lights.push_back(test::point_light({3, 5, -4}));
  s.background.rgb = Color(0.1, 0.2, 0.4);
  s.camera.location = {0, 0.5, -4};
  s.camera.right = {4.0 / 3, 0, 0};
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 48;
  o.height = 36;
  o.threads = threads;
  o.seed = 7;
  return Renderer(s, *accel, o).render();
}

TEST(GlossyTest, RoughImageIsBitIdenticalForAnyThreadCount) {
  const RenderResult one = render_rough_spheres(1, true);
  const RenderResult two = render_rough_spheres(2, true);
  EXPECT_EQ(one.image.rgb, two.image.rgb);
  EXPECT_EQ(one.rays.total(), two.rays.total());
  // Blur changes the picture, and sends more rays (8 per camera-ray hit on a rough surface).
  const RenderResult smooth = render_rough_spheres(1, false);
  EXPECT_NE(one.image.rgb, smooth.image.rgb);
  EXPECT_GT(one.rays.reflected + one.rays.refracted, 4 * (smooth.rays.reflected + smooth.rays.refracted));
}

}  // namespace
}  // namespace snell::render
