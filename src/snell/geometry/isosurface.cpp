#include "snell/geometry/isosurface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "snell/geometry/lipschitz_march.hpp"
#include "snell/math/constants.hpp"

namespace snell::geometry {

namespace {

/// A stretch of a ray that a march proved free of roots, in the isosurface's own space: a ray that runs
/// back along it need not march again. The case that pays is a light at the camera (a common headlight):
/// its shadow ray from a surface point retraces, in reverse, the camera ray that found the point, and
/// without this would march the whole way back to the container. Kept per thread, the last four marches
/// of any isosurface (a camera ray, then a shadow ray for each of a few lights); a shadow ray follows its
/// camera ray in the same thread.
struct ProvenSegment {
  std::uint64_t owner = 0;     // the isosurface's id (0: empty); not its address, which a later one may reuse
  Vec3 a, ab;                  // from end a to end a + ab
  double inverse_length2 = 0;  // 1 / |ab|^2
  bool negative = false;       // f < threshold along it (the inside)

  /// Whether p lies within `tolerance` of the segment.
  bool near(const Vec3& p, double tolerance) const {
    const double s = std::clamp(dot(p - a, ab) * inverse_length2, 0.0, 1.0);
    return length_squared(p - (a + ab * s)) <= tolerance * tolerance;
  }
};

constexpr std::size_t kProvenSegments = 4;

struct ProvenSegments {
  std::array<ProvenSegment, kProvenSegments> entries;
  std::size_t next = 0;  // the entry to overwrite
};

thread_local ProvenSegments proven_segments;

std::atomic<std::uint64_t> next_isosurface_id{1};

}  // namespace

Isosurface::Isosurface(IsosurfaceSettings settings)
    : settings_(std::move(settings)), id_(next_isosurface_id.fetch_add(1, std::memory_order_relaxed)) {
  if (!settings_.function) throw std::invalid_argument("isosurface: missing function");
  if (settings_.function->arity() != 3)
    throw std::invalid_argument("isosurface: the function must take three arguments (x, y, z)");
  if (!settings_.container) throw std::invalid_argument("isosurface: missing container");
  if (!(settings_.accuracy > 0)) throw std::invalid_argument("isosurface: accuracy must be positive");
  if (!(settings_.max_gradient > 0)) throw std::invalid_argument("isosurface: max_gradient must be positive");
  if (settings_.max_trace < 1) settings_.max_trace = 1;
}

Bounds3 Isosurface::bounds() const {
  return settings_.container->bounds();
}

double Isosurface::field(const Vec3& p) const {
  const double args[3] = {p.x, p.y, p.z};
  return settings_.function->call(args) - settings_.threshold;
}

void Isosurface::note_slope(double slope) const {
  double seen = steepest_.load(std::memory_order_relaxed);
  while (slope > seen && !steepest_.compare_exchange_weak(seen, slope, std::memory_order_relaxed)) {
  }
}

LocalHit Isosurface::surface_hit(const Ray& ray, double t, function::Function::LaneBatch* batch) const {
  // Forward differences with step `accuracy`, as POV-Ray's IsoSurface::Normal: f grows outwards. The
  // four samples are evaluated together, as four lanes of one run of the function's code (the march's
  // batch where it has one: its constants are in place already).
  LocalHit hit;
  hit.t = t;
  const Vec3 p = ray.at(t);
  const double h = settings_.accuracy;
  const double xs[4] = {p.x, p.x + h, p.x, p.x}, ys[4] = {p.y, p.y, p.y + h, p.y},
               zs[4] = {p.z, p.z, p.z, p.z + h};
  double f[4];
  if (batch) {
    constexpr std::size_t kLanes = function::Function::kMaxLanes;
    const double* const samples[3] = {xs, ys, zs};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t l = 0; l < kLanes; ++l) batch->argument(i)[l] = samples[i][l < 4 ? l : 0];
    const double* values = batch->run();
    for (std::size_t l = 0; l < 4; ++l) f[l] = values[l];
  } else {
    const double* const args[3] = {xs, ys, zs};
    settings_.function->call_lanes(args, 4, f);
  }
  hit.normal = {f[1] - f[0], f[2] - f[0], f[3] - f[0]};
  if (!(length_squared(hit.normal) > 0) || !is_finite(hit.normal)) hit.normal = -ray.direction;
  return hit;
}

