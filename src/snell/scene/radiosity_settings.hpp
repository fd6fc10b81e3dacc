#pragma once
// POV-Ray 3.7's `global_settings { radiosity { ... } }` (reference "Radiosity Basics" and "Configuring
// Radiosity"; defaults from source/core/lighting/radiosity.h). snell honours count, recursion_limit,
// brightness, gray_threshold and normal; the cache settings (error_bound, nearest_count, pretrace,
// low_error_factor, minimum/maximum_reuse, always_sample) are read and kept, but snell gathers along a fixed
// direction set at every shading point instead of caching (render/radiosity/hemisphere_gather.hpp).
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
  bool normal = false;
  bool media = false;
  bool always_sample = false;
};

}  // namespace snell::scene
