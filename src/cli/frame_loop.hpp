#pragma once
// Renders every frame of an animation (cli/animation.hpp): one after the other in one process; under mpirun
// either each frame by tiles over all ranks (fewer frames than ranks) or whole frames handed to ranks from
// rank 0's queue (at least as many frames as ranks; docs/distributed.md). With +C finished frames are
// skipped and an interrupted frame resumes from its resume file.
#include <atomic>
#include <filesystem>
#include <functional>

#include "cli/animation.hpp"
#include "cli/options.hpp"

namespace snell::cli {

/// One frame to render.
struct FrameTask {
  int number = 0;
  std::filesystem::path output;
  /// Continue from the frame's resume file.
  bool resume = false;
  /// This rank renders the whole frame alone and writes it (frames handed to ranks); otherwise the frame is
  /// rendered by tiles over all ranks and rank 0 writes it.
  bool whole_frame = false;
};

/// Renders one frame; returns its exit code (kOk, kInterrupted...). May throw like a still render.
using FrameRenderer = std::function<int(const FrameTask&)>;

/// Renders the frames of `plan` with `render_frame`, stopping at the first that does not return kOk (an
/// interruption). `announce` prints "frame k/n" lines. Returns the exit code.
int render_frames(const CliOptions& options, const FramePlan& plan, bool announce,
                  const std::atomic<bool>* cancel, const FrameRenderer& render_frame);

}  // namespace snell::cli
