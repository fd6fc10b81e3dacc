#include "snell/render/pixel_estimators.hpp"

#include <bit>
#include <cmath>

#include "snell/math/pcg32.hpp"
#include "snell/render/finite_sample.hpp"
#include "snell/render/renderer.hpp"

namespace snell::render {

using math::Color;

uint64_t CameraSampling::pixel_seed(int x, int y) const {
  const uint64_t pixel = static_cast<uint64_t>(y) * static_cast<uint64_t>(width) + static_cast<uint64_t>(x);
  return math::mix_seed(pixel, 0x5eed5a3d, static_cast<uint64_t>(frame), seed);
}

double CameraSampling::shutter_time(uint64_t pixel, int index, int count) const {
  if (!spec.motion_blur()) return time;
  const double u = sampler.get(pixel, static_cast<uint32_t>(index), static_cast<uint32_t>(count), kTime);
  return spec.shutter_open + u * (spec.shutter_close - spec.shutter_open);
}

Color CameraSampling::filtered_pixel(int x, int y, int count, TraceContext& context) const {
  const uint64_t pixel = pixel_seed(x, y);
  const auto n = static_cast<uint32_t>(count);
  const double r = filter.radius();
  const bool lens = spec.focal_blur();
  Color sum{0, 0, 0}, plain{0, 0, 0};
  double weights = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const double dx = (2 * sampler.get(pixel, i, n, kPixelX) - 1) * r;
    const double dy = (2 * sampler.get(pixel, i, n, kPixelY) - 1) * r;
    const double sx = (x + 0.5 + dx) / width, sy = (y + 0.5 + dy) / height;
    const double t = shutter_time(pixel, static_cast<int>(i), count);
    context.rng.seed(math::mix_seed(pixel, i + 1), 0x14057b7ef767814fULL);
    std::optional<math::Ray> ray;
    if (lens) {
      const math::Vec2 p = disc_point(sampler.get(pixel, i, n, kLensU), sampler.get(pixel, i, n, kLensV));
      ray = camera.generate_lens_ray(sx, sy, p.u, p.v, t);
    } else {
      ray = camera.generate_ray(sx, sy, t);
    }
    const Color c =
        ray ? finite_or_black(integrator.trace_camera_ray(*ray, context), context.counters) : Color{0, 0, 0};
    const double w = filter.weight(dx, dy);
    sum += w * c;
    plain += c;
    weights += w;
  }
  // A filter with negative lobes (Mitchell) can sum to almost nothing over few samples: fall back to the
  // plain mean then.
  if (std::fabs(weights) < 1e-9 * n) return plain / static_cast<double>(n);
  return sum / weights;
}

namespace {

struct Subdivision {
  double threshold, exponent, jitter;
  uint64_t seed;
  const std::function<Color(double, double)>& trace;

  /// A new sample at (px, py), moved by a jitter seeded by the point itself, so a point shared by two
  /// pixels gets the same colour from both.
  Color sample(double px, double py, double half) const {
    if (jitter <= 0) return trace(px, py);
    math::Pcg32 rng(math::mix_seed(std::bit_cast<uint64_t>(px), std::bit_cast<uint64_t>(py), seed),
                    0x9e3779b97f4a7c15ULL);
    const double jx = (rng.next_double() - 0.5) * jitter * half;
    const double jy = (rng.next_double() - 0.5) * jitter * half;
    return trace(px + jx, py + jy);
  }

  Color square(double x0, double y0, double size, const Color& c00, const Color& c10, const Color& c01,
               const Color& c11, int levels) const {
    const Color c[4] = {aa_encoded(c00, exponent), aa_encoded(c10, exponent), aa_encoded(c01, exponent),
                        aa_encoded(c11, exponent)};
    bool split = false;
    for (int i = 0; i < 4 && !split; ++i)
      for (int j = i + 1; j < 4 && !split; ++j) split = color_distance(c[i], c[j]) >= threshold;
    if (levels <= 0 || !split) return (c00 + c10 + c01 + c11) / 4.0;
    const double h = size / 2;
    const Color top = sample(x0 + h, y0, h), left = sample(x0, y0 + h, h);
    const Color right = sample(x0 + size, y0 + h, h), bottom = sample(x0 + h, y0 + size, h);
    const Color centre = sample(x0 + h, y0 + h, h);
    return (square(x0, y0, h, c00, top, left, centre, levels - 1) +
            square(x0 + h, y0, h, top, c10, centre, right, levels - 1) +
            square(x0, y0 + h, h, left, centre, c01, bottom, levels - 1) +
            square(x0 + h, y0 + h, h, centre, right, bottom, c11, levels - 1)) /
           4.0;
  }
};

}  // namespace

Color adaptive_pixel(int x, int y, const Color corners[4], int levels, double threshold, double exponent,
                     double jitter, uint64_t seed, const std::function<Color(double, double)>& trace) {
  const Subdivision s{threshold, exponent, jitter, seed, trace};
  return s.square(x, y, 1, corners[0], corners[1], corners[2], corners[3], levels);
}

}  // namespace snell::render
