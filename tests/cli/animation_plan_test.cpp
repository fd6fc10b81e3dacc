// The frames, clocks and file names of an animation (src/cli/animation.hpp) and the ffmpeg command that joins
// them (src/cli/video.hpp). Expected values are POV-Ray 3.7's, printed by `povray +KFI1 +KFF10 +KC ...` with
// a scene that #debugs frame_number and clock, and by the names of the files it wrote.
#include <gtest/gtest.h>

#include "cli/animation.hpp"
#include "cli/video.hpp"

namespace snell::cli {
namespace {

CliOptions range(int initial, int final, double initial_clock = 0, double final_clock = 1) {
  CliOptions o;
  o.initial_frame = initial;
  o.final_frame = final;
  o.initial_clock = initial_clock;
  o.final_clock = final_clock;
  o.output = "dir/out.png";
  return o;
}

TEST(AnimationPlanTest, ClockRunsLinearlyFromInitialToFinalClock) {
  const FramePlan plan = plan_frames(range(1, 5, 0, 2));
  EXPECT_TRUE(plan.animated);
  EXPECT_EQ(plan.first, 1);
  EXPECT_EQ(plan.last, 5);
  EXPECT_DOUBLE_EQ(frame_clock(plan, 1), 0.0);
  EXPECT_DOUBLE_EQ(frame_clock(plan, 3), 1.0);
  EXPECT_DOUBLE_EQ(frame_clock(plan, 5), 2.0);
  sdl::ParseOptions po;
  apply_frame(plan, 4, po);
  EXPECT_EQ(po.frame_number, 4);
  EXPECT_TRUE(po.clock_on);
  EXPECT_DOUBLE_EQ(po.clock, 1.5);
  EXPECT_DOUBLE_EQ(po.clock_delta(), 0.5);
}

TEST(AnimationPlanTest, CyclicStopsOneStepShortAndNamesWithTheExtraFramesDigits) {
  // povray +KFI1 +KFF10 +KI0 +KF1 +KC: clock 0, 0.1 ... 0.9 for frames 1..10, files out01.png ... out10.png.
  CliOptions o = range(1, 10);
  o.cyclic = true;
  const FramePlan plan = plan_frames(o);
  EXPECT_EQ(plan.last, 10);
  EXPECT_DOUBLE_EQ(frame_clock(plan, 10), 0.9);
  EXPECT_EQ(frame_output(plan, o.output, 1), "dir/out01.png");
  // Without +KC, frames 1..9 end at clock 1 and need one digit.
  const FramePlan plain = plan_frames(range(1, 9));
  EXPECT_DOUBLE_EQ(frame_clock(plain, 9), 1.0);
  EXPECT_EQ(frame_output(plain, "out.png", 7), "out7.png");
}

TEST(AnimationPlanTest, NamesArePaddedToTheFinalFramesWidth) {
  const FramePlan plan = plan_frames(range(1, 120));
  EXPECT_EQ(frame_output(plan, "dir/out.png", 7), "dir/out007.png");
  EXPECT_EQ(frame_output(plan, "a.b.exr", 120), "a.b120.exr");
}

TEST(AnimationPlanTest, SubsetTakesFramesOrAFractionAsPovRayDoes) {
  // povray +KFI0 +KFF20 +SF0.5 +EF12 renders frames 10, 11, 12 (0.5 of 21 frames, truncated), clock 0.5..0.6.
  CliOptions o = range(0, 20);
  o.subset_start = 0.5;
  o.subset_end = 12;
  const FramePlan plan = plan_frames(o);
  EXPECT_EQ(plan.first, 10);
  EXPECT_EQ(plan.last, 12);
  EXPECT_EQ(plan.count(), 3);
  EXPECT_DOUBLE_EQ(frame_clock(plan, 11), 0.55);
  EXPECT_EQ(frame_output(plan, "out.png", 10), "out10.png");
  // Bounds outside the range are clamped to it.
  o.subset_start = 15;
  o.subset_end = 99;
  const FramePlan clamped = plan_frames(o);
  EXPECT_EQ(clamped.first, 15);
  EXPECT_EQ(clamped.last, 20);
}

TEST(AnimationPlanTest, OneFrameIsAStill) {
  const FramePlan plan = plan_frames(range(3, 3, 0.25, 1));
  EXPECT_FALSE(plan.animated);
  EXPECT_EQ(plan.count(), 1);
  EXPECT_EQ(frame_output(plan, "out.png", 3), "out.png");
  sdl::ParseOptions po;
  apply_frame(plan, 3, po);
  EXPECT_FALSE(po.clock_on);
  EXPECT_DOUBLE_EQ(po.clock, 0.25);
}

TEST(AnimationPlanTest, FrameRangesParseAndBadOnesAreUsageErrors) {
  int first = 0, last = 0;
  parse_frame_range("--frames", "2-40", first, last);
  EXPECT_EQ(first, 2);
  EXPECT_EQ(last, 40);
  parse_frame_range("--frames", "7", first, last);
  EXPECT_EQ(first, 7);
  EXPECT_EQ(last, 7);
  for (const char* bad : {"", "5-2", "a-b", "1-", "-3", "1-2-3"})
    EXPECT_THROW(parse_frame_range("--frames", bad, first, last), UsageError) << bad;
}

TEST(VideoCommandTest, FfmpegReadsTheNumberedSequenceFromTheFirstFrame) {
  CliOptions o = range(1, 120);
  o.subset_start = 5;
  o.subset_end = 8;
  const FramePlan plan = plan_frames(o);
  const std::vector<std::string> expected = {
      "ffmpeg",        "-y",      "-loglevel", "error",           "-framerate",  "30",
      "-start_number", "5",       "-i",        "dir/out%03d.png", "-frames:v",   "4",
      "-c:v",          "libx264", "-pix_fmt",  "yuv420p",         "dir/anim.mp4"};
  EXPECT_EQ(ffmpeg_arguments(plan, "dir/out.png", "dir/anim.mp4", 30), expected);
}

TEST(VideoCommandTest, ShellLineQuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(shell_line({"ffmpeg", "-i", "my frames/out%02d.png", "it's.mp4"}),
            "ffmpeg -i 'my frames/out%02d.png' 'it'\\''s.mp4'");
}

TEST(VideoCommandTest, FindsProgramsOnPathOnly) {
  EXPECT_EQ(find_on_path("sh", "/nonexistent:/bin"), std::filesystem::path("/bin/sh"));
  EXPECT_FALSE(find_on_path("sh", "/nonexistent"));
  EXPECT_FALSE(find_on_path("sh", ""));
}

}  // namespace
}  // namespace snell::cli
