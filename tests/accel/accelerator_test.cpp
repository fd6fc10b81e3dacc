// Embree's nearest hit must equal brute force's (the reference: every object tested) for every ray,
// window and ray kind; Embree only chooses which objects to test, never how they are hit. Random scenes
// and windows for every accelerator, Embree included, are in own_accelerators_test.cpp.
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "accel_test_support.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/geometry/plane.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/pcg32.hpp"

using namespace snell;
using namespace snell::accel_test;
using math::Vec3;
using scene::RayKind;

TEST(EmbreeAcceleratorTest, RayKindFlagsHideObjects) {
  // One sphere in front of another; the front one is hidden from one kind of ray at a time.
  for (int flag = 0; flag < 3; ++flag) {
    scene::Scene s;
    auto front = make_object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 5), 1));
    auto back = make_object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 10), 1));
    front->flags.no_shadow = flag == 0;
    front->flags.no_image = flag == 1;
    front->flags.no_reflection = flag == 2;
    s.objects = {front, back};
    const auto embree = accel::make_accelerator("embree", s);
    const math::Ray ray{{0, 0, 0}, {0, 0, 1}, 0};
    for (RayKind kind : kKinds) {
      const bool hidden = (flag == 0 && kind == RayKind::shadow) ||
                          (flag == 1 && (kind == RayKind::camera || kind == RayKind::refraction)) ||
                          (flag == 2 && kind == RayKind::reflection);
      scene::SurfaceHit hit;
      ASSERT_TRUE(embree->intersect(ray, 0, math::kInfinity, kind, hit));
      EXPECT_EQ(hit.object, hidden ? back.get() : front.get());
      EXPECT_DOUBLE_EQ(hit.t, hidden ? 9.0 : 4.0);  // analytic: sphere surfaces at z = 4 and z = 9
    }
  }
}

TEST(AcceleratorTest, DistantCameraAndGrazingRaysKeepDoublePrecision) {
  // Tiny spheres seen from 1e5 away: float rays from the camera would be off by ~1e-2, more than the
  // spheres' size. Rays aim just inside and just outside each silhouette. The own structures' padding
  // (2^-40 of a box's magnitude) is tested here at its smallest.
  scene::Scene s;
  math::Pcg32 rng(9);
  std::vector<std::pair<Vec3, double>> spheres;
  for (int i = 0; i < 50; ++i) {
    spheres.emplace_back(uniform_vec(rng, -1, 1), uniform(rng, 1e-3, 1e-2));
    s.objects.push_back(
        make_object(std::make_shared<geometry::Sphere>(spheres.back().first, spheres.back().second)));
  }
  const auto brute = accel::make_accelerator("none", s);
  const Vec3 camera{3e4, -2e4, 1e5};
  for (const char* kind : {"embree", "bvh", "octree", "grid"}) {
    const auto tested = accel::make_accelerator(kind, s);
    int hits = 0;
    for (const auto& [c, r] : spheres) {
      Vec3 u, v;
      orthonormal_basis(normalize(c - camera), u, v);
      for (double f : {0.999999, 1.000001, 0.5}) {
        for (int k = 0; k < 8; ++k) {
          const double a = k * math::kTwoPi / 8;
          const Vec3 target = c + f * r * (std::cos(a) * u + std::sin(a) * v);
          const math::Ray ray{camera, target - camera, 0};
          expect_same_hit(*tested, *brute, ray, 0, math::kInfinity, RayKind::camera);
          scene::SurfaceHit h;
          hits += tested->intersect(ray, 0, math::kInfinity, RayKind::camera, h);
        }
      }
    }
    EXPECT_GE(hits, 50 * 16) << kind;  // every ray aimed inside a silhouette hits something
  }
}

TEST(EmbreeAcceleratorTest, EmptySceneHasNoHits) {
  const scene::Scene s;
  for (const char* kind : {"embree", "none"}) {
    const auto a = accel::make_accelerator(kind, s);
    scene::SurfaceHit hit;
    EXPECT_FALSE(a->intersect({{0, 0, 0}, {0, 0, 1}, 0}, 0, math::kInfinity, RayKind::camera, hit));
    EXPECT_EQ(a->stats().objects, 0u);
    EXPECT_EQ(a->stats().unbounded_objects, 0u);
    EXPECT_EQ(a->name(), kind);
  }
}

TEST(EmbreeAcceleratorTest, OnlyUnboundedObjects) {
  scene::Scene s;
  s.objects.push_back(make_object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -1)));
  const auto a = accel::make_accelerator("embree", s);
  scene::SurfaceHit hit;
  ASSERT_TRUE(a->intersect({{0, 0, 0}, {0, -2, 0}, 0}, 0, math::kInfinity, RayKind::camera, hit));
  EXPECT_DOUBLE_EQ(hit.t, 0.5);  // y = -1 reached at t = 0.5 with direction length 2
  EXPECT_EQ(a->stats().unbounded_objects, 1u);
}

TEST(EmbreeAcceleratorTest, StatsCountObjectsAndUnboundedOnes) {
  const scene::Scene s = random_scene(4, 40);
  for (const char* kind : {"embree", "none"}) {
    const auto a = accel::make_accelerator(kind, s);
    EXPECT_EQ(a->stats().objects, 42u);
    EXPECT_EQ(a->stats().unbounded_objects, 2u);  // the two planes
    EXPECT_GE(a->stats().build_seconds, 0.0);
  }
}

