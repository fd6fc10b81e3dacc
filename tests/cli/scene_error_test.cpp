// Scene errors reach the user as one `file:line:col: error:` line, the source line and a caret, with exit
// code 1 (DESIGN.md, "Errors"; docs/cli.md, exit codes).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"

namespace snell {
namespace {

using test::Outcome;

Outcome render_scene(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto scene = dir / (name + ".pov");
  std::ofstream(scene) << text;
  return test::run_command(std::string(SNELL_BINARY) + " +I" + scene.string() + " +O" +
                           (dir / (name + ".png")).string() + " +W16 +H12 -D --quiet");
}

/// The first line names file:line:col and says "error:"; a caret line follows.
void expect_located_error(const Outcome& r, const std::string& location, const std::string& words) {
  EXPECT_EQ(r.code, 1) << r.output;
  const std::string first = r.output.substr(0, r.output.find('\n'));
  EXPECT_NE(first.find(location), std::string::npos) << r.output;
  EXPECT_NE(first.find("error:"), std::string::npos) << r.output;
  EXPECT_NE(first.find(words), std::string::npos) << r.output;
  EXPECT_NE(r.output.find('^'), std::string::npos) << r.output;
}

TEST(SceneErrorTest, UnknownKeywordIsLocatedWithCaret) {
  const Outcome r = render_scene("snell_unknown_keyword", "sphere { 0, 1 }\nfrobnicate { 1 }\n");
  expect_located_error(r, "snell_unknown_keyword.pov:2:1:", "frobnicate");
}

TEST(SceneErrorTest, TruncatedSceneReportsEndOfFile) {
  const Outcome r = render_scene("snell_truncated", "sphere { <0, 1, 2>, 1\n  pigment { color rgb <1, 0");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("snell_truncated.pov:2:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
}

TEST(SceneErrorTest, MissingIncludeIsLocated) {
  const Outcome r = render_scene("snell_missing_include", "#include \"no_such_file.inc\"\n");
  expect_located_error(r, "snell_missing_include.pov:1:", "no_such_file.inc");
}

TEST(SceneErrorTest, NoImageIsWrittenOnError) {
  const auto png = std::filesystem::temp_directory_path() / "snell_error_no_output.png";
  std::filesystem::remove(png);
  render_scene("snell_error_no_output", "box { 0 }\n");
  EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace snell
