#include "cli/explain_layers.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "cli/options.hpp"
#include "cli/text_output.hpp"
#include "snell/io/encoding.hpp"
#include "snell/io/image_backend.hpp"
#include "snell/io/layered_exr.hpp"
#include "snell/render/explain/aov_render.hpp"
#include "snell/render/explain/layer_picture.hpp"
#include "snell/render/explain/object_label.hpp"

namespace snell::cli {

namespace {

namespace fs = std::filesystem;
namespace ex = render::explain;

/// Heatmaps and the layer each one shows.
const std::vector<std::string> kHeatmaps{"cost", "time", "samples", "depth"};

fs::path with_suffix(const fs::path& base, const std::string& suffix) {
  fs::path p = base;
  p += suffix;
  return p;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

/// The beauty image as the scene's own output would encode it, for the bounce PNGs.
ex::Picture colour_picture(const std::vector<float>& rgb, int width, int height,
                           const io::Encoding& encoding) {
  ex::Picture p(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = (static_cast<size_t>(y) * width + x) * 3;
      p.set(x, y,
            ex::to_rgb8({encoding.encode(rgb[i]), encoding.encode(rgb[i + 1]), encoding.encode(rgb[i + 2])}));
    }
  return p;
}

void print_stats(const ex::AovRender& r) {
  const double n = static_cast<double>(std::max<uint64_t>(r.camera_rays, 1));
  fmt::print(
      stderr,
      "snell explain: {} camera rays; per camera ray: {:.2f} accelerator nodes visited, {:.2f} objects "
      "tested, {:.3f} rays cast\n",
      r.camera_rays, double(r.nodes) / n, double(r.primitives) / n, double(r.rays) / n);
  fmt::print(stderr, "  most tested objects:\n");
  for (size_t i = 0; i < r.object_costs.size() && i < 10; ++i)
    fmt::print(stderr, "  {:>10} tests  object {:<6} {}\n", r.object_costs[i].tests,
               r.object_costs[i].index + 1, ex::object_label(*r.object_costs[i].object));
}

}  // namespace

void add_layer_options(CLI::App& app, LayerRequest& r) {
  app.add_option("--aov", r.aovs,
                 "layers for a multi-layer EXR: depth,normal,albedo,position,object,material,uv,"
                 "samples,cost,time")
      ->delimiter(',');
  app.add_flag("--aov-png", r.aov_png, "also write each layer as a PNG with its legend");
  app.add_option("--heatmap", r.heatmaps, "heatmap PNGs with a scale bar: cost, time, samples, depth")
      ->delimiter(',');
  app.add_option("--split-bounces", r.split_bounces,
                 "write direct light and each reflection and refraction depth up to N as EXR layers");
  app.add_flag("--stats", r.stats, "print the cost per camera ray and the ten most tested objects");
  app.add_option("-o,--output", r.output, "base name of layer outputs (default: the scene's name)");
}

bool check_layer_request(LayerRequest& r, const fs::path& scene_file) {
  for (const std::string& name : r.aovs)
    if (std::find(ex::aov_names().begin(), ex::aov_names().end(), name) == ex::aov_names().end())
      throw UsageError(
          fmt::format("--aov {}: unknown layer (known: depth, normal, albedo, position, object, "
                      "material, uv, samples, cost, time)",
                      name));
  for (const std::string& name : r.heatmaps)
    if (!contains(kHeatmaps, name))
      throw UsageError(
          fmt::format("--heatmap {}: unknown heatmap (known: cost, time, samples, depth)", name));
  if (r.split_bounces < -1 || r.split_bounces > 20)
    throw UsageError("--split-bounces must be between 0 and 20");
  if (r.aov_png && r.aovs.empty() && r.split_bounces < 0)
    throw UsageError("--aov-png needs --aov or --split-bounces");
  const bool any = !r.aovs.empty() || !r.heatmaps.empty() || r.split_bounces >= 0 || r.stats;
  if (!any) return false;
  if (r.output.empty()) r.output = scene_file.stem();
  check_writable(with_suffix(r.output, ".exr"), "-o");
  return true;
}

void write_layers(const LayerRequest& r, const scene::Scene& scene, const accel::Accelerator& accelerator,
                  const render::RenderOptions& options) {
  const bool exr = !r.aovs.empty() || r.split_bounces >= 0;
  if (exr) io::preload_image_backend();
  std::vector<std::string> names = r.aovs;
  for (const std::string& h : r.heatmaps)
    if (!contains(names, h)) names.push_back(h);
  if (r.stats && !contains(names, "cost")) names.push_back("cost");
  const ex::AovRender result = ex::render_aovs(scene, accelerator, options, names, r.split_bounces);
  const int w = options.width, h = options.height;
  const size_t n = static_cast<size_t>(w) * h;
  io::Encoding encoding;
  encoding.assumed_gamma = scene.effective_assumed_gamma();
  encoding.passthrough = scene.settings.assumed_gamma <= 0 && scene.settings.language_version < 3.7;

  // Layers that go into the EXR and the PNGs: the ones asked for by --aov, then the bounce images.
  std::vector<const ex::Layer*> written;
  for (const ex::Layer& l : result.layers)
    if (contains(r.aovs, l.name) || !contains(names, l.name)) written.push_back(&l);
  if (exr) {
    std::vector<std::string> channels{"R", "G", "B"};
    for (const ex::Layer* l : written)
      for (const std::string& c : l->channels) channels.push_back(l->name + "." + c);
    std::vector<float> pixels;
    pixels.reserve(n * channels.size());
    for (size_t i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) pixels.push_back(result.beauty.rgb[i * 3 + static_cast<size_t>(c)]);
      for (const ex::Layer* l : written)
        for (size_t c = 0; c < l->channels.size(); ++c)
          pixels.push_back(l->values[i * l->channels.size() + c]);
    }
    io::write_layered_exr(with_suffix(r.output, ".exr"), w, h, channels, pixels);
  }
  if (r.aov_png)
    for (const ex::Layer* l : written) {
      const fs::path path = with_suffix(r.output, "." + l->name + ".png");
      const bool bounce = !contains(names, l->name);
      ex::write_picture(path,
                        bounce ? colour_picture(l->values, w, h, encoding) : ex::layer_picture(*l, w, h));
    }
  for (const std::string& heat : r.heatmaps)
    for (const ex::Layer& l : result.layers)
      if (l.name == heat) {
        ex::write_picture(with_suffix(r.output, ".heatmap-" + heat + ".png"), ex::layer_picture(l, w, h));
      }
  if (r.stats) print_stats(result);
}

}  // namespace snell::cli
