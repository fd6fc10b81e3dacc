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
    constexpr double kPi = 3.14159265358979323846;
    constexpr double kPeriod = 1.00001;
    double v = value;
    // POV-Ray folds with a period slightly above 1 so that a raw value of exactly 1 (the centre of
    // `spherical`, say) keeps the last map entry instead of wrapping to the first. A zero frequency
    // leaves the value unfolded.
    // Most values already lie within one period, where fmod returns them unchanged: the library call
    // (70 instructions) is made only for the others.
    if (frequency != 0) {
      v = v * frequency + phase;
      if (!(std::fabs(v) < kPeriod)) v = std::fmod(v, kPeriod);
    }
    if (v < 0) v -= std::floor(v);  // negative values (and frequencies) wrap into [0,1)
    switch (wave) {
      case Wave::ramp:
        return v;
      case Wave::triangle: {
        const double f = v - std::floor(v);
        return f < 0.5 ? 2 * f : 2 * (1 - f);
      }
      case Wave::sine:
        return 0.5 + 0.5 * std::sin(v * 2 * kPi);
      case Wave::scallop:
        return std::fabs(std::sin(v * kPi));
      case Wave::cubic:
        return v * v * (3 - 2 * v);
      case Wave::poly:
        return std::pow(v, exponent);
    }
    return v;
  }
};

}  // namespace snell::texture
