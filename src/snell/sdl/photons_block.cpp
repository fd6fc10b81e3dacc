// The three `photons {}` blocks of POV-Ray 3.7 (reference "Photons"; keywords and defaults as
// source/parser/parser.cpp reads them): global_settings', an object's and a light_source's.
#include <algorithm>

#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

scene::PhotonSwitch to_switch(bool on) {
  return on ? scene::PhotonSwitch::on : scene::PhotonSwitch::off;
}

}  // namespace

scene::PhotonSettings Parser::parse_global_photons() {
  const Token open = peek();
  scene::PhotonSettings p;
  parse_keyword_block("photons", [&](const Token& t) {
    const std::string& w = t.text;
    if (w == "spacing") {
      p.spacing = parse_float();
      if (!(p.spacing > 0)) fail(t.where, "photons spacing must be greater than 0");
    } else if (w == "count") {
      p.count = parse_int("photons count", 0);
    } else if (w == "gather") {
      p.gather_min = parse_int("photons gather minimum", 0, 100000);
      accept(",");
      p.gather_max = parse_int("photons gather maximum", 0, 100000);
      if (p.gather_min > p.gather_max)
        fail(t.where, "the photons gather minimum must not be more than the maximum");
    } else if (w == "jitter") {
      p.jitter = parse_float();
    } else if (w == "max_trace_level") {
      p.max_trace_level = parse_int("photons max_trace_level");
    } else if (w == "adc_bailout") {
      p.adc_bailout = parse_float();
    } else if (w == "autostop") {
      p.autostop = parse_float();
    } else if (w == "expand_thresholds") {
      p.expand_tolerance = std::max(0.0, parse_float());
      accept(",");
      p.expand_min_count = std::max(0, parse_int("expand_thresholds count"));
    } else if (w == "radius") {
      // Up to four optional values: gather radius and multiplier, then the same for media.
      double* slots[] = {&p.gather_radius, &p.gather_radius_multiplier, nullptr, nullptr};
      for (double* slot : slots) {
        if (!starts_numeric()) break;
        const double v = parse_float();
        if (slot) *slot = v;
        if (!accept(",")) break;
      }
    } else if (w == "media") {
      p.media_steps = parse_int("photons media steps", 0);
      accept(",");
      if (starts_numeric()) p.media_spacing_factor = parse_float();
      if (!(p.media_spacing_factor > 0)) fail(t.where, "the media spacing factor must be greater than 0");
    } else if (w == "load_file" || w == "save_file") {
      warn(t.where, "photons " + w + " is not supported; the photon map is always shot");
      parse_string();
    } else {
      fail(t.where, "unknown photons keyword '" + w + "'");
    }
  });
  // POV-Ray: a maximum gather count of 0 switches photons off.
  if (p.gather_max == 0) warn(open.where, "photons gather maximum is 0: photons are off");
  return p;
}

void Parser::parse_object_photons(scene::ObjectPhotons& photons) {
  parse_keyword_block("photons", [&](const Token& t) {
    const std::string& w = t.text;
    if (w == "target") {
      // `target` takes an optional spacing multiplier; 0 or less clears the flag (POV-Ray).
      const double multiplier = starts_numeric() ? parse_float() : 1.0;
      if (multiplier > 0)
        photons.target = std::make_shared<const scene::PhotonTarget>(scene::PhotonTarget{multiplier});
      else
        photons.target.reset();
    } else if (w == "refraction") {
      photons.refraction = to_switch(parse_bool_optional(true));
    } else if (w == "reflection") {
      photons.reflection = to_switch(parse_bool_optional(true));
    } else if (w == "collect") {
      photons.collect = parse_bool_optional(true);
    } else if (w == "pass_through") {
      photons.pass_through = parse_bool_optional(true);
    } else if (w == "split_union") {
      parse_bool_optional(true);
    } else {
      fail(t.where, "unknown object photons keyword '" + w + "'");
    }
  });
}

void Parser::parse_light_photons(scene::LightPhotons& photons) {
  parse_keyword_block("photons", [&](const Token& t) {
    const std::string& w = t.text;
    if (w == "refraction") {
      photons.refraction = to_switch(parse_bool_optional(true));
    } else if (w == "reflection") {
      photons.reflection = to_switch(parse_bool_optional(true));
    } else if (w == "area_light") {
      photons.area_light = parse_bool_optional(true);
    } else {
      fail(t.where, "unknown light_source photons keyword '" + w + "'");
    }
  });
}

void Parser::parse_keyword_block(const char* context, const std::function<void(const Token&)>& keyword) {
  expect("{", context);
  for (;;) {
    if (accept("}")) return;
    const Token t = peek();
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in " + context);
    raw_next();
    keyword(t);
  }
}

}  // namespace snell::sdl
