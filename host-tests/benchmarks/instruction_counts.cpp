// costa_instruction_counts: instructions executed by each operation of operations.hpp, counted
// by callgrind. Run it under `valgrind --tool=callgrind` (tools/benchmark does).
//
// For each available operation: a fresh node is prepared and verified, warmed up by kWarmUpRuns
// runs, then CALLGRIND_ZERO_STATS, kMeasuredRuns runs (each followed by BenchNode::recycle(),
// as in costa_benchmarks), CALLGRIND_DUMP_STATS_AT(key). Zeroing and dumping do not depend on
// callgrind's collection state or command-line options, so nothing but the measured loop ends
// up in the dump named after the operation: its `totals:` line divided by
// (kMeasuredRuns * operationsPerRun) is instructions per operation. The loop itself, the
// recycle check and the two client requests add a few instructions per run.
//
// Prints one line per operation, tab-separated: key, label, measured runs, operations per run
// (0 and 0 for an operation that is not available yet). Exit status 1 when an operation could
// not be prepared, 2 when not running under valgrind.
#include <valgrind/callgrind.h>

#include <cstdio>
#include <string>

#include "operations.hpp"

namespace {

constexpr unsigned kWarmUpRuns = 100;
constexpr unsigned kMeasuredRuns = 1000;

}  // namespace

int main() {
  if (RUNNING_ON_VALGRIND == 0) {
    std::fprintf(stderr,
                 "costa_instruction_counts: run under valgrind --tool=callgrind "
                 "(see tools/benchmark)\n");
    return 2;
  }
  size_t count = 0;
  const costa::bench::Operation* operations = costa::bench::operations(&count);
  for (size_t i = 0; i < count; ++i) {
    const costa::bench::Operation& operation = operations[i];
    if (!operation.available()) {
      std::printf("%s\t%s\t0\t0\n", operation.key, operation.label);
      continue;
    }
    std::string error;
    const auto node = costa::bench::prepareNode(operation, kWarmUpRuns, &error);
    if (!node) {
      std::fprintf(stderr, "costa_instruction_counts: %s\n", error.c_str());
      return 1;
    }
    CALLGRIND_ZERO_STATS;
    for (unsigned run = 0; run < kMeasuredRuns; ++run) {
      operation.run(*node);
      node->recycle();
    }
    CALLGRIND_DUMP_STATS_AT(operation.key);
    std::printf("%s\t%s\t%u\t%u\n", operation.key, operation.label, kMeasuredRuns,
                operation.operationsPerRun);
  }
  return 0;
}
