#pragma once
// Property checks every shape must pass, with rays whose answers follow from the shape's definition alone:
// hits lie in the bounds, come sorted, `intersect` agrees with the first of `all_hits` and with `crosses`,
// scaling the direction divides t, normals are usable and (for solids) point from inside to outside.
#include <gtest/gtest.h>

#include <cmath>

#include "snell/geometry/shape.hpp"
#include "snell/math/pcg32.hpp"

namespace snell::geometry::shape_checks {

inline Vec3 random_unit(math::Pcg32& rng) {
  const double z = 2 * rng.next_double() - 1, phi = 2 * math::kPi * rng.next_double();
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

inline void expect_near(const Vec3& a, const Vec3& b, double eps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

/// Random rays aimed at random points around the shape, from outside its bounds.
/// `solid`: check outward normals against inside() just off the surface.
inline void check_random_rays(const Shape& shape, bool solid, int count = 2000, double eps = 1e-6) {
  const Bounds3 b = shape.bounds();
  ASSERT_TRUE(b.is_finite());
  const Vec3 c = b.center();
  const double r = 0.5 * length(b.extent()) + 1e-9;
  math::Pcg32 rng(42);
  int hit_rays = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3 origin = c + 3 * r * random_unit(rng);
    const Vec3 target = c + 0.8 * r * rng.next_double() * random_unit(rng);
    const double scale = 0.1 + 5 * rng.next_double();  // non-unit directions
    const Ray ray{origin, scale * normalize(target - origin), 0};
    HitList hits;
    shape.all_hits(ray, 1e-9, math::kInfinity, hits);
    LocalHit first;
    const bool any = shape.intersect(ray, 1e-9, math::kInfinity, first);
    ASSERT_EQ(any, !hits.empty());
    // crosses (shadow rays) agrees with intersect, also in windows that end just short of the first hit.
    EXPECT_EQ(shape.crosses(ray, 1e-9, math::kInfinity), any);
    if (!any) continue;
    EXPECT_FALSE(shape.crosses(ray, 1e-9, first.t * (1 - 1e-6)));
    EXPECT_TRUE(shape.crosses(ray, 1e-9, first.t * (1 + 1e-6)));
    ++hit_rays;
    EXPECT_DOUBLE_EQ(first.t, hits[0].t);
    for (size_t k = 0; k < hits.size(); ++k) {
      const LocalHit& h = hits[k];
      if (k > 0) {
        EXPECT_LE(hits[k - 1].t, h.t);
      }
      const Vec3 p = ray.at(h.t);
      const Vec3 slack(eps * (1 + r));
      EXPECT_TRUE(Bounds3(b.lo - slack, b.hi + slack).contains(p)) << "hit outside bounds";
      ASSERT_GT(length(h.normal), 0);
      EXPECT_TRUE(is_finite(h.normal));
      if (solid) {
        const Vec3 n = normalize(h.normal);
        const double step = 1e-5 * r;
        EXPECT_FALSE(shape.inside(p + step * n)) << "normal not outward at hit " << k;
      }
    }
    // The same ray with a scaled direction hits the same points at t / factor.
    const double factor = 2.5;
    LocalHit scaled;
    ASSERT_TRUE(shape.intersect(Ray{origin, factor * ray.direction, 0}, 1e-9, math::kInfinity, scaled));
    EXPECT_NEAR(scaled.t * factor, first.t, 1e-7 * first.t);
  }
  EXPECT_GT(hit_rays, count / 20) << "too few rays hit: the test is not testing";
  // A shape that says its inside lies within its bounds (CSG then answers inside() by a box test there):
  // no point outside the bounds is inside, however near; sampled on shells just outside the box.
  if (shape.inside_within_bounds()) {
    for (int i = 0; i < count; ++i) {
      const Vec3 u = random_unit(rng);
      Vec3 p = c + (0.5 + rng.next_double()) * r * u;
      for (int a = 0; a < 3; ++a)  // pull each coordinate onto the box face just outside, half the time
        if (rng.next_double() < 0.5 && (p[a] < b.lo[a] || p[a] > b.hi[a]))
          p[a] = p[a] < b.lo[a] ? b.lo[a] - 1e-9 * (1 + r) : b.hi[a] + 1e-9 * (1 + r);
      if (b.contains(p)) continue;
      EXPECT_FALSE(shape.inside(p)) << "inside() outside the bounds at " << p.x << ' ' << p.y << ' ' << p.z;
    }
  }
}

}  // namespace snell::geometry::shape_checks
