// costa-replay [SUITE...]: the transcript replayer on the host. Replays the compiled transcripts
// of each suite (all when none is named: example, solo, gefran) and prints the same report as
// the firmware replay images. Exit status 0 when every transcript passed, 1 when one did not,
// 2 for an unknown suite.
#include <cstdio>
#include <cstring>

#include "suite_report.hpp"
#include "suites.hpp"

namespace {

class StandardOutput final : public costa::replay::ReportOutput {
 public:
  void write(const char* text) noexcept override { std::fputs(text, stdout); }
};

const costa::replay::Suite* const kSuites[] = {
    &costa::replay::kExampleSuite, &costa::replay::kSoloSuite, &costa::replay::kGefranSuite};

const costa::replay::Suite* findSuite(const char* name) {
  for (const costa::replay::Suite* suite : kSuites) {
    if (std::strcmp(suite->name, name) == 0) {
      return suite;
    }
  }
  return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (findSuite(argv[i]) == nullptr) {
      std::fprintf(stderr,
                   "costa-replay: unknown suite '%s'\nusage: costa-replay [SUITE...]  (%s)\n",
                   argv[i], "example, solo, gefran");
      return 2;
    }
  }
  StandardOutput output;
  bool passed = true;
  const auto replay = [&](const costa::replay::Suite& suite) {
    const costa::replay::SuiteResult result = costa::replay::replaySuite(suite, output);
    passed = passed && result.failed == 0U && result.passed > 0U;
  };
  for (int i = 1; i < argc; ++i) {
    replay(*findSuite(argv[i]));
  }
  if (argc < 2) {
    for (const costa::replay::Suite* suite : kSuites) {
      replay(*suite);
    }
  }
  std::fflush(stdout);
  return passed ? 0 : 1;
}
