// Lens sample points: inside the aperture disc (radius 1/2, as POV-Ray scales its sample grid) and spread
// evenly over it (Vogel's spiral gives each point an equal-area share).
#include "snell/scene/lens_samples.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/pcg32.hpp"

namespace snell::scene {
namespace {

TEST(LensSamples, StayInsideTheDisc) {
  math::Pcg32 rng(7);
  for (int n : {1, 7, 19, 120})
    for (int k = 0; k < n; ++k) {
      const auto p = lens_sample(k, n, rng.next_double() * 6.3, rng.next_double(), rng.next_double());
      EXPECT_LE(std::hypot(p.u, p.v), 0.5 + 1e-12);
    }
}

TEST(LensSamples, CoverTheDiscEvenly) {
  // 400 points: each quadrant and each of the inner and outer halves of the area gets about its share.
  const int n = 400;
  int quadrant[4] = {0, 0, 0, 0};
  int inner = 0;
  double mean_u = 0, mean_v = 0;
  for (int k = 0; k < n; ++k) {
    const auto p = lens_sample(k, n, 0.3, 0.5, 0.5);
    ++quadrant[(p.u >= 0 ? 1 : 0) + (p.v >= 0 ? 2 : 0)];
    if (std::hypot(p.u, p.v) < 0.5 * std::sqrt(0.5)) ++inner;
    mean_u += p.u / n;
    mean_v += p.v / n;
  }
  for (int q : quadrant) EXPECT_NEAR(q, n / 4, 10);
  EXPECT_NEAR(inner, n / 2, 2);
  EXPECT_NEAR(mean_u, 0, 0.01);
  EXPECT_NEAR(mean_v, 0, 0.01);
}

TEST(LensSamples, RotationTurnsThePattern) {
  const auto a = lens_sample(5, 10, 0, 0.5, 0.5);
  const auto b = lens_sample(5, 10, 3.14159265358979323846, 0.5, 0.5);
  EXPECT_NEAR(a.u, -b.u, 1e-12);
  EXPECT_NEAR(a.v, -b.v, 1e-12);
}

}  // namespace
}  // namespace snell::scene
