#include "suites.hpp"

namespace costa::replay {

const Suite* findSuite(const char* name) noexcept {
  for (size_t i = 0; i < kSuiteCount; ++i) {
    const char* suite = kSuites[i]->name;
    size_t at = 0;
    while (suite[at] != '\0' && suite[at] == name[at]) {
      ++at;
    }
    if (suite[at] == '\0' && name[at] == '\0') {
      return kSuites[i];
    }
  }
  return nullptr;
}

}  // namespace costa::replay
