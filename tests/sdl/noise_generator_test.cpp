// `noise_generator 1|2|3` in patterns and in global_settings (POV-Ray 3.7 reference, "noise_generator"):
// pattern functions against the values POV-Ray 3.7.0 itself printed (Debian 12 `povray`, #debug of
// str(F(x, y, z), 0, 9) for `#declare F = function { pattern { ... } }`).
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "sdl_test_util.hpp"

using namespace snell;

namespace {

/// The value of `function { pattern { <pattern> } }` at `p`, parsed after `prelude`.
double pattern_value(const std::string& pattern, const math::Vec3& p, const std::string& prelude = "") {
  const std::string point = std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z);
  const scene::Scene s = sdl::test::parse(prelude + "#declare F = function { pattern { " + pattern +
                                          " } }\n"
                                          "plane { y, 0 pigment { rgb <F(" +
                                          point + "), 0, 0> } }");
  return sdl::test::solid_color(*s.objects.front()).rgb.r;
}

const std::array<math::Vec3, 3> kPoints = {math::Vec3{0.3, 0.7, 1.1}, math::Vec3{-2.25, 0.4, 3.6},
                                           math::Vec3{5.1, -1.3, 0.2}};

/// POV-Ray's values at kPoints, one row per pattern.
struct Expected {
  const char* pattern;
  std::array<double, 3> values;
};

const Expected kPovrayValues[] = {
    {"bozo noise_generator 1", {0.855310988, 0.166269551, 0.504273678}},
    {"bozo noise_generator 2", {0.689585217, 0.352054260, 0.517627548}},
    {"spotted noise_generator 3", {0.573302354, 0.423038085, 0.429105542}},
    {"granite noise_generator 1", {0.246679143, 0.298585332, 0.238070130}},
    {"granite noise_generator 3", {0.652755880, 0.354843785, 0.261584489}},
    {"wrinkles noise_generator 1", {0.669234674, 0.339634992, 0.440868563}},
    {"dents noise_generator 3", {0.188430489, 0.075707413, 0.079011875}},
    {"marble turbulence 0.8 noise_generator 1", {0.726283168, 0.561855522, 0.416308904}},
    {"agate noise_generator 3", {0.974836195, 0.832328008, 0.923864125}},
};

}  // namespace

TEST(NoiseGenerator, PatternsMatchPovrayForEachGenerator) {
  for (const Expected& e : kPovrayValues)
    for (size_t i = 0; i < kPoints.size(); ++i)
      EXPECT_NEAR(pattern_value(e.pattern, kPoints[i]), e.values[i], 1e-6) << e.pattern << " at point " << i;
}

TEST(NoiseGenerator, GlobalSettingsSetTheDefaultOfPatternsThatNameNone) {
  const std::string global1 = "global_settings { noise_generator 1 }\n";
  // bozo without its own generator follows the scene's (generator 1 values above)...
  EXPECT_NEAR(pattern_value("bozo", kPoints[0], global1), 0.855310988, 1e-6);
  // ...one that names its own keeps it, and without global_settings 3.7's default is 2.
  EXPECT_NEAR(pattern_value("bozo noise_generator 2", kPoints[0], global1), 0.689585217, 1e-6);
  EXPECT_NEAR(pattern_value("bozo", kPoints[0]), 0.689585217, 1e-6);
}

TEST(NoiseGenerator, RejectsAGeneratorPovrayDoesNotHave) {
  EXPECT_NE(sdl::test::error_of("plane { y, 0 pigment { bozo noise_generator 4 } }")
                .find("noise_generator must be 1, 2 or 3"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("global_settings { noise_generator 0 }").find("noise_generator must be"),
            std::string::npos);
}
