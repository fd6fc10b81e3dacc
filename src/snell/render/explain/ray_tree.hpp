#pragma once
// The ray tree of one camera sample as `snell explain` shows it (issue 14): every ray the Whitted integrator
// sent for the sample, what it met, the terms it added and why it ended. Built by RayTreeRecorder, a
// TraceObserver (render/trace_observer.hpp), while the integrator traces the sample as usual.
#include <memory>
#include <string_view>
#include <vector>

#include "snell/render/trace_observer.hpp"
#include "snell/scene/scene.hpp"

namespace snell::render::explain {

/// Why a ray stopped adding rays below it.
enum class RayEnd {
  shaded,                     // it hit a surface, which was lit (its children are the rays that sent)
  depth_limit,                // deeper than global_settings max_trace_level
  adc_bailout,                // its weight fell below global_settings adc_bailout
  miss,                       // it left the scene: the background (or sky sphere) colour
  total_internal_reflection,  // a refracted ray that was never sent (the reflected ray went instead)
  light_reached,              // a shadow ray that got to its light (perhaps tinted by transparent objects)
  light_blocked,              // a shadow ray stopped by an opaque object
  outside_projection,         // a shadow ray of a light with projected_through that misses that object
};
std::string_view to_string(RayEnd end);
std::string_view to_string(scene::RayKind kind);
std::string_view to_string(RayTerm term);

struct TermRecord {
  RayTerm term;
  math::Color weight;
  math::Color value;
};

struct Blocker {
  const scene::Object* object;
  double distance;
  bool opaque;
};

struct RayNode {
  scene::RayKind kind = scene::RayKind::camera;
  math::Ray ray;
  int level = 0;
  double weight = 1;
  /// Shadow rays: the light looked for and its index in the scene (0-based).
  const scene::Light* light = nullptr;
  int light_index = -1;
  bool hit = false;
  scene::SurfaceHit surface;
  /// Whether the ray goes into the solid it hit (against its outward normal).
  bool entering = false;
  std::vector<TermRecord> terms;
  std::vector<Blocker> blockers;
  math::Color result{0, 0, 0};
  RayEnd end = RayEnd::miss;
  std::vector<RayNode> children;
};

class RayTreeRecorder final : public TraceObserver {
 public:
  explicit RayTreeRecorder(const scene::Scene& scene) : scene_(scene) {}

  void ray_begin(scene::RayKind kind, const math::Ray& ray, int level, double weight,
                 const scene::Light* light) override;
  void ray_hit(const scene::SurfaceHit* hit) override;
  void shadow_blocker(const scene::SurfaceHit& hit, bool opaque) override;
  void term(RayTerm term, const math::Color& weight, const math::Color& value) override;
  void total_internal_reflection() override;
  void ray_end(const math::Color& result) override;

  /// The camera ray's tree once it has ended (null before).
  const RayNode* root() const { return root_.get(); }
  std::unique_ptr<RayNode> take_root() { return std::move(root_); }

 private:
  const scene::Scene& scene_;
  std::unique_ptr<RayNode> root_;
  /// The open rays, outermost first.
  std::vector<RayNode*> open_;
};

}  // namespace snell::render::explain
