#include "cli/app.hpp"

#include <fmt/core.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>

#include "cli/options.hpp"
#include "cli/progress.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/io/image_backend.hpp"
#include "snell/io/image_file.hpp"
#include "snell/render/renderer.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::cli {

namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_sigint(int) {
  g_interrupted.store(true);
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

const char* kPovHelp =
    "POV-Ray form:\n"
    "  snell +Iscene.pov [+Oout.png] [+W640] [+H480] [+A[0.3]] [+R3] [+J[1.0]] [+Ldir] [+WTn]\n"
    "        [+FN|+FN16|+FE|+FH] [-D] [Declare=NAME=value] [--quiet] [--stats] [--accel NAME]\n"
    "  snell --parse-only scene.pov   parses and builds the scene, prints a summary\n"
    "  -A / -J turn anti-aliasing / jitter off. Unknown or unsupported flags are warned about, never fatal.\n"
    "Exit codes: 0 ok, 1 scene error, 2 bad command line, 3 output error, 130 interrupted.\n";

std::unique_ptr<CLI::App> make_render_app(CliOptions& o, std::string& accel) {
  auto app = std::make_unique<CLI::App>("snell: renders POV-Ray 3.7 scenes", "snell");
  app->set_version_flag("--version", std::string("snell ") + SNELL_VERSION);
  app->require_subcommand(1);
  app->footer(kPovHelp);
  app->set_help_flag("--help", "print this help");
  CLI::App* render = app->add_subcommand("render", "render a scene to an image");
  render->set_help_flag("--help", "print this help");
  render->add_option("scene", o.input, "scene file (.pov)")->required();
  render->add_option("-o,--output", o.output, "output image (.png, .exr, .hdr); default: <scene>.png");
  render->add_option("-w,--width", o.width, "image width in pixels (default 800)");
  render->add_option("-h,--height", o.height, "image height in pixels (default 600)");
  render->add_option("--aa", o.aa_threshold, "anti-alias with this threshold (POV-Ray +A)")
      ->each([&o](const std::string&) { o.antialias = true; });
  render->add_option("--aa-depth", o.aa_depth,
                     "supersampling depth: depth^2 extra rays (POV-Ray +R, default 3)");
  render->add_flag("--jitter", o.jitter, "jitter supersamples (POV-Ray +J)");
  render->add_option("--threads", o.threads, "render threads (default: all cores)");
  render->add_option("--accel", accel, "ray accelerator: embree or none (default: embree when built)");
  render->add_option("--bits", o.bits, "PNG bit depth: 8 or 16");
  render->add_option("-L,--library-path", o.library_paths, "folder searched by #include (repeatable)");
  render->add_flag("--quiet", o.quiet, "no progress, warnings or statistics");
  render->add_flag("--stats", o.stats, "print statistics even with --quiet");
  render->add_flag("--parse-only", o.parse_only, "parse and build the scene, print a summary, render nothing");
  return app;
}

std::unique_ptr<accel::Accelerator> build_accelerator(const std::string& name, const scene::Scene& scene) {
  if (name != "auto") return accel::make_accelerator(name, scene);
  try {
    return accel::make_accelerator("embree", scene);
  } catch (const std::invalid_argument&) {
    return accel::make_accelerator("none", scene);
  }
}

int render(CliOptions& o) {
  validate(o);
  if (!o.quiet)
    for (const std::string& w : o.warnings) fmt::print(stderr, "snell: warning: {}\n", w);

  // Load the image plugin while the scene is parsed and rendered (snell/io/oiio_plugin_abi.hpp).
  if (!o.parse_only) io::preload_image_backend();
  const auto t_parse = Clock::now();
  sdl::ParseOptions po;
  po.library_paths = o.library_paths;
  po.library_paths.emplace_back(POVRAY_INCLUDE_DIR);
  po.image_width = o.width;
  po.image_height = o.height;
  po.declares = o.declares;
  const scene::Scene scene = sdl::parse_scene_file(o.input, po);
  const double parse_s = seconds_since(t_parse);
  if (o.parse_only) {
    fmt::print("snell: parsed {}: {} objects, {} lights, parse {:.3f}s\n", o.input.string(), scene.objects.size(),
               scene.lights.size(), parse_s);
    return kOk;
  }

  const auto t_build = Clock::now();
  const auto accelerator = build_accelerator(o.accel, scene);
  const double build_s = seconds_since(t_build);

  render::RenderOptions ro;
  ro.width = o.width;
  ro.height = o.height;
  ro.antialias = o.antialias;
  ro.aa_threshold = o.aa_threshold;
  ro.aa_depth = o.aa_depth;
  ro.jitter = o.jitter;
  ro.jitter_amount = o.jitter_amount;
  ro.threads = o.threads;
  ro.cancel = &g_interrupted;
  Progress progress(!o.quiet);
  ro.progress = [&progress](double f) { progress.update(f); };

  std::signal(SIGINT, on_sigint);
  const auto t_render = Clock::now();
  const render::RenderResult result = render::Renderer(scene, *accelerator, ro).render();
  const double render_s = seconds_since(t_render);
  progress.finish(render_s);

  const auto t_write = Clock::now();
  io::WriteOptions wo;
  wo.bits = o.bits;
  wo.encoding.assumed_gamma = scene.effective_assumed_gamma();
  wo.encoding.passthrough = scene.settings.assumed_gamma <= 0 && scene.settings.language_version < 3.7;
  io::write_image(o.output, result.image, wo);
  const double write_s = seconds_since(t_write);

  if (!o.quiet)
    for (const auto& note : scene.render_notes)
      if (const std::string text = note(); !text.empty()) fmt::print(stderr, "{}\n", text);
  if (!o.quiet || o.stats) {
    const render::RayCounters& r = result.rays;
    fmt::print(stderr,
               "snell: {}x{} -> {}\n"
               "  rays: {} camera, {} reflected, {} refracted, {} shadow ({} total); {} pixels supersampled\n"
               "  time: parse {:.3f}s, build {:.3f}s ({}), render {:.3f}s, write {:.3f}s\n",
               o.width, o.height, o.output.string(), r.camera, r.reflected, r.refracted, r.shadow, r.total(),
               result.supersampled_pixels, parse_s, build_s, accelerator->name(), render_s, write_s);
  }
  if (result.cancelled) {
    fmt::print(stderr, "snell: interrupted; the partial image was written to {}\n", o.output.string());
    return kInterrupted;
  }
  return kOk;
}

}  // namespace

