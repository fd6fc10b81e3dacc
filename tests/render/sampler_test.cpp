// Sample sequences against published values and their defining properties, and the reconstruction filters'
// normalisation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "snell/render/filter.hpp"
#include "snell/render/sampler.hpp"

namespace snell::render {
namespace {

TEST(Sampler, SobolFirstPointsMatchThePublishedTable) {
  // Bratley & Fox (1988) / Joe & Kuo: the first 3-D Sobol points in Gray-code order (index i is point
  // i ^ (i >> 1) of the direct order that sobol() uses).
  const double expected[8][3] = {{0, 0, 0},
                                 {0.5, 0.5, 0.5},
                                 {0.75, 0.25, 0.25},
                                 {0.25, 0.75, 0.75},
                                 {0.375, 0.375, 0.625},
                                 {0.875, 0.875, 0.125},
                                 {0.625, 0.125, 0.875},
                                 {0.125, 0.625, 0.375}};
  for (uint32_t i = 0; i < 8; ++i)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(sobol(i ^ (i >> 1), d), expected[i][d]) << "point " << i << " dim " << d;
}

TEST(Sampler, SobolDimensionsAreStratifiedAndTheFirstPairIsANet) {
  // Every Sobol dimension is a (0,1)-sequence: the first 2^m points fall one into each interval of
  // length 2^-m. Dimensions 0 and 1 form a (0,2)-sequence: one point in each elementary box of area 2^-m.
  constexpr int m = 8, n = 1 << m;
  for (int d = 0; d < kSobolDimensions; ++d) {
    std::set<int> cells;
    for (uint32_t i = 0; i < n; ++i) cells.insert(static_cast<int>(sobol(i, d) * n));
    EXPECT_EQ(cells.size(), size_t{n}) << "dimension " << d;
  }
  for (int k = 0; k <= m; ++k) {
    std::set<std::pair<int, int>> boxes;
    for (uint32_t i = 0; i < n; ++i)
      boxes.insert(
          {static_cast<int>(sobol(i, 0) * (1 << k)), static_cast<int>(sobol(i, 1) * (1 << (m - k)))});
    EXPECT_EQ(boxes.size(), size_t{n}) << "boxes 2^-" << k << " x 2^-" << (m - k);
  }
}

TEST(Sampler, HaltonFirstPointsMatchRadicalInverses) {
  const double base2[] = {0, 0.5, 0.25, 0.75, 0.125, 0.625};
  const double base3[] = {0, 1.0 / 3, 2.0 / 3, 1.0 / 9, 4.0 / 9, 7.0 / 9};
  for (uint32_t i = 0; i < 6; ++i) {
    EXPECT_DOUBLE_EQ(halton(i, 0), base2[i]);
    EXPECT_DOUBLE_EQ(halton(i, 1), base3[i]);
  }
  EXPECT_DOUBLE_EQ(halton(1, 2), 0.2);
  EXPECT_DOUBLE_EQ(halton(1, 4), 1.0 / 11);
}

TEST(Sampler, OwenScramblingKeepsStratificationAndChangesThePoints) {
  // A nested scramble maps each dyadic interval onto another one, so the first 2^m scrambled points are
  // still one per interval; different seeds give different points.
  constexpr int n = 64;
  std::set<int> cells;
  int moved = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t bits = static_cast<uint32_t>(sobol(i, 2) * 0x1p32);
    const uint32_t s = owen_scramble(bits, 1234);
    cells.insert(static_cast<int>(s >> 26));
    moved += s != owen_scramble(bits, 99);
  }
  EXPECT_EQ(cells.size(), size_t{n});
  EXPECT_GT(moved, n / 2);
}

TEST(Sampler, EverySamplerCoversEachDimensionUniformly) {
  // With n = 64 samples, stratified and Sobol put exactly one sample in each 1/n of every dimension (the
  // time dimension among them, so shutter times cover [open, close] evenly); Halton is stratified only
  // at powers of its base, so it is held to a discrepancy bound instead.
  constexpr uint32_t n = 64;
  for (const char* name : {"stratified", "sobol", "halton"}) {
    const auto sampler = make_sampler(name);
    ASSERT_TRUE(sampler);
    for (uint64_t pixel : {1ull, 77ull, 123456789ull})
      for (int d = 0; d < kSampleDimensions; ++d) {
        std::vector<double> v;
        for (uint32_t i = 0; i < n; ++i) v.push_back(sampler->get(pixel, i, n, d));
        std::sort(v.begin(), v.end());
        double worst = 0;  // Kolmogorov-Smirnov distance to the uniform distribution
        for (uint32_t i = 0; i < n; ++i) {
          ASSERT_GE(v[i], 0.0);
          ASSERT_LT(v[i], 1.0);
          worst = std::max({worst, std::fabs(v[i] - double(i) / n), std::fabs(v[i] - double(i + 1) / n)});
        }
        if (std::string(name) == "halton")
          EXPECT_LT(worst, 4.0 / n) << name << " dim " << d;
        else
          EXPECT_LE(worst, 1.0 / n + 1e-12) << name << " dim " << d;  // one per stratum
      }
  }
  EXPECT_FALSE(make_sampler("random"));
}

TEST(Sampler, SamplesAreAFunctionOfPixelIndexAndDimension) {
  const auto sampler = make_sampler("stratified");
  EXPECT_EQ(sampler->get(5, 3, 16, kTime), sampler->get(5, 3, 16, kTime));
  EXPECT_NE(sampler->get(5, 3, 16, kTime), sampler->get(6, 3, 16, kTime));
  EXPECT_NE(sampler->get(5, 3, 16, kTime), sampler->get(5, 3, 16, kLensU));
}

TEST(Filter, EveryFilterIntegratesToOne) {
  for (const char* spec :
       {"box", "tent", "gaussian", "mitchell", "box:1", "tent:2.5", "gaussian:0.8", "mitchell:1"}) {
    const auto f = Filter::parse(spec);
    ASSERT_TRUE(f) << spec;
    const int steps = 200000;
    const double r = f->radius(), h = 2 * r / steps;
    double sum = 0;  // midpoint rule
    for (int i = 0; i < steps; ++i) sum += f->value(-r + (i + 0.5) * h) * h;
    EXPECT_NEAR(sum, 1.0, 1e-6) << spec;
    EXPECT_EQ(f->value(r * 1.01), 0.0) << spec;
  }
}

TEST(Filter, ShapesAndDefaultRadii) {
  EXPECT_DOUBLE_EQ(Filter::parse("box")->radius(), 0.5);
  EXPECT_DOUBLE_EQ(Filter::parse("tent")->radius(), 1);
  EXPECT_DOUBLE_EQ(Filter::parse("gaussian")->radius(), 1.5);
  EXPECT_DOUBLE_EQ(Filter::parse("mitchell")->radius(), 2);
  // Tent: linear, half height half way. Mitchell-Netravali (B = C = 1/3): k(0) = (6 - 2B)/6 = 16/18 and
  // k(1) = B/6 = 1/18 on its [-2, 2] support (radius 2 keeps that scale).
  const auto tent = Filter::parse("tent");
  EXPECT_DOUBLE_EQ(tent->value(0.5), 0.5 * tent->value(0));
  const auto mitchell = Filter::parse("mitchell");
  EXPECT_NEAR(mitchell->value(0), 16.0 / 18, 1e-12);
  EXPECT_NEAR(mitchell->value(1), 1.0 / 18, 1e-12);
  EXPECT_LT(mitchell->value(1.5), 0);  // the negative lobe
  for (const char* bad : {"lanczos", "box:", "box:0", "box:-1", "tent:x", "gaussian:1e9"})
    EXPECT_FALSE(Filter::parse(bad)) << bad;
}

}  // namespace
}  // namespace snell::render
