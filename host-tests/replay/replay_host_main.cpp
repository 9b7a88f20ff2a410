// costa-replay [SUITE...]: the transcript replayer on the host. Replays the compiled transcripts
// of each suite (all when none is named: every directory of host-tests/transcripts) and prints
// the same report as the firmware replay images. Exit status 0 when every transcript passed, 1
// when one did not, 2 for an unknown suite.
#include <cstdio>
#include <string>

#include "suite_report.hpp"
#include "suites.hpp"

namespace {

class StandardOutput final : public costa::replay::ReportOutput {
 public:
  void write(const char* text) noexcept override { std::fputs(text, stdout); }
};

std::string suiteNames() {
  std::string names;
  for (size_t i = 0; i < costa::replay::kSuiteCount; ++i) {
    names += (names.empty() ? "" : ", ") + std::string(costa::replay::kSuites[i]->name);
  }
  return names;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (costa::replay::findSuite(argv[i]) == nullptr) {
      std::fprintf(stderr,
                   "costa-replay: unknown suite '%s'\nusage: costa-replay [SUITE...]  (%s)\n",
                   argv[i], suiteNames().c_str());
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
    replay(*costa::replay::findSuite(argv[i]));
  }
  if (argc < 2) {
    for (size_t i = 0; i < costa::replay::kSuiteCount; ++i) {
      replay(*costa::replay::kSuites[i]);
    }
  }
  std::fflush(stdout);
  return passed ? 0 : 1;
}
