// One node's object dictionary: the ROM definition plus the RAM block of variable values.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/abort_code.hpp"
#include "costa/od/bytes.hpp"
#include "costa/od/definition.hpp"
#include "costa/od/entry_ref.hpp"
#include "costa/od/little_endian.hpp"
#include "costa/od/scalar.hpp"

namespace costa::od {

/// The default of one RAM sub-index as its value holds it (CPU byte order; a `$NODEID` default
/// without the node-id; a VISIBLE_STRING with its terminating zero): storage bytes of the value
/// into `destination`. O(log defaults).
void copyDefault(const Definition& definition, const EntryRef& ref, uint8_t* destination) noexcept;

/// Reads and writes values by index and sub-index, with the checks every writer must pass
/// (length, limits, boolean range). Access rights (ro/wo) and side effects are not checked here:
/// those belong to the services that act for a remote client (SDO, PDO).
///
/// Owns nothing: the caller supplies the RAM block (`Definition::valuesSize` bytes, aligned for
/// any scalar). No allocation; every operation is O(log n) in the number of objects or better.
/// Not thread-safe: call from the context that runs the node.
class ObjectDictionary {
 public:
  ObjectDictionary(const Definition& definition, void* values) noexcept
      : definition_(&definition), values_(static_cast<uint8_t*>(values)) {}

  const Definition& definition() const noexcept { return *definition_; }
  void* values() noexcept { return values_; }
  const void* values() const noexcept { return values_; }

  /// Node-id used for `$NODEID` defaults and constants. Set by the node at reset communication.
  void setNodeId(uint8_t nodeId) noexcept { nodeId_ = nodeId; }
  uint8_t nodeId() const noexcept { return nodeId_; }

  /// Locates an object; nullptr when absent. O(log n).
  const Object* findObject(uint16_t index) const noexcept;
  /// Number of sub-indices of `object` (sub-index 0 included). O(rows).
  unsigned entryCount(const Object& object) const noexcept {
    return od::entryCount(*definition_, object);
  }
  /// Locates a sub-index; fails with kNoObject or kNoSubIndex. O(log n).
  AbortCode find(uint16_t index, uint8_t subIndex, EntryRef* out) const noexcept;
  /// Locates a sub-index; invalid ref when absent.
  EntryRef find(uint16_t index, uint8_t subIndex) const noexcept;

  /// Size in bytes of the current value: the type size, the string length up to the first NUL
  /// for VISIBLE_STRING, 0 for DOMAIN (whose data lives with the application).
  size_t valueSize(const EntryRef& ref) const noexcept;

  /// Copies up to `capacity` bytes of the value's wire representation (little-endian),
  /// starting at byte `offset`, into `destination`. Returns the number of bytes copied.
  size_t read(const EntryRef& ref, size_t offset, uint8_t* destination,
              size_t capacity) const noexcept;

  /// The whole value's wire representation into `destination`, which has room for ref.size()
  /// bytes: read(ref, 0, destination, ref.size()), returning valueSize(). A string is one copy
  /// of all its bytes (those past a VISIBLE_STRING's end too) and one search for its end.
  size_t readWhole(const EntryRef& ref, uint8_t* destination) const noexcept;

  /// The wire representation of a numeric value (ref.size() bytes) into `destination`. The
  /// usual case (a value of 1, 2 or 4 bytes in RAM on a little-endian CPU that loads at any
  /// address, not built for size) is one load and store.
  void readNumber(const EntryRef& ref, uint8_t* destination) const noexcept {
    if (kExpandFastPaths && kLittleEndianHost && kUnalignedAccess && !ref.inRom()) {
      const uint8_t* source = values_ + ref.offset();
      switch (ref.size()) {
        case 1: *destination = *source; return;
        case 2: copyBytes(destination, source, 2); return;
        case 4: copyBytes(destination, source, 4); return;
        default: break;
      }
    }
    read(ref, 0, destination, ref.size());
  }

  /// Checks a new value in wire representation without storing it: length (kLengthTooHigh,
  /// kLengthTooLow), BOOLEAN range (kInvalidValue), limits (kValueTooHigh, kValueTooLow).
  /// ROM entries and DOMAINs fail with kWriteOfReadOnly / kCannotStore.
  AbortCode check(const EntryRef& ref, const uint8_t* source, size_t length) const noexcept;

  /// check() and, when it passes, stores the value. A VISIBLE_STRING shorter than its
  /// capacity is padded with zeros. The usual write (a whole integer of 1, 2 or 4 bytes
  /// without limits, in RAM: kPlainInteger, on a little-endian CPU that stores at any address,
  /// not built for size) is a test and a copy.
  AbortCode write(const EntryRef& ref, const uint8_t* source, size_t length) noexcept {
    const SubEntry& row = *ref.row;
    if (kExpandFastPaths && kLittleEndianHost && kUnalignedAccess && length == row.size &&
        (row.attributes & kPlainInteger) != 0U) {
      uint8_t* target = values_ + ref.offset();
      switch (length) {
        case 1: *target = *source; return AbortCode::kNone;
        case 2: copyBytes(target, source, 2); return AbortCode::kNone;
        case 4: copyBytes(target, source, 4); return AbortCode::kNone;
        default: break;
      }
    }
    return writeChecked(ref, source, length);
  }

  /// Numeric value of an integer or boolean entry, widened (signed types sign-extended).
  /// Returns 0 for other types.
  uint64_t readUnsigned(const EntryRef& ref) const noexcept;
  int64_t readSigned(const EntryRef& ref) const noexcept;
  /// readUnsigned(ref) truncated to 32 bits, computed in 32 bits (what small cores prefer).
  uint32_t readUnsigned32(const EntryRef& ref) const noexcept;

