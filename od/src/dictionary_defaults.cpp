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

// Writes one default at `target`, adding `nodeId` to a `$NODEID` value.
void writeDefault(const Definition& definition, const DefaultValue& value, uint8_t* target,
                  uint8_t nodeId) noexcept {
  const uint8_t addend = (value.flags & kDefaultNodeId) != 0U ? nodeId : 0U;
  if ((value.flags & kDefaultInBytes) == 0U) {
    // The number itself: no carry of the 16-bit value's sum reaches the top bits.
    const uint32_t top = static_cast<uint32_t>(value.flags & kDefaultTopBits) << (29U - 5U);
    storeNative32(target, value.value + addend + top, value.size);
    return;
  }
  const uint8_t* stored = definition.defaultBytes + value.value;
  if (kLittleEndianHost || (value.flags & kDefaultNumber) == 0U) {
    copyBytes(target, stored, value.size);  // a longer number's little-endian bytes are its own
    addLittleEndian(target, value.size, addend);  // (a string's addend is 0: nothing)
  } else {
    storeNative(target, loadLittleEndianBytes(stored, value.size) + addend, value.size);
  }
}

// Writes the defaults of the RAM bytes [begin, end) into `target`, which stands for byte
// `begin` (zeroed before: the bytes no default covers stay zero).
void writeDefaults(const Definition& definition, size_t begin, size_t end, uint8_t* target,
                   uint8_t nodeId) noexcept {
  const DefaultValue* last = definition.defaults + definition.defaultCount;
  for (const DefaultValue* value = firstDefaultFrom(definition, begin);
       value < last && value->offset < end; ++value) {
    writeDefault(definition, *value, target + (value->offset - begin), nodeId);
  }
}

}  // namespace

void copyDefault(const Definition& definition, const EntryRef& ref, uint8_t* destination) noexcept {
  const size_t bytes = storageBytes(*ref.row);
  fillBytes(destination, 0, bytes);
  writeDefaults(definition, ref.offset(), ref.offset() + bytes, destination, 0);
}

void ObjectDictionary::restoreBytes(size_t begin, size_t end) noexcept {
  fillBytes(values_ + begin, 0, end - begin);
  writeDefaults(*definition_, begin, end, values_ + begin, nodeId_);
}

void ObjectDictionary::restoreDefault(const EntryRef& ref) noexcept {
  if (ramAddress(ref) != nullptr) {
    restoreBytes(ref.offset(), ref.offset() + storageBytes(*ref.row));
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

void ObjectDictionary::restoreDefaults(uint16_t first, uint16_t last) noexcept {
  // The values of the objects in [first, last] are the RAM block from the base of the first of
  // them to the base of the object after the last (Object::ramBase).
  const Definition& definition = *definition_;
  const Object* object = definition.objects;
  const Object* const end = object + definition.objectCount;
  while (object != end && object->index < first) {
    ++object;
  }
  const size_t begin = object != end ? object->ramBase : definition.valuesSize;
  while (object != end && object->index <= last) {
    ++object;
  }
  const size_t stop = object != end ? object->ramBase : definition.valuesSize;
  if (begin < stop) {  // (a table made by hand without ramInIndexOrder() restores nothing)
    restoreBytes(begin, stop);
  }
}

void ObjectDictionary::restoreGroupDefaults(uint8_t group) noexcept {
  const Definition& definition = *definition_;
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const Object& object = definition.objects[i];
    const SubEntry* rows = rowsOf(definition, object);
    for (uint8_t r = 0; r < object.rowCount; ++r) {
      const SubEntry& row = rows[r];
      if (row.group == group && row.type != DataType::kDomain && (row.attributes & kInRom) == 0U) {
        const size_t begin = valueOffset(object, row, 0);
        restoreBytes(begin, begin + row.count * storageBytes(row));
      }
    }
  }
}

}  // namespace costa::od
