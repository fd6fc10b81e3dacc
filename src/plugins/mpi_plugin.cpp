// snell's Open MPI plugin: the only code that includes mpi.h (see cli/mpi/mpi_plugin_abi.hpp).
#include <mpi.h>

#include "cli/mpi/mpi_plugin_abi.hpp"

namespace {

MPI_Datatype datatype(int type) {
  switch (type) {
    case kSnellMpiInt:
      return MPI_INT;
    case kSnellMpiFloat:
      return MPI_FLOAT;
    case kSnellMpiUint64:
      return MPI_UINT64_T;
    default:
      return MPI_BYTE;
  }
}

int source_of(int source) {
  return source == kSnellMpiAnySource ? MPI_ANY_SOURCE : source;
}

int tag_of(int tag) {
  return tag == kSnellMpiAnyTag ? MPI_ANY_TAG : tag;
}

void report(const MPI_Status& status, int* from, int* received_tag) {
  if (from) *from = status.MPI_SOURCE;
  if (received_tag) *received_tag = status.MPI_TAG;
}

void init(int* argc, char*** argv, int* rank, int* size) {
  // Render threads call MPI one at a time (under a lock), never two at once.
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
}

void finalize() {
  MPI_Finalize();
}

void send(const void* data, int count, int type, int destination, int tag) {
  MPI_Send(data, count, datatype(type), destination, tag, MPI_COMM_WORLD);
}

void recv(void* data, int count, int type, int source, int tag, int* from, int* received_tag) {
  MPI_Status status;
  MPI_Recv(data, count, datatype(type), source_of(source), tag_of(tag), MPI_COMM_WORLD, &status);
  report(status, from, received_tag);
}

int iprobe(int source, int tag, int* from, int* received_tag) {
  int ready = 0;
  MPI_Status status;
  MPI_Iprobe(source_of(source), tag_of(tag), MPI_COMM_WORLD, &ready, &status);
  if (ready) report(status, from, received_tag);
  return ready;
}

void broadcast(void* data, int count, int type, int root) {
  MPI_Bcast(data, count, datatype(type), root, MPI_COMM_WORLD);
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int snell_mpi_api(SnellMpiApi* api) {
  *api = {init, finalize, send, recv, iprobe, broadcast};
  return 0;
}
