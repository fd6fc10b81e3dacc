#include "cli/preview/open_preview.hpp"

#include <fmt/core.h>

#include <atomic>

#include "cli/distributed.hpp"

namespace snell::cli {

std::unique_ptr<PreviewWindow> open_preview(const CliOptions& options, const io::Encoding& encoding) {
  if (distributed::rank() != 0) return nullptr;
  std::string why;
  auto window = open_preview_window(options.width, options.height,
                                    "snell: " + options.input.filename().string(), encoding, why);
  static std::atomic<bool> warned{false};
  if (!window && !options.quiet && !warned.exchange(true))
    fmt::print(stderr, "snell: warning: +D: no preview window: {}; rendering on without it\n", why);
  return window;
}

void show_in_preview(PreviewWindow& window, const std::vector<render::Tile>& tiles, const io::Image& image) {
  for (const render::Tile& t : tiles) window.show_tile(t, image);
}

void show_in_preview(PreviewWindow& window, const render::Tile& tile, const io::Image& image,
                     double fraction) {
  window.show_tile(tile, image);
  window.set_progress(fraction);
}

}  // namespace snell::cli
