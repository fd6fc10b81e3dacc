#include "snell/render/photons/photon_map.hpp"

#include <algorithm>
#include <cmath>

namespace snell::render::photons {

using math::Color;
using math::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
/// Cone filter constant (Jensen 2001, eq. 7.4): weights fall from 1 at the point to 1 - 1/k at the radius.
constexpr double kCone = 1.0;
/// POV-Ray widens the search once, by twice the first radius (photons.cpp, setGatherOptions).
constexpr int kGatherSteps = 2;
/// A radius "as large as the scene" for the density survey.
constexpr double kUnbounded = 1e7;

uint64_t bytes_for(size_t photons) {
  // The photons, plus a tree node each (a position, an index and an axis).
  return static_cast<uint64_t>(photons) * (sizeof(Photon) + sizeof(Vec3) + 8);
}

std::vector<Vec3> positions_of(const std::vector<Photon>& photons) {
  std::vector<Vec3> p;
  p.reserve(photons.size());
  for (const Photon& photon : photons) p.push_back(photon.position);
  return p;
}

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons, const scene::PhotonSettings& settings,
                     const std::shared_ptr<memory::Budget>& budget)
    : charge_(budget, bytes_for(photons.size()), "photon map"),
      photons_(std::move(photons)),
      tree_(positions_of(photons_)),
      settings_(settings) {
  gather_radius_ = settings.gather_radius > 0 ? settings.gather_radius : estimate_gather_radius();
  gather_radius_ *= settings.gather_radius_multiplier;
}

double PhotonMap::estimate_gather_radius() const {
  // POV-Ray's estimate (photons.cpp, PhotonMap::setGatherOptions), on evenly spaced photons instead of random
  // ones: the radius that holds `gather max` photons at the mean density, widened where many photons sit in
  // sparser regions (below 70% of the mean).
  const size_t n = photons_.size();
  const size_t k = static_cast<size_t>(std::max(1, settings_.gather_max));
  if (n == 0) return 0;
  const size_t samples = std::clamp<size_t>(n / 20, 100, 1000);
  const auto density_at = [&](size_t sample, double size) {
    const Vec3& p = photons_[sample * n / samples].position;
    const std::vector<Neighbour> found = tree_.nearest(p, k, size);
    const double r = found.size() >= k ? std::sqrt(found.back().distance_squared) : size;
    return std::pair{static_cast<double>(found.size()), r};
  };
  double sum = 0;
  for (size_t i = 0; i < samples; ++i) {
    const auto [count, r] = density_at(i, kUnbounded);
    sum += r > 0 ? count / (kPi * r * r) : (i > 0 ? sum / static_cast<double>(i) : 0);
  }
  const double mean = sum / static_cast<double>(samples);
  if (!(mean > 0)) return 0;
  double radius = std::sqrt(static_cast<double>(k) / (mean * kPi));
  size_t sparse = 0;
  for (size_t i = 0; i < samples; ++i) {
    const auto [count, r] = density_at(i, radius);
    if (r <= 0) continue;
    const double density = count / (kPi * r * r);
    if (density < 0.7 * mean && density > 0.05 * mean) ++sparse;
  }
  return radius * (1.0 + 20.0 * static_cast<double>(sparse) / static_cast<double>(samples));
}

void PhotonMap::gather(const Vec3& point, const Vec3& normal, double size, Found& f) const {
  const size_t k = static_cast<size_t>(settings_.gather_max);
  f.photons.clear();
  // One buffer per thread for the tree's answer: a gather per shading point must not allocate.
  thread_local std::vector<Neighbour> near;
  const double farthest = tree_.nearest_in_any_order(point, k, size, near);
  f.radius = near.size() >= k && !near.empty() ? std::sqrt(farthest) : size;
  // A flattened search: distances grow with the offset along the normal, so photons on a nearby wall at a
  // corner do not bleed in (POV-Ray photons.cpp, gatherPhotonsRec's "discFix").
  const double limit = f.radius * f.radius;
  for (const Neighbour& nb : near) {
    const double off_plane = std::fabs(dot(normal, photons_[nb.index].position - point));
    if (nb.distance_squared * (1 + 16 * off_plane) <= limit) f.photons.push_back(nb);
  }
}

Color PhotonMap::radiance(const Vec3& point, const Vec3& raw_normal, const Vec3& normal,
                          bool double_illuminate, const Response& response) const {
  if (photons_.empty() || settings_.gather_max <= 0 || !(gather_radius_ > 0)) return Color(0);
  double size = gather_radius_;
  // Per-thread buffers, kept between calls: the surface response below traces nothing, so no second
  // gather on this thread can start while these are in use.
  thread_local Found found, wider;
  gather(point, normal, size, found);
  double previous = static_cast<double>(found.photons.size()) / (found.radius * found.radius);
  if (previous == 0) previous = 1e-16;
  for (int step = 1; step < kGatherSteps && found.photons.size() < static_cast<size_t>(settings_.gather_min);
       ++step) {
    size += 2 * gather_radius_;
    gather(point, normal, size, wider);
    const double count = static_cast<double>(wider.photons.size());
    const double density = count / (wider.radius * wider.radius);
    const bool few = count > 0 && count < settings_.expand_min_count;
    if (!((density - previous) / previous < settings_.expand_tolerance || few)) break;
    std::swap(found, wider);
    previous = density > 0 ? density : 1e-16;
  }
  if (found.photons.empty() || !(found.radius > 0)) return Color(0);
  Color sum;
  for (const Neighbour& nb : found.photons) {
    const Photon& photon = photons_[nb.index];
    if (!double_illuminate && dot(normal, photon.incoming) < 1e-10) continue;
    // The photon density already holds the cosine of incidence; the surface response applies it again, so
    // divide it out, limited to 10x as POV-Ray does against bright specks (trace.cpp,
    // ComputePhotonDiffuseLight).
    const double cos_in = std::clamp(dot(raw_normal, photon.incoming), 0.1, 1.0);
    const double cone = 1 - std::sqrt(nb.distance_squared) / (kCone * found.radius);
    sum += response(photon.incoming, photon.power * (cone / cos_in));
  }
  return sum / ((1 - 2 / (3 * kCone)) * kPi * found.radius * found.radius);
}

}  // namespace snell::render::photons
