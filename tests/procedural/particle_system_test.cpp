// Particle systems (Reeves 1983) checked against numbers that follow from the emitter's definition:
// steady-state count = rate x mean lifetime, uniform ages under a constant rate, and the exact parabola
// (and drag's terminal velocity) of Newtonian motion.
#include "snell/procedural/particle_system.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace snell::procedural {
namespace {

ParticleSettings fountain(double rate, Spread lifetime, double time) {
  ParticleSettings s;
  Emitter e;
  e.rate = rate;
  e.lifetime = lifetime;
  e.speed = {2, 0.5};
  e.spread_degrees = 30;
  s.emitters.push_back(e);
  s.time = time;
  s.seed = 7;
  return s;
}

TEST(ParticleSystem, SteadyStateCountIsRateTimesLifetime) {
  // A constant lifetime L: once t > L exactly rate x L particles are alive (one may be on the boundary).
  const auto particles = simulate_particles(fountain(100, {2, 0}, 5));
  EXPECT_NEAR(static_cast<double>(particles.size()), 200, 1);
}

TEST(ParticleSystem, SteadyStateCountUsesMeanLifetime) {
  // Lifetimes uniform in 2 +/- 0.5: the expected count is rate x E[L] = 1000 x 2 = 2000; each particle
  // is alive with probability P(L > age), so the count's standard deviation is below sqrt(2000) ~ 45.
  const auto particles = simulate_particles(fountain(1000, {2, 0.5}, 6));
  EXPECT_NEAR(static_cast<double>(particles.size()), 2000, 3 * 45);
}

TEST(ParticleSystem, AgesAreUniformUnderConstantRate) {
  // Under a constant rate and lifetime the ages fill [0, L) uniformly: each tenth of L holds rate x L / 10.
  const double lifetime = 2;
  const auto particles = simulate_particles(fountain(500, {lifetime, 0}, 7.3));
  std::vector<int> bins(10, 0);
  for (const Particle& p : particles) {
    ASSERT_GE(p.age, 0);
    ASSERT_LT(p.age, lifetime);
    ++bins[static_cast<size_t>(p.age / lifetime * 10)];
  }
  for (int count : bins) EXPECT_NEAR(count, 500 * lifetime / 10, 1);
}

TEST(ParticleSystem, GravityOnlyTrajectoryIsTheParabola) {
  // Born at t0 = 0.3 from <1,2,3> with velocity 5 * normalize(<1,2,0>), observed at T = 1.234 (not on the
  // step grid): x = x0 + v0 (T - t0) + g (T - t0)^2 / 2.
  ParticleSettings s;
  Emitter e;
  e.center = {1, 2, 3};
  e.burst = 1;
  e.burst_time = 0.3;
  e.direction = normalize(math::Vec3(1, 2, 0));
  e.speed = {5, 0};
  e.lifetime = {10, 0};
  s.emitters.push_back(e);
  s.forces.gravity = {0, -9.8, 0};
  s.time = 1.234;
  const auto particles = simulate_particles(s);
  ASSERT_EQ(particles.size(), 1u);
  const double tau = 1.234 - 0.3;
  const math::Vec3 v0 = normalize(math::Vec3(1, 2, 0)) * 5;
  const math::Vec3 expected = math::Vec3(1, 2, 3) + v0 * tau + math::Vec3(0, -9.8, 0) * (0.5 * tau * tau);
  EXPECT_NEAR(particles[0].position.x, expected.x, 1e-9);
  EXPECT_NEAR(particles[0].position.y, expected.y, 1e-9);
  EXPECT_NEAR(particles[0].position.z, expected.z, 1e-9);
  EXPECT_NEAR(particles[0].velocity.y, v0.y - 9.8 * tau, 1e-9);
  EXPECT_NEAR(particles[0].age, tau, 1e-12);
}

TEST(ParticleSystem, DragApproachesTerminalVelocity) {
  // dv/dt = g - k (v - w) tends to v = w + g / k; after 10 time constants e^-10 of the start remains.
  ParticleSettings s;
  Emitter e;
  e.burst = 1;
  e.speed = {3, 0};
  e.lifetime = {100, 0};
  s.emitters.push_back(e);
  s.forces.gravity = {0, -9.8, 0};
  s.forces.wind = {2, 0, 0};
  s.forces.drag = 2;
  s.time = 5;
  const auto particles = simulate_particles(s);
  ASSERT_EQ(particles.size(), 1u);
  EXPECT_NEAR(particles[0].velocity.x, 2, 1e-3);
  EXPECT_NEAR(particles[0].velocity.y, -4.9, 1e-3);
}

TEST(ParticleSystem, SameSeedGivesSameParticles) {
  ParticleSettings s = fountain(200, {1, 0.3}, 2.5);
  s.forces.turbulence = 2;
  s.forces.vortices.push_back({});
  const auto a = simulate_particles(s), b = simulate_particles(s);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].position, b[i].position);
  s.seed = 8;
  const auto c = simulate_particles(s);
  ASSERT_FALSE(c.empty());
  EXPECT_NE(a[0].position, c[0].position);
}

TEST(ParticleSystem, AParticleDoesNotDependOnTheFrameTimesBefore) {
  // A burst particle seen at T through steps of 0.1 equals one that took a different last step: its
  // attributes depend on (seed, emitter, index) only, and gravity-only motion is exact for any step.
  ParticleSettings s = fountain(0, {10, 0}, 1.05);
  s.emitters[0].burst = 5;
  s.forces.gravity = {0, -9.8, 0};
  s.step = 0.1;
  const auto coarse = simulate_particles(s);
  s.step = 1.0 / 64;
  const auto fine = simulate_particles(s);
  ASSERT_EQ(coarse.size(), 5u);
  ASSERT_EQ(fine.size(), 5u);
  for (size_t i = 0; i < 5; ++i) EXPECT_NEAR(length(coarse[i].position - fine[i].position), 0, 1e-9);
}

TEST(ParticleSystem, DeathByBoundsAndLimit) {
  ParticleSettings s = fountain(1000, {5, 0}, 3);
  s.forces.gravity = {0, -9.8, 0};
  s.bounds = math::Bounds3(math::Vec3(-10, -0.5, -10), math::Vec3(10, 10, 10));
  for (const Particle& p : simulate_particles(s)) EXPECT_GE(p.position.y, -0.5);
  s.bounds.reset();
  s.max_particles = 300;
  EXPECT_EQ(simulate_particles(s).size(), 300u);
  EXPECT_NEAR(peak_particle_estimate(fountain(1000, {5, 1}, 3)), 3000, 1e-9);
}

TEST(ParticleSystem, DiscEmitterStaysOnItsDisc) {
  ParticleSettings s = fountain(500, {1, 0}, 0.5);
  s.emitters[0].shape = Emitter::Shape::disc;
  s.emitters[0].center = {0, 1, 0};
  s.emitters[0].radius = 2;
  s.emitters[0].speed = {0, 0};
  const auto particles = simulate_particles(s);
  ASSERT_EQ(particles.size(), 250u);
  double mean_r2 = 0;
  for (const Particle& p : particles) {
    EXPECT_NEAR(p.position.y, 1, 1e-12);
    EXPECT_LE(std::hypot(p.position.x, p.position.z), 2 + 1e-12);
    mean_r2 += p.position.x * p.position.x + p.position.z * p.position.z;
  }
  // Uniform over the area: E[r^2] = R^2 / 2 = 2.
  EXPECT_NEAR(mean_r2 / 250, 2, 0.2);
}

}  // namespace
}  // namespace snell::procedural
