#pragma once
// Jensen's dipole BSSRDF for a semi-infinite homogeneous slab: the diffusion approximation of multiple
// subsurface scattering. Source: Jensen, Marschner, Levoy, Hanrahan 2001, "A Practical Model for
// Subsurface Light Transport" (SIGGRAPH 2001), eq. 4-5 and the total diffuse reflectance of section 2.
// One channel at a time; lengths in whatever unit the coefficients use (the measured table is in mm).
#include <optional>
#include <string_view>

#include "snell/math/color.hpp"

namespace snell::material {

/// One wavelength band of a dipole: the derived quantities of the paper's section 2.
struct DipoleChannel {
  double sigma_s_prime = 0;  ///< reduced scattering coefficient sigma_s'
  double sigma_a = 0;        ///< absorption coefficient
  double eta = 1.3;          ///< relative index of refraction (inside / outside)

  double sigma_t_prime() const { return sigma_a + sigma_s_prime; }
  /// Reduced albedo alpha' = sigma_s' / sigma_t'.
  double albedo() const;
  /// Effective transport coefficient sigma_tr = sqrt(3 sigma_a sigma_t').
  double sigma_tr() const;
  /// Depth of the real source below the surface, z_r = 1 / sigma_t'.
  double z_real() const;
  /// Height of the virtual (mirrored) source above the surface, z_v = z_r (1 + 4A/3).
  double z_virtual() const;
  /// Diffuse reflectance Rd(r) at distance r from the point of incidence (per unit area).
  double reflectance(double r) const;
  /// Total diffuse reflectance, the integral of Rd(r) 2 pi r dr, in closed form.
  double total_reflectance() const;
};

/// Diffuse Fresnel reflectance Fdr(eta) (Egan and Hilgeman's fit, as used by Jensen et al. 2001 eq. 7)
/// and the boundary term A = (1 + Fdr) / (1 - Fdr).
double diffuse_fresnel_reflectance(double eta);
double dipole_boundary_term(double eta);

/// RGB dipole: per-channel coefficients.
struct Dipole {
  math::Color sigma_s_prime;
  math::Color sigma_a;
  double eta = 1.3;

  DipoleChannel channel(int c) const;
  math::Color reflectance(double r) const;
  math::Color total_reflectance() const;
  math::Color sigma_tr() const;
};

/// The measured materials of Jensen et al. 2001, table of section 5 (values in mm^-1), looked up by a
/// case-insensitive name ("marble", "skimmilk", "skin1", ...). std::nullopt for unknown names.
std::optional<Dipole> measured_material(std::string_view name);
/// Comma-separated list of the names measured_material knows, for error messages and docs.
std::string_view measured_material_names();

}  // namespace snell::material

namespace snell::material {

/// The reduced albedo alpha' whose total diffuse reflectance is `rd` (0..1) for relative ior `eta`: the
/// inverse of DipoleChannel::total_reflectance, which grows monotonically with alpha'. POV-Ray maps a
/// subsurface finish's pigment * diffuse to alpha' this way (source/core/lighting/subsurface.cpp).
double albedo_for_total_reflectance(double rd, double eta);

/// POV-Ray 3.7's subsurface finish as a dipole: total reflectance `rd` per channel (pigment * diffuse) and
/// translucency = 1 / sigma_s' in mm (source/core/render/trace.cpp, ComputeSubsurfaceScattering).
Dipole dipole_from_translucency(const math::Color& rd, const math::Color& translucency, double eta);

}  // namespace snell::material
