#pragma once
// Layers as pictures with a legend drawn below them (`--aov-png`, `--heatmap`): a colour ramp with a scale
// bar and its numbers for scalar layers (depth, cost, samples, time), false colours with a key for ids
// (object, material), and vectors mapped to colours (normal, position, albedo, uv).
#include <string>
#include <vector>

#include "snell/render/explain/aov_render.hpp"
#include "snell/render/explain/picture.hpp"

namespace snell::render::explain {

/// The ramp colour of t in 0..1: dark blue through purple, red and orange to pale yellow.
math::Color ramp_color(double t);
/// A distinct colour for an id (-1: black).
math::Color id_color(int id);

/// `values` (one per pixel; non-finite ones drawn black) as a ramp from their minimum to their maximum,
/// with `title` and the scale bar below.
Picture heatmap_picture(const std::string& title, const std::vector<float>& values, int width, int height);

/// `layer` of a width x height render as a picture with its legend.
Picture layer_picture(const Layer& layer, int width, int height);

/// The cost heatmap's per-pixel value: accelerator nodes visited plus objects tested (from a "cost" layer).
std::vector<float> query_cost(const Layer& cost_layer);

}  // namespace snell::render::explain
