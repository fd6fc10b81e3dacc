// The single-precision four-box test of the BVH (float_slabs.hpp) against an exact reference: it may keep
// boxes the ray misses, but must never drop one the exact ray meets, nor report an entry beyond the exact
// one. Rays graze the boxes (through a corner, an edge or a face point), over scales from 1e-6 to 1e6 and
// origins up to 1e6 away from the boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "snell/geometry/float_slabs.hpp"
#include "snell/geometry/ray_box.hpp"
#include "snell/math/pcg32.hpp"

namespace {

using snell::geometry::FloatBox;
using snell::geometry::FloatSlabs;
using snell::math::Pcg32;
using snell::math::Ray;
using snell::math::Vec3;

double uniform(Pcg32& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.next_double();
}

/// Ray-box interval in long double (64-bit significand), from the float corners: far more precise than
/// the float test's slack, so a box it says is hit must be kept by the float test.
bool exact_overlap(const Ray& ray, const FloatBox& box, double t_min, double t_max, long double& entry) {
  long double t0 = t_min, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    const long double o = ray.origin[a], d = ray.direction[a];
    if (d == 0) {
      if (o < box.lo[a] || o > box.hi[a]) return false;
      continue;
    }
    long double tn = (box.lo[a] - o) / d, tf = (box.hi[a] - o) / d;
    if (tn > tf) std::swap(tn, tf);
    t0 = std::max(t0, tn);
    t1 = std::min(t1, tf);
  }
  entry = t0;
  return t0 <= t1;
}

struct alignas(16) FourBoxes {
  float planes[6][4];  // rows 0-2 lo, 3-5 hi
  void set(int k, const FloatBox& b) {
    for (int a = 0; a < 3; ++a) {
      planes[a][k] = b.lo[a];
      planes[3 + a][k] = b.hi[a];
    }
  }
};

/// A random box of size `scale` near `center`, and a point on its surface: a corner, an edge point or a
/// face point (grazing rays are aimed there).
FloatBox random_box(Pcg32& rng, const Vec3& center, double scale, Vec3& surface_point) {
  FloatBox b;
  for (int a = 0; a < 3; ++a) {
    const double lo = center[a] + uniform(rng, -scale, 0), hi = center[a] + uniform(rng, 0, scale);
    b.lo[a] = FloatSlabs::round_down(lo);
    b.hi[a] = FloatSlabs::round_up(hi);
  }
  const int free_axes = static_cast<int>(rng.next_uint() % 3);  // 0: corner, 1: edge, 2: face
  for (int a = 0; a < 3; ++a) {
    const bool on_plane = a >= free_axes;
    const double lo = b.lo[a], hi = b.hi[a];
    surface_point[a] = on_plane ? (rng.next_uint() % 2 ? lo : hi) : uniform(rng, lo, hi);
  }
  return b;
}

TEST(FloatSlabsTest, NeverDropsABoxTheExactRayMeets) {
  Pcg32 rng(2024);
  int exact_hits = 0, kept = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::pow(10.0, uniform(rng, -6, 6));
    const Vec3 center{uniform(rng, -1, 1) * scale * 10, uniform(rng, -1, 1) * scale * 10,
                      uniform(rng, -1, 1) * scale * 10};
    FourBoxes boxes;
    FloatBox box[4];
    Vec3 target[4];
    for (int k = 0; k < 4; ++k) {
      box[k] = random_box(rng, center, scale, target[k]);
      boxes.set(k, box[k]);
    }
    // Aim at box 0's surface point from a distance of up to 1e6 box sizes; some directions have a zero or
    // tiny component (rays parallel to a slab).
    Vec3 dir{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
    const int flat_axis = static_cast<int>(rng.next_uint() % 6);
    if (flat_axis < 3) dir[flat_axis] = trial % 2 ? 0.0 : 1e-20;
    dir = normalize(dir);
    const double distance = scale * std::pow(10.0, uniform(rng, -3, 6));
    const Ray ray{target[0] - dir * distance, dir, 0};
    const double t_min = trial % 3 == 0 ? 0.0 : 1e-6 * distance;
    const double t_max = trial % 5 == 0 ? distance : INFINITY;

    const FloatSlabs slabs(ray);
    ASSERT_TRUE(slabs.usable());
    float entry[4];
    const int mask =
        slabs.test(boxes.planes, FloatSlabs::round_down(t_min), FloatSlabs::round_up(t_max), entry);
    for (int k = 0; k < 4; ++k) {
      long double exact_entry;
      if (!exact_overlap(ray, box[k], t_min, t_max, exact_entry)) continue;
      ++exact_hits;
      ASSERT_TRUE(mask & (1 << k)) << "trial " << trial << " box " << k;
      EXPECT_LE(static_cast<long double>(entry[k]), exact_entry) << "trial " << trial << " box " << k;
      ++kept;
    }
  }
  // Most rays are aimed at a box, so the check is not empty.
  EXPECT_GT(exact_hits, 15000);
  EXPECT_EQ(kept, exact_hits);
}

TEST(FloatSlabsTest, TheEmptySlotIsNeverEntered) {
  Pcg32 rng(7);
  FourBoxes boxes;
  for (int k = 0; k < 4; ++k) boxes.set(k, FloatBox::nothing());
  for (int trial = 0; trial < 1000; ++trial) {
    Vec3 dir{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
    if (trial % 4 == 0) dir[trial % 3] = 0;
    const FloatSlabs slabs(Ray{{uniform(rng, -1e3, 1e3), 0, 0}, normalize(dir), 0});
    float entry[4];
    EXPECT_EQ(slabs.test(boxes.planes, 0.0f, INFINITY, entry), 0);
  }
}

TEST(FloatSlabsTest, RaysFloatCannotHoldAreLeftToTheDoubleTest) {
  EXPECT_TRUE(FloatSlabs(Ray{{1e20, 0, 0}, {1, 0, 0}, 0}).usable());
  EXPECT_FALSE(FloatSlabs(Ray{{1e31, 0, 0}, {1, 0, 0}, 0}).usable());
  EXPECT_FALSE(FloatSlabs(Ray{{0, 0, 0}, {1, 1e-35, 0}, 0}).usable());
  EXPECT_TRUE(FloatSlabs(Ray{{0, 0, 0}, {1, 0, -0.0}, 0}).usable());
}

TEST(FloatSlabsTest, BracketingRoundsBothWaysAsTheSeparateRoundings) {
  // float_bracket (the walk's setup) must give float_below and float_above exactly: floats themselves,
  // halfway cases, zero and values around the smallest normals.
  Pcg32 rng(3);
  std::vector<double> values = {0.0,    -0.0,    1.0,           -1.0,          0.1,
                                -0.1,   1e-40,   -1e-40,        1e30,          -1e30,
                                3.4e38, -3.4e38, 1.0 + 0x1p-24, 1.0 - 0x1p-25, -(1.0 + 0x1p-24)};
  for (int i = 0; i < 10000; ++i) {
    const double v = uniform(rng, -1, 1) * std::pow(10.0, uniform(rng, -40, 38));
    values.push_back(v);
    values.push_back(static_cast<float>(v));
  }
  for (const double v : values) {
    float below, above;
    snell::geometry::float_bracket(v, below, above);
    EXPECT_EQ(below, snell::geometry::float_below(v)) << v;
    EXPECT_EQ(above, snell::geometry::float_above(v)) << v;
    EXPECT_LE(static_cast<double>(below), v);
    EXPECT_GE(static_cast<double>(above), v);
  }
}

}  // namespace
