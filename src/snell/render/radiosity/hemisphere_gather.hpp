#pragma once
// Radiosity as POV-Ray 3.7 defines it (reference "Radiosity"; source/core/lighting/radiosity.cpp for the
// behaviour): at a diffuse point the ambient term is replaced by the mean radiance seen along `count`
// cosine-distributed directions around the normal, times `brightness`, recursing up to recursion_limit
// gathers deep. POV-Ray draws its directions from one fixed table and caches the result (Ward 1988); snell
// keeps the fixed table (so neighbouring points see the same directions and the image stays free of
// noise) but gathers at every point instead of interpolating, which makes the image independent of
// rendering order and thread count, at the cost of time.
#include <functional>
#include <vector>

#include "snell/math/color.hpp"
#include "snell/math/vec3.hpp"
#include "snell/scene/radiosity_settings.hpp"

namespace snell::render::radiosity {

/// `count` unit directions over the hemisphere around +z, cosine-distributed: a Fibonacci spiral on the
/// unit disc lifted to the hemisphere (Malley's method), so each stands for an equal share of irradiance.
std::vector<math::Vec3> cosine_directions(int count);

/// Unit vectors t, b such that (t, b, n) is a right-handed orthonormal frame; continuous in n except at
/// n.z = -1 (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1)).
void orthonormal_frame(const math::Vec3& n, math::Vec3& t, math::Vec3& b);

class HemisphereGather {
 public:
  explicit HemisphereGather(const scene::RadiositySettings& settings);

  /// Whether a point reached through `depth` nested gathers gathers again (POV-Ray:
  /// radiosityRecursionDepth < recursion_limit).
  bool gathers_at(int depth) const { return depth < settings_.recursion_limit; }

  /// POV-Ray's ambient colour at a point with unit normal `normal`: brightness times the mean of
  /// `radiance_along(direction)` over the direction table. Deeper gathers use a smaller table.
  math::Color ambient(const math::Vec3& normal, int depth,
                      const std::function<math::Color(const math::Vec3&)>& radiance_along) const;

  const scene::RadiositySettings& settings() const { return settings_; }

 private:
  scene::RadiositySettings settings_;
  std::vector<math::Vec3> first_;
  std::vector<math::Vec3> deeper_;
};

}  // namespace snell::render::radiosity
