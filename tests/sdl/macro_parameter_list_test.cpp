// POV-Ray 3.7 reads a macro's parameter list with optional commas and an optional trailing comma;
// shapes3.inc relies on both (checked against `povray`).
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
  EXPECT_NE(test::error_of("#macro M(A; B) #end").find("expected ',' or ')'"), std::string::npos);
  EXPECT_NE(test::error_of("#macro M(A,,B) #end").find("expected ',' or ')'"), std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