int run_app(const std::vector<std::string>& args) {
  try {
    if (!args.empty() && args[0] == "render") {
      CliOptions o;
      std::string accel = o.accel;
      auto app = make_render_app(o, accel);
      std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them back to front
      try {
        app->parse(reversed);
      } catch (const CLI::CallForHelp& e) {
        std::fputs(app->get_subcommand("render")->help().c_str(), stdout);
        return kOk;
      } catch (const CLI::ParseError& e) {
        throw UsageError(e.what());
      }
      o.accel = accel;
      return render(o);
    }
    if (args.size() == 1 && args[0] == "--version") {
      fmt::print("snell {}\n", SNELL_VERSION);
      return kOk;
    }
    if (args.empty() || (args.size() == 1 && (args[0] == "--help" || args[0] == "-h" || args[0] == "help"))) {
      CliOptions o;
      std::string accel;
      auto app = make_render_app(o, accel);
      std::fputs(app->help().c_str(), stdout);
      std::fputs(app->get_subcommand("render")->help().c_str(), stdout);
      return args.empty() ? kUsageError : kOk;
    }
    CliOptions o = parse_pov_arguments(args);
    return render(o);
  } catch (const UsageError& e) {
    fmt::print(stderr, "snell: error: {}\n", e.what());
    return kUsageError;
  } catch (const sdl::ParseError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kSceneError;
  } catch (const io::ImageIoError& e) {
    fmt::print(stderr, "snell: error: {}\n", e.what());
    return kIoError;
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "snell: error: {}\n", e.what());
    return kUsageError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "snell: error: {}\n", e.what());
    return kIoError;
  }
}

}  // namespace snell::cli
