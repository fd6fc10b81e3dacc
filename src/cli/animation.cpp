#include "cli/animation.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <string>

namespace snell::cli {

namespace {

int parse_frame_number(const std::string& flag, const std::string& text) {
  int v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || v < 0)
    throw UsageError("invalid frame range '" + text + "' for " + flag + " (expected A-B, e.g. 1-120)");
  return v;
}

/// POV-Ray's subset bound: a value strictly between 0 and 1 is a fraction of the frame count (counted from
/// 0, as POV-Ray does), any other value a frame number.
int subset_bound(double value, int initial, int final) {
  if (value > 0 && value < 1) return static_cast<int>((final - initial + 1) * value);
  return static_cast<int>(value);
}

}  // namespace

void parse_frame_range(const std::string& flag, const std::string& text, int& first, int& last) {
  const auto dash = text.find('-', 1);
  first = parse_frame_number(flag, text.substr(0, dash));
  last = dash == std::string::npos ? first : parse_frame_number(flag, text.substr(dash + 1));
  if (last < first) throw UsageError(flag + " " + text + ": the last frame comes before the first");
}

FramePlan plan_frames(const CliOptions& o) {
  if (o.initial_frame < 0) throw UsageError("the initial frame must not be negative");
  FramePlan plan;
  plan.initial_frame = o.initial_frame;
  // POV-Ray raises a final frame below the initial one to the initial one.
  plan.final_frame = std::max(o.final_frame, o.initial_frame);
  plan.initial_clock = o.initial_clock;
  plan.final_clock = o.final_clock;
  plan.cyclic = o.cyclic;
  plan.animated = plan.final_frame > plan.initial_frame;
  // Cyclic: POV-Ray counts one frame more (so the last rendered frame stops one clock step short of
  // final_clock) and names frames with that frame's digits.
  const int counted_final = plan.final_frame + (plan.cyclic && plan.animated ? 1 : 0);
  plan.first = o.subset_start < 0 ? plan.initial_frame
                                  : subset_bound(o.subset_start, plan.initial_frame, counted_final);
  plan.first = std::clamp(plan.first, plan.initial_frame, plan.final_frame);
  plan.last =
      o.subset_end < 0 ? plan.final_frame : subset_bound(o.subset_end, plan.initial_frame, counted_final);
  plan.last = std::clamp(plan.last, plan.first, plan.final_frame);
  plan.digits = static_cast<int>(std::to_string(counted_final).size());
  return plan;
}

void apply_frame(const FramePlan& plan, int frame, sdl::ParseOptions& po) {
  po.initial_frame = plan.initial_frame;
  po.final_frame = plan.final_frame;
  po.initial_clock = plan.initial_clock;
  po.final_clock = plan.final_clock;
  po.cyclic = plan.cyclic;
  po.clock_on = plan.animated;
  po.frame_number = plan.animated ? frame : 0;
  // POV-Ray's rule (animationprocessing.cpp); clock_delta has one more step when cyclic.
  po.clock =
      plan.animated ? po.initial_clock + po.clock_delta() * (frame - po.initial_frame) : po.initial_clock;
}

double frame_clock(const FramePlan& plan, int frame) {
  sdl::ParseOptions po;
  apply_frame(plan, frame, po);
  return po.clock;
}

std::filesystem::path frame_output(const FramePlan& plan, const std::filesystem::path& output, int frame) {
  if (!plan.animated) return output;
  std::filesystem::path named = output.parent_path();
  named /=
      fmt::format("{}{:0{}d}{}", output.stem().string(), frame, plan.digits, output.extension().string());
  return named;
}

}  // namespace snell::cli
