// A flat layer of 10,000 spheres (a 100 x 100 carpet one unit thick): the case where an octree that
// halves every node along all three axes cuts every sphere in two at each level and ends with thousands
// of objects per leaf. Every own structure must give brute force's nearest hit there, and test at least
// 20 times fewer objects per ray than brute force (which tests all 10,000).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "accel_test_support.hpp"
#include "snell/accel/indexed_objects.hpp"

using namespace snell;
using namespace snell::accel_test;
using math::Vec3;
using scene::RayKind;

namespace {

constexpr int kSide = 100;

scene::Scene flat_layer() {
  scene::Scene s;
  for (int i = 0; i < kSide; ++i)
    for (int k = 0; k < kSide; ++k)
      s.objects.push_back(
          make_object(std::make_shared<geometry::Sphere>(Vec3(i - kSide / 2.0, 0, k - kSide / 2.0), 0.45)));
  return s;
}

/// Rays from above and beside the layer toward random points of it, so that most hit a sphere.
std::vector<math::Ray> rays_at_layer(int n) {
  math::Pcg32 rng(99);
  std::vector<math::Ray> rays;
  for (int i = 0; i < n; ++i) {
    const Vec3 origin{uniform(rng, -60, 60), uniform(rng, -5, 20), uniform(rng, -60, 60)};
    const Vec3 target{uniform(rng, -50, 50), uniform(rng, -0.5, 0.5), uniform(rng, -50, 50)};
    rays.push_back({origin, target - origin, 0});
  }
  return rays;
}

/// Mean object tests per ray of `a` over `rays`.
double tests_per_ray(const accel::Accelerator& a, const std::vector<math::Ray>& rays) {
  accel::ObjectTestCounter::reset();
  accel::ObjectTestCounter::enabled = true;
  for (const math::Ray& ray : rays) {
    scene::SurfaceHit hit;
    a.intersect(ray, 1e-6, math::kInfinity, RayKind::camera, hit);
  }
  accel::ObjectTestCounter::enabled = false;
  return static_cast<double>(accel::ObjectTestCounter::total()) / static_cast<double>(rays.size());
}

class FlatLayerTest : public testing::TestWithParam<std::string> {};

TEST_P(FlatLayerTest, NearestHitMatchesBruteForceWithFarFewerTests) {
  const scene::Scene s = flat_layer();
  const auto tested = accel::make_accelerator(GetParam(), s);
  const auto brute = accel::make_accelerator("none", s);
  const std::vector<math::Ray> rays = rays_at_layer(400);
  int hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    expect_same_hit(*tested, *brute, rays[i], 1e-6, math::kInfinity, kKinds[i % 4]);
    scene::SurfaceHit h;
    hits += brute->intersect(rays[i], 1e-6, math::kInfinity, RayKind::camera, h);
  }
  EXPECT_GT(hits, 200) << "rays should mostly hit the layer";
  const double brute_tests = tests_per_ray(*brute, rays);
  EXPECT_DOUBLE_EQ(brute_tests, kSide * kSide);
  const double tested_tests = tests_per_ray(*tested, rays);
  EXPECT_LT(tested_tests * 20, brute_tests) << GetParam() << " tests " << tested_tests << " objects per ray";
}

INSTANTIATE_TEST_SUITE_P(Kinds, FlatLayerTest, testing::Values("bvh", "octree", "grid"),
                         [](const auto& info) { return info.param; });

}  // namespace
