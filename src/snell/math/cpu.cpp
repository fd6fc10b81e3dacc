#include "snell/math/cpu.hpp"

namespace snell::math {

bool has_avx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();  // this may run as a static initialiser, before libgcc's own
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

}  // namespace snell::math
