// Fresnel, Snell and TIR against ../shared/reference-values.md section 3 (de Greve 2006).
#include "snell/render/optics.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::render {
namespace {

double cos_deg(double d) {
  return std::cos(math::radians(d));
}

TEST(FresnelTest, AirToGlassMatchesReferenceTable) {
  struct Row {
    double angle, rs, rp, r;
  };
  for (const Row& row : {Row{0, 0.04, 0.04, 0.04}, Row{30, 0.057796, 0.025249, 0.041523},
                         Row{45, 0.092013, 0.008466, 0.050240}, Row{60, 0.176571, 0.001802, 0.089187},
                         Row{80, 0.538595, 0.236814, 0.387704}}) {
    const FresnelTerms t = fresnel_terms(cos_deg(row.angle), 1.0, 1.5);
    EXPECT_NEAR(t.rs, row.rs, 1e-6) << row.angle;
    EXPECT_NEAR(t.rp, row.rp, 1e-6) << row.angle;
    EXPECT_NEAR(fresnel_dielectric(cos_deg(row.angle), 1.0, 1.5), row.r, 1e-6) << row.angle;
  }
}

TEST(FresnelTest, GlassToAirAndWater) {
  EXPECT_NEAR(fresnel_dielectric(cos_deg(30), 1.5, 1.0), 0.055190, 1e-6);
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.33), 0.020059, 1e-6);
  EXPECT_NEAR(fresnel_dielectric(cos_deg(45), 1.0, 1.33), 0.027521, 1e-6);
  EXPECT_NEAR(fresnel_dielectric(cos_deg(45), 1.33, 1.0), 0.134187, 1e-6);
}

TEST(FresnelTest, BrewsterAngleHasNoPPolarisedReflection) {
  const FresnelTerms t = fresnel_terms(cos_deg(56.309932), 1.0, 1.5);
  EXPECT_NEAR(t.rp, 0.0, 1e-9);
  EXPECT_NEAR(t.rs, 0.147929, 1e-6);
}

TEST(FresnelTest, TotalInternalReflectionBeyondCriticalAngle) {
  EXPECT_FALSE(total_internal_reflection(cos_deg(41.80), 1.5, 1.0));
  EXPECT_TRUE(total_internal_reflection(cos_deg(41.82), 1.5, 1.0));
  EXPECT_FALSE(total_internal_reflection(cos_deg(48.75), 1.33, 1.0));
  EXPECT_TRUE(total_internal_reflection(cos_deg(48.76), 1.33, 1.0));
  EXPECT_DOUBLE_EQ(fresnel_dielectric(cos_deg(60), 1.5, 1.0), 1.0);
}

TEST(FresnelTest, SchlickApproximation) {
  EXPECT_NEAR(fresnel_schlick(cos_deg(45), 1.0, 1.5), 0.042069, 1e-6);
  EXPECT_NEAR(fresnel_schlick(cos_deg(60), 1.0, 1.5), 0.07, 1e-6);
  EXPECT_NEAR(fresnel_schlick(cos_deg(80), 1.0, 1.5), 0.409910, 1e-6);
}

TEST(RefractTest, VectorsMatchReference) {
  const double h = std::sqrt(0.5);
  const auto t = refract({h, -h, 0}, {0, 1, 0}, 1 / 1.5);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(t->x, 0.4714045208, 1e-9);
  EXPECT_NEAR(t->y, -0.8819171037, 1e-9);
  EXPECT_NEAR(t->z, 0.0, 1e-12);
  EXPECT_FALSE(refract({h, -h, 0}, {0, 1, 0}, 1.5).has_value());
  const auto t2 = refract({0.5, -std::sqrt(3.0) / 2, 0}, {0, 1, 0}, 1.5);
  ASSERT_TRUE(t2.has_value());
  EXPECT_NEAR(t2->x, 0.75, 1e-9);
  EXPECT_NEAR(t2->y, -0.6614378278, 1e-9);
}

TEST(RefractTest, SnellAngle) {
  const double a = math::radians(45);
  const auto t = refract({std::sin(a), -std::cos(a), 0}, {0, 1, 0}, 1 / 1.33);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(std::asin(t->x) / math::kDegreesToRadians, 32.117631, 1e-5);
}

}  // namespace
}  // namespace snell::render
