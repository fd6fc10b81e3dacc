#pragma once
// `--accel NAME` for every subcommand: "auto" is the box list for scenes of a few objects
// (accel/box_list.hpp), else Embree when built, else brute force.
#include <memory>
#include <string>

#include "snell/accel/accelerator.hpp"

namespace snell::cli {

/// Throws std::invalid_argument for unknown names.
std::unique_ptr<accel::Accelerator> build_accelerator(const std::string& name, const scene::Scene& scene);

}  // namespace snell::cli
