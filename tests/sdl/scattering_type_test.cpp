// The scattering type numbers of `media { scattering { TYPE, colour } }` (POV-Ray 3.7 reference,
// "Scattering": 1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein).
#include <gtest/gtest.h>

#include <string>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

using Phase = material::Media::Phase;

Phase phase_of(int type) {
  const auto s = test::parse("media { scattering { " + std::to_string(type) + ", rgb 0.1 } }");
  return s.atmosphere.at(0).phase;
}

TEST(SdlScatteringType, NumbersFollowPovRay) {
  EXPECT_EQ(phase_of(1), Phase::isotropic);
  EXPECT_EQ(phase_of(2), Phase::mie_hazy);
  EXPECT_EQ(phase_of(3), Phase::mie_murky);
  EXPECT_EQ(phase_of(4), Phase::rayleigh);
  EXPECT_EQ(phase_of(5), Phase::henyey_greenstein);
}

TEST(SdlScatteringType, MieHazeScattersMostlyForward) {
  // Type 2 is Mie haze, 1 + 9 ((1 + cos)/2)^8: 10 forward, 1 + 9/256 sideways, 1 backward, where Rayleigh
  // would be symmetric and at most twice as strong. POV-Ray 3.7 renders of a shell of type-2 media lit from
  // one side are brightest toward the light (benchmark.pov's clouds).
  const material::Media m = test::parse("media { scattering { 2, rgb 0.1 } }").atmosphere.at(0);
  const math::Vec3 view(1, 0, 0);
  const double sideways = 1.0 + 9.0 / 256.0;
  EXPECT_NEAR(m.phase_weight(view, view) / m.phase_weight({0, 1, 0}, view), 10.0 / sideways, 1e-9);
  EXPECT_NEAR(m.phase_weight(-view, view) / m.phase_weight({0, 1, 0}, view), 1.0 / sideways, 1e-9);
}

}  // namespace
}  // namespace snell::sdl
