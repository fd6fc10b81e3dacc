#pragma once
// The scene as the renderer sees it: built once (by the SDL parser, a procedural generator or C++ code),
// immutable while rendering, read by every thread without locks.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "snell/material/media.hpp"
#include "snell/material/pigment.hpp"
#include "snell/material/rgbft.hpp"
#include "snell/math/transform.hpp"
#include "snell/memory/budget.hpp"
#include "snell/scene/camera.hpp"
#include "snell/scene/fog.hpp"
#include "snell/scene/light.hpp"
#include "snell/scene/object.hpp"
#include "snell/scene/photon_settings.hpp"
#include "snell/scene/radiosity_settings.hpp"

namespace snell::scene {

/// POV-Ray `global_settings {}` and the language version that affects rendering.
struct GlobalSettings {
  /// The first `assumed_gamma` of the scene; 0 when none was given.
  double assumed_gamma = 0;
  int max_trace_level = 5;
  double adc_bailout = 1.0 / 255.0;
  math::Color ambient_light{1};
  /// `radiosity {}`: indirect diffuse light replaces the ambient term (POV-Ray 3.7 semantics).
  std::optional<RadiositySettings> radiosity;
  /// `photons {}`: caustics by photon mapping (render/photons/).
  std::optional<PhotonSettings> photons;
  /// `#version` in effect at the end of parsing (POV-Ray uses it for version-dependent defaults).
  double language_version = 3.7;
  /// `mm_per_unit` (default 10) and `subsurface { samples N, M }`: the scale of subsurface scattering and
  /// the number of diffuse probe samples per shading point (POV-Ray 3.7 reference, "Subsurface Light
  /// Transport"; the second count, single scattering, is used by POV-Ray's translucency estimate,
  /// render/subsurface_povray.hpp).
  double mm_per_unit = 10;
  int subsurface_samples = 50;
  int subsurface_single_samples = 50;
};

/// POV-Ray `sky_sphere {}`: pigments seen in the direction of every ray that hits nothing, the first one
/// at the bottom and each later one over it where it is opaque (POV-Ray 3.7 reference, "Sky Sphere").
struct SkySphere {
  std::vector<std::shared_ptr<const material::Pigment>> pigments;
  /// Sky space -> world: rays' directions are taken back through it before the pigments see them.
  math::Transform transform;
};

struct Scene {
  std::vector<std::shared_ptr<const Object>> objects;
  std::vector<Light> lights;
  CameraSpec camera;
  material::Rgbft background;
  std::optional<SkySphere> sky_sphere;
  /// `fog {}` blocks and `media {}` at the top level (the atmosphere), in the order written.
  std::vector<Fog> fogs;
  std::vector<material::Media> atmosphere;
  GlobalSettings settings;
  /// Checks to run after rendering, each returning a warning or an empty string (e.g. an isosurface whose
  /// rays met slopes steeper than its max_gradient).
  std::vector<std::function<std::string()>> render_notes;
  /// What the scene's big arrays hold against --max-memory (memory/budget.hpp); later consumers (photon
  /// maps, caches) charge it too.
  std::shared_ptr<memory::Budget> memory_budget;

  /// The gamma the output is encoded relative to: POV-Ray 3.7 reads colours as linear under
  /// `assumed_gamma 1`, and without any assumed_gamma below #version 3.7 does no gamma handling.
  double effective_assumed_gamma() const;
  /// The gamma POV-Ray decodes working colours with where it needs linear ones (the anti-aliasing test):
  /// effective_assumed_gamma(), or 1 for a pre-3.7 scene without assumed_gamma (gamma handling off).
  double working_gamma() const;
  /// What a ray that hits nothing sees: the sky sphere over the background.
  math::Color miss_color(const math::Vec3& direction) const;
};

}  // namespace snell::scene
