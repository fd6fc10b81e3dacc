// The GGX distribution and its visible-normal sampling against their defining integrals (Walter et al. 2007;
// Heitz 2014, 2018): D is normalised over the projected hemisphere, the visible normals' density integrates
// to 1 (Smith's weak white furnace), and sampled reflections follow the stated pdf (histogram).
#include "snell/render/microfacet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "snell/math/constants.hpp"
#include "snell/math/pcg32.hpp"

namespace snell::render {
namespace {

using math::kPi;
using math::Vec3;

Vec3 from_angles(double cos_theta, double phi) {
  const double s = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  return {s * std::cos(phi), s * std::sin(phi), cos_theta};
}

/// Integral over the upper hemisphere of f(w) dw by the midpoint rule in (cos theta, phi).
template <typename F>
double hemisphere_integral(const F& f, int n_cos, int n_phi) {
  double sum = 0;
  const double dc = 1.0 / n_cos, dp = 2 * kPi / n_phi;
  for (int i = 0; i < n_cos; ++i)
    for (int j = 0; j < n_phi; ++j) sum += f(from_angles((i + 0.5) * dc, (j + 0.5) * dp));
  return sum * dc * dp;
}

TEST(MicrofacetTest, DistributionIntegratesToOneOverProjectedHemisphere) {
  for (double alpha : {0.05, 0.3, 1.0}) {
    // D is rotationally symmetric: 2 pi integral of D(mu) mu dmu, fine enough for the alpha^2 wide peak.
    const int n = 400000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double mu = (i + 0.5) / n;
      sum += ggx_distribution(from_angles(mu, 0), alpha) * mu;
    }
    EXPECT_NEAR(2 * kPi * sum / n, 1.0, 1e-4) << "alpha " << alpha;
  }
}

TEST(MicrofacetTest, VisibleNormalDensityIntegratesToOne) {
  // Heitz 2014 eq. 18: integral of G1(v) max(0, v.m) D(m) dm = v.z, for any view direction.
  for (double alpha : {0.2, 0.6}) {
    for (double view_deg : {0.0, 45.0, 75.0}) {
      const Vec3 v = from_angles(std::cos(math::radians(view_deg)), 0.3);
      const double total =
          hemisphere_integral([&](const Vec3& m) { return ggx_visible_normal_pdf(v, m, alpha); }, 2000, 128);
      EXPECT_NEAR(total, 1.0, 5e-4) << "alpha " << alpha << " view " << view_deg;
    }
  }
}

TEST(MicrofacetTest, SmithLambdaMatchesClosedForm) {
  // Lambda(theta) = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2: alpha 0.5, theta 60 deg -> tan^2 = 3,
  // sqrt(1.75) = 1.3228756555 -> 0.1614378278; normal incidence masks nothing.
  EXPECT_NEAR(ggx_lambda(from_angles(0.5, 1.0), 0.5), 0.1614378278, 1e-9);
  EXPECT_EQ(ggx_masking(Vec3(0, 0, 1), 0.5), 1.0);
  // D at the normal is 1 / (pi alpha^2).
  EXPECT_NEAR(ggx_distribution(Vec3(0, 0, 1), 0.25), 1 / (kPi * 0.0625), 1e-12);
}

TEST(MicrofacetTest, ZeroWidthSamplesTheNormalExactly) {
  const Vec3 v = normalize(Vec3(0.3, -0.2, 0.9));
  for (double u : {0.0, 0.37, 0.99}) EXPECT_EQ(sample_ggx_visible_normal(v, 0.0, u, 1 - u), Vec3(0, 0, 1));
}

TEST(MicrofacetTest, SampledReflectionsFollowTheirPdf) {
  // Histogram of l = reflect(-v, m), m drawn by the sampling routine, in bins of (cos theta_l, phi_l),
  // against the pdf D_v / (4 v.m) integrated over each bin: two independent routes to the same density.
  const double alpha = 0.4;
  const Vec3 v = from_angles(std::cos(math::radians(50)), 0);
  const int n_cos = 8, n_phi = 8, sub = 24;
  std::vector<double> counts(n_cos * n_phi, 0.0);
  math::Pcg32 rng(12345);
  const int samples = 400000;
  for (int i = 0; i < samples; ++i) {
    const Vec3 m = sample_ggx_visible_normal(v, alpha, rng.next_double(), rng.next_double());
    const Vec3 l = 2 * dot(v, m) * m - v;
    if (l.z <= 0) continue;
    double phi = std::atan2(l.y, l.x);
    if (phi < 0) phi += 2 * kPi;
    const int ci = std::min(n_cos - 1, static_cast<int>(l.z * n_cos));
    const int pi = std::min(n_phi - 1, static_cast<int>(phi / (2 * kPi) * n_phi));
    counts[ci * n_phi + pi] += 1;
  }
  for (int ci = 0; ci < n_cos; ++ci)
    for (int pj = 0; pj < n_phi; ++pj) {
      // Midpoint rule inside the bin: sub x sub points.
      double expected = 0;
      const double dc = 1.0 / (n_cos * sub), dp = 2 * kPi / (n_phi * sub);
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          const Vec3 l = from_angles((ci * sub + a + 0.5) * dc, (pj * sub + b + 0.5) * dp);
          expected += ggx_reflection_pdf(v, l, alpha) * dc * dp;
        }
      const double observed = counts[ci * n_phi + pj] / samples;
      // Binomial standard deviation of the bin's fraction, plus a little for the quadrature.
      const double sigma = std::sqrt(std::max(expected, 1e-6) / samples);
      EXPECT_NEAR(observed, expected, 5 * sigma + 2e-4) << "bin cos " << ci << " phi " << pj;
    }
}

}  // namespace
}  // namespace snell::render
