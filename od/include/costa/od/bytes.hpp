// Copying and filling bytes in the freestanding core. The core is compiled with -ffreestanding,
// which makes `memcpy` an ordinary library call even for a size known at compile time (newlib-
// nano's is a byte loop); the builtins below let the compiler expand those copies inline (one
// load and one store for a 4-byte value) and still call the library for variable sizes.
#pragma once

#include <stddef.h>

#include "costa/od/little_endian.hpp"

namespace costa {

inline void copyBytes(void* to, const void* from, size_t count) noexcept {
  __builtin_memcpy(to, from, count);
}

inline void fillBytes(void* to, int value, size_t count) noexcept {
  __builtin_memset(to, value, count);
}

/// The alignment a value of type T has in a dictionary's value blocks (natural, at most 4).
template <typename T>
inline constexpr size_t kValueAlignment = alignof(T) < 4U ? alignof(T) : 4U;

/// Loads a T from `address`, aligned for it as every numeric value of a dictionary block is: one
/// load even where the CPU cannot load from any address.
template <typename T>
inline T loadAligned(const void* address) noexcept {
  T value;
  __builtin_memcpy(&value, __builtin_assume_aligned(address, kValueAlignment<T>), sizeof(T));
  return value;
}

/// Stores a T at `address`, aligned as for loadAligned().
template <typename T>
inline void storeAligned(void* address, T value) noexcept {
  __builtin_memcpy(__builtin_assume_aligned(address, kValueAlignment<T>), &value, sizeof(T));
}

/// True when the `count` bytes at `a` and at `b` are equal: the library's comparison where speed
/// counts, a loop in a build for size (kExpandFastPaths), which spares the library's code.
inline bool sameBytes(const void* a, const void* b, size_t count) noexcept {
  if constexpr (kExpandFastPaths) {
    return __builtin_memcmp(a, b, count) == 0;
  } else {
    const auto* left = static_cast<const unsigned char*>(a);
    const auto* right = static_cast<const unsigned char*>(b);
    for (size_t i = 0; i < count; ++i) {
      if (left[i] != right[i]) {
        return false;
      }
    }
    return true;
  }
}

}  // namespace costa
