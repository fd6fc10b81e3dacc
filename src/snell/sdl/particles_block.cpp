// `particle_system { }`: a snell extension (docs/procedural.md) that runs procedural/particle_system up to
// the frame's time and turns the particles into ordinary objects: spheres, one blob, an emissive medium
// or streaks. The generator knows nothing of the language; this file only reads the block and builds.
#include <algorithm>
#include <cmath>

#include "snell/material/interior.hpp"
#include "snell/procedural/particle_density.hpp"
#include "snell/procedural/particle_system.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"
#include "snell/texture/color_map.hpp"

namespace snell::sdl {

namespace {

/// Hard ceilings on what a scene may ask for, so a typo cannot exhaust memory or time.
constexpr double kMostParticles = 10'000'000;
constexpr double kMostSteps = 1'000'000;
constexpr double kMostBirths = 100'000'000;

enum class ParticleLook { spheres, blob, media, streaks };

/// How the particles become objects, and how they look over their age.
struct ParticleRendering {
  ParticleLook look = ParticleLook::spheres;
  double blob_threshold = 0.5;
  double blob_strength = 1;
  math::Color media_emission{1};
  math::Color media_absorption{0};
  int media_samples = 20;
  double streak_length = 0.25;  // seconds of trail behind each particle
  std::shared_ptr<const texture::ColorMap> color_map;
  std::shared_ptr<const texture::ColorMap> size_map;  // red channel: size factor over age

