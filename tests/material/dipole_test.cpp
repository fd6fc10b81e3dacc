// Jensen et al. 2001 dipole against the independently computed values of ../shared/reference-values.md
// section 2 (alpha', sigma_tr, z_r, z_v, total Rd, point values Rd(r)).
#include "snell/material/dipole.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace snell::material {
namespace {

Dipole named(const char* name) {
  const auto dipole = measured_material(name);
  EXPECT_TRUE(dipole.has_value()) << name;
  return dipole.value_or(Dipole{});
}

/// Integral of Rd(r) 2 pi r dr over [0, inf) by Simpson's rule in the variable u = r / (1 + r), which
/// maps the half line to [0, 1) and keeps the sharp peak at r = 0 resolved.
double integrated_reflectance(const DipoleChannel& channel) {
  const int n = 20000;
  const auto integrand = [&](double u) {
    if (u >= 1) return 0.0;
    const double r = u / (1 - u);
    const double dr_du = 1 / ((1 - u) * (1 - u));
    return channel.reflectance(r) * 2 * std::numbers::pi * r * dr_du;
  };
  double sum = integrand(0) + integrand(1);
  for (int i = 1; i < n; ++i) sum += integrand(double(i) / n) * (i % 2 ? 4 : 2);
  return sum / (3.0 * n);
}

TEST(Dipole, BoundaryTermMatchesReference) {
  EXPECT_NEAR(diffuse_fresnel_reflectance(1.3), 0.44476284, 1e-8);
  EXPECT_NEAR(dipole_boundary_term(1.3), 2.60206439, 1e-8);
  EXPECT_NEAR(dipole_boundary_term(1.5), 3.95949744, 1e-8);
  EXPECT_NEAR(dipole_boundary_term(1.0), 1.0032051, 1e-7);
}

struct TotalCase {
  const char* name;
  math::Color rd;
};

TEST(Dipole, TotalReflectanceMatchesPaperMaterials) {
  const TotalCase cases[] = {{"marble", {0.830191, 0.790960, 0.752610}},
                             {"skimmilk", {0.814946, 0.812984, 0.682295}},
                             {"Skin1", {0.435956, 0.227331, 0.130999}},
                             {"wholemilk", {0.907698, 0.880868, 0.759413}},
                             {"ketchup", {0.163836, 0.006337, 0.001830}}};
  for (const TotalCase& c : cases) {
    const Dipole dipole = named(c.name);
    const double want[3] = {c.rd.r, c.rd.g, c.rd.b};
    for (int ch = 0; ch < 3; ++ch) {
      const DipoleChannel channel = dipole.channel(ch);
      EXPECT_NEAR(channel.total_reflectance(), want[ch], 1e-4) << c.name << " channel " << ch;
      // The closed form must equal the integral of the profile Rd(r) over the plane.
      EXPECT_NEAR(integrated_reflectance(channel), want[ch], 1e-4) << c.name << " channel " << ch;
    }
  }
}

TEST(Dipole, DerivedQuantitiesOfMarble) {
  const DipoleChannel red = named("marble").channel(0);
  EXPECT_NEAR(red.albedo(), 0.999042, 1e-6);
  EXPECT_NEAR(red.sigma_tr(), 0.117517, 1e-6);
  EXPECT_NEAR(red.z_real(), 0.456184, 1e-6);
  EXPECT_NEAR(red.z_virtual(), 2.864527, 1e-6);
}

TEST(Dipole, ProfileMatchesPointValues) {
  const double radii[] = {0, 0.5, 1, 2, 5};
  const double marble[] = {3.907465e-01, 1.254476e-01, 3.484669e-02, 9.093840e-03, 1.266693e-03};
  const double skin1[] = {4.443106e-02, 3.604819e-02, 2.201903e-02, 7.261361e-03, 8.018348e-04};
  const double skimmilk[] = {4.082255e-02, 3.457204e-02, 2.314369e-02, 9.190400e-03, 1.662324e-03};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(named("marble").channel(0).reflectance(radii[i]), marble[i], marble[i] * 1e-5);
    EXPECT_NEAR(named("skin1").channel(0).reflectance(radii[i]), skin1[i], skin1[i] * 1e-5);
    EXPECT_NEAR(named("skimmilk").channel(0).reflectance(radii[i]), skimmilk[i], skimmilk[i] * 1e-5);
  }
}

TEST(Dipole, UnknownMaterialIsRejected) {
  EXPECT_FALSE(measured_material("granite").has_value());
  EXPECT_TRUE(measured_material("SPECTRALON").has_value());
}

}  // namespace
}  // namespace snell::material

namespace snell::material {
namespace {

TEST(Dipole, AlbedoInversionRecoversMarble) {
  const DipoleChannel red = measured_material("marble")->channel(0);
  EXPECT_NEAR(albedo_for_total_reflectance(0.830191, 1.5), red.albedo(), 1e-5);
  // POV-Ray's mapping: the dipole built from pigment = Rd and translucency = 1/sigma_s' reproduces Rd.
  const Dipole d = dipole_from_translucency({0.5, 0.3, 0.1}, {2, 1, 0.5}, 1.3);
  EXPECT_NEAR(d.total_reflectance().r, 0.5, 1e-6);
  EXPECT_NEAR(d.total_reflectance().b, 0.1, 1e-6);
  EXPECT_NEAR(d.sigma_s_prime.g, 1.0, 1e-12);
}

}  // namespace
}  // namespace snell::material
