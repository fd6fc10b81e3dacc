#pragma once
// The layer outputs of `snell explain` (docs/explain.md): --aov (a multi-layer EXR), --aov-png (each layer
// as a PNG with its legend), --heatmap, --split-bounces and --stats (where the time goes).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/render/renderer.hpp"

namespace snell::cli {

struct LayerRequest {
  std::vector<std::string> aovs;
  bool aov_png = false;
  std::vector<std::string> heatmaps;
  int split_bounces = -1;
  bool stats = false;
  /// Outputs are named <output>.exr, <output>.<layer>.png, <output>.heatmap-<name>.png.
  std::filesystem::path output;
};

void add_layer_options(CLI::App& app, LayerRequest& request);
/// Checks names and the output folder (UsageError) and fills in the default output (the scene's name in the
/// current folder); true when any layer output was asked for.
bool check_layer_request(LayerRequest& request, const std::filesystem::path& scene_file);
/// Renders the layers and writes what was asked; prints --stats to stderr.
void write_layers(const LayerRequest& request, const scene::Scene& scene,
                  const accel::Accelerator& accelerator, const render::RenderOptions& options);

}  // namespace snell::cli
