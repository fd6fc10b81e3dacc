#include "snell/scene/motion.hpp"

#include <algorithm>
#include <cmath>

namespace snell::scene {

namespace {

using Mat3 = std::array<double, 9>;  // row-major

double det3(const Mat3& a) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
         a[2] * (a[3] * a[7] - a[4] * a[6]);
}

/// (a^-1)^T = cofactor(a) / det(a).
Mat3 inverse_transpose(const Mat3& a) {
  const double d = det3(a);
  return {
      (a[4] * a[8] - a[5] * a[7]) / d,  -(a[3] * a[8] - a[5] * a[6]) / d, (a[3] * a[7] - a[4] * a[6]) / d,
      -(a[1] * a[8] - a[2] * a[7]) / d, (a[0] * a[8] - a[2] * a[6]) / d,  -(a[0] * a[7] - a[1] * a[6]) / d,
      (a[1] * a[5] - a[2] * a[4]) / d,  -(a[0] * a[5] - a[2] * a[3]) / d, (a[0] * a[4] - a[1] * a[3]) / d};
}

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i * 3 + j] += a[i * 3 + k] * b[k * 3 + j];
  return r;
}

Mat3 transpose(const Mat3& a) {
  return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
}

/// Rotation matrix of a unit quaternion (column vectors).
Mat3 rotation_matrix(const Quaternion& q) {
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

Quaternion normalized(Quaternion q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

/// Quaternion of a proper rotation matrix (Shoemake, "Animating rotation with quaternion curves", 1985:
/// branch on the largest of the trace and the diagonal for accuracy).
Quaternion quaternion_of(const Mat3& m) {
  const double trace = m[0] + m[4] + m[8];
  Quaternion q;
  if (trace > 0) {
    const double s = 2 * std::sqrt(trace + 1);
    q = {0.25 * s, (m[7] - m[5]) / s, (m[2] - m[6]) / s, (m[3] - m[1]) / s};
  } else if (m[0] >= m[4] && m[0] >= m[8]) {
    const double s = 2 * std::sqrt(1 + m[0] - m[4] - m[8]);
    q = {(m[7] - m[5]) / s, 0.25 * s, (m[1] + m[3]) / s, (m[2] + m[6]) / s};
  } else if (m[4] >= m[8]) {
    const double s = 2 * std::sqrt(1 + m[4] - m[0] - m[8]);
    q = {(m[2] - m[6]) / s, (m[1] + m[3]) / s, 0.25 * s, (m[5] + m[7]) / s};
  } else {
    const double s = 2 * std::sqrt(1 + m[8] - m[0] - m[4]);
    q = {(m[3] - m[1]) / s, (m[2] + m[6]) / s, (m[5] + m[7]) / s, 0.25 * s};
  }
  return normalized(q);
}

double quaternion_dot(const Quaternion& a, const Quaternion& b) {
  return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

/// Frobenius norm: a bound on the operator 2-norm.
double frobenius(const Mat3& a) {
  double s = 0;
  for (double v : a) s += v * v;
  return std::sqrt(s);
}

math::Bounds3 pose_bounds(const Pose& pose, const math::Bounds3& box) {
  const auto t = compose(pose);
  return t ? t->bounds(box) : math::Bounds3::infinite();
}

/// Whether two rotations are the same within rounding (q and -q are the same rotation).
bool same_rotation(const Quaternion& a, const Quaternion& b) {
  return std::fabs(quaternion_dot(a, b)) > 1 - 1e-14;
}

}  // namespace

Pose decompose(const math::Transform& t) {
  const auto& m = t.matrix().m;
  Pose pose;
  pose.translation = {m[0][3], m[1][3], m[2][3]};
  Mat3 a{m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]};
  // Polar decomposition a = Q S by the iteration Q <- (Q + Q^-T) / 2 (Higham), which converges to the
  // orthogonal factor quadratically.
  Mat3 q = a;
  for (int i = 0; i < 64; ++i) {
    const Mat3 it = inverse_transpose(q);
    Mat3 next;
    double change = 0;
    for (int k = 0; k < 9; ++k) {
      next[k] = 0.5 * (q[k] + it[k]);
      change = std::max(change, std::fabs(next[k] - q[k]));
    }
    q = next;
    if (change < 1e-15) break;
  }
  if (det3(q) < 0)  // a reflection: Q = (-Q)(-I), so the stretch takes the sign
    for (double& v : q) v = -v;
  Mat3 s = multiply(transpose(q), a);
  // Symmetrise away rounding.
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) s[i * 3 + j] = s[j * 3 + i] = 0.5 * (s[i * 3 + j] + s[j * 3 + i]);
  pose.rotation = quaternion_of(q);
  pose.stretch = s;
  return pose;
}

