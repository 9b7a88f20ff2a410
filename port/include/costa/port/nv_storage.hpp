// Byte-addressed non-volatile storage: EEPROM, a flash region, or a file.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace costa {

/// Non-volatile memory of a fixed size.
///
/// The model fits both EEPROM (byte writes) and flash (erase before write, then commit):
/// `erase` sets a range to 0xFF, `write` programs bytes, `commit` makes everything written so far
/// durable. Until `commit` returns true, a power loss may leave any prefix of the writes done.
/// `write` must take any byte range of erased bytes, in any order: a save programs a slot's
/// payload, then its header, then its first four bytes last (docs/storage.md). A flash that
/// programs only whole words or double words needs a driver that buffers a slot and programs it
/// at `commit` (as the file port does), or a slot alignment and writes that fit its unit.
/// All calls are made from the main loop and may take as long as the medium needs; the stack
/// calls them only on an explicit save or restore request, never while handling ordinary frames.
class NvStorage {
 public:
  NvStorage(const NvStorage&) = delete;
  NvStorage& operator=(const NvStorage&) = delete;

  // The defaults describe a device without storage: size 0, every access fails. (No pure
  // virtual functions in port interfaces: firmware needs nothing from the C++ runtime library.)

  /// Total size in bytes.
  virtual size_t size() const noexcept { return 0; }
  /// Copies `length` bytes at `offset` into `destination`. False on a medium error or out of range.
  virtual bool read(size_t offset, uint8_t* destination, size_t length) noexcept {
    (void)offset;
    (void)destination;
    (void)length;
    return false;
  }
  /// Programs `length` bytes at `offset`. False on a medium error or out of range.
  virtual bool write(size_t offset, const uint8_t* source, size_t length) noexcept {
    (void)offset;
    (void)source;
    (void)length;
    return false;
  }
  /// Sets `length` bytes at `offset` to 0xFF. False on a medium error or out of range.
  virtual bool erase(size_t offset, size_t length) noexcept {
    (void)offset;
    (void)length;
    return false;
  }
  /// Makes all writes and erases so far durable. False on a medium error.
  virtual bool commit() noexcept { return false; }

 protected:
  NvStorage() = default;
  ~NvStorage() = default;
};

}  // namespace costa
