#pragma once
// A shadow ray needs only whether a shape has a crossing in its window, not the nearest one nor its hit.
// The shapes whose crossings come from a loop over pieces (prism, lathe, sor) emit them through a callback
// and stop solving once their window's far end (taken by reference) falls below a piece's start.
#include "snell/math/constants.hpp"

namespace snell::geometry {

/// Whether `crossings(limit, emit)` emits anything: the first crossing closes the window (limit = -inf),
/// so the remaining pieces are skipped and no hit is built.
template <typename Crossings>
bool any_crossing(double t_max, Crossings&& crossings) {
  bool found = false;
  double limit = t_max;
  crossings(limit, [&](const auto&) {
    found = true;
    limit = -math::kInfinity;
  });
  return found;
}

}  // namespace snell::geometry
