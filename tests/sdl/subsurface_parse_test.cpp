// `subsurface {}` in finish and global_settings (POV-Ray 3.7 reference, "Subsurface Light Transport") and
// snell's `material "name"` shortcut for Jensen et al. 2001's measured table.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

using namespace snell;

TEST(SdlSubsurface, FinishAndGlobalSettingsAreRead) {
  const auto s = sdl::test::parse(R"(
    global_settings { mm_per_unit 40 subsurface { samples 400, 40 radiosity off } }
    sphere { 0, 1 pigment { rgb 1 } finish { diffuse 0.8 subsurface { translucency <0.4562, 0.3811, 0.3325> } } }
    sphere { 0, 1 pigment { rgb 1 } finish { subsurface { material "Marble" samples 10, 2 } } })");
  EXPECT_DOUBLE_EQ(s.settings.mm_per_unit, 40);
  EXPECT_EQ(s.settings.subsurface_samples, 400);
  EXPECT_EQ(s.settings.subsurface_single_samples, 40);
  const auto& f0 = s.objects[0]->texture->finish;
  EXPECT_TRUE(f0.subsurface);
  EXPECT_DOUBLE_EQ(f0.subsurface_translucency.g, 0.3811);
  EXPECT_FALSE(f0.subsurface_material.has_value());
  const auto& f1 = s.objects[1]->texture->finish;
  ASSERT_TRUE(f1.subsurface_material.has_value());
  EXPECT_DOUBLE_EQ(f1.subsurface_material->sigma_s_prime.r, 2.19);  // Jensen et al. 2001, marble
  EXPECT_DOUBLE_EQ(f1.subsurface_material->eta, 1.5);
}

TEST(SdlSubsurface, DefaultsFollowPovRay) {
  const auto s = sdl::test::parse("sphere { 0, 1 }");
  EXPECT_DOUBLE_EQ(s.settings.mm_per_unit, 10);
  EXPECT_FALSE(s.objects[0]->texture->finish.subsurface);
}

TEST(SdlSubsurface, UnknownMaterialIsAnError) {
  const std::string error =
      sdl::test::error_of("sphere { 0, 1 finish { subsurface { jensen \"granite\" } } }");
  EXPECT_NE(error.find("test.pov:1:"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown subsurface material \"granite\""), std::string::npos) << error;
}
