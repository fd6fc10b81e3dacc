#pragma once
// The interface between snell and its Open MPI plugin (src/plugins/mpi_plugin.cpp). Why a plugin: Open MPI's
// libraries (libmpi, open-pal, open-rte, hwloc, libevent, udev) cost every start of snell about 5 ms of
// dynamic loading, while only runs under mpirun use them; the plugin is loaded when a launcher started the
// process (mpi_session.cpp). Only the handful of calls the tile and frame queues make cross it, on
// MPI_COMM_WORLD, with plain C types.
#include <cstddef>

extern "C" {

/// Element types of a message.
enum SnellMpiType { kSnellMpiInt = 0, kSnellMpiFloat = 1, kSnellMpiUint64 = 2, kSnellMpiByte = 3 };
/// Wildcards for `source` and `tag` of recv and iprobe.
enum { kSnellMpiAnySource = -1, kSnellMpiAnyTag = -1 };

struct SnellMpiApi {
  /// MPI_Init_thread(MPI_THREAD_SERIALIZED) and this process's rank and the world size.
  void (*init)(int* argc, char*** argv, int* rank, int* size);
  void (*finalize)();
  void (*send)(const void* data, int count, int type, int destination, int tag);
  /// Blocking receive; the sender and tag of the message come back (either may be null).
  void (*recv)(void* data, int count, int type, int source, int tag, int* from, int* received_tag);
  /// Whether a message is waiting, and its sender and tag.
  int (*iprobe)(int source, int tag, int* from, int* received_tag);
  void (*broadcast)(void* data, int count, int type, int root);
};

/// The plugin's one entry point: fills `api`. Returns 0 on success.
using SnellMpiGetApi = int (*)(SnellMpiApi* api);
}
