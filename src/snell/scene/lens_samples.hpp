#pragma once
// Where on the lens each focal-blur ray leaves from. POV-Ray spreads blur_samples points evenly over the
// aperture disc and jitters them per pixel (reference "Focal Blur"), and may stop after any batch of them,
// so every prefix of the sequence must cover the disc too. We use Roberts' R2 low-discrepancy sequence
// (2018, "The Unreasonable Effectiveness of Quasirandom Sequences"), shifted per pixel (Cranley-Patterson
// rotation) so the pattern does not repeat from pixel to pixel, mapped area-preservingly onto the disc.
// Deterministic: a function of (pixel shift, sample index) only.
#include "snell/math/vec3.hpp"

namespace snell::scene {

/// Point `index` of the R2 sequence in the unit square, shifted by (shift_u, shift_v) modulo 1.
math::Vec2 r2_point(int index, double shift_u, double shift_v);

/// Sample `index` on the disc of radius 1/2 centred at the origin; `shift_u`, `shift_v` in [0,1) are the
/// pixel's shift of the sequence.
math::Vec2 lens_sample(int index, double shift_u, double shift_v);

}  // namespace snell::scene
