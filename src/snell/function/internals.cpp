#include "snell/function/internals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "snell/texture/perlin_noise.hpp"

namespace snell::function {

namespace {

// Formulas from the functions.inc documentation (POV-Ray 3.7 reference, "Internal Functions").
// Arguments: a[0..2] = x, y, z; a[3..] = the extra parameters in documented order.

double f_ellipsoid(const double* a) {  // 17: radius-like value of an ellipsoid with inverse semi-axes
  return std::sqrt(a[0] * a[0] * a[3] * a[3] + a[1] * a[1] * a[4] * a[4] + a[2] * a[2] * a[5] * a[5]);
}

double f_ph(const double* a) {  // 47: polar angle from +y
  return std::atan2(std::sqrt(a[0] * a[0] + a[2] * a[2]), a[1]);
}

double f_r(const double* a) {  // 57: distance from the origin
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

double f_rounded_box(const double* a) {  // 60: radius, then the box's half sizes along x, y, z
  const double radius = a[3];
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    // Distance outside the box shrunk by the rounding radius, on this axis.
    const double inner = a[4 + i] - radius;
    const double d = std::max(std::fabs(a[i]) - inner, 0.0);
    d2 += d * d;
  }
  // POV-Ray subtracts a further 1e-6 so that coincident surfaces do not flicker.
  return std::sqrt(d2) - radius - 1e-6;
}

double f_sphere(const double* a) {  // 61: signed distance to a sphere of radius a[3]
  return f_r(a) - a[3];
}

double f_superellipsoid(const double* a) {  // 68: east-west exponent e, north-south exponent n
  const double e = a[3], n = a[4];
  const double xy = std::pow(std::fabs(a[0]), 2 / e) + std::pow(std::fabs(a[1]), 2 / e);
  return 1 - std::pow(std::pow(xy, e / n) + std::pow(std::fabs(a[2]), 2 / n), n / 2);
}

double f_th(const double* a) {  // 69: azimuth around y, measured from +z towards +x
  return std::atan2(a[0], a[2]);
}

double f_torus(const double* a) {  // 70: major radius, minor radius; torus in the x-z plane
  const double ring = std::sqrt(a[0] * a[0] + a[2] * a[2]) - a[3];
  return std::sqrt(ring * ring + a[1] * a[1]) - a[4];
}

double f_noise3d(const double* a) {  // 76
  // POV-Ray's Noise() returns about [0, 1]; snell uses Perlin's improved noise mapped to [0, 1] (as
  // its bozo pattern does), so values differ pointwise from POV-Ray's lattice noise but share range,
  // mean and feature size.
  return std::clamp(0.5 + 0.5 * texture::improved_perlin_noise(a[0], a[1], a[2]), 0.0, 1.0);
}

struct Entry {
  const char* name;
  int extra;  // parameters after x, y, z
  Function::Native fn;
};

// Numbers and parameter counts as functions.inc declares them.
constexpr std::array<Entry, 79> kTable{{
    {"f_algbr_cyl1", 5, nullptr},
    {"f_algbr_cyl2", 5, nullptr},
    {"f_algbr_cyl3", 5, nullptr},
    {"f_algbr_cyl4", 5, nullptr},
    {"f_bicorn", 2, nullptr},
    {"f_bifolia", 2, nullptr},
    {"f_blob", 5, nullptr},
    {"f_blob2", 4, nullptr},
    {"f_boy_surface", 2, nullptr},
    {"f_comma", 1, nullptr},
    {"f_cross_ellipsoids", 4, nullptr},
    {"f_crossed_trough", 1, nullptr},
    {"f_cubic_saddle", 1, nullptr},
    {"f_cushion", 1, nullptr},
    {"f_devils_curve", 1, nullptr},
    {"f_devils_curve_2d", 6, nullptr},
    {"f_dupin_cyclid", 6, nullptr},
    {"f_ellipsoid", 3, f_ellipsoid},
    {"f_enneper", 1, nullptr},
    {"f_flange_cover", 4, nullptr},
    {"f_folium_surface", 3, nullptr},
    {"f_folium_surface_2d", 6, nullptr},
    {"f_glob", 1, nullptr},
    {"f_heart", 1, nullptr},
    {"f_helical_torus", 10, nullptr},
    {"f_helix1", 7, nullptr},
    {"f_helix2", 7, nullptr},
    {"f_hex_x", 1, nullptr},
    {"f_hex_y", 1, nullptr},
    {"f_hetero_mf", 6, nullptr},
    {"f_hunt_surface", 1, nullptr},
    {"f_hyperbolic_torus", 3, nullptr},
    {"f_isect_ellipsoids", 4, nullptr},
    {"f_kampyle_of_eudoxus", 3, nullptr},
    {"f_kampyle_of_eudoxus_2d", 6, nullptr},
    {"f_klein_bottle", 1, nullptr},
    {"f_kummer_surface_v1", 1, nullptr},
    {"f_kummer_surface_v2", 4, nullptr},
    {"f_lemniscate_of_gerono", 1, nullptr},
    {"f_lemniscate_of_gerono_2d", 6, nullptr},
    {"f_mesh1", 5, nullptr},
    {"f_mitre", 1, nullptr},
    {"f_nodal_cubic", 1, nullptr},
    {"f_odd", 1, nullptr},
    {"f_ovals_of_cassini", 4, nullptr},
    {"f_paraboloid", 1, nullptr},
    {"f_parabolic_torus", 3, nullptr},
    {"f_ph", 0, f_ph},
    {"f_pillow", 1, nullptr},
    {"f_piriform", 1, nullptr},
    {"f_piriform_2d", 7, nullptr},
    {"f_poly4", 5, nullptr},
    {"f_polytubes", 6, nullptr},
    {"f_quantum", 1, nullptr},
    {"f_quartic_paraboloid", 1, nullptr},
    {"f_quartic_saddle", 1, nullptr},
    {"f_quartic_cylinder", 3, nullptr},
    {"f_r", 0, f_r},
    {"f_ridge", 6, nullptr},
    {"f_ridged_mf", 6, nullptr},
    {"f_rounded_box", 4, f_rounded_box},
    {"f_sphere", 1, f_sphere},
    {"f_spikes", 5, nullptr},
    {"f_spikes_2d", 4, nullptr},
    {"f_spiral", 6, nullptr},
    {"f_steiners_roman", 1, nullptr},
    {"f_strophoid", 4, nullptr},
    {"f_strophoid_2d", 7, nullptr},
    {"f_superellipsoid", 2, f_superellipsoid},
    {"f_th", 0, f_th},
    {"f_torus", 2, f_torus},
    {"f_torus2", 3, nullptr},
    {"f_torus_gumdrop", 1, nullptr},
    {"f_umbrella", 1, nullptr},
    {"f_witch_of_agnesi", 2, nullptr},
    {"f_witch_of_agnesi_2d", 6, nullptr},
    {"f_noise3d", 0, f_noise3d},
    {"f_pattern", 0, nullptr},
    {"f_noise_generator", 1, nullptr},
}};

}  // namespace

std::shared_ptr<const Function> internal_function(int n) {
  if (n < 0 || n >= static_cast<int>(kTable.size()))
    throw FunctionError("internal(" + std::to_string(n) + "): no such internal function (0 to " +
                        std::to_string(kTable.size() - 1) + ")");
  const Entry& e = kTable[static_cast<std::size_t>(n)];
  const auto arity = static_cast<std::size_t>(3 + e.extra);
  if (e.fn) return Function::native(e.name, arity, e.fn);
  return Function::unsupported(
      e.name, arity,
      std::string(e.name) + " (internal(" + std::to_string(n) + ")) is not implemented in snell yet");
}

}  // namespace snell::function
