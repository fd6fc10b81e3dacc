#pragma once
// The MPI calls of the tile and frame queues, through the Open MPI plugin (mpi_plugin_abi.hpp), typed.
#include <cstdint>
#include <type_traits>

#include "cli/mpi/mpi_plugin_abi.hpp"

namespace snell::cli::distributed::mpi {

/// The plugin's calls; valid after the Session has started MPI.
const SnellMpiApi& api();

template <typename T>
constexpr int type_of() {
  static_assert(std::is_same_v<T, int> || std::is_same_v<T, float> || std::is_same_v<T, std::uint64_t>);
  if constexpr (std::is_same_v<T, float>) return kSnellMpiFloat;
  if constexpr (std::is_same_v<T, std::uint64_t>) return kSnellMpiUint64;
  return kSnellMpiInt;
}

template <typename T>
void send(const T* data, int count, int destination, int tag) {
  api().send(data, count, type_of<T>(), destination, tag);
}
inline void send_empty(int destination, int tag) {
  api().send(nullptr, 0, kSnellMpiInt, destination, tag);
}
template <typename T>
void recv(T* data, int count, int source, int tag) {
  api().recv(data, count, type_of<T>(), source, tag, nullptr, nullptr);
}
/// Receives (and drops) an empty or unknown message.
inline void recv_empty(int source, int tag) {
  api().recv(nullptr, 0, kSnellMpiByte, source, tag, nullptr, nullptr);
}

/// A message waiting from any rank: its sender and tag.
struct Waiting {
  bool ready = false;
  int from = -1;
  int tag = -1;
};
inline Waiting probe_any() {
  Waiting w;
  w.ready = api().iprobe(kSnellMpiAnySource, kSnellMpiAnyTag, &w.from, &w.tag) != 0;
  return w;
}

}  // namespace snell::cli::distributed::mpi
