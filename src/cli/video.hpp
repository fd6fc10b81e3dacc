#pragma once
// Joining an animation's numbered frames into a video with ffmpeg (`--video out.mp4`). ffmpeg is optional:
// snell never links it, it runs the `ffmpeg` program when it is on PATH and otherwise warns and prints the
// command to run later.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/animation.hpp"

namespace snell::cli {

/// The ffmpeg arguments (program name first) that join frames plan.first..plan.last of `frames` (the
/// unnumbered output name, e.g. out.png for out001.png...) into `video` at `fps` frames per second:
/// H.264 in yuv420p, which every player reads.
std::vector<std::string> ffmpeg_arguments(const FramePlan& plan, const std::filesystem::path& frames,
                                          const std::filesystem::path& video, double fps);

/// The arguments as one line for a shell (each quoted where needed), for messages.
std::string shell_line(const std::vector<std::string>& arguments);

/// `program`'s full path when it is an executable file in one of PATH's folders (`path_variable`).
std::optional<std::filesystem::path> find_on_path(const std::string& program,
                                                  const std::string& path_variable);

/// Runs ffmpeg to make the video; returns false (with a warning on stderr) when ffmpeg is missing or fails.
bool make_video(const FramePlan& plan, const std::filesystem::path& frames,
                const std::filesystem::path& video, double fps);

}  // namespace snell::cli
