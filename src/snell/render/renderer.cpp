#include "snell/render/renderer.hpp"

#include "snell/render/aa_neighbours.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include <algorithm>
#include <bit>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "snell/math/pcg32.hpp"
#include "snell/render/finite_sample.hpp"
#include "snell/render/first_sample_grid.hpp"
#include "snell/render/integrator.hpp"
#include "snell/render/pixel_estimators.hpp"
#include "snell/render/two_pass_queue.hpp"
#include "snell/scene/blur_confidence.hpp"
#include "snell/scene/hex_lens_grid.hpp"
#include "snell/scene/lens_samples.hpp"
#include "snell/texture/povray_noise.hpp"

namespace snell::render {

using math::Color;

#if defined(__SSE__)
/// MXCSR flush-to-zero (bit 15) and denormals-are-zero (bit 6).
constexpr unsigned kFlushDenormals = 0x8040;
#endif

math::Vec2 sample_position(const RenderOptions& options, int x, int y, int k) {
  const double w = options.width, h = options.height;
  if (k == 0) return {(x + 0.5) / w, (y + 0.5) / h};
  const int n = options.aa_depth;
  const int i = (k - 1) % n, j = (k - 1) / n;
  double dx = (i + 0.5) / n, dy = (j + 0.5) / n;
  if (options.jitter) {
    // POV-Ray's jitter (tracetask.cpp, SupersampleOnePixel; jitter.h, Jitter2d): a fixed offset for each
    // sub-sample's point, looked up from where it lies with pixel centres at integers, its grid offsets
    // summed step by step as POV-Ray sums them, scaled by the amount (at most 1) over the grid size.
    const double step = 1.0 / n, range = 0.5 - step * 0.5;
    double xx = -range, yy = -range;
    for (int s = 0; s < i; ++s) xx += step;
    for (int s = 0; s < j; ++s) yy += step;
    const math::Vec2 r = texture::povray_jitter2d(x + xx, y + yy);
    const double scale = std::clamp(options.jitter_amount, 0.0, 1.0) / n;
    dx += r.u * scale;
    dy += r.v * scale;
  }
  return {(x + dx) / w, (y + dy) / h};
}

void seed_camera_sample(math::Pcg32& rng, double sx, double sy, const RenderOptions& options) {
  rng.seed(math::mix_seed(std::bit_cast<uint64_t>(sx), std::bit_cast<uint64_t>(sy),
                          static_cast<uint64_t>(options.frame), options.seed),
           0x5851f42d4c957f2dULL);
}

double color_distance(const Color& a, const Color& b) {
  return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
}

Color aa_encoded(const Color& c, double exponent) {
  if (exponent == 1.0) return c;
  auto channel = [&](double v) { return v > 0 ? std::pow(v, exponent) : 0.0; };
  return {channel(c.r), channel(c.g), channel(c.b)};
}

double aa_compare_exponent_for(double working_gamma, double aa_gamma) {
  return aa_gamma > 0 ? working_gamma / aa_gamma : working_gamma;
}

Renderer::Renderer(const scene::Scene& scene, const accel::Accelerator& accelerator, RenderOptions options)
    : scene_(scene), accel_(accelerator), options_(std::move(options)) {
  if (options_.width <= 0 || options_.height <= 0) throw std::invalid_argument("image size must be positive");
  if (options_.width > 65536 || options_.height > 65536)
    throw std::invalid_argument("image size too large (at most 65536 pixels a side)");
  if (options_.aa_depth < 1 || options_.aa_depth > 9)
    throw std::invalid_argument("anti-aliasing depth must be between 1 and 9");
  if (options_.threads < 0) throw std::invalid_argument("thread count must not be negative");
  if (options_.aa_method != 1 && options_.aa_method != 2)
    throw std::invalid_argument("anti-aliasing method must be 1 or 2");
  if (options_.samples_per_pixel < 0 || options_.samples_per_pixel > 1 << 20)
    throw std::invalid_argument("samples per pixel must be between 0 and 1048576");
  if (!make_sampler(options_.sampler))
    throw std::invalid_argument("unknown sampler '" + options_.sampler + "' (" + std::string(kSamplerNames) +
                                ")");
  if (!Filter::parse(options_.filter))
    throw std::invalid_argument(
        "unknown filter '" + options_.filter +
        "' (box, tent, gaussian or mitchell, optionally :RADIUS with 0 < RADIUS <= 16)");
  if (!options_.region.empty() && region().empty())
    throw std::invalid_argument("the render region lies outside the image");
}

PixelRect Renderer::region() const {
  const PixelRect all{0, 0, options_.width, options_.height};
  if (options_.region.empty()) return all;
  const PixelRect& r = options_.region;
  return {std::max(r.x0, 0), std::max(r.y0, 0), std::min(r.x1, all.x1), std::min(r.y1, all.y1)};
}

io::Image Renderer::blank_target() const {
  io::Image image(options_.width, options_.height);
  image.clear_alpha();
  return image;
}

RenderResult Renderer::render() const {
  RenderResult result;
  result.image = blank_target();
  static_cast<RenderStats&>(result) = render_into(result.image);
  return result;
}

namespace {

// The most pixels one batch of two-pass anti-aliasing keeps first samples for (48 MiB of colours): a
// 1600x1200 image is one batch.
constexpr size_t kMaxGridPixels = size_t{1} << 21;

/// The colour one image point sees: its camera ray, or the mean of a mesh camera's rays there.
Color trace_camera_point(const scene::Camera& camera, const Integrator& integrator, double sx, double sy,
                         double time, TraceContext& ctx) {
  const int rays = camera.rays_per_point();
  if (rays == 1) {
    const auto ray = camera.generate_ray(sx, sy, time);
    return ray ? integrator.trace_camera_ray(*ray, ctx, camera.max_distance()) : Color{0, 0, 0};
  }
  // A mesh camera's rays_per_pixel: the mean of the rays it traces (POV-Ray's TracePixel skips the others).
  Color sum{0, 0, 0};
  int traced = 0;
  for (int n = 0; n < rays; ++n)
    if (const auto ray = camera.generate_numbered_ray(sx, sy, n, time)) {
      sum += integrator.trace_camera_ray(*ray, ctx, camera.max_distance());
      ++traced;
    }
  return traced > 0 ? sum / static_cast<double>(traced) : Color{0, 0, 0};
}

}  // namespace

RenderStats Renderer::render_into(io::Image& image) const {
  const auto integrator = make_integrator(options_.integrator, scene_, accel_);
  const auto camera = scene::make_camera(scene_.camera, options_.width, options_.height);
  const int w = options_.width, h = options_.height;
  if (image.width != w || image.height != h || !image.has_alpha())
    throw std::invalid_argument("render target does not match the image size");
  std::vector<Tile> tiles;
  if (options_.tiles)
    tiles = *options_.tiles;
  else if (!options_.tile_source)
    tiles = make_tiles(w, h, region());
  // Motion blur and --spp samples already spread over each pixel, so they are its anti-aliasing too.
  // Focal blur is anti-aliased as POV-Ray does it: a pixel that differs from a neighbour gets depth x depth
  // sub-samples, each one a whole focal-blur estimate.
  const scene::CameraSpec& cam = scene_.camera;
  const int spp = options_.samples_per_pixel;
  const bool antialias = options_.antialias && !cam.motion_blur() && spp == 0;
  const auto sampler = make_sampler(options_.sampler);
  const Filter filter = *Filter::parse(options_.filter);
  const CameraSampling sampling{*camera, cam, *integrator,    *sampler,      filter,
                                w,       h,   options_.frame, options_.seed, options_.time};

  RenderStats stats;
  tbb::enumerable_thread_specific<TraceContext> contexts;
  std::atomic<size_t> tiles_done{0};
  std::atomic<bool> stopped{false};
  std::mutex progress_mutex;
  const size_t total_tiles = tiles.size();

  auto cancelled = [&] { return options_.cancel && options_.cancel->load(std::memory_order_relaxed); };
  // Anti-aliasing's first samples traced once for all tiles (first_sample_grid.hpp) where a tile source
  // (a distributed render) does not hand tiles out one by one and samples do not depend on their tile.
  const bool two_passes =
      antialias && options_.aa_method != 2 && !options_.tile_source && !integrator->samples_depend_on_tile();
  // Progress counts tile passes: two per tile when the first samples are a pass of their own.
  std::atomic<size_t> passes_done{0};
  const size_t total_passes = total_tiles * (two_passes ? 2 : 1);
  auto pass_finished = [&] {
    const size_t done = ++passes_done;
    if (options_.progress && total_passes > 0) {
      std::lock_guard lock(progress_mutex);
      options_.progress(static_cast<double>(done) / static_cast<double>(total_passes));
    }
  };
  auto tile_finished = [&] {
    ++tiles_done;
    pass_finished();
  };

  // A point with no camera ray (outside a fisheye's circle) is black, as POV-Ray leaves it.
  // Each camera sample draws its random numbers (area light jitter) from a generator seeded by where it
  // falls in the image, so the image is the same for any thread count and tile order.
  auto trace_point = [&](double sx, double sy, TraceContext& ctx) {
    seed_camera_sample(ctx.rng, sx, sy, options_);
    return finite_or_black(trace_camera_point(*camera, *integrator, sx, sy, options_.time, ctx),
                           ctx.counters);
  };

  // Focal blur (POV-Ray "Focal Blur"): rays from points spread over the lens and over the pixel, taken in
  // batches until the pixel's mean colour is known well enough (confidence, variance) or blur_samples are
  // spent. Seeded by pixel and sample so images do not depend on threads.
  const bool focal_blur = cam.focal_blur();
  const std::vector<double> thresholds =
      focal_blur ? scene::blur_variance_thresholds(cam.blur_samples, cam.confidence, cam.variance)
                 : std::vector<double>{};
  // `sub` 0 is the pixel's first sample, spread over the pixel; anti-aliasing's sub-sample k is spread
  // over a pixel-sized square centred on its point (px, py) in pixels, as POV-Ray traces each sub-sample
  // through the whole focal blur (tracetask.cpp, SupersampleOnePixel).
  auto blurred_sample = [&](int x, int y, int sub, double px, double py, TraceContext& ctx) {
    const uint64_t pixel = static_cast<uint64_t>(y) * static_cast<uint64_t>(w) + static_cast<uint64_t>(x);
    const uint64_t frame = static_cast<uint64_t>(options_.frame);
    const uint64_t stream = 0x2545f4914f6cdd1dULL + 2 * static_cast<uint64_t>(sub);
    ctx.rng.seed(math::mix_seed(pixel, 0x1e45, frame, options_.seed), stream);
    const double shift_u = ctx.rng.next_double(), shift_v = ctx.rng.next_double();
    const double pix_u = ctx.rng.next_double(), pix_v = ctx.rng.next_double();
    const uint64_t shutter_seed = sampling.pixel_seed(x, y);
    Color sum{0, 0, 0}, sum_sq{0, 0, 0};
    int n = 0;
    for (int batch = 0; n < cam.blur_samples; ++batch) {
      const int size = scene::blur_batch_size(batch, cam.blur_samples);
      for (int i = 0; i < size && n < cam.blur_samples; ++i, ++n) {
        ctx.rng.seed(math::mix_seed(pixel, static_cast<uint64_t>(n) + 1, frame, options_.seed), stream);
        // Where in the pixel: Roberts' R2 sequence shifted per pixel, so every prefix covers the pixel.
        const math::Vec2 in_pixel = scene::r2_point(n + 1, pix_u, pix_v);
        const double dx = in_pixel.u, dy = in_pixel.v;
        // POV-Ray's hexagonal lens grids for 7, 19 and 37 samples, other counts a low-discrepancy disc.
        const double jitter_u = ctx.rng.next_double(), jitter_v = ctx.rng.next_double();
        const math::Vec2 lens = scene::hex_lens_sample(n, cam.blur_samples, jitter_u, jitter_v)
                                    .value_or(scene::lens_sample(n, shift_u, shift_v));
        const double time = sampling.shutter_time(shutter_seed, n, cam.blur_samples);
        const auto ray =
            camera->generate_lens_ray((px + dx - 0.5) / w, (py + dy - 0.5) / h, lens.u, lens.v, time);
        const Color c = ray ? finite_or_black(integrator->trace_camera_ray(*ray, ctx, camera->max_distance()),
                                              ctx.counters)
                            : Color{0, 0, 0};
        sum += c;
        sum_sq += Color{c.r * c.r, c.g * c.g, c.b * c.b};
      }
      // Variance of the mean, per channel.
      const double k = 1.0 / n;
      const auto var = [&](double s, double s2) { return std::fabs((s2 * k - (s * k) * (s * k)) * k); };
      const double worst = std::max({var(sum.r, sum_sq.r), var(sum.g, sum_sq.g), var(sum.b, sum_sq.b)});
      if (n >= cam.blur_samples_min && worst < thresholds[static_cast<size_t>(n - 1)]) break;
    }
    return sum / static_cast<double>(n);
  };

  // Pass 1: one ray through each pixel centre (or the --spp, focal blur or motion blur samples).
  auto first_sample = [&](int x, int y, TraceContext& ctx) {
    if (spp > 0) return sampling.filtered_pixel(x, y, spp, ctx);
    if (focal_blur) return blurred_sample(x, y, 0, x + 0.5, y + 0.5, ctx);
    if (cam.motion_blur()) return sampling.filtered_pixel(x, y, cam.shutter_samples, ctx);
    return trace_point((x + 0.5) / w, (y + 0.5) / h, ctx);
  };

  // POV-Ray's method 2: samples at the pixel corners (shared by neighbours, and the same whichever tile
  // traces them, since trace_point seeds by position), subdivided where they differ.
  auto render_adaptive = [&](const PixelRect& t, TraceContext& ctx) {
    const int cw = t.x1 - t.x0 + 1;
    std::vector<Color> corner(static_cast<size_t>(cw) * static_cast<size_t>(t.y1 - t.y0 + 1));
    auto at = [&](int x, int y) -> Color& { return corner[static_cast<size_t>(y - t.y0) * cw + (x - t.x0)]; };
    for (int y = t.y0; y <= t.y1; ++y)
      for (int x = t.x0; x <= t.x1; ++x)
        at(x, y) = trace_point(static_cast<double>(x) / w, static_cast<double>(y) / h, ctx);
    const std::function<Color(double, double)> trace = [&](double px, double py) {
      return trace_point(px / w, py / h, ctx);
    };
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) {
        const Color c[4] = {at(x, y), at(x + 1, y), at(x, y + 1), at(x + 1, y + 1)};
        image.set(x, y,
                  adaptive_pixel(x, y, c, options_.aa_depth - 1, options_.aa_threshold,
                                 options_.aa_compare_exponent, options_.jitter ? options_.jitter_amount : 0.0,
                                 options_.seed, trace));
      }
  };

