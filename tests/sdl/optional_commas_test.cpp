// Places where POV-Ray 3.7 treats commas as optional and real scenes leave them out (checked against
// `povray`): a macro's parameter list (shapes3.inc) and area_light's arguments (bsp/Tango.pov).
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

TEST(SdlMacroParameters, CommasAreOptionalAndMayTrail) {
  std::vector<std::string> messages;
  test::parse("#macro M(A, B C,) #debug str(A * 100 + B * 10 + C, 0, 0) #end M(1, 2, 3)", &messages);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0], "123");
}

TEST(SdlMacroParameters, OtherSeparatorsAreErrors) {
  EXPECT_NE(test::error_of("#macro M(A; B) #end").find("expected a parameter name or ')'"), std::string::npos);
  EXPECT_NE(test::error_of("#macro M(A,,B) #end").find("expected a parameter name or ')'"), std::string::npos);
}

TEST(SdlAreaLight, CommasAreOptional) {
  const scene::Scene scene =
      test::parse("light_source { 0 rgb 1 area_light <8,0,0> <0,0,8> 8, 4 adaptive 2 jitter }");
  ASSERT_EQ(scene.lights.size(), 1u);
  const scene::Light& light = scene.lights[0];
  EXPECT_TRUE(light.area);
  EXPECT_EQ(light.axis1.x, 8);
  EXPECT_EQ(light.axis2.z, 8);
  EXPECT_EQ(light.size1, 8);
  EXPECT_EQ(light.size2, 4);
}

}  // namespace
}  // namespace snell::sdl
