// Runs the `snell` binary: each bad command line gives one clear error line and a non-zero exit code.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "run_command.hpp"

namespace snell {
namespace {

using test::Outcome;

Outcome run(const std::string& args) {
  return test::run_command(std::string(SNELL_BINARY) + " " + args);
}

size_t lines(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

std::string scene_file() {
  // One file per test process: ctest runs these tests in parallel processes.
  const auto path =
      std::filesystem::temp_directory_path() / ("snell_cli_test_" + std::to_string(getpid()) + ".pov");
  std::ofstream(path) << "sphere { 0, 1 }\n";
  return path.string();
}

TEST(CliTest, VersionPrintsNameAndVersion) {
  const Outcome r = run("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.output.rfind(std::string("snell ") + SNELL_VERSION + " (with", 0), 0u) << r.output;
}

TEST(CliTest, HelpDescribesBothForms) {
  const Outcome r = run("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.output.find("render"), std::string::npos);
  EXPECT_NE(r.output.find("+W"), std::string::npos);
  EXPECT_NE(r.output.find("--aa-depth"), std::string::npos);
}

TEST(CliTest, ZeroWidthIsUsageError) {
  const Outcome r = run("+I" + scene_file() + " +W0 +H10");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find("image size must be positive"), std::string::npos);
}

TEST(CliTest, NegativeSizeIsUsageError) {
  const Outcome a = run("render " + scene_file() + " -w 10 -h -5");
  EXPECT_EQ(a.code, 2);
  EXPECT_EQ(lines(a.output), 1u) << a.output;
  const Outcome b = run("+I" + scene_file() + " +W-3");
  EXPECT_EQ(b.code, 2);
  EXPECT_EQ(lines(b.output), 1u) << b.output;
}

TEST(CliTest, MissingSceneFileIsUsageError) {
  const Outcome r = run("+I/nonexistent/scene.pov +W10 +H10");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/scene.pov"), std::string::npos);
  EXPECT_EQ(run("render /nonexistent/scene.pov").code, 2);
}

TEST(CliTest, BadNumberAndUnknownAcceleratorAreUsageErrors) {
  EXPECT_EQ(run("+I" + scene_file() + " +Wabc").code, 2);
  EXPECT_EQ(run("render " + scene_file() + " --accel octopus").code, 2);
}

TEST(CliTest, KnownButUnsupportedPovFlagIsOnlyAWarning) {
  // The scene error (exit 1) shows the command line itself was accepted despite +Q9.
  const Outcome r = run("+I" + scene_file() + " +W10 +H10 +Q9 -D");
  EXPECT_NE(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("warning: option '+Q9' is not supported yet"), std::string::npos) << r.output;
}

TEST(CliTest, UnknownPovFlagOrExtraArgumentIsAUsageError) {
  // As POV-Ray ("Failed to parse command-line option"): exit 2 and one line naming the option.
  for (const std::string bad : {" +ZZ", " --bogus", " -o out.png", " extra.pov"}) {
    const Outcome r = run("+I" + scene_file() + " +W10 +H10 -D" + bad);
    EXPECT_EQ(r.code, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace snell
