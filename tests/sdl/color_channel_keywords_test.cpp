// Channel keywords after a bare colour change that colour, as in POV-Ray's Parse_Colour
// (interior/crystal.pov: `pigment { White filter 0.95 }` is a glass-clear white).
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

TEST(SdlColorChannels, KeywordsAfterAColourIdentifierModifyIt) {
  const auto s = test::parse(R"(#declare White = rgb 1;
    sphere { 0, 1 pigment { White filter 0.95 } }
    sphere { 0, 1 pigment { White red 0.5 transmit 0.2 } }
    sphere { 0, 1 pigment { color White filter 0.95 } })");
  ASSERT_EQ(s.objects.size(), 3u);
  const material::Rgbft a = test::solid_color(*s.objects[0]);
  EXPECT_DOUBLE_EQ(a.rgb.r, 1.0);
  EXPECT_DOUBLE_EQ(a.rgb.b, 1.0);
  EXPECT_DOUBLE_EQ(a.filter, 0.95);
  const material::Rgbft b = test::solid_color(*s.objects[1]);
  EXPECT_DOUBLE_EQ(b.rgb.r, 0.5);
  EXPECT_DOUBLE_EQ(b.rgb.g, 1.0);
  EXPECT_DOUBLE_EQ(b.transmit, 0.2);
  EXPECT_EQ(test::solid_color(*s.objects[2]), a);
}

}  // namespace
}  // namespace snell::sdl
