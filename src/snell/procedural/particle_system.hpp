#pragma once
// Particle systems after Reeves 1983 ("Particle Systems - A Technique for Modeling a Class of Fuzzy
// Objects", SIGGRAPH): emitters create particles whose initial attributes are a mean plus a random
// variance, forces move them, and they die by age, by leaving a region or by fading out.
//
// The simulation is a pure function of its settings and the time: it always runs from t = 0 on the same
// fixed step grid (0, step, 2 step, ..., with one shorter last step to reach `time`), and every particle's
// random attributes come from a generator seeded by (seed, emitter, particle index). So a frame gives the
// same particles whether an animation is rendered from its first frame or that frame alone.
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "snell/math/bounds.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/procedural/object_probe.hpp"

namespace snell::procedural {

/// Reeves' "mean +/- variance": a value drawn uniformly from [mean - variance, mean + variance].
struct Spread {
  double mean = 0;
  double variance = 0;
  double sample(math::Pcg32& rng) const { return mean + variance * (2 * rng.next_double() - 1); }
};

struct Emitter {
  enum class Shape { point, disc, box, surface };
  Shape shape = Shape::point;
  /// point: the point; disc: its centre.
  math::Vec3 center;
  /// disc: the normal and radius.
  math::Vec3 normal{0, 1, 0};
  double radius = 1;
  /// box: opposite corners.
  math::Bounds3 box{math::Vec3(0), math::Vec3(0)};
  /// surface: the objects whose surface emits.
  ObjectProbe surface;

  /// Particles per second while the emitter runs, emitted evenly in time (Reeves' mean rate).
  double rate = 0;
  /// Particles emitted at once at `burst_time` (an explosion).
  long long burst = 0;
  double burst_time = 0;
  /// The emitter runs in [start, end).
  double start = 0;
  double end = std::numeric_limits<double>::infinity();

  Spread lifetime{1, 0};
  Spread speed{1, 0};
  Spread size{0.1, 0};
  /// Initial direction (unit) and the half-angle in degrees of the cone around it that directions fill
  /// uniformly; 180 sends particles everywhere. A surface emitter with `along_normal` uses the surface
  /// normal at each particle's birthplace as the axis instead.
  math::Vec3 direction{0, 1, 0};
  double spread_degrees = 0;
  bool along_normal = false;
  /// Added to every particle's initial velocity (e.g. a moving rocket).
  math::Vec3 velocity{0};
};

/// A line vortex around `axis` through `center`: tangential acceleration strength / (d^2 + core^2) * d at
/// distance d (the Biot-Savart field of a line vortex, its singularity smoothed by a core radius).
struct Vortex {
  math::Vec3 center;
  math::Vec3 axis{0, 1, 0};
  double strength = 1;
  double core = 0.5;
};

struct Forces {
  math::Vec3 gravity{0};
  /// The air's velocity; drag pulls each particle's velocity towards it: dv/dt = -drag (v - wind).
  math::Vec3 wind{0};
  double drag = 0;
  std::vector<Vortex> vortices;
  /// Acceleration of this size in a direction from gradient noise (POV-Ray's DNoise) at position/scale,
  /// drifting with time: a smooth, repeatable gusty field.
  double turbulence = 0;
  double turbulence_scale = 1;
};

struct Particle {
  math::Vec3 position, velocity;
  double age = 0;
  double lifetime = 1;
  double size = 0.1;
  int emitter = 0;
  /// Index of the particle within its emitter's sequence: with `emitter`, its identity.
  long long index = 0;
  /// Earlier positions, oldest first, one per step (kept only when ParticleSettings::trail_steps > 0).
  std::vector<math::Vec3> trail;

  double age_fraction() const { return lifetime > 0 ? age / lifetime : 1; }
};

struct ParticleSettings {
  std::vector<Emitter> emitters;
  Forces forces;
  /// The time to simulate up to (the frame's `clock`), and the fixed step.
  double time = 0;
  double step = 1.0 / 60.0;
  uint64_t seed = 0;
  /// Particles leaving this box die.
  std::optional<math::Bounds3> bounds;
  /// Extra death rule (fading out): a particle for which it answers true dies.
  std::function<bool(const Particle&)> dies;
  /// How many earlier positions each particle keeps (for streaks).
  int trail_steps = 0;
  /// No more particles than this are ever alive; emissions beyond it are dropped.
  long long max_particles = 100000;
};

/// The particles alive at `settings.time`, ordered by emitter, then emission.
std::vector<Particle> simulate_particles(const ParticleSettings& settings);

/// An upper bound on the particles alive at once (rates times the longest lifetime plus bursts), for
/// refusing a system that would exceed a limit before simulating it.
double peak_particle_estimate(const ParticleSettings& settings);

/// The particles born from t = 0 to `settings.time`: the simulation's work.
double total_particle_estimate(const ParticleSettings& settings);

}  // namespace snell::procedural