std::optional<math::Transform> compose(const Pose& pose) {
  const Mat3 a = multiply(rotation_matrix(pose.rotation), pose.stretch);
  math::Matrix4 m = math::Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m.m[i][j] = a[i * 3 + j];
    m.m[i][3] = pose.translation[i];
  }
  return math::Transform::from_matrix(m);
}

Pose interpolate(const Pose& a, const Pose& b, double u) {
  Pose r;
  r.translation = a.translation + u * (b.translation - a.translation);
  for (int k = 0; k < 9; ++k) r.stretch[k] = a.stretch[k] + u * (b.stretch[k] - a.stretch[k]);
  Quaternion qb = b.rotation;
  double d = quaternion_dot(a.rotation, qb);
  if (d < 0) {  // the shorter arc
    qb = {-qb.w, -qb.x, -qb.y, -qb.z};
    d = -d;
  }
  double wa = 1 - u, wb = u;
  if (d < 0.9995) {  // slerp; nearly equal rotations lerp (then normalise) to avoid dividing by sin ~ 0
    const double theta = std::acos(d);
    wa = std::sin((1 - u) * theta) / std::sin(theta);
    wb = std::sin(u * theta) / std::sin(theta);
  }
  const Quaternion& qa = a.rotation;
  r.rotation = normalized(
      {wa * qa.w + wb * qb.w, wa * qa.x + wb * qb.x, wa * qa.y + wb * qb.y, wa * qa.z + wb * qb.z});
  return r;
}

std::optional<math::Transform> MotionLayer::keyed(double time) const {
  if (keys.empty()) return math::Transform{};
  if (time <= keys.front().time) return compose(keys.front().pose);
  if (time >= keys.back().time) return compose(keys.back().pose);
  const auto next = std::upper_bound(keys.begin(), keys.end(), time,
                                     [](double t, const MotionKey& k) { return t < k.time; });
  const MotionKey& b = *next;
  const MotionKey& a = *(next - 1);
  return compose(interpolate(a.pose, b.pose, (time - a.time) / (b.time - a.time)));
}

math::Bounds3 MotionLayer::swept(const math::Bounds3& world_box) const {
  if (!world_box.is_finite() || world_box.empty() || keys.empty()) return world_box;
  const math::Bounds3 box = frame.inverse().bounds(world_box);  // in the block's space
  math::Bounds3 all = pose_bounds(keys.front().pose, box);
  double reach = 0;  // farthest point of the box from the key-space origin
  for (int c = 0; c < 8; ++c) {
    const math::Vec3 corner{(c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y,
                            (c & 4) ? box.hi.z : box.lo.z};
    reach = std::max(reach, length(corner));
  }
  for (size_t i = 1; i < keys.size(); ++i) {
    const Pose& a = keys[i - 1].pose;
    const Pose& b = keys[i].pose;
    // Without rotation each point moves along a segment (translation and stretch are linear in u).
    math::Bounds3 span = pose_bounds(a, box).unite(pose_bounds(b, box));
    if (!same_rotation(a.rotation, b.rotation)) {
      // |R(u) S(u) p| <= max(|S_a|, |S_b|) |p|: the Frobenius norm is convex in u and bounds the 2-norm.
      const double r = std::max(frobenius(a.stretch), frobenius(b.stretch)) * reach;
      span.unite(math::Bounds3(math::min(a.translation, b.translation) - math::Vec3(r),
                               math::max(a.translation, b.translation) + math::Vec3(r)));
    }
    all.unite(span);
  }
  // A relative pad covers rounding in the pose matrices and in rotations taken as equal.
  const math::Vec3 pad = 1e-9 * (math::abs(all.lo) + math::abs(all.hi)) + math::Vec3(1e-12);
  all = math::Bounds3(all.lo - pad, all.hi + pad);
  return frame.bounds(all);
}

std::optional<math::Transform> Motion::at(double time) const {
  math::Transform d;
  for (const MotionLayer& layer : layers_) {
    const auto k = layer.keyed(time);
    if (!k) return std::nullopt;
    d = d * (layer.frame * *k * layer.frame.inverse());
  }
  return d;
}

math::Bounds3 Motion::swept(const math::Bounds3& still_world_box) const {
  math::Bounds3 b = still_world_box;
  for (auto it = layers_.rbegin(); it != layers_.rend(); ++it) b = it->swept(b);
  return b;
}

}  // namespace snell::scene
