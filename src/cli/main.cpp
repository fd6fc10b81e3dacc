// The `snell` program (docs/cli.md).
#include <string>
#include <vector>

#include "cli/app.hpp"

int main(int argc, char** argv) {
  return snell::cli::run_app(std::vector<std::string>(argv + 1, argv + argc));
}
