// Embree must find exactly the hit that brute force finds (same object, t, point) for every ray: it only
// changes which objects get tested, never how.
#include "snell/accel/embree_accelerator.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

#include "scene_builder.hpp"
#include "snell/accel/brute_force.hpp"

namespace snell::accel {
namespace {

using math::Ray;
using math::Vec3;
using scene::RayKind;
using testing::random_scene;
using testing::RandomSceneOptions;
using testing::uniform;
using testing::uniform_vec;
using testing::unit_vec;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr RayKind kKinds[] = {RayKind::camera, RayKind::reflection, RayKind::refraction, RayKind::shadow};

/// Counts rays where the two accelerators disagree (and reports the first few).
struct Comparison {
  int rays = 0;
  int hits = 0;
  int mismatches = 0;

  void compare(const Accelerator& a, const Accelerator& b, const Ray& ray, double t_min, double t_max,
               RayKind kind) {
    scene::SurfaceHit ha, hb;
    const bool fa = a.intersect(ray, t_min, t_max, kind, ha);
    const bool fb = b.intersect(ray, t_min, t_max, kind, hb);
    ++rays;
    hits += fb;
    const bool same = fa == fb && (!fa || (ha.t == hb.t && ha.object == hb.object && ha.point == hb.point));
    if (same) return;
    if (++mismatches <= 5) {
      ADD_FAILURE() << a.name() << " vs " << b.name() << ": found " << fa << "/" << fb << " t " << ha.t << "/"
                    << hb.t << " for ray o=(" << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z
                    << ") d=(" << ray.direction.x << "," << ray.direction.y << "," << ray.direction.z
                    << ") window (" << t_min << "," << t_max << ")";
    }
  }
};

/// Random rays from inside and around the scene, with directions of random length (shapes see
/// non-unit directions anyway, and t must stay the caller's parameter).
Ray random_ray(math::Pcg32& rng, const RandomSceneOptions& opt) {
  const Vec3 o = opt.center + uniform_vec(rng, -1.5 * opt.extent, 1.5 * opt.extent);
  return {o, unit_vec(rng) * uniform(rng, 0.2, 5)};
}

TEST(EmbreeAccelerator, MatchesBruteForceOnRandomScenes) {
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    const RandomSceneOptions opt;
    const scene::Scene s = random_scene(seed, opt);
    const EmbreeAccelerator embree(s);
    const BruteForce brute(s);
    math::Pcg32 rng(seed, 77);
    Comparison c;
    for (int i = 0; i < 4000; ++i)
      c.compare(embree, brute, random_ray(rng, opt), 1e-6, kInf, RayKind::camera);
    EXPECT_EQ(c.mismatches, 0) << "seed " << seed;
    // The test means something only if many rays hit (and many miss).
    EXPECT_GT(c.hits, c.rays / 4);
    EXPECT_LT(c.hits, c.rays);
  }
}

TEST(EmbreeAccelerator, MatchesBruteForceWithinTWindows) {
  const RandomSceneOptions opt;
  const scene::Scene s = random_scene(11, opt);
  const EmbreeAccelerator embree(s);
  const BruteForce brute(s);
  math::Pcg32 rng(5);
  Comparison c;
  for (int i = 0; i < 6000; ++i) {
    const Ray ray = random_ray(rng, opt);
    // Windows that start behind the origin, end before far objects, or are empty.
    const double t_min = uniform(rng, -3, 6);
    const double t_max = i % 3 == 0 ? kInf : t_min + uniform(rng, -0.5, 8);
    c.compare(embree, brute, ray, t_min, t_max, RayKind::reflection);
  }
  EXPECT_EQ(c.mismatches, 0);
  EXPECT_GT(c.hits, c.rays / 10);
}

TEST(EmbreeAccelerator, HonoursObjectFlagsPerRayKind) {
  RandomSceneOptions opt;
  opt.random_flags = true;
  const scene::Scene s = random_scene(21, opt);
  const EmbreeAccelerator embree(s);
  const BruteForce brute(s);
  math::Pcg32 rng(9);
  for (RayKind kind : kKinds) {
    Comparison c;
    int invisible_hits = 0;
    for (int i = 0; i < 3000; ++i) {
      const Ray ray = random_ray(rng, opt);
      c.compare(embree, brute, ray, 1e-6, kInf, kind);
      scene::SurfaceHit h;
      if (embree.intersect(ray, 1e-6, kInf, kind, h) && !h.object->visible_to(kind)) ++invisible_hits;
    }
    EXPECT_EQ(c.mismatches, 0) << "kind " << static_cast<int>(kind);
    EXPECT_EQ(invisible_hits, 0);
  }
}

TEST(EmbreeAccelerator, NoShadowObjectIsInvisibleToShadowRaysOnly) {
  // One sphere in front of another, the front one no_shadow (POV-Ray's object modifier).
  scene::Scene s;
  s.objects.push_back(testing::make_object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 5), 1)));
  s.objects.push_back(testing::make_object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 10), 1)));
  const_cast<scene::Object&>(*s.objects[0]).flags.no_shadow = true;
  const EmbreeAccelerator embree(s);
  const Ray ray{Vec3(0), Vec3(0, 0, 1)};
  scene::SurfaceHit h;
  ASSERT_TRUE(embree.intersect(ray, 0, kInf, RayKind::camera, h));
  EXPECT_DOUBLE_EQ(h.t, 4);
  EXPECT_EQ(h.object, s.objects[0].get());
  ASSERT_TRUE(embree.intersect(ray, 0, kInf, RayKind::shadow, h));
  EXPECT_DOUBLE_EQ(h.t, 9);
  EXPECT_EQ(h.object, s.objects[1].get());
  EXPECT_EQ(h.point, Vec3(0, 0, 9));
}

