#include "snell/render/media.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "snell/math/constants.hpp"

namespace snell::render {

using material::Media;
using math::Color;
using math::Vec3;

namespace {

constexpr double kEpsilon = 1e-10;
/// POV-Ray's MAX_DISTANCE: how far a beam that leaves through the far end of the ray is taken to reach.
constexpr double kMaxDistance = 1e7;

Color exp_neg(const Color& c) {
  // Grey media (the usual case) thin every channel alike: one exp, the same value.
  if (c.r == c.g && c.g == c.b) {
    const double e = std::exp(-c.r);
    return {e, e, e};
  }
  return {std::exp(-c.r), std::exp(-c.g), std::exp(-c.b)};
}

double colour_distance(const Color& a, const Color& b) {
  return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
}

/// The forward part of the spotlight's falloff cone along the ray: solve |v + t d|^2 cos^2 = (k2 + t k1)^2
/// for the double cone and keep the nappe in front of the light (the viewer may start inside it).
bool spot_interval(const scene::Light& light, const math::Ray& ray, double& t0, double& t1) {
  const double cos_falloff = std::cos(math::radians(light.falloff));
  if (std::fabs(cos_falloff) < kEpsilon) return false;
  const double m = 1.0 / (cos_falloff * cos_falloff);
  const Vec3 to_target = light.point_at - light.position;
  const Vec3 axis = length_squared(to_target) > 0 ? normalize(to_target) : Vec3(0, 0, 1);
  const Vec3 v = ray.origin - light.position;
  const double k1 = dot(ray.direction, axis), k2 = dot(v, axis), l = length(v);
  const bool viewer_in_cone = l > kEpsilon && k2 / l >= cos_falloff;
  if (k1 <= 0 && k2 < 0) return false;
  const double k3 = dot(v, ray.direction), k4 = length_squared(v);
  const double a = 1.0 - k1 * k1 * m, b = k3 - k1 * k2 * m, c = k4 - k2 * k2 * m;
  if (a == 0) {
    if (!viewer_in_cone) return false;
    t0 = 0;
    t1 = -c / b;
    return true;
  }
  double d = b * b - a * c;
  if (d > kEpsilon) {
    d = std::sqrt(d);
    double ta = (-b + d) / a, tb = (-b - d) / a;
    if (ta > tb) std::swap(ta, tb);
    const double la = k2 + ta * k1, lb = k2 + tb * k1;  // along the axis: negative is the backward nappe
    if (la <= 0 && lb <= 0) return false;
    if (la <= 0) {
      if (viewer_in_cone) {
        t0 = 0;
        t1 = tb > 0 ? tb : kMaxDistance;
      } else {
        t0 = tb;
        t1 = kMaxDistance;
      }
    } else if (lb <= 0) {
      if (viewer_in_cone) {
        t0 = 0;
        t1 = ta;
      } else {
        t0 = ta;
        t1 = kMaxDistance;
      }
    } else {
      t0 = ta;
      t1 = tb;
    }
    return true;
  }
  if (d > -kEpsilon) {  // the ray grazes the cone
    t0 = viewer_in_cone ? 0 : -b / a;
    t1 = viewer_in_cone ? -b / a : kMaxDistance;
    return true;
  }
  return false;
}

/// Where the ray is within `falloff` of a cylinder light's axis, in front of the light.
bool cylinder_interval(const scene::Light& light, const math::Ray& ray, double& t0, double& t1) {
  const Vec3 to_target = light.point_at - light.position;
  const Vec3 axis = length_squared(to_target) > 0 ? normalize(to_target) : Vec3(0, 0, 1);
  const Vec3 v = ray.origin - light.position;
  const double k1 = dot(ray.direction, axis), k2 = dot(v, axis);
  if (k1 <= 0 && k2 < 0) return false;
  const double a = 1.0 - k1 * k1;
  if (a == 0) return false;
  const double falloff = std::max(light.falloff, light.radius);
  const double b = dot(v, ray.direction) - k1 * k2;
  const double c = length_squared(v) - k2 * k2 - falloff * falloff;
  double d = b * b - a * c;
  if (d <= kEpsilon) return false;
  d = std::sqrt(d);
  double ta = (-b + d) / a, tb = (-b - d) / a;
  if (ta > tb) std::swap(ta, tb);
  const double la = k2 + ta * k1, lb = k2 + tb * k1;
  if (la <= 0 && lb <= 0) return false;
  if (la <= 0) ta = 0;
  if (lb <= 0) tb = (kMaxDistance - k2) / k1;
  t0 = ta;
  t1 = tb;
  return true;
}

struct LitLight {
  const scene::Light* light;
  double t0, t1;
};

struct Interval {
  bool lit = false;
  double s0 = 0, ds = 0;
  int samples = 0;
  Color emitted{0};  // sum over samples of emission x length
  Color optical{0};  // sum over samples of extinction x length
};

/// Splits [0, depth] into stretches lit by some beam and dark ones (POV-Ray media.cpp,
/// ComputeMediaLightInterval: starts and ends are sorted separately, then overlapping beams merged).
struct LitStretch {
  bool lit;
  double s0, s1;
};

/// Scratch vectors of one media_along call, kept per thread and per nesting level so that a media ray
/// allocates nothing once the vectors have grown (they were ~7 allocations a camera ray on media1).
struct MediaScratch {
  std::vector<LitLight> lit;
  std::vector<double> starts, ends;
  std::vector<LitStretch> stretches;
  std::vector<Interval> intervals;
};

class ScratchLease {
 public:
  ScratchLease() {
    if (in_use_ == pool_.size()) pool_.emplace_back();  // a deque: earlier leases stay where they are
    scratch_ = &pool_[in_use_++];
  }
  ~ScratchLease() { --in_use_; }
  ScratchLease(const ScratchLease&) = delete;
  ScratchLease& operator=(const ScratchLease&) = delete;
  MediaScratch& operator*() const { return *scratch_; }

