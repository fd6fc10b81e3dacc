// Boids (Reynolds 1987): separation keeps flockmates apart, alignment makes them fly together, and the
// flock is a pure function of its seed.
#include "snell/procedural/flock.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace snell::procedural {
namespace {

double minimum_pair_distance(const std::vector<Boid>& boids) {
  double least = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < boids.size(); ++i)
    for (size_t j = i + 1; j < boids.size(); ++j)
      least = std::min(least, length(boids[i].position - boids[j].position));
  return least;
}

FlockSettings crowded() {
  FlockSettings s;
  s.count = 40;
  s.seed = 3;
  s.start = math::Bounds3(math::Vec3(-2), math::Vec3(2));
  s.separation_distance = 0.8;
  s.separation_weight = 3;
  s.cohesion_weight = 1;
  s.alignment_weight = 1;
  s.neighbour_radius = 3;
  s.max_speed = 2;
  s.min_speed = 0.5;
  s.max_force = 8;
  s.time = 10;
  return s;
}

/// The smallest distance between two boids over `steps` steps from the start.
double closest_approach(const FlockSettings& s, int steps) {
  std::vector<Boid> boids = initial_flock(s);
  double least = minimum_pair_distance(boids);
  for (int i = 0; i < steps; ++i) {
    step_flock(boids, s, s.step);
    least = std::min(least, minimum_pair_distance(boids));
  }
  return least;
}

TEST(Flock, KeepsItsSeparationDistance) {
  // Cohesion pulls the 40 boids together for 300 steps; separation must keep every pair at least half the
  // separation distance apart at every step.
  const FlockSettings s = crowded();
  EXPECT_GE(closest_approach(s, 300), 0.5 * s.separation_distance);
}

TEST(Flock, WithoutSeparationTheyCrowd) {
  // The same flock with separation off gets much closer: the previous test is about the rule.
  FlockSettings s = crowded();
  s.separation_weight = 0;
  EXPECT_LT(closest_approach(s, 300), 0.5 * s.separation_distance);
}

TEST(Flock, AlignmentMakesThemFlyTogether) {
  // The polarisation |sum v| / sum |v| starts near 0 for random headings and nears 1 as they align.
  FlockSettings s = crowded();
  s.cohesion_weight = 0;
  s.separation_weight = 0;
  s.neighbour_radius = 100;
  s.field_of_view_degrees = 360;
  const auto polarisation = [](const std::vector<Boid>& boids) {
    math::Vec3 sum(0);
    double speeds = 0;
    for (const Boid& b : boids) {
      sum += b.velocity;
      speeds += length(b.velocity);
    }
    return length(sum) / speeds;
  };
  EXPECT_LT(polarisation(initial_flock(s)), 0.4);
  s.time = 5;
  EXPECT_GT(polarisation(simulate_flock(s)), 0.95);
}

TEST(Flock, SameSeedSameFlock) {
  FlockSettings s = crowded();
  s.time = 3;
  const auto a = simulate_flock(s), b = simulate_flock(s);
  ASSERT_EQ(a.size(), 40u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].position, b[i].position);
    EXPECT_EQ(a[i].velocity, b[i].velocity);
  }
  s.seed = 4;
  EXPECT_NE(simulate_flock(s)[0].position, a[0].position);
}

TEST(Flock, SpeedStaysWithinLimits) {
  const FlockSettings s = crowded();
  for (const Boid& b : simulate_flock(s)) {
    EXPECT_LE(length(b.velocity), s.max_speed + 1e-9);
    EXPECT_GE(length(b.velocity), s.min_speed - 1e-9);
  }
}

}  // namespace
}  // namespace snell::procedural
