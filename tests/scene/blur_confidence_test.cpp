// Chi-square quantiles against closed forms and tables (Abramowitz & Stegun table 26.8), and POV-Ray's
// threshold rule: variance at the full count, scaled by quantile(n) / quantile(max - 1).
#include "snell/scene/blur_confidence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace snell::scene {
namespace {

TEST(BlurConfidence, ChiSquareQuantiles) {
  // Two degrees of freedom: P(X > x) = exp(-x / 2).
  EXPECT_NEAR(chi_square_upper_quantile(2, 0.9), -2 * std::log(0.9), 1e-9);
  EXPECT_NEAR(chi_square_upper_quantile(2, 0.05), -2 * std::log(0.05), 1e-9);
  // Tables: chi2(1) 10th percentile 0.01579, chi2(10) 4.865, chi2(10) 95th percentile 18.307.
  EXPECT_NEAR(chi_square_upper_quantile(1, 0.9), 0.015791, 1e-5);
  EXPECT_NEAR(chi_square_upper_quantile(10, 0.9), 4.86518, 1e-4);
  EXPECT_NEAR(chi_square_upper_quantile(10, 0.05), 18.3070, 1e-3);
  EXPECT_NEAR(chi_square_upper_quantile(100, 0.5), 99.3341, 1e-3);
  EXPECT_THROW(chi_square_upper_quantile(0, 0.5), std::invalid_argument);
  EXPECT_THROW(chi_square_upper_quantile(3, 1.0), std::invalid_argument);
}

TEST(BlurConfidence, ThresholdsGrowWithSampleCount) {
  const auto t = blur_variance_thresholds(20, 0.9, 0.01);
  ASSERT_EQ(t.size(), 20u);
  EXPECT_NEAR(t[18], 0.01, 1e-12);  // n = max - 1: exactly the variance
  EXPECT_NEAR(t[1], 0.01 * (-2 * std::log(0.9)) / chi_square_upper_quantile(19, 0.9), 1e-12);
  for (size_t i = 1; i < t.size(); ++i) EXPECT_GT(t[i], t[i - 1]);
  EXPECT_EQ(blur_variance_thresholds(1, 0.9, 0.01)[0], 0);
}

TEST(BlurConfidence, BatchesFollowTheHexagonalRings) {
  EXPECT_EQ(blur_batch_size(0, 4), 4);
  EXPECT_EQ(blur_batch_size(0, 7), 7);
  EXPECT_EQ(blur_batch_size(1, 7), 4);
  EXPECT_EQ(blur_batch_size(2, 19), 6);
  EXPECT_EQ(blur_batch_size(3, 19), 4);
  EXPECT_EQ(blur_batch_size(7, 120), 2);
  EXPECT_EQ(blur_batch_size(8, 120), 4);
}

}  // namespace
}  // namespace snell::scene
