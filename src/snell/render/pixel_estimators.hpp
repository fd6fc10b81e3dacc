#pragma once
// Ways to turn camera samples into a pixel colour besides POV-Ray's method 1 (renderer.cpp): a fixed number
// of filtered samples spread over pixel, lens and shutter (--spp, and motion blur), and POV-Ray's adaptive
// method 2 (+AM2). Every sample's random numbers are seeded by its pixel or image position, so results do
// not depend on threads or tiles.
#include <cstdint>
#include <functional>

#include "snell/math/color.hpp"
#include "snell/render/filter.hpp"
#include "snell/render/integrator.hpp"
#include "snell/render/sampler.hpp"
#include "snell/scene/camera.hpp"

namespace snell::render {

/// What tracing one camera sample needs.
struct CameraSampling {
  const scene::Camera& camera;
  const scene::CameraSpec& spec;
  const Integrator& integrator;
  const Sampler& sampler;
  const Filter& filter;
  int width = 0, height = 0;
  int frame = 0;
  uint64_t seed = 0;
  /// The time of every ray when the camera has no shutter.
  double time = 0;

  /// The seed that scrambles pixel (x, y)'s sample sequence.
  uint64_t pixel_seed(int x, int y) const;
  /// The shutter time of sample `index` of `count` (stratified over [open, close]); `time` without a
  /// shutter.
  double shutter_time(uint64_t pixel_seed, int index, int count) const;
  /// `count` samples spread over the filter's support around the pixel centre, over the lens (focal blur)
  /// and over the shutter, weighted by the filter.
  math::Color filtered_pixel(int x, int y, int count, TraceContext& context) const;
};

/// POV-Ray's adaptive anti-aliasing (+AM2; tracetask.cpp, AdaptiveSupersamplingM2): the pixel square whose
/// corners have colours `corners` (top-left, top-right, bottom-left, bottom-right) is split into four while
/// two corners differ by at least `threshold` (compared through aa_encoded with `exponent`) and `levels`
/// remain; each leaf contributes the mean of its
/// corners. `trace(px, py)` traces the image point in pixel units (pixel (x, y) spans [x, x+1]).
/// New sample points move by up to `jitter` / 2 of their square's half size, seeded by their position.
math::Color adaptive_pixel(int x, int y, const math::Color corners[4], int levels, double threshold,
                           double exponent, double jitter, uint64_t seed,
                           const std::function<math::Color(double, double)>& trace);

}  // namespace snell::render
