#pragma once
// The caustic photon map and its radiance estimate (Jensen 2001, "Realistic Image Synthesis Using Photon
// Mapping", ch. 7): the k nearest photons around a shading point, within a radius that grows when too few
// are found (POV-Ray 3.7 photons.cpp, gatherPhotonsAdaptive: the same thresholds and two steps), weighted by
// a cone filter (Jensen eq. 7.4, k = 1) and divided by the disc's area.
#include <functional>
#include <memory>
#include <vector>

#include "snell/math/color.hpp"
#include "snell/memory/budget.hpp"
#include "snell/render/photons/kd_tree.hpp"
#include "snell/render/photons/photon.hpp"
#include "snell/scene/photon_settings.hpp"

namespace snell::render::photons {

class PhotonMap {
 public:
  /// Charges the photons and the tree to `budget` (when set) before keeping them; throws
  /// memory::BudgetExceeded past its limit.
  PhotonMap(std::vector<Photon> photons, const scene::PhotonSettings& settings,
            const std::shared_ptr<memory::Budget>& budget);

  /// How the surface answers light of colour `colour` arriving from unit direction `to_light`.
  using Response = std::function<math::Color(const math::Vec3& to_light, const math::Color& colour)>;

  /// Light the photons around `point` bring, as the surface's `response` to each photon divided by the
  /// gathering disc's area. `raw_normal` and `normal` face the viewer; photons from behind the surface count
  /// only with `double_illuminate`.
  math::Color radiance(const math::Vec3& point, const math::Vec3& raw_normal, const math::Vec3& normal,
                       bool double_illuminate, const Response& response) const;

  size_t size() const { return photons_.size(); }
  const std::vector<Photon>& photons() const { return photons_; }
  /// Bytes of the photons and the tree.
  uint64_t memory_bytes() const { return charge_.bytes(); }
  /// The first search radius (given or estimated from the density).
  double gather_radius() const { return gather_radius_; }

 private:
  struct Found {
    std::vector<Neighbour> photons;
    double radius = 0;
  };
  /// The photons for `point` into `f` (its buffer reused).
  void gather(const math::Vec3& point, const math::Vec3& normal, double size, Found& f) const;
  double estimate_gather_radius() const;

  memory::Charge charge_;
  std::vector<Photon> photons_;
  KdTree tree_;
  scene::PhotonSettings settings_;
  double gather_radius_ = 0;
};

}  // namespace snell::render::photons
