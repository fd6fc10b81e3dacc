// `snell explain`: the ray tree of one pixel (text, --json, --svg), and the layer images of a whole render
// (--aov, --heatmap, --split-bounces). See docs/explain.md.
#include "cli/explain_command.hpp"

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <tuple>

#include "cli/accelerator_choice.hpp"
#include "cli/app.hpp"
#include "cli/explain_layers.hpp"
#include "cli/options.hpp"
#include "cli/text_output.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/explain/explain_pixel.hpp"
#include "snell/render/explain/tree_json.hpp"
#include "snell/render/explain/tree_svg.hpp"
#include "snell/render/explain/tree_text.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::cli {

namespace {

namespace fs = std::filesystem;

struct ExplainOptions : LayerRequest {
  fs::path scene;
  std::string pixel;
  int sample = 0;
  int width = 320;
  int height = 240;
  std::optional<double> aa;
  int aa_depth = 3;
  bool jitter = true;  // as POV-Ray and snell render
  std::string accel = "auto";
  std::vector<fs::path> library_paths;
  int threads = 0;
  fs::path json;
  fs::path svg;
};

/// "X,Y" with whole numbers; anything else is a usage error.
std::pair<int, int> parse_pixel(const std::string& text) {
  int x = 0, y = 0;
  char comma = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d %c %d %c", &x, &comma, &y, &extra) != 3 || comma != ',')
    throw UsageError(fmt::format("--pixel {}: expected X,Y (whole numbers, 0,0 is the top left)", text));
  return {x, y};
}

render::RenderOptions render_options(const ExplainOptions& o) {
  render::RenderOptions ro;
  ro.width = o.width;
  ro.height = o.height;
  ro.antialias = o.aa.has_value();
  ro.aa_threshold = o.aa.value_or(0.3);
  ro.aa_depth = o.aa_depth;
  ro.jitter = o.jitter;
  ro.threads = o.threads;
  if (ro.threads < 0) throw UsageError("--threads must not be negative");
  if (ro.width <= 0 || ro.height <= 0 || ro.width > 65536 || ro.height > 65536)
    throw UsageError(fmt::format("image size {}x{}: each side must be 1..65536", ro.width, ro.height));
  if (ro.aa_depth < 1 || ro.aa_depth > 9) throw UsageError("--aa-depth must be between 1 and 9");
  return ro;
}

scene::Scene load_scene(const ExplainOptions& o) {
  sdl::ParseOptions po;
  po.library_paths = o.library_paths;
  po.library_paths.emplace_back(POVRAY_INCLUDE_DIR);
  po.image_width = o.width;
  po.image_height = o.height;
  return sdl::parse_scene_file(o.scene, po);
}

}  // namespace

int run_explain(const std::vector<std::string>& args) {
  ExplainOptions o;
  CLI::App app("snell explain: shows how a pixel's colour is made (docs/explain.md)", "snell explain");
  app.set_help_flag("--help", "print this help");
  app.add_option("scene", o.scene, "scene file (.pov)")->required();
  app.add_option("--pixel", o.pixel, "the pixel to explain, X,Y from the top left");
  app.add_option("--sample", o.sample, "which sample: 0 the pixel centre, 1..depth^2 the supersamples");
  app.add_option("-w,--width", o.width, "image width in pixels (default 320)");
  app.add_option("-h,--height", o.height, "image height in pixels (default 240)");
  app.add_option("--aa", o.aa, "anti-alias with this threshold (as snell render --aa)");
  app.add_option("--aa-depth", o.aa_depth, "supersampling depth (default 3)");
  app.add_flag("--jitter,!--no-jitter", o.jitter,
               "jitter supersamples (the default; --no-jitter: a plain grid)");
  app.add_option("--accel", o.accel, "ray accelerator: " + std::string(accel::kAcceleratorKinds));
  app.add_option("-L,--library-path", o.library_paths, "folder searched by #include (repeatable)");
  app.add_option("--json", o.json, "also write the ray tree as JSON (docs/explain.schema.json)");
  app.add_option("--svg", o.svg, "also draw the ray tree over a plan of the scene (SVG)");
  app.add_option("--threads", o.threads, "render threads for layers (default: all cores)");
  add_layer_options(app, o);
  try {
    app.parse(std::vector<std::string>(args.rbegin(), args.rend()));
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return kOk;
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  // Everything about the command line is checked before the scene is read, and outputs before anything is
  // written, so a bad request costs nothing and leaves no file behind.
  render::RenderOptions ro = render_options(o);
  const bool layers = check_layer_request(o, o.scene);
  if (o.pixel.empty() && !layers)
    throw UsageError("explain needs --pixel X,Y, or layers (--aov, --heatmap, --split-bounces, --stats)");
  if (o.pixel.empty() && (!o.json.empty() || !o.svg.empty()))
    throw UsageError("--json and --svg need --pixel X,Y");
  int x = 0, y = 0;
  if (!o.pixel.empty()) {
    std::tie(x, y) = parse_pixel(o.pixel);
    if (x < 0 || y < 0 || x >= ro.width || y >= ro.height)
      throw UsageError(fmt::format("--pixel {},{} lies outside the {}x{} image (x 0..{}, y 0..{})", x, y,
                                   ro.width, ro.height, ro.width - 1, ro.height - 1));
    const int samples = render::explain::samples_per_pixel(ro);
    if (o.sample < 0 || o.sample >= samples)
      throw UsageError(fmt::format("--sample {}: this pixel has samples 0..{}{}", o.sample, samples - 1,
                                   ro.antialias ? "" : " (anti-aliasing is off)"));
  }
  if (!o.json.empty()) check_writable(o.json, "--json");
  if (!o.svg.empty()) check_writable(o.svg, "--svg");

  const scene::Scene scene = load_scene(o);
  ro.aa_compare_exponent = render::aa_compare_exponent_for(scene.working_gamma(), 2.5);
  const auto accelerator = build_accelerator(o.accel, scene);
  if (!o.pixel.empty()) {
    const render::explain::PixelExplanation e =
        render::explain::explain_pixel(scene, *accelerator, ro, x, y, o.sample);
    std::fputs(render::explain::tree_text(e, scene).c_str(), stdout);
    if (!o.json.empty()) write_text_file(o.json, render::explain::tree_json(e, o.scene.string()));
    if (!o.svg.empty()) write_text_file(o.svg, render::explain::tree_svg(e, scene));
  }
  if (layers) write_layers(o, scene, *accelerator, ro);
  return kOk;
}

}  // namespace snell::cli
