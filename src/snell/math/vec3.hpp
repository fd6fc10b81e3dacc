#pragma once
// Three-component double vector used for points, directions and normals alike. POV-Ray scenes mix
// 1e-4 and 1e5 in one file, so scene geometry stays in double precision (DESIGN.md, "Numbers").
#include <algorithm>
#include <cmath>

namespace snell::math {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  constexpr explicit Vec3(double s) : x(s), y(s), z(s) {}

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
  constexpr Vec3& operator/=(double s) { return *this *= 1.0 / s; }
  constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
constexpr Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
constexpr Vec3 operator*(Vec3 a, double s) { return a *= s; }
constexpr Vec3 operator*(double s, Vec3 a) { return a *= s; }
constexpr Vec3 operator/(Vec3 a, double s) { return a /= s; }
/// Component-wise product (POV-Ray's `<a> * <b>`).
constexpr Vec3 operator*(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
constexpr Vec3 operator/(const Vec3& a, const Vec3& b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }

constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double length_squared(const Vec3& v) { return dot(v, v); }
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline Vec3 normalize(const Vec3& v) {
  const double len = length(v);
  return len > 0 ? v / len : v;
}
constexpr Vec3 min(const Vec3& a, const Vec3& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
constexpr Vec3 max(const Vec3& a, const Vec3& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
inline Vec3 abs(const Vec3& v) { return {std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}; }
constexpr double min_component(const Vec3& v) { return std::min(v.x, std::min(v.y, v.z)); }
constexpr double max_component(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
/// Without a branch per component: x * 0 is 0 for finite x and NaN for an infinity or NaN, so the sum is 0
/// exactly when all three are finite (the BVH walk checks every ray this way).
inline bool is_finite(const Vec3& v) { return v.x * 0.0 + v.y * 0.0 + v.z * 0.0 == 0; }

/// Mirror reflection of incident direction `i` about unit normal `n`: r = i - 2 (i.n) n.
constexpr Vec3 reflect(const Vec3& i, const Vec3& n) { return i - 2.0 * dot(i, n) * n; }

/// Builds two unit vectors perpendicular to unit `n` and to each other (Duff et al. 2017, "Building an
/// Orthonormal Basis, Revisited").
inline void orthonormal_basis(const Vec3& n, Vec3& t, Vec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

struct Vec2 {
  double u = 0, v = 0;
};

}  // namespace snell::math
