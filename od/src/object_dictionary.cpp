#include "costa/od/object_dictionary.hpp"

#include "costa/od/bytes.hpp"
#include "costa/od/little_endian.hpp"

namespace costa::od {
namespace {

// Native bytes of a numeric value in a value block, zero-extended to 64 bits (any byte order).
uint64_t loadNative(const uint8_t* address, size_t size) noexcept {
  switch (size) {
    case 1: return *address;
    case 2: return loadAligned<uint16_t>(address);
    case 4: return loadAligned<uint32_t>(address);
    case 8: return loadAligned<uint64_t>(address);
    default: return 0;
  }
}

void storeNative(uint8_t* address, uint64_t raw, size_t size) noexcept {
  switch (size) {
    case 1: *address = static_cast<uint8_t>(raw); break;
    case 2: storeAligned(address, static_cast<uint16_t>(raw)); break;
    case 4: storeAligned(address, static_cast<uint32_t>(raw)); break;
    case 8: storeAligned(address, raw); break;
    default: break;
  }
}

// Compares a candidate integer value (raw wire bits) with the entry's limits.
AbortCode checkIntegerLimits(const EntryRef& ref, const Limits& limits, uint64_t raw) noexcept {
  if (isSigned(ref.type())) {
    const int64_t value = signExtend(raw, ref.size());
    if (value > static_cast<int64_t>(limits.high)) {
      return AbortCode::kValueTooHigh;
    }
    return value < static_cast<int64_t>(limits.low) ? AbortCode::kValueTooLow : AbortCode::kNone;
  }
  if (raw > limits.high) {
    return AbortCode::kValueTooHigh;
  }
  return raw < limits.low ? AbortCode::kValueTooLow : AbortCode::kNone;
}

// Copies a whole numeric value (1, 2, 4 or 8 bytes) with one load and one store.
void copyNumber(uint8_t* to, const uint8_t* from, size_t size) noexcept {
  switch (size) {
    case 1: *to = *from; break;
    case 2: copyBytes(to, from, 2); break;
    case 4: copyBytes(to, from, 4); break;
    default: copyBytes(to, from, 8); break;
  }
}

constexpr bool nodeIdConstant(uint8_t attributes) noexcept {
  return (attributes & (kNodeIdRelative | kInRom)) == (kNodeIdRelative | kInRom);
}

}  // namespace

ObjectDictionary::ObjectDictionary(const Definition& definition, void* values) noexcept
    : definition_(&definition), values_(static_cast<uint8_t*>(values)) {}

namespace {

// The objects after a collision in the hash table: the next slots, in turn.
[[gnu::noinline]] const Object* probeObject(const Definition& definition, uint16_t index,
                                            uint32_t slot) noexcept {
  const uint32_t mask = (uint32_t{1} << definition.objectSlotBits) - 1U;
  for (slot = (slot + 1U) & mask;; slot = (slot + 1U) & mask) {
    const uint16_t entry = definition.objectSlots[slot];
    if (entry == 0U) {
      return nullptr;
    }
    const Object* object = &definition.objects[entry - 1U];
    if (object->index == index) {
      return object;
    }
  }
}

// The object hash table (Definition::objectSlots): one probe for most objects of a table
// filled to 60 %; else a binary search without a branch on the comparison.
inline const Object* searchObject(const Definition& definition, uint16_t index) noexcept {
  if (definition.objectSlots != nullptr) {
    const uint32_t slot = objectSlotOf(index, definition.objectSlotBits);
    const uint16_t entry = definition.objectSlots[slot];
    if (entry == 0U) {
      return nullptr;
    }
    const Object* object = &definition.objects[entry - 1U];
    return object->index == index ? object : probeObject(definition, index, slot);
  }
  const Object* low = definition.objects;
  size_t count = definition.objectCount;
  if (count == 0U) {
    return nullptr;
  }
  while (count > 1U) {
    const size_t half = count / 2U;
    low = low[half - 1U].index < index ? low + half : low;
    count -= half;
  }
  return low->index == index ? low : nullptr;
}

}  // namespace

const Object* ObjectDictionary::findObject(uint16_t index) const noexcept {
  return searchObject(*definition_, index);
}

AbortCode ObjectDictionary::find(uint16_t index, uint8_t subIndex, EntryRef* out) const noexcept {
  const Object* object = searchObject(*definition_, index);
  if (object == nullptr) {
    return AbortCode::kNoObject;
  }
  const SubEntry* const rows = object->rows;
  for (uint8_t i = 0; i < object->rowCount; ++i) {
    // One comparison: below the row's first sub-index, the difference is negative, which is a
    // large unsigned number.
    if (static_cast<unsigned>(subIndex - rows[i].subIndex) < rows[i].count) {
      *out = EntryRef{object, &rows[i], subIndex};
      return AbortCode::kNone;
    }
  }
  return AbortCode::kNoSubIndex;
}

EntryRef ObjectDictionary::find(uint16_t index, uint8_t subIndex) const noexcept {
  const Object* object = searchObject(*definition_, index);
  return object == nullptr ? EntryRef{} : locate(*object, subIndex);
}

const uint8_t* ObjectDictionary::address(const EntryRef& ref) const noexcept {
  if (ref.type() == DataType::kDomain) {
    return nullptr;
  }
  if (ref.inRom()) {
    return static_cast<const uint8_t*>(definition_->constants) + ref.offset();
  }
  return values_ + ref.offset();
}

uint8_t* ObjectDictionary::ramAddress(const EntryRef& ref) noexcept {
  if (ref.type() == DataType::kDomain || ref.inRom()) {
    return nullptr;
  }
  return values_ + ref.offset();
}

size_t ObjectDictionary::valueSize(const EntryRef& ref) const noexcept {
  if (ref.type() == DataType::kDomain) {
    return 0;
  }
  if (ref.type() == DataType::kVisibleString) {
    const uint8_t* text = address(ref);
    const auto* end = static_cast<const uint8_t*>(__builtin_memchr(text, 0, ref.size()));
    return end != nullptr ? static_cast<size_t>(end - text) : ref.size();
  }
  return ref.size();
}

size_t ObjectDictionary::read(const EntryRef& ref, size_t offset, uint8_t* destination,
                              size_t capacity) const noexcept {
  const size_t total = valueSize(ref);
  if (offset >= total) {
    return 0;
  }
  size_t count = total - offset;
  if (count > capacity) {
    count = capacity;
  }
  const uint8_t* source =
      ref.inRom() ? static_cast<const uint8_t*>(definition_->constants) : values_;
  source += ref.offset();
  if (isNumeric(ref.type()) && (!kLittleEndianHost || nodeIdConstant(ref.attributes()))) {
    uint8_t wire[8];
    uint64_t raw = loadNative(source, ref.size());
    if (nodeIdConstant(ref.attributes())) {
      raw += nodeId_;
    }
    storeLittleEndian(wire, raw, ref.size());
    copyBytes(destination, wire + offset, count);
  } else if (offset == 0U && count == ref.size() && isNumeric(ref.type())) {
    copyNumber(destination, source, count);  // the usual read: a whole number
  } else {
    copyBytes(destination, source + offset, count);
  }
  return count;
}

size_t ObjectDictionary::readWhole(const EntryRef& ref, uint8_t* destination) const noexcept {
  const DataType type = ref.type();
  if (!kExpandFastPaths || isNumeric(type) || type == DataType::kDomain) {  // (for size: read())
    return read(ref, 0, destination, ref.size());
  }
  // A string goes on the wire as it is stored: no byte order, no node-id.
  const size_t size = ref.size();
  const uint8_t* source =
      ref.inRom() ? static_cast<const uint8_t*>(definition_->constants) : values_;
  copyBytes(destination, source + ref.offset(), size);
  if (type != DataType::kVisibleString) {
    return size;
  }
  const auto* end = static_cast<const uint8_t*>(__builtin_memchr(destination, 0, size));
  return end != nullptr ? static_cast<size_t>(end - destination) : size;
}

AbortCode ObjectDictionary::check(const EntryRef& ref, const uint8_t* source,
                                  size_t length) const noexcept {
  if (ref.inRom()) {
    return AbortCode::kWriteOfReadOnly;
  }
  const DataType type = ref.type();
  if (type == DataType::kDomain) {
    return AbortCode::kCannotStore;
  }
  if (length > ref.size()) {
    return AbortCode::kLengthTooHigh;
  }
  if (type == DataType::kVisibleString) {
    return AbortCode::kNone;
  }
  if (length < ref.size()) {
    return AbortCode::kLengthTooLow;
  }
  if (type == DataType::kBoolean) {
    return source[0] > 1U ? AbortCode::kInvalidValue : AbortCode::kNone;
  }
  if (ref.row->limits == 0U) {
    return AbortCode::kNone;
  }
  const Limits& limits = definition_->limits[ref.row->limits - 1U];
  const uint64_t raw = loadLittleEndian(source, ref.size());
  if (isReal(type)) {
    return definition_->realLimits != nullptr ? definition_->realLimits(type, raw, limits)
                                              : AbortCode::kNone;
  }
  return checkIntegerLimits(ref, limits, raw);
}

AbortCode ObjectDictionary::writeChecked(const EntryRef& ref, const uint8_t* source,
                                         size_t length) noexcept {
  const AbortCode verdict = check(ref, source, length);
  if (verdict != AbortCode::kNone) {
    return verdict;
  }
  uint8_t* target = values_ + ref.offset();
  if (isNumeric(ref.type())) {
    if (kLittleEndianHost) {
      copyNumber(target, source, ref.size());
    } else {
      storeNative(target, loadLittleEndian(source, ref.size()), ref.size());
    }
  } else {
    copyBytes(target, source, length);
    if (length < ref.size()) {
      fillBytes(target + length, 0, ref.size() - length);
    }
  }
  return AbortCode::kNone;
}

uint64_t ObjectDictionary::readUnsigned(const EntryRef& ref) const noexcept {
  const DataType type = ref.type();
  if (!isSigned(type) && !isUnsigned(type)) {
    return 0;
  }
  uint64_t raw = loadNative(address(ref), ref.size());
  if (nodeIdConstant(ref.attributes())) {
    raw += nodeId_;
  }
  if (isSigned(type)) {
    return static_cast<uint64_t>(signExtend(raw, ref.size()));
  }
  return raw;
}

int64_t ObjectDictionary::readSigned(const EntryRef& ref) const noexcept {
  return static_cast<int64_t>(readUnsigned(ref));
}

void ObjectDictionary::storeUnsigned(const EntryRef& ref, uint64_t value) noexcept {
  uint8_t* target = ramAddress(ref);
  if (target == nullptr || !(isSigned(ref.type()) || isUnsigned(ref.type()))) {
    return;
  }
  storeNative(target, value, ref.size());
}

uint64_t ObjectDictionary::readUnsigned(uint16_t index, uint8_t subIndex,
                                        uint64_t fallback) const noexcept {
  const EntryRef ref = find(index, subIndex);
  return ref.valid() ? readUnsigned(ref) : fallback;
}

uint32_t ObjectDictionary::readUnsigned32(uint16_t index, uint8_t subIndex,
                                          uint32_t fallback) const noexcept {
  const EntryRef ref = find(index, subIndex);
  return ref.valid() ? static_cast<uint32_t>(readUnsigned(ref)) : fallback;
}

bool ObjectDictionary::storeUnsigned(uint16_t index, uint8_t subIndex, uint64_t value) noexcept {
  const EntryRef ref = find(index, subIndex);
  if (!ref.valid()) {
    return false;
  }
  storeUnsigned(ref, value);
  return true;
}

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

// Writes one default at `target`.
void writeDefault(const Definition& definition, const DefaultValue& value,
                  uint8_t* target) noexcept {
  const size_t bytes = value.bytes();
  if (value.numeric()) {
    const uint64_t raw = bytes <= 4U
                             ? value.value
                             : loadLittleEndianBytes(definition.defaultBytes + value.value, bytes);
    storeNative(target, raw, bytes);
  } else {
    copyBytes(target, definition.defaultBytes + value.value, bytes);
  }
}

}  // namespace

