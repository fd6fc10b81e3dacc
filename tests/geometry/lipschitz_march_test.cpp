// The march's over-relaxed steps must not skip a root that the Lipschitz bound allows: a slow
// slope invites a long step, and a narrow dip of slope exactly L hides a pair of roots on the way.
#include "snell/geometry/lipschitz_march.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace snell::geometry
