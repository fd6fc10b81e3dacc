#include <stdexcept>
#include <string>

#include "snell/render/integrator.hpp"
#include "snell/render/path.hpp"
#include "snell/render/whitted.hpp"

namespace snell::render {

std::unique_ptr<Integrator> make_integrator(std::string_view name, const scene::Scene& scene,
                                            const accel::Accelerator& accelerator) {
  if (name == "whitted") return std::make_unique<WhittedIntegrator>(scene, accelerator);
  if (name == "path") return std::make_unique<PathIntegrator>(scene, accelerator);
  throw std::invalid_argument("unknown integrator '" + std::string(name) + "' (expected whitted or path)");
}

}  // namespace snell::render
