#include "semihosting.hpp"

#include <stdint.h>

namespace costa::replay::semihosting {
namespace {

enum Operation : uint32_t {
  kWrite0 = 0x04,  ///< r1: address of a NUL-terminated string
  kExit = 0x18,    ///< r1: the reason code itself (32-bit semihosting)
};

enum Reason : uint32_t {
  kApplicationExit = 0x20026,      ///< ADP_Stopped_ApplicationExit
  kRunTimeErrorUnknown = 0x20023,  ///< ADP_Stopped_RunTimeErrorUnknown
};

/// The semihosting call: operation in r0, argument in r1, result in r0.
uint32_t call(uint32_t operation, uint32_t argument) noexcept {
  uint32_t result = 0;
  asm volatile(
      "mov r0, %1\n"
      "mov r1, %2\n"
      "bkpt 0xAB\n"
      "mov %0, r0\n"
      : "=r"(result)
      : "r"(operation), "r"(argument)
      : "r0", "r1", "memory");
  return result;
}

}  // namespace

void writeString(const char* text) noexcept {
  call(kWrite0, reinterpret_cast<uintptr_t>(text));
}

void exit(bool success) noexcept {
  call(kExit, success ? kApplicationExit : kRunTimeErrorUnknown);
  for (;;) {  // a host that does not end the program: stop here
  }
}

}  // namespace costa::replay::semihosting
