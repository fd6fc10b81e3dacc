// The `snell` program (docs/cli.md).
#include <string>
#include <vector>

#include "cli/app.hpp"
#include "cli/distributed.hpp"

int main(int argc, char** argv) {
  const snell::cli::distributed::Session mpi(argc, argv);
  return snell::cli::run_app(std::vector<std::string>(argv + 1, argv + argc));
}
