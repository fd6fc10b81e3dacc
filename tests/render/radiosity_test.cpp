// Radiosity (POV-Ray 3.7 reference, "Radiosity"): the gather's direction table integrates cosine-weighted
// irradiance, and rendered points under a uniform sky take the analytic value diffuse * colour * sky.
#include "snell/render/radiosity/solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

TEST(RadiosityTest, DirectionTableIsCosineDistributedOverTheHemisphere) {
  const auto dirs = radiosity::cosine_directions(400);
  ASSERT_EQ(dirs.size(), 400u);
  double mean_cos = 0;
  for (const Vec3& d : dirs) {
    EXPECT_NEAR(length(d), 1.0, 1e-12);
    EXPECT_GT(d.z, 0.0);
    mean_cos += d.z;
  }
  // For a cosine-weighted density p = cos(theta)/pi, E[cos(theta)] = 2/3.
  EXPECT_NEAR(mean_cos / 400, 2.0 / 3.0, 1e-3);
}

TEST(RadiosityTest, FrameIsOrthonormalForAnyNormal) {
  for (const Vec3& n : {Vec3(0, 0, 1), Vec3(0, 0, -1 + 1e-9), normalize(Vec3(1, 2, -3)), Vec3(0, 1, 0)}) {
    Vec3 t, b;
    radiosity::orthonormal_frame(n, t, b);
    EXPECT_NEAR(dot(t, n), 0, 1e-9);
    EXPECT_NEAR(dot(b, n), 0, 1e-9);
    EXPECT_NEAR(dot(t, b), 0, 1e-9);
    EXPECT_NEAR(length(t), 1, 1e-9);
    EXPECT_NEAR(length(cross(t, b) - n), 0, 1e-9);
  }
}

TEST(RadiosityTest, SphereOverheadHidesSinSquaredOfTheIrradiance) {
  // A black sphere of radius R at height h above a point hides sin^2(alpha) = (R/h)^2 of the cosine-weighted
  // sky (its projected solid angle is pi sin^2(alpha)); the rest of a sky of radiance 1 gives 1 - (R/h)^2.
  scene::RadiositySettings settings;
  settings.count = 1600;
  settings.brightness = 2;
  const radiosity::Solver solver(settings, Vec3(0, 0, -5), nullptr, 5);
  const double radius = 1, height = 2;
  TraceContext context;  // no tile open: the gather is not kept
  const Color seen =
      solver.ambient(Vec3(0, 0, 0), Vec3(0, 1, 0), 1, context, [&](const Vec3& d, int, double) {
        const double along = d.y * height;  // closest approach of the ray to the centre (0, h, 0)
        const double miss = height * height - along * along;
        return miss < radius * radius ? Color(0) : Color(1);
      });
  EXPECT_NEAR(seen.r, 2 * (1 - (radius / height) * (radius / height)), 0.01);
}

TEST(RadiosityTest, BounceSettingsFollowPovRay) {
  // radiosity.cpp GetRecursionSettings: rays halve per bounce (at least 5), reuse counts nearest_count, 2,
  // 1, error bound and reuse distances double.
  scene::RadiositySettings s;
  s.count = 35;
  s.nearest_count = 5;
  const radiosity::BounceSettings b0 = radiosity::bounce_settings(s, 0),
                                  b1 = radiosity::bounce_settings(s, 1),
                                  b3 = radiosity::bounce_settings(s, 3);
  EXPECT_EQ(b0.rays, 35);
  EXPECT_EQ(b1.rays, 17);
  EXPECT_EQ(b3.rays, 5);
  EXPECT_EQ(b0.reuse_count, 5);
  EXPECT_EQ(b1.reuse_count, 2);
  EXPECT_EQ(b3.reuse_count, 1);
  EXPECT_DOUBLE_EQ(b1.error_factor, 2);
  EXPECT_DOUBLE_EQ(b1.minimum_reuse, 0.03);
  EXPECT_EQ(b0.directions.size(), 35u);
}

