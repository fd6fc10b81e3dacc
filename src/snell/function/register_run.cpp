// Evaluation of register code at one point and at several points at once.
#include <array>
#include <cmath>
#include <cstring>
#include <functional>

#include "snell/function/lane_math.hpp"
#include "snell/function/register_code.hpp"
#include "snell/function/register_step.hpp"

namespace snell::function {

namespace detail {

double call_with_registers(const RegisterInstruction& in, const double* r, const std::uint32_t* arguments) {
  std::array<double, 32> fixed;
  std::vector<double> heap;
  double* args = fixed.data();
  if (in.b > fixed.size()) {
    heap.resize(in.b);
    args = heap.data();
  }
  for (std::uint32_t i = 0; i < in.b; ++i) args[i] = r[arguments[in.a + i]];
  switch (in.op) {
    case Op::native:
      return in.native(args);
    case Op::call_component: {
      std::array<double, Function::kMaxComponents> out{};
      in.callee->call_vector(args, out.data());
      return out[in.component];
    }
    default:
      return in.callee->call(args);
  }
}

}  // namespace detail

double RegisterCode::run(const double* args) const {
  // Small codes (nearly all) run in a fixed register file; the rare large one on the heap. Not zeroed:
  // every register is written before it is read.
  constexpr std::size_t kFixed = 256;
  if (constants_.size() + arity_ + code_.size() <= kFixed) {
    std::array<double, kFixed> fixed;
    return run_in(fixed.data(), args);
  }
  std::vector<double> heap(constants_.size() + arity_ + code_.size());
  return run_in(heap.data(), args);
}

double RegisterCode::run_in(double* r, const double* args) const {
  // Plain loops: these copies are a few doubles, shorter than a call of memcpy.
  const std::size_t constants = constants_.size();
  for (std::size_t i = 0; i < constants; ++i) r[i] = constants_[i];
  for (std::size_t i = 0; i < arity_; ++i) r[constants + i] = args[i];
  double* out = r + constants + arity_;
  const std::uint32_t* arguments = arguments_.data();
  for (const RegisterInstruction& in : code_) *out++ = detail::step(in, r, arguments);
  return r[result_];
}

namespace {

constexpr std::size_t kLanes = RegisterCode::kMaxLanes;
static_assert(kLanes == lanes::kLaneWidth, "the lane kernels work on whole registers");

// Every register holds kLanes values, all of them real points (run_lanes repeats lane 0 in the lanes it
// was not given), so the arithmetic runs over whole registers: fixed-length loops the compiler turns into
// vector instructions.
template <typename F>
[[gnu::always_inline]] inline void each_lane(double* __restrict out, const double* a, const double* b, F f) {
  for (std::size_t l = 0; l < kLanes; ++l) out[l] = f(a[l], b[l]);
}

double truth(bool b) {
  return b ? 1 : 0;
}

/// Lanes past the first `lanes` repeat lane 0.
void repeat_first(double* r, std::size_t lanes) {
  for (std::size_t l = lanes; l < kLanes; ++l) r[l] = r[0];
}

/// The instructions that are not whole-register arithmetic or a lane kernel: one lane at a time through
/// the scalar step (calls, natives, the rarer operators and built-ins).
void lane_by_lane(const RegisterInstruction& in, const double* r, const std::uint32_t* arguments,
                  std::size_t lanes, double* dst) {
  if (in.op >= Op::call) {
    std::array<double, 32> fixed_point;
    std::array<std::uint32_t, 32> fixed_indices;
    std::vector<double> heap_point;
    std::vector<std::uint32_t> heap_indices;
    double* p = fixed_point.data();
    std::uint32_t* idx = fixed_indices.data();
    if (in.b > fixed_point.size()) {
      heap_point.resize(in.b), heap_indices.resize(in.b);
      p = heap_point.data(), idx = heap_indices.data();
    }
    for (std::uint32_t i = 0; i < in.b; ++i) idx[i] = i;
    RegisterInstruction call = in;
    call.a = 0;
    for (std::size_t l = 0; l < lanes; ++l) {
      for (std::uint32_t i = 0; i < in.b; ++i) p[i] = r[arguments[in.a + i] * kLanes + l];
      dst[l] = detail::step(call, p, idx);
    }
  } else {
    RegisterInstruction pair = in;
    pair.a = 0, pair.b = 1;
    const double* a = r + in.a * kLanes;
    const double* b = r + in.b * kLanes;
    for (std::size_t l = 0; l < lanes; ++l) {
      const double point[2] = {a[l], b[l]};
      dst[l] = detail::step(pair, point, nullptr);
    }
  }
  repeat_first(dst, lanes);
}

/// Runs `code` on register file r (kLanes doubles a register; the instructions' own registers start at
/// `first`). Built for plain x86-64 and for AVX2 (twice the width), picked when the program starts.
[[gnu::target_clones("avx2", "default")]] void run_lane_code(const RegisterInstruction* code,
                                                             std::size_t count, double* r, std::size_t first,
                                                             const std::uint32_t* arguments,
                                                             std::size_t lanes) {
  double* dst = r + first * kLanes;
  for (std::size_t i = 0; i < count; ++i, dst += kLanes) {
    const RegisterInstruction& in = code[i];
    const double* a = r + in.a * kLanes;
    const double* b = r + in.b * kLanes;
    switch (in.lane) {
      case LaneOp::add:
        each_lane(dst, a, b, std::plus<>{});
        break;
      case LaneOp::subtract:
        each_lane(dst, a, b, std::minus<>{});
        break;
      case LaneOp::multiply:
        each_lane(dst, a, b, std::multiplies<>{});
        break;
      case LaneOp::divide:
        each_lane(dst, a, b, std::divides<>{});
        break;
      case LaneOp::negate:
        each_lane(dst, a, b, [](double x, double) { return -x; });
        break;
      case LaneOp::less:
        each_lane(dst, a, b, [](double x, double y) { return truth(x < y); });
        break;
      case LaneOp::greater:
        each_lane(dst, a, b, [](double x, double y) { return truth(x > y); });
        break;
      case LaneOp::abs:
        each_lane(dst, a, b, [](double x, double) { return std::fabs(x); });
        break;
      case LaneOp::sqr:
        each_lane(dst, a, b, [](double x, double) { return x * x; });
        break;
      case LaneOp::sqrt:
        lanes::sqrt(a, dst);
        break;
      case LaneOp::sin:
        lanes::sin(a, dst);
        break;
      case LaneOp::cos:
        lanes::cos(a, dst);
        break;
      case LaneOp::atan2:
        lanes::atan2(a, b, dst);
        break;
      case LaneOp::min:  // std::min(x, y): y only where y < x, as the scalar built-in
        each_lane(dst, a, b, [](double x, double y) { return y < x ? y : x; });
        break;
      case LaneOp::max:
        each_lane(dst, a, b, [](double x, double y) { return x < y ? y : x; });
        break;
      case LaneOp::native: {
        std::array<const double*, Function::kMaxLaneArguments> columns;
        for (std::uint32_t k = 0; k < in.b; ++k) columns[k] = r + arguments[in.a + k] * kLanes;
        in.lane_native(columns.data(), dst);
        break;
      }
      case LaneOp::by_lane:
        lane_by_lane(in, r, arguments, lanes, dst);
        break;
      default:
        // Every LaneOp has its case above; saying so spares each instruction the jump table's range check.
        __builtin_unreachable();
    }
  }
}

}  // namespace

void RegisterCode::prepare_lanes(double* r) const {
  std::memcpy(r, lane_constants_.data(), constants_.size() * kLanes * sizeof(double));
}

const double* RegisterCode::run_prepared_lanes(double* r, std::size_t lanes) const {
  run_lane_code(code_.data(), code_.size(), r, constants_.size() + arity_, arguments_.data(), lanes);
  return r + result_ * kLanes;
}

void RegisterCode::run_lanes(const double* const* args, std::size_t lanes, double* out) const {
  if (lanes == 0) return;
  if (lanes > kLanes) throw FunctionError("internal error: too many lanes");
  // One register file, kLanes doubles a register, numbered as run_in's: constants, parameters, results.
  alignas(64) std::array<double, 128 * kLanes> fixed;
  std::vector<double> heap;
  double* r = fixed.data();
  if (lane_registers() * kLanes > fixed.size()) {
    heap.resize(lane_registers() * kLanes);
    r = heap.data();
  }
  prepare_lanes(r);
  for (std::size_t i = 0; i < arity_; ++i) {
    double* p = r + parameter_register(i) * kLanes;
    if (lanes == kLanes) {
      std::memcpy(p, args[i], kLanes * sizeof(double));  // a fixed size: a few vector moves
    } else {
      for (std::size_t l = 0; l < lanes; ++l) p[l] = args[i][l];
      repeat_first(p, lanes);
    }
  }
  std::memcpy(out, run_prepared_lanes(r, lanes), lanes * sizeof(double));
}

}  // namespace snell::function
