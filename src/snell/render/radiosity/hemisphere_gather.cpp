#include "snell/render/radiosity/hemisphere_gather.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace snell::render::radiosity {

using math::Color;
using math::Vec3;

std::vector<Vec3> cosine_directions(int count) {
  std::vector<Vec3> directions;
  directions.reserve(static_cast<size_t>(std::max(count, 0)));
  // Golden-angle spiral: point i at radius sqrt((i + 1/2) / count) covers equal disc areas.
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double u = (i + 0.5) / count;
    const double r = std::sqrt(u);
    const double phi = golden_angle * i;
    directions.push_back(Vec3{r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u))});
  }
  return directions;
}

void orthonormal_frame(const Vec3& n, Vec3& t, Vec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = Vec3{1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = Vec3{c, sign + n.y * n.y * a, -n.y};
}

HemisphereGather::HemisphereGather(const scene::RadiositySettings& settings)
    : settings_(settings),
      first_(cosine_directions(settings.count)),
      // Nested gathers multiply the work; POV-Ray's cache hides that, here they use a quarter of the rays.
      deeper_(cosine_directions(std::max(8, std::min(settings.count, settings.count / 4)))) {}

Color HemisphereGather::ambient(const Vec3& normal, int depth,
                                const std::function<Color(const Vec3&)>& radiance_along) const {
  const std::vector<Vec3>& table = depth == 0 ? first_ : deeper_;
  Vec3 t, b;
  orthonormal_frame(normal, t, b);
  Color sum(0);
  for (const Vec3& d : table) sum += radiance_along(d.x * t + d.y * b + d.z * normal);
  Color mean = sum * (1.0 / static_cast<double>(table.size()));
  // gray_threshold pulls the colour towards its grey (radiosity.cpp, ComputeAmbient).
  const double g = settings_.gray_threshold;
  mean = mean * (1 - g) + Color(mean.grey() * g);
  return mean * settings_.brightness;
}

}  // namespace snell::render::radiosity
