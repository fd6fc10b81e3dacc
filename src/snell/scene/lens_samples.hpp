#pragma once
// Where on the lens each focal-blur ray leaves from. POV-Ray spreads blur_samples points evenly over the
// aperture disc and jitters them per pixel (reference "Focal Blur"); we use a Vogel (golden-angle) spiral,
// which covers a disc evenly for any count, turned by a per-pixel angle so the pattern does not repeat from
// pixel to pixel. Deterministic: a function of (pixel seed, sample index) only.
#include <cstdint>

#include "snell/math/vec3.hpp"

namespace snell::scene {

/// Point `index` of `count` on the disc of radius 1/2 centred at the origin. `rotation` (radians) turns the
/// whole pattern; `jitter_u`, `jitter_v` in [0,1) move each point within its own share of the disc.
math::Vec2 lens_sample(int index, int count, double rotation, double jitter_u, double jitter_v);

}  // namespace snell::scene
