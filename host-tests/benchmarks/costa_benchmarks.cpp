// costa_benchmarks: wall-clock cost of each operation of operations.hpp, with Google
// Benchmark. One benchmark per available operation, named by its key. Each iteration is one
// run; `operations_per_iteration` says how many operations a run performs, so the time per
// operation is the time per iteration divided by it (tools/benchmark does that division).
//
//   costa_benchmarks [Google Benchmark options, e.g. --benchmark_format=json]
#include <benchmark/benchmark.h>

#include <string>

#include "operations.hpp"

namespace {

constexpr unsigned kWarmUpRuns = 100;

void measure(benchmark::State& state, const costa::bench::Operation* operation) {
  std::string error;
  const auto node = costa::bench::prepareNode(*operation, kWarmUpRuns, &error);
  if (!node) {
    state.SkipWithError(error.c_str());
    return;
  }
  for (auto _ : state) {
    operation->run(*node);
    node->recycle();
  }
  state.counters["operations_per_iteration"] = operation->operationsPerRun;
  state.SetItemsProcessed(state.iterations() * operation->operationsPerRun);
}

}  // namespace

int main(int argc, char** argv) {
  size_t count = 0;
  const costa::bench::Operation* operations = costa::bench::operations(&count);
  for (size_t i = 0; i < count; ++i) {
    if (operations[i].available()) {
      benchmark::RegisterBenchmark(operations[i].key, measure, &operations[i]);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
