// costa_hot_paths_callgrind: the x86-64 instructions of the hot paths (hot_paths.hpp), counted by
// callgrind. Run it under `valgrind --tool=callgrind` (tools/benchmark and tools/check-budgets
// do; tools/perf/hot_paths.py turns the dumps into net instructions per operation).
//
// For each operation, in the order of operations(): prepare() (one checked run, kWarmUpRuns
// runs, one checked run), then CALLGRIND_ZERO_STATS, kMeasuredRuns runs, and
// CALLGRIND_DUMP_STATS_AT(key): the dump's `totals:` divided by kMeasuredRuns is the gross cost
// of one run, the loop included. Zeroing and dumping do not depend on callgrind's options, so
// nothing else ends up in the dump. Callgrind's counts are the same on every run of one build.
//
// Prints one line per operation, tab-separated: key, label, measured runs, request frames per
// run. Exit status 1 when an operation failed its check, 2 when not running under valgrind.
#include <stdio.h>
#include <valgrind/callgrind.h>

#include "hot_paths.hpp"

namespace {

constexpr uint32_t kWarmUpRuns = 100;
constexpr uint32_t kMeasuredRuns = 1000;

costa::hotpaths::Bench bench;

}  // namespace

int main() {
  if (RUNNING_ON_VALGRIND == 0) {
    fprintf(stderr, "costa_hot_paths_callgrind: run under valgrind --tool=callgrind\n");
    return 2;
  }
  if (const char* error = bench.start()) {
    fprintf(stderr, "costa_hot_paths_callgrind: %s\n", error);
    return 1;
  }
  size_t count = 0;
  const costa::hotpaths::Operation* operations = costa::hotpaths::operations(&count);
  for (size_t i = 0; i < count; ++i) {
    const costa::hotpaths::Operation& operation = operations[i];
    if (const char* error = costa::hotpaths::prepare(bench, operation, kWarmUpRuns)) {
      fprintf(stderr, "costa_hot_paths_callgrind: %s: %s\n", operation.key, error);
      return 1;
    }
    CALLGRIND_ZERO_STATS;
    for (uint32_t run = 0; run < kMeasuredRuns; ++run) {
      operation.run(bench);
    }
    CALLGRIND_DUMP_STATS_AT(operation.key);
    printf("%s\t%s\t%u\t%u\n", operation.key, operation.label, static_cast<unsigned>(kMeasuredRuns),
           static_cast<unsigned>(operation.requestFrames));
  }
  return 0;
}