template <bool kNormals, typename Sink>
void Isosurface::trace(const Ray& ray, double t_min, double t_max, int limit, Sink&& sink) const {
  const Shape& box = *settings_.container;
  double entry_t, exit_t;  // where the ray enters and leaves the container (a graze does neither)
  if (!box.span(ray, entry_t, exit_t)) return;
  const double lo = std::max(entry_t, t_min), hi = std::min(exit_t, t_max);
  if (!(lo < hi)) return;
  // The container's own crossings, with their normals, for the rare ray whose inside reaches a wall.
  const auto entry = [&] {
    LocalHit h;
    box.intersect(ray, -math::kInfinity, math::kInfinity, h);
    return h;
  };
  const auto exit = [&] {
    LocalHit h;
    box.intersect(ray, entry_t, math::kInfinity, h);
    return h;
  };

  const double speed = length(ray.direction);  // local length per unit of t
  const double accuracy = settings_.accuracy;  // in t, as POV-Ray compares ray-parameter intervals
  const double lipschitz = settings_.max_gradient * speed;  // bound on |dg/dt|
  // Counted per ray and added to the shared counts once, when the trace ends.
  struct Count {
    const Isosurface& iso;
    std::uint64_t n = 0, hits = 0;
    ~Count() {
      if (!iso.settings_.count_work) return;
      iso.evaluations_.fetch_add(n, std::memory_order_relaxed);
      iso.hits_.fetch_add(hits, std::memory_order_relaxed);
      iso.rays_.fetch_add(1, std::memory_order_relaxed);
    }
  } evaluations{*this};
  const auto g = [&](double t) {
    ++evaluations.n;
    return field(ray.at(t));
  };
  int found = 0;

  double t = lo, gt = g(t);
  bool stepped_off = false;
  if (entry_t > t_min) {
    // The ray enters the container: where the inside reaches the container wall, the wall is the surface.
    if (!settings_.open && gt < 0) {
      sink(entry());
      if (++found >= limit) return;
    }
  } else if (std::fabs(gt) < 4 * lipschitz * accuracy) {
    // The ray starts on the surface (a shadow or reflected ray leaving it): step off it first, as POV-Ray
    // does, so that the root it came from is not found again.
    t = std::min(lo + 5 * accuracy, hi);
    stepped_off = true;
  }

  // Both ends of what is left within a hair (far below the accuracy) of a stretch already proved free of
  // roots: so is all of it, as the distance to a segment is convex. The ray's answer is that stretch's.
  // Only rays that start on the surface look (a ray from outside retraces nothing in practice).
  if (stepped_off) {
    const double hair = 1e-4 * accuracy * speed;
    const Vec3 from = ray.at(t), to = ray.at(hi);
    for (const ProvenSegment& p : proven_segments.entries) {
      if (p.owner != id_ || !p.near(from, hair) || !p.near(to, hair)) continue;
      if (!settings_.open && exit_t < t_max && p.negative) sink(exit());
      return;
    }
    gt = g(t);
  }

  // A function whose code runs on whole SIMD registers is evaluated at several points of the ray at once
  // (about the cost of one point); any other (natives such as noise run lane by lane) one point at a time.
  constexpr int kLanes = static_cast<int>(function::Function::kMaxLanes);

  // Roots refined to `accuracy`, as POV-Ray subdivides to it (reference, "accuracy"): the march brackets a
  // root within its minimum step, `accuracy`, so a bracket is refined by the secant through its ends alone,
  // with no further evaluation (a tenth of it took 3.3 more evaluations a root; isosurfaces.pov -5.5%
  // instructions, its SSIM to POV-Ray's image 0.99989 either way).
  const MarchSettings march{lipschitz, accuracy, accuracy};
  bool more = true;
  double steepest = 0;  // per ray, so the shared maximum is touched once per ray
  const double start = t;
  const bool start_negative = gt < 0;
  double first_root = hi;                          // where the stretch proved free of roots ends
  function::Function::LaneBatch* batch = nullptr;  // the march's, when it evaluates 8 points at once
  const auto on_root = [&](double root) {
    ++evaluations.hits;
    first_root = std::min(first_root, root);
    if constexpr (kNormals) {
      evaluations.n += 4;  // the normal's samples
      sink(surface_hit(ray, root, batch));
    } else {
      LocalHit h;
      h.t = root;
      sink(h);
    }
    more = ++found < limit;
    return more;
  };
  const auto on_slope = [&](double slope) { steepest = std::max(steepest, slope); };
  if (settings_.function->vectorised()) {
    // The points go straight into the function's registers (its constants filled once per ray).
    function::Function::LaneBatch lanes(*settings_.function);
    batch = &lanes;
    const auto g_lanes = [&](const double* __restrict ts, int n, double* __restrict out) {
      evaluations.n += static_cast<std::uint64_t>(n);
      // All lanes filled (ts repeats its last point past n): whole registers cost the same.
      double* __restrict xs = lanes.argument(0);
      double* __restrict ys = lanes.argument(1);
      double* __restrict zs = lanes.argument(2);
      const Vec3 o = ray.origin, d = ray.direction;  // locals: the stores below cannot alias them
      for (int i = 0; i < kLanes; ++i) xs[i] = o.x + ts[i] * d.x;
      for (int i = 0; i < kLanes; ++i) ys[i] = o.y + ts[i] * d.y;
      for (int i = 0; i < kLanes; ++i) zs[i] = o.z + ts[i] * d.z;
      const double* f = lanes.run();
      const double threshold = settings_.threshold;
      for (int i = 0; i < kLanes; ++i) out[i] = f[i] - threshold;
    };
    gt = march_roots_lanes<kLanes>(g, g_lanes, t, gt, hi, march, on_root, on_slope);
  } else {
    gt = march_roots(g, t, gt, hi, march, on_root, on_slope);
  }
  note_slope(steepest / speed);
  // Short of the root by the accuracy, the distance within which the march places it.
  const double proven_end = first_root < hi ? first_root - accuracy : hi;
  if (proven_end > start) {
    ProvenSegment& p = proven_segments.entries[proven_segments.next];
    proven_segments.next = (proven_segments.next + 1) % kProvenSegments;
    const Vec3 a = ray.at(start), ab = ray.at(proven_end) - a;
    p = {id_, a, ab, 1 / length_squared(ab), start_negative};
  }
  if (!more) return;
  if (!settings_.open && exit_t < t_max && gt < 0) sink(exit());
}

