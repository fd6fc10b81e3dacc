#pragma once
// Object motion for motion blur (a snell extension; POV-Ray 3.7 has none). A `motion { ... }` block puts a
// time-varying transform K(t) into an object's transform chain: the object's geometry at time t is
// (transforms after the block) * K(t) * (transforms before it). K(t) comes from keyed transforms, each
// decomposed into translation, rotation and stretch (polar decomposition, Shoemake & Duff, "Matrix
// animation and polar decomposition", 1992) and interpolated piecewise: translation and stretch linearly,
// rotation by slerp along the shorter arc. Before the first key and after the last the end keys hold.
#include <array>
#include <optional>
#include <vector>

#include "snell/math/bounds.hpp"
#include "snell/math/transform.hpp"

namespace snell::scene {

/// A unit quaternion w + xi + yj + zk.
struct Quaternion {
  double w = 1, x = 0, y = 0, z = 0;
  bool operator==(const Quaternion&) const = default;
};

/// An affine transform split as translation * rotation * stretch (stretch symmetric, row-major 3x3).
struct Pose {
  math::Vec3 translation;
  Quaternion rotation;
  std::array<double, 9> stretch{1, 0, 0, 0, 1, 0, 0, 0, 1};
};

/// Polar decomposition of `t`'s matrix. A reflection goes into the stretch (negated) so the rotation is
/// proper.
Pose decompose(const math::Transform& t);
/// The matrix of `pose`; nullopt when its stretch is singular (a scale interpolated through zero).
std::optional<math::Transform> compose(const Pose& pose);
/// Translation and stretch interpolated linearly, rotation by slerp (shorter arc), u in [0,1].
Pose interpolate(const Pose& a, const Pose& b, double u);

struct MotionKey {
  double time = 0;
  Pose pose;
};

/// One motion block: keys in increasing time, given in the space the block sits in, and `frame`, which
/// maps that space to world space (the transforms that came after the block).
struct MotionLayer {
  std::vector<MotionKey> keys;
  math::Transform frame;

  /// K(time): the keyed transform, interpolated.
  std::optional<math::Transform> keyed(double time) const;
  /// A box holding every point of `world_box` moved by frame * K(t) * frame^-1 for any t; conservative:
  /// intervals that only translate and stretch sweep each point along a segment (the union of the boxes at
  /// the keys holds it), intervals that rotate are bounded by a ball about the moving key-space origin.
  math::Bounds3 swept(const math::Bounds3& world_box) const;
};

/// The motion of a scene object: how its world-space geometry at time t differs from its `transform`
/// alone. Nested motion blocks (a moving object in a moving union) compose, outermost first.
class Motion {
 public:
  explicit Motion(std::vector<MotionLayer> layers) : layers_(std::move(layers)) {}
  /// D(t), which maps the object's still geometry to its place at `time`; nullopt when singular then.
  std::optional<math::Transform> at(double time) const;
  /// Bounds of `still_world_box` over all times.
  math::Bounds3 swept(const math::Bounds3& still_world_box) const;
  const std::vector<MotionLayer>& layers() const { return layers_; }

 private:
  std::vector<MotionLayer> layers_;
};

}  // namespace snell::scene
