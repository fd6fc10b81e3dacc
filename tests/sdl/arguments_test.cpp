// Arguments of scene items are read as POV-Ray's Parse_Float/Parse_Vector read them: arithmetic only, with
// optional commas, so a `<` after a value starts the next vector instead of a comparison.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"
#include "snell/geometry/box.hpp"
#include "snell/geometry/sphere.hpp"

namespace snell::sdl {
namespace {

TEST(SdlArguments, VectorsWithoutCommaAreTwoArguments) {
  const auto scene = test::parse("box { <-1,-1,-1><1,2,3> }");
  ASSERT_EQ(scene.objects.size(), 1u);
  const math::Bounds3 b = scene.objects[0]->shape->bounds();
  EXPECT_DOUBLE_EQ(b.lo.x, -1);
  EXPECT_DOUBLE_EQ(b.hi.z, 3);
}

TEST(SdlArguments, FloatFollowedByVectorWithoutComma) {
  const auto scene = test::parse("sphere { <0,1,0> 2 }");
  const auto* s = dynamic_cast<const geometry::Sphere*>(scene.objects.at(0)->shape.get());
  ASSERT_NE(s, nullptr);
  EXPECT_DOUBLE_EQ(s->radius(), 2);
  EXPECT_DOUBLE_EQ(s->center().y, 1);
}

TEST(SdlArguments, ComparisonsStillWorkInParenthesesAndDirectives) {
  const auto scene = test::parse(
      "#declare A = 2;\n"
      "#declare B = (A < 3 ? 5 : 6);\n"
      "#while (A < 4) #declare A = A + 1; #end\n"
      "#if (A = 4 & B = 5) sphere { 0, (B > 4) + A } #end\n");
  const auto* s = dynamic_cast<const geometry::Sphere*>(scene.objects.at(0)->shape.get());
  ASSERT_NE(s, nullptr);
  EXPECT_DOUBLE_EQ(s->radius(), 5);
}

}  // namespace
}  // namespace snell::sdl
