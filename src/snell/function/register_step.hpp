#pragma once
// One register instruction at one point: shared by RegisterCode::run and by the constant folding of
// its translation, so that a folded value is exactly the value the evaluator would compute.
#include "snell/function/register_code.hpp"

namespace snell::function::detail {

/// Calls `in`'s callee with the registers that arguments[in.a .. in.a + in.b) name (register_run.cpp;
/// kept out of line so that the arithmetic loop stays small).
double call_with_registers(const RegisterInstruction& in, const double* r, const std::uint32_t* arguments);

/// The value of `in`, its operands read from registers `r`.
inline double step(const RegisterInstruction& in, const double* r, const std::uint32_t* arguments) {
  if (in.op >= Op::call) return call_with_registers(in, r, arguments);
  const double a = r[in.a];
  switch (in.op) {
    case Op::add:
      return a + r[in.b];
    case Op::subtract:
      return a - r[in.b];
    case Op::multiply:
      return a * r[in.b];
    case Op::divide:
      return a / r[in.b];
    case Op::negate:
      return -a;
    case Op::logical_not:
      return a == 0 ? 1 : 0;
    case Op::less:
      return a < r[in.b] ? 1 : 0;
    case Op::less_equal:
      return a <= r[in.b] ? 1 : 0;
    case Op::equal:
      return a == r[in.b] ? 1 : 0;
    case Op::not_equal:
      return a != r[in.b] ? 1 : 0;
    case Op::greater_equal:
      return a >= r[in.b] ? 1 : 0;
    case Op::greater:
      return a > r[in.b] ? 1 : 0;
    case Op::logical_and:
      return (a != 0 && r[in.b] != 0) ? 1 : 0;
    case Op::logical_or:
      return (a != 0 || r[in.b] != 0) ? 1 : 0;
    case Op::unary:
      return in.unary(a);
    case Op::binary:
      return in.binary(a, r[in.b]);
    default:
      break;
  }
  return 0;  // not reached: the calls returned above
}

}  // namespace snell::function::detail
