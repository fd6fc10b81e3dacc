#include "snell/texture/average_pigment.hpp"

#include <cmath>
#include <stdexcept>

namespace snell::texture {

AveragePigment::AveragePigment(std::vector<PigmentMap::Entry> entries) : entries_(std::move(entries)) {
  if (entries_.empty()) throw std::invalid_argument("average needs a pigment_map with at least one entry");
  for (const auto& [weight, pigment] : entries_) total_weight_ += weight;
  if (!(std::fabs(total_weight_) > 0)) throw std::invalid_argument("average: the map's weights sum to zero");
}

material::Rgbft AveragePigment::at(const material::PatternPoint& point) const {
  material::Rgbft sum{math::Color(0), 0, 0};
  for (const auto& [weight, pigment] : entries_) {
    const material::Rgbft c = pigment->at(point);
    sum.rgb += c.rgb * weight;
    sum.filter += c.filter * weight;
    sum.transmit += c.transmit * weight;
  }
  const double k = 1.0 / total_weight_;
  return {sum.rgb * k, sum.filter * k, sum.transmit * k};
}

}  // namespace snell::texture
