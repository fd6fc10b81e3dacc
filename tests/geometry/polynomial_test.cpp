#include "snell/geometry/polynomial.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "snell/math/pcg32.hpp"

using namespace snell::geometry;

namespace {
// Ascending coefficients of prod (x - r_i).
std::vector<double> from_roots(const std::vector<double>& rs, double scale = 1) {
  std::vector<double> c{scale};
  for (double r : rs) {
    std::vector<double> next(c.size() + 1, 0.0);
    for (size_t i = 0; i < c.size(); ++i) {
      next[i + 1] += c[i];
      next[i] -= r * c[i];
    }
    c = next;
  }
  return c;
}

std::vector<double> roots_in(const std::vector<double>& c, double lo, double hi) {
  std::array<double, kMaxPolynomialDegree> out{};
  const int n = real_roots(c, lo, hi, out);
  return {out.begin(), out.begin() + n};
}
}  // namespace

TEST(PolynomialTest, QuarticWithFourSimpleRoots) {
  const auto r = roots_in(from_roots({-2, 0.5, 1, 3}), -10, 10);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_NEAR(r[0], -2, 1e-12);
  EXPECT_NEAR(r[1], 0.5, 1e-12);
  EXPECT_NEAR(r[2], 1, 1e-12);
  EXPECT_NEAR(r[3], 3, 1e-12);
}

TEST(PolynomialTest, OnlyRootsInsideTheHalfOpenInterval) {
  const auto c = from_roots({-2, 0.5, 1, 3});
  const auto r = roots_in(c, 0.5, 3);  // (0.5, 3]: 0.5 excluded, 3 included
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0], 1, 1e-12);
  EXPECT_NEAR(r[1], 3, 1e-12);
  EXPECT_TRUE(roots_in(c, 3.5, 100).empty());
}

TEST(PolynomialTest, DoubleRootIsFoundOnce) {
  const auto r = roots_in(from_roots({1, 1, 3, -2}), -10, 10);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], -2, 1e-10);
  EXPECT_NEAR(r[1], 1, 1e-7);
  EXPECT_NEAR(r[2], 3, 1e-10);
}

TEST(PolynomialTest, TwoDoubleRoots) {
  // (x^2 - 1)^2: touches zero at -1 and 1 without crossing (a ray grazing a torus twice).
  const auto r = roots_in(from_roots({-1, -1, 1, 1}), -5, 5);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0], -1, 1e-7);
  EXPECT_NEAR(r[1], 1, 1e-7);
}

TEST(PolynomialTest, WideRangeOfRootMagnitudes) {
  const auto r = roots_in(from_roots({1e-3, 1, 1e3, 1e5}), -1e6, 1e6);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_NEAR(r[0], 1e-3, 1e-12);
  EXPECT_NEAR(r[1], 1, 1e-10);
  EXPECT_NEAR(r[2], 1e3, 1e-8);
  EXPECT_NEAR(r[3], 1e5, 1e-5);
}

TEST(PolynomialTest, CloseRootsAreSeparated) {
  const auto r = roots_in(from_roots({2, 2.0001, 5}), 0, 10);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], 2, 1e-9);
  EXPECT_NEAR(r[1], 2.0001, 1e-9);
  EXPECT_NEAR(r[2], 5, 1e-9);
}

TEST(PolynomialTest, ScaleOfCoefficientsDoesNotMatter) {
  for (double scale : {1e-12, -3.0, 1e9}) {
    const auto r = roots_in(from_roots({-0.25, 0.75, 2}, scale), -1, 3);
    ASSERT_EQ(r.size(), 3u) << scale;
    EXPECT_NEAR(r[0], -0.25, 1e-12);
    EXPECT_NEAR(r[1], 0.75, 1e-12);
    EXPECT_NEAR(r[2], 2, 1e-12);
  }
}

TEST(PolynomialTest, NoRealRoots) {
  // x^4 + 1 and (x^2 + 1)(x^2 + 4).
  EXPECT_TRUE(roots_in({1, 0, 0, 0, 1}, -100, 100).empty());
  EXPECT_TRUE(roots_in({4, 0, 5, 0, 1}, -100, 100).empty());
}

TEST(PolynomialTest, NegligibleLeadingCoefficientLowersDegree) {
  // 1e-30 x^4 + (x - 2)(x + 1) behaves as the quadratic on a modest interval.
  auto c = from_roots({2, -1});
  c.push_back(0);
  c.push_back(1e-30);
  const auto r = roots_in(c, -10, 10);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0], -1, 1e-12);
  EXPECT_NEAR(r[1], 2, 1e-12);
}

TEST(PolynomialTest, CubicAndLinear) {
  const auto r = roots_in(from_roots({-1, 0, 4}), -2, 5);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[1], 0, 1e-13);
  const auto l = roots_in({-3, 2}, 0, 2);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_DOUBLE_EQ(l[0], 1.5);
}