TEST(EmbreeAcceleratorTest, ConcurrentQueriesAgreeWithBruteForce) {
  const scene::Scene s = random_scene(21, 500);
  const auto embree = accel::make_accelerator("embree", s);
  const auto brute = accel::make_accelerator("none", s);
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      math::Pcg32 rng(100 + t);
      for (int i = 0; i < 5000; ++i) {
        const math::Ray ray{uniform_vec(rng, -15, 15), uniform_vec(rng, -1, 1), 0};
        scene::SurfaceHit ha, hb;
        const bool fa = embree->intersect(ray, 1e-6, math::kInfinity, RayKind::camera, ha);
        const bool fb = brute->intersect(ray, 1e-6, math::kInfinity, RayKind::camera, hb);
        if (fa != fb || (fa && (ha.object != hb.object || ha.t != hb.t))) ++mismatches[t];
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int m : mismatches) EXPECT_EQ(m, 0);
}

// An occlusion query answers "is anything hit in the window" for every back end: Embree's rtcOccluded1
// walk and the default (the nearest hit) agree with brute force's nearest hit on random rays and short
// windows (shadow rays end at their light), for every ray kind, and name an object the ray really hits.
TEST(AcceleratorTest, OccluderAgreesWithBruteForce) {
  const scene::Scene s = random_scene(33, 300);
  const auto brute = accel::make_accelerator("none", s);
  for (const char* kind : {"embree", "bvh", "octree", "grid", "list", "none"}) {
    const auto a = accel::make_accelerator(kind, s);
    math::Pcg32 rng(5);
    int blocked = 0, mismatches = 0;
    for (int i = 0; i < 4000; ++i) {
      const math::Ray ray{uniform_vec(rng, -12, 12), uniform_vec(rng, -1, 1), 0};
      const double t_max = i % 2 ? math::kInfinity : uniform(rng, 0.5, 20);
      bool hit;
      mismatches += !occluder_agrees(*a, *brute, ray, t_max, kKinds[i % 4], hit);
      blocked += hit;
    }
    EXPECT_EQ(mismatches, 0) << kind;
    EXPECT_GT(blocked, 1000) << kind;
    EXPECT_LT(blocked, 3000) << kind;
  }
}

TEST(MakeAcceleratorTest, UnknownKindThrows) {
  const scene::Scene s;
  EXPECT_THROW(accel::make_accelerator("kdtree", s), std::invalid_argument);
}

TEST(EmbreeAcceleratorTest, DegenerateRaysAndWindowsMatchBruteForce) {
  const scene::Scene s = random_scene(8, 100);
  const auto embree = accel::make_accelerator("embree", s);
  const auto brute = accel::make_accelerator("none", s);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const math::Ray toward{{0, 0, -20}, {0.01, 0.02, 1}, 0};
  expect_same_hit(*embree, *brute, toward, 5, 5, RayKind::camera);     // empty window
  expect_same_hit(*embree, *brute, toward, 9, 3, RayKind::camera);     // reversed window
  expect_same_hit(*embree, *brute, toward, nan, 50, RayKind::camera);  // NaN window
  expect_same_hit(*embree, *brute, {{0, 0, 0}, {0, 0, 0}, 0}, 0, math::kInfinity, RayKind::camera);
  expect_same_hit(*embree, *brute, {{nan, 0, 0}, {0, 0, 1}, 0}, 0, math::kInfinity, RayKind::camera);
  expect_same_hit(*embree, *brute, {{0, 0, 0}, {0, 0, nan}, 0}, 0, math::kInfinity, RayKind::camera);
}

TEST(EmbreeAcceleratorTest, HugeObjectsBeyondFloatRangeAreStillHit) {
  // A sphere of radius 1e20 (POV-Ray scenes use such "sky spheres") has bounds Embree cannot store.
  scene::Scene s = random_scene(12, 20);
  s.objects.push_back(make_object(std::make_shared<geometry::Sphere>(Vec3(0), 1e20)));
  const auto embree = accel::make_accelerator("embree", s);
  const auto brute = accel::make_accelerator("none", s);
  EXPECT_EQ(embree->stats().unbounded_objects, 3u);
  math::Pcg32 rng(3);
  for (int i = 0; i < 500; ++i) {
    const math::Ray ray{uniform_vec(rng, -15, 15), normalize(uniform_vec(rng, -1, 1)), 0};
    expect_same_hit(*embree, *brute, ray, 1e-6, math::kInfinity, RayKind::camera);
  }
  // Alone with a small sphere, the huge one is what a ray leaving the small one meets, at t = 1e20.
  scene::Scene alone;
  alone.objects = {s.objects.back(), make_object(std::make_shared<geometry::Sphere>(Vec3(0), 1))};
  const auto a = accel::make_accelerator("embree", alone);
  scene::SurfaceHit hit;
  ASSERT_TRUE(a->intersect({{0, 0, 0}, {0, 1, 0}, 0}, 2, math::kInfinity, RayKind::camera, hit));
  EXPECT_DOUBLE_EQ(hit.t, 1e20);
  EXPECT_EQ(hit.object, s.objects.back().get());
}