 private:
  static thread_local std::deque<MediaScratch> pool_;
  static thread_local size_t in_use_;
  MediaScratch* scratch_;
};
thread_local std::deque<MediaScratch> ScratchLease::pool_;
thread_local size_t ScratchLease::in_use_ = 0;

void lit_stretches(MediaScratch& scratch, double depth) {
  std::vector<LitStretch>& out = scratch.stretches;
  out.clear();
  if (scratch.lit.empty()) {
    out.push_back({false, 0, depth});
    return;
  }
  std::vector<double>&starts = scratch.starts, &ends = scratch.ends;
  starts.clear();
  ends.clear();
  for (const LitLight& l : scratch.lit) {
    starts.push_back(l.t0);
    ends.push_back(l.t1);
  }
  std::sort(starts.begin(), starts.end());
  std::sort(ends.begin(), ends.end());
  if (starts[0] > 0) out.push_back({false, 0, starts[0]});
  out.push_back({true, starts[0], ends[0]});
  for (size_t i = 1; i < starts.size(); ++i) {
    if (starts[i] > out.back().s1) {
      out.push_back({false, out.back().s1, starts[i]});
      out.push_back({true, starts[i], ends[i]});
    } else {
      out.back().s1 = std::max(out.back().s1, ends[i]);
    }
  }
  if (out.back().s1 < depth) out.push_back({false, out.back().s1, depth});
}

/// Sampling intervals: `intervals` (at least one per stretch), lit stretches getting `ratio` of them
/// (POV-Ray media.cpp, ComputeMediaSampleInterval).
void sampling_intervals(MediaScratch& scratch, const Media& m, bool constant) {
  const std::vector<LitStretch>& stretches = scratch.stretches;
  std::vector<Interval>& out = scratch.intervals;
  out.clear();
  const size_t count = std::max(static_cast<size_t>(m.intervals), stretches.size());
  auto split = [&](const LitStretch& s, size_t n) {
    const double delta = (s.s1 - s.s0) / static_cast<double>(n);
    for (size_t j = 0; j < n; ++j) out.push_back({s.lit, s.s0 + delta * static_cast<double>(j), delta});
  };
  if (stretches.size() == 1) {
    split(stretches[0], !stretches[0].lit && constant ? 1 : count);
  } else {
    double sum = 0;
    for (const LitStretch& s : stretches) sum += s.lit ? m.ratio : 1.0 - m.ratio;
    size_t remaining = count;
    for (size_t i = 0; i < stretches.size(); ++i) {
      const double weight = stretches[i].lit ? m.ratio : 1.0 - m.ratio;
      size_t n = static_cast<size_t>(weight / sum * static_cast<double>(count)) + 1;
      n = std::min(n, remaining - stretches.size() + i + 1);
      split(stretches[i], std::max<size_t>(n, 1));
      remaining -= std::min(remaining, n);
    }
  }
}

class MediaSampler {
 public:
  MediaSampler(const std::vector<const Media*>& media, const std::vector<LitLight>& lights,
               const math::Ray& ray, math::Pcg32& rng, const LightSampler& light_at)
      : media_(media), lights_(lights), ray_(ray), rng_(rng), light_at_(light_at), lead_(media.front()) {
    for (const Media* m : media) {
      if (m->intervals > lead_->intervals) lead_ = m;
      aa_threshold_ = std::min(aa_threshold_, m->aa_threshold);
    }
  }