  /// Stores a numeric value without any check (the caller knows it is valid). No-op for ROM
  /// entries and non-integer types.
  void storeUnsigned(const EntryRef& ref, uint64_t value) noexcept {
    storeHalves(ref, static_cast<uint32_t>(value), static_cast<uint32_t>(value >> 32U));
  }
  /// The same with a value of 32 bits (zero-extended into an entry of 8 bytes), computed in 32
  /// bits (what small cores prefer).
  void storeUnsigned32(const EntryRef& ref, uint32_t value) noexcept { storeHalves(ref, value, 0); }

  /// `ref` resolved for the two below (see Scalar); not valid when `ref` is not. O(1).
  Scalar scalar(const EntryRef& ref) const noexcept;
  /// readUnsigned(ref) of the entry `scalar` was resolved from: a load and, for a signed type,
  /// a sign extension. `scalar` is valid. The usual case (a value of 1, 2 or 4 bytes in RAM,
  /// not built for size) is inline.
  uint64_t readUnsigned(const Scalar& scalar) const noexcept {
    if (kExpandFastPaths && (scalar.flags_ & Scalar::kInRom) == 0U) {
      const uint8_t* value = values_ + scalar.offset_;
      uint64_t raw = 0;
      switch (scalar.size_) {
        case 1: raw = *value; break;
        case 2: raw = loadAligned<uint16_t>(value); break;
        case 4: raw = loadAligned<uint32_t>(value); break;
        default: return readScalar(scalar);
      }
      if ((scalar.flags_ & Scalar::kSigned) == 0U) {
        return raw;
      }
      const unsigned unused = 64U - 8U * scalar.size_;
      return static_cast<uint64_t>(static_cast<int64_t>(raw << unused) >> unused);
    }
    return readScalar(scalar);
  }
  /// storeUnsigned(ref, value) of the entry `scalar` was resolved from: a store into RAM; none
  /// for ROM, for a type that is not an integer or boolean, or when `scalar` is not valid.
  void storeUnsigned(const Scalar& scalar, uint64_t value) noexcept {
    if (kExpandFastPaths && (scalar.flags_ & Scalar::kInRom) == 0U) {
      uint8_t* target = values_ + scalar.offset_;
      switch (scalar.size_) {
        case 1: *target = static_cast<uint8_t>(value); return;
        case 2: storeAligned(target, static_cast<uint16_t>(value)); return;
        case 4: storeAligned(target, static_cast<uint32_t>(value)); return;
        default: break;
      }
    }
    storeScalar(scalar, value);
  }

  /// The same two, every case out of line: what a build for size calls.
  uint64_t readScalar(const Scalar& scalar) const noexcept;
  void storeScalar(const Scalar& scalar, uint64_t value) noexcept;

  /// Convenience lookups for the stack's own objects: value of (index, sub) or `fallback` when
  /// absent.
  uint64_t readUnsigned(uint16_t index, uint8_t subIndex, uint64_t fallback) const noexcept;
  /// The same, truncated to 32 bits (as static_cast<uint32_t> of the above): for the stack's
  /// objects of 32 bits or less; cheaper to call where 64-bit values cost (small cores).
  uint32_t readUnsigned32(uint16_t index, uint8_t subIndex, uint32_t fallback) const noexcept;
  /// Stores when present; returns false when absent.
  bool storeUnsigned(uint16_t index, uint8_t subIndex, uint64_t value) noexcept;
  /// The same with a value of 32 bits (storeUnsigned32(ref, value)).
  bool storeUnsigned32(uint16_t index, uint8_t subIndex, uint32_t value) noexcept;

  /// Copies defaults into every RAM entry whose index is in [first, last]: the RAM block from
  /// the base of the first such object to that of the next (Object::ramBase), so a definition
  /// made by hand must satisfy ramInIndexOrder() as the generated ones do.
  void restoreDefaults(uint16_t first, uint16_t last) noexcept;
  /// Copies defaults into every RAM entry of storage group `group`.
  void restoreGroupDefaults(uint8_t group) noexcept;
  /// Copies its default into one RAM entry (with the node-id for a `$NODEID` entry); nothing for
  /// a ROM entry or a DOMAIN.
  void restoreDefault(const EntryRef& ref) noexcept;
  /// restoreDefault() when check() refuses the value the RAM entry holds: outside its limits, or
  /// a BOOLEAN above 1 (entries without limits are not read). Returns true when it did. The
  /// default itself is not checked (the generator warns of a `$NODEID` default that leaves the
  /// limits for some node-ids).
  bool restoreDefaultIfRefused(const EntryRef& ref) noexcept;

  /// Address of a RAM entry's value (nullptr for ROM entries and DOMAINs).
  uint8_t* ramAddress(const EntryRef& ref) noexcept;
  /// Address of an entry's value in RAM or ROM (nullptr for DOMAINs). A `$NODEID` constant
  /// holds its value without the node-id there.
  const uint8_t* address(const EntryRef& ref) const noexcept;

 private:
  /// Zeroes the bytes [begin, end) of the RAM block and writes the defaults among them (with
  /// the node-id for `$NODEID` values).
  void restoreBytes(size_t begin, size_t end) noexcept;
  AbortCode writeChecked(const EntryRef& ref, const uint8_t* source, size_t length) noexcept;
  /// storeUnsigned() of the value whose low and high 32 bits are `low` and `high`.
  void storeHalves(const EntryRef& ref, uint32_t low, uint32_t high) noexcept;

  const Definition* definition_;
  uint8_t* values_;
  uint8_t nodeId_ = 0;
};

}  // namespace costa::od
