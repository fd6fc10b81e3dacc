#pragma once
// The CLI's side of +D: opens the render window for one render or says once why there is none.
#include <memory>
#include <vector>

#include "cli/options.hpp"
#include "cli/preview/preview_window.hpp"

namespace snell::cli {

/// The window for a render of `options` (rank 0 only), or null after a warning (printed once per process,
/// so a --watch loop does not repeat it) when there is no display; the render goes on without it.
std::unique_ptr<PreviewWindow> open_preview(const CliOptions& options, const io::Encoding& encoding);

/// Shows the tiles a resume file brought (+C) in the window.
void show_in_preview(PreviewWindow& window, const std::vector<render::Tile>& tiles, const io::Image& image);

/// Shows a finished tile and the progress in the window.
void show_in_preview(PreviewWindow& window, const render::Tile& tile, const io::Image& image,
                     double fraction);

}  // namespace snell::cli