TEST(PolynomialTest, BadArgumentsThrow) {
  std::array<double, 8> out{};
  const std::vector<double> c{1, 2, 3};
  EXPECT_THROW(real_roots(c, 1, 0, out), std::invalid_argument);
  EXPECT_THROW(real_roots(c, 0, std::numeric_limits<double>::infinity(), out), std::invalid_argument);
  const std::vector<double> big(9, 1.0);
  EXPECT_THROW(real_roots(big, 0, 1, out), std::invalid_argument);
  EXPECT_EQ(real_roots(std::vector<double>{0, 0, 0}, 0, 1, out), 0);
}

TEST(PolynomialTest, QuadraticIsStableForSmallRoot) {
  double t0, t1;
  ASSERT_TRUE(solve_quadratic(1, -1e8, 1, t0, t1));
  EXPECT_NEAR(t0, 1e-8, 1e-20);
  EXPECT_NEAR(t1, 1e8, 1e-4);
  EXPECT_FALSE(solve_quadratic(1, 0, 1, t0, t1));
}

TEST(PolynomialTest, QuadraticsTakeTheHalfOpenIntervalAndDoubleRootsOnce) {
  // Quadratics are solved in closed form: same contract as the Sturm path.
  const auto c = from_roots({0.25, 0.75}, -3);
  EXPECT_EQ(roots_in(c, -1, 1), (std::vector<double>{0.25, 0.75}));
  EXPECT_EQ(roots_in(c, 0.25, 0.75), (std::vector<double>{0.75}));  // (0.25, 0.75]
  EXPECT_TRUE(roots_in(c, 0.75, 2).empty());
  EXPECT_EQ(roots_in(from_roots({0.5, 0.5}), 0, 1), (std::vector<double>{0.5}));
  EXPECT_TRUE(roots_in({1, 0, 1}, -5, 5).empty());  // x^2 + 1
  // A root near 1e-9 beside one near 1e9: no cancellation (the stable formula).
  const auto wide = roots_in(from_roots({1e-9, 1e9}), -1, 2e9);
  ASSERT_EQ(wide.size(), 2u);
  EXPECT_NEAR(wide[0], 1e-9, 1e-22);
  EXPECT_NEAR(wide[1], 1e9, 1e-4);
}

TEST(PolynomialTest, MaxRootsKeepsTheSmallest) {
  const auto c = from_roots({-2, 0.5, 1, 3});
  std::array<double, kMaxPolynomialDegree> out{};
  ASSERT_EQ(real_roots(c, -10, 10, out, 1), 1);
  EXPECT_NEAR(out[0], -2, 1e-12);
  ASSERT_EQ(real_roots(c, -1, 10, out, 2), 2);  // the window drops -2
  EXPECT_NEAR(out[0], 0.5, 1e-12);
  EXPECT_NEAR(out[1], 1, 1e-12);
  ASSERT_EQ(real_roots(from_roots({0.25, 0.75}), 0, 1, out, 1), 1);  // the closed-form quadratic too
  EXPECT_NEAR(out[0], 0.25, 1e-15);
}

TEST(PolynomialTest, SexticWithSixRootsAndWindowsBesideThem) {
  // The lathe's equation is a sextic: all six roots, and windows that end just short of a root (the sign
  // test must not drop a window that holds one, nor invent one).
  const std::vector<double> roots{-0.9, -0.3, 0.1, 0.45, 0.8, 1.0000001};
  const auto c = from_roots(roots, 2.5);
  const auto all = roots_in(c, -1, 2);
  ASSERT_EQ(all.size(), 6u);
  for (size_t i = 0; i < roots.size(); ++i) EXPECT_NEAR(all[i], roots[i], 1e-9) << i;
  EXPECT_TRUE(roots_in(c, 0.81, 1.0).empty());
  EXPECT_EQ(roots_in(c, 0.81, 1.0000002).size(), 1u);
  EXPECT_EQ(roots_in(c, 0.0999999, 0.1000001).size(), 1u);
  EXPECT_TRUE(roots_in(c, 0.1000001, 0.44).empty());
}

TEST(PolynomialTest, TouchingRootOfASexticIsFoundOnce) {
  // (x - 0.5)^2 (x + 2)(x - 3)(x^2 + 1): touches zero at 0.5 (a ray grazing a lathe's rim).
  auto c = from_roots({0.5, 0.5, -2, 3});
  std::vector<double> with_complex(c.size() + 2, 0.0);
  for (size_t i = 0; i < c.size(); ++i) {
    with_complex[i] += c[i];
    with_complex[i + 2] += c[i];
  }
  const auto r = roots_in(with_complex, -5, 5);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], -2, 1e-10);
  EXPECT_NEAR(r[1], 0.5, 1e-7);
  EXPECT_NEAR(r[2], 3, 1e-10);
}

