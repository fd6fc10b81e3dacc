#include "snell/function/register_code.hpp"

#include <bit>
#include <map>
#include <span>
#include <tuple>
#include <utility>

#include "snell/function/builtins.hpp"
#include "snell/function/register_step.hpp"

namespace snell::function {

namespace {

/// Calls of compiled functions are inlined up to this depth and this many nodes; deeper or larger ones
/// (recursion cannot happen: a function can only call functions declared before it) stay calls.
constexpr int kMaxInlineDepth = 16;
constexpr std::size_t kMaxNodes = 1 << 14;

struct Node {
  enum class Kind : std::uint8_t { constant, parameter, operation };
  Kind kind = Kind::constant;
  double value = 0;                 // constant
  std::uint32_t parameter = 0;      // parameter
  RegisterInstruction instruction;  // operation; its a and b are set when the code is laid out
  std::vector<std::uint32_t> operands;
  std::shared_ptr<const Function> callee;
};

LaneOp lane_op(const RegisterInstruction& in) {
  switch (in.op) {
    case Op::add:
      return LaneOp::add;
    case Op::subtract:
      return LaneOp::subtract;
    case Op::multiply:
      return LaneOp::multiply;
    case Op::divide:
      return LaneOp::divide;
    case Op::negate:
      return LaneOp::negate;
    case Op::less:
      return LaneOp::less;
    case Op::greater:
      return LaneOp::greater;
    case Op::native:
      return in.lane_native && in.b <= Function::kMaxLaneArguments ? LaneOp::native : LaneOp::by_lane;
    case Op::unary:
    case Op::binary:
      switch (in.op == Op::unary ? lane_kernel(in.unary) : lane_kernel(in.binary)) {
        case LaneKernel::abs:
          return LaneOp::abs;
        case LaneKernel::sqr:
          return LaneOp::sqr;
        case LaneKernel::sqrt:
          return LaneOp::sqrt;
        case LaneKernel::sin:
          return LaneOp::sin;
        case LaneKernel::cos:
          return LaneOp::cos;
        case LaneKernel::atan2:
          return LaneOp::atan2;
        case LaneKernel::min:
          return LaneOp::min;
        case LaneKernel::max:
          return LaneOp::max;
        case LaneKernel::none:
          break;
      }
      break;
    default:
      break;
  }
  return LaneOp::by_lane;
}

using NodeKey = std::tuple<int, int, std::uint64_t, std::uintptr_t, std::uintptr_t, std::uintptr_t,
                           std::uintptr_t, std::uint32_t, std::vector<std::uint32_t>>;

NodeKey key_of(const Node& n) {
  const RegisterInstruction& in = n.instruction;
  return {static_cast<int>(n.kind),
          static_cast<int>(in.op),
          n.kind == Node::Kind::constant ? std::bit_cast<std::uint64_t>(n.value) : n.parameter,
          reinterpret_cast<std::uintptr_t>(in.unary),
          reinterpret_cast<std::uintptr_t>(in.binary),
          reinterpret_cast<std::uintptr_t>(in.native),
          reinterpret_cast<std::uintptr_t>(n.callee.get()),
          in.component,
          n.operands};
}

}  // namespace

/// Builds the node graph (hash-consed, constants folded), then lays it out as register code.
class RegisterCodeBuilder {
 public:
  std::uint32_t translate(const Program& program, std::span<const std::uint32_t> parameters, int depth) {
    if (program.code.empty()) return constant(0);  // as the stack evaluator: an empty program gives 0
    std::vector<std::uint32_t> stack;
    const auto pop = [&] {
      if (stack.empty()) throw FunctionError("internal error: a function's program underflows");
      const std::uint32_t top = stack.back();
      stack.pop_back();
      return top;
    };
    const auto pop_n = [&](std::uint32_t count) {
      if (stack.size() < count) throw FunctionError("internal error: a function's program underflows");
      std::vector<std::uint32_t> args(stack.end() - count, stack.end());
      stack.resize(stack.size() - count);
      return args;
    };
    for (const Instruction& in : program.code) {
      Node n;
      n.kind = Node::Kind::operation;
      switch (in.op) {
        case Op::constant:
          stack.push_back(constant(in.value));
          continue;
        case Op::parameter:
          if (in.index >= parameters.size()) throw FunctionError("internal error: no such parameter");
          stack.push_back(parameters[in.index]);
          continue;
        case Op::negate:
        case Op::logical_not:
          n.instruction.op = in.op;
          n.operands = {pop()};
          break;
        case Op::unary:
          n.instruction.op = Op::unary;
          n.instruction.unary = in.unary;
          n.operands = {pop()};
          break;
        case Op::binary:
          n.instruction.op = Op::binary;
          n.instruction.binary = in.binary;
          n.operands = pop_n(2);
          break;
        case Op::call:
        case Op::call_component: {
          const std::shared_ptr<const Function>& callee = program.callees.at(in.index);
          n.operands = pop_n(in.count);
          if (in.op == Op::call_component) {
            n.instruction.op = Op::call_component;
            n.instruction.component = static_cast<std::uint32_t>(in.value);
            n.instruction.callee = callee.get();
            n.callee = callee;
          } else if (callee->stack_program() && callee->arity() == in.count && depth < kMaxInlineDepth &&
                     nodes_.size() < kMaxNodes) {
            stack.push_back(translate(*callee->stack_program(), n.operands, depth + 1));
            continue;
          } else if (callee->native_function() && callee->arity() == in.count) {
            n.instruction.op = Op::native;
            n.instruction.native = callee->native_function();
            n.instruction.lane_native = callee->lane_native_function();
          } else {
            n.instruction.op = Op::call;
            n.instruction.callee = callee.get();
            n.callee = callee;
          }
          break;
        }
        default:
          n.instruction.op = in.op;
          n.operands = pop_n(2);
          break;
      }
      stack.push_back(operation(std::move(n)));
    }
    if (stack.size() != 1) throw FunctionError("internal error: a function body must leave one value");
    return stack.back();
  }

