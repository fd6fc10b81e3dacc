#include <stdexcept>
#include <string>
#include <utility>

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

namespace {

using Factory = std::unique_ptr<Accelerator> (*)(const scene::Scene&);

template <class T>
std::unique_ptr<Accelerator> make(const scene::Scene& scene) {
  return std::make_unique<T>(scene);
}

/// Every back end by its --accel name, the one list that make_accelerator and is_accelerator_kind read.
constexpr std::pair<std::string_view, Factory> kKinds[] = {
    {"embree", &make<EmbreeAccelerator>},
    {"bvh", &make<Bvh>},
    {"octree", &make<Octree>},
    {"grid", &make<Grid>},
    {"list", &make<BoxList>},
    {"none", &make<BruteForce>},
};

}  // namespace

bool is_accelerator_kind(std::string_view kind) {
  for (const auto& [name, factory] : kKinds)
    if (name == kind) return true;
  return false;
}

std::unique_ptr<Accelerator> make_accelerator(std::string_view kind, const scene::Scene& scene) {
  for (const auto& [name, factory] : kKinds)
    if (name == kind) return factory(scene);
  throw std::invalid_argument("unknown accelerator '" + std::string(kind) + "' (expected " +
                              std::string(kAcceleratorKinds) + ")");
}

}  // namespace snell::accel