scene::Scene sphere_under_white_sky(int recursion_limit) {
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0.3);  // ignored under radiosity in 3.7 scenes
  f.diffuse = 0.5;
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 1.0),
                                   test::texture({Color(1, 0.5, 0.25)}, f)));
  s.background.rgb = Color(1);
  s.camera.location = {0, 0, -5};
  s.camera.direction = {0, 0, 1};
  s.camera.right = {1, 0, 0};
  scene::RadiositySettings r;
  r.count = 20;
  r.recursion_limit = recursion_limit;
  s.settings.radiosity = r;
  return s;
}

RenderResult render_small(const scene::Scene& s, int threads) {
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 9;
  o.height = 9;
  o.threads = threads;
  return Renderer(s, *accel, o).render();
}

TEST(RadiosityTest, ConvexDiffuseSurfaceUnderUniformSkyIsDiffuseTimesColour) {
  // Every direction above a convex surface sees the sky of radiance 1: ambient = 1, so the surface shows
  // diffuse * pigment, with no `ambient` term.
  const RenderResult r = render_small(sphere_under_white_sky(1), 1);
  const Color c = r.image.at(4, 4);
  EXPECT_NEAR(c.r, 0.5, 1e-6);
  EXPECT_NEAR(c.g, 0.25, 1e-6);
  EXPECT_NEAR(c.b, 0.125, 1e-6);
}

TEST(RadiosityTest, WithoutRadiosityTheAmbientTermStays) {
  scene::Scene s = sphere_under_white_sky(1);
  s.settings.radiosity.reset();
  EXPECT_NEAR(render_small(s, 1).image.at(4, 4).r, 0.3, 1e-6);
}

TEST(RadiosityTest, SameImageForAnyThreadCount) {
  scene::Scene s = sphere_under_white_sky(2);
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -1.0), test::texture({Color(0.8)})));
  s.lights.push_back(test::point_light({3, 5, -4}));
  const RenderResult one = render_small(s, 1);
  const RenderResult three = render_small(s, 3);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 9; ++x) EXPECT_EQ(one.image.at(x, y), three.image.at(x, y));
}

/// Pretrace passes and rays from the radiosity line of the statistics ("N pretrace passes (M rays)").
std::pair<uint64_t, uint64_t> pretrace_counts(const RenderResult& r) {
  unsigned long long passes = 0, rays = 0;
  const size_t at = r.integrator_summary.find("radiosity: ");
  if (at == std::string::npos ||
      std::sscanf(r.integrator_summary.c_str() + at, "radiosity: %llu pretrace passes (%llu rays)", &passes,
                  &rays) != 2)
    ADD_FAILURE() << r.integrator_summary;
  return {passes, rays};
}

TEST(RadiosityTest, GatherRaysSeeAreaLightsAsPointLights) {
  // POV-Ray 3.7 traces radiosity's gather rays without area lights (radiosity.cpp clears Q_AREA_LIGHT).
  // A 2 x 2 area light tests its 4 corners from a camera hit, 1 ray from a gather hit, a point light 1 from
  // both: so the pretrace's rays with the area light exceed those with the point light by at most 3 per
  // pretrace camera ray (81 per pass on a 9 x 9 image), however many gather rays hit the scene.
  scene::Scene s = sphere_under_white_sky(1);
  s.background.rgb = Color(0.2);
  s.settings.radiosity->count = 400;
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -1.0), test::texture({Color(0.8)})));
  scene::Light point = test::point_light({3, 5, -4});
  scene::Light area = point;
  area.area = true;
  area.axis1 = {0.5, 0, 0};
  area.axis2 = {0, 0, 0.5};
  area.size1 = area.size2 = 2;
  scene::Scene with_point = s, with_area = s;
  with_point.lights.push_back(point);
  with_area.lights.push_back(area);
  const auto [passes, point_rays] = pretrace_counts(render_small(with_point, 1));
  const auto [area_passes, area_rays] = pretrace_counts(render_small(with_area, 1));
  ASSERT_EQ(passes, area_passes);
  ASSERT_GT(point_rays, 10 * 81 * passes);  // the gathers' rays outnumber the camera rays many times
  EXPECT_GT(area_rays, point_rays);
  EXPECT_LE(area_rays - point_rays, 3 * 81 * passes);
}

}  // namespace
}  // namespace snell::render