  std::uint32_t parameter(std::uint32_t index) {
    Node n;
    n.kind = Node::Kind::parameter;
    n.parameter = index;
    return intern(std::move(n));
  }

  RegisterCode finish(std::uint32_t result, std::size_t arity) {
    // Lay out only what the result needs (folding leaves its inputs behind): constants first, then the
    // parameters, then the operations in creation order, which is a topological order.
    std::vector<bool> needed(nodes_.size(), false);
    needed[result] = true;
    for (std::size_t i = nodes_.size(); i-- > 0;)
      if (needed[i])
        for (std::uint32_t o : nodes_[i].operands) needed[o] = true;
    RegisterCode code;
    code.arity_ = arity;
    std::vector<std::uint32_t> reg(nodes_.size(), 0);
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (needed[i] && nodes_[i].kind == Node::Kind::constant) {
        reg[i] = static_cast<std::uint32_t>(code.constants_.size());
        code.constants_.push_back(nodes_[i].value);
      }
    }
    const auto first_parameter = static_cast<std::uint32_t>(code.constants_.size());
    const auto first_instruction = first_parameter + static_cast<std::uint32_t>(arity);
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (!needed[i]) continue;
      Node& n = nodes_[i];
      if (n.kind == Node::Kind::parameter) reg[i] = first_parameter + n.parameter;
      if (n.kind != Node::Kind::operation) continue;
      RegisterInstruction in = n.instruction;
      if (in.op >= Op::call) {
        in.a = static_cast<std::uint32_t>(code.arguments_.size());
        in.b = static_cast<std::uint32_t>(n.operands.size());
        for (std::uint32_t o : n.operands) code.arguments_.push_back(reg[o]);
      } else {
        in.a = reg[n.operands[0]];
        in.b = n.operands.size() > 1 ? reg[n.operands[1]] : in.a;
      }
      if (n.callee) code.callees_.push_back(n.callee);
      reg[i] = first_instruction + static_cast<std::uint32_t>(code.code_.size());
      code.code_.push_back(in);
    }
    code.result_ = reg[result];
    for (RegisterInstruction& in : code.code_) {
      in.lane = lane_op(in);
      code.vectorised_ = code.vectorised_ && in.lane != LaneOp::by_lane;
    }
    code.lane_constants_.reserve(code.constants_.size() * RegisterCode::kMaxLanes);
    for (double c : code.constants_)
      code.lane_constants_.insert(code.lane_constants_.end(), RegisterCode::kMaxLanes, c);
    return code;
  }

 private:
  std::uint32_t constant(double value) {
    Node n;
    n.kind = Node::Kind::constant;
    n.value = value;
    return intern(std::move(n));
  }

  /// Folds an operation on constants (a pure one: arithmetic, built-ins, natives; never a call, which
  /// may throw or depend on more than its arguments), else interns it.
  std::uint32_t operation(Node n) {
    const bool pure = n.instruction.op < Op::call || n.instruction.op == Op::native;
    bool all_constant = pure;
    for (std::uint32_t o : n.operands) all_constant = all_constant && nodes_[o].kind == Node::Kind::constant;
    if (!all_constant) return intern(std::move(n));
    std::vector<double> values;
    std::vector<std::uint32_t> arguments;
    for (std::uint32_t o : n.operands) {
      arguments.push_back(static_cast<std::uint32_t>(values.size()));
      values.push_back(nodes_[o].value);
    }
    RegisterInstruction in = n.instruction;
    in.a = 0;
    in.b = in.op == Op::native ? static_cast<std::uint32_t>(values.size()) : (values.size() > 1 ? 1 : 0);
    return constant(detail::step(in, values.data(), arguments.data()));
  }

  std::uint32_t intern(Node n) {
    NodeKey key = key_of(n);
    if (const auto it = seen_.find(key); it != seen_.end()) return it->second;
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(std::move(n));
    seen_.emplace(std::move(key), index);
    return index;
  }

  std::vector<Node> nodes_;
  std::map<NodeKey, std::uint32_t> seen_;
};

RegisterCode::RegisterCode(const Program& program, std::size_t arity) {
  RegisterCodeBuilder builder;
  std::vector<std::uint32_t> parameters;
  for (std::size_t i = 0; i < arity; ++i)
    parameters.push_back(builder.parameter(static_cast<std::uint32_t>(i)));
  *this = builder.finish(builder.translate(program, parameters, 0), arity);
}

}  // namespace snell::function