void copyDefault(const Definition& definition, const EntryRef& ref, uint8_t* destination) noexcept {
  const size_t bytes = storageBytes(*ref.row);
  fillBytes(destination, 0, bytes);
  const DefaultValue* value = firstDefaultFrom(definition, ref.offset());
  if (value < definition.defaults + definition.defaultCount && value->offset == ref.offset()) {
    writeDefault(definition, *value, destination);
  }
}

void ObjectDictionary::restoreRow(const SubEntry& row) noexcept {
  if (row.type == DataType::kDomain || (row.attributes & kInRom) != 0U) {
    return;
  }
  const size_t bytes = storageBytes(row);
  const size_t end = row.offset + row.count * bytes;
  fillBytes(values_ + row.offset, 0, end - row.offset);
  const Definition& definition = *definition_;
  const DefaultValue* last = definition.defaults + definition.defaultCount;
  for (const DefaultValue* value = firstDefaultFrom(definition, row.offset);
       value < last && value->offset < end; ++value) {
    writeDefault(definition, *value, values_ + value->offset);
  }
  if ((row.attributes & kNodeIdRelative) != 0U) {
    addNodeId(row);
  }
}

void ObjectDictionary::addNodeId(const SubEntry& row) noexcept {
  const size_t end = row.offset + row.count * storageBytes(row);
  for (size_t offset = row.offset; offset < end; offset += storageBytes(row)) {
    storeNative(values_ + offset, loadNative(values_ + offset, row.size) + nodeId_, row.size);
  }
}