bool Isosurface::intersect(const Ray& ray, double t_min, double t_max, LocalHit& hit) const {
  bool any = false;
  trace<true>(ray, t_min, t_max, 1, [&](const LocalHit& h) {
    hit = h;
    any = true;
  });
  return any;
}

void Isosurface::all_hits(const Ray& ray, double t_min, double t_max, HitList& hits) const {
  trace<true>(ray, t_min, t_max, settings_.max_trace, [&](const LocalHit& h) { hits.push_back(h); });
}

bool Isosurface::crosses(const Ray& ray, double t_min, double t_max) const {
  // A shadow ray needs no normal: its four samples were a sixth of a surface point's cost.
  bool any = false;
  trace<false>(ray, t_min, t_max, 1, [&](const LocalHit&) { any = true; });
  return any;
}

bool Isosurface::inside(const Vec3& p) const {
  return settings_.container->inside(p) && field(p) < 0;
}

double estimate_max_gradient(const function::Function& f, const Bounds3& box, double floor, double factor) {
  // A 24^3 lattice of forward differences: deterministic, and cheap next to rendering.
  constexpr int kSteps = 24;
  const Vec3 cell = box.extent() / kSteps;
  const auto eval = [&](const Vec3& p) {
    const double a[3] = {p.x, p.y, p.z};
    return f.call(a);
  };
  double steepest = 0;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j)
      for (int k = 0; k < kSteps; ++k) {
        const Vec3 p = box.lo + cell * Vec3(i, j, k);
        const double f0 = eval(p);
        const Vec3 grad = {(eval(p + Vec3(cell.x, 0, 0)) - f0) / cell.x,
                           (eval(p + Vec3(0, cell.y, 0)) - f0) / cell.y,
                           (eval(p + Vec3(0, 0, cell.z)) - f0) / cell.z};
        if (is_finite(grad)) steepest = std::max(steepest, length(grad));
      }
  return std::max(floor, steepest * factor);
}

}  // namespace snell::geometry
