#pragma once
// What the processor offers beyond the x86-64 baseline the program is built for, asked once at run time.

namespace snell::math {

/// The processor has AVX2 (always false off x86-64 or without GCC/Clang's builtins).
bool has_avx2();

}  // namespace snell::math
