#include "snell/render/area_light.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace snell::render {

using math::Color;
using math::Vec3;

std::pair<Vec3, Vec3> area_light_axes(const scene::Light& light, const Vec3& to_light) {
  if (!light.orient) return {light.axis1, light.axis2};
  // POV-Ray's `orient`: axis1 across the light ray (using +y instead of +z as the helper when the ray is
  // nearly along z), axis2 across both; both take axis1's length so the light looks square.
  const double size = length(light.axis1);
  const Vec3 helper = std::fabs(std::fabs(to_light.z) - 1.0) < 0.01 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
  const Vec3 a1 = normalize(cross(to_light, helper));
  const Vec3 a2 = normalize(cross(to_light, a1));
  return {a1 * size, a2 * size};
}

Vec3 area_light_offset(const scene::Light& light, const Vec3& axis1, const Vec3& axis2, double u, double v) {
  if (light.circular && light.size1 > 1 && light.size2 > 1) {
    // Each square ring of grid points goes onto the circle of the same half-width: scale the point by
    // max(|u|,|v|) / |(u,v)| (the small shift keeps the centre off 0/0, as POV-Ray's does).
    double cu = u / (light.size1 - 1) - 0.5 + 0.001;
    double cv = v / (light.size2 - 1) - 0.5 + 0.001;
    const double scale = std::max(std::fabs(cu), std::fabs(cv)) / std::sqrt(cu * cu + cv * cv);
    cu *= scale;
    cv *= scale;
    return axis1 * cu + axis2 * cv;
  }
  Vec3 offset{0, 0, 0};
  if (light.size1 > 1) offset += axis1 * (u / (light.size1 - 1) - 0.5);
  if (light.size2 > 1) offset += axis2 * (v / (light.size2 - 1) - 0.5);
  return offset;
}

Vec3 area_light_sample_offset(const scene::Light& light, const Vec3& axis1, const Vec3& axis2, int u, int v,
                              math::Pcg32& rng) {
  double ju = u, jv = v;
  if (light.jitter) {
    ju += rng.next_double() - 0.5;
    jv += rng.next_double() - 0.5;
  }
  return area_light_offset(light, axis1, axis2, ju, jv);
}

namespace {

/// POV-Ray's colour distance for adaptive decisions: the sum of the channels' absolute differences.
double colour_distance(const Color& a, const Color& b) {
  return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
}

class GridSampler {
 public:
  GridSampler(const scene::Light& light, const Vec3& axis1, const Vec3& axis2, math::Pcg32& rng,
              const std::function<Color(const Vec3&)>& shadow)
      : light_(light),
        axis1_(axis1),
        axis2_(axis2),
        rng_(rng),
        shadow_(shadow),
        grid_(grid_buffer()),
        known_(known_buffer()) {
    const size_t n = static_cast<size_t>(light.size1) * static_cast<size_t>(light.size2);
    grid_.resize(n);
    known_.assign(n, 0);
  }

  /// Mean over the region [u1,u2] x [v1,v2] at recursion `level`.
  Color region(int u1, int v1, int u2, int v2, int level) {
    const Color c[4] = {at(u1, v1), at(u2, v1), at(u1, v2), at(u2, v2)};
    if (u2 - u1 > 1 || v2 - v1 > 1) {
      const bool split = level < light_.adaptive || colour_distance(c[0], c[1]) > 0.1 ||
                         colour_distance(c[1], c[3]) > 0.1 || colour_distance(c[3], c[2]) > 0.1 ||
                         colour_distance(c[2], c[0]) > 0.1;
      if (split) {
        // Quarters share the middle row/column when the region has an odd number of points.
        const int ul = (u1 + u2) / 2, uh = (u1 + u2 + 1) / 2;
        const int vl = (v1 + v2) / 2, vh = (v1 + v2 + 1) / 2;
        return (region(u1, v1, ul, vl, level + 1) + region(uh, v1, u2, vl, level + 1) +
                region(u1, vh, ul, v2, level + 1) + region(uh, vh, u2, v2, level + 1)) *
               0.25;
      }
    }
    return (c[0] + c[1] + c[2] + c[3]) * 0.25;
  }

 private:
  Color at(int u, int v) {
    const size_t i = static_cast<size_t>(u) * static_cast<size_t>(light_.size2) + static_cast<size_t>(v);
    if (!known_[i]) {
      grid_[i] = shadow_(area_light_sample_offset(light_, axis1_, axis2_, u, v, rng_));
      known_[i] = 1;
    }
    return grid_[i];
  }

  // The grid's buffers live on per thread: one area light test per lit point must not allocate. Shadow
  // rays shade nothing, so no second sampler starts on this thread while one is in use.
  static std::vector<Color>& grid_buffer() {
    thread_local std::vector<Color> buffer;
    return buffer;
  }
  static std::vector<char>& known_buffer() {
    thread_local std::vector<char> buffer;
    return buffer;
  }

  const scene::Light& light_;
  Vec3 axis1_, axis2_;
  math::Pcg32& rng_;
  const std::function<Color(const Vec3&)>& shadow_;
  std::vector<Color>& grid_;
  std::vector<char>& known_;
};

}  // namespace

Color area_light_shadow(const scene::Light& light, const Vec3& axis1, const Vec3& axis2, math::Pcg32& rng,
                        const std::function<Color(const Vec3&)>& shadow) {
  GridSampler sampler(light, axis1, axis2, rng, shadow);
  return sampler.region(0, 0, light.size1 - 1, light.size2 - 1, 0);
}

}  // namespace snell::render
