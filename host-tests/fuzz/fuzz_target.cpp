// libFuzzer entry point for one device (COSTA_FUZZ_DEVICE, set by the build: a name of the
// device list). A violated invariant is printed and ends the run with a trap, which libFuzzer
// reports as a crash and saves the input (tools/fuzz).
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <string>

#include "fuzz_session.hpp"

#ifndef COSTA_FUZZ_DEVICE
#error "COSTA_FUZZ_DEVICE names the device to fuzz"
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string problem = costa::fuzz::runFuzzInput(COSTA_FUZZ_DEVICE, data, size);
  if (!problem.empty()) {
    fprintf(stderr, "costa fuzz (%s): invariant violated: %s\n", COSTA_FUZZ_DEVICE,
            problem.c_str());
    fflush(stderr);
    __builtin_trap();
  }
  return 0;
}
