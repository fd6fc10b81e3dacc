// POV-Ray's estimate of subsurface light for `translucency` finishes (render/subsurface_povray.hpp),
// checked against numbers worked out by hand from the formulas POV-Ray 3.7 uses.
#include "snell/render/subsurface_povray.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

TEST(PovraySubsurface, FresnelTermsAtKnownAngles) {
  // Normal incidence: 1 - ((eta - 1) / (eta + 1))^2 = 0.96 for eta 1.5.
  EXPECT_NEAR(povray_fresnel_transmittance(0.0, 1.5), 0.96, 1e-12);
  // Grazing light is all reflected.
  EXPECT_NEAR(povray_fresnel_transmittance(std::acos(0.0), 1.5), 0.0, 1e-9);
  // POV-Ray's diffuse Fresnel approximation: ((1 - 1/eta) + 3 (1 - 1/eta)^4.5) / 4.
  EXPECT_NEAR(povray_diffuse_fresnel_reflectance(1.5), (1.0 / 3 + 3 * std::pow(1.0 / 3, 4.5)) / 4, 1e-12);
  EXPECT_NEAR(povray_diffuse_fresnel_reflectance(1.0), 0.0, 1e-12);
}

TEST(PovraySubsurface, ReducedAlbedoInvertsTotalReflectance) {
  // Worked out by bisection of Jensen et al. 2001 section 2.3's Rd(alpha') with A = 1.19462 (eta 1.5).
  EXPECT_NEAR(povray_reduced_albedo(0.5, 1.5), 0.950991, 1e-5);
  EXPECT_NEAR(povray_reduced_albedo(0.0, 1.5), 0.0, 1e-9);
  EXPECT_NEAR(povray_reduced_albedo(1.0, 1.5), 1.0, 1e-9);
}

}  // namespace
}  // namespace snell::render
