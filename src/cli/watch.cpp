#include "cli/watch.hpp"

#include <fmt/core.h>
#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <chrono>
#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <system_error>

#include "snell/sdl/parse.hpp"

namespace snell::cli {

namespace {

namespace fs = std::filesystem;

/// The files one render read, with their modification times at the moment they were read.
using FileTimes = std::map<fs::path, std::optional<fs::file_time_type>>;

std::optional<fs::file_time_type> modified(const fs::path& path) {
  std::error_code ec;
  const auto t = fs::last_write_time(path, ec);
  if (ec) return std::nullopt;
  return t;
}

/// A file changed between being read and being watched: render again at once.
const fs::path* changed_since_read(const FileTimes& files) {
  for (const auto& [path, time] : files)
    if (modified(path) != time) return &path;
  return nullptr;
}

/// An inotify instance watching the folders of `files` (editors often save by writing a new file and
/// renaming it over the old one, which a watch on the file itself would miss).
class FolderWatch {
 public:
  explicit FolderWatch(const FileTimes& files) : fd_(inotify_init1(IN_NONBLOCK | IN_CLOEXEC)) {
    if (fd_ < 0) throw std::system_error(errno, std::generic_category(), "--watch: inotify");
    std::map<fs::path, std::set<std::string>> by_folder;
    for (const auto& [path, time] : files) {
      const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
      by_folder[folder].insert(path.filename().string());
    }
    for (const auto& [folder, names] : by_folder) {
      const int wd = inotify_add_watch(
          fd_, folder.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_ATTRIB | IN_MODIFY);
      if (wd >= 0) names_[wd] = {folder, names};
    }
  }
  ~FolderWatch() { close(fd_); }
  FolderWatch(const FolderWatch&) = delete;
  FolderWatch& operator=(const FolderWatch&) = delete;

  /// Waits up to `timeout` for a change to one of the files; returns its path, or nothing.
  std::optional<fs::path> wait(std::chrono::milliseconds timeout) {
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(timeout.count())) <= 0) return std::nullopt;  // also EINTR (a signal)
    std::optional<fs::path> changed;
    alignas(inotify_event) char buffer[8192];
    for (ssize_t n; (n = read(fd_, buffer, sizeof buffer)) > 0;)
      for (ssize_t at = 0; at < n;) {
        const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
        at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
        const auto found = names_.find(e->wd);
        if (found == names_.end() || e->len == 0) continue;
        if (found->second.second.count(e->name)) changed = found->second.first / e->name;
      }
    return changed;
  }

 private:
  int fd_;
  std::map<int, std::pair<fs::path, std::set<std::string>>> names_;
};

}  // namespace

int watch_and_render(CliOptions options, const std::function<int(CliOptions&)>& render_once,
                     const std::atomic<bool>& stop) {
  if (!options.size_given) {
    options.width = kWatchWidth;
    options.height = kWatchHeight;
  }
  FileTimes files;
  options.on_file_read = [&files](const fs::path& path) { files.emplace(path, modified(path)); };
  for (bool first = true; !stop; first = false) {
    files.clear();
    files.emplace(options.input, modified(options.input));
    CliOptions run = options;  // render_once fills in defaults (the output name)
    try {
      render_once(run);
    } catch (const UsageError& e) {
      if (first) throw;
      fmt::print(stderr, "snell: error: {}\n", e.what());
    } catch (const sdl::ParseError& e) {
      fmt::print(stderr, "{}\n", e.what());
    } catch (const std::exception& e) {
      fmt::print(stderr, "snell: error: {}\n", e.what());
    }
    if (stop) break;
    if (!options.quiet)
      fmt::print(stderr, "snell: watching {} file{} for changes; Ctrl-C ends\n", files.size(),
                 files.size() == 1 ? "" : "s");
    FolderWatch watch(files);
    const fs::path* stale = changed_since_read(files);
    std::optional<fs::path> changed = stale ? std::optional(*stale) : std::nullopt;
    while (!changed && !stop) changed = watch.wait(std::chrono::milliseconds(200));
    if (stop) break;
    // An editor's save is several events (truncate, write, rename); let them settle before parsing.
    while (watch.wait(std::chrono::milliseconds(100))) {
    }
    if (!options.quiet) fmt::print(stderr, "snell: {} changed; rendering again\n", changed->string());
  }
  return 0;
}

}  // namespace snell::cli
