// Lens sample points: inside the aperture disc (radius 1/2, as POV-Ray scales its sample grid) and spread
// evenly over it, in full and in the first few (focal blur may stop after any batch).
#include "snell/scene/lens_samples.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/pcg32.hpp"

namespace snell::scene {
namespace {

TEST(LensSamples, StayInsideTheDisc) {
  math::Pcg32 rng(7);
  for (int k = 0; k < 500; ++k) {
    const auto p = lens_sample(k, rng.next_double(), rng.next_double());
    EXPECT_LE(std::hypot(p.u, p.v), 0.5 + 1e-12);
  }
}

void expect_even(int n, double shift_u, double shift_v, int quadrant_tol, int inner_tol) {
  // Each quadrant gets about a quarter; the inner disc of half the area gets about half.
  int quadrant[4] = {0, 0, 0, 0};
  int inner = 0;
  for (int k = 0; k < n; ++k) {
    const auto p = lens_sample(k, shift_u, shift_v);
    ++quadrant[(p.u >= 0 ? 1 : 0) + (p.v >= 0 ? 2 : 0)];
    if (std::hypot(p.u, p.v) < 0.5 * std::sqrt(0.5)) ++inner;
  }
  for (int q : quadrant) EXPECT_NEAR(q, n / 4.0, quadrant_tol) << n << " samples";
  EXPECT_NEAR(inner, n / 2.0, inner_tol) << n << " samples";
}

TEST(LensSamples, CoverTheDiscEvenly) {
  expect_even(400, 0.3, 0.7, 4, 2);
  expect_even(400, 0.91, 0.05, 4, 2);
}

TEST(LensSamples, EveryPrefixCoversTheDisc) {
  expect_even(8, 0.3, 0.7, 1, 1);
  expect_even(20, 0.6, 0.2, 2, 2);
}

TEST(LensSamples, ShiftMovesThePattern) {
  const auto a = lens_sample(3, 0.1, 0.2), b = lens_sample(3, 0.6, 0.2);
  EXPECT_GT(std::hypot(a.u - b.u, a.v - b.v), 0.05);
}

}  // namespace
}  // namespace snell::scene
