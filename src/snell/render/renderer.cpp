#include "snell/render/renderer.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "snell/math/pcg32.hpp"
#include "snell/render/integrator.hpp"
#include "snell/scene/blur_confidence.hpp"
#include "snell/scene/lens_samples.hpp"

namespace snell::render {

using math::Color;

namespace {

constexpr int kTileSize = 32;

struct Tile {
  int x0, y0, x1, y1;
};

std::vector<Tile> make_tiles(int width, int height) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
  return tiles;
}

}  // namespace

double color_distance(const Color& a, const Color& b) {
  return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
}

Renderer::Renderer(const scene::Scene& scene, const accel::Accelerator& accelerator, RenderOptions options)
    : scene_(scene), accel_(accelerator), options_(std::move(options)) {
  if (options_.width <= 0 || options_.height <= 0) throw std::invalid_argument("image size must be positive");
  if (options_.width > 65536 || options_.height > 65536)
    throw std::invalid_argument("image size too large (at most 65536 pixels a side)");
  if (options_.aa_depth < 1 || options_.aa_depth > 9)
    throw std::invalid_argument("anti-aliasing depth must be between 1 and 9");
  if (options_.threads < 0) throw std::invalid_argument("thread count must not be negative");
}

RenderResult Renderer::render() const {
  const auto integrator = make_integrator(options_.integrator, scene_, accel_);
  const auto camera = scene::make_camera(scene_.camera);
  const int w = options_.width, h = options_.height;
  const std::vector<Tile> tiles = make_tiles(w, h);
  // Focal blur samples already spread over each pixel, so they are its anti-aliasing too.
  const int passes = options_.antialias && !scene_.camera.focal_blur() ? 2 : 1;

  RenderResult result;
  result.image = io::Image(w, h);
  tbb::enumerable_thread_specific<TraceContext> contexts;
  std::atomic<size_t> tiles_done{0};
  std::atomic<uint64_t> supersampled{0};
  std::atomic<bool> stopped{false};
  std::mutex progress_mutex;
  const size_t total_tiles = tiles.size() * passes;

  auto cancelled = [&] { return options_.cancel && options_.cancel->load(std::memory_order_relaxed); };
  auto tile_finished = [&] {
    const size_t done = ++tiles_done;
    if (options_.progress) {
      std::lock_guard lock(progress_mutex);
      options_.progress(static_cast<double>(done) / static_cast<double>(total_tiles));
    }
  };

  // A point with no camera ray (outside a fisheye's circle) is black, as POV-Ray leaves it.
  // Each camera sample draws its random numbers (area light jitter) from a generator seeded by where it
  // falls in the image, so the image is the same for any thread count and tile order.
  auto trace_point = [&](double sx, double sy, TraceContext& ctx) {
    ctx.rng.seed(math::mix_seed(std::bit_cast<uint64_t>(sx), std::bit_cast<uint64_t>(sy),
                                static_cast<uint64_t>(options_.frame), options_.seed),
                 0x5851f42d4c957f2dULL);
    const auto ray = camera->generate_ray(sx, sy, options_.time);
    return ray ? integrator->trace_camera_ray(*ray, ctx) : Color{0, 0, 0};
  };

  // Focal blur (POV-Ray "Focal Blur"): rays from points spread over the lens and over the pixel, taken in
  // batches until the pixel's mean colour is known well enough (confidence, variance) or blur_samples are
  // spent. Seeded by pixel and sample so images do not depend on threads.
  const scene::CameraSpec& cam = scene_.camera;
  const bool focal_blur = cam.focal_blur();
  const std::vector<double> thresholds =
      focal_blur ? scene::blur_variance_thresholds(cam.blur_samples, cam.confidence, cam.variance)
                 : std::vector<double>{};
  auto blurred_pixel = [&](int x, int y, TraceContext& ctx) {
    const uint64_t pixel = static_cast<uint64_t>(y) * static_cast<uint64_t>(w) + static_cast<uint64_t>(x);
    const uint64_t frame = static_cast<uint64_t>(options_.frame);
    constexpr uint64_t kStream = 0x2545f4914f6cdd1dULL;
    ctx.rng.seed(math::mix_seed(pixel, 0x1e45, frame, options_.seed), kStream);
    const double shift_u = ctx.rng.next_double(), shift_v = ctx.rng.next_double();
    Color sum{0, 0, 0}, sum_sq{0, 0, 0};
    int n = 0;
    for (int batch = 0; n < cam.blur_samples; ++batch) {
      const int size = scene::blur_batch_size(batch, cam.blur_samples);
      for (int i = 0; i < size && n < cam.blur_samples; ++i, ++n) {
        ctx.rng.seed(math::mix_seed(pixel, static_cast<uint64_t>(n) + 1, frame, options_.seed), kStream);
        const double dx = ctx.rng.next_double(), dy = ctx.rng.next_double();
        const math::Vec2 lens = scene::lens_sample(n, shift_u, shift_v);
        const auto ray = camera->generate_lens_ray((x + dx) / w, (y + dy) / h, lens.u, lens.v, options_.time);
        const Color c = ray ? integrator->trace_camera_ray(*ray, ctx) : Color{0, 0, 0};
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

  // Pass 1: one ray through each pixel centre (or the focal blur samples).
  io::Image& image = result.image;
  auto first_pass = [&](const Tile& t) {
    TraceContext& ctx = contexts.local();
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x)
        image.set(x, y,
                  focal_blur ? blurred_pixel(x, y, ctx) : trace_point((x + 0.5) / w, (y + 0.5) / h, ctx));
  };

  // Pass 2 (POV-Ray "Anti-Aliasing Options", method 1): a pixel that differs from a neighbour by more than
  // the threshold gets depth x depth more samples on a sub-pixel grid, averaged with its first sample.
  const io::Image* first = nullptr;
  io::Image first_copy;
  auto second_pass = [&](const Tile& t) {
    TraceContext& ctx = contexts.local();
    const int n = options_.aa_depth;
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) {
        const Color c = first->at(x, y);
        bool differs = false;
        const int nx[4] = {x - 1, x + 1, x, x};
        const int ny[4] = {y, y, y - 1, y + 1};
        for (int k = 0; k < 4 && !differs; ++k)
          if (nx[k] >= 0 && nx[k] < w && ny[k] >= 0 && ny[k] < h)
            differs = color_distance(c, first->at(nx[k], ny[k])) > options_.aa_threshold;
        if (!differs) continue;
        ++supersampled;
        Color sum = c;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) {
            double dx = (i + 0.5) / n, dy = (j + 0.5) / n;
            if (options_.jitter) {
              const uint64_t pixel =
                  static_cast<uint64_t>(y) * static_cast<uint64_t>(w) + static_cast<uint64_t>(x);
              ctx.rng.seed(math::mix_seed(pixel, static_cast<uint64_t>(j * n + i + 1),
                                          static_cast<uint64_t>(options_.frame), options_.seed),
                           0xda3e39cb94b95bdbULL);
              dx += options_.jitter_amount * (ctx.rng.next_double() - 0.5) / n;
              dy += options_.jitter_amount * (ctx.rng.next_double() - 0.5) / n;
            }
            sum += trace_point((x + dx) / w, (y + dy) / h, ctx);
          }
        image.set(x, y, sum / static_cast<double>(n * n + 1));
      }
  };

  auto run_pass = [&](const auto& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i) {
                          if (cancelled()) {
                            stopped = true;
                            return;
                          }
                          body(tiles[i]);
                          tile_finished();
                        }
                      });
  };

  auto run_all = [&] {
    run_pass(first_pass);
    if (passes == 2 && !stopped) {
      first_copy = image;
      first = &first_copy;
      run_pass(second_pass);
    }
  };
  if (options_.threads > 0) {
    tbb::task_arena arena(options_.threads);
    arena.execute(run_all);
  } else {
    run_all();
  }

  for (const TraceContext& ctx : contexts) result.rays += ctx.counters;
  result.supersampled_pixels = supersampled;
  result.cancelled = stopped;
  return result;
}

}  // namespace snell::render
