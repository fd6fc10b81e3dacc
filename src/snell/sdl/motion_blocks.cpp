// Motion blur syntax (a snell extension; POV-Ray 3.7 has none, and MegaPOV's `motion_blur` clock-step
// objects are not followed): the camera's `shutter { open T close T samples N }` and an object's
// `motion { ... }` block. See docs/language.md, "Motion blur".
#include <cmath>

#include "snell/scene/motion.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

void Parser::parse_motion_block(ParsedObject& o, const Token& keyword) {
  // Either transforms alone (`motion { translate x }`: identity at time 0, those transforms at time 1) or
  // keys: `motion { key 0 translate -x  key 0.5 rotate y*30  key 1 translate x }`.
  expect("{", "motion");
  scene::MotionLayer layer;
  bool single = false;
  math::Transform current;
  while (!accept("}")) {
    const Token t = peek();
    if (t.kind == Token::Kind::end) fail(t.where, "unexpected end of file: missing '}' of motion");
    if (t.is_word("key")) {
      raw_next();
      if (single) fail(t.where, "motion: 'key' cannot follow transforms that have no key");
      const double time = parse_float();
      if (!std::isfinite(time)) fail(t.where, "motion: key time must be finite");
      if (!layer.keys.empty() && !(time > layer.keys.back().time))
        fail(t.where, "motion: key times must increase");
      layer.keys.push_back({time, scene::Pose{}});  // a key without transforms is the identity
      current = math::Transform{};
      continue;
    }
    auto step = parse_transform_item();
    if (!step) fail(t.where, "unexpected '" + t.text + "' in motion (expected a transform or 'key')");
    current = *step * current;
    if (layer.keys.empty())
      single = true;
    else
      layer.keys.back().pose = scene::decompose(current);
  }
  if (layer.keys.empty() && !single) fail(keyword.where, "motion needs a transform or at least one key");
  if (single) layer.keys = {{0, scene::Pose{}}, {1, scene::decompose(current)}};
  o.motion.push_back(std::move(layer));
}

void Parser::parse_shutter_block(scene::CameraSpec& cam, const Token& keyword) {
  expect("{", "shutter");
  while (!accept("}")) {
    const Token t = next();
    if (t.is_word("open"))
      cam.shutter_open = parse_float();
    else if (t.is_word("close"))
      cam.shutter_close = parse_float();
    else if (t.is_word("samples"))
      cam.shutter_samples = parse_int("shutter samples", 1, 4096);
    else if (t.kind == Token::Kind::end)
      fail(t.where, "unexpected end of file: missing '}' of shutter");
    else
      fail(t.where, "unexpected '" + t.text + "' in shutter (expected open, close or samples)");
  }
  if (!std::isfinite(cam.shutter_open) || !std::isfinite(cam.shutter_close) ||
      cam.shutter_close < cam.shutter_open)
    fail(keyword.where, "shutter: close must not come before open");
}

}  // namespace snell::sdl
