// The vector kernels of multi-point evaluation against the C library, over many arguments: sin, cos and
// atan2 within about one unit in the last place, special values exactly as libm gives them, and the SSE2
// and AVX2 builds bit for bit equal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "snell/function/lane_math.hpp"

namespace snell::function::lanes {
namespace {

constexpr std::size_t kW = kLaneWidth;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// Arguments spread over magnitudes 1e-8 .. 1e6, both signs, plus the awkward ones.
std::vector<double> arguments(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> exponent(-8, 6), mantissa(1, 10);
  std::vector<double> xs;
  for (std::size_t i = 0; i < count; ++i)
    xs.push_back((rng() & 1 ? 1 : -1) * std::pow(10.0, exponent(rng)) * mantissa(rng) / 10);
  for (int k = -40; k <= 40; ++k) {  // near multiples of pi/4, where the reduction and the quadrant turn
    const double m = k * 0.78539816339744830962;
    xs.insert(xs.end(), {m, std::nextafter(m, kInf), std::nextafter(m, -kInf)});
  }
  xs.insert(xs.end(), {0.0, -0.0, 1e-310, -1e-310, 1e6, -1e6, 1.5e6, 1e300, kInf, -kInf, kNan});
  while (xs.size() % kW) xs.push_back(1);
  return xs;
}

bool same(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}

/// |value - reference| within `ulps` units of the reference's last place, or `absolute` (exact for
/// non-finite references).
::testing::AssertionResult close(double value, double reference, double ulps, double arg,
                                 double absolute = 0) {
  if (!std::isfinite(reference) || reference == 0) {
    if (same(value, reference)) return ::testing::AssertionSuccess();
  } else if (std::fabs(value - reference) <= std::max(ulps * std::fabs(reference) * 0x1p-52, absolute)) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "at " << arg << ": " << value << " against libm's " << reference;
}

TEST(LaneMath, SinAndCosMatchLibm) {
  const std::vector<double> xs = arguments(40000, 1);
  for (std::size_t i = 0; i < xs.size(); i += kW) {
    double s[kW], c[kW];
    sin(&xs[i], s);
    cos(&xs[i], c);
    for (std::size_t l = 0; l < kW; ++l) {
      const double x = xs[i + l];
      // Near the zeros (x close to a multiple of pi/2) the error is the reduction's, |x| 4e-31: absolute.
      EXPECT_TRUE(close(s[l], std::sin(x), 2, x, 1e-29 * std::fabs(x)));
      EXPECT_TRUE(close(c[l], std::cos(x), 2, x, 1e-29 * std::fabs(x)));
    }
  }
}

TEST(LaneMath, Atan2MatchesLibmInEveryQuadrant) {
  const std::vector<double> ys = arguments(20000, 2), xs = arguments(20000, 3);
  ASSERT_EQ(xs.size(), ys.size());
  for (std::size_t i = 0; i < xs.size(); i += kW) {
    double a[kW];
    atan2(&ys[i], &xs[i], a);
    for (std::size_t l = 0; l < kW; ++l)
      EXPECT_TRUE(close(a[l], std::atan2(ys[i + l], xs[i + l]), 2, ys[i + l] / xs[i + l]));
  }
  // Signed zeros and the axes, exactly as libm.
  const double y[kW] = {0.0, -0.0, 0.0, -0.0, 1, -1, kInf, 2};
  const double x[kW] = {1, 1, -1, -1, 0.0, -0.0, kInf, -kInf};
  double a[kW];
  atan2(y, x, a);
  for (std::size_t l = 0; l < kW; ++l) EXPECT_TRUE(same(a[l], std::atan2(y[l], x[l]))) << l;
}

TEST(LaneMath, SqrtIsCorrectlyRounded) {
  const std::vector<double> xs = arguments(4000, 4);
  for (std::size_t i = 0; i < xs.size(); i += kW) {
    double r[kW];
    sqrt(&xs[i], r);
    for (std::size_t l = 0; l < kW; ++l) EXPECT_TRUE(same(r[l], std::sqrt(xs[i + l]))) << xs[i + l];
  }
}

TEST(LaneMath, PortableAndAvx2BuildsGiveTheSameBits) {
  const std::vector<double> xs = arguments(20000, 5), ys = arguments(20000, 6);
  const auto run = [&] {
    std::vector<double> out(3 * xs.size());
    for (std::size_t i = 0; i < xs.size(); i += kW) {
      sin(&xs[i], &out[i]);
      cos(&xs[i], &out[xs.size() + i]);
      atan2(&ys[i], &xs[i], &out[2 * xs.size() + i]);
    }
    return out;
  };
  const bool avx2 = use_portable_kernels(true);
  const std::vector<double> portable = run();
  use_portable_kernels(false);
  if (!avx2) GTEST_SKIP() << "no AVX2 on this processor";
  const std::vector<double> fast = run();
  for (std::size_t i = 0; i < fast.size(); ++i) ASSERT_TRUE(same(fast[i], portable[i])) << i;
}

}  // namespace
}  // namespace snell::function::lanes
