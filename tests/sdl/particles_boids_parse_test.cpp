// The particle_system and boids blocks (docs/procedural.md): what they build, and their errors.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"
#include "snell/geometry/blob.hpp"
#include "snell/material/interior.hpp"

namespace snell::sdl {
namespace {

using test::error_of;
using test::parse;

TEST(ParticlesParse, SpheresOnePerLiveParticle) {
  // rate 50 x lifetime 1 (constant) = 50 particles alive at time 3.
  const auto s = parse(R"(
    particle_system {
      emitter { point <0,1,0> rate 50 lifetime 1 +/- 0 speed 2 +/- 0.5 direction y spread 20 size 0.05 }
      gravity <0,-9.8,0> time 3 seed 3
      color_map { [0 rgb <1,1,0>] [1 rgbt <1,0,0,0.5>] }
      render { spheres }
      finish { emission 1 }
    })");
  ASSERT_NEAR(static_cast<double>(s.objects.size()), 50, 1);
  const material::Rgbft c = test::solid_color(*s.objects[0]);
  EXPECT_EQ(c.rgb.r, 1);
  EXPECT_GT(c.transmit, 0);  // part way along the map
  EXPECT_EQ(s.objects[0]->texture->finish.emission.r, 1);
}

TEST(ParticlesParse, MeanPlusMinusVarianceAcceptsSums) {
  // `(1 + 1) +/- 0` and `1 + 1` both mean 2; lifetime 2 x rate 10 = 20 particles.
  for (const char* lifetime : {"(1 + 1) +/- 0", "1 + 1", "4/2 +/- 0"}) {
    const auto s = parse(std::string("particle_system { emitter { point 0 rate 10 lifetime ") + lifetime +
                         " } time 5 }");
    EXPECT_NEAR(static_cast<double>(s.objects.size()), 20, 1) << lifetime;
  }
}

TEST(ParticlesParse, BlobMediaAndStreaks) {
  const std::string system = R"(
    particle_system {
      emitter { disc { <0,0,0>, y, 0.5 } rate 40 lifetime 1 speed 1 size 0.3 }
      wind <1,0,0> drag 1 turbulence 1 size 0.5 vortex { <0,0,0>, y, 1 core 0.2 } time 2 )";
  const auto blob = parse(system + "render { blob threshold 0.3 } pigment { rgb 1 } }");
  ASSERT_EQ(blob.objects.size(), 1u);
  EXPECT_NE(dynamic_cast<const geometry::Blob*>(blob.objects[0]->shape.get()), nullptr);
  const auto media = parse(system + "render { media emission 2 samples 5 } }");
  ASSERT_EQ(media.objects.size(), 1u);
  ASSERT_TRUE(media.objects[0]->interior);
  EXPECT_EQ(media.objects[0]->interior->media.size(), 1u);
  EXPECT_TRUE(media.objects[0]->flags.hollow);
  const auto streaks = parse(system + "render { streaks length 0.2 } }");
  EXPECT_GT(streaks.objects.size(), 40u);  // several fading cone pieces per particle
}

TEST(ParticlesParse, SurfaceEmitterStartsOnTheSurface) {
  // Particles with speed 0 stay where they were born: on the unit sphere around <0,2,0>.
  const auto s = parse(R"(
    particle_system {
      emitter { surface { sphere { <0,2,0>, 1 } } rate 100 lifetime 1 speed 0 size 0.01 }
      time 0.5 render { spheres } })");
  ASSERT_EQ(s.objects.size(), 50u);
  for (const auto& o : s.objects)
    EXPECT_NEAR(length(o->world_bounds().center() - math::Vec3(0, 2, 0)), 1, 1e-6);
}

TEST(ParticlesParse, Errors) {
  EXPECT_NE(error_of("particle_system { time 1 }")
                .find("test.pov:1:1: error: particle_system needs at least one emitter"),
            std::string::npos);
  EXPECT_NE(error_of("particle_system { emitter { point 0 rate 1e6 lifetime 10 } time 20 }")
                .find("more than max_particles 100000"),
            std::string::npos);
  EXPECT_NE(error_of("particle_system {\n emitter { point 0 rate 1 lifetime 1 +/- -1 } time 2 }")
                .find("test.pov:2:"),
            std::string::npos);
  EXPECT_NE(error_of("particle_system { emitter { point 0 rate 1 } render { cubes } }").find("render takes"),
            std::string::npos);
  EXPECT_NE(
      error_of("particle_system { emitter { point 0 rate 1 } time 1e9 step 1e-3 }").find("simulation steps"),
      std::string::npos);
  EXPECT_NE(error_of("particle_system { emitter { point 0 rate 1e7 lifetime 0.001 } time 100 }")
                .find("more than 100000000"),
            std::string::npos);
  EXPECT_NE(error_of("boids { count 5 }").find("boid { object }"), std::string::npos);
  EXPECT_NE(error_of("boids { count 1e9 boid { sphere { 0, 1 } } }").find("boid count"), std::string::npos);
}

TEST(BoidsParse, OneOrientedObjectPerBoid) {
  // A cone pointing along +z: after placement its tip lies ahead of its base along the velocity, so every
  // boid's bounds are non-degenerate and there is one object per boid.
  const auto s = parse(R"(
    boids { count 12 seed 4 time 2 start <-2,-2,-2>, <2,2,2> separation 0.5, 2 max_speed 2 min_speed 1
            boid { cone { <0,0,-0.2>, 0.1, <0,0,0.2>, 0 } } pigment { rgb 1 } })");
  ASSERT_EQ(s.objects.size(), 12u);
}

TEST(BoidsParse, AvoidKeepsABoidInsideAHollowSphere) {
  // A boid flying at 1..1.5 units/s for 20 s from the centre of a sphere of radius 3 meets the wall within
  // 3 s; with avoidance it turns away every time, without it it flies out.
  const std::string flock = R"(
    boids { count 1 seed 9 time 20 start <0,0,0>, <0,0,0> max_speed 1.5 min_speed 1 max_force 6
            boid { sphere { 0, 0.01 } } )";
  const auto inside = parse(flock + "avoid { sphere { 0, 3 } } distance 1.5 weight 4 }");
  const auto outside = parse(flock + "}");
  ASSERT_EQ(inside.objects.size(), 1u);
  EXPECT_LT(length(inside.objects[0]->world_bounds().center()), 3);
  EXPECT_GT(length(outside.objects[0]->world_bounds().center()), 3);
}

}  // namespace
}  // namespace snell::sdl
