// Prints the libFuzzer dictionary of a device (fuzz_dictionary.hpp), for tools/fuzz:
//
//   costa_fuzz_dictionary DEVICE > DEVICE.dict
#include <stdio.h>

#include <string>

#include "fuzz_dictionary.hpp"
#include "fuzzed_device.hpp"

int main(int argc, char** argv) {
  const costa::fuzz::FuzzedDeviceInfo* device =
      argc == 2 ? costa::fuzz::findFuzzedDevice(argv[1]) : nullptr;
  if (device == nullptr) {
    std::string names;
    for (const std::string& name : costa::fuzz::fuzzedDeviceNames()) {
      names += (names.empty() ? "" : ", ") + name;
    }
    fprintf(stderr, "usage: costa_fuzz_dictionary DEVICE  (DEVICE: %s)\n", names.c_str());
    return 2;
  }
  fputs(costa::fuzz::fuzzDictionary(*device->definition, device->controlWords).c_str(), stdout);
  return 0;
}