TEST(EmbreeAccelerator, FindsGrazingHitsOnBoundingBoxFaces) {
  // Rays that touch a sphere just inside its extreme points run within 1e-9 r of a face of its bounding
  // box, far below float precision: only the box padding lets Embree still call the object.
  for (const double scale : {1e-3, 1.0, 1e4}) {
    RandomSceneOptions opt;
    opt.extent = 10 * scale;
    opt.center = Vec3(3, -2, 7) * scale;
    opt.ellipsoids = 0;
    opt.plane = false;
    const scene::Scene s = random_scene(31, opt);
    const EmbreeAccelerator embree(s);
    const BruteForce brute(s);
    math::Pcg32 rng(3);
    Comparison c;
    for (const auto& o : s.objects) {
      const auto& sphere = static_cast<const geometry::Sphere&>(*o->shape);
      for (int axis = 0; axis < 3; ++axis) {
        for (const double side : {-1.0, 1.0}) {
          Vec3 target = sphere.center();
          target[axis] += side * sphere.radius() * (1 - 1e-9);
          Vec3 dir = unit_vec(rng);
          dir[axis] = 0;  // parallel to the box face
          const Vec3 origin = target - dir * uniform(rng, 0.5, 3) * opt.extent;
          c.compare(embree, brute, Ray{origin, dir}, 0, kInf, RayKind::camera);
        }
      }
    }
    EXPECT_EQ(c.mismatches, 0) << "scale " << scale;
    EXPECT_GT(c.hits, c.rays / 2);
  }
}

TEST(EmbreeAccelerator, DirectionsOutsideFloatRangeStillHit) {
  // Directions that underflow or overflow a float cannot go to Embree; t stays the caller's parameter,
  // so the sphere at z = 5, radius 1 is met at t = 4 / |d|.
  scene::Scene s;
  s.objects.push_back(testing::make_object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 5), 1)));
  const EmbreeAccelerator embree(s);
  for (const double len : {1e-50, 1e40}) {
    scene::SurfaceHit h;
    ASSERT_TRUE(embree.intersect(Ray{Vec3(0), Vec3(0, 0, len)}, 0, kInf, RayKind::camera, h)) << len;
    EXPECT_NEAR(h.t * len, 4, 1e-12) << len;
  }
}

