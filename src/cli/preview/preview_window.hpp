#pragma once
// The render window of `+D` / `--display` (issue 12), as POV-Ray's: tiles appear as they finish, the title
// shows progress and the time left. Free of SDL on purpose: only sdl_preview_window.cpp includes SDL2, and a
// build without SDL2 (no_preview_window.cpp) still links, warning that it has no window.
#include <atomic>
#include <filesystem>
#include <memory>
#include <string>

#include "snell/io/encoding.hpp"
#include "snell/io/image.hpp"
#include "snell/render/tiles.hpp"

namespace snell::cli {

class PreviewWindow {
 public:
  virtual ~PreviewWindow() = default;
  /// Copies the finished tile's pixels (already in `image`) into the window. Thread-safe.
  virtual void show_tile(const render::Tile& tile, const io::Image& image) = 0;
  /// Progress in [0,1]; the title shows it with the estimated time left. Thread-safe.
  virtual void set_progress(double fraction) = 0;
  /// The render has ended: shows the last tiles, writes the window's pixels to `snapshot` when it is not
  /// empty (a test hook), waits for a key or the window's close button when `wait_for_key` (POV-Ray's +P) or
  /// until `stop_waiting` becomes true (Ctrl-C), then closes the window.
  virtual void finish(const std::filesystem::path& snapshot, bool wait_for_key,
                      const std::atomic<bool>* stop_waiting) = 0;
};

/// Opens a window of the image's size titled with `title`. Pixels pass through `encoding`, the same
/// encoding the output file gets, so the window shows the file's values. Returns null and sets `why` when
/// there is no display (no $DISPLAY / $WAYLAND_DISPLAY, SDL cannot start) or snell was built without SDL2.
std::unique_ptr<PreviewWindow> open_preview_window(int width, int height, const std::string& title,
                                                   const io::Encoding& encoding, std::string& why);

}  // namespace snell::cli
