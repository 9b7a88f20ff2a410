// The mapping of a PDO, resolved once when it is configured into what its frames need: where
// each entry's bytes live and whether they can be copied as they are (CiA 301 7.5.2.37,
// 7.5.2.39). Costa maps whole entries at byte granularity: an entry's mapping length must equal
// its size in bits.
//
// An entry is copied straight between the frame and the dictionary's value blocks unless it
// needs more: an RPDO entry with a hook (the application's or a service's), with limits, a
// BOOLEAN, or a stored entry when writes are observed (save on write); a TPDO entry of a
// `$NODEID` constant. Those go through ObjectAccess (hook, checks) and the dictionary. Hooks
// attached later take effect when the mapping is resolved again (PdoEngine::refreshMappings()).
//
// Context: the one that runs the node. No allocation. pack()/unpack() are O(mapped entries) plus
// a lookup and the hook's cost for each entry that needs more than a copy.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/hot_path.hpp"
#include "costa/object_access.hpp"
#include "costa/od/bytes.hpp"
#include "costa/od/object_dictionary.hpp"
#include "costa/pdo_profile.hpp"

namespace costa {

/// One mapping object value: index << 16 | sub-index << 8 | length in bits.
constexpr uint32_t mappingValue(uint16_t index, uint8_t subIndex, uint8_t bits) noexcept {
  return (static_cast<uint32_t>(index) << 16U) | (static_cast<uint32_t>(subIndex) << 8U) | bits;
}

enum class PdoDirection : uint8_t { kReceive, kTransmit };

class PdoMap {
 public:
  static constexpr size_t kMaxEntries = kMaxPdoEntries;  ///< 64 bits at byte granularity.
  static constexpr size_t kMaxBytes = 8;

  /// Checks one mapping value for `direction`: kNoObject / kNoSubIndex (no such entry),
  /// kNotMappable (entry not mappable in this direction), kParameterIncompatible (length not a
  /// whole entry). Dummy entries (indices 0x0002..0x0007, the integer data types) are accepted
  /// for RPDOs only, and only those the dictionary's dummyUsage (its EDS's [DummyUsage]) names;
  /// the others are kNotMappable. A value of 0 is accepted (an unused entry). O(log objects).
  static AbortCode checkEntry(const od::ObjectDictionary& dictionary, uint32_t value,
                              PdoDirection direction) noexcept {
    od::EntryRef ref;
    return checkEntry(dictionary, value, direction, &ref);
  }
  /// The same, and `*ref` locates the entry (left as it was for 0 or a dummy entry).
  static AbortCode checkEntry(const od::ObjectDictionary& dictionary, uint32_t value,
                              PdoDirection direction, od::EntryRef* ref) noexcept;

  /// Resolves `count` mapping values; on failure the map is left empty and the abort code is
  /// returned (checkEntry's codes, kMappingTooLong beyond 64 bits). O(count x log objects).
  AbortCode resolve(const ObjectAccess& access, const uint32_t* values, size_t count,
                    PdoDirection direction) noexcept;

  void clear() noexcept {
    count_ = 0;
    bytes_ = 0;
    accessMask_ = 0;
    markMask_ = 0;
  }
  size_t bytes() const noexcept { return bytes_; }
  size_t count() const noexcept { return count_; }
  /// True when every entry is copied as it is (no hook, no check, no dummy).
  bool plain() const noexcept { return (accessMask_ | markMask_) == 0U; }
  /// True when the sub-index `ref` locates is mapped (asked of TPDO maps: markChanged()).
  bool contains(const od::EntryRef& ref) const noexcept;

  /// Copies the mapped values into `out` (bytes() bytes), all in one call, so a frame never
  /// mixes two writes of an entry. (Built for size, every mapping takes the one general loop:
  /// pack() is then a call of packThroughAccess(), inlined, not a function of its own.)
  void pack(const ObjectAccess& access, uint8_t* out) const noexcept {
    if (!kExpandFastPaths || (accessMask_ | markMask_) != 0U) {
      packThroughAccess(access, out);
      return;
    }
    const auto* values = static_cast<const uint8_t*>(access.dictionary().values());
    for (size_t i = 0; i < count_; ++i) {
      copyValue(out, values + slots_[i].where, slots_[i].length);
      out += slots_[i].length;
    }
  }

