// The renderer with POV-Ray's other camera types and focal blur: pixels a projection has no ray for are
// black (POV-Ray leaves them transparent black whatever the background), and focal blur takes
// blur_samples rays per pixel, seeded so that the image does not depend on the thread count.
#include <gtest/gtest.h>

#include "scene_builder.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

scene::Scene spheres(const scene::CameraSpec& camera) {
  scene::Scene s;
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(-0.6, 0, 0), 0.7),
                                   test::texture({Color(0.9, 0.2, 0.1)})));
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0.9, 0.2, 2.5), 0.6),
                                   test::texture({Color(0.2, 0.9, 0.4)})));
  s.lights.push_back(test::point_light({3, 5, -4}));
  s.background.rgb = Color(0.1, 0.2, 0.4);
  s.camera = camera;
  return s;
}

RenderResult render(const scene::Scene& s, int threads, bool aa = false) {
  const auto accel = accel::make_accelerator("none", s);
  RenderOptions o;
  o.width = 40;
  o.height = 30;
  o.threads = threads;
  o.antialias = aa;
  o.seed = 3;
  return Renderer(s, *accel, o).render();
}

scene::CameraSpec blurred() {
  scene::CameraSpec c;
  c.location = {0, 0.5, -4};
  c.right = {4.0 / 3, 0, 0};
  c.aperture = 0.8;
  c.blur_samples = 9;
  c.focal_distance = 4;
  return c;
}

TEST(CameraRender, FocalBlurIsIdenticalForAnyThreadCount) {
  const scene::Scene s = spheres(blurred());
  const RenderResult one = render(s, 1), two = render(s, 2);
  EXPECT_EQ(one.image.rgb, two.image.rgb);
  // POV-Ray's stopping rule: the first batch of 7 always, the other 2 only where the colour varies.
  EXPECT_GE(one.rays.camera, 40u * 30u * 7u);
  EXPECT_LT(one.rays.camera, 40u * 30u * 9u);
  EXPECT_GT(one.rays.camera, 40u * 30u * 7u);
  // Anti-aliasing as POV-Ray's (tracetask.cpp, SupersampleOnePixel): pixels that differ from a neighbour
  // get 3x3 sub-samples, each a whole focal-blur estimate of at least the first batch of 7 rays; the
  // others keep their first-pass colour. Same image for any thread count.
  const RenderResult aa = render(s, 2, true), aa_one = render(s, 1, true);
  EXPECT_GT(aa.supersampled_pixels, 0u);
  EXPECT_LT(aa.supersampled_pixels, 40u * 30u / 2);
  EXPECT_GE(aa.rays.camera, one.rays.camera + aa.supersampled_pixels * 9u * 7u);
  EXPECT_EQ(aa.image.rgb, aa_one.image.rgb);
  size_t unchanged = 0;
  for (size_t i = 0; i < aa.image.rgb.size(); ++i) unchanged += aa.image.rgb[i] == one.image.rgb[i];
  EXPECT_GE(unchanged, (40u * 30u - aa.supersampled_pixels) * 3u);
  // blur_samples 9, 9: no stopping before 9.
  scene::Scene all = s;
  all.camera.blur_samples_min = 9;
  EXPECT_EQ(render(all, 2).rays.camera, 40u * 30u * 9u);
}

TEST(CameraRender, FocalBlurStopsEarlierWithLooserVariance) {
  scene::Scene tight = spheres(blurred()), loose = tight;
  tight.camera.blur_samples = loose.camera.blur_samples = 40;
  tight.camera.variance = 1e-6;
  loose.camera.variance = 0.1;
  EXPECT_LT(render(loose, 2).rays.camera, render(tight, 2).rays.camera);
}

scene::Scene one_sphere(const scene::CameraSpec& camera, double z, double radius) {
  scene::Scene s;
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0.5, z), radius),
                                   test::texture({Color(0.9, 0.9, 0.9)})));
  s.lights.push_back(test::point_light({0, 0.5, -10}));
  s.camera = camera;
  return s;
}

TEST(CameraRender, FocalBlurBlursOnlyOffTheFocalPlane) {
  // Two spheres of the same size in the image, one at the focal distance (4) and one twice as far: only
  // the far one's outline spreads (by several pixels with this aperture); the near one is just
  // anti-aliased by the samples spread over each pixel.
  scene::CameraSpec lens = blurred();
  lens.aperture = 3;
  scene::CameraSpec pin = lens;
  pin.aperture = 0;
  const auto change = [&](double z, double radius) {
    const RenderResult sharp = render(one_sphere(pin, z, radius), 2);
    const RenderResult soft = render(one_sphere(lens, z, radius), 2);
    double sum = 0;
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 40; ++x) sum += color_distance(sharp.image.at(x, y), soft.image.at(x, y));
    return sum;
  };
  EXPECT_GT(change(4, 0.8), 3 * change(0, 0.4));
}

TEST(CameraRender, FisheyeOutsideItsCircleIsBlack) {
  scene::CameraSpec c;
  c.kind = scene::CameraSpec::Kind::fisheye;
  c.location = {0, 0.5, -4};
  c.right = {1, 0, 0};
  c.angle = 180;
  const RenderResult r = render(spheres(c), 2);
  const Color corner = r.image.at(0, 0), centre = r.image.at(20, 15);
  EXPECT_EQ(corner.r + corner.g + corner.b, 0);
  EXPECT_GT(centre.r + centre.g + centre.b, 0);
  EXPECT_LT(r.rays.camera, 40u * 30u);  // no rays for the corners
}

}  // namespace
}  // namespace snell::render
