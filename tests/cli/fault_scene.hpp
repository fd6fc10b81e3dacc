#pragma once
// Renders a small scene with the snell binary for the fault tests (issue 12): the scene goes to a
// per-process folder, the image to EXR (floats, so a NaN would survive into the file), and the test gets
// the exit code, the messages and the image.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"
#include "snell/io/image_file.hpp"

namespace snell::test {

struct FaultRun {
  Outcome outcome;
  bool written = false;
  io::Image image;
};

inline std::filesystem::path fault_folder() {
  const auto dir = std::filesystem::temp_directory_path() / ("snell_fault_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// The camera and light every fault scene shares: a unit sphere at the origin fills the middle of the image.
inline const char* kFaultSceneHeader =
    "camera { location <0, 0, -5> look_at 0 }\n"
    "light_source { <5, 5, -5> rgb 1 }\n";

/// Writes `body` (after kFaultSceneHeader, so its first line is line 3) as `name`.pov and renders it at
/// 40x30 without anti-aliasing.
inline FaultRun render_fault_scene(const std::string& name, const std::string& body,
                                   const std::string& flags = "") {
  const auto dir = fault_folder();
  const auto scene = dir / (name + ".pov"), image = dir / (name + ".exr");
  std::ofstream(scene) << kFaultSceneHeader << body;
  std::filesystem::remove(image);
  FaultRun run;
  run.outcome = run_command("cd " + dir.string() + " && " + SNELL_BINARY + " +I" + scene.filename().string() +
                            " +O" + image.string() + " +W40 +H30 -D " + flags);
  run.written = std::filesystem::exists(image);
  if (run.written) run.image = io::read_image(image);
  return run;
}

inline bool all_finite(const io::Image& image) {
  for (float v : image.rgb)
    if (!std::isfinite(v)) return false;
  return true;
}

/// A message line `name.pov:line:col: severity: ...words...` is in the output.
inline void expect_message(const Outcome& r, const std::string& location, const std::string& severity,
                           const std::string& words) {
  const std::string head = location + " " + severity + ":";
  const size_t at = r.output.find(head);
  ASSERT_NE(at, std::string::npos) << "no '" << head << "' in:\n" << r.output;
  const std::string line = r.output.substr(at, r.output.find('\n', at) - at);
  EXPECT_NE(line.find(words), std::string::npos) << line;
}

/// A warning: the render goes on (exit 0) and writes a finite image.
inline void expect_warning_and_finite_image(const FaultRun& run, const std::string& location,
                                            const std::string& words) {
  EXPECT_EQ(run.outcome.code, 0) << run.outcome.output;
  expect_message(run.outcome, location, "warning", words);
  ASSERT_TRUE(run.written) << run.outcome.output;
  EXPECT_TRUE(all_finite(run.image));
}

/// An error: exit code 1 (a scene error, docs/cli.md) and no image.
inline void expect_scene_error(const FaultRun& run, const std::string& location, const std::string& words) {
  EXPECT_EQ(run.outcome.code, 1) << run.outcome.output;
  expect_message(run.outcome, location, "error", words);
  EXPECT_FALSE(run.written);
}

}  // namespace snell::test
