#include "snell/procedural/flock.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/constants.hpp"
#include "snell/math/pcg32.hpp"

namespace snell::procedural {

namespace {

math::Vec3 limit_length(const math::Vec3& v, double most) {
  const double l = length(v);
  return l > most && l > 0 ? v * (most / l) : v;
}

/// Reynolds' steering: the change that turns `velocity` into flying at full speed towards `direction`.
math::Vec3 steer_towards(const math::Vec3& direction, const math::Vec3& velocity, const FlockSettings& s) {
  const double l = length(direction);
  if (!(l > 0)) return math::Vec3(0);
  return limit_length(direction * (s.max_speed / l) - velocity, s.max_force);
}

math::Vec3 steering(const std::vector<Boid>& boids, size_t self, const FlockSettings& s) {
  const Boid& me = boids[self];
  const double speed = length(me.velocity);
  const math::Vec3 heading = speed > 0 ? me.velocity / speed : math::Vec3(0, 0, 1);
  const double cos_half_view = std::cos(0.5 * s.field_of_view_degrees * math::kDegreesToRadians);
  math::Vec3 away(0), velocity_sum(0), centre_sum(0);
  int seen = 0;
  for (size_t j = 0; j < boids.size(); ++j) {
    if (j == self) continue;
    const math::Vec3 d = boids[j].position - me.position;
    const double dist = length(d);
    if (dist >= s.neighbour_radius) continue;
    // Separation does not look: a boid feels a flockmate too close behind it as well.
    if (dist < s.separation_distance) away -= dist > 0 ? d / (dist * dist) : heading;
    if (s.field_of_view_degrees < 360 && dist > 0 && dot(d / dist, heading) < cos_half_view) continue;
    velocity_sum += boids[j].velocity;
    centre_sum += boids[j].position;
    ++seen;
  }
  math::Vec3 force = steer_towards(away, me.velocity, s) * s.separation_weight;
  if (seen > 0) {
    force += steer_towards(velocity_sum / seen, me.velocity, s) * s.alignment_weight;
    force += steer_towards(centre_sum / seen - me.position, me.velocity, s) * s.cohesion_weight;
  }
  if (!s.obstacles.empty() && speed > 0) {
    if (const auto hit = s.obstacles.nearest(me.position, heading, s.avoid_distance)) {
      // Turn along the surface and off it (its normal taken on the boid's side), harder the closer it is.
      const double urgency = 1 - hit->distance / s.avoid_distance;
      const math::Vec3 off = dot(hit->normal, heading) > 0 ? -hit->normal : hit->normal;
      const math::Vec3 slide = heading - off * dot(heading, off);
      force +=
          steer_towards(slide + off * (2 * urgency), me.velocity, s) * (s.avoid_weight * (0.5 + urgency));
    }
  }
  if (s.bounds && !s.bounds->contains(me.position))
    force += steer_towards(s.bounds->center() - me.position, me.velocity, s) * s.bounds_weight;
  return force;
}

}  // namespace

std::vector<Boid> initial_flock(const FlockSettings& s) {
  math::Pcg32 rng(math::mix_seed(s.seed, 0xb01d));
  std::vector<Boid> boids;
  const math::Vec3 extent = s.start.extent();
  for (int i = 0; i < s.count; ++i) {
    math::Vec3 p;
    // Dart throwing: a few tries for a spot clear of the others, else the last try.
    for (int attempt = 0; attempt < 50; ++attempt) {
      p = s.start.lo + math::Vec3(rng.next_double(), rng.next_double(), rng.next_double()) * extent;
      const bool clear = std::none_of(boids.begin(), boids.end(), [&](const Boid& b) {
        return length(b.position - p) < s.separation_distance;
      });
      if (clear) break;
    }
    boids.push_back({p, uniform_sphere_direction(rng) * s.start_speed});
  }
  return boids;
}

void step_flock(std::vector<Boid>& boids, const FlockSettings& s, double dt) {
  std::vector<math::Vec3> forces(boids.size());
  for (size_t i = 0; i < boids.size(); ++i) forces[i] = limit_length(steering(boids, i, s), s.max_force);
  for (size_t i = 0; i < boids.size(); ++i) {
    Boid& b = boids[i];
    b.velocity = limit_length(b.velocity + forces[i] * dt, s.max_speed);
    const double speed = length(b.velocity);
    if (speed < s.min_speed)
      b.velocity = speed > 0 ? b.velocity * (s.min_speed / speed) : math::Vec3(0, 0, s.min_speed);
    b.position += b.velocity * dt;
  }
}

std::vector<Boid> simulate_flock(const FlockSettings& s) {
  std::vector<Boid> boids = initial_flock(s);
  if (!(s.time > 0) || !(s.step > 0)) return boids;
  const auto steps = static_cast<long long>(std::ceil(s.time / s.step - 1e-9));
  for (long long i = 0; i < steps; ++i) {
    const double t0 = static_cast<double>(i) * s.step;
    const double t1 = i + 1 == steps ? s.time : std::min(s.time, t0 + s.step);
    step_flock(boids, s, t1 - t0);
  }
  return boids;
}

}  // namespace snell::procedural
