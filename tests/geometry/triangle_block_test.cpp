// The single-precision triangle filter (triangle_block.hpp) against the double-precision test it stands in
// front of: it may keep triangles the ray misses, but must never drop one the double test hits within the
// window, nor give an entry beyond that hit. Rays aim at vertices, edges and interior points from near and
// far (grazing and edge-on too), over scales from 1e-5 to 1e5 and origins up to 1e6 triangle sizes away,
// with four and eight lanes per instruction.
#include "snell/geometry/triangle_block.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/geometry/triangle_kernel.hpp"
#include "snell/math/pcg32.hpp"

namespace {

using snell::geometry::intersect_triangle;
using snell::geometry::TriangleBlock;
using snell::geometry::TriangleHit;
using snell::geometry::TriangleRay;
using snell::math::Pcg32;
using snell::math::Ray;
using snell::math::Vec3;

double uniform(Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}
Vec3 uniform_vec(Pcg32& rng, double lo, double hi) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}

struct Trial {
  TriangleBlock block;
  Vec3 v[TriangleBlock::kSize][3];
};

/// Eight random triangles of size `scale` near `center`; some are slivers or nearly degenerate.
Trial random_block(Pcg32& rng, const Vec3& center, double scale) {
  Trial t;
  for (int l = 0; l < TriangleBlock::kSize; ++l) {
    const Vec3 c = center + uniform_vec(rng, -scale, scale);
    for (Vec3& p : t.v[l]) p = c + uniform_vec(rng, -scale, scale);
    if (l == 5) t.v[l][2] = t.v[l][0] + (t.v[l][1] - t.v[l][0]) * uniform(rng, 0, 1) + Vec3(1e-9 * scale);
    t.block.add(t.v[l][0], t.v[l][1], t.v[l][2]);
  }
  return t;
}

/// A point on triangle l: a vertex, an edge point or an interior point.
Vec3 target_on(Pcg32& rng, const Trial& t, int l) {
  const Vec3* v = t.v[l];
  switch (rng.next_uint() % 3) {
    case 0:
      return v[rng.next_uint() % 3];
    case 1: {
      const int k = static_cast<int>(rng.next_uint() % 3);
      return v[k] + (v[(k + 1) % 3] - v[k]) * uniform(rng, 0, 1);
    }
    default: {
      const double b1 = uniform(rng, 0, 1), b2 = uniform(rng, 0, 1 - b1);
      return v[0] + (v[1] - v[0]) * b1 + (v[2] - v[0]) * b2;
    }
  }
}

