#pragma once
// POV-Ray's focal-blur lens points for 7, 19 and 37 blur_samples (tracepixel.cpp, FocalBlurData: its
// HexGrid2/3/4): the points of a hexagonal lattice filling a hexagon of one, two or three rings inside
// the radius-1/2 disc, each jittered per ray by at most half the lattice spacing. Traced in POV-Ray's
// batches (7, 6, 6, then 4 and 2: blur_confidence.hpp), each batch spread over the whole hexagon, so
// that a pixel which stops early has still seen the whole lens. These fixed points give much less noise
// than random lens points at the same count, which is what makes POV-Ray's blur smooth.
#include <optional>

#include "snell/math/vec3.hpp"

namespace snell::scene {

/// Lens point `index` of the hexagonal grid for `blur_samples` (7, 19 or 37; none for other counts or
/// indices past the grid), on the disc of radius 1/2; `jitter_u`, `jitter_v` in [0,1) move it within its
/// lattice cell.
std::optional<math::Vec2> hex_lens_sample(int index, int blur_samples, double jitter_u, double jitter_v);

}  // namespace snell::scene
