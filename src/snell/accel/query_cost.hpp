#pragma once
// What ray queries cost, for `snell explain`'s cost layer and heatmap (issue 14): accelerator nodes (grid
// cells) visited and objects tested. Counting is off unless a thread points t_query_cost at a tally, so a
// normal render pays one thread-local load per object test and per query.
#include <cstdint>
#include <unordered_map>

#include "snell/scene/object.hpp"

namespace snell::accel {

struct QueryCost {
  uint64_t nodes = 0;
  uint64_t primitives = 0;
  /// When set, objects tested counted by scene object (the CSG or top-level object).
  std::unordered_map<const scene::Object*, uint64_t>* per_object = nullptr;
};

/// The calling thread's tally, or null (the default): accelerators add their counts here.
inline thread_local QueryCost* t_query_cost = nullptr;

inline void count_object_test(const scene::Object& object) {
  if (QueryCost* cost = t_query_cost) {
    ++cost->primitives;
    if (cost->per_object) ++(*cost->per_object)[&object];
  }
}

/// Counts the nodes one query visits in a local and adds them to the thread's tally when it goes out of
/// scope, so the traversal loop only increments a register.
class NodeTally {
 public:
  NodeTally() = default;
  ~NodeTally() {
    if (QueryCost* cost = t_query_cost) cost->nodes += count_;
  }
  NodeTally(const NodeTally&) = delete;
  NodeTally& operator=(const NodeTally&) = delete;
  void visit() { ++count_; }
  void add(uint64_t nodes) { count_ += nodes; }

 private:
  uint64_t count_ = 0;
};

}  // namespace snell::accel
