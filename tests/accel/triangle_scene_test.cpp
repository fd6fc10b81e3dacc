// Scenes of triangles, where the own BVH packs plain triangles into blocks filtered in single precision
// and the other structures test them without building a SurfaceHit: every accelerator must still return
// brute force's nearest hit (same object, t and point), with triangles placed by transforms, smooth ones,
// ray-kind flags, `bounded_by` and spheres among them; occlusion queries must agree; and all of it with
// the portable (four-lane) build as well as the fastest.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "accel_test_support.hpp"
#include "snell/geometry/triangle.hpp"
#include "snell/math/float_lanes.hpp"

using namespace snell;
using namespace snell::accel_test;
using math::Transform;
using math::Vec3;
using scene::RayKind;

namespace {

/// `count` small triangles in a 20-unit cube (some sharing edges, some smooth, some moved by a transform,
/// a few with bounded_by or large), plus spheres and a plane; ray-kind flags as in random_scene.
scene::Scene triangle_scene(uint64_t seed, int count) {
  math::Pcg32 rng(seed);
  scene::Scene s;
  for (int i = 0; i < count; ++i) {
    const Vec3 c = uniform_vec(rng, -10, 10);
    const double size = i % 50 == 0 ? 8 : uniform(rng, 0.2, 1.5);
    Vec3 v[3];
    for (Vec3& p : v) p = c + uniform_vec(rng, -size, size);
    std::shared_ptr<scene::Object> o;
    if (i % 7 == 0) {
      o = make_object(std::make_shared<geometry::Triangle>(
          v[0], uniform_vec(rng, -1, 1), v[1], uniform_vec(rng, -1, 1), v[2], uniform_vec(rng, -1, 1)));
    } else if (i % 5 == 0) {
      const Transform t = Transform::translate(uniform_vec(rng, -2, 2)) *
                          Transform::rotate_xyz_degrees(uniform_vec(rng, 0, 360)) *
                          Transform::scale(uniform_vec(rng, 0.5, 2));
      o = make_object(std::make_shared<geometry::Triangle>(v[0] - c, v[1] - c, v[2] - c),
                      Transform::translate(c) * t);
    } else {
      o = make_object(std::make_shared<geometry::Triangle>(v[0], v[1], v[2]));
    }
    if (i % 31 == 0) o->bounded_by = math::Bounds3(c - Vec3(0.3), c + Vec3(0.5));
    o->flags.no_shadow = rng.next_double() < 0.2;
    o->flags.no_image = rng.next_double() < 0.2;
    o->flags.no_reflection = rng.next_double() < 0.2;
    o->flags.inverse = rng.next_double() < 0.1;
    s.objects.push_back(o);
    // Every fourth triangle gets a neighbour across an edge: rays through the edge hit both at one t.
    if (i % 4 == 0)
      s.objects.push_back(make_object(std::make_shared<geometry::Triangle>(v[1], v[0], c * 2 - v[2])));
  }
  const scene::Scene spheres = random_scene(seed + 1, count / 10);
  s.objects.insert(s.objects.end(), spheres.objects.begin(), spheres.objects.end());
  return s;
}

class TriangleSceneTest : public testing::TestWithParam<std::string> {
 protected:
  void TearDown() override { math::lanes::use_portable_lanes(false); }
};

TEST_P(TriangleSceneTest, NearestHitMatchesBruteForce) {
  for (const bool portable : {false, true}) {
    math::lanes::use_portable_lanes(portable);
    for (uint64_t seed : {1u, 2u}) {
      const scene::Scene s = triangle_scene(seed, 3000);
      const auto tested = accel::make_accelerator(GetParam(), s);
      const auto brute = accel::make_accelerator("none", s);
      math::Pcg32 rng(seed * 17);
      const int hits = compare_random_rays(*tested, *brute, rng, 3000, 25, true);
      if (HasFatalFailure()) return;
      EXPECT_GT(hits, 1000) << "scene too sparse to test anything";
    }
  }
}

TEST_P(TriangleSceneTest, HitsAreBuiltAsObjectIntersectBuildsThem) {
  const scene::Scene s = triangle_scene(5, 2000);
  const auto tested = accel::make_accelerator(GetParam(), s);
  const auto brute = accel::make_accelerator("none", s);
  math::Pcg32 rng(8);
  for (int i = 0; i < 2000; ++i) {
    const math::Ray ray{uniform_vec(rng, -15, 15), normalize(uniform_vec(rng, -1, 1)), 0};
    scene::SurfaceHit a, b;
    if (!brute->intersect(ray, 1e-6, math::kInfinity, RayKind::camera, b)) continue;
    ASSERT_TRUE(tested->intersect(ray, 1e-6, math::kInfinity, RayKind::camera, a));
    ASSERT_EQ(a.object, b.object);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a.normal[k], b.normal[k]);
      EXPECT_EQ(a.shading_normal[k], b.shading_normal[k]);
    }
    EXPECT_EQ(a.uv.u, b.uv.u);
    EXPECT_EQ(a.uv.v, b.uv.v);
    EXPECT_EQ(a.solid, b.solid);
  }
}

TEST_P(TriangleSceneTest, OccluderAgreesWithBruteForce) {
  for (const bool portable : {false, true}) {
    math::lanes::use_portable_lanes(portable);
    const scene::Scene s = triangle_scene(9, 3000);
    const auto tested = accel::make_accelerator(GetParam(), s);
    const auto brute = accel::make_accelerator("none", s);
    math::Pcg32 rng(4);
    int blocked = 0, mismatches = 0;
    for (int i = 0; i < 3000; ++i) {
      const math::Ray ray{uniform_vec(rng, -12, 12), uniform_vec(rng, -1, 1), 0};
      const double t_max = i % 2 ? math::kInfinity : uniform(rng, 0.5, 10);
      bool hit;
      mismatches += !occluder_agrees(*tested, *brute, ray, t_max, kKinds[i % 4], hit);
      blocked += hit;
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(blocked, 500);
    EXPECT_LT(blocked, 2900);
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, TriangleSceneTest, testing::Values("embree", "bvh", "octree", "grid", "list"),
                         [](const auto& info) { return info.param; });

}  // namespace
