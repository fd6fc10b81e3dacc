// `global_settings { radiosity {} }` (POV-Ray 3.7 reference, "Radiosity Basics"): settings are read with
// POV-Ray's defaults, and unknown keywords are errors with a position.
#include <gtest/gtest.h>

#include <string>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

TEST(SdlRadiosity, NoBlockMeansNoRadiosity) {
  EXPECT_FALSE(test::parse("global_settings { assumed_gamma 1 }").settings.radiosity);
}

TEST(SdlRadiosity, EmptyBlockTakesPovRayDefaults) {
  const auto s = test::parse("global_settings { radiosity { } }");
  ASSERT_TRUE(s.settings.radiosity);
  const scene::RadiositySettings& r = *s.settings.radiosity;
  EXPECT_EQ(r.count, 35);
  EXPECT_EQ(r.recursion_limit, 2);
  EXPECT_DOUBLE_EQ(r.error_bound, 1.8);
  EXPECT_DOUBLE_EQ(r.brightness, 1.0);
  EXPECT_FALSE(r.normal);
}

TEST(SdlRadiosity, SettingsOfRadiosity2AreRead) {
  const auto s = test::parse(R"(global_settings { radiosity {
      pretrace_start 0.08 pretrace_end 0.04 count 50, 400 nearest_count 5 error_bound 0.2
      recursion_limit 1 low_error_factor .5 gray_threshold 0.0 minimum_reuse 0.015 maximum_reuse 0.1
      brightness 1.5 adc_bailout 0.01/2 normal on media off always_sample off } })");
  const scene::RadiositySettings& r = *s.settings.radiosity;
  EXPECT_EQ(r.count, 50);
  EXPECT_EQ(r.direction_pool, 400);
  EXPECT_EQ(r.recursion_limit, 1);
  EXPECT_DOUBLE_EQ(r.error_bound, 0.2);
  EXPECT_DOUBLE_EQ(r.brightness, 1.5);
  EXPECT_DOUBLE_EQ(r.adc_bailout, 0.005);
  EXPECT_DOUBLE_EQ(r.maximum_reuse, 0.1);
  EXPECT_TRUE(r.normal);
  EXPECT_FALSE(r.media);
  EXPECT_FALSE(r.always_sample);
}

TEST(SdlRadiosity, BadSettingsAreErrors) {
  EXPECT_NE(
      test::error_of("global_settings { radiosity { cuont 3 } }").find("unknown radiosity keyword 'cuont'"),
      std::string::npos);
  EXPECT_NE(test::error_of("global_settings { radiosity { count 0 } }").find("count"), std::string::npos);
  EXPECT_NE(test::error_of("global_settings { radiosity { recursion_limit 200 } }").find("recursion_limit"),
            std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
