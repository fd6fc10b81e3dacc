#include "cli/frame_loop.hpp"

#include <fmt/core.h>

#include <cstdio>

#include "cli/app.hpp"
#include "cli/checkpoint.hpp"
#include "cli/distributed.hpp"

namespace snell::cli {

namespace {

enum class FrameState { kFresh, kPartial, kFinished };

/// With +C: a frame whose image exists without a resume file beside it is finished; one with a resume file
/// was interrupted.
FrameState frame_state(const CliOptions& o, const std::filesystem::path& output) {
  if (!o.resume) return FrameState::kFresh;
  std::error_code ec;
  if (std::filesystem::exists(resume_path(output), ec)) return FrameState::kPartial;
  if (std::filesystem::exists(output, ec)) return FrameState::kFinished;
  return FrameState::kFresh;
}

class FrameRun {
 public:
  FrameRun(const CliOptions& o, const FramePlan& plan, bool announce, const FrameRenderer& render_frame)
      : o_(o), plan_(plan), announce_(announce), render_frame_(render_frame) {}

  /// Frame `index` (0-based in the subset); `state` as frame_state found it (on rank 0 for tiled frames).
  int render(int index, FrameState state, bool whole_frame) const {
    FrameTask task;
    task.number = plan_.first + index;
    task.output = frame_output(plan_, o_.output, task.number);
    task.whole_frame = whole_frame;
    task.resume = state == FrameState::kPartial;
    if (announce_ && (whole_frame || distributed::rank() == 0)) {
      const std::string rank =
          whole_frame && distributed::size() > 1 ? fmt::format(" on rank {}", distributed::rank()) : "";
      if (state == FrameState::kFinished)
        fmt::print(stderr, "snell: frame {}/{} ({}) already rendered: {}\n", index + 1, plan_.count(),
                   task.number, task.output.string());
      else
        fmt::print(stderr, "snell: frame {}/{} (frame_number {}, clock {:g}){} -> {}\n", index + 1,
                   plan_.count(), task.number, frame_clock(plan_, task.number), rank, task.output.string());
    }
    if (state == FrameState::kFinished) return kOk;
    return render_frame_(task);
  }

  FrameState state(int index) const {
    return frame_state(o_, frame_output(plan_, o_.output, plan_.first + index));
  }

 private:
  const CliOptions& o_;
  const FramePlan& plan_;
  bool announce_;
  const FrameRenderer& render_frame_;
};

}  // namespace

int render_frames(const CliOptions& o, const FramePlan& plan, bool announce, const std::atomic<bool>* cancel,
                  const FrameRenderer& render_frame) {
  if (!plan.animated) {
    FrameTask still;
    still.output = o.output;
    still.resume = o.resume;
    return render_frame(still);
  }
  const FrameRun run(o, plan, announce, render_frame);
  // Whole frames to ranks once there is a frame for every rank: no tile traffic and no gather, and each
  // rank writes its own frames. Fewer frames than ranks: each frame by tiles over all ranks.
  if (distributed::size() > 1 && plan.count() >= distributed::size()) {
    return distributed::render_frames(plan.count(), cancel, [&run](int index) {
      return run.render(index, run.state(index), /*whole_frame=*/true);
    });
  }
  for (int index = 0; index < plan.count(); ++index) {
    // Every rank renders every tiled frame; rank 0, which writes the images, decides which are done.
    const auto state =
        static_cast<FrameState>(distributed::broadcast_from_lead(static_cast<int>(run.state(index))));
    if (const int code = run.render(index, state, /*whole_frame=*/false); code != kOk) return code;
  }
  return kOk;
}

}  // namespace snell::cli