TEST(EmbreeAccelerator, ObjectsBeyondFloatRangeAreTestedDirectly) {
  // A sphere scaled past float range cannot be an Embree box; it must still be found, and the ordinary
  // objects beside it must still match brute force.
  scene::Scene s = random_scene(51);
  s.objects.push_back(testing::make_object(
      std::make_shared<geometry::Sphere>(Vec3(0), 1),
      math::Transform::translate(Vec3(0, 0, 5e40)) * math::Transform::scale(Vec3(1e39))));
  const EmbreeAccelerator embree(s);
  const BruteForce brute(s);
  EXPECT_EQ(embree.stats().unbounded_objects, 2u);
  scene::SurfaceHit h;
  ASSERT_TRUE(embree.intersect(Ray{Vec3(0, 0, 1e41), Vec3(0, 0, -1)}, 0, kInf, RayKind::camera, h));
  EXPECT_EQ(h.object, s.objects.back().get());
  EXPECT_NEAR(h.t / 4.9e40, 1, 1e-12);  // from z = 1e41 down to the top of the sphere, 5.1e40
  math::Pcg32 rng(4);
  Comparison c;
  for (int i = 0; i < 2000; ++i) c.compare(embree, brute, random_ray(rng, {}), 1e-6, kInf, RayKind::camera);
  EXPECT_EQ(c.mismatches, 0);
}

TEST(EmbreeAccelerator, EmptySceneHasNoHits) {
  const scene::Scene s;
  const EmbreeAccelerator embree(s);
  scene::SurfaceHit h;
  EXPECT_FALSE(embree.intersect(Ray{Vec3(0), Vec3(0, 0, 1)}, 0, kInf, RayKind::camera, h));
  EXPECT_EQ(embree.stats().objects, 0u);
  EXPECT_EQ(embree.stats().unbounded_objects, 0u);
}

TEST(EmbreeAccelerator, PlaneOnlySceneIsTestedDirectly) {
  scene::Scene s;
  s.objects.push_back(testing::make_object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), -1)));
  const EmbreeAccelerator embree(s);
  EXPECT_EQ(embree.stats().objects, 1u);
  EXPECT_EQ(embree.stats().unbounded_objects, 1u);
  scene::SurfaceHit h;
  ASSERT_TRUE(embree.intersect(Ray{Vec3(0, 1, 0), Vec3(0, -2, 0)}, 0, kInf, RayKind::camera, h));
  EXPECT_DOUBLE_EQ(h.t, 1);  // y = 1 - 2t reaches -1 at t = 1
  EXPECT_FALSE(embree.intersect(Ray{Vec3(0, 1, 0), Vec3(0, -2, 0)}, 0, 0.9, RayKind::camera, h));
}

TEST(EmbreeAccelerator, StatsCountObjectsAndUnbounded) {
  const scene::Scene s = random_scene(2);
  const EmbreeAccelerator embree(s);
  EXPECT_EQ(embree.stats().objects, s.objects.size());
  EXPECT_EQ(embree.stats().unbounded_objects, 1u);
  EXPECT_GE(embree.stats().build_seconds, 0);
  EXPECT_EQ(embree.name(), "embree");
}

TEST(EmbreeAccelerator, ConcurrentQueriesMatchBruteForce) {
  const RandomSceneOptions opt;
  const scene::Scene s = random_scene(41, opt);
  const EmbreeAccelerator embree(s);
  const BruteForce brute(s);
  std::atomic<int> mismatches{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      math::Pcg32 rng(100 + t);
      for (int i = 0; i < 3000; ++i) {
        const Ray ray = random_ray(rng, opt);
        scene::SurfaceHit ha, hb;
        const bool fa = embree.intersect(ray, 1e-6, kInf, RayKind::camera, ha);
        const bool fb = brute.intersect(ray, 1e-6, kInf, RayKind::camera, hb);
        if (fa != fb || (fa && (ha.t != hb.t || ha.object != hb.object))) ++mismatches;
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(MakeAccelerator, KnowsEmbreeAndNone) {
  const scene::Scene s = random_scene(3);
  EXPECT_EQ(make_accelerator("embree", s)->name(), "embree");
  EXPECT_EQ(make_accelerator("none", s)->name(), "none");
  EXPECT_EQ(make_accelerator("none", s)->stats().unbounded_objects, 1u);
  EXPECT_THROW(make_accelerator("kd-tree", s), std::invalid_argument);
}

}  // namespace
}  // namespace snell::accel
