#include <stdexcept>
#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/accel/box_list.hpp"
#include "snell/accel/brute_force.hpp"
#include "snell/accel/bvh.hpp"
#include "snell/accel/embree_accelerator.hpp"
#include "snell/accel/grid.hpp"
#include "snell/accel/octree.hpp"

namespace snell::accel {

const scene::Object* Accelerator::occluder(const math::Ray& ray, double t_min, double t_max,
                                           scene::RayKind kind) const {
  scene::SurfaceHit hit;
  return intersect(ray, t_min, t_max, kind, hit) ? hit.object : nullptr;
}

std::unique_ptr<Accelerator> make_accelerator(std::string_view kind, const scene::Scene& scene) {
  if (kind == "embree") return std::make_unique<EmbreeAccelerator>(scene);
  if (kind == "bvh") return std::make_unique<Bvh>(scene);
  if (kind == "octree") return std::make_unique<Octree>(scene);
  if (kind == "grid") return std::make_unique<Grid>(scene);
  if (kind == "list") return std::make_unique<BoxList>(scene);
  if (kind == "none") return std::make_unique<BruteForce>(scene);
  throw std::invalid_argument("unknown accelerator '" + std::string(kind) +
                              "' (expected embree, bvh, octree, grid, list or none)");
}

}  // namespace snell::accel
