#pragma once
// Patterns built on one random point per unit cube (POV-Ray 3.7 reference, "cells", "crackle"): a
// Voronoi diagram of those points. The points and cell values are POV-Ray's own (povray_hash3d and
// povray_pattern_random), so the cells sit where POV-Ray's do.
#include "snell/math/vec3.hpp"
#include "snell/texture/pattern.hpp"
#include "snell/texture/povray_noise.hpp"

namespace snell::texture {

/// `cells`: one random value in [0,1) per unit cube.
class CellsPattern final : public ValuePattern {
 public:
  double value(const Vec3& p) const override;
};

/// `crackle { form <f1,f2,f3> metric m offset o solid }`.
struct CrackleParams {
  /// Weights of the distances to the nearest, second and third point; POV-Ray's default <-1,1,0> gives
  /// the classic cracks (0 on the cell borders, rising inside the cells).
  Vec3 form{-1, 1, 0};
  /// Minkowski exponent of the distance: 2 Euclidean, 1 Manhattan, others sum(|d_i|^m)^(1/m).
  double metric = 2;
  /// Added to every distance (as offset^m inside the Minkowski sum).
  double offset = 0;
  /// Each cell one flat value instead of the distance blend.
  bool solid = false;
  /// The generator of the solid cells' noise.
  NoiseChoice noise;
};

class CracklePattern final : public ValuePattern {
 public:
  explicit CracklePattern(const CrackleParams& params = {}) : params_(params) {}
  /// The form-weighted distances, clamped to [0,1] as POV-Ray does.
  double value(const Vec3& p) const override;

 private:
  CrackleParams params_;
};

}  // namespace snell::texture
