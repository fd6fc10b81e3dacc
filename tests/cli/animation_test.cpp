// Animations through the `snell` binary (issue 8's animation, issue 11): every frame of a range is parsed
// and rendered with its own clock, written under POV-Ray's numbered names, identical to rendering that frame
// alone; +C skips finished frames and resumes the interrupted one; --video warns when ffmpeg is missing.
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

#include <fmt/core.h>

#include "run_command.hpp"
#include "snell/io/image_file.hpp"

extern char** environ;

namespace snell {
namespace {

namespace fs = std::filesystem;

/// `dir/stem7.exr`: the file of frame 7.
fs::path frame_file(const fs::path& dir, const char* stem, int frame, const char* extension = ".exr") {
  return dir / fmt::format("{}{}{}", stem, frame, extension);
}

class AnimationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("snell_animation_test_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  test::Outcome snell(const std::string& flags) const {
    return test::run_command(std::string(SNELL_BINARY) + " +I" + scene_.string() + " +W64 +H48 +A0.3 " +
                             flags);
  }

  fs::path dir_;
  const fs::path scene_ = fs::path(SNELL_SOURCE_DIR) / "tests/cli/moving_sphere.pov";
};

TEST_F(AnimationTest, EveryFrameIsWrittenAndEqualsThatFrameRenderedAlone) {
  const auto all = snell("+KFI1 +KFF4 +O" + (dir_ / "a.exr").string());
  ASSERT_EQ(all.code, 0) << all.output;
  EXPECT_NE(all.output.find("frame 3/4 (frame_number 3, clock 0.666667)"), std::string::npos) << all.output;
  for (int f = 1; f <= 4; ++f) EXPECT_TRUE(fs::exists(frame_file(dir_, "a", f))) << f;
  EXPECT_FALSE(fs::exists(dir_ / "a.exr"));
  // Frame 3 alone (+SF3 +EF3 of the same range) has the same pixels; the scene moves, so frames differ.
  const auto alone = snell("+KFI1 +KFF4 +SF3 +EF3 --quiet +O" + (dir_ / "b.exr").string());
  ASSERT_EQ(alone.code, 0) << alone.output;
  EXPECT_FALSE(fs::exists(dir_ / "b1.exr"));
  const io::Image three = io::read_image(dir_ / "a3.exr");
  EXPECT_EQ(three.rgb, io::read_image(dir_ / "b3.exr").rgb);
  EXPECT_NE(three.rgb, io::read_image(dir_ / "a2.exr").rgb);
}

TEST_F(AnimationTest, FramesFlagNumbersByTheFinalFramesWidth) {
  const auto r =
      test::run_command(std::string(SNELL_BINARY) + " render " + scene_.string() +
                        " -w 32 -h 24 --frames 9-10 --subset 9-10 --quiet -o " + (dir_ / "s.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "s09.png"));
  EXPECT_TRUE(fs::exists(dir_ / "s10.png"));
}

TEST_F(AnimationTest, OneFrameRangeIsAStill) {
  const auto r = snell("--frames 1-1 --quiet +O" + (dir_ / "still.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "still.png"));
  EXPECT_FALSE(fs::exists(dir_ / "still1.png"));
}

TEST_F(AnimationTest, VideoWithoutFfmpegWarnsAndKeepsTheFrames) {
  // An empty PATH hides any ffmpeg; the command to run later is printed.
  const auto r = test::run_command("env PATH=" + dir_.string() + " " + SNELL_BINARY + " +I" +
                                   scene_.string() + " +W32 +H24 +KFI1 +KFF2 --video " +
                                   (dir_ / "v.mp4").string() + " +O" + (dir_ / "v.png").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: ffmpeg is not installed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("-start_number 1 -i " + (dir_ / "v%01d.png").string()), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "v1.png"));
  EXPECT_TRUE(fs::exists(dir_ / "v2.png"));
  EXPECT_FALSE(fs::exists(dir_ / "v.mp4"));
}

TEST_F(AnimationTest, VideoRunsFfmpegFromPathWithTheFrameSequence) {
  // A stand-in ffmpeg records its arguments and writes the video file.
  const fs::path bin = dir_ / "bin";
  fs::create_directories(bin);
  std::ofstream(bin / "ffmpeg") << "#!/bin/sh\necho \"$@\" > " << (dir_ / "ffmpeg-args").string()
                                << "\nfor last; do :; done\ntouch \"$last\"\n";
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
  const auto r = test::run_command("env PATH=" + bin.string() + ":/usr/bin:/bin " + SNELL_BINARY + " +I" +
                                   scene_.string() + " +W32 +H24 +KFI1 +KFF12 +SF11 --fps 30 --video " +
                                   (dir_ / "v.mp4").string() + " --quiet +O" + (dir_ / "v.png").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "v.mp4"));
  std::ifstream args_file(dir_ / "ffmpeg-args");
  std::string args;
  std::getline(args_file, args);
  EXPECT_EQ(args, "-y -loglevel error -framerate 30 -start_number 11 -i " + (dir_ / "v%02d.png").string() +
                      " -frames:v 2 -c:v libx264 -pix_fmt yuv420p " + (dir_ / "v.mp4").string());
}

TEST_F(AnimationTest, VideoOfAStillIsAUsageError) {
  const auto r = snell("--video " + (dir_ / "v.mp4").string() + " +O" + (dir_ / "v.png").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--video needs an animation"), std::string::npos) << r.output;
}

TEST_F(AnimationTest, ContinueSkipsFinishedFramesAndResumesTheInterruptedOne) {
  const fs::path scene = fs::path(SNELL_SOURCE_DIR) / "tests/cli/slow_animation.pov";
  auto args = [&](const std::string& out) {
    return std::vector<std::string>{SNELL_BINARY,
                                    "+I" + scene.string(),
                                    "+O" + (dir_ / out).string(),
                                    "+W96",
                                    "+H72",
                                    "+KFI1",
                                    "+KFF3",
                                    "--threads",
                                    "1",
                                    "--checkpoint",
                                    "0.02"};
  };
  // The reference: all three frames without interruption.
  std::string reference;
  for (const std::string& a : args("ref.exr")) reference += a + " ";
  ASSERT_EQ(test::run_command(reference + " --quiet").code, 0);

  // Interrupt once frame 2 has checkpointed some tiles.
  std::vector<std::string> storage = args("out.exr");
  std::vector<char*> argv;
  for (std::string& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ), 0);
  const fs::path frame2_resume = dir_ / "out2.exr.snell-resume";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(frame2_resume) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 0) GTEST_SKIP() << "the render finished before the signal arrived";
  ASSERT_EQ(WEXITSTATUS(status), 130);
  ASSERT_TRUE(fs::exists(frame2_resume));
  ASSERT_FALSE(fs::exists(dir_ / "out3.exr"));

  std::string again;
  for (const std::string& a : args("out.exr")) again += a + " ";
  const auto resumed = test::run_command(again + " +C");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("frame 1/3 (1) already rendered"), std::string::npos) << resumed.output;
  EXPECT_NE(resumed.output.find("continuing:"), std::string::npos) << resumed.output;
  EXPECT_FALSE(fs::exists(frame2_resume));
  for (int f = 1; f <= 3; ++f)
    EXPECT_EQ(io::read_image(frame_file(dir_, "out", f)).rgb, io::read_image(frame_file(dir_, "ref", f)).rgb)
        << "frame " << f;
}

}  // namespace
}  // namespace snell
