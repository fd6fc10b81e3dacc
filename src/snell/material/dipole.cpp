#include "snell/material/dipole.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

namespace snell::material {

double diffuse_fresnel_reflectance(double eta) {
  return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

double dipole_boundary_term(double eta) {
  const double fdr = diffuse_fresnel_reflectance(eta);
  return (1 + fdr) / (1 - fdr);
}

double DipoleChannel::albedo() const {
  const double t = sigma_t_prime();
  return t > 0 ? sigma_s_prime / t : 0;
}

double DipoleChannel::sigma_tr() const {
  return std::sqrt(3 * sigma_a * sigma_t_prime());
}

double DipoleChannel::z_real() const {
  return 1 / sigma_t_prime();
}

double DipoleChannel::z_virtual() const {
  return z_real() * (1 + 4 * dipole_boundary_term(eta) / 3);
}

double DipoleChannel::reflectance(double r) const {
  if (sigma_t_prime() <= 0) return 0;
  const double tr = sigma_tr();
  const double zr = z_real();
  const double zv = z_virtual();
  const double dr = std::sqrt(r * r + zr * zr);
  const double dv = std::sqrt(r * r + zv * zv);
  // Jensen et al. 2001 eq. 5: the real source below and the virtual source above the surface.
  const double real = zr * (tr * dr + 1) * std::exp(-tr * dr) / (dr * dr * dr);
  const double virt = zv * (tr * dv + 1) * std::exp(-tr * dv) / (dv * dv * dv);
  return albedo() / (4 * std::numbers::pi) * (real + virt);
}

double DipoleChannel::total_reflectance() const {
  if (sigma_t_prime() <= 0) return 0;
  const double a = albedo();
  const double s = std::sqrt(3 * (1 - a));
  const double boundary = dipole_boundary_term(eta);
  return a / 2 * (1 + std::exp(-4.0 / 3.0 * boundary * s)) * std::exp(-s);
}

DipoleChannel Dipole::channel(int c) const {
  const auto pick = [c](const math::Color& v) { return c == 0 ? v.r : c == 1 ? v.g : v.b; };
  return {pick(sigma_s_prime), pick(sigma_a), eta};
}

math::Color Dipole::reflectance(double r) const {
  return {channel(0).reflectance(r), channel(1).reflectance(r), channel(2).reflectance(r)};
}

math::Color Dipole::total_reflectance() const {
  return {channel(0).total_reflectance(), channel(1).total_reflectance(), channel(2).total_reflectance()};
}

math::Color Dipole::sigma_tr() const {
  return {channel(0).sigma_tr(), channel(1).sigma_tr(), channel(2).sigma_tr()};
}

namespace {

struct MeasuredEntry {
  std::string_view name;
  Dipole dipole;
};

// Jensen et al. 2001, table of measured sigma_s' and sigma_a (mm^-1); eta as tabulated by Mitsuba 0.5
// (see ../shared/reference-values.md section 2, which prefers pbrt-v3's Chicken sigma_a).
constexpr std::array<MeasuredEntry, 12> kMeasured{{
    {"apple", {{2.29, 2.39, 1.97}, {0.0030, 0.0034, 0.046}, 1.3}},
    {"chicken1", {{0.15, 0.21, 0.38}, {0.015, 0.077, 0.19}, 1.3}},
    {"chicken2", {{0.19, 0.25, 0.32}, {0.018, 0.088, 0.20}, 1.3}},
    {"cream", {{7.38, 5.47, 3.15}, {0.0002, 0.0028, 0.0163}, 1.3}},
    {"ketchup", {{0.18, 0.07, 0.03}, {0.061, 0.97, 1.45}, 1.3}},
    {"marble", {{2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}, 1.5}},
    {"potato", {{0.68, 0.70, 0.55}, {0.0024, 0.0090, 0.12}, 1.3}},
    {"skimmilk", {{0.70, 1.22, 1.90}, {0.0014, 0.0025, 0.0142}, 1.3}},
    {"skin1", {{0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3}},
    {"skin2", {{1.09, 1.59, 1.79}, {0.013, 0.070, 0.145}, 1.3}},
    {"spectralon", {{11.6, 20.4, 14.9}, {0.0, 0.0, 0.0}, 1.3}},
    {"wholemilk", {{2.55, 3.21, 3.77}, {0.0011, 0.0024, 0.014}, 1.3}},
}};

}  // namespace

std::optional<Dipole> measured_material(std::string_view name) {
  std::string lower(name);
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (const MeasuredEntry& entry : kMeasured)
    if (entry.name == lower) return entry.dipole;
  return std::nullopt;
}

std::string_view measured_material_names() {
  return "apple, chicken1, chicken2, cream, ketchup, marble, potato, skimmilk, skin1, skin2, "
         "spectralon, wholemilk";
}

}  // namespace snell::material

namespace snell::material {

double albedo_for_total_reflectance(double rd, double eta) {
  rd = std::clamp(rd, 0.0, 1.0);
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    const DipoleChannel c{mid, 1 - mid, eta};  // sigma_t' = 1, so alpha' = mid
    (c.total_reflectance() < rd ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Dipole dipole_from_translucency(const math::Color& rd, const math::Color& translucency, double eta) {
  Dipole d;
  d.eta = eta;
  const auto channel = [&](double reflectance, double mean_free_path, double& s, double& a) {
    const double albedo = std::max(albedo_for_total_reflectance(reflectance, eta), 1e-6);
    s = 1 / std::max(std::fabs(mean_free_path), 1e-9);
    a = s / albedo - s;
  };
  channel(rd.r, translucency.r, d.sigma_s_prime.r, d.sigma_a.r);
  channel(rd.g, translucency.g, d.sigma_s_prime.g, d.sigma_a.g);
  channel(rd.b, translucency.b, d.sigma_s_prime.b, d.sigma_a.b);
  return d;
}

}  // namespace snell::material
