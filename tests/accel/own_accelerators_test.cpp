// Every accelerator (embree and the own bvh, octree, grid) must return brute force's nearest hit (the
// reference: every object tested) for every ray, window and ray kind, on scenes of spheres, rotated boxes,
// ellipsoids and planes; and every accelerator must honour `bounded_by` boxes the same way.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "accel_test_support.hpp"
#include "snell/geometry/box.hpp"

using namespace snell;
using namespace snell::accel_test;
using math::Transform;
using math::Vec3;
using scene::RayKind;

namespace {

/// random_scene plus rotated boxes, a few of them large (crossing many grid cells and octree nodes).
scene::Scene mixed_scene(uint64_t seed, int count) {
  scene::Scene s = random_scene(seed, count);
  math::Pcg32 rng(seed + 1000);
  for (int i = 0; i < count / 3; ++i) {
    const double size = i % 20 == 0 ? 6 : uniform(rng, 0.1, 1.5);
    const Transform t = Transform::translate(uniform_vec(rng, -10, 10)) *
                        Transform::rotate_xyz_degrees(uniform_vec(rng, 0, 360));
    s.objects.push_back(make_object(std::make_shared<geometry::Box>(Vec3(-size), Vec3(size)), t));
  }
  return s;
}

class OwnAcceleratorTest : public testing::TestWithParam<std::string> {};

TEST_P(OwnAcceleratorTest, NearestHitMatchesBruteForce) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const scene::Scene s = mixed_scene(seed, 300);
    const auto tested = accel::make_accelerator(GetParam(), s);
    const auto brute = accel::make_accelerator("none", s);
    math::Pcg32 rng(seed * 31);
    // Origins inside and outside the objects' region.
    const int hits = compare_random_rays(*tested, *brute, rng, 4000, 25);
    EXPECT_GT(hits, 2000) << "scene too sparse to test anything";
  }
}

TEST_P(OwnAcceleratorTest, RespectsTMinTMaxWindows) {
  const scene::Scene s = mixed_scene(11, 200);
  const auto tested = accel::make_accelerator(GetParam(), s);
  const auto brute = accel::make_accelerator("none", s);
  math::Pcg32 rng(5);
  for (int i = 0; i < 4000; ++i) {
    const math::Ray ray{uniform_vec(rng, -15, 15), normalize(uniform_vec(rng, -1, 1)), 0};
    const double t_min = uniform(rng, 0, 20);
    const double t_max = t_min + uniform(rng, 0, 15);
    expect_same_hit(*tested, *brute, ray, t_min, t_max, kKinds[i % 4]);
  }
}

TEST_P(OwnAcceleratorTest, AxisParallelRaysAlongCellPlanes) {
  // Rays parallel to two axes that start on the scene's grid planes: the 0 * inf corner of slab tests and
  // the DDA's parallel axes.
  const scene::Scene s = mixed_scene(4, 300);
  const auto tested = accel::make_accelerator(GetParam(), s);
  const auto brute = accel::make_accelerator("none", s);
  for (int a = 0; a < 3; ++a)
    for (double u = -12; u <= 12; u += 0.5)
      for (double v = -12; v <= 12; v += 0.5) {
        Vec3 origin{u, v, u};
        origin[a] = -30;
        Vec3 direction{0, 0, 0};
        direction[a] = 1;
        expect_same_hit(*tested, *brute, {origin, direction, 0}, 0, math::kInfinity, RayKind::camera);
        expect_same_hit(*tested, *brute, {-origin, -direction, 0}, 0, math::kInfinity, RayKind::shadow);
      }
}

TEST_P(OwnAcceleratorTest, CoincidentObjectsAndDegenerateRays) {
  // 200 equal spheres (no SAH split separates equal centroids) inside a larger sphere.
  scene::Scene s;
  for (int i = 0; i < 200; ++i)
    s.objects.push_back(make_object(std::make_shared<geometry::Sphere>(Vec3(1), 0.5)));
  s.objects.push_back(make_object(std::make_shared<geometry::Sphere>(Vec3(0), 5)));
  const auto tested = accel::make_accelerator(GetParam(), s);
  const auto brute = accel::make_accelerator("none", s);
  scene::SurfaceHit hit;
  // From inside the big sphere: the small spheres' near surface z = 0.5 comes first (t = 3.5); which of
  // the equal spheres is reported is not specified.
  ASSERT_TRUE(tested->intersect({{1, 1, -3}, {0, 0, 1}, 0}, 0, math::kInfinity, RayKind::camera, hit));
  EXPECT_DOUBLE_EQ(hit.t, 3.5);
  ASSERT_TRUE(tested->intersect({{1, 1, 2}, {0, 0, 1}, 0}, 0, math::kInfinity, RayKind::camera, hit));
  EXPECT_DOUBLE_EQ(hit.t, std::sqrt(23.0) - 2);  // big sphere from inside at z = sqrt(25 - 1 - 1)
  EXPECT_EQ(hit.object, s.objects.back().get());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const math::Ray toward{{0, 0, -20}, {0.01, 0.02, 1}, 0};
  expect_same_hit(*tested, *brute, toward, 5, 5, RayKind::camera);
  expect_same_hit(*tested, *brute, toward, 9, 3, RayKind::camera);
  expect_same_hit(*tested, *brute, toward, nan, 50, RayKind::camera);
  expect_same_hit(*tested, *brute, {{0, 0, 0}, {0, 0, 0}, 0}, 0, math::kInfinity, RayKind::camera);
  expect_same_hit(*tested, *brute, {{nan, 0, 0}, {0, 0, 1}, 0}, 0, math::kInfinity, RayKind::camera);
  expect_same_hit(*tested, *brute, {{0, 0, 0}, {0, 0, nan}, 0}, 0, math::kInfinity, RayKind::camera);
}

