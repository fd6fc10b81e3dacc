#include "snell/function/internals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "snell/function/algebraic_surfaces.hpp"
#include "snell/function/lane_math.hpp"
#include "snell/function/plane_curves.hpp"
#include "snell/function/special_shapes.hpp"
#include "snell/math/constants.hpp"
#include "snell/texture/povray_noise.hpp"

namespace snell::function {

namespace {

using math::kPi;

// Formulas from the functions.inc documentation (POV-Ray 3.7 reference, "Internal Functions").
// Arguments: a[0..2] = x, y, z; a[3..] = the extra parameters in documented order.

// The natives isosurfaces call most, written once as formulas over a number type T: double computes one
// point (the Native), Lanes kMaxLanes points at once (the LaneNative), by the same operations in the same
// order, so that every lane equals the one-point call bit for bit (angles excepted: their lanes use the
// vector atan2, within 2 ulp of libm's, as compiled functions' lanes do).
constexpr std::size_t kLanes = Function::kMaxLanes;

/// One value at kLanes points; arithmetic lane by lane (fixed-length loops, which the compiler vectorises).
struct Lanes {
  double v[kLanes];
};

template <typename F>
[[gnu::always_inline]] inline Lanes each(const Lanes& a, const Lanes& b, F f) {
  Lanes out;
  for (std::size_t l = 0; l < kLanes; ++l) out.v[l] = f(a.v[l], b.v[l]);
  return out;
}
Lanes operator+(const Lanes& a, const Lanes& b) {
  return each(a, b, [](double x, double y) { return x + y; });
}
Lanes operator-(const Lanes& a, const Lanes& b) {
  return each(a, b, [](double x, double y) { return x - y; });
}
Lanes operator*(const Lanes& a, const Lanes& b) {
  return each(a, b, [](double x, double y) { return x * y; });
}
Lanes operator-(const Lanes& a, double b) {
  return each(a, a, [b](double x, double) { return x - b; });
}

template <typename T>
T constant(double c);
template <>
double constant<double>(double c) {
  return c;
}
template <>
Lanes constant<Lanes>(double c) {
  Lanes out;
  for (double& v : out.v) v = c;
  return out;
}

double root(double x) {
  return std::sqrt(x);
}
Lanes root(const Lanes& x) {
  Lanes out;
  lanes::sqrt(x.v, out.v);
  return out;
}
double magnitude(double x) {
  return std::fabs(x);
}
Lanes magnitude(const Lanes& x) {
  return each(x, x, [](double a, double) { return std::fabs(a); });
}
double at_least_zero(double x) {
  return std::max(x, 0.0);
}
Lanes at_least_zero(const Lanes& x) {
  return each(x, x, [](double a, double) { return std::max(a, 0.0); });
}
double angle(double y, double x) {
  return std::atan2(y, x);
}
Lanes angle(const Lanes& y, const Lanes& x) {
  Lanes out;
  lanes::atan2(y.v, x.v, out.v);
  return out;
}

/// Argument i of one point (a Native's arguments) or of kLanes points (a LaneNative's).
struct Point {
  const double* a;
  double operator[](std::size_t i) const { return a[i]; }
};
struct Points {
  const double* const* a;
  Lanes operator[](std::size_t i) const {
    Lanes out;
    for (std::size_t l = 0; l < kLanes; ++l) out.v[l] = a[i][l];
    return out;
  }
};

/// The Native and the LaneNative of a formula F (F::value<T>(args), args[i] of type T).
template <typename F>
double at_point(const double* a) {
  return F::template value<double>(Point{a});
}
template <typename F>
void at_lanes(const double* const* a, double* out) {
  const Lanes v = F::template value<Lanes>(Points{a});
  for (std::size_t l = 0; l < kLanes; ++l) out[l] = v.v[l];
}

struct Ellipsoid {  // 17: radius-like value of an ellipsoid with inverse semi-axes
  template <typename T, typename A>
  static T value(const A& a) {
    return root(a[0] * a[0] * a[3] * a[3] + a[1] * a[1] * a[4] * a[4] + a[2] * a[2] * a[5] * a[5]);
  }
};

struct Ph {  // 47: polar angle from +y
  template <typename T, typename A>
  static T value(const A& a) {
    return angle(root(a[0] * a[0] + a[2] * a[2]), a[1]);
  }
};

struct R {  // 57: distance from the origin
  template <typename T, typename A>
  static T value(const A& a) {
    return root(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  }
};

struct RoundedBox {  // 60: radius, then the box's half sizes along x, y, z
  template <typename T, typename A>
  static T value(const A& a) {
    const T radius = a[3];
    T d2 = constant<T>(0);
    for (std::size_t i = 0; i < 3; ++i) {
      // Distance outside the box shrunk by the rounding radius, on this axis.
      const T inner = a[4 + i] - radius;
      const T d = at_least_zero(magnitude(a[i]) - inner);
      d2 = d2 + d * d;
    }
    // POV-Ray subtracts a further 1e-6 so that coincident surfaces do not flicker.
    return root(d2) - radius - 1e-6;
  }
};

struct Sphere {  // 61: signed distance to a sphere of radius a[3]
  template <typename T, typename A>
  static T value(const A& a) {
    return R::value<T>(a) - a[3];
  }
};

double f_superellipsoid(const double* a) {  // 68: east-west exponent e, north-south exponent n
  const double e = a[3], n = a[4];
  const double xy = std::pow(std::fabs(a[0]), 2 / e) + std::pow(std::fabs(a[1]), 2 / e);
  return 1 - std::pow(std::pow(xy, e / n) + std::pow(std::fabs(a[2]), 2 / n), n / 2);
}

struct Th {  // 69: azimuth around y, measured from +z towards +x
  template <typename T, typename A>
  static T value(const A& a) {
    return angle(a[0], a[2]);
  }
};

struct Torus {  // 70: major radius, minor radius; torus in the x-z plane
  template <typename T, typename A>
  static T value(const A& a) {
    const T ring = root(a[0] * a[0] + a[2] * a[2]) - a[3];
    return root(ring * ring + a[1] * a[1]) - a[4];
  }
};

/// POV-Ray's Noise() in [0, 1] with 3.7's default generator (range corrected; texture/povray_noise.hpp).
double noise01(double x, double y, double z) {
  return texture::povray_noise({x, y, z});
}

double f_noise3d(const double* a) {  // 76
  return noise01(a[0], a[1], a[2]);
}

void f_noise3d_lanes(const double* const* a, double* out) {
  texture::povray_noise_lanes(a[0], a[1], a[2], out);
}

/// A noise generator parameter of an internal function: POV-Ray (vm/fnintern.cpp) keeps its low two bits,
/// and 0 ("default") takes the original generator's path.
texture::NoiseGenerator generator_parameter(double value) {
  const int bits = static_cast<int>(std::clamp(value, -1.0e9, 1.0e9)) & 3;
  return bits == 0 ? texture::NoiseGenerator::original : static_cast<texture::NoiseGenerator>(bits);
}

double f_noise_generator(const double* a) {  // 78: the generator number (a[3]) picks POV-Ray's variant
  return texture::povray_noise({a[0], a[1], a[2]}, generator_parameter(a[3]));
}

void f_noise_generator_lanes(const double* const* a, double* out) {
  const texture::NoiseGenerator generator = generator_parameter(a[3][0]);
  bool same = true;
  for (std::size_t l = 1; l < kLanes; ++l) same = same && generator_parameter(a[3][l]) == generator;
  if (same) return texture::povray_noise_lanes(a[0], a[1], a[2], out, generator);
  for (std::size_t l = 0; l < kLanes; ++l) {
    const double point[4] = {a[0][l], a[1][l], a[2][l], a[3][l]};
    out[l] = f_noise_generator(point);
  }
}

double f_helix1(const double* a) {  // 25
  // Parameters (functions.inc): helix count, period, minor radius, major radius, shape (stretch along
  // y), cross section (1 circle, 2 diamond, 0 square, else a superellipse exponent), section rotation in
  // degrees. The distance to the nearest tube is measured in a frame that winds with the helix: radial
  // offset from the major radius, and the angular offset to the nearest turn turned into length along y.
  const double count = a[3], period = a[4], minor = a[5], major = a[6], shape = a[7], section = a[8];
  const double r = std::sqrt(a[0] * a[0] + a[2] * a[2]);
  const double x = (a[0] == 0 && a[2] == 0) ? 1e-6 : a[0];
  double turn = std::fmod(std::atan2(a[2], x) * count + a[1] * period * count, 2 * kPi);
  if (turn < 0) turn += 2 * kPi;
  double u = r - major, v = (turn - kPi) / shape / (period * count);
  double section_radius;
  if (section == 1) {
    section_radius = std::sqrt(u * u + v * v);
  } else {
    if (a[9] != 0) {
      const double c = std::cos(a[9] * kPi / 180), s = std::sin(a[9] * kPi / 180);
      const double ur = u * c - v * s;
      v = u * s + v * c;
      u = ur;
    }
    section_radius = section == 0
                         ? std::max(std::fabs(u), std::fabs(v))
                         : std::pow(std::pow(std::fabs(u), 2 / section) + std::pow(std::fabs(v), 2 / section),
                                    section / 2);
  }
  return std::min(major + r, section_radius) - minor;
}

double f_ridged_mf(const double* a) {  // 59
  // Musgrave's ridged multifractal (Ebert et al., "Texturing and Modeling", 3rd ed., ch. 16): parameters
  // H, lacunarity, octaves, offset, gain, noise generator. Each octave is (offset - |2 noise - 1|)^2,
  // weighted by the previous octave's value times gain (clamped to [0, 1]) and by frequency^-H.
  const double h = a[3], lacunarity = a[4], offset = a[6], gain = a[7];
  const int octaves = static_cast<int>(std::clamp(a[5], 0.0, 64.0));
  const texture::NoiseGenerator generator = generator_parameter(a[8]);
  // frequency^-H with frequency = lacunarity^i: one pow per call (it was most of an isosurface's time).
  const double step = std::pow(lacunarity, -h);
  // The octaves' points do not depend on the sum, so their noises are computed kNoiseLanes at a time
  // (the points by the same running products as one at a time), then summed in order.
  constexpr int kLanes = texture::kNoiseLanes;
  alignas(32) double px[kLanes], py[kLanes], pz[kLanes], noise[kLanes];
  double x = a[0], y = a[1], z = a[2];
  double signal = 0, result = 0, spectral = 1;
  const int count = std::max(octaves, 1);  // the first octave counts even for octaves 0
  for (int first = 0; first < count; first += kLanes) {
    const int n = std::min(kLanes, count - first);
    for (int l = 0; l < kLanes; ++l) {
      if (l >= n) {
        px[l] = py[l] = pz[l] = 0;
        continue;
      }
      if (first + l > 0) x *= lacunarity, y *= lacunarity, z *= lacunarity;
      px[l] = x, py[l] = y, pz[l] = z;
    }
    texture::povray_noise_lanes(px, py, pz, noise, generator);
    for (int l = 0; l < n; ++l) {
      const double r = offset - std::fabs(2 * noise[l] - 1), ridge = r * r;
      if (first + l == 0) {
        signal = result = ridge;
        continue;
      }
      spectral *= step;
      const double weight = std::clamp(signal * gain, 0.0, 1.0);
      signal = ridge * weight;
      result += signal * spectral;
    }
  }
  return result;
}

double f_hetero_mf(const double* a) {  // 29
  // Musgrave's heterogeneous multifractal (Ebert et al., "Texturing and Modeling", ch. 16; POV-Ray's
  // parameter order): H, lacunarity, octaves (a fraction adds part of one more), offset, T, noise generator.
  // Each octave adds (2 noise - 1 + offset) f^-H, multiplied T times by the signal so far (T = 0: plain
  // fBm, T = 1: heterogeneous).
  const double h = a[3], lacunarity = a[4], octaves = std::clamp(a[5], 0.0, 64.0), offset = a[6];
  const int power = static_cast<int>(std::clamp(a[7], 0.0, 64.0));
  const texture::NoiseGenerator generator = generator_parameter(a[8]);
  math::Vec3 p{a[0], a[1], a[2]};
  const auto octave = [&] { return 2 * texture::povray_noise(p, generator) - 1 + offset; };
  double signal = octave();
  p = p * lacunarity;
  const double step = std::pow(lacunarity, -h);
  double weight = step;
  for (int i = 1; i < octaves; ++i) {
    double increment = octave() * weight;
    for (int k = 0; k < power; ++k) increment *= signal;
    signal += increment;
    p = p * lacunarity;
    weight *= step;
  }
  const double part = octaves - std::floor(octaves);
  if (part != 0) signal += part * octave() * weight * signal;
  return signal;
}

double f_ridge(const double* a) {  // 58
  // Ridged turbulence: lambda, octaves (a fraction weighs one more octave in part), omega, offset, ridge,
  // noise generator. Each octave is |noise - ridge| normalised by the ridge's larger side, minus the offset,
  // weighted by omega^i at frequency lambda^i; the sum is divided by the total weight and normalised by the
  // offset's larger side.
  const double lambda = a[3], octaves = std::clamp(a[4], 0.0, 64.0), omega = a[5], offset = a[6],
               ridge = a[7];
  const texture::NoiseGenerator generator = generator_parameter(a[8]);
  const math::Vec3 p{a[0], a[1], a[2]};
  const double ridge_scale = 1 / std::max(ridge, 1 - ridge), offset_scale = 1 / std::max(offset, 1 - offset);
  const auto crest = [&](double frequency) {
    return std::fabs(texture::povray_noise(p * frequency, generator) - ridge) * ridge_scale - offset;
  };
  const int whole = static_cast<int>(octaves);
  double value = crest(1), total = 1, frequency = lambda, weight = omega;
  for (int i = 2; i <= whole; ++i) {
    value += weight * crest(frequency);
    total += weight;
    frequency *= lambda;
    weight *= omega;
  }
  if (const double part = octaves - whole; part != 0) {
    value += weight * crest(frequency) * part;
    total += weight * part;
  }
  return value * offset_scale / total;
}

struct Entry {
  const char* name;
  int extra;  // parameters after x, y, z
  Function::Native fn;
  Function::LaneNative lanes = nullptr;  // the same at several points at once, where written
};

// Numbers and parameter counts as functions.inc declares them.
constexpr std::array<Entry, 79> kTable{{
    {"f_algbr_cyl1", 5, curves::algbr_cyl1},
    {"f_algbr_cyl2", 5, curves::algbr_cyl2},
    {"f_algbr_cyl3", 5, curves::algbr_cyl3},
    {"f_algbr_cyl4", 5, curves::algbr_cyl4},
    {"f_bicorn", 2, surfaces::bicorn},
    {"f_bifolia", 2, surfaces::bifolia},
    {"f_blob", 5, curves::blob},
    {"f_blob2", 4, curves::blob2},
    {"f_boy_surface", 2, special::boy_surface},
    {"f_comma", 1, special::comma},
    {"f_cross_ellipsoids", 4, surfaces::cross_ellipsoids},
    {"f_crossed_trough", 1, surfaces::crossed_trough},
    {"f_cubic_saddle", 1, surfaces::cubic_saddle},
    {"f_cushion", 1, surfaces::cushion},
    {"f_devils_curve", 1, surfaces::devils_curve},
    {"f_devils_curve_2d", 6, curves::devils_curve_2d},
    {"f_dupin_cyclid", 6, special::dupin_cyclid},
    {"f_ellipsoid", 3, at_point<Ellipsoid>, at_lanes<Ellipsoid>},
    {"f_enneper", 1, special::enneper},
    {"f_flange_cover", 4, curves::flange_cover},
    {"f_folium_surface", 3, surfaces::folium_surface},
    {"f_folium_surface_2d", 6, curves::folium_surface_2d},
    {"f_glob", 1, surfaces::glob},
    {"f_heart", 1, surfaces::heart},
    {"f_helical_torus", 10, special::helical_torus},
    {"f_helix1", 7, f_helix1},
    {"f_helix2", 7, special::helix2},
    {"f_hex_x", 1, special::hex_x},
    {"f_hex_y", 1, special::hex_y},
    {"f_hetero_mf", 6, f_hetero_mf},
    {"f_hunt_surface", 1, surfaces::hunt_surface},
    {"f_hyperbolic_torus", 3, surfaces::hyperbolic_torus},
    {"f_isect_ellipsoids", 4, surfaces::isect_ellipsoids},
    {"f_kampyle_of_eudoxus", 3, surfaces::kampyle_of_eudoxus},
    {"f_kampyle_of_eudoxus_2d", 6, curves::kampyle_of_eudoxus_2d},
    {"f_klein_bottle", 1, surfaces::klein_bottle},
    {"f_kummer_surface_v1", 1, surfaces::kummer_surface_v1},
    {"f_kummer_surface_v2", 4, surfaces::kummer_surface_v2},
    {"f_lemniscate_of_gerono", 1, surfaces::lemniscate_of_gerono},
    {"f_lemniscate_of_gerono_2d", 6, curves::lemniscate_of_gerono_2d},
    {"f_mesh1", 5, curves::mesh1},
    {"f_mitre", 1, surfaces::mitre},
    {"f_nodal_cubic", 1, surfaces::nodal_cubic},
    {"f_odd", 1, surfaces::cushion},
    {"f_ovals_of_cassini", 4, surfaces::ovals_of_cassini},
    {"f_paraboloid", 1, surfaces::paraboloid},
    {"f_parabolic_torus", 3, surfaces::parabolic_torus},
    {"f_ph", 0, at_point<Ph>, at_lanes<Ph>},
    {"f_pillow", 1, surfaces::pillow},
    {"f_piriform", 1, surfaces::piriform},
    {"f_piriform_2d", 7, curves::piriform_2d},
    {"f_poly4", 5, curves::poly4},
    {"f_polytubes", 6, curves::polytubes},
    {"f_quantum", 1, special::quantum},
    {"f_quartic_paraboloid", 1, surfaces::quartic_paraboloid},
    {"f_quartic_saddle", 1, surfaces::quartic_saddle},
    {"f_quartic_cylinder", 3, surfaces::quartic_cylinder},
    {"f_r", 0, at_point<R>, at_lanes<R>},
    {"f_ridge", 6, f_ridge},
    {"f_ridged_mf", 6, f_ridged_mf},
    {"f_rounded_box", 4, at_point<RoundedBox>, at_lanes<RoundedBox>},
    {"f_sphere", 1, at_point<Sphere>, at_lanes<Sphere>},
    {"f_spikes", 5, curves::spikes},
    {"f_spikes_2d", 4, curves::spikes_2d},
    {"f_spiral", 6, curves::spiral},
    {"f_steiners_roman", 1, surfaces::steiners_roman},
    {"f_strophoid", 4, surfaces::strophoid},
    {"f_strophoid_2d", 7, curves::strophoid_2d},
    {"f_superellipsoid", 2, f_superellipsoid},
    {"f_th", 0, at_point<Th>, at_lanes<Th>},
    {"f_torus", 2, at_point<Torus>, at_lanes<Torus>},
    {"f_torus2", 3, surfaces::torus2},
    {"f_torus_gumdrop", 1, surfaces::torus_gumdrop},
    {"f_umbrella", 1, surfaces::umbrella},
    {"f_witch_of_agnesi", 2, surfaces::witch_of_agnesi},
    {"f_witch_of_agnesi_2d", 6, curves::witch_of_agnesi_2d},
    {"f_noise3d", 0, f_noise3d, f_noise3d_lanes},
    {"f_pattern", 0, nullptr},
    {"f_noise_generator", 1, f_noise_generator, f_noise_generator_lanes},
}};

}  // namespace

std::shared_ptr<const Function> internal_function(int n) {
  if (n < 0 || n >= static_cast<int>(kTable.size()))
    throw FunctionError("internal(" + std::to_string(n) + "): no such internal function (0 to " +
                        std::to_string(kTable.size() - 1) + ")");
  const Entry& e = kTable[static_cast<std::size_t>(n)];
  const auto arity = static_cast<std::size_t>(3 + e.extra);
  if (e.fn) return Function::native(e.name, arity, e.fn, e.lanes);
  return Function::unsupported(
      e.name, arity,
      std::string(e.name) + " (internal(" + std::to_string(n) + ")) is not implemented in snell yet");
}

}  // namespace snell::function
