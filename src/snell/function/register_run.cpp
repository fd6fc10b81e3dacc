// Evaluation of register code at one point and at several points at once.
#include <array>
#include <cstring>
#include <functional>

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

using Lane = double[RegisterCode::kMaxLanes];

template <typename F>
void each_lane(std::size_t lanes, double* out, const double* a, const double* b, F f) {
  for (std::size_t l = 0; l < lanes; ++l) out[l] = f(a[l], b[l]);
}

double truth(bool b) {
  return b ? 1 : 0;
}

}  // namespace

void RegisterCode::run_lanes(const double* const* args, std::size_t lanes, double* out) const {
  constexpr std::size_t kLanes = kMaxLanes;
  if (lanes > kLanes) throw FunctionError("internal error: too many lanes");
  // Registers past the constants, kLanes doubles each (constants are read from lane_constants_).
  std::array<double, 96 * kLanes> fixed;
  std::vector<double> heap;
  const std::size_t own = arity_ + code_.size();
  double* regs = fixed.data();
  if (own * kLanes > fixed.size()) {
    heap.resize(own * kLanes);
    regs = heap.data();
  }
  const std::size_t constants = constants_.size();
  const auto lane = [&](std::uint32_t r) -> const double* {
    return r < constants ? lane_constants_.data() + r * kLanes : regs + (r - constants) * kLanes;
  };
  for (std::size_t i = 0; i < arity_; ++i) std::memcpy(regs + i * kLanes, args[i], lanes * sizeof(double));
  double* dst = regs + arity_ * kLanes;
  std::array<double, 32> point;  // one lane's operands, for the instructions evaluated lane by lane
  for (const RegisterInstruction& in : code_) {
    const double* a = in.op < Op::call ? lane(in.a) : nullptr;
    const double* b = in.op < Op::call ? lane(in.b) : nullptr;
    switch (in.op) {
      case Op::add:
        each_lane(lanes, dst, a, b, std::plus<>{});
        break;
      case Op::subtract:
        each_lane(lanes, dst, a, b, std::minus<>{});
        break;
      case Op::multiply:
        each_lane(lanes, dst, a, b, std::multiplies<>{});
        break;
      case Op::divide:
        each_lane(lanes, dst, a, b, std::divides<>{});
        break;
      case Op::negate:
        each_lane(lanes, dst, a, b, [](double x, double) { return -x; });
        break;
      case Op::unary:
        for (std::size_t l = 0; l < lanes; ++l) dst[l] = in.unary(a[l]);
        break;
      case Op::binary:
        for (std::size_t l = 0; l < lanes; ++l) dst[l] = in.binary(a[l], b[l]);
        break;
      case Op::less:
        each_lane(lanes, dst, a, b, [](double x, double y) { return truth(x < y); });
        break;
      case Op::greater:
        each_lane(lanes, dst, a, b, [](double x, double y) { return truth(x > y); });
        break;
      default:
        // The rarer operators and the calls: one lane at a time through the scalar step.
        if (in.op >= Op::call) {
          std::array<std::uint32_t, 32> indices;
          std::vector<double> heap_point;
          std::vector<std::uint32_t> heap_indices;
          double* p = point.data();
          std::uint32_t* idx = indices.data();
          if (in.b > point.size()) {
            heap_point.resize(in.b), heap_indices.resize(in.b);
            p = heap_point.data(), idx = heap_indices.data();
          }
          for (std::uint32_t i = 0; i < in.b; ++i) idx[i] = i;
          RegisterInstruction call = in;
          call.a = 0;
          for (std::size_t l = 0; l < lanes; ++l) {
            for (std::uint32_t i = 0; i < in.b; ++i) p[i] = lane(arguments_[in.a + i])[l];
            dst[l] = detail::step(call, p, idx);
          }
        } else {
          RegisterInstruction pair = in;
          pair.a = 0, pair.b = 1;
          for (std::size_t l = 0; l < lanes; ++l) {
            point[0] = a[l], point[1] = b[l];
            dst[l] = detail::step(pair, point.data(), nullptr);
          }
        }
        break;
    }
    dst += kLanes;
  }
  std::memcpy(out, lane(result_), lanes * sizeof(double));
}

}  // namespace snell::function
