#include "snell/texture/bump_map.hpp"

#include <cmath>

namespace snell::texture {

namespace {

/// Below this a frame axis counts as degenerate (POV-Ray's EPSILON).
constexpr double kDegenerate = 1e-10;

}  // namespace

double BumpMapPattern::grey(double u, double v) const {
  // POV-Ray's grey scale weights (base/colour.h kRedIntensity, kGreenIntensity, kBlueIntensity); for a
  // palette image read `use_index` the parser stored the index in all three channels.
  const math::Color c = image_->texel(u - std::floor(u), v - std::floor(v));
  return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
}

double BumpMapPattern::value(const Vec3& p) const {
  const ImageUv uv = image_map_uv(image_->spec().type, p);
  return grey(uv.u, uv.v);
}

Vec3 BumpMapPattern::set_normal(const Vec3& p, const Vec3& n, double bump_size) const {
  const ImageMapSpec& spec = image_->spec();
  const ImageUv uv = image_map_uv(spec.type, p);
  if (spec.once && (uv.u < 0 || uv.u >= 1 || uv.v < 0 || uv.v >= 1)) return n;
  const double du = 1.0 / spec.image->width, dv = 1.0 / spec.image->height;
  // Heights at the pixel (0,0), the pixel one left and one down (-1,1) and one right and one down (1,1).
  const double h_here = bump_size * grey(uv.u, uv.v);
  const double h_left = bump_size * grey(uv.u - du, uv.v - dv);
  const double h_right = bump_size * grey(uv.u + du, uv.v - dv);
  const Vec3 to_here{1, h_here - h_left, -1};
  const Vec3 across{2, h_right - h_left, 0};
  const Vec3 bump = normalize(cross(across, to_here));
  // The frame: n up, n x y across (x when n is along y), their cross product forward.
  Vec3 up = n;
  Vec3 side = cross(n, Vec3{0, 1, 0});
  double side_length = length(side);
  if (side_length < kDegenerate) {
    up = Vec3{0, n.y > 0 ? 1.0 : -1.0, 0};
    side = Vec3{1, 0, 0};
    side_length = 1;
  }
  side = side * (1 / side_length);
  const Vec3 forward = normalize(cross(side, up));
  return side * bump.x + up * bump.y - forward * bump.z;
}

}  // namespace snell::texture
