#pragma once
// `ripples` and `waves` (POV-Ray 3.7 reference, "ripples", "waves"): circular waves spreading from ten
// fixed centres near the origin, placed as POV-Ray places them (ripple_patterns.cpp, wave_sources).
#include <array>

#include "snell/texture/pattern.hpp"

namespace snell::texture {

/// A wave centre on the unit sphere and its relative frequency (in [0.01, 1.01), used by `waves` only).
struct WaveSource {
  Vec3 centre;
  double frequency;
};

/// The ten wave centres, fixed for every render.
const std::array<WaveSource, 10>& wave_sources();

/// `ripples`: evenly spaced rings; `frequency` rings per unit, shifted by `phase`.
class RipplesPattern final : public ValuePattern, public BumpSource {
 public:
  RipplesPattern(double frequency = 1, double phase = 0) : frequency_(frequency), phase_(phase) {}
  /// 0.5 (1 + mean of sin(2 pi (distance * frequency + phase))) over the centres, in [0,1].
  double value(const Vec3& p) const override;
  /// Each centre tilts the normal along its radius by the wave's height there (POV-Ray normal.cpp).
  Vec3 bump(const Vec3& p) const override;

 private:
  double frequency_, phase_;
};

/// `waves`: like ripples, each centre with its own frequency and an amplitude inverse to it, so the
/// waves are of mixed lengths like a sea; values about [0.3, 0.7].
class WavesPattern final : public ValuePattern, public BumpSource {
 public:
  WavesPattern(double frequency = 1, double phase = 0) : frequency_(frequency), phase_(phase) {}
  double value(const Vec3& p) const override;
  Vec3 bump(const Vec3& p) const override;

 private:
  double frequency_, phase_;
};

}  // namespace snell::texture
