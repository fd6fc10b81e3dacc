#include "snell/render/optics.hpp"

#include <algorithm>
#include <cmath>

namespace snell::render {

namespace {
/// cos of the transmitted angle, or a negative value under total internal reflection.
double cos_transmitted(double cos_i, double eta) {
  const double sin2_t = eta * eta * std::max(0.0, 1.0 - cos_i * cos_i);
  if (sin2_t > 1.0) return -1.0;
  return std::sqrt(1.0 - sin2_t);
}
}  // namespace

FresnelTerms fresnel_terms(double cos_i, double n1, double n2) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  const double cos_t = cos_transmitted(cos_i, n1 / n2);
  if (cos_t < 0) return {};
  const double rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  const double rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
  return {rs * rs, rp * rp};
}

double fresnel_dielectric(double cos_i, double n1, double n2) {
  const FresnelTerms f = fresnel_terms(cos_i, n1, n2);
  return 0.5 * (f.rs + f.rp);
}

double fresnel_schlick(double cos_i, double n1, double n2) {
  const double r0 = ((n1 - n2) / (n1 + n2)) * ((n1 - n2) / (n1 + n2));
  double c = std::clamp(cos_i, 0.0, 1.0);
  if (n1 > n2) {
    c = cos_transmitted(c, n1 / n2);
    if (c < 0) return 1.0;
  }
  return r0 + (1 - r0) * std::pow(1 - c, 5);
}

bool total_internal_reflection(double cos_i, double n1, double n2) {
  return cos_transmitted(std::clamp(cos_i, 0.0, 1.0), n1 / n2) < 0;
}

std::optional<math::Vec3> refract(const math::Vec3& incident, const math::Vec3& n, double eta) {
  const double c = -dot(incident, n);
  const double k = 1.0 - eta * eta * (1.0 - c * c);
  if (k < 0) return std::nullopt;
  return eta * incident + (eta * c - std::sqrt(k)) * n;
}

}  // namespace snell::render
