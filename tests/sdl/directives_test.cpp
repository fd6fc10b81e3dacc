#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sdl_test_util.hpp"
#include "snell/geometry/sphere.hpp"

namespace snell::sdl {
namespace {

double radius(const scene::Scene& s, size_t i) {
  return dynamic_cast<const geometry::Sphere*>(s.objects.at(i)->shape.get())->radius();
}

TEST(SdlDirectives, WhileLoopRunsTheCountedNumberOfTimes) {
  const auto scene = test::parse(R"(
    #declare I = 0;
    #while (I < 7)
      sphere { <I, 0, 0>, 0.1 + I }
      #declare I = I + 1;
    #end
  )");
  ASSERT_EQ(scene.objects.size(), 7u);
  EXPECT_DOUBLE_EQ(radius(scene, 6), 6.1);
}

TEST(SdlDirectives, NestedWhileLoops) {
  const auto scene = test::parse(R"(
    #declare I = 0;
    #while (I < 3)
      #declare J = 0;
      #while (J < 4) sphere { 0, 1 } #declare J = J + 1; #end
      #declare I = I + 1;
    #end
  )");
  EXPECT_EQ(scene.objects.size(), 12u);
}

TEST(SdlDirectives, IfElseifElseAndIfdef) {
  const auto scene = test::parse(R"(
    #declare A = 2;
    #if (A = 1) sphere { 0, 1 } #elseif (A = 2) sphere { 0, 2 } #else sphere { 0, 3 } #end
    #if (0) sphere { 0, 4 } #else sphere { 0, 5 } #end
    #ifdef (A) sphere { 0, 6 } #end
    #ifndef (B) sphere { 0, 7 } #end
    #undef A
    #ifdef (A) sphere { 0, 8 } #end
  )");
  ASSERT_EQ(scene.objects.size(), 4u);
  EXPECT_DOUBLE_EQ(radius(scene, 0), 2);
  EXPECT_DOUBLE_EQ(radius(scene, 1), 5);
  EXPECT_DOUBLE_EQ(radius(scene, 2), 6);
  EXPECT_DOUBLE_EQ(radius(scene, 3), 7);
}

TEST(SdlDirectives, SwitchCaseRangeBreak) {
  const auto scene = test::parse(R"(
    #declare I = 0;
    #while (I < 4)
      #switch (I)
        #case (0) sphere { 0, 10 } #break
        #range (1, 2) sphere { 0, 20 } #break
        #else sphere { 0, 30 }
      #end
      #declare I = I + 1;
    #end
  )");
  ASSERT_EQ(scene.objects.size(), 4u);
  EXPECT_DOUBLE_EQ(radius(scene, 0), 10);
  EXPECT_DOUBLE_EQ(radius(scene, 1), 20);
  EXPECT_DOUBLE_EQ(radius(scene, 2), 20);
  EXPECT_DOUBLE_EQ(radius(scene, 3), 30);
}

TEST(SdlDirectives, MacrosBindParametersAsLocalsAndReturnValues) {
  const auto scene = test::parse(R"(
    #macro Square(X) (X * X) #end
    #macro Ball(P, R) #local Twice = 2 * R; sphere { P, Twice } #end
    #declare Twice = 100;
    sphere { 0, Square(3) + 1 }
    Ball(<1, 2, 3>, 0.5)
    sphere { 0, Twice }
  )");
  ASSERT_EQ(scene.objects.size(), 3u);
  EXPECT_DOUBLE_EQ(radius(scene, 0), 10);
  EXPECT_DOUBLE_EQ(radius(scene, 1), 1);
  EXPECT_DOUBLE_EQ(radius(scene, 2), 100);  // the macro's #local did not touch the global
}

TEST(SdlDirectives, RecursiveMacroStopsAtItsBaseCase) {
  const auto scene = test::parse(R"(
    #macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
    sphere { 0, Fact(5) }
  )");
  EXPECT_DOUBLE_EQ(radius(scene, 0), 120);
}

TEST(SdlDirectives, RunawayRecursionIsAnError) {
  const std::string e = test::error_of("#macro F(N) F(N + 1) #end\nsphere { 0, F(1) }");
  EXPECT_NE(e.find("nested deeper"), std::string::npos) << e;
}

TEST(SdlDirectives, WhileLimitIsAnError) {
  ParseOptions options;
  options.max_while_iterations = 1000;
  try {
    parse_scene_string("#while (1)\n#end", "loop.pov", options);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("loop.pov:1:1: error: #while loop ran more than 1000"),
              std::string::npos)
        << e.what();
  }
}

TEST(SdlDirectives, DebugAndWarningGoToTheMessageSink) {
  std::vector<std::string> messages;
  test::parse("#debug concat(\"hello \", str(2, 0, 0))\n#warning \"careful\"", &messages);
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0], "hello 2");
  EXPECT_EQ(messages[1].rfind("test.pov:2:1: warning: careful", 0), 0u) << messages[1];
}

TEST(SdlDirectives, IncludeSearchesTheLibraryPathAndRestoresVersion) {
  const auto dir = std::filesystem::temp_directory_path() / "snell_sdl_include_test";
  std::filesystem::create_directories(dir / "lib");
  std::ofstream(dir / "lib" / "part.inc") << "#version 3.5;\n#declare PartRadius = version;\n";
  std::ofstream(dir / "scene.pov") << "#version 3.7;\n#include \"part.inc\"\nsphere { 0, PartRadius }\n"
                                      "sphere { 0, version }\n";
  ParseOptions options;
  options.library_paths.push_back(dir / "lib");
  options.message_sink = [](const std::string&) {};
  const auto scene = parse_scene_file(dir / "scene.pov", options);
  EXPECT_DOUBLE_EQ(radius(scene, 0), 3.5);
  EXPECT_DOUBLE_EQ(radius(scene, 1), 3.7);
}

TEST(SdlDirectives, PovRayIncludeFilesParse) {
  for (const char* inc : {"colors.inc", "finish.inc", "metals.inc", "golds.inc", "glass.inc", "textures.inc",
                          "stones.inc", "woods.inc", "shapes.inc", "math.inc", "transforms.inc"}) {
    SCOPED_TRACE(inc);
    std::vector<std::string> messages;
    const std::string e = [&] {
      try {
        test::parse(std::string("#include \"") + inc + "\"", &messages);
      } catch (const ParseError& err) {
        return std::string(err.what());
      }
      return std::string();
    }();
    RecordProperty(inc, e.empty() ? "ok" : e.substr(0, 200));
    const std::string name = inc;
    if (name == "colors.inc" || name == "finish.inc" || name == "metals.inc" || name == "golds.inc" ||
        name == "glass.inc") {
      EXPECT_EQ(e, "");
    }
  }
}

}  // namespace
}  // namespace snell::sdl
