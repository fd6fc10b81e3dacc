// Layers against analytic answers: the depth layer is the distance along the camera ray to a plane and to a
// sphere; object ids do not depend on the thread count; the beauty image is the renderer's.
#include "snell/render/explain/aov_render.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "explain_scenes.hpp"

namespace snell::render::explain {
namespace {

using math::Vec3;

const Layer& layer(const AovRender& r, const std::string& name) {
  for (const Layer& l : r.layers)
    if (l.name == name) return l;
  throw std::logic_error("no layer " + name);
}

TEST(AovTest, DepthIsTheAnalyticDistanceToAPlaneAndASphere) {
  const scene::Scene scene = test::parse(R"(
#version 3.7;
camera { location <0, 1, -5> look_at <0, 0, 0> }
light_source { <3, 5, -4> color rgb 1 }
sphere { <0.5, 0.2, 0>, 1 pigment { rgb 1 } }
plane { y, -1 pigment { rgb 1 } }
)");
  const auto accel = accel::make_accelerator("bvh", scene);
  RenderOptions o;
  o.width = 40;
  o.height = 30;
  const AovRender r = render_aovs(scene, *accel, o, {"depth", "object"}, -1);
  const Layer& depth = layer(r, "depth");
  const Layer& object = layer(r, "object");
  const auto camera = scene::make_camera(scene.camera);
  int on_sphere = 0, on_plane = 0;
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      const auto ray = camera->generate_ray((x + 0.5) / o.width, (y + 0.5) / o.height, 0);
      ASSERT_TRUE(ray);
      const Vec3 p = ray->origin, d = normalize(ray->direction);
      // Sphere |p + t d - c|^2 = 1: t = -b - sqrt(b^2 - q), b = d.(p - c), q = |p - c|^2 - 1.
      const Vec3 oc = p - Vec3(0.5, 0.2, 0);
      const double b = dot(d, oc), q = dot(oc, oc) - 1;
      const double t_sphere = b * b - q >= 0 ? -b - std::sqrt(b * b - q) : math::kInfinity;
      // Plane y = -1: t = (-1 - p.y) / d.y.
      const double t_plane = d.y < 0 ? (-1 - p.y) / d.y : math::kInfinity;
      const double expected = std::min(t_sphere, t_plane);
      const size_t i = static_cast<size_t>(y) * o.width + x;
      if (!std::isfinite(expected)) {
        EXPECT_TRUE(std::isinf(depth.values[i]));
        EXPECT_EQ(object.values[i], -1.0f);
        continue;
      }
      (t_sphere < t_plane ? on_sphere : on_plane)++;
      EXPECT_NEAR(depth.values[i], expected, 1e-6 * std::max(1.0, expected / 8)) << x << "," << y;
      EXPECT_EQ(object.values[i], t_sphere < t_plane ? 0.0f : 1.0f);
    }
  EXPECT_GT(on_sphere, 50);
  EXPECT_GT(on_plane, 50);
}

TEST(AovTest, ObjectIdsAndBeautyAreTheSameForOneAndManyThreads) {
  const scene::Scene scene = test::parse(test::kGlassSphere);
  const auto accel = accel::make_accelerator("bvh", scene);
  RenderOptions o;
  o.width = 48;
  o.height = 36;
  o.antialias = true;
  o.aa_threshold = 0.1;
  o.aa_depth = 2;
  o.threads = 1;
  const AovRender one = render_aovs(scene, *accel, o, {"object", "material", "samples"}, -1);
  o.threads = 4;
  const AovRender many = render_aovs(scene, *accel, o, {"object", "material", "samples"}, -1);
  EXPECT_EQ(layer(one, "object").values, layer(many, "object").values);
  EXPECT_EQ(layer(one, "material").values, layer(many, "material").values);
  EXPECT_EQ(layer(one, "samples").values, layer(many, "samples").values);
  EXPECT_EQ(one.beauty.rgb, many.beauty.rgb);
  // The same pixels as the renderer's, supersampled where it supersamples (1 or 2^2 + 1 samples).
  const RenderResult reference = Renderer(scene, *accel, o).render();
  EXPECT_EQ(one.beauty.rgb, reference.image.rgb);
  double supersampled = 0;
  for (const float s : layer(one, "samples").values) {
    EXPECT_TRUE(s == 1 || s == 5);
    supersampled += s == 5;
  }
  EXPECT_EQ(supersampled, static_cast<double>(reference.supersampled_pixels));
}

TEST(AovTest, UnknownLayerIsRefused) {
  const scene::Scene scene = test::parse(test::kGlassSphere);
  const auto accel = accel::make_accelerator("none", scene);
  RenderOptions o;
  o.width = 4;
  o.height = 3;
  EXPECT_THROW(render_aovs(scene, *accel, o, {"depth", "colour"}, -1), std::invalid_argument);
}

}  // namespace
}  // namespace snell::render::explain
