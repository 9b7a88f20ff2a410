// Copying and filling bytes in the freestanding core. The core is compiled with -ffreestanding,
// which makes `memcpy` an ordinary library call even for a size known at compile time (newlib-
// nano's is a byte loop); the builtins below let the compiler expand those copies inline (one
// load and one store for a 4-byte value) and still call the library for variable sizes.
#pragma once

#include <stddef.h>

namespace costa {

inline void copyBytes(void* to, const void* from, size_t count) noexcept {
  __builtin_memcpy(to, from, count);
}

inline void fillBytes(void* to, int value, size_t count) noexcept {
  __builtin_memset(to, value, count);
}

inline int compareBytes(const void* a, const void* b, size_t count) noexcept {
  return __builtin_memcmp(a, b, count);
}

}  // namespace costa
