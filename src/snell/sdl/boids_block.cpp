// `boids { }`: a snell extension (docs/procedural.md) that flies procedural/flock up to the frame's time
// and places a copy of the user's boid object at each boid, turned so that its +z axis points along the
// boid's velocity and its +y axis stays as close to the world's +y as that allows.
#include <cmath>

#include <fmt/format.h>

#include "snell/procedural/flock.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

constexpr int kMostBoids = 100'000;
constexpr double kMostBoidSteps = 1e9;  // boids times steps: the work of the O(n^2) simulation

/// Object space -> world: +z along `velocity`, +y towards the world's up, the origin at `position`.
math::Transform boid_placement(const procedural::Boid& boid) {
  const double speed = length(boid.velocity);
  const math::Vec3 forward = speed > 0 ? boid.velocity / speed : math::Vec3(0, 0, 1);
  math::Vec3 up_hint(0, 1, 0);
  if (std::fabs(dot(forward, up_hint)) > 0.999) up_hint = math::Vec3(1, 0, 0);
  const math::Vec3 right = normalize(cross(up_hint, forward));
  const math::Vec3 up = cross(forward, right);
  math::Matrix4 m = math::Matrix4::identity();
  for (int r = 0; r < 3; ++r) {
    m.m[static_cast<size_t>(r)][0] = right[r];
    m.m[static_cast<size_t>(r)][1] = up[r];
    m.m[static_cast<size_t>(r)][2] = forward[r];
    m.m[static_cast<size_t>(r)][3] = boid.position[r];
  }
  // A rotation and a translation: the inverse is the transposed rotation and the rotated, negated shift.
  math::Matrix4 inv = math::Matrix4::identity();
  for (int r = 0; r < 3; ++r) {
    const math::Vec3 axis = r == 0 ? right : (r == 1 ? up : forward);
    for (int c = 0; c < 3; ++c) inv.m[static_cast<size_t>(r)][static_cast<size_t>(c)] = axis[c];
    inv.m[static_cast<size_t>(r)][3] = -dot(axis, boid.position);
  }
  return math::Transform(m, inv);
}

}  // namespace

procedural::ObjectProbe Parser::parse_probe_objects(const char* context) {
  expect("{", context);
  std::vector<std::shared_ptr<const scene::Object>> parts;
  std::vector<scene::Light> lights;
  while (auto object = parse_object_if_any()) flatten(*object, parts, lights);
  expect("}", context);
  return procedural::ObjectProbe(std::move(parts));
}

ParsedObject Parser::parse_boids(const Token& keyword) {
  expect("{", "boids");
  procedural::FlockSettings s;
  std::optional<ParsedObject> model;
  const auto number = [&](const Token& t, double& target, double lowest) {
    raw_next();
    target = parse_float();
    if (!(target >= lowest)) fail(t.where, t.text + " must be at least " + fmt::format("{:g}", lowest));
  };
  for (;;) {
    const Token t = peek();
    if (t.is_word("count")) {
      raw_next();
      s.count = parse_int("boid count", 1, kMostBoids);
    } else if (t.is_word("seed")) {
      raw_next();
      s.seed = static_cast<uint64_t>(static_cast<long long>(parse_float()));
    } else if (t.is_word("time")) {
      raw_next();
      s.time = parse_float();
    } else if (t.is_word("step")) {
      number(t, s.step, 1e-6);
    } else if (t.is_word("start")) {
      raw_next();
      const math::Vec3 a = parse_vector();
      accept(",");
      s.start = math::Bounds3(a, parse_vector());
    } else if (t.is_word("start_speed")) {
      number(t, s.start_speed, 0);
    } else if (t.is_word("separation")) {
      number(t, s.separation_distance, 0);
      accept(",");
      s.separation_weight = parse_float();
    } else if (t.is_word("alignment")) {
      raw_next();
      s.alignment_weight = parse_float();
    } else if (t.is_word("cohesion")) {
      raw_next();
      s.cohesion_weight = parse_float();
    } else if (t.is_word("neighbour_radius") || t.is_word("neighbor_radius")) {
      number(t, s.neighbour_radius, 0);
    } else if (t.is_word("field_of_view")) {
      number(t, s.field_of_view_degrees, 0);
    } else if (t.is_word("max_speed")) {
      number(t, s.max_speed, 1e-9);
    } else if (t.is_word("min_speed")) {
      number(t, s.min_speed, 0);
    } else if (t.is_word("max_force")) {
      number(t, s.max_force, 0);
    } else if (t.is_word("avoid")) {
      raw_next();
      s.obstacles = parse_probe_objects("avoid");
      for (;;) {
        if (peek().is_word("distance")) {
          number(peek(), s.avoid_distance, 1e-9);
        } else if (peek().is_word("weight")) {
          number(peek(), s.avoid_weight, 0);
        } else {
          break;
        }
      }
    } else if (t.is_word("bounds")) {
      raw_next();
      const math::Vec3 a = parse_vector();
      accept(",");
      s.bounds = math::Bounds3(a, parse_vector());
      if (peek().is_word("weight")) number(peek(), s.bounds_weight, 0);
    } else if (t.is_word("boid")) {
      raw_next();
      expect("{", "boid");
      model = parse_object_if_any();
      if (!model)
        fail(peek().where, "boid { } needs an object, e.g. boid { cone { <0,0,0>, 0.1, <0,0,0.4>, 0 } }");
      expect("}", "boid");
    } else {
      break;
    }
  }
  if (!model) fail(keyword.where, "boids needs a boid { object } to place at each boid");
  if (s.min_speed > s.max_speed) fail(keyword.where, "min_speed is larger than max_speed");
  const double steps = s.time / s.step;
  if (steps * static_cast<double>(s.count) * static_cast<double>(s.count) > kMostBoidSteps)
    fail(keyword.where, "count^2 x time / step is more than 1e9; use fewer boids or a larger step");

  ParsedObject o;
  o.where = keyword.where;
  parse_object_modifiers(o);
  long long nodes = 1;
  for (const procedural::Boid& boid : procedural::simulate_flock(s)) {
    ParsedObject copy = *model;
    copy.apply(boid_placement(boid));
    count_objects(nodes, copy, keyword.where);
    o.children.push_back(std::move(copy));
  }
  return o;
}

}  // namespace snell::sdl
