// `seed(n)` and `rand(stream)` (POV-Ray 3.7 reference, "Float Functions"). POV-Ray's own generator is a
// linear congruential one whose exact sequence this does not reproduce: snell draws from PCG32 streams
// (math/pcg32.hpp) seeded from n. Values are uniform in [0, 1) and the same seed gives the same sequence
// on every run and platform, but scenes that scatter objects with rand() place them differently from
// POV-Ray.
#include <cmath>

#include "snell/sdl/parser.hpp"

namespace snell::sdl {

Numeric Parser::parse_random_function(const Token& name) {
  const std::string& f = name.text;
  expect("(", f.c_str());
  const scene::SourceLocation where = peek().where;
  const double arg = parse_float();
  expect(")", f.c_str());
  if (f == "seed") {
    // POV-Ray truncates the seed to an integer; two streams from the same seed give
    // the same sequence, each advancing on its own.
    if (!std::isfinite(arg)) fail(where, "seed needs a finite number");
    const auto n = static_cast<int64_t>(std::trunc(std::fmod(arg, 9.2e18)));
    random_streams_.emplace_back(math::mix_seed(static_cast<uint64_t>(n)));
    return Numeric::of(static_cast<double>(random_streams_.size() - 1));
  }
  const double index = std::floor(arg);
  if (!(index >= 0 && index < static_cast<double>(random_streams_.size())))
    fail(where, "rand: " + std::to_string(arg) + " is not a stream made by seed()");
  return Numeric::of(random_streams_[static_cast<size_t>(index)].next_double());
}

}  // namespace snell::sdl