  const Media& lead() const { return *lead_; }

  /// Emission x length and extinction x length of interval `iv` sampled at fraction `f` of its length.
  void sample(const Interval& iv, double f, Color& emitted, Color& optical) const {
    const double t = iv.s0 + f * iv.ds;
    const Vec3 p = ray_.at(t);
    Color extinction(0), emission(0), scattering(0);
    for (const Media* m : media_) {
      const Color d = m->densities.empty() ? Color(1) : m->density_at(p);
      extinction += d * m->extinction();
      emission += d * m->emission;
      scattering += d * m->scattering;
    }
    if (iv.lit && !scattering.is_black()) {
      for (const LitLight& l : lights_) {
        if (t < l.t0 || t > l.t1) continue;
        const LightAtPoint arriving = light_at_(*l.light, p);
        if (arriving.color.is_black()) continue;
        double k = 0;
        for (const Media* m : media_) k += m->phase_weight(arriving.direction, ray_.direction);
        k /= static_cast<double>(media_.size());
        emission += k * scattering * arriving.color;
      }
    }
    emitted = emission * iv.ds;
    optical = extinction * iv.ds;
  }

  /// Method 3 over one interval as POV-Ray 3.7 does it (media.cpp, ComputeMediaAdaptiveSampling):
  /// samples/2 + 1 sub-intervals (at least two), each 1/(count + 1) of the interval long, so the last
  /// such piece of the interval goes unsampled; each refined by midpoints, its emission thinned only by the
  /// sub-intervals before it (not within itself). POV-Ray 3.8 changed all three; 3.7's output is the
  /// reference.
  void adaptive(Interval& iv) {
    const Media& m = *lead_;
    const int count = std::max(2, m.min_samples / 2 + 1);
    const double dd = 1.0 / (count + 1);
    Color c0, od0;
    sample(iv, dd * m.jitter * (rng_.next_double() - 0.5), c0, od0);
    double d0 = dd;
    for (int j = 1; j <= count; ++j, d0 += dd) {
      Color c1, od1, result, result_od;
      sample(iv, d0 + dd * m.jitter * (rng_.next_double() - 0.5), c1, od1);
      refine(iv, d0 - dd, d0, c0, c1, od0, od1, m.aa_level - 1, result, result_od);
      iv.emitted += result * exp_neg(iv.optical / count);
      iv.optical += result_od;
      c0 = c1;
      od0 = od1;
    }
    iv.samples = count;
  }

  /// Methods 1 and 2: `min_samples` random (1) or jittered evenly spaced (2) samples.
  void regular(Interval& iv) {
    const Media& m = *lead_;
    for (int j = 0; j < m.min_samples; ++j) {
      const double f = m.method == 2
                           ? (j + 0.5) / m.min_samples + rng_.next_double() * m.jitter / m.min_samples
                           : rng_.next_double();
      Color c, od;
      sample(iv, f, c, od);
      iv.emitted += c * exp_neg(od * f);
      iv.optical += od;
      ++iv.samples;
    }
  }

 private:
  /// POV-Ray's recursive midpoint refinement (media.cpp, ComputeOneMediaSampleRecursive), with its weights.
  void refine(const Interval& iv, double d1, double d3, const Color& c1, const Color& c3, const Color& od1,
              const Color& od3, int depth, Color& result, Color& result_od) {
    const double d2 = 0.5 * (d1 + d3) + lead_->jitter * (d3 - d1) * (rng_.next_double() - 0.5);
    Color c2, od2;
    sample(iv, d2, c2, od2);
    if (depth <= 0) {
      result = (c1 + c2 + c3) / 3.0;
      result_od = (od1 + od2 + od3) / 3.0;
      return;
    }
    Color r2, o2;
    if (colour_distance(c1, c2) > aa_threshold_) {
      refine(iv, d1, 0.5 * (d1 + d3), c1, c2, od1, od2, depth - 1, r2, o2);
      result = r2 / 2.0;
      result_od = o2 / 2.0;
    } else {
      result = c1 / 3.0 + c2 / 6.0;
      result_od = od1 / 3.0 + od2 / 6.0;
    }
    if (colour_distance(c2, c3) > aa_threshold_) {
      refine(iv, 0.5 * (d1 + d3), d3, c2, c3, od2, od3, depth - 1, r2, o2);
      result += r2 / 2.0;
      result_od += o2 / 2.0;
    } else {
      result += c2 / 6.0 + c3 / 3.0;
      result_od += od2 / 6.0 + od3 / 3.0;
    }
  }

