#include "snell/render/photons/shooting.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "snell/math/constants.hpp"
#include "snell/math/pcg32.hpp"
#include "snell/memory/budget.hpp"
#include "snell/render/light_ray.hpp"
#include "snell/render/photons/photon_path.hpp"

namespace snell::render::photons {

using math::Color;
using math::Vec3;

namespace {

constexpr double kEpsilon = 1e-10;
constexpr double kPi = 3.14159265358979323846;
/// More photons than any map could hold (the kd-tree indexes them with 32 bits).
constexpr double kMostPhotons = 1e9;

/// A target object: all scene objects sharing one PhotonTarget (the parts of a target union).
struct Target {
  const scene::PhotonTarget* id;
  const scene::ObjectPhotons* settings;
  math::Bounds3 bounds;
};

std::vector<Target> collect_targets(const scene::Scene& scene) {
  std::vector<Target> targets;
  for (const auto& object : scene.objects) {
    const scene::ObjectPhotons& p = object->flags.photons;
    if (!p.target) continue;
    auto found =
        std::find_if(targets.begin(), targets.end(), [&](const Target& t) { return t.id == p.target.get(); });
    if (found == targets.end())
      targets.push_back(Target{p.target.get(), &p, object->world_bounds()});
    else
      found->bounds.unite(object->world_bounds());
  }
  return targets;
}

bool is_parallel(const scene::Light& light) {
  return light.kind == scene::Light::Kind::parallel || light.kind == scene::Light::Kind::cylinder;
}

/// Whether a light shoots at a target at all: reflection or refraction switched on by one of them and off
/// by neither (POV-Ray, LightTargetCombo::computeMergedFlags).
bool combo_active(const scene::LightPhotons& light, const scene::ObjectPhotons& target) {
  const auto merged = [](scene::PhotonSwitch a, scene::PhotonSwitch b) {
    return (a == scene::PhotonSwitch::on || b == scene::PhotonSwitch::on) && a != scene::PhotonSwitch::off &&
           b != scene::PhotonSwitch::off;
  };
  return merged(light.refraction, target.refraction) || merged(light.reflection, target.reflection);
}

/// The rings of photon directions from one light at one target.
struct Combo {
  const scene::Light* light;
  const Target* target;
  size_t light_index, target_index;
  bool parallel;
  Vec3 centre;
  /// Unit direction to the centre and two unit vectors across it.
  Vec3 axis, across1, across2;
  double distance;
  /// Angular spacing (spatial for parallel lights, where "angles" are radii) and the largest angle.
  double spread, dtheta, max_theta;

