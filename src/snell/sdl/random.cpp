// `seed(n)` and `rand(stream)` (POV-Ray 3.7 reference, "Float Functions"), drawing the same numbers as
// POV-Ray so that scenes which scatter objects with rand() place them where POV-Ray does.
//
// POV-Ray's generator (source/core/math/randomsequence.cpp, POV_rand; seeding in
// source/parser/parser_expressions.cpp, stream_seed) is a 32-bit linear congruential one:
//   state = state * 1812433253 + 12345   (mod 2^32)
//   rand  = state / (2^32 - 1)           (so 0 <= rand <= 1, both ends reachable)
// and seed(n) starts a stream whose state is the integer part of n, truncated toward zero and taken
// modulo 2^32 (C's (unsigned)(int)n).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {

/// Advances one POV-Ray random stream and returns its next value in [0, 1].
double next_povray_rand(uint32_t& state) {
  state = state * 1812433253u + 12345u;
  return static_cast<double>(state) / 4294967295.0;
}

/// The starting state seed(n) gives: n truncated toward zero, as a 32-bit two's-complement integer.
/// POV-Ray converts through a C int; values outside its range are clamped here instead of being
/// undefined behaviour.
uint32_t seed_state(double n) {
  const double clamped = std::clamp(std::trunc(n), -2147483648.0, 2147483647.0);
  return static_cast<uint32_t>(static_cast<int32_t>(clamped));
}

}  // namespace

Numeric Parser::parse_random_function(const Token& name) {
  const std::string& f = name.text;
  expect("(", f.c_str());
  const scene::SourceLocation where = peek().where;
  const double arg = parse_float();
  expect(")", f.c_str());
  if (f == "seed") {
    // Two streams from the same seed give the same sequence, each advancing on its own.
    if (!std::isfinite(arg)) fail(where, "seed needs a finite number");
    random_streams_.push_back(seed_state(arg));
    return Numeric::of(static_cast<double>(random_streams_.size() - 1));
  }
  const double index = std::trunc(arg);
  if (!(index >= 0 && index < static_cast<double>(random_streams_.size())))
    fail(where, "rand: " + std::to_string(arg) + " is not a stream made by seed()");
  return Numeric::of(next_povray_rand(random_streams_[static_cast<size_t>(index)]));
}

}  // namespace snell::sdl
