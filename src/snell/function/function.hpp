#pragma once
// Compiled POV-Ray user functions (POV-Ray 3.7 reference, "User-Defined Functions"): `function { expr }`
// is compiled once into a flat stack program, so isosurfaces and parametric objects can evaluate it
// millions of times without touching the parser. Depends on math only (plus texture's Perlin noise for
// f_noise3d), never on the scene-language parser.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace snell::function {

/// A call that cannot be evaluated (an internal not implemented, a pattern function, a bad argument count).
class FunctionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Function;
class RegisterCode;

enum class Op : std::uint8_t {
  constant,   // push value
  parameter,  // push args[index]
  add,
  subtract,
  multiply,
  divide,
  negate,
  logical_not,
  less,
  less_equal,
  equal,
  not_equal,
  greater_equal,
  greater,
  logical_and,
  logical_or,
  unary,           // top = unary(top)
  binary,          // b = pop, a = pop, push binary(a, b)
  call,            // pop `count` arguments, push callees[index](arguments)
  call_component,  // like call, for a vector-valued callee: push component `value` of its result
  native,          // register code only (register_code.hpp): a native callee called directly
};

struct Instruction {
  Op op = Op::constant;
  std::uint32_t index = 0;
  std::uint32_t count = 0;
  double value = 0;
  double (*unary)(double) = nullptr;
  double (*binary)(double, double) = nullptr;
};

/// A straight-line stack program (functions have no side effects, so select() evaluates all its arguments
/// and needs no jumps).
struct Program {
  std::vector<Instruction> code;
  std::vector<std::shared_ptr<const Function>> callees;
  std::uint32_t max_stack = 0;
};

/// Appends instructions while tracking the stack depth, so the evaluator can size its stack once.
class ProgramBuilder {
 public:
  void constant(double value);
  void parameter(std::uint32_t index);
  /// Any operator but constant/parameter/unary/binary/call.
  void op(Op op);
  void unary(double (*fn)(double));
  void binary(double (*fn)(double, double));
  void call(std::shared_ptr<const Function> callee, std::uint32_t argument_count);
  /// Calls a vector-valued callee (a pigment, spline or transform function) and keeps one component.
  void call_component(std::shared_ptr<const Function> callee, std::uint32_t argument_count,
                      std::uint32_t component);
  Program finish();

 private:
  void push(int change);
  Program program_;
  std::shared_ptr<const RegisterCode> code_;  // what a compiled function runs (register_code.hpp)
  std::uint32_t depth_ = 0;
};

class Function {
 public:
  using Native = double (*)(const double* args);
  /// A native's values at kMaxLanes points at once: argument i of point l is args[i][l], the value goes to
  /// out[l]; for every lane the same value as the Native at that point.
  using LaneNative = void (*)(const double* const* args, double* out);
  /// The most points call_lanes takes at once.
  static constexpr std::size_t kMaxLanes = 8;
  /// The most arguments a native takes through its LaneNative (more go lane by lane), and a LaneBatch.
  static constexpr std::size_t kMaxLaneArguments = 16;
  /// Writes components() values to `out`.
  using VectorNative = std::function<void(const double* args, double* out)>;
  /// The most components a vector function returns: a colour's red, green, blue, filter, transmit.
  static constexpr std::size_t kMaxComponents = 5;

  static std::shared_ptr<const Function> compiled(std::vector<std::string> parameters, Program program);
  /// `lanes`, when given, computes fn at kMaxLanes points at once (register code then evaluates calls of
  /// it on whole registers).
  static std::shared_ptr<const Function> native(std::string name, std::size_t arity, Native fn,
                                                LaneNative lanes = nullptr);
  /// Declares fine; every call throws FunctionError with `reason`.
  /// A vector-valued function (POV-Ray's `function { pigment {..} }`, `{ spline {..} }`,
  /// `{ transform {..} }`): used through a component, `F(x,y,z).red`, or as a whole in scene expressions.
  static std::shared_ptr<const Function> vector(std::string name, std::size_t arity, std::size_t components,
                                                VectorNative fn);
  static std::shared_ptr<const Function> unsupported(std::string name, std::size_t arity, std::string reason);

  std::size_t arity() const { return arity_; }
  const std::string& name() const { return name_; }
  const std::vector<std::string>& parameters() const { return parameters_; }
  bool supported() const { return kind_ != Kind::unsupported; }
  /// 1 for float functions; 3 (vector) or 5 (colour) for vector functions.
  std::size_t components() const { return components_; }

  /// Evaluates with exactly arity() arguments; throws FunctionError otherwise or when unsupported.
  double operator()(std::span<const double> args) const;
  /// A float function's value; a vector function's first component (as POV-Ray's VM leaves it).
  double call(const double* args) const;
  /// All components() values of a call (a float function fills one).
  void call_vector(const double* args, double* out) const;
  /// call() at `lanes` points at once (at most kMaxLanes): parameter i of point l is args[i][l], the
  /// value goes to out[l]. A compiled function runs its code once for all points (SIMD lanes).
  void call_lanes(const double* const* args, std::size_t lanes, double* out) const;
  /// Repeated evaluation at kMaxLanes points with the least copying, for a caller that evaluates one
  /// function many times (an isosurface's march along a ray): fill argument(i)[0 .. kMaxLanes) for each
  /// parameter, then run() returns the kMaxLanes values (valid until the next run). A compiled function's
  /// arguments are written straight into its register file, whose constants are filled once, when the
  /// batch is made. Takes at most kMaxLaneArguments parameters (FunctionError otherwise).
  class LaneBatch {
   public:
    explicit LaneBatch(const Function& f);
    LaneBatch(const LaneBatch&) = delete;
    LaneBatch& operator=(const LaneBatch&) = delete;
    double* argument(std::size_t i) { return arguments_[i]; }
    const double* run();

   private:
    static constexpr std::size_t kFixed = 128 * kMaxLanes;
    const Function& f_;
    const RegisterCode* code_ = nullptr;  // a compiled function's code, else null
    std::array<double*, kMaxLaneArguments> arguments_{};
    double* registers_ = nullptr;
    alignas(64) std::array<double, kFixed> fixed_;
    std::vector<double> heap_;
    std::array<double, kMaxLanes> out_;
  };

  /// Whether call_lanes costs about one call whatever the number of lanes: a compiled function whose code
  /// runs on whole SIMD registers throughout. Otherwise (natives, calls of pattern functions, built-ins
  /// without lane kernels) some of it runs lane by lane, and extra lanes cost nearly as much as calls.
  bool vectorised() const;

  /// A compiled function's stack program (what the register code was made from); else null.
  const Program* stack_program() const { return kind_ == Kind::compiled ? &program_ : nullptr; }
  /// A native function's entry point; else null.
  Native native_function() const { return kind_ == Kind::native ? native_ : nullptr; }
  /// A native function's multi-point entry point, where it has one; else null.
  LaneNative lane_native_function() const { return kind_ == Kind::native ? lane_native_ : nullptr; }

 private:
  enum class Kind { compiled, native, vector, unsupported };

  Kind kind_ = Kind::compiled;
  std::string name_;
  std::size_t arity_ = 0;
  std::vector<std::string> parameters_;
  Program program_;
  std::shared_ptr<const RegisterCode> code_;  // what a compiled function runs (register_code.hpp)
  Native native_ = nullptr;
  LaneNative lane_native_ = nullptr;
  VectorNative vector_;
  std::size_t components_ = 1;
  std::string reason_;
};

}  // namespace snell::function
