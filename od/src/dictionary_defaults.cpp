// Defaults: the RAM values an object dictionary starts from, restored by index range or by
// storage group, and one entry's default for the parameter store.
#include "costa/od/object_dictionary.hpp"

#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"

namespace costa::od {
namespace {

// Bytes a value of `row` takes in its block: a VISIBLE_STRING keeps a terminating zero.
size_t storageBytes(const SubEntry& row) noexcept {
  return row.type == DataType::kVisibleString ? row.size + 1U : row.size;
}

// The first default at or after `offset` (binary search: the defaults are sorted by offset).
const DefaultValue* firstDefaultFrom(const Definition& definition, size_t offset) noexcept {
  const DefaultValue* low = definition.defaults;
  size_t count = definition.defaultCount;
  while (count > 0U) {
    const size_t half = count / 2U;
    if (low[half].offset < offset) {
      low += half + 1U;
      count -= half + 1U;
    } else {
      count = half;
    }
  }
  return low;
}

// Writes one default of `row` (storage bytes, whether it is a number) at `target`.
void writeDefault(const Definition& definition, const SubEntry& row, const DefaultValue& value,
                  uint8_t* target) noexcept {
  const size_t bytes = storageBytes(row);
  if (isNumeric(row.type) && bytes <= 4U) {
    storeNative32(target, value.value(), bytes);  // the number itself
    return;
  }
  const uint8_t* stored = definition.defaultBytes + value.value();
  if (!isNumeric(row.type) || kLittleEndianHost) {
    copyBytes(target, stored, bytes);  // a longer number's little-endian bytes are its own here
  } else {
    storeNative(target, loadLittleEndianBytes(stored, bytes), bytes);
  }
}

}  // namespace

void copyDefault(const Definition& definition, const EntryRef& ref, uint8_t* destination) noexcept {
  const size_t bytes = storageBytes(*ref.row);
  fillBytes(destination, 0, bytes);
  const DefaultValue* value = firstDefaultFrom(definition, ref.offset());
  if (value < definition.defaults + definition.defaultCount && value->offset == ref.offset()) {
    writeDefault(definition, *ref.row, *value, destination);
  }
}

void ObjectDictionary::restoreRow(const Object& object, const SubEntry& row) noexcept {
  if (row.type == DataType::kDomain || (row.attributes & kInRom) != 0U) {
    return;
  }
  const size_t begin = valueOffset(object, row, 0);
  const size_t end = begin + row.count * storageBytes(row);
  fillBytes(values_ + begin, 0, end - begin);
  const Definition& definition = *definition_;
  const DefaultValue* last = definition.defaults + definition.defaultCount;
  for (const DefaultValue* value = firstDefaultFrom(definition, begin);
       value < last && value->offset < end; ++value) {
    writeDefault(definition, row, *value, values_ + value->offset);
  }
  if ((row.attributes & kNodeIdRelative) != 0U) {
    addNodeId(object, row);
  }
}

void ObjectDictionary::restoreDefault(const EntryRef& ref) noexcept {
  uint8_t* value = ramAddress(ref);
  if (value == nullptr) {
    return;
  }
  copyDefault(*definition_, ref, value);
  if (ref.has(kNodeIdRelative)) {
    addNodeIdTo(value, ref.size());
  }
}

bool ObjectDictionary::restoreDefaultIfRefused(const EntryRef& ref) noexcept {
  uint8_t value[8] = {};
  if ((ref.row->limits == 0U && ref.type() != DataType::kBoolean) || ref.size() > sizeof(value) ||
      ramAddress(ref) == nullptr) {
    return false;
  }
  readNumber(ref, value);
  if (check(ref, value, ref.size()) == AbortCode::kNone) {
    return false;
  }
  restoreDefault(ref);
  return true;
}

void ObjectDictionary::addNodeId(const Object& object, const SubEntry& row) noexcept {
  const size_t begin = valueOffset(object, row, 0);
  const size_t end = begin + row.count * storageBytes(row);
  for (size_t offset = begin; offset < end; offset += storageBytes(row)) {
    addNodeIdTo(values_ + offset, row.size);
  }
}

void ObjectDictionary::restoreRows(uint16_t first, uint16_t last, unsigned group) noexcept {
  const Definition& definition = *definition_;
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const Object& object = definition.objects[i];
    if (object.index > last) {
      break;  // objects are in the order of their indices
    }
    if (object.index < first) {
      continue;
    }
    const SubEntry* rows = rowsOf(definition, object);
    for (uint8_t r = 0; r < object.rowCount; ++r) {
      if (group == kAnyGroup || rows[r].group == group) {
        restoreRow(object, rows[r]);
      }
    }
  }
}

void ObjectDictionary::restoreDefaults(uint16_t first, uint16_t last) noexcept {
  restoreRows(first, last, kAnyGroup);
}

void ObjectDictionary::restoreGroupDefaults(uint8_t group) noexcept {
  restoreRows(0, UINT16_MAX, group);
}

}  // namespace costa::od
