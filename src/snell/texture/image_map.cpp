#include "snell/texture/image_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace snell::texture {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

ImageUv image_map_uv(ImageMapType type, const math::Vec3& p) {
  switch (type) {
    case ImageMapType::planar:
      return {p.x, p.y};
    case ImageMapType::spherical: {
      const double r = length(p);
      const double longitude = std::atan2(p.x, p.z) / (2 * kPi);
      return {longitude - std::floor(longitude),
              r > 0 ? 0.5 + std::asin(std::clamp(p.y / r, -1.0, 1.0)) / kPi : 0.5};
    }
    case ImageMapType::cylindrical: {
      const double longitude = std::atan2(p.x, p.z) / (2 * kPi);
      return {longitude - std::floor(longitude), p.y};
    }
  }
  return {p.x, p.y};
}

ImageMapPigment::ImageMapPigment(ImageMapSpec spec) : spec_(std::move(spec)) {
  if (!spec_.image || spec_.image->width <= 0 || spec_.image->height <= 0)
    throw std::invalid_argument("image_map needs a non-empty image");
}

math::Color ImageMapPigment::texel(double u, double v) const {
  const io::Image& im = *spec_.image;
  const int w = im.width, h = im.height;
  // Row 0 is the top of the image, which lies at v = 1.
  const double x = u * w, y = (1 - v) * h;
  auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  if (spec_.interpolate == 0)
    return im.at(wrap(static_cast<int>(std::floor(x)), w), wrap(static_cast<int>(std::floor(y)), h));
  // Bilinear between the four pixel centres around (x, y).
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double tx = fx - x0, ty = fy - y0;
  const math::Color top =
      math::lerp(im.at(wrap(x0, w), wrap(y0, h)), im.at(wrap(x0 + 1, w), wrap(y0, h)), tx);
  const math::Color bottom =
      math::lerp(im.at(wrap(x0, w), wrap(y0 + 1, h)), im.at(wrap(x0 + 1, w), wrap(y0 + 1, h)), tx);
  return math::lerp(top, bottom, ty);
}

material::Rgbft ImageMapPigment::at(const material::PatternPoint& point) const {
  const ImageUv uv = image_map_uv(spec_.type, point.p);
  if (spec_.once && (uv.u < 0 || uv.u >= 1 || uv.v < 0 || uv.v >= 1)) return {math::Color(0), 0, 1};
  const double u = uv.u - std::floor(uv.u), v = uv.v - std::floor(uv.v);
  return {texel(u, v), spec_.filter_all, spec_.transmit_all};
}

}  // namespace snell::texture
