#pragma once
// The scene as the renderer sees it: built once (by the SDL parser, a procedural generator or C++ code),
// immutable while rendering, read by every thread without locks.
#include <memory>
#include <vector>

#include "snell/material/rgbft.hpp"
#include "snell/scene/camera.hpp"
#include "snell/scene/light.hpp"
#include "snell/scene/object.hpp"

namespace snell::scene {

/// POV-Ray `global_settings {}` and the language version that affects rendering.
struct GlobalSettings {
  /// The first `assumed_gamma` of the scene; 0 when none was given.
  double assumed_gamma = 0;
  int max_trace_level = 5;
  double adc_bailout = 1.0 / 255.0;
  math::Color ambient_light{1};
  /// `#version` in effect at the end of parsing (POV-Ray uses it for version-dependent defaults).
  double language_version = 3.7;
};

struct Scene {
  std::vector<std::shared_ptr<const Object>> objects;
  std::vector<Light> lights;
  CameraSpec camera;
  material::Rgbft background;
  GlobalSettings settings;

  /// The gamma the output is encoded relative to: POV-Ray 3.7 reads colours as linear under
  /// `assumed_gamma 1`, and without any assumed_gamma below #version 3.7 does no gamma handling.
  double effective_assumed_gamma() const;
};

}  // namespace snell::scene
