#pragma once
// POV-Ray 3.7's `global_settings { radiosity { ... } }` (reference "Radiosity Basics" and "Configuring
// Radiosity"; defaults from source/core/lighting/radiosity.h). Used by the irradiance cache
// (render/radiosity/solver.hpp); docs/language.md lists what differs from POV-Ray.
namespace snell::scene {

struct RadiositySettings {
  int count = 35;
  /// Second count: the size of the direction table POV-Ray draws `count` directions from.
  int direction_pool = 0;
  int recursion_limit = 2;
  double brightness = 1;
  double error_bound = 1.8;
  int nearest_count = 5;
  double pretrace_start = 0.08;
  double pretrace_end = 0.04;
  double low_error_factor = 0.5;
  double gray_threshold = 0;
  double minimum_reuse = 0.015;
  double maximum_reuse = 0.2;
  double adc_bailout = 0.01;
  /// Caps each gather ray's brightest channel; 0 or negative: no cap.
  double max_sample = -1;
  bool normal = false;
  bool media = false;
  bool always_sample = false;
};

}  // namespace snell::scene
