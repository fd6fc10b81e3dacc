#pragma once
// Boids after Reynolds 1987 ("Flocks, Herds, and Schools: A Distributed Behavioral Model", SIGGRAPH) with
// the steering formulation of Reynolds 1999 ("Steering Behaviors For Autonomous Characters"): each boid
// sees the flockmates within a radius and field of view and steers (desired velocity - velocity, limited
// to a maximum force) for separation, alignment and cohesion, and away from obstacles ahead of it.
//
// Like the particle systems it is a pure function of its settings: simulated from t = 0 on a fixed step
// grid up to `time`, the starting state drawn from `seed`.
#include <cstdint>
#include <optional>
#include <vector>

#include "snell/math/bounds.hpp"
#include "snell/procedural/object_probe.hpp"

namespace snell::procedural {

struct Boid {
  math::Vec3 position, velocity;
};

struct FlockSettings {
  int count = 20;
  uint64_t seed = 0;
  double time = 0;
  double step = 1.0 / 30.0;
  /// Boids start at random points of this box (at least `separation_distance` apart where the box has
  /// room), flying in random directions at `start_speed`.
  math::Bounds3 start{math::Vec3(-1), math::Vec3(1)};
  double start_speed = 1;

  double separation_distance = 0.5;
  double separation_weight = 1.5;
  double alignment_weight = 1;
  double cohesion_weight = 1;
  /// Flockmates farther than this, or outside the field of view (full angle, degrees, centred on the
  /// velocity), are not seen.
  double neighbour_radius = 2;
  double field_of_view_degrees = 270;
  double max_speed = 2;
  double min_speed = 0;
  double max_force = 4;

  /// Obstacles: each boid looks `avoid_distance` ahead along its velocity and steers away from what it sees.
  ObjectProbe obstacles;
  double avoid_distance = 2;
  double avoid_weight = 3;
  /// Boids outside this box steer back towards its centre.
  std::optional<math::Bounds3> bounds;
  double bounds_weight = 1;
};

/// The flock at `settings.time`.
std::vector<Boid> simulate_flock(const FlockSettings& settings);

/// One step of `dt` seconds for every boid (exposed for tests).
void step_flock(std::vector<Boid>& boids, const FlockSettings& settings, double dt);

/// The starting flock drawn from the seed.
std::vector<Boid> initial_flock(const FlockSettings& settings);

}  // namespace snell::procedural
