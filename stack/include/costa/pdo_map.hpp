// The mapping of a PDO: which dictionary entries fill which bytes of the frame (CiA 301 7.5.2.37,
// 7.5.2.39). Costa maps whole entries at byte granularity: an entry's mapping length must equal
// its size in bits.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/object_access.hpp"
#include "costa/od/object_dictionary.hpp"

namespace costa {

/// One mapping object value: index << 16 | sub-index << 8 | length in bits.
constexpr uint32_t mappingValue(uint16_t index, uint8_t subIndex, uint8_t bits) noexcept {
  return (static_cast<uint32_t>(index) << 16U) | (static_cast<uint32_t>(subIndex) << 8U) | bits;
}

enum class PdoDirection : uint8_t { kReceive, kTransmit };

class PdoMap {
 public:
  static constexpr size_t kMaxEntries = 8;  ///< 64 bits at byte granularity.
  static constexpr size_t kMaxBytes = 8;

  /// Checks one mapping value for `direction`: kNoObject / kNoSubIndex (no such entry),
  /// kNotMappable (entry not mappable in this direction), kParameterIncompatible (length not a
  /// whole entry). Dummy entries (indices 0x0002..0x0007, the integer data types) are accepted
  /// for RPDOs only. A value of 0 is accepted (an unused entry).
  static AbortCode checkEntry(const od::ObjectDictionary& dictionary, uint32_t value,
                              PdoDirection direction) noexcept;

  /// Resolves `count` mapping values; on failure the map is left empty and the abort code is
  /// returned (checkEntry's codes, kMappingTooLong beyond 64 bits).
  AbortCode resolve(const od::ObjectDictionary& dictionary, const uint32_t* values, size_t count,
                    PdoDirection direction) noexcept;

  void clear() noexcept {
    count_ = 0;
    bytes_ = 0;
  }
  size_t bytes() const noexcept { return bytes_; }
  size_t count() const noexcept { return count_; }
  /// True when the entry (index, subIndex) is mapped.
  bool contains(uint16_t index, uint8_t subIndex) const noexcept;

  /// Copies the mapped values into `out` (bytes() bytes). All values are read in one call, so
  /// a frame never mixes two writes of an entry.
  void pack(const od::ObjectDictionary& dictionary, uint8_t* out) const noexcept;

  /// Writes received data (at least bytes() bytes) into the mapped entries through their hooks.
  /// Every value is checked first; if one fails, nothing is written and its abort code returned.
  AbortCode unpack(ObjectAccess& access, const uint8_t* data) const noexcept;

 private:
  struct Slot {
    od::EntryRef ref;  ///< invalid for a dummy entry
    uint8_t bytes = 0;
  };
  Slot slots_[kMaxEntries] = {};
  size_t count_ = 0;
  size_t bytes_ = 0;
};

}  // namespace costa
