#pragma once
// Up to eight triangles in single precision, laid out for SIMD tests (one lane per triangle), and the
// conservative test of a ray against all of them: a filter in front of the double-precision test
// (triangle_kernel.hpp), which decides hits, so that results stay those of the double test. The one
// exception is a clear hit (see candidates_among with `clear`), which the same error bounds, read the other
// way, show the double test would take: an occlusion query may stop on it untested.
//
// The filter is the watertight test of Woop, Benthin and Wald ("Watertight ray/triangle intersection",
// JCGT 2(1), 2013): vertices relative to the ray origin are sheared so that the ray runs along +z, and the
// ray meets the triangle when the three 2D edge functions U, V, W share a sign. Its hit distance is a
// convex combination of the vertices' sheared depths, so the hit lies between the nearest and the
// farthest vertex depth: that range, not a division, culls by the ray's window.
//
// Why nothing the double test accepts is dropped: with u = 2^-24, R the largest |coordinate| of the
// block's vertices plus that of the ray origin, and float rounding to nearest,
//  - each translated coordinate (vertex and origin rounded to float, then subtracted) is within 2.01 u R
//    of the exact one, and each sheared coordinate (the shear factors dx/dz, dy/dz rounded, |dx/dz| <= 1
//    as z is the ray's largest axis) within delta = 8.2 u R (kShearError: 10 u R) of the exact shear by the
//    exact direction, in which the exact ray is the z axis;
//  - an edge function U = Cx By - Cy Bx then errs by at most delta S + 2 delta^2 + u S^2 / 2, where S is
//    the sum of the six |sheared x, y| (each factor pair's error, and three roundings of products of size
//    at most S^2 / 4); a lane is dropped only when some function is below -E and some above +E, E that
//    bound, so the exact functions cannot share a sign;
//  - S is bounded once per block, not per lane: a ray the double test can find a hit for passes through
//    (within its tiny error of) the box of the block's vertices, of longest side W, at some point e; a
//    sheared coordinate is the offset of a vertex p from the ray's point at p's depth along z, which lies
//    within |p_z - e_z| <= W of e in x and y (|dx/dz|, |dy/dz| <= 1), so each exact |sheared x, y| is at
//    most 2W and each computed one 2 (W + delta): S <= 12 (W + delta). Of a ray that passes nowhere near
//    the block the double test finds no hit, so dropping its lanes is right whatever the bound. (Summed
//    per lane, S cost eleven of about eighty instructions a block.)
//  - a sheared depth errs by at most 3.1 u R |1 / dz| + u |depth|, and the range is widened by more;
//  - the double test itself errs (it is Moeller-Trumbore in double, not the exact test): by about
//    35 * 2^-53 R L in an edge function (L the longest edge), which E also covers, and in its distance by
//    about 2^-53 R / sin(angle of the ray to the plane), under the depth margin unless the ray lies within
//    2^-20 of the triangle's plane. Such near edge-on lanes (|U + V + W| <= 2^-20 S^2 + 3 E, which holds
//    whenever the exact |U + V + W| is below 2^-20 S^2) are never dropped by depth, and entered at the
//    window's start. The sign test holds for them too: the double test's numerators of b1 and b2 are the
//    edge functions (scaled), within E of the exact ones, so where those clearly differ in sign b1 and b2
//    do, or (two clearly of one sign, the third clearly of the other) b1 + b2 exceeds 1 by more than its
//    roundings, whatever the sign and size of its near-zero determinant;
//  - the depth range's margins are folded into the window once per window (Window): a lane is dropped
//    when its nearest vertex depth lies beyond (t_max + D)(1 + 8u), D the depth error, or its farthest
//    before (t_min - D)(1 -+ 8u), which (roundings included) drops no lane that widening each depth by
//    2u |depth| + D and comparing with the window would keep.
// NaN and infinite values (huge vertices, rays float cannot hold) make every comparison that drops a lane
// fail, so such lanes are kept and the double test decides.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "snell/geometry/ray_box.hpp"
#include "snell/math/float_lanes.hpp"
#include "snell/math/ray.hpp"

