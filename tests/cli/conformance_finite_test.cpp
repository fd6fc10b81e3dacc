// No conformance scene's image holds a NaN or an infinite value (issue 12): each scene of
// ../shared/conformance/scenes.tsv is rendered to EXR (floats, so nothing is clamped away) at 40x30
// without anti-aliasing, and every value is checked. The scenes are POV-Ray's own examples (Debian's
// povray-examples); the test is skipped where they or the conformance kit are missing.
// tools/check-finite.sh does the same at any size from the shell.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fault_scene.hpp"

namespace snell::test {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(SNELL_SOURCE_DIR) / ".." / "shared" / "conformance" / "scenes.tsv";
const fs::path kExamples = "/usr/share/doc/povray/examples";
const fs::path kIncludes = "/usr/share/povray-3.7/include";

struct ConformanceScene {
  std::string name;
  std::string path;  // relative to kExamples
};

/// The rows of scenes.tsv (name, scene, features, time), or none where the kit is missing.
std::vector<ConformanceScene> conformance_scenes() {
  std::vector<ConformanceScene> scenes;
  std::ifstream in(kScenes);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    ConformanceScene s;
    if (std::getline(row, s.name, '\t') && std::getline(row, s.path, '\t') && s.name != "name")
      scenes.push_back(s);
  }
  if (scenes.empty()) scenes.push_back({"kit_missing", ""});  // one skipped test rather than none
  return scenes;
}

class ConformanceFinite : public ::testing::TestWithParam<ConformanceScene> {};

TEST_P(ConformanceFinite, ImageHasOnlyFiniteValues) {
  const ConformanceScene& s = GetParam();
  const fs::path scene = kExamples / s.path;
  if (s.path.empty() || !fs::exists(scene)) GTEST_SKIP() << "no conformance kit or povray-examples";
  // The scene runs from a folder of its own, so files it writes (#fopen) stay out of the examples; its
  // includes and images are found through +L.
  const fs::path dir = fault_folder() / s.name;
  fs::create_directories(dir);
  fs::copy_file(scene, dir / scene.filename(), fs::copy_options::overwrite_existing);
  const fs::path image = dir / (s.name + ".exr");
  const Outcome r = run_command("cd " + dir.string() + " && " + SNELL_BINARY + " +I" +
                                scene.filename().string() + " +O" + image.string() + " +W40 +H30 -A -D +L" +
                                scene.parent_path().string() + " +L" + kIncludes.string() + " --quiet");
  // A scene snell cannot read yet (exit 1, a located error) has no image to check.
  if (r.code == 1) GTEST_SKIP() << "scene not supported yet: " << r.output.substr(0, r.output.find('\n'));
  ASSERT_EQ(r.code, 0) << r.output;
  const io::Image rendered = io::read_image(image);
  ASSERT_EQ(rendered.width, 40);
  size_t bad = 0;
  for (float v : rendered.rgb) bad += !std::isfinite(v);
  EXPECT_EQ(bad, 0u) << s.name << ": values that are NaN or infinite";
  EXPECT_EQ(r.output.find("NaN or infinite"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ConformanceFinite, ::testing::ValuesIn(conformance_scenes()),
                         [](const ::testing::TestParamInfo<ConformanceScene>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace snell::test
