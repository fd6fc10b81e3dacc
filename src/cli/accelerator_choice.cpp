#include "cli/accelerator_choice.hpp"

#include <stdexcept>

#include "snell/accel/box_list.hpp"

namespace snell::cli {

std::unique_ptr<accel::Accelerator> build_accelerator(const std::string& name, const scene::Scene& scene) {
  if (name != "auto") return accel::make_accelerator(name, scene);
  if (accel::prefers_box_list(scene)) return accel::make_accelerator("list", scene);
  try {
    return accel::make_accelerator("embree", scene);
  } catch (const std::invalid_argument&) {
    return accel::make_accelerator("none", scene);
  }
}

}  // namespace snell::cli