  material::Rgbft color(const procedural::Particle& p) const {
    return color_map ? color_map->at(std::clamp(p.age_fraction(), 0.0, 1.0))
                     : material::Rgbft{math::Color(1), 0, 0};
  }
  double radius(const procedural::Particle& p) const {
    const double factor = size_map ? size_map->at(std::clamp(p.age_fraction(), 0.0, 1.0)).rgb.r : 1;
    return p.size * std::max(0.0, factor);
  }
};

/// How much a particle still shows (Reeves: a particle dies when its intensity falls below a threshold).
double intensity(const material::Rgbft& c) {
  return std::max({c.rgb.r, c.rgb.g, c.rgb.b}) * std::clamp(1 - c.transmit, 0.0, 1.0);
}

ParsedObject solid_child(std::shared_ptr<const geometry::Shape> shape, const material::Texture& base,
                         const std::optional<material::Rgbft>& color, const scene::SourceLocation& where) {
  ParsedObject child;
  child.where = where;
  child.shape = std::move(shape);
  if (color) {
    auto texture = std::make_shared<material::Texture>(base);
    texture->pigment = std::make_shared<material::SolidPigment>(*color);
    texture->selector = nullptr;
    texture->below = nullptr;
    child.texture = std::move(texture);
  }
  return child;
}

/// Cone pieces along the particle's trail, more transparent towards the tail: a streak that fades.
void add_streak(const procedural::Particle& p, const ParticleRendering& look, const material::Texture& base,
                const scene::SourceLocation& where, std::vector<ParsedObject>& out) {
  std::vector<math::Vec3> points;
  constexpr size_t kMostPieces = 6;
  const size_t n = p.trail.size();
  const size_t stride = std::max<size_t>(1, (n + kMostPieces - 1) / kMostPieces);
  for (size_t i = 0; i < n; i += stride) points.push_back(p.trail[i]);
  points.push_back(p.position);
  const double radius = look.radius(p);
  const material::Rgbft color = look.color(p);
  if (!(radius > 0)) return;
  const size_t pieces = points.size() - 1;
  for (size_t i = 0; i < pieces; ++i) {
    if (length(points[i + 1] - points[i]) < 1e-6 * radius) continue;
    const double tail = static_cast<double>(i) / static_cast<double>(pieces);
    const double head = static_cast<double>(i + 1) / static_cast<double>(pieces);
    material::Rgbft piece = color;
    piece.transmit = 1 - (1 - color.transmit) * head;  // opaque at the head, clear at the tail
    out.push_back(solid_child(
        shapes::cone(points[i], radius * std::max(0.2, tail), points[i + 1], radius * head, false), base,
        piece, where));
  }
  if (pieces == 0) out.push_back(solid_child(shapes::sphere(p.position, radius), base, color, where));
}

/// A hollow box around the particles filled with a medium whose density is the particle cloud.
ParsedObject media_container(const std::vector<procedural::Particle>& particles,
                             const ParticleRendering& look, const scene::SourceLocation& where) {
  std::vector<procedural::DensityBlob> blobs;
  math::Bounds3 box;
  for (const procedural::Particle& p : particles) {
    const double r = look.radius(p);
    const material::Rgbft c = look.color(p);
    if (!(r > 0)) continue;
    blobs.push_back({p.position, r, c.rgb * std::clamp(1 - c.transmit, 0.0, 1.0)});
    box.unite(p.position - math::Vec3(r));
    box.unite(p.position + math::Vec3(r));
  }
  ParsedObject container;
  container.where = where;
  if (blobs.empty()) return container;  // an empty union: nothing to render yet
  material::Media media;
  media.emission = look.media_emission;
  media.absorption = look.media_absorption;
  media.min_samples = media.max_samples = look.media_samples;
  media.densities.push_back({std::make_shared<procedural::ParticleDensity>(std::move(blobs)), {}});
  auto interior = std::make_shared<material::Interior>();
  interior->media.push_back(std::move(media));
  container.shape = shapes::box(box.lo, box.hi);
  container.interior = std::move(interior);
  container.flags.hollow = true;
  auto clear = std::make_shared<material::Texture>(*material::Texture::default_texture());
  clear->pigment = std::make_shared<material::SolidPigment>(material::Rgbft{math::Color(1), 0, 1});
  clear->finish.ambient = math::Color(0);
  clear->finish.diffuse = 0;
  container.texture = std::move(clear);
  return container;
}

}  // namespace

std::pair<double, double> Parser::parse_mean_variance() {
  // `mean +/- variance`: the mean is read up to a `+` or `-` (so write a sum as `(a + b) +/- v`), then
  // a `+` followed by `/` starts the variance.
  const scene::SourceLocation where = peek().where;
  Numeric mean = parse_multiplicative();
  for (;;) {
    const Token& t = peek_after_value();
    if (!t.is_symbol("+") && !t.is_symbol("-")) break;
    const bool plus = t.is_symbol("+");
    raw_next();
    if (plus && peek().is_symbol("/")) {
      raw_next();
      expect("-", "+/-");
      if (mean.size != 1) fail(where, "expected a float before +/-");
      const double variance = parse_float();
      if (!(variance >= 0)) fail(where, "the variance after +/- must not be negative");
      return {mean.x(), variance};
    }
    const Numeric term = parse_multiplicative();
    mean.v[0] += plus ? term.x() : -term.x();
  }
  if (mean.size != 1) fail(where, "expected a float");
  return {mean.x(), 0};
}

void Parser::parse_particle_emitter(procedural::Emitter& e) {
  expect("{", "emitter");
  const auto spread = [&] {
    const auto [mean, variance] = parse_mean_variance();
    return procedural::Spread{mean, variance};
  };
  const auto positive = [&](const Token& t, double v) {
    if (!(v >= 0)) fail(t.where, t.text + " must not be negative");
    return v;
  };
  for (;;) {
    const Token t = next();
    if (t.is_symbol("}")) break;
    if (t.is_word("point")) {
      e.shape = procedural::Emitter::Shape::point;
      e.center = parse_vector();
    } else if (t.is_word("disc")) {
      e.shape = procedural::Emitter::Shape::disc;
      expect("{", "disc");
      e.center = parse_vector();
      accept(",");
      const math::Vec3 n = parse_vector();
      if (length_squared(n) == 0) fail(t.where, "the disc's normal has zero length");
      e.normal = normalize(n);
      accept(",");
      e.radius = positive(t, parse_float());
      expect("}", "disc");
    } else if (t.is_word("box")) {
      e.shape = procedural::Emitter::Shape::box;
      expect("{", "box");
      const math::Vec3 a = parse_vector();
      accept(",");
      e.box = math::Bounds3(a, parse_vector());
      expect("}", "box");
    } else if (t.is_word("surface")) {
      e.shape = procedural::Emitter::Shape::surface;
      e.surface = parse_probe_objects("surface");
      if (e.surface.empty() || !e.surface.bounds().is_finite())
        fail(t.where, "surface needs finite objects, e.g. surface { sphere { <0,0,0>, 1 } }");
    } else if (t.is_word("rate")) {
      e.rate = positive(t, parse_float());
    } else if (t.is_word("burst")) {
      const double count = parse_float();
      if (!(count >= 0 && count <= kMostParticles)) fail(t.where, "burst count must be from 0 to 10000000");
      e.burst = static_cast<long long>(count);
      if (!peek().is_word("at")) fail(peek().where, "expected 'at time' after burst's count");
      raw_next();
      e.burst_time = parse_float();
    } else if (t.is_word("start")) {
      e.start = parse_float();
    } else if (t.is_word("end")) {
      e.end = parse_float();
    } else if (t.is_word("lifetime")) {
      e.lifetime = spread();
    } else if (t.is_word("speed")) {
      e.speed = spread();
    } else if (t.is_word("size")) {
      e.size = spread();
    } else if (t.is_word("direction")) {
      const math::Vec3 d = parse_vector();
      if (length_squared(d) == 0) fail(t.where, "direction has zero length");
      e.direction = normalize(d);
    } else if (t.is_word("spread")) {
      e.spread_degrees = std::clamp(parse_float(), 0.0, 180.0);
    } else if (t.is_word("along_normal")) {
      e.along_normal = true;
    } else if (t.is_word("velocity")) {
      e.velocity = parse_vector();
    } else {
      fail(t.where, "unexpected '" + t.text + "' in emitter");
    }
  }
}

ParsedObject Parser::parse_particle_system(const Token& keyword) {
  expect("{", "particle_system");
  procedural::ParticleSettings settings;
  ParticleRendering look;
  std::optional<double> fade_threshold;
  for (;;) {
    const Token t = peek();
    if (t.is_word("emitter")) {
      raw_next();
      settings.emitters.emplace_back();
      parse_particle_emitter(settings.emitters.back());
    } else if (t.is_word("gravity")) {
      raw_next();
      settings.forces.gravity = parse_vector();
    } else if (t.is_word("wind")) {
      raw_next();
      settings.forces.wind = parse_vector();
    } else if (t.is_word("drag")) {
      raw_next();
      settings.forces.drag = parse_float();
      if (!(settings.forces.drag >= 0)) fail(t.where, "drag must not be negative");
    } else if (t.is_word("vortex")) {
      raw_next();
      expect("{", "vortex");
      procedural::Vortex v;
      v.center = parse_vector();
      accept(",");
      const math::Vec3 axis = parse_vector();
      if (length_squared(axis) == 0) fail(t.where, "the vortex axis has zero length");
      v.axis = normalize(axis);
      accept(",");
      v.strength = parse_float();
      if (peek().is_word("core")) {
        raw_next();
        v.core = parse_float();
        if (!(v.core > 0)) fail(t.where, "the vortex core must be positive");
      }
      expect("}", "vortex");
      settings.forces.vortices.push_back(v);
    } else if (t.is_word("turbulence")) {
      raw_next();
      settings.forces.turbulence = parse_float();
      if (peek().is_word("size")) {
        raw_next();
        settings.forces.turbulence_scale = parse_float();
        if (!(settings.forces.turbulence_scale > 0)) fail(t.where, "turbulence size must be positive");
      }
    } else if (t.is_word("bounds")) {
      raw_next();
      const math::Vec3 a = parse_vector();
      accept(",");
      settings.bounds = math::Bounds3(a, parse_vector());
    } else if (t.is_word("fade_out")) {
      raw_next();
      fade_threshold = parse_float();
    } else if (t.is_word("color_map") || t.is_word("colour_map")) {
      raw_next();
      look.color_map = parse_color_map();
    } else if (t.is_word("size_map")) {
      raw_next();
      look.size_map = parse_color_map();
    } else if (t.is_word("time")) {
      raw_next();
      settings.time = parse_float();
    } else if (t.is_word("step")) {
      raw_next();
      settings.step = parse_float();
      if (!(settings.step > 0)) fail(t.where, "step must be positive");
    } else if (t.is_word("seed")) {
      raw_next();
      settings.seed = static_cast<uint64_t>(static_cast<long long>(parse_float()));
    } else if (t.is_word("max_particles")) {
      raw_next();
      const double most = parse_float();
      if (!(most >= 1 && most <= kMostParticles)) fail(t.where, "max_particles must be from 1 to 10000000");
      settings.max_particles = static_cast<long long>(most);
    } else if (t.is_word("render")) {
      raw_next();
      expect("{", "render");
      const Token kind = next();
      if (kind.is_word("spheres")) {
        look.look = ParticleLook::spheres;
      } else if (kind.is_word("blob")) {
        look.look = ParticleLook::blob;
        for (;;) {
          if (peek().is_word("threshold")) {
            raw_next();
            look.blob_threshold = parse_float();
          } else if (peek().is_word("strength")) {
            raw_next();
            look.blob_strength = parse_float();
          } else {
            break;
          }
        }
      } else if (kind.is_word("media")) {
        look.look = ParticleLook::media;
        for (;;) {
          if (peek().is_word("emission")) {
            raw_next();
            look.media_emission = parse_color().rgb;
          } else if (peek().is_word("absorption")) {
            raw_next();
            look.media_absorption = parse_color().rgb;
          } else if (peek().is_word("samples")) {
            raw_next();
            look.media_samples = parse_int("media samples", 1, 1000);
          } else {
            break;
          }
        }
      } else if (kind.is_word("streaks")) {
        look.look = ParticleLook::streaks;
        if (peek().is_word("length")) {
          raw_next();
          look.streak_length = parse_float();
          if (!(look.streak_length > 0)) fail(kind.where, "streak length must be positive");
        }
      } else {
        fail(kind.where, "render takes spheres, blob, media or streaks, found '" + kind.text + "'");
      }
      expect("}", "render");
    } else {
      break;
    }
  }
  if (settings.emitters.empty()) fail(keyword.where, "particle_system needs at least one emitter { }");
  if (settings.time / settings.step > kMostSteps)
    fail(keyword.where, "time / step is more than 1000000 simulation steps; use a larger step");
  const double peak = procedural::peak_particle_estimate(settings);
  if (peak > static_cast<double>(settings.max_particles))
    fail(keyword.where, "this particle_system may hold " + std::to_string(static_cast<long long>(peak)) +
                            " particles at once, more than max_particles " +
                            std::to_string(settings.max_particles) +
                            "; lower the rates or raise max_particles");
  if (procedural::total_particle_estimate(settings) > kMostBirths)
    fail(keyword.where, "this particle_system would create more than 100000000 particles up to its time");
  if (fade_threshold)
    settings.dies = [look, threshold = *fade_threshold](const procedural::Particle& p) {
      return intensity(look.color(p)) < threshold;
    };
  if (look.look == ParticleLook::streaks)
    settings.trail_steps = static_cast<int>(std::ceil(look.streak_length / settings.step));

  ParsedObject o;
  o.where = keyword.where;
  parse_object_modifiers(o);  // texture, finish, transforms... up to the closing brace

  const std::vector<procedural::Particle> particles = procedural::simulate_particles(settings);
  const material::Texture& base = o.texture ? *o.texture : *default_texture_;
  long long nodes = 1;
  const auto add = [&](ParsedObject child) {
    count_objects(nodes, child, keyword.where);
    o.children.push_back(std::move(child));
  };
  std::optional<material::Rgbft> no_color;
  switch (look.look) {
    case ParticleLook::spheres:
      for (const procedural::Particle& p : particles)
        if (const double r = look.radius(p); r > 0)
          add(solid_child(shapes::sphere(p.position, r), base,
                          look.color_map ? std::optional(look.color(p)) : no_color, keyword.where));
      break;
    case ParticleLook::blob: {
      // One blob: each particle a component whose strength fades with its colour's intensity.
      std::vector<geometry::BlobComponent> components;
      for (const procedural::Particle& p : particles) {
        geometry::BlobComponent c;
        c.center = p.position;
        c.radius = look.radius(p);
        c.strength = look.blob_strength * (look.color_map ? intensity(look.color(p)) : 1.0);
        if (c.radius > 0 && c.strength > 0) components.push_back(c);
      }
      if (!components.empty())
        add(solid_child(shapes::blob(look.blob_threshold, std::move(components)), base, no_color,
                        keyword.where));
      break;
    }
    case ParticleLook::media:
      if (ParsedObject container = media_container(particles, look, keyword.where); container.shape)
        add(std::move(container));
      break;
    case ParticleLook::streaks: {
      std::vector<ParsedObject> pieces;
      for (const procedural::Particle& p : particles) add_streak(p, look, base, keyword.where, pieces);
      for (ParsedObject& piece : pieces) add(std::move(piece));
      break;
    }
  }
  return o;
}

}  // namespace snell::sdl
