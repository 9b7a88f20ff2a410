// Replays fuzz inputs through the same checks as the fuzzer, without libFuzzer:
//
//   costa_fuzz_replay [--trace] DEVICE PATH...
//   costa_fuzz_replay --list-devices
//
// PATH is a file or a directory (all files below it, sorted). Prints each violation with its
// file; exits 1 when any input violates an invariant, when a path does not exist, or when no
// input was found at all; 2 on a bad command line. --trace prints every event and every
// transmitted frame of each input. --list-devices prints the devices it knows, one a line.
#include <stdio.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_session.hpp"
#include "fuzzed_device.hpp"

namespace {

namespace fs = std::filesystem;

bool collect(const fs::path& path, std::vector<fs::path>* files) {
  std::error_code error;
  if (fs::is_regular_file(path, error)) {
    files->push_back(path);
    return true;
  }
  if (!fs::is_directory(path, error)) {
    return false;
  }
  std::vector<fs::path> found;
  for (const auto& entry : fs::recursive_directory_iterator(path)) {
    if (entry.is_regular_file()) {
      found.push_back(entry.path());
    }
  }
  std::sort(found.begin(), found.end());
  files->insert(files->end(), found.begin(), found.end());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> devices = costa::fuzz::fuzzedDeviceNames();
  if (argc == 2 && std::string(argv[1]) == "--list-devices") {
    for (const std::string& device : devices) {
      printf("%s\n", device.c_str());
    }
    return 0;
  }
  const bool tracing = argc > 1 && std::string(argv[1]) == "--trace";
  const int first = tracing ? 2 : 1;
  if (argc < first + 2 || std::find(devices.begin(), devices.end(), argv[first]) == devices.end()) {
    std::string names;
    for (const std::string& device : devices) {
      names += (names.empty() ? "" : ", ") + device;
    }
    fprintf(stderr, "usage: costa_fuzz_replay [--trace] DEVICE PATH...  (DEVICE: %s)\n",
            names.c_str());
    return 2;
  }
  const std::string device = argv[first];
  std::vector<fs::path> files;
  int status = 0;
  for (int i = first + 1; i < argc; ++i) {
    if (!collect(argv[i], &files)) {
      fprintf(stderr, "%s: no such file or directory\n", argv[i]);
      status = 1;
    }
  }
  size_t failed = 0;
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    std::string trace;
    const std::string problem =
        costa::fuzz::runFuzzInput(device, bytes.data(), bytes.size(), tracing ? &trace : nullptr);
    if (tracing) {
      printf("== %s\n%s", file.c_str(), trace.c_str());
    }
    if (!problem.empty()) {
      fprintf(stderr, "%s: %s\n", file.c_str(), problem.c_str());
      ++failed;
    }
  }
  printf("%s: %zu inputs replayed, %zu violated an invariant\n", device.c_str(), files.size(),
         failed);
  if (files.empty()) {
    fprintf(stderr, "no input to replay\n");
    status = 1;
  }
  return failed != 0U ? 1 : status;
}
