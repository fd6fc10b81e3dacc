// Cases that need Embree's float traversal to hand every double-precision hit to our callback: rays
// grazing the faces of bounding boxes (only the box padding saves them), directions float cannot hold,
// and object flags checked against analytic answers rather than against brute force.
#include <gtest/gtest.h>

#include <limits>
#include <memory>

#include "snell/accel/accelerator.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/pcg32.hpp"

namespace snell::accel {
namespace {

using math::Ray;
using math::Vec3;
using scene::RayKind;

constexpr double kInf = std::numeric_limits<double>::infinity();

double uniform(math::Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}

std::shared_ptr<scene::Object> sphere(const Vec3& c, double r) {
  auto o = std::make_shared<scene::Object>();
  o->shape = std::make_shared<geometry::Sphere>(c, r);
  return o;
}

TEST(EmbreePrecision, GrazingHitsOnBoundingBoxFacesMatchBruteForce) {
  // Each ray touches a sphere 1e-9 r inside one of its six extreme points, running parallel to that face
  // of its bounding box: far below float precision, so Embree calls the sphere only if its box is padded.
  // Checked at three scene scales, since the padding is relative.
  for (const double scale : {1e-3, 1.0, 1e4}) {
    math::Pcg32 rng(31);
    scene::Scene s;
    const Vec3 center = Vec3(3, -2, 7) * scale;
    for (int i = 0; i < 100; ++i) {
      const Vec3 c =
          center + Vec3(uniform(rng, -10, 10), uniform(rng, -10, 10), uniform(rng, -10, 10)) * scale;
      s.objects.push_back(sphere(c, uniform(rng, 0.05, 0.8) * scale));
    }
    const auto embree = make_accelerator("embree", s);
    const auto brute = make_accelerator("none", s);
    int rays = 0, hits = 0, mismatches = 0;
    for (const auto& o : s.objects) {
      const auto& sph = static_cast<const geometry::Sphere&>(*o->shape);
      for (int axis = 0; axis < 3; ++axis) {
        for (const double side : {-1.0, 1.0}) {
          Vec3 target = sph.center();
          target[axis] += side * sph.radius() * (1 - 1e-9);
          Vec3 dir(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
          dir[axis] = 0;  // parallel to the box face
          const Ray ray{target - dir * uniform(rng, 5, 30) * scale, dir};
          scene::SurfaceHit he, hb;
          const bool fe = embree->intersect(ray, 0, kInf, RayKind::camera, he);
          const bool fb = brute->intersect(ray, 0, kInf, RayKind::camera, hb);
          ++rays;
          hits += fb;
          if (fe != fb || (fb && (he.t != hb.t || he.object != hb.object || he.point != hb.point)))
            ++mismatches;
        }
      }
    }
    EXPECT_EQ(mismatches, 0) << "scale " << scale;
    EXPECT_GT(hits, rays / 2) << "scale " << scale;  // most rays must really hit for the test to mean much
  }
}

TEST(EmbreePrecision, DirectionsOutsideFloatRangeStillHit) {
  // A direction that underflows or overflows a float cannot reach Embree as is; t stays the caller's
  // parameter, so the sphere at z = 5, radius 1 is met at t = 4 / |d|.
  scene::Scene s;
  s.objects.push_back(sphere({0, 0, 5}, 1));
  const auto embree = make_accelerator("embree", s);
  for (const double len : {1e-50, 1e-30, 1e40}) {
    scene::SurfaceHit h;
    ASSERT_TRUE(embree->intersect(Ray{Vec3(0), Vec3(0, 0, len)}, 0, kInf, RayKind::camera, h)) << len;
    EXPECT_NEAR(h.t * len, 4, 1e-12) << len;
    EXPECT_NEAR(h.point.z, 4, 1e-12);
  }
}

TEST(EmbreePrecision, NoShadowObjectIsSkippedByShadowRaysOnly) {
  // POV-Ray's no_shadow: the object is seen by camera rays but casts no shadow.
  scene::Scene s;
  s.objects.push_back(sphere({0, 0, 5}, 1));
  s.objects.push_back(sphere({0, 0, 10}, 1));
  const_cast<scene::Object&>(*s.objects[0]).flags.no_shadow = true;
  const auto embree = make_accelerator("embree", s);
  const Ray ray{Vec3(0), Vec3(0, 0, 1)};
  scene::SurfaceHit h;
  ASSERT_TRUE(embree->intersect(ray, 0, kInf, RayKind::camera, h));
  EXPECT_DOUBLE_EQ(h.t, 4);
  EXPECT_EQ(h.object, s.objects[0].get());
  ASSERT_TRUE(embree->intersect(ray, 0, kInf, RayKind::shadow, h));
  EXPECT_DOUBLE_EQ(h.t, 9);
  EXPECT_EQ(h.object, s.objects[1].get());
  // The shadow ray's window ending before the far sphere finds nothing at all.
  EXPECT_FALSE(embree->intersect(ray, 0, 8.5, RayKind::shadow, h));
}

}  // namespace
}  // namespace snell::accel
