// The operations whose cost is measured, shared by costa_benchmarks (time) and
// costa_instruction_counts (instructions under callgrind), so both measure the same thing.
//
// An operation is prepared once on a fresh BenchNode (configuration over SDO, NMT state), then
// `run` is called again and again. One run may perform several operations (a whole segmented
// transfer, a pair of NMT commands that leaves the node as it found it): results are divided by
// `operationsPerRun`. Before anything is measured, one run is checked against the exact frames
// it must produce, so a benchmark cannot silently measure an abort or nothing at all.
#pragma once

#include <memory>
#include <string>

#include "bench_node.hpp"

namespace costa::bench {

struct Operation {
  const char* key;    ///< Benchmark name and callgrind dump name.
  const char* label;  ///< Row of the results table.
  unsigned operationsPerRun;
  /// Brings a fresh node into the state the operation needs; returns what went wrong.
  std::string (*prepare)(BenchNode& node);
  /// The measured work. nullptr: the stack cannot do this yet (the table says so).
  void (*run)(BenchNode& node);
  /// Checks what one run (from an empty recorder) did; returns what went wrong.
  std::string (*verify)(BenchNode& node);

  bool available() const { return run != nullptr; }
};

/// Every operation, in table order.
const Operation* operations(size_t* count);

/// A node prepared for `operation` whose first run has been verified and which has been warmed
/// up by `warmUpRuns` further runs. Null, with `error` set, when any of that failed.
std::unique_ptr<BenchNode> prepareNode(const Operation& operation, unsigned warmUpRuns,
                                       std::string* error);

}  // namespace costa::bench
