// Caustic photon mapping (render/photons/): power conservation through a glass slab against the Fresnel
// transmittance, the photon count over a sphere's solid angle, the paraxial focus of a glass sphere
// (f = n R / (2 (n - 1)) from its centre), the caustic against the direct light, identical photon maps for 1
// and 2 threads, the memory budget, and the parser's three photons blocks.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/render/photons/caustics.hpp"
#include "snell/render/photons/shooting.hpp"
#include "snell/render/renderer.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::render::photons {
namespace {

using math::Color;
using math::Vec3;

constexpr double kPi = 3.14159265358979323846;

scene::Scene parse(const std::string& text) {
  return sdl::parse_scene_string(text, "photons.pov", {});
}

ShootingResult shoot(const scene::Scene& s) {
  const auto a = accel::make_accelerator("bvh", s);
  return shoot_caustic_photons(s, *a);
}

/// Glass with Fresnel reflection whose transmission is what the reflection leaves (conserve_energy).
constexpr const char* kGlass =
    "pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } "
    "interior { ior 1.5 }";

TEST(PhotonsTest, SlabUnderParallelLightPassesTheFresnelTransmittance) {
  // A 2 x 2 glass slab under a vertical parallel light: photons cross its top and bottom faces at normal
  // incidence, each passing T = 1 - ((n-1)/(n+1))^2, and reach the floor. A parallel photon of spacing s
  // carries colour * s^2, so the floor's photons sum to colour * area * T^2.
  const double spacing = 0.01;
  const scene::Scene s = parse(std::string(R"(
    global_settings { photons { spacing )") +
                               std::to_string(spacing) + R"( jitter 0.4 autostop 0 } }
    light_source { <0, 10, 0> color rgb 1 parallel point_at <0, 0, 0> photons { refraction on } }
    plane { y, -2 pigment { rgb 1 } }
    box { <-1, -0.25, -1>, <1, 0.25, 1> )" +
                               kGlass + " photons { target reflection off collect off } }");
  const ShootingResult shot = shoot(s);
  double sum = 0;
  for (const Photon& p : shot.photons) {
    EXPECT_NEAR(p.position.y, -2, 1e-6);
    sum += p.power.r;
  }
  const double r = std::pow(0.5 / 2.5, 2);
  const double expected = 4 * (1 - r) * (1 - r);
  RecordProperty("deposited_over_expected", std::to_string(sum / expected));
  EXPECT_NEAR(sum / expected, 1.0, 0.01) << shot.photons.size() << " photons";
}

TEST(PhotonsTest, PhotonsCoverTheSolidAngleOfTheTarget) {
  // A point light at distance D from a target shoots over the cone of half-angle asin(R/D), R the radius of
  // the sphere around the target's bounding box (sqrt(3) for a unit sphere, as in POV-Ray), in cells of
  // (angular spacing)^2: 2 pi (1 - cos) / atan(spacing / D)^2 photons. (`autostop 1` shoots them all; with 0
  // POV-Ray stops at the first ring that misses the target.)
  const scene::Scene s = parse(std::string(R"(
    global_settings { photons { spacing 0.02 autostop 1 } }
    light_source { <0, 8, 0> color rgb 1 photons { refraction on } }
    sphere { 0, 1 )") + kGlass +
                               " photons { target } }");
  const ShootingResult shot = shoot(s);
  const double cone = std::asin(std::sqrt(3.0) / 8.0);
  const double cell = std::atan(0.02 / 8.0);
  const double expected = 2 * kPi * (1 - std::cos(cone)) / (cell * cell);
  RecordProperty("shot_over_expected", std::to_string(static_cast<double>(shot.shot) / expected));
  EXPECT_NEAR(static_cast<double>(shot.shot) / expected, 1.0, 0.01);
}

TEST(PhotonsTest, ShadowlessLightsShootNoPhotons) {
  // A shadowless light is POV-Ray's fill light, which its photon pass skips (photonstrategytask.cpp):
  // adding one beside a light must leave the shot photons as they are.
  const std::string rest = R"(
    global_settings { photons { spacing 0.05 autostop 1 } }
    light_source { <0, 8, 0> color rgb 1 photons { refraction on } }
    plane { y, -2 pigment { rgb 1 } }
    sphere { 0, 1 )" + std::string(kGlass) +
                           " photons { target } }";
  const ShootingResult alone = shoot(parse(rest));
  const ShootingResult with_fill =
      shoot(parse(rest + " light_source { <5, 8, 0> color rgb 1 shadowless photons { refraction on } }"));
  EXPECT_GT(alone.shot, 100u);
  EXPECT_EQ(with_fill.shot, alone.shot);
  EXPECT_EQ(with_fill.photons.size(), alone.photons.size());
}

TEST(PhotonsTest, PhotonsFromAFarLightDoNotMeetTheirMirrorAgain) {
  // A mirror cylinder lit from 1.4e5 units away: its quadratic's roots lose digits with the square of the
  // distance, and a hit point left inside the surface sends the reflected photon straight back into it. A
  // convex mirror cannot light itself, so no photon may be stored on it; the floor gets the rest.
  const ShootingResult shot = shoot(parse(R"(
    global_settings { photons { spacing 0.02 autostop 1 } }
    light_source { <100000, 100000, 0> color rgb 1 photons { reflection on } }
    plane { y, -1 pigment { rgb 1 } }
    cylinder { <0, -0.5, 0>, <0, 0.5, 0>, 1 pigment { rgb 1 } finish { reflection 1 }
               photons { target reflection on } })"));
  size_t on_mirror = 0, on_floor = 0;
  for (const Photon& p : shot.photons) {
    if (std::fabs(std::hypot(p.position.x, p.position.z) - 1) < 1e-3 && std::fabs(p.position.y) < 0.501)
      ++on_mirror;
    if (std::fabs(p.position.y + 1) < 1e-6) ++on_floor;
  }
  EXPECT_GT(shot.shot, 1000u);
  EXPECT_GT(on_floor, 100u);
  EXPECT_EQ(on_mirror, 0u) << "of " << shot.photons.size() << " photons";
}

TEST(PhotonsTest, GlassSphereFocusesNearTheParaxialFocus) {
  // A narrow beam (cylinder light of radius 0.1) along the axis of a glass sphere of radius 1, n = 1.5: the
  // rays cross the axis at the paraxial focus f = n R / (2 (n - 1)) = 1.5 below the centre. Each stored
  // photon's incoming direction gives its ray; where it crosses the axis is read back from it.
  const scene::Scene s = parse(std::string(R"(
    global_settings { photons { spacing 0.002 } }
    light_source { <0, 10, 0> color rgb 1 cylinder point_at <0, 0, 0> radius 0.1 falloff 0.1
                   photons { refraction on } }
    plane { y, -3 pigment { rgb 1 } }
    sphere { 0, 1 )") + kGlass +
                               " photons { target reflection off collect off } }");
  const ShootingResult shot = shoot(s);
  ASSERT_GT(shot.photons.size(), 500u);
  double sum = 0;
  int n = 0;
  for (const Photon& p : shot.photons) {
    const double off_axis = std::hypot(p.position.x, p.position.z);
    const double towards_axis = std::hypot(p.incoming.x, p.incoming.z);
    if (towards_axis < 1e-9) continue;
    const double t = off_axis / towards_axis;  // along `incoming` back to the axis
    sum += p.position.y + t * p.incoming.y;
    ++n;
  }
  const double focus = sum / n;
  RecordProperty("focus_y", std::to_string(focus));
  EXPECT_NEAR(focus, -1.5, 0.015);
}

TEST(PhotonsTest, CausticAtTheFocusOutshinesTheDirectLight) {
  // The whole sphere under a parallel light of colour 1 (direct irradiance 1 on the floor): at the focus the
  // photons bring many times more.
  const scene::Scene s = parse(std::string(R"(
    global_settings { photons { spacing 0.01 } }
    light_source { <0, 10, 0> color rgb 1 parallel point_at <0, 0, 0> photons { refraction on } }
    plane { y, -1.45 pigment { rgb 1 } }
    sphere { 0, 1 )") + kGlass +
                               " photons { target reflection off } }");
  const auto a = accel::make_accelerator("bvh", s);
  const auto caustics = make_caustics(s, *a);
  ASSERT_TRUE(caustics);
  const auto irradiance = [&](const Vec3& p) {
    return caustics->map().radiance(p, Vec3(0, 1, 0), Vec3(0, 1, 0), false,
                                    [](const Vec3& dir, const Color& c) { return c * dir.y; });
  };
  const Color focus = irradiance({0, -1.45, 0});
  const Color aside = irradiance({2.5, -1.45, 0});
  RecordProperty("focus_irradiance", std::to_string(focus.r));
  EXPECT_GT(focus.r, 10.0);
  EXPECT_LT(aside.r, 0.01);  // no photons outside the sphere's shadow
}

TEST(PhotonsTest, RenderedCausticIsBrighterThanTheShadow) {
  // Through the Whitted integrator: looking down at the floor under the sphere, the caustic's centre
  // outshines the lit floor; without photons it gets the light filtered by the glass's pigment (1).
  const std::string scene_text = std::string(R"(
    camera { orthographic location <0, -1.4, 0> look_at <0, -2, 0> right <0.2, 0, 0> up <0, 0, 0.2> }
    light_source { <0, 10, 0> color rgb 1 parallel point_at <0, 0, 0> photons { refraction on } }
    plane { y, -1.45 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
    sphere { 0, 1 no_image )") + kGlass +
                                 " photons { target reflection off } }";
  RenderOptions o;
  o.width = 8;
  o.height = 8;
  o.antialias = false;
  const auto render_centre = [&](const std::string& text) {
    const scene::Scene s = parse(text);
    const auto a = accel::make_accelerator("bvh", s);
    return Renderer(s, *a, o).render().image.at(4, 4);
  };
  const Color with = render_centre("global_settings { photons { spacing 0.01 } }" + scene_text);
  const Color without = render_centre(scene_text);
  EXPECT_NEAR(without.r, 1.0, 1e-6);
  RecordProperty("caustic_pixel", std::to_string(with.r));
  EXPECT_GT(with.r, 5.0);
}

TEST(PhotonsTest, PhotonMapIsTheSameForOneAndTwoThreads) {
  const scene::Scene s = parse(std::string(R"(
    global_settings { photons { spacing 0.03 } }
    light_source { <3, 8, -2> color rgb <1, 0.9, 0.8> photons { refraction on reflection on } }
    plane { y, -1 pigment { rgb 1 } }
    sphere { 0, 1 )") + kGlass +
                               " photons { target } }");
  const auto a = accel::make_accelerator("bvh", s);
  ShootingResult one, two;
  tbb::task_arena(1).execute([&] { one = shoot_caustic_photons(s, *a); });
  tbb::task_arena(2).execute([&] { two = shoot_caustic_photons(s, *a); });
  ASSERT_GT(one.photons.size(), 1000u);
  ASSERT_EQ(one.photons.size(), two.photons.size());
  for (size_t i = 0; i < one.photons.size(); ++i) {
    ASSERT_EQ(one.photons[i].position, two.photons[i].position) << i;
    ASSERT_EQ(one.photons[i].power.r, two.photons[i].power.r) << i;
  }
}

TEST(PhotonsTest, PhotonMapIsChargedToTheMemoryBudget) {
  scene::Scene s = parse(std::string(R"(
    global_settings { photons { spacing 0.02 } }
    light_source { <0, 8, 0> color rgb 1 photons { refraction on } }
    plane { y, -1 pigment { rgb 1 } }
    sphere { 0, 1 )") + kGlass +
                         " photons { target } }");
  const auto a = accel::make_accelerator("bvh", s);
  s.memory_budget = std::make_shared<memory::Budget>(1000);
  EXPECT_THROW(make_caustics(s, *a), memory::BudgetExceeded);
  s.memory_budget = std::make_shared<memory::Budget>(memory::Budget::kUnlimited);
  const auto caustics = make_caustics(s, *a);
  EXPECT_EQ(s.memory_budget->used(), caustics->map().memory_bytes());
  EXPECT_GT(caustics->map().memory_bytes(), caustics->map().size() * sizeof(Photon));
}

TEST(PhotonsTest, SpacingTooFineFailsBeforeShooting) {
  // About 1e11 directions: refused up front (a clear error, not memory piling up).
  const scene::Scene s = parse(std::string(R"(
    global_settings { photons { spacing 0.00001 } }
    light_source { <0, 8, 0> color rgb 1 photons { refraction on } }
    sphere { 0, 1 )") + kGlass +
                               " photons { target } }");
  const auto a = accel::make_accelerator("bvh", s);
  try {
    make_caustics(s, *a);
    FAIL() << "no error";
  } catch (const memory::BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("larger spacing"), std::string::npos) << e.what();
  }
}

TEST(PhotonsTest, ParsesThePhotonsBlocks) {
  const scene::Scene s = parse(R"(
    global_settings { photons { count 20000 gather 10, 50 jitter 0.2 max_trace_level 7 adc_bailout 0.05
                                autostop 0.3 expand_thresholds 0.1, 20 radius 0.5, 2 media 100, 2 } }
    light_source { <0, 8, 0> color rgb 1 photons { refraction off reflection on area_light } }
    union { sphere { 0, 1 } sphere { x, 1 photons { collect off } }
            photons { target 0.5 refraction on pass_through } })");
  ASSERT_TRUE(s.settings.photons);
  const scene::PhotonSettings& p = *s.settings.photons;
  EXPECT_EQ(p.count, 20000);
  EXPECT_EQ(p.gather_min, 10);
  EXPECT_EQ(p.gather_max, 50);
  EXPECT_DOUBLE_EQ(p.jitter, 0.2);
  EXPECT_EQ(p.max_trace_level, 7);
  EXPECT_DOUBLE_EQ(p.adc_bailout, 0.05);
  EXPECT_DOUBLE_EQ(p.autostop, 0.3);
  EXPECT_DOUBLE_EQ(p.expand_tolerance, 0.1);
  EXPECT_EQ(p.expand_min_count, 20);
  EXPECT_DOUBLE_EQ(p.gather_radius, 0.5);
  EXPECT_DOUBLE_EQ(p.gather_radius_multiplier, 2);
  EXPECT_EQ(p.media_steps, 100);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].photons.refraction, scene::PhotonSwitch::off);
  EXPECT_EQ(s.lights[0].photons.reflection, scene::PhotonSwitch::on);
  EXPECT_TRUE(s.lights[0].photons.area_light);
  ASSERT_EQ(s.objects.size(), 2u);
  const scene::ObjectPhotons& a = s.objects[0]->flags.photons;
  const scene::ObjectPhotons& b = s.objects[1]->flags.photons;
  ASSERT_TRUE(a.target);
  EXPECT_EQ(a.target, b.target);  // one target: the union's parts share it
  EXPECT_DOUBLE_EQ(a.target->spacing_multiplier, 0.5);
  EXPECT_EQ(b.refraction, scene::PhotonSwitch::on);
  EXPECT_TRUE(a.collect);
  EXPECT_FALSE(b.collect);
  EXPECT_TRUE(a.pass_through);
}

TEST(PhotonsTest, BadPhotonsBlocksAreErrorsAtTheirPlace) {
  const auto message = [](const std::string& text) {
    try {
      parse(text);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("global_settings { photons { spacing 0 } }").find("photons.pov:1:"), std::string::npos);
  EXPECT_NE(message("global_settings { photons { gather 30, 10 } }").find("gather minimum"),
            std::string::npos);
  EXPECT_NE(message("sphere { 0, 1 photons { targett } }").find("unknown object photons keyword"),
            std::string::npos);
  EXPECT_NE(message("light_source { 0 rgb 1 photons { collect off } }").find("unknown light_source photons"),
            std::string::npos);
}

}  // namespace
}  // namespace snell::render::photons
