#pragma once
// A TraceObserver for whole renders of layers (aov_render.hpp): it keeps the camera ray's first hit and
// splits the sample's colour by the bounce that brought it (`--split-bounces N`).
//
// Light by bounce: every term a surface adds itself (emitted, ambient, diffuse, phong, specular) and the
// background a ray that misses brings are sorted into a bucket by the ray that found them: the camera ray's
// go to "direct", a ray at bounce depth d (1..N) to "reflection d" or "refraction d" by its own kind, and
// deeper ones to "deeper". A child's buckets reach its parent scaled by the weight of the parent's
// reflected or transmitted term, so the buckets sum to the colour wherever the Whitted recursion is linear
// (not through fog or media, nor with reflection exponent != 1).
#include <string>
#include <vector>

#include "snell/render/trace_observer.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render::explain {

/// Names of the bounce images for depth `n`: direct, reflection1, refraction1, ..., deeper.
std::vector<std::string> bounce_names(int n);

class SampleObserver final : public TraceObserver {
 public:
  /// `split_depth` < 0: no bounce split.
  explicit SampleObserver(int split_depth);

  /// Forgets the last sample.
  void reset();

  void ray_begin(scene::RayKind kind, const math::Ray& ray, int level, double weight,
                 const scene::Light* light) override;
  void ray_hit(const scene::SurfaceHit* hit) override;
  void shadow_blocker(const scene::SurfaceHit&, bool) override {}
  void term(RayTerm term, const math::Color& weight, const math::Color& value) override;
  void total_internal_reflection() override {}
  void ray_end(const math::Color& result) override;

  /// The camera ray's first hit, if it hit.
  bool first_hit_found() const { return first_hit_found_; }
  const scene::SurfaceHit& first_hit() const { return first_hit_; }
  const math::Ray& camera_ray() const { return camera_ray_; }
  /// The finished sample's colour by bounce (bounce_names order).
  const std::vector<math::Color>& bounces() const { return done_; }

 private:
  struct Frame {
    int bucket = 0;
    bool shadow = false;
    bool missed = false;
    std::vector<math::Color> buckets;
  };
  int bucket_of(scene::RayKind kind, int level) const;

  int split_depth_;
  size_t bucket_count_;
  bool first_hit_found_ = false;
  scene::SurfaceHit first_hit_;
  math::Ray camera_ray_;
  std::vector<Frame> open_;
  /// The last non-shadow ray to end, waiting for its parent's reflected/transmitted term.
  Frame pending_;
  bool has_pending_ = false;
  std::vector<math::Color> done_;
};

}  // namespace snell::render::explain
