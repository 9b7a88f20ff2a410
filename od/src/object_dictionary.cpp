#include "costa/od/object_dictionary.hpp"

#include "costa/od/bytes.hpp"
#include "costa/od/integer_limits.hpp"
#include "costa/od/little_endian.hpp"

namespace costa::od {
namespace {

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

namespace {

// The objects after a collision in the hash table: the next slots, in turn.
[[gnu::noinline]] const Object* probeObject(const Definition& definition, uint16_t index,
                                            uint32_t slot) noexcept {
  const uint32_t mask = (uint32_t{1} << (32U - definition.objectSlotShift)) - 1U;
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

// A binary search of the sorted objects without a branch on the comparison.
[[gnu::noinline]] const Object* searchSorted(const Definition& definition,
                                             uint16_t index) noexcept {
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

// The object hash table (Definition::objectSlots): one probe for most objects of a table
// filled to 60 %; else, and in a build for size (which has no table), the binary search (a
// call of its own: the usual lookup needs fewer registers, and the finds share one copy).
inline const Object* searchObject(const Definition& definition, uint16_t index) noexcept {
  if (kExpandFastPaths && definition.objectSlots != nullptr) {
    const uint32_t slot = objectSlotOf(index, definition.objectSlotShift);
    const uint16_t entry = definition.objectSlots[slot];
    if (entry == 0U) {
      return nullptr;
    }
    const Object* object = &definition.objects[entry - 1U];
    return object->index == index ? object : probeObject(definition, index, slot);
  }
  return searchSorted(definition, index);
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
  const SubEntry* row = rowsOf(*definition_, *object);
  for (unsigned left = object->rowCount; left != 0U; --left, ++row) {
    // One comparison: below the row's first sub-index, the difference is negative, which is a
    // large unsigned number.
    const auto k = static_cast<unsigned>(subIndex - row->subIndex);
    if (k < row->count) {
      *out = EntryRef{object, row, subIndex, static_cast<uint16_t>(valueOffset(*object, *row, k))};
      return AbortCode::kNone;
    }
  }
  return AbortCode::kNoSubIndex;
}

EntryRef ObjectDictionary::find(uint16_t index, uint8_t subIndex) const noexcept {
  EntryRef ref;
  (void)find(index, subIndex, &ref);  // `ref` stays invalid when it fails
  return ref;
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

namespace {
/// The bytes of a VISIBLE_STRING before its first NUL, at most `capacity`: the library's search
/// where speed counts, a loop where size does (it spares the library function's code).
size_t textLength(const uint8_t* text, size_t capacity) noexcept {
  if constexpr (kExpandFastPaths) {
    const auto* end = static_cast<const uint8_t*>(__builtin_memchr(text, 0, capacity));
    return end != nullptr ? static_cast<size_t>(end - text) : capacity;
  } else {
    size_t length = 0;
    while (length < capacity && text[length] != 0U) {
      ++length;
    }
    return length;
  }
}
}  // namespace

size_t ObjectDictionary::valueSize(const EntryRef& ref) const noexcept {
  if (ref.type() == DataType::kDomain) {
    return 0;
  }
  if (ref.type() == DataType::kVisibleString) {
    return textLength(address(ref), ref.size());
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
    if constexpr (kLittleEndianHost) {  // a `$NODEID` constant: its bytes plus the node-id
      copyBytes(wire, source, ref.size());
      addLittleEndian(wire, ref.size(), nodeId_);
    } else {
      uint64_t raw = loadNative(source, ref.size());
      if (nodeIdConstant(ref.attributes())) {
        raw += nodeId_;
      }
      storeLittleEndian(wire, raw, ref.size());
    }
    copyBytes(destination, wire + offset, count);
  } else if (kExpandFastPaths && offset == 0U && count == ref.size() && isNumeric(ref.type())) {
    copyNumber(destination, source, count);  // the usual read: a whole number (for size: below)
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
  return textLength(destination, size);
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
  if (ref.row->limits == 0U || definition_->limitCheck == nullptr) {
    return AbortCode::kNone;
  }
  const Limits& limits = definition_->limits[ref.row->limits - 1U];
  if (kExpandFastPaths && !isReal(type)) {  // where speed counts, integers without the call
    return integerLimitsVerdict(type, ref.size(), loadLittleEndian(source, ref.size()), limits);
  }
  return definition_->limitCheck(type, source, ref.size(), limits);
}

AbortCode ObjectDictionary::writeChecked(const EntryRef& ref, const uint8_t* source,
                                         size_t length) noexcept {
  const AbortCode verdict = check(ref, source, length);
  if (verdict != AbortCode::kNone) {
    return verdict;
  }
  uint8_t* target = values_ + ref.offset();
  // A number's wire bytes are its RAM bytes on a little-endian CPU: built for size, they take
  // the copy below (check() passed: the length is the size).
  if (isNumeric(ref.type()) && (kExpandFastPaths || !kLittleEndianHost)) {
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

uint32_t ObjectDictionary::readUnsigned32(const EntryRef& ref) const noexcept {
  const uint32_t typeBit = detail::typeBit(ref.type());  // one bit for both tests below
  if ((typeBit & (detail::kSignedTypes | detail::kUnsignedTypes)) == 0U) {
    return 0;
  }
  const uint8_t* value = address(ref);
  const size_t size = ref.size();
  uint32_t raw = 0;  // as loadNative(): 0 for a size other than 1, 2, 4 and 8
  if (size == 1U) {
    raw = *value;
  } else if (size == 2U) {
    raw = loadAligned<uint16_t>(value);
  } else if (size == 4U || size == 8U) {  // of 8 bytes, the low half
    raw = loadAligned<uint32_t>(kLittleEndianHost || size == 4U ? value : value + 4);
  }
  if (nodeIdConstant(ref.attributes())) {
    raw += nodeId_;
  }
  if (size - 1U < 3U) {  // 1 to 3 bytes: within the value's width (a `$NODEID` constant's sum,
    // as it goes on the wire), a signed value's sign in the upper bits
    const auto unused = static_cast<unsigned>(32U - 8U * size);
    raw <<= unused;
    raw = (typeBit & detail::kSignedTypes) != 0U
              ? static_cast<uint32_t>(static_cast<int32_t>(raw) >> unused)
              : raw >> unused;
  }
  return raw;
}

uint64_t ObjectDictionary::readUnsigned(const EntryRef& ref) const noexcept {
  const uint32_t low = readUnsigned32(ref);  // 0 for a type that is not an integer
  const DataType type = ref.type();
  if (ref.size() != 8U || (!isSigned(type) && !isUnsigned(type))) {
    // Of up to 4 bytes, widened; 5 to 7 bytes hold 0 (and a `$NODEID` constant its node-id).
    return isSigned(type) ? static_cast<uint64_t>(static_cast<int32_t>(low)) : low;
  }
  auto raw = loadAligned<uint64_t>(address(ref));
  if (nodeIdConstant(ref.attributes())) {
    raw += nodeId_;
  }
  return raw;
}

int64_t ObjectDictionary::readSigned(const EntryRef& ref) const noexcept {
  return static_cast<int64_t>(readUnsigned(ref));
}

void ObjectDictionary::storeHalves(const EntryRef& ref, uint32_t low, uint32_t high) noexcept {
  uint8_t* target = ramAddress(ref);
  if (target == nullptr || !(isSigned(ref.type()) || isUnsigned(ref.type()))) {
    return;
  }
  if (ref.size() == 8U) {  // two aligned words, in the CPU's order of the halves
    storeAligned(target + (kLittleEndianHost ? 0U : 4U), low);
    storeAligned(target + (kLittleEndianHost ? 4U : 0U), high);
    return;
  }
  storeNative32(target, low, ref.size());
}

uint64_t ObjectDictionary::readUnsigned(uint16_t index, uint8_t subIndex,
                                        uint64_t fallback) const noexcept {
  const EntryRef ref = find(index, subIndex);
  return ref.valid() ? readUnsigned(ref) : fallback;
}

uint32_t ObjectDictionary::readUnsigned32(uint16_t index, uint8_t subIndex,
                                          uint32_t fallback) const noexcept {
  const EntryRef ref = find(index, subIndex);
  return ref.valid() ? readUnsigned32(ref) : fallback;
}

bool ObjectDictionary::storeUnsigned(uint16_t index, uint8_t subIndex, uint64_t value) noexcept {
  const EntryRef ref = find(index, subIndex);
  if (!ref.valid()) {
    return false;
  }
  storeUnsigned(ref, value);
  return true;
}

bool ObjectDictionary::storeUnsigned32(uint16_t index, uint8_t subIndex, uint32_t value) noexcept {
  const EntryRef ref = find(index, subIndex);
  if (!ref.valid()) {
    return false;
  }
  storeHalves(ref, value, 0);
  return true;
}

}  // namespace costa::od
