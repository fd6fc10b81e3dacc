// Placeholder until the CLI lands (render helper replaces this file).
#include <cstdio>
int main() {
  std::puts("snell " SNELL_VERSION);
  return 0;
}
