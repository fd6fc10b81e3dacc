#pragma once
// Warps move the point a pattern is evaluated at (POV-Ray reference, "Warps"): transforms written inside
// a pigment and classic `turbulence`. POV-Ray keeps them in a list in the order written and applies them
// last-first, so `pigment { P turbulence 0.5 scale 2 }` scales first and then perturbs in pattern space.
#include <memory>
#include <vector>

#include "snell/math/transform.hpp"
#include "snell/math/vec3.hpp"

namespace snell::texture {

using math::Vec3;

class Warp {
 public:
  virtual ~Warp() = default;
  virtual Vec3 warp(const Vec3& p) const = 0;
};

/// A transform inside a pigment: the pattern moves by `transform`, so points go through its inverse.
class TransformWarp final : public Warp {
 public:
  explicit TransformWarp(const math::Transform& transform) : transform_(transform) {}
  Vec3 warp(const Vec3& p) const override { return transform_.inverse_point(p); }
  const math::Transform& transform() const { return transform_; }

 private:
  math::Transform transform_;
};

/// Classic `turbulence <t> octaves n omega w lambda l`: p + t * (fractal vector noise at p).
/// POV-Ray sums its own lattice noise (DNoise); this sums improved Perlin noise instead, so the shapes are
/// alike in scale and roughness but not identical point for point.
struct TurbulenceParams {
  Vec3 amount{0, 0, 0};
  int octaves = 6;
  double omega = 0.5;
  double lambda = 2.0;
};

class TurbulenceWarp final : public Warp {
 public:
  explicit TurbulenceWarp(const TurbulenceParams& params) : params_(params) {}
  Vec3 warp(const Vec3& p) const override;
  const TurbulenceParams& params() const { return params_; }

 private:
  TurbulenceParams params_;
};

/// Warps in the order written; `apply` runs them last-first, as POV-Ray does.
class WarpList {
 public:
  void push(std::shared_ptr<const Warp> warp) { warps_.push_back(std::move(warp)); }
  bool empty() const { return warps_.empty(); }
  Vec3 apply(const Vec3& p) const {
    Vec3 q = p;
    for (auto it = warps_.rbegin(); it != warps_.rend(); ++it) q = (*it)->warp(q);
    return q;
  }
  const std::vector<std::shared_ptr<const Warp>>& warps() const { return warps_; }

 private:
  std::vector<std::shared_ptr<const Warp>> warps_;
};

/// Vector-valued fractal noise: POV-Ray's DTurbulence, an octave sum of its DNoise (povray_noise.hpp).
Vec3 vector_turbulence(const Vec3& p, int octaves, double omega, double lambda);
/// One octave of the vector noise, each component in about [-1, 1] (POV-Ray's DNoise in role).
inline Vec3 vector_noise(const Vec3& p) {
  return vector_turbulence(p, 1, 0.5, 2);
}

}  // namespace snell::texture
