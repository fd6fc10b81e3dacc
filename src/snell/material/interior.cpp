#include "snell/material/interior.hpp"

namespace snell::material {

std::shared_ptr<const Interior> Interior::transformed(const std::shared_ptr<const Interior>& interior,
                                                      const math::Transform& t) {
  if (!interior || interior->media.empty()) return interior;
  auto moved = std::make_shared<Interior>(*interior);
  for (Media& m : moved->media) m = m.transformed(t);
  return moved;
}

}  // namespace snell::material
