#include "cli/video.hpp"

#include <fmt/core.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <sstream>

extern char** environ;

namespace snell::cli {

std::vector<std::string> ffmpeg_arguments(const FramePlan& plan, const std::filesystem::path& frames,
                                          const std::filesystem::path& video, double fps) {
  // ffmpeg's image2 demuxer reads a numbered sequence from a printf pattern: out%03d.png from 001 on.
  std::filesystem::path pattern = frames.parent_path();
  pattern /= fmt::format("{}%0{}d{}", frames.stem().string(), plan.digits, frames.extension().string());
  return {"ffmpeg",
          "-y",
          "-loglevel",
          "error",
          "-framerate",
          fmt::format("{}", fps),
          "-start_number",
          std::to_string(plan.first),
          "-i",
          pattern.string(),
          "-frames:v",
          std::to_string(plan.count()),
          "-c:v",
          "libx264",
          "-pix_fmt",
          "yuv420p",
          video.string()};
}

std::string shell_line(const std::vector<std::string>& arguments) {
  std::string line;
  for (const std::string& a : arguments) {
    if (!line.empty()) line += ' ';
    if (a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./:%=") ==
        std::string::npos) {
      line += a;
      continue;
    }
    line += '\'';
    for (char c : a) {
      if (c == '\'')
        line.append("'\\''");  // end the quote, an escaped quote, start a new quote
      else
        line.push_back(c);
    }
    line += '\'';
  }
  return line;
}

std::optional<std::filesystem::path> find_on_path(const std::string& program,
                                                  const std::string& path_variable) {
  std::istringstream folders(path_variable);
  for (std::string folder; std::getline(folders, folder, ':');) {
    // An empty PATH entry is the current folder.
    const std::filesystem::path candidate =
        (folder.empty() ? std::filesystem::path(".") : std::filesystem::path(folder)) / program;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0)
      return candidate;
  }
  return std::nullopt;
}

bool make_video(const FramePlan& plan, const std::filesystem::path& frames,
                const std::filesystem::path& video, double fps) {
  const std::vector<std::string> arguments = ffmpeg_arguments(plan, frames, video, fps);
  const char* path = std::getenv("PATH");
  const auto ffmpeg = find_on_path("ffmpeg", path ? path : "");
  if (!ffmpeg) {
    fmt::print(
        stderr,
        "snell: warning: ffmpeg is not installed (not found on PATH), so no video {} was made; the frames "
        "are written. With ffmpeg installed, join them with:\n  {}\n",
        video.string(), shell_line(arguments));
    return false;
  }
  std::vector<char*> argv;
  std::vector<std::string> storage = arguments;
  for (std::string& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  int status = 0;
  if (posix_spawn(&pid, ffmpeg->c_str(), nullptr, nullptr, argv.data(), environ) != 0 ||
      waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    fmt::print(stderr, "snell: warning: ffmpeg failed to make {}; the command was:\n  {}\n", video.string(),
               shell_line(arguments));
    return false;
  }
  return true;
}

}  // namespace snell::cli