namespace snell::geometry {

/// Five cache lines: the first holds the scalars (read first: the accelerator's ray-kind tag), the other
/// four and a half the vertices, each row of eight floats 32-byte aligned for whole-register loads. The
/// triangles are numbered by the owner consecutively (lane l holds triangle first + l), so no ids are
/// stored: a sixth line per block was a sixth more memory to fetch for each block a ray visits.
struct alignas(64) TriangleBlock {
  static constexpr int kSize = 8;
  /// Error scales over the block's triangles: the largest |vertex coordinate| and the longest edge
  /// (infinite where a vertex is beyond float's range: then no lane is ever dropped).
  float magnitude = 0;
  float longest_edge = 0;
  /// The longest side of the box around the block's vertices (rounded up; infinite like the two above):
  /// it bounds how far from the ray a vertex can be in the sheared frame, for every ray that passes near
  /// the block (the filter's error bound).
  float extent = 0;
  /// Lanes in use: 0 .. count - 1.
  uint32_t count = 0;
  /// 32 bits of the owner's (the accelerator keeps which ray kinds see each triangle).
  uint32_t tag = 0;
  /// The owner's number of the triangle in lane 0.
  uint32_t first = 0;
  /// Lanes whose double test runs on the very vertices stored here (set by the owner: no transform
  /// between them), so that the filter's clear hits may stand for it (TriangleRay::Lanes, `clear`).
  uint8_t decisive = 0;
  /// Vertex k's coordinate a of triangle l is v[k][a][l], rounded to the nearest float.
  alignas(32) float v[3][3][kSize] = {};

  /// Puts triangle (a, b, c) in the next lane: the owner's triangle first + count.
  void add(const math::Vec3& a, const math::Vec3& b, const math::Vec3& c) {
    const math::Vec3* vertex[3] = {&a, &b, &c};
    const int lane = static_cast<int>(count++);
    for (int k = 0; k < 3; ++k) {
      for (int axis = 0; axis < 3; ++axis) {
        const double x = (*vertex[k])[axis];
        v[k][axis][lane] = static_cast<float>(x);
        magnitude = std::abs(x) < 1e30 ? std::max(magnitude, float_above(std::abs(x))) : INFINITY;
      }
      const double edge = length(*vertex[(k + 1) % 3] - *vertex[k]);
      longest_edge = std::max(longest_edge, edge < 1e30 ? float_above(edge) : INFINITY);
    }
    for (int axis = 0; axis < 3; ++axis) {
      double lo = INFINITY, hi = -INFINITY;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < static_cast<int>(count); ++l) {
          lo = std::min(lo, static_cast<double>(v[k][axis][l]));
          hi = std::max(hi, static_cast<double>(v[k][axis][l]));
        }
      extent = std::max(extent, hi - lo < 1e30 ? float_above(hi - lo) : INFINITY);
    }
  }
};

static_assert(sizeof(TriangleBlock) == 5 * 64, "five cache lines");

/// The largest error scales over an owner's blocks (TriangleBlock::magnitude and longest_edge): the filter's
/// error terms grow with both, so terms computed from these once per ray hold for every block, and spare
/// each block their arithmetic. Not usable (finite() false) where a vertex lies beyond float's range.
struct TriangleScales {
  float magnitude = 0;
  float longest_edge = 0;
  void include(const TriangleBlock& b) {
    magnitude = std::max(magnitude, b.magnitude);
    longest_edge = std::max(longest_edge, b.longest_edge);
  }
  bool finite() const { return std::isfinite(magnitude) && std::isfinite(longest_edge); }
};