  int ring_count() const { return dtheta > 0 ? static_cast<int>(std::ceil(max_theta / dtheta)) : 0; }
  double dphi(double theta) const {
    if (theta < kEpsilon) return 2 * kPi;
    return parallel ? dtheta / theta : dtheta / std::sin(theta);
  }
};

Combo make_combo(const scene::Light& light, const Target& target, double spacing) {
  Combo c{};
  c.light = &light;
  c.target = &target;
  c.parallel = is_parallel(light);
  c.centre = target.bounds.center();
  const double radius = 0.5 * length(target.bounds.extent());
  if (c.parallel) {
    const Vec3 beam = light.point_at - light.position;
    c.axis = length_squared(beam) > 0 ? normalize(beam) : Vec3(0, -1, 0);
    c.distance = dot(c.centre - light.position, c.axis);
  } else {
    const Vec3 to_centre = c.centre - light.position;
    c.distance = length(to_centre);
    c.axis = c.distance > kEpsilon ? to_centre / c.distance : Vec3(0, 0, 1);
  }
  const Vec3 helper = std::fabs(c.axis.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  c.across1 = normalize(cross(c.axis, helper));
  c.across2 = cross(c.axis, c.across1);
  c.spread = spacing * target.id->spacing_multiplier;
  if (c.parallel) {
    c.dtheta = c.spread;
    c.max_theta = radius;
  } else {
    // Inside the bounding sphere photons go every way; spacing then counts at the sphere's radius.
    const double reach = std::max(c.distance, radius);
    c.spread /= reach;
    c.dtheta = std::atan(c.spread);
    c.max_theta = c.distance >= radius ? std::asin(radius / c.distance) : kPi;
  }
  return c;
}

/// Photons one combo shoots, about: its rings cover angles up to half a ring past the largest, in cells of
/// dtheta^2 (solid angle for a point light, area for a parallel one).
double estimated_photons(const Combo& c) {
  const double reach = c.max_theta + 0.5 * c.dtheta;
  const double cells = c.parallel ? kPi * reach * reach : 2 * kPi * (1 - std::cos(std::min(reach, kPi)));
  return cells / (c.dtheta * c.dtheta);
}

struct Ring {
  std::vector<Photon> photons;
  uint64_t shot = 0;
  bool hit_target = false;
};

Ring shoot_ring(const Combo& c, int ring, const scene::PhotonSettings& settings,
                const PhotonPathLimits& limits, const accel::Accelerator& accel,
                const InteriorStack& inside) {
  Ring out;
  math::Pcg32 rng(
      0x9e3779b97f4a7c15ULL ^ (c.light_index * 0x100000001b3ULL + c.target_index * 0x2545f4914f6cdd1dULL),
      static_cast<uint64_t>(ring) * 2 + 1);
  PhotonPath path(accel, *c.light, limits, c.spread, c.target->id);
  scene::Light unfaded = *c.light;
  unfaded.fade_power = 0;  // fade counts over the whole path, when the photon is stored
  const double theta = ring * c.dtheta;
  const double dphi = c.dphi(theta);
  const double min_phi = -kPi + dphi * rng.next_double() * 0.5;
  const double max_phi = kPi - dphi / 2 + (min_phi + kPi);
  for (double phi = min_phi; phi < max_phi; phi += dphi) {
    const double jphi = phi + dphi * (rng.next_double() - 0.5) * settings.jitter;
    const double jtheta = theta + c.dtheta * (rng.next_double() - 0.5) * settings.jitter;
    const Vec3 around = std::cos(jphi) * c.across1 + std::sin(jphi) * c.across2;
    math::Ray ray;
    if (c.parallel) {
      ray.origin = c.centre - c.distance * c.axis + jtheta * around;
      ray.direction = c.axis;
    } else {
      ray.origin = c.light->position;
      ray.direction = normalize(std::cos(jtheta) * c.axis + std::sin(jtheta) * around);
    }
    const double attenuation =
        light_attenuation(unfaded, ray.origin + ray.direction, LightRay{-ray.direction, 1.0, Color(0)});
    ++out.shot;
    if (attenuation < 1e-5) continue;
    path.shoot(ray, c.light->color * attenuation, inside, out.photons);
  }
  out.hit_target = path.hit_target();
  return out;
}

InteriorStack objects_around(const scene::Scene& scene, const Vec3& point) {
  InteriorStack inside;
  for (const auto& object : scene.objects)
    if (object->interior && object->inside(point)) inside.push(object.get());
  return inside;
}

}  // namespace

ShootingResult shoot_caustic_photons(const scene::Scene& scene, const accel::Accelerator& accel) {
  const auto start = std::chrono::steady_clock::now();
  const scene::PhotonSettings& settings = *scene.settings.photons;
  ShootingResult result;
  result.spacing = settings.spacing;
  const std::vector<Target> targets = collect_targets(scene);
  PhotonPathLimits limits;
  limits.max_trace_level =
      settings.max_trace_level >= 0 ? settings.max_trace_level : scene.settings.max_trace_level;
  limits.adc_bailout = settings.adc_bailout >= 0 ? settings.adc_bailout : scene.settings.adc_bailout;

  const auto combos_at = [&](double spacing) {
    std::vector<Combo> combos;
    for (size_t li = 0; li < scene.lights.size(); ++li) {
      // A shadowless light is POV-Ray's fill light, which shoots no photons (photonstrategytask.cpp,
      // PhotonStrategyTask::Run skips FILL_LIGHT_SOURCE).
      if (scene.lights[li].shadowless) continue;
      for (size_t ti = 0; ti < targets.size(); ++ti) {
        if (!combo_active(scene.lights[li].photons, *targets[ti].settings)) continue;
        if (!targets[ti].bounds.is_finite()) continue;  // an infinite target has no bounding sphere
        Combo c = make_combo(scene.lights[li], targets[ti], spacing);
        c.light_index = li;
        c.target_index = ti;
        if (c.dtheta > 0) combos.push_back(c);
      }
    }
    return combos;
  };
  std::vector<Combo> combos = combos_at(settings.spacing);
  if (settings.count > 0 && !combos.empty()) {
    // `count`: photons go as the inverse square of the spacing (POV-Ray photonestimationtask.cpp).
    double estimate = 0;
    for (const Combo& c : combos) estimate += estimated_photons(c);
    if (estimate > 0) {
      result.spacing = settings.spacing * std::sqrt(estimate / settings.count);
      combos = combos_at(result.spacing);
    }
  }

  // Charge at least a photon per direction before shooting, so that a spacing far too fine for the memory
  // budget fails here rather than while the photons pile up.
  double planned = 0;
  for (const Combo& c : combos) planned += estimated_photons(c);
  if (!(planned < kMostPhotons))
    throw memory::BudgetExceeded("photons: the spacing would shoot about " + std::to_string(planned) +
                                 " photons; use a larger spacing or a smaller count");
  const memory::Charge planned_charge(scene.memory_budget, static_cast<uint64_t>(planned) * sizeof(Photon),
                                      "photon map");

  for (const Combo& c : combos) {
    const InteriorStack inside = c.parallel ? InteriorStack{} : objects_around(scene, c.light->position);
    const int rings = c.ring_count();
    std::vector<Ring> done(static_cast<size_t>(rings));
    tbb::parallel_for(0, rings, [&](int ring) {
      done[static_cast<size_t>(ring)] = shoot_ring(c, ring, settings, limits, accel, inside);
    });
    // Autostop: past `autostop` of the angle, the first ring that misses the target (after one that hit)
    // ends the shooting; decided in ring order, so in the same place for any thread count.
    bool hit_once = false;
    for (int ring = 0; ring < rings; ++ring) {
      Ring& r = done[static_cast<size_t>(ring)];
      result.shot += r.shot;
      result.photons.insert(result.photons.end(), r.photons.begin(), r.photons.end());
      hit_once = hit_once || r.hit_target;
      if (hit_once && !r.hit_target && ring * c.dtheta > settings.autostop * c.max_theta) break;
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace snell::render::photons
