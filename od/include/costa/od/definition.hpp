// The read-only description of one object dictionary, as emitted by the generator
// (od/generator). Everything here lives in ROM; the values of variables live in a RAM block
// owned by the node (see ObjectDictionary).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "costa/od/data_type.hpp"

namespace costa::od {

/// Attribute bits of a sub-entry.
enum Attribute : uint16_t {
  kReadable = 1U << 0,        ///< SDO upload allowed (ro, rw, rwr, rww, const).
  kWritable = 1U << 1,        ///< SDO download allowed (wo, rw, rwr, rww).
  kInRom = 1U << 2,           ///< `const`: the value is in the constants block, not in RAM.
  kRpdoMappable = 1U << 3,    ///< May be mapped into an RPDO.
  kTpdoMappable = 1U << 4,    ///< May be mapped into a TPDO.
  kNodeIdRelative = 1U << 5,  ///< Default is `$NODEID + value`.
  kHasLimits = 1U << 6,       ///< `limits` points at LowLimit/HighLimit.
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

/// One sub-index of an object.
struct SubEntry {
  uint8_t subIndex;
  DataType type;
  uint16_t attributes;   ///< Attribute bits.
  uint16_t size;         ///< Bytes of the value; capacity for VISIBLE_STRING; 0 for DOMAIN.
  uint8_t group;         ///< StorageGroup.
  uint32_t offset;       ///< Byte offset in the RAM values block, or in the ROM constants block
                         ///< when kInRom. The ROM defaults block has the values' layout.
  const Limits* limits;  ///< Non-null exactly when kHasLimits.
};

/// Object codes of CiA 301 (EDS ObjectType).
enum class ObjectCode : uint8_t {
  kDomain = 0x02,
  kVar = 0x07,
  kArray = 0x08,
  kRecord = 0x09,
};

/// One index of the dictionary; `subs` is sorted by sub-index.
struct Object {
  uint16_t index;
  ObjectCode code;
  uint8_t subCount;
  const SubEntry* subs;
};

/// A whole dictionary. `objects` is sorted by index.
struct Definition {
  const Object* objects;
  uint16_t objectCount;
  const void* constants;   ///< ROM block holding `const` values.
  const void* defaults;    ///< ROM block holding default values, laid out like the RAM block.
  uint32_t valuesSize;     ///< Size of the RAM values block in bytes.
  uint32_t layoutId;       ///< Identifies the layout of the stored groups (for stored images).
  const char* deviceName;  ///< Name of the device description the tables were generated from.
};

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
