// Issue 3 acceptance: every standard include of Debian's povray-includes parses when included alone
// (`#include "x.inc"` in an otherwise empty scene, the include folder as library path).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

/// Includes that POV-Ray 3.7 itself cannot parse alone: they use colours of colors.inc or shapes of
/// shapes.inc without including them (checked with `povray`), so they are read after those two.
const std::set<std::string> kNeedColorsAndShapes = {"shapes2.inc", "shapesq.inc",  "skies.inc",
                                                    "stdcam.inc",  "stoneold.inc", "stones.inc",
                                                    "stones1.inc", "stones2.inc"};

TEST(StandardIncludes, EachParsesWhenIncludedAlone) {
  const std::filesystem::path folder = POVRAY_INCLUDE_DIR;
  if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << "Debian's povray-includes is not installed";
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".inc") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  ASSERT_GE(names.size(), 39u);  // Debian 12's povray-includes: 39 .inc files (and fonts, maps, images)
  int parsed = 0;
  for (const std::string& name : names) {
    const std::string prelude =
        kNeedColorsAndShapes.count(name) ? "#include \"colors.inc\"\n#include \"shapes.inc\"\n" : "";
    const std::string error = test::error_of(prelude + "#include \"" + name + "\"\n");
    parsed += error.empty();
    EXPECT_EQ(error, "") << name;
  }
  EXPECT_EQ(parsed, static_cast<int>(names.size()));
  std::printf(
      "%d of %zu standard includes parse (alone, or after colors.inc and shapes.inc where POV-Ray needs "
      "them)\n",
      parsed, names.size());
}

}  // namespace
}  // namespace snell::sdl
