#pragma once
// The Renderer: splits the image into tiles, traces them on all cores (oneTBB) and applies POV-Ray's
// anti-aliasing method 1. Every random number of a sample comes from a generator seeded by (pixel, sample,
// frame, seed), so the image is bit-identical for any thread count and tile order (DESIGN.md, "Numbers").
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/io/image.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/render/ray_counters.hpp"
#include "snell/render/tiles.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render {

struct RenderOptions {
  int width = 320;
  int height = 240;
  /// POV-Ray +A: supersample pixels whose colour differs from a neighbour's by more than `aa_threshold`
  /// (sum of absolute RGB differences); +R `aa_depth` gives aa_depth^2 extra samples; +J jitters them.
  bool antialias = false;
  double aa_threshold = 0.3;
  /// Colours are compared after POV-Ray's anti-aliasing gamma (view.cpp, aaGammaCurve): each channel of
  /// the working colour goes through c^aa_compare_exponent, the exponent being the scene's working gamma
  /// divided by Antialias_Gamma (+AG, default 2.5). Dark differences weigh more, as the eye sees them.
  double aa_compare_exponent = 1.0 / 2.5;
  int aa_depth = 3;
  bool jitter = false;
  double jitter_amount = 1.0;
  /// POV-Ray +AM: 1 (supersample pixels that differ from a neighbour) or 2 (adaptive recursive subdivision
  /// from the pixel corners, aa_depth - 1 levels deep).
  int aa_method = 1;
  /// --spp N: every pixel takes N samples (over pixel, lens and shutter) from `sampler`, weighted by
  /// `filter`; 0 keeps POV-Ray's anti-aliasing. `filter` also weights motion-blur samples.
  int samples_per_pixel = 0;
  std::string sampler = "sobol";
  std::string filter = "box";
  /// 0 = all cores.
  int threads = 0;
  uint64_t seed = 0;
  int frame = 0;
  double time = 0;
  std::string integrator = "whitted";
  /// The pixels to render (POV-Ray +SC/+EC/+SR/+ER); empty means the whole image. Pixels outside keep
  /// alpha 0. Every pixel inside comes out exactly as in a render of the whole image.
  PixelRect region;
  /// When set, tiles come from here instead of the region's tiling (region unused): each render thread
  /// asks for the next tile until it returns nothing. Calls may overlap. Rank 0 of a distributed render
  /// renders this way (src/cli/local_render.cpp), sharing the tiles with the other ranks.
  std::function<std::optional<Tile>()> tile_source;
  /// When set (and no tile_source), the tiles to render, in index order, instead of the region's tiling:
  /// the `snell` program's tiles, less those a resume file holds (src/cli/local_render.cpp).
  std::optional<std::vector<Tile>> tiles;
  /// Set from another thread (Ctrl-C) to stop early; finished tiles stay in the image.
  const std::atomic<bool>* cancel = nullptr;
  /// Called with the fraction done (0..1), serialised, from worker threads.
  std::function<void(double)> progress;
  /// Called from a worker thread once a tile's final pixels (and alpha 1) are in the target image; calls
  /// may overlap, so the callee serialises. Used for checkpoints and for sending tiles to another rank.
  std::function<void(const Tile&, const io::Image&)> tile_done;
};

struct RenderStats {
  RayCounters rays;
  uint64_t supersampled_pixels = 0;
  uint64_t tiles_rendered = 0;
  bool cancelled = false;
  /// The integrator's own statistics (radiosity cache, photon map), one line each, or empty.
  std::string integrator_summary;
};

struct RenderResult : RenderStats {
  /// Linear RGB with a coverage channel (Image::alpha): 1 for rendered pixels.
  io::Image image;
};

class Renderer {
 public:
  /// Throws std::invalid_argument for bad options (size, aa depth, threads, integrator name).
  Renderer(const scene::Scene& scene, const accel::Accelerator& accelerator, RenderOptions options);
  RenderResult render() const;
  /// Renders the region's tiles (or the tile source's) into `target` (width x height, with a coverage
  /// channel, as from blank_target()), leaving other pixels untouched.
  RenderStats render_into(io::Image& target) const;
  /// A black image of the options' size with every pixel marked unrendered.
  io::Image blank_target() const;
  /// The region actually rendered: the options' region clipped to the image, or the whole image.
  PixelRect region() const;

 private:
  const scene::Scene& scene_;
  const accel::Accelerator& accel_;
  RenderOptions options_;
};

/// Where sample `k` of pixel (x, y) lies in the image (0..1 across and down): k = 0 is the first pass's
/// pixel centre, k = 1..aa_depth^2 the supersampling grid row by row, jittered as POV-Ray jitters it when
/// options.jitter.
math::Vec2 sample_position(const RenderOptions& options, int x, int y, int k);
/// Seeds `rng` for the camera sample at image point (sx, sy), so its random numbers (area light jitter)
/// depend only on where it falls, never on threads or tiles.
void seed_camera_sample(math::Pcg32& rng, double sx, double sy, const RenderOptions& options);

/// POV-Ray's anti-aliasing colour distance: the sum of the absolute channel differences.
double color_distance(const math::Color& a, const math::Color& b);

/// A colour as the anti-aliasing test compares it: each channel (clamped at 0) to the power `exponent`
/// (RenderOptions::aa_compare_exponent).
math::Color aa_encoded(const math::Color& c, double exponent);

/// The exponent of RenderOptions::aa_compare_exponent for a scene: POV-Ray decodes the working colour
/// (gamma `working_gamma`, 1 where the scene has no gamma handling) and encodes it with `aa_gamma`; an
/// `aa_gamma` of 0 or less leaves out the encoding.
double aa_compare_exponent_for(double working_gamma, double aa_gamma);

}  // namespace snell::render
