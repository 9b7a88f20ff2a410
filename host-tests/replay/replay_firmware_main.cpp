// A firmware replay image: one suite of compiled transcripts replayed on the Cortex-M core,
// the report written through semihosting, the result as the program's exit status. Run under
// qemu-system-arm -M mps2-an386 (tools/firmware-replay).
#include "replay_script.hpp"
#include "semihosting.hpp"
#include "suite_report.hpp"

#ifndef COSTA_REPLAY_SUITE
#error "COSTA_REPLAY_SUITE names the suite this image replays (see CMakeLists.txt)"
#endif

namespace costa::replay {
extern const Suite COSTA_REPLAY_SUITE;
}  // namespace costa::replay

namespace {

class SemihostingOutput final : public costa::replay::ReportOutput {
 public:
  void write(const char* text) noexcept override { costa::replay::semihosting::writeString(text); }
};

}  // namespace

int main() {
  SemihostingOutput output;
  const costa::replay::SuiteResult result =
      costa::replay::replaySuite(costa::replay::COSTA_REPLAY_SUITE, output);
  costa::replay::semihosting::exit(result.failed == 0U && result.passed > 0U);
}
