#pragma once
// The form in which a compiled function is evaluated. The parser's stack program (function.hpp) is
// translated once into single-assignment register code: every instruction writes its own register and
// names its operands directly, so constants and parameters cost no instructions, calls of other compiled
// functions are inlined, operations on constants are folded, and a value computed twice (`cos(y)` in a
// twisted box) is computed once (common subexpressions, found by hash-consing). Each instruction performs
// exactly the operation the stack program would, in the same order, so the values are bit-identical.
//
// run_lanes() evaluates the code at up to kMaxLanes points at once: one dispatch per instruction for all
// points, the arithmetic on the lanes is a loop the compiler vectorises, and sin, cos, atan2 and sqrt run
// as vector kernels (lane_math.hpp; SIMD multi-point evaluation, used for an isosurface's march and normal
// samples). Those kernels may differ from libm in the last bit or two, so lane values equal scalar values
// to about 1e-15 relative, not bit for bit, where the code uses them.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "snell/function/function.hpp"

namespace snell::function {

/// How run_lanes computes an instruction: on whole registers (arithmetic, < and >, the built-ins with
/// lane kernels, natives with multi-point entry points), or one lane at a time through the scalar step
/// (calls, other natives, the rest).
enum class LaneOp : std::uint8_t {
  add,
  subtract,
  multiply,
  divide,
  negate,
  less,
  greater,
  abs,
  sqr,
  sqrt,
  sin,
  cos,
  atan2,
  min,
  max,
  native,  // a native with a multi-point entry point (Function::LaneNative)
  by_lane,
};

/// One operation of register code. Its `op` is a stack-program operator other than constant and
/// parameter (those become registers); the calls (call, call_component, native) come last in Op, and
/// take their arguments from a list: registers arguments[a .. a + b).
struct RegisterInstruction {
  Op op = Op::add;
  LaneOp lane = LaneOp::by_lane;  // set when the code is laid out
  std::uint32_t a = 0;            // first operand's register (calls: first index into the argument list)
  std::uint32_t b = 0;            // second operand's register (calls: argument count)
  double (*unary)(double) = nullptr;
  double (*binary)(double, double) = nullptr;
  Function::Native native = nullptr;
  Function::LaneNative lane_native = nullptr;  // native's multi-point entry point, if it has one
  const Function* callee = nullptr;
  std::uint32_t component = 0;
};

class RegisterCode {
 public:
  static constexpr std::size_t kMaxLanes = Function::kMaxLanes;

  /// Translates `program` of a function with `arity` parameters. Throws FunctionError on a malformed
  /// program (one that does not leave exactly one value).
  RegisterCode(const Program& program, std::size_t arity);

  /// The value at one point; `args` holds arity() values.
  double run(const double* args) const;
  /// Values at `lanes` (1..kMaxLanes) points: parameter i of point l is args[i][l]; results go to out[l].
  void run_lanes(const double* const* args, std::size_t lanes, double* out) const;

  /// run_lanes in parts, for a caller that runs the code many times on one register file (kMaxLanes
  /// doubles a register, lane_registers() of them): prepare_lanes fills the constants once, then each
  /// run fills the parameters' registers (parameter_register(i)) and calls run_prepared_lanes, which
  /// returns the result's register. Lanes past `lanes` repeat lane 0 (instructions that go lane by lane
  /// compute only the first `lanes` and copy lane 0 into the rest).
  std::size_t lane_registers() const { return constants_.size() + arity_ + code_.size(); }
  std::size_t parameter_register(std::size_t i) const { return constants_.size() + i; }
  void prepare_lanes(double* registers) const;
  const double* run_prepared_lanes(double* registers, std::size_t lanes = kMaxLanes) const;

  std::size_t instruction_count() const { return code_.size(); }
  /// Whether run_lanes computes every instruction on whole registers, none lane by lane (LaneOp).
  bool vectorised() const { return vectorised_; }
  std::size_t constant_count() const { return constants_.size(); }

 private:
  friend class RegisterCodeBuilder;
  RegisterCode() = default;
  double run_in(double* registers, const double* args) const;

  // Registers: [0, constants) hold constants_, then the parameters, then one per instruction.
  std::vector<double> constants_;
  std::vector<double> lane_constants_;  // each constant repeated kMaxLanes times, for run_lanes
  std::size_t arity_ = 0;
  std::vector<RegisterInstruction> code_;
  std::vector<std::uint32_t> arguments_;  // argument registers of native calls and calls
  std::uint32_t result_ = 0;
  bool vectorised_ = true;
  std::vector<std::shared_ptr<const Function>> callees_;  // keeps call targets alive
};

}  // namespace snell::function