template <typename Wanted>
void ObjectDictionary::restoreRows(const Object& object, Wanted wanted) noexcept {
  for (uint8_t i = 0; i < object.rowCount; ++i) {
    if (wanted(object.rows[i])) {
      restoreRow(object.rows[i]);
    }
  }
}

namespace {
// Calls visit(row) for every row of the objects whose index lies in [first, last].
template <typename Visit>
void forEachRowIn(const Definition& definition, uint16_t first, uint16_t last, Visit visit) {
  for (size_t i = 0; i < definition.objectCount; ++i) {
    const Object& object = definition.objects[i];
    if (object.index > last) {
      break;  // objects are in the order of their indices
    }
    if (object.index < first) {
      continue;
    }
    for (uint8_t r = 0; r < object.rowCount; ++r) {
      visit(object.rows[r]);
    }
  }
}
}  // namespace

void ObjectDictionary::restoreDefaults(uint16_t first, uint16_t last) noexcept {
  // The RAM values of [first, last] are one range of the block (ramInIndexOrder): zero it,
  // then write the non-zero defaults that fall in it, then add the node-id where it belongs.
  const Definition& definition = *definition_;
  size_t begin = SIZE_MAX;
  size_t end = 0;
  if (first == 0U && last == UINT16_MAX) {
    begin = 0;
    end = definition.valuesSize;
  } else {
    forEachRowIn(definition, first, last, [&begin, &end](const SubEntry& row) {
      if (row.type == DataType::kDomain || (row.attributes & kInRom) != 0U) {
        return;
      }
      begin = begin == SIZE_MAX ? row.offset : begin;
      end = row.offset + row.count * storageBytes(row);
    });
  }
  if (begin == SIZE_MAX) {
    return;
  }
  fillBytes(values_ + begin, 0, end - begin);
  const DefaultValue* stop = definition.defaults + definition.defaultCount;
  for (const DefaultValue* value = firstDefaultFrom(definition, begin);
       value < stop && value->offset < end; ++value) {
    writeDefault(definition, *value, values_ + value->offset);
  }
  forEachRowIn(definition, first, last, [this](const SubEntry& row) {
    if ((row.attributes & (kNodeIdRelative | kInRom)) == kNodeIdRelative) {
      addNodeId(row);
    }
  });
}

void ObjectDictionary::restoreGroupDefaults(uint8_t group) noexcept {
  for (size_t i = 0; i < definition_->objectCount; ++i) {
    restoreRows(definition_->objects[i],
                [group](const SubEntry& row) { return row.group == group; });
  }
}

}  // namespace costa::od
