#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

TEST(SdlErrors, MessageHasLocationSourceLineAndCaret) {
  const std::string e = test::error_of("sphere { 0, 1 }\n  sphere { 0, 1 frobnicate }\n");
  EXPECT_EQ(e,
            "test.pov:2:17: error: unexpected 'frobnicate' in object\n  sphere { 0, 1 frobnicate }\n         "
            "       ^");
}

TEST(SdlErrors, CommonMistakes) {
  const auto has = [](const std::string& text, const std::string& part) {
    const std::string e = test::error_of(text);
    EXPECT_NE(e.find(part), std::string::npos) << "got: " << e;
  };
  has("spheer { 0, 1 }", "test.pov:1:1: error: unknown keyword 'spheer'");
  has("sphere { 0, 1", "unexpected end of file");
  has("sphere { 0, 1 / 0 }", "test.pov:1:15: error: division by zero");
  has("#declare S = \"abc\";\nsphere { 0, S }",
      "test.pov:2:13: error: expected a float, vector or color, but 'S' is a string");
  has("sphere { <1, 2>, <1, 2, 3> }", "expected a float, found a vector");
  has("#if (1) sphere { 0, 1 }", "no matching #end");
  has("#end", "#end without a matching");
  has("#include \"no_such_file.inc\"", "test.pov:1:1: error: cannot find include file \"no_such_file.inc\"");
  has("#error \"stop here\"", "test.pov:1:1: error: #error: stop here");
  has("sphere { 0, \"unterminated }", "unterminated string");
  has("/* never closed", "unterminated comment");
  has("sphere { 0, 1 pigment { facets } }", "the facets pattern can only be used in a normal");
  has("sphere { 0, 1 pigment { tiling 6 } }", "tiling 6 is not supported yet");
  has("sphere { 0, sqrt(-1) }", "sqrt: negative argument");
  has("#macro M(A, B) sphere { A, B } #end M(1)", "macro M takes 2 parameter(s), called with 1");
  // An all-zero column only warns and becomes 1 (POV-Ray's Parse_Matrix); two equal columns stay singular.
  has("sphere { 0, 1 matrix <1,1,0, 1,1,0, 0,0,1, 0,0,0> }", "singular matrix");
  has("camera { location 0 look_at 0 }", "camera location and look_at are the same point");
  has("cylinder { 0, 0, 1 }", "cylinder base and cap are the same point");
  has("sphere { 0, 1 } @", "unexpected character '@'");
  has("sphere { 0, Undeclared }", "test.pov:1:13: error: unknown identifier 'Undeclared'");
}

TEST(SdlErrors, ErrorsInIncludedFilesNameTheIncludeSite) {
  const auto dir = std::filesystem::temp_directory_path() / "snell_sdl_error_include";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.inc") << "#declare A = 1;\n#declare B = A / 0;\n";
  std::ofstream(dir / "main.pov") << "// scene\n#include \"bad.inc\"\n";
  try {
    parse_scene_file(dir / "main.pov", ParseOptions{});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.inc:2:16: error: division by zero"), std::string::npos) << m;
    EXPECT_NE(m.find("note: included from " + (dir / "main.pov").string() + ":2:1"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace snell::sdl

namespace snell::sdl {
namespace {

std::string nested_error(const std::string& text) {
  try {
    test::parse(text);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

TEST(SdlNestingLimit, DeepInputIsAnErrorNotACrash) {
  EXPECT_NE(nested_error("sphere { 0, " + std::string(100000, '(') + "1").find("nested more than"),
            std::string::npos);
  EXPECT_NE(nested_error("sphere { 0, " + std::string(100000, '-') + "1 }").find("nested more than"),
            std::string::npos);
  std::string unions;
  for (int i = 0; i < 5000; ++i) unions += "union { ";
  EXPECT_NE(nested_error(unions).find("nested more than"), std::string::npos);
  std::string pigments = "sphere { 0, 1 ";
  for (int i = 0; i < 5000; ++i) pigments += "pigment { checker ";
  EXPECT_NE(nested_error(pigments).find("nested more than"), std::string::npos);
}

TEST(SdlNestingLimit, ModerateNestingIsFine) {
  EXPECT_EQ(nested_error("sphere { 0, " + std::string(50, '(') + "1" + std::string(50, ')') + " }"), "");
}

}  // namespace
}  // namespace snell::sdl
