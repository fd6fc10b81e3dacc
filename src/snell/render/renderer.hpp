#pragma once
// The Renderer: splits the image into tiles, traces them on all cores (oneTBB) and applies POV-Ray's
// anti-aliasing method 1. Every random number of a sample comes from a generator seeded by (pixel, sample,
// frame, seed), so the image is bit-identical for any thread count and tile order (DESIGN.md, "Numbers").
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/io/image.hpp"
#include "snell/render/ray_counters.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render {

struct RenderOptions {
  int width = 320;
  int height = 240;
  /// POV-Ray +A: supersample pixels whose colour differs from a neighbour's by more than `aa_threshold`
  /// (sum of absolute RGB differences); +R `aa_depth` gives aa_depth^2 extra samples; +J jitters them.
  bool antialias = false;
  double aa_threshold = 0.3;
  int aa_depth = 3;
  bool jitter = false;
  double jitter_amount = 1.0;
  /// 0 = all cores.
  int threads = 0;
  uint64_t seed = 0;
  int frame = 0;
  double time = 0;
  std::string integrator = "whitted";
  /// Set from another thread (Ctrl-C) to stop early; finished tiles stay in the image.
  const std::atomic<bool>* cancel = nullptr;
  /// Called with the fraction done (0..1), serialised, from worker threads.
  std::function<void(double)> progress;
};

struct RenderResult {
  io::Image image;
  RayCounters rays;
  uint64_t supersampled_pixels = 0;
  bool cancelled = false;
};

class Renderer {
 public:
  /// Throws std::invalid_argument for bad options (size, aa depth, threads, integrator name).
  Renderer(const scene::Scene& scene, const accel::Accelerator& accelerator, RenderOptions options);
  RenderResult render() const;

 private:
  const scene::Scene& scene_;
  const accel::Accelerator& accel_;
  RenderOptions options_;
};

/// POV-Ray's anti-aliasing colour distance: the sum of the absolute channel differences.
double color_distance(const math::Color& a, const math::Color& b);

}  // namespace snell::render
