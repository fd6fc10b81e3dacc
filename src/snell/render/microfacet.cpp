#include "snell/render/microfacet.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::render {

using math::Vec3;

double ggx_distribution(const Vec3& m, double alpha) {
  if (m.z <= 0) return 0;
  // D = alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2), Walter et al. 2007 eq. 33 rewritten without tan.
  const double a2 = alpha * alpha;
  const double d = m.z * m.z * (a2 - 1) + 1;
  return a2 / (math::kPi * d * d);
}

double ggx_lambda(const Vec3& v, double alpha) {
  // Lambda = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2 (Heitz 2014, eq. 72).
  const double cos2 = v.z * v.z;
  if (cos2 <= 0) return math::kInfinity;
  const double tan2 = std::max(0.0, 1 - cos2) / cos2;
  return 0.5 * (-1 + std::sqrt(1 + alpha * alpha * tan2));
}

double ggx_masking(const Vec3& v, double alpha) {
  return 1 / (1 + ggx_lambda(v, alpha));
}

double ggx_masking_shadowing(const Vec3& v, const Vec3& l, double alpha) {
  return 1 / (1 + ggx_lambda(v, alpha) + ggx_lambda(l, alpha));
}

double ggx_visible_normal_pdf(const Vec3& v, const Vec3& m, double alpha) {
  if (v.z <= 0) return 0;
  return ggx_masking(v, alpha) * std::max(0.0, dot(v, m)) * ggx_distribution(m, alpha) / v.z;
}

double ggx_reflection_pdf(const Vec3& v, const Vec3& l, double alpha) {
  const Vec3 h = v + l;
  if (length_squared(h) == 0) return 0;
  const Vec3 m = normalize(h);
  const double vm = dot(v, m);
  return vm > 0 ? ggx_visible_normal_pdf(v, m, alpha) / (4 * vm) : 0;
}

Vec3 sample_ggx_visible_normal(const Vec3& v, double alpha, double u1, double u2) {
  if (alpha <= 0) return {0, 0, 1};
  // Heitz 2018, section 2: stretch the view into the configuration where the distribution is a hemisphere,
  // sample the projected half-disc the stretched view sees (a disc whose far half is squashed by
  // (1 + v.z) / 2), lift the point onto the hemisphere, and unstretch the normal.
  const Vec3 vh = normalize(Vec3(alpha * v.x, alpha * v.y, v.z));
  const double len2 = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = len2 > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(len2) : Vec3(1, 0, 0);
  const Vec3 t2 = cross(vh, t1);
  const double r = std::sqrt(u1);
  const double phi = math::kTwoPi * u2;
  const double p1 = r * std::cos(phi);
  const double s = 0.5 * (1 + vh.z);
  const double p2 = (1 - s) * std::sqrt(std::max(0.0, 1 - p1 * p1)) + s * r * std::sin(phi);
  const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1 - p1 * p1 - p2 * p2)) * vh;
  const Vec3 m{alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)};
  return length_squared(m) > 0 ? normalize(m) : Vec3(0, 0, 1);
}

}  // namespace snell::render
