// The march's over-relaxed steps must not skip a root that the Lipschitz bound allows: a slow
// slope invites a long step, and a narrow dip of slope exactly L hides a pair of roots on the way. The
// multi-point march (march_roots_lanes) must prove the same and find the same roots.
#include "snell/geometry/lipschitz_march.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace snell::geometry {
namespace {

std::vector<double> roots_of(const auto& g, double hi, const MarchSettings& s) {
  std::vector<double> roots;
  march_roots(
      g, 0, g(0), hi, s,
      [&](double t) {
        roots.push_back(t);
        return true;
      },
      [](double) {});
  return roots;
}

TEST(LipschitzMarchTest, PredictedStepsDoNotSkipANarrowDip) {
  // 1 - 0.1 t reaches zero at t = 10; the dip |t - 3| - 0.02 (slope 1 = L) crosses zero at 2.98 and 3.02.
  const auto g = [](double t) { return std::min(1 - 0.1 * t, std::fabs(t - 3) - 0.02); };
  const std::vector<double> roots = roots_of(g, 20, {1, 1e-3, 1e-9});
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_NEAR(roots[0], 2.98, 1e-8);
  EXPECT_NEAR(roots[1], 3.02, 1e-8);
  EXPECT_NEAR(roots[2], 10, 1e-8);
}

TEST(LipschitzMarchTest, OverRelaxedStepsSaveEvaluations) {
  // A slope of 0.01 under a bound of 1: safe steps shrink g by 1% each, ln(1e-3) / ln(0.99) = 687 of them
  // down to the minimum step, then 100 minimum steps; over-relaxed steps take about 1.9% each.
  int evaluations = 0;
  const auto g = [&](double t) {
    ++evaluations;
    return 1 - 0.01 * t;
  };
  double root = 0;
  march_roots(
      g, 0, g(0), 200, {1, 1e-3, 1e-9},
      [&](double t) {
        root = t;
        return false;  // the first crossing only
      },
      [](double) {});
  EXPECT_NEAR(root, 100, 1e-8);
  EXPECT_LT(evaluations, 600);
  RecordProperty("evaluations", evaluations);
}

/// The multi-point march with 8 lanes; counts the passes (calls of g_lanes) and the points evaluated.
struct LaneMarch {
  int passes = 0, points = 0;
  std::vector<double> roots;
  bool first_only = false;

  template <typename G>
  void run(const G& g, double lo, double hi, const MarchSettings& s) {
    const auto g_lanes = [&](const double* ts, int n, double* out) {
      ++passes, points += n;
      for (int i = 0; i < 8; ++i) out[i] = g(ts[i]);
    };
    march_roots_lanes<8>(
        g, g_lanes, lo, g(lo), hi, s,
        [&](double t) {
          roots.push_back(t);
          return !first_only;
        },
        [](double) {});
  }
};

TEST(LipschitzMarchTest, LanesFindTheSameRootsAsTheScalarMarch) {
  const auto g = [](double t) { return std::min(1 - 0.1 * t, std::fabs(t - 3) - 0.02); };
  LaneMarch lanes;
  lanes.run(g, 0, 20, {1, 1e-3, 1e-9});
  const std::vector<double> scalar = roots_of(g, 20, {1, 1e-3, 1e-9});
  ASSERT_EQ(lanes.roots.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(lanes.roots[i], scalar[i], 1e-8);
}

TEST(LipschitzMarchTest, LanesTakeEightMinimumStepsAPass) {
  // A bound of 1000 on a slope of 0.01: every safe step is the minimum step 1e-3 (|g| < 1), so each pass
  // takes all 8 predicted steps: about 100 / 1e-3 / 8 passes to the root at t = 100.
  LaneMarch lanes;
  lanes.first_only = true;
  lanes.run([](double t) { return 0.5 - 0.005 * t; }, 0, 200, {1000, 1e-3, 1e-9});
  ASSERT_EQ(lanes.roots.size(), 1u);
  EXPECT_NEAR(lanes.roots[0], 100, 1e-8);
  EXPECT_LE(lanes.passes, 100 / 1e-3 / 8 + 2);
  EXPECT_GE(lanes.points, 8 * (lanes.passes - 2));  // no pass cut short
}

TEST(LipschitzMarchTest, LanesEndOnNanAndOnLargeParameters) {
  // A NaN everywhere gives minimum steps and no root; far from t = 0 a safe step added to t rounds, and
  // must still count as safe (else the march would retry it for ever).
  LaneMarch nan;
  nan.run([](double) { return std::numeric_limits<double>::quiet_NaN(); }, 0, 0.1, {1, 1e-3, 1e-9});
  EXPECT_TRUE(nan.roots.empty());
  EXPECT_LE(nan.points, 101 + 8);
  LaneMarch far;
  far.run([](double t) { return 0.3 + 1e-7 * (t - 1e7); }, 1e7, 1e7 + 50, {1, 1e-3, 1e-9});
  EXPECT_TRUE(far.roots.empty());
  EXPECT_LE(far.passes, 60);
}

}  // namespace
}  // namespace snell::geometry
