#pragma once
// The renderer's guard against NaN and infinite samples (issue 12): a fault the scene checks cannot catch
// (a function that returns nan, a transform near singular, an overflow in a shape's solver) must not
// reach the image, where one NaN sample would also poison anti-aliasing and every later operation on the
// file. Such a sample is counted, for the statistics and a warning, and taken as black.
#include <cmath>

#include "snell/math/color.hpp"
#include "snell/render/ray_counters.hpp"

namespace snell::render {

inline math::Color finite_or_black(const math::Color& sample, RayCounters& counters) {
  if (std::isfinite(sample.r) && std::isfinite(sample.g) && std::isfinite(sample.b)) return sample;
  ++counters.non_finite_samples;
  return {0, 0, 0};
}

}  // namespace snell::render
