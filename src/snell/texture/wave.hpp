#pragma once
// POV-Ray's wave types (reference, "Wave Types"): how a pattern's raw value is folded into [0,1] before
// the map lookup, after `frequency` and `phase` are applied.
#include <cmath>

namespace snell::texture {

enum class Wave { ramp, triangle, sine, scallop, cubic, poly };

struct WaveShaping {
  Wave wave = Wave::ramp;
  double frequency = 1;
  double phase = 0;
  double exponent = 1;  // poly_wave

  double apply(double value) const {
    double v = value * frequency + phase;
    switch (wave) {
      case Wave::ramp:
        return v - std::floor(v);
      case Wave::triangle: {
        v -= std::floor(v);
        return v < 0.5 ? 2 * v : 2 - 2 * v;
      }
      case Wave::sine:
        return 0.5 + 0.5 * std::sin(v * 2 * 3.14159265358979323846);
      case Wave::scallop:
        return std::fabs(std::sin(v * 3.14159265358979323846));
      case Wave::cubic: {
        v -= std::floor(v);
        return v * v * (3 - 2 * v);
      }
      case Wave::poly: {
        v -= std::floor(v);
        return std::pow(v, exponent);
      }
    }
    return v;
  }
};

}  // namespace snell::texture