  /// First phase of an RPDO: checks every entry of `data` (at least bytes() bytes) as its hook
  /// or the dictionary would, writing nothing. The first refusal's abort code.
  AbortCode check(ObjectAccess& access, const uint8_t* data) const noexcept {
    for (size_t i = 0; i < count_; ++i) {
      if (needsAccess(i)) {
        const AbortCode verdict = access.check(locate(access, i), data, slots_[i].length);
        if (verdict != AbortCode::kNone) {
          return verdict;
        }
      }
      data += slots_[i].length;
    }
    return AbortCode::kNone;
  }
  /// Second phase: writes every entry. When an entry's hook refuses (a hook that checks only in
  /// write()), the entries written so far, the refusing one included, get back the bytes they
  /// held before the PDO (an entry mapped twice too) and the refusal is returned: an RPDO is
  /// written whole or not at all. With plain(), a copy per entry (built for size, in the one
  /// general loop, which then saves nothing).
  AbortCode write(ObjectAccess& access, const uint8_t* data) const noexcept {
    if (!kExpandFastPaths || !plain()) {
      return writeThroughAccess(access, data);
    }
    auto* values = static_cast<uint8_t*>(access.dictionary().values());
    for (size_t i = 0; i < count_; ++i) {
      copyValue(values + slots_[i].where, data, slots_[i].length);
      data += slots_[i].length;
    }
    return AbortCode::kNone;
  }

 private:
  /// Copies one value; the common sizes are a load and a store, also built for size: one call
  /// of memcpy for every length saves 24 bytes of flash, but makes Cortex-M4's PDOs 9 to 13 %
  /// slower and Cortex-M0+'s RPDO of eight UNSIGNED8 10 % (tools/cortex-m-counts).
  static void copyValue(uint8_t* to, const uint8_t* from, size_t length) noexcept {
    if (length == 4U) {
      copyBytes(to, from, 4);
    } else if (length == 1U) {
      *to = *from;
    } else if (length == 2U) {
      copyBytes(to, from, 2);
    } else {
      copyBytes(to, from, length);
    }
  }

  void packThroughAccess(const ObjectAccess& access, uint8_t* out) const noexcept;
  AbortCode writeThroughAccess(ObjectAccess& access, const uint8_t* data) const noexcept;
  /// Where an entry's bytes are: the offset of its value in the RAM block, or for an entry
  /// that needs ObjectAccess (its bit in accessMask_) its index and sub-index.
  struct Slot {
    uint16_t where;
    uint8_t subIndex;
    uint8_t length;
  };
  bool needsAccess(size_t slot) const noexcept { return (accessMask_ & (1U << slot)) != 0U; }
  /// In an RPDO: slot `slot` is a dummy entry.
  bool skipped(size_t slot) const noexcept { return (markMask_ & (1U << slot)) != 0U; }
  /// In a TPDO: slot `slot` is copied from the constants block.
  bool inRom(size_t slot) const noexcept { return (markMask_ & (1U << slot)) != 0U; }
  od::EntryRef locate(const ObjectAccess& access, size_t slot) const noexcept {
    return access.dictionary().find(slots_[slot].where, slots_[slot].subIndex);
  }

  // The four bytes first, within reach of Thumb-1's short offsets from the channel that holds
  // the map.
  uint8_t count_ = 0;
  uint8_t bytes_ = 0;
  uint8_t accessMask_ = 0;  ///< bit i: slot i goes through ObjectAccess
  /// Bit i: in an RPDO, slot i is a dummy entry (skipped()); in a TPDO, slot i is a constant
  /// (inRom()). A map has one direction (RPDOs map no constants, TPDOs no dummy entries), so
  /// one byte serves both and the map stays 36 bytes.
  uint8_t markMask_ = 0;
  Slot slots_[kMaxEntries] = {};
};

}  // namespace costa
