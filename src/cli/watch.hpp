#pragma once
// `--watch` (issue 12): the edit-render loop. Renders the scene, then waits (Linux inotify) until the scene
// or any file the parser read for it (includes, image maps, height fields, fonts, #fopen files) changes, and
// renders again; SIGINT/SIGTERM ends it with exit code 0.
#include <atomic>
#include <functional>

#include "cli/options.hpp"

namespace snell::cli {

/// Preview size of --watch when no +W/+H (or -w/-h, Width=/Height=) is given.
constexpr int kWatchWidth = 320;
constexpr int kWatchHeight = 240;

/// Runs `render_once` now and after every change until `stop` becomes true; returns the exit code (0 when
/// stopped). A command-line error in the first render is thrown as usual; later scene, output or
/// command-line errors (a half-typed scene, a deleted file) are printed and the loop waits for the next edit.
int watch_and_render(CliOptions options, const std::function<int(CliOptions&)>& render_once,
                     const std::atomic<bool>& stop);

}  // namespace snell::cli
