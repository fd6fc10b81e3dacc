#pragma once
// POV-Ray's built-in functions, reached as `function { internal(N) }` (functions.inc declares them by
// number; POV-Ray 3.7 reference "functions.inc"). Each takes x, y, z then its extra parameters.
#include <memory>

#include "snell/function/function.hpp"

namespace snell::function {

/// The internal function number `n` (0..78). Those snell implements evaluate; the others declare fine but
/// throw FunctionError naming the function when called. Throws FunctionError for an unknown number.
std::shared_ptr<const Function> internal_function(int n);

}  // namespace snell::function
