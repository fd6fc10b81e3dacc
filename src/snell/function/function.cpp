#include "snell/function/function.hpp"

#include <array>
#include <utility>

namespace snell::function {

void ProgramBuilder::push(int change) {
  depth_ = static_cast<std::uint32_t>(static_cast<int>(depth_) + change);
  if (depth_ > program_.max_stack) program_.max_stack = depth_;
}

void ProgramBuilder::constant(double value) {
  program_.code.push_back({Op::constant, 0, 0, value, nullptr, nullptr});
  push(1);
}

void ProgramBuilder::parameter(std::uint32_t index) {
  program_.code.push_back({Op::parameter, index, 0, 0, nullptr, nullptr});
  push(1);
}

void ProgramBuilder::op(Op op) {
  program_.code.push_back({op, 0, 0, 0, nullptr, nullptr});
  if (op != Op::negate && op != Op::logical_not) push(-1);
}

void ProgramBuilder::unary(double (*fn)(double)) {
  program_.code.push_back({Op::unary, 0, 0, 0, fn, nullptr});
}

void ProgramBuilder::binary(double (*fn)(double, double)) {
  program_.code.push_back({Op::binary, 0, 0, 0, nullptr, fn});
  push(-1);
}

void ProgramBuilder::call(std::shared_ptr<const Function> callee, std::uint32_t argument_count) {
  program_.callees.push_back(std::move(callee));
  program_.code.push_back({Op::call, static_cast<std::uint32_t>(program_.callees.size() - 1), argument_count,
                           0, nullptr, nullptr});
  push(1 - static_cast<int>(argument_count));
}

void ProgramBuilder::call_component(std::shared_ptr<const Function> callee, std::uint32_t argument_count,
                                    std::uint32_t component) {
  call(std::move(callee), argument_count);
  program_.code.back().op = Op::call_component;
  program_.code.back().value = component;
}

Program ProgramBuilder::finish() {
  if (depth_ != 1) throw FunctionError("internal error: a function body must leave one value");
  return std::move(program_);
}

std::shared_ptr<const Function> Function::compiled(std::vector<std::string> parameters, Program program) {
  auto f = std::make_shared<Function>();
  f->kind_ = Kind::compiled;
  f->name_ = "function";
  f->arity_ = parameters.size();
  f->parameters_ = std::move(parameters);
  f->program_ = std::move(program);
  return f;
}

std::shared_ptr<const Function> Function::native(std::string name, std::size_t arity, Native fn) {
  auto f = std::make_shared<Function>();
  f->kind_ = Kind::native;
  f->name_ = std::move(name);
  f->arity_ = arity;
  f->native_ = fn;
  return f;
}

std::shared_ptr<const Function> Function::vector(std::string name, std::size_t arity, std::size_t components,
                                                 VectorNative fn) {
  if (components < 1 || components > kMaxComponents)
    throw FunctionError("a vector function has 1 to 5 components");
  auto f = std::make_shared<Function>();
  f->kind_ = Kind::vector;
  f->name_ = std::move(name);
  f->arity_ = arity;
  f->components_ = components;
  f->vector_ = std::move(fn);
  return f;
}

std::shared_ptr<const Function> Function::unsupported(std::string name, std::size_t arity,
                                                      std::string reason) {
  auto f = std::make_shared<Function>();
  f->kind_ = Kind::unsupported;
  f->name_ = std::move(name);
  f->arity_ = arity;
  f->reason_ = std::move(reason);
  return f;
}

double Function::operator()(std::span<const double> args) const {
  if (args.size() != arity_)
    throw FunctionError(name_ + " takes " + std::to_string(arity_) + " argument(s), given " +
                        std::to_string(args.size()));
  return call(args.data());
}

double Function::call(const double* args) const {
  switch (kind_) {
    case Kind::native:
      return native_(args);
    case Kind::vector: {
      std::array<double, kMaxComponents> out{};
      vector_(args, out.data());
      return out[0];
    }
    case Kind::unsupported:
      throw FunctionError(reason_);
    case Kind::compiled:
      break;
  }
  return run(args);
}

void Function::call_vector(const double* args, double* out) const {
  if (kind_ == Kind::vector)
    vector_(args, out);
  else
    out[0] = call(args);
}

double Function::run(const double* args) const {
  // Small programs (nearly all) run on a fixed stack; the rare deep one on the heap.
  // Not zeroed (that cost more than a small program's run): every slot is written before it is read; the
  // first is set so that an empty program returns 0.
  std::array<double, 64> fixed;
  fixed[0] = 0;
  std::vector<double> heap;
  double* stack = fixed.data();
  if (program_.max_stack > fixed.size()) {
    heap.resize(program_.max_stack);
    stack = heap.data();
  }
  std::size_t sp = 0;  // next free slot
  const auto& code = program_.code;
  for (const Instruction& in : code) {
    switch (in.op) {
      case Op::constant:
        stack[sp++] = in.value;
        break;
      case Op::parameter:
        stack[sp++] = args[in.index];
        break;
      case Op::add:
        --sp, stack[sp - 1] += stack[sp];
        break;
      case Op::subtract:
        --sp, stack[sp - 1] -= stack[sp];
        break;
      case Op::multiply:
        --sp, stack[sp - 1] *= stack[sp];
        break;
      case Op::divide:
        --sp, stack[sp - 1] /= stack[sp];
        break;
      case Op::negate:
        stack[sp - 1] = -stack[sp - 1];
        break;
      case Op::logical_not:
        stack[sp - 1] = stack[sp - 1] == 0 ? 1 : 0;
        break;
      case Op::less:
        --sp, stack[sp - 1] = stack[sp - 1] < stack[sp] ? 1 : 0;
        break;
      case Op::less_equal:
        --sp, stack[sp - 1] = stack[sp - 1] <= stack[sp] ? 1 : 0;
        break;
      case Op::equal:
        --sp, stack[sp - 1] = stack[sp - 1] == stack[sp] ? 1 : 0;
        break;
      case Op::not_equal:
        --sp, stack[sp - 1] = stack[sp - 1] != stack[sp] ? 1 : 0;
        break;
      case Op::greater_equal:
        --sp, stack[sp - 1] = stack[sp - 1] >= stack[sp] ? 1 : 0;
        break;
      case Op::greater:
        --sp, stack[sp - 1] = stack[sp - 1] > stack[sp] ? 1 : 0;
        break;
      case Op::logical_and:
        --sp, stack[sp - 1] = (stack[sp - 1] != 0 && stack[sp] != 0) ? 1 : 0;
        break;
      case Op::logical_or:
        --sp, stack[sp - 1] = (stack[sp - 1] != 0 || stack[sp] != 0) ? 1 : 0;
        break;
      case Op::unary:
        stack[sp - 1] = in.unary(stack[sp - 1]);
        break;
      case Op::binary:
        --sp, stack[sp - 1] = in.binary(stack[sp - 1], stack[sp]);
        break;
      case Op::call: {
        sp -= in.count;
        stack[sp] = program_.callees[in.index]->call(stack + sp);
        ++sp;
        break;
      }
      case Op::call_component: {
        std::array<double, kMaxComponents> out{};
        sp -= in.count;
        program_.callees[in.index]->call_vector(stack + sp, out.data());
        stack[sp++] = out[static_cast<std::size_t>(in.value)];
        break;
      }
    }
  }
  return stack[0];
}

}  // namespace snell::function
