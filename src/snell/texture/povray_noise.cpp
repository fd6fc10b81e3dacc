#include "snell/texture/povray_noise.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "snell/math/cpu.hpp"
#include "snell/math/simd.hpp"

namespace snell::texture {

namespace {

using math::Vec3;
namespace simd = math::simd;

// The 267 random coefficients POV-Ray's lattice noise draws from (data table "RTable" in POV-Ray 3.7's
// core/material/noise.cpp; POV-Ray also stores each value halved, which value_term below computes).
constexpr std::array<double, 267> kCoefficients = {
    -1,        0.604974,   -0.937102, 0.414115,   0.576226,  -0.0161593, 0.432334,  0.103685,   0.590539,
    0.0286412, 0.46981,    -0.84622,  -0.0734112, -0.304097, -0.40206,   -0.210132, -0.919127,  0.652033,
    -0.83151,  -0.183948,  -0.671107, 0.852476,   0.043595,  -0.404532,  0.75494,   -0.335653,  0.618433,
    0.605707,  0.708583,   -0.477195, 0.899474,   0.490623,  0.221729,   -0.400381, -0.853727,  -0.932586,
    0.659113,  0.961303,   0.325948,  -0.750851,  0.842466,  0.734401,   -0.649866, 0.394491,   -0.466056,
    -0.434073, 0.109026,   0.0847028, -0.738857,  0.241505,  0.16228,    -0.71426,  -0.883665,  -0.150408,
    -0.90396,  -0.686549,  -0.785214, 0.488548,   0.0246433, 0.142473,   -0.602136, 0.375845,   -0.00779736,
    0.498955,  -0.268147,  0.856382,  -0.386007,  -0.596094, -0.867735,  -0.570977, -0.914366,  0.28896,
    0.672206,  -0.233783,  0.94815,   0.895262,   0.343252,  -0.173388,  -0.767971, -0.314748,  0.824308,
    -0.342092, 0.721431,   -0.24004,  -0.63653,   0.553277,  0.376272,   0.158984,  -0.452659,  0.396323,
    -0.420676, -0.454154,  0.122179,  0.295857,   0.0664225, -0.202075,  -0.724788, 0.453513,   0.224567,
    -0.908812, 0.176349,   -0.320516, -0.697139,  0.742702,  -0.900786,  0.471489,  -0.133532,  0.119127,
    -0.889769, -0.23183,   -0.669673, -0.046891,  -0.803433, -0.966735,  0.475578,  -0.652644,  0.0112459,
    -0.730007, 0.128283,   0.145647,  -0.619318,  0.272023,  0.392966,   0.646418,  -0.0207675, -0.315908,
    0.480797,  0.535668,   -0.250172, -0.83093,   -0.653773, -0.443809,  0.119982,  -0.897642,  0.89453,
    0.165789,  0.633875,   -0.886839, 0.930877,   -0.537194, 0.587732,   0.722011,  -0.209461,  -0.0424659,
    -0.814267, -0.919432,  0.280262,  -0.66302,   -0.558099, -0.537469,  -0.598779, 0.929656,   -0.170794,
    -0.537163, 0.312581,   0.959442,  0.722652,   0.499931,  0.175616,   -0.534874, -0.685115,  0.444999,
    0.17171,   0.108202,   -0.768704, -0.463828,  0.254231,  0.546014,   0.869474,  0.875212,   -0.944427,
    0.130724,  -0.110185,  0.312184,  -0.33138,   -0.629206, 0.0606546,  0.722866,  -0.0979477, 0.821561,
    0.0931258, -0.972808,  0.0318151, -0.867033,  -0.387228, 0.280995,   -0.218189, -0.539178,  -0.427359,
    -0.602075, 0.311971,   0.277974,  0.773159,   0.592493,  -0.0331884, -0.630854, -0.269947,  0.339132,
    0.581079,  0.209461,   -0.317433, -0.284993,  0.181323,  0.341634,   0.804959,  -0.229572,  -0.758907,
    -0.336721, 0.605463,   -0.991272, -0.0188754, -0.300191, 0.368307,   -0.176135, -0.3832,    -0.749569,
    0.62356,   -0.573938,  0.278309,  -0.971313,  0.839994,  -0.830686,  0.439078,  0.66128,    0.694514,
    0.0565042, 0.54342,    -0.438804, -0.0228428, -0.687068, 0.857267,   0.301991,  -0.494255,  -0.941039,
    0.775509,  0.410575,   -0.362081, -0.671534,  -0.348379, 0.932433,   0.886442,  0.868681,   -0.225666,
    -0.062211, -0.0976425, -0.641444, -0.848112,  0.724697,  0.473503,   0.998749,  0.174701,   0.559625,
    -0.029099, -0.337392,  -0.958129, -0.659785,  0.236042,  -0.246937,  0.659449,  -0.027512,  0.821897,
    -0.226215, 0.0181735,  0.500481,  -0.420127,  -0.427878, 0.566186,
};

/// POV-Ray's table generator (the same LCG as its rand()); its tables take bits 16..30 of the state.
struct TableRandom {
  uint32_t state;
  int next() {
    state = state * 1812433253u + 12345u;
    return static_cast<int>((state >> 16) & 0x7FFF);
  }
};

/// Shuffled 0..4095, repeated twice so that sums of two entries index it directly (InitTextureTable).
struct LatticeHash {
  std::array<uint16_t, 8192> table{};
  LatticeHash() {
    for (int i = 0; i < 4096; ++i) table[i] = static_cast<uint16_t>(i);
    TableRandom random{0};
    for (int i = 4095; i >= 0; --i) std::swap(table[i], table[random.next() % 4096]);
    std::copy_n(table.begin(), 4096, table.begin() + 4096);
  }
  int pair(int a, int b) const { return table[table[a] ^ b]; }
  /// Index of the first of four coefficients for a hashed (x, y) column and the z cell.
  int coefficient(int xy_hash, int z) const { return table[xy_hash ^ z] & 0xFF; }
};

/// Perlin's 1985 gradient tables: 2048 unit gradients and a permutation, each followed by a copy of its
/// start (InitSolidNoise; the permutation loop reproduces POV-Ray's, which swaps every other entry and
/// starts at the slot past the end).
struct SolidNoiseTables {
  static constexpr int kEntries = 2048;
  std::array<int, 2 * (kEntries + 1)> permutation{};
  std::array<Vec3, 2 * (kEntries + 1)> gradients{};
  SolidNoiseTables() {
    TableRandom random{1};
    for (int i = 0; i < kEntries; ++i) {
      Vec3 v;
      double length_squared = 0;
      do {
        for (int j = 0; j < 3; ++j)
          v[j] = static_cast<double>(random.next() % (2 * kEntries) - kEntries) / kEntries;
        length_squared = dot(v, v);
      } while (length_squared > 1.0 || length_squared < 1.0e-5);
      gradients[i] = v / std::sqrt(length_squared);
    }
    for (int i = 0; i < kEntries; ++i) permutation[i] = i;
    for (int i = kEntries; i > 0; i -= 2) std::swap(permutation[i], permutation[random.next() % kEntries]);
    for (int i = 0; i < kEntries + 2; ++i) {
      permutation[kEntries + i] = permutation[i];
      gradients[kEntries + i] = gradients[i];
    }
  }
};

const LatticeHash& lattice_hash() {
  static const LatticeHash hash;
  return hash;
}

const SolidNoiseTables& solid_tables() {
  static const SolidNoiseTables tables;
  return tables;
}

double s_curve(double t) {
  return t * t * (3.0 - 2.0 * t);
}

/// One axis of the lattice: the cell (offset by 10000 and wrapped to 12 bits) and the position in it.
/// POV-Ray rounds negative coordinates within 1e-10 of an integer up to it ("JB fix").
struct LatticeAxis {
  int cell;
  double offset;
  explicit LatticeAxis(double x) {
    const double bounded = std::clamp(x, -1.0e9, 1.0e9);  // keeps the int conversion defined
    const int whole = bounded >= 0 ? static_cast<int>(bounded) : static_cast<int>(bounded - (1 - 1.0e-10));
    cell = (whole + 10000) & 0xFFF;
    offset = bounded - whole;
  }
};

/// The coefficient indices of the 8 corners of lattice cell (x, y, z), corner c = dx + 2 dy + 4 dz at
/// out[c * stride]: coefficient(pair(x + dx, y + dy), z + dz), each shared table entry read once.
inline void corner_indices(unsigned x, unsigned y, unsigned z, unsigned* out, size_t stride) {
  const std::uint16_t* t = lattice_hash().table.data();
  const unsigned x0 = t[x], x1 = t[x + 1];
  const unsigned column[4] = {t[x0 ^ y], t[x1 ^ y], t[x0 ^ (y + 1)], t[x1 ^ (y + 1)]};
  for (unsigned corner = 0; corner < 8; ++corner)
    out[corner * stride] = t[column[corner & 3] ^ (z + (corner >> 2))] & 0xFF;
}

/// The 8 corners of the lattice cell around a point: their coefficient indices, and per axis the S-curve
/// weights and offsets of the cell's two sides, from which each corner's weight and offset follow.
struct LatticeCell {
  unsigned index[8];
  double side_weight[3][2];  // axis a, side 0 or 1: 1 - s or s
  double side_offset[3][2];  // the point's offset from that side: o or o - 1
  explicit LatticeCell(const Vec3& p) {
    const LatticeAxis axes[3] = {LatticeAxis(p.x), LatticeAxis(p.y), LatticeAxis(p.z)};
    for (int a = 0; a < 3; ++a) {
      const double s = s_curve(axes[a].offset);
      side_weight[a][0] = 1 - s;
      side_weight[a][1] = s;
      side_offset[a][0] = axes[a].offset;
      side_offset[a][1] = axes[a].offset - 1;
    }
    corner_indices(static_cast<unsigned>(axes[0].cell), static_cast<unsigned>(axes[1].cell),
                   static_cast<unsigned>(axes[2].cell), index, 1);
  }
  /// Corner c = dx + 2 dy + 4 dz: its S-curve weight and the point's offset from it.
  double weight(int c) const {
    return side_weight[0][c & 1] * side_weight[1][(c >> 1) & 1] * side_weight[2][c >> 2];
  }
  Vec3 offset(int c) const {
    return {side_offset[0][c & 1], side_offset[1][(c >> 1) & 1], side_offset[2][c >> 2]};
  }
};

/// The linear function a corner contributes: half its first coefficient plus the next three times the
/// offset (POV-Ray's INCRSUM).
double value_term(unsigned k, const Vec3& d) {
  return 0.5 * kCoefficients[k] + kCoefficients[k + 1] * d.x + kCoefficients[k + 2] * d.y +
         kCoefficients[k + 3] * d.z;
}

double lattice_noise(const Vec3& p) {
  const LatticeCell cell(p);
  double sum = 0;
  for (int c = 0; c < 8; ++c) sum += cell.weight(c) * value_term(cell.index[c], cell.offset(c));
  return sum;
}

/// The lattice coefficients of corner index k as lattice_noise reads them, one row of four per index: half
/// the first (the halving is exact, so it is done once here), then the three slopes. Rows go up to index
/// 263 because DNoise's third component reads 8 entries further along than the noise (povray_dnoise).
struct CornerCoefficients {
  static constexpr int kRows = 256 + 8;
  alignas(32) std::array<std::array<double, 4>, kRows> rows;
  CornerCoefficients() {
    for (int k = 0; k < kRows; ++k)
      rows[k] = {0.5 * kCoefficients[k], kCoefficients[k + 1], kCoefficients[k + 2], kCoefficients[k + 3]};
  }
};

const CornerCoefficients& corner_coefficients() {
  static const CornerCoefficients c;
  return c;
}

/// Component j of the rows rows[index[l] + shift] for the W lanes l: out[j][l].
template <int W, typename V>
SNELL_SIMD_INLINE void gather_rows(const CornerCoefficients& c, const unsigned* index, unsigned shift,
                                   V (&out)[4]) {
  if constexpr (W == 4) {
    // Four rows, transposed.
    const V r0 = simd::load<V>(c.rows[index[0] + shift].data()),
            r1 = simd::load<V>(c.rows[index[1] + shift].data()),
            r2 = simd::load<V>(c.rows[index[2] + shift].data()),
            r3 = simd::load<V>(c.rows[index[3] + shift].data());
    using M = typename simd::Vec<W>::M;
    const V a = __builtin_shuffle(r0, r1, M{0, 4, 2, 6}), b = __builtin_shuffle(r0, r1, M{1, 5, 3, 7});
    const V e = __builtin_shuffle(r2, r3, M{0, 4, 2, 6}), f = __builtin_shuffle(r2, r3, M{1, 5, 3, 7});
    out[0] = __builtin_shuffle(a, e, M{0, 1, 4, 5});
    out[1] = __builtin_shuffle(b, f, M{0, 1, 4, 5});
    out[2] = __builtin_shuffle(a, e, M{2, 3, 6, 7});
    out[3] = __builtin_shuffle(b, f, M{2, 3, 6, 7});
  } else {
    // Two rows, each as two halves, transposed.
    using M = typename simd::Vec<W>::M;
    for (int half = 0; half < 2; ++half) {
      const V r0 = simd::load<V>(c.rows[index[0] + shift].data() + 2 * half),
              r1 = simd::load<V>(c.rows[index[1] + shift].data() + 2 * half);
      out[2 * half] = __builtin_shuffle(r0, r1, M{0, 2});
      out[2 * half + 1] = __builtin_shuffle(r0, r1, M{1, 3});
    }
  }
}

/// The lattice sums at the W points p[0..2][0..W): with Components = 1 lattice_noise, with 3 the three
/// components of povray_dnoise (component a reads its coefficients 4 a entries along). The same operations
/// in the same order as the scalar code on vectors of W points (math/simd.hpp), the table look-ups point
/// by point.
template <int W, int Components>
SNELL_SIMD_INLINE void lattice_sums_chunk(const double* const* p, double* const* out) {
  using V = typename simd::Vec<W>::V;
  using M = typename simd::Vec<W>::M;
  using I = typename simd::Vec<W>::I;
  const V zero{};
  // LatticeAxis on each axis: the cell and the offset in it.
  V offset[3], s[3];
  unsigned cell[3][W];
  for (int a = 0; a < 3; ++a) {
    const V x = simd::load<V>(p[a]);
    const V bounded = simd::select((M)(x < zero - 1.0e9), zero - 1.0e9,
                                   simd::select((M)(zero + 1.0e9 < x), zero + 1.0e9, x));
    const V shifted = simd::select((M)(bounded >= zero), bounded, bounded - (1 - 1.0e-10));
    const I whole = __builtin_convertvector(shifted, I);  // truncation, as static_cast<int>
    const I c = (whole + 10000) & 0xFFF;
    for (int l = 0; l < W; ++l) cell[a][l] = static_cast<unsigned>(c[l]);
    offset[a] = bounded - __builtin_convertvector(whole, V);
    s[a] = offset[a] * offset[a] * (3.0 - 2.0 * offset[a]);  // s_curve
  }
  // The corners' coefficient indices, as LatticeCell hashes them, index[corner][lane].
  unsigned index[8][W];
  for (int l = 0; l < W; ++l) corner_indices(cell[0][l], cell[1][l], cell[2][l], &index[0][l], W);
  const CornerCoefficients& k = corner_coefficients();
  const V one_minus[3] = {1.0 - s[0], 1.0 - s[1], 1.0 - s[2]};
  const V offset_minus[3] = {offset[0] - 1.0, offset[1] - 1.0, offset[2] - 1.0};
  V sum[Components] = {};
  for (int corner = 0; corner < 8; ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
    const V weight = (dx ? s[0] : one_minus[0]) * (dy ? s[1] : one_minus[1]) * (dz ? s[2] : one_minus[2]);
    for (int a = 0; a < Components; ++a) {
      V c[4];
      gather_rows<W>(k, index[corner], 4 * a, c);
      // value_term
      const V term = c[0] + c[1] * (dx ? offset_minus[0] : offset[0]) +
                     c[2] * (dy ? offset_minus[1] : offset[1]) + c[3] * (dz ? offset_minus[2] : offset[2]);
      sum[a] += weight * term;
    }
  }
  for (int a = 0; a < Components; ++a) simd::store(out[a], sum[a]);
}

/// lattice_sums_chunk over the first `count` of kNoiseLanes points, whole chunks of W (the inputs are
/// read up to the next multiple of W, so all kNoiseLanes entries must be set).
template <int W, int Components>
SNELL_SIMD_INLINE void lattice_sums_all(const double* x, const double* y, const double* z, double* const* out,
                                        int count) {
  for (int l = 0; l < count; l += W) {
    const double* const p[3] = {x + l, y + l, z + l};
    double* o[Components];
    for (int a = 0; a < Components; ++a) o[a] = out[a] + l;
    lattice_sums_chunk<W, Components>(p, o);
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
template <int Components>
[[gnu::target("avx2")]] void lattice_sums_avx2(const double* x, const double* y, const double* z,
                                               double* const* out, int count) {
  lattice_sums_all<4, Components>(x, y, z, out, count);
}
#endif

/// lattice_sums_chunk at the first `count` of kNoiseLanes points. Built for plain x86-64 and for AVX2
/// (twice the width), picked when the program starts; both give the scalar code's bits.
template <int Components>
void lattice_sums_lanes(const double* x, const double* y, const double* z, double* const* out,
                        int count = kNoiseLanes) {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = math::has_avx2();
  if (avx2) return lattice_sums_avx2<Components>(x, y, z, out, count);
#endif
  lattice_sums_all<2, Components>(x, y, z, out, count);
}

/// Perlin's 1985 noise ("SolidNoise"), about [-1, 1]; POV-Ray shifts coordinates by a large
/// non-integer so that negative ones need no special case.
double solid_noise(const Vec3& p) {
  constexpr double kRollover = 10000000.023157213;
  constexpr int kMask = SolidNoiseTables::kEntries - 1;
  const SolidNoiseTables& t = solid_tables();
  int b0[3], b1[3];
  double r0[3], s[3];
  for (int a = 0; a < 3; ++a) {
    const double shifted = p[a] + kRollover;
    const double whole = std::floor(shifted);
    b0[a] = static_cast<int>(static_cast<int64_t>(whole) & kMask);
    b1[a] = (b0[a] + 1) & kMask;
    r0[a] = shifted - whole;
    s[a] = s_curve(r0[a]);
  }
  const int i = t.permutation[b0[0]], j = t.permutation[b1[0]];
  const int column[2][2] = {{t.permutation[i + b0[1]], t.permutation[i + b1[1]]},
                            {t.permutation[j + b0[1]], t.permutation[j + b1[1]]}};
  const int z_cell[2] = {b0[2], b1[2]};
  auto corner = [&](int dx, int dy, int dz) {
    return dot(t.gradients[column[dx][dy] + z_cell[dz]], Vec3{r0[0] - dx, r0[1] - dy, r0[2] - dz});
  };
  auto lerp = [](double w, double a, double b) { return a + w * (b - a); };
  double face[2];
  for (int dz = 0; dz < 2; ++dz)
    face[dz] = lerp(s[1], lerp(s[0], corner(0, 0, dz), corner(1, 0, dz)),
                    lerp(s[0], corner(0, 1, dz), corner(1, 1, dz)));
  return lerp(s[2], face[0], face[1]);
}

/// The noise in [0, 1] from the lattice sum, for the original and range-corrected generators.
double lattice_to_unit(double sum, NoiseGenerator generator) {
  // Range corrected: POV-Ray's measured range of the raw sum, [-1.05242, 0.988997], mapped onto [0, 1].
  const double n = generator == NoiseGenerator::range_corrected ? (sum + 1.05242) * 0.48985582 : sum + 0.5;
  return std::clamp(n, 0.0, 1.0);
}

/// DNoise's coefficient rows of corner index k with the three components side by side: term j of
/// component a is entry k + 4a + j (each component draws 4 entries further along the table, POV-Ray's
/// DNoise), term 0 halved as value_term halves it; lane 3 is unused.
struct DNoiseCoefficients {
  alignas(32) std::array<std::array<std::array<double, 4>, 4>, 256> rows{};
  DNoiseCoefficients() {
    for (int k = 0; k < 256; ++k)
      for (int term = 0; term < 4; ++term)
        for (int axis = 0; axis < 3; ++axis)
          rows[k][term][axis] = (term == 0 ? 0.5 : 1.0) * kCoefficients[k + 4 * axis + term];
  }
};

const DNoiseCoefficients& dnoise_coefficients() {
  static const DNoiseCoefficients c;
  return c;
}

/// The DNoise sum over a cell's corners, the three components' value_terms as one 4-wide computation:
/// per lane the scalar operations in their order (no fused multiply-add, math/simd.hpp), so every build
/// gives the same bits.
SNELL_SIMD_INLINE Vec3 dnoise_sum_lanes(const LatticeCell& cell) {
  using V = simd::Vec<4>::V;
  const DNoiseCoefficients& k = dnoise_coefficients();
  V sum{};
  for (int c = 0; c < 8; ++c) {
    const auto& row = k.rows[cell.index[c]];
    const Vec3 d = cell.offset(c);
    const V term = simd::load<V>(row[0].data()) + simd::load<V>(row[1].data()) * d.x +
                   simd::load<V>(row[2].data()) * d.y + simd::load<V>(row[3].data()) * d.z;
    sum += cell.weight(c) * term;
  }
  return {sum[0], sum[1], sum[2]};
}

Vec3 dnoise_sum(const LatticeCell& cell) {
  return dnoise_sum_lanes(cell);
}

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] Vec3 dnoise_sum_avx2(const LatticeCell& cell) {
  return dnoise_sum_lanes(cell);
}
#endif

}  // namespace

double povray_noise(const Vec3& p, NoiseGenerator generator) {
  if (generator == NoiseGenerator::perlin) return std::clamp(0.5 * (1.59 * solid_noise(p) + 0.985), 0.0, 1.0);
  return lattice_to_unit(lattice_noise(p), generator);
}

void povray_noise_lanes(const double* x, const double* y, const double* z, double* out,
                        NoiseGenerator generator) {
  if (generator == NoiseGenerator::perlin) {
    for (int l = 0; l < kNoiseLanes; ++l) out[l] = povray_noise({x[l], y[l], z[l]}, generator);
    return;
  }
  double* const sums[1] = {out};
  lattice_sums_lanes<1>(x, y, z, sums);
  for (int l = 0; l < kNoiseLanes; ++l) out[l] = lattice_to_unit(out[l], generator);
}

namespace {

/// The points p * scales[i] for i < count (count <= kNoiseLanes) as three coordinate rows, the rest of
/// the kNoiseLanes lanes zero.
struct ScaledPoints {
  alignas(32) double x[kNoiseLanes] = {}, y[kNoiseLanes] = {}, z[kNoiseLanes] = {};
  ScaledPoints(const Vec3& p, const double* scales, int count) {
    for (int i = 0; i < count; ++i) {
      const Vec3 q = p * scales[i];
      x[i] = q.x, y[i] = q.y, z[i] = q.z;
    }
  }
};

}  // namespace

void povray_noise_scaled(const Vec3& p, const double* scales, int count, double* out,
                         NoiseGenerator generator) {
  for (int first = 0; first < count; first += kNoiseLanes) {
    const int n = std::min(kNoiseLanes, count - first);
    if (generator == NoiseGenerator::perlin) {
      for (int i = 0; i < n; ++i) out[first + i] = povray_noise(p * scales[first + i], generator);
      continue;
    }
    const ScaledPoints points(p, scales + first, n);
    alignas(32) double sums[kNoiseLanes];
    double* const rows[1] = {sums};
    lattice_sums_lanes<1>(points.x, points.y, points.z, rows, n);
    for (int i = 0; i < n; ++i) out[first + i] = lattice_to_unit(sums[i], generator);
  }
}

void povray_dnoise_scaled(const Vec3& p, const double* scales, int count, Vec3* out) {
  for (int first = 0; first < count; first += kNoiseLanes) {
    const int n = std::min(kNoiseLanes, count - first);
    const ScaledPoints points(p, scales + first, n);
    alignas(32) double sums[3][kNoiseLanes];
    double* const rows[3] = {sums[0], sums[1], sums[2]};
    lattice_sums_lanes<3>(points.x, points.y, points.z, rows, n);
    for (int i = 0; i < n; ++i) out[first + i] = Vec3{sums[0][i], sums[1][i], sums[2][i]};
  }
}

int povray_hash3d(int x, int y, int z) {
  const LatticeHash& hash = lattice_hash();
  return hash.table[hash.pair(x & 0xFFF, y & 0xFFF) ^ (z & 0xFFF)];
}

double povray_pattern_random(size_t index) {
  static const std::vector<double> table = [] {
    std::mt19937 twister;  // default seed, as boost's
    std::vector<double> t(32768);
    for (double& v : t) v = static_cast<double>(twister()) / 4294967296.0;
    return t;
  }();
  return table[index % table.size()];
}

Vec3 povray_point_in_cube(int x, int y, int z) {
  const auto seed = static_cast<size_t>(povray_hash3d(x, y, z));
  return {x + povray_pattern_random(seed), y + povray_pattern_random(seed + 1),
          z + povray_pattern_random(seed + 2)};
}

math::Vec2 povray_jitter2d(double x, double y) {
  static const std::array<double, 256> offsets = [] {
    std::array<double, 256> t{};
    for (unsigned i = 0; i < t.size(); ++i) {
      unsigned bits = 0;
      for (unsigned b = 0; b < 8; ++b)
        if ((i >> b) & 1) bits ^= 0x8002u ^ (3u << (b + 7));
      t[i] = bits / 65536.0 - 0.5;
    }
    return t;
  }();
  const LatticeHash& hash = lattice_hash();
  const auto pick = [&](double a, double ka, double b, double kb) {
    const int first = hash.table[static_cast<int>(a * ka) & 0xFFF];
    return offsets[hash.table[(first ^ static_cast<int>(b * kb)) & 0xFFF] & 0xFF];
  };
  return {pick(x, 1021.0, y, 1019.0), pick(x, 1019.0, y, 1021.0)};
}

Vec3 povray_dnoise(const Vec3& p) {
  const LatticeCell cell(p);
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = math::has_avx2();
  if (avx2) return dnoise_sum_avx2(cell);
#endif
  return dnoise_sum(cell);
}

double povray_turbulence(const Vec3& p, int octaves, double lambda, double omega, NoiseGenerator generator) {
  // Octave i (from 1) is the noise at p times lambda^(i-1), weighted by omega^(i-1); the first is kept as
  // it is. The powers are built by the same running products as POV-Ray's loop, so the sum has its bits.
  double value = 0, frequency = 1, weight = 1;
  const int total = std::max(octaves, 1);
  for (int first = 1; first <= total; first += kNoiseLanes) {
    const int n = std::min(kNoiseLanes, total - first + 1);
    double scales[kNoiseLanes], weights[kNoiseLanes], noise[kNoiseLanes];
    for (int i = 0; i < n; ++i, frequency *= lambda, weight *= omega)
      scales[i] = frequency, weights[i] = weight;
    povray_noise_scaled(p, scales, n, noise, generator);
    for (int i = 0; i < n; ++i) {
      const double v = noise[i];
      if (first + i == 1)
        value = generator == NoiseGenerator::original ? v : std::clamp(2.0 * v - 0.5, 0.0, 1.0);
      else
        value += weights[i] * (generator == NoiseGenerator::original ? v : 2.0 * v - 0.5);
    }
  }
  return value;
}

Vec3 povray_vector_turbulence(const Vec3& p, int octaves, double lambda, double omega) {
  // As povray_turbulence: octave i at p times lambda^(i-1), weighted by omega^(i-1), the first unweighted.
  // The lattice sums are read straight from their rows: an array of kNoiseLanes Vec3 was cleared for
  // every call (a `rep stos`, a third of this function in wood_1.pov's profile).
  Vec3 sum{0, 0, 0};
  double frequency = 1, weight = 1;
  const int total = std::max(octaves, 1);
  for (int first = 1; first <= total; first += kNoiseLanes) {
    const int n = std::min(kNoiseLanes, total - first + 1);
    double scales[kNoiseLanes], weights[kNoiseLanes];
    for (int i = 0; i < n; ++i, frequency *= lambda, weight *= omega)
      scales[i] = frequency, weights[i] = weight;
    const ScaledPoints points(p, scales, n);
    alignas(32) double sums[3][kNoiseLanes];
    double* const rows[3] = {sums[0], sums[1], sums[2]};
    lattice_sums_lanes<3>(points.x, points.y, points.z, rows, n);
    for (int i = 0; i < n; ++i) {
      const Vec3 noise{sums[0][i], sums[1][i], sums[2][i]};
      if (first + i == 1)
        sum = noise;
      else
        sum += noise * weights[i];
    }
  }
  return sum;
}

}  // namespace snell::texture