TEST(PolynomialTest, RandomPolynomialsWithSimpleDoubleAndClusteredRoots) {
  // Polynomials of degree 3 to 6 built from known roots in [-1, 2] (some doubled, some in pairs 1e-3 apart)
  // and, for the rest of the degree, positive quadratic factors: every root in the window (0, 1] must be
  // found, simple ones exactly once and to 1e-9, and nothing else. This pins down the Newton refinement's
  // early stop (|p| within its rounding error) on the kinds of polynomial grazing rays produce.
  snell::math::Pcg32 rng(7);
  for (int trial = 0; trial < 4000; ++trial) {
    const int degree = 3 + static_cast<int>(rng.next_uint() % 4);
    std::vector<double> real;
    std::vector<bool> doubled;
    int left = degree;
    while (left > 0) {
      const double kind = rng.next_double(), r = -1 + 3 * rng.next_double();
      if (left >= 2 && kind < 0.2) {  // a double root
        real.insert(real.end(), {r, r});
        doubled.insert(doubled.end(), {true, true});
        left -= 2;
      } else if (left >= 2 && kind < 0.4) {  // a cluster of two simple roots
        real.insert(real.end(), {r, r + 1e-3});
        doubled.insert(doubled.end(), {false, false});
        left -= 2;
      } else if (left >= 2 && kind < 0.55) {  // no real root: (x - r)^2 + s^2
        real.push_back(std::nan(""));
        doubled.push_back(false);
        left -= 2;
      } else {
        real.push_back(r);
        doubled.push_back(false);
        left -= 1;
      }
    }
    std::vector<double> c{0.5 + rng.next_double()};
    std::vector<double> expected;
    std::vector<bool> expected_double;
    bool near_an_end = false;  // or near another group: skipped
    for (size_t i = 0; i < real.size(); ++i) {
      std::vector<double> factor;
      if (std::isnan(real[i])) {
        const double m = -1 + 3 * rng.next_double(), s = 0.05 + rng.next_double();
        factor = {m * m + s * s, -2 * m, 1};
      } else {
        factor = {-real[i], 1};
        near_an_end = near_an_end || std::fabs(real[i]) < 1e-6 || std::fabs(real[i] - 1) < 1e-6;
        if (real[i] > 0 && real[i] <= 1 && (i == 0 || real[i] != real[i - 1] || !doubled[i])) {
          expected.push_back(real[i]);
          expected_double.push_back(doubled[i]);
        }
      }
      std::vector<double> next(c.size() + factor.size() - 1, 0.0);
      for (size_t a = 0; a < c.size(); ++a)
        for (size_t b = 0; b < factor.size(); ++b) next[a + b] += c[a] * factor[b];
      c = next;
    }
    // Groups (a double root, a cluster, a single root) nearer than 0.02 to one another make a root of
    // higher multiplicity, whose accuracy is the fourth root of the rounding: not what this test checks.
    for (size_t i = 0; i < real.size(); ++i)
      for (size_t j = i + 1; j < real.size(); ++j)
        if (std::fabs(real[i] - real[j]) > 2e-3 && std::fabs(real[i] - real[j]) < 0.02) near_an_end = true;
    if (near_an_end) continue;
    const auto found = roots_in(c, 0, 1);
    for (size_t k = 0; k + 1 < found.size(); ++k) EXPECT_LT(found[k], found[k + 1]) << trial;
    // Each expected root is found: simple ones once to 1e-9; a double root (whose rounded coefficients may
    // split it into two roots or none, 1e-8 apart) once or twice to 1e-6, or missed only if it became a
    // complex pair, which the touching test still reports within its rounding.
    size_t matched = 0;
    for (size_t e = 0; e < expected.size(); ++e) {
      const double tol = expected_double[e] ? 1e-6 : 1e-7;
      int near = 0;
      for (const double f : found) near += std::fabs(f - expected[e]) <= tol;
      if (expected_double[e]) {
        EXPECT_GE(near, 1) << "trial " << trial << " double root " << expected[e];
        EXPECT_LE(near, 2) << "trial " << trial << " double root " << expected[e];
      } else {
        EXPECT_EQ(near, 1) << "trial " << trial << " root " << expected[e];
      }
      matched += static_cast<size_t>(near);
    }
    EXPECT_EQ(matched, found.size()) << "trial " << trial
                                     << ": a root found that is none of the polynomial's";
  }
}

TEST(PolynomialTest, HasRootAgreesWithRealRoots) {
  // Random polynomials of degree 1 to 6 from random roots (some doubled, so that touching roots come up)
  // and random windows, some empty: has_root says whether real_roots finds anything, without refining.
  snell::math::Pcg32 rng(11);
  int with = 0, without = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int degree = 1 + static_cast<int>(rng.next_uint() % 6);
    std::vector<double> rs;
    while (static_cast<int>(rs.size()) < degree) {
      const double r = -2 + 4 * rng.next_double();
      rs.push_back(r);
      if (static_cast<int>(rs.size()) < degree && rng.next_double() < 0.2) rs.push_back(r);
    }
    std::vector<double> c = from_roots(rs, 0.1 + rng.next_double());
    c[0] += 0.3 * (rng.next_double() - 0.5);  // moves roots, may pair some off into the complex plane
    const double lo = -2 + 4 * rng.next_double(), hi = lo + 2 * (rng.next_double() - 0.1);
    const bool expected = lo < hi && !roots_in(c, lo, hi).empty();
    ASSERT_EQ(has_root(c, lo, hi), expected) << "trial " << trial;
    (expected ? with : without)++;
  }
  EXPECT_GT(with, 4000);
  EXPECT_GT(without, 4000);
}