  const std::vector<const Media*>& media_;
  const std::vector<LitLight>& lights_;
  const math::Ray& ray_;
  math::Pcg32& rng_;
  const LightSampler& light_at_;
  const Media* lead_;  // the medium with the most intervals, which sets the sampling
  double aa_threshold_ = 1e300;
};

bool all_constant(const std::vector<const Media*>& media) {
  return std::all_of(media.begin(), media.end(), [](const Media* m) { return m->densities.empty(); });
}

}  // namespace

bool light_interval(const scene::Light& light, const math::Ray& ray, double& t0, double& t1) {
  switch (light.kind) {
    case scene::Light::Kind::spotlight:
      return spot_interval(light, ray, t0, t1);
    case scene::Light::Kind::cylinder:
      return cylinder_interval(light, ray, t0, t1);
    case scene::Light::Kind::point:
    case scene::Light::Kind::parallel:
      break;
  }
  t0 = 0;
  t1 = math::kInfinity;
  return true;
}

MediaEffect media_along(const std::vector<const Media*>& media, const std::vector<scene::Light>& lights,
                        const math::Ray& ray, double depth, math::Pcg32& rng, const LightSampler& light_at) {
  MediaEffect effect;
  if (media.empty() || !(depth > 0)) return effect;
  const ScratchLease lease;
  MediaScratch& scratch = *lease;
  std::vector<LitLight>& lit = scratch.lit;
  lit.clear();
  for (const scene::Light& light : lights) {
    // A shadowless light is POV-Ray's fill light, a kind its media never gather light from (media.cpp,
    // ComputeOneMediaLightInterval knows point, spot and cylinder lights only).
    if (!light.media_interaction || light.shadowless) continue;
    double t0 = 0, t1 = 0;
    if (light_interval(light, ray, t0, t1) && t0 < depth && t1 > 1e-6)
      lit.push_back({&light, std::max(t0, 0.0), std::min(t1, depth)});
  }
  MediaSampler sampler(media, lit, ray, rng, light_at);
  lit_stretches(scratch, depth);
  sampling_intervals(scratch, sampler.lead(), all_constant(media));
  Color optical(0);
  for (Interval& iv : scratch.intervals) {
    if (sampler.lead().method == 3)
      sampler.adaptive(iv);
    else
      sampler.regular(iv);
    const double n = 1.0 / std::max(1, iv.samples);
    effect.emitted += iv.emitted * n * exp_neg(optical);
    optical += iv.optical * n;
  }
  effect.transmittance = exp_neg(optical);
  return effect;
}

Color media_transmittance(const std::vector<const Media*>& media, const math::Ray& ray, double depth) {
  if (media.empty() || !(depth > 0)) return Color(1);
  Color extinction(0);
  if (all_constant(media)) {
    for (const Media* m : media) extinction += m->extinction();
    return exp_neg(extinction * depth);
  }
  // Varying density, sampled as POV-Ray 3.7 samples a shadow ray (media.cpp, ComputeMedia without lights):
  // the lead medium's intervals, each its method's samples. Emission is not computed on shadow rays, so
  // method 3 never refines: each of its sub-intervals averages its two ends and its middle. Jitter is left
  // out (the grid it perturbs is kept), and method 1's random samples are taken stratified: the same mean,
  // without noise.
  const Media* lead = media.front();
  for (const Media* m : media)
    if (m->intervals > lead->intervals) lead = m;
  const int intervals = std::max(1, lead->intervals);
  const double ds = depth / intervals;
  auto extinction_at = [&](double t) {
    Color e(0);
    const Vec3 p = ray.at(t);
    for (const Media* m : media) e += (m->densities.empty() ? Color(1) : m->density_at(p)) * m->extinction();
    return e;
  };
  for (int i = 0; i < intervals; ++i) {
    const double s0 = i * ds;
    Color sum(0);
    if (lead->method == 3) {
      const int count = std::max(2, lead->min_samples / 2 + 1);
      const double dd = 1.0 / (count + 1);
      Color previous = extinction_at(s0);
      for (int j = 1; j <= count; ++j) {
        const Color next = extinction_at(s0 + j * dd * ds);
        sum += (previous + extinction_at(s0 + (j - 0.5) * dd * ds) + next) / 3.0;
        previous = next;
      }
      extinction += sum / count;
    } else {
      const int samples = std::max(1, lead->min_samples);
      for (int j = 0; j < samples; ++j) sum += extinction_at(s0 + (j + 0.5) / samples * ds);
      extinction += sum / samples;
    }
  }
  return exp_neg(extinction * ds);
}

}  // namespace snell::render
