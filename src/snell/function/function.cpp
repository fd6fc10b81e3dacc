#include "snell/function/function.hpp"

#include "snell/function/register_code.hpp"

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
  f->code_ = std::make_shared<const RegisterCode>(f->program_, f->arity_);
  return f;
}

std::shared_ptr<const Function> Function::native(std::string name, std::size_t arity, Native fn,
                                                 LaneNative lanes) {
  auto f = std::make_shared<Function>();
  f->kind_ = Kind::native;
  f->name_ = std::move(name);
  f->arity_ = arity;
  f->native_ = fn;
  f->lane_native_ = lanes;
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
  return code_->run(args);
}

void Function::call_vector(const double* args, double* out) const {
  if (kind_ == Kind::vector)
    vector_(args, out);
  else
    out[0] = call(args);
}

bool Function::vectorised() const {
  return (kind_ == Kind::compiled && code_->vectorised()) || (kind_ == Kind::native && lane_native_);
}

void Function::call_lanes(const double* const* args, std::size_t lanes, double* out) const {
  if (kind_ == Kind::compiled) return code_->run_lanes(args, lanes, out);
  if (kind_ == Kind::native && lane_native_ && lanes <= kMaxLanes && arity_ <= kMaxLaneArguments) {
    // Whole registers: lanes past `lanes` repeat lane 0.
    std::array<std::array<double, kMaxLanes>, kMaxLaneArguments> full;
    std::array<const double*, kMaxLaneArguments> columns;
    for (std::size_t i = 0; i < arity_; ++i) {
      for (std::size_t l = 0; l < kMaxLanes; ++l) full[i][l] = args[i][l < lanes ? l : 0];
      columns[i] = full[i].data();
    }
    std::array<double, kMaxLanes> values;
    lane_native_(columns.data(), values.data());
    for (std::size_t l = 0; l < lanes; ++l) out[l] = values[l];
    return;
  }
  std::array<double, 64> point{};
  if (arity_ > point.size()) throw FunctionError(name_ + ": too many arguments for a multi-point call");
  for (std::size_t l = 0; l < lanes; ++l) {
    for (std::size_t i = 0; i < arity_; ++i) point[i] = args[i][l];
    out[l] = call(point.data());
  }
}

Function::LaneBatch::LaneBatch(const Function& f) : f_(f) {
  if (f.arity_ > kMaxLaneArguments)
    throw FunctionError(f.name_ + ": too many arguments for a multi-point call");
  std::size_t registers = f.arity_;  // any other function: the arguments' columns only
  std::size_t first_argument = 0;
  if (f.kind_ == Kind::compiled) {
    code_ = f.code_.get();
    registers = code_->lane_registers();
    first_argument = code_->parameter_register(0);
  }
  registers_ = fixed_.data();
  if (registers * kMaxLanes > fixed_.size()) {
    heap_.resize(registers * kMaxLanes);
    registers_ = heap_.data();
  }
  if (code_) code_->prepare_lanes(registers_);
  for (std::size_t i = 0; i < f.arity_; ++i) arguments_[i] = registers_ + (first_argument + i) * kMaxLanes;
}

const double* Function::LaneBatch::run() {
  if (code_) return code_->run_prepared_lanes(registers_);
  f_.call_lanes(arguments_.data(), kMaxLanes, out_.data());
  return out_.data();
}

}  // namespace snell::function
