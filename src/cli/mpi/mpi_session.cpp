// MPI start-up for `mpirun ... snell ...`. MPI is started only when a launcher set up this process (Open MPI,
// PMI or PMIx variables), so a plain `snell` run never pays for MPI_Init or needs a launcher.
#include <mpi.h>

#include <cstdlib>

#include "cli/distributed.hpp"

namespace snell::cli::distributed {

namespace {

bool g_started = false;
int g_rank = 0;
int g_size = 1;

bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

}  // namespace

Session::Session(int& argc, char**& argv) {
  if (!launched_by_mpirun()) return;
  // Render threads call MPI one at a time (under a lock), never two at once.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  g_started = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
}

Session::~Session() {
  if (g_started) MPI_Finalize();
}

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
