// Interruption, resume and partial renders through the `snell` binary (issue 12, issue 11's +SR/+ER/+SC/+EC):
// the resumed or merged image must hold exactly the pixels of one uninterrupted render.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "run_command.hpp"
#include "snell/io/image_file.hpp"

extern char** environ;

namespace snell {
namespace {

namespace fs = std::filesystem;

fs::path work_dir() {
  const fs::path dir = fs::temp_directory_path() / ("snell_interrupt_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

/// Slow enough at one thread (focal blur, reflection, refraction) that a signal lands mid-render.
fs::path slow_scene(const fs::path& dir) {
  const fs::path path = dir / "slow.pov";
  std::ofstream(path) << R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at 0 aperture 0.6 blur_samples 20 focal_point <0, 0, 0> }
light_source { <4, 6, -5>, 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0.2 } finish { reflection 0.3 } }
#for (I, 0, 8)
  sphere { <mod(I, 3) - 1, 0, div(I, 3) - 1>, 0.45
    pigment { rgbf <0.9, 0.6 + I / 30, 0.7, 0.6> } finish { reflection 0.4 phong 0.8 } interior { ior 1.5 } }
#end
)";
  return path;
}

std::string snell_command(const fs::path& scene, const fs::path& out, const std::string& extra) {
  return std::string(SNELL_BINARY) + " +I" + scene.string() + " +O" + out.string() +
         " +W96 +H72 +A0.3 --quiet " + extra;
}

/// Starts snell with `args`, waits until `wait_for` exists (a checkpoint shows tiles are finished), then
/// sends `sig`. Returns the exit status (or 128 + signal).
int run_and_signal(const std::vector<std::string>& args, const fs::path& wait_for, int sig) {
  std::vector<char*> argv;
  std::vector<std::string> storage = args;
  for (std::string& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(wait_for) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, sig);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::vector<std::string> slow_args(const fs::path& scene, const fs::path& out) {
  return {SNELL_BINARY,
          "+I" + scene.string(),
          "+O" + out.string(),
          "+W96",
          "+H72",
          "+A0.3",
          "--quiet",
          "--threads",
          "1",
          "--checkpoint",
          "0.001"};
}

/// Renders the scene once, uninterrupted, for all tests to compare with.
class InterruptTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = work_dir();
    scene_ = slow_scene(dir_);
    const auto r = test::run_command(snell_command(scene_, dir_ / "whole.exr", ""));
    ASSERT_EQ(r.code, 0) << r.output;
    whole_ = io::read_image(dir_ / "whole.exr");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static inline fs::path dir_, scene_;
  static inline io::Image whole_;
};

TEST_F(InterruptTest, SigintWritesPartialImageAndResumeFileThenContinueCompletesIt) {
  const fs::path out = dir_ / "cut.exr", resume = dir_ / "cut.exr.snell-resume";
  // --checkpoint 0.001 writes the resume file as soon as a tile is finished: the cue for the signal.
  EXPECT_EQ(run_and_signal(slow_args(scene_, out), resume, SIGINT), 130);
  ASSERT_TRUE(fs::exists(out));
  ASSERT_TRUE(fs::exists(resume));
  const io::Image partial = io::read_image(out);
  ASSERT_TRUE(partial.has_alpha());
  EXPECT_FALSE(partial.fully_covered());
  for (int y = 0; y < 72; ++y)
    for (int x = 0; x < 96; ++x)
      if (partial.alpha_at(x, y) > 0) {
        ASSERT_EQ(partial.at(x, y), whole_.at(x, y));
      }

  const auto r = test::run_command(snell_command(scene_, out, "+C"));
  ASSERT_EQ(r.code, 0) << r.output;
  const io::Image finished = io::read_image(out);
  EXPECT_FALSE(finished.has_alpha());
  EXPECT_EQ(finished.rgb, whole_.rgb);
  EXPECT_FALSE(fs::exists(resume)) << "a finished render removes its resume file";
}

TEST_F(InterruptTest, SigkillLosesOnlyWorkSinceTheLastCheckpoint) {
  const fs::path out = dir_ / "killed.exr", resume = dir_ / "killed.exr.snell-resume";
  EXPECT_EQ(run_and_signal(slow_args(scene_, out), resume, SIGKILL), 128 + SIGKILL);
  ASSERT_TRUE(fs::exists(resume));
  EXPECT_FALSE(fs::exists(out)) << "no image is written by a killed render";
  const auto r = test::run_command(snell_command(scene_, out, "--continue"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(io::read_image(out).rgb, whole_.rgb);
}

TEST_F(InterruptTest, ResumeFileOfOtherFlagsIsRejected) {
  const fs::path out = dir_ / "other.exr", resume = dir_ / "other.exr.snell-resume";
  EXPECT_EQ(run_and_signal(slow_args(scene_, out), resume, SIGINT), 130);
  const auto r = test::run_command(snell_command(scene_, out, "+C +R2"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("different scene, flags or snell version"), std::string::npos) << r.output;
}

TEST_F(InterruptTest, FourQuadrantsMergeIntoTheWholeImage) {
  std::vector<std::string> parts;
  for (const char* rows : {"+SR0.0 +ER0.5", "+SR0.5 +ER1.0"})
    for (const char* cols : {"+SC1 +EC48", "+SC49 +EC96"}) {
      const fs::path part = dir_ / ("part" + std::to_string(parts.size()) + ".exr");
      const auto r = test::run_command(snell_command(scene_, part, std::string(rows) + " " + cols));
      ASSERT_EQ(r.code, 0) << r.output;
      parts.push_back(part.string());
    }
  std::string command = std::string(SNELL_BINARY) + " merge --quiet";
  for (const auto& p : parts) command += " " + p;
  const auto r = test::run_command(command + " -o " + (dir_ / "merged.exr").string());
  ASSERT_EQ(r.code, 0) << r.output;
  const io::Image merged = io::read_image(dir_ / "merged.exr");
  EXPECT_FALSE(merged.has_alpha());
  EXPECT_EQ(merged.rgb, whole_.rgb);
}

TEST(PartialRenderTest, BadBoundsAreUsageErrors) {
  const fs::path dir = work_dir();
  const fs::path scene = dir / "s.pov";
  std::ofstream(scene) << "sphere { 0, 1 }\n";
  for (const char* bounds : {"+SR0.6 +ER0.4", "+SR1.5", "+EC0", "+SCabc"}) {
    const auto r = test::run_command(snell_command(scene, dir / "o.png", bounds));
    EXPECT_EQ(r.code, 2) << bounds << ": " << r.output;
  }
  const auto merge = test::run_command(std::string(SNELL_BINARY) + " merge " + (dir / "none.exr").string() +
                                       " -o " + (dir / "m.png").string());
  EXPECT_NE(merge.code, 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace snell
