// The read-only description of one object dictionary, as emitted by the generator
// (od/generator). Everything here lives in ROM; the values of variables live in a RAM block
// owned by the node (see ObjectDictionary).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/abort_code.hpp"
#include "costa/od/data_type.hpp"

namespace costa::od {

/// Attribute bits of a sub-entry.
enum Attribute : uint8_t {
  kReadable = 1U << 0,        ///< SDO upload allowed (ro, rw, rwr, rww, const).
  kWritable = 1U << 1,        ///< SDO download allowed (wo, rw, rwr, rww).
  kInRom = 1U << 2,           ///< `const`: the value is in the constants block, not in RAM.
  kRpdoMappable = 1U << 3,    ///< May be mapped into an RPDO.
  kTpdoMappable = 1U << 4,    ///< May be mapped into a TPDO.
  kNodeIdRelative = 1U << 5,  ///< Default is `$NODEID + value`.
  kHasLimits = 1U << 6,       ///< SubEntry::limits names a LowLimit/HighLimit row.
  /// An integer (not a BOOLEAN) in RAM without limits: a write of its size has nothing to
  /// check. Set by the generator; a row without it takes the full checks.
  kPlainInteger = 1U << 7,
};

/// Storage groups: which save/restore command covers a sub-entry (0x1010/0x1011 sub-indices).
enum StorageGroup : uint8_t {
  kGroupNone = 0,           ///< Volatile, never stored.
  kGroupCommunication = 1,  ///< 0x1000..0x1FFF parameters.
  kGroupApplication = 2,    ///< Manufacturer and profile parameters.
  kGroupLss = 3,            ///< LSS-configured parameters (node-id, bit rate).
  // Devices may use further groups from 4 on.
};

/// LowLimit and HighLimit as raw 64-bit patterns, interpreted by the entry's data type:
/// unsigned types as uint64_t, signed types as int64_t (two's complement), REAL32 and REAL64
/// as the bits of a double.
struct Limits {
  uint64_t low;
  uint64_t high;
};

/// Checks a value of `type` (its `size` bytes on the wire, little-endian, at `source`) against
/// its limits: kValueTooHigh, kValueTooLow, kInvalidValue (a REAL that is NaN) or kNone. The
/// generator names one in a Definition only when the dictionary has an entry with limits:
/// checkIntegerLimits when none of them is a REAL, checkLimits otherwise. So a dictionary
/// without limits links no limit code, and one without REAL limits no floating-point code.
using LimitCheck = AbortCode (*)(DataType type, const uint8_t* source, size_t size,
                                 const Limits& limits);
/// Integer limits only (a REAL passes).
AbortCode checkIntegerLimits(DataType type, const uint8_t* source, size_t size,
                             const Limits& limits) noexcept;
/// Integer and REAL limits.
AbortCode checkLimits(DataType type, const uint8_t* source, size_t size,
                      const Limits& limits) noexcept;

/// Flag bits of a DefaultValue.
enum DefaultFlag : uint8_t {
  /// value is where the default's bytes begin in Definition::defaultBytes (little-endian for a
  /// number); else value is the number itself (CPU byte order once stored).
  kDefaultInBytes = 1U << 0,
  kDefaultNumber = 1U << 1,  ///< A number (in CPU byte order in RAM), not a string's bytes.
  kDefaultNodeId = 1U << 2,  ///< `$NODEID + value`: the node-id is added as it is restored.
  /// Bits 29..31 of a number held as itself (not kDefaultInBytes), in bits 5..7 of the flags:
  /// a COB-ID's flag bits (invalid, no RTR, 29-bit frame) above its 16-bit value.
  kDefaultTopBits = 7U << 5,
};

/// The kDefaultTopBits of the flags of `number`, a number held as itself (bits 16..28 clear).
constexpr uint8_t defaultTopBits(uint32_t number) noexcept {
  return static_cast<uint8_t>((number >> 29U) << 5U);
}

/// A default of the RAM block: the `size` bytes at `offset`. A number of up to 4 bytes whose
/// bits 16..28 are clear is `value` itself (its bits 0..15) plus kDefaultTopBits (its bits
/// 29..31); anything else (larger numbers, strings with a
/// VISIBLE_STRING's terminating zero, octet strings) is the little-endian bytes at
/// Definition::defaultBytes + value (kDefaultInBytes), in pieces of at most 255 bytes. Every
/// byte no DefaultValue covers defaults to zero; every `$NODEID` value has one (its value
/// without the node-id, perhaps 0). Each says how many bytes it writes, so a range of the RAM
/// block is restored without its rows. Six bytes.
struct DefaultValue {
  uint16_t value;
  uint16_t offset;
  uint8_t size;   ///< Bytes of the value in the RAM block.
  uint8_t flags;  ///< DefaultFlag bits.
};

/// True when `defaults` are in strictly increasing order of offsets (the generator checks its
/// tables with it at compile time; lookups depend on it).
template <size_t N>
constexpr bool sortedByOffset(const DefaultValue (&defaults)[N]) noexcept {
  for (size_t i = 1; i < N; ++i) {
    if (defaults[i].offset <= defaults[i - 1U].offset) {
      return false;
    }
  }
  return true;
}

/// One row of an object: `count` consecutive sub-indices from `subIndex` that share every
/// property. Value k of the row (sub-index subIndex + k) lies at `offset + k * size` from its
/// object's base in the RAM block (Object::ramBase), or, when kInRom, from the start of the
/// constants block; the generator merges only fixed-size values stored back to back (array
/// items, record members of one type). Objects of one shape (the PDO parameters of a kind, VARs
/// of one type and access) share their rows, and objects whose constants are equal too share
/// one copy of those constants. Use EntryRef for one sub-index's properties.
struct SubEntry {
  uint8_t subIndex;    ///< First sub-index of the row.
  uint8_t count;       ///< Sub-indices in the row, 1..255.
  DataType type;       ///< CiA 301 data type.
  uint8_t attributes;  ///< Attribute bits.
  uint16_t size;       ///< Bytes of one value; capacity for VISIBLE_STRING; 0 for DOMAIN.
  uint8_t group;       ///< StorageGroup.
  uint8_t limits;      ///< 0: no limits; else 1 + the row of Definition::limits.
  uint16_t offset;     ///< Of the first value: from the object's base in the RAM values
                       ///< block, or from the start of the ROM constants block when kInRom.
};

/// Object codes of CiA 301 (EDS ObjectType).
enum class ObjectCode : uint8_t {
  kDomain = 0x02,
  kVar = 0x07,
  kArray = 0x08,
  kRecord = 0x09,
};

/// One index of the dictionary: `rowCount` rows from Definition::rows[firstRow], sorted by
/// sub-index (rowsOf()), and where its values begin in the RAM block (the rows of its constants
/// say where those are). 8 bytes, no pointer: the rows of objects of one shape are one run of
/// Definition::rows.
struct Object {
  uint16_t index;
  ObjectCode code;
  uint8_t rowCount;
  uint16_t firstRow;
  /// Offset of its values in the RAM block (its rows' offsets add to it); of an object without
  /// RAM values, that of the next object's (Definition::valuesSize after the last). So the
  /// values of the objects from one to another are the RAM block from one's base to the other's.
  uint16_t ramBase;
};

/// A whole dictionary. `objects` is sorted by index.
struct Definition {
  const Object* objects;
  uint16_t objectCount;
  const SubEntry* rows;          ///< Every object's rows (Object::firstRow).
  const void* constants;         ///< ROM block holding `const` values.
  const DefaultValue* defaults;  ///< Non-zero and `$NODEID` defaults of the RAM block, by offset.
  const uint8_t* defaultBytes;   ///< Bytes of the defaults longer than 4 bytes.
  uint16_t defaultCount;
  uint32_t valuesSize;     ///< Size of the RAM values block in bytes.
  uint32_t layoutId;       ///< Identifies the layout of the stored groups (for stored images).
  const char* deviceName;  ///< Name of the device description the tables were generated from.
  const Limits* limits;    ///< Rows named by SubEntry::limits (null when none has limits).
  /// The check of the entries that have limits; null: limits are not checked (the generator
  /// names one whenever an entry has limits).
  LimitCheck limitCheck;
  /// Open-addressed hash table of the objects: 2^(32 - objectSlotShift) entries, each 0 (empty) or
  /// 1 + the object's position in `objects`; see objectSlotOf(). Null: lookups search the
  /// sorted `objects` instead (a definition made by hand; every generated one built for size,
  /// -Os, where the binary search spares the table and its code).
  const uint16_t* objectSlots;
  uint8_t objectSlotShift;  ///< 32 - log2 of the table's size (objectSlotOf())
  /// Bit n set: the dummy entry of data type 0x000n (n = 2..7, INTEGER8..UNSIGNED32) may be
  /// mapped into an RPDO (the EDS's [DummyUsage]). 0: none may.
  uint8_t dummyUsage;
};

/// The first slot of the object hash table to look at for `index`: Fibonacci hashing of the
/// 16-bit index (its product with 40503, 2^16 over the golden ratio, modulo 2^16, whose top
/// 32 - `shift` bits are the slot: computed in the top half of a 32-bit product, a multiply and
/// a shift); collisions go on to the next slot (linear probing). The generator builds the table
/// with this very function.
constexpr uint32_t objectSlotOf(uint16_t index, uint8_t shift) noexcept {
  return (static_cast<uint32_t>(index) * (40503U << 16U)) >> shift;
}

/// The rows of `object` (Object::rowCount of them).
constexpr const SubEntry* rowsOf(const Definition& definition, const Object& object) noexcept {
  return definition.rows + object.firstRow;
}

/// Offset of value `k` of `row` of `object` in the row's block.
constexpr uint32_t valueOffset(const Object& object, const SubEntry& row, uint32_t k) noexcept {
  return ((row.attributes & kInRom) != 0U ? 0U : object.ramBase) + row.offset + k * row.size;
}

/// True when the RAM values of `objects` lie in the order of their indices and sub-indices, as
/// the generator lays them out (it checks its tables with it at compile time), and every
/// object's values lie between its Object::ramBase and the next object's: the values of a range
/// of indices are one range of the RAM block, and a dump of the block reads in the
/// dictionary's order.
template <size_t N>
constexpr bool ramInIndexOrder(const Object (&objects)[N], const SubEntry* rows) noexcept {
  uint32_t end = 0;
  for (size_t i = 0; i < N; ++i) {
    if (objects[i].ramBase < end || (i > 0U && objects[i].ramBase < objects[i - 1U].ramBase)) {
      return false;
    }
    for (unsigned r = 0; r < objects[i].rowCount; ++r) {
      const SubEntry& row = rows[objects[i].firstRow + r];
      if ((row.attributes & kInRom) != 0U || row.type == DataType::kDomain) {
        continue;
      }
      const uint32_t offset = valueOffset(objects[i], row, 0);
      if (offset < end) {
        return false;
      }
      const uint32_t bytes = row.type == DataType::kVisibleString ? row.size + 1U : row.size;
      end = offset + row.count * bytes;
    }
  }
  return true;
}

/// Number of sub-indices an object has (sub-index 0 included).
constexpr unsigned entryCount(const Definition& definition, const Object& object) noexcept {
  unsigned count = 0;
  const SubEntry* rows = rowsOf(definition, object);
  for (unsigned row = 0; row < object.rowCount; ++row) {
    count += rows[row].count;
  }
  return count;
}

/// Optional names of objects and sub-indices, emitted in a separate translation unit so that
/// firmware builds need not link them. Sorted by (index, subIndex).
struct EntryName {
  uint16_t index;
  uint8_t subIndex;
  const char* name;
};

struct NameTable {
  const EntryName* names;
  uint32_t count;
};

}  // namespace costa::od
