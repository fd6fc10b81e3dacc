#include "snell/texture/ripple_patterns.hpp"

#include <cmath>
#include <cstdint>

#include "snell/texture/povray_noise.hpp"

namespace snell::texture {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

/// The waves from every centre at p: their mean height and the mean of each centre's radial direction
/// weighted by its height (POV-Ray normal.cpp, ripples/waves). `own_frequencies` gives each centre its
/// frequency and an amplitude 1/frequency (`waves`); otherwise all share `frequency` (`ripples`).
struct WaveSum {
  double mean_height = 0;
  Vec3 mean_tilt{0, 0, 0};
};

WaveSum sum_waves(const Vec3& p, double frequency, double phase, bool own_frequencies) {
  WaveSum sum;
  const double n = static_cast<double>(wave_sources().size());
  for (const WaveSource& s : wave_sources()) {
    const Vec3 offset = p - s.centre;
    double distance = length(offset);
    if (distance == 0) distance = 1;  // POV-Ray's choice at the centre itself
    const double f = own_frequencies ? frequency * s.frequency : frequency;
    const double amplitude = own_frequencies ? 1 / s.frequency : 1;
    const double height = amplitude * std::sin(kTwoPi * (distance * f + phase));
    sum.mean_height += height / n;
    sum.mean_tilt = sum.mean_tilt + offset * (height / (distance * n));
  }
  return sum;
}

}  // namespace

const std::array<WaveSource, 10>& wave_sources() {
  // POV-Ray's centres and frequencies (core/material/noise.cpp, Initialize_Waves): centre i is the
  // direction of DNoise at (i, 0, 0); the frequencies come from its LCG started at -560851967, taking
  // bits 16..30 of each state scaled to [0, 1] plus 0.01.
  static const std::array<WaveSource, 10> sources = [] {
    std::array<WaveSource, 10> s{};
    uint32_t state = static_cast<uint32_t>(-560851967);
    for (size_t i = 0; i < s.size(); ++i) {
      s[i].centre = normalize(povray_dnoise(Vec3{static_cast<double>(i), 0, 0}));
      state = state * 1812433253u + 12345u;
      s[i].frequency = static_cast<double>((state >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
    }
    return s;
  }();
  return sources;
}

double RipplesPattern::value(const Vec3& p) const {
  return 0.5 * (1 + sum_waves(p, frequency_, phase_, false).mean_height);
}

Vec3 RipplesPattern::bump(const Vec3& p) const {
  return sum_waves(p, frequency_, phase_, false).mean_tilt;
}

double WavesPattern::value(const Vec3& p) const {
  return 0.2 * (2.5 + sum_waves(p, frequency_, phase_, true).mean_height);
}

Vec3 WavesPattern::bump(const Vec3& p) const {
  return sum_waves(p, frequency_, phase_, true).mean_tilt;
}

}  // namespace snell::texture
