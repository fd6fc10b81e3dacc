#include "snell/texture/average_normal.hpp"

#include <cmath>
#include <stdexcept>

namespace snell::texture {

AverageNormal::AverageNormal(std::vector<std::pair<double, NormalPtr>> entries)
    : entries_(std::move(entries)) {
  if (entries_.empty()) throw std::invalid_argument("average needs a normal_map with at least one entry");
  double total = 0;
  for (const auto& [weight, normal] : entries_) total += weight;
  if (!(std::fabs(total) > 0)) throw std::invalid_argument("average: the map's weights sum to zero");
}

math::Vec3 AverageNormal::perturb(const math::Vec3& normal, const material::PatternPoint& point) const {
  math::Vec3 sum{0, 0, 0};
  for (const auto& [weight, entry] : entries_)
    sum += weight * (entry ? entry->perturb(normal, point) : normal);
  // The weights' sum only scales the mean, which normalising removes; a mean of zero leaves the normal.
  const double length = math::length(sum);
  return length > 0 ? sum / length : normal;
}

}  // namespace snell::texture
