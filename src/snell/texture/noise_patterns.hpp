#pragma once
// POV-Ray's noise-based value patterns that use their turbulence themselves instead of as a warp
// (POV-Ray 3.7 reference, "marble", "wood", "agate", "granite"). The shapes follow POV-Ray's formulas;
// the scalar noise under them is POV-Ray's, from the pattern's `noise_generator` (povray_noise.hpp).
#include <optional>

#include "snell/texture/pattern.hpp"
#include "snell/texture/povray_noise.hpp"
#include "snell/texture/warp.hpp"

namespace snell::texture {

/// `marble`: x plus turbulence, meant for the triangle wave (bands along x).
class MarblePattern final : public ValuePattern {
 public:
  MarblePattern(std::optional<TurbulenceParams> turbulence, NoiseChoice noise)
      : turbulence_(turbulence), noise_(std::move(noise)) {}
  double value(const Vec3& p) const override;

 private:
  std::optional<TurbulenceParams> turbulence_;
  NoiseChoice noise_;
};

/// `wood`: distance from the z axis (rings), the point wobbled by turbulence.
class WoodPattern final : public ValuePattern {
 public:
  explicit WoodPattern(std::optional<TurbulenceParams> turbulence) : turbulence_(turbulence) {}
  double value(const Vec3& p) const override;

 private:
  std::optional<TurbulenceParams> turbulence_;
};

/// `agate`: bands along z bent by turbulence, (0.5 (1 + sin(2 pi (1.3 t + 1.1 z))))^0.77.
class AgatePattern final : public ValuePattern {
 public:
  AgatePattern(TurbulenceParams turbulence, double agate_turb, NoiseChoice noise)
      : turbulence_(turbulence), agate_turb_(agate_turb), noise_(std::move(noise)) {}
  double value(const Vec3& p) const override;

 private:
  TurbulenceParams turbulence_;
  double agate_turb_;
  NoiseChoice noise_;
};

/// `granite`: six octaves of |noise| at 4x scale, each halving in amplitude (1/f noise); generator 1
/// takes |0.5 - noise| per octave, the others |1 - 2 noise| capped at 0.5.
class GranitePattern final : public ValuePattern {
 public:
  explicit GranitePattern(NoiseChoice noise = {}) : noise_(std::move(noise)) {}
  double value(const Vec3& p) const override;

 private:
  NoiseChoice noise_;
};

/// `wrinkles`: ten octaves of noise, each twice the frequency and half the amplitude of the last, halved
/// (POV-Ray pattern.cpp): about [0,1], centred near 0.5 and smoother than granite. Generators 2 and 3
/// stretch each octave to 2 noise - 0.5 clamped to [0,1]; generator 1 takes the noise as it is.
/// As a normal, the absolute vector noise of the same octaves, which gives creases rather than bumps.
class WrinklesPattern final : public ValuePattern, public BumpSource {
 public:
  explicit WrinklesPattern(NoiseChoice noise = {}) : noise_(std::move(noise)) {}
  double value(const Vec3& p) const override;
  Vec3 bump(const Vec3& p) const override;

 private:
  NoiseChoice noise_;
};

/// `bumps`: smooth noise in [0,1] (the bozo values); as a normal, vector noise added to the normal.
class BumpsPattern final : public ValuePattern, public BumpSource {
 public:
  explicit BumpsPattern(NoiseChoice noise = {}) : noise_(std::move(noise)) {}
  double value(const Vec3& p) const override;
  Vec3 bump(const Vec3& p) const override;

 private:
  NoiseChoice noise_;
};

/// `dents`: the cube of the noise in [0,1], mostly low with sparse peaks; as a normal, vector noise
/// scaled by that value (dents where the noise is high).
class DentsPattern final : public ValuePattern, public BumpSource {
 public:
  explicit DentsPattern(NoiseChoice noise = {}) : noise_(std::move(noise)) {}
  double value(const Vec3& p) const override;
  Vec3 bump(const Vec3& p) const override;

 private:
  NoiseChoice noise_;
};

}  // namespace snell::texture
