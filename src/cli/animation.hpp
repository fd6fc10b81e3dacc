#pragma once
// The frames of an animation and what each frame's scene sees, after POV-Ray 3.7's "Animation Options"
// (its frontend/animationprocessing.cpp): frames initial..final, clock linear in the frame number, a subset
// +SF..+EF of them rendered, each written under the output name with the frame number appended.
#include <filesystem>

#include "cli/options.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::cli {

struct FramePlan {
  /// More than one frame in the range: the scene sees clock_on, outputs are numbered.
  bool animated = false;
  int initial_frame = 1, final_frame = 1;
  double initial_clock = 0, final_clock = 1;
  bool cyclic = false;
  /// The frames rendered, first..last inclusive (the subset).
  int first = 1, last = 1;
  /// Digits of the frame number in output names: those of the final frame (one more frame when cyclic).
  int digits = 1;
  int count() const { return last - first + 1; }
};

/// The frames `options` asks for. Throws UsageError for a range that is empty or negative.
FramePlan plan_frames(const CliOptions& options);

/// Sets the animation values of `parse` (clock, frame_number, clock_delta's inputs) for `frame`.
void apply_frame(const FramePlan& plan, int frame, sdl::ParseOptions& parse);

/// The clock of `frame`: initial_clock + (frame - initial_frame) * clock_delta.
double frame_clock(const FramePlan& plan, int frame);

/// `out.png` for frame 7 of 1..120 -> `out007.png`; a still keeps its name.
std::filesystem::path frame_output(const FramePlan& plan, const std::filesystem::path& output, int frame);

}  // namespace snell::cli
