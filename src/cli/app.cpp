#include "cli/app.hpp"

#include <fmt/core.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <mutex>

#include "cli/accelerator_choice.hpp"
#include "cli/checkpoint.hpp"
#include "cli/distributed.hpp"
#include "cli/explain_command.hpp"
#include "cli/frame_loop.hpp"
#include "cli/merge_command.hpp"
#include "cli/options.hpp"
#include "cli/preview/open_preview.hpp"
#include "cli/progress.hpp"
#include "cli/render_fingerprint.hpp"
#include "cli/video.hpp"
#include "cli/watch.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/accel/embree_accelerator.hpp"
#include "snell/accel/object_test_counter.hpp"
#include "snell/io/image_backend.hpp"
#include "snell/io/image_file.hpp"
#include "snell/memory/budget.hpp"
#include "snell/render/renderer.hpp"
#include "snell/render/resume_file.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::cli {

namespace {

std::atomic<bool> g_interrupted{false};

// The first SIGINT/SIGTERM lets running tiles finish and the partial image and resume file be written; a
// second one ends the process at once. Files are only ever renamed into place, so none is left broken.
extern "C" void on_stop_signal(int) {
  if (g_interrupted.exchange(true)) _exit(130);
}

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

/// Errors are the same on every rank of a distributed render; rank 0 prints them once. A rank rendering
/// whole frames alone prints its own (`every_rank`).
void report_error(const char* what, bool every_rank = false) {
  if (every_rank || distributed::rank() == 0) fmt::print(stderr, "snell: error: {}\n", what);
}

/// Prints the exception being handled and returns its exit code.
int report_current_exception(bool every_rank = false) {
  try {
    throw;
  } catch (const UsageError& e) {
    report_error(e.what(), every_rank);
    return kUsageError;
  } catch (const sdl::ParseError& e) {
    if (every_rank || distributed::rank() == 0) fmt::print(stderr, "{}\n", e.what());
    return kSceneError;
  } catch (const render::ResumeError& e) {
    report_error(e.what(), every_rank);
    return kUsageError;
  } catch (const io::ImageIoError& e) {
    report_error(e.what(), every_rank);
    return kIoError;
  } catch (const std::invalid_argument& e) {
    report_error(e.what(), every_rank);
    return kUsageError;
  } catch (const std::exception& e) {
    report_error(e.what(), every_rank);
    return kIoError;
  }
}

std::string version_line() {
  return fmt::format("snell {} ({})", SNELL_VERSION, distributed::support());
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

const char* kPovHelp =
    "POV-Ray form:\n"
    "  snell +Iscene.pov [+Oout.png] [+W640] [+H480] [+A[0.3]] [+R3] [+J[1.0]] [+Ldir] [+WTn]\n"
    "        [+FN|+FN16|+FE|+FH] [+D [+P]] [Declare=NAME=value] [--quiet] [--stats] [--accel NAME]\n"
    "  snell --parse-only scene.pov   parses and builds the scene, prints a summary\n"
    "  +SR/+ER/+SC/+EC partial render, +C continue an interrupted one, --checkpoint S\n"
    "  +KFI1 +KFF120 (or --frames 1-120) +KI0 +KF1 +KC +SFn +EFn: an animation, out.png -> out001.png...;\n"
    "  --video out.mp4 [--fps 24] joins the frames with ffmpeg when it is installed\n"
    "  +D / --display render window, --watch render again on every change of the scene or its files\n"
    "  snell merge part1.exr part2.exr -o out.png   joins partial renders\n"
    "  snell explain scene.pov --pixel X,Y   shows how a pixel is made (snell explain --help)\n"
    "  -A / -J turn anti-aliasing / jitter off. Unknown or unsupported flags are warned about, never fatal.\n"
    "Exit codes: 0 ok, 1 scene error, 2 bad command line, 3 output error, 130 interrupted.\n";

std::unique_ptr<CLI::App> make_render_app(CliOptions& o, std::string& accel) {
  auto app = std::make_unique<CLI::App>("snell: renders POV-Ray 3.7 scenes", "snell");
  app->set_version_flag("--version", version_line());
  app->require_subcommand(1);
  app->footer(kPovHelp);
  app->set_help_flag("--help", "print this help");
  CLI::App* render = app->add_subcommand("render", "render a scene to an image");
  render->set_help_flag("--help", "print this help");
  render->add_option("scene", o.input, "scene file (.pov)")->required();
  render->add_option("-o,--output", o.output, "output image (.png, .exr, .hdr); default: <scene>.png");
  render->add_option("-w,--width", o.width, "image width in pixels (default 800)")
      ->each([&o](const std::string&) { o.size_given = true; });
  render->add_option("-h,--height", o.height, "image height in pixels (default 600)")
      ->each([&o](const std::string&) { o.size_given = true; });
  render->add_option("--aa", o.aa_threshold, "anti-alias with this threshold (POV-Ray +A)")
      ->each([&o](const std::string&) { o.antialias = true; });
  render->add_option("--aa-gamma", o.aa_gamma,
                     "gamma the anti-aliasing test compares colours in (POV-Ray +AG, default 2.5)");
  render->add_option("--aa-depth", o.aa_depth,
                     "supersampling depth: depth^2 extra rays (POV-Ray +R, default 3)");
  render->add_flag("--jitter,!--no-jitter", o.jitter,
                   "jitter supersamples as POV-Ray does (the default, +J); --no-jitter: a plain grid (-J)");
  render->add_option("--aa-method", o.aa_method, "anti-aliasing method 1 or 2 (POV-Ray +AM, default 1)");
  render->add_option(
      "--spp", o.samples_per_pixel,
      "N samples in every pixel (over pixel, lens and shutter) instead of POV-Ray anti-aliasing");
  render->add_option("--sampler", o.sampler,
                     "sample sequence for --spp and blur: sobol (default), halton, stratified");
  render->add_option(
      "--filter", o.filter,
      "pixel filter NAME[:RADIUS]: box (default, 0.5), tent (1), gaussian (1.5), mitchell (2)");
  render->add_option("--threads", o.threads, "render threads (default: all cores)");
  render->add_option("--integrator", o.integrator, "whitted (POV-Ray's shading, default) or path");
  render->add_option("--accel", accel,
                     "ray accelerator: " + std::string(accel::kAcceleratorKinds) +
                         " (default: list for scenes of a few objects, else embree)");
  render->add_option("--bits", o.bits, "PNG bit depth: 8 or 16");
  render->add_option("-L,--library-path", o.library_paths, "folder searched by #include (repeatable)");
  render->add_flag("--quiet", o.quiet, "no progress, warnings or statistics");
  render->add_flag("--stats", o.stats, "print statistics even with --quiet");
  render->add_flag("--display", o.display, "show the render in a window (POV-Ray +D)");
  render->add_option("--display-snapshot", o.display_snapshot)->group("");  // test hook: window pixels as PNG
  render->add_flag("--watch", o.watch,
                   "render again whenever the scene or a file it reads changes (320x240 unless -w/-h)");
  render->add_flag("--parse-only", o.parse_only,
                   "parse and build the scene, print a summary, render nothing");
  render->add_option("--start-row", o.start_row,
                     "partial render: first row (1-based, or a fraction like 0.5)");
  render->add_option("--end-row", o.end_row, "partial render: last row (inclusive, or a fraction)");
  render->add_option("--start-col", o.start_col, "partial render: first column (1-based, or a fraction)");
  render->add_option("--end-col", o.end_col, "partial render: last column (inclusive, or a fraction)");
  render->add_flag("-c,--continue", o.resume,
                   "finish an interrupted render from its resume file (POV-Ray +C)");
  render->add_option("--checkpoint", o.checkpoint_seconds,
                     "write the resume file every S seconds while rendering");
  render->add_option_function<std::string>(
      "--frames",
      [&o](const std::string& r) { parse_frame_range("--frames", r, o.initial_frame, o.final_frame); },
      "animation: render frames A-B, out.png -> out1.png... (POV-Ray +KFI/+KFF)");
  render
      ->add_option_function<std::vector<double>>(
          "--clock",
          [&o](const std::vector<double>& v) {
            o.initial_clock = v.at(0);
            o.final_clock = v.at(1);
          },
          "animation: clock at the initial and at the final frame (default 0 1; POV-Ray +KI/+KF)")
      ->expected(2);
  render->add_flag("--cyclic", o.cyclic,
                   "animation: the last frame stops one step before the final clock (+KC)");
  render->add_option_function<std::string>(
      "--subset",
      [&o](const std::string& r) {
        int first = 0, last = 0;
        parse_frame_range("--subset", r, first, last);
        o.subset_start = first;
        o.subset_end = last;
      },
      "animation: render only frames A-B of the range (POV-Ray +SF/+EF)");
  render->add_option("--video", o.video, "animation: join the frames into this video with ffmpeg (.mp4)");
  render->add_option("--fps", o.fps, "frames per second of --video (default 24)");
  render->add_option("--max-loop", o.max_loop, "most iterations of one #while or #for (default 10 million)");
  render->add_option(
      "--max-memory", o.max_memory,
      "memory the scene's meshes, images and arrays may take, e.g. 2G or 512M (default: 3/4 of RAM)");
  return app;
}

/// One frame (or the still): parse, render, write. The scene is parsed again for every frame, since scenes
/// branch on clock.
int render_frame(CliOptions o, const FramePlan& plan, const PixelBounds& bounds, const FrameTask& task) {
  o.output = task.output;
  o.frame = task.number;
  o.resume = task.resume;
  const auto t_parse = Clock::now();
  sdl::ParseOptions po;
  po.library_paths = o.library_paths;
  po.library_paths.emplace_back(POVRAY_INCLUDE_DIR);
  po.image_width = o.width;
  po.image_height = o.height;
  po.declares = o.declares;
  po.max_while_iterations = o.max_loop;
  apply_frame(plan, task.number, po);
  po.on_file_read = o.on_file_read;
  po.memory_budget = std::make_shared<memory::Budget>(
      o.max_memory.empty() ? memory::default_limit() : *memory::parse_size(o.max_memory));
  const scene::Scene scene = sdl::parse_scene_file(o.input, po);
  const double parse_s = seconds_since(t_parse);
  if (o.parse_only) {
    fmt::print("snell: parsed {}: {} objects, {} lights, parse {:.3f}s\n", o.input.string(),
               scene.objects.size(), scene.lights.size(), parse_s);
    return kOk;
  }

  if (g_interrupted) {
    fmt::print(stderr, "snell: interrupted before rendering; nothing written\n");
    return kInterrupted;
  }
  const auto t_build = Clock::now();
  const auto accelerator = build_accelerator(o.accel, scene);
  const double build_s = seconds_since(t_build);
  accel::ObjectTestCounter::enabled = o.stats;  // tests per ray for --stats

  render::RenderOptions ro;
  ro.width = o.width;
  ro.height = o.height;
  ro.antialias = o.antialias;
  ro.aa_threshold = o.aa_threshold;
  ro.aa_compare_exponent = render::aa_compare_exponent_for(scene.working_gamma(), o.aa_gamma);
  ro.aa_depth = o.aa_depth;
  ro.jitter = o.jitter;
  ro.jitter_amount = o.jitter_amount;
  ro.aa_method = o.aa_method;
  ro.samples_per_pixel = o.samples_per_pixel;
  ro.sampler = o.sampler;
  ro.filter = o.filter;
  ro.threads = o.threads;
  ro.integrator = o.integrator;
  ro.region = {bounds.x0, bounds.y0, bounds.x1, bounds.y1};
  ro.cancel = &g_interrupted;
  Progress progress(!o.quiet);
  io::WriteOptions wo;
  wo.bits = o.bits;
  wo.encoding.assumed_gamma = scene.effective_assumed_gamma();
  wo.encoding.passthrough = scene.settings.assumed_gamma <= 0 && scene.settings.language_version < 3.7;
  const std::unique_ptr<PreviewWindow> preview = o.display ? open_preview(o, wo.encoding) : nullptr;

  const uint64_t fingerprint = render_fingerprint(o, bounds);
  io::Image image(o.width, o.height);
  image.clear_alpha();
  std::vector<render::Tile> resumed;
  if (o.resume) {
    if (std::filesystem::exists(resume_path(o.output))) {
      render::ResumeData data =
          render::read_resume_file(resume_path(o.output), fingerprint, o.width, o.height);
      image = std::move(data.image);
      resumed = std::move(data.tiles);
      if (!o.quiet) fmt::print(stderr, "snell: continuing: {} tiles already rendered\n", resumed.size());
    } else if (!o.quiet) {
      fmt::print(stderr, "snell: warning: no resume file {}; rendering from the start\n",
                 resume_path(o.output).string());
    }
  }
  Checkpoint checkpoint(resume_path(o.output), fingerprint, image, resumed, o.checkpoint_seconds);
  std::vector<bool> resumed_index(static_cast<size_t>(render::tiles_across(o.width)) *
                                  render::tiles_down(o.height));
  for (const render::Tile& t : resumed) resumed_index[static_cast<size_t>(t.index)] = true;
  if (preview) show_in_preview(*preview, resumed, image);
  distributed::Job job{scene, *accelerator, ro, {}, {}};
  for (const render::Tile& t : render::make_tiles(o.width, o.height, ro.region))
    if (!resumed_index[static_cast<size_t>(t.index)]) job.tiles.push_back(t);
  // Progress counts tiles as they reach this process's image (on rank 0 also other ranks' tiles).
  std::mutex progress_mutex;
  size_t tiles_finished = 0;
  job.tile_done = [&](const render::Tile& t) {
    checkpoint.tile_done(t);
    std::lock_guard lock(progress_mutex);
    const double fraction = static_cast<double>(++tiles_finished) / static_cast<double>(job.tiles.size());
    progress.update(fraction);
    if (preview) show_in_preview(*preview, t, image, fraction);
  };

  const auto t_render = Clock::now();
  const render::RenderStats result =
      task.whole_frame ? distributed::render_alone(job, image) : distributed::render(job, image);
  const double render_s = seconds_since(t_render);
  progress.finish(render_s);
  // Other ranks have sent their tiles to rank 0, which writes the image (a whole frame: this rank).
  if (!task.whole_frame && distributed::rank() != 0) return result.cancelled ? kInterrupted : kOk;

  const auto t_write = Clock::now();
  // Unrendered pixels (a partial or interrupted render) stay transparent; a full image is written as RGB.
  image.drop_alpha_if_covered();
  io::write_image(o.output, image, wo);
  if (result.cancelled)
    checkpoint.save();
  else
    checkpoint.remove();
  const double write_s = seconds_since(t_write);

  if (!o.quiet)
    for (const auto& note : scene.render_notes)
      if (const std::string text = note(); !text.empty()) fmt::print(stderr, "{}\n", text);
  if (result.rays.non_finite_samples > 0)  // the renderer's guard (render/finite_sample.hpp) fired
    fmt::print(stderr, "snell: warning: {} samples were NaN or infinite and were rendered black\n",
               result.rays.non_finite_samples);
  if (!o.quiet || o.stats) {
    const render::RayCounters& r = result.rays;
    fmt::print(stderr,
               "snell: {}x{} -> {}\n"
               "  rays: {} camera, {} reflected, {} refracted, {} shadow ({} total); {} pixels supersampled\n"
               "  time: parse {:.3f}s, build {:.3f}s ({}), render {:.3f}s, write {:.3f}s\n",
               o.width, o.height, o.output.string(), r.camera, r.reflected, r.refracted, r.shadow, r.total(),
               result.supersampled_pixels, parse_s, build_s, accelerator->name(), render_s, write_s);
  }
  if (o.stats) {
    const accel::AcceleratorStats a = accelerator->stats();
    const double tests = static_cast<double>(accel::ObjectTestCounter::total());
    fmt::print(
        stderr,
        "  accel: {} objects ({} unbounded), {} nodes, {:.1f} KiB, built in {:.3f}s, {:.2f} object tests per "
        "ray\n",
        a.objects, a.unbounded_objects, a.nodes, static_cast<double>(a.memory_bytes) / 1024, a.build_seconds,
        tests / static_cast<double>(std::max<uint64_t>(1, result.rays.total())));
    if (a.mesh_instances > 0)
      fmt::print(stderr, "  accel: {} mesh instances of {} native triangles\n", a.mesh_instances,
                 a.native_triangles);
    // The integrator's own lines (radiosity cache, photon map), indented like the others.
    if (!result.integrator_summary.empty()) {
      std::string lines = result.integrator_summary;
      for (size_t at = lines.find('\n'); at != std::string::npos; at = lines.find('\n', at + 3))
        lines.replace(at, 1, "\n  ");
      fmt::print(stderr, "  {}\n", lines);
    }
  }
  if (preview) preview->finish(o.display_snapshot, o.pause_when_done, &g_interrupted);
  if (result.cancelled) {
    fmt::print(stderr,
               "snell: interrupted; the partial image was written to {} and the finished tiles to {}\n"
               "snell: to finish it, run the same command again with +C (or --continue)\n",
               o.output.string(), checkpoint.path().string());
    return kInterrupted;
  }
  return kOk;
}

int render(CliOptions& o) {
  validate(o);
  const FramePlan plan = plan_frames(o);
  if (!o.video.empty() && !plan.animated)
    throw UsageError("--video needs an animation: a frame range such as --frames 1-24 or +KFI1 +KFF24");
  if (o.fps <= 0) throw UsageError("--fps must be positive");
  const bool announce = !o.quiet;
  // Every rank parses and renders; only rank 0 reports and writes (and, with whole frames, each rank).
  if (distributed::rank() != 0) {
    o.quiet = true;
    o.stats = false;
  }
  const PixelBounds bounds = render_region(o);
  install_stop_handlers();
  if (!o.quiet)
    for (const std::string& w : o.warnings) fmt::print(stderr, "snell: warning: {}\n", w);

  // Load the image plugin while the scene is parsed and rendered (snell/io/oiio_plugin_abi.hpp); PNG output
  // does without it (a scene's image maps load it when they are parsed).
  if (!o.parse_only && io::writes_through_plugin(o.output)) io::preload_image_backend();
  if (!o.parse_only && (o.accel == "auto" || o.accel == "embree"))
    accel::warm_up_embree();  // overlaps parsing
  const int code = render_frames(o, plan, announce, &g_interrupted, [&](const FrameTask& task) {
    try {
      return render_frame(o, plan, bounds, task);
    } catch (...) {
      // A rank rendering a frame alone is the only one to see its error: it reports it and ends the job.
      if (!task.whole_frame || distributed::size() == 1) throw;
      distributed::abort_all(report_current_exception(/*every_rank=*/true));
    }
  });
  if (code == kOk && !o.video.empty() && !o.parse_only && distributed::rank() == 0)
    make_video(plan, o.output, o.video, o.fps);
  return code;
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
      return o.watch ? watch_and_render(o, render, g_interrupted) : render(o);
    }
    if (!args.empty() && args[0] == "merge") return run_merge({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "explain") return run_explain({args.begin() + 1, args.end()});
    if (args.size() == 1 && args[0] == "--version") {
      fmt::print("{}\n", version_line());
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
    return o.watch ? watch_and_render(o, render, g_interrupted) : render(o);
  } catch (...) {
    return report_current_exception();
  }
}

}  // namespace snell::cli
