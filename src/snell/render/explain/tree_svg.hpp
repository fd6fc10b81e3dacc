#pragma once
// The ray tree drawn over a plan of the scene (`snell explain --svg FILE`): camera, lights, the outlines of
// the bounded objects (from their bounds; spheres as circles), every ray of the tree and its hit points,
// the figure of a lecture on Whitted ray tracing made from the user's own scene.
#include <string>

#include "snell/render/explain/explain_pixel.hpp"

namespace snell::render::explain {

/// Which plane the plan shows: the two axes kept (0 x, 1 y, 2 z) and the one dropped.
struct PlanAxes {
  int across, up, dropped;
};
/// The plane that contains the camera ray best: it drops the axis along which the ray moves least
/// (y on ties, a top view x/z); a camera ray along z thus gives the top view.
PlanAxes plan_axes(const math::Vec3& camera_direction);

std::string tree_svg(const PixelExplanation& explanation, const scene::Scene& scene);

}  // namespace snell::render::explain
