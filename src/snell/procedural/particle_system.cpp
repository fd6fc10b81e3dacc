#include "snell/procedural/particle_system.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/constants.hpp"
#include "snell/texture/povray_noise.hpp"

namespace snell::procedural {

namespace {

/// Streams of the per-particle generators: regular emission and bursts never share a sequence.
constexpr uint64_t kRateStream = 1, kBurstStream = 2;

/// A direction in the cone of half-angle `degrees` around unit `axis`, uniform over its solid angle.
math::Vec3 cone_direction(const math::Vec3& axis, double degrees, math::Pcg32& rng) {
  const double cos_max = std::cos(std::clamp(degrees, 0.0, 180.0) * math::kDegreesToRadians);
  const double cos_theta = 1 - rng.next_double() * (1 - cos_max);
  const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  const double phi = math::kTwoPi * rng.next_double();
  math::Vec3 t, b;
  math::orthonormal_basis(axis, t, b);
  return axis * cos_theta + (t * std::cos(phi) + b * std::sin(phi)) * sin_theta;
}

/// A new particle of `emitter`; nullopt when a surface emitter found no surface.
std::optional<Particle> spawn(const Emitter& emitter, int emitter_index, long long index, math::Pcg32& rng) {
  Particle p;
  p.emitter = emitter_index;
  p.index = index;
  math::Vec3 axis = emitter.direction;
  switch (emitter.shape) {
    case Emitter::Shape::point:
      p.position = emitter.center;
      break;
    case Emitter::Shape::disc: {
      math::Vec3 t, b;
      math::orthonormal_basis(emitter.normal, t, b);
      const double r = emitter.radius * std::sqrt(rng.next_double());  // uniform over the disc's area
      const double phi = math::kTwoPi * rng.next_double();
      p.position = emitter.center + (t * std::cos(phi) + b * std::sin(phi)) * r;
      break;
    }
    case Emitter::Shape::box:
      p.position = emitter.box.lo +
                   math::Vec3(rng.next_double(), rng.next_double(), rng.next_double()) * emitter.box.extent();
      break;
    case Emitter::Shape::surface: {
      const auto hit = emitter.surface.sample_surface(rng);
      if (!hit) return std::nullopt;
      p.position = hit->point;
      if (emitter.along_normal) axis = hit->normal;
      break;
    }
  }
  p.lifetime = std::max(0.0, emitter.lifetime.sample(rng));
  p.size = std::max(0.0, emitter.size.sample(rng));
  p.velocity =
      cone_direction(axis, emitter.spread_degrees, rng) * emitter.speed.sample(rng) + emitter.velocity;
  return p;
}

/// The acceleration that does not depend on velocity, at a point and time.
math::Vec3 field_acceleration(const Forces& forces, const math::Vec3& p, double time) {
  math::Vec3 a = forces.gravity;
  for (const Vortex& v : forces.vortices) {
    const math::Vec3 d = p - v.center;
    const math::Vec3 radial = d - v.axis * dot(d, v.axis);
    a += cross(v.axis, radial) * (v.strength / (length_squared(radial) + v.core * v.core));
  }
  if (forces.turbulence != 0) {
    const math::Vec3 q = p / forces.turbulence_scale + math::Vec3(0.31, 0.17, 0.23) * time;
    a += texture::povray_dnoise(q) * forces.turbulence;
  }
  return a;
}

/// Moves a particle by `h` seconds under the forces, the acceleration held at its value at the start.
/// With linear drag k the motion under constant acceleration a is solved exactly:
/// v(h) = c + (v0 - c) e^(-kh), x(h) = x0 + c h + (v0 - c)(1 - e^(-kh))/k with c = wind + a/k;
/// without drag it is the parabola x0 + v0 h + a h^2 / 2. Both are exact for gravity alone.
void advance(Particle& particle, const Forces& forces, double h, double time) {
  const math::Vec3 a = field_acceleration(forces, particle.position, time);
  if (forces.drag > 0) {
    const double k = forces.drag;
    const math::Vec3 c = forces.wind + a / k;
    const double e = std::exp(-k * h);
    particle.position += c * h + (particle.velocity - c) * ((1 - e) / k);
    particle.velocity = c + (particle.velocity - c) * e;
  } else {
    particle.position += particle.velocity * h + a * (0.5 * h * h);
    particle.velocity += a * h;
  }
  particle.age += h;
}

bool is_dead(const Particle& p, const ParticleSettings& settings) {
  if (p.age >= p.lifetime) return true;
  if (settings.bounds && !settings.bounds->contains(p.position)) return true;
  return settings.dies && settings.dies(p);
}

void remember(Particle& p, int trail_steps) {
  if (trail_steps <= 0) return;
  p.trail.push_back(p.position);
  if (static_cast<int>(p.trail.size()) > trail_steps) p.trail.erase(p.trail.begin());
}

}  // namespace

std::vector<Particle> simulate_particles(const ParticleSettings& settings) {
  std::vector<Particle> alive;
  const double end_time = settings.time;
  if (!(end_time > 0) || !(settings.step > 0)) return alive;
  const auto steps = static_cast<long long>(std::ceil(end_time / settings.step - 1e-9));
  std::vector<long long> next_index(settings.emitters.size(), 0);
  std::vector<Particle> born;
  for (long long i = 0; i < steps; ++i) {
    const double t0 = static_cast<double>(i) * settings.step;
    const double t1 = i + 1 == steps ? end_time : std::min(end_time, t0 + settings.step);
    for (Particle& p : alive) advance(p, settings.forces, t1 - t0, t0);
    // New particles of this step, each moved from its own birth time to t1.
    born.clear();
    const auto emit = [&](int e, long long index, uint64_t stream, double birth) {
      if (static_cast<long long>(alive.size() + born.size()) >= settings.max_particles) return;
      math::Pcg32 rng(
          math::mix_seed(settings.seed, static_cast<uint64_t>(e), stream, static_cast<uint64_t>(index)));
      auto p = spawn(settings.emitters[static_cast<size_t>(e)], e, index, rng);
      if (!p) return;
      remember(*p, settings.trail_steps);
      advance(*p, settings.forces, t1 - birth, birth);
      born.push_back(std::move(*p));
    };
    for (size_t e = 0; e < settings.emitters.size(); ++e) {
      const Emitter& emitter = settings.emitters[e];
      const int id = static_cast<int>(e);
      if (emitter.burst > 0 && emitter.burst_time >= t0 && emitter.burst_time < t1)
        for (long long k = 0; k < emitter.burst; ++k) emit(id, k, kBurstStream, emitter.burst_time);
      if (emitter.rate > 0) {
        // The k-th particle is born at start + (k + 1/2) / rate: evenly, so `rate` per second exactly.
        for (long long& k = next_index[e];; ++k) {
          const double birth = emitter.start + (static_cast<double>(k) + 0.5) / emitter.rate;
          if (birth >= t1 || birth >= emitter.end) break;
          if (birth >= t0) emit(id, k, kRateStream, birth);
        }
      }
    }
    alive.insert(alive.end(), std::make_move_iterator(born.begin()), std::make_move_iterator(born.end()));
    std::erase_if(alive, [&](const Particle& p) { return is_dead(p, settings); });
    for (Particle& p : alive) remember(p, settings.trail_steps);
  }
  std::stable_sort(alive.begin(), alive.end(), [](const Particle& a, const Particle& b) {
    return a.emitter != b.emitter ? a.emitter < b.emitter : a.index < b.index;
  });
  return alive;
}

double peak_particle_estimate(const ParticleSettings& settings) {
  double total = 0;
  for (const Emitter& e : settings.emitters) {
    const double longest = std::max(0.0, e.lifetime.mean + std::fabs(e.lifetime.variance));
    const double window = std::max(0.0, std::min(e.end, settings.time) - e.start);
    total += e.rate * std::min(longest, window) + static_cast<double>(std::max(0LL, e.burst));
  }
  return total;
}

double total_particle_estimate(const ParticleSettings& settings) {
  double total = 0;
  for (const Emitter& e : settings.emitters) {
    const double window = std::max(0.0, std::min(e.end, settings.time) - e.start);
    total += e.rate * window + static_cast<double>(std::max(0LL, e.burst));
  }
  return total;
}

}  // namespace snell::procedural
