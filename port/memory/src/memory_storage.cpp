#include "costa/port/memory/memory_storage.hpp"

#include <string.h>

namespace costa::port {

bool MemoryStorage::read(size_t offset, uint8_t* destination, size_t length) noexcept {
  if (!inRange(offset, length)) {
    return false;
  }
  if (length != 0U) {
    memcpy(destination, bytes_ + offset, length);
  }
  return true;
}

bool MemoryStorage::write(size_t offset, const uint8_t* source, size_t length) noexcept {
  if (!powered_ || !inRange(offset, length)) {
    return false;
  }
  ++writeCalls_;
  const size_t applied = admit(length);
  if (applied != 0U) {
    memcpy(bytes_ + offset, source, applied);
  }
  bytesWritten_ += applied;
  return applied == length;
}

bool MemoryStorage::erase(size_t offset, size_t length) noexcept {
  if (!powered_ || !inRange(offset, length)) {
    return false;
  }
  ++eraseCalls_;
  const size_t applied = admit(length);
  if (applied != 0U) {
    memset(bytes_ + offset, 0xFF, applied);
  }
  bytesErased_ += applied;
  return applied == length;
}

bool MemoryStorage::commit() noexcept {
  if (!powered_) {
    return false;
  }
  ++commits_;
  return true;
}

void MemoryStorage::resetCounters() noexcept {
  bytesWritten_ = 0;
  bytesErased_ = 0;
  writeCalls_ = 0;
  eraseCalls_ = 0;
  commits_ = 0;
}

size_t MemoryStorage::admit(size_t length) noexcept {
  if (!cutArmed_ || length <= budget_) {
    if (cutArmed_) {
      budget_ -= length;
    }
    return length;
  }
  const size_t applied = budget_;
  budget_ = 0;
  cutArmed_ = false;
  powered_ = false;
  return applied;
}

}  // namespace costa::port
