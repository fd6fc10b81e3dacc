// MPI start-up for `mpirun ... snell ...`. MPI is started only when a launcher set up this process (Open MPI,
// PMI or PMIx variables), so a plain `snell` run never loads Open MPI, pays for MPI_Init or needs a launcher.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/distributed.hpp"
#include "cli/mpi/mpi_transport.hpp"
#include "snell/io/plugin_loader.hpp"

namespace snell::cli::distributed {

namespace {

bool g_started = false;
int g_rank = 0;
int g_size = 1;
SnellMpiApi g_api{};

bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

}  // namespace

Session::Session(int& argc, char**& argv) {
  if (!launched_by_mpirun()) return;
  std::string error;
  void* plugin = io::open_plugin("libsnell_mpi.so", error);
  const auto get_api = reinterpret_cast<SnellMpiGetApi>(io::plugin_symbol(plugin, "snell_mpi_api"));
  if (!get_api || get_api(&g_api) != 0) {
    // Every rank fails alike, so each says why and stops (there is no MPI to abort the others with).
    std::fprintf(stderr, "snell: error: started by mpirun, but the MPI plugin cannot be loaded: %s\n",
                 plugin ? "libsnell_mpi.so lacks snell_mpi_api" : error.c_str());
    std::exit(1);
  }
  g_api.init(&argc, &argv, &g_rank, &g_size);
  g_started = true;
}

Session::~Session() {
  if (g_started) g_api.finalize();
}

namespace mpi {
const SnellMpiApi& api() {
  return g_api;
}
}  // namespace mpi

int rank() {
  return g_rank;
}
int size() {
  return g_size;
}
const char* support() {
  return "with Open MPI";
}

}  // namespace snell::cli::distributed