template <int L>
void check_never_drops_a_hit(uint64_t seed) {
  Pcg32 rng(seed);
  int double_hits = 0, dropped_misses = 0, clear_hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::pow(10.0, uniform(rng, -5, 5));
    const Vec3 center = uniform_vec(rng, -1, 1) * scale * std::pow(10.0, uniform(rng, 0, 3));
    const Trial t = random_block(rng, center, scale);
    const int aimed = static_cast<int>(rng.next_uint() % TriangleBlock::kSize);
    const Vec3 target = target_on(rng, t, aimed);
    Vec3 dir = uniform_vec(rng, -1, 1);
    if (trial % 7 == 0) {  // within the triangle's plane, or nearly: edge-on
      const Vec3 n = cross(t.v[aimed][1] - t.v[aimed][0], t.v[aimed][2] - t.v[aimed][0]);
      dir = t.v[aimed][1] - t.v[aimed][0] + n * (trial % 2 ? 0.0 : 1e-9 * uniform(rng, -1, 1));
    }
    if (trial % 11 == 0) dir[trial % 3] = 0;
    const double distance = scale * std::pow(10.0, uniform(rng, -2, 6));
    const Vec3 unit = normalize(dir);
    // Directions of any length: rays reach shapes in object space unnormalised.
    const Ray ray{target - unit * distance, unit * uniform(rng, 0.01, 100), 0};
    const double reach = distance / length(ray.direction);
    double t_min = trial % 3 == 0 ? 0.0 : uniform(rng, 0, 1) * reach;
    const double t_max = trial % 5 == 0 ? reach : INFINITY;
    // Windows that start right at the aimed hit, as a shadow ray's starts at the surface it leaves.
    if (trial % 13 == 1) t_min = reach * (1 + uniform(rng, -1, 1) * std::pow(2.0, -uniform(rng, 10, 50)));
    const TriangleRay triangle_ray(ray);
    float entry[TriangleBlock::kSize];
    const unsigned kept = triangle_ray.candidates<L>(t.block, snell::geometry::float_below(t_min),
                                                     snell::geometry::float_above(t_max), entry);
    // The error terms an owner computes once per ray from scales at least the block's own (the largest
    // over its blocks: TriangleScales) keep at least the same lanes.
    const TriangleRay::Lanes<L> lanes(triangle_ray);
    const auto grow = static_cast<float>(std::pow(10.0, uniform(rng, 0, 3)));
    float wide_entry[TriangleBlock::kSize];
    const unsigned kept_wide =
        lanes.candidates_among(t.block, (1u << t.block.count) - 1, snell::geometry::float_below(t_min),
                               snell::geometry::float_above(t_max), wide_entry,
                               lanes.errors(t.block.magnitude * grow, t.block.longest_edge * grow));
    ASSERT_EQ(kept_wide & kept, kept) << "trial " << trial;
    // The lanes called clear, which an occlusion query takes without the double test.
    TriangleBlock decisive = t.block;
    decisive.decisive = 0xff;
    const auto errors = lanes.errors(decisive.magnitude, decisive.longest_edge);
    const auto window = TriangleRay::Lanes<L>::window(snell::geometry::float_below(t_min),
                                                      snell::geometry::float_above(t_max), errors);
    unsigned clear = 0;
    float clear_entry[TriangleBlock::kSize];
    ASSERT_EQ(
        lanes.candidates_among(decisive, (1u << decisive.count) - 1, window, clear_entry, errors, clear),
        kept);
    for (int l = 0; l < TriangleBlock::kSize; ++l) {
      TriangleHit hit;
      const bool hits = intersect_triangle(t.v[l][0], t.v[l][1], t.v[l][2], ray, t_min, t_max, hit);
      if (clear >> l & 1) {
        ++clear_hits;
        ASSERT_TRUE(hits) << "trial " << trial << " lane " << l << " called clear";
      }
      if (!hits) {
        dropped_misses += !(kept >> l & 1);
        continue;
      }
      ++double_hits;
      ASSERT_TRUE(kept >> l & 1) << "trial " << trial << " lane " << l << " t " << hit.t;
      EXPECT_LE(entry[l], hit.t) << "trial " << trial << " lane " << l;
      EXPECT_LE(wide_entry[l], hit.t) << "trial " << trial << " lane " << l;
    }
  }
  EXPECT_GT(double_hits, 12000);
  // And clear hits are common enough to matter (about a quarter of these hits, many aimed at edges).
  EXPECT_GT(clear_hits, 2500);
  // And it is a filter: most triangles the ray misses are dropped.
  EXPECT_GT(dropped_misses, 20000 * 4);
}

TEST(TriangleBlockTest, FourLanesNeverDropAHit) {
  check_never_drops_a_hit<4>(11);
}

TEST(TriangleBlockTest, EightLanesNeverDropAHit) {
  check_never_drops_a_hit<8>(12);
}

TEST(TriangleBlockTest, UnusedLanesAreNeverKept) {
  TriangleBlock b;
  b.add({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  b.add({0, 0, 1}, {1, 0, 1}, {0, 1, 1});
  const TriangleRay ray(Ray{{0.2, 0.2, -1}, {0, 0, 1}, 0});
  float entry[TriangleBlock::kSize];
  EXPECT_EQ(ray.candidates<4>(b, 0, INFINITY, entry), 3u);
  EXPECT_EQ(ray.candidates<4>(b, 0, 1.5f, entry), 1u);  // the second lies at t = 2
  EXPECT_EQ(ray.candidates<8>(b, 2.5f, INFINITY, entry), 0u);
  EXPECT_EQ(b.count, 2u);
}

TEST(TriangleBlockTest, WhatFloatCannotHoldIsLeftToTheDoubleTest) {
  TriangleBlock huge;
  huge.add({1e35, 0, 0}, {0, 1e35, 0}, {0, 0, 1});
  float entry[TriangleBlock::kSize];
  EXPECT_EQ(TriangleRay(Ray{{5, 5, 5}, {1, 0, 0}, 0}).candidates<4>(huge, 0, INFINITY, entry), 1u);
  TriangleBlock small;
  small.add({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_FALSE(TriangleRay(Ray{{1e31, 0, 0}, {1, 0, 0}, 0}).usable());
  EXPECT_FALSE(TriangleRay(Ray{{0, 0, 0}, {0, 0, 0}, 0}).usable());
  EXPECT_EQ(TriangleRay(Ray{{0, 0, 0}, {0, 0, 0}, 0}).candidates<4>(small, 0, INFINITY, entry), 1u);
  EXPECT_EQ(TriangleRay(Ray{{0, 0, NAN}, {0, 0, 1}, 0}).candidates<4>(small, 0, INFINITY, entry), 1u);
}

}  // namespace
