#include "snell/texture/average_texture.hpp"

#include "snell/texture/average_normal.hpp"
#include "snell/texture/average_pigment.hpp"
#include "snell/texture/pattern_normal.hpp"
#include "snell/texture/pattern_pigment.hpp"

namespace snell::texture {

void average_textures(const std::vector<std::pair<double, std::shared_ptr<const material::Texture>>>& entries,
                      material::Texture& out) {
  std::vector<PigmentMap::Entry> pigments;
  std::vector<std::pair<double, NormalPtr>> normals;
  bool any_normal = false;
  const material::Texture* heaviest = nullptr;
  out.averaged.clear();
  double heaviest_weight = 0;
  for (const auto& [weight, entry] : entries) {
    if (!entry) continue;
    // The entry's own transforms are relative to the averaged texture's space.
    PigmentPtr pigment = entry->pigment ? transform_pigment(entry->pigment, entry->transform) : nullptr;
    if (!pigment) pigment = std::make_shared<material::SolidPigment>(material::Rgbft{});
    pigments.emplace_back(weight, pigment);
    NormalPtr normal = std::make_shared<FlatNormal>();
    if (entry->normal) {
      normal = std::make_shared<TransformedNormal>(entry->normal, entry->transform);
      any_normal = true;
    }
    normals.emplace_back(weight, normal);
    out.averaged.emplace_back(weight, entry->transformed(out.transform));
    if (!heaviest || weight > heaviest_weight) {
      heaviest = entry.get();
      heaviest_weight = weight;
    }
  }
  if (pigments.empty()) return;
  out.pigment = std::make_shared<AveragePigment>(std::move(pigments));
  out.normal = any_normal ? std::make_shared<AverageNormal>(std::move(normals)) : nullptr;
  out.finish = heaviest->finish;
}

}  // namespace snell::texture
