// Prints the libFuzzer dictionary of a device (fuzz_dictionary.hpp), for tools/fuzz:
//
//   costa_fuzz_dictionary DEVICE > DEVICE.dict
#include <stdio.h>

#include <string>

#include "fuzz_dictionary.hpp"
#include "fuzzed_device.hpp"

int main(int argc, char** argv) {
  const costa::od::Definition* definition =
      argc == 2 ? costa::fuzz::fuzzedDefinition(argv[1]) : nullptr;
  if (definition == nullptr) {
    fprintf(stderr, "usage: costa_fuzz_dictionary DEVICE  (DEVICE: example, solo, gra, grn)\n");
    return 2;
  }
  fputs(costa::fuzz::fuzzDictionary(*definition).c_str(), stdout);
  return 0;
}
