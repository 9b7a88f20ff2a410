// Non-volatile storage in RAM, with power-loss injection, for tests and simulations.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/port/nv_storage.hpp"

namespace costa::port {

/// EEPROM-like storage over a caller-owned buffer: every programmed or erased byte is durable at
/// once (commit only counts), erased bytes read 0xFF. Never allocates.
///
/// Power loss: after cutPowerAfter(n), the next n bytes programmed or erased succeed; the write
/// or erase that would program byte n + 1 applies only the bytes before it and fails, and from
/// then on every write, erase and commit fails until restorePower(). Bytes are applied in
/// ascending address order, so a cut leaves exactly a prefix of the operation done. Reads keep
/// working, so that a test can inspect the medium while the power is off.
class MemoryStorage : public NvStorage {
 public:
  /// Uses `size` bytes at `buffer` as they are (to erase them, call erase(0, size)).
  MemoryStorage(uint8_t* buffer, size_t size) noexcept : bytes_(buffer), size_(size) {}

  size_t size() const noexcept override { return size_; }
  bool read(size_t offset, uint8_t* destination, size_t length) noexcept override;
  bool write(size_t offset, const uint8_t* source, size_t length) noexcept override;
  bool erase(size_t offset, size_t length) noexcept override;
  bool commit() noexcept override;

  /// The power fails once `bytes` more bytes have been programmed or erased.
  void cutPowerAfter(size_t bytes) noexcept {
    cutArmed_ = true;
    budget_ = bytes;
  }
  /// Powers the medium again and disarms any pending cut. Counters are kept.
  void restorePower() noexcept {
    cutArmed_ = false;
    powered_ = true;
  }
  bool powered() const noexcept { return powered_; }

  /// Counters since construction or resetCounters(). Refused calls are not counted.
  size_t bytesWritten() const noexcept { return bytesWritten_; }
  size_t bytesErased() const noexcept { return bytesErased_; }
  size_t writeCalls() const noexcept { return writeCalls_; }
  size_t eraseCalls() const noexcept { return eraseCalls_; }
  size_t commits() const noexcept { return commits_; }
  /// Write, erase and commit calls together: zero means the medium was not touched.
  size_t modifyingCalls() const noexcept { return writeCalls_ + eraseCalls_ + commits_; }
  void resetCounters() noexcept;

  /// Direct access to the medium's bytes, for tests that inspect or damage it.
  uint8_t* bytes() noexcept { return bytes_; }
  const uint8_t* bytes() const noexcept { return bytes_; }

 private:
  bool inRange(size_t offset, size_t length) const noexcept {
    return offset <= size_ && length <= size_ - offset;
  }
  /// How many of `length` bytes may be applied before the power fails; cuts the power when
  /// fewer than `length`.
  size_t admit(size_t length) noexcept;

  uint8_t* bytes_;
  size_t size_;
  bool powered_ = true;
  bool cutArmed_ = false;
  size_t budget_ = 0;
  size_t bytesWritten_ = 0;
  size_t bytesErased_ = 0;
  size_t writeCalls_ = 0;
  size_t eraseCalls_ = 0;
  size_t commits_ = 0;
};

/// MemoryStorage that owns `Size` bytes, initially erased.
template <size_t Size>
class MemoryStorageOf : public MemoryStorage {
 public:
  MemoryStorageOf() noexcept : MemoryStorage(buffer_, Size) {
    for (uint8_t& byte : buffer_) {
      byte = 0xFFU;
    }
  }

 private:
  uint8_t buffer_[Size]{};
};

}  // namespace costa::port