  // Pass 2 (POV-Ray "Anti-Aliasing Options", method 1): a pixel that differs from its left or top neighbour
  // by at least the threshold gets depth x depth more samples on a sub-pixel grid, averaged with its first
  // sample, in POV-Ray's order over the tile (aa_neighbours.hpp).
  auto supersample = [&](int x, int y, const Color& c, TraceContext& ctx) {
    ++ctx.supersampled_pixels;
    const int n = options_.aa_depth;
    Color sum = c;
    for (int k = 1; k <= n * n; ++k) {
      const math::Vec2 p = sample_position(options_, x, y, k);
      sum += focal_blur ? blurred_sample(x, y, k, p.u * w, p.v * h, ctx) : trace_point(p.u, p.v, ctx);
    }
    return sum / static_cast<double>(n * n + 1);
  };

  // Method 1 over one tile, with `first(x, y)` its block's first samples and those of its border.
  auto antialias_tile = [&](const Tile& tile, const auto& first, TraceContext& ctx) {
    const PixelRect& t = tile.rect;
    const PixelRect f = full_tile_rect(tile.index, w, h);
    const int fw = f.x1 - f.x0;
    std::vector<Color> out;
    std::vector<char> refined;
    supersample_block(
        f, options_.aa_threshold, options_.aa_compare_exponent, first,
        [&](int x, int y, const Color& c) { return supersample(x, y, c, ctx); }, out, refined);
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) image.set(x, y, out[static_cast<size_t>(y - f.y0) * fw + (x - f.x0)]);
  };

  // Same denormal handling on every thread: Embree's threads flush denormals to zero and a caller's may
  // not, and a pixel must not depend on which thread traced it.
  auto begin_tile = [&]() -> TraceContext& {
#if defined(__SSE__)
    _mm_setcsr(_mm_getcsr() | kFlushDenormals);
#endif
    TraceContext& ctx = contexts.local();
    integrator->begin_tile(ctx);
    return ctx;
  };
  auto end_tile = [&](const Tile& tile) {
    const PixelRect& t = tile.rect;
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) image.set_alpha(x, y, 1.0f);
    if (options_.tile_done) options_.tile_done(tile, image);
  };

  // A self-contained tile: with anti-aliasing it traces the first pass over itself, the row above and the
  // column to its left (first-pass samples depend only on their pixel), so its pixels are the same
  // whichever tiles, ranks or resumed runs render the rest of the image.
  auto render_tile = [&](const Tile& tile) {
    TraceContext& ctx = begin_tile();
    const PixelRect& t = tile.rect;
    if (antialias && options_.aa_method == 2) {
      render_adaptive(t, ctx);
    } else if (!antialias) {
      for (int y = t.y0; y < t.y1; ++y)
        for (int x = t.x0; x < t.x1; ++x) image.set(x, y, first_sample(x, y, ctx));
    } else {
      // A tile is one of POV-Ray's render blocks (both 32 pixels, aligned with the image): its first samples,
      // and those of the row above and the column to the left, outside the image too as POV-Ray traces them.
      // A tile cut by a partial render's region is worked whole, as its pixels' turns depend on the rest.
      // A grid of this tile alone gives it every border sample to trace.
      FirstSampleGrid grid(std::span<const Tile>(&tile, 1), w, h);
      grid.for_each_owned(0, [&](int x, int y) { grid.at(x, y) = first_sample(x, y, ctx); });
      antialias_tile(
          tile, [&](int x, int y) { return grid.at(x, y); }, ctx);
    }
    end_tile(tile);
  };

  // A tile source (a distributed render's queue) is drained by one loop per thread.
  auto drain_source = [&] {
    const int loops = options_.threads > 0 ? options_.threads : tbb::this_task_arena::max_concurrency();
    tbb::parallel_for(0, loops, [&](int) {
      while (!cancelled()) {
        const std::optional<Tile> tile = options_.tile_source();
        if (!tile) return;
        render_tile(*tile);
        tile_finished();
      }
      stopped = true;
    });
  };

  // Calls work(i) for i below `count` (tiles, or two-pass work) on the render's threads until cancelled.
  auto for_each_piece = [&](size_t count, const auto& work) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) {
        if (cancelled()) {
          stopped = true;
          return;
        }
        work(i);
      }
    });
  };

  // Anti-aliasing in two passes over each batch of tiles (first_sample_grid.hpp): a tile's border is read
  // from its neighbours' first samples, the work handed out by a TwoPassQueue; the same image as
  // render_tile's. One task per piece of work, each taking the queue's next, so that idle threads steal
  // work as they do over a one-pass render's tiles.
  auto render_two_passes = [&] {
    for (const std::span<const Tile> batch : tile_batches(tiles, w, h, kMaxGridPixels)) {
      FirstSampleGrid grid(batch, w, h);
      std::vector<std::vector<size_t>> needs;
      for (size_t i = 0; i < batch.size(); ++i) needs.push_back(grid.needs(i));
      TwoPassQueue queue(std::move(needs));
      auto work_once = [&] {
        const TwoPassQueue::Work work = queue.next();
        if (work.pass == TwoPassQueue::Work::Pass::none) return;
        TraceContext& ctx = begin_tile();
        if (work.pass == TwoPassQueue::Work::Pass::first) {
          grid.for_each_owned(work.tile, [&](int x, int y) { grid.at(x, y) = first_sample(x, y, ctx); });
          queue.first_done(work.tile);
          pass_finished();
        } else {
          const Tile& tile = batch[work.tile];
          antialias_tile(
              tile, [&](int x, int y) { return grid.at(x, y); }, ctx);
          end_tile(tile);
          tile_finished();
        }
      };
      for_each_piece(2 * batch.size(), [&](size_t) {
        try {
          work_once();
        } catch (...) {
          queue.abandon();  // no thread may wait for a first pass this one will not finish
          throw;
        }
      });
      if (stopped) return;
    }
  };

  auto run_all = [&] {
    integrator->prepare(*camera, w, h, region(), options_.time);
    if (options_.tile_source) return drain_source();
    if (two_passes) return render_two_passes();
    for_each_piece(tiles.size(), [&](size_t i) {
      render_tile(tiles[i]);
      tile_finished();
    });
  };
  if (options_.threads > 0) {
    tbb::task_arena arena(options_.threads);
    arena.execute(run_all);
  } else {
    run_all();
  }

  for (const TraceContext& ctx : contexts) {
    stats.rays += ctx.counters;
    stats.supersampled_pixels += ctx.supersampled_pixels;
  }
  stats.tiles_rendered = tiles_done;
  stats.cancelled = stopped;
  stats.integrator_summary = integrator->summary();
  return stats;
}

}  // namespace snell::render
