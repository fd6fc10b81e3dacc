// The parser's guards against runaway scenes (ParseOptions::max_*): each breach is a located ParseError,
// never a hang, a crash or memory without bound.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

std::string error_with(const std::string& text, const ParseOptions& options) {
  try {
    parse_scene_string(text, "limits.pov", options);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

ParseOptions quiet() {
  ParseOptions o;
  o.message_sink = [](const std::string&) {};
  return o;
}

TEST(SdlLimits, MacroThatCallsItselfTwicePerLevelHitsTheTokenBudget) {
  // 2^200 calls: under the macro depth limit at every moment, so only the token budget stops it.
  ParseOptions o = quiet();
  o.max_tokens = 100'000;
  const std::string e = error_with("#macro M(N) #if (N < 200) M(N + 1) M(N + 1) #end #end M(0)", o);
  EXPECT_NE(e.find("limits.pov:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("more than 100000 tokens"), std::string::npos) << e;
}

TEST(SdlLimits, NestedLoopsHitTheTokenBudget) {
  ParseOptions o = quiet();
  o.max_tokens = 50'000;
  const std::string loops =
      "#declare I = 0; #while (I < 1000) #declare J = 0; #while (J < 1000) #declare J = J + 1; #end "
      "#declare I = I + 1; #end";
  EXPECT_NE(error_with(loops, o).find("ParseOptions::max_tokens"), std::string::npos);
  o.max_tokens = 100'000'000;
  EXPECT_EQ(error_with("#declare I = 0; #while (I < 100) #declare I = I + 1; #end", o), "");
}

TEST(SdlLimits, ArraySizeIsBounded) {
  ParseOptions o = quiet();
  o.max_array_elements = 1000;
  EXPECT_NE(error_with("#declare A = array[1001];", o).find("array larger than 1000"), std::string::npos);
  // Each size alone is allowed; their product is not (and must not overflow on the way).
  EXPECT_NE(error_with("#declare A = array[1000][1000][1000][1000][1000];", o).find("array larger than 1000"),
            std::string::npos);
  EXPECT_EQ(error_with("#declare A = array[10][100];", o), "");
  // POV-Ray 3.7 allows at most 5 dimensions (parser.h, POV_ARRAY::kMaxDimensions).
  EXPECT_NE(error_with("#declare A = array[1][1][1][1][1][1];", o).find("at most 5 dimensions"),
            std::string::npos);
}

TEST(SdlLimits, StringLengthIsBounded) {
  ParseOptions o = quiet();
  o.max_string_length = 1000;
  const std::string doubling = "#declare S = \"0123456789\"; #while (1) #declare S = concat(S, S); #end";
  const std::string e = error_with(doubling, o);
  EXPECT_NE(e.find("longer than 1000 characters"), std::string::npos) << e;
}

TEST(SdlLimits, ObjectTreesThatDoubleThemselvesAreBounded) {
  ParseOptions o = quiet();
  o.max_objects = 10'000;
  std::string doubling = "#declare A = sphere { 0, 1 }\n";
  for (int i = 0; i < 40; ++i) doubling += "#declare A = union { object { A } object { A } }\n";
  const std::string e = error_with(doubling, o);
  // Twelve doublings make 2^13 - 1 = 8191 nodes; the 13th (line 14) would make 16383.
  EXPECT_NE(e.find("limits.pov:14:"), std::string::npos) << e;
  EXPECT_NE(e.find("more than 10000 objects"), std::string::npos) << e;
  std::string clips = "#declare A = sphere { 0, 1 }\n";
  for (int i = 0; i < 40; ++i) clips += "#declare A = sphere { 0, 1 clipped_by { A A } }\n";
  EXPECT_NE(error_with(clips, o).find("ParseOptions::max_objects"), std::string::npos);
}

TEST(SdlLimits, DirectivesNestedThroughAnUnfinishedDeclareAreBounded) {
  // Found by libFuzzer (fuzz/corpus/regressions/while-around-unfinished-declare.pov): each iteration starts
  // a #declare whose value is still being read when the #while's #end loops back, so the directives nest
  // one level deeper per iteration until the stack overflowed.
  const std::string e = error_with(
      "#declare N = 2;\n#while (N < 100)\n  #declare N = #switch\n  #if (mod(N, 3) = 0) box { N, N + 1 } "
      "#end\n"
      "#end\n",
      quiet());
  EXPECT_NE(e.find("limits.pov:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("nested more than 256 levels deep"), std::string::npos) << e;
}

}  // namespace
}  // namespace snell::sdl
