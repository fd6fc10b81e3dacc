#pragma once
// The records a tile gathers while it renders (render/radiosity/solver.hpp): a tile sees the shared cache
// of the finished passes plus its own new records, never another tile's of the same pass, so its pixels
// do not depend on which thread rendered which tile first (POV-Ray keeps the same rule for its pretrace
// tiles, radiosity.cpp AverageNearBlock; snell applies it to the final pass too).
#include <vector>

#include "snell/render/radiosity/record_grid.hpp"

namespace snell::render::radiosity {

struct TileRecords {
  /// New records by bounce depth (0: gathered at camera-visible points).
  std::vector<RecordGrid> by_depth;
  /// Set by Solver::begin_tile: gathers are kept here. Unset (e.g. `snell explain`) nothing is kept.
  bool open = false;
  /// The final pass (full error_bound, smooth blending) rather than a pretrace pass.
  bool final_pass = true;
};

}  // namespace snell::render::radiosity