TEST_P(OwnAcceleratorTest, StatsDescribeTheStructure) {
  const scene::Scene s = random_scene(4, 1000);
  const auto a = accel::make_accelerator(GetParam(), s);
  EXPECT_EQ(a->name(), GetParam());
  if (GetParam() == "embree") return;  // Embree does not tell its node count or memory
  EXPECT_EQ(a->stats().objects, 1002u);
  EXPECT_EQ(a->stats().unbounded_objects, 2u);  // the two planes
  if (GetParam() == "list") {                   // no tree: one box per bounded object
    EXPECT_EQ(a->stats().nodes, 0u);
    EXPECT_EQ(a->stats().memory_bytes, 1000 * sizeof(math::Bounds3));
    return;
  }
  EXPECT_GT(a->stats().nodes, 8u);
  EXPECT_GT(a->stats().memory_bytes, 1000 * sizeof(void*));
}

TEST_P(OwnAcceleratorTest, EmptyAndUnboundedOnlyScenes) {
  scene::Scene s;
  scene::SurfaceHit hit;
  EXPECT_FALSE(accel::make_accelerator(GetParam(), s)
                   ->intersect({{0, 0, 0}, {0, 0, 1}, 0}, 0, math::kInfinity, RayKind::camera, hit));
  s.objects.push_back(make_object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -1)));
  const auto a = accel::make_accelerator(GetParam(), s);
  ASSERT_TRUE(a->intersect({{0, 0, 0}, {0, -2, 0}, 0}, 0, math::kInfinity, RayKind::camera, hit));
  EXPECT_DOUBLE_EQ(hit.t, 0.5);  // y = -1 reached at t = 0.5 with direction length 2
}

INSTANTIATE_TEST_SUITE_P(Kinds, OwnAcceleratorTest,
                         testing::Values("embree", "bvh", "octree", "grid", "list"),
                         [](const auto& info) { return info.param; });

class BoundedByTest : public testing::TestWithParam<std::string> {};

TEST_P(BoundedByTest, OnlyThePartInsideTheBoundIsSeen) {
  // A radius-2 sphere bounded by x, y in [-3, 3], z in [-3, 1]: from -z the ray meets the sphere at
  // z = -2 (t = 8), inside the box. From +z the near surface z = 2 lies outside the box; the ray enters
  // the box at z = 1 inside the sphere and leaves the sphere at z = -2 (t = 12). A ray at x = 3.5 misses
  // the box.
  scene::Scene s;
  auto bounded = make_object(std::make_shared<geometry::Sphere>(Vec3(0), 2));
  bounded->bounded_by = math::Bounds3(Vec3(-3, -3, -3), Vec3(3, 3, 1));
  s.objects.push_back(bounded);
  // A plane bounded by a box becomes a bounded object; outside the box it is not there.
  auto floor = make_object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -5));
  floor->bounded_by = math::Bounds3(Vec3(-3, -6, -3), Vec3(3, -4, 3));
  s.objects.push_back(floor);
  const auto a = accel::make_accelerator(GetParam(), s);
  scene::SurfaceHit hit;
  ASSERT_TRUE(a->intersect({{0, 0, -10}, {0, 0, 1}, 0}, 0, math::kInfinity, RayKind::camera, hit));
  EXPECT_DOUBLE_EQ(hit.t, 8.0);
  ASSERT_TRUE(a->intersect({{0, 0, 10}, {0, 0, -1}, 0}, 0, math::kInfinity, RayKind::camera, hit));
  EXPECT_DOUBLE_EQ(hit.t, 12.0);
  EXPECT_FALSE(a->intersect({{3.5, 0, -10}, {0, 0, 1}, 0}, 0, math::kInfinity, RayKind::camera, hit));
  ASSERT_TRUE(a->intersect({{2.5, 0, 0}, {0, -1, 0}, 0}, 0, math::kInfinity, RayKind::shadow, hit));
  EXPECT_DOUBLE_EQ(hit.t, 5.0);  // the plane y = -5 inside its bound
  EXPECT_FALSE(a->intersect({{3.5, 0, 0}, {0, -1, 0}, 0}, 0, math::kInfinity, RayKind::shadow, hit));
}

TEST_P(BoundedByTest, RandomBoundsMatchBruteForce) {
  // Bounds of every size, some smaller than their objects and some apart from them.
  scene::Scene s = random_scene(17, 200);
  math::Pcg32 rng(23);
  for (auto& o : s.objects) {
    auto bounded = std::make_shared<scene::Object>(*o);
    const Vec3 c = uniform_vec(rng, -10, 10), half = uniform_vec(rng, 0.5, 4);
    bounded->bounded_by = math::Bounds3(c - half, c + half);
    o = bounded;
  }
  const auto tested = accel::make_accelerator(GetParam(), s);
  const auto brute = accel::make_accelerator("none", s);
  for (int i = 0; i < 3000; ++i) {
    const math::Ray ray{uniform_vec(rng, -15, 15), uniform_vec(rng, -1, 1), 0};
    expect_same_hit(*tested, *brute, ray, 1e-6, math::kInfinity, kKinds[i % 4]);
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, BoundedByTest,
                         testing::Values("embree", "bvh", "octree", "grid", "list", "none"),
                         [](const auto& info) { return info.param; });

TEST(MakeAcceleratorTest, KnowsEveryName) {
  const scene::Scene s;
  for (const char* kind : {"embree", "bvh", "octree", "grid", "none"})
    EXPECT_EQ(accel::make_accelerator(kind, s)->name(), kind);
}

}  // namespace