/// One ray prepared for TriangleBlock tests: its largest axis, shear and origin in float.
class TriangleRay {
 public:
  explicit TriangleRay(const math::Ray& ray) {
    const math::Vec3& d = ray.direction;
    const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    kz_ = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    kx_ = (kz_ + 1) % 3;
    ky_ = (kx_ + 1) % 3;
    const double dz = d[kz_];
    const double inverse = 1 / dz;
    for (int a = 0; a < 3; ++a) origin_[a] = static_cast<float>(ray.origin[a]);
    // One rounding of the largest |coordinate| (rounding up keeps the order); a NaN stays NaN, which
    // float_above makes infinite.
    const math::Vec3& o = ray.origin;
    const double largest = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)});
    origin_magnitude_ = float_above(std::isnan(o.x + o.y + o.z) ? NAN : largest);
    shear_x_ = static_cast<float>(d[kx_] * inverse);
    shear_y_ = static_cast<float>(d[ky_] * inverse);
    depth_scale_ = static_cast<float>(inverse);
    // Rays float cannot represent (origins beyond 1e30, a zero, NaN or tiny direction): every lane kept.
    usable_ = origin_magnitude_ < 1e30f && std::abs(inverse) < 1e30 && std::isfinite(d[kx_] + d[ky_]);
  }

  bool usable() const { return usable_; }

  /// Bit l set when the ray may meet lane l's triangle with t in [t_min, t_max] (floats rounded outward
  /// from the window); entry[l] is then a lower bound of that t. L lanes per instruction.
  template <int WideL>
  SNELL_LANES_INLINE unsigned candidates(const TriangleBlock& b, float t_min, float t_max,
                                         float (&entry)[TriangleBlock::kSize]) const {
    return Lanes<WideL>(*this).candidates(b, t_min, t_max, entry);
  }

  /// The ray's values spread over the lanes once, for a walk that filters many blocks (as
  /// FloatSlabs::Lanes): per block only its loads and arithmetic remain.
  template <int WideL>
  class Lanes {
   public:
    static constexpr int L = WideL < TriangleBlock::kSize ? WideL : TriangleBlock::kSize;
    using F = typename math::lanes::Lanes<L>::F;
    using M = typename math::lanes::Lanes<L>::M;

    SNELL_LANES_INLINE explicit Lanes(const TriangleRay& ray)
        : origin_magnitude_(ray.origin_magnitude_),
          depth_scale_magnitude_(std::abs(ray.depth_scale_)),
          usable_(ray.usable_) {
      using math::lanes::splat;
      const int axis[3] = {ray.kx_, ray.ky_, ray.kz_};
      for (int i = 0; i < 3; ++i) {
        row_offset_[i] = axis[i] * static_cast<std::ptrdiff_t>(sizeof(Row));
        splat(origin_[i], ray.origin_[axis[i]]);
      }
      splat(shear_x_, ray.shear_x_);
      splat(shear_y_, ray.shear_y_);
      splat(depth_scale_, ray.depth_scale_);
    }

    /// TriangleRay::candidates.
    SNELL_LANES_INLINE unsigned candidates(const TriangleBlock& b, float t_min, float t_max,
                                           float (&entry)[TriangleBlock::kSize]) const {
      return candidates_among(b, (1u << b.count) - 1, t_min, t_max, entry);
    }

    /// The filter's error terms for this ray and blocks of the given scales (or any smaller ones).
    struct Errors {
      float shear, edge_constant, depth;
    };
    SNELL_LANES_INLINE Errors errors(float magnitude, float longest_edge) const {
      constexpr float u = 0x1p-24f;
      const float r = magnitude + origin_magnitude_;
      const float shear = 10 * u * r;
      // The constant part of the edge function bound: 2 delta^2, and the double test's own error.
      return {shear, 2 * shear * shear + 0x1p-40f * r * longest_edge, 3.5f * u * r * depth_scale_magnitude_};
    }

    /// candidates() restricted to the lanes set in `lanes` (a subset of those in use): for an owner that
    /// keeps such a mask per block anyway (the scene BVH's lanes visible to each ray kind), which spares the
    /// mask of the lanes in use.
    SNELL_LANES_INLINE unsigned candidates_among(const TriangleBlock& b, unsigned lanes, float t_min,
                                                 float t_max, float (&entry)[TriangleBlock::kSize]) const {
      return candidates_among(b, lanes, t_min, t_max, entry, errors(b.magnitude, b.longest_edge));
    }

    /// The window [t_min, t_max] and the bounds on a lane's raw vertex depths that it implies with the
    /// depth error of `errors` (see the comment at the top): made once per window, not per block.
    /// clear_low and clear_high bound a lane's raw vertex depths for a clear hit: twice the depth error
    /// inside the window, and 16 u of relative slack for the widening by 2 u |depth| and the roundings
    /// of these sums (t_max here rounded up: the slack and the second depth error cover that ulp).
    struct Window {
      float t_min;
      float depth_low, depth_high;
      float clear_low, clear_high;
    };
    static Window window(float t_min, float t_max, const Errors& errors) {
      constexpr float u = 0x1p-24f;
      const float before = t_min - errors.depth;
      const float clear_low = t_min + 2 * errors.depth, clear_high = t_max - 2 * errors.depth;
      return {t_min, before * (before >= 0 ? 1 - 8 * u : 1 + 8 * u), (t_max + errors.depth) * (1 + 8 * u),
              clear_low * (clear_low >= 0 ? 1 + 16 * u : 1 - 16 * u),
              clear_high > 0 ? clear_high * (1 - 16 * u) : -INFINITY};
    }

    /// A window kept for a walk whose t_max only drops on hits: remade when t_max changes.
    class WindowOnChange {
     public:
      WindowOnChange(float t_min, double t_max, const Errors& errors)
          : errors_(errors), t_max_(t_max), window_(window(t_min, float_above(t_max), errors)) {}
      const Window& operator()(double t_max) {
        if (t_max != t_max_) {
          t_max_ = t_max;
          window_ = window(window_.t_min, float_above(t_max), errors_);
        }
        return window_;
      }

     private:
      Errors errors_;
      double t_max_;
      Window window_;
    };

    /// candidates_among with error terms computed by errors() for scales at least the block's own (once per
    /// ray, for all blocks of an owner: TriangleScales).
    SNELL_LANES_INLINE unsigned candidates_among(const TriangleBlock& b, unsigned lanes, float t_min,
                                                 float t_max, float (&entry)[TriangleBlock::kSize],
                                                 const Errors& errors) const {
      return candidates_among(b, lanes, window(t_min, t_max, errors), entry, errors);
    }

    /// candidates_among over a window made by window() with the same error terms.
    SNELL_LANES_INLINE unsigned candidates_among(const TriangleBlock& b, unsigned lanes, const Window& w,
                                                 float (&entry)[TriangleBlock::kSize],
                                                 const Errors& errors) const {
      unsigned unused;
      return filter<false>(b, lanes, w, entry, errors, unused);
    }

    /// The same, and `clear` the kept lanes of b.decisive that the double test is sure to hit within the
    /// window: all three edge functions beyond the bound on one side (the double test's numerators of b1,
    /// b2 and 1 - b1 - b2 then share their sign, the argument of the comment at the top read the other
    /// way), the ray not near edge-on, and all vertex depths inside the window by twice the depth error
    /// (the double test's distance lies within the exact depths by less than one). An occlusion query
    /// takes such a lane's object without the double test and its read of the triangle's record.
    SNELL_LANES_INLINE unsigned candidates_among(const TriangleBlock& b, unsigned lanes, const Window& w,
                                                 float (&entry)[TriangleBlock::kSize], const Errors& errors,
                                                 unsigned& clear) const {
      clear = 0;
      const unsigned kept = filter<true>(b, lanes, w, entry, errors, clear);
      clear &= kept & b.decisive;
      return kept;
    }

    /// The same with the block's own error terms (as the candidates_among of t_min, t_max above).
    SNELL_LANES_INLINE unsigned candidates_among(const TriangleBlock& b, unsigned lanes, float t_min,
                                                 float t_max, float (&entry)[TriangleBlock::kSize],
                                                 unsigned& clear) const {
      const Errors own = errors(b.magnitude, b.longest_edge);
      return candidates_among(b, lanes, window(t_min, t_max, own), entry, own, clear);
    }

   private:
    template <bool kClear>
    SNELL_LANES_INLINE unsigned filter(const TriangleBlock& b, unsigned lanes, const Window& w,
                                       float (&entry)[TriangleBlock::kSize], const Errors& errors,
                                       unsigned& clear) const {
      if (!usable_) {
        for (float& e : entry) e = -INFINITY;
        return lanes;
      }
      using math::lanes::load;
      using math::lanes::splat;
      constexpr float u = 0x1p-24f;
      const float shear_error = errors.shear, depth_error = errors.depth;
      // S, E and the edge-on threshold for the whole block (see the comment at the top); S slightly
      // enlarged, for the roundings of these few scalar operations.
      const float s = (12 * (1 + 0x1p-20f)) * (b.extent + shear_error);
      const float bound_scalar = s * (shear_error + u * s) + errors.edge_constant;
      F bound, edge_on_threshold;
      splat(bound, bound_scalar);
      splat(edge_on_threshold, s * s * 0x1p-20f + 3 * bound_scalar);
      const float t_min = w.t_min;
      unsigned mask = 0;
      for (int first = 0; first < TriangleBlock::kSize; first += L) {
        F x[3], y[3], z[3];
        for (int k = 0; k < 3; ++k) {
          F px, py, pz;
          const char* rows = reinterpret_cast<const char*>(b.v[k]);
          load(px, reinterpret_cast<const float*>(rows + row_offset_[0]) + first);
          load(py, reinterpret_cast<const float*>(rows + row_offset_[1]) + first);
          load(pz, reinterpret_cast<const float*>(rows + row_offset_[2]) + first);
          pz -= origin_[2];
          x[k] = (px - origin_[0]) - shear_x_ * pz;
          y[k] = (py - origin_[1]) - shear_y_ * pz;
          z[k] = depth_scale_ * pz;
        }
        const F e_u = x[2] * y[1] - y[2] * x[1];
        const F e_v = x[0] * y[2] - y[0] * x[2];
        const F e_w = x[1] * y[0] - y[1] * x[0];
        // Some function clearly negative and some clearly positive: the exact ones cannot share a sign
        // (the least below -bound and the greatest above it: four minps / maxps instead of six compares
        // and four ors; each minimum and maximum with a comparison of its own, as GCC turned one shared
        // comparison into a compare and two blends).
        const F least_uv = e_u < e_v ? e_u : e_v, greatest_uv = e_v < e_u ? e_u : e_v;
        const F least = e_w < least_uv ? e_w : least_uv, greatest = e_w < greatest_uv ? greatest_uv : e_w;
        const M negative = least < -bound;
        const M positive = greatest > bound;
        const F det = e_u + e_v + e_w;
        const M edge_on = (F)((M)det & INT32_MAX) <= edge_on_threshold;
        const F near = z[0] < z[1] ? z[0] : z[1], far = z[1] < z[0] ? z[0] : z[1];
        F lowest = z[2] < near ? z[2] : near;
        const F highest = z[2] < far ? far : z[2];
        const M beyond = (lowest > w.depth_high) | (highest < w.depth_low);
        const M dropped = (negative & positive) | (beyond & ~edge_on);
        const unsigned kept = ~math::lanes::bits(dropped) & ((1u << L) - 1);
        // Entries only where a lane is kept (most blocks keep none): the nearest depth widened by its
        // error, and edge-on lanes, which may hit anywhere along the window, at its start.
        if (kept != 0) {
          if constexpr (kClear) {
            F clear_low, clear_high;
            splat(clear_low, w.clear_low);
            splat(clear_high, w.clear_high);
            const M inside = (least > bound) | (greatest < -bound);
            const M sure = inside & ~edge_on & (lowest > clear_low) & (highest < clear_high);
            clear |= (math::lanes::bits(sure) & ((1u << L) - 1)) << first;
          }
          lowest -= (F)((M)lowest & INT32_MAX) * (2 * u) + depth_error;
          const F low = (F)(((M)lowest & ~edge_on) | ((M)(t_min - F{}) & edge_on));
          math::lanes::store(entry + first, low);
        }
        mask |= kept << first;
      }
      return mask & lanes;
    }

    /// The byte offsets within a vertex's rows of the ray's sheared x, y and its z axis (added to the
    /// vertex's address: a row index cost a sign extension and a shift per load), and the origin in those
    /// rows.
    using Row = float[TriangleBlock::kSize];
    std::ptrdiff_t row_offset_[3];
    F origin_[3];
    F shear_x_, shear_y_, depth_scale_;
    float origin_magnitude_, depth_scale_magnitude_;
    bool usable_;
  };

 private:
  float origin_[3] = {};
  float origin_magnitude_ = 0;
  float shear_x_ = 0, shear_y_ = 0, depth_scale_ = 0;
  int kx_ = 0, ky_ = 1, kz_ = 2;
  bool usable_ = true;
};

}  // namespace snell::geometry
