// `snell explain` from the command line: the text tree, JSON valid against docs/explain.schema.json
// (checked by python3-jsonschema), the layer files, and bad input (one error line, exit code 2, no file).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../cli/run_command.hpp"

namespace snell {
namespace {

namespace fs = std::filesystem;

const std::string kScenes = std::string(SNELL_SOURCE_DIR) + "/scenes/";

test::Outcome explain(const std::string& args) {
  return test::run_command(std::string(SNELL_BINARY) + " explain " + args);
}

fs::path temp(const std::string& name) {
  return fs::temp_directory_path() / ("snell-explain-" + std::to_string(getpid()) + "-" + name);
}

int lines(const std::string& s) {
  int n = 0;
  for (const char c : s) n += c == '\n';
  return n;
}

TEST(ExplainCliTest, TextTreeNamesTheGlassSphereAndItsChildren) {
  const auto r = explain(kScenes + "explain-glass.pov -w 80 -h 60 --pixel 40,30");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("camera ray, level 1"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("sphere \"Glass\" (" + kScenes + "explain-glass.pov:13:1"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("refracted ray, level 2"), std::string::npos);
  EXPECT_NE(r.output.find("reflected ray, level 2"), std::string::npos);
  EXPECT_NE(r.output.find("shadow ray to light 1"), std::string::npos);
}

TEST(ExplainCliTest, JsonValidatesAgainstTheSchema) {
  const fs::path json = temp("tree.json"), svg = temp("tree.svg");
  const auto r = explain(kScenes + "explain-shadows.pov -w 80 -h 60 --pixel 30,40 --json " + json.string() +
                         " --svg " + svg.string());
  ASSERT_EQ(r.code, 0) << r.output;
  ASSERT_TRUE(fs::exists(json));
  ASSERT_TRUE(fs::exists(svg));
  const std::string schema = std::string(SNELL_SOURCE_DIR) + "/docs/explain.schema.json";
  const auto check = test::run_command(
      "/usr/bin/python3 -c \"import json, sys, jsonschema; "
      "jsonschema.validate(json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))); print('valid')\" " +
      json.string() + " " + schema);
  EXPECT_EQ(check.code, 0) << check.output;
  EXPECT_NE(check.output.find("valid"), std::string::npos);
  // A document that breaks the schema is refused, so the check can fail.
  std::ofstream(json) << R"({"scene": "x", "pixel": [1, 2], "sample": 0, "image_point": [0, 0],
    "colour": [0, 0, 0], "ray": {"kind": "sideways"}})";
  const auto bad = test::run_command(
      "/usr/bin/python3 -c \"import json, sys, jsonschema; "
      "jsonschema.validate(json.load(open(sys.argv[1])), json.load(open(sys.argv[2])))\" " +
      json.string() + " " + schema + " 2>/dev/null");
  EXPECT_NE(bad.code, 0);
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("camera"), std::string::npos);
  fs::remove(json);
  fs::remove(svg);
}

TEST(ExplainCliTest, LayersGoIntoOneMultiLayerExrAndLegendPngs) {
  const fs::path base = temp("layers");
  const auto r = explain(kScenes +
                         "explain-glass.pov -w 40 -h 30 --aov depth,object,cost --aov-png "
                         "--heatmap cost --split-bounces 1 --stats -o " +
                         base.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("most tested objects"), std::string::npos) << r.output;
  const std::string b = base.string();
  for (const std::string suffix : {".exr", ".depth.png", ".object.png", ".cost.png", ".heatmap-cost.png",
                                   ".direct.png", ".refraction1.png"}) {
    EXPECT_TRUE(fs::exists(b + suffix)) << suffix;
    fs::remove(b + suffix);
  }
  for (const std::string suffix : {".reflection1.png", ".deeper.png"}) fs::remove(b + suffix);
}

TEST(ExplainCliTest, BadInputGivesOneErrorLineAndExitCode2AndNoFile) {
  const fs::path json = temp("bad.json");
  auto r = explain(kScenes + "explain-glass.pov -w 80 -h 60 --pixel 80,10 --json " + json.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("outside the 80x60 image"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(json));

  const fs::path base = temp("bad");
  r = explain(kScenes + "explain-glass.pov -w 8 -h 6 --aov depth,colour -o " + base.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--aov colour: unknown layer"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(base.string() + ".exr"));

  const std::string nowhere = "/nonexistent-folder-" + std::to_string(getpid()) + "/tree.svg";
  r = explain(kScenes + "explain-glass.pov -w 8 -h 6 --pixel 1,1 --json " + json.string() + " --svg " +
              nowhere);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--svg"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(json));  // nothing written, not even the outputs that could have been
}

}  // namespace
}  // namespace snell
